// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Approximate geodesic distances by interval merging (thesis, chapter 4.2): the exact window propagation
// where a window about to propagate absorbs the neighbouring windows whose distance functions it reproduces
// within a tolerance. The work is in internal/exact_window_propagation.h (absorb_similar_neighbours).

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_MERGED_WINDOW_GEODESIC_DISTANCES_3_H
#define CGAL_POLYHEDRAL_GEODESICS_3_MERGED_WINDOW_GEODESIC_DISTANCES_3_H

#include <CGAL/Polyhedral_geodesics_3/Geodesic_types.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_distances_facade.h>
#include <CGAL/Polyhedral_geodesics_3/internal/exact_window_propagation.h>

#include <CGAL/boost/graph/properties.h>

#include <stdexcept>

namespace CGAL {
namespace Polyhedral_geodesics_3 {

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief Approximate geodesic distances, nearest sources and shortest paths by window propagation with
  interval merging: a trade-off between `Exact_geodesic_distances_3` (tolerance 0, the same result bit
  for bit) and fewer, wider windows.

  Before a window propagates, each contiguous neighbour on its edge that has not propagated yet and looks
  into the same face is absorbed when the window's distance function, extended over the neighbour's
  interval, lies between the neighbour's own function and that function plus `merge_tolerance` (checked at
  five points of the interval). Consequences, which the tests assert:
  - every distance is at least the exact one (merges only raise values, and every value remains the
    length bound of a real path), so the error is one-sided;
  - the thesis's dependence DAG stays acyclic by construction: only windows without children are merged,
    and a window's descendants cannot undercut it, so no window is ever replaced by its own descendants and
    path tracing always descends to a source;
  - the error of a vertex grows with the number of merges on the way from its source (each adds at most
    `merge_tolerance`); the measured trade-off is in the package manual.

  The API is that of `Exact_geodesic_distances_3` (it models the same concept, see there), plus the
  tolerance.

  \tparam TriangleMesh, FT_, VertexPointMap as in `Exact_geodesic_distances_3`.
*/
template <class TriangleMesh, class FT_ = double,
          class VertexPointMap = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>
class Merged_window_geodesic_distances_3
  : public internal::Geodesic_distances_facade<TriangleMesh, FT_, VertexPointMap,
                                               internal::Exact_window_propagation<FT_>>
{
  typedef internal::Geodesic_distances_facade<TriangleMesh, FT_, VertexPointMap,
                                              internal::Exact_window_propagation<FT_>> Base;

public:
  /// Precomputes the compact mesh; `merge_tolerance` is absolute (mesh units), >= 0.
  /// Throws `std::invalid_argument` on non-triangle faces or a negative or NaN tolerance.
  explicit Merged_window_geodesic_distances_3(const TriangleMesh& tm, FT_ merge_tolerance = FT_(0),
                                              Geodesic_memory_mode mode = Geodesic_memory_mode::full_field)
    : Base(tm, get(CGAL::vertex_point, tm), mode)
  {
    set_merge_tolerance(merge_tolerance);
  }

  Merged_window_geodesic_distances_3(const TriangleMesh& tm, VertexPointMap vpm, FT_ merge_tolerance,
                                     Geodesic_memory_mode mode = Geodesic_memory_mode::full_field)
    : Base(tm, vpm, mode)
  {
    set_merge_tolerance(merge_tolerance);
  }

  /// Sets the tolerance (absolute, >= 0); the next query recomputes.
  void set_merge_tolerance(FT_ tolerance)
  {
    if(!(tolerance >= FT_(0)))
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3::Merged_window_geodesic_distances_3: "
                                  "the merge tolerance must be >= 0");
    tolerance_ = tolerance;
    this->engine().set_merge_tolerance(tolerance);
    this->invalidate();
  }

  FT_ merge_tolerance() const { return tolerance_; }

private:
  FT_ tolerance_ = FT_(0);
};

} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_MERGED_WINDOW_GEODESIC_DISTANCES_3_H
