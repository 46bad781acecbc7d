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

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {
namespace internal {

/// Returns an empty string when valid, else what is wrong.
template <class P>
std::string validate_triangulation(const P& pts, const Point_grid_2& grid, const std::vector<int>& hull,
                                   const std::vector<std::array<int, 3>>& tri)
{
  const std::size_t n = pts.size(), h = hull.size();
  if(tri.size() != 2 * n - h - 2)
    return "wrong number of triangles: " + std::to_string(tri.size()) + " instead of 2n-h-2 = " + std::to_string(2 * n - h - 2);
  std::unordered_map<std::uint64_t, int> half;   // directed edge -> count
  half.reserve(tri.size() * 6);
  std::vector<char> used(n, 0);
  auto key = [n](int a, int b) { return std::uint64_t(a) * n + std::uint64_t(b); };
  for(const auto& t : tri) {
    for(int i = 0; i < 3; ++i) {
      if(t[i] < 0 || std::size_t(t[i]) >= n) return "vertex index out of range";
      used[t[i]] = 1;
    }
    if(pts.orientation(t[0], t[1], t[2]) <= 0) return "a triangle is degenerate or clockwise";
    for(int i = 0; i < 3; ++i)
      if(++half[key(t[i], t[(i + 1) % 3])] > 1) return "a directed edge is used twice (overlap)";
    const double x0 = std::min({pts.x(t[0]), pts.x(t[1]), pts.x(t[2])}), x1 = std::max({pts.x(t[0]), pts.x(t[1]), pts.x(t[2])});
    const double y0 = std::min({pts.y(t[0]), pts.y(t[1]), pts.y(t[2])}), y1 = std::max({pts.y(t[0]), pts.y(t[1]), pts.y(t[2])});
    const bool occupied = grid.any_in_box(x0, y0, x1, y1, [&](int r) {
      if(r == t[0] || r == t[1] || r == t[2]) return false;
      const int o0 = pts.orientation(t[0], t[1], r), o1 = pts.orientation(t[1], t[2], r), o2 = pts.orientation(t[2], t[0], r);
      return o0 >= 0 && o1 >= 0 && o2 >= 0;   // inside or on an edge
    });
    if(occupied) return "a triangle contains an input point";
  }
  for(std::size_t i = 0; i < n; ++i)
    if(!used[i]) return "input point " + std::to_string(i) + " is not a vertex";
  std::unordered_map<std::uint64_t, char> hull_edge;
  for(std::size_t i = 0; i < h; ++i) {
    const int a = hull[i], b = hull[(i + 1) % h];
    if(half.count(key(a, b)) == 0) return "hull edge not covered";
    if(half.count(key(b, a)) != 0) return "hull edge covered from outside";
    hull_edge[key(a, b)] = 1;
  }
  for(const auto& kv : half) {
    if(hull_edge.count(kv.first)) continue;
    const int a = int(kv.first / n), b = int(kv.first % n);
    if(half.count(key(b, a)) == 0) return "an interior edge has a triangle on one side only";
  }
  return std::string();
}

} // namespace internal
} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_VALIDATION_2_H
