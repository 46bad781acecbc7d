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
#include <CGAL/Min_cut/internal/contract_terminal_nodes.h>
#include <CGAL/Min_cut/solve_min_cut.h>
#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/internal/surface_domain_cells_3.h>
#include <CGAL/Variational_minimization/internal/surface_dual_network_3.h>
#include <CGAL/Variational_minimization/internal/surface_height_3.h>
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
  // Duplicates are harmless (the arrangement drops them), but they would count against n.
  std::vector<Lattice_plane_3> unique;
  for(const Lattice_plane_3& p : kept) {
    const Lattice_plane_3 q = internal::normalized_plane(p);
    bool seen = false;
    for(const Lattice_plane_3& u : unique) seen = seen || (u.a == q.a && u.b == q.b && u.c == q.c && u.d == q.d);
    if(!seen) unique.push_back(q);
  }
  result.planes = unique;
  result.kept_planes = unique.size();
  std::vector<internal::Surface_height_3> heights;
  for(const Minimal_surface_3& s : surfaces) heights.emplace_back(s);
  auto envelope = [&](double x, double y, double& lo, double& hi) {
    lo = 1e300;
    hi = -1e300;
    for(const auto& h : heights) {
      const double z = h(x, y);
      lo = (std::min)(lo, z);
      hi = (std::max)(hi, z);
    }
  };
  // New planes through random points of the widened envelope.
  {
    const double L = double(Arr::lattice_size);
    const double sx = (problem.domain.xmax() - problem.domain.xmin()) / L,
                 sy = (problem.domain.ymax() - problem.domain.ymin()) / L, sz = (problem.zmax - problem.zmin) / L;
    std::mt19937_64 rng(options.seed * 6364136223846793005ull + 1442695040888963407ull);
    std::uniform_real_distribution<double> U(0, 1), S(-options.max_slope, options.max_slope);
    std::normal_distribution<double> N;
    const std::vector<internal::Lattice_point_2> polygon = problem.lattice_polygon();
    while(result.planes.size() < n) {
      const double u = U(rng), v = U(rng);
      if(problem.is_polygonal() && !internal::lattice_polygon_contains(polygon, u * L, v * L)) continue;
      const double x = problem.domain.xmin() + u * (problem.domain.xmax() - problem.domain.xmin()),
                   y = problem.domain.ymin() + v * (problem.domain.ymax() - problem.domain.ymin());
      double lo, hi;
      envelope(x, y, lo, hi);
      lo = (std::max)(problem.zmin, lo - margin);
      hi = (std::min)(problem.zmax, hi + margin);
      const double z = lo + U(rng) * (hi - lo);
      const std::array<double, 3> q = {{u * L, v * L, (z - problem.zmin) / sz}};
      std::array<double, 3> normal;
      if(options.distribution == Plane_distribution_3::isotropic) normal = {{N(rng), N(rng), N(rng)}};
      else normal = {{-S(rng) * sx / sz, -S(rng) * sy / sz, 1.0}};
      if(!(std::abs(normal[0]) + std::abs(normal[1]) + std::abs(normal[2]) > 1e-12)) continue;
      result.planes.push_back(internal::plane_through(normal, q));
    }
  }
  reporter(std::size_t(runs));
  const Arr arrangement(result.planes, CGAL::MDCS::No_progress(), threads);
  result.cells = arrangement.number_of_cells();
  // Cells outside the widened envelope, by an interior point (the mean of the vertices: no s_r crosses a cell),
  // are contracted into the source (label 1) or the sink (label 2).
  std::vector<char> label(arrangement.number_of_cells(), 0);
  const double eps = margin + 1e-9 * (problem.zmax - problem.zmin);
  // Cells outside a polygonal Ω have no arcs: merging them into the source leaves them out of the network.
  const std::vector<char> inside = internal::surface_domain_cells_3(arrangement, problem);
  for(std::size_t c = 0; c < arrangement.number_of_cells(); ++c) {
    if(!inside[c]) {
      label[c] = 1;
      ++result.cells_outside;
      continue;
    }
    std::array<double, 3> m = {{0, 0, 0}};
    std::size_t k = 0;
    for(Arr::Facet_index f : arrangement.cell_facets(Arr::Cell_index(c)))
      for(std::size_t i = 0; i < arrangement.facet_degree(f); ++i, ++k)
        for(int j = 0; j < 3; ++j) m[j] += arrangement.point(arrangement.facet_vertex(f, i))[j];
    for(int j = 0; j < 3; ++j) m[j] /= double(k);
    const std::array<double, 3> p = problem.to_world(m);
    double lo, hi;
    envelope(p[0], p[1], lo, hi);
    if(p[2] < lo - eps) {
      label[c] = 1;
      ++result.cells_below;
    } else if(p[2] > hi + eps) {
      label[c] = 2;
      ++result.cells_above;
    }
  }
  // The contracted network is built straight from the arrangement: neither the full network nor a weight vector
  // exists, and G is integrated only over the facets that can still matter (those touching a cell inside the
  // envelope, and those between a cell below it and one above it, which every cut crosses).
  const auto weight_of = [&](Arr::Facet_index f) {
    return surface_facet_weight_3(arrangement, problem, G, f, quadrature_level);
  };
  CGAL::Min_cut::internal::Contracted_network<double> reduced;
  {
    CGAL::Min_cut::internal::Terminal_contraction<double> builder(label);
    internal::build_surface_dual_network_3(arrangement, weight_of, problem, builder);
    reduced = builder.release();
  }
  result.network_nodes = reduced.network.number_of_nodes();
  result.network_facets = reduced.network.number_of_facets();
  result.surface = internal::surface_from_contracted_cut_3(arrangement, problem, weight_of, reduced, engine);
  reporter.finish();
  return result;
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_REFINE_SURFACE_3_H
