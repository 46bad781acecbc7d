// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Integrands G(f, f', x) of univariate variational problems  F(f) = int_a^b G(f, f', x) dx,
// the CurveFunctional_2 concept they model, and the detection of an optional closed-form edge weight.

#ifndef CGAL_VARIATIONAL_MINIMIZATION_CURVE_FUNCTIONALS_2_H
#define CGAL_VARIATIONAL_MINIMIZATION_CURVE_FUNCTIONALS_2_H

#include <cmath>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Variational_minimization {

/*!
  \defgroup PkgVariationalMinimizationFunctionals Curve functionals

  \section CurveFunctional_2_concept Concept CurveFunctional_2

  A model of `CurveFunctional_2` describes the integrand `G` of a univariate variational problem
  \f$ F(f) = \int_a^b G(f(x), f'(x), x)\, dx \f$.

  Requirements on a type `F` with a `const F& g`:
  - `F` is copy constructible (algorithms store copies; a model should therefore be cheap to copy, e.g. hold
    its data by value or through a shared pointer);
  - `double v = g(f, fp, x);` with `double f, fp, x` returns \f$ G(f, f', x) \f$. The value must be `>= 0` and
    not NaN wherever it is evaluated; `+infinity` is allowed and marks forbidden positions or slopes
    (an edge that sees it gets an infinite weight and is never used).

  Optional:
  - `double w = g.edge_weight(x0, y0, x1, y1, slope);` returns the exact integral
    \f$ \int_{x_0}^{x_1} G(y(x), k, x)\, dx \f$ along the segment from `(x0, y0)` to `(x1, y1)`, where
    `x0 < x1` and `k = slope` is finite. The slope is passed separately because the end points may be rounded
    approximations of exact arrangement vertices: a model must use `slope` for \f$ f' \f$ and the end
    points (linear interpolation between them) for the positions. `edge_weight_2()` uses this member when
    it exists (detected by `has_closed_form_edge_weight`) and adaptive quadrature otherwise.

  \cgalHasModel `Surface_of_rotation_functional`, `Arc_length_functional`,
  `Density_weighted_length_functional`, `Callable_functional`.
*/

/*!
  \ingroup PkgVariationalMinimizationFunctionals
  Detects whether `F` has the optional member
  `double edge_weight(double x0, double y0, double x1, double y1, double slope) const`
  of the `CurveFunctional_2` concept. `value` is `true` exactly when that call on a `const F&` is valid and
  its result converts to `double`.
*/
template <class F, class = void>
struct has_closed_form_edge_weight : std::false_type
{};

#ifndef DOXYGEN_RUNNING
template <class F>
struct has_closed_form_edge_weight<
  F,
  std::void_t<decltype(std::declval<const F&>().edge_weight(0., 0., 0., 0., 0.))> >
  : std::is_convertible<decltype(std::declval<const F&>().edge_weight(0., 0., 0., 0., 0.)), double>
{};
#endif

/// `has_closed_form_edge_weight<F>::%value`.
template <class F>
constexpr bool has_closed_form_edge_weight_v = has_closed_form_edge_weight<F>::value;

namespace internal {

// 2*pi; std::numbers::pi is C++20 only.
constexpr double two_pi = 6.283185307179586476925286766559;

// sqrt(1 + k^2) without overflow for the huge slopes of nearly vertical arrangement lines.
inline double arc_factor(double k) { return std::hypot(1.0, k); }

// Exact integral of |y| over [0, dx] for y linear from y0 to y1.
// When the sign changes the two triangles on either side of the zero crossing contribute
// dx * y0^2 / (2(|y0|+|y1|)) and dx * y1^2 / (2(|y0|+|y1|)); computing it this way avoids locating the
// crossing explicitly (and the cancellation in (0.5 k x^2 + b x) evaluated at the ends, thesis eq. 2.3.6).
inline double integral_of_abs_linear(double dx, double y0, double y1)
{
  const double a0 = std::fabs(y0), a1 = std::fabs(y1);
  if((y0 >= 0 && y1 >= 0) || (y0 <= 0 && y1 <= 0))
    return 0.5 * dx * (a0 + a1);
  return 0.5 * dx * (y0 * y0 + y1 * y1) / (a0 + a1);
}

} // namespace internal

/*!
  \ingroup PkgVariationalMinimizationFunctionals
  The minimal surface of rotation (catenoid problem): \f$ G = 2\pi |f| \sqrt{1 + f'^2} \f$, the area of the
  surface swept by the graph of `f` rotating about the x axis.

  Closed-form edge weight (thesis eq. 2.3.5-2.3.6): \f$ 2\pi\sqrt{1+k^2}\int_{x_0}^{x_1} |y(x)|\,dx \f$,
  split where the segment crosses `f = 0`.

  \cgalModels `CurveFunctional_2`
*/
struct Surface_of_rotation_functional
{
  /// \f$ 2\pi |f| \sqrt{1 + f'^2} \f$.
  double operator()(double f, double fp, double /*x*/) const
  {
    return internal::two_pi * std::fabs(f) * internal::arc_factor(fp);
  }

  /// Exact integral along the segment; see the `CurveFunctional_2` concept.
  double edge_weight(double x0, double y0, double x1, double y1, double slope) const
  {
    return internal::two_pi * internal::arc_factor(slope) *
           internal::integral_of_abs_linear(x1 - x0, y0, y1);
  }
};

/*!
  \ingroup PkgVariationalMinimizationFunctionals
  Arc length: \f$ G = \sqrt{1 + f'^2} \f$; the minimiser is the straight line.
  The closed-form edge weight is the segment length \f$ (x_1 - x_0)\sqrt{1+k^2} \f$.

  \cgalModels `CurveFunctional_2`
*/
struct Arc_length_functional
{
  /// \f$ \sqrt{1 + f'^2} \f$.
  double operator()(double /*f*/, double fp, double /*x*/) const { return internal::arc_factor(fp); }

  /// Length of the segment, with the slope taken from `slope` (see the `CurveFunctional_2` concept).
  double edge_weight(double x0, double /*y0*/, double x1, double /*y1*/, double slope) const
  {
    return (x1 - x0) * internal::arc_factor(slope);
  }
};

/*!
  \ingroup PkgVariationalMinimizationFunctionals
  Length weighted by a density: \f$ G = \rho(x, f)\sqrt{1 + f'^2} \f$ (a geodesic in a conformally flat
  metric, e.g. light in a medium with refractive index \f$\rho\f$). No closed form: edge weights use
  quadrature.

  \tparam Density a copyable callable `double(double x, double f)` returning \f$\rho \ge 0\f$
  (note the argument order `(x, f)`). A negative or NaN density is reported by `edge_weight_2()`.

  \cgalModels `CurveFunctional_2`
*/
template <class Density>
class Density_weighted_length_functional
{
public:
  /// Stores a copy of `rho`.
  explicit Density_weighted_length_functional(Density rho = Density()) : rho_(std::move(rho)) {}

  /// \f$ \rho(x, f)\sqrt{1 + f'^2} \f$.
  double operator()(double f, double fp, double x) const
  {
    return static_cast<double>(rho_(x, f)) * internal::arc_factor(fp);
  }

  /// The density.
  const Density& density() const { return rho_; }

private:
  Density rho_;
};

/// Deduces the density type of a `Density_weighted_length_functional`.
template <class Density>
Density_weighted_length_functional<Density> make_density_weighted_length_functional(Density rho)
{
  return Density_weighted_length_functional<Density>(std::move(rho));
}

/*!
  \ingroup PkgVariationalMinimizationFunctionals
  Adapts any callable `double(double f, double fp, double x)` to the `CurveFunctional_2` concept.
  The adaptor never provides a closed-form edge weight, even if the wrapped object has one, so it can also be
  used to force quadrature (e.g. to test a closed form).

  \cgalModels `CurveFunctional_2`
*/
template <class G>
class Callable_functional
{
public:
  /// Stores a copy of `g`.
  explicit Callable_functional(G g = G()) : g_(std::move(g)) {}

  /// `g(f, fp, x)` converted to `double`.
  double operator()(double f, double fp, double x) const { return static_cast<double>(g_(f, fp, x)); }

  /// The wrapped callable.
  const G& callable() const { return g_; }

private:
  G g_;
};

/// Wraps `g` in a `Callable_functional`, deducing its type (handy for lambdas).
template <class G>
Callable_functional<G> make_callable_functional(G g)
{
  return Callable_functional<G>(std::move(g));
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_CURVE_FUNCTIONALS_2_H
