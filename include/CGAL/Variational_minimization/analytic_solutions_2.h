// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Analytic oracles for the minimal surface of rotation between two coaxial rings of radius R at x = -h and
// x = +h: the catenoids f(x) = c cosh(x / c) and the Goldschmidt (two discs) solution.

#ifndef CGAL_VARIATIONAL_MINIMIZATION_ANALYTIC_SOLUTIONS_2_H
#define CGAL_VARIATIONAL_MINIMIZATION_ANALYTIC_SOLUTIONS_2_H

#include <cfloat>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Variational_minimization {

/*!
  \defgroup PkgVariationalMinimizationOracles Analytic solutions (surface of rotation)

  The surface of rotation problem minimises \f$ 2\pi\int_{-h}^{h} |f|\sqrt{1+f'^2}\,dx \f$ with
  \f$ f(\pm h) = R \f$. Its smooth stationary curves are catenoids \f$ f(x) = c\cosh(x/c) \f$ with
  \f$ c\cosh(h/c) = R \f$. With \f$ t = h/c \f$ this reads \f$ \cosh(t)/t = R/h \f$; the left side has a
  single minimum at \f$ t^* \f$, the root of \f$ t\tanh t = 1 \f$ (\f$ t^* = 1.19967864025773\ldots \f$),
  so there are two catenoids when \f$ R > R_{min} = h\sinh t^* \approx 1.50887956 h \f$, one at equality
  and none below. The shallow one (larger c) is a local minimum, the deep one a saddle.
  The Goldschmidt solution (two discs joined by a segment of the axis, area \f$ 2\pi R^2 \f$) is not a
  function graph, but functions approach its area arbitrarily closely, so the infimum of the problem is the
  smaller of the shallow catenoid's area and \f$ 2\pi R^2 \f$. For h = 1 the two are equal at
  R = 1.8950254554... (`catenoid_goldschmidt_crossover_radius()`).

  Accuracy: the roots are found by bisection in `long double` until the bracket cannot shrink, so the
  residual \f$ c\cosh(h/c) - R \f$ is a few ulps of `R` and, away from \f$ R_{min} \f$, `c` is accurate to a
  few double ulps. Near \f$ R_{min} \f$ the problem itself is ill conditioned (\f$ dc \sim \sqrt{dR} \f$):
  the rounding of `R` to double (relative \f$ 10^{-16} \f$) alone moves `c` by up to about
  \f$ 10^{-8} \f$ relative there. Areas are evaluated in `long double`.
*/

/*!
  \ingroup PkgVariationalMinimizationOracles
  The catenoids spanning rings of radius `R` at `x = -h` and `x = h`.
*/
struct Catenoid_solutions
{
  /// `true` when \f$ R \ge R_{min}(h) \f$.
  bool exists = false;
  /// Parameter c of the shallow (stable, larger c) catenoid; NaN when none exists.
  double c_shallow = std::numeric_limits<double>::quiet_NaN();
  /// Parameter c of the deep (unstable, smaller c) catenoid; NaN when none exists.
  double c_deep = std::numeric_limits<double>::quiet_NaN();
};

namespace internal {

inline void check_catenoid_input(double value, const char* name)
{
  if(!(value > 0) || !std::isfinite(value))
    throw std::invalid_argument(std::string("MDCS: ") + name + " must be positive and finite");
}

// cosh(t) / t, the ring radius in units of h as a function of t = h / c.
inline long double catenoid_phi(long double t) { return std::cosh(t) / t; }

// Root of t tanh(t) = 1 by Newton's method from t = 1.2, which is within 4e-4 of the root, so a few steps
// reach long double precision. Cached: it depends on no input.
inline long double catenoid_t_star()
{
  static const long double t_star = [] {
    long double t = 1.2L;
    for(int i = 0; i < 50; ++i) {
      const long double th = std::tanh(t);
      const long double g = t * th - 1;
      const long double dg = th + t * (1 - th * th);
      const long double next = t - g / dg;
      if(next == t)
        break;
      t = next;
    }
    return t;
  }();
  return t_star;
}

// Bisection for phi(t) = rho on [lo, hi] where phi - rho changes sign; runs until the bracket cannot shrink.
inline long double catenoid_bisect(long double lo, long double hi, long double rho)
{
  const bool lo_above = catenoid_phi(lo) > rho;
  for(int i = 0; i < 20000; ++i) {
    const long double mid = lo + (hi - lo) / 2;
    if(mid <= lo || mid >= hi)
      break;
    if((catenoid_phi(mid) > rho) == lo_above)
      lo = mid;
    else
      hi = mid;
  }
  return lo + (hi - lo) / 2;
}

} // namespace internal

/*!
  \ingroup PkgVariationalMinimizationOracles
  The critical parameter \f$ c^* = h / t^* \f$ (about 0.8335565596 h) at which the two catenoid branches
  meet. \throws std::invalid_argument unless `h` is positive and finite.
*/
inline double catenoid_critical_parameter(double h = 1)
{
  internal::check_catenoid_input(h, "the half width h");
  return static_cast<double>(static_cast<long double>(h) / internal::catenoid_t_star());
}

/*!
  \ingroup PkgVariationalMinimizationOracles
  \f$ R_{min}(h) = h\sinh t^* \f$ (about 1.5088795615 h): the smallest ring radius spanned by a catenoid.
  (From \f$ t^*\tanh t^* = 1 \f$, \f$ \cosh(t^*)/t^* = \sinh t^* \f$.)
  \throws std::invalid_argument unless `h` is positive and finite.
*/
inline double catenoid_minimum_radius(double h = 1)
{
  internal::check_catenoid_input(h, "the half width h");
  return static_cast<double>(static_cast<long double>(h) * std::sinh(internal::catenoid_t_star()));
}

/*!
  \ingroup PkgVariationalMinimizationOracles
  Solves \f$ c\cosh(h/c) = R \f$ for both branches.
  A radius within 4 double ulps below \f$ R_{min} \f$ counts as \f$ R_{min} \f$ (both parameters are then
  \f$ c^* \f$), so that `catenoid_solutions(catenoid_minimum_radius(h), h)` exists despite rounding.
  \throws std::invalid_argument unless `R` and `h` are positive and finite.
*/
inline Catenoid_solutions catenoid_solutions(double R, double h = 1)
{
  internal::check_catenoid_input(R, "the ring radius R");
  internal::check_catenoid_input(h, "the half width h");
  Catenoid_solutions result;
  const long double t_star = internal::catenoid_t_star();
  const long double rho = static_cast<long double>(R) / static_cast<long double>(h);
  const long double rho_min = internal::catenoid_phi(t_star);
  // Tolerance for the rounding of R_min to double (see the documentation above).
  const long double rounding_slack = 4 * static_cast<long double>(DBL_EPSILON);
  if(rho < rho_min * (1 - rounding_slack))
    return result;
  result.exists = true;
  if(rho <= rho_min) {
    result.c_shallow = result.c_deep = static_cast<double>(static_cast<long double>(h) / t_star);
    return result;
  }
  // Shallow branch, t in (0, t*): phi decreases from +inf; phi(1/rho) = rho cosh(1/rho) >= rho brackets it.
  const long double t_lo = (1 / rho < t_star) ? 1 / rho : t_star;
  const long double t_shallow = internal::catenoid_bisect(t_lo, t_star, rho);
  // Deep branch, t > t*: phi increases to +inf; double the upper end until it exceeds rho
  // (phi(t) > e^t / (2t), so this ends within a few steps even for huge rho).
  long double t_hi = 2 * t_star;
  while(internal::catenoid_phi(t_hi) <= rho)
    t_hi *= 2;
  const long double t_deep = internal::catenoid_bisect(t_star, t_hi, rho);
  result.c_shallow = static_cast<double>(static_cast<long double>(h) / t_shallow);
  result.c_deep = static_cast<double>(static_cast<long double>(h) / t_deep);
  return result;
}

/*!
  \ingroup PkgVariationalMinimizationOracles
  The catenary \f$ c\cosh(x/c) \f$. \throws std::invalid_argument unless `c` is positive and finite.
*/
inline double catenoid_value(double c, double x)
{
  internal::check_catenoid_input(c, "the catenoid parameter c");
  return c * std::cosh(x / c);
}

/*!
  \ingroup PkgVariationalMinimizationOracles
  Area of the catenoid \f$ c\cosh(x/c) \f$, \f$ -h \le x \le h \f$:
  \f$ 2\pi\int_{-h}^{h} c\cosh^2(x/c)\,dx = \pi c\,(2h + c\sinh(2h/c)) \f$.
  \throws std::invalid_argument unless `c` and `h` are positive and finite.
*/
inline double catenoid_energy(double c, double h = 1)
{
  internal::check_catenoid_input(c, "the catenoid parameter c");
  internal::check_catenoid_input(h, "the half width h");
  const long double pi = 3.141592653589793238462643383279503L;
  const long double lc = c, lh = h;
  return static_cast<double>(pi * lc * (2 * lh + lc * std::sinh(2 * lh / lc)));
}

/*!
  \ingroup PkgVariationalMinimizationOracles
  Area \f$ 2\pi R^2 \f$ of the Goldschmidt solution (two discs of radius `R`).
  \throws std::invalid_argument unless `R` is positive and finite.
*/
inline double goldschmidt_energy(double R)
{
  internal::check_catenoid_input(R, "the ring radius R");
  return 6.283185307179586476925286766559 * R * R;
}

/*!
  \ingroup PkgVariationalMinimizationOracles
  Which configuration attains the infimum of the surface of rotation problem.
*/
struct Surface_of_rotation_minimum
{
  /// The winning configuration.
  enum class Branch { Catenoid, Goldschmidt };
  /// `Branch::Catenoid` when the shallow catenoid exists and its area is below \f$ 2\pi R^2 \f$.
  Branch branch = Branch::Goldschmidt;
  /// The infimum of the area.
  double energy = std::numeric_limits<double>::quiet_NaN();
  /// The catenoids (whether or not they win).
  Catenoid_solutions catenoids;
  /// Area of the shallow catenoid; NaN when no catenoid exists.
  double catenoid_energy = std::numeric_limits<double>::quiet_NaN();
  /// \f$ 2\pi R^2 \f$.
  double goldschmidt_energy = std::numeric_limits<double>::quiet_NaN();
};

/*!
  \ingroup PkgVariationalMinimizationOracles
  The global minimum of the surface of rotation between rings of radius `R` at `x = +-h`: the shallow
  catenoid if it exists and has the smaller area (the deep one never does), otherwise Goldschmidt.
  Ties go to the catenoid (the only one that is a function).
  \throws std::invalid_argument unless `R` and `h` are positive and finite.
*/
inline Surface_of_rotation_minimum global_minimum_surface_of_rotation(double R, double h = 1)
{
  Surface_of_rotation_minimum result;
  result.catenoids = catenoid_solutions(R, h);
  result.goldschmidt_energy = goldschmidt_energy(R);
  result.energy = result.goldschmidt_energy;
  result.branch = Surface_of_rotation_minimum::Branch::Goldschmidt;
  if(result.catenoids.exists) {
    const double shallow = catenoid_energy(result.catenoids.c_shallow, h);
    const double deep = catenoid_energy(result.catenoids.c_deep, h);
    result.catenoid_energy = shallow < deep ? shallow : deep;
    if(result.catenoid_energy <= result.goldschmidt_energy) {
      result.branch = Surface_of_rotation_minimum::Branch::Catenoid;
      result.energy = result.catenoid_energy;
    }
  }
  return result;
}

/*!
  \ingroup PkgVariationalMinimizationOracles
  The ring radius at which the shallow catenoid and the Goldschmidt solution have the same area
  (about 1.8950254554 h): the catenoid wins above it, Goldschmidt below. Found by bisection on R.
  \throws std::invalid_argument unless `h` is positive and finite.
*/
inline double catenoid_goldschmidt_crossover_radius(double h = 1)
{
  // Work for h = 1 and scale: both areas scale with h^2 at fixed R / h.
  internal::check_catenoid_input(h, "the half width h");
  // At R_min the catenoid (area ~ 18.3) costs more than 2 pi R_min^2 (~ 14.3); at R = 3 it costs less.
  double lo = catenoid_minimum_radius(1), hi = 3;
  for(int i = 0; i < 200; ++i) {
    const double mid = lo + (hi - lo) / 2;
    if(mid <= lo || mid >= hi)
      break;
    const double c = catenoid_solutions(mid, 1).c_shallow;
    if(catenoid_energy(c, 1) > goldschmidt_energy(mid))
      lo = mid;
    else
      hi = mid;
  }
  return h * (lo + (hi - lo) / 2);
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_ANALYTIC_SOLUTIONS_2_H
