// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The result of a univariate solve.

#ifndef CGAL_VARIATIONAL_MINIMIZATION_MINIMAL_CURVE_2_H
#define CGAL_VARIATIONAL_MINIMIZATION_MINIMAL_CURVE_2_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/*!
  \brief The globally minimal discrete curve found on a grid.

  When no discrete function satisfies the end conditions on the given grid (for example no line of an
  arrangement passes through a fixed end point), `is_feasible` is `false`, `energy` is +infinity and
  the polyline is empty: never a partial or arbitrary curve.
*/
struct Minimal_curve_2
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 Point_2;

  bool is_feasible = false;
  /// Sum of the weights of the curve's edges (the discrete energy); +infinity when infeasible.
  double energy = std::numeric_limits<double>::infinity();
  /// The value the solver optimised: the min-cut value for the cut solver, the path length for the
  /// shortest-path solver. Equal to `energy` up to rounding (the duality theorem, checked by the tests).
  double solver_value = std::numeric_limits<double>::infinity();
  /// The curve's vertices from left to right (rounded to doubles).
  std::vector<Point_2> polyline;
  /// The arrangement edges of the curve from left to right (empty for solvers without an arrangement).
  std::vector<std::uint32_t> edges;
};

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_MINIMAL_CURVE_2_H
