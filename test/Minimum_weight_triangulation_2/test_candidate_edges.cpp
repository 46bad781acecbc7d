// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The diamond test's candidate edges against a brute-force diamond test, on the pairs where the grid search
// is hardest: points very close to the boundary of the point set, whose sectors along the boundary are
// searched far (beyond ring 32 of the grid, where the ring's sides are scanned in blocks).

#if defined(MDCS_HAS_CLP) && defined(MDCS_HAS_GLPK)

#include "mwt_test_helpers.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <utility>
#include <vector>

using namespace mwt_test;

namespace {

// Brute force with the library's conservative in-half test: pq survives unless a point lies in the open
// segment or both halves hold a point.
template <class P>
bool brute_force_survives(const P& pts, int p, int q)
{
  bool left = false, right = false;
  for(int r = 0; r < int(pts.size()); ++r) {
    if(r == p || r == q) continue;
    const int o = pts.orientation(p, q, r);
    if(o == 0) {
      if(pts.strictly_between(p, q, r)) return false;
      continue;
    }
    if(MWT::internal::in_diamond_half(pts, p, q, r)) (o > 0 ? left : right) = true;
    if(left && right) return false;
  }
  return true;
}

} // namespace

TEST_CASE("diamond test: candidates near the boundary equal a brute-force diamond test", "[mwt][diamond][oracle]")
{
  // 12,000 uniform points (a grid of about 77 x 77 cells) plus points squeezed against the bottom side
  std::vector<Point> p = uniform_points(12000, 99);
  for(int i = 0; i < 40; ++i) p.emplace_back(0.0125 + 0.025 * i, 1e-7 * (1 + (i * 7) % 13));
  MWT::Minimum_weight_triangulation_lp_2<K> m(p);
  m.compute_candidate_edges();
  std::set<std::pair<int, int>> cand(m.candidate_edges().begin(), m.candidate_edges().end());
  MWT::internal::Indexed_points_2<K> pts(p);

  // the 60 lowest points (the squeezed ones first) against the 400 lowest
  std::vector<int> order(p.size());
  for(std::size_t i = 0; i < p.size(); ++i) order[i] = int(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return p[a].y() < p[b].y(); });
  std::size_t checked = 0, kept = 0, long_kept = 0;
  for(int a = 0; a < 60; ++a)
    for(int b = 0; b < 400; ++b) {
      const int u = std::min(order[a], order[b]), v = std::max(order[a], order[b]);
      if(u == v) continue;
      const bool brute = brute_force_survives(pts, u, v);
      INFO("pair " << u << " " << v);
      CHECK(brute == (cand.count({u, v}) == 1));
      ++checked;
      kept += brute;
      long_kept += brute && std::abs(CGAL::to_double(p[u].x() - p[v].x())) > 0.1;
    }
  CHECK(checked > 20000);
  CHECK(kept > 100);
  CHECK(long_kept > 0);   // edges along the boundary, longer than 30 grid cells: the far search found them
}

#endif
