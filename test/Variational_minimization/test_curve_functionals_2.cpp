// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Variational_minimization/curve_functionals_2.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <type_traits>

namespace VM = CGAL::Variational_minimization;

namespace {

const double two_pi = 6.283185307179586476925286766559;

struct Wrong_signature_edge_weight
{
  double operator()(double, double, double) const { return 1; }
  double edge_weight(const std::string&) const { return 1; }
};

struct Non_const_edge_weight
{
  double operator()(double, double, double) const { return 1; }
  double edge_weight(double, double, double, double, double) { return 1; }
};

struct Unit_density
{
  double operator()(double, double) const { return 1; }
};

} // namespace

TEST_CASE("has_closed_form_edge_weight: detection", "[Variational_minimization][functionals]")
{
  STATIC_REQUIRE(VM::has_closed_form_edge_weight<VM::Surface_of_rotation_functional>::value);
  STATIC_REQUIRE(VM::has_closed_form_edge_weight_v<VM::Arc_length_functional>);
  STATIC_REQUIRE(!VM::has_closed_form_edge_weight_v<VM::Density_weighted_length_functional<Unit_density> >);
  // The adaptor hides the closed form of what it wraps, so it can force quadrature.
  STATIC_REQUIRE(!VM::has_closed_form_edge_weight_v<VM::Callable_functional<VM::Arc_length_functional> >);
  STATIC_REQUIRE(!VM::has_closed_form_edge_weight_v<Wrong_signature_edge_weight>);
  STATIC_REQUIRE(!VM::has_closed_form_edge_weight_v<Non_const_edge_weight>);
  STATIC_REQUIRE(!VM::has_closed_form_edge_weight_v<int>);
}

TEST_CASE("curve functionals: models are copyable", "[Variational_minimization][functionals]")
{
  auto lambda = [](double f, double, double) { return f * f; };
  STATIC_REQUIRE(std::is_copy_constructible<VM::Surface_of_rotation_functional>::value);
  STATIC_REQUIRE(std::is_copy_constructible<VM::Arc_length_functional>::value);
  STATIC_REQUIRE(std::is_copy_constructible<VM::Density_weighted_length_functional<Unit_density> >::value);
  STATIC_REQUIRE(std::is_copy_constructible<decltype(VM::make_callable_functional(lambda))>::value);
}

TEST_CASE("Surface_of_rotation_functional: values", "[Variational_minimization][functionals]")
{
  const VM::Surface_of_rotation_functional G;
  // sqrt(1 + 0.75^2) = 1.25.
  CHECK(G(2, 0.75, 0.3) == Approx(two_pi * 2 * 1.25).epsilon(1e-15));
  CHECK(G(-2, -0.75, -7) == Approx(two_pi * 2 * 1.25).epsilon(1e-15));
  CHECK(G(0, 5, 1) == 0);
  // Huge slopes do not overflow in sqrt(1 + k^2).
  CHECK(G(1, 1e200, 0) == Approx(two_pi * 1e200).epsilon(1e-15));
}

TEST_CASE("Surface_of_rotation_functional: closed-form edge weight", "[Variational_minimization][functionals]")
{
  const VM::Surface_of_rotation_functional G;
  // Entirely above the axis: the trapezoid area (1 + 3)/2 * 2 times 2 pi sqrt(1 + 1).
  CHECK(G.edge_weight(0, 1, 2, 3, 1) == Approx(two_pi * std::sqrt(2.0) * 4).epsilon(1e-14));
  // Entirely below: the same by symmetry.
  CHECK(G.edge_weight(0, -1, 2, -3, -1) == Approx(two_pi * std::sqrt(2.0) * 4).epsilon(1e-14));
  // Crossing f = 0 at x = 1: two triangles of area 1/2 each.
  CHECK(G.edge_weight(0, 1, 2, -1, -1) == Approx(two_pi * std::sqrt(2.0) * 1).epsilon(1e-14));
  // Asymmetric crossing: y from -1 to 3 over [0, 4], zero at x = 1: areas 1/2 and 9/2.
  CHECK(G.edge_weight(0, -1, 4, 3, 1) == Approx(two_pi * std::sqrt(2.0) * 5).epsilon(1e-14));
  // On the axis.
  CHECK(G.edge_weight(0, 0, 1, 0, 0) == 0);
  // The slope argument, not the end points, gives f' (the end points may be rounded).
  CHECK(G.edge_weight(0, 1, 1, 1, 0.75) == Approx(two_pi * 1.25).epsilon(1e-15));
}

TEST_CASE("Arc_length_functional: values and closed form", "[Variational_minimization][functionals]")
{
  const VM::Arc_length_functional G;
  CHECK(G(123, 0.75, -4) == Approx(1.25).epsilon(1e-15));
  CHECK(G.edge_weight(1, 0, 5, 3, 0.75) == Approx(5).epsilon(1e-15));
}

TEST_CASE("Density_weighted_length_functional: values", "[Variational_minimization][functionals]")
{
  const auto G = VM::make_density_weighted_length_functional([](double x, double f) { return x + 2 * f; });
  // rho(x = 3, f = 1) = 5 (argument order (x, f)), times 1.25.
  CHECK(G(1, 0.75, 3) == Approx(6.25).epsilon(1e-15));
  CHECK(G.density()(1, 0) == 1);
}

TEST_CASE("Callable_functional: forwards (f, f', x)", "[Variational_minimization][functionals]")
{
  const auto G = VM::make_callable_functional([](double f, double fp, double x) { return f + 10 * fp + 100 * x; });
  CHECK(G(1, 2, 3) == 321);
  const VM::Callable_functional<VM::Arc_length_functional> wrapped;
  CHECK(wrapped(0, 0.75, 0) == Approx(1.25));
}
