// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact geodesic distances and shortest paths on a triangle mesh by interval (window) propagation with
// side lobes: the public class and the one-shot function. The work is in internal/exact_window_propagation.h
// (the full field, limits, stop targets) and internal/vertex_oriented_propagation.h (distances_only runs);
// internal/Exact_geodesic_engine.h picks one per run.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_EXACT_GEODESIC_DISTANCES_3_H
#define CGAL_POLYHEDRAL_GEODESICS_3_EXACT_GEODESIC_DISTANCES_3_H

#include <CGAL/MDCS/concurrency.h>
#include <CGAL/MDCS/progress.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_types.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_distances_facade.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Exact_geodesic_engine.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

#include <array>
#include <cstddef>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief Exact geodesic distances, nearest sources and shortest paths on a triangle mesh.

  The algorithm is the interval propagation of Surazhsky et al. ("Fast exact and approximate geodesics
  on meshes", 2005) in the form of the thesis's chapter 4.1: the distance function on every edge is a
  list of *windows*, each with a pseudo-source in the unfolded plane and a distance offset; propagating
  a window across a face yields the part that sees its pseudo-source plus a left and a right *side
  lobe* rooted at the window's end points, so saddle and boundary vertices need no special case and the
  wavefront has no gaps. Windows on an edge are combined by their lower envelope. Windows that cannot
  beat the distances already known at the vertices of their face are pruned (Xin and Wang's filter).

  In `Geodesic_memory_mode::distances_only`, without a distance limit or stop targets, the distances at the
  vertices come from a faster schedule of the same windows (Qin et al., "Fast and exact discrete geodesic
  computation based on triangle-oriented wavefront propagation", 2016): vertices are settled in order of
  distance and the windows waiting on the edges around a settled vertex cross their faces in batches, with no
  lower envelope and no window queue; each batch is trimmed by the vertices of its face and by itself, and the
  batch's best path to the opposite vertex splits the face between the two other edges. Saddle and boundary
  vertices emit their own windows, and a settled one whose distance drops later is settled again, so the
  result is exact whatever the order. `set_vertex_oriented_propagation(false)` makes such runs use the window
  propagation too (same distances up to rounding, about 1e-15 relative).

  Usage: construct once per mesh, add sources, then query; the propagation runs on the first query
  (or explicitly with `compute()`) and again only after the sources or the options change.

  \tparam TriangleMesh a model of `FaceGraph` whose faces are all triangles (checked: other faces are
          rejected with `std::invalid_argument`). No internal indices are required.
  \tparam FT_ the number type of the computation: `double` (default) or a type with exact or
          high-precision square roots (e.g. `boost::multiprecision::mpfr_float_50`,
          `CGAL::Exact_predicates_exact_constructions_kernel_with_sqrt::FT`). Every combinatorial decision
          is a sign of an expression in `FT`.
  \tparam VertexPointMap a readable property map from vertices to 3D points of any CGAL kernel
          (coordinates are converted with `CGAL::to_double()`, exact for the usual double-based inputs).

  Unreachable points (another connected component than every source, or farther than the distance
  limit) have distance `+infinity` and no nearest source (`std::size_t(-1)`); paths to them are empty.

  \cgalModels `GeodesicDistances3` (the member functions are documented there and in the package manual).
*/
template <class TriangleMesh, class FT_ = double,
          class VertexPointMap = typename internal::Default_vertex_point_map<TriangleMesh>::type>
class Exact_geodesic_distances_3
  : public internal::Geodesic_distances_facade<TriangleMesh, FT_, VertexPointMap,
                                               internal::Exact_geodesic_engine<FT_>>
{
  typedef internal::Geodesic_distances_facade<TriangleMesh, FT_, VertexPointMap,
                                              internal::Exact_geodesic_engine<FT_>> Base;

public:
  /// Precomputes the compact mesh. Throws `std::invalid_argument` on non-triangle faces.
  explicit Exact_geodesic_distances_3(const TriangleMesh& tm,
                                      Geodesic_memory_mode mode = Geodesic_memory_mode::full_field)
    : Base(tm, get(CGAL::vertex_point, tm), mode)
  {}

  Exact_geodesic_distances_3(const TriangleMesh& tm, VertexPointMap vpm,
                             Geodesic_memory_mode mode = Geodesic_memory_mode::full_field)
    : Base(tm, vpm, mode)
  {}

  /// On a prepared surface (see `Geodesic_surface_3`), shared with other objects: nothing is rebuilt.
  explicit Exact_geodesic_distances_3(std::shared_ptr<const typename Base::Surface> surface,
                                      Geodesic_memory_mode mode = Geodesic_memory_mode::full_field)
    : Base(std::move(surface), mode)
  {}

  /// On a prepared surface that outlives the object.
  explicit Exact_geodesic_distances_3(const typename Base::Surface& surface,
                                      Geodesic_memory_mode mode = Geodesic_memory_mode::full_field)
    : Base(surface, mode)
  {}

  /// Whether `distances_only` runs without a distance limit or stop targets use the vertex-oriented
  /// schedule (default `true`, several times faster) or the window propagation of the full field. On a mesh
  /// with a face of zero area (collinear corners or a zero-length edge) the window propagation runs anyway:
  /// the vertex-oriented schedule misses paths along the line of such faces (`used_vertex_oriented_propagation()`
  /// tells which one ran).
  void set_vertex_oriented_propagation(bool enable)
  {
    this->engine().set_vertex_oriented_allowed(enable);
    this->invalidate();
  }

  /// See `set_vertex_oriented_propagation()`.
  bool vertex_oriented_propagation() const { return this->engine_const().vertex_oriented_allowed(); }

  /// Whether `full_field` runs, distance limits and stop targets also use the vertex-oriented schedule (default
  /// `true`; `false`: they use the window propagation). A full field then keeps, per vertex, how it got its
  /// distance (32 bytes per vertex with `double`) instead of the windows of every edge; shortest paths walk back
  /// along those records, and a distance or nearest source at a `Face_location` runs a second propagation from
  /// that point, bounded by the vertex distances (so a point query costs a small propagation, not a lookup).
  /// Same results as the window propagation (1e-12 relative). Not used on meshes where the vertex-oriented
  /// schedule is not (see `set_vertex_oriented_propagation()`), nor for full-field runs on meshes with a needle
  /// face (a face lower than 1e-7 times one of its edges), where walking a path across the needle loses digits.
  void set_vertex_oriented_full_field(bool enable)
  {
    this->engine().set_vertex_oriented_full_field(enable);
    this->invalidate();
  }

  /// See `set_vertex_oriented_full_field()`.
  bool vertex_oriented_full_field() const { return this->engine_const().vertex_oriented_full_field(); }

  /*!
    \brief Runs the vertex-oriented schedule of `distances_only` runs in parallel, on `threads` threads (0: every
    hardware thread), with `ConcurrencyTag` `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag` (when TBB is
    linked in); `CGAL::Sequential_tag` (the default) runs the sequential schedule.

    The parallel schedule processes the windows in rounds: vertices are settled until a few hundred edge lists are
    ready, the lists cross their faces on several threads, each reading the state of the start of the round and
    writing into its own buffer, and the buffers are applied in a fixed order. The distances are therefore
    identical, bit for bit, for every thread count (1 thread included), and equal to the sequential schedule's up to
    rounding (about 1e-15 relative). Runs with stop targets or Parent records (`full_field` with
    `set_vertex_oriented_full_field(true)`) stay sequential; `used_parallel_propagation()` tells.
  */
  template <class ConcurrencyTag>
  void set_concurrency(ConcurrencyTag, std::size_t threads = 0)
  {
    this->engine().set_parallel(CGAL::MDCS::Is_parallel_tag<ConcurrencyTag>::value,
                                CGAL::MDCS::effective_threads<ConcurrencyTag>(threads));
    this->invalidate();
  }

  /// The number of threads of the parallel schedule (1 with `CGAL::Sequential_tag`).
  std::size_t threads() const { return this->engine_const().threads(); }

  /// Whether the last propagation used the parallel schedule (see `set_concurrency()`).
  bool used_parallel_propagation() const { return this->engine_const().used_parallel_schedule(); }

  /// \cond SKIP_IN_MANUAL
  // The parallel schedule's rounds (lists per round, default 256; tests and benchmarks) and its measurements.
  void set_parallel_lists_per_round(std::size_t n)
  {
    this->engine().set_parallel_lists_per_round(n);
    this->invalidate();
  }
  void set_parallel_profile(bool profile) { this->engine().set_parallel_profile(profile); }
  const internal::Vertex_oriented_parallel_profile& parallel_profile() const
  {
    return this->engine_const().parallel_profile();
  }
  /// \endcond

  /// Whether the last propagation used the vertex-oriented schedule.
  bool used_vertex_oriented_propagation() const { return this->engine_const().uses_vertex_oriented_engine(); }

  /// Whether distances and paths at `Face_location`s now come from a window field built after the run. On the
  /// vertex-oriented records each such query runs a small propagation of its own (about 1 ms on 40k vertices);
  /// after many of them, once their cost exceeds twice the run's (counted in windows, so independent of the
  /// machine), the window propagation runs once and answers the later ones in microseconds. Vertex distances,
  /// nearest sources and paths to vertices keep coming from the records. Values agree to 1e-12 relative.
  bool point_queries_from_window_field() const { return this->engine_const().point_queries_from_windows(); }
};

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief One-shot exact geodesic distances from the vertices in `sources` to every vertex of `tm`,
  written into `distance_map` (`+infinity` where unreachable). Runs in `distances_only` mode.

  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map} the 3D point of each vertex, default `get(CGAL::vertex_point, tm)` \cgalParamNEnd
  \cgalNamedParamsEnd
*/
template <class TriangleMesh, class VertexRange, class VertexDistanceMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters,
          std::enable_if_t<!std::is_convertible<VertexRange,
                             typename boost::graph_traits<TriangleMesh>::vertex_descriptor>::value, int> = 0>
void exact_geodesic_distances_3(const TriangleMesh& tm, const VertexRange& sources, VertexDistanceMap distance_map,
                                const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  VPM vpm = choose_parameter(get_parameter(np, internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  Exact_geodesic_distances_3<TriangleMesh, double, VPM> geodesics(tm, vpm, Geodesic_memory_mode::distances_only);
  for(auto v : sources)
    geodesics.add_source(v);
  geodesics.distances(distance_map);
}

/// The same for one source vertex.
template <class TriangleMesh, class VertexDistanceMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
void exact_geodesic_distances_3(const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::vertex_descriptor source,
                                VertexDistanceMap distance_map, const NamedParameters& np = CGAL::parameters::default_values())
{
  const std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 1> sources = {source};
  exact_geodesic_distances_3(tm, sources, distance_map, np);
}

} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_EXACT_GEODESIC_DISTANCES_3_H
