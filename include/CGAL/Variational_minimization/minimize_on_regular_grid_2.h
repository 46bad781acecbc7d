// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The univariate problem on the regular grid C_n of the thesis (ch. 2.5.2), solved by dynamic programming.

#ifndef CGAL_VARIATIONAL_MINIMIZATION_MINIMIZE_ON_REGULAR_GRID_2_H
#define CGAL_VARIATIONAL_MINIMIZATION_MINIMIZE_ON_REGULAR_GRID_2_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Variational_minimization/Curve_problem_2.h>
#include <CGAL/Variational_minimization/Minimal_curve_2.h>
#include <CGAL/Variational_minimization/edge_weight_2.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/*!
  \brief Minimises the functional over the functions of the regular grid C_n (thesis ch. 2.5.2).

  C_n has n + 1 columns x_i = a + i (b - a) / n and n² + 1 rows y_j = ymin + j (ymax - ymin) / n², and an edge
  between every pair of vertices in adjacent columns (about n⁵ edges, so cost grows as n⁵: n = 20 evaluates
  3.2 million edge weights). C_n is not planar — its edges cross without vertices — so the dual min-cut does not
  apply; the exact discrete optimum is found by dynamic programming over the columns (a directed shortest
  path). The planar version C_n^pl is the arrangement of the lines through those edges
  (`regular_grid_lines_2()`), solved by `minimize_curve_functional_2()`.

  \pre 1 <= n <= 64 (C_n has about n^5 edges); each fixed end value lies on a grid row (within 1e-9 of the range); otherwise
  `std::invalid_argument` is thrown. A relaxed end admits every row inside its range.
*/
template <class Functional, class Progress = CGAL::MDCS::No_progress>
Minimal_curve_2 minimize_on_regular_grid_2(const Curve_problem_2& problem, const Functional& G, std::size_t n,
                                           Progress progress = Progress())
{
  problem.validate();
  if(n == 0)
    throw std::invalid_argument("MDCS: the regular grid C_n needs n >= 1");
  if(n > 64)   // n = 24: 8 * 10^6 edges (the manual's table); n = 1000 was accepted before and ran for ever
    throw std::invalid_argument("MDCS: the regular grid C_n with n = " + std::to_string(n) +
                                " would have about n^5 edges (more than 10^9); n must be at most 64: use a line "
                                "arrangement instead");
  const std::size_t rows = n * n + 1;
  const double x0 = problem.box.xmin(), y0 = problem.box.ymin();
  const double dx = (problem.box.xmax() - x0) / double(n);
  const double range = problem.box.ymax() - y0;
  const double dy = range / double(n * n);
  auto x_of = [&](std::size_t i) { return i == n ? problem.box.xmax() : x0 + double(i) * dx; };
  auto y_of = [&](std::size_t j) { return j == rows - 1 ? problem.box.ymax() : y0 + double(j) * dy; };

  // Rows admitted by an end condition.
  const double tolerance = 1e-9 * range;
  auto admitted = [&](const End_condition& end, const char* name) {
    std::vector<char> ok(rows, 0);
    bool any = false;
    for(std::size_t j = 0; j < rows; ++j)
      if(y_of(j) >= end.low - tolerance && y_of(j) <= end.high + tolerance) ok[j] = 1, any = true;
    if(!any)
      throw std::invalid_argument(std::string("MDCS: the ") + name + " end value " + std::to_string(end.low) +
                                  " is not a row of C_" + std::to_string(n) +
                                  "; choose the box so that the end values are grid rows");
    return ok;
  };
  const std::vector<char> sources = admitted(problem.left, "left");
  const std::vector<char> targets = admitted(problem.right, "right");

  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> current(rows, inf), next(rows);
  std::vector<std::uint32_t> predecessor(n * rows); // row in column i of the best edge into (i + 1, k)
  for(std::size_t j = 0; j < rows; ++j)
    if(sources[j]) current[j] = 0;

  CGAL::MDCS::internal::Progress_reporter<Progress> report(progress, "regular-grid", n);
  for(std::size_t i = 0; i < n; ++i) {
    report(i);
    const double xa = x_of(i), xb = x_of(i + 1);
    for(std::size_t k = 0; k < rows; ++k) {
      double best = inf;
      std::uint32_t arg = 0;
      const double yb = y_of(k);
      for(std::size_t j = 0; j < rows; ++j) {
        if(current[j] == inf) continue;
        const double ya = y_of(j);
        const double d = current[j] + edge_weight_2(G, xa, ya, xb, yb, (yb - ya) / (xb - xa));
        if(d < best) best = d, arg = std::uint32_t(j);
      }
      next[k] = best;
      predecessor[i * rows + k] = arg;
    }
    current.swap(next);
  }
  report.finish();

  Minimal_curve_2 curve;
  std::size_t best_row = rows;
  for(std::size_t k = 0; k < rows; ++k)
    if(targets[k] && current[k] < inf && (best_row == rows || current[k] < current[best_row])) best_row = k;
  if(best_row == rows) return curve;

  curve.is_feasible = true;
  curve.solver_value = curve.energy = current[best_row];
  curve.polyline.resize(n + 1);
  std::size_t row = best_row;
  for(std::size_t i = n; ; --i) {
    curve.polyline[i] = Minimal_curve_2::Point_2(x_of(i), y_of(row));
    if(i == 0) break;
    row = predecessor[(i - 1) * rows + row];
  }
  return curve;
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_MINIMIZE_ON_REGULAR_GRID_2_H
