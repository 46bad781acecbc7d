// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Globally minimal discrete surfaces by a min-cut of the directed dual graph of a plane arrangement
// (thesis ch. 2.6.2-2.7).
#ifndef CGAL_VARIATIONAL_MINIMIZATION_MINIMIZE_SURFACE_FUNCTIONAL_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_MINIMIZE_SURFACE_FUNCTIONAL_3_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Min_cut/solve_min_cut.h>
#include <CGAL/Min_cut/internal/contract_terminal_nodes.h>
#include <CGAL/Min_cut/internal/pseudoflow_solver.h>
#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/internal/Surface_residual_graph_3.h>
#include <CGAL/Variational_minimization/internal/surface_dual_network_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief Builds the arrangement of `planes` in the lattice box of `problem` (see `surface_planes_3()`).
  \throws std::invalid_argument when the problem is invalid or a plane breaks the bounds of `Lattice_plane_3`.
*/
template <class Progress = CGAL::MDCS::No_progress>
Plane_arrangement_3 build_surface_arrangement_3(const Surface_problem_3& problem,
                                                const std::vector<Lattice_plane_3>& planes,
                                                Progress progress = Progress())
{
  problem.validate();
  return Plane_arrangement_3(planes, progress);
}

namespace internal {

// The triangulated surface of a set of facets, oriented upwards, in world coordinates. `weight_of(f)`: the weight
// of facet f (a std::vector<double> or a callable).
inline double facet_weight_of(const std::vector<double>& weights, std::uint32_t f) { return weights[f]; }
template <class WeightOf>
double facet_weight_of(const WeightOf& weight_of, std::uint32_t f) { return weight_of(f); }

template <class WeightOf>
void surface_mesh_from_facets(const Plane_arrangement_3& arrangement, const Surface_problem_3& problem,
                              const WeightOf& weight_of, Minimal_surface_3& s)
{
  std::unordered_map<std::uint32_t, std::uint32_t> index;
  double energy = 0, projected = 0;
  for(std::uint32_t f : s.facets) {
    energy += facet_weight_of(weight_of, f);
    s.planes.push_back(arrangement.facet(f).plane);
    std::vector<std::uint32_t> ids;
    std::vector<std::array<double, 2>> xy;
    for(std::size_t k = 0; k < arrangement.facet_degree(f); ++k) {
      const std::uint32_t v = arrangement.facet_vertex(f, k);
      auto it = index.find(v);
      if(it == index.end()) {
        it = index.emplace(v, std::uint32_t(s.points.size())).first;
        s.points.push_back(problem.to_world(arrangement.point(v)));
      }
      ids.push_back(it->second);
      xy.push_back({{s.points[it->second][0], s.points[it->second][1]}});
    }
    double area = polygon_area_2(xy);
    if(area < 0) {
      std::reverse(ids.begin(), ids.end());
      area = -area;
    }
    projected += area;
    for(std::size_t k = 1; k + 1 < ids.size(); ++k) s.triangles.push_back({{ids[0], ids[k], ids[k + 1]}});
  }
  std::sort(s.planes.begin(), s.planes.end());
  s.planes.erase(std::unique(s.planes.begin(), s.planes.end()), s.planes.end());
  s.energy = energy;
  s.projected_area = projected;
  // each weight is finite (checked where it is computed); their sum may still overflow: never a feasible surface
  // with an infinite energy
  if(!std::isfinite(s.energy) || !std::isfinite(s.solver_value))
    throw std::invalid_argument("MDCS: the minimal surface's energy is not finite: the facet weights add up beyond "
                                "the double range; scale the functional down");
}

// The facets of a minimum cut of the dual network (the surface) and whether the cut is finite.
struct Surface_cut_3
{
  bool is_finite = false;
  double value = 0;
  std::vector<std::uint32_t> facets;
};

// The surface of a cut: infeasible when the cut is infinite, otherwise its facets as a mesh, with the energy
// summed from `weight_of` (a weight vector or a per-facet callable).
template <class WeightOf>
Minimal_surface_3 surface_from_cut_3(const Plane_arrangement_3& arrangement, const Surface_problem_3& problem,
                                     Surface_cut_3 cut, const WeightOf& weight_of)
{
  Minimal_surface_3 surface;
  if(!cut.is_finite) return surface;
  surface.is_feasible = true;
  surface.solver_value = cut.value;
  surface.facets.swap(cut.facets);
  surface_mesh_from_facets(arrangement, problem, weight_of, surface);
  return surface;
}

// Any engine: the dual network as a CGAL::Min_cut::Flow_network, solved by solve_min_cut().
template <class Engine, class Progress>
Surface_cut_3 surface_min_cut_3(const Plane_arrangement_3& arrangement, const std::vector<double>& weights,
                                const Surface_problem_3& problem, Engine engine, Progress& progress)
{
  Surface_cut_3 out;
  const auto cut = [&] {
    const CGAL::Min_cut::Flow_network<double> network = surface_dual_network_3(arrangement, weights, problem);
    return CGAL::Min_cut::solve_min_cut(network, engine, progress);
  }();
  if(!cut.is_finite) return out;
  out.is_finite = true;
  out.value = cut.value;
  for(const auto& facet : cut.chain) {
    if(!facet.forward)
      throw std::logic_error("MDCS: internal error: a finite cut crossed a facet downwards");
    out.facets.push_back(facet.id);
  }
  return out;
}

// Pseudoflow run straight on the arrangement (Surface_residual_graph_3), without the Flow_network and the
// engine's copy of the arcs: 8 bytes per facet and 44 per cell instead of about 64 per facet and 80 per cell (a
// polygonal domain: 1 byte per facet more).
// The weights come from a callable; `stage_weights`: the callable computes them (the "network" stage is then
// reported as "weights").
template <class WeightOf, class Progress>
Surface_cut_3 surface_pseudoflow_cut_3(const Plane_arrangement_3& arrangement, const WeightOf& weight_of,
                                       const Surface_problem_3& problem, Progress& progress, bool stage_weights)
{
  typedef Plane_arrangement_3 Arr;
  typedef CGAL::MDCS::internal::Progress_reporter<Progress> Reporter;
  std::vector<char> side;
  Surface_cut_3 out;
  {
    Reporter network_stage(progress, stage_weights ? "weights" : "network", 1);
    Surface_residual_graph_3 graph(arrangement, weight_of, problem);
    network_stage.finish();
    Reporter max_flow_stage(progress, "max-flow", 1);
    {
      CGAL::Min_cut::internal::Pseudoflow_solver<double, Surface_residual_graph_3> solver(graph);
      solver.run(side);
    }
    max_flow_stage.finish();
    // The chain in the order of solve_min_cut(): interior facets, source facets, sink facets (by index).
    std::vector<std::uint32_t> source_facets, sink_facets;
    bool crosses_infinite_arc = false;
    double value = 0;
    const std::size_t nf = arrangement.number_of_facets();
    for(std::size_t i = 0; i < nf; ++i) {
      const Arr::Facet_index f = Arr::Facet_index(i);
      const Arr::Facet& F = arrangement.facet(f);
      if(graph.is_terminal(f)) {
        const double c = graph.terminal_capacity(f);
        if(c == 0) continue;
        const char s = side[graph.terminal_cell(f)];
        const bool cut = (c > 0 && !s) || (c < 0 && s);
        if(!cut) continue;
        if(graph.is_tie(f)) crosses_infinite_arc = true; // a tie to a terminal
        else (c > 0 ? source_facets : sink_facets).push_back(f);
        continue;
      }
      const char su = side[F.negative_cell], sv = side[F.positive_cell];
      if(su == sv) continue;
      const Arr::Cell_index tail = su ? F.negative_cell : F.positive_cell;
      if(graph.residual(tail, f) == std::numeric_limits<double>::infinity() || tail != graph.below(F))
        crosses_infinite_arc = true;
      else {
        out.facets.push_back(f);
        value += weight_of(f);
      }
    }
    if(crosses_infinite_arc) return Surface_cut_3();
    for(std::uint32_t f : source_facets) value += weight_of(f);
    for(std::uint32_t f : sink_facets) value += weight_of(f);
    out.facets.insert(out.facets.end(), source_facets.begin(), source_facets.end());
    out.facets.insert(out.facets.end(), sink_facets.begin(), sink_facets.end());
    out.value = value;
  }
  out.is_finite = true;
  return out;
}

// Pseudoflow with a weight vector.
template <class Progress>
Surface_cut_3 surface_min_cut_3(const Plane_arrangement_3& arrangement, const std::vector<double>& weights,
                                const Surface_problem_3& problem, CGAL::Min_cut::Pseudoflow_max_flow, Progress& progress)
{
  if(weights.size() != arrangement.number_of_facets())
    throw std::invalid_argument("MDCS: minimize_surface_functional_3: one weight per arrangement facet is required");
  return surface_pseudoflow_cut_3(arrangement, [&](std::uint32_t f) { return weights[f]; }, problem, progress, false);
}

// The surface of the minimum cut of a network contracted by CGAL::Min_cut::internal::contract_terminal_nodes or
// built by Terminal_contraction (refinement, basin search): the cut's facets plus the facets the contraction fixed,
// with the energy summed from `weights` (a weight vector or a per-facet callable). Infeasible when the contracted
// network or its cut is infinite.
template <class Engine, class WeightOf>
Minimal_surface_3 surface_from_contracted_cut_3(const Plane_arrangement_3& arrangement, const Surface_problem_3& problem,
                                                const WeightOf& weights,
                                                const CGAL::Min_cut::internal::Contracted_network<double>& reduced,
                                                Engine engine)
{
  Minimal_surface_3 s;
  if(!reduced.is_finite) return s;
  const auto cut = CGAL::Min_cut::solve_min_cut(reduced.network, engine);
  if(!cut.is_finite) return s;
  s.is_feasible = true;
  s.solver_value = cut.value + reduced.constant;
  for(const auto& facet : cut.chain) {
    if(!facet.forward || facet.id >= arrangement.number_of_facets())
      throw std::logic_error("MDCS: internal error: a finite cut crossed a facet downwards");
    s.facets.push_back(facet.id);
  }
  s.facets.insert(s.facets.end(), reduced.constant_facets.begin(), reduced.constant_facets.end());
  surface_mesh_from_facets(arrangement, problem, weights, s);
  return s;
}

} // namespace internal

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief Finds the globally minimal discrete surface on `arrangement` by a minimum cut of its directed dual graph.

  \param arrangement built from planes that include pencils through the boundary segments of `problem`
         (`surface_planes_3()`), so that the boundary curve is made of arrangement edges.
  \param weights the facet weights, from `surface_facet_weights_3()`.
  \param problem the domain, the height range and the boundary conditions (the same as for the arrangement).
  \param engine a model of `MaxFlowEngine` (`CGAL::Min_cut::Boykov_kolmogorov_max_flow`,
         `CGAL::Min_cut::Push_relabel_max_flow`, `CGAL::Min_cut::Pseudoflow_max_flow`).
  \param progress a progress callback, stages `"network"` and `"max-flow"`.

  The result is the function of minimal energy among those formed by facets of the arrangement that meet the
  boundary condition; `solver_value` is the cut value, `energy` the sum of the facets' weights (equal up to
  rounding). If no such function exists, `is_feasible` is false.
*/
template <class Engine, class Progress = CGAL::MDCS::No_progress>
Minimal_surface_3 minimize_surface_functional_3(const Plane_arrangement_3& arrangement,
                                                const std::vector<double>& weights, const Surface_problem_3& problem,
                                                Engine engine, Progress progress = Progress())
{
  problem.validate();
  if(weights.size() != arrangement.number_of_facets())
    throw std::invalid_argument("MDCS: minimize_surface_functional_3: one weight per arrangement facet is required");
  return internal::surface_from_cut_3(arrangement, problem,
                                      internal::surface_min_cut_3(arrangement, weights, problem, engine, progress), weights);
}

/// Same, with the default max-flow engine of `CGAL::Min_cut::solve_min_cut()`.
inline Minimal_surface_3 minimize_surface_functional_3(const Plane_arrangement_3& arrangement,
                                                       const std::vector<double>& weights,
                                                       const Surface_problem_3& problem)
{
  return minimize_surface_functional_3(arrangement, weights, problem, CGAL::Min_cut::Default_max_flow_engine());
}

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief Same, with the facet weights of the functional `G` (a model of `SurfaceFunctional_3`) computed on the fly,
  as `surface_facet_weights_3(arrangement, problem, G, quadrature_level)` would give them.

  With `CGAL::Min_cut::Pseudoflow_max_flow` (the default) the weights go straight into the solver's residual
  capacities and no weight vector is kept: the weights of the surface's facets are computed again at the end.
  This is the leanest path: besides the arrangement, 8 bytes per facet and 44 per cell (plus 1 per cell for the
  sides, and on a polygonal domain 1 per facet for its kind). Other engines get a weight vector and the generic path. `progress` sees the stages `"weights"` and
  `"max-flow"` (and `"network"` for other engines).
  \throws std::invalid_argument if the problem is invalid or G is negative or NaN somewhere.
*/
template <class Functional, class Engine = CGAL::Min_cut::Default_max_flow_engine,
          class Progress = CGAL::MDCS::No_progress>
Minimal_surface_3 minimize_surface_functional_3(const Plane_arrangement_3& arrangement, const Surface_problem_3& problem,
                                                const Functional& G, int quadrature_level = 1,
                                                Engine engine = Engine(), Progress progress = Progress())
{
  problem.validate();
  if(quadrature_level < 0 || quadrature_level > 8)
    throw std::invalid_argument("MDCS: minimize_surface_functional_3: quadrature_level must be in [0, 8]");
  if(!std::is_same<Engine, CGAL::Min_cut::Pseudoflow_max_flow>::value) {
    const std::vector<double> w = surface_facet_weights_3(arrangement, problem, G, quadrature_level, progress);
    return minimize_surface_functional_3(arrangement, w, problem, engine, progress);
  }
  const auto weight_of = [&](std::uint32_t f) {
    return surface_facet_weight_3(arrangement, problem, G, f, quadrature_level);
  };
  return internal::surface_from_cut_3(
    arrangement, problem, internal::surface_pseudoflow_cut_3(arrangement, weight_of, problem, progress, true), weight_of);
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_MINIMIZE_SURFACE_FUNCTIONAL_3_H
