// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// An independent exact oracle for the minimum weight triangulation of up to about 14 points: a depth-first
// search over all triangulations that grows the triangulated region one triangle at a time, with branch and
// bound on the partial weight. No LP, no diamond test, no skeleton, no dynamic program.
//
// Search: the state is a set of triangles (pairwise interior-disjoint, each empty) and their edges. An edge
// side that must be covered but is not yet ("open": the inner side of a hull edge, the other side of an
// interior edge) is picked; every triangulation that extends the state has exactly one triangle on it, so
// branching over the third vertex c enumerates each triangulation once. A triangle abc is admissible when it
// is counter-clockwise, empty (no input point inside or on its boundary but a, b, c), its new edges contain no
// input point and cross no chosen edge properly, and none of its three edge sides is already covered. When
// no open side is left, the triangles cover the hull (its boundary is the hull boundary) and, being empty,
// use every point: a triangulation. Every predicate is CGAL's exact orientation (EPICK).
//
// Branch and bound keeps every triangulation whose weight is within a relative 1e-12 of the best found, so
// the oracle also reports whether the optimum is unique (up to that tolerance) and returns its edge set.

#ifndef MDCS_TEST_MWT_EXHAUSTIVE_ORACLE_H
#define MDCS_TEST_MWT_EXHAUSTIVE_ORACLE_H

#include "mwt_test_helpers.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

namespace mwt_test {

struct Exhaustive_mwt
{
  double weight = HUGE_VAL;
  std::set<std::pair<int, int>> edges;   ///< the edges of one optimal triangulation
  bool unique = true;                    ///< no other triangulation within 1e-12 (relative) of the optimum
  long long triangulations_visited = 0;  ///< complete triangulations reached (within the bound)
};

/// `required`: segments every triangulation searched must contain (pairwise non-crossing valid segments, e.g.
/// certain edges); the minimum is then taken over the triangulations that contain them.
inline Exhaustive_mwt exhaustive_mwt(const std::vector<Point>& p, const std::vector<std::pair<int, int>>& required = {})
{
  const int n = int(p.size());
  if(n < 3 || n > 24) throw std::invalid_argument("exhaustive_mwt: 3 to 24 points");
  const double rel = 1e-12;
  auto orient = [&](int a, int b, int c) { return int(CGAL::orientation(p[a], p[b], p[c])); };
  // valid segments (no input point in their relative interior)
  const std::vector<std::pair<int, int>> E = valid_segments(p);
  const std::size_t M = E.size();
  std::vector<int> eid(std::size_t(n * n), -1);
  for(std::size_t i = 0; i < M; ++i) eid[E[i].first * n + E[i].second] = eid[E[i].second * n + E[i].first] = int(i);
  std::vector<double> len(M);
  for(std::size_t i = 0; i < M; ++i) len[i] = length(p[E[i].first], p[E[i].second]);
  const std::vector<std::vector<char>> cross = crossing_matrix(p, E);
  // `need[a*n+b]`: the side left of a->b must be covered (the inner side of a hull edge; both sides of an
  // interior edge)
  std::vector<char> hull_edge(M, 0);
  for(std::size_t i = 0; i < M; ++i) hull_edge[i] = is_hull_segment(p, E[i]);
  std::vector<char> need(std::size_t(n * n), 0);
  for(std::size_t i = 0; i < M; ++i)
    for(int s = 0; s < 2; ++s) {
      const int u = s ? E[i].second : E[i].first, v = s ? E[i].first : E[i].second;
      bool inner = !hull_edge[i];   // a hull edge: only its inner side (some point strictly left of u -> v)
      for(int c = 0; c < n && !inner; ++c) inner = orient(u, v, c) > 0;
      need[u * n + v] = inner;
    }
  // admissible third vertices of the side left of a->b, sorted by the weight they add at most
  std::vector<std::vector<int>> apex(std::size_t(n * n));
  for(int a = 0; a < n; ++a)
    for(int b = 0; b < n; ++b) {
      if(a == b || eid[a * n + b] < 0) continue;
      std::vector<int>& L = apex[a * n + b];
      for(int c = 0; c < n; ++c) {
        if(c == a || c == b || orient(a, b, c) <= 0 || eid[b * n + c] < 0 || eid[c * n + a] < 0) continue;
        bool empty = true;
        for(int d = 0; d < n && empty; ++d)
          if(d != a && d != b && d != c && orient(a, b, d) >= 0 && orient(b, c, d) >= 0 && orient(c, a, d) >= 0) empty = false;
        if(empty) L.push_back(c);
      }
      std::sort(L.begin(), L.end(), [&](int u, int v) {
        return len[eid[b * n + u]] + len[eid[u * n + a]] < len[eid[b * n + v]] + len[eid[v * n + a]];
      });
    }
  std::vector<char> chosen(M, 0), covered(std::size_t(n * n), 0);
  std::vector<int> chosen_list;
  Exhaustive_mwt out;
  double sum = 0;   // weight of the chosen edges (saved and restored, never subtracted: no drift)
  std::size_t near_best = 0;   // triangulations found within the tolerance of the current best
  auto open_side = [&]() -> int {
    for(int e : chosen_list) {
      const int a = E[e].first, b = E[e].second;
      for(int s = 0; s < 2; ++s) {
        const int u = s ? b : a, v = s ? a : b;
        if(!covered[u * n + v] && need[u * n + v]) return u * n + v;
      }
    }
    return -1;
  };
  auto add_edge = [&](int e) {
    if(chosen[e]) return false;
    chosen[e] = 1;
    chosen_list.push_back(e);
    sum += len[e];
    return true;
  };
  auto remove_edge = [&](int e) {
    chosen[e] = 0;
    chosen_list.pop_back();
  };
  std::function<void()> rec = [&]() {
    if(sum > out.weight * (1 + rel)) return;
    const int side = open_side();
    if(side < 0) {
      ++out.triangulations_visited;
      if(sum < out.weight * (1 - rel)) {
        out.weight = sum;
        near_best = 1;
        out.edges.clear();
        for(int e : chosen_list) out.edges.insert(E[e]);
      } else {
        ++near_best;
        if(sum < out.weight) {
          out.weight = sum;
          out.edges.clear();
          for(int e : chosen_list) out.edges.insert(E[e]);
        }
      }
      return;
    }
    const int a = side / n, b = side % n;
    for(int c : apex[side]) {
      const int e1 = eid[b * n + c], e2 = eid[c * n + a];
      if(covered[b * n + c] || covered[c * n + a]) continue;
      bool ok = true;
      for(int e : {e1, e2})
        if(!chosen[e])
          for(int f : chosen_list)
            if(cross[e][f]) { ok = false; break; }
      if(!ok) continue;
      covered[a * n + b] = covered[b * n + c] = covered[c * n + a] = 1;
      const double saved = sum;
      const bool n1 = add_edge(e1), n2 = add_edge(e2);
      rec();
      if(n2) remove_edge(e2);
      if(n1) remove_edge(e1);
      sum = saved;
      covered[a * n + b] = covered[b * n + c] = covered[c * n + a] = 0;
    }
  };
  // start from the hull edges (all of them are in every triangulation) and the required ones
  for(std::size_t e = 0; e < M; ++e)
    if(hull_edge[e]) add_edge(int(e));
  for(const auto& r : required) {
    const int e = r.first >= 0 && r.first < n && r.second >= 0 && r.second < n ? eid[r.first * n + r.second] : -1;
    if(e < 0) throw std::invalid_argument("exhaustive_mwt: a required segment is no valid segment");
    for(int f : chosen_list)
      if(cross[e][f]) throw std::invalid_argument("exhaustive_mwt: two required segments cross");
    add_edge(e);
  }
  rec();
  // near_best counts the triangulations within the tolerance of the best at the time they were found; a
  // recount against the final optimum is not needed for uniqueness: when the best improves by more than the
  // tolerance the count restarts
  out.unique = near_best == 1;
  return out;
}

} // namespace mwt_test

#endif // MDCS_TEST_MWT_EXHAUSTIVE_ORACLE_H
