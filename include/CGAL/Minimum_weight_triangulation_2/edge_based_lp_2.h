// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The edge-based LP of the MWT (thesis ch. 3.2.1), for comparison with the triangle LP: a variable per
// segment without an input point in its interior, x_i + x_j <= 1 for every properly crossing pair,
// x_i + sum_{j crosses i} x_j >= 1 for every segment, 0 <= x <= 1, minimise sum |e_i| x_i.
// O(n^4) crossing tests: small inputs only.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_EDGE_BASED_LP_2_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_EDGE_BASED_LP_2_H

#include <CGAL/Minimum_weight_triangulation_2/Linear_program.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Candidate_edges_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Coordinate_range_2.h>
#include <CGAL/Kernel_traits.h>

#include <cmath>
#include <iterator>
#include <utility>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {

/// The edge-based LP of a point set and the segment of each of its columns.
struct Edge_based_lp
{
  Sparse_linear_program lp;
  std::vector<std::pair<int, int>> edges;   ///< per column
};

/*!
  \brief Builds the edge-based LP (costs are Euclidean lengths, unscaled).
  \throws std::invalid_argument on the same bad input as `minimum_weight_triangulation_2()` (coordinate range included).
*/
template <class PointRange>
Edge_based_lp make_edge_based_lp_2(const PointRange& points)
{
  typedef typename std::iterator_traits<decltype(std::begin(points))>::value_type Point_2;
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel K;
  const std::vector<Point_2> p(std::begin(points), std::end(points));
  internal::Indexed_points_2<K> pts(p);
  internal::checked_hull_boundary(pts);
  internal::check_coordinate_range(pts, "make_edge_based_lp_2");
  internal::Point_grid_2 grid(pts);
  CGAL::MDCS::No_progress none;
  Edge_based_lp out;
  out.edges = internal::all_valid_edges(pts, grid, none);
  const std::size_t m = out.edges.size();
  std::vector<std::vector<int>> crossing(m);
  for(std::size_t i = 0; i < m; ++i)
    for(std::size_t j = i + 1; j < m; ++j) {
      const int a = out.edges[i].first, b = out.edges[i].second, c = out.edges[j].first, d = out.edges[j].second;
      if(a == c || a == d || b == c || b == d) continue;
      if(pts.orientation(a, b, c) * pts.orientation(a, b, d) < 0 && pts.orientation(c, d, a) * pts.orientation(c, d, b) < 0) {
        crossing[i].push_back(int(j));
        crossing[j].push_back(int(i));
      }
    }
  // rows: one cover row per edge (>= 1), then one row per crossing pair (<= 1)
  std::vector<std::vector<std::pair<int, double>>> columns(m);
  for(std::size_t i = 0; i < m; ++i) {
    const int r = out.lp.add_row(1, Sparse_linear_program::infinity());
    columns[i].emplace_back(r, 1.0);
    for(int j : crossing[i]) columns[j].emplace_back(r, 1.0);
  }
  for(std::size_t i = 0; i < m; ++i)
    for(int j : crossing[i])
      if(std::size_t(j) > i) {
        const int r = out.lp.add_row(-Sparse_linear_program::infinity(), 1);
        columns[i].emplace_back(r, 1.0);
        columns[j].emplace_back(r, 1.0);
      }
  for(std::size_t i = 0; i < m; ++i) {
    std::vector<int> rows;
    std::vector<double> vals;
    for(const auto& rv : columns[i]) { rows.push_back(rv.first); vals.push_back(rv.second); }
    const int a = out.edges[i].first, b = out.edges[i].second;
    const double len = std::hypot(pts.x(b) - pts.x(a), pts.y(b) - pts.y(a));
    out.lp.add_column(len, 0, 1, rows.data(), vals.data(), int(rows.size()));
  }
  return out;
}

} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_EDGE_BASED_LP_2_H
