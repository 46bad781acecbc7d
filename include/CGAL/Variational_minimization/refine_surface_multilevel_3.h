// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Multi-level adaptive refinement (thesis ch. 2.7.2, Table 2.4): plane selection repeated over levels, each level
// searching a narrower envelope around the previous level's optimum (offsets such as 1, 0.2, 0.05 of the range).
#ifndef CGAL_VARIATIONAL_MINIMIZATION_REFINE_SURFACE_MULTILEVEL_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_REFINE_SURFACE_MULTILEVEL_3_H

#include <CGAL/MDCS/concurrency.h>
#include <CGAL/MDCS/progress.h>
#include <CGAL/Min_cut/solve_min_cut.h>
#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/internal/surface_envelope_cut_3.h>
#include <CGAL/Variational_minimization/select_planes_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/// The levels of `refine_surface_multilevel_3()`.
struct Surface_multilevel_options_3
{
  /// The envelope half-width of each level as a share of zmax - zmin, strictly decreasing and > 0. The first level
  /// has no previous optimum to centre an envelope on and searches the whole box, so its offset must be >= 1 (an
  /// envelope of half-width 1 around any surface of the box is the box). The thesis's Table 2.4 uses 1, 0.2, 0.05.
  std::vector<double> offsets{1.0, 0.2, 0.05};
  /// Plane selection iterations per level (the thesis: 5).
  int selection_iterations = 5;
};

/// One level of `refine_surface_multilevel_3()`.
struct Surface_refinement_level_3
{
  double offset = 0;                  ///< the envelope half-width, as a share of zmax - zmin
  double energy = 0;                  ///< the best energy after this level (non-increasing over the levels)
  std::vector<double> solve_energies; ///< the optimum of each plane selection iteration of this level, in order
  std::size_t planes = 0;             ///< planes of the arrangement of the level's last iteration
  std::size_t kept_planes = 0;        ///< of which carried over from the previous level (pencils and optimum)
  std::size_t cells = 0;              ///< cells of the level's last arrangement
  std::size_t network_nodes = 0;      ///< cells left inside the envelope (nodes of the last network solved)
  double seconds = 0;                 ///< wall time of the level
};

/// The outcome of `refine_surface_multilevel_3()`.
struct Surface_multilevel_result_3
{
  /// The best surface over all levels, and the planes of the arrangement it was found on.
  Minimal_surface_3 surface;
  std::vector<Lattice_plane_3> planes;
  std::vector<Surface_refinement_level_3> levels;
};

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief Multi-level adaptive refinement (thesis ch. 2.7.2): level 0 is `select_planes_3(problem, G, n,
  levels.selection_iterations, options)` on the whole box. Level l > 0 draws an arrangement of `n` planes: the
  pencils and the planes carrying a facet of the best surface s so far, then new planes through random points
  between s - o_l (zmax - zmin) and s + o_l (zmax - zmin) (o_l = `levels.offsets[l]`; clamped to the box), with the
  orientations of `options.distribution`. Its cells farther than that below s are contracted into the source,
  those above into the sink, and the cut is searched inside the envelope only; then, as in plane selection, the
  planes of the level's best surface and the pencils are kept and the others redrawn inside the same envelope,
  `levels.selection_iterations` times. s is feasible on every arrangement of level l (its planes are kept and no
  cell crosses it), so each level's first solve is no worse than s (up to the rounding of the weights; exactly for
  closed-form weights) and the best energy never increases from one level to the next.
  Seeds: level 0 uses `options.seed`; level l iteration i draws with a generator seeded from both.
  The facet weights are computed on `options.threads` threads (identical results for every count).
  `progress` is called with stage `"multilevel refinement"`, once per level.
  \throws std::invalid_argument for an invalid problem or functional, no level, a first offset below 1, an offset
          that is not finite, not > 0 or not smaller than the previous one, `selection_iterations < 1`, or a level
          without a feasible surface.
*/
template <class Functional, class Engine = CGAL::Min_cut::Default_max_flow_engine,
          class Progress = CGAL::MDCS::No_progress>
Surface_multilevel_result_3 refine_surface_multilevel_3(
  const Surface_problem_3& problem, const Functional& G, std::size_t n,
  const Surface_multilevel_options_3& levels = Surface_multilevel_options_3(),
  const Surface_plane_options_3& options = Surface_plane_options_3(), int quadrature_level = 1,
  Engine engine = Engine(), Progress progress = Progress())
{
  typedef Plane_arrangement_3 Arr;
  typedef std::chrono::steady_clock Clock;
  const char* const name = "MDCS: refine_surface_multilevel_3: ";
  const std::vector<double>& offsets = levels.offsets;
  if(offsets.empty()) throw std::invalid_argument(std::string(name) + "at least one level (offset) is needed");
  if(!(offsets[0] >= 1) || !std::isfinite(offsets[0]))
    throw std::invalid_argument(std::string(name) + "the first level searches the whole box: its offset must be a "
                                                    "finite number >= 1");
  for(std::size_t l = 1; l < offsets.size(); ++l)
    if(!(offsets[l] > 0 && offsets[l] < offsets[l - 1]))
      throw std::invalid_argument(std::string(name) + "the offsets must be > 0 and strictly decreasing (level " +
                                  std::to_string(l) + ")");
  if(levels.selection_iterations < 1)
    throw std::invalid_argument(std::string(name) + "at least one plane selection iteration per level is needed");
  problem.validate();
  CGAL::MDCS::internal::Progress_reporter<Progress> reporter(progress, "multilevel refinement", offsets.size());
  const std::size_t threads = CGAL::MDCS::effective_threads(options.threads, true);
  const std::size_t pencils = surface_pencil_count_3(problem, n, options);
  const double range = problem.zmax - problem.zmin;
  Surface_multilevel_result_3 result;

  reporter(0);
  Clock::time_point start = Clock::now();
  {
    const Plane_selection_result_3 first =
      select_planes_3(problem, G, n, levels.selection_iterations, options, quadrature_level, engine);
    if(!first.surface.is_feasible) throw std::invalid_argument(std::string(name) + "level 0 found no surface");
    result.surface = first.surface;
    result.planes = first.planes;
    Surface_refinement_level_3 level;
    level.offset = offsets[0];
    level.energy = first.surface.energy;
    level.solve_energies = first.energies;
    level.planes = first.planes.size();
    level.kept_planes = 0;
    level.cells = first.cells.back();
    level.network_nodes = first.cells.back();
    level.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    result.levels.push_back(level);
  }
  // The pencils are the first planes of every list below (surface_planes_3 puts them first and they are kept).
  const std::vector<Lattice_plane_3> pencil_planes(result.planes.begin(),
                                                   result.planes.begin() + std::ptrdiff_t(pencils));
  // The planes of the best surface and the pencils, each once.
  const auto kept_planes = [&](const Minimal_surface_3& s, const std::vector<Lattice_plane_3>& planes) {
    std::vector<Lattice_plane_3> kept = pencil_planes;
    for(std::uint32_t p : s.planes)
      if(p >= Arr::number_of_walls) kept.push_back(planes[p - Arr::number_of_walls]);
    return internal::unique_planes_3(kept);
  };
  for(std::size_t l = 1; l < offsets.size(); ++l) {
    reporter(l);
    start = Clock::now();
    // The envelope stays around the previous level's optimum for the whole level (it refers to this copy).
    const std::vector<Minimal_surface_3> centre{result.surface};
    const internal::Surface_envelope_3 envelope(problem, centre, offsets[l] * range);
    Surface_refinement_level_3 level;
    level.offset = offsets[l];
    for(int it = 0; it < levels.selection_iterations; ++it) {
      std::vector<Lattice_plane_3> planes = kept_planes(result.surface, result.planes);
      if(it == 0) level.kept_planes = planes.size();
      std::mt19937_64 rng((options.seed + 7919 * std::uint64_t(l)) * 6364136223846793005ull +
                          1442695040888963407ull * std::uint64_t(2 * it + 1));
      internal::add_planes_in_envelope_3(problem, options, envelope, n, rng, planes);
      const Arr arrangement(planes, CGAL::MDCS::No_progress(), threads);
      internal::Envelope_cut_counts_3 counts;
      const Minimal_surface_3 s = internal::minimize_in_envelope_3(arrangement, problem, G, envelope,
                                                                   quadrature_level, engine, counts);
      if(!s.is_feasible)
        throw std::invalid_argument(std::string(name) + "level " + std::to_string(l) + " found no surface");
      level.solve_energies.push_back(s.energy);
      level.planes = planes.size();
      level.cells = counts.cells;
      level.network_nodes = counts.network_nodes;
      if(s.energy < result.surface.energy) {
        result.surface = s;
        result.planes = planes;
      }
    }
    level.energy = result.surface.energy;
    level.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    result.levels.push_back(level);
  }
  reporter.finish();
  return result;
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_REFINE_SURFACE_MULTILEVEL_3_H
