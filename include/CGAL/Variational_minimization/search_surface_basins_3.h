// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Basin search (issue 6, blob experiment): plane selection finds discrete optima whose relaxed energies lie in
// several basins of the continuous problem; the discrete energies at a few 10^5 cells do not tell the basins apart.
// The basin search compares candidates by their *relaxed* energy and proposes new candidates by constrained
// minimum cuts: over one tile of the domain the cut is forced above (or below) the current relaxed optimum, the
// rest of the surface is free; the best discrete surface under that constraint is relaxed and kept if its relaxed
// energy is lower.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_SEARCH_SURFACE_BASINS_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_SEARCH_SURFACE_BASINS_3_H

#include <CGAL/MDCS/concurrency.h>
#include <CGAL/MDCS/progress.h>
#include <CGAL/Min_cut/internal/contract_terminal_nodes.h>
#include <CGAL/Min_cut/solve_min_cut.h>
#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/internal/surface_dual_network_3.h>
#include <CGAL/Variational_minimization/internal/surface_envelope_cut_3.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/relax_surface_3.h>
#include <CGAL/Variational_minimization/select_planes_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/// Options of `search_surface_basins_3()` and `select_planes_relaxed_3()`.
struct Surface_basin_search_options_3
{
  /// The tilings of the domain's bounding box: `t` gives `t x t` equal tiles. Every tile is tried twice per sweep
  /// (surface forced up, then down).
  std::vector<int> tilings = {3, 4};
  /// How far the surface is forced away from the current relaxed optimum over a tile, as a share of zmax - zmin.
  double shift = 0.1;
  /// Sweeps over all moves at most; the search stops after a sweep that improved nothing.
  int sweeps = 3;
  /// A second stage with wider moves, run once the first stage (`tilings`, `shift`) stops: coarser tiles and a
  /// larger shift can leave a basin from which no move of the first stage improves (blob seed 125 of the
  /// benchmark). It only adds moves, so the result is never worse than the first stage's. Empty: no second stage.
  std::vector<int> wide_tilings = {2, 3, 4};
  /// The shift of the second stage, as a share of zmax - zmin.
  double wide_shift = 0.3;
  /// The relaxation that gives every candidate its energy (default: L-BFGS on 20^2 then 40^2).
  Surface_relaxation_options_3 relaxation = [] {
    Surface_relaxation_options_3 o;
    o.grids = {20, 40};
    return o;
  }();
  /// Threads (0: all hardware threads; TBB needed, else 1) for the relaxations of the starts and the moves, which
  /// are evaluated speculatively in parallel batches (see `search_surface_basins_3()`). Results do not depend on it.
  std::size_t threads = 1;
};

/// The outcome of `search_surface_basins_3()`.
struct Surface_basin_search_result_3
{
  /// The best relaxed surface found (never worse than the relaxed start).
  Relaxed_surface_3 relaxed;
  /// The discrete surface it was relaxed from.
  Minimal_surface_3 discrete;
  /// The relaxed energy of the start.
  double start_energy = std::numeric_limits<double>::infinity();
  /// Moves tried (constrained cuts solved; infinite cuts included), moves that lowered the relaxed energy, sweeps.
  std::size_t moves = 0, improvements = 0, sweeps = 0;
};

namespace internal {

// The height of a relaxed grid surface at (x, y): linear on the grid's triangles (as relax_surface_3 meshes them).
inline double relaxed_height_3(const Surface_problem_3& problem, const Relaxed_surface_3& r, double x, double y)
{
  const int n = r.n;
  const double u = (x - problem.domain.xmin()) / (problem.domain.xmax() - problem.domain.xmin()) * n;
  const double v = (y - problem.domain.ymin()) / (problem.domain.ymax() - problem.domain.ymin()) * n;
  const int i = (std::max)(0, (std::min)(n - 1, int(std::floor(u))));
  const int j = (std::max)(0, (std::min)(n - 1, int(std::floor(v))));
  const double a = (std::max)(0.0, (std::min)(1.0, u - i)), b = (std::max)(0.0, (std::min)(1.0, v - j));
  auto at = [&](int p, int q) { return r.heights[std::size_t(q) * std::size_t(n + 1) + std::size_t(p)]; };
  if(a + b <= 1) return at(i, j) + a * (at(i + 1, j) - at(i, j)) + b * (at(i, j + 1) - at(i, j));
  return at(i + 1, j + 1) + (1 - a) * (at(i, j + 1) - at(i + 1, j + 1)) + (1 - b) * (at(i + 1, j) - at(i + 1, j + 1));
}

// The input checks of search_surface_basins_3().
inline void check_basin_search_input_3(const Plane_arrangement_3& arrangement, const std::vector<double>& weights,
                                       const Surface_problem_3& problem, const Surface_basin_search_options_3& options)
{
  problem.validate();
  if(problem.is_polygonal())
    throw std::invalid_argument("MDCS: search_surface_basins_3: the basin search needs a rectangular domain (it "
                                "relaxes on grids over the rectangle)");
  if(weights.size() != arrangement.number_of_facets())
    throw std::invalid_argument("MDCS: search_surface_basins_3: one weight per facet of the arrangement is needed");
  for(const std::vector<int>* tilings : {&options.tilings, &options.wide_tilings})
    for(int t : *tilings)
      if(t < 1 || t > 64) throw std::invalid_argument("MDCS: search_surface_basins_3: tilings must be in [1, 64]");
  if(!(options.shift > 0 && std::isfinite(options.shift)))
    throw std::invalid_argument("MDCS: search_surface_basins_3: the shift must be finite and > 0");
  if(!options.wide_tilings.empty() && !(options.wide_shift > 0 && std::isfinite(options.wide_shift)))
    throw std::invalid_argument("MDCS: search_surface_basins_3: the wide shift must be finite and > 0");
}

// One move of the basin search: tile (ti, tj) of the t x t tiling, surface forced up (+1) or down (-1).
struct Basin_move_3
{
  int t, ti, tj, direction;
};

// What a move gives against the current relaxed optimum: whether it tied any cell, the constrained discrete
// optimum and its relaxation (when feasible).
struct Basin_move_outcome_3
{
  bool tied = false;
  Minimal_surface_3 discrete;
  Relaxed_surface_3 relaxed;
};

// Evaluates `move` against `current` (read only): the code of the sequential search, so that a move evaluated on
// any thread gives the same outcome.
template <class Functional, class Engine>
Basin_move_outcome_3 evaluate_basin_move_3(const Plane_arrangement_3& arrangement, const std::vector<double>& weights,
                                           const Surface_problem_3& problem, const Functional& G,
                                           const Surface_basin_search_options_3& options, double delta,
                                           const CGAL::Min_cut::Flow_network<double>& network,
                                           const std::vector<std::array<double, 3>>& points,
                                           const Relaxed_surface_3& current, const Basin_move_3& move, Engine engine,
                                           std::vector<char>& label)
{
  Basin_move_outcome_3 out;
  const double wx = problem.domain.xmax() - problem.domain.xmin(), wy = problem.domain.ymax() - problem.domain.ymin();
  label.assign(points.size(), 0);
  std::size_t tied = 0;
  const int t = move.t;
  for(std::size_t c = 0; c < points.size(); ++c) {
    const auto& p = points[c];
    const int i = (std::min)(t - 1, int(std::floor((p[0] - problem.domain.xmin()) / wx * t)));
    const int j = (std::min)(t - 1, int(std::floor((p[1] - problem.domain.ymin()) / wy * t)));
    if(i != move.ti || j != move.tj) continue;
    const double h = relaxed_height_3(problem, current, p[0], p[1]);
    if(move.direction > 0 && p[2] < h + delta) label[c] = 1;
    else if(move.direction < 0 && p[2] > h - delta) label[c] = 2;
    tied += label[c] != 0;
  }
  if(tied == 0) return out;
  out.tied = true;
  out.discrete = surface_from_contracted_cut_3(
    arrangement, problem, weights, CGAL::Min_cut::internal::contract_terminal_nodes(network, label), engine);
  if(out.discrete.is_feasible) out.relaxed = relax_surface_3(problem, G, out.discrete, options.relaxation);
  return out;
}

// One stage of the basin search: sweeps over the moves of `tilings` with the shift `shift` (see
// search_surface_basins_3()), until a sweep improves nothing or `options.sweeps` are done.
//
// On several threads the moves are evaluated speculatively: a batch of consecutive moves is evaluated in parallel
// against the current optimum, then scanned in order; the first that improves is accepted and the rest of the
// batch, evaluated against the old optimum, is discarded and evaluated again from the next move on. The moves
// accepted are therefore exactly those of the sequential search, whatever the number of threads; only the
// discarded evaluations cost extra (at most one batch per improvement, and improvements are rare).
template <class Functional, class Engine, class Progress>
void basin_search_stage_3(const Plane_arrangement_3& arrangement, const std::vector<double>& weights,
                          const Surface_problem_3& problem, const Functional& G,
                          const Surface_basin_search_options_3& options, const std::vector<int>& tilings,
                          double shift, const CGAL::Min_cut::Flow_network<double>& network,
                          const std::vector<std::array<double, 3>>& points, Engine engine, Progress& progress,
                          Surface_basin_search_result_3& result)
{
  std::vector<Basin_move_3> moves;
  for(int t : tilings)
    for(int tj = 0; tj < t; ++tj)
      for(int ti = 0; ti < t; ++ti)
        for(int direction : {+1, -1}) moves.push_back(Basin_move_3{t, ti, tj, direction});
  const std::size_t per_sweep = moves.size();
  if(per_sweep == 0) return;
  const double delta = shift * (problem.zmax - problem.zmin);
  const std::size_t threads = CGAL::MDCS::effective_threads(options.threads, true);
  const std::size_t batch = threads <= 1 ? 1 : threads;
  std::vector<Basin_move_outcome_3> outcomes(batch);
  std::vector<std::vector<char>> labels(batch);
  for(int sweep = 0; sweep < options.sweeps; ++sweep) {
    CGAL::MDCS::internal::Progress_reporter<Progress> reporter(progress, "basin search", per_sweep);
    ++result.sweeps;
    bool improved = false;
    std::size_t next = 0;
    while(next < per_sweep) {
      reporter(next);
      const std::size_t count = (std::min)(batch, per_sweep - next);
      CGAL::MDCS::parallel_for_blocks_lowest_error(count, 1, threads, [&](std::size_t k, std::size_t, std::size_t) {
        outcomes[k] = evaluate_basin_move_3(arrangement, weights, problem, G, options, delta, network, points,
                                            result.relaxed, moves[next + k], engine, labels[k]);
      });
      std::size_t k = 0;
      for(; k < count; ++k) {
        ++result.moves;
        Basin_move_outcome_3& o = outcomes[k];
        if(!o.tied || !o.discrete.is_feasible) continue;
        if(o.relaxed.energy < result.relaxed.energy * (1 - 1e-9)) {
          result.relaxed = std::move(o.relaxed);
          result.discrete = std::move(o.discrete);
          ++result.improvements;
          improved = true;
          ++k;
          break; // the later moves of the batch saw the old optimum: evaluate them again
        }
      }
      next += k;
    }
    reporter.finish();
    if(!improved) break;
  }
}

// Continues a basin search from `result.relaxed` / `result.discrete` (see search_surface_basins_3()).
template <class Functional, class Engine, class Progress>
void continue_basin_search_3(const Plane_arrangement_3& arrangement, const std::vector<double>& weights,
                             const Surface_problem_3& problem, const Functional& G,
                             const Surface_basin_search_options_3& options, Engine engine, Progress& progress,
                             Surface_basin_search_result_3& result)
{
  result.start_energy = result.relaxed.energy;
  if(options.sweeps < 1 || (options.tilings.empty() && options.wide_tilings.empty())) return;
  const CGAL::Min_cut::Flow_network<double> network = surface_dual_network_3(arrangement, weights, problem);
  const std::vector<std::array<double, 3>> points = cell_points_3(arrangement, problem);
  basin_search_stage_3(arrangement, weights, problem, G, options, options.tilings, options.shift, network, points,
                       engine, progress, result);
  basin_search_stage_3(arrangement, weights, problem, G, options, options.wide_tilings, options.wide_shift, network,
                       points, engine, progress, result);
}

} // namespace internal

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief Basin search on one arrangement: starting from the relaxed surfaces of `starts` (discrete surfaces, e.g.
  the round optima of `select_planes_3()`; each is relaxed with `options.relaxation` and the best kept), tries
  *moves*: for every tile of every tiling in `options.tilings` and both directions, the minimum cut of the
  arrangement's dual network (weights `weights`) with the cells of the tile lying below (above) the current relaxed
  optimum shifted up (down) by `options.shift * (zmax - zmin)` tied to the source (sink) — the best discrete
  surface that leaves the current basin over that tile. That surface is relaxed; if its relaxed energy is lower,
  it becomes the current optimum (the next moves use it). Sweeps repeat until one improves nothing or
  `options.sweeps` are done. Then a second stage does the same with `options.wide_tilings` and
  `options.wide_shift` (wider moves; empty `wide_tilings`: none). Deterministic; the relaxed energy never increases.
  On `options.threads` threads the starts are relaxed in parallel and the moves evaluated in parallel batches
  against the current optimum, scanned in order: the first improving move is accepted and the rest of its batch is
  evaluated again, so the accepted moves, hence the result, are those of the sequential search. The constrained cuts use
  `CGAL::Min_cut::internal::contract_terminal_nodes` on the full `Flow_network` (built once).
  `progress` is called with stage `"basin search"` (fraction of the moves of the sweep).
  \throws std::invalid_argument for an invalid or polygonal problem, no feasible start, a weight vector of the
          wrong size, a tiling < 1, or a shift that is not finite and > 0.
*/
template <class Functional, class Engine = CGAL::Min_cut::Default_max_flow_engine,
          class Progress = CGAL::MDCS::No_progress>
Surface_basin_search_result_3 search_surface_basins_3(const Plane_arrangement_3& arrangement,
                                                      const std::vector<double>& weights,
                                                      const Surface_problem_3& problem, const Functional& G,
                                                      const std::vector<Minimal_surface_3>& starts,
                                                      const Surface_basin_search_options_3& options =
                                                        Surface_basin_search_options_3(),
                                                      Engine engine = Engine(), Progress progress = Progress())
{
  internal::check_basin_search_input_3(arrangement, weights, problem, options);
  Surface_basin_search_result_3 result;
  // The starts are relaxed independently (in parallel), the best chosen in their order.
  std::vector<Relaxed_surface_3> relaxed(starts.size());
  CGAL::MDCS::parallel_for_blocks_lowest_error(starts.size(), 1, CGAL::MDCS::effective_threads(options.threads, true),
                                               [&](std::size_t k, std::size_t, std::size_t) {
    if(starts[k].is_feasible) relaxed[k] = relax_surface_3(problem, G, starts[k], options.relaxation);
  });
  for(std::size_t k = 0; k < starts.size(); ++k) {
    if(!starts[k].is_feasible) continue;
    if(relaxed[k].energy < result.relaxed.energy) {
      result.relaxed = std::move(relaxed[k]);
      result.discrete = starts[k];
    }
  }
  if(!(result.relaxed.energy < std::numeric_limits<double>::infinity()))
    throw std::invalid_argument("MDCS: search_surface_basins_3: no feasible start surface");
  internal::continue_basin_search_3(arrangement, weights, problem, G, options, engine, progress, result);
  return result;
}

/// The outcome of `select_planes_relaxed_3()`.
struct Relaxed_plane_selection_result_3
{
  /// Plane selection (every round's optimum in `selection.surfaces`).
  Plane_selection_result_3 selection;
  /// The relaxed energy of each round's optimum (rounds with the same discrete energy share one relaxation).
  std::vector<double> round_relaxed_energies;
  /// The basin search on the arrangement of the best discrete optimum, started from the best relaxed round
  /// optimum: its `relaxed` member is the answer.
  Surface_basin_search_result_3 search;
};

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief Plane selection with relaxed comparison and basin search: `select_planes_3(problem, G, n, rounds,
  plane_options)`, every distinct round optimum relaxed (`search_options.relaxation`), then
  `search_surface_basins_3()` on the arrangement of the best discrete optimum, started from the best relaxed round
  optimum. The answer (`search.relaxed`) has a relaxed energy no higher than the best relaxed round optimum,
  i.e. than plain plane selection with every round relaxed; with `search_options.sweeps = 0` it is exactly that.
  Deterministic for given options (seed included), whatever the thread counts: `plane_options.threads` for the
  selection's facet weights, `search_options.threads` for the relaxations and the search (the larger of the two for
  the final arrangement's weights). `progress` is called with the stages of the two steps.
  \throws std::invalid_argument as `select_planes_3()` and `search_surface_basins_3()`.
*/
template <class Functional, class Engine = CGAL::Min_cut::Default_max_flow_engine,
          class Progress = CGAL::MDCS::No_progress>
Relaxed_plane_selection_result_3 select_planes_relaxed_3(const Surface_problem_3& problem, const Functional& G,
                                                         std::size_t n, int rounds,
                                                         const Surface_plane_options_3& plane_options =
                                                           Surface_plane_options_3(),
                                                         const Surface_basin_search_options_3& search_options =
                                                           Surface_basin_search_options_3(),
                                                         Engine engine = Engine(), Progress progress = Progress())
{
  problem.validate();
  if(problem.is_polygonal())
    throw std::invalid_argument("MDCS: select_planes_relaxed_3: the relaxation needs a rectangular domain");
  Relaxed_plane_selection_result_3 out;
  out.selection = select_planes_3(problem, G, n, rounds, plane_options, 1, engine, progress);
  const Plane_arrangement_3 arrangement(out.selection.planes, CGAL::MDCS::No_progress(),
                                         CGAL::MDCS::effective_threads(plane_options.threads, true));
  const std::vector<double> w =
    surface_facet_weights_3<CGAL::Parallel_if_available_tag>(arrangement, problem, G, 1,
                                                              (std::max)(CGAL::MDCS::effective_threads(plane_options.threads, true),
                                                                         CGAL::MDCS::effective_threads(search_options.threads, true)));
  internal::check_basin_search_input_3(arrangement, w, problem, search_options);
  // Relax each distinct round optimum once (an equal discrete energy is the same kept surface).
  std::vector<double> seen, relaxed;
  Surface_basin_search_result_3& result = out.search;
  // The distinct round optima (in round order), relaxed independently (in parallel), then compared in that order.
  std::vector<std::size_t> distinct;
  for(std::size_t i = 0; i < out.selection.surfaces.size(); ++i) {
    const Minimal_surface_3& s = out.selection.surfaces[i];
    if(std::find(seen.begin(), seen.end(), s.energy) != seen.end()) continue;
    if(!s.is_feasible) throw std::invalid_argument("MDCS: select_planes_relaxed_3: a round found no surface");
    seen.push_back(s.energy);
    distinct.push_back(i);
  }
  std::vector<Relaxed_surface_3> relaxations(distinct.size());
  CGAL::MDCS::parallel_for_blocks_lowest_error(
    distinct.size(), 1, CGAL::MDCS::effective_threads(search_options.threads, true),
    [&](std::size_t k, std::size_t, std::size_t) {
      relaxations[k] = relax_surface_3(problem, G, out.selection.surfaces[distinct[k]], search_options.relaxation);
    });
  for(std::size_t k = 0; k < distinct.size(); ++k) {
    relaxed.push_back(relaxations[k].energy);
    if(relaxations[k].energy < result.relaxed.energy) {
      result.relaxed = std::move(relaxations[k]);
      result.discrete = out.selection.surfaces[distinct[k]];
    }
  }
  for(const Minimal_surface_3& s : out.selection.surfaces)
    out.round_relaxed_energies.push_back(relaxed[std::size_t(std::find(seen.begin(), seen.end(), s.energy) - seen.begin())]);
  internal::continue_basin_search_3(arrangement, w, problem, G, search_options, engine, progress, result);
  return out;
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_SEARCH_SURFACE_BASINS_3_H
