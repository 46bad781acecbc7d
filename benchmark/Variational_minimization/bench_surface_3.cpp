// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Benchmark of the bivariate solver (thesis ch. 2.7, Tables 2.2 and 2.3):
//   1. cost vs size: planes, cells, facets, build time, weight time, cut time with three max-flow engines,
//      peak memory, growth exponents (Table 2.2);
//   2. Scherk's surface: area error vs cells, raw and after relaxation;
//   3. the blob problem (many local minima, Table 2.3): random-start local descent, one global solve, plane
//      selection; energies, times, memory;
//   4. Scherk's surface at about 1M cells with 16 boundary segments per side: random planes against tangent-plane
//      refinement (refine_surface_by_tangent_planes_3), raw errors per round.
//
//   bench_surface_3 [--quick] [--large] [--budget SECONDS] [--part 1|2|3|4] [--csv-prefix PATH]
//                   [--blob-runs N] [--blob-first SEED] [--blob-starts N] [--blob-rounds R] [--blob-planes N]
//                   [--blob-near F] [--blob-search] [--no-global] [--blob-best E] [--blob-shift S]
//                   [--blob-tilings T1,T2,...] [--blob-no-wide] [--jobs J]
//
// --budget (default 60): part 1 stops growing once one row took longer than this (build + weights + cuts).
// --large: part 1 goes on to about 3M cells (the goal sizes of issue 6) whatever the budget.
// Part 3: N global runs (seeds SEED..SEED+N-1, default 8 from 100), N local descents (default 100), plane selection
// with N planes x R rounds (default 160 x 6; --blob-near F: a share F of the redrawn planes near the optimum);
// --blob-search: plane selection by select_planes_relaxed_3 (every round relaxed, then the basin search of
// search_surface_basins_3 on the final arrangement; the plain columns are the same run before the search);
// --blob-shift, --blob-tilings: the search's first stage (default 0.1 and 3,4); --blob-no-wide: no second stage
// (default: tilings 2,3,4 with shift 0.3 once the first stops); --blob-best E: a best energy known
// from earlier runs, for "reaches the best"; --no-global: skip the one-solve global runs; --jobs J runs them on J threads (each run single-threaded; the peak
// memory column is then not measured).
// Part 4 (not in the default run, about 6 minutes: --part 4): seeds 1-3 (--quick: seed 1, 4 rounds).
// CSV files: PATH_table22.csv, PATH_scherk.csv, PATH_blobs.csv, PATH_scherk_tangent.csv (default PATH: surface).

#include <CGAL/Min_cut/solve_min_cut.h>
#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/analytic_solutions_3.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/refine_surface_by_tangent_planes_3.h>
#include <CGAL/Variational_minimization/relax_surface_3.h>
#include <CGAL/Variational_minimization/search_surface_basins_3.h>
#include <CGAL/Variational_minimization/select_planes_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include "mdcs_bench.h"
#include <MDCS_test/surface_problems.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <limits>
#include <vector>

namespace VM = CGAL::Variational_minimization;
using mdcs_bench::fmt;

namespace {

// Least-squares slope of log(y) against log(x).
double growth_exponent(const std::vector<double>& x, const std::vector<double>& y)
{
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  std::size_t n = 0;
  for(std::size_t i = 0; i < x.size(); ++i) {
    if(!(x[i] > 0) || !(y[i] > 0)) continue;
    const double a = std::log(x[i]), b = std::log(y[i]);
    sx += a; sy += b; sxx += a * a; sxy += a * b;
    ++n;
  }
  if(n < 2) return NAN;
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// Returns freed memory to the system, so that the next peak measures one phase (glibc keeps freed blocks).
void release_memory()
{
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

// Process CPU time in seconds (the machine may be shared: wall-clock times then overstate the cost).
double cpu_seconds() { return double(std::clock()) / CLOCKS_PER_SEC; }


template <class Engine>
double time_cut(const VM::Plane_arrangement_3& A, const std::vector<double>& w, const VM::Surface_problem_3& P,
                double& value, double& cpu)
{
  const double t0 = mdcs_bench::now_seconds(), c0 = cpu_seconds();
  const VM::Minimal_surface_3 s = VM::minimize_surface_functional_3(A, w, P, Engine());
  value = s.solver_value;
  cpu = cpu_seconds() - c0;
  return mdcs_bench::now_seconds() - t0;
}

void part_table22(bool quick, bool large, double budget, const std::string& prefix)
{
  std::printf("\n== 1. Cost vs size (thesis Table 2.2). Problem: area, boundary f = 0.5 + (x-0.5)(y-0.5) on the unit "
              "square, 4 boundary segments per side;\n   planes: isotropic random through uniform points of the box, "
              "10%% pencils through the boundary segments (at least one each); seed 1.\n"
              "   peak MiB: growth of the process's peak resident set during the whole run of the row: build, then the default\n"
              "   solve minimize_surface_functional_3(arrangement, problem, G) (weights computed into pseudoflow run on the\n"
              "   arrangement); weights_s and cut_pf_s split that solve. Push-relabel and BK (<= 1.5M cells) run afterwards\n"
              "   on a weight vector, outside the peak.\n\n");
  const VM::Surface_problem_3 P = MDCS_test::saddle_problem(4);
  VM::Surface_plane_options_3 o;
  o.distribution = VM::Plane_distribution_3::isotropic;
  o.pencil_fraction = 0.1;
  mdcs_bench::Table table({"distribution", "planes", "cells", "facets", "vertices", "build_s", "build_cpu_s",
                           "weights_s", "cut_pf_s", "cut_pf_cpu_s", "cut_pr_s", "cut_bk_s", "cut_value", "engines_agree",
                           "arrangement_MiB", "peak_MiB", "bytes_per_cell"});
  std::vector<double> cells, planes_v, build, cut_pf, cut_pr, cut_bk;
  std::vector<long> sizes = {40, 60, 80, 100, 120, 140, 160, 180, 200, 220, 240, 260, 280, 300, 320, 340, 360, 380, 400};
  if(quick) sizes = {40, 60, 80, 100};
  if(large) sizes = {200, 260, 300, 340, 380, 420};
  for(long n : sizes) {
    release_memory();
    mdcs_bench::reset_peak_rss();
    const double rss0 = mdcs_bench::current_rss_mib();
    const auto planes = VM::surface_planes_3(P, std::size_t(n), o);
    double t0 = mdcs_bench::now_seconds();
    const double c0 = cpu_seconds();
    std::unique_ptr<VM::Plane_arrangement_3> A(new VM::Plane_arrangement_3(planes));
    const double tb = mdcs_bench::now_seconds() - t0, cb = cpu_seconds() - c0;
    // The whole run: build, then the default solve (pseudoflow run on the arrangement, weights computed into it).
    // The "weights" stage of its progress report splits its time into weights and cut.
    double weights_end = 0, weights_end_cpu = 0;
    auto stages = [&](const char* stage, double) {
      if(weights_end == 0 && std::string(stage) == "max-flow") {
        weights_end = mdcs_bench::now_seconds();
        weights_end_cpu = cpu_seconds();
      }
      return true;
    };
    t0 = mdcs_bench::now_seconds();
    const VM::Minimal_surface_3 lean = VM::minimize_surface_functional_3(
      *A, P, VM::Area_functional_3(), 1, CGAL::Min_cut::Pseudoflow_max_flow(), stages);
    const double tw = weights_end - t0, tpf = mdcs_bench::now_seconds() - weights_end;
    const double cpf = cpu_seconds() - weights_end_cpu;
    const double v_pf = lean.solver_value;
    const double peak = mdcs_bench::peak_rss_mib() - rss0;
    // The other engines (and pseudoflow again, through the generic Flow_network path) on a weight vector.
    double v_pr = 0, v_bk = 0, v_pf2 = 0, cpr = 0, cbk = 0, cpf2 = 0;
    const bool small = A->number_of_cells() <= 1500000;
    bool agree = true;
    double tpr = NAN, tbk = NAN;
    if(small) {
      const std::vector<double> w = VM::surface_facet_weights_3(*A, P, VM::Area_functional_3());
      time_cut<CGAL::Min_cut::Pseudoflow_max_flow>(*A, w, P, v_pf2, cpf2);
      tpr = time_cut<CGAL::Min_cut::Push_relabel_max_flow>(*A, w, P, v_pr, cpr);
      tbk = time_cut<CGAL::Min_cut::Boykov_kolmogorov_max_flow>(*A, w, P, v_bk, cbk);
      agree = std::abs(v_pf - v_pr) <= 1e-9 * v_pf && std::abs(v_pf - v_bk) <= 1e-9 * v_pf &&
              std::abs(v_pf - v_pf2) <= 1e-9 * v_pf;
    }
    const double mib = double(A->memory_bytes()) / 1048576.0;
    table.add_row({"isotropic", std::to_string(n), std::to_string(A->number_of_cells()),
                   std::to_string(A->number_of_facets()), std::to_string(A->number_of_vertices()), fmt(tb), fmt(cb),
                   fmt(tw), fmt(tpf), fmt(cpf), fmt(tpr), fmt(tbk), fmt(v_pf, "%.10g"), agree ? "yes" : "NO", fmt(mib), fmt(peak),
                   fmt(double(A->memory_bytes()) / double(A->number_of_cells()), "%.0f")});
    std::printf("  planes %ld: %zu cells, build %.3g s (cpu %.3g s), cut pf %.3g s (cpu %.3g s), pr %.3g s, bk %.3g s, "
                "peak %.0f MiB\n", n, A->number_of_cells(), tb, cb, tpf, cpf, tpr, tbk, peak);
    std::fflush(stdout);
    cells.push_back(double(A->number_of_cells()));
    planes_v.push_back(double(n));
    build.push_back(cb);
    cut_pf.push_back(cpf);
    cut_pr.push_back(cpr > 0 ? cpr : NAN);
    cut_bk.push_back(cbk > 0 ? cbk : NAN);
    const double row = cb + tw + cpf + (small ? cpr + cbk : 0);
    if(!large && row > budget) break;
    if(large && A->number_of_cells() > 3200000) break;
  }
  std::printf("\n");
  table.print();
  table.write_csv(prefix + "_table22.csv");
  std::printf("\ngrowth exponents (least squares on log-log): cells ~ planes^%.2f; build ~ cells^%.2f; cut ~ cells^%.2f "
              "(CPU times; pseudoflow), ^%.2f (push-relabel), ^%.2f (Boykov-Kolmogorov)\n",
              growth_exponent(planes_v, cells), growth_exponent(cells, build), growth_exponent(cells, cut_pf),
              growth_exponent(cells, cut_pr), growth_exponent(cells, cut_bk));
}

void part_scherk(bool quick, const std::string& prefix)
{
  const double a = 1.2, exact = VM::scherk_surface_area(a);
  std::printf("\n== 2. Scherk's surface f = ln(cos y / cos x) on [-1.2, 1.2]^2, exact area %.10f (Gauss quadrature).\n"
              "   planes: slope-limited |slope| <= 3, 20%% pencils, 4 boundary segments per side; relaxation: L-BFGS on "
              "20^2, 40^2, 80^2 grids. Three seeds per size.\n\n", exact);
  const VM::Surface_problem_3 P = VM::scherk_surface_problem_3(4);
  mdcs_bench::Table table({"planes", "seed", "cells", "raw_energy", "raw_rel_error", "relaxed_energy",
                           "relaxed_rel_error", "solve_s", "relax_s"});
  std::vector<long> sizes = {40, 80, 120, 160, 200, 240, 260};
  if(quick) sizes = {40, 80};
  std::vector<std::string> medians;
  for(long n : sizes) {
    std::vector<double> raw_errors, cell_counts;
    for(std::uint64_t seed : {1u, 2u, 3u}) {
      VM::Surface_plane_options_3 o;
      o.distribution = VM::Plane_distribution_3::slope_limited;
      o.max_slope = 3;
      o.pencil_fraction = 0.2;
      o.seed = seed;
      double t0 = mdcs_bench::now_seconds();
      const VM::Plane_arrangement_3 A(VM::surface_planes_3(P, std::size_t(n), o));
      const auto w = VM::surface_facet_weights_3(A, P, VM::Area_functional_3());
      const VM::Minimal_surface_3 s = VM::minimize_surface_functional_3(A, w, P);
      const double ts = mdcs_bench::now_seconds() - t0;
      t0 = mdcs_bench::now_seconds();
      const VM::Relaxed_surface_3 r = VM::relax_surface_3(P, VM::Area_functional_3(), s);
      const double tr = mdcs_bench::now_seconds() - t0;
      table.add_row({std::to_string(n), std::to_string(seed), std::to_string(A.number_of_cells()),
                     fmt(s.energy, "%.10g"), fmt((s.energy - exact) / exact, "%.3e"), fmt(r.energy, "%.10g"),
                     fmt((r.energy - exact) / exact, "%.3e"), fmt(ts), fmt(tr)});
      raw_errors.push_back((s.energy - exact) / exact);
      cell_counts.push_back(double(A.number_of_cells()));
    }
    medians.push_back(std::to_string(n) + " planes: median cells " + fmt(mdcs_bench::median(cell_counts), "%.0f") +
                      ", median raw error " + fmt(mdcs_bench::median(raw_errors), "%.3e"));
  }
  table.print();
  table.write_csv(prefix + "_scherk.csv");
  std::printf("\nmedians over the seeds:\n");
  for(const std::string& m : medians) std::printf("  %s\n", m.c_str());
  // What the raw energy converges to: the discrete problem spans the piecewise linear boundary curve (the
  // boundary samples), not Scherk's. Its minimal area, by relaxation on fine grids with that curve as boundary:
  for(int segments : {4, 8, 16}) {
    const VM::Surface_problem_3 Q = MDCS_test::scherk_piecewise_linear_boundary_problem(segments);
    VM::Surface_relaxation_options_3 ro;
    ro.grids = {20, 40, 80, 160};
    const double e = VM::relax_surface_3(Q, VM::Area_functional_3(), [](double x, double y) {
                       return VM::scherk_surface_height(x, y); }, ro).energy;
    std::printf("  limit of the raw energy with %2d boundary segments per side (area spanning the piecewise linear "
                "boundary, 160^2 grid): %.8f, error %.3e\n", segments, e, (e - exact) / exact);
  }
}

// Part 4: the discretisation excess of random planes (about +4% of the area at 1M cells with 16 segments per
// side, whose boundary curve alone gives -0.32%) against tangent-plane refinement at the same size.
void part_scherk_tangent(bool quick, const std::string& prefix)
{
  const double exact = VM::scherk_surface_area(1.2);
  const int segments = 16, rounds = quick ? 4 : 12;
  const long random_planes = 260, tangent_planes = 200;
  std::printf("\n== 4. Scherk's surface, %d boundary segments per side (limit of the raw energy -0.32%%): random planes "
              "(%ld) against tangent-plane refinement (%ld planes, %d rounds, fit radius 0.2); slope-limited "
              "|slope| <= 3, 20%% pencils. Raw errors: no relaxation.\n\n", segments, random_planes, tangent_planes,
              rounds);
  const VM::Surface_problem_3 P = VM::scherk_surface_problem_3(segments);
  mdcs_bench::Table table({"method", "seed", "round", "planes", "cells", "raw_energy", "raw_rel_error", "seconds",
                           "peak_MiB"});
  std::vector<double> random_errors, tangent_errors, tangent_cells, max_cells;
  std::vector<std::uint64_t> seeds = {1u, 2u, 3u};
  if(quick) seeds = {1u};
  for(std::uint64_t seed : seeds) {
    VM::Surface_plane_options_3 o;
    o.distribution = VM::Plane_distribution_3::slope_limited;
    o.max_slope = 3;
    o.pencil_fraction = 0.2;
    o.seed = seed;
    {
      mdcs_bench::reset_peak_rss();
      const double t0 = mdcs_bench::cpu_seconds();
      const VM::Plane_arrangement_3 A(VM::surface_planes_3(P, std::size_t(random_planes), o));
      const VM::Minimal_surface_3 s = VM::minimize_surface_functional_3(A, P, VM::Area_functional_3());
      const double e = (s.energy - exact) / exact;
      table.add_row({"random", std::to_string(seed), "-", std::to_string(random_planes),
                     std::to_string(A.number_of_cells()), fmt(s.energy, "%.10g"), fmt(e, "%.3e"),
                     fmt(mdcs_bench::cpu_seconds() - t0), fmt(mdcs_bench::peak_rss_mib(), "%.0f")});
      random_errors.push_back(e);
    }
    mdcs_bench::reset_peak_rss();
    VM::Tangent_refinement_options_3 t;
    t.rounds = rounds;
    // The callback sees fraction k / (rounds + 1) when round k starts: the CPU time at each start.
    std::vector<double> round_start(std::size_t(rounds) + 2, -1);
    const double t0 = mdcs_bench::cpu_seconds();
    const auto progress = [&](const char*, double fraction) {
      const std::size_t k = std::size_t(std::llround(fraction * (rounds + 1)));
      if(k < round_start.size() && round_start[k] < 0) round_start[k] = mdcs_bench::cpu_seconds();
      return true;
    };
    const VM::Tangent_refinement_result_3 r = VM::refine_surface_by_tangent_planes_3(
      P, VM::Area_functional_3(), std::size_t(tangent_planes), t, o, 1, CGAL::Min_cut::Default_max_flow_engine(),
      progress);
    const double total = mdcs_bench::cpu_seconds() - t0, peak = mdcs_bench::peak_rss_mib();
    for(std::size_t k = 0; k < r.round_energies.size(); ++k)
      table.add_row({"tangent", std::to_string(seed), std::to_string(k), std::to_string(tangent_planes),
                     std::to_string(r.round_cells[k]), fmt(r.round_energies[k], "%.10g"),
                     fmt((r.round_energies[k] - exact) / exact, "%.3e"),
                     fmt(round_start[k + 1] - round_start[k]), "-"});
    table.add_row({"tangent-best", std::to_string(seed), std::to_string(r.best_round), std::to_string(tangent_planes),
                   std::to_string(r.round_cells[std::size_t(r.best_round)]), fmt(r.surface.energy, "%.10g"),
                   fmt((r.surface.energy - exact) / exact, "%.3e"), fmt(total), fmt(peak, "%.0f")});
    tangent_errors.push_back((r.surface.energy - exact) / exact);
    tangent_cells.push_back(double(r.round_cells[std::size_t(r.best_round)]));
    max_cells.push_back(double(*std::max_element(r.round_cells.begin(), r.round_cells.end())));
  }
  table.print();
  table.write_csv(prefix + "_scherk_tangent.csv");
  std::printf("\nmedians over the seeds: random planes raw error %.3e; tangent-plane refinement raw error %.3e "
              "(best round's arrangement %.0f cells; largest round %.0f cells)\n",
              mdcs_bench::median(random_errors), mdcs_bench::median(tangent_errors), mdcs_bench::median(tangent_cells),
              mdcs_bench::median(max_cells));
}

// The settings of part 3 (command line: --blob-runs, --blob-first, --blob-starts, --blob-rounds, --blob-planes,
// --jobs).
struct Blob_settings
{
  int runs = 8;            // global runs (seeds first, first + 1, ...)
  int first = 100;         // first seed
  int starts = 100;        // random-start local descents
  int rounds = 6;          // plane selection rounds
  long planes_select = 160;
  long planes_global = 200;
  int jobs = 1;            // runs in parallel threads (each single-threaded); peak memory only with 1
  double near = 0;         // plane selection: share of the redrawn planes near the optimum (selection_near_fraction)
  bool search = false;     // basin search after plane selection (select_planes_relaxed_3)
  bool global = true;      // the one-solve global runs
  double known_best = NAN; // --blob-best E: a best energy known from earlier runs (for "reaches best")
  double search_shift = 0.1;              // --blob-shift: Surface_basin_search_options_3::shift
  std::vector<int> search_tilings{3, 4};  // --blob-tilings 3,4: Surface_basin_search_options_3::tilings
  bool search_wide = true;                // --blob-no-wide: no second (wide) stage (wide_tilings empty)
};

// One global run of the blob problem: one solve, and plane selection whose every distinct round optimum is relaxed.
struct Blob_run
{
  std::size_t global_cells = 0, selection_cells = 0;
  double global_discrete = 0, global_relaxed = 0, global_seconds = 0, global_peak = -1;
  double selection_discrete = 0, selection_final_relaxed = 0, selection_relaxed = 0, selection_seconds = 0,
         selection_peak = -1;
  int selection_best_round = 0, relaxed_rounds = 0;
  double search_relaxed = NAN, search_seconds = NAN; // basin search: energy, seconds after plane selection
  std::size_t search_moves = 0, search_improvements = 0;
};

template <class Functional>
Blob_run blob_run(const VM::Surface_problem_3& P, const Functional& G, const Blob_settings& b, int r,
                  const VM::Surface_relaxation_options_3& ro)
{
  Blob_run out;
  VM::Surface_plane_options_3 o;
  o.distribution = VM::Plane_distribution_3::slope_limited;
  o.max_slope = 2;
  o.seed = std::uint64_t(b.first + r);
  o.selection_near_fraction = b.near;
  const bool memory = b.jobs == 1;
  double rss0 = 0;
  if(memory) { release_memory(); mdcs_bench::reset_peak_rss(); rss0 = mdcs_bench::current_rss_mib(); }
  double t0 = mdcs_bench::now_seconds();
  if(b.global) {
    const VM::Plane_arrangement_3 A(VM::surface_planes_3(P, std::size_t(b.planes_global), o));
    const VM::Minimal_surface_3 s = VM::minimize_surface_functional_3(A, P, G);
    out.global_cells = A.number_of_cells();
    out.global_discrete = s.energy;
    out.global_relaxed = VM::relax_surface_3(P, G, s, ro).energy;
  }
  out.global_seconds = mdcs_bench::now_seconds() - t0;
  if(memory) { out.global_peak = mdcs_bench::peak_rss_mib() - rss0; release_memory(); mdcs_bench::reset_peak_rss();
               rss0 = mdcs_bench::current_rss_mib(); }
  t0 = mdcs_bench::now_seconds();
  if(b.search) {
    double search_start = 0;
    auto mark = [&](const char* stage, double) {
      if(search_start == 0 && std::string(stage) == "basin search") search_start = mdcs_bench::now_seconds();
      return true;
    };
    VM::Surface_basin_search_options_3 so;
    so.relaxation = ro;
    so.shift = b.search_shift;
    so.tilings = b.search_tilings;
    if(!b.search_wide) so.wide_tilings.clear();
    const VM::Relaxed_plane_selection_result_3 R = VM::select_planes_relaxed_3(
      P, G, std::size_t(b.planes_select), b.rounds, o, so, CGAL::Min_cut::Default_max_flow_engine(), mark);
    const double t1 = mdcs_bench::now_seconds();
    out.selection_cells = R.selection.cells.back();
    out.selection_discrete = R.selection.surface.energy;
    out.selection_relaxed = std::numeric_limits<double>::infinity();
    std::vector<double> seen;
    for(std::size_t i = 0; i < R.round_relaxed_energies.size(); ++i) {
      const double d = R.selection.surfaces[i].energy, e = R.round_relaxed_energies[i];
      if(std::find(seen.begin(), seen.end(), d) == seen.end()) { seen.push_back(d); ++out.relaxed_rounds; }
      if(d == R.selection.surface.energy) out.selection_final_relaxed = e;
      if(e < out.selection_relaxed) { out.selection_relaxed = e; out.selection_best_round = int(i); }
    }
    out.search_relaxed = R.search.relaxed.energy;
    out.search_moves = R.search.moves;
    out.search_improvements = R.search.improvements;
    out.search_seconds = t1 - (search_start > 0 ? search_start : t1);
    out.selection_seconds = (search_start > 0 ? search_start : t1) - t0;
    if(memory) out.selection_peak = mdcs_bench::peak_rss_mib() - rss0;
    return out;
  }
  const VM::Plane_selection_result_3 sel = VM::select_planes_3(P, G, std::size_t(b.planes_select), b.rounds, o);
  out.selection_cells = sel.cells.back();
  out.selection_discrete = sel.surface.energy;
  // Relax every distinct round optimum (optima of different rounds may lie in different basins) and keep the best;
  // also record what relaxing the final (best discrete) optimum alone gives.
  std::vector<double> seen;
  out.selection_relaxed = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0; i < sel.surfaces.size(); ++i) {
    const double d = sel.surfaces[i].energy;
    if(std::find(seen.begin(), seen.end(), d) != seen.end()) continue;
    seen.push_back(d);
    const double e = VM::relax_surface_3(P, G, sel.surfaces[i], ro).energy;
    ++out.relaxed_rounds;
    if(d == sel.surface.energy) out.selection_final_relaxed = e;
    if(e < out.selection_relaxed) { out.selection_relaxed = e; out.selection_best_round = int(i); }
  }
  out.selection_seconds = mdcs_bench::now_seconds() - t0;
  if(memory) out.selection_peak = mdcs_bench::peak_rss_mib() - rss0;
  return out;
}

// Runs f(i) for i in [0, n) on `jobs` threads.
template <class F>
void parallel_for(int n, int jobs, const F& f)
{
  if(jobs <= 1) { for(int i = 0; i < n; ++i) f(i); return; }
  std::atomic<int> next(0);
  std::vector<std::thread> pool;
  for(int j = 0; j < jobs; ++j)
    pool.emplace_back([&] { for(int i = next++; i < n; i = next++) f(i); });
  for(std::thread& t : pool) t.join();
}

void part_blobs(bool quick, const std::string& prefix, Blob_settings b)
{
  const VM::Surface_problem_3 P = MDCS_test::blob_problem();
  const int m = 9, k = 4;
  const VM::Density_weighted_area_functional_3 G = VM::random_blob_functional_3(P, m, k, 0.08, -1.5, 5);
  if(quick) { b.runs = (std::min)(b.runs, 2); b.starts = (std::min)(b.starts, 20); b.rounds = (std::min)(b.rounds, 4);
              b.planes_global = (std::min)(b.planes_global, 100L); b.planes_select = (std::min)(b.planes_select, 80L); }
  std::printf("\n== 3. Blob problem (thesis Table 2.3): density-weighted area, D = exp(sum of %d wells), %d columns x %d "
              "wells (about %.0f local minima), boundary free in [0, 1].\n   Local descent: L-BFGS on 20^2 then 40^2 "
              "from a random smooth start (bilinear on a random 5 x 5 grid). Every global result is relaxed the same "
              "way;\n   plane selection (%ld planes x %d rounds, near fraction %g) relaxes every distinct round optimum and keeps "
              "the best. Seeds %d..%d, %d thread(s)%s.\n\n", m * k, m, k, std::pow(k + 1.0, m), b.planes_select, b.rounds, b.near,
              b.first, b.first + b.runs - 1, b.jobs, b.jobs > 1 ? " (no peak memory)" : "");
  VM::Surface_relaxation_options_3 ro;
  ro.grids = {20, 40};
  // The random starts are drawn first, in order, so that the result does not depend on the number of threads.
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<std::array<double, 25>> starts(std::size_t(b.starts));
  for(auto& c : starts)
    for(double& v : c) v = U(rng);
  std::vector<double> local(starts.size()), local_seconds(starts.size());
  parallel_for(b.starts, b.jobs, [&](int s) {
    const std::array<double, 25>& c = starts[std::size_t(s)];
    auto init = [&](double x, double y) {
      const double u = x * 4, v = y * 4;
      const int i = std::min(3, int(u)), j = std::min(3, int(v));
      const double a = u - i, e = v - j;
      return (1 - a) * (1 - e) * c[5 * i + j] + a * (1 - e) * c[5 * (i + 1) + j] + (1 - a) * e * c[5 * i + j + 1] +
             a * e * c[5 * (i + 1) + j + 1];
    };
    const double t0 = mdcs_bench::now_seconds();
    local[std::size_t(s)] = VM::relax_surface_3(P, G, init, ro).energy;
    local_seconds[std::size_t(s)] = mdcs_bench::now_seconds() - t0;
  });
  std::vector<Blob_run> runs(std::size_t(b.runs));
  parallel_for(b.runs, b.jobs, [&](int r) { runs[std::size_t(r)] = blob_run(P, G, b, r, ro); });

  double t_local = 0;
  for(double t : local_seconds) t_local += t;
  const double best_local = local.empty() ? std::numeric_limits<double>::infinity()
                                          : *std::min_element(local.begin(), local.end());
  std::vector<double> global, selection, selection_final, search;
  for(const Blob_run& x : runs) {
    if(b.global) global.push_back(x.global_relaxed);
    selection.push_back(x.selection_relaxed);
    selection_final.push_back(x.selection_final_relaxed);
    if(b.search) search.push_back(x.search_relaxed);
  }
  double best = best_local;
  if(b.known_best > 0) best = std::min(best, b.known_best);
  for(double e : global) best = std::min(best, e);
  for(double e : selection) best = std::min(best, e);
  for(double e : search) best = std::min(best, e);
  auto reaches = [&](double e) { return e <= best * (1 + 1e-4); };
  auto hits = [&](const std::vector<double>& v) {
    std::size_t c = 0;
    for(double e : v) c += reaches(e) ? 1 : 0;
    return c;
  };
  mdcs_bench::Table table({"method", "run", "seed", "planes", "cells", "discrete_energy", "relaxed_energy",
                           "relaxed_final_only", "best_round", "reaches_best", "seconds", "peak_MiB"});
  if(!local.empty())
    table.add_row({"local descent (random start)", std::to_string(local.size()) + " runs", "-", "-", "-", "-",
                   fmt(best_local, "%.8g") + " (best)", "-", "-", std::to_string(hits(local)) + "/" +
                   std::to_string(local.size()), fmt(t_local / double(local.size())) + " per run", "-"});
  for(std::size_t r = 0; r < runs.size(); ++r) {
    const Blob_run& x = runs[r];
    const std::string seed = std::to_string(b.first + int(r));
    if(b.global)
    table.add_row({"global (one solve)", std::to_string(r), seed, std::to_string(b.planes_global),
                   std::to_string(x.global_cells), fmt(x.global_discrete, "%.8g"), fmt(x.global_relaxed, "%.8g"), "-",
                   "-", reaches(x.global_relaxed) ? "yes" : "no", fmt(x.global_seconds),
                   x.global_peak >= 0 ? fmt(x.global_peak) : "-"});
    table.add_row({"plane selection x" + std::to_string(b.rounds), std::to_string(r), seed,
                   std::to_string(b.planes_select), std::to_string(x.selection_cells), fmt(x.selection_discrete, "%.8g"),
                   fmt(x.selection_relaxed, "%.8g"), fmt(x.selection_final_relaxed, "%.8g"),
                   std::to_string(x.selection_best_round) + " (" + std::to_string(x.relaxed_rounds) + " relaxed)",
                   reaches(x.selection_relaxed) ? "yes" : "no", fmt(x.selection_seconds),
                   x.selection_peak >= 0 ? fmt(x.selection_peak) : "-"});
    if(b.search)
      table.add_row({"+ basin search", std::to_string(r), seed, std::to_string(b.planes_select),
                     std::to_string(x.selection_cells), "-", fmt(x.search_relaxed, "%.8g"), "-",
                     std::to_string(x.search_improvements) + "/" + std::to_string(x.search_moves) + " moves improved",
                     reaches(x.search_relaxed) ? "yes" : "no",
                     fmt(x.selection_seconds + x.search_seconds) + " (search " + fmt(x.search_seconds) + ")",
                     x.selection_peak >= 0 ? fmt(x.selection_peak) : "-"});
  }
  table.print();
  table.write_csv(prefix + "_blobs.csv");
  std::printf("\nbest energy of any method %.8g; runs within 1e-4 of it: local %zu / %zu, global %zu / %zu, plane "
              "selection (best relaxed round) %zu / %zu, plane selection (final optimum relaxed only) %zu / %zu\n",
              best, hits(local), local.size(), hits(global), global.size(), hits(selection), selection.size(),
              hits(selection_final), selection_final.size());
  if(b.search)
    std::printf("plane selection + basin search (select_planes_relaxed_3) %zu / %zu\n", hits(search), search.size());
  if(runs.empty()) return;
  std::vector<double> sorted = local;
  std::sort(sorted.begin(), sorted.end());
  if(!sorted.empty())
    std::printf("local descent energies: min %.6g, median %.6g, max %.6g\n", sorted.front(), sorted[sorted.size() / 2],
                sorted.back());
  // The energy histogram (thesis Table 2.3 as counts per energy bin), relaxed energies of every method.
  double hi = best;
  for(const std::vector<double>* v : {&local, &global, &selection, &search})
    for(double e : *v) hi = std::max(hi, e);
  const double lo = best;
  const int bins = 12;
  const double width = (hi - lo) / bins > 0 ? (hi - lo) / bins : 1e-9;
  std::vector<std::array<int, 4>> counts(bins, std::array<int, 4>{{0, 0, 0, 0}});
  auto bin_of = [&](double e) { return std::min(bins - 1, std::max(0, int((e - lo) / width))); };
  for(double e : local) ++counts[bin_of(e)][0];
  for(double e : global) ++counts[bin_of(e)][1];
  for(double e : selection) ++counts[bin_of(e)][2];
  for(double e : search) ++counts[bin_of(e)][3];
  mdcs_bench::Table histogram({"energy_from", "energy_to", "local_descent", "global_one_solve", "plane_selection",
                               "plane_selection_basin_search"});
  std::printf("\nenergy histogram (relaxed energies; the first bin starts at the best energy):\n");
  for(int i = 0; i < bins; ++i) {
    const double e0 = lo + i * width, e1 = lo + (i + 1) * width;
    histogram.add_row({fmt(e0, "%.5f"), fmt(e1, "%.5f"), std::to_string(counts[i][0]), std::to_string(counts[i][1]),
                       std::to_string(counts[i][2]), b.search ? std::to_string(counts[i][3]) : "-"});
    std::printf("  [%.5f, %.5f) local %-40s global %-8s selection %-16s search %s\n", e0, e1,
                std::string(std::size_t(counts[i][0]), '#').c_str(), std::string(std::size_t(counts[i][1]), '#').c_str(),
                std::string(std::size_t(counts[i][2]), '#').c_str(), std::string(std::size_t(counts[i][3]), '#').c_str());
  }
  histogram.write_csv(prefix + "_blobs_histogram.csv");
}

} // namespace

int main(int argc, char** argv)
{
  bool quick = false, large = false;
  int part = 0;
  double budget = 60;
  std::string prefix = "surface";
  Blob_settings blobs;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--quick") quick = true;
    else if(a == "--large") large = true;
    else if(a == "--budget" && i + 1 < argc) budget = std::atof(argv[++i]);
    else if(a == "--csv-prefix" && i + 1 < argc) prefix = argv[++i];
    else if(a == "--part" && i + 1 < argc) part = std::atoi(argv[++i]);
    else if(a == "--blob-runs" && i + 1 < argc) blobs.runs = std::atoi(argv[++i]);
    else if(a == "--blob-first" && i + 1 < argc) blobs.first = std::atoi(argv[++i]);
    else if(a == "--blob-starts" && i + 1 < argc) blobs.starts = std::atoi(argv[++i]);
    else if(a == "--blob-rounds" && i + 1 < argc) blobs.rounds = std::atoi(argv[++i]);
    else if(a == "--blob-planes" && i + 1 < argc) blobs.planes_select = std::atol(argv[++i]);
    else if(a == "--blob-near" && i + 1 < argc) blobs.near = std::atof(argv[++i]);
    else if(a == "--blob-search") blobs.search = true;
    else if(a == "--no-global") blobs.global = false;
    else if(a == "--blob-best" && i + 1 < argc) blobs.known_best = std::atof(argv[++i]);
    else if(a == "--blob-shift" && i + 1 < argc) blobs.search_shift = std::atof(argv[++i]);
    else if(a == "--blob-no-wide") blobs.search_wide = false;
    else if(a == "--blob-tilings" && i + 1 < argc) {
      blobs.search_tilings.clear();
      for(const char* c = argv[++i]; *c;) {
        char* end = nullptr;
        blobs.search_tilings.push_back(int(std::strtol(c, &end, 10)));
        if(end == c) break;
        c = *end == ',' ? end + 1 : end;
      }
    }
    else if(a == "--jobs" && i + 1 < argc) blobs.jobs = std::max(1, std::atoi(argv[++i]));
    else {
      std::fprintf(stderr, "usage: bench_surface_3 [--quick] [--large] [--budget SECONDS] [--part 1|2|3|4] "
                           "[--csv-prefix PATH]\n       [--blob-runs N] [--blob-first SEED] [--blob-starts N] "
                           "[--blob-rounds R] [--blob-planes N] [--blob-near F] [--blob-search] [--no-global]\n"
                           "       [--blob-best E] [--blob-shift S] [--blob-tilings T1,T2,...] [--blob-no-wide] [--jobs J]\n");
      return 2;
    }
  }
  if(part == 0 || part == 1) part_table22(quick, large, budget, prefix);
  if(part == 0 || part == 2) part_scherk(quick, prefix);
  if(part == 0 || part == 3) part_blobs(quick, prefix, blobs);
  if(part == 4) part_scherk_tangent(quick, prefix);
  return 0;
}
