// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Benchmark of the bivariate solver (thesis ch. 2.7, Tables 2.2 and 2.3):
//   1. cost vs size: planes, cells, facets, build time, weight time, cut time with three max-flow engines,
//      peak memory, growth exponents (Table 2.2);
//   2. Scherk's surface: area error vs cells, raw and after relaxation;
//   3. the blob problem (many local minima, Table 2.3): random-start local descent, one global solve, plane
//      selection; energies, times, memory.
//
//   bench_surface_3 [--quick] [--large] [--budget SECONDS] [--part 1|2|3] [--csv-prefix PATH]
//
// --budget (default 60): part 1 stops growing once one row took longer than this (build + weights + cuts).
// --large: part 1 goes on to about 3M cells (the goal sizes of issue 6) whatever the budget.
// CSV files: PATH_table22.csv, PATH_scherk.csv, PATH_blobs.csv (default PATH: surface).

#include <CGAL/Min_cut/solve_min_cut.h>
#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/analytic_solutions_3.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/relax_surface_3.h>
#include <CGAL/Variational_minimization/select_planes_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include "mdcs_bench.h"

#include <algorithm>
#include <array>
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
  VM::Surface_problem_3 P;
  P.boundary_segments_per_side = 4;
  P.lower_boundary = [](double x, double y) { return 0.5 + (x - 0.5) * (y - 0.5); };
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
    VM::Surface_problem_3 Q = VM::scherk_surface_problem_3(segments);
    const double h = 2 * a / segments;
    auto interpolate = [=](double t, double fixed, bool x_side) {
      const int k = std::min(segments - 1, int(std::floor((t + a) / h)));
      const double t0 = -a + k * h, u = (t - t0) / h;
      const double g0 = x_side ? VM::scherk_surface_height(fixed, t0) : VM::scherk_surface_height(t0, fixed);
      const double g1 = x_side ? VM::scherk_surface_height(fixed, t0 + h) : VM::scherk_surface_height(t0 + h, fixed);
      return (1 - u) * g0 + u * g1;
    };
    Q.lower_boundary = [=](double x, double y) {
      if(std::abs(std::abs(x) - a) < 1e-12) return interpolate(y, x, true);
      if(std::abs(std::abs(y) - a) < 1e-12) return interpolate(x, y, false);
      return VM::scherk_surface_height(x, y);
    };
    VM::Surface_relaxation_options_3 ro;
    ro.grids = {20, 40, 80, 160};
    const double e = VM::relax_surface_3(Q, VM::Area_functional_3(), [](double x, double y) {
                       return VM::scherk_surface_height(x, y); }, ro).energy;
    std::printf("  limit of the raw energy with %2d boundary segments per side (area spanning the piecewise linear "
                "boundary, 160^2 grid): %.8f, error %.3e\n", segments, e, (e - exact) / exact);
  }
}

void part_blobs(bool quick, const std::string& prefix)
{
  VM::Surface_problem_3 P;
  P.boundary_segments_per_side = 1;
  P.lower_boundary = [](double, double) { return 0.0; };
  P.upper_boundary = [](double, double) { return 1.0; };
  const int m = 9, k = 4;
  const VM::Density_weighted_area_functional_3 G = VM::random_blob_functional_3(P, m, k, 0.08, -1.5, 5);
  std::printf("\n== 3. Blob problem (thesis Table 2.3): density-weighted area, D = exp(sum of %d wells), %d columns x %d "
              "wells (about %.0f local minima), boundary free in [0, 1].\n   Local descent: L-BFGS on 20^2 then 40^2 "
              "from a random smooth start (bilinear on a random 5 x 5 grid). Every global result is relaxed the same "
              "way.\n\n", m * k, m, k, std::pow(k + 1.0, m));
  VM::Surface_relaxation_options_3 ro;
  ro.grids = {20, 40};
  mdcs_bench::Table table({"method", "run", "planes", "cells", "discrete_energy", "relaxed_energy", "seconds",
                           "peak_MiB"});
  std::vector<double> local;
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> U(0, 1);
  const int starts = quick ? 20 : 100;
  double t_local = 0;
  for(int s = 0; s < starts; ++s) {
    double c[5][5];
    for(auto& row : c)
      for(auto& v : row) v = U(rng);
    auto init = [&](double x, double y) {
      const double u = x * 4, v = y * 4;
      const int i = std::min(3, int(u)), j = std::min(3, int(v));
      const double a = u - i, b = v - j;
      return (1 - a) * (1 - b) * c[i][j] + a * (1 - b) * c[i + 1][j] + (1 - a) * b * c[i][j + 1] + a * b * c[i + 1][j + 1];
    };
    const double t0 = mdcs_bench::now_seconds();
    local.push_back(VM::relax_surface_3(P, G, init, ro).energy);
    t_local += mdcs_bench::now_seconds() - t0;
  }
  const double best_local = *std::min_element(local.begin(), local.end());
  table.add_row({"local descent (random start)", std::to_string(starts) + " runs", "-", "-", "-",
                 fmt(best_local, "%.8g") + " (best)", fmt(t_local / starts) + " per run", "-"});
  std::vector<double> global, selection;
  // Plane selection with its default options (every dropped plane redrawn through the whole box), 160 planes and
  // 6 rounds. Whether a run reaches the best basin is a matter of luck at these sizes: 120 x 5 reached it in 2 of
  // 4 runs, 120 x 10 in 3 of 4, 160 x 6 in 1 of 4 (doc/Variational_minimization/minimal_surfaces_3.md).
  const long n_global = quick ? 100 : 200, n_select = quick ? 80 : 160;
  const int selection_rounds = quick ? 4 : 6;
  const int runs = quick ? 2 : 4;
  for(int r = 0; r < runs; ++r) {
    VM::Surface_plane_options_3 o;
    o.distribution = VM::Plane_distribution_3::slope_limited;
    o.max_slope = 2;
    o.seed = std::uint64_t(100 + r);
    release_memory();
    mdcs_bench::reset_peak_rss();
    double rss0 = mdcs_bench::current_rss_mib();
    double t0 = mdcs_bench::now_seconds();
    {
      const VM::Plane_arrangement_3 A(VM::surface_planes_3(P, std::size_t(n_global), o));
      const auto w = VM::surface_facet_weights_3(A, P, G);
      const VM::Minimal_surface_3 s = VM::minimize_surface_functional_3(A, w, P);
      const double e = VM::relax_surface_3(P, G, s, ro).energy;
      global.push_back(e);
      table.add_row({"global (one solve)", std::to_string(r), std::to_string(n_global), std::to_string(A.number_of_cells()),
                     fmt(s.energy, "%.8g"), fmt(e, "%.8g"), fmt(mdcs_bench::now_seconds() - t0),
                     fmt(mdcs_bench::peak_rss_mib() - rss0)});
    }
    release_memory();
    mdcs_bench::reset_peak_rss();
    rss0 = mdcs_bench::current_rss_mib();
    t0 = mdcs_bench::now_seconds();
    const VM::Plane_selection_result_3 sel = VM::select_planes_3(P, G, std::size_t(n_select), selection_rounds, o);
    const double e = VM::relax_surface_3(P, G, sel.surface, ro).energy;
    selection.push_back(e);
    table.add_row({"plane selection x" + std::to_string(selection_rounds), std::to_string(r), std::to_string(n_select), std::to_string(sel.cells.back()),
                   fmt(sel.surface.energy, "%.8g"), fmt(e, "%.8g"), fmt(mdcs_bench::now_seconds() - t0),
                   fmt(mdcs_bench::peak_rss_mib() - rss0)});
  }
  table.print();
  table.write_csv(prefix + "_blobs.csv");
  double best = best_local;
  for(double e : global) best = std::min(best, e);
  for(double e : selection) best = std::min(best, e);
  auto hits = [&](const std::vector<double>& v) {
    std::size_t c = 0;
    for(double e : v) c += (e <= best * (1 + 1e-4)) ? 1 : 0;
    return c;
  };
  std::printf("\nbest energy of any method %.8g; runs within 1e-4 of it: local %zu / %zu, global %zu / %zu, plane "
              "selection %zu / %zu\n", best, hits(local), local.size(), hits(global), global.size(), hits(selection),
              selection.size());
  std::sort(local.begin(), local.end());
  std::printf("local descent energies: min %.6g, median %.6g, max %.6g\n", local.front(), local[local.size() / 2],
              local.back());
  // The energy histogram (thesis Table 2.3 as counts per energy bin), relaxed energies of every method.
  const double lo = best, hi = std::max({local.back(), *std::max_element(global.begin(), global.end()),
                                         *std::max_element(selection.begin(), selection.end())});
  const int bins = 12;
  const double width = (hi - lo) / bins > 0 ? (hi - lo) / bins : 1e-9;
  std::vector<std::array<int, 3>> counts(bins, std::array<int, 3>{{0, 0, 0}});
  auto bin_of = [&](double e) { return std::min(bins - 1, std::max(0, int((e - lo) / width))); };
  for(double e : local) ++counts[bin_of(e)][0];
  for(double e : global) ++counts[bin_of(e)][1];
  for(double e : selection) ++counts[bin_of(e)][2];
  mdcs_bench::Table histogram({"energy_from", "energy_to", "local_descent", "global_one_solve", "plane_selection"});
  std::printf("\nenergy histogram (relaxed energies; the first bin starts at the best energy):\n");
  for(int b = 0; b < bins; ++b) {
    const double e0 = lo + b * width, e1 = lo + (b + 1) * width;
    histogram.add_row({fmt(e0, "%.5f"), fmt(e1, "%.5f"), std::to_string(counts[b][0]), std::to_string(counts[b][1]),
                       std::to_string(counts[b][2])});
    std::printf("  [%.5f, %.5f) local %-40s global %-4s selection %s\n", e0, e1,
                std::string(std::size_t(counts[b][0]), '#').c_str(), std::string(std::size_t(counts[b][1]), '#').c_str(),
                std::string(std::size_t(counts[b][2]), '#').c_str());
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
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--quick") quick = true;
    else if(a == "--large") large = true;
    else if(a == "--budget" && i + 1 < argc) budget = std::atof(argv[++i]);
    else if(a == "--csv-prefix" && i + 1 < argc) prefix = argv[++i];
    else if(a == "--part" && i + 1 < argc) part = std::atoi(argv[++i]);
    else {
      std::fprintf(stderr, "usage: bench_surface_3 [--quick] [--large] [--budget SECONDS] [--part 1|2|3] "
                           "[--csv-prefix PATH]\n");
      return 2;
    }
  }
  if(part == 0 || part == 1) part_table22(quick, large, budget, prefix);
  if(part == 0 || part == 2) part_scherk(quick, prefix);
  if(part == 0 || part == 3) part_blobs(quick, prefix);
  return 0;
}
