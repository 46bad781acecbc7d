// Triangle meshes for the mdcs commands: the mesh type, reading OFF / PLY / OBJ / STL with CGAL's repair when the
// file is not a valid polygon mesh as is, triangulation of larger faces, and generated meshes (@torus,
// @icosphere) for machines without CGAL's data.
#ifndef MDCS_CLI_MESH_INPUT_H
#define MDCS_CLI_MESH_INPUT_H

#include "cli_common.h"
#include "cmd_mincut.h" // Input_error
#include "geodesic_render.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace mdcs_cli {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Geo_kernel;
typedef Geo_kernel::Point_3 Geo_point;
typedef CGAL::Surface_mesh<Geo_point> Geo_mesh;

namespace geo_detail {
inline Geo_vec vec(const Geo_point& p) { return {{p.x(), p.y(), p.z()}}; }
} // namespace geo_detail

// ------------------------------------------------------------------------------------------------------------
// Generated meshes (for a machine without CGAL's data, and for `@torus` / `@icosphere`).

inline void add_outward_triangles(Geo_mesh& m, const std::vector<Geo_point>& points,
                                  std::vector<std::array<std::size_t, 3>> triangles)
{
  double volume = 0; // six times the signed volume: flip everything if the faces point inwards
  for(const auto& t : triangles)
    volume += geo_detail::dot(geo_detail::vec(points[t[0]]), geo_detail::cross(geo_detail::vec(points[t[1]]), geo_detail::vec(points[t[2]])));
  if(volume < 0)
    for(auto& t : triangles) std::swap(t[1], t[2]);
  std::vector<Geo_mesh::Vertex_index> v;
  for(const Geo_point& p : points) v.push_back(m.add_vertex(p));
  for(const auto& t : triangles) m.add_face(v[t[0]], v[t[1]], v[t[2]]);
}

// A torus around the y axis: radii R and r, nu x nv quads split into two triangles each.
inline void make_torus_mesh(Geo_mesh& m, double R, double r, std::size_t nu, std::size_t nv)
{
  std::vector<Geo_point> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  const double pi = 3.14159265358979323846;
  for(std::size_t i = 0; i < nu; ++i)
    for(std::size_t j = 0; j < nv; ++j) {
      const double u = 2 * pi * double(i) / double(nu), w = 2 * pi * double(j) / double(nv);
      points.emplace_back((R + r * std::cos(w)) * std::cos(u), r * std::sin(w), (R + r * std::cos(w)) * std::sin(u));
    }
  auto id = [&](std::size_t i, std::size_t j) { return (i % nu) * nv + (j % nv); };
  for(std::size_t i = 0; i < nu; ++i)
    for(std::size_t j = 0; j < nv; ++j) {
      triangles.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}});
      triangles.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}});
    }
  add_outward_triangles(m, points, triangles);
}

// The unit icosphere: an icosahedron with every triangle split into four, `levels` times.
inline void make_icosphere_mesh(Geo_mesh& m, int levels)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2;
  std::vector<Geo_vec> p = {{{-1, t, 0}}, {{1, t, 0}}, {{-1, -t, 0}}, {{1, -t, 0}}, {{0, -1, t}}, {{0, 1, t}},
                            {{0, -1, -t}}, {{0, 1, -t}}, {{t, 0, -1}}, {{t, 0, 1}}, {{-t, 0, -1}}, {{-t, 0, 1}}};
  for(auto& x : p) x = geo_detail::normalized(x);
  std::vector<std::array<std::size_t, 3>> f = {{{0, 11, 5}}, {{0, 5, 1}}, {{0, 1, 7}}, {{0, 7, 10}}, {{0, 10, 11}},
    {{1, 5, 9}}, {{5, 11, 4}}, {{11, 10, 2}}, {{10, 7, 6}}, {{7, 1, 8}}, {{3, 9, 4}}, {{3, 4, 2}}, {{3, 2, 6}},
    {{3, 6, 8}}, {{3, 8, 9}}, {{4, 9, 5}}, {{2, 4, 11}}, {{6, 2, 10}}, {{8, 6, 7}}, {{9, 8, 1}}};
  for(int level = 0; level < levels; ++level) {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> middle;
    auto mid = [&](std::size_t a, std::size_t b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto it = middle.find(key);
      if(it != middle.end()) return it->second;
      p.push_back(geo_detail::normalized({{p[a][0] + p[b][0], p[a][1] + p[b][1], p[a][2] + p[b][2]}}));
      return middle[key] = p.size() - 1;
    };
    std::vector<std::array<std::size_t, 3>> g;
    for(const auto& tri : f) {
      const std::size_t a = mid(tri[0], tri[1]), b = mid(tri[1], tri[2]), c = mid(tri[2], tri[0]);
      g.push_back({{tri[0], a, c}});
      g.push_back({{tri[1], b, a}});
      g.push_back({{tri[2], c, b}});
      g.push_back({{a, b, c}});
    }
    f.swap(g);
  }
  std::vector<Geo_point> points;
  for(const auto& x : p) points.emplace_back(x[0], x[1], x[2]);
  add_outward_triangles(m, points, f);
}

// Reads MESH (or generates @torus / @icosphere); repairs and triangulates when needed, noting it in `notes`.
inline void load_geodesics_mesh(const std::string& path, Geo_mesh& mesh, std::vector<std::string>& notes)
{
  mesh.clear();
  if(path == "@torus") {
    make_torus_mesh(mesh, 1.0, 0.4, 96, 40);
    return;
  }
  if(path == "@icosphere") {
    make_icosphere_mesh(mesh, 4);
    return;
  }
  std::error_code ec;
  if(!std::filesystem::is_regular_file(path, ec)) throw Input_error("cannot open '" + path + "'");
  bool ok = false;
  try {
    ok = CGAL::IO::read_polygon_mesh(path, mesh);
  } catch(const std::exception&) {
    ok = false;
  }
  if(!ok || faces(mesh).empty()) {
    // Not a valid polygon mesh as is (e.g. non-manifold, or a polygon soup): CGAL's repair and orientation.
    mesh.clear();
    bool repaired = false;
    try {
      repaired = CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(path, mesh);
    } catch(const std::exception&) {
      repaired = false;
    }
    if(!repaired)
      throw Input_error("cannot read a polygon mesh from '" + path + "' (OFF, PLY, OBJ or STL; not a polygon mesh even after repair)");
    if(!faces(mesh).empty())
      notes.push_back("the file is not a valid polygon mesh as is: it was repaired and oriented (CGAL::Polygon_mesh_processing::IO::"
                      "read_polygon_mesh); vertex and face indices refer to the repaired mesh (the one the command writes out)");
  }
  if(faces(mesh).empty()) throw Input_error("'" + path + "' has no face");
  if(mesh.has_garbage()) mesh.collect_garbage();
  if(!CGAL::is_triangle_mesh(mesh)) {
    const std::size_t before = mesh.number_of_faces();
    if(!CGAL::Polygon_mesh_processing::triangulate_faces(mesh))
      throw Input_error("'" + path + "' has faces that cannot be triangulated");
    if(mesh.has_garbage()) mesh.collect_garbage();
    notes.push_back("faces with more than three corners were triangulated (" + std::to_string(before) + " -> " +
                    std::to_string(mesh.number_of_faces()) + " faces); face indices refer to the triangulated mesh");
  }
}

} // namespace mdcs_cli

#endif // MDCS_CLI_MESH_INPUT_H
