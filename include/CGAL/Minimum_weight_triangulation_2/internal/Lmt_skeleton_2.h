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
#include <CGAL/MDCS/progress.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {
namespace internal {

/// State of a candidate edge after the LMT-skeleton.
enum Lmt_edge_state : char { lmt_impossible = 0, lmt_possible = 1, lmt_certain = 2 };

/// Exact: |ab| <= |cd| (Euclidean).
template <class P>
bool not_longer(const P& pts, int a, int b, int c, int d)
{
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

/*!
  Marks every edge impossible, possible or certain. `tri` are the empty triangles over `edges` (all of them,
  before `remove_unusable_triangles`), `is_hull` flags hull edges (always certain).
*/
template <class P, class Progress>
std::vector<char> lmt_skeleton(const P& pts, const std::vector<Edge>& edges, const std::vector<Lp_triangle>& tri,
                               const std::vector<char>& is_hull, Progress& progress)
{
  const std::size_t m = edges.size();
  std::vector<std::vector<int>> side_tri[2];
  side_tri[0].resize(m);
  side_tri[1].resize(m);
  for(std::size_t t = 0; t < tri.size(); ++t)
    for(int i = 0; i < 3; ++i) side_tri[tri[t].side[i] > 0 ? 0 : 1][tri[t].edge[i]].push_back(int(t));
  std::vector<char> alive(m, 1), queued(m, 1);
  auto tri_alive = [&](int t) { return alive[tri[t].edge[0]] && alive[tri[t].edge[1]] && alive[tri[t].edge[2]]; };
  auto apex = [&](int t, int e) {
    for(int i = 0; i < 3; ++i)
      if(tri[t].edge[i] == e) return tri[t].v[(i + 2) % 3];
    return -1;
  };
  // an interior edge keeps a witness: a live triangle on each side with a non-convex quadrilateral or |ab| <= |cd|
  auto has_witness = [&](int e) {
    const int a = edges[e].first, b = edges[e].second;
    for(int t1 : side_tri[0][e]) {
      if(!tri_alive(t1)) continue;
      const int c = apex(t1, e);
      for(int t2 : side_tri[1][e]) {
        if(!tri_alive(t2)) continue;
        const int d = apex(t2, e);
        if(!properly_cross(pts, a, b, c, d)) return true;   // acbd not strictly convex: no flip
        if(not_longer(pts, a, b, c, d)) return true;
      }
    }
    return false;
  };
  std::vector<int> work;
  for(std::size_t e = 0; e < m; ++e)
    if(!is_hull[e]) work.push_back(int(e));
    else queued[e] = 0;
  std::reverse(work.begin(), work.end());
  CGAL::MDCS::internal::Progress_reporter<Progress> report(progress, "LMT-skeleton", m);
  std::size_t steps = 0;
  while(!work.empty()) {
    const int e = work.back();
    work.pop_back();
    queued[e] = 0;
    if(++steps <= m) report(steps);
    if(!alive[e] || has_witness(e)) continue;
    alive[e] = 0;
    for(int s = 0; s < 2; ++s)
      for(int t : side_tri[s][e])
        for(int i = 0; i < 3; ++i) {
          const int f = tri[t].edge[i];
          if(alive[f] && !is_hull[f] && !queued[f]) { queued[f] = 1; work.push_back(f); }
        }
  }
  report.finish();

  // certain: alive and crossed by no other alive edge (edges bucketed in a grid by bounding box)
  std::vector<char> state(m, lmt_impossible);
  double xmin = HUGE_VAL, ymin = HUGE_VAL, xmax = -HUGE_VAL, ymax = -HUGE_VAL;
  for(std::size_t i = 0; i < pts.size(); ++i) {
    xmin = std::min(xmin, pts.x(int(i))); xmax = std::max(xmax, pts.x(int(i)));
    ymin = std::min(ymin, pts.y(int(i))); ymax = std::max(ymax, pts.y(int(i)));
  }
  const int G = std::max(1, std::min(2048, int(std::sqrt(double(pts.size()) / 2.0))));
  const double wx = std::max(xmax - xmin, 1e-300) / G, wy = std::max(ymax - ymin, 1e-300) / G;
  auto cx = [&](double x) { return std::max(0, std::min(G - 1, int((x - xmin) / wx))); };
  auto cy = [&](double y) { return std::max(0, std::min(G - 1, int((y - ymin) / wy))); };
  std::vector<std::vector<int>> cell(std::size_t(G) * G);
  auto box = [&](int e, int& i0, int& i1, int& j0, int& j1) {
    const int a = edges[e].first, b = edges[e].second;
    i0 = cx(std::min(pts.x(a), pts.x(b))); i1 = cx(std::max(pts.x(a), pts.x(b)));
    j0 = cy(std::min(pts.y(a), pts.y(b))); j1 = cy(std::max(pts.y(a), pts.y(b)));
  };
  for(std::size_t e = 0; e < m; ++e) {
    if(!alive[e]) continue;
    int i0, i1, j0, j1;
    box(int(e), i0, i1, j0, j1);
    for(int j = j0; j <= j1; ++j)
      for(int i = i0; i <= i1; ++i) cell[std::size_t(i) + std::size_t(G) * j].push_back(int(e));
  }
  std::vector<char> crossed(m, 0);
  std::vector<int> stamp(m, -1);
  for(std::size_t e = 0; e < m; ++e) {
    if(!alive[e] || crossed[e]) continue;
    int i0, i1, j0, j1;
    box(int(e), i0, i1, j0, j1);
    for(int j = j0; j <= j1 && !crossed[e]; ++j)
      for(int i = i0; i <= i1 && !crossed[e]; ++i)
        for(int f : cell[std::size_t(i) + std::size_t(G) * j]) {
          if(f == int(e) || stamp[f] == int(e)) continue;
          stamp[f] = int(e);
          if(properly_cross(pts, edges[e].first, edges[e].second, edges[f].first, edges[f].second)) {
            crossed[e] = crossed[f] = 1;
            break;
          }
        }
  }
  for(std::size_t e = 0; e < m; ++e)
    if(is_hull[e]) state[e] = lmt_certain;
    else if(alive[e]) state[e] = crossed[e] ? lmt_possible : lmt_certain;
  return state;
}

} // namespace internal
} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_LMT_SKELETON_2_H
