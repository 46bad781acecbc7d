// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Input checks, the convex hull boundary (with collinear points) and the candidate edges: either every
// segment without an input point in its interior, or those that also pass the diamond test of Das and
// Joseph, with the larger angle pi/4.6 proven by Drysdale, McElfresh and Snoeyink ("On exclusion regions
// for optimal triangulations", 2001): an edge is in no MWT when both isosceles triangles with base angle
// pi/4.6 on it contain input points.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_CANDIDATE_EDGES_2_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_CANDIDATE_EDGES_2_H

#include <CGAL/Minimum_weight_triangulation_2/internal/Indexed_points_2.h>
#include <CGAL/MDCS/progress.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {
namespace internal {

typedef std::pair<int, int> Edge;   // first < second

/// Throws std::invalid_argument on fewer than 3 points, non-finite coordinates, duplicates, all collinear.
/// Returns the convex hull boundary, counter-clockwise, including collinear boundary points.
template <class P>
std::vector<int> checked_hull_boundary(const P& pts)
{
  const int n = int(pts.size());
  if(n < 3) throw std::invalid_argument("minimum_weight_triangulation_2: needs at least 3 points, got " + std::to_string(n));
  for(int i = 0; i < n; ++i)
    if(!std::isfinite(pts.x(i)) || !std::isfinite(pts.y(i)))
      throw std::invalid_argument("minimum_weight_triangulation_2: point " + std::to_string(i) + " has a non-finite coordinate");
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  auto less = [&](int a, int b) {
    const auto &A = pts.point(a), &B = pts.point(b);
    return A.x() < B.x() || (A.x() == B.x() && A.y() < B.y());
  };
  std::sort(order.begin(), order.end(), less);
  for(int i = 1; i < n; ++i)
    if(!less(order[i - 1], order[i]))
      throw std::invalid_argument("minimum_weight_triangulation_2: duplicate points " + std::to_string(order[i - 1]) +
                                  " and " + std::to_string(order[i]));
  bool collinear = true;
  for(int i = 2; i < n && collinear; ++i) collinear = pts.orientation(order[0], order[1], order[i]) == 0;
  if(collinear) throw std::invalid_argument("minimum_weight_triangulation_2: all points are collinear, there is no triangle");
  std::vector<int> lower, upper;
  for(int i = 0; i < n; ++i) {
    while(lower.size() >= 2 && pts.orientation(lower[lower.size() - 2], lower.back(), order[i]) < 0) lower.pop_back();
    lower.push_back(order[i]);
  }
  for(int i = n - 1; i >= 0; --i) {
    while(upper.size() >= 2 && pts.orientation(upper[upper.size() - 2], upper.back(), order[i]) < 0) upper.pop_back();
    upper.push_back(order[i]);
  }
  lower.pop_back();
  upper.pop_back();
  lower.insert(lower.end(), upper.begin(), upper.end());
  return lower;
}

/// Base angle of the diamond test and its tangent (rounded down).
inline double diamond_angle() { return 3.14159265358979323846 / 4.6; }
inline double diamond_tangent() { static const double t = std::tan(diamond_angle()) * (1 - 1e-12); return t; }

/// Conservative inside test of r in the isosceles triangle over (p, q) with base angle pi/4.6 on r's side:
/// true only when r is strictly inside by a margin larger than the rounding error.
template <class P>
bool in_diamond_half(const P& pts, int p, int q, int r)
{
  const double ux = pts.x(q) - pts.x(p), uy = pts.y(q) - pts.y(p);
  const double vx = pts.x(r) - pts.x(p), vy = pts.y(r) - pts.y(p);
  const double wx = pts.x(r) - pts.x(q), wy = pts.y(r) - pts.y(q);
  const double cross = std::abs(ux * vy - uy * vx);
  const double dot1 = ux * vx + uy * vy, dot2 = -(ux * wx + uy * wy);
  const double m = std::max({std::abs(pts.x(p)), std::abs(pts.y(p)), std::abs(pts.x(q)), std::abs(pts.y(q)),
                             std::abs(pts.x(r)), std::abs(pts.y(r))});
  const double eps = 2.3e-16, delta = 2 * eps * m;  // error bound of one coordinate difference
  const double U = std::abs(ux) + std::abs(uy), V = std::abs(vx) + std::abs(vy) + std::abs(wx) + std::abs(wy);
  const double err = 4 * delta * (U + V + 2 * delta) + 8 * eps * U * V;
  const double t = diamond_tangent();
  return cross + err < t * (dot1 - err) && cross + err < t * (dot2 - err);
}

/// Every segment (i, j) with no input point in its interior: O(n^2) segments, grid query each.
template <class P, class Progress>
std::vector<Edge> all_valid_edges(const P& pts, const Point_grid_2& grid, Progress& progress)
{
  const int n = int(pts.size());
  std::vector<Edge> out;
  CGAL::MDCS::internal::Progress_reporter<Progress> report(progress, "candidate edges", std::size_t(n));
  for(int p = 0; p < n; ++p) {
    report(std::size_t(p));
    for(int q = p + 1; q < n; ++q) {
      const bool blocked = grid.any_in_box(std::min(pts.x(p), pts.x(q)), std::min(pts.y(p), pts.y(q)),
                                           std::max(pts.x(p), pts.x(q)), std::max(pts.y(p), pts.y(q)),
                                           [&](int r) { return r != p && r != q && pts.strictly_between(p, q, r); });
      if(!blocked) out.emplace_back(p, q);
    }
  }
  report.finish();
  return out;
}

/// Diamond-test candidates: for each point, grid rings are searched outward until every direction is
/// proven dead beyond the searched radius (a point r at distance d and angle theta kills, on one side,
/// every edge in the directions (theta - a, theta) or (theta, theta + a) longer than 2 cos(a) d, a = pi/4.6).
template <class P, class Progress>
std::vector<Edge> diamond_candidate_edges(const P& pts, const Point_grid_2& grid, Progress& progress)
{
  const int n = int(pts.size());
  const int S = 64;
  const double two_pi = 6.283185307179586, w = two_pi / S, pi8 = diamond_angle(), slack = 1e-9;
  const double kill_factor = 2 * std::cos(pi8) * (1 + 1e-6);   // 2 cos(pi/4.6) = 1.5505
  std::vector<Edge> out;
  std::vector<double> kl(S), kr(S);
  std::vector<std::pair<int, double>> seen;
  // far[s]: the farthest point of the bounding box in the (slightly widened) direction sector s of p; a sector
  // is finished once the searched radius passes it, even if no point killed it (points near the boundary)
  double bx0 = HUGE_VAL, by0 = HUGE_VAL, bx1 = -HUGE_VAL, by1 = -HUGE_VAL;
  for(int i = 0; i < n; ++i) {
    bx0 = std::min(bx0, pts.x(i)); bx1 = std::max(bx1, pts.x(i));
    by0 = std::min(by0, pts.y(i)); by1 = std::max(by1, pts.y(i));
  }
  const double diag = std::hypot(bx1 - bx0, by1 - by0);
  std::vector<double> far(S);
  auto exit_distance = [&](double px, double py, double a) {
    const double dx = std::cos(a), dy = std::sin(a);
    double t = HUGE_VAL;
    if(dx > 1e-300) t = std::min(t, (bx1 - px) / dx);
    if(dx < -1e-300) t = std::min(t, (bx0 - px) / dx);
    if(dy > 1e-300) t = std::min(t, (by1 - py) / dy);
    if(dy < -1e-300) t = std::min(t, (by0 - py) / dy);
    return std::max(0.0, t);
  };
  auto compute_far = [&](int p) {
    const double px = pts.x(p), py = pts.y(p), widen = 1e-6;
    const double cxs[4] = {bx0, bx1, bx1, bx0}, cys[4] = {by0, by0, by1, by1};
    for(int s = 0; s < S; ++s) {
      const double a0 = s * w - widen, a1 = (s + 1) * w + widen;
      double f = std::max(exit_distance(px, py, a0), exit_distance(px, py, a1));
      for(int c = 0; c < 4; ++c) {
        double a = std::atan2(cys[c] - py, cxs[c] - px);
        if(a < a0) a += two_pi;
        if(a >= a0 && a <= a1) f = std::max(f, std::hypot(cxs[c] - px, cys[c] - py));
      }
      far[s] = f * (1 + 1e-9) + 1e-12 * diag;
    }
  };
  CGAL::MDCS::internal::Progress_reporter<Progress> report(progress, "candidate edges", std::size_t(n));
  auto angle = [&](int p, int r) {
    double a = std::atan2(pts.y(r) - pts.y(p), pts.x(r) - pts.x(p));
    return a < 0 ? a + two_pi : a;
  };
  auto kill = [&](std::vector<double>& k, double lo, double hi, double d) {
    const int s0 = int(std::ceil(lo / w)), s1 = int(std::floor(hi / w)) - 1;
    for(int s = s0; s <= s1; ++s) {
      double& v = k[((s % S) + S) % S];
      v = std::min(v, d);
    }
  };
  for(int p = 0; p < n; ++p) {
    report(std::size_t(p));
    std::fill(kl.begin(), kl.end(), HUGE_VAL);
    std::fill(kr.begin(), kr.end(), HUGE_VAL);
    seen.clear();
    compute_far(p);
    const int ci = grid.cx(pts.x(p)), cj = grid.cy(pts.y(p));
    const double c = grid.cell_size();
    for(int k = 0;; ++k) {
      for(int j = cj - k; j <= cj + k; ++j) {
        if(j < 0 || j >= grid.ny()) continue;
        const bool full_row = (j == cj - k || j == cj + k);
        for(int i = ci - k; i <= ci + k; i += (full_row || k == 0) ? 1 : 2 * k) {
          if(i < 0 || i >= grid.nx()) continue;
          for(const int* it = grid.begin(i, j); it != grid.end(i, j); ++it) {
            const int r = *it;
            if(r == p) continue;
            const double d = std::hypot(pts.x(r) - pts.x(p), pts.y(r) - pts.y(p));
            const double th = angle(p, r);
            seen.emplace_back(r, th);
            kill(kl, th - pi8 + slack, th - slack, kill_factor * d);
            kill(kr, th + slack, th + pi8 - slack, kill_factor * d);
          }
        }
      }
      const bool all = ci - k <= 0 && cj - k <= 0 && ci + k >= grid.nx() - 1 && cj + k >= grid.ny() - 1;
      if(all) break;
      const double reach = k * c * (1 - 1e-9);
      bool done = true;
      for(int s = 0; s < S && done; ++s) done = std::max(kl[s], kr[s]) < reach || far[s] < reach;
      if(done) break;
    }
    for(const auto& rs : seen) {
      const int q = rs.first;
      if(q < p) continue;
      const double d = std::hypot(pts.x(q) - pts.x(p), pts.y(q) - pts.y(p));
      const int s = std::min(S - 1, int(rs.second / w));
      if(d > std::max(kl[s], kr[s])) continue;   // proven dead by the kill regions
      // exact diamond test with the grid
      const double mx = 0.5 * (pts.x(p) + pts.x(q)), my = 0.5 * (pts.y(p) + pts.y(q));
      const double hh = 0.5 * std::tan(pi8) * (1 + 1e-6);   // apex height / |pq|
      const double hx = -(pts.y(q) - pts.y(p)) * hh, hy = (pts.x(q) - pts.x(p)) * hh;
      const double x0 = std::min({pts.x(p), pts.x(q), mx + hx, mx - hx}), x1 = std::max({pts.x(p), pts.x(q), mx + hx, mx - hx});
      const double y0 = std::min({pts.y(p), pts.y(q), my + hy, my - hy}), y1 = std::max({pts.y(p), pts.y(q), my + hy, my - hy});
      bool left = false, right = false;
      const bool dead = grid.any_in_box(x0, y0, x1, y1, [&](int r) {
        if(r == p || r == q) return false;
        const int o = pts.orientation(p, q, r);
        if(o == 0) return pts.strictly_between(p, q, r);
        if(o > 0 ? left : right) return false;
        if(in_diamond_half(pts, p, q, r)) (o > 0 ? left : right) = true;
        return left && right;
      });
      if(!dead) out.emplace_back(p, q);
    }
  }
  report.finish();
  return out;
}

} // namespace internal
} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_CANDIDATE_EDGES_2_H
