// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Globally minimal discrete curves by a min-cut of the directed dual graph of a line arrangement.

#ifndef CGAL_VARIATIONAL_MINIMIZATION_MINIMIZE_CURVE_FUNCTIONAL_2_H
#define CGAL_VARIATIONAL_MINIMIZATION_MINIMIZE_CURVE_FUNCTIONAL_2_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Min_cut/solve_min_cut.h>
#include <CGAL/Min_cut/solve_planar_min_cut.h>
#include <CGAL/Variational_minimization/Curve_problem_2.h>
#include <CGAL/Variational_minimization/Line_arrangement_2.h>
#include <CGAL/Variational_minimization/Minimal_curve_2.h>
#include <CGAL/Variational_minimization/curve_edge_weights_2.h>
#include <CGAL/Variational_minimization/internal/curve_dual_network_2.h>
#include <CGAL/Variational_minimization/internal/curve_from_edges_2.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/*!
  \brief Builds the arrangement of `lines` in the problem's box, with the side walls split at the end values.

  \throws std::invalid_argument when the problem is invalid (see `Curve_problem_2::validate()`), when `lines`
  is empty, or when no line crosses the interior of the box.
*/
template <class Progress = CGAL::MDCS::No_progress>
Line_arrangement_2 build_curve_arrangement_2(const Curve_problem_2& problem,
                                             const std::vector<Arrangement_line_2>& lines,
                                             Progress progress = Progress())
{
  problem.validate();
  if(lines.empty())
    throw std::invalid_argument("MDCS: a curve problem needs at least one line (the grid is empty)");
  Line_arrangement_2 arrangement(problem.box, lines, problem.left_marks(), problem.right_marks(), progress);
  bool any = false;
  for(std::size_t i = 0; i < arrangement.number_of_input_lines() && !any; ++i)
    any = arrangement.is_line_used(Line_arrangement_2::Line_index(i));
  if(!any)
    throw std::invalid_argument("MDCS: the arrangement is degenerate: none of the " + std::to_string(lines.size()) +
                                " lines crosses the interior of the box");
  return arrangement;
}

namespace internal {

inline Minimal_curve_2 curve_from_cut_2(const Line_arrangement_2& arrangement, const std::vector<double>& weights,
                                        const CGAL::Min_cut::Min_cut_result<double>& cut)
{
  Minimal_curve_2 curve;
  if(!cut.is_finite)
    return curve; // infeasible: no function on this grid meets the end conditions
  curve.is_feasible = true;
  curve.solver_value = cut.value;
  std::vector<Line_arrangement_2::Edge_index> edges;
  edges.reserve(cut.chain.size());
  for(const auto& facet : cut.chain) {
    if(!facet.forward)
      throw std::logic_error("MDCS: internal error: a finite cut crossed an edge downwards");
    edges.push_back(facet.id);
  }
  order_curve_edges(arrangement, weights, edges, curve);
  // finite weights (checked) may still add up beyond the double range: never report an infinite energy as feasible
  if(!std::isfinite(curve.energy) || !std::isfinite(curve.solver_value))
    throw std::invalid_argument("MDCS: the minimal curve's energy is not finite: the edge weights add up beyond the "
                                "double range; scale the functional down");
  return curve;
}

inline void check_curve_weights_2(const Line_arrangement_2& arrangement, const std::vector<double>& weights,
                                  const Curve_problem_2& problem)
{
  problem.validate();
  if(weights.size() != arrangement.number_of_edges())
    throw std::invalid_argument("MDCS: minimize_curve_functional_2: one weight per arrangement edge is required");
  for(std::size_t e = 0; e < weights.size(); ++e)
    if(!(weights[e] >= 0))   // +infinity is allowed: an edge the curve must not use
      throw std::invalid_argument("MDCS: minimize_curve_functional_2: the weight of edge " + std::to_string(e) +
                                  " is negative or NaN (weights must be >= 0, +infinity allowed)");
}

} // namespace internal

/*!
  \brief Finds the globally minimal discrete curve on `arrangement` by a minimum cut of its directed dual
  graph (thesis ch. 2.6.1).

  \param arrangement built with `build_curve_arrangement_2(problem, ...)` (its side walls must be split at the
         end values).
  \param weights the edge weights, from `curve_edge_weights_2()`.
  \param problem the box and the end conditions (the same as for the arrangement).
  \param engine `CGAL::Min_cut::Planar_min_cut` (the default: the cut as a shortest path in the planar dual
         of the network, `CGAL::Min_cut::solve_planar_min_cut()`), or a model of `MaxFlowEngine`
         (`CGAL::Min_cut::Pseudoflow_max_flow`, `CGAL::Min_cut::Push_relabel_max_flow`,
         `CGAL::Min_cut::Boykov_kolmogorov_max_flow`) run by `CGAL::Min_cut::solve_min_cut()`.
  \param progress a progress callback, stages `"network"` and `"max-flow"` (general engines) or
         `"dual-graph"`, `"shortest-path"` and `"sides"` (planar).

  The result is the curve whose energy is minimal among all functions formed by edges of the arrangement
  that meet the end conditions; `solver_value` is the cut value, `energy` the sum of the curve's edge
  weights (equal up to rounding). If no such function exists, `is_feasible` is false.

  **Which engine.** Measured with `bench_curve_2` (catenoid, random lines, one core): the planar cut solves
  10^4 lines (29 million cells) in seconds where pseudoflow, the fastest general engine, needs about 20 minutes
  (it grows as about n^1.55 on these networks); the general engines are there for comparison and because the
  same network code serves the bivariate problems, whose networks are not planar.
*/
template <class Engine, class Progress = CGAL::MDCS::No_progress>
Minimal_curve_2 minimize_curve_functional_2(const Line_arrangement_2& arrangement, const std::vector<double>& weights,
                                            const Curve_problem_2& problem, Engine engine,
                                            Progress progress = Progress())
{
  internal::check_curve_weights_2(arrangement, weights, problem);
  const CGAL::Min_cut::Flow_network<double> network = internal::curve_dual_network_2(arrangement, weights, problem);
  return internal::curve_from_cut_2(arrangement, weights, CGAL::Min_cut::solve_min_cut(network, engine, progress));
}

/// Same, with the planar cut (`CGAL::Min_cut::solve_planar_min_cut()`).
template <class Progress = CGAL::MDCS::No_progress>
Minimal_curve_2 minimize_curve_functional_2(const Line_arrangement_2& arrangement, const std::vector<double>& weights,
                                            const Curve_problem_2& problem, CGAL::Min_cut::Planar_min_cut,
                                            Progress progress = Progress())
{
  internal::check_curve_weights_2(arrangement, weights, problem);
  CGAL::Min_cut::Planar_dual dual;
  const CGAL::Min_cut::Flow_network<double> network =
    internal::curve_dual_network_2(arrangement, weights, problem, &dual);
  return internal::curve_from_cut_2(arrangement, weights, CGAL::Min_cut::solve_planar_min_cut(network, dual, progress));
}

/// Same, with the default engine, `CGAL::Min_cut::Planar_min_cut`.
inline Minimal_curve_2 minimize_curve_functional_2(const Line_arrangement_2& arrangement,
                                                   const std::vector<double>& weights,
                                                   const Curve_problem_2& problem)
{
  return minimize_curve_functional_2(arrangement, weights, problem, CGAL::Min_cut::Planar_min_cut());
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_MINIMIZE_CURVE_FUNCTIONAL_2_H
