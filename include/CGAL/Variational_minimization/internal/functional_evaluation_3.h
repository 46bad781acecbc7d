// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Evaluation of a user functional G(f, fx, fy, x, y): the checked value (finite and >= 0, else a clear error)
// and its partial derivatives in (f, fx, fy) by central differences. Shared by the facet weights, the grid
// relaxation and the polygon-mesh relaxation, so that all of them reject bad G the same way.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_FUNCTIONAL_EVALUATION_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_FUNCTIONAL_EVALUATION_3_H

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

template <class Functional>
double checked_value(const Functional& G, double f, double fx, double fy, double x, double y)
{
  const double v = G(f, fx, fy, x, y);
  if(!(v >= 0) || !std::isfinite(v)) {
    std::ostringstream s;
    s << "MDCS: the functional G must be finite and >= 0, but G(f = " << f << ", fx = " << fx << ", fy = " << fy
      << ", x = " << x << ", y = " << y << ") = " << v;
    throw std::invalid_argument(s.str());
  }
  return v;
}

// d[0], d[1], d[2]: the partial derivatives of G in f, fx and fy at (f, fx, fy, x, y), by central differences
// with the step 1e-6 (1 + |argument|).
template <class Functional>
void functional_partials(const Functional& G, double f, double fx, double fy, double x, double y, double d[3])
{
  const double base[3] = {f, fx, fy};
  for(int which = 0; which < 3; ++which) {
    const double h = 1e-6 * (1 + std::abs(base[which]));
    double p[3] = {f, fx, fy}, m[3] = {f, fx, fy};
    p[which] += h;
    m[which] -= h;
    d[which] = (G(p[0], p[1], p[2], x, y) - G(m[0], m[1], m[2], x, y)) / (2 * h);
  }
}

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_FUNCTIONAL_EVALUATION_3_H
