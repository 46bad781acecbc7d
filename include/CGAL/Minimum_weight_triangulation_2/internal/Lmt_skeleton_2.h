// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The LMT-skeleton (Dickerson and Montague; Beirouti and Snoeyink's formulation) on the candidate edges and
// their empty triangles. Every minimum weight triangulation is locally minimal: an interior edge ab with the
// triangles abc and abd is not longer than cd when acbd is convex. An edge that has no such pair of triangles
// whose edges are all still possible is in no locally minimal triangulation and is marked impossible; this is
// repeated until nothing changes. A possible edge crossed by no other possible edge is then certain: it is
// in every locally minimal triangulation over the candidates, hence in every MWT. All predicates are exact
// (orientations and squared-distance comparisons of the kernel).

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_LMT_SKELETON_2_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_LMT_SKELETON_2_H

#include <CGAL/Minimum_weight_triangulation_2/internal/Empty_triangles_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Parallel_stage_2.h>
#include <CGAL/MDCS/concurrency.h>
#include <CGAL/MDCS/progress.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {
namespace internal {

/// State of a candidate edge after the LMT-skeleton.
enum Lmt_edge_state : char { lmt_impossible = 0, lmt_possible = 1, lmt_certain = 2 };

/// Exact: |ab| <= |cd| (Euclidean); a static filter on the doubles when they are the kernel's coordinates.
template <class P>
bool not_longer(const P& pts, int a, int b, int c, int d)
{
  if(pts.has_exact_doubles()) {
    const double ux = pts.x(b) - pts.x(a), uy = pts.y(b) - pts.y(a), vx = pts.x(d) - pts.x(c), vy = pts.y(d) - pts.y(c);
    const double l = ux * ux + uy * uy, r = vx * vx + vy * vy;
    // each side: rounded differences, squares and sum, relative error < 4.5 eps; the subtraction adds eps
    const double bound = 8e-16 * (l + r);
    if(bound > 1e-300 && l - r > bound) return false;
    if(bound > 1e-300 && r - l > bound) return true;
  }
  return CGAL::compare_distance(pts.point(a), pts.point(b), pts.point(c), pts.point(d)) != CGAL::LARGER;
}

/// Exact: the open segments ab and cd cross at one interior point (no shared endpoint).
template <class P>
bool properly_cross(const P& pts, int a, int b, int c, int d)
{
  if(a == c || a == d || b == c || b == d) return false;
  const int o1 = pts.orientation(a, b, c), o2 = pts.orientation(a, b, d);
  if(o1 * o2 >= 0) return false;
  const int o3 = pts.orientation(c, d, a), o4 = pts.orientation(c, d, b);
  return o3 * o4 < 0;
}

/// Triangles by edge and side: for edge e and side s (0: left of lower -> higher index, 1: right), the
/// triangles at(e, s) as a compressed array (32-bit offsets: 3 entries per triangle, at most 2^32 - 1), each
/// list in increasing triangle order.
class Edge_triangles
{
public:
  Edge_triangles(const Triangle_set& tri, std::size_t m, const Parallel_stage& par = Parallel_stage())
    : start_(2 * m + 1)
  {
    if(3 * tri.size() >= std::size_t(UINT32_MAX))
      throw std::length_error("minimum_weight_triangulation_2: too many empty triangles for 32-bit indices");
    // atomic counts and places, then every list sorted: the arrays of a sequential fill, for every thread count
    build(tri, m, par);
  }
  const int* begin(int e, int s) const { return item_.data() + start_[2 * std::size_t(e) + std::size_t(s)]; }
  const int* end(int e, int s) const { return item_.data() + start_[2 * std::size_t(e) + std::size_t(s) + 1]; }

private:
  void build(const Triangle_set& tri, std::size_t m, const Parallel_stage& par)
  {
    const std::size_t T = tri.size(), slots = 2 * m;
    const std::size_t tri_block = 1 << 14, slot_block = 1 << 16;
    const std::unique_ptr<std::atomic<std::uint32_t>[]> count = zeroed_counters<std::uint32_t>(slots, par);
    par.for_blocks(T, tri_block, [&](std::size_t t0, std::size_t t1, std::size_t) {
      for(std::size_t t = t0; t < t1; ++t)
        for(int i = 0; i < 3; ++i)
          count[slot(tri.edge(int(t), i), tri.side(int(t), i))].fetch_add(1, std::memory_order_relaxed);
    });
    // prefix sums: per block of slots, then over the blocks, then inside the blocks
    const std::size_t nb = (slots + slot_block - 1) / slot_block;
    std::vector<std::uint32_t> block_sum(nb + 1, 0);
    par.for_blocks(slots, slot_block, [&](std::size_t k0, std::size_t k1, std::size_t b) {
      std::uint32_t s = 0;
      for(std::size_t k = k0; k < k1; ++k) s += count[k].load(std::memory_order_relaxed);
      block_sum[b + 1] = s;
    });
    for(std::size_t b = 0; b < nb; ++b) block_sum[b + 1] += block_sum[b];
    par.for_blocks(slots, slot_block, [&](std::size_t k0, std::size_t k1, std::size_t b) {
      std::uint32_t s = block_sum[b];
      for(std::size_t k = k0; k < k1; ++k) {
        start_[k] = s;
        s += count[k].load(std::memory_order_relaxed);
        count[k].store(0, std::memory_order_relaxed);   // becomes the fill cursor
      }
    });
    start_[slots] = block_sum[nb];
    item_.resize(start_[slots]);   // not initialised: every entry is placed below
    par.for_blocks(T, tri_block, [&](std::size_t t0, std::size_t t1, std::size_t) {
      for(std::size_t t = t0; t < t1; ++t)
        for(int i = 0; i < 3; ++i) {
          const std::size_t k = slot(tri.edge(int(t), i), tri.side(int(t), i));
          item_[start_[k] + count[k].fetch_add(1, std::memory_order_relaxed)] = int(t);
        }
    });
    par.for_blocks(slots, slot_block, [&](std::size_t k0, std::size_t k1, std::size_t) {
      for(std::size_t k = k0; k < k1; ++k)
        std::sort(item_.begin() + std::ptrdiff_t(start_[k]), item_.begin() + std::ptrdiff_t(start_[k + 1]));
    });
  }

  static std::size_t slot(int e, int side) { return 2 * std::size_t(e) + (side > 0 ? 0 : 1); }
  Uninit_vector<std::uint32_t> start_;   // every entry written by the prefix sums
  Uninit_vector<int> item_;
};

/*!
  Marks every edge impossible, possible or certain. `tri` are the empty triangles over `edges` (all of them,
  before `remove_unusable_triangles`), `by_edge` their lists per edge and side, `is_hull` flags hull edges
  (always certain).

  Killing is monotone (fewer live edges never give an edge a witness back), so any order of the tests that
  re-tests an edge after every death among the edges of its triangles ends at the same skeleton: the largest
  set of edges that all keep a witness within it. In parallel (`par`) the edges are cut into fixed ranges of
  2^14 indices, and the loop runs in rounds: in a round every range works through its queued edges with a work
  list of its own, like the sequential loop (an edge of the range whose neighbour dies is tested again at once,
  in cache); a death queues the live edges of its triangles that belong to other ranges for the next round,
  which starts when every range is done. An edge is thus tested again after every death that its test may have
  missed: the deaths of its own range are seen at once, those of other ranges (written concurrently, atomic
  flags) by the next round's test. The skeleton is the same for every thread count; only the number of tests
  varies. The certain edges are then found in parallel over a grid of edge boxes.
*/
template <class P, class Progress>
std::vector<char> lmt_skeleton(const P& pts, const std::vector<Edge>& edges, const Triangle_set& tri,
                               const Edge_triangles& by_edge, const std::vector<char>& is_hull, Progress& progress,
                               const Parallel_stage& par = Parallel_stage())
{
  const std::size_t m = edges.size();
  const std::unique_ptr<std::atomic<char>[]> alive_flag = zeroed_counters<char>(m, par);
  par.for_blocks(m, 1 << 16, [&](std::size_t e0, std::size_t e1, std::size_t) {
    for(std::size_t e = e0; e < e1; ++e) alive_flag[e].store(1, std::memory_order_relaxed);
  });
  // acquire/release: a test that reads a death happens after the test that decided it, so deaths never justify
  // each other in a cycle (every death is justified by a state that actually existed)
  auto alive = [&](std::size_t e) { return alive_flag[e].load(std::memory_order_acquire) != 0; };
  auto tri_alive = [&](int t) {
    const auto& te = tri.edges(t);
    return alive(std::size_t(te[0])) && alive(std::size_t(te[1])) && alive(std::size_t(te[2]));
  };
  auto apex = [&](int t, int e) { return tri.apex(t, e); };
  // an interior edge keeps a witness: a live triangle on each side with a non-convex quadrilateral or |ab| <= |cd|
  // (c is strictly left and d strictly right of ab, so acbd is strictly convex iff cd crosses the line ab
  // between a and b); right_apex: the apexes of the live triangles right of the edge (a workspace)
  auto has_witness = [&](int e, std::vector<int>& right_apex) {
    const int a = edges[e].first, b = edges[e].second;
    right_apex.clear();
    for(const int* t2 = by_edge.begin(e, 1); t2 != by_edge.end(e, 1); ++t2)
      if(tri_alive(*t2)) right_apex.push_back(apex(*t2, e));
    if(right_apex.empty()) return false;
    for(const int* t1 = by_edge.begin(e, 0); t1 != by_edge.end(e, 0); ++t1) {
      if(!tri_alive(*t1)) continue;
      const int c = apex(*t1, e);
      for(const int d : right_apex) {
        if(not_longer(pts, a, b, c, d)) return true;
        if(pts.orientation(c, d, a) * pts.orientation(c, d, b) >= 0) return true;   // acbd not strictly convex: no flip
      }
    }
    return false;
  };
  CGAL::MDCS::Parallel_progress<Progress> report(progress, "LMT-skeleton", m);
  const std::size_t range = 1 << 14, ranges = (m + range - 1) / range;
  {
    Uninit_vector<int> round;   // the queued edges, increasing
    round.reserve(m);
    par.append_in_order(m, 1 << 16, round, [&](std::size_t e0, std::size_t e1, Uninit_vector<int>& out) {
      for(std::size_t e = e0; e < e1; ++e)
        if(!is_hull[e]) out.push_back(int(e));
    });
    const std::unique_ptr<std::atomic<char>[]> queued = zeroed_counters<char>(m, par);
    while(!round.empty()) {
      // the next round: live interior edges of other ranges next to a death, each once
      Uninit_vector<int> next;
      par.append_in_order(ranges, 1, next, [&](std::size_t r, std::size_t, Uninit_vector<int>& out) {
        if(report.cancelled()) return;
        const int lo = int(r * range), hi = int(std::min(m, (r + 1) * range));
        auto first = std::lower_bound(round.begin(), round.end(), lo);
        auto last = std::lower_bound(first, round.end(), hi);
        if(first == last) return;
        std::vector<int> work(std::make_reverse_iterator(last), std::make_reverse_iterator(first));   // increasing pops
        std::vector<char> in_work(std::size_t(hi - lo), 0);
        for(int e : work) in_work[std::size_t(e - lo)] = 1;
        std::vector<int> right_apex;
        std::size_t tests = 0;
        while(!work.empty()) {
          const int e = work.back();
          work.pop_back();
          in_work[std::size_t(e - lo)] = 0;
          if(++tests == 1024) {   // progress (and cancellation) within a range, too
            if(!report.advance(tests)) return;
            tests = 0;
          }
          if(!alive(std::size_t(e)) || has_witness(e, right_apex)) continue;
          alive_flag[std::size_t(e)].store(0, std::memory_order_release);
          for(int s = 0; s < 2; ++s)
            for(const int* tp = by_edge.begin(e, s); tp != by_edge.end(e, s); ++tp)
              for(int i = 0; i < 3; ++i) {
                const int f = tri.edge(*tp, i);
                if(!alive(std::size_t(f)) || is_hull[f]) continue;
                if(f >= lo && f < hi) {
                  if(!in_work[std::size_t(f - lo)]) { in_work[std::size_t(f - lo)] = 1; work.push_back(f); }
                } else if(!queued[f].exchange(1, std::memory_order_relaxed)) {
                  out.push_back(f);
                }
              }
        }
        report.advance(tests);
      });
      if(report.cancelled()) report.finish();   // throws
      Uninit_vector<int>().swap(round);
      std::sort(next.begin(), next.end());
      par.for_blocks(next.size(), 1 << 16, [&](std::size_t k0, std::size_t k1, std::size_t) {
        for(std::size_t k = k0; k < k1; ++k) queued[std::size_t(next[k])].store(0, std::memory_order_relaxed);
      });
      round.swap(next);
    }
  }   // the work arrays are released before the crossing tests (memory peak of the pipeline)
  report.finish();

  // certain: alive and crossed by no other alive edge (edges bucketed in a grid by bounding box)
  std::vector<char> state(m, lmt_impossible);
  double xmin = HUGE_VAL, ymin = HUGE_VAL, xmax = -HUGE_VAL, ymax = -HUGE_VAL;
  for(std::size_t i = 0; i < pts.size(); ++i) {
    xmin = std::min(xmin, pts.x(int(i))); xmax = std::max(xmax, pts.x(int(i)));
    ymin = std::min(ymin, pts.y(int(i))); ymax = std::max(ymax, pts.y(int(i)));
  }
  const int G = std::max(1, std::min(2048, int(std::sqrt(double(pts.size()) / 2.0))));
  // (cells by a multiplication: the same function for the buckets and the test cell of a pair)
  const double iwx = G / std::max(xmax - xmin, 1e-300), iwy = G / std::max(ymax - ymin, 1e-300);
  auto cx = [&](double x) { return std::max(0, std::min(G - 1, int((x - xmin) * iwx))); };
  auto cy = [&](double y) { return std::max(0, std::min(G - 1, int((y - ymin) * iwy))); };
  auto box = [&](int e, int& i0, int& i1, int& j0, int& j1) {
    const int a = edges[e].first, b = edges[e].second;
    i0 = cx(std::min(pts.x(a), pts.x(b))); i1 = cx(std::max(pts.x(a), pts.x(b)));
    j0 = cy(std::min(pts.y(a), pts.y(b))); j1 = cy(std::max(pts.y(a), pts.y(b)));
  };
  // cell lists as a compressed array (count, then fill; atomic counters, the order inside a cell is free)
  const std::size_t cells = std::size_t(G) * G, edge_block = 1 << 14;
  std::vector<std::size_t> cell_start(cells + 1, 0);
  Uninit_vector<int> cell_item;
  {
    const std::unique_ptr<std::atomic<std::uint32_t>[]> cell_count = zeroed_counters<std::uint32_t>(cells, par);
    auto for_cells = [&](std::size_t e, bool fill) {
      int i0, i1, j0, j1;
      box(int(e), i0, i1, j0, j1);
      for(int j = j0; j <= j1; ++j)
        for(int i = i0; i <= i1; ++i) {
          const std::size_t c = std::size_t(i) + std::size_t(G) * std::size_t(j);
          const std::uint32_t k = cell_count[c].fetch_add(1, std::memory_order_relaxed);
          if(fill) cell_item[cell_start[c] + k] = int(e);
        }
    };
    par.for_blocks(m, edge_block, [&](std::size_t e0, std::size_t e1, std::size_t) {
      for(std::size_t e = e0; e < e1; ++e)
        if(alive(e)) for_cells(e, false);
    });
    for(std::size_t c = 0; c < cells; ++c) {
      cell_start[c + 1] = cell_start[c] + cell_count[c].load(std::memory_order_relaxed);
      cell_count[c].store(0, std::memory_order_relaxed);
    }
    cell_item.resize(cell_start.back());
    par.for_blocks(m, edge_block, [&](std::size_t e0, std::size_t e1, std::size_t) {
      for(std::size_t e = e0; e < e1; ++e)
        if(alive(e)) for_cells(e, true);
    });
  }
  // Each pair of edges is tested once by each of them, in one cell only: the lowest cell of the intersection of
  // their cell ranges (no per-edge stamps). A crossing marks both edges; an edge already marked is skipped.
  const std::unique_ptr<std::atomic<char>[]> crossed = zeroed_counters<char>(m, par);
  par.for_blocks(m, edge_block, [&](std::size_t e0, std::size_t e1, std::size_t) {
    for(std::size_t e = e0; e < e1; ++e) {
      if(!alive(e) || crossed[e].load(std::memory_order_relaxed)) continue;
      int i0, i1, j0, j1;
      box(int(e), i0, i1, j0, j1);
      const int a = edges[e].first, b = edges[e].second;
      const double ex0 = std::min(pts.x(a), pts.x(b)), ex1 = std::max(pts.x(a), pts.x(b));
      const double ey0 = std::min(pts.y(a), pts.y(b)), ey1 = std::max(pts.y(a), pts.y(b));
      bool found = false;
      for(int j = j0; j <= j1 && !found; ++j)
        for(int i = i0; i <= i1 && !found; ++i)
          for(std::size_t k = cell_start[std::size_t(i) + std::size_t(G) * j]; k < cell_start[std::size_t(i) + std::size_t(G) * j + 1]; ++k) {
            const int f = cell_item[k];
            if(f == int(e)) continue;
            const int c = edges[f].first, d = edges[f].second;
            const double fx0 = std::min(pts.x(c), pts.x(d)), fx1 = std::max(pts.x(c), pts.x(d));
            const double fy0 = std::min(pts.y(c), pts.y(d)), fy1 = std::max(pts.y(c), pts.y(d));
            // disjoint bounding boxes: no crossing
            if(fx1 < ex0 || fx0 > ex1 || fy1 < ey0 || fy0 > ey1) continue;
            if(i != std::max(i0, cx(fx0)) || j != std::max(j0, cy(fy0))) continue;   // tested in another cell
            if(properly_cross(pts, a, b, c, d)) {
              crossed[e].store(1, std::memory_order_relaxed);
              crossed[std::size_t(f)].store(1, std::memory_order_relaxed);
              found = true;
              break;
            }
          }
    }
  });
  par.for_blocks(m, 1 << 16, [&](std::size_t e0, std::size_t e1, std::size_t) {
    for(std::size_t e = e0; e < e1; ++e)
      if(is_hull[e]) state[e] = lmt_certain;
      else if(alive(e)) state[e] = crossed[e].load(std::memory_order_relaxed) ? lmt_possible : lmt_certain;
  });
  return state;
}

} // namespace internal
} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_LMT_SKELETON_2_H
