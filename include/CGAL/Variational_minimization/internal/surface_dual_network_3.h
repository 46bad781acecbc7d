// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The directed dual flow network of a plane arrangement for the bivariate problem (thesis ch. 2.6.2).
#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_DUAL_NETWORK_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_DUAL_NETWORK_3_H

#include <CGAL/Min_cut/Flow_network.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

// The boundary curve on one side wall as a function of the wall coordinate s (lattice), piecewise linear.
struct Wall_curve_3
{
  std::vector<std::array<double, 2>> points; // (s, Z), sorted by s

  double operator()(double s) const
  {
    auto it = std::lower_bound(points.begin(), points.end(), s,
                               [](const std::array<double, 2>& p, double v) { return p[0] < v; });
    if(it == points.begin()) return points.front()[1];
    if(it == points.end()) return points.back()[1];
    const auto& b = *it;
    const auto& a = *(it - 1);
    if(b[0] == a[0]) return b[1];
    const double t = (s - a[0]) / (b[0] - a[0]);
    return a[1] + t * (b[1] - a[1]);
  }
};

// Wall w in 0..3 (planes X = 0, X = L, Y = 0, Y = L): the wall coordinate is Y for the X walls, X for the Y walls.
inline std::array<Wall_curve_3, 4> wall_curves_3(const std::vector<std::array<std::int64_t, 3>>& loop)
{
  const std::int64_t L = Plane_arrangement_3::lattice_size;
  std::array<Wall_curve_3, 4> out;
  for(const auto& p : loop) {
    if(p[0] == 0) out[0].points.push_back({{double(p[1]), double(p[2])}});
    if(p[0] == L) out[1].points.push_back({{double(p[1]), double(p[2])}});
    if(p[1] == 0) out[2].points.push_back({{double(p[0]), double(p[2])}});
    if(p[1] == L) out[3].points.push_back({{double(p[0]), double(p[2])}});
  }
  for(auto& c : out) std::sort(c.points.begin(), c.points.end());
  return out;
}

// A facet on a side wall (plane < 4): +1 if it lies below the lower boundary curve (its cell is tied to the
// source), -1 above the upper curve (tied to the sink), 0 between them (relaxed boundary: no arc). The centroid
// of the facet decides: the arrangement contains the boundary curves as edges (pencils of planes through their
// segments), so each wall facet lies on one side of each curve.
inline int side_wall_tie_3(const Plane_arrangement_3& arrangement, Plane_arrangement_3::Facet_index f,
                           const std::array<Wall_curve_3, 4>& lower, const std::array<Wall_curve_3, 4>& upper)
{
  const Plane_arrangement_3::Plane_index wall = arrangement.facet(f).plane;
  double s = 0, z = 0;
  const std::size_t n = arrangement.facet_degree(f);
  const int axis = wall < 2 ? 1 : 0;
  for(std::size_t k = 0; k < n; ++k) {
    const std::array<double, 3> p = arrangement.point(arrangement.facet_vertex(f, k));
    s += p[axis];
    z += p[2];
  }
  s /= double(n);
  z /= double(n);
  if(z < lower[wall](s)) return 1;
  if(z > upper[wall](s)) return -1;
  return 0;
}

// Cells are nodes. A non-vertical facet separates the cell below from the cell above: the arc below->above costs
// the facet weight, the reverse arc is infinite, so every finite cut is the graph of a function. Vertical facets
// are infinite both ways. Floor facets tie their cell to the source, ceiling facets to the sink, with their weight.
// Side-wall facets below the lower boundary curve tie their cell to the source, above the upper curve to the sink
// (infinitely); those between the curves (relaxed boundary) get no arc.
inline CGAL::Min_cut::Flow_network<double> surface_dual_network_3(const Plane_arrangement_3& arrangement,
                                                                  const std::vector<double>& weights,
                                                                  const Surface_problem_3& problem)
{
  typedef CGAL::Min_cut::Flow_network<double> Network;
  typedef Plane_arrangement_3 Arr;
  const double inf = Network::infinity();
  const std::array<Wall_curve_3, 4> lower = wall_curves_3(problem.boundary_loop(false));
  const std::array<Wall_curve_3, 4> upper = wall_curves_3(problem.boundary_loop(true));
  Network network;
  network.reserve(arrangement.number_of_cells(), arrangement.number_of_facets(), 0);
  network.add_nodes(arrangement.number_of_cells());
  for(std::size_t i = 0; i < arrangement.number_of_facets(); ++i) {
    const Arr::Facet_index f = Arr::Facet_index(i);
    const Arr::Facet& x = arrangement.facet(f);
    const Network::Facet_index id = Network::Facet_index(i);
    const Arr::Cell_index inside = x.negative_cell == Arr::null_index ? x.positive_cell : x.negative_cell;
    if(x.plane == 4) {
      network.add_source_facet(inside, weights[i], id);
    } else if(x.plane == 5) {
      network.add_sink_facet(inside, weights[i], id);
    } else if(x.plane < 4) {
      const int tie = side_wall_tie_3(arrangement, f, lower, upper);
      if(tie > 0) network.add_source_facet(inside, inf, id);
      else if(tie < 0) network.add_sink_facet(inside, inf, id);
    } else {
      const Lattice_plane_3& p = arrangement.plane(x.plane);
      if(p.c == 0) network.add_facet(x.negative_cell, x.positive_cell, inf, inf, id);
      else if(p.c > 0) network.add_facet(x.negative_cell, x.positive_cell, weights[i], inf, id);
      else network.add_facet(x.positive_cell, x.negative_cell, weights[i], inf, id);
    }
  }
  return network;
}

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_DUAL_NETWORK_3_H
