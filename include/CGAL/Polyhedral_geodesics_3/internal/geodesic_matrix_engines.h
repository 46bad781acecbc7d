// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The engines behind geodesic_distance_matrix.h: the method of a matrix request mapped to the propagation engine of
// its public class, and one single-source run of an engine on any compact mesh (the whole mesh, shared by every
// thread, or a neighbourhood of the source).

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_GEODESIC_MATRIX_ENGINES_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_GEODESIC_MATRIX_ENGINES_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Exact_geodesic_engine.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>
#include <CGAL/Polyhedral_geodesics_3/internal/dijkstra_edge_propagation.h>
#include <CGAL/Polyhedral_geodesics_3/internal/fast_marching_propagation.h>
#include <CGAL/Polyhedral_geodesics_3/internal/flat_exact_propagation.h>

#include <memory>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  The method of a distance matrix: the propagation of one of the package's classes.
*/
enum class Geodesic_method
{
  exact,          ///< `Exact_geodesic_distances_3` (distances_only: the vertex-oriented schedule without a limit)
  merged_windows, ///< `Merged_window_geodesic_distances_3` with `Geodesic_matrix_options::merge_tolerance`
  flat_exact,     ///< `Flat_exact_geodesic_distances_3`
  fast_marching,  ///< `Fast_marching_geodesic_distances_3`
  dijkstra        ///< `Dijkstra_geodesic_distances_3` (shortest paths along the edges)
};

/// The name of a method, as the command-line tool spells it.
inline const char* geodesic_method_name(Geodesic_method m)
{
  switch(m) {
  case Geodesic_method::exact: return "exact";
  case Geodesic_method::merged_windows: return "merged";
  case Geodesic_method::flat_exact: return "flat-exact";
  case Geodesic_method::fast_marching: return "fmm";
  case Geodesic_method::dijkstra: return "dijkstra";
  }
  return "?";
}

namespace internal {

typedef Geodesic_mesh<double> Matrix_mesh;
typedef Matrix_mesh::Index Matrix_index;

// A single-source run of any engine of the facade protocol (see Geodesic_distances_facade.h), distances only, with
// an optional limit. The engine keeps its arrays for the next run.
template <class Engine>
void run_single_source(Engine& engine, Matrix_index source, bool has_limit, double limit)
{
  engine.clear();
  engine.set_keep_windows(false);
  if(has_limit) engine.set_distance_limit(limit);
  else engine.clear_distance_limit();
  engine.set_stop_targets(std::vector<Matrix_index>());
  engine.add_vertex_source(source, 0);
  MDCS::No_progress none;
  engine.run(none);
}

// An engine of the method on `mesh`; `merge_tolerance` is given to the window engines (0: exact).
template <class Engine>
struct Matrix_engine_maker
{
  static std::unique_ptr<Engine> make(const Matrix_mesh& mesh, double) { return std::unique_ptr<Engine>(new Engine(mesh)); }
};

template <>
struct Matrix_engine_maker<Exact_geodesic_engine<double>>
{
  static std::unique_ptr<Exact_geodesic_engine<double>> make(const Matrix_mesh& mesh, double merge_tolerance)
  {
    std::unique_ptr<Exact_geodesic_engine<double>> e(new Exact_geodesic_engine<double>(mesh));
    e->set_merge_tolerance(merge_tolerance);
    return e;
  }
};

template <class Engine>
std::unique_ptr<Engine> make_matrix_engine(const Matrix_mesh& mesh, double merge_tolerance)
{
  return Matrix_engine_maker<Engine>::make(mesh, merge_tolerance);
}

// Calls f.template operator()<Engine>() with the engine type of `method` (a generic lambda taking a tag).
template <class Engine>
struct Engine_tag
{
  typedef Engine type;
};

template <class F>
void with_matrix_engine(Geodesic_method method, F f)
{
  switch(method) {
  case Geodesic_method::exact:
  case Geodesic_method::merged_windows: f(Engine_tag<Exact_geodesic_engine<double>>()); return;
  case Geodesic_method::flat_exact: f(Engine_tag<Flat_exact_propagation<double>>()); return;
  case Geodesic_method::fast_marching: f(Engine_tag<Fast_marching_propagation<double>>()); return;
  case Geodesic_method::dijkstra: f(Engine_tag<Dijkstra_edge_propagation<double>>()); return;
  }
}

// The radius of the neighbourhood that holds every vertex a method reports within `max_distance`. The exact
// methods' distances (merged: upper bounds of them) and Dijkstra's (lengths of edge paths) are lengths of surface
// paths, which stay in the Euclidean ball of that radius. Fast marching and flat-exact values are estimates that
// may fall below the length of any path and whose updates reach across several faces (fast marching unfolds
// obtuse corners): their neighbourhood is twice as wide (the tests compare with runs on the whole mesh).
inline double neighbourhood_radius(Geodesic_method method, double max_distance)
{
  const double slack = 1 + 1e-9; // rounding of the distances and of the point-triangle test
  if(method == Geodesic_method::fast_marching || method == Geodesic_method::flat_exact) return 2 * max_distance * slack;
  return max_distance * slack;
}

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_GEODESIC_MATRIX_ENGINES_H
