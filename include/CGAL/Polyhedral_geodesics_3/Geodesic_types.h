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
  bool stopped_early = false;          ///< the propagation stopped at the distance limit or at the stop targets
};

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
