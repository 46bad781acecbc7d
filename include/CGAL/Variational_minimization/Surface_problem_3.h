// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The bivariate variational problem: its domain, range of values and boundary condition, and the map between its
// world coordinates and the integer lattice of Plane_arrangement_3.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_SURFACE_PROBLEM_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_SURFACE_PROBLEM_3_H

#include <CGAL/Bbox_2.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief A bivariate problem: minimise F(f) = ∬_Ω G(f, f_x, f_y, x, y) dx dy over functions
  f : Ω -> [zmin, zmax] with a boundary condition on ∂Ω.

  Ω is the rectangle `domain`. The boundary condition is either *fixed*, f = g on ∂Ω (`lower_boundary = g`,
  `upper_boundary` empty), or *relaxed*, g0 <= f <= g1 on ∂Ω (both set). The boundary curves are sampled at
  `boundary_segments_per_side + 1` points per side (at most 257, at multiples of 1/256 of the side) and rounded to
  the lattice of the arrangement: the discrete problem uses these piecewise linear curves (their vertices are
  within `(zmax - zmin) / 2^17` of g).

  The box Ω x [zmin, zmax] is mapped affinely onto the lattice box [0, L]^3 of `Plane_arrangement_3`.
*/
struct Surface_problem_3
{
  CGAL::Bbox_2 domain = CGAL::Bbox_2(0, 0, 1, 1);
  double zmin = 0;
  double zmax = 1;
  std::function<double(double, double)> lower_boundary;
  std::function<double(double, double)> upper_boundary;
  int boundary_segments_per_side = 8;

  bool is_relaxed() const { return bool(upper_boundary); }

  /// Throws `std::invalid_argument` with a message saying what is wrong.
  void validate() const
  {
    auto fail = [](const std::string& what) { throw std::invalid_argument("MDCS: invalid surface problem: " + what); };
    const double v[6] = {domain.xmin(), domain.xmax(), domain.ymin(), domain.ymax(), zmin, zmax};
    for(double c : v)
      if(!std::isfinite(c)) fail("the domain and the range of values must be finite");
    if(!(domain.xmin() < domain.xmax()) || !(domain.ymin() < domain.ymax()))
      fail("the domain rectangle is empty (need xmin < xmax and ymin < ymax)");
    if(!(zmin < zmax)) fail("the range of values is empty (need zmin < zmax)");
    if(!lower_boundary) fail("no boundary function is given (lower_boundary is empty)");
    if(boundary_segments_per_side < 1 || boundary_segments_per_side > 256)
      fail("boundary_segments_per_side must be in [1, 256]");
    for(const std::array<double, 2>& p : boundary_samples()) {
      const double lo = lower_boundary(p[0], p[1]);
      const double hi = upper_boundary ? upper_boundary(p[0], p[1]) : lo;
      std::ostringstream s;
      s << "at the boundary point (" << p[0] << ", " << p[1] << ") ";
      if(!std::isfinite(lo) || !std::isfinite(hi)) fail(s.str() + "the boundary data is not finite");
      if(lo < zmin || hi > zmax) {
        s << "the boundary data [" << lo << ", " << hi << "] lies outside the range of values [" << zmin << ", "
          << zmax << "]";
        fail(s.str());
      }
      if(lo > hi) fail(s.str() + "the lower boundary lies above the upper boundary");
    }
  }

  /// The boundary sample points of Ω, counter-clockwise from (xmin, ymin), `4 * boundary_segments_per_side` of them.
  std::vector<std::array<double, 2>> boundary_samples() const
  {
    std::vector<std::array<double, 2>> out;
    const int k = boundary_segments_per_side;
    const std::array<double, 2> corner[5] = {{{domain.xmin(), domain.ymin()}}, {{domain.xmax(), domain.ymin()}},
                                             {{domain.xmax(), domain.ymax()}}, {{domain.xmin(), domain.ymax()}},
                                             {{domain.xmin(), domain.ymin()}}};
    for(int s = 0; s < 4; ++s)
      for(int i = 0; i < k; ++i) {
        // The lattice position first, so that the sample is exactly a lattice point of the side.
        const std::int64_t t = lattice_step(i, k);
        const double u = double(t) / double(Plane_arrangement_3::lattice_size);
        out.push_back({{corner[s][0] + u * (corner[s + 1][0] - corner[s][0]),
                        corner[s][1] + u * (corner[s + 1][1] - corner[s][1])}});
      }
    return out;
  }

  /// The lattice loop of the lower (`upper == false`) or upper boundary curve: lattice points (X, Y, Z),
  /// counter-clockwise, one per boundary sample.
  std::vector<std::array<std::int64_t, 3>> boundary_loop(bool upper) const
  {
    const std::int64_t L = Plane_arrangement_3::lattice_size;
    const int k = boundary_segments_per_side;
    std::vector<std::array<std::int64_t, 3>> out;
    const std::vector<std::array<double, 2>> samples = boundary_samples();
    for(std::size_t i = 0; i < samples.size(); ++i) {
      const int s = int(i) / k;
      const std::int64_t t = lattice_step(int(i) % k, k);
      std::int64_t X = 0, Y = 0;
      switch(s) {
      case 0: X = t; Y = 0; break;
      case 1: X = L; Y = t; break;
      case 2: X = L - t; Y = L; break;
      default: X = 0; Y = L - t; break;
      }
      const auto& g = (upper && upper_boundary) ? upper_boundary : lower_boundary;
      const double z = g(samples[i][0], samples[i][1]);
      std::int64_t Z = std::llround((z - zmin) / (zmax - zmin) * double(L));
      Z = (std::max)(std::int64_t(0), (std::min)(L, Z));
      out.push_back({{X, Y, Z}});
    }
    return out;
  }

  /// World coordinates of a lattice point.
  std::array<double, 3> to_world(const std::array<double, 3>& p) const
  {
    const double L = double(Plane_arrangement_3::lattice_size);
    return {{domain.xmin() + p[0] / L * (domain.xmax() - domain.xmin()),
             domain.ymin() + p[1] / L * (domain.ymax() - domain.ymin()), zmin + p[2] / L * (zmax - zmin)}};
  }

  /*!
    The world plane z = A x + B y + C of a non-vertical lattice plane (c != 0), as {A, B, C}.
  */
  std::array<double, 3> world_plane(const Lattice_plane_3& p) const
  {
    const double L = double(Plane_arrangement_3::lattice_size);
    const double sx = (domain.xmax() - domain.xmin()) / L, sy = (domain.ymax() - domain.ymin()) / L,
                 sz = (zmax - zmin) / L;
    const double a = double(p.a), b = double(p.b), c = double(p.c), d = double(p.d);
    const double A = -sz * a / (c * sx), B = -sz * b / (c * sy);
    const double C = zmin - sz / c * (d - a * domain.xmin() / sx - b * domain.ymin() / sy);
    return {{A, B, C}};
  }

  double domain_area() const { return (domain.xmax() - domain.xmin()) * (domain.ymax() - domain.ymin()); }

private:
  // Boundary samples lie at multiples of 2^8 in X and Y, so that planes through two boundary samples and the apex of
  // the boundary cone keep their integer coefficients within the bounds of Lattice_plane_3.
  static std::int64_t lattice_step(int i, int k)
  {
    return 256 * std::llround(double(i) * double(Plane_arrangement_3::lattice_size / 256) / double(k));
  }
};

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_SURFACE_PROBLEM_3_H
