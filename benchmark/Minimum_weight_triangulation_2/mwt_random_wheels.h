// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The random-wheel experiment of the thesis's Fig. 3.5 (ch. 3.5), the `--random-wheels` mode of bench_mwt: for
// every number k of points on the circle, `trials` random wheels (MDCS_test::random_wheel, seed fixed per k) and
// the fraction settled by the triangle LP alone (integral optimum) and by the LMT-skeleton alone (connected
// certain edges), with Wilson 95 % intervals; a CSV and an SVG plot of the two curves (Fig. 3.5b).
// Cross-check on every trial: when the LP is integral its weight equals that of the library's LMT pipeline.

#ifndef MDCS_BENCH_MWT_RANDOM_WHEELS_H
#define MDCS_BENCH_MWT_RANDOM_WHEELS_H

#include <CGAL/Variational_minimization/IO/write_curve_svg.h>
#include <MDCS_test/random_wheels.h>

#include "mdcs_bench.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace mwt_random_wheels {

namespace SVG = CGAL::Variational_minimization;

struct Row
{
  int k = 0;
  long trials = 0, redraws = 0, lp_integral = 0, lmt_connected = 0, lmt_not_lp = 0, lp_not_lmt = 0,
       pipeline_without_lp = 0, weight_mismatches = 0;
  double seconds = 0;
};

// The SVG of Fig. 3.5b: the fractions against k, the 95 % intervals dashed, grid lines every 0.1 and every 5 points.
inline void write_plot(const std::vector<Row>& rows, const std::string& path)
{
  SVG::Svg_curve_plot plot;
  plot.xmin = rows.front().k;
  plot.xmax = rows.back().k;
  plot.ymin = 0;
  plot.ymax = 1;
  plot.preserve_aspect_ratio = false;
  plot.width = 760;
  plot.height = 480;
  plot.legend_position = SVG::Svg_curve_plot::BOTTOM_LEFT;
  plot.title = "Random wheels (thesis Fig. 3.5b): settled without branch and bound";
  plot.x_label = "k (points on the circle)";
  plot.y_label = "fraction";
  for(int y = 1; y < 10; ++y) plot.grid_segments.push_back({plot.xmin, y / 10.0, plot.xmax, y / 10.0});
  for(int x = (rows.front().k + 4) / 5 * 5; x < rows.back().k; x += 5)
    plot.grid_segments.push_back({double(x), 0.0, double(x), 1.0});
  // each 95 % interval drawn as the outline of its band: the lower ends left to right, the upper ends back
  auto band = [&](long Row::*successes, const char* color, const char* label) {
    SVG::Svg_curve c;
    c.color = color;
    c.dashed = true;
    c.label = label;
    for(const Row& r : rows) c.points.push_back({double(r.k), MDCS_test::wilson_interval(r.*successes, r.trials).first});
    for(auto r = rows.rbegin(); r != rows.rend(); ++r)
      c.points.push_back({double(r->k), MDCS_test::wilson_interval((*r).*successes, r->trials).second});
    return c;
  };
  SVG::Svg_curve lmt;
  lmt.color = "#1b9e40";
  lmt.label = "LMT-skeleton connected";
  for(const Row& r : rows) {
    plot.solution.push_back({double(r.k), double(r.lp_integral) / double(r.trials)});
    lmt.points.push_back({double(r.k), double(r.lmt_connected) / double(r.trials)});
  }
  plot.solution_label = "LP optimum integral";
  plot.extra_curves = {band(&Row::lp_integral, "#1f3a93", "LP: 95% interval"),
                       band(&Row::lmt_connected, "#1b9e40", "LMT: 95% interval"), lmt};
  plot.caption_lines = {"k = " + std::to_string(rows.front().k) + ".." + std::to_string(rows.back().k) + ", " +
                          std::to_string(rows.front().trials) + " wheels per k; grid lines every 0.1 and every 5 points",
                        "centre + k points at uniform random angles on the unit circle (centre strictly inside the hull)"};
  SVG::write_curve_svg(path, plot);
}

/// Runs the experiment for k = k_min..k_max; writes `csv` and `svg` (when not empty). Returns false when a weight
/// differs between the LP and the LMT pipeline.
inline bool run(int k_min, int k_max, long trials, const std::string& csv, const std::string& svg)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 Point;
  std::vector<Row> rows;
  mdcs_bench::Table table({"k", "n", "trials", "redraws", "lp_integral", "lp_fraction", "lp_ci_low", "lp_ci_high",
                           "lmt_connected", "lmt_fraction", "lmt_ci_low", "lmt_ci_high", "lmt_not_lp", "lp_not_lmt",
                           "pipeline_without_lp", "weight_mismatches", "seconds"});
  for(int k = k_min; k <= k_max; ++k) {
    Row row;
    row.k = k;
    CGAL::Random rng(20260000u + unsigned(k));   // fixed seed per k: any k range reproduces the same rows
    const double t0 = mdcs_bench::cpu_seconds();
    for(long i = 0; i < trials; ++i) {
      const auto p = MDCS_test::random_wheel<Point>(k, rng, &row.redraws);
      const MDCS_test::Random_wheel_trial t = MDCS_test::random_wheel_trial(p, false);
      ++row.trials;
      row.lp_integral += t.lp_integral;
      row.lmt_connected += t.lmt_connected;
      row.lmt_not_lp += t.lmt_connected && !t.lp_integral;
      row.lp_not_lmt += t.lp_integral && !t.lmt_connected;
      row.pipeline_without_lp += t.pipeline_without_lp;
      if(t.lp_integral && !(std::abs(t.lp_weight - t.pipeline_weight) <= 1e-9 * t.pipeline_weight))
        ++row.weight_mismatches;
    }
    row.seconds = mdcs_bench::cpu_seconds() - t0;
    const auto lp_ci = MDCS_test::wilson_interval(row.lp_integral, row.trials);
    const auto lmt_ci = MDCS_test::wilson_interval(row.lmt_connected, row.trials);
    table.add_row({std::to_string(k), std::to_string(k + 1), std::to_string(row.trials), std::to_string(row.redraws),
                   std::to_string(row.lp_integral), mdcs_bench::fmt(double(row.lp_integral) / double(row.trials), "%.4f"),
                   mdcs_bench::fmt(lp_ci.first, "%.4f"), mdcs_bench::fmt(lp_ci.second, "%.4f"),
                   std::to_string(row.lmt_connected),
                   mdcs_bench::fmt(double(row.lmt_connected) / double(row.trials), "%.4f"),
                   mdcs_bench::fmt(lmt_ci.first, "%.4f"), mdcs_bench::fmt(lmt_ci.second, "%.4f"),
                   std::to_string(row.lmt_not_lp), std::to_string(row.lp_not_lmt),
                   std::to_string(row.pipeline_without_lp), std::to_string(row.weight_mismatches),
                   mdcs_bench::fmt(row.seconds, "%.2f")});
    std::fprintf(stderr, "k=%d: LP %ld/%ld, LMT %ld/%ld, %.1f s\n", k, row.lp_integral, row.trials, row.lmt_connected,
                 row.trials, row.seconds);
    rows.push_back(row);
  }
  table.print();
  if(!table.write_csv(csv)) std::fprintf(stderr, "cannot write %s\n", csv.c_str());
  if(!svg.empty() && rows.size() >= 2) write_plot(rows, svg);
  bool same = true;
  for(const Row& r : rows) same = same && r.weight_mismatches == 0;
  if(!same) std::fprintf(stderr, "an integral LP weight differs from the LMT pipeline's\n");
  return same;
}

} // namespace mwt_random_wheels

#endif // MDCS_BENCH_MWT_RANDOM_WHEELS_H
