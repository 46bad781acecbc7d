// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Adaptive refinement (thesis ch. 2.7, issue 6 item 4): several solves on independent random arrangements give an
// envelope of the optimum; a new arrangement keeps the planes of every run's optimum and adds new planes inside
// the envelope; its cells below the envelope are tied to the source, those above to the sink.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_REFINE_SURFACE_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_REFINE_SURFACE_3_H

#include <CGAL/MDCS/concurrency.h>
#include <CGAL/MDCS/progress.h>
#include <CGAL/Min_cut/solve_min_cut.h>
#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/internal/surface_envelope_cut_3.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/// The outcome of `refine_surface_3()`.
struct Surface_refinement_result_3
{
  /// The optimum on the refined arrangement (no worse than the best run, up to rounding of the weights).
  Minimal_surface_3 surface;
  /// The energy of each independent run's optimum.
  std::vector<double> run_energies;
  /// The planes of the refined arrangement, and how many of them were kept from the runs' optima.
  std::vector<Lattice_plane_3> planes;
  std::size_t kept_planes = 0;
  /// The refined arrangement's cells, and those tied to the source (below the envelope) or the sink (above).
  std::size_t cells = 0, cells_below = 0, cells_above = 0;
  /// On a polygonal domain, the cells outside Ω (no arcs; left out of the network); 0 on a rectangle.
  std::size_t cells_outside = 0;
  /// The contracted flow network that was solved: its nodes (the cells inside the widened envelope) and interior
  /// facets (arcs between two of them).
  std::size_t network_nodes = 0, network_facets = 0;
};

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief Adaptive refinement: `runs` solves with `n` planes each (seeds `options.seed + 104729 r`) give surfaces
  s_1..s_runs and their envelope [min s_r, max s_r]. The refined arrangement has `n` planes: the pencils of the
  first run and every plane carrying a facet of a run's optimum (so that each s_r is a union of its facets), then
  new planes through random points of the envelope widened by `margin` (world z units), with the orientations of
  `options.distribution`. Its cells lying lower than `margin` below the envelope are tied to the source, those
  higher than `margin` above it to the sink, so the cut is searched inside the envelope only: these cells are
  contracted into the terminals (`network_nodes` and `network_facets` give the smaller network that is solved).
  Every s_r stays feasible, hence the refined energy is at most the best run's (up to the rounding of the weights;
  exactly for closed-form weights). If the runs' optima need more than `n` planes, all are kept (more than `n`).
  The runs are computed on `options.threads` threads (0: all hardware threads), one run per thread (memory: one
  arrangement per busy thread); the result does not depend on the thread count.
  `progress` is called with stage `"refinement"`.
  On a polygonal domain the kept planes include the vertical planes of the polygon's edges (they are among the
  first run's pencils), the new planes pass through random points of the envelope over Ω (points of the bounding
  box outside the polygon are redrawn), and the cells outside Ω, which have no arcs, are left out of the network
  (they are not counted in `cells_below` or `cells_above`).
  \throws std::invalid_argument for an invalid problem or functional, `runs < 1`, a negative or NaN margin, or a
          run without a feasible surface.
*/
template <class Functional, class Engine = CGAL::Min_cut::Default_max_flow_engine,
          class Progress = CGAL::MDCS::No_progress>
Surface_refinement_result_3 refine_surface_3(const Surface_problem_3& problem, const Functional& G, std::size_t n,
                                             int runs, const Surface_plane_options_3& options = Surface_plane_options_3(),
                                             double margin = 0, int quadrature_level = 1, Engine engine = Engine(),
                                             Progress progress = Progress())
{
  typedef Plane_arrangement_3 Arr;
  if(runs < 1) throw std::invalid_argument("MDCS: refine_surface_3: at least one run is needed");
  if(!(margin >= 0)) throw std::invalid_argument("MDCS: refine_surface_3: the margin must be >= 0");
  problem.validate();
  CGAL::MDCS::internal::Progress_reporter<Progress> reporter(progress, "refinement", std::size_t(runs) + 1);
  Surface_refinement_result_3 result;
  std::vector<Minimal_surface_3> surfaces(static_cast<std::size_t>(runs));
  std::vector<std::vector<Lattice_plane_3>> run_planes(static_cast<std::size_t>(runs));
  std::vector<Lattice_plane_3> kept;
  // The runs are independent: on several threads each runs on one of them (spare threads compute facet weights);
  // their results are combined below in run order, so nothing depends on the thread count.
  const std::size_t threads = CGAL::MDCS::effective_threads(options.threads, true);
  const std::size_t outer = (std::min)(threads, std::size_t(runs)), inner = (std::max)(std::size_t(1), threads / outer);
  const auto solve_run = [&](std::size_t r) {
    Surface_plane_options_3 o = options;
    o.seed = options.seed + 104729 * std::uint64_t(r);
    run_planes[r] = surface_planes_3(problem, n, o);
    const Arr arrangement(run_planes[r], CGAL::MDCS::No_progress(), inner);
    CGAL::MDCS::No_progress none;
    surfaces[r] = internal::minimize_surface_functional_threads_3(arrangement, problem, G, quadrature_level, inner,
                                                                  engine, none);
  };
  if(outer <= 1) {
    for(int r = 0; r < runs; ++r) {
      reporter(std::size_t(r));
      solve_run(std::size_t(r));
    }
  } else {
    CGAL::MDCS::Parallel_progress<Progress> parallel_reporter(progress, "refinement", std::size_t(runs) + 1);
    CGAL::MDCS::parallel_for_blocks_lowest_error(std::size_t(runs), 1, outer, [&](std::size_t r, std::size_t, std::size_t) {
      if(parallel_reporter.cancelled()) return;
      solve_run(r);
      parallel_reporter.advance();
    });
    if(parallel_reporter.cancelled()) parallel_reporter.finish(); // throws Operation_cancelled
  }
  for(int r = 0; r < runs; ++r) {
    const std::vector<Lattice_plane_3>& planes = run_planes[std::size_t(r)];
    const Minimal_surface_3& s = surfaces[std::size_t(r)];
    if(!s.is_feasible) throw std::invalid_argument("MDCS: refine_surface_3: a run found no surface");
    result.run_energies.push_back(s.energy);
    if(r == 0)
      for(std::size_t i = 0; i < surface_pencil_count_3(problem, n, options) && i < planes.size(); ++i)
        kept.push_back(planes[i]);
    for(std::uint32_t p : s.planes)
      if(p >= Arr::number_of_walls) kept.push_back(planes[p - Arr::number_of_walls]);
  }
  result.planes = internal::unique_planes_3(kept);
  result.kept_planes = result.planes.size();
  const internal::Surface_envelope_3 envelope(problem, surfaces, margin);
  {
    std::mt19937_64 rng(options.seed * 6364136223846793005ull + 1442695040888963407ull);
    internal::add_planes_in_envelope_3(problem, options, envelope, n, rng, result.planes);
  }
  reporter(std::size_t(runs));
  const Arr arrangement(result.planes, CGAL::MDCS::No_progress(), threads);
  internal::Envelope_cut_counts_3 counts;
  result.surface = internal::minimize_in_envelope_3(arrangement, problem, G, envelope, quadrature_level, engine, counts);
  std::tie(result.cells, result.cells_below, result.cells_above, result.cells_outside, result.network_nodes,
           result.network_facets) = std::make_tuple(counts.cells, counts.cells_below, counts.cells_above,
                                                    counts.cells_outside, counts.network_nodes, counts.network_facets);
  reporter.finish();
  return result;
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_REFINE_SURFACE_3_H
