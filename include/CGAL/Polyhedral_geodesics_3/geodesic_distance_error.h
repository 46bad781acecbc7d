// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The error of approximate geodesic distances against exact ones: the mean relative error of the thesis
// (eq. 4.4.1) and the worst cases, over the vertices of a mesh.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_GEODESIC_DISTANCE_ERROR_H
#define CGAL_POLYHEDRAL_GEODESICS_3_GEODESIC_DISTANCE_ERROR_H

#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace CGAL {
namespace Polyhedral_geodesics_3 {

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief The error of approximate geodesic distances, as returned by `geodesic_distance_error()`.

  Relative errors are fractions (multiply by 100 for percents).
*/
struct Geodesic_distance_error
{
  /// the thesis's \f$ E = \frac{1}{N} \sum_i \left| \frac{\bar d_i - d_i}{d_i} \right| \f$ (eq. 4.4.1) over the
  /// `compared` vertices; 0 when `compared == 0`
  double mean_relative = 0;
  /// the largest \f$ |\bar d_i - d_i| / d_i \f$ over the `compared` vertices; 0 when `compared == 0`
  double max_relative = 0;
  /// the largest \f$ |\bar d_i - d_i| \f$ over the vertices where both distances are finite (sources included)
  double max_absolute = 0;
  /// vertices where both distances are finite and the exact distance is positive (the \f$ N \f$ of the mean)
  std::size_t compared = 0;
  /// vertices with exact distance 0 (the sources, and vertices at the same place), left out of the relative errors
  std::size_t skipped_sources = 0;
  /// vertices whose distance is finite in one map and infinite (or NaN) in the other; left out of every other field
  std::size_t unreachable_mismatches = 0;
};

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief Compares approximate geodesic distances with exact ones at every vertex of `tm`: the mean relative
  error of the thesis (eq. 4.4.1), the largest relative and absolute errors, and the vertices that one map
  reaches and the other does not.

  For every vertex `v`, with \f$ \bar d \f$ = `get(approx, v)` and \f$ d \f$ = `get(exact, v)` (converted with
  `CGAL::to_double()`; infinity and NaN both mean "unreachable"):
  - both infinite: the vertex is ignored (unreachable in both);
  - exactly one infinite: it counts in `unreachable_mismatches` and nowhere else;
  - both finite and \f$ d = 0 \f$: it counts in `skipped_sources` (its relative error is undefined) and its absolute
    error in `max_absolute`;
  - both finite and \f$ d > 0 \f$: it counts in `compared`, and \f$ |\bar d - d| / d \f$ in `mean_relative` and
    `max_relative`, \f$ |\bar d - d| \f$ in `max_absolute`.

  Typical use: `exact` from `Exact_geodesic_distances_3::distances()`, `approx` from another class of the package
  (or from `CGAL::Heat_method_3`) with the same sources.

  \tparam TriangleMesh a model of `VertexListGraph`
  \tparam ApproxDistanceMap, ExactDistanceMap models of `ReadablePropertyMap` with the vertex descriptor of
          `TriangleMesh` as key type and a number type accepted by `CGAL::to_double()` as value type

  \throws std::invalid_argument if an exact distance is negative.
*/
template <class TriangleMesh, class ApproxDistanceMap, class ExactDistanceMap>
Geodesic_distance_error geodesic_distance_error(const TriangleMesh& tm, ApproxDistanceMap approx, ExactDistanceMap exact)
{
  Geodesic_distance_error e;
  long double sum = 0; // the N terms of the mean, each at most a few units in practice
  for(auto v : vertices(tm)) {
    const double a = CGAL::to_double(get(approx, v));
    const double d = CGAL::to_double(get(exact, v));
    const bool fa = std::isfinite(a), fd = std::isfinite(d);
    if(fd && d < 0)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3::geodesic_distance_error: an exact distance is negative");
    if(!fa && !fd)
      continue;
    if(fa != fd) {
      ++e.unreachable_mismatches;
      continue;
    }
    const double absolute = std::abs(a - d);
    e.max_absolute = (std::max)(e.max_absolute, absolute);
    if(d == 0) {
      ++e.skipped_sources;
      continue;
    }
    const double relative = absolute / d;
    ++e.compared;
    sum += relative;
    e.max_relative = (std::max)(e.max_relative, relative);
  }
  if(e.compared > 0)
    e.mean_relative = double(sum / static_cast<long double>(e.compared));
  return e;
}

} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_GEODESIC_DISTANCE_ERROR_H
