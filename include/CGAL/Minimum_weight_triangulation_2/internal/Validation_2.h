// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact validation of a triangulation of a point set: counter-clockwise non-degenerate empty triangles,
// Euler count 2n - h - 2, every hull edge covered once from inside, every other edge by exactly two
// triangles on opposite sides, every input point used. By the covering argument of the thesis (thm 3.4.1)
// these local conditions imply that the triangles tile the convex hull exactly once.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_VALIDATION_2_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_VALIDATION_2_H

#include <CGAL/Minimum_weight_triangulation_2/internal/Indexed_points_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Parallel_stage_2.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {
namespace internal {

/*!
  Returns an empty string when valid, else what is wrong: the first failing triangle (index range, orientation,
  emptiness) in triangle order, then a directed edge used twice, an input point that is no vertex, the hull
  edges, an interior edge with a triangle on one side only. The triangles are checked in blocks in parallel
  (`par`); the directed edges are rows per source vertex (sorted), so the verdict and its message are the same for
  every thread count.
*/
template <class P>
std::string validate_triangulation(const P& pts, const Point_grid_2& grid, const std::vector<int>& hull,
                                   const std::vector<std::array<int, 3>>& tri,
                                   const Parallel_stage& par = Parallel_stage())
{
  const std::size_t n = pts.size(), h = hull.size();
  if(tri.size() != 2 * n - h - 2)
    return "wrong number of triangles: " + std::to_string(tri.size()) + " instead of 2n-h-2 = " + std::to_string(2 * n - h - 2);
  // 1. every triangle: indices, counter-clockwise, no input point inside or on an edge
  const std::size_t block = 4096, blocks = (tri.size() + block - 1) / block;
  std::vector<const char*> failure(blocks, nullptr);   // the first failure of each block
  const std::unique_ptr<std::atomic<char>[]> used = zeroed_counters<char>(n, par);
  par.for_blocks(tri.size(), block, [&](std::size_t t0, std::size_t t1, std::size_t b) {
    for(std::size_t k = t0; k < t1; ++k) {
      const std::array<int, 3>& t = tri[k];
      if(t[0] < 0 || t[1] < 0 || t[2] < 0 || std::size_t(t[0]) >= n || std::size_t(t[1]) >= n || std::size_t(t[2]) >= n) {
        failure[b] = "vertex index out of range";
        return;
      }
      for(int i = 0; i < 3; ++i) used[std::size_t(t[i])].store(1, std::memory_order_relaxed);
      if(pts.orientation(t[0], t[1], t[2]) <= 0) {
        failure[b] = "a triangle is degenerate or clockwise";
        return;
      }
      const double x0 = std::min({pts.x(t[0]), pts.x(t[1]), pts.x(t[2])}), x1 = std::max({pts.x(t[0]), pts.x(t[1]), pts.x(t[2])});
      const double y0 = std::min({pts.y(t[0]), pts.y(t[1]), pts.y(t[2])}), y1 = std::max({pts.y(t[0]), pts.y(t[1]), pts.y(t[2])});
      const bool occupied = grid.any_in_box(x0, y0, x1, y1, [&](int r) {
        if(r == t[0] || r == t[1] || r == t[2]) return false;
        const int o0 = pts.orientation(t[0], t[1], r), o1 = pts.orientation(t[1], t[2], r), o2 = pts.orientation(t[2], t[0], r);
        return o0 >= 0 && o1 >= 0 && o2 >= 0;   // inside or on an edge
      });
      if(occupied) {
        failure[b] = "a triangle contains an input point";
        return;
      }
    }
  });
  for(const char* f : failure)
    if(f) return f;
  // 2. the directed edges a -> b, per source a, sorted
  std::vector<std::size_t> start;
  Uninit_vector<int> target;
  build_sorted_rows(n, tri.size(), [&](std::size_t k, auto&& add) {
    for(int i = 0; i < 3; ++i) add(tri[k][i], tri[k][(i + 1) % 3]);
  }, false, start, target, par);
  auto has = [&](int a, int b) {
    return std::binary_search(target.begin() + std::ptrdiff_t(start[std::size_t(a)]),
                              target.begin() + std::ptrdiff_t(start[std::size_t(a) + 1]), b);
  };
  std::vector<int> hull_next(n, -1);   // the hull edges a -> hull_next[a]
  for(std::size_t i = 0; i < h; ++i) hull_next[std::size_t(hull[i])] = hull[(i + 1) % h];
  // per block of vertices: 1 a repeated directed edge, 2 an interior edge with one side only (the first vertex
  // decides; repeated edges are reported before unused points, which come before the edge checks)
  std::vector<char> vertex_failure((n + block - 1) / block, 0);
  par.for_blocks(n, block, [&](std::size_t a0, std::size_t a1, std::size_t b) {
    char repeated = 0, one_sided = 0;
    for(std::size_t a = a0; a < a1; ++a)
      for(std::size_t k = start[a]; k < start[a + 1]; ++k) {
        const int v = target[k];
        if(k + 1 < start[a + 1] && target[k + 1] == v) repeated = 1;
        if(!one_sided && hull_next[a] != v && !has(v, int(a))) one_sided = 1;
      }
    vertex_failure[b] = repeated ? 1 : (one_sided ? 2 : 0);
  });
  for(char f : vertex_failure)
    if(f == 1) return "a directed edge is used twice (overlap)";
  for(std::size_t i = 0; i < n; ++i)
    if(!used[i].load(std::memory_order_relaxed)) return "input point " + std::to_string(i) + " is not a vertex";
  for(std::size_t i = 0; i < h; ++i) {
    const int a = hull[i], b = hull[(i + 1) % h];
    if(!has(a, b)) return "hull edge not covered";
    if(has(b, a)) return "hull edge covered from outside";
  }
  for(char f : vertex_failure)
    if(f == 2) return "an interior edge has a triangle on one side only";
  return std::string();
}

} // namespace internal
} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_VALIDATION_2_H
