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

/// The candidate edges as a compressed adjacency: for every vertex its neighbours in increasing order with the
/// index of the joining edge; find(a, b) is a binary search in the shorter of the two rows.
class Edge_index
{
public:
  struct Entry { int v, edge; };

  explicit Edge_index(const std::vector<Edge>& edges, std::size_t n) : start_(n + 1, 0)
  {
    for(const Edge& e : edges) { ++start_[std::size_t(e.first) + 1]; ++start_[std::size_t(e.second) + 1]; }
    for(std::size_t v = 1; v <= n; ++v) start_[v] += start_[v - 1];
    nbr_.resize(start_[n]);
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for(std::size_t i = 0; i < edges.size(); ++i) {
      nbr_[fill[std::size_t(edges[i].first)]++] = Entry{edges[i].second, int(i)};
      nbr_[fill[std::size_t(edges[i].second)]++] = Entry{edges[i].first, int(i)};
    }
    for(std::size_t v = 0; v < n; ++v)
      std::sort(nbr_.begin() + std::ptrdiff_t(start_[v]), nbr_.begin() + std::ptrdiff_t(start_[v + 1]),
                [](const Entry& x, const Entry& y) { return x.v < y.v; });
  }

  /// Index of the edge ab, -1 if it is no candidate.
  int find(int a, int b) const
  {
    if(degree(a) > degree(b)) std::swap(a, b);
    const Entry *lo = begin(a), *hi = end(a);
    const Entry* it = std::lower_bound(lo, hi, b, [](const Entry& x, int v) { return x.v < v; });
    return (it != hi && it->v == b) ? it->edge : -1;
  }
  const Entry* begin(int v) const { return nbr_.data() + start_[std::size_t(v)]; }
  const Entry* end(int v) const { return nbr_.data() + start_[std::size_t(v) + 1]; }
  std::size_t degree(int v) const { return start_[std::size_t(v) + 1] - start_[std::size_t(v)]; }
  /// Twice the number of edges.
  std::size_t degree_sum() const { return nbr_.size(); }

private:
  std::vector<std::size_t> start_;
  std::vector<Entry> nbr_;
};

/// Every empty triangle whose sides are candidate edges (exact orientations).
template <class P, class Progress>
std::vector<Lp_triangle> empty_triangles(const P& pts, const Point_grid_2& grid, const Edge_index& index, Progress& progress)
{
  const int n = int(pts.size());
  std::vector<int> mark(std::size_t(n), -1), mark_edge(std::size_t(n), -1);
  std::vector<Lp_triangle> out;
  out.reserve(index.degree_sum() / 2 * 27 / 10 + 16);   // about 2.6 triangles per edge on uniform points
  CGAL::MDCS::internal::Progress_reporter<Progress> report(progress, "empty triangles", std::size_t(n));
  for(int a = 0; a < n; ++a) {
    report(std::size_t(a));
    for(const auto* e = index.begin(a); e != index.end(a); ++e) { mark[e->v] = a; mark_edge[e->v] = e->edge; }
    for(const auto* eb = index.begin(a); eb != index.end(a); ++eb) {
      const int b = eb->v;
      if(b <= a) continue;
      for(const auto* ec = index.begin(b); ec != index.end(b); ++ec) {
        const int c = ec->v;
        if(c <= b || mark[c] != a) continue;
        const int o = pts.orientation(a, b, c);
        if(o == 0) continue;
        const double x0 = std::min({pts.x(a), pts.x(b), pts.x(c)}), x1 = std::max({pts.x(a), pts.x(b), pts.x(c)});
        const double y0 = std::min({pts.y(a), pts.y(b), pts.y(c)}), y1 = std::max({pts.y(a), pts.y(b), pts.y(c)});
        const bool occupied = grid.any_in_box_xy(x0, y0, x1, y1, [&](int r, double rx, double ry) {
          if(r == a || r == b || r == c) return false;
          return pts.orientation(a, b, r, rx, ry) == o && pts.orientation(b, c, r, rx, ry) == o &&
                 pts.orientation(c, a, r, rx, ry) == o;
        });
        if(occupied) continue;
        // sides ab, bc, ca; counter-clockwise (a, b, c) or (a, c, b); side +1: the triangle lies left of lower -> higher
        Lp_triangle t;
        if(o > 0) {
          t.v = {{a, b, c}};
          t.edge = {{eb->edge, ec->edge, mark_edge[c]}};
          t.side = {{1, 1, -1}};
        } else {
          t.v = {{a, c, b}};
          t.edge = {{mark_edge[c], ec->edge, eb->edge}};
          t.side = {{1, -1, -1}};
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
