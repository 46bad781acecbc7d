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
//
// A polygonal domain (the network of build_polygon_dual_network_3()): a facet between two cells over Ω is an interior
// arc as above; a facet between a cell over Ω and the outside (or the box) is a terminal facet of that cell, like a
// wall: floor and ceiling facets with their weight, vertical facets tied to the source below the lower boundary
// curve and to the sink above the upper one; a facet with no cell over Ω gives no arc (residual 0, and G is not
// evaluated on it). Cells outside Ω stay isolated nodes. One byte per facet says which of these it is.
class Surface_residual_graph_3
{
public:
  typedef std::uint32_t Index;
  typedef Plane_arrangement_3 Arr;

  // `weight_of(f)` gives the weight of facet f (called once per non-vertical facet off the side walls, in
  // increasing order of f).
  template <class WeightOf>
  Surface_residual_graph_3(const Arr& arrangement, const WeightOf& weight_of, const Surface_problem_3& problem)
    : a_(arrangement), polygonal_(problem.is_polygonal())
  {
    const std::size_t nf = arrangement.number_of_facets();
    if(arrangement.number_of_cells() > std::size_t(0xFFFFFFFFu) - 3)
      throw std::invalid_argument("MDCS: minimize_surface_functional_3: too many cells for 32-bit node indices");
    sign_.resize(arrangement.number_of_planes());
    for(std::size_t p = 0; p < sign_.size(); ++p) {
      const auto c = arrangement.plane(Index(p)).c;
      sign_[p] = static_cast<signed char>(c > 0 ? 1 : (c < 0 ? -1 : 0));
    }
    const double inf = std::numeric_limits<double>::infinity();
    double finite_sum = 0;
    std::size_t ties = 0;
    // The weight of a non-vertical facet, checked.
    const auto checked_weight = [&](Index f) {
      const double w = weight_of(f);
      // Written as !(w >= 0) so that NaN is rejected too.
      if(!(w >= 0) || w == inf)
        throw std::invalid_argument("MDCS: minimize_surface_functional_3: facet " + std::to_string(f) +
                                    " has weight " + std::to_string(w) +
                                    "; the weight of a non-vertical facet must be finite and >= 0");
      finite_sum += w;
      return w;
    };
    // The arcs come from the builder that also writes the Flow_network of the generic path
    // (build_surface_dual_network_3), so both paths classify the facets the same way.
    r_.assign(nf, 0.0);
    if(polygonal_) kind_.assign(nf, no_arc);
    Residual_builder out{*this, ties};
    build_surface_dual_network_3(arrangement, checked_weight, problem, out);
    bound_ = 1 + 2 * finite_sum;
    if(!std::isfinite(bound_) || !std::isfinite(finite_sum + double(ties + 1) * bound_))
      throw std::domain_error("MDCS: minimize_surface_functional_3: the facet weights are too large (their sum, or "
                              "the bound that replaces infinite capacities, overflows); scale them down");
    // An infinite tie keeps the finite bound M instead (its sign says source or sink).
    for(std::size_t i = 0; i < nf; ++i)
      if(is_tie(Index(i)) && r_[i] != 0) r_[i] = r_[i] > 0 ? bound_ : -bound_;
  }

  std::size_t number_of_nodes() const { return a_.number_of_cells(); }
  Index degree(Index x) const { return Index(a_.cell_facets(x).size()); }
  Index arc(Index x, Index k) const { return a_.cell_facets(x)[k]; }

  Index head(Index x, Index f) const
  {
    if(is_terminal(f)) return x;
    const Arr::Facet& F = a_.facet(f);
    return F.negative_cell == x ? F.positive_cell : F.negative_cell;
  }

  double residual(Index x, Index f) const
  {
    if(is_terminal(f)) return 0;
    return x == below(a_.facet(f)) ? r_[f] : std::numeric_limits<double>::infinity();
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
      if(!is_terminal(f)) total += 2 * bound_;
    return total;
  }

  /// The bound that stands for an infinite terminal capacity.
  double infinite_capacity() const { return bound_; }

  /// The cell below an interior facet (the tail of its finite arc).
  Index below(const Arr::Facet& F) const { return sign_[F.plane] > 0 ? F.negative_cell : F.positive_cell; }

  /// Whether facet `f` is no arc between two nodes: a wall facet of a rectangle, or a facet of a polygonal domain
  /// with at most one cell over Ω (terminal arc of that cell, or no arc at all).
  bool is_terminal(Index f) const
  {
    return polygonal_ ? kind_[f] != interior : a_.facet(f).plane < Arr::number_of_walls;
  }

  /// The node a terminal facet ties (its cell inside the box, or over Ω).
  Index terminal_cell(Index f) const
  {
    const Arr::Facet& F = a_.facet(f);
    if(polygonal_) return kind_[f] == terminal_negative ? F.negative_cell : F.positive_cell;
    return F.negative_cell == Arr::null_index ? F.positive_cell : F.negative_cell;
  }

  /// Whether terminal facet `f` is an infinite tie (a vertical facet on the boundary), not a floor or ceiling arc.
  bool is_tie(Index f) const
  {
    const Index p = a_.facet(f).plane;
    if(polygonal_) return (kind_[f] == terminal_negative || kind_[f] == terminal_positive) && p != 4 && p != 5;
    return p < 4;
  }

  /// The terminal capacity of a terminal facet: > 0 an arc from the source, < 0 an arc to the sink (M for a tie),
  /// 0 none.
  double terminal_capacity(Index f) const { return r_[f]; }

  std::size_t memory_bytes() const { return r_.capacity() * sizeof(double) + sign_.capacity() + kind_.capacity(); }

private:
  // Fills the residuals from the dual network's arcs: an interior arc below->above holds its capacity (infinite for
  // a vertical facet); a terminal arc holds +c (from the source) or -c (to the sink), +-infinity for a tie until M
  // is known. Facets without an arc keep 0.
  struct Residual_builder
  {
    Surface_residual_graph_3& g;
    std::size_t& ties;
    bool needs_facet(Index, Index) const { return true; }
    bool needs_source_facet(Index) const { return true; }
    bool needs_sink_facet(Index) const { return true; }
    void add_facet(Index, Index, double c_uv, double, Index f)
    {
      g.r_[f] = c_uv;
      if(g.polygonal_) g.kind_[f] = interior;
    }
    void add_source_facet(Index n, double c, Index f) { terminal(n, c, f); }
    void add_sink_facet(Index n, double c, Index f) { terminal(n, -c, f); }
    void terminal(Index n, double c, Index f)
    {
      g.r_[f] = c;
      if(std::isinf(c)) ++ties;
      if(g.polygonal_) g.kind_[f] = n == g.a_.facet(f).negative_cell ? terminal_negative : terminal_positive;
    }
  };

  // Per node, the summed source and sink capacities, each capped at M (one tie is enough).
  void terminals(Index x, double& source, double& sink) const
  {
    for(Index f : a_.cell_facets(x)) {
      // A boundary facet of a polygonal domain is in the lists of both its cells: only its cell over Ω is tied.
      if(!is_terminal(f) || (polygonal_ && terminal_cell(f) != x)) continue;
      const double c = r_[f];
      if(c > 0) source += c;
      else sink -= c;
    }
    source = (std::min)(source, bound_);
    sink = (std::min)(sink, bound_);
  }

  // Kinds of the facets of a polygonal domain.
  enum : char { interior = 0, terminal_negative = 1, terminal_positive = 2, no_arc = 3 };

  const Arr& a_;
  bool polygonal_;
  std::vector<double> r_;
  std::vector<signed char> sign_;
  std::vector<char> kind_; // polygonal domains only
  double bound_ = 1;
};

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_RESIDUAL_GRAPH_3_H
