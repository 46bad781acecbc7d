// Univariate solve benchmark: time and peak memory vs number of lines, split into arrangement build, edge
// weights, the min-cut (the planar cut, the default; pseudoflow; both Boost engines) and the shortest-path
// oracle; and the catenoid energy error vs the grid size for random line arrangements and the regular grids
// C_n / C_n^pl.
//
//   bench_curve_2 [--max-lines N] [--runs K] [--only N] [--pseudoflow-up-to N (default 3000)]
//                 [--boost-engines-up-to N (default 1000)] [--csv PREFIX]
// writes PREFIX_time.csv and PREFIX_error.csv (default PREFIX: curve_benchmark).
#include <mdcs_bench.h>

#include <CGAL/Min_cut.h>
#include <CGAL/Variational_minimization.h>

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

namespace VM = CGAL::Variational_minimization;
using mdcs_bench::fmt;

namespace {

VM::Curve_problem_2 catenoid_problem(double R)
{
  return VM::Curve_problem_2{CGAL::Bbox_2(-1, 0, 1, R), VM::End_condition::fixed(R), VM::End_condition::fixed(R)};
}

std::vector<VM::Arrangement_line_2> catenoid_lines(const VM::Curve_problem_2& p, std::size_t n, std::uint64_t seed)
{
  VM::Random_lines_options options;
  options.pencil_points = {VM::Point_2(p.box.xmin(), p.left.low), VM::Point_2(p.box.xmax(), p.right.low)};
  options.pencil_fraction = 0.1;
  return VM::random_lines_2(p.box, n, seed, options);
}

struct Phase_times
{
  std::vector<double> build, weights, cut_planar, cut_pf, cut_pr, cut_bk, path, total, total_wall;
  double peak_build = 0, peak_cut_planar = 0, peak_cut_pf = 0, peak_cut_pr = 0, peak_cut_bk = 0, peak_path = 0;
  std::size_t V = 0, E = 0, F = 0;
  double energy = 0, max_duality_gap = 0;
};

} // namespace

int main(int argc, char** argv)
{
  std::size_t max_lines = 10000;
  std::size_t slow_engine_limit = 1000;
  std::size_t cut_limit = 3000; // pseudoflow: about 20 minutes at 10^4 lines
  std::size_t only = 0; // run only this number of lines in part 1, and skip part 2
  int runs = 3;
  std::string prefix = "curve_benchmark";
  for(int i = 1; i < argc; ++i) {
    if(!std::strcmp(argv[i], "--max-lines") && i + 1 < argc) max_lines = std::strtoul(argv[++i], nullptr, 10);
    else if(!std::strcmp(argv[i], "--runs") && i + 1 < argc) runs = std::atoi(argv[++i]);
    else if(!std::strcmp(argv[i], "--boost-engines-up-to") && i + 1 < argc) slow_engine_limit = std::strtoul(argv[++i], nullptr, 10);
    else if(!std::strcmp(argv[i], "--pseudoflow-up-to") && i + 1 < argc) cut_limit = std::strtoul(argv[++i], nullptr, 10);
    else if(!std::strcmp(argv[i], "--only") && i + 1 < argc) only = std::strtoul(argv[++i], nullptr, 10);
    else if(!std::strcmp(argv[i], "--csv") && i + 1 < argc) prefix = argv[++i];
    else {
      std::cerr << "usage: bench_curve_2 [--max-lines N] [--runs K] [--boost-engines-up-to N] [--pseudoflow-up-to N] [--only N]"
                   " [--csv PREFIX]\n";
      return 2;
    }
  }

  const double R = 2.0;
  const VM::Curve_problem_2 problem = catenoid_problem(R);
  const double exact = VM::global_minimum_surface_of_rotation(R).energy;
  const VM::Surface_of_rotation_functional G;

  // ---- 1. time and memory vs number of lines ------------------------------------------------------------
  std::cout << "Catenoid R = 2 on random lines (10% in pencils through the end points), one core.\n"
            << "Times are CPU seconds (one thread; the machine may be shared), medians of " << runs
            << " runs;\nsolve = build + weights + planar cut (the default), solve_wall_s its wall-clock time;\n"
            << "peak = process peak RSS during the phase (the arrangement and weights included).\n\n";
  mdcs_bench::Table time_table({"lines", "V", "E", "F", "build_s", "weights_s", "cut_planar_s", "cut_pf_s", "cut_pr_s",
                                "cut_bk_s", "path_s", "solve_s", "solve_wall_s", "peak_build_MiB", "peak_cut_planar_MiB",
                                "peak_cut_pf_MiB", "peak_cut_pr_MiB", "peak_cut_bk_MiB", "peak_path_MiB", "rel_error",
                                "cut_vs_path"});
  for(std::size_t n : {100, 300, 1000, 3000, 10000}) {
    if(n > max_lines) break;
    if(only != 0 && n != only) continue;
    Phase_times t;
    const int k = runs;
    for(int r = 0; r < k; ++r) {
      const auto lines = catenoid_lines(problem, n, 1);
      mdcs_bench::reset_peak_rss();
      const double w0 = mdcs_bench::now_seconds();
      double t0 = mdcs_bench::cpu_seconds();
      const VM::Line_arrangement_2 arrangement = VM::build_curve_arrangement_2(problem, lines);
      double t1 = mdcs_bench::cpu_seconds();
      t.peak_build = mdcs_bench::peak_rss_mib();
      const std::vector<double> weights = VM::curve_edge_weights_2(arrangement, G);
      double t2 = mdcs_bench::cpu_seconds();
      mdcs_bench::reset_peak_rss();
      const auto planar = VM::minimize_curve_functional_2(arrangement, weights, problem, CGAL::Min_cut::Planar_min_cut());
      double t2p = mdcs_bench::cpu_seconds();
      t.total_wall.push_back(mdcs_bench::now_seconds() - w0);
      t.peak_cut_planar = mdcs_bench::peak_rss_mib();
      mdcs_bench::reset_peak_rss();
      const auto pf = n <= cut_limit ? VM::minimize_curve_functional_2(arrangement, weights, problem, CGAL::Min_cut::Pseudoflow_max_flow())
                                     : planar;
      double t3a = mdcs_bench::cpu_seconds();
      t.peak_cut_pf = mdcs_bench::peak_rss_mib();
      // Boost's engines are too slow to run above slow_engine_limit lines (minutes to hours).
      VM::Minimal_curve_2 pr = pf, bk = pf;
      double t3 = t3a, t4 = t3a;
      if(n <= slow_engine_limit && n <= cut_limit) {
        mdcs_bench::reset_peak_rss();
        pr = VM::minimize_curve_functional_2(arrangement, weights, problem, CGAL::Min_cut::Push_relabel_max_flow());
        t3 = mdcs_bench::cpu_seconds();
        t.peak_cut_pr = mdcs_bench::peak_rss_mib();
        mdcs_bench::reset_peak_rss();
        bk = VM::minimize_curve_functional_2(arrangement, weights, problem, CGAL::Min_cut::Boykov_kolmogorov_max_flow());
        t4 = mdcs_bench::cpu_seconds();
        t.peak_cut_bk = mdcs_bench::peak_rss_mib();
      }
      mdcs_bench::reset_peak_rss();
      const auto path = VM::directed_shortest_path_2(arrangement, weights, problem);
      double t5 = mdcs_bench::cpu_seconds();
      t.peak_path = mdcs_bench::peak_rss_mib();
      t.build.push_back(t1 - t0);
      t.weights.push_back(t2 - t1);
      t.cut_planar.push_back(t2p - t2);
      t.cut_pf.push_back(t3a - t2p);
      t.cut_pr.push_back(t3 - t3a);
      t.cut_bk.push_back(t4 - t3);
      t.path.push_back(t5 - t4);
      t.total.push_back((t1 - t0) + (t2 - t1) + (t2p - t2));
      t.V = arrangement.number_of_vertices();
      t.E = arrangement.number_of_edges();
      t.F = arrangement.number_of_faces();
      t.energy = planar.energy;
      const double gap = std::max({std::abs(planar.solver_value - path.solver_value), std::abs(pf.solver_value - path.solver_value), std::abs(pr.solver_value - path.solver_value),
                                   std::abs(bk.solver_value - path.solver_value)}) / path.solver_value;
      t.max_duality_gap = std::max(t.max_duality_gap, gap);
    }
    time_table.add_row({std::to_string(n), std::to_string(t.V), std::to_string(t.E), std::to_string(t.F),
                        fmt(mdcs_bench::median(t.build)), fmt(mdcs_bench::median(t.weights)),
                        fmt(mdcs_bench::median(t.cut_planar)), n <= cut_limit ? fmt(mdcs_bench::median(t.cut_pf)) : "-", n <= slow_engine_limit ? fmt(mdcs_bench::median(t.cut_pr)) : "-",
                        n <= slow_engine_limit ? fmt(mdcs_bench::median(t.cut_bk)) : "-",
                        fmt(mdcs_bench::median(t.path)), fmt(mdcs_bench::median(t.total)),
                        fmt(mdcs_bench::median(t.total_wall)),
                        fmt(t.peak_build, "%.0f"), fmt(t.peak_cut_planar, "%.0f"), n <= cut_limit ? fmt(t.peak_cut_pf, "%.0f") : "-", n <= slow_engine_limit ? fmt(t.peak_cut_pr, "%.0f") : "-",
                        n <= slow_engine_limit ? fmt(t.peak_cut_bk, "%.0f") : "-", fmt(t.peak_path, "%.0f"),
                        fmt((t.energy - exact) / exact, "%.3e"), fmt(t.max_duality_gap, "%.1e")});
    std::cout << "  done: " << n << " lines\n" << std::flush;
  }
  std::cout << "\n";
  time_table.print();
  time_table.write_csv(prefix + "_time.csv");
  if(only != 0) return 0;

  // ---- 2. energy error vs grid size: random arrangements vs the regular grids -----------------------------
  std::cout << "\nCatenoid R = 2: relative energy error of the discrete optimum (exact F = " << fmt(exact, "%.6f")
            << ").\nRandom: median over 3 seeds. C_n: dynamic programming on the non-planar grid. C_n^pl: cut on the"
               " arrangement of the lines through C_n's edges.\n\n";
  mdcs_bench::Table error_table({"grid", "size", "edges", "rel_error", "seconds"});
  for(std::size_t n : {100, 200, 400, 800, 1600, 3200}) {
    if(n > max_lines) break;
    std::vector<double> errors, secs;
    std::size_t edges = 0;
    for(std::uint64_t seed = 1; seed <= 3; ++seed) {
      const double t0 = mdcs_bench::cpu_seconds();
      const auto arrangement = VM::build_curve_arrangement_2(problem, catenoid_lines(problem, n, seed));
      const auto weights = VM::curve_edge_weights_2(arrangement, G);
      const auto curve = VM::minimize_curve_functional_2(arrangement, weights, problem);
      secs.push_back(mdcs_bench::cpu_seconds() - t0);
      errors.push_back((curve.energy - exact) / exact);
      edges = arrangement.number_of_edges();
    }
    error_table.add_row({"random lines", std::to_string(n), std::to_string(edges), fmt(mdcs_bench::median(errors), "%.3e"),
                         fmt(mdcs_bench::median(secs))});
  }
  for(std::size_t n : {2, 4, 8, 12, 16, 24}) {
    const double t0 = mdcs_bench::cpu_seconds();
    const auto curve = VM::minimize_on_regular_grid_2(problem, G, n);
    const double s = mdcs_bench::cpu_seconds() - t0;
    const std::size_t edges = n * (n * n + 1) * (n * n + 1);
    error_table.add_row({"C_n (DP)", "n=" + std::to_string(n), std::to_string(edges), fmt((curve.energy - exact) / exact, "%.3e"),
                         fmt(s)});
  }
  for(std::size_t n : {2, 3}) {
    const double t0 = mdcs_bench::cpu_seconds();
    const auto lines = VM::regular_grid_lines_2(problem.box, n);
    const auto arrangement = VM::build_curve_arrangement_2(problem, lines);
    const auto weights = VM::curve_edge_weights_2(arrangement, G);
    const auto curve = VM::minimize_curve_functional_2(arrangement, weights, problem);
    const double s = mdcs_bench::cpu_seconds() - t0;
    error_table.add_row({"C_n^pl (cut)", "n=" + std::to_string(n) + " (" + std::to_string(lines.size()) + " lines)",
                         std::to_string(arrangement.number_of_edges()), fmt((curve.energy - exact) / exact, "%.3e"), fmt(s)});
  }
  error_table.print();
  error_table.write_csv(prefix + "_error.csv");
  std::cout << "\nCSV: " << prefix << "_time.csv, " << prefix << "_error.csv\n";
  return 0;
}
