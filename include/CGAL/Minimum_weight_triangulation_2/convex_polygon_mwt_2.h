// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// convex_polygon_mwt_2(): the O(k^3) dynamic program (Klincsek) for the minimum weight triangulation of a
// convex polygon. Its decisions are exact for the double coordinates: double sums with a forward error bound,
// and an exact comparison of the sums of lengths where the bound does not separate the best candidate
// (internal/Exact_length_sum_2.h).

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_CONVEX_POLYGON_MWT_2_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_CONVEX_POLYGON_MWT_2_H

#include <CGAL/Minimum_weight_triangulation_2/Mwt_result.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Coordinate_range_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Polygon_dp_2.h>
#include <CGAL/MDCS/progress.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {

/// The largest polygon `convex_polygon_mwt_2()` accepts: its tables take 12 k^2 bytes (3 GiB at this size) and
/// O(k^3) time (hours at this size; the progress callback reports and can cancel).
inline std::size_t convex_polygon_mwt_max_vertices() { return 16384; }

/*!
  \brief Minimum weight triangulation of a strictly convex polygon given by its vertices in
  counter-clockwise order, by dynamic programming in O(k^3) time and O(k^2) memory.

  Writes the k-2 triangles (index triples into the input, counter-clockwise) to `out` and returns the
  weight (sum of all edge lengths, boundary included). Every choice of the program is exact for the double
  coordinates of the vertices (a minimum of exact sums of lengths, ties broken by the smallest apex index):
  sums are compared in double where a forward error bound decides, exactly otherwise; `exact_decisions`, if
  given, receives the number of exact comparisons made.
  `progress` (a callable `bool(const char* stage, double fraction)`, see CGAL/MDCS/progress.h) sees the stage
  "convex dynamic program" about a hundred times, with the fraction of the work done.
  \throws std::invalid_argument when fewer than 3 or more than `convex_polygon_mwt_max_vertices()` vertices are
  given, a coordinate is outside `Mwt_coordinate_range`, or the polygon is not strictly convex and
  counter-clockwise (checked with the kernel's exact orientation).
  \throws CGAL::MDCS::Operation_cancelled when `progress` returns false.
*/
template <class PointRange, class OutputIterator, class Progress = CGAL::MDCS::No_progress>
double convex_polygon_mwt_2(const PointRange& polygon, OutputIterator out, Edge_metric metric = Edge_metric::L2,
                            std::size_t* exact_decisions = nullptr, Progress progress = Progress())
{
  typedef typename std::iterator_traits<decltype(std::begin(polygon))>::value_type Point_2;
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel K;
  const std::size_t size = std::size_t(std::distance(std::begin(polygon), std::end(polygon)));
  if(size < 3) throw std::invalid_argument("convex_polygon_mwt_2: needs at least 3 vertices");
  if(size > convex_polygon_mwt_max_vertices())
    throw std::invalid_argument("convex_polygon_mwt_2: " + std::to_string(size) + " vertices; at most " +
                                std::to_string(convex_polygon_mwt_max_vertices()) + " (the tables take 12 k^2 bytes)");
  const std::vector<Point_2> p(std::begin(polygon), std::end(polygon));
  const int k = int(p.size());
  {
    // the coordinates as the program reads them: squared differences must stay finite and normal
    struct Doubles
    {
      const std::vector<Point_2>& p;
      std::size_t size() const { return p.size(); }
      double x(int i) const { return CGAL::to_double(p[std::size_t(i)].x()); }
      double y(int i) const { return CGAL::to_double(p[std::size_t(i)].y()); }
    } doubles{p};
    internal::check_coordinate_range(doubles, "convex_polygon_mwt_2");
  }
  typename K::Orientation_2 orient = K().orientation_2_object();
  for(int i = 0; i < k; ++i) {
    if(orient(p[i], p[(i + 1) % k], p[(i + 2) % k]) != CGAL::LEFT_TURN)
      throw std::invalid_argument("convex_polygon_mwt_2: the polygon is not strictly convex and counter-clockwise");
    if(i >= 1 && i + 1 < k && orient(p[0], p[i], p[i + 1]) != CGAL::LEFT_TURN)
      throw std::invalid_argument("convex_polygon_mwt_2: the polygon is not simple (it winds more than once)");
  }
  auto len = [&](int a, int b) {
    const double dx = CGAL::to_double(p[b].x()) - CGAL::to_double(p[a].x());
    const double dy = CGAL::to_double(p[b].y()) - CGAL::to_double(p[a].y());
    if(!std::isfinite(dx) || !std::isfinite(dy)) throw std::invalid_argument("convex_polygon_mwt_2: non-finite coordinate");
    switch(metric) {
      case Edge_metric::L1: return std::abs(dx) + std::abs(dy);
      case Edge_metric::Linf: return std::max(std::abs(dx), std::abs(dy));
      default: return std::sqrt(dx * dx + dy * dy);
    }
  };
  std::vector<double> x(std::size_t(k), 0.0), y(std::size_t(k), 0.0);
  for(int i = 0; i < k; ++i) { x[i] = CGAL::to_double(p[i].x()); y[i] = CGAL::to_double(p[i].y()); }
  // work of gap g: (k - g) sub-polygons of g - 1 apexes each; reported by the share of sum over g of (k - g)(g - 1)
  const double total_work = std::max(1.0, double(k) * double(k - 1) * double(k - 2) / 6.0);
  double work = 0;
  CGAL::MDCS::internal::Progress_reporter<Progress> report(progress, "convex dynamic program", 1000);
  auto on_gap = [&](int gap) {
    work += double(k - gap) * double(gap - 1);
    report(std::size_t(1000.0 * std::min(1.0, work / total_work)));
  };
  auto every_chord = [](int, int) { return true; };
  auto every_apex = [](int, int, int) { return true; };
  const double diagonals =
    internal::polygon_min_weight_dp(k, x, y, len, every_chord, every_apex, on_gap, metric, out, exact_decisions);
  report.finish();
  double perimeter = 0;
  for(int i = 0; i < k; ++i) perimeter += len(i, (i + 1) % k);
  return perimeter + diagonals;
}

} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_CONVEX_POLYGON_MWT_2_H
