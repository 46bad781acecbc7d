// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Analytic oracle for bivariate problems: Scherk's minimal surface f(x, y) = ln(cos y / cos x).

#ifndef CGAL_VARIATIONAL_MINIMIZATION_ANALYTIC_SOLUTIONS_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_ANALYTIC_SOLUTIONS_3_H

#include <CGAL/Variational_minimization/Surface_problem_3.h>

#include <cmath>
#include <stdexcept>

namespace CGAL {
namespace Variational_minimization {

/// \ingroup PkgVariationalMinimizationSurfaces
/// Scherk's first surface \f$ f(x, y) = \ln(\cos y / \cos x) \f$, a minimal surface on \f$ |x|, |y| < \pi/2 \f$.
inline double scherk_surface_height(double x, double y) { return std::log(std::cos(y) / std::cos(x)); }

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief The area problem whose minimiser is Scherk's surface: the domain \f$ [-1.2, 1.2]^2 \f$ (where the surface
  stays within \f$ |z| < 1.1 \f$), the box \f$ [-1.1, 1.1] \f$ in z, fixed boundary values
  `scherk_surface_height()` sampled at `segments_per_side` segments per side. Its reference energy is
  `scherk_surface_area(1.2)`.
*/
inline Surface_problem_3 scherk_surface_problem_3(int segments_per_side = 4)
{
  Surface_problem_3 P;
  const double a = 1.2;
  P.domain = CGAL::Bbox_2(-a, -a, a, a);
  P.zmin = -1.1;
  P.zmax = 1.1;
  P.boundary_segments_per_side = segments_per_side;
  P.lower_boundary = [](double x, double y) { return scherk_surface_height(x, y); };
  return P;
}

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief The area of Scherk's surface over \f$ [-a, a]^2 \f$, \f$ 0 < a < \pi/2 \f$: the reference of the
  tests and benchmarks (the surface is the minimiser of the area for its own boundary values).

  The integrand \f$ \sqrt{1 + \tan^2 x + \tan^2 y} \f$ is smooth on the square, so a 5-point Gauss-Legendre
  rule on `panels` x `panels` squares converges fast (a = 1.2: 60 panels give about 1e-12 relative).
  \throws std::invalid_argument unless 0 < a < pi/2 and panels >= 1
*/
inline double scherk_surface_area(double a, int panels = 160)
{
  if(!(a > 0 && a < 1.5707963267948966) || panels < 1)
    throw std::invalid_argument("MDCS: scherk_surface_area: needs 0 < a < pi/2 and at least one panel");
  static const double x[5] = {-0.9061798459386640, -0.5384693101056831, 0, 0.5384693101056831, 0.9061798459386640};
  static const double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                              0.2369268850561891};
  const double h = 2 * a / panels;
  double sum = 0;
  for(int i = 0; i < panels; ++i)
    for(int j = 0; j < panels; ++j)
      for(int k = 0; k < 5; ++k)
        for(int l = 0; l < 5; ++l) {
          const double tu = std::tan(-a + h * (i + 0.5 + 0.5 * x[k])), tv = std::tan(-a + h * (j + 0.5 + 0.5 * x[l]));
          sum += w[k] * w[l] * std::sqrt(1 + tu * tu + tv * tv);
        }
  return sum * h * h / 4;
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_ANALYTIC_SOLUTIONS_3_H
