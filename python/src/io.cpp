// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Mesh files for the Python layer: OFF, PLY, OBJ and STL read as vertex and triangle arrays (CGAL's readers;
// polygons with more than three corners are triangulated).

#include "geodesic_surface.h" // Geo_mesh, mesh_from_arrays()

#include <CGAL/MDCS/IO/read_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <filesystem>

namespace mdcs_python {
namespace {

py::tuple read_mesh(const std::string& path)
{
  std::error_code ec;
  if(!std::filesystem::is_regular_file(path, ec)) throw Value_error("mdcs: cannot open '" + path + "' (no such file)");
  std::vector<Geo_point> points;
  std::vector<std::vector<std::size_t>> polygons;
  // The library's validating readers: counts checked against the file's size before anything is allocated,
  // every index and coordinate checked; a Read_error names the file, the line or element, and the problem.
  std::string error;
  {
    py::gil_scoped_release release;
    try {
      CGAL::MDCS::IO::read_polygon_soup(path, points, polygons);
    } catch(const CGAL::MDCS::IO::Read_error& e) {
      error = e.what();
    } catch(const std::bad_alloc&) {
      error = "'" + path + "': not enough memory to read it";
    }
  }
  if(!error.empty()) throw Value_error("mdcs: cannot read a mesh: " + error);
  if(polygons.empty()) throw Value_error("mdcs: '" + path + "' has no face");
  for(std::size_t f = 0; f < polygons.size(); ++f) {
    if(polygons[f].size() < 3) throw Value_error("mdcs: '" + path + "': face " + std::to_string(f) + " has fewer than 3 corners");
    for(std::size_t v : polygons[f])
      if(v >= points.size())
        throw Value_error("mdcs: '" + path + "': face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                          " of " + std::to_string(points.size()));
  }
  for(std::size_t i = 0; i < points.size(); ++i)
    if(!std::isfinite(points[i].x()) || !std::isfinite(points[i].y()) || !std::isfinite(points[i].z()))
      throw Value_error("mdcs: '" + path + "': vertex " + std::to_string(i) + " is not finite");

  std::vector<double> V;
  std::vector<std::int64_t> F;
  bool triangles = true;
  for(const auto& p : polygons) triangles = triangles && p.size() == 3;
  if(triangles) {
    for(const auto& p : points) V.insert(V.end(), {p.x(), p.y(), p.z()});
    for(const auto& p : polygons)
      for(std::size_t v : p) F.push_back(std::int64_t(v));
  } else {
    // Larger polygons: a surface mesh (oriented if needed), its faces triangulated.
    namespace PMP = CGAL::Polygon_mesh_processing;
    Geo_mesh mesh;
    if(!PMP::is_polygon_soup_a_polygon_mesh(polygons)) PMP::orient_polygon_soup(points, polygons);
    PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
    if(!PMP::triangulate_faces(mesh))
      throw Value_error("mdcs: '" + path + "' has polygons that cannot be triangulated");
    if(mesh.has_garbage()) mesh.collect_garbage();
    for(auto v : mesh.vertices()) {
      const Geo_point& p = mesh.point(v);
      V.insert(V.end(), {p.x(), p.y(), p.z()});
    }
    for(auto f : mesh.faces())
      for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) F.push_back(std::int64_t(v));
  }
  const py::ssize_t n = py::ssize_t(V.size() / 3), m = py::ssize_t(F.size() / 3);
  return py::make_tuple(to_numpy(std::move(V), n, 3), to_numpy(std::move(F), m, 3));
}

} // namespace

void bind_io(py::module_& m)
{
  py::module_ io = m.def_submodule("io", "C++ core of mdcs.io (use mdcs.io)");
  io.def("read_mesh", &read_mesh, py::arg("path"));
}

} // namespace mdcs_python
