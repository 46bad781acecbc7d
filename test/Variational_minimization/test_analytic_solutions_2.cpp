// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <MDCS_test/test_numbers.h>

#include <CGAL/Variational_minimization/analytic_solutions_2.h>
#include <CGAL/Variational_minimization/curve_functionals_2.h>
#include <CGAL/Variational_minimization/edge_weight_2.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace VM = CGAL::Variational_minimization;

namespace {

using MDCS_test::pi;

// Area of the surface of rotation of c cosh(x / c) on [-h, h] by direct quadrature of 2 pi f sqrt(1 + f'^2).
double catenoid_area_by_quadrature(double c, double h)
{
  auto integrand = [c](double x) {
    const double f = c * std::cosh(x / c), fp = std::sinh(x / c);
    return 2 * pi * f * std::sqrt(1 + fp * fp);
  };
  return boost::math::quadrature::gauss_kronrod<double, 15>::integrate(integrand, -h, h, 20, 1e-14);
}

using Branch = VM::Surface_of_rotation_minimum::Branch;

} // namespace

TEST_CASE("catenoid_minimum_radius: critical values", "[Variational_minimization][analytic]")
{
  // Reference values from 30-digit arithmetic (mpmath): t* tanh t* = 1, t* = 1.19967864025773...
  CHECK(VM::catenoid_critical_parameter() == Approx(0.833556559600964698).epsilon(1e-15));
  CHECK(VM::catenoid_minimum_radius() == Approx(1.508879561538319929).epsilon(1e-15));
  // Both scale with h.
  CHECK(VM::catenoid_minimum_radius(2.5) == Approx(2.5 * 1.508879561538319929).epsilon(1e-15));
  CHECK(VM::catenoid_critical_parameter(0.1) == Approx(0.0833556559600964698).epsilon(1e-15));
  // R_min is the minimum of c cosh(h / c) over c.
  const double c_star = VM::catenoid_critical_parameter(), r_min = VM::catenoid_minimum_radius();
  for(double dc : {-1e-3, 1e-3, -0.1, 0.1})
    CHECK(VM::catenoid_value(c_star + dc, 1) > r_min);
}

TEST_CASE("catenoid_solutions: R = 2, h = 1", "[Variational_minimization][analytic]")
{
  const VM::Catenoid_solutions s = VM::catenoid_solutions(2.0);
  REQUIRE(s.exists);
  CHECK(s.c_shallow == Approx(1.69667587619).epsilon(1e-11));
  CHECK(s.c_deep == Approx(0.470189980469).epsilon(1e-11));
  CHECK(std::fabs(VM::catenoid_value(s.c_shallow, 1) - 2) <= 4e-15);
  CHECK(std::fabs(VM::catenoid_value(s.c_deep, 1) - 2) <= 4e-15);
  CHECK(VM::catenoid_value(s.c_shallow, -1) == VM::catenoid_value(s.c_shallow, 1));
  CHECK(VM::catenoid_energy(s.c_shallow) == Approx(23.967188).epsilon(1e-7));
  CHECK(VM::catenoid_energy(s.c_shallow) == Approx(23.9671879032).epsilon(1e-11));
  CHECK(VM::catenoid_energy(s.c_deep) == Approx(27.3826215772).epsilon(1e-11));
}

TEST_CASE("catenoid_energy: formula matches quadrature of the area", "[Variational_minimization][analytic]")
{
  for(double c : {0.4, 0.8335, 1.0, 1.69667587619, 5.0})
    for(double h : {0.5, 1.0, 2.0})
      CHECK(VM::catenoid_energy(c, h) == Approx(catenoid_area_by_quadrature(c, h)).epsilon(1e-12));
}

TEST_CASE("catenoid_energy: discretised curves converge to it", "[Variational_minimization][analytic]")
{
  // Chords of the catenoid on a fine uniform grid, weighed with the surface of rotation's edge weights.
  const double c = VM::catenoid_solutions(2.0).c_shallow;
  const VM::Surface_of_rotation_functional G;
  const int m = 4000;
  double sum = 0;
  for(int i = 0; i < m; ++i) {
    const double x0 = -1 + 2.0 * i / m, x1 = -1 + 2.0 * (i + 1) / m;
    const double y0 = VM::catenoid_value(c, x0), y1 = VM::catenoid_value(c, x1);
    sum += VM::edge_weight_2(G, x0, y0, x1, y1, (y1 - y0) / (x1 - x0));
  }
  // Chords are O(dx^2) off the curve; the polygon's area is within about 1e-6 relative.
  CHECK(sum == Approx(VM::catenoid_energy(c)).epsilon(1e-6));
}

TEST_CASE("catenoid_solutions: existence threshold and branches", "[Variational_minimization][analytic]")
{
  CHECK_FALSE(VM::catenoid_solutions(1.5).exists);
  CHECK_FALSE(VM::catenoid_solutions(1.0).exists);
  CHECK_FALSE(VM::catenoid_solutions(1e-300).exists);
  CHECK(std::isnan(VM::catenoid_solutions(1.0).c_shallow));
  // At R_min (rounded to double) both branches meet at c*.
  const VM::Catenoid_solutions at_min = VM::catenoid_solutions(VM::catenoid_minimum_radius());
  REQUIRE(at_min.exists);
  CHECK(at_min.c_shallow == Approx(VM::catenoid_critical_parameter()).epsilon(1e-7));
  CHECK(at_min.c_deep == Approx(VM::catenoid_critical_parameter()).epsilon(1e-7));
  // Just above: two roots close to c*, on either side, with tiny residuals.
  const VM::Catenoid_solutions just_above = VM::catenoid_solutions(VM::catenoid_minimum_radius() * (1 + 1e-10));
  REQUIRE(just_above.exists);
  CHECK(just_above.c_shallow > VM::catenoid_critical_parameter());
  CHECK(just_above.c_deep < VM::catenoid_critical_parameter());
  CHECK(just_above.c_shallow == Approx(VM::catenoid_critical_parameter()).epsilon(1e-4));
  // Wide range of R, and scaling with h.
  for(double R : {1.51, 1.6, 3.0, 10.0, 1e3, 1e6}) {
    const VM::Catenoid_solutions s = VM::catenoid_solutions(R);
    REQUIRE(s.exists);
    CHECK(s.c_deep < s.c_shallow);
    CHECK(VM::catenoid_value(s.c_shallow, 1) == Approx(R).epsilon(1e-14));
    CHECK(VM::catenoid_value(s.c_deep, 1) == Approx(R).epsilon(1e-14));
    const VM::Catenoid_solutions scaled = VM::catenoid_solutions(3 * R, 3.0);
    CHECK(scaled.c_shallow == Approx(3 * s.c_shallow).epsilon(1e-14));
    CHECK(scaled.c_deep == Approx(3 * s.c_deep).epsilon(1e-14));
  }
}

TEST_CASE("global_minimum_surface_of_rotation: which branch wins", "[Variational_minimization][analytic]")
{
  // Below R_min: no catenoid at all.
  for(double R : {0.5, 1.0, 1.5}) {
    const VM::Surface_of_rotation_minimum s = VM::global_minimum_surface_of_rotation(R);
    CHECK(s.branch == Branch::Goldschmidt);
    CHECK_FALSE(s.catenoids.exists);
    CHECK(s.energy == Approx(2 * pi * R * R).epsilon(1e-15));
    CHECK(std::isnan(s.catenoid_energy));
  }
  // Catenoids exist but cost more than the two discs.
  for(double R : {1.6, 1.7, 1.85}) {
    const VM::Surface_of_rotation_minimum s = VM::global_minimum_surface_of_rotation(R);
    CHECK(s.branch == Branch::Goldschmidt);
    CHECK(s.catenoids.exists);
    CHECK(s.catenoid_energy > s.goldschmidt_energy);
    CHECK(s.energy == s.goldschmidt_energy);
    CHECK(s.goldschmidt_energy == Approx(VM::goldschmidt_energy(R)));
  }
  // The catenoid wins.
  for(double R : {1.95, 2.0, 2.2}) {
    const VM::Surface_of_rotation_minimum s = VM::global_minimum_surface_of_rotation(R);
    CHECK(s.branch == Branch::Catenoid);
    CHECK(s.catenoid_energy < s.goldschmidt_energy);
    CHECK(s.energy == Approx(VM::catenoid_energy(s.catenoids.c_shallow)).epsilon(1e-15));
  }
  // Values (mpmath references) at the tested radii.
  CHECK(VM::global_minimum_surface_of_rotation(1.7).catenoid_energy == Approx(19.9071341663).epsilon(1e-10));
  CHECK(VM::global_minimum_surface_of_rotation(1.7).energy == Approx(18.1584055377).epsilon(1e-10));
  CHECK(VM::global_minimum_surface_of_rotation(1.85).catenoid_energy == Approx(21.9569826335).epsilon(1e-10));
  CHECK(VM::global_minimum_surface_of_rotation(1.95).energy == Approx(23.3004241166).epsilon(1e-10));
  CHECK(VM::global_minimum_surface_of_rotation(2.2).energy == Approx(26.6097942435).epsilon(1e-10));
}

TEST_CASE("catenoid_goldschmidt_crossover_radius: value", "[Variational_minimization][analytic]")
{
  const double r = VM::catenoid_goldschmidt_crossover_radius();
  CHECK(r == Approx(1.89502545541442).epsilon(1e-12));
  CHECK(VM::global_minimum_surface_of_rotation(r * (1 - 1e-9)).branch == Branch::Goldschmidt);
  CHECK(VM::global_minimum_surface_of_rotation(r * (1 + 1e-9)).branch == Branch::Catenoid);
  CHECK(VM::catenoid_goldschmidt_crossover_radius(2.0) == Approx(2 * r).epsilon(1e-12));
}

TEST_CASE("analytic solutions: invalid input throws", "[Variational_minimization][analytic]")
{
  const double nan_value = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(VM::catenoid_solutions(-1.0), std::invalid_argument);
  CHECK_THROWS_AS(VM::catenoid_solutions(0.0), std::invalid_argument);
  CHECK_THROWS_AS(VM::catenoid_solutions(nan_value), std::invalid_argument);
  CHECK_THROWS_AS(VM::catenoid_solutions(2.0, 0.0), std::invalid_argument);
  CHECK_THROWS_AS(VM::catenoid_solutions(2.0, std::numeric_limits<double>::infinity()), std::invalid_argument);
  CHECK_THROWS_AS(VM::catenoid_value(0.0, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(VM::catenoid_energy(-1.0, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(VM::goldschmidt_energy(nan_value), std::invalid_argument);
  CHECK_THROWS_AS(VM::global_minimum_surface_of_rotation(2.0, -1.0), std::invalid_argument);
}
