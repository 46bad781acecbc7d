// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The residual graph of the surface problem's dual network read straight from a Plane_arrangement_3, for the
// pseudoflow solver of the Min_cut package (interface in CGAL/Min_cut/internal/Pseudoflow_csr_graph.h). No copy
// of the arcs: the cells' facet lists of the arrangement are the adjacency, and the only per-facet storage is one
// residual capacity (8 bytes).
#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_RESIDUAL_GRAPH_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_RESIDUAL_GRAPH_3_H

#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/internal/surface_dual_network_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

// The network is the one of surface_dual_network_3(): a non-vertical facet is an arc below->above of capacity
// w and an infinite arc above->below; a vertical facet is infinite both ways; floor and ceiling facets are terminal
// arcs of capacity w; side-wall facets tie their cell to a terminal, or give no arc.
//
// Residuals. An arc of infinite capacity can never saturate, so only the finite direction of a facet needs a
// residual: r[f] is the residual of below->above; above->below reads +infinity (pushing delta along it adds delta
// to r[f]); a vertical facet has r[f] = +infinity. Wall facets are no interior arcs: they read as self-loops with
// residual 0, and r[f] holds their terminal capacity instead (> 0: source arc, < 0: sink arc, 0: none).
// Terminals keep the finite bound M = 1 + 2 * (sum of finite capacities) for an infinite tie, as in
// CGAL::Min_cut::Max_flow_problem, so that excesses stay finite; interior arcs keep true infinities.
class Surface_residual_graph_3
{
public:
  typedef std::uint32_t Index;
  typedef Plane_arrangement_3 Arr;

  // `weight_of(f)` gives the weight of facet f (called once per non-vertical facet off the side walls, in
  // increasing order of f).
  template <class WeightOf>
  Surface_residual_graph_3(const Arr& arrangement, const WeightOf& weight_of, const Surface_problem_3& problem)
    : a_(arrangement)
  {
    const std::size_t nf = arrangement.number_of_facets();
    if(arrangement.number_of_cells() > std::size_t(0xFFFFFFFFu) - 3)
      throw std::invalid_argument("MDCS: minimize_surface_functional_3: too many cells for 32-bit node indices");
    sign_.resize(arrangement.number_of_planes());
    for(std::size_t p = 0; p < sign_.size(); ++p) {
      const auto c = arrangement.plane(Index(p)).c;
      sign_[p] = static_cast<signed char>(c > 0 ? 1 : (c < 0 ? -1 : 0));
    }
    const std::array<Wall_curve_3, 4> lower = wall_curves_3(problem.boundary_loop(false));
    const std::array<Wall_curve_3, 4> upper = wall_curves_3(problem.boundary_loop(true));
    const double inf = std::numeric_limits<double>::infinity();
    r_.resize(nf);
    double finite_sum = 0;
    std::size_t ties = 0;
    for(std::size_t i = 0; i < nf; ++i) {
      const Index f = Index(i);
      const Index p = arrangement.facet(f).plane;
      if(p < 4) {
        const int tie = side_wall_tie_3(arrangement, f, lower, upper);
        r_[i] = double(tie); // scaled by M below
        ties += tie != 0 ? 1 : 0;
        continue;
      }
      if(p >= Arr::number_of_walls && sign_[p] == 0) {
        r_[i] = inf;
        continue;
      }
      const double w = weight_of(f);
      // Written as !(w >= 0) so that NaN is rejected too.
      if(!(w >= 0) || w == inf)
        throw std::invalid_argument("MDCS: minimize_surface_functional_3: facet " + std::to_string(i) +
                                    " has weight " + std::to_string(w) +
                                    "; the weight of a non-vertical facet must be finite and >= 0");
      finite_sum += w;
      r_[i] = p == 5 ? -w : w; // the ceiling's arcs go to the sink
    }
    bound_ = 1 + 2 * finite_sum;
    if(!std::isfinite(bound_) || !std::isfinite(finite_sum + double(ties + 1) * bound_))
      throw std::domain_error("MDCS: minimize_surface_functional_3: the facet weights are too large (their sum, or "
                              "the bound that replaces infinite capacities, overflows); scale them down");
    for(std::size_t i = 0; i < nf; ++i)
      if(arrangement.facet(Index(i)).plane < 4) r_[i] *= bound_;
  }

  std::size_t number_of_nodes() const { return a_.number_of_cells(); }
  Index degree(Index x) const { return Index(a_.cell_facets(x).size()); }
  Index arc(Index x, Index k) const { return a_.cell_facets(x)[k]; }

  Index head(Index x, Index f) const
  {
    const Arr::Facet& F = a_.facet(f);
    if(F.plane < Arr::number_of_walls) return x;
    return F.negative_cell == x ? F.positive_cell : F.negative_cell;
  }

  double residual(Index x, Index f) const
  {
    const Arr::Facet& F = a_.facet(f);
    if(F.plane < Arr::number_of_walls) return 0;
    return x == below(F) ? r_[f] : std::numeric_limits<double>::infinity();
  }

  Index reverse(Index, Index f) const { return f; }

  void push(Index x, Index f, double d)
  {
    if(x == below(a_.facet(f))) r_[f] -= d;
    else r_[f] += d;
  }

  // Only a finite residual saturates: the arc below->above.
  void saturate(Index, Index f) { r_[f] = 0; }

  double initial_excess(Index x) const
  {
    double source = 0, sink = 0;
    terminals(x, source, sink);
    return source - sink;
  }

  double capacity_scale(Index x) const
  {
    double source = 0, sink = 0;
    terminals(x, source, sink);
    // An infinite capacity counts as M, as in the Max_flow_problem of the same network; a finite one (at most
    // M / 2) as M too, an upper bound that needs no stored weights.
    double total = source + sink;
    for(Index f : a_.cell_facets(x))
      if(a_.facet(f).plane >= Arr::number_of_walls) total += 2 * bound_;
    return total;
  }

  /// The bound that stands for an infinite terminal capacity.
  double infinite_capacity() const { return bound_; }

  /// The cell of facet `f` below it (the tail of its finite arc); for a wall facet, its cell inside the box.
  Index below(const Arr::Facet& F) const
  {
    if(F.plane < Arr::number_of_walls) return F.negative_cell == Arr::null_index ? F.positive_cell : F.negative_cell;
    return sign_[F.plane] > 0 ? F.negative_cell : F.positive_cell;
  }

  /// The terminal capacity of a wall facet: > 0 an arc from the source, < 0 an arc to the sink (M for a tie).
  double terminal_capacity(Index f) const { return r_[f]; }

  std::size_t memory_bytes() const { return r_.capacity() * sizeof(double) + sign_.capacity(); }

private:
  // Per node, the summed source and sink capacities, each capped at M (one tie is enough).
  void terminals(Index x, double& source, double& sink) const
  {
    for(Index f : a_.cell_facets(x)) {
      if(a_.facet(f).plane >= Arr::number_of_walls) continue;
      const double c = r_[f];
      if(c > 0) source += c;
      else sink -= c;
    }
    source = (std::min)(source, bound_);
    sink = (std::min)(sink, bound_);
  }

  const Arr& a_;
  std::vector<double> r_;
  std::vector<signed char> sign_;
  double bound_ = 1;
};

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_RESIDUAL_GRAPH_3_H
