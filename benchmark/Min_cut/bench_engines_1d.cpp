// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Max-flow engines on the networks that the 1D solver really builds: the directed duals of line
// arrangements for the catenoid problem (surface of rotation between two rings of radius 2),
// built with the library (build_curve_arrangement_2, curve_edge_weights_2, curve_dual_network_2).
// For each size and engine: median wall time of solve_min_cut, peak memory above the memory held
// before the call (the network itself excluded), and whether every engine gives the same value
// (relative 1e-9) and the same source side as push-relabel.
//
// Usage: bench_engines_1d [--csv FILE] [--large] [--all] [--runs K]
//   --csv    output file (default engines_1d_benchmark.csv)
//   --large  adds 10000 lines
//   --all    runs Boykov-Kolmogorov at every size (default: up to 1000 lines; it is the slowest)
//   --runs   runs per measurement up to 2000 lines (default 3; one run above 2000 lines)

#include <CGAL/Min_cut.h>
#include <CGAL/Min_cut/Pseudoflow_max_flow.h>
#include <CGAL/Variational_minimization.h>

#include "mdcs_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace MC = CGAL::Min_cut;
namespace VM = CGAL::Variational_minimization;
typedef MC::Flow_network<double> Network;

// The catenoid problem of test/include/MDCS_test/curve_problems.h with R = 2: both ends fixed at
// the top of the box, a tenth of the lines through each end point.
Network catenoid_network(std::size_t lines)
{
  const double R = 2;
  const VM::Curve_problem_2 problem{CGAL::Bbox_2(-1, 0, 1, R), VM::End_condition::fixed(R), VM::End_condition::fixed(R)};
  VM::Random_lines_options options;
  options.pencil_points = {VM::Point_2(-1, R), VM::Point_2(1, R)};
  const auto arrangement = VM::build_curve_arrangement_2(problem, VM::random_lines_2(problem.box, lines, 1, options));
  const auto weights = VM::curve_edge_weights_2(arrangement, VM::Surface_of_rotation_functional());
  return VM::internal::curve_dual_network_2(arrangement, weights, problem);
}

struct Measure
{
  bool ran = false;
  double seconds = 0, peak_mib = 0;
  MC::Min_cut_result<double> result;
};

template <class Engine>
Measure measure(const Network& network, int runs)
{
  Measure m;
  m.ran = true;
  std::vector<double> times, peaks;
  for(int r = 0; r < runs; ++r) {
    m.result = MC::Min_cut_result<double>();
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
    mdcs_bench::reset_peak_rss();
    const double base = mdcs_bench::current_rss_mib();
    const double t0 = mdcs_bench::now_seconds();
    m.result = MC::solve_min_cut(network, Engine());
    times.push_back(mdcs_bench::now_seconds() - t0);
    peaks.push_back(mdcs_bench::peak_rss_mib() - base);
  }
  m.seconds = mdcs_bench::median(times);
  m.peak_mib = mdcs_bench::median(peaks);
  return m;
}

int main(int argc, char** argv)
{
  std::string csv = "engines_1d_benchmark.csv";
  bool large = false, all = false;
  int runs = 3;
  for(int a = 1; a < argc; ++a) {
    if(!std::strcmp(argv[a], "--csv") && a + 1 < argc) csv = argv[++a];
    else if(!std::strcmp(argv[a], "--large")) large = true;
    else if(!std::strcmp(argv[a], "--all")) all = true;
    else if(!std::strcmp(argv[a], "--runs") && a + 1 < argc) runs = std::max(1, std::atoi(argv[++a]));
    else {
      std::fprintf(stderr, "usage: %s [--csv FILE] [--large] [--all] [--runs K]\n", argv[0]);
      return 1;
    }
  }
#if defined(__GLIBC__)
  // Large blocks in mmap: freed memory leaves the resident set, so each run starts from the same base.
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif

  std::vector<std::size_t> sizes = {100, 300, 1000, 2000, 3000};
  if(large) sizes.push_back(10000);

  mdcs_bench::Table table({"lines", "nodes", "arcs", "engine", "time_s", "peak_MiB", "bytes_per_arc", "cut_value",
                           "rel_diff_vs_PR", "same_sides_as_PR", "speedup_vs_PR"});
  bool all_agree = true;
  for(const std::size_t lines : sizes) {
    const double t0 = mdcs_bench::now_seconds();
    const Network network = catenoid_network(lines);
    const double build = mdcs_bench::now_seconds() - t0;
    const std::size_t arcs =
      2 * network.number_of_facets() + network.number_of_source_facets() + network.number_of_sink_facets();
    std::fprintf(stderr, "%zu lines: %zu nodes, %zu arcs (built in %.1f s)\n", lines, network.number_of_nodes(),
                 arcs, build);
    const int k = lines > 2000 ? 1 : runs;

    const Measure pr = measure<MC::Push_relabel_max_flow>(network, k);
    std::fprintf(stderr, "  push_relabel %.3f s\n", pr.seconds);
    Measure bk;
    if(all || lines <= 1000) {
      bk = measure<MC::Boykov_kolmogorov_max_flow>(network, k);
      std::fprintf(stderr, "  boykov_kolmogorov %.3f s\n", bk.seconds);
    }
    const Measure pf = measure<MC::Pseudoflow_max_flow>(network, k);
    std::fprintf(stderr, "  pseudoflow %.3f s\n", pf.seconds);

    auto row = [&](const char* engine, const Measure& m) {
      if(!m.ran) return;
      const double rel = std::abs(m.result.value - pr.result.value) / std::max(1e-300, std::abs(pr.result.value));
      const bool same_sides = m.result.on_source_side == pr.result.on_source_side;
      if(!(rel <= 1e-9) || !same_sides || m.result.is_finite != pr.result.is_finite) all_agree = false;
      table.add_row({std::to_string(lines), std::to_string(network.number_of_nodes()), std::to_string(arcs), engine,
                     mdcs_bench::fmt(m.seconds, "%.3f"), mdcs_bench::fmt(m.peak_mib, "%.1f"),
                     mdcs_bench::fmt(m.peak_mib * 1048576.0 / double(arcs), "%.1f"),
                     mdcs_bench::fmt(m.result.value, "%.12g"), mdcs_bench::fmt(rel, "%.1e"),
                     same_sides ? "yes" : "NO", mdcs_bench::fmt(pr.seconds / m.seconds, "%.2f")});
    };
    row("push_relabel", pr);
    row("boykov_kolmogorov", bk);
    row("pseudoflow", pf);
  }
  table.print();
  if(!table.write_csv(csv)) {
    std::fprintf(stderr, "cannot write %s\n", csv.c_str());
    return 1;
  }
  std::printf("CSV written to %s\n", csv.c_str());
  if(!all_agree) {
    std::printf("ENGINES DISAGREE (value beyond 1e-9 relative, or sides)\n");
    return 2;
  }
  return 0;
}
