// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tangent-plane refinement: the planes of each new arrangement are fitted to the previous optimum (tangent planes
// at spread-out points, and boundary pencils with the optimum's slope across the boundary), so that the facets
// available to the cut have the orientations the minimiser needs. Random planes rarely do: that is the
// discretisation excess of a random complex (a few percent of the area at 1M cells on Scherk's surface).
#ifndef CGAL_VARIATIONAL_MINIMIZATION_REFINE_SURFACE_BY_TANGENT_PLANES_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_REFINE_SURFACE_BY_TANGENT_PLANES_3_H

#include <CGAL/MDCS/concurrency.h>
#include <CGAL/MDCS/progress.h>
#include <CGAL/Min_cut/solve_min_cut.h>
#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/internal/surface_height_3.h>
#include <CGAL/Variational_minimization/internal/surface_tangent_fit_3.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/// The parameters of `refine_surface_by_tangent_planes_3()`.
struct Tangent_refinement_options_3
{
  /// The number of refined arrangements after the first (random) one.
  int rounds = 12;
  /// The radius of the local fits, as a share of the shorter side of Ω's bounding box.
  double fit_radius = 0.2;
  /// Threads for the tangent-plane fits and the facet weights of every round (0: all hardware threads; TBB needed,
  /// else 1). Results do not depend on it.
  std::size_t threads = 1;
};

/// The outcome of `refine_surface_by_tangent_planes_3()`.
struct Tangent_refinement_result_3
{
  /// The optimum of lowest energy over all rounds (round 0 is the random arrangement).
  Minimal_surface_3 surface;
  /// The round that gave `surface`.
  int best_round = 0;
  /// Per round: the optimum's energy (+infinity if the round had no feasible surface) and the arrangement's cells.
  std::vector<double> round_energies;
  std::vector<std::size_t> round_cells;
  /// The planes of the best round's arrangement.
  std::vector<Lattice_plane_3> planes;
};

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief Tangent-plane refinement: round 0 solves on `surface_planes_3(problem, n, options)`; each further round
  solves on a new arrangement of `n` planes fitted to the previous round's optimum s (the latest feasible one):

  - the first `surface_pencil_count_3(problem, n, options)` planes of round 0 (on a fixed boundary they hold the
    boundary cone, or the polygon's walls and boundary triangulation, so that every round is feasible);
  - on a fixed boundary, one pencil plane through each boundary segment whose slope across the segment, into Ω,
    is that of s (least-squares quadratic along the inward direction over the fit radius);
  - up to `n`, the tangent planes of s at points spread over Ω by jittered grids (least-squares quadratic fitted
    to the height of s on the disk of the fit radius, cut to Ω).

  Every arrangement is solved globally; the planes only decide which facets the cut can use. The heights are
  those of the discrete optimum itself (no relaxation is involved), so each round's energy is that of a minimal
  discrete surface. Energies are not monotone from round to round (the planes change); the result is the best
  round. On Scherk's surface, 200 planes and 12 rounds bring the raw area error from +6% (random planes, 0.58M
  cells) to about +0.5% (0.86M cells): see the manual's benchmark section. Useful for smooth minimisers; for a
  non-smooth G (the blob problem) prefer `select_planes_3()` and `refine_surface_3()`, which keep the planes of the
  optimum.

  The fits and the facet weights of every round run on `tangent_options.threads` threads; the planes and the
  result do not depend on the thread count (the cell boxes of the arrangement build too; the rest of the build and
  the max-flow stay sequential).
  `progress` is called with stage `"tangent refinement"`, once per round.
  \throws std::invalid_argument for an invalid problem or functional, `rounds < 0`, a fit radius not in (0, 1],
          `n` not larger than the planes kept from round 0 plus the boundary pencils, or no feasible surface in
          round 0.
*/
template <class Functional, class Engine = CGAL::Min_cut::Default_max_flow_engine,
          class Progress = CGAL::MDCS::No_progress>
Tangent_refinement_result_3
refine_surface_by_tangent_planes_3(const Surface_problem_3& problem, const Functional& G, std::size_t n,
                                   const Tangent_refinement_options_3& tangent_options = Tangent_refinement_options_3(),
                                   const Surface_plane_options_3& options = Surface_plane_options_3(),
                                   int quadrature_level = 1, Engine engine = Engine(), Progress progress = Progress())
{
  if(tangent_options.rounds < 0)
    throw std::invalid_argument("MDCS: refine_surface_by_tangent_planes_3: rounds must be >= 0");
  if(!(tangent_options.fit_radius > 0 && tangent_options.fit_radius <= 1))
    throw std::invalid_argument("MDCS: refine_surface_by_tangent_planes_3: fit_radius must be in (0, 1]");
  problem.validate();
  const std::size_t kept = surface_pencil_count_3(problem, n, options);
  const std::size_t fitted_pencils = problem.is_relaxed() ? 0 : problem.boundary_loop(false).size();
  if(n <= kept + fitted_pencils)
    throw std::invalid_argument("MDCS: refine_surface_by_tangent_planes_3: n = " + std::to_string(n) +
                                " leaves no tangent planes (the boundary needs " +
                                std::to_string(kept + fitted_pencils) + " planes)");
  CGAL::MDCS::internal::Progress_reporter<Progress> reporter(progress, "tangent refinement",
                                                             std::size_t(tangent_options.rounds) + 1);
  const double radius = tangent_options.fit_radius * (std::min)(problem.domain.xmax() - problem.domain.xmin(),
                                                                 problem.domain.ymax() - problem.domain.ymin());
  const internal::Surface_domain_test_3 inside(problem);
  const std::size_t threads = CGAL::MDCS::effective_threads(tangent_options.threads, true);
  Tangent_refinement_result_3 result;
  std::vector<Lattice_plane_3> planes = surface_planes_3(problem, n, options);
  const std::vector<Lattice_plane_3> boundary_planes(planes.begin(), planes.begin() + std::ptrdiff_t(kept));
  Minimal_surface_3 latest;
  for(int round = 0; round <= tangent_options.rounds; ++round) {
    reporter(std::size_t(round));
    if(round > 0) {
      // The estimate: the latest feasible optimum's height.
      const internal::Surface_height_3 height(latest);
      planes = boundary_planes;
      if(!problem.is_relaxed()) internal::add_fitted_boundary_pencils_3(problem, height, inside, radius, planes);
      internal::Stratified_domain_points_3 points(problem, inside, n - planes.size(),
                                                  options.seed * 0x9E3779B97F4A7C15ull + std::uint64_t(round));
      // The points are drawn in order, fitted in parallel, and used in order exactly as one loop would: each
      // batch has as many points as planes are missing (the points drawn beyond the last one used are unused,
      // and the stream of points is not used afterwards).
      std::size_t failures = 0;
      std::vector<std::array<double, 2>> batch;
      std::vector<std::array<double, 3>> fits;
      std::vector<char> fitted;
      while(planes.size() < n) {
        batch.clear();
        for(std::size_t k = planes.size(); k < n; ++k) batch.push_back(points.next());
        fits.assign(batch.size(), std::array<double, 3>{{0, 0, 0}});
        fitted.assign(batch.size(), 0);
        CGAL::MDCS::parallel_for_blocks_lowest_error(batch.size(), 16, threads,
                                                     [&](std::size_t begin, std::size_t end, std::size_t) {
          for(std::size_t k = begin; k < end; ++k)
            fitted[k] = internal::fit_tangent_3(height, inside, batch[k][0], batch[k][1], radius, fits[k]) ? 1 : 0;
        });
        for(std::size_t k = 0; k < batch.size() && planes.size() < n; ++k) {
          if(fitted[k])
            planes.push_back(internal::world_tangent_plane_3(problem, batch[k][0], batch[k][1], fits[k]));
          else if(++failures > 100 * n)
            throw std::logic_error("MDCS: refine_surface_by_tangent_planes_3: no tangent plane could be fitted");
        }
      }
    }
    const Plane_arrangement_3 arrangement(planes, CGAL::MDCS::No_progress(), threads);
    CGAL::MDCS::No_progress none;
    Minimal_surface_3 s = internal::minimize_surface_functional_threads_3(arrangement, problem, G, quadrature_level,
                                                                          threads, engine, none);
    result.round_cells.push_back(arrangement.number_of_cells());
    result.round_energies.push_back(s.is_feasible ? s.energy : std::numeric_limits<double>::infinity());
    if(!s.is_feasible) {
      if(round == 0) throw std::invalid_argument("MDCS: refine_surface_by_tangent_planes_3: round 0 found no surface");
      continue;
    }
    if(round == 0 || s.energy < result.surface.energy) {
      result.surface = s;
      result.best_round = round;
      result.planes = planes;
    }
    latest = std::move(s);
  }
  reporter.finish();
  return result;
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_REFINE_SURFACE_BY_TANGENT_PLANES_3_H
