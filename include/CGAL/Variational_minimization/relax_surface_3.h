// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Relaxation (thesis ch. 2.7): a local optimiser that continues from a discrete optimum on a hierarchy of regular
// grids (20^2, 40^2, 80^2 squares by default), and the random-start local descent it is compared with.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_RELAX_SURFACE_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_RELAX_SURFACE_3_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/internal/grid_surface_3.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/// Options of `relax_surface_3()`.
struct Surface_relaxation_options_3
{
  std::vector<int> grids = {20, 40, 80}; ///< squares per side of each level, coarse to fine
  int max_iterations = 400;              ///< L-BFGS iterations per level at most
  double tolerance = 1e-11;              ///< stop a level when the relative energy decrease of an iteration is below
  int memory = 8;                        ///< L-BFGS memory
};

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  A piecewise linear function on the regular grid of `n x n` squares over the domain (two triangles per square):
  node heights row by row (`(n + 1)^2` values, node (i, j) at index `j (n + 1) + i`), and its energy
  (centroid quadrature, exact for area and membrane).
*/
struct Relaxed_surface_3
{
  int n = 0;
  std::vector<double> heights;
  double energy = std::numeric_limits<double>::infinity();
  std::size_t iterations = 0;
};

namespace internal {

// Projected L-BFGS on box bounds [lo, hi] (equal bounds fix a variable).
template <class Functional>
double lbfgs_on_grid(const Grid_frame_3& g, const Functional& G, std::vector<double>& f, const std::vector<double>& lo,
                     const std::vector<double>& hi, const Surface_relaxation_options_3& o, std::size_t& iterations)
{
  const std::size_t n = f.size();
  for(std::size_t i = 0; i < n; ++i) f[i] = std::min(hi[i], std::max(lo[i], f[i]));
  std::vector<double> grad, new_grad, d(n), trial(n);
  double energy = grid_energy_3(g, G, f, &grad);
  std::deque<std::vector<double>> S, Y;
  std::deque<double> rho;
  auto project_gradient = [&](std::vector<double>& v, const std::vector<double>& x, const std::vector<double>& gr) {
    for(std::size_t i = 0; i < n; ++i)
      if(lo[i] == hi[i] || (x[i] <= lo[i] && gr[i] > 0) || (x[i] >= hi[i] && gr[i] < 0)) v[i] = 0;
  };
  for(int it = 0; it < o.max_iterations; ++it) {
    // Two-loop recursion.
    for(std::size_t i = 0; i < n; ++i) d[i] = -grad[i];
    project_gradient(d, f, grad);
    std::vector<double> alpha(S.size());
    for(std::size_t k = S.size(); k-- > 0;) {
      double s = 0;
      for(std::size_t i = 0; i < n; ++i) s += S[k][i] * d[i];
      alpha[k] = rho[k] * s;
      for(std::size_t i = 0; i < n; ++i) d[i] -= alpha[k] * Y[k][i];
    }
    if(!S.empty()) {
      double sy = 0, yy = 0;
      for(std::size_t i = 0; i < n; ++i) {
        sy += S.back()[i] * Y.back()[i];
        yy += Y.back()[i] * Y.back()[i];
      }
      const double gamma = yy > 0 ? sy / yy : 1;
      for(double& v : d) v *= gamma;
    }
    for(std::size_t k = 0; k < S.size(); ++k) {
      double s = 0;
      for(std::size_t i = 0; i < n; ++i) s += Y[k][i] * d[i];
      const double beta = rho[k] * s;
      for(std::size_t i = 0; i < n; ++i) d[i] += (alpha[k] - beta) * S[k][i];
    }
    project_gradient(d, f, grad);
    double slope = 0;
    for(std::size_t i = 0; i < n; ++i) slope += d[i] * grad[i];
    if(!(slope < 0)) { // not a descent direction: restart with the projected steepest descent
      S.clear(); Y.clear(); rho.clear();
      for(std::size_t i = 0; i < n; ++i) d[i] = -grad[i];
      project_gradient(d, f, grad);
      slope = 0;
      for(std::size_t i = 0; i < n; ++i) slope += d[i] * grad[i];
      if(!(slope < 0)) break; // stationary
      double norm = 0;
      for(double v : d) norm = std::max(norm, std::abs(v));
      const double scale = 0.1 * (g.hx + g.hy) / norm; // a first step of a tenth of a grid spacing
      for(double& v : d) v *= scale;
      slope *= scale;
    }
    // Backtracking line search on the projected path.
    double step = 1, new_energy = energy;
    bool accepted = false;
    for(int ls = 0; ls < 40; ++ls) {
      for(std::size_t i = 0; i < n; ++i) trial[i] = std::min(hi[i], std::max(lo[i], f[i] + step * d[i]));
      new_energy = grid_energy_3(g, G, trial, nullptr);
      if(new_energy <= energy + 1e-4 * step * slope) {
        accepted = true;
        break;
      }
      step *= 0.5;
    }
    ++iterations;
    if(!accepted) break;
    grid_energy_3(g, G, trial, &new_grad);
    std::vector<double> s(n), y(n);
    double sy = 0;
    for(std::size_t i = 0; i < n; ++i) {
      s[i] = trial[i] - f[i];
      y[i] = new_grad[i] - grad[i];
      sy += s[i] * y[i];
    }
    const double decrease = energy - new_energy;
    f.swap(trial);
    grad.swap(new_grad);
    energy = new_energy;
    if(sy > 1e-300) {
      S.push_back(std::move(s));
      Y.push_back(std::move(y));
      rho.push_back(1 / sy);
      if(int(S.size()) > o.memory) { S.pop_front(); Y.pop_front(); rho.pop_front(); }
    }
    if(decrease <= o.tolerance * std::abs(energy)) break;
  }
  return energy;
}

} // namespace internal

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief Relaxation: minimises the energy of piecewise linear functions on the grids of `options.grids` in turn,
  by projected L-BFGS, starting from `initial(x, y)` on the first grid and from the previous level's result
  (bilinear interpolation) on the next ones. Boundary nodes take the exact boundary data (fixed) or stay in
  [g0, g1] (relaxed); all nodes stay in [zmin, zmax]. The result is a local minimum near the start.
  \throws std::invalid_argument if the problem is invalid or has a polygonal domain, a grid has fewer than 1 square per side, or G is
          negative or NaN somewhere.
*/
template <class Functional, class Initial, class Progress = CGAL::MDCS::No_progress>
Relaxed_surface_3 relax_surface_3(const Surface_problem_3& problem, const Functional& G, const Initial& initial,
                                  const Surface_relaxation_options_3& options = Surface_relaxation_options_3(),
                                  Progress progress = Progress())
{
  problem.validate();
  if(problem.is_polygonal())
    throw std::invalid_argument("MDCS: relax_surface_3: the relaxation needs a rectangular domain (its grids cover "
                                "the rectangle); a polygonal domain is not supported");
  if(options.grids.empty()) throw std::invalid_argument("MDCS: relax_surface_3: no grid given");
  for(int n : options.grids)
    if(n < 1 || n > 4096) throw std::invalid_argument("MDCS: relax_surface_3: grid sizes must be in [1, 4096]");
  CGAL::MDCS::internal::Progress_reporter<Progress> reporter(progress, "relaxation", options.grids.size());
  Relaxed_surface_3 result;
  std::vector<double> previous;
  int previous_n = 0;
  for(std::size_t level = 0; level < options.grids.size(); ++level) {
    reporter(level);
    const int n = options.grids[level];
    const internal::Grid_frame_3 g(problem, n);
    std::vector<double> f(g.size()), lo(g.size(), problem.zmin), hi(g.size(), problem.zmax);
    for(int j = 0; j <= n; ++j)
      for(int i = 0; i <= n; ++i) {
        const double x = g.x(i), y = g.y(j);
        const std::size_t k = g.index(i, j);
        if(level == 0) f[k] = initial(x, y);
        else {
          // Bilinear interpolation of the previous level.
          const double u = double(i) * previous_n / n, v = double(j) * previous_n / n;
          const int i0 = std::min(previous_n - 1, int(u)), j0 = std::min(previous_n - 1, int(v));
          const double a = u - i0, b = v - j0;
          auto at = [&](int p, int q) { return previous[std::size_t(q) * std::size_t(previous_n + 1) + std::size_t(p)]; };
          f[k] = (1 - a) * (1 - b) * at(i0, j0) + a * (1 - b) * at(i0 + 1, j0) + (1 - a) * b * at(i0, j0 + 1) +
                 a * b * at(i0 + 1, j0 + 1);
        }
        if(g.on_boundary(i, j)) {
          lo[k] = problem.lower_boundary(x, y);
          hi[k] = problem.is_relaxed() ? problem.upper_boundary(x, y) : lo[k];
        }
      }
    result.energy = internal::lbfgs_on_grid(g, G, f, lo, hi, options, result.iterations);
    previous.swap(f);
    previous_n = n;
  }
  reporter.finish();
  result.n = previous_n;
  result.heights = previous;
  return result;
}

/// Relaxation from a discrete surface (its heights sampled at the nodes of the first grid).
template <class Functional, class Progress = CGAL::MDCS::No_progress>
Relaxed_surface_3 relax_surface_3(const Surface_problem_3& problem, const Functional& G, const Minimal_surface_3& start,
                                  const Surface_relaxation_options_3& options = Surface_relaxation_options_3(),
                                  Progress progress = Progress())
{
  if(!start.is_feasible) throw std::invalid_argument("MDCS: relax_surface_3: the start surface is infeasible");
  const internal::Surface_height_sampler_3 sampler(start, problem);
  return relax_surface_3(problem, G, [&](double x, double y) { return sampler(x, y); }, options, progress);
}

/// The triangulated mesh of a grid function (for output).
inline Minimal_surface_3 grid_surface_mesh_3(const Surface_problem_3& problem, const Relaxed_surface_3& r)
{
  Minimal_surface_3 s;
  s.is_feasible = true;
  s.energy = s.solver_value = r.energy;
  const internal::Grid_frame_3 g(problem, r.n);
  for(int j = 0; j <= r.n; ++j)
    for(int i = 0; i <= r.n; ++i) s.points.push_back({{g.x(i), g.y(j), r.heights[g.index(i, j)]}});
  for(int j = 0; j < r.n; ++j)
    for(int i = 0; i < r.n; ++i) {
      const std::uint32_t a = std::uint32_t(g.index(i, j)), b = std::uint32_t(g.index(i + 1, j)),
                          c = std::uint32_t(g.index(i, j + 1)), d = std::uint32_t(g.index(i + 1, j + 1));
      s.triangles.push_back({{a, b, c}});
      s.triangles.push_back({{d, c, b}});
    }
  s.projected_area = problem.domain_area();
  return s;
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_RELAX_SURFACE_3_H
