// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Globally minimal discrete surfaces by a min-cut of the directed dual graph of a plane arrangement
// (thesis ch. 2.6.2-2.7).
#ifndef CGAL_VARIATIONAL_MINIMIZATION_MINIMIZE_SURFACE_FUNCTIONAL_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_MINIMIZE_SURFACE_FUNCTIONAL_3_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Min_cut/solve_min_cut.h>
#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/internal/surface_dual_network_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
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

// The triangulated surface of a set of facets, oriented upwards, in world coordinates.
inline void surface_mesh_from_facets(const Plane_arrangement_3& arrangement, const Surface_problem_3& problem,
                                     const std::vector<double>& weights, Minimal_surface_3& s)
{
  std::unordered_map<std::uint32_t, std::uint32_t> index;
  double energy = 0, projected = 0;
  for(std::uint32_t f : s.facets) {
    energy += weights[f];
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
}

} // namespace internal

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief Finds the globally minimal discrete surface on `arrangement` by a minimum cut of its directed dual graph.

  \param arrangement built from planes that include pencils through the boundary segments of `problem`
         (`surface_planes_3()`), so that the boundary curve is made of arrangement edges.
  \param weights the facet weights, from `surface_facet_weights_3()`.
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
  const CGAL::Min_cut::Flow_network<double> network = internal::surface_dual_network_3(arrangement, weights, problem);
  const auto cut = CGAL::Min_cut::solve_min_cut(network, engine, progress);
  Minimal_surface_3 surface;
  if(!cut.is_finite) return surface;
  surface.is_feasible = true;
  surface.solver_value = cut.value;
  for(const auto& facet : cut.chain) {
    if(!facet.forward)
      throw std::logic_error("MDCS: internal error: a finite cut crossed a facet downwards");
    surface.facets.push_back(facet.id);
  }
  internal::surface_mesh_from_facets(arrangement, problem, weights, surface);
  return surface;
}

/// Same, with the default max-flow engine of `CGAL::Min_cut::solve_min_cut()`.
inline Minimal_surface_3 minimize_surface_functional_3(const Plane_arrangement_3& arrangement,
                                                       const std::vector<double>& weights,
                                                       const Surface_problem_3& problem)
{
  return minimize_surface_functional_3(arrangement, weights, problem, CGAL::Min_cut::Default_max_flow_engine());
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_MINIMIZE_SURFACE_FUNCTIONAL_3_H
