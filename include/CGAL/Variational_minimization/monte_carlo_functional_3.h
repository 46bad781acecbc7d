// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Monte Carlo facet weights (issue 6 item 2, "Monte Carlo as an option"): a functional adaptor whose facet
// integral is the mean of G at random points of the facet's projection times its area. For functionals that are
// expensive or rough (a sampled density, a table lookup), where the Gauss rule's fixed points can alias.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_MONTE_CARLO_FUNCTIONAL_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_MONTE_CARLO_FUNCTIONAL_3_H

#include <CGAL/Variational_minimization/internal/functional_evaluation_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

inline std::uint64_t splitmix64(std::uint64_t& state)
{
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

inline std::uint64_t double_bits(double v)
{
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

} // namespace internal

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief A model of `SurfaceFunctional_3` that evaluates G like `Functional` but integrates it over a facet by
  Monte Carlo: `samples` points uniform in the facet's projection (a fan triangle chosen by area, then a uniform
  point in it), the weight being the area times the mean of G. The random stream of a facet is seeded by `seed`
  and the bits of its plane and vertices, so a facet always gets the same weight (whatever the order of
  evaluation: the lean solve computes the surface's weights twice and the energy must equal the cut value) and
  runs are reproducible. The standard error falls as 1/sqrt(samples); for a G constant on each facet (area,
  a functional of (f_x, f_y) only) the estimate is exact. Use it through every function that takes a
  functional: `surface_facet_weights_3(arrangement, problem, Monte_carlo_functional_3<G>(g, 64))`.
  \throws std::invalid_argument (constructor) if `samples` is 0; (integration) if G is negative, NaN or
          infinite at a sample.
*/
template <class Functional>
class Monte_carlo_functional_3
{
public:
  Monte_carlo_functional_3(const Functional& G, unsigned samples, std::uint64_t seed = 1)
    : G_(G), samples_(samples), seed_(seed)
  {
    if(samples == 0) throw std::invalid_argument("MDCS: Monte_carlo_functional_3: at least one sample is needed");
  }

  double operator()(double f, double fx, double fy, double x, double y) const { return G_(f, fx, fy, x, y); }

  double facet_integral(double A, double B, double C, const std::vector<std::array<double, 2>>& polygon) const
  {
    if(polygon.size() < 3) return 0;
    std::vector<double> cumulative;
    cumulative.reserve(polygon.size() - 2);
    double area = 0;
    for(std::size_t i = 1; i + 1 < polygon.size(); ++i) {
      const auto& a = polygon[0];
      const auto& b = polygon[i];
      const auto& c = polygon[i + 1];
      area += 0.5 * std::abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
      cumulative.push_back(area);
    }
    if(!(area > 0)) return 0;
    std::uint64_t state = seed_ ^ internal::double_bits(A);
    state = internal::splitmix64(state) ^ internal::double_bits(B);
    state = internal::splitmix64(state) ^ internal::double_bits(C);
    for(const auto& p : polygon) {
      state = internal::splitmix64(state) ^ internal::double_bits(p[0]);
      state = internal::splitmix64(state) ^ internal::double_bits(p[1]);
    }
    const auto uniform = [&state]() { return double(internal::splitmix64(state) >> 11) * 0x1.0p-53; };
    double sum = 0;
    for(unsigned k = 0; k < samples_; ++k) {
      const double pick = uniform() * area;
      const std::size_t t = std::size_t(std::lower_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin());
      const auto& a = polygon[0];
      const auto& b = polygon[(std::min)(t, cumulative.size() - 1) + 1];
      const auto& c = polygon[(std::min)(t, cumulative.size() - 1) + 2];
      // A uniform point of the triangle: fold the unit square's upper half back.
      double u = uniform(), v = uniform();
      if(u + v > 1) {
        u = 1 - u;
        v = 1 - v;
      }
      const double x = a[0] + u * (b[0] - a[0]) + v * (c[0] - a[0]), y = a[1] + u * (b[1] - a[1]) + v * (c[1] - a[1]);
      sum += internal::checked_value(G_, A * x + B * y + C, A, B, x, y);
    }
    return area * sum / double(samples_);
  }

  const Functional& functional() const { return G_; }
  unsigned samples() const { return samples_; }

private:
  Functional G_;
  unsigned samples_;
  std::uint64_t seed_;
};

/// Makes a `Monte_carlo_functional_3`.
template <class Functional>
Monte_carlo_functional_3<Functional> make_monte_carlo_functional_3(const Functional& G, unsigned samples,
                                                                   std::uint64_t seed = 1)
{
  return Monte_carlo_functional_3<Functional>(G, samples, seed);
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_MONTE_CARLO_FUNCTIONAL_3_H
