// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Ready-made bivariate functionals G(f, f_x, f_y, x, y) >= 0 (thesis ch. 2.7.1-2.7.2).
#ifndef CGAL_VARIATIONAL_MINIMIZATION_SURFACE_FUNCTIONALS_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_SURFACE_FUNCTIONALS_3_H

#include <CGAL/Variational_minimization/Surface_problem_3.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  Concept `SurfaceFunctional_3`: a copyable callable `double operator()(double f, double fx, double fy, double x,
  double y) const` returning G >= 0 (a negative or NaN value is reported as an error by the weight computation).
  A model may also provide `double facet_integral(double A, double B, double C, const
  std::vector<std::array<double, 2>>& polygon) const`: the exact integral of G(Ax+By+C, A, B, x, y) over a convex
  polygon of the (x, y) plane (counter-clockwise), used instead of quadrature.
*/
namespace internal {

inline double polygon_area_2(const std::vector<std::array<double, 2>>& p)
{
  double s = 0;
  for(std::size_t i = 0, n = p.size(); i < n; ++i) {
    const auto& a = p[i];
    const auto& b = p[(i + 1) % n];
    s += a[0] * b[1] - a[1] * b[0];
  }
  return 0.5 * s;
}

inline std::array<double, 2> polygon_centroid_2(const std::vector<std::array<double, 2>>& p)
{
  double s = 0, cx = 0, cy = 0;
  for(std::size_t i = 0, n = p.size(); i < n; ++i) {
    const auto& a = p[i];
    const auto& b = p[(i + 1) % n];
    const double w = a[0] * b[1] - a[1] * b[0];
    s += w;
    cx += (a[0] + b[0]) * w;
    cy += (a[1] + b[1]) * w;
  }
  if(s == 0) return p.empty() ? std::array<double, 2>{{0, 0}} : p[0];
  return {{cx / (3 * s), cy / (3 * s)}};
}

template <class F, class = void>
struct has_facet_integral : std::false_type
{};
template <class F>
struct has_facet_integral<F, decltype((void)std::declval<const F&>().facet_integral(
                                        0.0, 0.0, 0.0, std::declval<const std::vector<std::array<double, 2>>&>()))>
  : std::true_type
{};

} // namespace internal

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief A functional that is only bounded below, made non-negative: G + `shift`, with `shift` >= -inf G. Adding a
  constant adds `shift` times |Ω| to every function's energy, so the minimiser is the same; the energy of the
  original functional is the reported energy minus `shift * problem.domain_area()`. When G has a
  `facet_integral`, so has the shifted functional (plus `shift` times the facet's projected area).
*/
template <class Functional, bool = internal::has_facet_integral<Functional>::value>
class Shifted_functional_3
{
public:
  Shifted_functional_3(const Functional& G, double shift) : G_(G), shift_(shift) {}
  double operator()(double f, double fx, double fy, double x, double y) const { return G_(f, fx, fy, x, y) + shift_; }
  double shift() const { return shift_; }
  const Functional& functional() const { return G_; }

protected:
  Functional G_;
  double shift_;
};

template <class Functional>
class Shifted_functional_3<Functional, true> : public Shifted_functional_3<Functional, false>
{
public:
  using Shifted_functional_3<Functional, false>::Shifted_functional_3;
  double facet_integral(double A, double B, double C, const std::vector<std::array<double, 2>>& polygon) const
  {
    return this->G_.facet_integral(A, B, C, polygon) + this->shift_ * std::abs(internal::polygon_area_2(polygon));
  }
};

/// Makes a `Shifted_functional_3`.
template <class Functional>
Shifted_functional_3<Functional> make_shifted_functional_3(const Functional& G, double shift)
{
  return Shifted_functional_3<Functional>(G, shift);
}

/// Area: G = sqrt(1 + f_x^2 + f_y^2). Closed form on a facet: sqrt(1 + A^2 + B^2) times its projected area.
struct Area_functional_3
{
  double operator()(double, double fx, double fy, double, double) const { return std::sqrt(1 + fx * fx + fy * fy); }
  double facet_integral(double A, double B, double, const std::vector<std::array<double, 2>>& polygon) const
  {
    return std::sqrt(1 + A * A + B * B) * std::abs(internal::polygon_area_2(polygon));
  }
};

/*!
  Heavy membrane in a gravity field pointing down (thesis eq. 2.7.2, F1 - k g f with g = -k_g): area plus the
  potential energy k_g f, shifted by the constant -k_g z_bottom |Ω| so that it is non-negative for f >= z_bottom:
  G = sqrt(1 + |∇f|^2) + k_g (f - z_bottom). The minimiser is the same as without the shift; it sags.
*/
struct Membrane_functional_3
{
  double k_g = 1;      ///< density times gravity (>= 0; negative values make the membrane rise)
  double z_bottom = 0; ///< the bottom of the range of values
  double operator()(double f, double fx, double fy, double, double) const
  {
    return std::sqrt(1 + fx * fx + fy * fy) + k_g * (f - z_bottom);
  }
  double facet_integral(double A, double B, double C, const std::vector<std::array<double, 2>>& polygon) const
  {
    // G is linear in f, so it is >= 0 on the facet when it is at the vertices; NaN reports a negative G.
    for(const auto& v : polygon) {
      const double g = std::sqrt(1 + A * A + B * B) + k_g * ((A * v[0] + B * v[1] + C) - z_bottom);
      if(g < -1e-9 * (1 + std::abs(z_bottom))) return std::numeric_limits<double>::quiet_NaN();
    }
    // The integral of a linear function is its value at the centroid times the area.
    const double area = std::abs(internal::polygon_area_2(polygon));
    const std::array<double, 2> c = internal::polygon_centroid_2(polygon);
    return (std::max)(0.0, area * (std::sqrt(1 + A * A + B * B) + k_g * ((A * c[0] + B * c[1] + C) - z_bottom)));
  }
};

/// A 3D Gaussian blob `amplitude * exp(-|p - center|^2 / (2 sigma^2))` (in the exponent of the density).
struct Gaussian_blob_3
{
  double x, y, z, sigma, amplitude;
};

/*!
  Density-weighted area (thesis 2.7.2): G = D(x, y, f) sqrt(1 + |∇f|^2) with D = base * exp(sum of Gaussian blobs):
  always positive; a blob of negative amplitude is a cheap *well* the surface wants to pass through, one of
  positive amplitude an obstacle. With m blob columns and k wells per column there are about (k + 1)^m locally
  minimal functions.
*/
struct Density_weighted_area_functional_3
{
  double base = 1;
  std::vector<Gaussian_blob_3> blobs;
  double density(double x, double y, double z) const
  {
    double e = 0;
    for(const Gaussian_blob_3& b : blobs) {
      const double r2 = (x - b.x) * (x - b.x) + (y - b.y) * (y - b.y) + (z - b.z) * (z - b.z);
      e += b.amplitude * std::exp(-r2 / (2 * b.sigma * b.sigma));
    }
    return base * std::exp(e);
  }
  double operator()(double f, double fx, double fy, double x, double y) const
  {
    return density(x, y, f) * std::sqrt(1 + fx * fx + fy * fy);
  }
};

/*!
  The blob field of the thesis's experiment: `m` locations over Ω (a jittered grid), `k` blobs at random heights in
  (zmin, zmax) above each (at least 3 sigma apart when room allows), all of width `sigma` and amplitude `amplitude`
  (negative: wells), on a base density 1.
*/
inline Density_weighted_area_functional_3 random_blob_functional_3(const Surface_problem_3& problem, int m, int k,
                                                                   double sigma, double amplitude,
                                                                   std::uint64_t seed)
{
  Density_weighted_area_functional_3 G;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  const int side = int(std::ceil(std::sqrt(double(m))));
  const double w = problem.domain.xmax() - problem.domain.xmin(), h = problem.domain.ymax() - problem.domain.ymin();
  for(int i = 0; i < m; ++i) {
    const double cx = problem.domain.xmin() + w * ((i % side) + 0.25 + 0.5 * U(rng)) / side;
    const double cy = problem.domain.ymin() + h * ((i / side) + 0.25 + 0.5 * U(rng)) / side;
    std::vector<double> heights;
    for(int j = 0; j < k; ++j) {
      double z = 0;
      for(int attempt = 0; attempt < 100; ++attempt) {
        z = problem.zmin + (problem.zmax - problem.zmin) * (0.1 + 0.8 * U(rng));
        bool apart = true;
        for(double h : heights) apart = apart && std::abs(h - z) >= 3 * sigma;
        if(apart) break;
      }
      heights.push_back(z);
      G.blobs.push_back(Gaussian_blob_3{cx, cy, z, sigma, amplitude});
    }
  }
  return G;
}

/*!
  The two-level blob field of the thesis's Table 2.4 (ch. 2.7.2): the field of `random_blob_functional_3(problem, m,
  k, sigma, amplitude, seed)` plus as many blobs again (m k), `detail_ratio` times narrower (the thesis: 5), of the
  same amplitude, at uniformly random points of Ω x (zmin + 0.1 (zmax - zmin), zmax - 0.1 (zmax - zmin)). The narrow
  blobs are a second, finer level of detail: they change the energy of a surface by much less than the wide ones,
  so the coarse structure decides the basin and the fine one the exact optimum inside it.
  \throws std::invalid_argument unless detail_ratio >= 1
*/
inline Density_weighted_area_functional_3 two_level_blob_functional_3(const Surface_problem_3& problem, int m, int k,
                                                                      double sigma, double amplitude,
                                                                      std::uint64_t seed, double detail_ratio = 5)
{
  if(!(detail_ratio >= 1) || !std::isfinite(detail_ratio))
    throw std::invalid_argument("MDCS: two_level_blob_functional_3: detail_ratio must be finite and >= 1");
  Density_weighted_area_functional_3 G = random_blob_functional_3(problem, m, k, sigma, amplitude, seed);
  // A generator of its own, so that the coarse level is exactly random_blob_functional_3's field.
  std::mt19937_64 rng(seed ^ 0xD1B54A32D192ED03ull);
  std::uniform_real_distribution<double> U(0, 1);
  const double w = problem.domain.xmax() - problem.domain.xmin(), h = problem.domain.ymax() - problem.domain.ymin();
  const std::size_t coarse = G.blobs.size();
  for(std::size_t i = 0; i < coarse; ++i) {
    const double x = problem.domain.xmin() + w * U(rng), y = problem.domain.ymin() + h * U(rng);
    const double z = problem.zmin + (problem.zmax - problem.zmin) * (0.1 + 0.8 * U(rng));
    G.blobs.push_back(Gaussian_blob_3{x, y, z, sigma / detail_ratio, amplitude});
  }
  return G;
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_SURFACE_FUNCTIONALS_3_H
