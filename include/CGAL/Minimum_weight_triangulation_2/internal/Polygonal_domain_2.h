// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The work of polygon_with_holes_mwt_2(): a polygonal domain (an outer ring, holes, isolated interior points) in
// one vertex numbering, its input checks, the segments and empty triangles inside it, and its triangle LP (thesis
// ch. 3.2: every boundary edge covered once from its inner side, every other edge balanced) with the rigorous dual
// bound and the exact check that a 0/1 point of the LP is a triangulation of the domain. Exact predicates of the
// kernel throughout; lengths in double and in interval arithmetic.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_POLYGONAL_DOMAIN_2_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_POLYGONAL_DOMAIN_2_H

#include <CGAL/Minimum_weight_triangulation_2/Linear_program.h>
#include <CGAL/Minimum_weight_triangulation_2/Mwt_result.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Coordinate_range_2.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/MDCS/progress.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/intersections.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {
namespace internal {

// A polygonal domain in the numbering of polygon_with_holes_mwt_2(): the outer ring's vertices in input order,
// then each hole's in input order, then the interior points. Every ring is walked with the domain on its left
// (outer ring counter-clockwise, holes clockwise, whatever the input orientation): next[v] / prev[v] are the ring
// neighbours in that walk, -1 for an interior point.
template <class K>
class Polygonal_domain_2
{
public:
  typedef typename K::Point_2 Point_2;
  typedef typename K::Segment_2 Segment_2;
  typedef CGAL::Interval_nt<true> Interval;

  std::vector<Point_2> points;
  std::vector<int> ring_start;   // ring r has the vertices [ring_start[r], ring_start[r + 1]); ring 0 is outer
  std::vector<int> next, prev;
  int first_interior_point = 0;

  std::size_t size() const { return points.size(); }
  int holes() const { return int(ring_start.size()) - 2; }
  int interior_points() const { return int(points.size()) - first_interior_point; }
  bool on_boundary(int v) const { return v < first_interior_point; }
  double x(int i) const { return CGAL::to_double(points[std::size_t(i)].x()); }
  double y(int i) const { return CGAL::to_double(points[std::size_t(i)].y()); }

  // Triangles of every triangulation of the domain, by Euler's formula: V - E + (F + 1 + h) = 2 (the triangles,
  // the unbounded face, the h holes) and 3 F = 2 E - B (every edge in two triangles but the B boundary edges,
  // in one); with B = V - m (m interior points): F = V + m + 2 h - 2.
  std::size_t triangles_of_a_triangulation() const
  {
    return points.size() + std::size_t(interior_points()) + 2 * std::size_t(holes()) - 2;
  }

  // The domain from its rings and points, checked (std::invalid_argument, `who` starts the message).
  Polygonal_domain_2(const std::vector<std::vector<Point_2>>& rings, const std::vector<Point_2>& isolated,
                     const char* who)
    : who_(who)
  {
    for(std::size_t r = 0; r < rings.size(); ++r) {
      if(rings[r].size() < 3)
        fail(ring_name(int(r)) + " has " + std::to_string(rings[r].size()) + " vertices; a ring needs at least 3");
      ring_start.push_back(int(points.size()));
      points.insert(points.end(), rings[r].begin(), rings[r].end());
    }
    ring_start.push_back(int(points.size()));
    first_interior_point = int(points.size());
    points.insert(points.end(), isolated.begin(), isolated.end());
    check_coordinate_range(*this, who_);
    check_distinct();
    next.assign(points.size(), -1);
    prev.assign(points.size(), -1);
    for(int r = 0; r < int(rings.size()); ++r) {
      if(all_collinear(r)) fail(ring_name(r) + " has zero area (all its vertices are collinear)");
      check_simple_ring(r);
      const CGAL::Orientation o = ring_orientation(r);
      if(o == CGAL::COLLINEAR) fail(ring_name(r) + " has zero area");
      // the domain lies left of the walk: the outer ring counter-clockwise, a hole clockwise
      const bool forward = (r == 0) == (o == CGAL::COUNTERCLOCKWISE);
      const int b = ring_start[r], k = ring_start[r + 1] - b;
      for(int i = 0; i < k; ++i) {
        const int v = b + i, s = b + (i + 1) % k, p = b + (i + k - 1) % k;
        next[v] = forward ? s : p;
        prev[v] = forward ? p : s;
      }
    }
    check_rings_apart();
    check_nesting();
    check_interior_points();
  }

  // Whether the segment (a, b) between two vertices lies in the domain and meets its boundary and the vertices
  // only at a and b: boundary edges are; otherwise it must leave a and b into the domain (the cone of a ring
  // vertex; any direction from an interior point), pass through no vertex, and cross no boundary edge. Then it
  // cannot leave the domain in between (it would have to touch or cross the boundary). Exact.
  bool is_domain_segment(int a, int b) const
  {
    if(next[a] == b || next[b] == a) return true;
    if(!in_cone(a, b) || !in_cone(b, a)) return false;
    const auto orient = K().orientation_2_object();
    const Point_2 &pa = points[a], &pb = points[b];
    for(int c = 0; c < int(points.size()); ++c) {
      if(c == a || c == b) continue;
      const CGAL::Orientation oc = orient(pa, pb, points[c]);
      if(oc == CGAL::COLLINEAR && CGAL::collinear_are_ordered_along_line(pa, points[c], pb)) return false;
      const int d = next[c];
      if(d < 0 || d == a || d == b) continue;
      // a proper crossing of the boundary edge (c, d); touching is the vertex case above
      const CGAL::Orientation od = orient(pa, pb, points[d]);
      if(oc == CGAL::COLLINEAR || od == CGAL::COLLINEAR || oc == od) continue;
      const CGAL::Orientation o1 = orient(points[c], points[d], pa), o2 = orient(points[c], points[d], pb);
      if(o1 != CGAL::COLLINEAR && o2 != CGAL::COLLINEAR && o1 != o2) return false;
    }
    return true;
  }

  // The empty triangles of the domain, counter-clockwise index triples: their three sides are domain segments
  // and no vertex lies inside them (none lies on a side: a domain segment contains no vertex). A hole inside such
  // a triangle would put its vertices inside, so the triangle lies in the domain. The segments take O(V^2 (V + B))
  // orientation tests; the emptiness test is a bitwise AND of the sets of vertices strictly left of each side
  // (V / 64 words per triangle, the sets O(V^3) tests for the ordered pairs of segment ends). The progress
  // callback (stage "empty triangles") is asked about a hundred times.
  std::vector<std::array<int, 3>> empty_triangles(const std::function<bool(const char*, double)>& progress) const
  {
    const int n = int(points.size());
    const std::size_t N = std::size_t(n), W = (N + 63) / 64;
    const auto orient = K().orientation_2_object();
    auto ask = [&](double f) {
      if(progress && !progress("empty triangles", f)) throw CGAL::MDCS::Operation_cancelled("empty triangles");
    };
    ask(0);
    std::vector<char> segment(N * N, 0);
    // left[(u * n + v) * W ...]: the vertices strictly left of the line u -> v, for the segments (u, v) only
    std::vector<std::uint64_t> left;
    std::vector<std::size_t> left_of(N * N, std::size_t(-1));
    const int step = (std::max)(1, n / 50);
    for(int a = 0; a < n; ++a) {
      if(a % step == 0) ask(0.5 * a / n);
      for(int b = a + 1; b < n; ++b) {
        if(!is_domain_segment(a, b)) continue;
        segment[std::size_t(a) * N + b] = segment[std::size_t(b) * N + a] = 1;
        const std::size_t ab = left.size();
        left.resize(ab + 2 * W, 0);
        for(int v = 0; v < n; ++v) {
          const CGAL::Orientation o = orient(points[a], points[b], points[v]);
          if(o == CGAL::LEFT_TURN) left[ab + std::size_t(v) / 64] |= std::uint64_t(1) << (v % 64);
          else if(o == CGAL::RIGHT_TURN) left[ab + W + std::size_t(v) / 64] |= std::uint64_t(1) << (v % 64);
        }
        left_of[std::size_t(a) * N + b] = ab;
        left_of[std::size_t(b) * N + a] = ab + W;
      }
    }
    std::vector<std::array<int, 3>> tri;
    for(int a = 0; a < n; ++a) {
      if(a % step == 0) ask(0.5 + 0.5 * a / n);
      for(int b = a + 1; b < n; ++b) {
        if(!segment[std::size_t(a) * N + b]) continue;
        for(int c = b + 1; c < n; ++c) {
          if(!segment[std::size_t(a) * N + c] || !segment[std::size_t(b) * N + c]) continue;
          const CGAL::Orientation o = orient(points[a], points[b], points[c]);
          if(o == CGAL::COLLINEAR) continue;
          const std::array<int, 3> t = o == CGAL::LEFT_TURN ? std::array<int, 3>{a, b, c} : std::array<int, 3>{a, c, b};
          if(outside_side(t)) continue;
          // the corners are on the sides, never strictly left of all three
          const std::uint64_t* l0 = &left[left_of[std::size_t(t[0]) * N + t[1]]];
          const std::uint64_t* l1 = &left[left_of[std::size_t(t[1]) * N + t[2]]];
          const std::uint64_t* l2 = &left[left_of[std::size_t(t[2]) * N + t[0]]];
          bool empty = true;
          for(std::size_t w = 0; w < W && empty; ++w) empty = (l0[w] & l1[w] & l2[w]) == 0;
          if(empty) tri.push_back(t);
        }
      }
    }
    ask(1);
    return tri;
  }

  // Length of the segment (a, b) in the metric, in double and as an interval holding the exact length.
  double length(int a, int b, Edge_metric metric) const
  {
    const double dx = x(b) - x(a), dy = y(b) - y(a);
    switch(metric) {
      case Edge_metric::L1: return std::abs(dx) + std::abs(dy);
      case Edge_metric::Linf: return (std::max)(std::abs(dx), std::abs(dy));
      default: return std::sqrt(dx * dx + dy * dy);
    }
  }
  Interval interval_length(int a, int b, Edge_metric metric) const
  {
    const Interval dx = Interval(x(b)) - Interval(x(a)), dy = Interval(y(b)) - Interval(y(a));
    switch(metric) {
      case Edge_metric::L1: return CGAL::abs(dx) + CGAL::abs(dy);
      case Edge_metric::Linf: {
        const Interval ax = CGAL::abs(dx), ay = CGAL::abs(dy);
        return Interval((std::max)(ax.inf(), ay.inf()), (std::max)(ax.sup(), ay.sup()));
      }
      default: return CGAL::sqrt(CGAL::square(dx) + CGAL::square(dy));
    }
  }

  // Whether (a, b) is a boundary edge (either direction).
  bool is_boundary_edge(int a, int b) const { return next[a] == b || next[b] == a; }

  // Twice the area of the domain, exactly.
  CGAL::Exact_rational twice_area() const
  {
    CGAL::Exact_rational s(0);
    for(int v = 0; v < first_interior_point; ++v) {
      const int w = next[v];   // walks with the domain on the left: holes count negatively
      s += CGAL::Exact_rational(x(v)) * CGAL::Exact_rational(y(w)) - CGAL::Exact_rational(x(w)) * CGAL::Exact_rational(y(v));
    }
    return s;
  }

private:
  [[noreturn]] void fail(const std::string& what) const { throw std::invalid_argument(std::string(who_) + ": " + what); }

  std::string ring_name(int r) const { return r == 0 ? std::string("the outer boundary") : "hole " + std::to_string(r - 1); }

  // "vertex i of the outer boundary" / "vertex i of hole j" / "interior point i" for a global index
  std::string vertex_name(int v) const
  {
    if(v >= first_interior_point) return "interior point " + std::to_string(v - first_interior_point);
    int r = 0;
    while(ring_start[r + 1] <= v) ++r;
    return "vertex " + std::to_string(v - ring_start[r]) + " of " + ring_name(r);
  }

  int ring_of(int v) const
  {
    int r = 0;
    while(ring_start[r + 1] <= v) ++r;
    return r;
  }

  int input_next(int v) const
  {
    const int r = ring_of(v), b = ring_start[r], k = ring_start[r + 1] - b;
    return b + (v - b + 1) % k;
  }

  void check_distinct() const
  {
    std::vector<int> order(points.size());
    for(std::size_t i = 0; i < order.size(); ++i) order[i] = int(i);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      const CGAL::Comparison_result c = CGAL::compare_xy(points[a], points[b]);
      return c == CGAL::SMALLER || (c == CGAL::EQUAL && a < b);
    });
    for(std::size_t i = 1; i < order.size(); ++i)
      if(points[order[i - 1]] == points[order[i]])
        fail(vertex_name(order[i - 1]) + " and " + vertex_name(order[i]) + " coincide");
  }

  bool all_collinear(int r) const
  {
    const int b = ring_start[r], e = ring_start[r + 1];
    for(int i = b + 2; i < e; ++i)
      if(!CGAL::collinear(points[b], points[b + 1], points[i])) return false;
    return true;
  }

  // No two edges of ring r meet, except consecutive ones at their shared vertex (without overlapping).
  void check_simple_ring(int r) const
  {
    const auto orient = K().orientation_2_object();
    const int b = ring_start[r], k = ring_start[r + 1] - b;
    for(int i = 0; i < k; ++i)
      for(int j = i + 1; j < k; ++j) {
        const int i1 = (i + 1) % k, j1 = (j + 1) % k;
        if(j == i1 || i == j1) {
          const int shared = j == i1 ? j : i, u = j == i1 ? i : j, w = j == i1 ? j1 : i1;
          if(orient(points[b + u], points[b + shared], points[b + w]) == CGAL::COLLINEAR &&
             !CGAL::collinear_are_ordered_along_line(points[b + u], points[b + shared], points[b + w]))
            fail(ring_name(r) + " is not simple (its edges " + std::to_string(i) + " and " + std::to_string(j) +
                 " overlap)");
          continue;
        }
        if(CGAL::do_intersect(Segment_2(points[b + i], points[b + i1]), Segment_2(points[b + j], points[b + j1])))
          fail(ring_name(r) + " is not simple (its edges " + std::to_string(i) + " and " + std::to_string(j) + " meet)");
      }
  }

  // The orientation of a simple ring: the turn at its lowest-leftmost vertex (collinear only without area).
  CGAL::Orientation ring_orientation(int r) const
  {
    const int b = ring_start[r], k = ring_start[r + 1] - b;
    int m = 0;
    for(int i = 1; i < k; ++i)
      if(CGAL::compare_xy(points[b + i], points[b + m]) == CGAL::SMALLER) m = i;
    return K().orientation_2_object()(points[b + (m + k - 1) % k], points[b + m], points[b + (m + 1) % k]);
  }

  // No edge of a ring meets an edge of another ring (touching included: the domain's boundary must be a disjoint
  // union of simple cycles).
  void check_rings_apart() const
  {
    for(int u = 0; u < first_interior_point; ++u)
      for(int v = u + 1; v < first_interior_point; ++v) {
        const int ru = ring_of(u), rv = ring_of(v);
        if(ru == rv) continue;
        if(CGAL::do_intersect(Segment_2(points[u], points[input_next(u)]), Segment_2(points[v], points[input_next(v)])))
          fail(ring_name(ru) + " and " + ring_name(rv) + " cross or touch (edge from " + vertex_name(u) +
               " and edge from " + vertex_name(v) + ")");
      }
  }

  CGAL::Bounded_side side_of_ring(int r, const Point_2& p) const
  {
    return CGAL::bounded_side_2(points.begin() + ring_start[r], points.begin() + ring_start[r + 1], p, K());
  }

  // Rings apart: a hole lies inside the outer ring (one vertex tells), and inside no other hole.
  void check_nesting() const
  {
    for(int r = 1; r + 1 < int(ring_start.size()); ++r) {
      const Point_2& p = points[ring_start[r]];
      if(side_of_ring(0, p) != CGAL::ON_BOUNDED_SIDE) fail(ring_name(r) + " lies outside the outer boundary");
      for(int s = 1; s + 1 < int(ring_start.size()); ++s)
        if(s != r && side_of_ring(s, p) == CGAL::ON_BOUNDED_SIDE) fail(ring_name(r) + " lies inside " + ring_name(s));
    }
  }

  void check_interior_points() const
  {
    for(int v = first_interior_point; v < int(points.size()); ++v) {
      const CGAL::Bounded_side s = side_of_ring(0, points[v]);
      if(s == CGAL::ON_BOUNDARY) fail(vertex_name(v) + " lies on the outer boundary");
      if(s == CGAL::ON_UNBOUNDED_SIDE) fail(vertex_name(v) + " lies outside the outer boundary");
      for(int r = 1; r + 1 < int(ring_start.size()); ++r) {
        const CGAL::Bounded_side h = side_of_ring(r, points[v]);
        if(h == CGAL::ON_BOUNDARY) fail(vertex_name(v) + " lies on the boundary of " + ring_name(r));
        if(h == CGAL::ON_BOUNDED_SIDE) fail(vertex_name(v) + " lies inside " + ring_name(r));
      }
    }
  }

  // Whether the segment from vertex u toward vertex v starts into the domain (the open cone left of the walk at
  // a ring vertex; every direction at an interior point).
  bool in_cone(int u, int v) const
  {
    if(!on_boundary(u)) return true;
    const auto orient = K().orientation_2_object();
    const Point_2 &pu = points[u], &pv = points[v], &pn = points[next[u]], &pp = points[prev[u]];
    auto left = [&](const Point_2& a, const Point_2& b, const Point_2& c) { return orient(a, b, c) == CGAL::LEFT_TURN; };
    if(orient(pu, pn, pp) != CGAL::RIGHT_TURN)   // convex or flat corner
      return left(pu, pv, pp) && left(pv, pu, pn);
    return !(orient(pu, pv, pn) != CGAL::RIGHT_TURN && orient(pv, pu, pp) != CGAL::RIGHT_TURN);   // reflex corner
  }

  // A counter-clockwise triangle with a boundary edge walked against the domain's direction lies outside (cannot
  // happen for triangles of domain segments; a cheap guard).
  bool outside_side(const std::array<int, 3>& t) const
  {
    for(int i = 0; i < 3; ++i)
      if(next[t[(i + 1) % 3]] == t[i]) return true;
    return false;
  }

  const char* who_;
};

// The triangle LP of a domain (thesis ch. 3.2): one column per empty triangle, its cost the lengths of its sides,
// halved for the sides that are not boundary edges (so the objective of a triangulation is its weight); one row
// per boundary edge (its triangles on the inner side sum to 1) and per other domain segment that is a side of
// some triangle (triangles on its left minus those on its right: 0).
struct Domain_linear_program
{
  Sparse_linear_program lp;
  std::vector<std::pair<int, int>> row_edge;   // (a, b), a < b
  std::vector<char> row_is_boundary;

  template <class Domain>
  Domain_linear_program(const Domain& d, const std::vector<std::array<int, 3>>& triangles, Edge_metric metric)
  {
    const std::size_t N = d.size();
    std::vector<int> row_of(N * N, -1);   // by a * N + b, a < b
    auto add_row = [&](int a, int b) {
      int& row = row_of[std::size_t(a) * N + std::size_t(b)];
      if(row >= 0) return;
      const bool boundary = d.is_boundary_edge(a, b);
      row = boundary ? lp.add_row(1, 1) : lp.add_row(0, 0);
      row_edge.emplace_back(a, b);
      row_is_boundary.push_back(char(boundary));
    };
    for(const auto& t : triangles)
      for(int i = 0; i < 3; ++i) add_row(std::min(t[i], t[(i + 1) % 3]), std::max(t[i], t[(i + 1) % 3]));
    // a boundary edge no triangle covers leaves its row without entries: the LP is infeasible, as it must be
    for(int v = 0; v < int(d.first_interior_point); ++v) add_row(std::min(v, d.next[v]), std::max(v, d.next[v]));
    lp.cost.reserve(triangles.size());
    lp.col_lower.reserve(triangles.size());
    lp.col_upper.reserve(triangles.size());
    lp.column_start.reserve(triangles.size() + 1);
    lp.row_index.reserve(3 * triangles.size());
    lp.value.reserve(3 * triangles.size());
    for(const auto& t : triangles) {
      int rows[3];
      double coef[3];
      double cost = 0;
      for(int i = 0; i < 3; ++i) {
        const int a = t[i], b = t[(i + 1) % 3];
        rows[i] = row_of[std::size_t(std::min(a, b)) * N + std::size_t(std::max(a, b))];
        const bool boundary = row_is_boundary[std::size_t(rows[i])] != 0;
        // a side walked a -> b has the triangle on its left: +1 when a < b, -1 otherwise (boundary: always +1)
        coef[i] = boundary ? 1.0 : (a < b ? 1.0 : -1.0);
        cost += boundary ? d.length(a, b, metric) : 0.5 * d.length(a, b, metric);
      }
      lp.add_column(cost, 0, Sparse_linear_program::infinity(), rows, coef, 3);
    }
  }

  // A rigorous lower bound of the weight of every triangulation from duals y of the rows (any y): a
  // triangulation is a 0/1 point x of the LP, so its weight c x = b y + (c - A^T y) x >= b y + sum_j min(0, rc_j)
  // with b the right-hand sides (1 on the boundary rows). Costs and reduced costs in interval arithmetic.
  // -infinity when the duals are unusable.
  template <class Domain>
  double dual_lower_bound(const Domain& d, const std::vector<std::array<int, 3>>& triangles,
                          const std::vector<double>& y, Edge_metric metric) const
  {
    typedef CGAL::Interval_nt<true> Interval;
    if(y.size() != lp.number_of_rows) return -std::numeric_limits<double>::infinity();
    for(double v : y)
      if(!std::isfinite(v)) return -std::numeric_limits<double>::infinity();
    Interval bound(0);
    for(std::size_t i = 0; i < y.size(); ++i)
      if(row_is_boundary[i]) bound += Interval(y[i]);
    for(std::size_t j = 0; j < triangles.size(); ++j) {
      const auto& t = triangles[j];
      Interval rc(0);
      for(int i = 0; i < 3; ++i) {
        const int a = t[i], b = t[(i + 1) % 3];
        const Interval len = d.interval_length(a, b, metric);
        rc += d.is_boundary_edge(a, b) ? len : len / 2;
      }
      for(int k = lp.column_start[j]; k < lp.column_start[j + 1]; ++k)
        rc -= Interval(lp.value[std::size_t(k)]) * Interval(y[std::size_t(lp.row_index[std::size_t(k)])]);
      if(rc.inf() < 0) bound += Interval(rc.inf());
    }
    return bound.inf();
  }

  // Empty when the triangles (columns of the LP) chosen form a triangulation of the domain, else why not: the
  // count of Euler's formula, every boundary row covered once, every other row balanced (then the triangles,
  // all counter-clockwise, cover the domain exactly once: the winding number of their sum is 1 inside, 0 outside;
  // empty triangles tiling the domain meet edge to edge and use every interior point), and, as a check in exact
  // rationals, their areas summing to the domain's.
  template <class Domain>
  std::string not_a_triangulation(const Domain& d, const std::vector<std::array<int, 3>>& triangles,
                                  const std::vector<std::size_t>& chosen) const
  {
    if(chosen.size() != d.triangles_of_a_triangulation())
      return std::to_string(chosen.size()) + " triangles instead of " + std::to_string(d.triangles_of_a_triangulation());
    std::vector<long> sum(lp.number_of_rows, 0);
    CGAL::Exact_rational area(0);
    for(std::size_t j : chosen) {
      for(int k = lp.column_start[j]; k < lp.column_start[j + 1]; ++k)
        sum[std::size_t(lp.row_index[std::size_t(k)])] += long(lp.value[std::size_t(k)]);
      const auto& t = triangles[j];
      for(int i = 0; i < 3; ++i) {
        const int a = t[i], b = t[(i + 1) % 3];
        area += CGAL::Exact_rational(d.x(a)) * CGAL::Exact_rational(d.y(b)) -
                CGAL::Exact_rational(d.x(b)) * CGAL::Exact_rational(d.y(a));
      }
    }
    for(std::size_t i = 0; i < sum.size(); ++i)
      if(sum[i] != (row_is_boundary[i] ? 1 : 0))
        return "the edge (" + std::to_string(row_edge[i].first) + ", " + std::to_string(row_edge[i].second) + ") is " +
               (row_is_boundary[i] ? "not covered once" : "not balanced");
    if(area != d.twice_area()) return "the triangles' areas do not sum to the domain's area";
    return std::string();
  }
};

} // namespace internal
} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_POLYGONAL_DOMAIN_2_H
