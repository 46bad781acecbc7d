// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The weight of one arrangement edge: the integral of G(f, f', x) along a straight segment.

#ifndef CGAL_VARIATIONAL_MINIMIZATION_EDGE_WEIGHT_2_H
#define CGAL_VARIATIONAL_MINIMIZATION_EDGE_WEIGHT_2_H

#include <CGAL/Variational_minimization/curve_functionals_2.h>

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <array>
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
  Only panels whose error estimate is too large are bisected, so a kink (such as `|f|` crossing zero) costs
  about 30 evaluations per level (about 470 in all at the default tolerance), while a pathological integrand
  that never converges costs at most about 15 * 2^15 evaluations instead of running away.
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

// Integrand x -> G(y(x), k, x) along a segment, validating every value on the fly: one comparison rejects
// both NaN and negative values (-0.0 passes); +infinity is returned as is and handled by the integrator.
template <class Functional>
struct Checked_segment_integrand
{
  const Functional& g;
  double x0, y0, dx, dy, slope;

  double operator()(double x) const
  {
    const double t = (x - x0) / dx;
    const double f = y0 + t * dy;
    const double v = static_cast<double>(g(f, slope, x));
    if(!(v >= 0))
      throw_bad_functional_value(f, slope, x, v);
    return v;
  }
};

// The 15-point Gauss-Kronrod rule on [-1, 1] (Boost.Math's abscissae and weights), its embedded 7-point
// Gauss rule, and barycentric weights of the degree-14 interpolant through the 15 nodes, used to extrapolate
// to the panel ends.
struct Gauss_kronrod_15
{
  static constexpr int n = 15;
  std::array<double, n> x;        // ascending nodes; x[7] = 0
  std::array<double, n> kronrod;  // weights
  std::array<double, n> gauss;    // 0 on Kronrod-only nodes
  std::array<double, n> bary;     // barycentric weights
  double outer_gap;               // 1 - largest node: the width (in units of h) a panel's nodes never see

  static const Gauss_kronrod_15& get()
  {
    static const Gauss_kronrod_15 rule;
    return rule;
  }

private:
  Gauss_kronrod_15()
  {
    using GK = boost::math::quadrature::gauss_kronrod<double, 15>;
    using GL = boost::math::quadrature::gauss<double, 7>;
    // Boost lists the non-negative abscissae from 0 upwards; even indices are the Gauss nodes.
    for(int i = 0; i < 8; ++i) {
      x[7 + i] = GK::abscissa()[i];
      x[7 - i] = -GK::abscissa()[i];
      kronrod[7 + i] = kronrod[7 - i] = GK::weights()[i];
      gauss[7 + i] = gauss[7 - i] = (i % 2 == 0) ? GL::weights()[i / 2] : 0.;
    }
    for(int j = 0; j < n; ++j) {
      double p = 1;
      for(int k = 0; k < n; ++k)
        if(k != j)
          p *= x[j] - x[k];
      bary[j] = 1 / p;
    }
    outer_gap = 1 - x[n - 1];
  }
};

// Value at t (outside the nodes) of the polynomial interpolating v at the rule's nodes.
inline double extrapolate_gk15(const Gauss_kronrod_15& rule, const std::array<double, 15>& v, double t)
{
  double num = 0, den = 0;
  for(int j = 0; j < Gauss_kronrod_15::n; ++j) {
    const double c = rule.bary[j] / (t - rule.x[j]);
    num += c * v[j];
    den += c;
  }
  return num / den;
}

// Adaptive Gauss-Kronrod on [a, b], where fa = f(a) and fb = f(b) are already known.
//
// Why not boost::math::quadrature::gauss_kronrod<double, 15>::integrate (whose rule is used here):
// - Gauss-Kronrod nodes never come closer to a panel end than 0.43% of its width, so a kink there
//   (|f| crossing zero, say, near a bisection point) is invisible to the |K15 - G7| error estimate. On
//   random segments crossing f = 0, about 3% of Boost's results for 2 pi |f| sqrt(1 + k^2) were off by up to
//   1e-5 relative. Here each panel also compares f at its ends (free: they are the parent's end and centre
//   node) with the extrapolated node interpolant, and the mismatch times the unseen width joins the error.
// - Boost 1.74 compares the unscaled [-1, 1] error with tolerances scaled to the sub-interval, so it
//   over-refines short panels and under-refines long ones.
// Returns +infinity as soon as f is +infinity at a node.
template <class F>
double adaptive_gk15(const F& f, double a, double b, double fa, double fb, double relative_tolerance,
                     double absolute_tolerance, unsigned depth_left)
{
  const Gauss_kronrod_15& rule = Gauss_kronrod_15::get();
  const double infinity = std::numeric_limits<double>::infinity();
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  std::array<double, Gauss_kronrod_15::n> v;
  double k15 = 0, g7 = 0;
  for(int j = 0; j < Gauss_kronrod_15::n; ++j) {
    v[j] = f(j == 7 ? c : c + h * rule.x[j]);
    if(v[j] == infinity)
      return infinity;
    k15 += rule.kronrod[j] * v[j];
    g7 += rule.gauss[j] * v[j];
  }
  k15 *= h;
  g7 *= h;
  double error = std::fabs(k15 - g7);
  const double unseen = 0.5 * rule.outer_gap * h;
  if(fa != infinity)
    error += unseen * std::fabs(fa - extrapolate_gk15(rule, v, -1));
  if(fb != infinity)
    error += unseen * std::fabs(fb - extrapolate_gk15(rule, v, 1));
  if(absolute_tolerance == 0)
    absolute_tolerance = relative_tolerance * k15; // top level: k15 estimates int |f| since f >= 0
  // Same acceptance as Boost: the panel is good if its error is small compared with the whole integral's
  // share (halved at each level) or with its own value.
  // Also accept errors at the level of rounding noise (a requested tolerance below it would otherwise bisect
  // smooth integrands down to max_depth).
  const double noise = 64 * std::numeric_limits<double>::epsilon() * k15;
  if(depth_left == 0 || error <= absolute_tolerance || error <= relative_tolerance * k15 || error <= noise ||
     !(c > a && c < b))
    return k15;
  const double left =
    adaptive_gk15(f, a, c, fa, v[7], relative_tolerance, 0.5 * absolute_tolerance, depth_left - 1);
  if(left == infinity)
    return infinity;
  return left + adaptive_gk15(f, c, b, v[7], fb, relative_tolerance, 0.5 * absolute_tolerance, depth_left - 1);
}

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
    the integral is computed by adaptive 15-point Gauss–Kronrod quadrature (the rule of
    `boost::math::quadrature::gauss_kronrod<double, 15>`) with at most `max_depth` bisections, aiming at a
    relative error `relative_tolerance`. Each panel's error estimate is |K15 - G7| plus a check of `G` at the
    panel's ends against the extrapolated node interpolant, so kinks near panel ends (which Gauss–Kronrod
    nodes never see) are refined too. The estimate is heuristic: on segments of `2 pi |f| sqrt(1 + k^2)`
    crossing `f = 0` the observed relative error stayed below `0.3 * relative_tolerance` for the default
    1e-10 and for 1e-8, but up to about 40 times `relative_tolerance` for coarse tolerances (1e-4, 1e-6), where
    an unrefined panel's |K15 - G7| underestimates a kink; below about 1e-11 the depth limit can bind for
    kinks. For smooth `G` the result is typically accurate to a few ulps. `G` is evaluated at both end
    points too.
  - The end points may be given in either order; the weight does not depend on the orientation.
  - A vertical segment (`slope` is `+-infinity`) of positive length gets `+infinity`: a function graph
    cannot use it. A segment with `x0 == x1` and finite `slope` has zero extent in x and gets 0, as does
    a segment of zero length.
  - `+infinity` values of `G` are allowed: if `G` is `+infinity` at a quadrature node (or the closed form
    returns `+infinity`), the weight is `+infinity`. An infinite value at an end point alone is ignored
    (it may be an integrable singularity, or the boundary of a forbidden region that the edge only touches).

  \tparam Functional a model of `CurveFunctional_2`.
  \param G the integrand.
  \param x0,y0,x1,y1 the segment's end points.
  \param slope the exact slope of the segment's line (`+-infinity` for a vertical line).
  \param relative_tolerance target relative accuracy of the quadrature (unused by closed forms).
  \param max_depth maximal bisection depth of the quadrature.
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
    const internal::Checked_segment_integrand<Functional> integrand{G, x0, y0, x1 - x0, y1 - y0, slope};
    w = internal::adaptive_gk15(integrand, x0, x1, integrand(x0), integrand(x1), relative_tolerance, 0.,
                                max_depth);
  }
  if(!(w >= 0))
    internal::throw_bad_edge_weight(x0, y0, x1, y1, slope, w);
  return w;
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_EDGE_WEIGHT_2_H
