// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Min-cut engines on the networks of the variational problems: 2D grids of cells, 4-connected, random
// capacities in both directions, terminal arcs only on the bottom (source) and top (sink) rows.
// "function" grids make every downward arc infinite, as the directed dual of a function graph does.
// For each grid and engine: median wall time of solve_min_cut over the runs, peak memory above the
// memory held before the call (the network itself excluded), and that peak per arc.
//
// Usage: bench_min_cut [--csv FILE] [--large] [--runs K] [--engine both|push_relabel|boykov_kolmogorov]
//   --csv    output file (default min_cut_benchmark.csv)
//   --large  adds 3 * 10^6 nodes
//   --runs   runs per measurement (default 3)
//   --engine which engines to run (default both; Boykov-Kolmogorov takes minutes from 10^6 nodes)

#include <CGAL/Min_cut.h>

#include "mdcs_bench.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace MC = CGAL::Min_cut;
typedef MC::Flow_network<double> Network;

// Width x width cells; cell (x, y) has index y * width + x, y grows upwards.
Network make_grid(std::size_t width, bool function_constrained, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> cost(0.1, 1.0);
  Network network;
  const std::size_t n = width * width;
  network.reserve(n, 2 * n, 2 * width);
  network.add_nodes(n);
  std::uint32_t id = 0;
  for(std::size_t y = 0; y < width; ++y)
    for(std::size_t x = 0; x < width; ++x) {
      const auto i = MC::Flow_network<double>::Node_index(y * width + x);
      if(x + 1 < width) network.add_facet(i, i + 1, cost(rng), cost(rng), id++);
      if(y + 1 < width) {
        const double up = cost(rng), down = cost(rng);
        network.add_facet(i, MC::Flow_network<double>::Node_index(i + width), up,
                          function_constrained ? Network::infinity() : down, id++);
      }
      // Terminal arcs cost more than interior ones, so the cut runs through the interior.
      if(y == 0) network.add_source_facet(i, 4 * cost(rng), id++);
      if(y + 1 == width) network.add_sink_facet(i, 4 * cost(rng), id++);
    }
  return network;
}

struct Measure
{
  double seconds, peak_mib, value;
};

template <class Engine>
Measure measure(const Network& network, int runs)
{
  std::vector<double> times, peaks;
  double value = 0;
  for(int r = 0; r < runs; ++r) {
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
    mdcs_bench::reset_peak_rss();
    const double base = mdcs_bench::current_rss_mib();
    const double t0 = mdcs_bench::now_seconds();
    {
      const auto result = MC::solve_min_cut(network, Engine());
      value = result.value;
      times.push_back(mdcs_bench::now_seconds() - t0);
    }
    peaks.push_back(mdcs_bench::peak_rss_mib() - base);
  }
  return Measure{mdcs_bench::median(times), mdcs_bench::median(peaks), value};
}

int main(int argc, char** argv)
{
  std::string csv = "min_cut_benchmark.csv";
  bool large = false;
  int runs = 3;
  std::string engines = "both";
  for(int a = 1; a < argc; ++a) {
    if(!std::strcmp(argv[a], "--csv") && a + 1 < argc) csv = argv[++a];
    else if(!std::strcmp(argv[a], "--engine") && a + 1 < argc) engines = argv[++a];
    else if(!std::strcmp(argv[a], "--large")) large = true;
    else if(!std::strcmp(argv[a], "--runs") && a + 1 < argc) runs = std::max(1, std::atoi(argv[++a]));
    else {
      std::fprintf(stderr, "usage: %s [--csv FILE] [--large] [--runs K] [--engine both|push_relabel|boykov_kolmogorov]\n",
                   argv[0]);
      return 1;
    }
  }
  const bool run_bk = engines == "both" || engines == "boykov_kolmogorov";
  const bool run_pr = engines == "both" || engines == "push_relabel";
  if(!run_bk && !run_pr) {
    std::fprintf(stderr, "unknown engine '%s'\n", engines.c_str());
    return 1;
  }
#if defined(__GLIBC__)
  // A fixed threshold keeps large blocks in mmap, so freed memory leaves the resident set and each
  // run's peak is measured from the same base.
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif

  std::vector<std::size_t> sizes = {10000, 100000, 1000000};
  if(large) sizes.push_back(3000000);

  mdcs_bench::Table table({"grid", "kind", "nodes", "arcs", "engine", "time_s", "peak_MiB", "bytes_per_arc",
                           "cut_value", "rel_diff", "speedup_vs_BK"});
  for(const bool function_constrained : {false, true})
    for(const std::size_t target : sizes) {
      const std::size_t width = std::size_t(std::lround(std::sqrt(double(target))));
      const Network network = make_grid(width, function_constrained, 12345u + unsigned(width));
      // Directed arcs of the network: both directions of every interior facet, plus terminal arcs.
      const std::size_t arcs =
        2 * network.number_of_facets() + network.number_of_source_facets() + network.number_of_sink_facets();

      const Measure none{0, 0, 0};
      const Measure bk = run_bk ? measure<MC::Boykov_kolmogorov_max_flow>(network, runs) : none;
      const Measure pr = run_pr ? measure<MC::Push_relabel_max_flow>(network, runs) : none;
      const std::string grid = std::to_string(width) + "x" + std::to_string(width);
      const char* kind = function_constrained ? "function" : "plain";
      auto row = [&](const char* engine, const Measure& m) {
        table.add_row({grid, kind, std::to_string(width * width), std::to_string(arcs), engine,
                       mdcs_bench::fmt(m.seconds, "%.3f"), mdcs_bench::fmt(m.peak_mib, "%.1f"),
                       mdcs_bench::fmt(m.peak_mib * 1048576.0 / double(arcs), "%.1f"),
                       mdcs_bench::fmt(m.value, "%.10g"),
                       run_bk ? mdcs_bench::fmt(std::abs(m.value - bk.value) / bk.value, "%.1e") : "-",
                       run_bk ? mdcs_bench::fmt(bk.seconds / m.seconds, "%.2f") : "-"});
      };
      if(run_bk) row("boykov_kolmogorov", bk);
      if(run_pr) row("push_relabel", pr);
      std::fprintf(stderr, "done: %s %s\n", grid.c_str(), kind);
    }
  table.print();
  if(!table.write_csv(csv)) {
    std::fprintf(stderr, "cannot write %s\n", csv.c_str());
    return 1;
  }
  std::printf("CSV written to %s\n", csv.c_str());
  return 0;
}
