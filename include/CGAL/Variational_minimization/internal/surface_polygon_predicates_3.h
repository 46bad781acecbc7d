// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact predicates on lattice polygons (integer coordinates below 2^17): the checks of a polygonal domain of
// Surface_problem_3 and the triangulation of its boundary loop.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_POLYGON_PREDICATES_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_POLYGON_PREDICATES_3_H

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

typedef std::array<std::int64_t, 2> Lattice_point_2;

// Twice the signed area (positive counter-clockwise); exact for coordinates below 2^30.
template <class Point>
std::int64_t lattice_polygon_area2(const std::vector<Point>& p)
{
  std::int64_t a = 0;
  for(std::size_t i = 0; i < p.size(); ++i) {
    const auto& u = p[i];
    const auto& v = p[(i + 1) % p.size()];
    a += u[0] * v[1] - u[1] * v[0];
  }
  return a;
}

// The sign of the orientation of (a, b, c): > 0 counter-clockwise.
template <class P, class Q, class R>
int orient_2_lattice(const P& a, const Q& b, const R& c)
{
  const std::int64_t d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  return d > 0 ? 1 : (d < 0 ? -1 : 0);
}

// Whether c lies on the closed segment a-b (given a, b, c collinear).
template <class P>
bool lattice_on_segment(const P& a, const P& b, const P& c)
{
  return (std::min)(a[0], b[0]) <= c[0] && c[0] <= (std::max)(a[0], b[0]) && (std::min)(a[1], b[1]) <= c[1] &&
         c[1] <= (std::max)(a[1], b[1]);
}

// Whether the closed segments p1-p2 and q1-q2 have a point in common.
template <class P>
bool lattice_segments_meet(const P& p1, const P& p2, const P& q1, const P& q2)
{
  const int d1 = orient_2_lattice(q1, q2, p1), d2 = orient_2_lattice(q1, q2, p2);
  const int d3 = orient_2_lattice(p1, p2, q1), d4 = orient_2_lattice(p1, p2, q2);
  if(d1 * d2 < 0 && d3 * d4 < 0) return true;
  return (d1 == 0 && lattice_on_segment(q1, q2, p1)) || (d2 == 0 && lattice_on_segment(q1, q2, p2)) ||
         (d3 == 0 && lattice_on_segment(p1, p2, q1)) || (d4 == 0 && lattice_on_segment(p1, p2, q2));
}

// A triangulation of the simple counter-clockwise polygon `p` (which may have vertices on straight angles) by ear
// clipping: index triples, every triangle with positive area. O(n^3) in the worst case, for boundary loops of a few
// hundred points.
template <class P>
std::vector<std::array<std::size_t, 3>> lattice_polygon_triangulation(const std::vector<P>& p)
{
  std::vector<std::size_t> live(p.size());
  for(std::size_t i = 0; i < p.size(); ++i) live[i] = i;
  std::vector<std::array<std::size_t, 3>> out;
  while(live.size() > 3) {
    const std::size_t n = live.size();
    bool clipped = false;
    for(std::size_t k = 0; k < n && !clipped; ++k) {
      const std::size_t a = live[(k + n - 1) % n], b = live[k], c = live[(k + 1) % n];
      if(orient_2_lattice(p[a], p[b], p[c]) <= 0) continue; // reflex or straight: no ear
      bool empty = true;
      for(std::size_t j = 0; j < n && empty; ++j) {
        const std::size_t v = live[j];
        if(v == a || v == b || v == c) continue;
        // No other vertex in the closed triangle (a vertex on the diagonal a-c would split it).
        if(orient_2_lattice(p[a], p[b], p[v]) >= 0 && orient_2_lattice(p[b], p[c], p[v]) >= 0 &&
           orient_2_lattice(p[c], p[a], p[v]) >= 0)
          empty = false;
      }
      if(!empty) continue;
      out.push_back({{a, b, c}});
      live.erase(live.begin() + std::ptrdiff_t(k));
      clipped = true;
    }
    if(!clipped) throw std::logic_error("MDCS: internal error: no ear in a simple polygon");
  }
  if(orient_2_lattice(p[live[0]], p[live[1]], p[live[2]]) <= 0)
    throw std::logic_error("MDCS: internal error: degenerate last triangle of a polygon triangulation");
  out.push_back({{live[0], live[1], live[2]}});
  return out;
}

// Whether the point (x, y) lies inside the polygon `p` (crossing number; a point on the boundary may go either way).
template <class P>
bool lattice_polygon_contains(const std::vector<P>& p, double x, double y)
{
  bool in = false;
  for(std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    const double xi = double(p[i][0]), yi = double(p[i][1]), xj = double(p[j][0]), yj = double(p[j][1]);
    if((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi) in = !in;
  }
  return in;
}

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_POLYGON_PREDICATES_3_H
