// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// read_triangle_mesh(): a mesh file into a triangle mesh (any MutableFaceGraph) through the distrustful
// readers, with the surface as the file gives it or a clear refusal; CGAL's soup repair only on request.

#ifndef CGAL_MDCS_IO_READ_TRIANGLE_MESH_H
#define CGAL_MDCS_IO_READ_TRIANGLE_MESH_H

#include <CGAL/MDCS/IO/Read_error.h>
#include <CGAL/MDCS/IO/read_polygon_soup.h>
#include <CGAL/MDCS/analyze_polygon_soup.h>
#include <CGAL/MDCS/triangulate_polygon_soup.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace MDCS {
namespace IO {

/// \ingroup PkgMDCSIO
/// Options of `read_triangle_mesh()`.
struct Triangle_mesh_reading_options
{
  /// Run CGAL's soup repair (`repair_polygon_soup()`, `orient_polygon_soup()`) when the file is not a valid
  /// oriented manifold mesh, instead of refusing it. The repair changes the surface (it merges coincident
  /// points, drops degenerate and duplicate faces and isolated points, reorients faces, and cuts the surface
  /// open along non-manifold edges, at pinched vertices and across non-orientable parts): the report's
  /// notes say so.
  bool repair = false;
  /// The file format (by default from the extension, then from the content).
  Mesh_file_format format = Mesh_file_format::automatic;
  /// Appended to the message of a refusal (for example how to ask for the repair in a program's options).
  std::string refusal_hint;
};

/// \ingroup PkgMDCSIO
/// What `read_triangle_mesh()` found and did.
struct Triangle_mesh_reading_report
{
  Mesh_file_format format = Mesh_file_format::automatic;
  Polygon_soup_analysis analysis;                 ///< of the soup as the file gives it
  bool repaired = false;                          ///< CGAL's repair ran (the surface differs from the file's)
  std::size_t points_after_repair = 0, faces_after_repair = 0;
  Polygon_soup_triangulation_report triangulation; ///< how polygons with more than 3 corners were split
  std::vector<std::size_t> face_to_file_face;     ///< per mesh face, its face in the file (empty after a repair)
  /// Sentences for the user: repair, triangulation, isolated or coincident points, zero-area faces, components.
  std::vector<std::string> notes;
};

/*!
  \ingroup PkgMDCSIO
  \brief reads a triangle mesh from an OFF, PLY, OBJ or STL file, distrusting the file and refusing surfaces
  that are not valid oriented manifold meshes unless asked to repair them.

  1. `read_polygon_soup()` reads the file (every count, index and coordinate validated).
  2. `analyze_polygon_soup()` classifies the soup. A soup that is a valid oriented polygon mesh (every edge
     shared by at most two faces in opposite directions, no pinched vertex, no repeated vertex in a face) is
     kept as it is: mesh vertex i is point i of the file (isolated points included) and faces keep the file's
     order. Any other soup is refused with a `Read_error` that names the first defect (for example "edge (12,
     40) is shared by 3 face sides"), unless `options.repair` is set: then CGAL's `repair_polygon_soup()` and
     `orient_polygon_soup()` make a mesh of it, the report says so, and point and face numbers are those of
     the repaired soup.
  3. Polygons with more than three corners are split by `triangulate_polygon_soup()`; each face's
     triangles follow each other in the file's face order (`face_to_file_face`).

  \tparam TriangleMesh a model of `MutableFaceGraph` with an internal vertex point map whose points are
          constructible from three doubles (`Surface_mesh`, `Polyhedron_3`, ...)
  \param tm cleared, then filled
  \throws Read_error for a file that cannot be read (see `read_polygon_soup()`), has no face, or describes a
          surface that is refused (or that even the repair cannot make a mesh of)
*/
template <class TriangleMesh>
Triangle_mesh_reading_report read_triangle_mesh(const std::string& file_name, TriangleMesh& tm,
                                                const Triangle_mesh_reading_options& options = Triangle_mesh_reading_options())
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  typedef typename CGAL::GetVertexPointMap<TriangleMesh>::type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point;
  typedef std::vector<std::size_t> Polygon;

  Triangle_mesh_reading_report report;
  CGAL::clear(tm);
  auto count = [](std::size_t n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); };
  std::vector<Point> points;
  std::vector<Polygon> polygons;
  report.format = read_polygon_soup(file_name, points, polygons, options.format);
  if(polygons.empty())
    throw Read_error(file_name, 0, "", "the file has no face (" + std::to_string(points.size()) + " points): not a surface");

  report.analysis = analyze_polygon_soup(points, polygons);
  const Polygon_soup_analysis& a = report.analysis;
  auto refuse = [&](const std::string& why) {
    throw Read_error(file_name, 0, "", why + (options.refusal_hint.empty() ? std::string() : "; " + options.refusal_hint));
  };
  if(!a.is_polygon_mesh()) {
    if(!options.repair) refuse("not a valid oriented manifold mesh: " + a.problem() + " [" + a.summary() + "]");
    PMP::repair_polygon_soup(points, polygons);
    const bool no_duplication = PMP::orient_polygon_soup(points, polygons);
    if(polygons.empty()) refuse("no face is left after CGAL's soup repair (" + a.problem() + ")");
    if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
      refuse("not a polygon mesh even after CGAL's soup repair: " + analyze_polygon_soup(points, polygons).problem());
    report.repaired = true;
    report.points_after_repair = points.size();
    report.faces_after_repair = polygons.size();
    report.notes.push_back("the file is not a valid oriented manifold mesh (" + a.problem() +
                           "); CGAL's soup repair made a mesh of it (" + std::to_string(a.number_of_points) + " -> " +
                           std::to_string(points.size()) + " vertices, " + std::to_string(a.number_of_polygons) + " -> " +
                           std::to_string(polygons.size()) + " faces" +
                           (no_duplication ? "" : ", vertices duplicated to cut non-manifold or non-orientable parts open") +
                           "): results are for the repaired surface, and vertex and face numbers refer to it");
  }

  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<std::size_t> triangle_to_polygon;
  triangles.reserve(polygons.size());
  report.triangulation = triangulate_polygon_soup(points, polygons, triangles, &triangle_to_polygon);
  const Polygon_soup_triangulation_report& t = report.triangulation;
  if(t.polygons_split() > 0) {
    report.notes.push_back(count(t.polygons_split(), "face", "faces") + " with more than three corners " +
                           (t.polygons_split() == 1 ? "was" : "were") + " triangulated (" +
                           std::to_string(polygons.size()) + " -> " + std::to_string(triangles.size()) +
                           " faces" + (t.by_fan > 0 ? "; " + count(t.by_fan, "degenerate one as a fan", "degenerate ones as fans") : "") +
                           "): face numbers refer to the triangles");
    if(!PMP::is_polygon_soup_a_polygon_mesh(triangles))
      refuse("triangulating the faces with more than three corners does not give a manifold mesh: " +
             analyze_polygon_soup(points, triangles).problem());
  }
  if(!report.repaired) report.face_to_file_face = triangle_to_polygon;

  if(a.isolated_points > 0 && !report.repaired)
    report.notes.push_back(count(a.isolated_points, "vertex belongs", "vertices belong") + " to no face (vertex " +
                           std::to_string(a.example_isolated_point) + " is one); they are kept, unreachable");
  if(a.coincident_points > 0)
    report.notes.push_back(count(a.coincident_points, "vertex has", "vertices have") + " the same coordinates as another one (" +
                           std::to_string(a.example_coincident_points[0]) + " and " +
                           std::to_string(a.example_coincident_points[1]) + ")" +
                           (report.repaired ? "" : "; they are distinct vertices of the mesh"));
  if(a.degenerate_polygons > 0)
    report.notes.push_back(count(a.degenerate_polygons, "face has", "faces have") + " zero area (face " +
                           std::to_string(a.example_degenerate_polygon) + " is one)");
  if(a.connected_components > 1 && !report.repaired)
    report.notes.push_back("the surface has " + std::to_string(a.connected_components) + " connected components");

  PMP::polygon_soup_to_polygon_mesh(points, triangles, tm);
  return report;
}

} // namespace IO
} // namespace MDCS
} // namespace CGAL

#endif // CGAL_MDCS_IO_READ_TRIANGLE_MESH_H
