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
#include <CGAL/Minimum_weight_triangulation_2/internal/Parallel_stage_2.h>
#include <CGAL/MDCS/concurrency.h>
#include <CGAL/MDCS/progress.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {
namespace internal {

struct Lp_triangle
{
  std::array<int, 3> v;      // counter-clockwise
  std::array<int, 3> edge;   // edge[i] joins v[i] and v[(i+1)%3]
  /// +1: the triangle lies left of its edge i (lower index -> higher index), -1: right
  int side(int i) const { return v[i] < v[(i + 1) % 3] ? 1 : -1; }
};

/*!
  Triangles stored by their three edges only (12 bytes each, the empty triangles are about 30 per point): edge i
  joins the vertices i and i + 1 of the counter-clockwise triangle, so vertex i is the common endpoint of the
  edges i - 1 and i. `edges` (the candidate edges, first < second) must outlive the set.
*/
class Triangle_set
{
public:
  explicit Triangle_set(const std::vector<Edge>& edges) : edges_(&edges) {}
  /// Takes the triangles (three edge indices each, as edges(t)) over.
  Triangle_set(const std::vector<Edge>& edges, Uninit_vector<std::array<int, 3>>&& by_edges)
    : edges_(&edges), e_(std::move(by_edges))
  {}
  Triangle_set(const std::vector<Edge>& edges, const std::vector<Lp_triangle>& tri) : edges_(&edges)
  {
    e_.reserve(tri.size());
    for(const auto& t : tri) e_.push_back(t.edge);
  }

  std::size_t size() const { return e_.size(); }
  void reserve(std::size_t n) { e_.reserve(n); }
  void push_back(int e0, int e1, int e2) { e_.push_back(std::array<int, 3>{{e0, e1, e2}}); }
  int edge(int t, int i) const { return e_[std::size_t(t)][std::size_t(i)]; }
  const std::array<int, 3>& edges(int t) const { return e_[std::size_t(t)]; }
  /// Vertex i (counter-clockwise): the common endpoint of the edges i - 1 and i.
  int vertex(int t, int i) const
  {
    const Edge& a = (*edges_)[std::size_t(e_[std::size_t(t)][std::size_t((i + 2) % 3)])];
    const Edge& b = (*edges_)[std::size_t(e_[std::size_t(t)][std::size_t(i)])];
    return (b.first == a.first || b.first == a.second) ? b.first : b.second;
  }
  /// +1: the triangle lies left of its edge i (lower index -> higher index), -1: right.
  int side(int t, int i) const
  {
    const Edge& a = (*edges_)[std::size_t(e_[std::size_t(t)][std::size_t((i + 2) % 3)])];
    const int lo = (*edges_)[std::size_t(e_[std::size_t(t)][std::size_t(i)])].first;
    return (lo == a.first || lo == a.second) ? 1 : -1;
  }
  /// The vertex of triangle t opposite to its edge e (e must be one of its edges).
  int apex(int t, int e) const
  {
    const auto& te = e_[std::size_t(t)];
    const int i = te[0] == e ? 0 : (te[1] == e ? 1 : 2);
    const Edge& d = (*edges_)[std::size_t(e)];
    const Edge& f = (*edges_)[std::size_t(te[std::size_t((i + 1) % 3)])];
    return (f.first == d.first || f.first == d.second) ? f.second : f.first;
  }
  std::array<int, 3> vertices(int t) const { return {{vertex(t, 0), vertex(t, 1), vertex(t, 2)}}; }
  Lp_triangle triangle(int t) const { return Lp_triangle{vertices(t), e_[std::size_t(t)]}; }
  /// Keeps the triangles t with keep(t) (in order) and releases the memory of the others (blocks in parallel).
  template <class Keep>
  void compact(Keep keep, const Parallel_stage& par = Parallel_stage())
  {
    const std::size_t block = 1 << 14;
    std::vector<std::size_t> count((e_.size() + block - 1) / block, 0);
    par.for_blocks(e_.size(), block, [&](std::size_t t0, std::size_t t1, std::size_t b) {
      for(std::size_t t = t0; t < t1; ++t) count[b] += keep(int(t)) ? 1 : 0;
    });
    std::size_t total = 0;
    for(std::size_t c : count) total += c;
    Uninit_vector<std::array<int, 3>> kept;
    kept.reserve(total);
    par.append_in_order(e_.size(), block, kept, [&](std::size_t t0, std::size_t t1, Uninit_vector<std::array<int, 3>>& o) {
      for(std::size_t t = t0; t < t1; ++t)
        if(keep(int(t))) o.push_back(e_[t]);
    });
    e_.swap(kept);
  }

private:
  const std::vector<Edge>* edges_;
  Uninit_vector<std::array<int, 3>> e_;
};

/// The candidate edges as a compressed adjacency: for every vertex its neighbours in increasing order with the
/// index of the joining edge; find(a, b) is a binary search in the shorter of the two rows.
class Edge_index
{
public:
  struct Entry { int v, edge; };

  explicit Edge_index(const std::vector<Edge>& edges, std::size_t n, const Parallel_stage& par = Parallel_stage())
    : Edge_index(edges, n, [](std::size_t) { return true; }, par)
  {}

  /// The index of the edges i with keep(i) only (find() gives -1 for the others). Built in parallel (`par`):
  /// atomic counts and places, then every row sorted (its neighbours are distinct, so the rows do not depend on
  /// the thread count).
  template <class Keep>
  Edge_index(const std::vector<Edge>& edges, std::size_t n, Keep keep, const Parallel_stage& par = Parallel_stage())
    : start_(n + 1, 0)
  {
    if(2 * edges.size() >= std::size_t(UINT32_MAX))
      throw std::length_error("minimum_weight_triangulation_2: too many candidate edges for 32-bit indices");
    const std::size_t edge_block = 1 << 14;
    const std::unique_ptr<std::atomic<std::uint32_t>[]> cursor = zeroed_counters<std::uint32_t>(n, par);
    par.for_blocks(edges.size(), edge_block, [&](std::size_t i0, std::size_t i1, std::size_t) {
      for(std::size_t i = i0; i < i1; ++i)
        if(keep(i)) {
          cursor[std::size_t(edges[i].first)].fetch_add(1, std::memory_order_relaxed);
          cursor[std::size_t(edges[i].second)].fetch_add(1, std::memory_order_relaxed);
        }
    });
    for(std::size_t v = 0; v < n; ++v) {
      start_[v + 1] = start_[v] + cursor[v].load(std::memory_order_relaxed);
      cursor[v].store(0, std::memory_order_relaxed);
    }
    nbr_.resize(start_[n]);
    par.for_blocks(edges.size(), edge_block, [&](std::size_t i0, std::size_t i1, std::size_t) {
      for(std::size_t i = i0; i < i1; ++i)
        if(keep(i)) {
          const std::size_t a = std::size_t(edges[i].first), b = std::size_t(edges[i].second);
          nbr_[start_[a] + cursor[a].fetch_add(1, std::memory_order_relaxed)] = Entry{int(b), int(i)};
          nbr_[start_[b] + cursor[b].fetch_add(1, std::memory_order_relaxed)] = Entry{int(a), int(i)};
        }
    });
    par.for_blocks(n, 4096, [&](std::size_t v0, std::size_t v1, std::size_t) {
      for(std::size_t v = v0; v < v1; ++v)
        std::sort(nbr_.begin() + std::ptrdiff_t(start_[v]), nbr_.begin() + std::ptrdiff_t(start_[v + 1]),
                  [](const Entry& x, const Entry& y) { return x.v < y.v; });
    });
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
  std::vector<std::uint32_t> start_;   // 32 bits: half the memory of size_t (at most 2^32 - 1 entries, checked)
  Uninit_vector<Entry> nbr_;
};

/// Every empty triangle whose sides are candidate edges (exact orientations), by edges (`edges`: the
/// candidate edges of `index`). Triangle (a < b < c) is found from a: the common neighbours c > b of a and b
/// (a merge of their sorted rows). Blocks of vertices a in parallel (`par`), joined in the order of a.
template <class P, class Progress>
Triangle_set empty_triangles(const P& pts, const Point_grid_2& grid, const Edge_index& index,
                             const std::vector<Edge>& edges, Progress& progress,
                             const Parallel_stage& par = Parallel_stage())
{
  typedef std::array<int, 3> By_edges;
  const int n = int(pts.size());
  Uninit_vector<By_edges> out;
  out.reserve(index.degree_sum() / 2 * 27 / 10 + 16);   // about 2.6 triangles per edge on uniform points
  CGAL::MDCS::Parallel_progress<Progress> report(progress, "empty triangles", std::size_t(n));
  par.append_in_order(std::size_t(n), 512, out, [&](std::size_t a0, std::size_t a1, Uninit_vector<By_edges>& block_out) {
    if(report.cancelled()) return;
    for(int a = int(a0); a < int(a1); ++a) {
      const Edge_index::Entry* const a_end = index.end(a);
      for(const auto* eb = index.begin(a); eb != a_end; ++eb) {
        const int b = eb->v;
        if(b <= a) continue;
        // the rows are sorted by neighbour: the neighbours c > b of b that are neighbours of a (edge ac = ea->edge)
        const Edge_index::Entry* ea = eb + 1;
        for(const auto* ec = index.begin(b); ec != index.end(b) && ea != a_end; ++ec) {
          const int c = ec->v;
          if(c <= b) continue;
          while(ea != a_end && ea->v < c) ++ea;
          if(ea == a_end || ea->v != c) continue;
          const int ac = ea->edge;
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
          // counter-clockwise (a, b, c) with the sides ab, bc, ca, or (a, c, b) with ac, cb, ba
          if(o > 0) block_out.push_back(By_edges{{eb->edge, ec->edge, ac}});
          else block_out.push_back(By_edges{{ac, ec->edge, eb->edge}});
        }
      }
    }
    report.advance(a1 - a0);
  });
  report.finish();
  return Triangle_set(edges, std::move(out));
}

/// Removes triangles on interior edges that have triangles on one side only, until none is left.
/// `is_hull[e]` marks hull edges. Returns the surviving triangles (the result does not depend on the order of
/// the removals: it is the largest subset in which no interior edge has triangles on one side only). When the
/// triangles use few of the edges (the LP of the pipeline: a few faces), the edges are numbered locally, so the
/// work does not grow with the number of candidate edges.
inline std::vector<Lp_triangle> remove_unusable_triangles(const std::vector<Lp_triangle>& tri,
                                                          const std::vector<char>& is_hull)
{
  const std::size_t all_edges = is_hull.size();
  std::vector<int> ids;   // local numbering: the sorted edges of the triangles (empty: the edge indices)
  if(24 * tri.size() < all_edges) {
    for(const auto& t : tri)
      for(int i = 0; i < 3; ++i) ids.push_back(t.edge[i]);
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  }
  const bool local = !ids.empty() || tri.empty();
  const std::size_t m = local ? ids.size() : all_edges;
  auto id = [&](int e) {
    return local ? std::size_t(std::lower_bound(ids.begin(), ids.end(), e) - ids.begin()) : std::size_t(e);
  };
  auto hull = [&](std::size_t k) { return is_hull[local ? std::size_t(ids[k]) : k] != 0; };
  std::vector<std::array<int, 2>> count(m, {0, 0});
  // the triangles of every edge as a compressed array
  std::vector<std::size_t> start(m + 1, 0);
  for(const auto& t : tri)
    for(int i = 0; i < 3; ++i) ++start[id(t.edge[i]) + 1];
  for(std::size_t e = 1; e <= m; ++e) start[e] += start[e - 1];
  std::vector<int> on_edge(start[m]);
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for(std::size_t t = 0; t < tri.size(); ++t)
      for(int i = 0; i < 3; ++i) {
        const std::size_t k = id(tri[t].edge[i]);
        ++count[k][tri[t].side(i) > 0 ? 0 : 1];
        on_edge[fill[k]++] = int(t);
      }
  }
  std::vector<char> alive(tri.size(), 1);
  std::vector<std::size_t> queue;
  for(std::size_t e = 0; e < m; ++e)
    if(!hull(e) && (count[e][0] == 0) != (count[e][1] == 0)) queue.push_back(e);
  while(!queue.empty()) {
    const std::size_t e = queue.back();
    queue.pop_back();
    for(std::size_t k = start[e]; k < start[e + 1]; ++k) {
      const int t = on_edge[k];
      if(!alive[t]) continue;
      alive[t] = 0;
      for(int i = 0; i < 3; ++i) {
        const std::size_t f = id(tri[t].edge[i]);
        int& c = count[f][tri[t].side(i) > 0 ? 0 : 1];
        --c;
        if(c == 0 && !hull(f) && count[f][tri[t].side(i) > 0 ? 1 : 0] > 0) queue.push_back(f);
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
