// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Small types shared by the geodesic distance classes: memory modes, statistics, and the concept of a
// path visitor.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_GEODESIC_TYPES_H
#define CGAL_POLYHEDRAL_GEODESICS_3_GEODESIC_TYPES_H

#include <cstddef>
#include <limits>

namespace CGAL {
namespace Polyhedral_geodesics_3 {

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  What a geodesic distance object keeps after `compute()`.
*/
enum class Geodesic_memory_mode
{
  /// Only the vertex distances (and nearest sources) survive. The windows of an edge are released once the
  /// front has passed it (covered end to end, all values below the front), the rest at the end.
  /// Point queries and shortest paths throw `std::logic_error`.
  distances_only,
  /// The whole distance field (every window on every edge) is kept: distances at any surface point,
  /// nearest sources at any point, and shortest paths.
  full_field
};

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  Counters of one propagation, for benchmarks and for tuning.
*/
struct Geodesic_statistics
{
  std::size_t windows_created = 0;     ///< windows (intervals) inserted into the envelope of an edge
  std::size_t windows_propagated = 0;  ///< windows taken from the queue and propagated across a face
  std::size_t windows_pruned = 0;      ///< candidate windows discarded because known vertex distances beat them
  std::size_t windows_merged = 0;      ///< joins of two neighbouring windows with the same distance function
  std::size_t peak_live_windows = 0;   ///< largest number of windows stored at the same time
  std::size_t stored_windows = 0;      ///< windows stored when the propagation ended
  std::size_t peak_memory_bytes = 0;   ///< bytes of window storage and queue at their peak (an estimate)
  std::size_t vertex_updates = 0;      ///< vertex distances lowered (flat-exact, fast marching, Dijkstra)
  std::size_t updates_rejected_by_dag = 0; ///< lowerings refused because they would close a dependence cycle
  std::size_t stranded_expansions = 0; ///< rounds of the safety net that expands the reached neighbours of a vertex left unreached (merging only, in practice)
  bool stopped_early = false;          ///< the propagation stopped at the distance limit or at the stop targets
};

#ifdef DOXYGEN_RUNNING
/*!
  \ingroup PkgPolyhedralGeodesics3Concepts
  \cgalConcept

  The interface shared by every geodesic distance class of the package, exact or approximate. A model is
  constructed on a triangle mesh (`Model(tm, mode)` or `Model(tm, vertex_point_map, mode)`), receives
  sources, and answers queries; the propagation runs on the first query (or on `compute()`) and again only
  after the sources or the options change.

  \cgalHasModel `CGAL::Polyhedral_geodesics_3::Exact_geodesic_distances_3`
  \cgalHasModel `CGAL::Polyhedral_geodesics_3::Merged_window_geodesic_distances_3`
  \cgalHasModel `CGAL::Polyhedral_geodesics_3::Flat_exact_geodesic_distances_3`
  \cgalHasModel `CGAL::Polyhedral_geodesics_3::Fast_marching_geodesic_distances_3`
  \cgalHasModel `CGAL::Polyhedral_geodesics_3::Dijkstra_geodesic_distances_3`
*/
class GeodesicDistances3
{
public:
  /// a surface point: a face and barycentric coordinates, as `Polygon_mesh_processing::Face_location`
  typedef unspecified_type Face_location;
  /// returned by `nearest_source()` for unreachable points
  static constexpr std::size_t no_source = std::size_t(-1);

  /// adds a source at a vertex or at a surface point; returns its index (0, 1, ...)
  std::size_t add_source(vertex_descriptor v);
  std::size_t add_source(const Face_location& location);
  /// removes source `i`, keeping the others (later sources move down one index); the results are those of a
  /// new object given the remaining sources in the same order
  void remove_source(std::size_t i);
  void clear_sources();
  /// stops at geodesic distance `limit`; farther points report `+infinity`
  void set_distance_limit(FT limit);
  /// stops once the given vertices are final; other vertices report their distance or `+infinity`
  template <class VertexRange> void set_stop_targets(const VertexRange& targets);
  /// runs the propagation; `progress` is a callable `bool(const char* stage, double fraction)`
  template <class Progress> void compute(Progress progress);
  /// distances (`+infinity` where unreachable) and nearest sources
  FT distance(vertex_descriptor v);
  FT distance(const Face_location& location);
  std::pair<FT, std::size_t> nearest_source(vertex_descriptor v);
  template <class VertexDistanceMap> void distances(VertexDistanceMap distance_map);
  /// the path from `target` to its nearest source, as points or as a `GeodesicPathVisitor` sequence
  template <class OutputIterator> OutputIterator shortest_path_points(vertex_descriptor target, OutputIterator out);
  template <class Visitor> void shortest_path_sequence(vertex_descriptor target, Visitor& visitor);
  /// makes every reported path locally shortest first (straight in every unfolding, through saddle and border
  /// vertices only), keeping its ends; off by default; the distances do not change
  void set_path_shortening(bool on);
  bool path_shortening() const;
  /// counters of the last propagation
  const Geodesic_statistics& statistics() const;
};
#endif

#ifdef DOXYGEN_RUNNING
/*!
  \ingroup PkgPolyhedralGeodesics3Concepts
  \cgalConcept

  Receives the points of a shortest path, from the query point to its nearest source, as mesh
  locations. Every path is a sequence of calls: first the query point, then every edge crossing and
  every vertex passed through, last the source.

  \cgalHasModel any class with these three call operators, e.g. a lambda-based overload set.
*/
class GeodesicPathVisitor
{
public:
  /// the path passes through (or starts or ends at) vertex `v`
  void operator()(vertex_descriptor v);
  /// the path crosses the edge of `h` at the point `(1-t) * source(h) + t * target(h)`, `0 < t < 1`
  void operator()(halfedge_descriptor h, FT t);
  /// the path starts or ends at a point strictly inside face `f`, with barycentric coordinates `b`
  /// in the order of `Polygon_mesh_processing::Face_location`
  void operator()(face_descriptor f, const std::array<FT, 3>& b);
};
#endif

} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_GEODESIC_TYPES_H
