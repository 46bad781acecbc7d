// Surfaces that are not oriented manifold meshes, for `mdcs geodesics`: a file with edges of three or more faces,
// pinched vertices or non-orientable (reversed) gluings is used as the file gives it, as a triangle soup
// (Geodesic_surface_3<Triangle_soup>: edge adjacency from the face indices), instead of being refused or changed
// by CGAL's soup repair. The accessors below (geo_*) give the few things the command needs from either kind of
// surface (a Surface_mesh or a Geo_soup), so that one templated run serves both.
#ifndef MDCS_CLI_GEODESIC_SOUP_H
#define MDCS_CLI_GEODESIC_SOUP_H

#include "geodesics_options.h"
#include "mesh_input.h"

#include <CGAL/MDCS/IO/read_polygon_soup.h>
#include <CGAL/MDCS/analyze_polygon_soup.h>
#include <CGAL/MDCS/triangulate_polygon_soup.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_surface_3.h>

#include <boost/range/irange.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace mdcs_cli {

// A triangle soup as the file gives it (faces with more than three corners triangulated) and its geodesic surface.
struct Geo_soup
{
  std::vector<Geo_point> points;
  std::vector<std::array<std::size_t, 3>> triangles; // corners in the file's order
  std::vector<char> used;                             // per point: belongs to a triangle
  std::shared_ptr<const CGAL::Polyhedral_geodesics_3::Geodesic_surface_3<CGAL::Polyhedral_geodesics_3::Triangle_soup>> surface;
  std::string problem; // why the file is not an oriented manifold mesh (the reader's analysis)
};

// The vertex range of a soup (vertex indices), for library functions that iterate `vertices(tm)`.
inline auto vertices(const Geo_soup& s) { return boost::irange<std::size_t>(0, s.points.size()); }

// Which surface the results are for (summary.txt, summary.json's inputs.surface): the file's as given (a soup that
// is not an oriented manifold mesh, with its shape report), the file's mesh, or the mesh CGAL's repair made of it.
struct Geo_surface_shape
{
  bool as_given_soup = false, repaired = false;
  std::size_t nonmanifold_edges = 0, reversed_edges = 0, pinched_vertices = 0, border_edges = 0;

  Json_object json() const
  {
    Json_object o;
    o.add("used_as_given", !repaired).add("repaired", repaired).add("oriented_manifold_mesh", !as_given_soup);
    if(as_given_soup)
      o.add("nonmanifold_edges", (unsigned long long)nonmanifold_edges).add("reversed_edges", (unsigned long long)reversed_edges)
        .add("pinched_vertices", (unsigned long long)pinched_vertices).add("border_edges", (unsigned long long)border_edges);
    return o;
  }
  std::string text() const
  {
    if(!as_given_soup) return "";
    return "surface: used as given, not an oriented manifold mesh: " + std::to_string(nonmanifold_edges) + " edges of three or more faces, " +
           std::to_string(reversed_edges) + " edges glued with reversed orientation, " + std::to_string(pinched_vertices) +
           " pinched vertices, " + std::to_string(border_edges) + " border edges\n";
  }
};

struct Geo_edge_stats
{
  double total = 0, longest = 0;
  std::size_t count = 0;
  double mean() const { return count > 0 ? total / double(count) : 0; }
};

// --- The accessors, for a Surface_mesh and for a soup ----------------------------------------------------------

inline std::size_t geo_vertex_count(const Geo_mesh& m) { return m.number_of_vertices(); }
inline std::size_t geo_vertex_count(const Geo_soup& s) { return s.points.size(); }
inline std::size_t geo_face_count(const Geo_mesh& m) { return m.number_of_faces(); }
inline std::size_t geo_face_count(const Geo_soup& s) { return s.triangles.size(); }
inline bool geo_is_isolated(const Geo_mesh& m, std::size_t v) { return m.is_isolated(Geo_mesh::Vertex_index(Geo_mesh::size_type(v))); }
inline bool geo_is_isolated(const Geo_soup& s, std::size_t v) { return !s.used[v]; }
inline const Geo_point& geo_vertex_point(const Geo_mesh& m, std::size_t v) { return m.point(Geo_mesh::Vertex_index(Geo_mesh::size_type(v))); }
inline const Geo_point& geo_vertex_point(const Geo_soup& s, std::size_t v) { return s.points[v]; }

// The corners of a triangle in listing order (the order of distances.ply, and of the file).
inline std::array<std::size_t, 3> geo_triangle(const Geo_mesh& m, std::size_t f)
{
  const auto h = m.halfedge(Geo_mesh::Face_index(Geo_mesh::size_type(f)));
  return {{m.target(h).idx(), m.target(m.next(h)).idx(), m.target(m.next(m.next(h))).idx()}};
}
inline const std::array<std::size_t, 3>& geo_triangle(const Geo_soup& s, std::size_t f) { return s.triangles[f]; }

// The lengths of the edges (each edge once: for a soup, each vertex pair of a triangle side once).
inline Geo_edge_stats geo_edge_lengths(const Geo_mesh& m)
{
  Geo_edge_stats e;
  for(Geo_mesh::Edge_index x : m.edges()) {
    const double l = std::sqrt(CGAL::squared_distance(m.point(m.vertex(x, 0)), m.point(m.vertex(x, 1))));
    e.total += l;
    e.longest = std::max(e.longest, l);
    ++e.count;
  }
  return e;
}
inline Geo_edge_stats geo_edge_lengths(const Geo_soup& s)
{
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  edges.reserve(3 * s.triangles.size());
  for(const auto& t : s.triangles)
    for(std::size_t k = 0; k < 3; ++k) edges.push_back(std::minmax(t[k], t[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  Geo_edge_stats e;
  for(const auto& x : edges) {
    const double l = std::sqrt(CGAL::squared_distance(s.points[x.first], s.points[x.second]));
    e.total += l;
    e.longest = std::max(e.longest, l);
  }
  e.count = edges.size();
  return e;
}

inline Geo_surface_shape geo_surface_shape(const Geo_mesh&, bool repaired)
{
  Geo_surface_shape shape;
  shape.repaired = repaired;
  return shape;
}
inline Geo_surface_shape geo_surface_shape(const Geo_soup& soup, bool = false)
{
  Geo_surface_shape shape;
  shape.as_given_soup = true;
  shape.nonmanifold_edges = soup.surface->number_of_nonmanifold_edges();
  shape.reversed_edges = soup.surface->number_of_reversed_edges();
  shape.pinched_vertices = soup.surface->number_of_pinched_vertices();
  shape.border_edges = soup.surface->number_of_border_edges();
  return shape;
}

// The methods and comparisons that cannot run on a surface used as given (exit 3, saying why and what works).
inline void refuse_unsupported_on_soup(const Geo_mesh&, const Geodesics_settings&) {}
inline void refuse_unsupported_on_soup(const Geo_soup& soup, const Geodesics_settings& s)
{
  const auto& surface = *soup.surface;
  const std::string alternatives = "; methods that compute on this surface as given: exact, merged:EPS, dijkstra" +
                                   std::string(surface.has_oriented_manifold_edges() ? ", flat-exact, fmm" : "") + "; or " + repair_hint();
  const std::string what = "the file is not an oriented manifold mesh (" + soup.problem + ")";
  if(s.method.is_heat())
    throw Input_error("--method " + s.method.text + ": CGAL's heat method needs an oriented manifold Surface_mesh, and " + what + alternatives);
  if((s.method.kind == Geo_method_kind::fmm || s.method.kind == Geo_method_kind::flat_exact) && !surface.has_oriented_manifold_edges())
    throw Input_error("--method " + s.method.text + ": " + s.method.description() + " need every edge shared by at most two faces with "
                      "opposite orientations (they unfold a face across an edge into one consistently oriented neighbour), and the "
                      "surface has " + std::to_string(surface.number_of_nonmanifold_edges()) + " edges of three or more faces and " +
                      std::to_string(surface.number_of_reversed_edges()) + " edges glued with reversed orientation (" + soup.problem + ")" +
                      alternatives);
  if(s.compare_cgal)
    throw Input_error("--compare-cgal: CGAL's Surface_mesh_shortest_path needs an oriented manifold Surface_mesh, and " + what +
                      "; --compare-exact works on it");
}

// --- Reading ---------------------------------------------------------------------------------------------------

// Makes the soup of a file that is not an oriented manifold mesh (for load_geodesics_input) from its points and
// polygons. Throws Input_error for what no surface can be made of (a polygon with a repeated corner, more than 31
// faces on one edge, ...), with the hint about --repair.
inline void make_geodesics_soup(const std::string& path, std::vector<std::vector<std::size_t>>& polygons, Geo_soup& soup,
                                std::vector<std::string>& notes)
{
  const CGAL::MDCS::Polygon_soup_analysis a = CGAL::MDCS::analyze_polygon_soup(soup.points, polygons);
  soup.problem = a.problem();
  const CGAL::MDCS::Polygon_soup_triangulation_report t = CGAL::MDCS::triangulate_polygon_soup(soup.points, polygons, soup.triangles);
  try {
    soup.surface = CGAL::Polyhedral_geodesics_3::make_geodesic_surface(soup.points, soup.triangles);
  } catch(const std::invalid_argument& e) {
    throw Input_error(path + ": not a surface, even as given (" + soup.problem + "): " + e.what() + "; " + repair_hint());
  }
  soup.used.assign(soup.points.size(), 0);
  for(const auto& tri : soup.triangles)
    for(std::size_t v : tri) soup.used[v] = 1;
  const auto& s = *soup.surface;
  notes.push_back("the file is not a valid oriented manifold mesh (" + soup.problem + "): geodesics are computed on the surface as "
                  "given (" + std::to_string(s.number_of_nonmanifold_edges()) + " edges of three or more faces, " +
                  std::to_string(s.number_of_reversed_edges()) + " edges glued with reversed orientation, " +
                  std::to_string(s.number_of_pinched_vertices()) + " pinched vertices); vertex and face numbers are the file's; "
                  "--repair would run CGAL's soup repair instead, which changes the surface");
  if(t.polygons_split() > 0)
    notes.push_back(std::to_string(t.polygons_split()) + " faces with more than three corners were triangulated (" +
                    std::to_string(polygons.size()) + " -> " + std::to_string(soup.triangles.size()) + " faces): face numbers refer to the triangles");
  if(s.number_of_isolated_vertices() > 0)
    notes.push_back(std::to_string(s.number_of_isolated_vertices()) + " vertices belong to no face; they are kept, unreachable");
  if(a.connected_components > 1) notes.push_back("the surface has " + std::to_string(a.connected_components) + " connected components");
}

// What load_geodesics_input made of a file.
enum class Geo_input_kind { mesh, repaired_mesh, soup };

// Reads MESH for `mdcs geodesics`: a valid oriented manifold mesh (or @torus / @icosphere) into `mesh`; with
// `repair`, any other file through CGAL's soup repair into `mesh`; without it, any other file as given into `soup`
// (only after the mesh reader refused it, so that valid meshes are read once).
inline Geo_input_kind load_geodesics_input(const std::string& path, Geo_mesh& mesh, Geo_soup& soup, std::vector<std::string>& notes,
                                           bool repair)
{
  std::vector<std::vector<std::size_t>> polygons;
  try {
    return load_geodesics_mesh(path, mesh, notes, repair) ? Geo_input_kind::repaired_mesh : Geo_input_kind::mesh;
  } catch(const Input_error&) {
    if(repair) throw;
    // A malformed file, or one without a face, keeps the mesh reader's refusal.
    bool readable = true;
    try {
      CGAL::MDCS::IO::read_polygon_soup(path, soup.points, polygons);
    } catch(const CGAL::MDCS::IO::Read_error&) {
      readable = false;
    }
    if(!readable || polygons.empty()) throw;
  }
  mesh.clear();
  make_geodesics_soup(path, polygons, soup, notes);
  return Geo_input_kind::soup;
}

} // namespace mdcs_cli

#endif // MDCS_CLI_GEODESIC_SOUP_H
