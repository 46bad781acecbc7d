// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Plane selection (thesis ch. 2.7): solve, keep the planes the optimum uses, redraw the others, solve again.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_SELECT_PLANES_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_SELECT_PLANES_3_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Min_cut/solve_min_cut.h>
#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>
#include <CGAL/Variational_minimization/internal/grid_surface_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

// Appends `count` planes through (x, y, height(x, y) + spread * N(0, 1)) for uniform (x, y) in the domain (heights
// clamped to [zmin, zmax]), with normals drawn as surface_planes_3() draws them for `options.distribution`.
template <class Height, class Rng>
void add_planes_near_surface_3(const Surface_problem_3& problem, const Surface_plane_options_3& options,
                               const Height& height, std::size_t count, Rng& rng, std::vector<Lattice_plane_3>& out)
{
  const double L = double(Plane_arrangement_3::lattice_size);
  const double wx = problem.domain.xmax() - problem.domain.xmin(), wy = problem.domain.ymax() - problem.domain.ymin(),
               wz = problem.zmax - problem.zmin;
  std::uniform_real_distribution<double> U(0, 1), S(-options.max_slope, options.max_slope);
  std::normal_distribution<double> N;
  for(std::size_t k = 0; k < count; ++k) {
    const double u = U(rng), v = U(rng);
    const double z = height(problem.domain.xmin() + u * wx, problem.domain.ymin() + v * wy) +
                     options.selection_near_spread * wz * N(rng);
    const double t = (std::min)(1.0, (std::max)(0.0, (z - problem.zmin) / wz));
    const std::array<double, 3> q = {{u * L, v * L, t * L}};
    std::array<double, 3> normal;
    do {
      if(options.distribution == Plane_distribution_3::isotropic) normal = {{N(rng), N(rng), N(rng)}};
      else normal = {{-S(rng) * (wx / L) / (wz / L), -S(rng) * (wy / L) / (wz / L), 1.0}};
    } while(!(std::abs(normal[0]) + std::abs(normal[1]) + std::abs(normal[2]) > 1e-12));
    out.push_back(plane_through(normal, q));
  }
}

} // namespace internal

/// The outcome of `select_planes_3()`.
struct Plane_selection_result_3
{
  /// The best surface found (the energy never increases from one iteration to the next).
  Minimal_surface_3 surface;
  /// The energy of each iteration's optimum, in order (non-increasing up to rounding of the weights).
  std::vector<double> energies;
  /// The cells of each iteration's arrangement.
  std::vector<std::size_t> cells;
  /// The planes of the arrangement the best surface was found on.
  std::vector<Lattice_plane_3> planes;
  /// The optimum of each iteration, in order (for instance to relax each: the optima of several iterations may
  /// lie in different basins of the continuous problem).
  std::vector<Minimal_surface_3> surfaces;
};

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief Plane selection: `iterations` solves with `n` planes each. After each solve the planes that carry a facet
  of the optimum are kept, with every pencil plane (so that the optimum stays representable), and the others are
  replaced by new random planes of `options.distribution`: a share `options.selection_near_fraction` (default 0)
  through random points near the current optimum (heights spread by `options.selection_near_spread` times
  zmax - zmin), the rest through the whole box. The optimum of an iteration is therefore available to
  the next one, and the energy cannot increase (up to rounding of quadrature weights; the best is kept anyway).
  `progress` is called with stage `"plane selection"`.
  \throws std::invalid_argument for an invalid problem or functional, or `iterations < 1`.
*/
template <class Functional, class Engine = CGAL::Min_cut::Default_max_flow_engine,
          class Progress = CGAL::MDCS::No_progress>
Plane_selection_result_3 select_planes_3(const Surface_problem_3& problem, const Functional& G, std::size_t n,
                                         int iterations, const Surface_plane_options_3& options = Surface_plane_options_3(),
                                         int quadrature_level = 1, Engine engine = Engine(),
                                         Progress progress = Progress())
{
  if(iterations < 1) throw std::invalid_argument("MDCS: select_planes_3: at least one iteration is needed");
  if(!(options.selection_near_fraction >= 0 && options.selection_near_fraction <= 1) ||
     !(options.selection_near_spread >= 0 && std::isfinite(options.selection_near_spread)))
    throw std::invalid_argument("MDCS: select_planes_3: selection_near_fraction must be in [0, 1] and "
                                "selection_near_spread finite and >= 0");
  if(problem.is_polygonal() && options.selection_near_fraction > 0)
    throw std::invalid_argument("MDCS: select_planes_3: planes near the optimum (selection_near_fraction > 0) need a "
                                "rectangular domain");
  CGAL::MDCS::internal::Progress_reporter<Progress> reporter(progress, "plane selection", std::size_t(iterations));
  const std::size_t pencils = surface_pencil_count_3(problem, n, options);
  std::vector<Lattice_plane_3> planes = surface_planes_3(problem, n, options);
  Plane_selection_result_3 result;
  for(int it = 0; it < iterations; ++it) {
    reporter(std::size_t(it));
    const Plane_arrangement_3 arrangement(planes);
    Minimal_surface_3 s = minimize_surface_functional_3(arrangement, problem, G, quadrature_level, engine);
    result.energies.push_back(s.energy);
    result.cells.push_back(arrangement.number_of_cells());
    result.surfaces.push_back(s);
    if(it == 0 || s.energy < result.surface.energy) {
      result.surface = s;
      result.planes = planes;
    }
    if(it + 1 == iterations) break;
    // Keep the pencils and the planes of the best surface; redraw the rest.
    std::vector<char> keep(result.planes.size(), 0);
    for(std::size_t i = 0; i < pencils && i < keep.size(); ++i) keep[i] = 1;
    for(std::uint32_t p : result.surface.planes)
      if(p >= Plane_arrangement_3::number_of_walls) keep[p - Plane_arrangement_3::number_of_walls] = 1;
    std::vector<Lattice_plane_3> next;
    for(std::size_t i = 0; i < result.planes.size(); ++i)
      if(keep[i]) next.push_back(result.planes[i]);
    Surface_plane_options_3 fresh = options;
    fresh.seed = options.seed + 7919 * std::uint64_t(it + 1);
    // Planes near the current optimum: through a random point of the domain at the optimum's height (plus a
    // normal deviate), oriented as options.distribution draws them. They refine where the surface lives, so
    // that discrete energies tell neighbouring basins apart; the uniform ones keep exploring.
    const std::size_t slots = n > next.size() ? n - next.size() : 0;
    const std::size_t near =
      std::size_t(std::floor(options.selection_near_fraction * double(slots)));
    if(near > 0) {
      std::mt19937_64 rng(fresh.seed ^ 0x9E3779B97F4A7C15ull);
      const internal::Surface_height_sampler_3 height(result.surface, problem);
      internal::add_planes_near_surface_3(problem, options, height, near, rng, next);
    }
    const std::vector<Lattice_plane_3> random = internal::draw_surface_planes_3(problem, n + pencils, fresh);
    for(std::size_t i = surface_pencil_count_3(problem, n + pencils, fresh); i < random.size() && next.size() < n; ++i)
      next.push_back(random[i]);
    // The kept planes keep their positions at the front: pencils first, as surface_planes_3 lists them.
    planes.swap(next);
  }
  reporter.finish();
  return result;
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_SELECT_PLANES_3_H
