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
#include <CGAL/Minimum_weight_triangulation_2/internal/Parallel_stage_2.h>
#include <CGAL/MDCS/concurrency.h>
#include <CGAL/MDCS/progress.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
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
/// Returns the convex hull boundary, counter-clockwise, including collinear boundary points. The points are
/// sorted in parallel (`par`; a stable sort, so the same order for every thread count).
template <class P>
std::vector<int> checked_hull_boundary(const P& pts, const Parallel_stage& par = Parallel_stage())
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
  parallel_stable_sort(order, less, par);
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

/// Polar angle of (dx, dy) != (0, 0) in [0, 2 pi], with an absolute error below fast_angle_error(): the odd
/// polynomial of Abramowitz and Stegun 4.4.49 for atan on [0, 1] (error 2e-8; 1.4e-8 measured on 2e7 samples).
inline double fast_angle(double dx, double dy)
{
  const double ax = std::abs(dx), ay = std::abs(dy);
  const double t = ax >= ay ? ay / ax : ax / ay, z = t * t;
  double a = t * (1 + z * (-0.3333314528 + z * (0.1999355085 + z * (-0.1420889944 + z * (0.1065626393 +
             z * (-0.0752896400 + z * (0.0429096138 + z * (-0.0161657367 + z * 0.0028662257))))))));
  if(ay > ax) a = 1.5707963267948966 - a;
  if(dx < 0) a = 3.141592653589793 - a;
  if(dy < 0) a = 6.283185307179586 - a;
  return a;
}
inline double fast_angle_error() { return 1e-7; }

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

/// Every segment (i, j) with no input point in its interior: O(n^2) segments, grid query each. Blocks of
/// points p in parallel (`par`), their edges (p, q > p) joined in the order of p.
template <class P, class Progress>
std::vector<Edge> all_valid_edges(const P& pts, const Point_grid_2& grid, Progress& progress,
                                  const Parallel_stage& par = Parallel_stage())
{
  const int n = int(pts.size());
  std::vector<Edge> out;
  CGAL::MDCS::Parallel_progress<Progress> report(progress, "candidate edges", std::size_t(n));
  par.append_in_order(std::size_t(n), 16, out, [&](std::size_t b0, std::size_t b1, std::vector<Edge>& o) {
    if(report.cancelled()) return;
    for(int p = int(b0); p < int(b1); ++p)
      for(int q = p + 1; q < n; ++q) {
        const bool blocked = grid.any_in_box(std::min(pts.x(p), pts.x(q)), std::min(pts.y(p), pts.y(q)),
                                             std::max(pts.x(p), pts.x(q)), std::max(pts.y(p), pts.y(q)),
                                             [&](int r) { return r != p && r != q && pts.strictly_between(p, q, r); });
        if(!blocked) o.emplace_back(p, q);
      }
    report.advance(b1 - b0);
  });
  report.finish();
  return out;
}

/// Exact (conservative) search in the half of the diamond of (p, q) on the side `side` (+1 left, -1 right):
/// 2 when an input point lies in the open segment pq (then pq is no edge), 1 when an input point lies strictly
/// inside that half, 0 otherwise. The search box holds the segment, so a 0 also says that pq is not blocked.
template <class P>
int diamond_half_state(const P& pts, const Point_grid_2& grid, int p, int q, int side)
{
  const double px = pts.x(p), py = pts.y(p), qx = pts.x(q), qy = pts.y(q);
  static const double hh = 0.5 * std::tan(diamond_angle()) * (1 + 1e-6);   // apex height / |pq|, rounded up
  const double ax = 0.5 * (px + qx) - side * (qy - py) * hh, ay = 0.5 * (py + qy) + side * (qx - px) * hh;
  int state = 0;
  grid.any_in_box_xy(std::min({px, qx, ax}), std::min({py, qy, ay}), std::max({px, qx, ax}), std::max({py, qy, ay}),
                  [&](int r, double rx, double ry) {
                    if(r == p || r == q) return false;
                    const int o = pts.orientation(p, q, r, rx, ry);
                    if(o == 0) {
                      if(pts.strictly_between(p, q, r)) { state = 2; return true; }
                      return false;
                    }
                    if(o == side && in_diamond_half(pts, p, q, r)) { state = 1; return true; }
                    return false;
                  });
  return state;
}

/*!
  Diamond-test candidates, in two passes.

  Pass 1, for each point p: grid rings are searched outward until every direction sector is proven dead beyond
  the searched radius (a point r at distance d and angle theta proves, on one side, that every edge from p in
  the directions (theta - a, theta) or (theta, theta + a) longer than 2 cos(a) d has a point in that half of
  its diamond, a = pi/4.6). After the first rings, a cell is skipped when every direction from p into it lies
  in sectors that are finished and outside the kill wedges of the unfinished sides (a 64-bit sector mask per
  cell offset, and beyond ring 32 per block of 32 cells of a ring's side first): near the boundary of the point
  set only the thin wedges along it are searched far. The bound of
  sector s (both sides) is kept per point (rounded up to float); the pairs (p, q > p) not proven dead are kept
  with the sides proven occupied.
  Pass 2: a pair is also dropped when q's bound for the direction q -> p proves it dead; the others get the
  exact test, side by side, on the grid cells of that half only (a half proven occupied is not searched).
  Points near the boundary of the point set have sectors that no point kills; the second pass keeps their
  long edges from costing a search over a large box each.

  Both passes run over blocks in parallel (`par`): a point's search writes its own bounds and pairs only, a
  pair's test its own verdict; the pairs and the edges are joined in block order, as the sequential loops
  make them.
*/
template <class P, class Progress>
std::vector<Edge> diamond_candidate_edges(const P& pts, const Point_grid_2& grid, Progress& progress,
                                          const Parallel_stage& par = Parallel_stage())
{
  const int n = int(pts.size());
  const int S = 64;
  const double two_pi = 6.283185307179586, w = two_pi / S, pi8 = diamond_angle();
  // angles come from fast_angle (error below E = fast_angle_error()); a sector is marked only when it lies inside
  // the killed range with this margin (> 2 E) on both sides: a direction computed in sector s truly lies within E
  // of it, and the killing point's true angle within E of its computed one
  const double slack = 3 * fast_angle_error();
  const double kill_factor = 2 * std::cos(pi8) * (1 + 1e-6);   // 2 cos(pi/4.6) = 1.5505
  Uninit_vector<float> bound(std::size_t(n) * S);               // per point and sector: max(left, right) kill radius
  struct Pair { int p, q; unsigned char known; };               // known: bit 0 left occupied, bit 1 right occupied
  Uninit_vector<Pair> pairs;
  pairs.reserve(std::size_t(n) * 24);
  struct Seen { int r; double th, d; };
  double bx0 = HUGE_VAL, by0 = HUGE_VAL, bx1 = -HUGE_VAL, by1 = -HUGE_VAL;
  for(int i = 0; i < n; ++i) {
    bx0 = std::min(bx0, pts.x(i)); bx1 = std::max(bx1, pts.x(i));
    by0 = std::min(by0, pts.y(i)); by1 = std::max(by1, pts.y(i));
  }
  const double diag = std::hypot(bx1 - bx0, by1 - by0);
  // far[s]: the farthest point of the bounding box in the (slightly widened) direction sector s of p; a sector
  // is finished once the searched radius passes it, even if no point killed it (points near the boundary)
  const double widen = 1e-6;
  std::vector<double> ca0(S), sa0(S), ca1(S), sa1(S);
  for(int s = 0; s < S; ++s) {
    ca0[s] = std::cos(s * w - widen); sa0[s] = std::sin(s * w - widen);
    ca1[s] = std::cos((s + 1) * w + widen); sa1[s] = std::sin((s + 1) * w + widen);
  }
  auto exit_distance = [&](double px, double py, double dx, double dy) {
    double t = HUGE_VAL;
    if(dx > 1e-300) t = std::min(t, (bx1 - px) / dx);
    if(dx < -1e-300) t = std::min(t, (bx0 - px) / dx);
    if(dy > 1e-300) t = std::min(t, (by1 - py) / dy);
    if(dy < -1e-300) t = std::min(t, (by0 - py) / dy);
    return std::max(0.0, t);
  };
  auto angle = [](double dx, double dy) { return fast_angle(dx, dy); };
  auto sector = [&](double th) { return std::min(S - 1, int(th / w)); };
  // kill ranges in units of sectors, on arrays extended by X sectors on both sides (no modulo in the hot loop);
  // folded(k, s) is the bound of sector s
  const int X = 16;
  const double inv_w = 1 / w, a_w = pi8 / w, slack_w = slack / w;
  // floor and ceil of small values without a library call (|x| < 2^31)
  auto ifloor = [](double x) { const int i = int(x); return i - (x < double(i) ? 1 : 0); };
  auto iceil = [](double x) { const int i = int(x); return i + (x > double(i) ? 1 : 0); };
  auto kill = [&](double* k, double lo, double hi, double d) {
    const int s1 = ifloor(hi) - 1;
    for(int s = iceil(lo); s <= s1; ++s) k[s] = std::min(k[s], d);
  };
  auto rotl = [](std::uint64_t x, int t) { return t == 0 ? x : ((x << t) | (x >> (64 - t))); };
  auto folded = [&](const std::vector<double>& k, int s) {
    double v = k[std::size_t(s + X)];
    if(s < X) v = std::min(v, k[std::size_t(s + X + S)]);
    if(s >= S - X) v = std::min(v, k[std::size_t(s + X - S)]);
    return v;
  };
  auto round_up = [](double x) {
    if(!(x < 3e38)) return std::numeric_limits<float>::infinity();
    float f = float(x);
    if(double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
  };
  const int wedge = int(std::ceil(pi8 / w)) + 1;
  // the sectors of every direction of a vector in the box [x0, x1] x [y0, y1] (which does not hold the origin),
  // widened by the angle error: the directions form an arc shorter than pi around the centre's direction
  auto offset_mask = [&](double x0, double x1, double y0, double y1) {
    const double tc = angle(0.5 * (x0 + x1), 0.5 * (y0 + y1));
    double lo = 0, hi = 0;
    const double xs[2] = {x0, x1}, ys[2] = {y0, y1};
    for(int a = 0; a < 2; ++a)
      for(int b = 0; b < 2; ++b) {
        if(xs[a] == 0 && ys[b] == 0) return ~std::uint64_t(0);
        double d = angle(xs[a], ys[b]) - tc;
        if(d > 3.141592653589793) d -= two_pi;
        if(d < -3.141592653589793) d += two_pi;
        lo = std::min(lo, d);
        hi = std::max(hi, d);
      }
    double a0 = tc + lo - slack - 1e-9;
    if(a0 < 0) a0 += two_pi;
    const int s0 = ifloor(a0 / w), cnt = ifloor((a0 + (hi - lo) + 2 * slack + 2e-9) / w) - s0 + 1;
    if(cnt >= S) return ~std::uint64_t(0);
    const std::uint64_t run = (std::uint64_t(1) << cnt) - 1;
    const int sh = ((s0 % S) + S) % S;
    return sh == 0 ? run : ((run << sh) | (run >> (S - sh)));
  };
  // cell_mask[(di, dj)]: the sectors of every direction from a point of a cell to a point of the cell (di, dj)
  // cells away, |di|, |dj| <= K, max(|di|, |dj|) >= 2: the directions of the box [(di-1)c, (di+1)c] x
  // [(dj-1)c, (dj+1)c], which does not hold the origin (the scale c does not change the directions)
  const int K = 32;
  std::vector<std::uint64_t> cell_mask(std::size_t(2 * K + 1) * std::size_t(2 * K + 1), ~std::uint64_t(0));
  for(int dj = -K; dj <= K; ++dj)
    for(int di = -K; di <= K; ++di)
      if(std::max(std::abs(di), std::abs(dj)) >= 2)
        cell_mask[std::size_t(di + K) + std::size_t(2 * K + 1) * std::size_t(dj + K)] =
          offset_mask(di - 1.0, di + 1.0, dj - 1.0, dj + 1.0);
  // pass 1 counts one step per point, pass 2 as many steps in all
  CGAL::MDCS::Parallel_progress<Progress> report(progress, "candidate edges", 2 * std::size_t(n));
  // pass 1 on a block of points [p0, p1): a workspace per block (a few kB)
  auto search_block = [&](std::size_t p0, std::size_t p1, Uninit_vector<Pair>& block_pairs) {
    if(report.cancelled()) return;
    std::vector<double> kl(S), kr(S), far(S), kle(S + 2 * X), kre(S + 2 * X);
    std::vector<Seen> seen;
    // far_of(s) is computed when first needed (most sectors are finished by kills)
    double corner_angle[4], corner_distance[4];
    bool corners_done = false;
    auto far_of = [&](int p, int s) {
      if(far[s] >= 0) return far[s];
      const double px = pts.x(p), py = pts.y(p);
      if(!corners_done) {
        const double cxs[4] = {bx0, bx1, bx1, bx0}, cys[4] = {by0, by0, by1, by1};
        for(int c = 0; c < 4; ++c) {
          corner_angle[c] = std::atan2(cys[c] - py, cxs[c] - px);
          if(corner_angle[c] < 0) corner_angle[c] += two_pi;
          corner_distance[c] = std::hypot(cxs[c] - px, cys[c] - py);
        }
        corners_done = true;
      }
      const double a0 = s * w - widen, a1 = (s + 1) * w + widen;
      double f = std::max(exit_distance(px, py, ca0[s], sa0[s]), exit_distance(px, py, ca1[s], sa1[s]));
      for(int c = 0; c < 4; ++c) {
        double a = corner_angle[c];
        if(a < a0) a += two_pi;
        if(a >= a0 && a <= a1) f = std::max(f, corner_distance[c]);
      }
      return far[s] = f * (1 + 1e-9) + 1e-12 * diag;
    };
    for(int p = int(p0); p < int(p1); ++p) {
      std::fill(kle.begin(), kle.end(), HUGE_VAL);
      std::fill(kre.begin(), kre.end(), HUGE_VAL);
      std::fill(far.begin(), far.end(), -1.0);
      corners_done = false;
      seen.clear();
      const double px = pts.x(p), py = pts.y(p);
      const int ci = grid.cx(px), cj = grid.cy(py);
      const double c = grid.cell_size();
      // need: bit s set when sector s may still receive a kill or a candidate: an unfinished sector, and the
      // sectors of the kill wedges of its unfinished sides (a cell of a later ring meeting none of them is skipped:
      // its points are farther than the bounds of the sectors they could be candidates in or kill)
      std::uint64_t need = ~std::uint64_t(0);
      const double box_distance = std::min(std::min(px - bx0, bx1 - px), std::min(py - by0, by1 - py));
      auto visit_cell = [&](int i, int j) {
        for(int it = grid.first(i, j); it != grid.first(i + 1, j); ++it) {
          const int r = grid.item(it);
          if(r == p) continue;
          const double dx = grid.item_x(it) - px, dy = grid.item_y(it) - py;
          const double d = std::sqrt(dx * dx + dy * dy);
          const double th = angle(dx, dy);
          seen.push_back(Seen{r, th, d});
          const double u = th * inv_w;
          kill(kle.data() + X, u - a_w + slack_w, u - slack_w, kill_factor * d);
          kill(kre.data() + X, u + slack_w, u + a_w - slack_w, kill_factor * d);
        }
      };
      // rings beyond K (points near the boundary of the point set): the ring's sides in blocks of 32 cells; a
      // block, then a cell, is skipped when the sectors of its offset box miss `need`
      const int block = 32;
      auto side = [&](bool row, int fixed, int from, int to) {
        for(int b0 = from; b0 <= to; b0 += block) {
          const int b1 = std::min(to, b0 + block - 1);
          const double f0 = fixed - (row ? cj : ci) - 1.0, f1 = f0 + 2;
          const double g0 = b0 - (row ? ci : cj) - 1.0, g1 = b1 - (row ? ci : cj) + 1.0;
          if((row ? offset_mask(g0, g1, f0, f1) : offset_mask(f0, f1, g0, g1)) & need) {
            for(int t = b0; t <= b1; ++t) {
              const int i = row ? t : fixed, j = row ? fixed : t;
              if(grid.first(i, j) == grid.first(i + 1, j)) continue;
              const double h0 = t - (row ? ci : cj) - 1.0, h1 = h0 + 2;
              if((row ? offset_mask(h0, h1, f0, f1) : offset_mask(f0, f1, h0, h1)) & need) visit_cell(i, j);
            }
          }
        }
      };
      for(int k = 0;; ++k) {
        if(k > K && need != ~std::uint64_t(0)) {
          const int i0 = std::max(0, ci - k), i1 = std::min(grid.nx() - 1, ci + k);
          const int j0 = std::max(0, cj - k + 1), j1 = std::min(grid.ny() - 1, cj + k - 1);
          if(cj - k >= 0) side(true, cj - k, i0, i1);
          if(cj + k < grid.ny()) side(true, cj + k, i0, i1);
          if(ci - k >= 0) side(false, ci - k, j0, j1);
          if(ci + k < grid.nx()) side(false, ci + k, j0, j1);
        } else {
          for(int j = cj - k; j <= cj + k; ++j) {
            if(j < 0 || j >= grid.ny()) continue;
            const bool full_row = (j == cj - k || j == cj + k);
            for(int i = ci - k; i <= ci + k; i += (full_row || k == 0) ? 1 : 2 * k) {
              if(i < 0 || i >= grid.nx()) continue;
              if(grid.begin(i, j) == grid.end(i, j)) continue;
              if(k >= 2 && k <= K && need != ~std::uint64_t(0) &&
                 (cell_mask[std::size_t(i - ci + K) + std::size_t(2 * K + 1) * std::size_t(j - cj + K)] & need) == 0) continue;
              visit_cell(i, j);
            }
          }
        }
        const bool all = ci - k <= 0 && cj - k <= 0 && ci + k >= grid.nx() - 1 && cj + k >= grid.ny() - 1;
        if(all) break;
        const double reach = k * c * (1 - 1e-9);
        // open: unfinished sectors; open_l / open_r: those whose left / right side is not yet killed
        std::uint64_t open = 0, open_l = 0, open_r = 0;
        for(int s = 0; s < S; ++s) {
          kl[s] = folded(kle, s);
          kr[s] = folded(kre, s);
          if(std::max(kl[s], kr[s]) < reach) continue;
          // far_of(s) >= the distance from p to the bounding box's boundary
          if(reach > box_distance && far_of(p, s) < reach) continue;
          const std::uint64_t bit = std::uint64_t(1) << s;
          open |= bit;
          if(!(kl[s] < reach)) open_l |= bit;
          if(!(kr[s] < reach)) open_r |= bit;
        }
        if(open == 0) break;
        // kl[s] comes from points at angles in (s w, (s + 1) w + a), kr[s] from (s w - a, (s + 1) w)
        need = open;
        for(int t = 1; t <= wedge; ++t) need |= rotl(open_l, t) | rotl(open_r, S - t);
      }
      for(int s = 0; s < S; ++s) { kl[s] = folded(kle, s); kr[s] = folded(kre, s); }
      float* B = bound.data() + std::size_t(p) * S;
      for(int s = 0; s < S; ++s) B[s] = round_up(std::max(kl[s], kr[s]));
      for(const Seen& x : seen) {
        if(x.r < p) continue;
        const int s = sector(x.th);
        if(x.d > std::max(kl[s], kr[s])) continue;   // proven dead by the kill regions
        block_pairs.push_back(Pair{p, x.r, (unsigned char)((x.d > kl[s] ? 1 : 0) | (x.d > kr[s] ? 2 : 0))});
      }
    }
    report.advance(p1 - p0);
  };
  par.append_in_order(std::size_t(n), 256, pairs, search_block);
  if(report.cancelled()) report.finish();   // throws
  // pass 2 (every bound of pass 1 is final): the pairs in blocks
  std::vector<Edge> out;
  out.reserve(pairs.size());
  const std::size_t pair_count = pairs.size();
  par.append_in_order(pair_count, 4096, out, [&](std::size_t b0, std::size_t b1, std::vector<Edge>& block_out) {
    if(report.cancelled()) return;
    for(std::size_t k = b0; k < b1; ++k) {
      const Pair& e = pairs[k];
      const int p = e.p, q = e.q;
      const double dx = pts.x(p) - pts.x(q), dy = pts.y(p) - pts.y(q);
      const double d = std::sqrt(dx * dx + dy * dy);
      if(double(bound[std::size_t(q) * S + sector(angle(dx, dy))]) * (1 + 1e-9) < d) continue;   // dead as seen from q
      // both halves occupied, or a point inside pq: no MWT edge; a half searched to the end also saw the segment
      const int left = (e.known & 1) ? 1 : diamond_half_state(pts, grid, p, q, 1);
      if(left == 2) continue;
      if(left == 0) { block_out.emplace_back(p, q); continue; }
      const int right = (e.known & 2) ? 1 : diamond_half_state(pts, grid, p, q, -1);
      if(right == 0) block_out.emplace_back(p, q);
    }
    // n steps over all the pairs (the integer parts telescope)
    report.advance(std::size_t((unsigned long long)(b1) * std::size_t(n) / pair_count -
                          (unsigned long long)(b0) * std::size_t(n) / pair_count));
  });
  report.finish();
  return out;
}

} // namespace internal
} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_CANDIDATE_EDGES_2_H
