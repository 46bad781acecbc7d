// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Klincsek's O(k^3) dynamic program over the sub-polygons i, i+1, ..., j of a polygon, shared by
// convex_polygon_mwt_2() (every chord usable) and simple_polygon_mwt_2() (only edges and diagonals inside the
// polygon). Its decisions are exact for the double coordinates: double sums with a forward error bound, and an
// exact comparison of the sums of lengths where the bound does not separate the best apex (smallest apex on exact
// ties; Exact_length_sum_2.h).

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_POLYGON_DP_2_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_POLYGON_DP_2_H

#include <CGAL/Minimum_weight_triangulation_2/Mwt_result.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Exact_length_sum_2.h>

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {
namespace internal {

// Polygon vertices 0..k-1 at (x[i], y[i]); len(a, b) the metric length of a chord; chord_usable(i, j) (i < j)
// whether the sub-polygon i..j may be triangulated (its chord is an edge or a diagonal); apex_usable(i, c, j)
// whether triangle (i, c, j) may be used (its sides already checked as chords); on_gap(gap) is called before the
// sub-polygons of each gap (progress). Writes the triangles (i, c, j) of the whole polygon to `out` and returns the
// total length of the diagonals, +infinity when the polygon has no triangulation (nothing written then).
template <class Length, class ChordUsable, class ApexUsable, class OnGap, class OutputIterator>
double polygon_min_weight_dp(int k, const std::vector<double>& x, const std::vector<double>& y, Length len,
                             ChordUsable chord_usable, ApexUsable apex_usable, OnGap on_gap, Edge_metric metric,
                             OutputIterator& out, std::size_t* exact_decisions)
{
  const double inf = std::numeric_limits<double>::infinity();
  const std::size_t size = std::size_t(k);
  // D[i][j]: minimum total length of the diagonals triangulating the sub-polygon i..j, +infinity without one
  std::vector<double> D(size * size, inf);
  std::vector<int> best(size * size, -1);
  for(int i = 0; i + 1 < k; ++i)
    D[i * k + i + 1] = 0;
  const Length_sum_error_bound err(2 * size);
  std::size_t exact = 0;
  // the diagonals of the sub-polygon i..j with apex c (best[] final inside), appended to `o`
  auto segments = [&](int i0, int j0, int c0, std::vector<Length_segment>& o) {
    std::vector<std::array<int, 3>> stack{{i0, j0, c0}};
    while(!stack.empty()) {
      const auto t = stack.back();
      stack.pop_back();
      const int i = t[0], j = t[1], c = t[2];
      if(c > i + 1) { o.push_back({{x[i], y[i], x[c], y[c]}}); stack.push_back({i, c, best[i * k + c]}); }
      if(j > c + 1) { o.push_back({{x[c], y[c], x[j], y[j]}}); stack.push_back({c, j, best[c * k + j]}); }
    }
  };
  for(int gap = 2; gap < k; ++gap) {
    on_gap(gap);
    for(int i = 0; i + gap < k; ++i) {
      const int j = i + gap;
      if(!chord_usable(i, j))
        continue;
      auto candidate = [&](int c) { return D[i * k + c] < inf && D[c * k + j] < inf && apex_usable(i, c, j); };
      auto value = [&](int c) {
        return D[i * k + c] + D[c * k + j] + (c > i + 1 ? len(i, c) : 0.0) + (j > c + 1 ? len(c, j) : 0.0);
      };
      double m = inf, second = inf;
      for(int c = i + 1; c < j; ++c) {
        if(!candidate(c))
          continue;
        const double v = value(c);
        if(v < m) { second = m; m = v; best[i * k + j] = c; }
        else if(v < second) second = v;
      }
      if(m < inf && second < inf && !err.certainly_less(m, second)) {
        // ambiguous in double: the exact minimum, the smallest apex on exact ties
        std::vector<Length_segment> cs, s;
        int cc = -1;
        double cv = m;
        for(int c = i + 1; c < j; ++c) {
          if(!candidate(c))
            continue;
          const double v = value(c);
          if(err.certainly_less(m, v))
            continue;
          s.clear();
          segments(i, j, c, s);
          if(cc < 0 || compare_length_sums(s, cs, metric) < 0) { cc = c; cv = v; cs.swap(s); }
        }
        best[i * k + j] = cc;
        m = cv;
        ++exact;
      }
      D[i * k + j] = m;
    }
  }
  if(exact_decisions)
    *exact_decisions = exact;
  if(!(D[k - 1] < inf))
    return inf;
  std::vector<std::array<int, 2>> stack{{0, k - 1}};
  while(!stack.empty()) {
    const auto ij = stack.back();
    stack.pop_back();
    if(ij[1] - ij[0] < 2)
      continue;
    const int c = best[ij[0] * k + ij[1]];
    *out++ = std::array<int, 3>{ij[0], c, ij[1]};
    stack.push_back({ij[0], c});
    stack.push_back({c, ij[1]});
  }
  return D[k - 1];
}

} // namespace internal
} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_POLYGON_DP_2_H
