// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The thesis's Table 2.4 (ch. 2.7.2): the density-weighted area with two levels of detail (the 36 wells of the
// Table 2.3 blob problem plus 36 wells 5 times narrower; two_level_blob_functional_3), solved by
//   a. local descent (L-BFGS, relax_surface_3) from random smooth starts,
//   b. one global solve with --global-planes planes,
//   c. single-level plane selection, --planes planes x (levels x iterations) solves,
//   d. multi-level adaptive refinement (refine_surface_multilevel_3), --planes planes, offsets 1, 0.2, 0.05 of the
//      range, --iterations plane selection iterations per level (the same number of solves as c),
// every global result relaxed the same way as the local descents. Per seed: energies, CPU seconds (the process's; all
// of it runs on one thread, so the figures do not depend on the load of a shared machine), cells, peak memory.
//
//   bench_surface_two_level_3 [--quick] [--seeds N] [--first SEED] [--starts N] [--planes N] [--global-planes N]
//                             [--iterations I] [--grids 20,40,80] [--out PATH]
//
// Defaults: 4 seeds from 1, 20 local starts, 100 planes, 150 global planes, 5 iterations per level, relaxation
// grids 20, 40, 80 (the thesis's). Writes PATH.csv (default benchmark/results/surface_two_level_table24) and PATH.svg:
// the best discrete energy after each solve, plane selection against multi-level refinement, one line per seed.

#include <CGAL/Variational_minimization/refine_surface_multilevel_3.h>
#include <CGAL/Variational_minimization/relax_surface_3.h>
#include <CGAL/Variational_minimization/select_planes_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include "mdcs_bench.h"
#include <MDCS_test/surface_problems.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace VM = CGAL::Variational_minimization;
using mdcs_bench::fmt;

namespace {

struct Settings
{
  int seeds = 4, first = 1, starts = 20, iterations = 5;
  long planes = 100, global_planes = 150;
  std::vector<int> grids{20, 40, 80};
  std::string out = "benchmark/results/surface_two_level_table24";
};

// One global method's outcome on one seed.
struct Outcome
{
  std::string method;
  int seed = 0;
  long planes = 0;
  std::size_t solves = 0, cells = 0, network_nodes = 0;
  double discrete = 0, relaxed = 0, seconds = 0, relax_seconds = 0, peak = 0;
  std::vector<double> best_after_solve; // the best discrete energy after each solve
};

// Peak resident memory of the process since the last call (MiB), or NaN where the kernel does not let us reset
// the high-water mark. (The absolute peak: a difference to the resident size at the reset came out slightly negative
// where a phase freed more than it allocated, since the kernel updates the high-water mark lazily.)
double peak_since_reset(bool& reset_ok)
{
  const double peak = reset_ok ? mdcs_bench::peak_rss_mib() : std::numeric_limits<double>::quiet_NaN();
  reset_ok = mdcs_bench::reset_peak_rss();
  return peak;
}

std::vector<double> running_minimum(const std::vector<double>& energies)
{
  std::vector<double> out;
  for(double e : energies) out.push_back(out.empty() ? e : (std::min)(out.back(), e));
  return out;
}

// An SVG of the best discrete energy against the number of solves: one polyline per run, plane selection in blue,
// multi-level refinement in orange, the level boundaries dashed.
void write_svg(const std::string& path, const std::vector<Outcome>& runs, int iterations, std::size_t levels)
{
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  std::size_t solves = 0;
  for(const Outcome& r : runs)
    for(double e : r.best_after_solve) {
      lo = (std::min)(lo, e);
      hi = (std::max)(hi, e);
      solves = (std::max)(solves, r.best_after_solve.size());
    }
  if(solves < 2 || !(hi > lo)) return;
  const double W = 720, H = 400, left = 70, right = 250, top = 30, bottom = 50;
  const auto X = [&](double k) { return left + (W - left - right) * (k - 1) / double(solves - 1); };
  const auto Y = [&](double e) { return top + (H - top - bottom) * (hi - e) / (hi - lo); };
  std::ofstream svg(path);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << left << "\" y=\"18\">Two-level blob functional: best discrete energy after each solve</text>\n";
  for(std::size_t l = 1; l < levels; ++l) {
    const double x = X(double(l * std::size_t(iterations)) + 0.5);
    svg << "<line x1=\"" << x << "\" y1=\"" << top << "\" x2=\"" << x << "\" y2=\"" << H - bottom
        << "\" stroke=\"#999\" stroke-dasharray=\"4 3\"/>\n";
  }
  svg << "<line x1=\"" << left << "\" y1=\"" << H - bottom << "\" x2=\"" << W - right << "\" y2=\"" << H - bottom
      << "\" stroke=\"black\"/>\n<line x1=\"" << left << "\" y1=\"" << top << "\" x2=\"" << left << "\" y2=\""
      << H - bottom << "\" stroke=\"black\"/>\n";
  for(int t = 0; t <= 4; ++t) {
    const double e = lo + (hi - lo) * t / 4;
    svg << "<text x=\"" << left - 6 << "\" y=\"" << Y(e) + 4 << "\" text-anchor=\"end\">" << fmt(e, "%.4f")
        << "</text>\n";
  }
  for(std::size_t k = 1; k <= solves; ++k)
    svg << "<text x=\"" << X(double(k)) << "\" y=\"" << H - bottom + 16 << "\" text-anchor=\"middle\">" << k
        << "</text>\n";
  svg << "<text x=\"" << (left + W - right) / 2 << "\" y=\"" << H - 10 << "\" text-anchor=\"middle\">solves "
      << "(dashed: level boundaries of the multi-level refinement)</text>\n";
  const char* colours[2] = {"#1f77b4", "#ff7f0e"};
  for(const Outcome& r : runs) {
    if(r.best_after_solve.size() < 2) continue;
    const bool multilevel = r.method.find("multi-level") != std::string::npos;
    svg << "<polyline fill=\"none\" stroke-width=\"1.5\" stroke=\"" << colours[multilevel ? 1 : 0] << "\" points=\"";
    for(std::size_t k = 0; k < r.best_after_solve.size(); ++k)
      svg << X(double(k + 1)) << "," << Y(r.best_after_solve[k]) << " ";
    svg << "\"/>\n";
  }
  const char* names[2] = {"plane selection", "multi-level refinement"};
  for(int i = 0; i < 2; ++i)
    svg << "<line x1=\"" << W - right + 12 << "\" y1=\"" << top + 20 * i + 10 << "\" x2=\"" << W - right + 36
        << "\" y2=\"" << top + 20 * i + 10 << "\" stroke=\"" << colours[i] << "\" stroke-width=\"2\"/><text x=\""
        << W - right + 42 << "\" y=\"" << top + 20 * i + 14 << "\">" << names[i] << "</text>\n";
  svg << "</svg>\n";
}

std::vector<int> parse_list(const char* s)
{
  std::vector<int> v;
  for(char* end = nullptr; *s; s = *end ? end + 1 : end) {
    v.push_back(int(std::strtol(s, &end, 10)));
    if(end == s) break;
  }
  return v;
}

} // namespace

int main(int argc, char** argv)
{
  Settings b;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--quick") { b.seeds = 1; b.starts = 4; b.planes = 50; b.global_planes = 70; b.iterations = 2;
                         b.grids = {20, 40}; }
    else if(a == "--seeds" && i + 1 < argc) b.seeds = std::atoi(argv[++i]);
    else if(a == "--first" && i + 1 < argc) b.first = std::atoi(argv[++i]);
    else if(a == "--starts" && i + 1 < argc) b.starts = std::atoi(argv[++i]);
    else if(a == "--planes" && i + 1 < argc) b.planes = std::atol(argv[++i]);
    else if(a == "--global-planes" && i + 1 < argc) b.global_planes = std::atol(argv[++i]);
    else if(a == "--iterations" && i + 1 < argc) b.iterations = std::atoi(argv[++i]);
    else if(a == "--grids" && i + 1 < argc) b.grids = parse_list(argv[++i]);
    else if(a == "--out" && i + 1 < argc) b.out = argv[++i];
    else {
      std::fprintf(stderr, "usage: bench_surface_two_level_3 [--quick] [--seeds N] [--first SEED] [--starts N] "
                           "[--planes N] [--global-planes N]\n       [--iterations I] [--grids 20,40,80] [--out PATH]\n");
      return 2;
    }
  }
  const VM::Surface_problem_3 P = MDCS_test::blob_problem();
  const VM::Density_weighted_area_functional_3 G = VM::two_level_blob_functional_3(P, 9, 4, 0.08, -1.5, 5);
  VM::Surface_relaxation_options_3 ro;
  ro.grids = b.grids;
  VM::Surface_multilevel_options_3 L; // offsets 1, 0.2, 0.05
  L.selection_iterations = b.iterations;
  const int solves = int(L.offsets.size()) * b.iterations;
  std::printf("Two-level blob functional (thesis Table 2.4): 36 wells (sigma 0.08) + 36 wells (sigma 0.016), boundary "
              "free in [0, 1].\nSeeds %d..%d; %d local starts; global %ld planes; plane selection %ld planes x %d; "
              "multi-level %ld planes, %zu levels x %d; relaxation grids", b.first, b.first + b.seeds - 1, b.starts,
              b.global_planes, b.planes, solves, b.planes, L.offsets.size(), b.iterations);
  for(int g : ro.grids) std::printf(" %d", g);
  std::printf(".\n\n");

  bool reset_ok = mdcs_bench::reset_peak_rss();
  // a. Local descents from random smooth starts (bilinear through a random 5 x 5 grid of heights in [0, 1]).
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<double> local, local_seconds;
  for(int s = 0; s < b.starts; ++s) {
    std::array<double, 25> h;
    for(double& v : h) v = U(rng);
    const auto start = [&h](double x, double y) {
      const double u = (std::min)(3.999999, 4 * x), v = (std::min)(3.999999, 4 * y);
      const int i = int(u), j = int(v);
      const double a = u - i, c = v - j;
      return (1 - c) * ((1 - a) * h[5 * j + i] + a * h[5 * j + i + 1]) +
             c * ((1 - a) * h[5 * (j + 1) + i] + a * h[5 * (j + 1) + i + 1]);
    };
    const double t0 = mdcs_bench::cpu_seconds();
    local.push_back(VM::relax_surface_3(P, G, start, ro).energy);
    local_seconds.push_back(mdcs_bench::cpu_seconds() - t0);
  }
  const double local_peak = peak_since_reset(reset_ok);

  std::vector<Outcome> runs;
  for(int seed = b.first; seed < b.first + b.seeds; ++seed) {
    const VM::Surface_plane_options_3 o = MDCS_test::blob_planes(std::uint64_t(seed));
    const auto finish = [&](Outcome& r, const VM::Minimal_surface_3& s, double t0) {
      r.seed = seed;
      r.discrete = s.energy;
      const double t1 = mdcs_bench::cpu_seconds();
      r.relaxed = VM::relax_surface_3(P, G, s, ro).energy;
      r.relax_seconds = mdcs_bench::cpu_seconds() - t1;
      r.seconds = mdcs_bench::cpu_seconds() - t0;
      r.peak = peak_since_reset(reset_ok);
      std::printf("seed %d %-28s discrete %.6f relaxed %.6f  %.1f s\n", seed, r.method.c_str(), r.discrete, r.relaxed,
                  r.seconds);
      std::fflush(stdout);
      runs.push_back(r);
    };
    { // b. one global solve
      Outcome r;
      r.method = "global, one solve";
      r.planes = b.global_planes;
      r.solves = 1;
      const double t0 = mdcs_bench::cpu_seconds();
      const VM::Plane_arrangement_3 A(VM::surface_planes_3(P, std::size_t(b.global_planes), o));
      const VM::Minimal_surface_3 s = VM::minimize_surface_functional_3(A, P, G);
      r.cells = r.network_nodes = A.number_of_cells();
      r.best_after_solve = {s.energy};
      finish(r, s, t0);
    }
    { // c. single-level plane selection, as many solves as the multi-level refinement
      Outcome r;
      r.method = "plane selection x" + std::to_string(solves);
      r.planes = b.planes;
      r.solves = std::size_t(solves);
      const double t0 = mdcs_bench::cpu_seconds();
      const VM::Plane_selection_result_3 S = VM::select_planes_3(P, G, std::size_t(b.planes), solves, o);
      r.cells = r.network_nodes = *std::max_element(S.cells.begin(), S.cells.end());
      r.best_after_solve = running_minimum(S.energies);
      finish(r, S.surface, t0);
    }
    { // d. multi-level adaptive refinement
      Outcome r;
      r.method = "multi-level " + std::to_string(L.offsets.size()) + " x" + std::to_string(b.iterations);
      r.planes = b.planes;
      r.solves = std::size_t(solves);
      const double t0 = mdcs_bench::cpu_seconds();
      const VM::Surface_multilevel_result_3 M = VM::refine_surface_multilevel_3(P, G, std::size_t(b.planes), L, o);
      std::vector<double> energies;
      for(const VM::Surface_refinement_level_3& level : M.levels) {
        energies.insert(energies.end(), level.solve_energies.begin(), level.solve_energies.end());
        r.cells = (std::max)(r.cells, level.cells);
        std::printf("   level offset %.2f: best %.6f, %zu planes (%zu kept), %zu cells, %zu inside the envelope, "
                    "%.1f s\n", level.offset, level.energy, level.planes, level.kept_planes, level.cells,
                    level.network_nodes, level.seconds);
      }
      r.network_nodes = M.levels.back().network_nodes;
      r.best_after_solve = running_minimum(energies);
      finish(r, M.surface, t0);
    }
  }

  double best = *std::min_element(local.begin(), local.end());
  for(const Outcome& r : runs) best = (std::min)(best, r.relaxed);
  const auto reaches = [&](double e) { return e <= best * (1 + 1e-4); };
  std::size_t local_hits = 0;
  for(double e : local) local_hits += reaches(e) ? 1 : 0;
  mdcs_bench::Table table({"method", "seed", "planes", "solves", "largest_cells", "last_network_nodes",
                           "discrete_energy", "relaxed_energy", "reaches_best", "cpu_seconds", "relax_cpu_seconds",
                           "peak_MiB"});
  std::vector<double> sorted = local;
  std::sort(sorted.begin(), sorted.end());
  table.add_row({"local descent (random start)", std::to_string(local.size()) + " starts", "-", "-", "-", "-", "-",
                 fmt(sorted.front(), "%.8g") + " best; median " + fmt(sorted[sorted.size() / 2], "%.6g"),
                 std::to_string(local_hits) + "/" + std::to_string(local.size()),
                 fmt(mdcs_bench::median(local_seconds)) + " median CPU per run", "-", fmt(local_peak)});
  for(const Outcome& r : runs)
    table.add_row({r.method, std::to_string(r.seed), std::to_string(r.planes), std::to_string(r.solves),
                   std::to_string(r.cells), std::to_string(r.network_nodes), fmt(r.discrete, "%.8g"),
                   fmt(r.relaxed, "%.8g"), reaches(r.relaxed) ? "yes" : "no", fmt(r.seconds), fmt(r.relax_seconds),
                   fmt(r.peak)});
  std::printf("\n");
  table.print();
  table.write_csv(b.out + ".csv");
  write_svg(b.out + ".svg", runs, b.iterations, L.offsets.size());
  std::printf("\nbest relaxed energy of any method %.8g (reaches: within 1e-4 of it); wrote %s.csv and %s.svg\n", best,
              b.out.c_str(), b.out.c_str());
  return 0;
}
