// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The independent oracle for the univariate problem: the left-to-right shortest path on the arrangement.

#ifndef CGAL_VARIATIONAL_MINIMIZATION_DIRECTED_SHORTEST_PATH_2_H
#define CGAL_VARIATIONAL_MINIMIZATION_DIRECTED_SHORTEST_PATH_2_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Variational_minimization/Curve_problem_2.h>
#include <CGAL/Variational_minimization/Line_arrangement_2.h>
#include <CGAL/Variational_minimization/Minimal_curve_2.h>
#include <CGAL/Variational_minimization/internal/curve_from_edges_2.h>
#include <CGAL/Variational_minimization/internal/curve_walls_2.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/*!
  \brief Finds the minimal discrete curve on `arrangement` as a directed shortest path (thesis ch. 2.3).

  Every non-vertical edge is traversed left to right only, so every path is the graph of a function. The
  sources are the left-wall vertices allowed by the left end condition, the targets the right-wall vertices
  allowed by the right one (several of each for relaxed conditions). The graph is acyclic, so the path is
  found in linear time after a topological sort (Kahn's algorithm: no coordinate comparison is involved).

  This solver is independent of the min-cut: the two must give the same energy on every instance (the
  duality theorem), which the test suite checks. It is also the faster one in 1D; the cut is what
  generalises to surfaces.
*/
template <class Progress = CGAL::MDCS::No_progress>
Minimal_curve_2 directed_shortest_path_2(const Line_arrangement_2& arrangement, const std::vector<double>& weights,
                                         const Curve_problem_2& problem, Progress progress = Progress())
{
  typedef Line_arrangement_2 Arr;
  typedef Arr::Vertex_index Vertex_index;
  problem.validate();
  if(weights.size() != arrangement.number_of_edges())
    throw std::invalid_argument("MDCS: directed_shortest_path_2: one weight per arrangement edge is required");

  const std::size_t nv = arrangement.number_of_vertices();
  const std::size_t ne = arrangement.number_of_edges();
  CGAL::MDCS::internal::Progress_reporter<Progress> report(progress, "shortest-path", nv);

  // Out-edges in compressed rows: the usable edges are the finite-weight ones (vertical edges are infinite).
  std::vector<std::uint32_t> first(nv + 1, 0), in_degree(nv, 0);
  for(std::size_t i = 0; i < ne; ++i)
    if(std::isfinite(weights[i])) {
      const auto& e = arrangement.edge(Arr::Edge_index(i));
      ++first[e.source + 1];
      ++in_degree[e.target];
    }
  for(std::size_t v = 0; v < nv; ++v) first[v + 1] += first[v];
  std::vector<Arr::Edge_index> out(first[nv]);
  {
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for(std::size_t i = 0; i < ne; ++i)
      if(std::isfinite(weights[i])) out[fill[arrangement.edge(Arr::Edge_index(i)).source]++] = Arr::Edge_index(i);
  }

  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> distance(nv, inf);
  std::vector<Arr::Edge_index> predecessor(nv, Arr::null_index);
  const internal::Side_wall_classification left = internal::classify_side_wall(arrangement, Arr::LEFT_WALL, problem.left);
  const internal::Side_wall_classification right = internal::classify_side_wall(arrangement, Arr::RIGHT_WALL, problem.right);
  for(Vertex_index s : left.admissible_vertices) distance[s] = 0;

  // Kahn's algorithm: process vertices in a topological order of the left-to-right DAG.
  std::vector<Vertex_index> stack;
  for(std::size_t v = 0; v < nv; ++v)
    if(in_degree[v] == 0) stack.push_back(Vertex_index(v));
  std::size_t processed = 0;
  while(!stack.empty()) {
    const Vertex_index v = stack.back();
    stack.pop_back();
    report(processed++);
    for(std::uint32_t k = first[v]; k < first[v + 1]; ++k) {
      const Arr::Edge_index e = out[k];
      const Vertex_index w = arrangement.edge(e).target;
      if(distance[v] + weights[e] < distance[w]) {
        distance[w] = distance[v] + weights[e];
        predecessor[w] = e;
      }
      if(--in_degree[w] == 0) stack.push_back(w);
    }
  }
  if(processed != nv)
    throw std::logic_error("MDCS: internal error: the left-to-right edge graph has a cycle");
  report.finish();

  Vertex_index best = Arr::null_index;
  for(Vertex_index t : right.admissible_vertices)
    if(std::isfinite(distance[t]) && (best == Arr::null_index || distance[t] < distance[best])) best = t;
  Minimal_curve_2 curve;
  if(best == Arr::null_index) return curve;

  curve.is_feasible = true;
  curve.solver_value = distance[best];
  std::vector<Arr::Edge_index> edges;
  for(Vertex_index v = best; predecessor[v] != Arr::null_index; v = arrangement.edge(predecessor[v]).source)
    edges.push_back(predecessor[v]);
  internal::order_curve_edges(arrangement, weights, edges, curve);
  return curve;
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_DIRECTED_SHORTEST_PATH_2_H
