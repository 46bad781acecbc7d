// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Regular plane grids against random planes (thesis ch. 2.5.3; issue 30 item 2): the error of the minimal discrete
// energy, and of the surface's heights, against the number of planes, on two problems with a known minimum:
//   membrane: sagging_membrane_problem() (unit square, rim at 0.75, area + 2 f); reference: relaxation on 20^2..160^2
//             grids (the minimiser is unique; the relaxed function is also the reference of the heights);
//   scherk:   Scherk's surface on [-1.2, 1.2]^2, 4 boundary segments per side; reference energy: the minimal area
//             spanning the piecewise linear boundary curve (what the discrete energies converge to), by relaxation;
//             heights against the analytic surface ln(cos y / cos x).
// Sources: the regular grid regular_surface_planes_3(n) with m = 1 and m = n offset steps (m = n for n = 2, 3 on the
// membrane, n = 2 on Scherk), and slope-limited random planes (surface_planes_3, 20% pencils, the same max_slope) with
// as many planes as the grid of each n with m = 1, several seeds (median, min, max; at most 3 on Scherk).
//
//   bench_surface_plane_grids_3 [--quick] [--seeds K] [--problem membrane|scherk|both] [--csv PATH]
//
// Defaults: 5 seeds, both problems, benchmark/results/surface_plane_grids.csv (relative to the working directory).
// The manual's picture is drawn from the CSV by benchmark/python/plot_surface_plane_grids.py.

#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/analytic_solutions_3.h>
#include <CGAL/Variational_minimization/internal/surface_height_3.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/plane_grids_3.h>
#include <CGAL/Variational_minimization/relax_surface_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include "mdcs_bench.h"
#include <MDCS_test/surface_problems.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace VM = CGAL::Variational_minimization;
using mdcs_bench::fmt;

namespace {

struct Experiment
{
  std::string name;
  VM::Surface_problem_3 problem;
  std::function<std::vector<double>(const VM::Plane_arrangement_3&)> weights;
  double max_slope = 1;
  std::vector<std::size_t> grid_steps; // the n of the regular grids
  std::size_t largest_n_with_m_n = 0;  // the grids with m = n are run for 2 <= n <= this
  int seeds = 5;
  double reference_energy = 0;
  std::function<double(double, double)> reference_height;
};

struct Run
{
  std::size_t planes = 0, cells = 0, used_planes = 0, used_interior = 0;
  double energy = 0, energy_error = 0, height_error = 0, seconds = 0, cpu_seconds = 0;
};

// The discrete minimum on `planes`, its energy error relative to the reference, and the RMS of its height error at
// the 39 x 39 interior points of a 40 x 40 grid over the domain.
Run solve(const Experiment& e, const std::vector<VM::Lattice_plane_3>& planes)
{
  Run r;
  const double t0 = mdcs_bench::now_seconds(), c0 = mdcs_bench::cpu_seconds();
  const VM::Plane_arrangement_3 A(planes);
  const VM::Minimal_surface_3 s = VM::minimize_surface_functional_3(A, e.weights(A), e.problem);
  r.seconds = mdcs_bench::now_seconds() - t0;
  r.cpu_seconds = mdcs_bench::cpu_seconds() - c0;
  r.planes = planes.size();
  r.cells = A.number_of_cells();
  r.energy = s.energy;
  // Which planes the optimum lies on: a boundary plane holds a segment of the boundary curve (a cone or pencil
  // plane), the others are interior (the grid's gradient families, or the free random planes).
  const auto loop = e.problem.boundary_loop(false);
  for(std::uint32_t q : s.planes) {
    if(q < VM::Plane_arrangement_3::number_of_walls) continue;
    const VM::Lattice_plane_3& p = planes[q - VM::Plane_arrangement_3::number_of_walls];
    auto holds = [&](const std::array<std::int64_t, 3>& v) { return p.a * v[0] + p.b * v[1] + p.c * v[2] + p.d == 0; };
    bool boundary = false;
    for(std::size_t i = 0; i < loop.size() && !boundary; ++i) boundary = holds(loop[i]) && holds(loop[(i + 1) % loop.size()]);
    ++r.used_planes;
    if(!boundary) ++r.used_interior;
  }
  r.energy_error = (s.energy - e.reference_energy) / e.reference_energy;
  const VM::internal::Surface_height_3 height(s);
  const CGAL::Bbox_2& D = e.problem.domain;
  double sum = 0;
  int count = 0;
  for(int i = 1; i < 40; ++i)
    for(int j = 1; j < 40; ++j) {
      const double x = D.xmin() + (D.xmax() - D.xmin()) * i / 40.0, y = D.ymin() + (D.ymax() - D.ymin()) * j / 40.0;
      const double d = height(x, y) - e.reference_height(x, y);
      sum += d * d;
      ++count;
    }
  r.height_error = std::sqrt(sum / count);
  return r;
}

// The relaxed function of `r` (level n) at (x, y): linear on the two triangles of each grid square.
double relaxed_height(const VM::Surface_problem_3& P, const VM::Relaxed_surface_3& r, double x, double y)
{
  const CGAL::Bbox_2& D = P.domain;
  const double u = (x - D.xmin()) / (D.xmax() - D.xmin()) * r.n, v = (y - D.ymin()) / (D.ymax() - D.ymin()) * r.n;
  const int i = std::min(r.n - 1, std::max(0, int(std::floor(u)))), j = std::min(r.n - 1, std::max(0, int(std::floor(v))));
  const double s = u - i, t = v - j;
  auto h = [&](int a, int b) { return r.heights[std::size_t(b) * std::size_t(r.n + 1) + std::size_t(a)]; };
  // Any split of the square interpolates within the grid's own error; the mean of both splits is symmetric.
  const double lower = s + t <= 1 ? h(i, j) + s * (h(i + 1, j) - h(i, j)) + t * (h(i, j + 1) - h(i, j))
                                  : h(i + 1, j + 1) + (1 - s) * (h(i, j + 1) - h(i + 1, j + 1)) +
                                      (1 - t) * (h(i + 1, j) - h(i + 1, j + 1));
  const double upper = s >= t ? h(i, j) + s * (h(i + 1, j) - h(i, j)) + t * (h(i + 1, j + 1) - h(i + 1, j))
                              : h(i, j) + t * (h(i, j + 1) - h(i, j)) + s * (h(i + 1, j + 1) - h(i, j + 1));
  return 0.5 * (lower + upper);
}

} // namespace

int main(int argc, char** argv)
{
  bool quick = false;
  int seeds = 5;
  std::string which = "both", csv = "benchmark/results/surface_plane_grids.csv";
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--quick") quick = true;
    else if(a == "--seeds" && i + 1 < argc) seeds = std::max(1, std::atoi(argv[++i]));
    else if(a == "--problem" && i + 1 < argc) which = argv[++i];
    else if(a == "--csv" && i + 1 < argc) csv = argv[++i];
    else {
      std::fprintf(stderr, "usage: %s [--quick] [--seeds K] [--problem membrane|scherk|both] [--csv PATH]\n",
                   argv[0]);
      return 2;
    }
  }

  std::vector<Experiment> experiments;
  VM::Surface_relaxation_options_3 fine;
  fine.grids = {20, 40, 80, 160};
  if(which == "membrane" || which == "both") {
    Experiment e;
    e.name = "membrane";
    e.problem = MDCS_test::sagging_membrane_problem();
    const VM::Membrane_functional_3 G = MDCS_test::sagging_membrane_functional();
    e.weights = [G, P = e.problem](const VM::Plane_arrangement_3& A) { return VM::surface_facet_weights_3(A, P, G); };
    e.max_slope = 1;
    e.largest_n_with_m_n = 3;
    e.seeds = seeds;
    e.grid_steps = quick ? std::vector<std::size_t>{1, 2, 3} : std::vector<std::size_t>{1, 2, 3, 4, 5};
    const auto relaxed = std::make_shared<VM::Relaxed_surface_3>(
      VM::relax_surface_3(e.problem, G, [](double, double) { return 0.75; }, fine));
    e.reference_energy = relaxed->energy;
    e.reference_height = [relaxed, P = e.problem](double x, double y) { return relaxed_height(P, *relaxed, x, y); };
    experiments.push_back(e);
  }
  if(which == "scherk" || which == "both") {
    Experiment e;
    e.name = "scherk";
    e.problem = VM::scherk_surface_problem_3(4);
    e.weights = [P = e.problem](const VM::Plane_arrangement_3& A) {
      return VM::surface_facet_weights_3(A, P, VM::Area_functional_3());
    };
    e.max_slope = 3;
    e.largest_n_with_m_n = 2;
    e.seeds = std::min(seeds, 3); // about 2M cells per random arrangement at n = 3 (80-110 s each under load)
    e.grid_steps = quick ? std::vector<std::size_t>{1, 2} : std::vector<std::size_t>{1, 2, 3};
    e.reference_energy = VM::relax_surface_3(MDCS_test::scherk_piecewise_linear_boundary_problem(4),
                                             VM::Area_functional_3(), VM::scherk_surface_height, fine).energy;
    e.reference_height = VM::scherk_surface_height;
    experiments.push_back(e);
  }

  std::printf("Regular plane grids against random planes (build + weights + cut per row; wall-clock and CPU seconds:\n"
              "the machine may be shared).\n");
  mdcs_bench::Table table({"problem", "source", "n", "m", "seed", "planes", "cells", "energy", "reference_energy",
                           "energy_rel_error", "height_rms_error", "used_planes", "used_interior_planes", "seconds",
                           "cpu_seconds"});
  for(const Experiment& e : experiments) {
    std::printf("\n== %s: reference energy %.10f, max_slope %g\n", e.name.c_str(), e.reference_energy, e.max_slope);
    auto add = [&](const char* source, std::size_t n, std::size_t m, const std::string& seed, const Run& r) {
      table.add_row({e.name, source, n ? std::to_string(n) : "", m ? std::to_string(m) : "", seed,
                     std::to_string(r.planes), std::to_string(r.cells), fmt(r.energy, "%.10g"),
                     fmt(e.reference_energy, "%.10g"), fmt(r.energy_error, "%.4e"), fmt(r.height_error, "%.4e"),
                     std::to_string(r.used_planes), std::to_string(r.used_interior), fmt(r.seconds, "%.3g"),
                     fmt(r.cpu_seconds, "%.3g")});
      std::printf("  %-6s n=%zu m=%zu seed=%s planes=%zu cells=%zu error=%.4e height=%.4e used %zu (%zu interior) "
                  "(%.2f s)\n", source, n, m, seed.c_str(), r.planes, r.cells, r.energy_error, r.height_error,
                  r.used_planes, r.used_interior, r.seconds);
      std::fflush(stdout);
    };
    for(std::size_t n : e.grid_steps) {
      VM::Regular_surface_plane_options_3 o;
      o.max_slope = e.max_slope;
      o.offset_steps = 1;
      const Run r1 = solve(e, VM::regular_surface_planes_3(e.problem, n, o));
      add("grid", n, 1, "", r1);
      if(n > 1 && n <= e.largest_n_with_m_n) {
        o.offset_steps = n;
        add("grid", n, n, "", solve(e, VM::regular_surface_planes_3(e.problem, n, o)));
      }
      // Random planes, as many as the grid with m = 1.
      for(int seed = 1; seed <= e.seeds; ++seed) {
        VM::Surface_plane_options_3 ro;
        ro.distribution = VM::Plane_distribution_3::slope_limited;
        ro.max_slope = e.max_slope;
        ro.pencil_fraction = 0.2;
        ro.seed = std::uint64_t(seed);
        add("random", 0, 0, std::to_string(seed), solve(e, VM::surface_planes_3(e.problem, r1.planes, ro)));
      }
    }
  }
  std::printf("\n");
  table.print();
  if(!table.write_csv(csv)) std::fprintf(stderr, "cannot write %s\n", csv.c_str());
  return 0;
}
