// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Test helpers of Minimum_weight_triangulation_2: point generators and an independent brute-force MWT
// (enumeration of all maximal non-crossing edge sets; no LP, no empty triangles).

#ifndef MDCS_TEST_MWT_TEST_HELPERS_H
#define MDCS_TEST_MWT_TEST_HELPERS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Minimum_weight_triangulation_2.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/Delaunay_triangulation_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace mwt_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;
namespace MWT = CGAL::Minimum_weight_triangulation_2;

inline std::vector<Point> uniform_points(int n, unsigned seed)
{
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point> p;
  for(int i = 0; i < n; ++i) p.emplace_back(u(g), u(g));
  return p;
}

inline std::vector<Point> clustered_points(int n, unsigned seed)
{
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> nd(0, 0.03);
  std::vector<Point> centres;
  for(int i = 0; i < 5; ++i) centres.emplace_back(u(g), u(g));
  std::vector<Point> p;
  for(int i = 0; i < n; ++i) {
    const Point& c = centres[i % 5];
    p.emplace_back(c.x() + nd(g), c.y() + nd(g));
  }
  return p;
}

/// The wheel of the thesis: a centre and k points evenly on the unit circle.
inline std::vector<Point> wheel(int k)
{
  std::vector<Point> p{Point(0, 0)};
  for(int i = 0; i < k; ++i) {
    const double a = 2 * M_PI * i / k;
    p.emplace_back(std::cos(a), std::sin(a));
  }
  return p;
}

/// Length according to the metric.
inline double length(const Point& a, const Point& b, MWT::Edge_metric m = MWT::Edge_metric::L2)
{
  const double dx = b.x() - a.x(), dy = b.y() - a.y();
  if(m == MWT::Edge_metric::L1) return std::abs(dx) + std::abs(dy);
  if(m == MWT::Edge_metric::Linf) return std::max(std::abs(dx), std::abs(dy));
  return std::sqrt(dx * dx + dy * dy);
}

/// The segments between input points (a < b) with no input point in their relative interior: the possible
/// triangulation edges. Exact orientation tests.
inline std::vector<std::pair<int, int>> valid_segments(const std::vector<Point>& p)
{
  const int n = int(p.size());
  std::vector<std::pair<int, int>> E;
  for(int a = 0; a < n; ++a)
    for(int b = a + 1; b < n; ++b) {
      bool ok = true;
      for(int c = 0; c < n && ok; ++c)
        if(c != a && c != b && CGAL::orientation(p[a], p[b], p[c]) == CGAL::COLLINEAR &&
           CGAL::collinear_are_strictly_ordered_along_line(p[a], p[c], p[b]))
          ok = false;
      if(ok) E.emplace_back(a, b);
    }
  return E;
}

/// cross[i][j]: segments E[i] and E[j] (no shared end point) cross properly.
inline std::vector<std::vector<char>> crossing_matrix(const std::vector<Point>& p,
                                                      const std::vector<std::pair<int, int>>& E)
{
  auto orient = [&](int a, int b, int c) { return int(CGAL::orientation(p[a], p[b], p[c])); };
  const std::size_t M = E.size();
  std::vector<std::vector<char>> cross(M, std::vector<char>(M, 0));
  for(std::size_t i = 0; i < M; ++i)
    for(std::size_t j = i + 1; j < M; ++j) {
      const int a = E[i].first, b = E[i].second, c = E[j].first, d = E[j].second;
      if(a == c || a == d || b == c || b == d) continue;
      cross[i][j] = cross[j][i] = orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0;
    }
  return cross;
}

/// A segment with no input point strictly on one of its sides: an edge of the convex hull boundary.
inline bool is_hull_segment(const std::vector<Point>& p, const std::pair<int, int>& e)
{
  int pos = 0, neg = 0;
  for(const Point& q : p) {
    const CGAL::Orientation o = CGAL::orientation(p[e.first], p[e.second], q);
    pos += o == CGAL::LEFT_TURN;
    neg += o == CGAL::RIGHT_TURN;
  }
  return pos == 0 || neg == 0;
}

/// Brute force: minimum over all triangulations (maximal non-crossing sets of segments with no point in
/// their interior, of size 3n - h - 3) of the total edge length. Exponential: n <= 9.
inline double brute_force_mwt(const std::vector<Point>& p, MWT::Edge_metric m = MWT::Edge_metric::L2)
{
  const int n = int(p.size());
  const std::vector<std::pair<int, int>> E = valid_segments(p);
  // h: points on the hull boundary
  std::set<int> hull_pts;
  for(const auto& e : E)
    if(is_hull_segment(p, e)) { hull_pts.insert(e.first); hull_pts.insert(e.second); }
  const std::size_t target = 3 * std::size_t(n) - hull_pts.size() - 3;
  const std::size_t M = E.size();
  const std::vector<std::vector<char>> cross = crossing_matrix(p, E);
  std::vector<double> w(M);
  for(std::size_t i = 0; i < M; ++i) w[i] = length(p[E[i].first], p[E[i].second], m);
  double best = std::numeric_limits<double>::infinity();
  std::vector<std::size_t> chosen;
  std::function<void(std::size_t, double)> rec = [&](std::size_t i, double sum) {
    if(sum >= best) return;
    if(chosen.size() == target) { best = sum; return; }
    if(i == M || chosen.size() + (M - i) < target) return;
    bool free = true;
    for(std::size_t c : chosen) if(cross[i][c]) { free = false; break; }
    if(free) {
      chosen.push_back(i);
      rec(i + 1, sum + w[i]);
      chosen.pop_back();
    }
    rec(i + 1, sum);
  };
  rec(0, 0.0);
  return best;
}

/// Independent check: the triangles' edges do not cross properly, the count is 2n - h - 2 and the total
/// area equals the hull area (so the triangles tile the hull once).
inline bool independent_triangulation_check(const std::vector<Point>& p, const std::vector<std::array<int, 3>>& tri)
{
  std::set<std::pair<int, int>> E;
  double area = 0;
  for(const auto& t : tri) {
    area += CGAL::to_double(CGAL::area(p[t[0]], p[t[1]], p[t[2]]));
    for(int i = 0; i < 3; ++i) E.insert(std::minmax(t[i], t[(i + 1) % 3]));
  }
  std::vector<std::pair<int, int>> v(E.begin(), E.end());
  for(std::size_t i = 0; i < v.size(); ++i)
    for(std::size_t j = i + 1; j < v.size(); ++j) {
      const int a = v[i].first, b = v[i].second, c = v[j].first, d = v[j].second;
      if(a == c || a == d || b == c || b == d) continue;
      if(CGAL::do_intersect(K::Segment_2(p[a], p[b]), K::Segment_2(p[c], p[d]))) return false;
    }
  std::vector<Point> hull;
  CGAL::convex_hull_2(p.begin(), p.end(), std::back_inserter(hull));
  double hull_area = 0;
  for(std::size_t i = 1; i + 1 < hull.size(); ++i) hull_area += CGAL::to_double(CGAL::area(hull[0], hull[i], hull[i + 1]));
  return std::abs(area - hull_area) <= 1e-9 * std::max(1.0, hull_area);
}

inline double edge_weight(const std::vector<Point>& p, const std::vector<std::array<int, 3>>& tri,
                          MWT::Edge_metric m = MWT::Edge_metric::L2)
{
  std::set<std::pair<int, int>> E;
  for(const auto& t : tri)
    for(int i = 0; i < 3; ++i) E.insert(std::minmax(t[i], t[(i + 1) % 3]));
  double s = 0;
  for(const auto& e : E) s += length(p[e.first], p[e.second], m);
  return s;
}

// Options with the LMT-skeleton as the first stage.
inline MWT::Mwt_options lmt()
{
  MWT::Mwt_options o;
  o.use_lmt_skeleton = true;
  return o;
}

} // namespace mwt_test

#endif // MDCS_TEST_MWT_TEST_HELPERS_H
