// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Relaxation (thesis ch. 2.7): a local optimiser that continues from a discrete optimum on a hierarchy of regular
// grids (20^2, 40^2, 80^2 squares by default; on a polygonal domain, Delaunay meshes of the polygon with the same
// edge lengths), and the random-start local descent it is compared with.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_RELAX_SURFACE_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_RELAX_SURFACE_3_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/internal/grid_surface_3.h>
#include <CGAL/Variational_minimization/internal/mesh_surface_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <memory>
#include <sstream>
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

  On a polygonal domain the function lives on a triangle mesh of the polygon instead (`nodes`, `triangles`, not
  empty; `heights[k]` is the height at `nodes[k]`), the mesh of the last level `n` (see `relax_surface_3()`).
*/
struct Relaxed_surface_3
{
  int n = 0;
  std::vector<double> heights;
  double energy = std::numeric_limits<double>::infinity();
  std::size_t iterations = 0;
  /// Polygonal domains only: the mesh nodes (x, y) and its triangles (counter-clockwise node triples).
  std::vector<std::array<double, 2>> nodes;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  /// Per level: the energy of the start function (interpolated from the previous level) and of the result; the
  /// local optimiser never increases the energy within a level.
  std::vector<double> level_start_energies, level_energies;
};

namespace internal {

// Every value of G is checked finite where it is evaluated; their sum may still overflow: never a relaxed surface
// with an infinite energy.
inline void check_relaxed_energy_3(const Relaxed_surface_3& r)
{
  if(!std::isfinite(r.energy))
    throw std::invalid_argument("MDCS: relax_surface_3: the relaxed energy is not finite: the functional's values add "
                                "up beyond the double range; scale the functional down");
}

} // namespace internal

namespace internal {

// Projected L-BFGS on box bounds [lo, hi] (equal bounds fix a variable). `energy_of(f, grad)` returns the energy
// of f and, when grad is not null, its gradient; `first_step` is the largest change of a node in a steepest
// descent restart. `start_energy`, if not null, receives the energy of the (clamped) start.
template <class EnergyOf>
double projected_lbfgs_3(const EnergyOf& energy_of, double first_step, std::vector<double>& f,
                         const std::vector<double>& lo, const std::vector<double>& hi,
                         const Surface_relaxation_options_3& o, std::size_t& iterations,
                         double* start_energy = nullptr)
{
  const std::size_t n = f.size();
  for(std::size_t i = 0; i < n; ++i) f[i] = std::min(hi[i], std::max(lo[i], f[i]));
  std::vector<double> grad, new_grad, d(n), trial(n);
  double energy = energy_of(f, &grad);
  if(start_energy) *start_energy = energy;
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
      const double scale = first_step / norm;
      for(double& v : d) v *= scale;
      slope *= scale;
    }
    // Backtracking line search on the projected path.
    double step = 1, new_energy = energy;
    bool accepted = false;
    for(int ls = 0; ls < 40; ++ls) {
      for(std::size_t i = 0; i < n; ++i) trial[i] = std::min(hi[i], std::max(lo[i], f[i] + step * d[i]));
      new_energy = energy_of(trial, nullptr);
      if(new_energy <= energy + 1e-4 * step * slope) {
        accepted = true;
        break;
      }
      step *= 0.5;
    }
    ++iterations;
    if(!accepted) break;
    energy_of(trial, &new_grad);
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

// The same on the regular grid of the rectangle (a first step of a tenth of a grid spacing).
template <class Functional>
double lbfgs_on_grid(const Grid_frame_3& g, const Functional& G, std::vector<double>& f, const std::vector<double>& lo,
                     const std::vector<double>& hi, const Surface_relaxation_options_3& o, std::size_t& iterations,
                     double* start_energy = nullptr)
{
  return projected_lbfgs_3([&](const std::vector<double>& x, std::vector<double>* grad) {
                             return grid_energy_3(g, G, x, grad);
                           },
                           0.1 * (g.hx + g.hy), f, lo, hi, o, iterations, start_energy);
}

// The triangulated function of a relaxation level (for the interpolation to the next level).
inline Minimal_surface_3 mesh_function_3(const Triangle_mesh_frame_3& m, const std::vector<double>& f)
{
  Minimal_surface_3 s;
  for(std::size_t k = 0; k < m.nodes.size(); ++k) s.points.push_back({{m.nodes[k][0], m.nodes[k][1], f[k]}});
  s.triangles = m.triangles;
  return s;
}

// relax_surface_3() on a polygonal domain: the levels are meshes of the polygon (polygon_relaxation_mesh_3), the
// next level starts from the previous one's function (linear interpolation on its triangles).
template <class Functional, class Initial, class Reporter>
Relaxed_surface_3 relax_surface_on_polygon_3(const Surface_problem_3& problem, const Functional& G,
                                             const Initial& initial, const Surface_relaxation_options_3& options,
                                             Reporter& reporter)
{
  Relaxed_surface_3 result;
  Triangle_mesh_frame_3 previous_mesh;
  std::vector<double> previous;
  for(std::size_t level = 0; level < options.grids.size(); ++level) {
    reporter(level);
    const int n = options.grids[level];
    Triangle_mesh_frame_3 m = polygon_relaxation_mesh_3(problem, n);
    std::vector<double> f(m.size()), lo(m.size(), problem.zmin), hi(m.size(), problem.zmax);
    const Minimal_surface_3 last = mesh_function_3(previous_mesh, previous);
    std::unique_ptr<Surface_height_sampler_3> sampler;
    if(level > 0) sampler.reset(new Surface_height_sampler_3(last, problem));
    for(std::size_t k = 0; k < m.size(); ++k) {
      const double x = m.nodes[k][0], y = m.nodes[k][1];
      f[k] = level == 0 ? initial(x, y) : (*sampler)(x, y);
      if(!std::isfinite(f[k])) throw std::invalid_argument("MDCS: relax_surface_3: the start function is not finite");
      if(m.on_boundary[k]) {
        lo[k] = problem.lower_boundary(x, y);
        hi[k] = problem.is_relaxed() ? problem.upper_boundary(x, y) : lo[k];
        if(!std::isfinite(lo[k]) || !std::isfinite(hi[k]) || lo[k] > hi[k]) {
          std::ostringstream s;
          s << "MDCS: relax_surface_3: at the boundary point (" << x << ", " << y << ") the boundary data ["
            << lo[k] << ", " << hi[k] << "] is not finite or the lower boundary lies above the upper one";
          throw std::invalid_argument(s.str());
        }
      }
    }
    const double hx = (problem.domain.xmax() - problem.domain.xmin()) / n,
                 hy = (problem.domain.ymax() - problem.domain.ymin()) / n;
    double start = 0;
    result.energy = projected_lbfgs_3([&](const std::vector<double>& x, std::vector<double>* grad) {
                                        return mesh_energy_3(m, G, x, grad);
                                      },
                                      0.1 * (hx + hy), f, lo, hi, options, result.iterations, &start);
    result.level_start_energies.push_back(start);
    result.level_energies.push_back(result.energy);
    previous.swap(f);
    previous_mesh = std::move(m);
  }
  result.n = options.grids.back();
  result.heights = previous;
  result.nodes = previous_mesh.nodes;
  result.triangles = previous_mesh.triangles;
  check_relaxed_energy_3(result);
  return result;
}

} // namespace internal

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief Relaxation: minimises the energy of piecewise linear functions on the grids of `options.grids` in turn,
  by projected L-BFGS, starting from `initial(x, y)` on the first grid and from the previous level's result
  (bilinear interpolation) on the next ones. Boundary nodes take the exact boundary data (fixed) or stay in
  [g0, g1] (relaxed); all nodes stay in [zmin, zmax]. The result is a local minimum near the start.

  On a polygonal domain, level `n` is not a grid but a triangle mesh of the (rounded) polygon: its constrained
  Delaunay triangulation refined by CGAL's `Delaunay_mesher_2` (angles >= 20.7 degrees, edges no longer than the
  diagonal of a square of the `n x n` grid over the bounding box). The nodes on the polygon's edges are the
  boundary nodes; the energy is integrated over Ω only (same centroid rule); the next level starts from the
  previous one by linear interpolation on its triangles. The result holds the last mesh (`nodes`, `triangles`).
  \throws std::invalid_argument if the problem is invalid, a grid has fewer than 1 square per side, or G is
          negative or NaN somewhere.
*/
template <class Functional, class Initial, class Progress = CGAL::MDCS::No_progress>
Relaxed_surface_3 relax_surface_3(const Surface_problem_3& problem, const Functional& G, const Initial& initial,
                                  const Surface_relaxation_options_3& options = Surface_relaxation_options_3(),
                                  Progress progress = Progress())
{
  problem.validate();
  if(options.grids.empty()) throw std::invalid_argument("MDCS: relax_surface_3: no grid given");
  for(int n : options.grids)
    if(n < 1 || n > 4096) throw std::invalid_argument("MDCS: relax_surface_3: grid sizes must be in [1, 4096]");
  if(options.grids.size() > 64) throw std::invalid_argument("MDCS: relax_surface_3: at most 64 grid levels");
  // the L-BFGS memory sizes two arrays of `memory` vectors per node: bounded like the grids
  if(options.memory < 1 || options.memory > 100 || options.max_iterations < 0 || !(options.tolerance >= 0) ||
     !std::isfinite(options.tolerance))
    throw std::invalid_argument("MDCS: relax_surface_3: memory must be in [1, 100], max_iterations >= 0 and tolerance "
                                "finite and >= 0");
  CGAL::MDCS::internal::Progress_reporter<Progress> reporter(progress, "relaxation", options.grids.size());
  if(problem.is_polygonal()) {
    Relaxed_surface_3 r = internal::relax_surface_on_polygon_3(problem, G, initial, options, reporter);
    reporter.finish();
    return r;
  }
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
        if(level == 0) {
          f[k] = initial(x, y);
          if(!std::isfinite(f[k])) throw std::invalid_argument("MDCS: relax_surface_3: the start function is not finite");
        } else {
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
    double start = 0;
    result.energy = internal::lbfgs_on_grid(g, G, f, lo, hi, options, result.iterations, &start);
    result.level_start_energies.push_back(start);
    result.level_energies.push_back(result.energy);
    previous.swap(f);
    previous_n = n;
  }
  reporter.finish();
  result.n = previous_n;
  result.heights = previous;
  internal::check_relaxed_energy_3(result);
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

/// The triangulated mesh of a grid function, or of a polygon's mesh function (for output).
inline Minimal_surface_3 grid_surface_mesh_3(const Surface_problem_3& problem, const Relaxed_surface_3& r)
{
  Minimal_surface_3 s;
  s.is_feasible = true;
  s.energy = s.solver_value = r.energy;
  if(!r.triangles.empty()) {
    for(std::size_t k = 0; k < r.nodes.size(); ++k) s.points.push_back({{r.nodes[k][0], r.nodes[k][1], r.heights[k]}});
    s.triangles = r.triangles;
    s.projected_area = 0;
    for(const auto& t : r.triangles) {
      const auto &a = r.nodes[t[0]], &b = r.nodes[t[1]], &c = r.nodes[t[2]];
      s.projected_area += 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    }
    return s;
  }
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
