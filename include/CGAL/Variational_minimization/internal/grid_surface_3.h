// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Piecewise linear functions on a regular (n+1) x (n+1) grid of nodes over the domain (two triangles per square),
// their energy for a functional G (centroid rule: exact for G depending only on the gradient, and for G linear in f),
// its gradient, and the sampling of a triangulated surface at the grid nodes.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_GRID_SURFACE_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_GRID_SURFACE_3_H

#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/internal/functional_evaluation_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

struct Grid_frame_3
{
  int n;
  double x0, y0, hx, hy;
  Grid_frame_3(const Surface_problem_3& p, int n_)
    : n(n_), x0(p.domain.xmin()), y0(p.domain.ymin()), hx((p.domain.xmax() - p.domain.xmin()) / n_),
      hy((p.domain.ymax() - p.domain.ymin()) / n_)
  {}
  std::size_t index(int i, int j) const { return std::size_t(j) * std::size_t(n + 1) + std::size_t(i); }
  std::size_t size() const { return std::size_t(n + 1) * std::size_t(n + 1); }
  double x(int i) const { return i == n ? x0 + hx * n : x0 + hx * i; }
  double y(int j) const { return j == n ? y0 + hy * n : y0 + hy * j; }
  bool on_boundary(int i, int j) const { return i == 0 || j == 0 || i == n || j == n; }
};

// Energy and (optionally) gradient. Each square (i, j) has the triangles (i,j),(i+1,j),(i,j+1) and
// (i+1,j+1),(i,j+1),(i+1,j).
template <class Functional>
double grid_energy_3(const Grid_frame_3& g, const Functional& G, const std::vector<double>& f, std::vector<double>* grad)
{
  if(grad) grad->assign(f.size(), 0.0);
  const double area = 0.5 * g.hx * g.hy;
  double energy = 0;
  for(int j = 0; j < g.n; ++j)
    for(int i = 0; i < g.n; ++i)
      for(int t = 0; t < 2; ++t) {
        std::size_t v[3];
        double fx, fy, cx, cy;
        // d(fx)/d f_v and d(fy)/d f_v for the three vertices
        double dx[3], dy[3];
        if(t == 0) {
          v[0] = g.index(i, j); v[1] = g.index(i + 1, j); v[2] = g.index(i, j + 1);
          fx = (f[v[1]] - f[v[0]]) / g.hx;
          fy = (f[v[2]] - f[v[0]]) / g.hy;
          dx[0] = -1 / g.hx; dx[1] = 1 / g.hx; dx[2] = 0;
          dy[0] = -1 / g.hy; dy[1] = 0; dy[2] = 1 / g.hy;
          cx = g.x0 + g.hx * (i + 1.0 / 3);
          cy = g.y0 + g.hy * (j + 1.0 / 3);
        } else {
          v[0] = g.index(i + 1, j + 1); v[1] = g.index(i, j + 1); v[2] = g.index(i + 1, j);
          fx = (f[v[0]] - f[v[1]]) / g.hx;
          fy = (f[v[0]] - f[v[2]]) / g.hy;
          dx[0] = 1 / g.hx; dx[1] = -1 / g.hx; dx[2] = 0;
          dy[0] = 1 / g.hy; dy[1] = 0; dy[2] = -1 / g.hy;
          cx = g.x0 + g.hx * (i + 2.0 / 3);
          cy = g.y0 + g.hy * (j + 2.0 / 3);
        }
        const double fc = (f[v[0]] + f[v[1]] + f[v[2]]) / 3;
        energy += area * checked_value(G, fc, fx, fy, cx, cy);
        if(grad) {
          double d[3];
          functional_partials(G, fc, fx, fy, cx, cy, d);
          for(int k = 0; k < 3; ++k) (*grad)[v[k]] += area * (d[0] / 3 + d[1] * dx[k] + d[2] * dy[k]);
        }
      }
  return energy;
}

// Heights of a triangulated (single-valued) surface at points, through a bucket grid over the domain.
class Surface_height_sampler_3
{
public:
  Surface_height_sampler_3(const Minimal_surface_3& s, const Surface_problem_3& p) : s_(s), p_(p)
  {
    m_ = std::max(1, int(std::sqrt(double(s.triangles.size()) / 2)));
    buckets_.resize(std::size_t(m_) * std::size_t(m_));
    for(std::size_t t = 0; t < s.triangles.size(); ++t) {
      double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
      for(int k = 0; k < 3; ++k)
        for(int d = 0; d < 2; ++d) {
          lo[d] = std::min(lo[d], s.points[s.triangles[t][k]][d]);
          hi[d] = std::max(hi[d], s.points[s.triangles[t][k]][d]);
        }
      const int i0 = cell(lo[0], 0), i1 = cell(hi[0], 0), j0 = cell(lo[1], 1), j1 = cell(hi[1], 1);
      for(int j = j0; j <= j1; ++j)
        for(int i = i0; i <= i1; ++i) buckets_[std::size_t(j) * std::size_t(m_) + std::size_t(i)].push_back(t);
    }
  }

  // The height at (x, y): the triangle containing the point (with a small tolerance), the nearest otherwise.
  double operator()(double x, double y) const
  {
    const auto& list = buckets_[std::size_t(cell(y, 1)) * std::size_t(m_) + std::size_t(cell(x, 0))];
    double best = std::numeric_limits<double>::infinity(), value = 0.5 * (p_.zmin + p_.zmax);
    for(std::size_t t : list) {
      const auto& a = s_.points[s_.triangles[t][0]];
      const auto& b = s_.points[s_.triangles[t][1]];
      const auto& c = s_.points[s_.triangles[t][2]];
      const double det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      if(det == 0) continue;
      const double l1 = ((x - a[0]) * (c[1] - a[1]) - (y - a[1]) * (c[0] - a[0])) / det;
      const double l2 = ((b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])) / det;
      const double l0 = 1 - l1 - l2;
      const double outside = std::max({0.0, -l0, -l1, -l2});
      if(outside < best) {
        best = outside;
        value = l0 * a[2] + l1 * b[2] + l2 * c[2];
        if(outside == 0) break;
      }
    }
    return value;
  }

private:
  int cell(double v, int axis) const
  {
    const double lo = axis == 0 ? p_.domain.xmin() : p_.domain.ymin();
    const double hi = axis == 0 ? p_.domain.xmax() : p_.domain.ymax();
    const int k = int(std::floor((v - lo) / (hi - lo) * m_));
    return std::max(0, std::min(m_ - 1, k));
  }
  const Minimal_surface_3& s_;
  const Surface_problem_3& p_;
  int m_;
  std::vector<std::vector<std::size_t>> buckets_;
};

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_GRID_SURFACE_3_H
