// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Facet weights of the bivariate problem (thesis eq. 2.5.2): the integral of G(Ax+By+C, A, B, x, y) over the
// projection of each facet, in closed form when the functional offers one, else by Gauss quadrature.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_SURFACE_FACET_WEIGHTS_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_SURFACE_FACET_WEIGHTS_3_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/internal/functional_evaluation_3.h>
#include <CGAL/Variational_minimization/internal/surface_domain_cells_3.h>

#include <algorithm>
#include <array>
#include <type_traits>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

// The degree-5 seven-point rule on the triangle (a, b, c), recursively subdivided `level` times.
template <class Functional>
double triangle_integral(const Functional& G, double A, double B, double C, const std::array<double, 2>& a,
                         const std::array<double, 2>& b, const std::array<double, 2>& c, int level)
{
  if(level > 0) {
    const std::array<double, 2> ab = {{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2}},
                                bc = {{(b[0] + c[0]) / 2, (b[1] + c[1]) / 2}},
                                ca = {{(c[0] + a[0]) / 2, (c[1] + a[1]) / 2}};
    return triangle_integral(G, A, B, C, a, ab, ca, level - 1) + triangle_integral(G, A, B, C, ab, b, bc, level - 1) +
           triangle_integral(G, A, B, C, ca, bc, c, level - 1) + triangle_integral(G, A, B, C, ab, bc, ca, level - 1);
  }
  const double area = 0.5 * std::abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
  if(area == 0) return 0;
  static const double r = 0.0597158717897698, s = 0.4701420641051151, t = 0.7974269853530873,
                      u = 0.1012865073234563;
  static const double wc = 0.225, w1 = 0.1323941527885062, w2 = 0.1259391805448271;
  static const double bary[7][4] = {{1.0 / 3, 1.0 / 3, 1.0 / 3, wc}, {r, s, s, w1}, {s, r, s, w1}, {s, s, r, w1},
                                    {t, u, u, w2},                   {u, t, u, w2}, {u, u, t, w2}};
  double sum = 0;
  for(const auto& q : bary) {
    const double x = q[0] * a[0] + q[1] * b[0] + q[2] * c[0], y = q[0] * a[1] + q[1] * b[1] + q[2] * c[1];
    sum += q[3] * checked_value(G, A * x + B * y + C, A, B, x, y);
  }
  return area * sum;
}

template <class Functional>
double polygon_integral(const Functional& G, double A, double B, double C,
                        const std::vector<std::array<double, 2>>& polygon, int, std::true_type)
{
  const double v = G.facet_integral(A, B, C, polygon);
  if(!(v >= 0) || !std::isfinite(v)) {
    std::ostringstream s;
    s << "MDCS: the functional's facet integral must be finite and >= 0, but it is " << v << " on the plane z = "
      << A << " x + " << B << " y + " << C;
    throw std::invalid_argument(s.str());
  }
  return v;
}

template <class Functional>
double polygon_integral(const Functional& G, double A, double B, double C,
                        const std::vector<std::array<double, 2>>& polygon, int level, std::false_type)
{
  double sum = 0;
  for(std::size_t i = 1; i + 1 < polygon.size(); ++i)
    sum += triangle_integral(G, A, B, C, polygon[0], polygon[i], polygon[i + 1], level);
  if(!std::isfinite(sum)) {   // finite values of G whose integral overflows: +inf would silently forbid the facet
    std::ostringstream s;
    s << "MDCS: the functional's integral over a facet is not finite (its values are finite but too large) on the "
         "plane z = " << A << " x + " << B << " y + " << C << "; scale the functional down";
    throw std::invalid_argument(s.str());
  }
  return sum;
}

} // namespace internal

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief The integral of G(Ax+By+C, A, B, x, y) over the convex polygon `polygon` of the (x, y) plane: the
  functional's `facet_integral` when it has one, else the degree-5 Gauss rule on a fan triangulation subdivided
  `quadrature_level` times (4^level sub-triangles per fan triangle).
  \throws std::invalid_argument if G is negative, NaN or infinite at a quadrature point.
*/
template <class Functional>
double surface_polygon_integral_3(const Functional& G, double A, double B, double C,
                                  const std::vector<std::array<double, 2>>& polygon, int quadrature_level = 1)
{
  if(polygon.size() < 3) return 0;
  return internal::polygon_integral(G, A, B, C, polygon, quadrature_level,
                                    std::integral_constant<bool, internal::has_facet_integral<Functional>::value>());
}

/// The (x, y) projection of a facet in world coordinates, counter-clockwise.
inline std::vector<std::array<double, 2>> surface_facet_projection_3(const Plane_arrangement_3& arrangement,
                                                                     const Surface_problem_3& problem,
                                                                     Plane_arrangement_3::Facet_index f)
{
  std::vector<std::array<double, 2>> poly;
  poly.reserve(arrangement.facet_degree(f));
  for(std::size_t k = 0; k < arrangement.facet_degree(f); ++k) {
    const std::array<double, 3> w = problem.to_world(arrangement.point(arrangement.facet_vertex(f, k)));
    poly.push_back({{w[0], w[1]}});
  }
  if(internal::polygon_area_2(poly) < 0) std::reverse(poly.begin(), poly.end());
  return poly;
}

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief The weight of facet `f` of `arrangement` for the functional `G` (see `surface_facet_weights_3()`).
*/
template <class Functional>
double surface_facet_weight_3(const Plane_arrangement_3& arrangement, const Surface_problem_3& problem,
                              const Functional& G, Plane_arrangement_3::Facet_index f, int quadrature_level = 1)
{
  const Plane_arrangement_3::Plane_index p = arrangement.facet(f).plane;
  if(p < 4) return 0; // side walls
  const Lattice_plane_3& plane = arrangement.plane(p);
  if(plane.c == 0) return std::numeric_limits<double>::infinity();
  const std::array<double, 3> abc = problem.world_plane(plane);
  return surface_polygon_integral_3(G, abc[0], abc[1], abc[2], surface_facet_projection_3(arrangement, problem, f),
                                    quadrature_level);
}

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief The weight of every facet of `arrangement` for the functional `G` (a model of `SurfaceFunctional_3`).
  Vertical facets inside the box weigh +infinity (they cannot belong to a function), facets on the side walls 0
  (they never enter the cut), facets on the floor and the ceiling the integral over them (a function may run
  along them). On a polygonal domain, facets with no cell over Ω weigh 0 (G is not evaluated there).
  `progress` is called with stage `"weights"`.
  \throws std::invalid_argument if the problem is invalid or G is negative or NaN somewhere.
*/
template <class Functional, class Progress = CGAL::MDCS::No_progress>
std::vector<double> surface_facet_weights_3(const Plane_arrangement_3& arrangement, const Surface_problem_3& problem,
                                            const Functional& G, int quadrature_level = 1,
                                            Progress progress = Progress())
{
  problem.validate();
  if(quadrature_level < 0 || quadrature_level > 8)
    throw std::invalid_argument("MDCS: surface_facet_weights_3: quadrature_level must be in [0, 8]");
  const std::size_t n = arrangement.number_of_facets();
  std::vector<double> w(n, 0.0);
  CGAL::MDCS::internal::Progress_reporter<Progress> reporter(progress, "weights", n);
  // A polygonal domain: facets of cells outside Ω only get weight 0 (G is not evaluated outside Ω).
  const bool polygonal = problem.is_polygonal();
  const std::vector<char> inside = polygonal ? internal::surface_domain_cells_3(arrangement, problem)
                                             : std::vector<char>();
  for(std::size_t i = 0; i < n; ++i) {
    reporter(i);
    if(polygonal) {
      const Plane_arrangement_3::Facet& F = arrangement.facet(Plane_arrangement_3::Facet_index(i));
      const bool in = (F.negative_cell != Plane_arrangement_3::null_index && inside[F.negative_cell]) ||
                      (F.positive_cell != Plane_arrangement_3::null_index && inside[F.positive_cell]);
      if(!in) continue;
    }
    w[i] = surface_facet_weight_3(arrangement, problem, G, Plane_arrangement_3::Facet_index(i), quadrature_level);
  }
  reporter.finish();
  return w;
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_SURFACE_FACET_WEIGHTS_3_H
