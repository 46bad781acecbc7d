// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A local optimiser for the discretised functional over piecewise-linear functions on a uniform grid.
// It is the baseline a user would try first: it finds the nearest local minimum, which is why a global
// method is needed (e.g. it stays on the catenoid when the Goldschmidt solution is cheaper).

#ifndef CGAL_VARIATIONAL_MINIMIZATION_LOCAL_DESCENT_2_H
#define CGAL_VARIATIONAL_MINIMIZATION_LOCAL_DESCENT_2_H

#include <CGAL/Variational_minimization/curve_functionals_2.h>
#include <CGAL/Variational_minimization/edge_weight_2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <deque>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/*!
  \defgroup PkgVariationalMinimizationLocalDescent Local descent
*/

/*!
  \ingroup PkgVariationalMinimizationLocalDescent
  Why `local_descent_2()` stopped.
*/
enum class Local_descent_stop
{
  Gradient_small,     ///< the scaled projected gradient fell below `gradient_tolerance` (converged)
  Energy_stalled,     ///< the relative energy change stayed below `energy_tolerance` (converged)
  Line_search_failed, ///< no decrease even along the steepest descent direction (numerical noise floor)
  Max_iterations,     ///< `max_iterations` reached
  Infinite_energy     ///< the initial curve has infinite energy; nothing was done
};

/*!
  \ingroup PkgVariationalMinimizationLocalDescent
  Options of `local_descent_2()`.
*/
struct Local_descent_options
{
  /// Maximal number of L-BFGS iterations.
  std::size_t max_iterations = 20000;
  /// Stop when \f$ \max_i |\partial E / \partial y_i| / \Delta x \le \f$ `gradient_tolerance` over the free
  /// nodes; dividing by the grid step makes it a discrete Euler–Lagrange residual, independent of `m`.
  double gradient_tolerance = 1e-8;
  /// Stop when \f$ |\Delta E| \le \f$ `energy_tolerance` \f$ \cdot |E| \f$ three iterations in a row.
  /// With the defaults this is usually what ends the iteration: the rounding of the energy sum, not the
  /// gradient, limits how far a minimum can be resolved (e.g. the scaled gradient stalls near 1e-4 for the
  /// catenoid with m = 200, where the energy is resolved to about 1e-12 relative).
  double energy_tolerance = 1e-13;
  /// Number of L-BFGS correction pairs; 0 gives projected steepest descent.
  std::size_t memory = 10;
  /// Interior node values are clamped to [`ymin`, `ymax`] (the end values are not).
  double ymin = -std::numeric_limits<double>::infinity();
  /// See `ymin`.
  double ymax = std::numeric_limits<double>::infinity();
  /// Relative tolerance passed to `edge_weight_2()` (used only by functionals without a closed form).
  double quadrature_tolerance = 1e-10;
  /// Relative step of the central differences; 0 selects \f$ \epsilon^{1/3} \approx 6\cdot 10^{-6} \f$,
  /// which balances truncation and rounding errors. The absolute step is this times `max(1, |y_i|)`.
  double finite_difference_step = 0;
};

/*!
  \ingroup PkgVariationalMinimizationLocalDescent
  Result of `local_descent_2()`.
*/
struct Local_descent_result
{
  /// Discrete energy \f$ \sum_i w_i \f$ of the final curve.
  double energy = std::numeric_limits<double>::quiet_NaN();
  /// The `m + 1` node values, end values included.
  std::vector<double> values;
  /// Number of accepted iterations.
  std::size_t iterations = 0;
  /// `true` for `Gradient_small` and `Energy_stalled`.
  bool converged = false;
  /// Why the iteration stopped.
  Local_descent_stop stop_reason = Local_descent_stop::Max_iterations;
  /// Final scaled projected gradient norm (see `Local_descent_options::gradient_tolerance`).
  double gradient_norm = std::numeric_limits<double>::quiet_NaN();
};

namespace internal {

template <class Functional>
class Local_descent_problem
{
public:
  Local_descent_problem(const Functional& g, double a, double b, std::size_t m, const Local_descent_options& o)
    : g_(g), x_(m + 1), opt_(o)
  {
    for(std::size_t i = 0; i <= m; ++i)
      x_[i] = a + (b - a) * (static_cast<double>(i) / static_cast<double>(m));
    x_[m] = b; // exact end, whatever the rounding above
    dx_ = (b - a) / static_cast<double>(m);
    step_ = o.finite_difference_step > 0 ? o.finite_difference_step
                                         : std::cbrt(std::numeric_limits<double>::epsilon());
  }

  double grid_step() const { return dx_; }

  double segment(std::size_t j, double yl, double yr) const
  {
    const double h = x_[j + 1] - x_[j];
    return edge_weight_2(g_, x_[j], yl, x_[j + 1], yr, (yr - yl) / h, opt_.quadrature_tolerance);
  }

  double energy(const std::vector<double>& y) const
  {
    double e = 0;
    for(std::size_t j = 0; j + 1 < y.size(); ++j)
      e += segment(j, y[j], y[j + 1]);
    return e;
  }

  // Gradient with respect to the interior nodes (entry i for node i; entries 0 and m stay 0).
  // Node i only touches segments i-1 and i, so each entry costs four edge weights. Differences are one-sided
  // where a bound or an infinite weight forbids one side, and 0 when both sides are forbidden.
  void gradient(const std::vector<double>& y, std::vector<double>& grad) const
  {
    const std::size_t m = y.size() - 1;
    grad.assign(m + 1, 0.);
    for(std::size_t i = 1; i < m; ++i) {
      const double yi = y[i];
      const double eps = step_ * std::max(1.0, std::fabs(yi));
      const double up = yi + eps, down = yi - eps;
      const bool up_ok = up <= opt_.ymax, down_ok = down >= opt_.ymin;
      const double e_up = up_ok ? local(i, y, up) : inf();
      const double e_down = down_ok ? local(i, y, down) : inf();
      const bool fu = std::isfinite(e_up), fd = std::isfinite(e_down);
      if(fu && fd)
        grad[i] = (e_up - e_down) / (up - down);
      else if(fu || fd) {
        const double e_mid = local(i, y, yi);
        if(!std::isfinite(e_mid))
          continue;
        grad[i] = fu ? (e_up - e_mid) / (up - yi) : (e_mid - e_down) / (yi - down);
      }
    }
  }

  double project(double v) const { return std::min(opt_.ymax, std::max(opt_.ymin, v)); }

  bool at_blocking_bound(double yi, double gi) const
  {
    return (yi <= opt_.ymin && gi > 0) || (yi >= opt_.ymax && gi < 0);
  }

private:
  static double inf() { return std::numeric_limits<double>::infinity(); }

  double local(std::size_t i, const std::vector<double>& y, double yi) const
  {
    return segment(i - 1, y[i - 1], yi) + segment(i, yi, y[i + 1]);
  }

  const Functional& g_;
  std::vector<double> x_;
  Local_descent_options opt_;
  double dx_, step_;
};

inline double dot(const std::vector<double>& u, const std::vector<double>& v)
{
  double s = 0;
  for(std::size_t i = 0; i < u.size(); ++i)
    s += u[i] * v[i];
  return s;
}

inline void check_local_descent_input(double a, double b, const std::vector<double>& values,
                                      const Local_descent_options& o)
{
  if(!std::isfinite(a) || !std::isfinite(b) || !(a < b))
    throw std::invalid_argument("MDCS: local_descent_2: need finite a < b");
  if(values.size() < 2)
    throw std::invalid_argument("MDCS: local_descent_2: need at least 2 node values (m >= 1 intervals)");
  for(double v : values)
    if(!std::isfinite(v))
      throw std::invalid_argument("MDCS: local_descent_2: node values must be finite");
  if(std::isnan(o.ymin) || std::isnan(o.ymax) || !(o.ymin <= o.ymax))
    throw std::invalid_argument("MDCS: local_descent_2: need ymin <= ymax");
  if(!(o.gradient_tolerance >= 0) || !(o.energy_tolerance >= 0) || !(o.quadrature_tolerance > 0) ||
     !(o.finite_difference_step >= 0))
    throw std::invalid_argument("MDCS: local_descent_2: tolerances must be non-negative "
                                "(quadrature_tolerance positive)");
}

} // namespace internal

/*!
  \ingroup PkgVariationalMinimizationLocalDescent
  Minimises the discrete energy \f$ E(y) = \sum_{i=0}^{m-1} w_i \f$, where \f$ w_i \f$ is the
  `edge_weight_2()` of the segment from \f$ (x_i, y_i) \f$ to \f$ (x_{i+1}, y_{i+1}) \f$ on the uniform grid
  \f$ x_i = a + i (b - a)/m \f$, over the interior node values \f$ y_1, \dots, y_{m-1} \f$ (clamped to
  [`ymin`, `ymax`]); \f$ y_0 \f$ and \f$ y_m \f$ stay fixed.

  The method is projected L-BFGS with an Armijo backtracking line search (falling back to steepest descent
  when the quasi-Newton direction does not decrease the energy) and a central-difference gradient (each entry
  costs four edge weights, so an iteration is O(m)). It finds a *local* minimum near the start: that is its
  purpose in MDCS, as the baseline the globally minimal discrete curve is compared with.

  \tparam Functional a model of `CurveFunctional_2`.
  \param G the integrand.
  \param a,b the interval, `a < b`.
  \param initial_values the `m + 1` initial node values; the first and last are the fixed end values.
  \param options stopping criteria, bounds, tolerances.
  \throws std::invalid_argument on bad input (non-finite values, `a >= b`, fewer than 2 values, `ymin > ymax`).
  \throws std::domain_error from `edge_weight_2()` if `G` is negative or NaN somewhere it is evaluated.
  \warning The gradient is approximate; near the optimum the iteration may stop with `Line_search_failed`
  (numerical noise floor), which usually still is a good approximation of the local minimum.
*/
template <class Functional>
Local_descent_result local_descent_2(const Functional& G, double a, double b,
                                     std::vector<double> initial_values,
                                     const Local_descent_options& options = Local_descent_options())
{
  internal::check_local_descent_input(a, b, initial_values, options);
  const std::size_t m = initial_values.size() - 1;
  internal::Local_descent_problem<Functional> problem(G, a, b, m, options);

  Local_descent_result result;
  std::vector<double> y = std::move(initial_values);
  for(std::size_t i = 1; i < m; ++i)
    y[i] = problem.project(y[i]);
  double energy = problem.energy(y);
  const double dx = problem.grid_step();

  auto finish = [&](Local_descent_stop reason, double gnorm) {
    result.energy = energy;
    result.values = y;
    result.stop_reason = reason;
    result.converged = reason == Local_descent_stop::Gradient_small || reason == Local_descent_stop::Energy_stalled;
    result.gradient_norm = gnorm;
    return result;
  };

  if(!std::isfinite(energy))
    return finish(Local_descent_stop::Infinite_energy, std::numeric_limits<double>::quiet_NaN());

  std::vector<double> g, pg(m + 1, 0.);
  problem.gradient(y, g);
  // Projected gradient: zero where a bound blocks the descent direction.
  auto project_gradient = [&](const std::vector<double>& yy, const std::vector<double>& gg) {
    double norm = 0;
    for(std::size_t i = 1; i < m; ++i) {
      pg[i] = problem.at_blocking_bound(yy[i], gg[i]) ? 0. : gg[i];
      norm = std::max(norm, std::fabs(pg[i]));
    }
    return norm / dx;
  };
  double gnorm = project_gradient(y, g);
  if(m < 2 || gnorm <= options.gradient_tolerance)
    return finish(Local_descent_stop::Gradient_small, gnorm);

  std::deque<std::pair<std::vector<double>, std::vector<double> > > memory; // (s, y) correction pairs
  std::vector<double> d(m + 1), trial(m + 1), step(m + 1), g_new, alpha_buffer;
  std::size_t stalled = 0;
  const double armijo = 1e-4;
  // First step (and after a reset): move the largest node by 1% of the curve's scale.
  auto first_step_length = [&](double dmax) {
    double scale = 1;
    for(double v : y)
      scale = std::max(scale, std::fabs(v));
    return dmax > 0 ? 0.01 * scale / dmax : 1.;
  };

  for(std::size_t iter = 0; iter < options.max_iterations; ++iter) {
    bool used_memory = false;
    bool accepted = false;
    double new_energy = energy;
    for(int attempt = 0; attempt < 2 && !accepted; ++attempt) {
      // Direction: L-BFGS two-loop recursion on the projected gradient, or steepest descent.
      d = pg;
      used_memory = !memory.empty() && attempt == 0;
      if(used_memory) {
        alpha_buffer.assign(memory.size(), 0.);
        for(std::size_t k = memory.size(); k-- > 0;) {
          const auto& sy = memory[k];
          const double rho = 1 / internal::dot(sy.second, sy.first);
          alpha_buffer[k] = rho * internal::dot(sy.first, d);
          for(std::size_t i = 1; i < m; ++i)
            d[i] -= alpha_buffer[k] * sy.second[i];
        }
        const auto& last = memory.back();
        const double gamma = internal::dot(last.first, last.second) / internal::dot(last.second, last.second);
        for(std::size_t i = 1; i < m; ++i)
          d[i] *= gamma;
        for(std::size_t k = 0; k < memory.size(); ++k) {
          const auto& sy = memory[k];
          const double rho = 1 / internal::dot(sy.second, sy.first);
          const double beta = rho * internal::dot(sy.second, d);
          for(std::size_t i = 1; i < m; ++i)
            d[i] += (alpha_buffer[k] - beta) * sy.first[i];
        }
      }
      double dmax = 0;
      for(std::size_t i = 0; i <= m; ++i) {
        d[i] = (i == 0 || i == m || problem.at_blocking_bound(y[i], g[i])) ? 0. : -d[i];
        dmax = std::max(dmax, std::fabs(d[i]));
      }
      if(used_memory && !(internal::dot(d, g) < 0)) {
        memory.clear(); // not a descent direction: curvature information is stale
        continue;
      }
      double t = used_memory ? 1. : first_step_length(dmax);
      for(int k = 0; k < 60; ++k, t *= 0.5) {
        trial[0] = y[0];
        trial[m] = y[m];
        for(std::size_t i = 1; i < m; ++i)
          trial[i] = problem.project(y[i] + t * d[i]);
        for(std::size_t i = 0; i <= m; ++i)
          step[i] = trial[i] - y[i];
        const double slope = internal::dot(g, step);
        if(!(slope < 0))
          continue;
        const double e = problem.energy(trial);
        if(e <= energy + armijo * slope) {
          new_energy = e;
          accepted = true;
          break;
        }
      }
      if(!accepted) {
        if(!used_memory)
          break; // steepest descent failed too: a second identical try is pointless
        memory.clear();
      }
    }
    if(!accepted)
      return finish(Local_descent_stop::Line_search_failed, gnorm);

    problem.gradient(trial, g_new);
    std::vector<double> s(m + 1), yv(m + 1);
    for(std::size_t i = 0; i <= m; ++i) {
      s[i] = trial[i] - y[i];
      yv[i] = g_new[i] - g[i];
    }
    const double sy = internal::dot(s, yv);
    // Keep only pairs with clearly positive curvature so the implicit inverse Hessian stays positive definite.
    if(options.memory > 0 && sy > 1e-12 * std::sqrt(internal::dot(s, s) * internal::dot(yv, yv))) {
      memory.emplace_back(std::move(s), std::move(yv));
      if(memory.size() > options.memory)
        memory.pop_front();
    }
    const double change = std::fabs(energy - new_energy);
    y.swap(trial);
    g.swap(g_new);
    energy = new_energy;
    ++result.iterations;
    gnorm = project_gradient(y, g);
    if(gnorm <= options.gradient_tolerance)
      return finish(Local_descent_stop::Gradient_small, gnorm);
    stalled = change <= options.energy_tolerance * std::fabs(energy) ? stalled + 1 : 0;
    if(stalled >= 3)
      return finish(Local_descent_stop::Energy_stalled, gnorm);
  }
  return finish(Local_descent_stop::Max_iterations, gnorm);
}

/*!
  \ingroup PkgVariationalMinimizationLocalDescent
  Same as above with `m` intervals, end values `A = f(a)` and `B = f(b)`, and the interior initial values
  sampled from the callable `initial_curve(x)` (a `double(double)`).
  \throws std::invalid_argument if `m == 0`, plus the exceptions of the overload above.
*/
template <class Functional, class InitialCurve>
Local_descent_result local_descent_2(const Functional& G, double a, double b, double A, double B,
                                     std::size_t m, const InitialCurve& initial_curve,
                                     const Local_descent_options& options = Local_descent_options())
{
  if(m == 0)
    throw std::invalid_argument("MDCS: local_descent_2: need m >= 1 intervals");
  std::vector<double> values(m + 1);
  values[0] = A;
  values[m] = B;
  for(std::size_t i = 1; i < m; ++i)
    values[i] = static_cast<double>(initial_curve(a + (b - a) * (static_cast<double>(i) / static_cast<double>(m))));
  return local_descent_2(G, a, b, std::move(values), options);
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_LOCAL_DESCENT_2_H
