// Triangle meshes for the mdcs commands: the mesh type, reading OFF / PLY / OBJ / STL through the library's
// distrustful readers (CGAL::MDCS::IO::read_triangle_mesh: the surface as the file gives it, or a refusal that
// says why; CGAL's soup repair only with --repair), triangulation of larger faces, and generated meshes
// (@torus, @icosphere) for machines without CGAL's data.
#ifndef MDCS_CLI_MESH_INPUT_H
#define MDCS_CLI_MESH_INPUT_H

#include "cli_common.h"
#include "cmd_mincut.h" // Input_error
#include "geodesic_render.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/MDCS/IO/read_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

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

// The hint of a refusal: how to ask for the repair.
inline const char* repair_hint()
{
  return "pass --repair to run CGAL's soup repair instead (it changes the surface: results are then for the repaired one)";
}

// Reads MESH (or generates @torus / @icosphere). A file that is a valid oriented manifold mesh is used as it is
// (the file's vertex and face order; larger faces triangulated, with a note); any other file is refused
// (Input_error, exit 3, saying why) unless `repair` is set, which runs CGAL's soup repair and notes it in
// `notes` (the commands print the notes on stderr and write them into their outputs). Returns whether it repaired.
inline bool load_geodesics_mesh(const std::string& path, Geo_mesh& mesh, std::vector<std::string>& notes, bool repair = false)
{
  mesh.clear();
  if(path == "@torus") {
    make_torus_mesh(mesh, 1.0, 0.4, 96, 40);
    return false;
  }
  if(path == "@icosphere") {
    make_icosphere_mesh(mesh, 4);
    return false;
  }
  CGAL::MDCS::IO::Triangle_mesh_reading_options options;
  options.repair = repair;
  options.refusal_hint = repair_hint();
  try {
    const CGAL::MDCS::IO::Triangle_mesh_reading_report report = CGAL::MDCS::IO::read_triangle_mesh(path, mesh, options);
    notes.insert(notes.end(), report.notes.begin(), report.notes.end());
    if(repair && !report.repaired)
      notes.push_back("--repair was given, but the file is a valid oriented manifold mesh: nothing was repaired");
    return report.repaired;
  } catch(const CGAL::MDCS::IO::Read_error& e) {
    throw Input_error(e.what());
  }
}

} // namespace mdcs_cli

#endif // MDCS_CLI_MESH_INPUT_H
