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
#include <cstdint>
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
/// triangles at(e, s) as a compressed array (32-bit offsets: 3 entries per triangle, at most 2^32 - 1).
class Edge_triangles
{
public:
  Edge_triangles(const Triangle_set& tri, std::size_t m) : start_(2 * m + 1, 0)
  {
    if(3 * tri.size() >= std::size_t(UINT32_MAX))
      throw std::length_error("minimum_weight_triangulation_2: too many empty triangles for 32-bit indices");
    for(std::size_t t = 0; t < tri.size(); ++t)
      for(int i = 0; i < 3; ++i) ++start_[slot(tri.edge(int(t), i), tri.side(int(t), i)) + 1];
    for(std::size_t k = 1; k < start_.size(); ++k) start_[k] += start_[k - 1];
    item_.resize(start_.back());
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for(std::size_t t = 0; t < tri.size(); ++t)
      for(int i = 0; i < 3; ++i) item_[fill[slot(tri.edge(int(t), i), tri.side(int(t), i))]++] = int(t);
  }
  const int* begin(int e, int s) const { return item_.data() + start_[2 * std::size_t(e) + std::size_t(s)]; }
  const int* end(int e, int s) const { return item_.data() + start_[2 * std::size_t(e) + std::size_t(s) + 1]; }

private:
  static std::size_t slot(int e, int side) { return 2 * std::size_t(e) + (side > 0 ? 0 : 1); }
  std::vector<std::uint32_t> start_;
  std::vector<int> item_;
};

/*!
  Marks every edge impossible, possible or certain. `tri` are the empty triangles over `edges` (all of them,
  before `remove_unusable_triangles`), `by_edge` their lists per edge and side, `is_hull` flags hull edges
  (always certain).
*/
template <class P, class Progress>
std::vector<char> lmt_skeleton(const P& pts, const std::vector<Edge>& edges, const Triangle_set& tri,
                               const Edge_triangles& by_edge, const std::vector<char>& is_hull, Progress& progress)
{
  const std::size_t m = edges.size();
  std::vector<char> alive(m, 1), queued(m, 1);
  auto tri_alive = [&](int t) {
    const auto& te = tri.edges(t);
    return alive[te[0]] && alive[te[1]] && alive[te[2]];
  };
  auto apex = [&](int t, int e) { return tri.apex(t, e); };
  // an interior edge keeps a witness: a live triangle on each side with a non-convex quadrilateral or |ab| <= |cd|
  // (c is strictly left and d strictly right of ab, so acbd is strictly convex iff cd crosses the line ab
  // between a and b)
  std::vector<int> right_apex;   // the apexes of the live triangles right of the edge (computed once per edge)
  auto has_witness = [&](int e) {
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
  std::vector<int> work;
  work.reserve(m);   // never more than m entries (queued): no growth by doubling
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
      for(const int* tp = by_edge.begin(e, s); tp != by_edge.end(e, s); ++tp)
        for(int i = 0; i < 3; ++i) {
          const int f = tri.edge(*tp, i);
          if(alive[f] && !is_hull[f] && !queued[f]) { queued[f] = 1; work.push_back(f); }
        }
  }
  report.finish();
  std::vector<int>().swap(work);       // release before the crossing tests (memory peak of the pipeline)
  std::vector<char>().swap(queued);

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
  std::vector<int> cell_item;
  std::vector<std::size_t> cell_fill;
  auto box = [&](int e, int& i0, int& i1, int& j0, int& j1) {
    const int a = edges[e].first, b = edges[e].second;
    i0 = cx(std::min(pts.x(a), pts.x(b))); i1 = cx(std::max(pts.x(a), pts.x(b)));
    j0 = cy(std::min(pts.y(a), pts.y(b))); j1 = cy(std::max(pts.y(a), pts.y(b)));
  };
  // cell lists as a compressed array (count, then fill)
  std::vector<std::size_t> cell_start(std::size_t(G) * G + 1, 0);
  for(int pass = 0; pass < 2; ++pass) {
    for(std::size_t e = 0; e < m; ++e) {
      if(!alive[e]) continue;
      int i0, i1, j0, j1;
      box(int(e), i0, i1, j0, j1);
      for(int j = j0; j <= j1; ++j)
        for(int i = i0; i <= i1; ++i) {
          const std::size_t c = std::size_t(i) + std::size_t(G) * std::size_t(j);
          if(pass == 0) ++cell_start[c + 1];
          else cell_item[cell_fill[c]++] = int(e);
        }
    }
    if(pass == 0) {
      for(std::size_t c = 1; c < cell_start.size(); ++c) cell_start[c] += cell_start[c - 1];
      cell_item.resize(cell_start.back());
      cell_fill.assign(cell_start.begin(), cell_start.end() - 1);
    }
  }
  std::vector<char> crossed(m, 0);
  std::vector<int> stamp(m, -1);
  for(std::size_t e = 0; e < m; ++e) {
    if(!alive[e] || crossed[e]) continue;
    int i0, i1, j0, j1;
    box(int(e), i0, i1, j0, j1);
    const int a = edges[e].first, b = edges[e].second;
    const double ex0 = std::min(pts.x(a), pts.x(b)), ex1 = std::max(pts.x(a), pts.x(b));
    const double ey0 = std::min(pts.y(a), pts.y(b)), ey1 = std::max(pts.y(a), pts.y(b));
    for(int j = j0; j <= j1 && !crossed[e]; ++j)
      for(int i = i0; i <= i1 && !crossed[e]; ++i)
        for(std::size_t k = cell_start[std::size_t(i) + std::size_t(G) * j]; k < cell_start[std::size_t(i) + std::size_t(G) * j + 1]; ++k) {
          const int f = cell_item[k];
          if(f == int(e) || stamp[f] == int(e)) continue;
          stamp[f] = int(e);
          const int c = edges[f].first, d = edges[f].second;
          // disjoint bounding boxes: no crossing
          if(std::max(pts.x(c), pts.x(d)) < ex0 || std::min(pts.x(c), pts.x(d)) > ex1 ||
             std::max(pts.y(c), pts.y(d)) < ey0 || std::min(pts.y(c), pts.y(d)) > ey1) continue;
          if(properly_cross(pts, edges[e].first, edges[e].second, c, d)) {
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
