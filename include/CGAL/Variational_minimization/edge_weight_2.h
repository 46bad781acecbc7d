// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The weight of one arrangement edge: the integral of G(f, f', x) along a straight segment.

#ifndef CGAL_VARIATIONAL_MINIMIZATION_EDGE_WEIGHT_2_H
#define CGAL_VARIATIONAL_MINIMIZATION_EDGE_WEIGHT_2_H

#include <CGAL/Variational_minimization/curve_functionals_2.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace CGAL {
namespace Variational_minimization {

/*!
  \ingroup PkgVariationalMinimizationFunctionals
  Default maximal bisection depth of the adaptive Gauss–Kronrod quadrature in `edge_weight_2()`.
  Boost only bisects sub-intervals whose error estimate is too large, so a kink (such as `|f|` crossing
  zero) costs about 30 evaluations per level, while a pathological integrand that never converges costs at
  most about 15 * 2^15 evaluations instead of running away.
*/
constexpr unsigned edge_weight_default_max_depth = 15;

namespace internal {

[[noreturn]] inline void throw_bad_functional_value(double f, double fp, double x, double value)
{
  std::ostringstream os;
  os.precision(17);
  os << "MDCS: the functional G must be >= 0 and finite; G(f=" << f << ", f'=" << fp << ", x=" << x
     << ") = " << value;
  throw std::domain_error(os.str());
}

[[noreturn]] inline void throw_bad_edge_weight(double x0, double y0, double x1, double y1, double slope,
                                               double value)
{
  std::ostringstream os;
  os.precision(17);
  os << "MDCS: the functional G must be >= 0 and finite; its edge weight from (x=" << x0 << ", f=" << y0
     << ") to (x=" << x1 << ", f=" << y1 << ") with f'=" << slope << " is " << value;
  throw std::domain_error(os.str());
}

// Integrand x -> G(y(x), k, x) along a segment, validating every value on the fly.
// A +infinity value is not fed to the quadrature (Kronrod error estimates would turn it into NaN);
// it is recorded and the caller returns +infinity.
template <class Functional>
struct Checked_segment_integrand
{
  const Functional& g;
  double x0, y0, dx, dy, slope;
  bool* saw_infinity;

  double operator()(double x) const
  {
    const double t = (x - x0) / dx;
    const double f = y0 + t * dy;
    const double v = static_cast<double>(g(f, slope, x));
    // One comparison rejects both NaN and negative values; -0.0 passes.
    if(!(v >= 0))
      throw_bad_functional_value(f, slope, x, v);
    if(v == std::numeric_limits<double>::infinity()) {
      *saw_infinity = true;
      return 0;
    }
    return v;
  }
};

} // namespace internal

/*!
  \ingroup PkgVariationalMinimizationFunctionals
  The slope of the line through `(x0, y0)` and `(x1, y1)`: `+infinity` (or `-infinity`) when `x0 == x1` and
  the points differ, 0 for coincident points. Convenience for callers that have no exact slope at hand.
*/
inline double segment_slope_2(double x0, double y0, double x1, double y1)
{
  if(x0 == x1) {
    if(y0 == y1)
      return 0;
    return y1 > y0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
  }
  return (y1 - y0) / (x1 - x0);
}

/*!
  \ingroup PkgVariationalMinimizationFunctionals
  The weight \f$ w = \int_{x_0}^{x_1} G(y(x), k, x)\, dx \f$ of the straight segment from `(x0, y0)` to
  `(x1, y1)` lying on a line of slope `k = slope`; `y(x)` interpolates the end points linearly.

  - If `G` has the optional closed form (`has_closed_form_edge_weight<Functional>`), it is used; otherwise
    the integral is computed by adaptive Gauss–Kronrod (15 points) quadrature,
    `boost::math::quadrature::gauss_kronrod<double, 15>`, to the relative tolerance `relative_tolerance`
    with at most `max_depth` bisections (the result is the best estimate found if the tolerance cannot be
    met within that depth).
  - The end points may be given in either order; the weight does not depend on the orientation.
  - A vertical segment (`slope` is `+-infinity`) of positive length gets `+infinity`: a function graph
    cannot use it. A segment with `x0 == x1` and finite `slope` has zero extent in x and gets 0, as does
    a segment of zero length.
  - `+infinity` values of `G` are allowed: if `G` is `+infinity` at an evaluation point (or the closed form
    returns `+infinity`), the weight is `+infinity`.

  \tparam Functional a model of `CurveFunctional_2`.
  \pre all coordinates are finite, `slope` is not NaN, `relative_tolerance > 0`.
  \throws std::invalid_argument on a violated precondition.
  \throws std::domain_error if `G` returns a negative value or NaN at an evaluation point, or the resulting
          weight is negative or NaN. The message names the offending point `(f, f', x)`. Quadrature only
          sees its nodes, so a negative dip of `G` strictly between nodes can go unnoticed.
  \warning The result is a floating-point approximation (closed forms round too).
*/
template <class Functional>
double edge_weight_2(const Functional& G, double x0, double y0, double x1, double y1, double slope,
                     double relative_tolerance = 1e-10,
                     unsigned max_depth = edge_weight_default_max_depth)
{
  if(!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1))
    throw std::invalid_argument("MDCS: edge_weight_2: segment end points must be finite");
  if(std::isnan(slope))
    throw std::invalid_argument("MDCS: edge_weight_2: the slope must not be NaN");
  if(!(relative_tolerance > 0) || !std::isfinite(relative_tolerance))
    throw std::invalid_argument("MDCS: edge_weight_2: relative_tolerance must be positive and finite");

  const double infinity = std::numeric_limits<double>::infinity();
  if(x0 > x1) {
    std::swap(x0, x1);
    std::swap(y0, y1);
  }
  if(std::isinf(slope))
    return (x0 == x1 && y0 == y1) ? 0. : infinity;
  if(x0 == x1)
    return 0.;

  double w;
  if constexpr(has_closed_form_edge_weight<Functional>::value) {
    w = static_cast<double>(G.edge_weight(x0, y0, x1, y1, slope));
  } else {
    bool saw_infinity = false;
    const internal::Checked_segment_integrand<Functional> integrand{G, x0, y0, x1 - x0, y1 - y0, slope,
                                                                    &saw_infinity};
    w = boost::math::quadrature::gauss_kronrod<double, 15>::integrate(integrand, x0, x1, max_depth,
                                                                       relative_tolerance);
    if(saw_infinity)
      return infinity;
  }
  if(!(w >= 0))
    internal::throw_bad_edge_weight(x0, y0, x1, y1, slope, w);
  return w;
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_EDGE_WEIGHT_2_H
