// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Benchmark of minimum_weight_triangulation_2 on the LP-only path (diamond test + triangle LP):
// uniform, clustered and normal points, odd wheels (fractional LP -> branch and bound), per-stage times,
// peak memory, and the fraction of integral LP optima over many random sets (thesis ch. 3.4.4).
//
// usage: bench_mwt [--large] [--sizes N1,N2,..] [--uniform-only] [--no-random] [--lmt] [--bb-limit S] [--repeats R]
//                  [--sets S] [--max-wheel K] [--trace-memory] [--csv FILE]
//   --lmt: the LMT-skeleton + face dynamic program + LP pipeline (Mwt_options::use_lmt_skeleton);
//   --no-random: wheels only; --bb-limit: branch-and-bound limit per wheel in seconds (default 120).
//   default sizes 100, 300, 1000, 2000 uniform; --large adds 5000 and 10000 (one run each unless --sizes is
//   given). Wheels k = 13..K (default 41, 0: none); --sets: random sets for the integrality count (default 100).
//   Stage times (t_*) are processor seconds of the process (std::clock, MDCS_MWT_CPU_TIMERS), medians over the
//   repeats; t_total = their sum (t_setup: Hilbert sort, checks, hull, grid). peak_MiB: process peak so far.
//   dp_exact_faces / dp_exact_decisions (--lmt): faces and decisions of the face programs that double
//   precision could not separate and the exact comparison of sums of square roots decided. dp_weak_faces
//   (--lmt): faces solved by the program whose boundary walk repeats a vertex (dangling edges, pinch vertices).
//   --trace-memory: the peak resident set of every stage (the progress callback resets the kernel's peak
//   counter, /proc/self/clear_refs, when a stage starts), printed and written to <csv>_memory.csv; peak_MiB is
//   then the maximum over the stages (the kernel's own peak, and /usr/bin/time's, only cover the last stage).
//   --threads T1,T2,..: thread scaling (issue 29) instead of the tables above: every size (uniform; clustered too
//   without --uniform-only) with each thread count (CGAL::Parallel_if_available_tag, Mwt_options::threads),
//   interleaved over the repeats; per stage wall-clock and processor seconds (between the progress callback's
//   stage changes), medians, speed-up and efficiency against the first count, a check that every result is
//   identical, the serial fraction of the one-thread runs and the Amdahl projection to 4, 8 and 16 threads
//   (<csv>_threads*.csv). --project-total S: also project a one-thread total of S seconds (e.g. of 10^7 points)
//   to 16 threads with that serial fraction. Exit code 1 when a result differs between thread counts.
//   --random-wheels K1..K2: the random-wheel experiment of the thesis's Fig. 3.5 instead (mwt_random_wheels.h):
//   --wheel-trials T random wheels (default 200) for each k = K1..K2 points on the circle; the fractions settled by
//   the LP alone and by the LMT-skeleton alone with 95 % intervals, in <csv> and the plot <csv minus .csv>.svg.
//   Exit code 1 when an integral LP weight differs from the LMT pipeline's.
//   --qp-scaling: the exact QP_solver model's processor time against the LP size instead (mwt_qp_scaling.h):
//   uniform, clustered, regular and random wheels for each of --sizes (points, or points on the circle), each
//   family until a solve takes longer than --qp-stop S seconds (default 30); medians of --repeats runs of the solves
//   under 2 s; a family also stops at an LP of more than --qp-columns C columns (default 1000, 0: none; listed,
//   not solved); --qp-families: a comma-separated subset of uniform,clustered,wheel,random_wheel. Exit code 1
//   when an optimum differs from exact GLPK's.

// stage times in processor time (std::clock): the benchmark machine may be shared
#define MDCS_MWT_CPU_TIMERS 1
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Minimum_weight_triangulation_2.h>

#include "mdcs_bench.h"
#include "mwt_qp_scaling.h"
#include "mwt_random_wheels.h"
#include "mwt_thread_scaling.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;
namespace MWT = CGAL::Minimum_weight_triangulation_2;

std::vector<Point> points(const std::string& d, int n, unsigned seed)
{
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> nd(0, 1);
  std::vector<Point> p;
  if(d == "uniform") for(int i = 0; i < n; ++i) p.emplace_back(u(g), u(g));
  else if(d == "normal") for(int i = 0; i < n; ++i) p.emplace_back(nd(g), nd(g));
  else {   // clustered: n/100 Gaussian clusters
    const int c = std::max(1, n / 100);
    std::vector<Point> centre;
    for(int i = 0; i < c; ++i) centre.emplace_back(u(g), u(g));
    const double s = 0.3 / std::sqrt(double(c));
    for(int i = 0; i < n; ++i) {
      const Point& q = centre[std::size_t(g() % c)];
      p.emplace_back(q.x() + s * nd(g), q.y() + s * nd(g));
    }
  }
  return p;
}

std::vector<Point> wheel(int k)
{
  std::vector<Point> p{Point(0, 0)};
  for(int i = 0; i < k; ++i) p.emplace_back(std::cos(2 * M_PI * i / k), std::sin(2 * M_PI * i / k));
  return p;
}

} // namespace

int main(int argc, char** argv)
{
  bool large = false, uniform_only = false, lmt = false, no_random = false, trace_memory = false;
  double bb_limit = 120;
  std::vector<int> sizes{100, 300, 1000, 2000};
  bool explicit_sizes = false;
  int repeats = 3, sets = 100, max_wheel = 41;
  std::string csv = "mwt.csv";
  std::vector<std::size_t> thread_list;   // --threads: the thread-scaling mode
  double project_total = 0;
  bool random_wheels = false;
  int wheel_k_min = 0, wheel_k_max = 0;
  long wheel_trials = 200;
  bool qp_scaling = false;
  double qp_stop = 30;
  long qp_columns = 1000;
  std::string qp_families = "uniform,clustered,wheel,random_wheel";
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--large") large = true;
    else if(a == "--repeats" && i + 1 < argc) repeats = std::max(1, std::atoi(argv[++i]));
    else if(a == "--sets" && i + 1 < argc) sets = std::max(0, std::atoi(argv[++i]));
    else if(a == "--max-wheel" && i + 1 < argc) max_wheel = std::atoi(argv[++i]);
    else if(a == "--csv" && i + 1 < argc) csv = argv[++i];
    else if(a == "--uniform-only") uniform_only = true;
    else if(a == "--lmt") lmt = true;
    else if(a == "--no-random") no_random = true;
    else if(a == "--trace-memory") trace_memory = true;
    else if(a == "--bb-limit" && i + 1 < argc) bb_limit = std::atof(argv[++i]);
    else if(a == "--project-total" && i + 1 < argc) project_total = std::atof(argv[++i]);
    else if(a == "--random-wheels" && i + 1 < argc) {
      random_wheels = true;
      if(std::sscanf(argv[++i], "%d..%d", &wheel_k_min, &wheel_k_max) != 2) wheel_k_min = wheel_k_max = 0;
    }
    else if(a == "--qp-scaling") qp_scaling = true;
    else if(a == "--qp-stop" && i + 1 < argc) qp_stop = std::atof(argv[++i]);
    else if(a == "--qp-families" && i + 1 < argc) qp_families = argv[++i];
    else if(a == "--qp-columns" && i + 1 < argc) qp_columns = std::max(0L, std::atol(argv[++i]));
    else if(a == "--wheel-trials" && i + 1 < argc) wheel_trials = std::atol(argv[++i]);
    else if(a == "--threads" && i + 1 < argc) {
      std::string list = argv[++i];
      for(std::size_t pos = 0; pos < list.size();) {
        const std::size_t comma = list.find(',', pos);
        thread_list.push_back(std::size_t(std::max(1, std::atoi(list.substr(pos, comma - pos).c_str()))));
        pos = comma == std::string::npos ? list.size() : comma + 1;
      }
    }
    else if(a == "--sizes" && i + 1 < argc) {
      sizes.clear();
      explicit_sizes = true;
      std::string list = argv[++i];
      for(std::size_t pos = 0; pos < list.size();) {
        const std::size_t comma = list.find(',', pos);
        sizes.push_back(std::atoi(list.substr(pos, comma - pos).c_str()));
        pos = comma == std::string::npos ? list.size() : comma + 1;
      }
    }
    else { std::fprintf(stderr, "usage: bench_mwt [--large] [--sizes N1,N2,..] [--uniform-only] [--no-random] [--lmt] [--bb-limit S] [--repeats R] [--sets S] [--max-wheel K] [--trace-memory] [--csv FILE] [--threads T1,T2,.. [--project-total S]] [--random-wheels K1..K2 [--wheel-trials T]] [--qp-scaling [--qp-stop S] [--qp-columns C] [--qp-families F1,F2,..]]\n"); return 2; }
  }
  if(qp_scaling) {
    std::printf("QP_solver scaling: processor seconds of the exact LP solve\n");
    return mwt_qp_scaling::run<K>(sizes, repeats, qp_stop, std::size_t(qp_columns), qp_families, csv) ? 0 : 1;
  }
  if(random_wheels) {
    if(wheel_k_min < 3 || wheel_k_max <= wheel_k_min || wheel_trials < 1) {
      std::fprintf(stderr, "bench_mwt: --random-wheels K1..K2 needs 3 <= K1 < K2 and --wheel-trials >= 1\n");
      return 2;
    }
    const auto dot = csv.rfind(".csv");
    return mwt_random_wheels::run(wheel_k_min, wheel_k_max, wheel_trials, csv,
                                  (dot == std::string::npos ? csv : csv.substr(0, dot)) + ".svg") ? 0 : 1;
  }
  if(!thread_list.empty()) {
    std::vector<std::pair<std::string, std::vector<Point>>> inputs;
    for(int n : sizes) inputs.emplace_back("uniform", points("uniform", n, 1));
    if(!uniform_only)
      for(int n : sizes) inputs.emplace_back("clustered", points("clustered", n, 2));
    MWT::Mwt_options o;
    o.use_lmt_skeleton = lmt;
    o.branch_and_bound_time_limit = bb_limit;
    const auto dot = csv.rfind(".csv");
    std::printf("thread scaling: %s, hardware threads %zu, TBB %s\n", lmt ? "LMT pipeline" : "LP path",
                CGAL::MDCS::hardware_threads(), CGAL::MDCS::has_parallel_support() ? "linked" : "NOT linked (sequential)");
    return mwt_scaling::thread_scaling(inputs, o, thread_list, repeats, dot == std::string::npos ? csv : csv.substr(0, dot),
                                       project_total) ? 0 : 1;
  }
  mdcs_bench::Table table({"input", "n", "status", "weight", "LP_opt", "cand_edges", "edges_per_n", "triangles", "lp_cols",
                           "lp_rows", "t_setup", "t_candidates", "t_triangles", "t_lp_build", "t_lp_solve", "t_certificate",
                           "t_branch_bound", "t_total", "peak_MiB", "lmt_certain", "lmt_possible", "faces",
                           "dp_faces", "dp_triangles", "largest_face", "t_lmt", "t_face_dp", "dp_exact_faces",
                           "dp_exact_decisions", "dp_weak_faces"});
  // --trace-memory: per stage the resident set when it starts and its peak (peak counter reset at every start)
  mdcs_bench::Table memory_table({"input", "n", "stage", "resident_at_start_MiB", "peak_MiB"});
  // the resets make the kernel's peak (VmHWM, also what /usr/bin/time reports) the peak since the last stage
  // start: traced_peak keeps the maximum over the stages
  std::string stage_now;
  double stage_rss0 = 0, traced_peak = 0;
  auto close_stage = [&](const std::string& name, std::size_t n) {
    const double peak = mdcs_bench::peak_rss_mib();
    traced_peak = std::max(traced_peak, peak);
    if(!stage_now.empty())
      memory_table.add_row({name, std::to_string(n), stage_now, mdcs_bench::fmt(stage_rss0, "%.0f"),
                            mdcs_bench::fmt(peak, "%.0f")});
    stage_now.clear();
  };
  auto open_stage = [&](const std::string& stage) {
    mdcs_bench::reset_peak_rss();
    stage_now = stage;
    stage_rss0 = mdcs_bench::current_rss_mib();
  };
  auto run = [&](const std::string& name, const std::vector<Point>& p, int reps, double bb_limit) {
    std::vector<double> tsu, tc, tt, tb, ts, tcert, tbb, tot, tl, tf;
    MWT::Mwt_result r;
    for(int k = 0; k < reps; ++k) {
      MWT::Mwt_options o;
      o.branch_and_bound_time_limit = bb_limit;
      o.use_lmt_skeleton = lmt;
      const bool trace = trace_memory && k == reps - 1;
      if(trace) {
        open_stage("setup (Hilbert sort, hull, grid)");
        o.progress = [&](const char* stage, double) {
          if(stage_now != stage) { close_stage(name, p.size()); open_stage(stage); }
          return true;
        };
      }
      r = MWT::minimum_weight_triangulation_2(p, o);
      if(trace) close_stage(name, p.size());
      const auto& s = r.statistics;
      tsu.push_back(s.time_setup); tc.push_back(s.time_candidates); tt.push_back(s.time_triangles); tb.push_back(s.time_lp_build);
      ts.push_back(s.time_lp_solve); tcert.push_back(s.time_certificate); tbb.push_back(s.time_branch_and_bound);
      tot.push_back(s.time_total); tl.push_back(s.time_lmt); tf.push_back(s.time_face_dp);
    }
    const auto& s = r.statistics;
    table.add_row({name, std::to_string(p.size()), MWT::to_string(r.status), mdcs_bench::fmt(r.weight, "%.6f"),
                   mdcs_bench::fmt(r.lp_objective, "%.6f"), std::to_string(s.candidate_edges),
                   mdcs_bench::fmt(double(s.candidate_edges) / p.size(), "%.2f"), std::to_string(s.empty_triangles),
                   std::to_string(s.lp_columns), std::to_string(s.lp_rows), mdcs_bench::fmt(mdcs_bench::median(tsu)), mdcs_bench::fmt(mdcs_bench::median(tc)),
                   mdcs_bench::fmt(mdcs_bench::median(tt)), mdcs_bench::fmt(mdcs_bench::median(tb)),
                   mdcs_bench::fmt(mdcs_bench::median(ts)), mdcs_bench::fmt(mdcs_bench::median(tcert)),
                   mdcs_bench::fmt(mdcs_bench::median(tbb)), mdcs_bench::fmt(mdcs_bench::median(tot)),
                   mdcs_bench::fmt(std::max(mdcs_bench::peak_rss_mib(), traced_peak), "%.0f"), std::to_string(s.lmt_certain_edges),
                   std::to_string(s.lmt_possible_edges), std::to_string(s.lmt_faces), std::to_string(s.lmt_solved_faces),
                   std::to_string(s.dp_triangles), std::to_string(s.lmt_largest_face), mdcs_bench::fmt(mdcs_bench::median(tl)),
                   mdcs_bench::fmt(mdcs_bench::median(tf)), std::to_string(s.dp_exact_faces),
                   std::to_string(s.dp_exact_decisions), std::to_string(s.dp_weakly_simple_faces)});
    std::fprintf(stderr, "%s n=%zu: %s, %.3f s\n", name.c_str(), p.size(), MWT::to_string(r.status), mdcs_bench::median(tot));
  };
  if(large) { sizes.push_back(5000); sizes.push_back(10000); }
  if(no_random) { sizes.clear(); uniform_only = true; }
  for(int n : sizes) run("uniform", points("uniform", n, 1), (n >= 5000 && !explicit_sizes) ? 1 : repeats, 0);
  if(!uniform_only) for(int n : {1000, 2000}) {
    run("clustered", points("clustered", n, 2), repeats, 0);
    run("normal", points("normal", n, 3), repeats, 0);
  }
  for(int k = 13; k <= max_wheel; k += (k < 21 ? 2 : 10)) run("wheel", wheel(k), 1, bb_limit);
  table.print();
  if(!table.write_csv(csv)) std::fprintf(stderr, "cannot write %s\n", csv.c_str());
  if(trace_memory) {
    std::printf("\nPeak resident set per stage (MiB; a stage lasts until the next one reports: \"face dynamic program\"\n"
                "includes building the LP, and the last stage the certificate and the validation):\n");
    memory_table.print();
    const auto dot = csv.rfind(".csv");
    memory_table.write_csv((dot == std::string::npos ? csv : csv.substr(0, dot)) + "_memory.csv");
  }

  // Thesis experiment: fraction of integral LP optima over random uniform sets of 10, 20, 60, 200 points.
  if(sets > 0) {
    const int sz[4] = {10, 20, 60, 200};
    int integral[4] = {0, 0, 0, 0}, count[4] = {0, 0, 0, 0}, certified = 0, exact = 0;
    const double t0 = mdcs_bench::now_seconds();
    for(int s = 0; s < sets; ++s) {
      const int c = s % 4;
      const auto r = MWT::minimum_weight_triangulation_2(points("uniform", sz[c], 5000 + unsigned(s)));
      ++count[c];
      integral[c] += r.lp_integral;
      certified += r.status == MWT::Mwt_status::certified_optimal;
      exact += r.certificate_exact;
    }
    mdcs_bench::Table t2({"n", "sets", "integral_LP", "fraction"});
    for(int c = 0; c < 4; ++c)
      t2.add_row({std::to_string(sz[c]), std::to_string(count[c]), std::to_string(integral[c]),
                  mdcs_bench::fmt(count[c] ? double(integral[c]) / count[c] : 0.0, "%.4f")});
    std::printf("\nIntegral LP optima over %d random uniform sets (%d certified optimal, %d of them with the exact "
                "certificate), %.1f s:\n", sets, certified, exact, mdcs_bench::now_seconds() - t0);
    t2.print();
    std::string csv2 = csv;
    const auto dot = csv2.rfind(".csv");
    csv2 = (dot == std::string::npos ? csv2 : csv2.substr(0, dot)) + "_integrality.csv";
    t2.write_csv(csv2);
  }
  return 0;
}
