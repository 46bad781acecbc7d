// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Variational_minimization/analytic_solutions_2.h>
#include <CGAL/Variational_minimization/curve_functionals_2.h>
#include <CGAL/Variational_minimization/local_descent_2.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace VM = CGAL::Variational_minimization;

TEST_CASE("local_descent_2: arc length converges to the straight line", "[Variational_minimization][local_descent]")
{
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-2, 2);
  const double a = -1, b = 2, A = 0.5, B = -1.5;
  const double distance = std::hypot(b - a, B - A);
  for(std::size_t m : {1u, 2u, 7u, 50u, 200u}) {
    std::vector<double> start(m + 1);
    for(double& v : start)
      v = u(rng);
    start.front() = A;
    start.back() = B;
    const VM::Local_descent_result r = VM::local_descent_2(VM::Arc_length_functional(), a, b, start);
    INFO("m = " << m << ", iterations " << r.iterations);
    CHECK(r.converged);
    CHECK(r.energy - distance <= 1e-6);
    CHECK(r.energy >= distance - 1e-12);
    REQUIRE(r.values.size() == m + 1);
    CHECK(r.values.front() == A);
    CHECK(r.values.back() == B);
    for(std::size_t i = 0; i <= m; ++i)
      CHECK(r.values[i] == Approx(A + (B - A) * double(i) / double(m)).margin(1e-4));
  }
}

TEST_CASE("local_descent_2: quadrature-only functional works too", "[Variational_minimization][local_descent]")
{
  // Arc length through the quadrature path (no closed form), from a zigzag.
  const auto G = VM::make_callable_functional(VM::Arc_length_functional());
  const VM::Local_descent_result r =
    VM::local_descent_2(G, 0, 1, 0, 1, 20, [](double x) { return std::sin(20 * x); });
  CHECK(r.energy == Approx(std::sqrt(2.0)).epsilon(1e-7));
}

TEST_CASE("local_descent_2: from the shallow catenoid at R = 1.7 it stays on the catenoid",
          "[Variational_minimization][local_descent]")
{
  // The Goldschmidt solution (2 pi 1.7^2 = 18.158) is the global minimum, but a local method started on
  // the catenoid (19.907) cannot get there.
  const double R = 1.7;
  const VM::Surface_of_rotation_minimum global = VM::global_minimum_surface_of_rotation(R);
  REQUIRE(global.branch == VM::Surface_of_rotation_minimum::Branch::Goldschmidt);
  const double c = global.catenoids.c_shallow;
  const VM::Local_descent_result r = VM::local_descent_2(VM::Surface_of_rotation_functional(), -1, 1, R, R, 200,
                                                         [c](double x) { return VM::catenoid_value(c, x); });
  CHECK(r.converged);
  CHECK(r.energy == Approx(global.catenoid_energy).epsilon(0.01));
  CHECK(*std::min_element(r.values.begin(), r.values.end()) > 0.5);
  CHECK(r.energy > global.goldschmidt_energy * 1.05);
  // It also stays near the curve itself.
  for(std::size_t i = 0; i <= 200; ++i)
    CHECK(r.values[i] == Approx(VM::catenoid_value(c, -1 + double(i) / 100.0)).margin(1e-3));
}

TEST_CASE("local_descent_2: at R = 2 from a straight line it reaches the catenoid",
          "[Variational_minimization][local_descent]")
{
  const double R = 2.0;
  const VM::Surface_of_rotation_minimum global = VM::global_minimum_surface_of_rotation(R);
  REQUIRE(global.branch == VM::Surface_of_rotation_minimum::Branch::Catenoid);
  const VM::Local_descent_result r =
    VM::local_descent_2(VM::Surface_of_rotation_functional(), -1, 1, R, R, 200, [R](double) { return R; });
  CHECK(r.converged);
  CHECK(r.energy == Approx(global.energy).epsilon(0.005));
  CHECK(r.energy == Approx(23.967188).epsilon(0.005));
  CHECK(r.values[100] == Approx(global.catenoids.c_shallow).margin(1e-3));
}

TEST_CASE("local_descent_2: below R_min it collapses towards the Goldschmidt solution",
          "[Variational_minimization][local_descent]")
{
  // No catenoid exists at R = 1.5 < R_min = 1.5089: the descent pulls the curve down to the axis, with
  // nearly vertical first and last segments, and the energy approaches 2 pi R^2 from above.
  const double R = 1.5;
  const VM::Local_descent_result r =
    VM::local_descent_2(VM::Surface_of_rotation_functional(), -1, 1, R, R, 200, [R](double) { return R; });
  CHECK(r.energy >= VM::goldschmidt_energy(R));
  CHECK(r.energy == Approx(VM::goldschmidt_energy(R)).epsilon(0.005));
  CHECK(std::fabs(r.values[100]) < 0.01);
}

TEST_CASE("local_descent_2: bounds clamp the interior nodes", "[Variational_minimization][local_descent]")
{
  // Straight line f = 0 is forbidden by ymin = 0.2: the optimum climbs to 0.2 at the first interior node and
  // runs along the bound.
  VM::Local_descent_options options;
  options.ymin = 0.2;
  options.ymax = 5;
  const std::size_t m = 10;
  const VM::Local_descent_result r =
    VM::local_descent_2(VM::Arc_length_functional(), 0, 1, 0, 0, m, [](double x) { return 1 + x; }, options);
  for(std::size_t i = 1; i < m; ++i)
    CHECK(r.values[i] == Approx(0.2).margin(1e-12));
  CHECK(r.values[0] == 0);
  CHECK(r.values[m] == 0);
  CHECK(r.energy == Approx(2 * std::hypot(0.1, 0.2) + 0.8).epsilon(1e-12));
  CHECK(r.converged);
}

TEST_CASE("local_descent_2: stopping and bad input", "[Variational_minimization][local_descent]")
{
  const VM::Arc_length_functional G;
  VM::Local_descent_options few;
  few.max_iterations = 1;
  const VM::Local_descent_result r = VM::local_descent_2(G, 0, 1, 0, 1, 50, [](double x) { return std::sin(9 * x); }, few);
  CHECK(r.stop_reason == VM::Local_descent_stop::Max_iterations);
  CHECK_FALSE(r.converged);
  CHECK(r.iterations == 1);

  const double inf = std::numeric_limits<double>::infinity();
  const auto wall = VM::make_callable_functional([inf](double f, double, double) { return f > 1 ? inf : 1.0; });
  const VM::Local_descent_result w = VM::local_descent_2(wall, 0, 1, 0, 0, 4, [](double) { return 2.0; });
  CHECK(w.stop_reason == VM::Local_descent_stop::Infinite_energy);
  CHECK(w.energy == inf);

  CHECK_THROWS_AS(VM::local_descent_2(G, 1, 0, std::vector<double>{0, 1}), std::invalid_argument);
  CHECK_THROWS_AS(VM::local_descent_2(G, 0, 1, std::vector<double>{0}), std::invalid_argument);
  CHECK_THROWS_AS(VM::local_descent_2(G, 0, 1, std::vector<double>{0, std::nan(""), 1}), std::invalid_argument);
  CHECK_THROWS_AS(VM::local_descent_2(G, 0, 1, 0, 1, 0, [](double) { return 0.0; }), std::invalid_argument);
  VM::Local_descent_options bad;
  bad.ymin = 1;
  bad.ymax = 0;
  CHECK_THROWS_AS(VM::local_descent_2(G, 0, 1, std::vector<double>{0, 0, 1}, bad), std::invalid_argument);
  const auto negative = VM::make_callable_functional([](double f, double, double) { return f; });
  CHECK_THROWS_AS(VM::local_descent_2(negative, 0, 1, std::vector<double>{-1, -1, -1}), std::domain_error);
}
