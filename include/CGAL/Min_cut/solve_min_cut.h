// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// solve_min_cut(): the minimum s-t cut of a Flow_network and the primal chain it stands for.

#ifndef CGAL_MIN_CUT_SOLVE_MIN_CUT_H
#define CGAL_MIN_CUT_SOLVE_MIN_CUT_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Min_cut/Boykov_kolmogorov_max_flow.h>
#include <CGAL/Min_cut/Flow_network.h>
#include <CGAL/Min_cut/Pseudoflow_max_flow.h>
#include <CGAL/Min_cut/Push_relabel_max_flow.h>

#include <cstddef>
#include <cstdint>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Min_cut {

#ifdef DOXYGEN_RUNNING
/*!
  \ingroup PkgMinCutConcepts
  \cgalConcept

  A max-flow engine computes a maximum flow and a minimum cut of a `Max_flow_problem`: a network
  given as plain read-only data (number of nodes; per node the summed source and sink capacities;
  the list of arc pairs `u, v, c_uv, c_vu`), with every infinite capacity already replaced by the
  finite bound `M`. Nothing in it refers to Boost, so any max-flow code can be wrapped: Kolmogorov's
  maxflow library (`add_node`, `add_tweights`, `add_edge(u, v, c_uv, c_vu)`), EIBFS, HPF, ...

  \cgalHasModel `CGAL::Min_cut::Push_relabel_max_flow` (the default of `solve_min_cut()`)
  \cgalHasModel `CGAL::Min_cut::Boykov_kolmogorov_max_flow`
*/
class MaxFlowEngine
{
public:
  /// Computes a maximum flow of `problem` and returns its value. Resizes `on_source_side` to
  /// `problem.number_of_nodes()` and sets entry `i` to 1 if node `i` is on the source side of a
  /// minimum cut, 0 otherwise. Any minimum cut is valid; the models of this package return the
  /// minimal source side (nodes reachable from the source in the final residual network).
  /// May be non-const: `solve_min_cut()` calls it once on its own copy of the engine.
  template <class Capacity>
  Capacity operator()(const CGAL::Min_cut::Max_flow_problem<Capacity>& problem, std::vector<char>& on_source_side);
};
#endif

/// A facet of the primal chain: the caller's facet id, and for an interior facet (u, v) whether the
/// cut arc is `u->v` (`forward == true`, u on the source side) or `v->u`. Terminal facets have `forward == true`.
struct Cut_facet
{
  std::uint32_t id; // Flow_network<>::Facet_index
  bool forward;
};

/*!
  \ingroup PkgMinCutRef
  \brief The result of `solve_min_cut()`.

  - `on_source_side[i]` is 1 if node `i` is on the source side, 0 otherwise. The source side is the
    minimal one: the nodes that every minimum cut puts on the source side (with the engines of this
    package; a user engine may return any minimum cut). Nodes that the source cannot reach at all,
    isolated nodes among them, are on the sink side.
  - `chain` is the primal chain, the boundary of the source side: every interior facet whose two
    cells lie on different sides (in insertion order, zero-capacity facets included, since the
    chain must be closed), then every source facet whose node is on the sink side, then every sink
    facet whose node is on the source side.
  - `value` is the sum of the capacities of the cut arcs, i.e. of the chain.
  - `is_finite` is false when every cut crosses an arc of infinite capacity, that is, when the
    constraints expressed by infinite capacities cannot all hold. Then `value` is `+infinity`, and
    the sides and the chain describe a cut that crosses infinite arcs (useful to locate the conflict).
*/
template <class Capacity>
struct Min_cut_result
{
  Capacity value;
  bool is_finite;
  std::vector<char> on_source_side;
  std::vector<Cut_facet> chain;
};

/// The engine `solve_min_cut()` uses when none is given: pseudoflow. On the duals of line
/// arrangements (terminal arcs only on the boundary, infinite "stay a function" arcs: a maximum
/// closure problem) it measured 6-7 times faster than Boost's push-relabel from 3*10^4 to 2.6*10^6
/// nodes, with 35 instead of 60 bytes per arc, and identical values and sides
/// (benchmark/Min_cut/bench_engines_1d.cpp). Push-relabel was in turn 2-7 times faster than
/// Boykov-Kolmogorov on such networks above 10^5 nodes (benchmark/Min_cut/bench_min_cut.cpp).
/// Tables in doc/Min_cut/Min_cut.md.
typedef Pseudoflow_max_flow Default_max_flow_engine;

/*!
  \ingroup PkgMinCutRef
  \brief Computes a minimum s-t cut of `network` and the primal chain it stands for.

  Infinite capacities are replaced by the finite bound `M = 1 + 2 * (sum of all finite capacities)`
  (see `Max_flow_problem`); no cut that avoids infinite arcs costs `M / 2` or more, so the cut is
  declared infinite exactly when the maximum flow reaches `M` (or the returned cut crosses an
  infinite arc). An infinite result is reported as `is_finite == false` and `value == +infinity`,
  never as a large finite number.

  \tparam Capacity a floating-point type
  \tparam Engine a model of `MaxFlowEngine`: `Push_relabel_max_flow` (default) or `Boykov_kolmogorov_max_flow`
  \tparam Progress a callable `bool(const char* stage, double fraction)`; the stages are `"network"`
          (building the engine's view) and `"max-flow"` (reported at 0 and 1 only: the engines
          cannot report partial progress). Returning `false` cancels.

  \throws CGAL::MDCS::Operation_cancelled when `progress` returns false
  \throws std::domain_error when the finite capacities are too large to replace infinity safely
  \throws std::invalid_argument when the network exceeds the engine's limits (32-bit indices), or the
          engine breaks its contract (wrong number of sides)
  \throws std::length_error when the engine runs out of memory (a huge node count: isolated nodes are allowed)

  \warning The flow is computed in floating point. The value is recomputed exactly as the sum of
  the chain's capacities, but two cuts whose values differ by rounding (about the machine epsilon
  times the sum of the capacities, infinite ones counted as `M`) may be confused.
*/
template <class Capacity, class Engine = Default_max_flow_engine, class Progress = CGAL::MDCS::No_progress>
Min_cut_result<Capacity> solve_min_cut(const Flow_network<Capacity>& network, Engine engine = Engine(),
                                       Progress progress = Progress())
{
  typedef CGAL::MDCS::internal::Progress_reporter<Progress> Reporter;
  const std::size_t n = network.number_of_nodes();

  Min_cut_result<Capacity> result;
  Capacity flow = 0;
  Reporter network_stage(progress, "network", 1);
  try {
    const Max_flow_problem<Capacity> problem(network);
    network_stage.finish();
    Reporter max_flow_stage(progress, "max-flow", 1);
    flow = engine(problem, result.on_source_side);
    max_flow_stage.finish();
    flow = flow >= problem.infinite_capacity() ? Flow_network<Capacity>::infinity() : flow;
  } catch(const std::bad_alloc&) {
    // isolated nodes are allowed, so a node count alone is no error; running out of memory on it is reported
    throw std::length_error("MDCS: solve_min_cut: out of memory for a network of " + std::to_string(n) + " nodes and " +
                            std::to_string(network.number_of_facets() + network.number_of_source_facets() +
                                           network.number_of_sink_facets()) +
                            " facets (the engines need tens of bytes per node and per arc)");
  }
  if(result.on_source_side.size() != n)
    throw std::invalid_argument("MDCS: solve_min_cut: the max-flow engine returned " +
                                std::to_string(result.on_source_side.size()) + " node sides for " +
                                std::to_string(n) + " nodes");

  // The value is summed over the cut itself rather than taken from the engine, so that it equals
  // the capacity of the returned chain and carries true infinities.
  const Capacity inf = Flow_network<Capacity>::infinity();
  const std::vector<char>& side = result.on_source_side;
  Capacity value = 0;
  bool crosses_infinite_arc = false;
  auto cut = [&](std::uint32_t id, bool forward, Capacity c) {
    result.chain.push_back(Cut_facet{id, forward});
    if(c == inf) crosses_infinite_arc = true;
    else value += c;
  };
  for(const auto& f : network.facets()) {
    if(side[f.u] && !side[f.v]) cut(f.id, true, f.c_uv);
    else if(!side[f.u] && side[f.v]) cut(f.id, false, f.c_vu);
  }
  for(const auto& f : network.source_facets())
    if(!side[f.node]) cut(f.id, true, f.capacity);
  for(const auto& f : network.sink_facets())
    if(side[f.node]) cut(f.id, true, f.capacity);

  // The two tests agree for an exact minimum cut; either alone suffices to show that the
  // constraints conflict, so rounding cannot turn an infeasible problem into a finite value.
  result.is_finite = !crosses_infinite_arc && flow != inf;
  result.value = result.is_finite ? value : inf;
  return result;
}

} // namespace Min_cut
} // namespace CGAL

#endif // CGAL_MIN_CUT_SOLVE_MIN_CUT_H
