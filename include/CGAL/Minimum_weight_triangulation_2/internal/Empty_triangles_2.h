// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Empty triangles over candidate edges: every triangle whose three sides are candidate edges and that has
// no input point in its interior (exact orientations; candidate edges carry no point in their interior).
// Then the triangles that cannot be used (an interior edge with triangles on one side only) are removed
// iteratively, which the LP constraints imply anyway.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_EMPTY_TRIANGLES_2_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_EMPTY_TRIANGLES_2_H

#include <CGAL/Minimum_weight_triangulation_2/internal/Candidate_edges_2.h>
#include <CGAL/MDCS/progress.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {
namespace internal {

struct Lp_triangle
{
  std::array<int, 3> v;      // counter-clockwise
  std::array<int, 3> edge;   // edge[i] joins v[i] and v[(i+1)%3]
  std::array<int, 3> side;   // +1: the triangle lies left of its edge (lower index -> higher index)
};

class Edge_index
{
public:
  explicit Edge_index(const std::vector<Edge>& edges, std::size_t n) : n_(n)
  {
    map_.reserve(edges.size() * 2);
    for(std::size_t i = 0; i < edges.size(); ++i) map_.emplace(key(edges[i].first, edges[i].second), int(i));
  }
  int find(int a, int b) const
  {
    auto it = map_.find(a < b ? key(a, b) : key(b, a));
    return it == map_.end() ? -1 : it->second;
  }

private:
  std::uint64_t key(int a, int b) const { return std::uint64_t(a) * n_ + std::uint64_t(b); }
  std::size_t n_;
  std::unordered_map<std::uint64_t, int> map_;
};

template <class P, class Progress>
std::vector<Lp_triangle> empty_triangles(const P& pts, const Point_grid_2& grid, const std::vector<Edge>& edges,
                                         const Edge_index& index, Progress& progress)
{
  const int n = int(pts.size());
  std::vector<std::vector<int>> adj(n);
  for(const Edge& e : edges) { adj[e.first].push_back(e.second); adj[e.second].push_back(e.first); }
  for(auto& a : adj) std::sort(a.begin(), a.end());
  std::vector<int> mark(n, -1);
  std::vector<Lp_triangle> out;
  CGAL::MDCS::internal::Progress_reporter<Progress> report(progress, "empty triangles", std::size_t(n));
  for(int a = 0; a < n; ++a) {
    report(std::size_t(a));
    for(int b : adj[a]) mark[b] = a;
    for(int b : adj[a]) {
      if(b <= a) continue;
      for(int c : adj[b]) {
        if(c <= b || mark[c] != a) continue;
        const int o = pts.orientation(a, b, c);
        if(o == 0) continue;
        const double x0 = std::min({pts.x(a), pts.x(b), pts.x(c)}), x1 = std::max({pts.x(a), pts.x(b), pts.x(c)});
        const double y0 = std::min({pts.y(a), pts.y(b), pts.y(c)}), y1 = std::max({pts.y(a), pts.y(b), pts.y(c)});
        const bool occupied = grid.any_in_box(x0, y0, x1, y1, [&](int r) {
          if(r == a || r == b || r == c) return false;
          return pts.orientation(a, b, r) == o && pts.orientation(b, c, r) == o && pts.orientation(c, a, r) == o;
        });
        if(occupied) continue;
        Lp_triangle t;
        t.v = o > 0 ? std::array<int, 3>{a, b, c} : std::array<int, 3>{a, c, b};
        for(int i = 0; i < 3; ++i) {
          const int u = t.v[i], w = t.v[(i + 1) % 3];
          t.edge[i] = index.find(u, w);
          t.side[i] = u < w ? 1 : -1;   // the triangle is left of u -> w (counter-clockwise)
        }
        out.push_back(t);
      }
    }
  }
  report.finish();
  return out;
}

/// Removes triangles on interior edges that have triangles on one side only, until none is left.
/// `is_hull[e]` marks hull edges. Returns the surviving triangles.
inline std::vector<Lp_triangle> remove_unusable_triangles(const std::vector<Lp_triangle>& tri,
                                                          const std::vector<char>& is_hull)
{
  const std::size_t m = is_hull.size();
  std::vector<std::array<int, 2>> count(m, {0, 0});
  std::vector<std::vector<int>> on_edge(m);
  for(std::size_t t = 0; t < tri.size(); ++t)
    for(int i = 0; i < 3; ++i) {
      ++count[tri[t].edge[i]][tri[t].side[i] > 0 ? 0 : 1];
      on_edge[tri[t].edge[i]].push_back(int(t));
    }
  std::vector<char> alive(tri.size(), 1);
  std::vector<int> queue;
  for(std::size_t e = 0; e < m; ++e)
    if(!is_hull[e] && (count[e][0] == 0) != (count[e][1] == 0)) queue.push_back(int(e));
  while(!queue.empty()) {
    const int e = queue.back();
    queue.pop_back();
    for(int t : on_edge[e]) {
      if(!alive[t]) continue;
      alive[t] = 0;
      for(int i = 0; i < 3; ++i) {
        const int f = tri[t].edge[i];
        int& c = count[f][tri[t].side[i] > 0 ? 0 : 1];
        --c;
        if(c == 0 && !is_hull[f] && count[f][tri[t].side[i] > 0 ? 1 : 0] > 0) queue.push_back(f);
      }
    }
  }
  std::vector<Lp_triangle> out;
  for(std::size_t t = 0; t < tri.size(); ++t)
    if(alive[t]) out.push_back(tri[t]);
  return out;
}

} // namespace internal
} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_EMPTY_TRIANGLES_2_H
