// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The prepared surface behind mdcs.geodesics.Mesh: the triangle mesh built once from the vertex and face arrays,
// the maps between the caller's indices and the mesh's, and a pool of geodesic distance objects (one per method and
// memory mode, reused across calls and handed to one thread at a time).
//
// The mesh is a CGAL::Surface_mesh built by build_surface_mesh() (geodesic_surface.cpp), the one function to change
// when the library's own prepared surface (shareable by every geodesic class and thread, built from a triangle soup
// including non-manifold and non-orientable ones) replaces it: a soup that is not a manifold, consistently oriented
// mesh is oriented by CGAL's orient_polygon_soup(), which splits non-manifold vertices (and cuts non-orientable
// surfaces) into copies; the distance of a caller's vertex is the smallest over its copies.

#ifndef MDCS_PYTHON_GEODESIC_SURFACE_H
#define MDCS_PYTHON_GEODESIC_SURFACE_H

#include "common.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_types.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace mdcs_python {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Geo_kernel;
typedef Geo_kernel::Point_3 Geo_point;
typedef CGAL::Surface_mesh<Geo_point> Geo_mesh;

/// Checked mesh arrays: vertices (n, 3) finite floats, faces (m >= 1, 3) indices in range with distinct corners.
std::pair<Double_array, Index_array> checked_mesh_arrays(py::handle vertices, py::handle faces);

/// The one function that turns the arrays into a Surface_mesh (vertex i and face f of the arrays are vertex i and
/// face f of the mesh). A soup that is not an oriented manifold mesh is oriented by CGAL's orient_polygon_soup(),
/// which may reverse faces and appends copies of split vertices after the n input points: returns the
/// (original, copy) pairs. ValueError when even that does not give a surface mesh.
std::vector<std::pair<std::size_t, std::size_t>> mesh_from_arrays(const double* vertices, std::size_t n,
                                                                  const std::int64_t* faces, std::size_t m,
                                                                  Geo_mesh& mesh, bool& oriented);

enum class Geodesic_method { exact, merged, flat_exact, fast_marching, dijkstra };

/// "exact", "merged", "flat_exact" (or "flat-exact"), "fast_marching" (or "fmm"), "dijkstra"; ValueError otherwise.
Geodesic_method parse_geodesic_method(const std::string& name);
const char* method_name(Geodesic_method method);

/// One point of a path as the library reports it, in the mesh's own indices.
struct Raw_path_node
{
  enum Kind { VERTEX = 0, EDGE = 1, FACE = 2 };
  int kind;
  std::size_t index;              // mesh vertex, halfedge or face index
  double t;                       // EDGE: (1-t) source(h) + t target(h)
  std::array<double, 3> barycentric; // FACE: in the mesh's corner order
};

/// One of the library's geodesic distance objects on the surface's mesh, behind a virtual interface so that the
/// five classes are instantiated in two translation units (geodesic_solvers_*.cpp).
class Geodesic_solver
{
public:
  virtual ~Geodesic_solver() = default;
  virtual void clear_sources() = 0;
  virtual void add_vertex_source(std::size_t mesh_vertex) = 0;
  virtual void add_point_source(std::size_t mesh_face, const std::array<double, 3>& barycentric) = 0;
  /// +infinity: no limit
  virtual void set_distance_limit(double limit) = 0;
  virtual void set_stop_targets(const std::vector<std::size_t>& mesh_vertices) = 0;
  virtual void set_path_shortening(bool on) = 0;
  /// The propagation's threads (1: the sequential schedule, else the parallel one on that many threads, 0 = every
  /// hardware thread). Only the exact class has a parallel single-source schedule; the others ignore it.
  virtual void set_threads(std::size_t) {}
  virtual void compute(Progress_bridge& progress) = 0;
  virtual void compute_quietly() = 0;
  /// Distances and nearest sources (-1: unreachable) of every mesh vertex, after compute().
  virtual void vertex_results(std::vector<double>& distances, std::vector<std::int64_t>* nearest) = 0;
  virtual std::pair<double, std::int64_t> point_result(std::size_t mesh_face, const std::array<double, 3>& b) = 0;
  virtual void path(std::size_t mesh_face, const std::array<double, 3>& b, std::vector<Raw_path_node>& out) = 0;
  virtual void vertex_path(std::size_t mesh_vertex, std::vector<Raw_path_node>& out) = 0;
  virtual CGAL::Polyhedral_geodesics_3::Geodesic_statistics statistics() const = 0;
};

/// Defined in geodesic_solvers_exact.cpp (exact, merged) and geodesic_solvers_approximate.cpp (the others).
std::unique_ptr<Geodesic_solver> make_window_solver(const Geo_mesh& mesh, bool merged, double tolerance, bool full_field);
std::unique_ptr<Geodesic_solver> make_approximate_solver(const Geo_mesh& mesh, Geodesic_method method, bool full_field);

/// What a solver is made for; solvers of the same kind are interchangeable.
struct Solver_kind
{
  Geodesic_method method = Geodesic_method::exact;
  double tolerance = 0; // merged only
  bool full_field = false;
  bool operator==(const Solver_kind& o) const
  {
    return method == o.method && tolerance == o.tolerance && full_field == o.full_field;
  }
};

/// A source as the caller gives it, translated to the mesh: a vertex (all its copies) or a surface point.
struct Mesh_source
{
  bool at_vertex = true;
  std::vector<std::size_t> vertices;          // the mesh copies of the vertex
  std::size_t face = 0;                       // surface point: mesh face
  std::array<double, 3> barycentric{{0, 0, 0}}; // in the mesh's corner order
};

class Geodesic_surface
{
public:
  /// `vertices` n x 3 (finite), `faces` m x 3 (indices in range, three distinct corners): checked by the caller.
  Geodesic_surface(const double* vertices, std::size_t n, const std::int64_t* faces, std::size_t m);

  std::size_t number_of_vertices() const { return n_; }
  std::size_t number_of_faces() const { return m_; }
  const Geo_mesh& mesh() const { return mesh_; }
  /// Whether the faces had to be oriented or vertices split (a non-manifold or non-orientable soup).
  bool was_oriented() const { return oriented_; }
  std::size_t number_of_split_vertices() const { return split_vertices_; }
  std::size_t number_of_isolated_vertices() const { return isolated_; }
  double mean_edge_length() const { return mean_edge_length_; }

  /// The caller's vertex of mesh vertex `v`.
  std::size_t user_vertex(std::size_t mesh_vertex) const { return user_of_mesh_vertex_[mesh_vertex]; }
  /// The mesh vertices of the caller's vertex `u` (usually one).
  std::vector<std::size_t> mesh_vertices(std::size_t u) const;
  bool is_isolated(std::size_t u) const { return isolated_flag_[u] != 0; }
  /// The caller's barycentric coordinates (in the order of faces[f]) in the mesh's corner order, and back.
  std::array<double, 3> to_mesh_barycentric(std::size_t f, const std::array<double, 3>& b) const;
  std::array<double, 3> to_user_barycentric(std::size_t f, const std::array<double, 3>& b) const;
  /// The caller's corner `k` of face `f` is the mesh's corner `corner_position(f, k)`.
  int corner_position(std::size_t f, int k) const { return corner_of_[f][std::size_t(k)]; }

  Mesh_source vertex_source(std::size_t u) const;
  Mesh_source point_source(std::size_t f, const std::array<double, 3>& user_barycentric) const;
  void add_source(Geodesic_solver& solver, const Mesh_source& s) const;

  /// Per caller vertex: the smallest distance over its copies and that copy's nearest source (mapped through
  /// `source_of`, the caller's source index of each solver source). Isolated vertices: +infinity and -1.
  void user_results(const std::vector<double>& mesh_distances, const std::vector<std::int64_t>* mesh_nearest,
                    const std::vector<std::int64_t>& source_of, double* distances, std::int64_t* nearest) const;

  /// Converted path nodes.
  struct Path
  {
    std::vector<double> points;        // k x 3
    std::vector<std::uint8_t> kinds;   // 0 vertex, 1 edge, 2 face
    std::vector<std::int64_t> vertex;  // caller's vertex or -1
    std::vector<std::int64_t> edge;    // k x 2: the caller's vertices of the crossed edge, or -1
    std::vector<double> t;             // position on the edge (from edge[:, 0] to edge[:, 1]) or NaN
    std::vector<std::int64_t> face;    // face of a point inside a face, or -1
    std::vector<double> barycentric;   // k x 3, in the order of faces[face], or NaN
  };
  void convert_path(const std::vector<Raw_path_node>& raw, Path& out) const;

  /// A solver of this kind from the pool, or a new one.
  std::unique_ptr<Geodesic_solver> acquire(const Solver_kind& kind) const;
  /// Returns a solver to the pool (kept when the pool is not full and the solver holds no window field).
  void release(const Solver_kind& kind, std::unique_ptr<Geodesic_solver> solver) const;
  std::unique_ptr<Geodesic_solver> make_solver(const Solver_kind& kind) const;

private:
  std::size_t n_, m_;
  Geo_mesh mesh_;
  bool oriented_ = false;
  std::size_t split_vertices_ = 0, isolated_ = 0;
  double mean_edge_length_ = 0;
  std::vector<std::uint32_t> user_of_mesh_vertex_;
  std::vector<std::uint32_t> extra_copies_begin_, extra_copies_; // CSR of copies beyond the first (split vertices)
  std::vector<char> isolated_flag_;
  std::vector<std::array<std::int8_t, 3>> corner_of_;

  mutable std::mutex pool_mutex_;
  mutable std::vector<std::pair<Solver_kind, std::unique_ptr<Geodesic_solver>>> pool_;
};

/// Locates points and rays on the surface (geodesic_queries.cpp): an AABB tree of the mesh, built once.
struct Point_locator;
std::shared_ptr<const Point_locator> make_point_locator(const Geodesic_surface& s);
/// The surface point closest to each of the k points (k x 3): the caller's face and barycentric coordinates.
void locate_points(const Geodesic_surface& s, const Point_locator& l, const double* points, std::size_t k,
                   std::int64_t* faces, double* barycentric);
/// The first surface point of each ray (origins and directions k x 3, directions nonzero), or face -1 and NaN.
void locate_rays(const Geodesic_surface& s, const Point_locator& l, const double* origins, const double* directions,
                 std::size_t k, std::int64_t* faces, double* barycentric);

/// One iso-distance curve: its level, whether closed, its points (x, y, z, x, y, z, ...).
struct Iso_curve
{
  double level = 0;
  bool closed = false;
  std::vector<double> points;
};
/// The iso-distance curves of vertex distances on the caller's arrays (checked by the caller), by increasing level.
std::vector<Iso_curve> iso_curves(const double* vertices, std::size_t n, const std::int64_t* faces, std::size_t m,
                                  const double* distances, const std::vector<double>& levels);

} // namespace mdcs_python

#endif // MDCS_PYTHON_GEODESIC_SURFACE_H
