// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The directed dual flow network of a plane arrangement for the bivariate problem (thesis ch. 2.6.2).
#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_DUAL_NETWORK_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_DUAL_NETWORK_3_H

#include <CGAL/Min_cut/Flow_network.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/internal/surface_domain_cells_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
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

// The boundary curves of a polygonal domain, per edge, as functions of the position s in [0, 1] along the edge.
class Polygon_wall_curves_3
{
public:
  explicit Polygon_wall_curves_3(const Surface_problem_3& problem)
    : poly_(problem.lattice_polygon()), lower_(poly_.size()), upper_(poly_.size())
  {
    const std::vector<std::array<std::int64_t, 3>> samples = problem.polygon_samples();
    const std::vector<std::array<std::int64_t, 3>> lo = problem.boundary_loop(false), hi = problem.boundary_loop(true);
    for(std::size_t i = 0; i < samples.size(); ++i) {
      const std::size_t e = std::size_t(samples[i][2]);
      lower_[e].points.push_back({{position(e, samples[i][0], samples[i][1]), double(lo[i][2])}});
      upper_[e].points.push_back({{position(e, samples[i][0], samples[i][1]), double(hi[i][2])}});
      // The first sample of an edge (its first vertex) is the last point of the previous edge.
      if(i > 0 && samples[i - 1][2] == samples[i][2]) continue;
      const std::size_t p = (e + poly_.size() - 1) % poly_.size();
      lower_[p].points.push_back({{1.0, double(lo[i][2])}});
      upper_[p].points.push_back({{1.0, double(hi[i][2])}});
    }
    for(auto& c : lower_) std::sort(c.points.begin(), c.points.end());
    for(auto& c : upper_) std::sort(c.points.begin(), c.points.end());
  }

  // A vertical facet between a cell over Ω and the outside: +1 below the lower curve (source), -1 above the upper
  // curve (sink), 0 between them. Its centroid decides, against the curves of the nearest edge.
  int tie(const Plane_arrangement_3& arrangement, Plane_arrangement_3::Facet_index f) const
  {
    double x = 0, y = 0, z = 0;
    const std::size_t n = arrangement.facet_degree(f);
    for(std::size_t k = 0; k < n; ++k) {
      const std::array<double, 3>& p = arrangement.point(arrangement.facet_vertex(f, k));
      x += p[0]; y += p[1]; z += p[2];
    }
    x /= double(n); y /= double(n); z /= double(n);
    std::size_t best = 0;
    double best_d = std::numeric_limits<double>::infinity(), best_s = 0;
    for(std::size_t e = 0; e < poly_.size(); ++e) {
      const double s = (std::max)(0.0, (std::min)(1.0, position(e, x, y)));
      const auto& a = poly_[e];
      const auto& b = poly_[(e + 1) % poly_.size()];
      const double px = double(a[0]) + s * double(b[0] - a[0]) - x, py = double(a[1]) + s * double(b[1] - a[1]) - y;
      const double d = px * px + py * py;
      if(d < best_d) { best_d = d; best = e; best_s = s; }
    }
    if(z < lower_[best](best_s)) return 1;
    if(z > upper_[best](best_s)) return -1;
    return 0;
  }

private:
  double position(std::size_t e, double x, double y) const
  {
    const auto& a = poly_[e];
    const auto& b = poly_[(e + 1) % poly_.size()];
    const double dx = double(b[0] - a[0]), dy = double(b[1] - a[1]);
    return ((x - double(a[0])) * dx + (y - double(a[1])) * dy) / (dx * dx + dy * dy);
  }

  std::vector<Lattice_point_2> poly_;
  std::vector<Wall_curve_3> lower_, upper_;
};

// The networks below are written through a builder with the interface of CGAL::Min_cut::Flow_network (add_facet,
// add_source_facet, add_sink_facet) plus needs_facet(u, v), needs_source_facet(n), needs_sink_facet(n): a facet
// the builder does not need is skipped before its weight is asked for. `weight_of(f)` gives the weight of facet f
// (a callable; it is called only for non-vertical facets with a cell over the domain that the builder needs).
// Full_network_builder writes everything into a Flow_network; CGAL::Min_cut::internal::Terminal_contraction
// builds the contracted network of adaptive refinement directly.
struct Full_network_builder
{
  CGAL::Min_cut::Flow_network<double>& network;
  typedef CGAL::Min_cut::Flow_network<double>::Node_index Node_index;
  typedef CGAL::Min_cut::Flow_network<double>::Facet_index Facet_index;
  bool needs_facet(Node_index, Node_index) const { return true; }
  bool needs_source_facet(Node_index) const { return true; }
  bool needs_sink_facet(Node_index) const { return true; }
  void add_facet(Node_index u, Node_index v, double c_uv, double c_vu, Facet_index id) { network.add_facet(u, v, c_uv, c_vu, id); }
  void add_source_facet(Node_index n, double c, Facet_index id) { network.add_source_facet(n, c, id); }
  void add_sink_facet(Node_index n, double c, Facet_index id) { network.add_sink_facet(n, c, id); }
};

// The arcs of a facet between two cells over the domain: a non-vertical facet separates the cell below from the
// cell above, the arc below->above costs the facet weight and the reverse arc is infinite (so every finite cut is
// the graph of a function); a vertical facet is infinite both ways.
template <class Builder, class WeightOf>
void add_interior_facet_3(Builder& out, const Plane_arrangement_3::Facet& x, const Lattice_plane_3& p,
                          const WeightOf& weight_of, Plane_arrangement_3::Facet_index f)
{
  const double inf = std::numeric_limits<double>::infinity();
  if(!out.needs_facet(x.negative_cell, x.positive_cell)) return;
  if(p.c == 0) out.add_facet(x.negative_cell, x.positive_cell, inf, inf, f);
  else if(p.c > 0) out.add_facet(x.negative_cell, x.positive_cell, weight_of(f), inf, f);
  else out.add_facet(x.positive_cell, x.negative_cell, weight_of(f), inf, f);
}

// A polygonal domain: cells outside Ω get no arcs; a facet between a cell over Ω and the outside (or the box) ties
// that cell like a side wall: floor and ceiling facets with their weight, vertical facets infinitely below the
// lower curve (source) and above the upper one (sink).
template <class Builder, class WeightOf>
void build_polygon_dual_network_3(const Plane_arrangement_3& arrangement, const WeightOf& weight_of,
                                  const Surface_problem_3& problem, Builder& out)
{
  typedef Plane_arrangement_3 Arr;
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<char> inside = surface_domain_cells_3(arrangement, problem);
  const Polygon_wall_curves_3 curves(problem);
  for(std::size_t i = 0; i < arrangement.number_of_facets(); ++i) {
    const Arr::Facet_index f = Arr::Facet_index(i);
    const Arr::Facet& x = arrangement.facet(f);
    const bool in_n = x.negative_cell != Arr::null_index && inside[x.negative_cell];
    const bool in_p = x.positive_cell != Arr::null_index && inside[x.positive_cell];
    if(!in_n && !in_p) continue;
    const Lattice_plane_3& p = arrangement.plane(x.plane);
    if(in_n && in_p) {
      add_interior_facet_3(out, x, p, weight_of, f);
      continue;
    }
    const Arr::Cell_index cell = in_n ? x.negative_cell : x.positive_cell;
    if(x.plane == 4) {
      if(out.needs_source_facet(cell)) out.add_source_facet(cell, weight_of(f), f);
    } else if(x.plane == 5) {
      if(out.needs_sink_facet(cell)) out.add_sink_facet(cell, weight_of(f), f);
    } else if(p.c != 0)
      throw std::logic_error("MDCS: internal error: a non-vertical facet between a cell over the domain and the "
                             "outside (are the planes of the polygon's edges in the arrangement?)");
    else {
      const int tie = curves.tie(arrangement, f);
      if(tie > 0 && out.needs_source_facet(cell)) out.add_source_facet(cell, inf, f);
      else if(tie < 0 && out.needs_sink_facet(cell)) out.add_sink_facet(cell, inf, f);
    }
  }
}

// Cells are nodes. A non-vertical facet separates the cell below from the cell above: the arc below->above costs
// the facet weight, the reverse arc is infinite, so every finite cut is the graph of a function. Vertical facets
// are infinite both ways. Floor facets tie their cell to the source, ceiling facets to the sink, with their weight.
// Side-wall facets below the lower boundary curve tie their cell to the source, above the upper curve to the sink
// (infinitely); those between the curves (relaxed boundary) get no arc. A polygonal domain: see above.
template <class Builder, class WeightOf>
void build_surface_dual_network_3(const Plane_arrangement_3& arrangement, const WeightOf& weight_of,
                                  const Surface_problem_3& problem, Builder& out)
{
  if(problem.is_polygonal()) return build_polygon_dual_network_3(arrangement, weight_of, problem, out);
  typedef Plane_arrangement_3 Arr;
  const double inf = std::numeric_limits<double>::infinity();
  const std::array<Wall_curve_3, 4> lower = wall_curves_3(problem.boundary_loop(false));
  const std::array<Wall_curve_3, 4> upper = wall_curves_3(problem.boundary_loop(true));
  for(std::size_t i = 0; i < arrangement.number_of_facets(); ++i) {
    const Arr::Facet_index f = Arr::Facet_index(i);
    const Arr::Facet& x = arrangement.facet(f);
    const Arr::Cell_index inside = x.negative_cell == Arr::null_index ? x.positive_cell : x.negative_cell;
    if(x.plane == 4) {
      if(out.needs_source_facet(inside)) out.add_source_facet(inside, weight_of(f), f);
    } else if(x.plane == 5) {
      if(out.needs_sink_facet(inside)) out.add_sink_facet(inside, weight_of(f), f);
    } else if(x.plane < 4) {
      const int tie = side_wall_tie_3(arrangement, f, lower, upper);
      if(tie > 0 && out.needs_source_facet(inside)) out.add_source_facet(inside, inf, f);
      else if(tie < 0 && out.needs_sink_facet(inside)) out.add_sink_facet(inside, inf, f);
    } else {
      add_interior_facet_3(out, x, arrangement.plane(x.plane), weight_of, f);
    }
  }
}

// The whole network as a Flow_network, from a weight vector.
inline CGAL::Min_cut::Flow_network<double> surface_dual_network_3(const Plane_arrangement_3& arrangement,
                                                                  const std::vector<double>& weights,
                                                                  const Surface_problem_3& problem)
{
  CGAL::Min_cut::Flow_network<double> network;
  network.reserve(arrangement.number_of_cells(), arrangement.number_of_facets(), 0);
  network.add_nodes(arrangement.number_of_cells());
  Full_network_builder out{network};
  build_surface_dual_network_3(arrangement, [&](Plane_arrangement_3::Facet_index f) { return weights[f]; }, problem,
                               out);
  return network;
}

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_DUAL_NETWORK_3_H
