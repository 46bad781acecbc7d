// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The `--qp-scaling` mode of bench_mwt: processor time of CGAL's exact QP_solver
// (QP_solver_linear_program_solver, Gmpzf) on the MWT triangle LP against the LP's size, for uniform points,
// clustered points (five tight Gaussian clusters), regular wheels and random wheels. It measured the default of
// Mwt_options::qp_max_columns: QP_solver runs its whole simplex inside one call that cannot be interrupted, so
// the only guard is to refuse programs whose size predicts a long solve.
// Per family the sizes grow until one solve takes longer than `stop_after` seconds (the next would be far longer)
// or the LP has more than `max_columns` columns (listed, not solved; 0: no such stop).
// Exact GLPK solves the same LP as a cross-check of the optimum and for comparison.

#ifndef MDCS_BENCH_MWT_QP_SCALING_H
#define MDCS_BENCH_MWT_QP_SCALING_H

#include <CGAL/Minimum_weight_triangulation_2.h>
#include <CGAL/Minimum_weight_triangulation_2/QP_solver_linear_program_solver.h>
#include <CGAL/Random.h>
#include <MDCS_test/random_wheels.h>

#include "mdcs_bench.h"

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace mwt_qp_scaling {

namespace MWT = CGAL::Minimum_weight_triangulation_2;

// Five tight clusters (standard deviation 0.03 in the unit square): many short candidate edges per point.
template <class Point>
std::vector<Point> clustered(int n, unsigned seed)
{
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> nd(0, 0.03);
  std::vector<Point> centres;
  for(int i = 0; i < 5; ++i) centres.emplace_back(u(g), u(g));
  std::vector<Point> p;
  for(int i = 0; i < n; ++i) p.emplace_back(centres[std::size_t(i % 5)].x() + nd(g), centres[std::size_t(i % 5)].y() + nd(g));
  return p;
}

template <class Point>
std::vector<Point> uniform(int n, unsigned seed)
{
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point> p;
  for(int i = 0; i < n; ++i) p.emplace_back(u(g), u(g));
  return p;
}

template <class Point>
std::vector<Point> regular_wheel(int k)
{
  std::vector<Point> p{Point(0, 0)};
  for(int i = 0; i < k; ++i) p.emplace_back(std::cos(2 * M_PI * i / k), std::sin(2 * M_PI * i / k));
  return p;
}

// Runs the `families` (a comma-separated list) over `sizes` (points, or points on the circle for the wheels); `repeats` runs of the
// solves that take less than 2 s (one run of the longer ones), medians of the processor time. Returns false when
// the QP optimum differs from exact GLPK's.
template <class Kernel>
bool run(const std::vector<int>& sizes, int repeats, double stop_after, std::size_t max_columns,
         const std::string& families, const std::string& csv)
{
  typedef typename Kernel::Point_2 Point;
  mdcs_bench::Table table({"input", "n", "lp_cols", "lp_rows", "lp_nonzeros", "qp_iterations", "t_qp_cpu",
                           "runs", "t_glpk_exact_cpu", "qp_objective", "glpk_objective", "integral"});
  bool agree = true;
  for(const std::string family : {"uniform", "clustered", "wheel", "random_wheel"}) {
    if(("," + families + ",").find("," + family + ",") == std::string::npos) continue;
    for(int n : sizes) {
      std::vector<Point> p;
      if(family == "uniform") p = uniform<Point>(n, 1);
      else if(family == "clustered") p = clustered<Point>(n, 2);
      else if(family == "wheel") p = regular_wheel<Point>(n);
      else {
        CGAL::Random rng(unsigned(1000 + n));
        p = MDCS_test::random_wheel<Point>(n, rng);
      }
      MWT::Minimum_weight_triangulation_lp_2<Kernel> m(p);
      m.build_linear_program();
      const MWT::Sparse_linear_program& lp = m.linear_program();
      if(max_columns > 0 && lp.number_of_columns() > max_columns) {   // not solved: the family stops here
        table.add_row({family, std::to_string(n), std::to_string(lp.number_of_columns()), std::to_string(lp.number_of_rows),
                       std::to_string(lp.number_of_nonzeros()), "", "not run", "0", "", "", "", ""});
        std::fprintf(stderr, "%s n=%d: %zu columns > %zu, not run\n", family.c_str(), n, lp.number_of_columns(), max_columns);
        break;
      }
      std::vector<double> t;
      MWT::Linear_program_solution qp;
      for(int k = 0; k < repeats; ++k) {
        const double t0 = mdcs_bench::cpu_seconds();
        qp = MWT::QP_solver_linear_program_solver<>().solve(lp);
        t.push_back(mdcs_bench::cpu_seconds() - t0);
        if(t.back() >= 2) break;
      }
      std::vector<double> tg;
      MWT::Linear_program_solution glpk;
      for(int k = 0; k < 3; ++k) {
        const double t0 = mdcs_bench::cpu_seconds();
        glpk = MWT::GLPK_linear_program_solver(/*exact*/ true).solve(lp);
        tg.push_back(mdcs_bench::cpu_seconds() - t0);
      }
      const bool same = qp.status == MWT::Lp_status::optimal && glpk.status == MWT::Lp_status::optimal &&
                        std::abs(qp.objective - glpk.objective) <= 1e-12 * std::abs(glpk.objective);
      agree = agree && same;
      bool integral = true;
      for(double x : qp.primal) integral = integral && (std::abs(x) <= 1e-9 || std::abs(x - 1) <= 1e-9);
      table.add_row({family, std::to_string(n), std::to_string(lp.number_of_columns()), std::to_string(lp.number_of_rows),
                     std::to_string(lp.number_of_nonzeros()), std::to_string(qp.iterations),
                     mdcs_bench::fmt(mdcs_bench::median(t), "%.4f"), std::to_string(t.size()),
                     mdcs_bench::fmt(mdcs_bench::median(tg), "%.5f"), mdcs_bench::fmt(qp.objective, "%.12g"),
                     mdcs_bench::fmt(glpk.objective, "%.12g"), integral ? "yes" : "no"});
      std::fprintf(stderr, "%s n=%d: %zu columns, %zu rows, QP %.3f s (%s)\n", family.c_str(), n,
                   lp.number_of_columns(), lp.number_of_rows, mdcs_bench::median(t), same ? "same optimum as GLPK" : "DIFFERS");
      std::fflush(stderr);
      if(mdcs_bench::median(t) > stop_after) break;
    }
  }
  table.print();
  if(!table.write_csv(csv)) std::fprintf(stderr, "cannot write %s\n", csv.c_str());
  return agree;
}

} // namespace mwt_qp_scaling

#endif // MDCS_BENCH_MWT_QP_SCALING_H
