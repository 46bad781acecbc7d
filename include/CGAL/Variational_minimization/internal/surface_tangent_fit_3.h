// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Local least-squares fits to a height field over the domain of a Surface_problem_3, and the planes they give:
// tangent planes at interior points and pencil planes through the boundary segments whose slope across the
// segment matches the field's. Used by refine_surface_by_tangent_planes_3().
#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_TANGENT_FIT_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_TANGENT_FIT_3_H

#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/internal/surface_polygon_predicates_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

// Whether the world point (x, y) lies in the closed domain of the problem (rectangle, or rounded polygon).
class Surface_domain_test_3
{
public:
  explicit Surface_domain_test_3(const Surface_problem_3& problem)
    : problem_(problem), polygon_(problem.is_polygonal() ? problem.lattice_polygon()
                                                         : std::vector<std::array<std::int64_t, 2>>())
  {}

  bool operator()(double x, double y) const
  {
    const auto& d = problem_.domain;
    if(!(x >= d.xmin() && x <= d.xmax() && y >= d.ymin() && y <= d.ymax())) return false;
    if(polygon_.empty()) return true;
    const double L = double(Plane_arrangement_3::lattice_size);
    return lattice_polygon_contains(polygon_, (x - d.xmin()) / (d.xmax() - d.xmin()) * L,
                                    (y - d.ymin()) / (d.ymax() - d.ymin()) * L);
  }

private:
  const Surface_problem_3& problem_;
  std::vector<std::array<std::int64_t, 2>> polygon_;
};

// The height and gradient at (x, y) of the least-squares quadratic fitted to `height` on the grid points of the disk
// of radius r about (x, y) that lie in the domain. A quadratic, not a plane, so that the curvature does not bias the
// gradient where the disk is cut by the boundary. Falls back to a plane on too few points; false if even that fails.
template <class Height>
bool fit_tangent_3(const Height& height, const Surface_domain_test_3& inside, double x, double y, double r,
                   std::array<double, 3>& zgxgy)
{
  const int K = 6;
  std::vector<std::array<double, 6>> rows;
  std::vector<double> z;
  for(int i = -K; i <= K; ++i)
    for(int j = -K; j <= K; ++j) {
      if(i * i + j * j > K * K) continue;
      const double dx = r * i / K, dy = r * j / K;
      if(!inside(x + dx, y + dy)) continue;
      rows.push_back({{1, dx, dy, dx * dx, dx * dy, dy * dy}});
      z.push_back(height(x + dx, y + dy));
    }
  for(int columns : {6, 3}) {
    if(rows.size() < std::size_t(2 * columns)) continue;
    Eigen::MatrixXd A(Eigen::Index(rows.size()), columns);
    Eigen::VectorXd b(Eigen::Index(rows.size()));
    for(std::size_t k = 0; k < rows.size(); ++k) {
      for(int c = 0; c < columns; ++c) A(Eigen::Index(k), c) = rows[k][std::size_t(c)];
      b(Eigen::Index(k)) = z[k];
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
    if(qr.rank() < columns) continue;
    const Eigen::VectorXd s = qr.solve(b);
    if(!(std::isfinite(s(0)) && std::isfinite(s(1)) && std::isfinite(s(2)))) continue;
    zgxgy = {{s(0), s(1), s(2)}};
    return true;
  }
  return false;
}

// The slope of `height` from the boundary point (x, y) at height z0 along the unit direction d (into the domain):
// least squares of z - z0 = s t + c t^2 on 8 points t in (0, r]; false on fewer than 3 usable points.
template <class Height>
bool fit_boundary_slope_3(const Height& height, const Surface_domain_test_3& inside, double x, double y, double z0,
                          const std::array<double, 2>& d, double r, double& slope)
{
  double a11 = 0, a12 = 0, a22 = 0, b1 = 0, b2 = 0;
  int used = 0;
  for(int k = 1; k <= 8; ++k) {
    const double t = r * k / 8, px = x + d[0] * t, py = y + d[1] * t;
    if(!inside(px, py)) continue;
    const double z = height(px, py) - z0;
    a11 += t * t; a12 += t * t * t; a22 += t * t * t * t;
    b1 += t * z; b2 += t * t * z;
    ++used;
  }
  const double det = a11 * a22 - a12 * a12;
  if(used < 3 || !(std::abs(det) > 0)) return false;
  slope = (b1 * a22 - b2 * a12) / det;
  return std::isfinite(slope);
}

// The plane z = z0 + gx (X - x) + gy (Y - y) (world) in the lattice of the problem.
inline Lattice_plane_3 world_tangent_plane_3(const Surface_problem_3& problem, double x, double y,
                                             const std::array<double, 3>& zgxgy)
{
  const double L = double(Plane_arrangement_3::lattice_size);
  const auto& d = problem.domain;
  const double sx = (d.xmax() - d.xmin()) / L, sy = (d.ymax() - d.ymin()) / L, sz = (problem.zmax - problem.zmin) / L;
  const std::array<double, 3> normal = {{-zgxgy[1] * sx / sz, -zgxgy[2] * sy / sz, 1.0}};
  const std::array<double, 3> q = {{(x - d.xmin()) / sx, (y - d.ymin()) / sy, (zgxgy[0] - problem.zmin) / sz}};
  return plane_through(normal, q);
}

// One pencil plane through each segment of the lower boundary curve, turned so that its slope across the segment
// (into the domain) is the one fitted to `height`; a segment whose fit fails gets none.
template <class Height>
void add_fitted_boundary_pencils_3(const Surface_problem_3& problem, const Height& height,
                                   const Surface_domain_test_3& inside, double r, std::vector<Lattice_plane_3>& out)
{
  const std::int64_t L = Plane_arrangement_3::lattice_size;
  const auto& dom = problem.domain;
  const double sx = (dom.xmax() - dom.xmin()) / double(L), sy = (dom.ymax() - dom.ymin()) / double(L),
               sz = (problem.zmax - problem.zmin) / double(L);
  const auto loop = problem.boundary_loop(false);
  for(std::size_t i = 0; i < loop.size(); ++i) {
    const auto& p = loop[i];
    const auto& q = loop[(i + 1) % loop.size()];
    const double mx = dom.xmin() + 0.5 * double(p[0] + q[0]) * sx, my = dom.ymin() + 0.5 * double(p[1] + q[1]) * sy;
    const double mz = problem.zmin + 0.5 * double(p[2] + q[2]) * sz;
    std::array<double, 2> d;
    if(problem.is_polygonal()) {
      // The direction polygon_pencil_plane() measures its slope along: the lattice left normal, in world units.
      const double ux = double(q[0] - p[0]), uy = double(q[1] - p[1]);
      d = {{-uy * sx, ux * sy}};
    } else {
      const bool x_wall = p[0] == q[0] && (p[0] == 0 || p[0] == L);
      d = x_wall ? std::array<double, 2>{{p[0] == 0 ? 1.0 : -1.0, 0.0}}
                 : std::array<double, 2>{{0.0, p[1] == 0 ? 1.0 : -1.0}};
    }
    const double len = std::hypot(d[0], d[1]);
    if(!(len > 0)) continue;
    d = {{d[0] / len, d[1] / len}};
    double slope;
    if(!fit_boundary_slope_3(height, inside, mx, my, mz, d, r, slope)) continue;
    if(problem.is_polygonal())
      out.push_back(polygon_pencil_plane(p, q, slope, problem));
    else {
      const double h = d[0] != 0 ? dom.xmax() - dom.xmin() : dom.ymax() - dom.ymin();
      out.push_back(sloped_pencil_plane(p, q, slope * h / (problem.zmax - problem.zmin)));
    }
  }
}

// Points of the domain from jittered grids over its bounding box (one fresh grid of about `count` inside points
// whenever the previous one is used up): spread more evenly than independent uniform points.
class Stratified_domain_points_3
{
public:
  Stratified_domain_points_3(const Surface_problem_3& problem, const Surface_domain_test_3& inside, std::size_t count,
                             std::uint64_t seed)
    : problem_(problem), inside_(inside), count_((std::max)(std::size_t(1), count)), rng_(seed)
  {}

  std::array<double, 2> next()
  {
    while(next_ >= points_.size()) refill();
    return points_[next_++];
  }

private:
  void refill()
  {
    const auto& d = problem_.domain;
    std::uniform_real_distribution<double> U(0, 1);
    // The grid is sized for the share of the box covered by the domain, estimated by the previous grid.
    const double share = grids_ == 0 ? 1.0 : (std::max)(0.05, double(points_.size()) / double(last_grid_));
    const int g = (std::max)(1, int(std::ceil(std::sqrt(double(count_) / share))));
    points_.clear();
    next_ = 0;
    for(int i = 0; i < g; ++i)
      for(int j = 0; j < g; ++j) {
        const double x = d.xmin() + (i + U(rng_)) / g * (d.xmax() - d.xmin()),
                     y = d.ymin() + (j + U(rng_)) / g * (d.ymax() - d.ymin());
        if(inside_(x, y)) points_.push_back({{x, y}});
      }
    last_grid_ = std::size_t(g) * std::size_t(g);
    ++grids_;
    std::shuffle(points_.begin(), points_.end(), rng_);
    if(grids_ > 64 && points_.empty()) throw std::logic_error("MDCS: no sample point falls in the domain");
  }

  const Surface_problem_3& problem_;
  const Surface_domain_test_3& inside_;
  std::size_t count_;
  std::mt19937_64 rng_;
  std::vector<std::array<double, 2>> points_;
  std::size_t next_ = 0, last_grid_ = 1, grids_ = 0;
};

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_TANGENT_FIT_3_H
