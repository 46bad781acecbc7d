// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The height of a triangulated single-valued surface (Minimal_surface_3) at a point of the domain: the envelope
// of refine_surface_3().
#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_HEIGHT_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_HEIGHT_3_H

#include <CGAL/Variational_minimization/Minimal_surface_3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

// The height of a single-valued triangulated surface (Minimal_surface_3, world coordinates) at (x, y), by a grid of
// buckets over the triangles' xy boxes. Outside every triangle (rounding at shared edges), the nearest one by
// barycentric violation.
class Surface_height_3
{
public:
  explicit Surface_height_3(const Minimal_surface_3& s) : s_(s)
  {
    if(s.triangles.empty()) throw std::invalid_argument("MDCS: refine_surface_3: an empty surface");
    lo_[0] = lo_[1] = 1e300;
    double hi[2] = {-1e300, -1e300};
    for(const auto& p : s.points)
      for(int i = 0; i < 2; ++i) {
        lo_[i] = (std::min)(lo_[i], p[i]);
        hi[i] = (std::max)(hi[i], p[i]);
      }
    n_ = (std::max)(std::size_t(1), std::size_t(std::sqrt(double(s.triangles.size()))));
    for(int i = 0; i < 2; ++i) step_[i] = (std::max)(hi[i] - lo_[i], 1e-300) / double(n_);
    buckets_.assign(n_ * n_, {});
    for(std::size_t t = 0; t < s.triangles.size(); ++t) {
      double a[2] = {1e300, 1e300}, b[2] = {-1e300, -1e300};
      for(std::uint32_t v : s.triangles[t])
        for(int i = 0; i < 2; ++i) {
          a[i] = (std::min)(a[i], s.points[v][i]);
          b[i] = (std::max)(b[i], s.points[v][i]);
        }
      for(std::size_t j = cell(a[1], 1); j <= cell(b[1], 1); ++j)
        for(std::size_t i = cell(a[0], 0); i <= cell(b[0], 0); ++i) buckets_[j * n_ + i].push_back(std::uint32_t(t));
    }
  }

  double operator()(double x, double y) const
  {
    const std::vector<std::uint32_t>& bucket = buckets_[cell(y, 1) * n_ + cell(x, 0)];
    double best_violation = 1e300, best_z = 0;
    for(std::uint32_t t : bucket) {
      const auto& p = s_.points[s_.triangles[t][0]];
      const auto& q = s_.points[s_.triangles[t][1]];
      const auto& r = s_.points[s_.triangles[t][2]];
      const double det = (q[0] - p[0]) * (r[1] - p[1]) - (r[0] - p[0]) * (q[1] - p[1]);
      if(det == 0) continue;
      const double u = ((x - p[0]) * (r[1] - p[1]) - (r[0] - p[0]) * (y - p[1])) / det;
      const double v = ((q[0] - p[0]) * (y - p[1]) - (x - p[0]) * (q[1] - p[1])) / det;
      const double violation = (std::max)({0.0, -u, -v, u + v - 1});
      if(violation < best_violation) {
        best_violation = violation;
        best_z = p[2] + u * (q[2] - p[2]) + v * (r[2] - p[2]);
        if(violation == 0) break;
      }
    }
    return best_z;
  }

private:
  std::size_t cell(double v, int axis) const
  {
    const double k = std::floor((v - lo_[axis]) / step_[axis]);
    return k <= 0 ? 0 : (std::min)(n_ - 1, std::size_t(k));
  }

  const Minimal_surface_3& s_;
  double lo_[2], step_[2];
  std::size_t n_;
  std::vector<std::vector<std::uint32_t>> buckets_;
};

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_HEIGHT_3_H
