// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <MDCS_test/test_numbers.h>

#include <CGAL/Variational_minimization/curve_functionals_2.h>
#include <CGAL/Variational_minimization/edge_weight_2.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

namespace VM = CGAL::Variational_minimization;

namespace {

using MDCS_test::inf;
const double nan_value = std::numeric_limits<double>::quiet_NaN();

using MDCS_test::relative_difference;

// A closed form that lies, to check that edge_weight_2 validates closed-form results too.
struct Bad_closed_form
{
  double value;
  double operator()(double, double, double) const { return 1; }
  double edge_weight(double, double, double, double, double) const { return value; }
};

// Counts evaluations, to check that closed forms bypass quadrature.
struct Counting_functional
{
  int* count;
  double operator()(double, double fp, double) const
  {
    ++*count;
    return std::hypot(1.0, fp);
  }
};

std::string domain_error_message(const std::function<void()>& f)
{
  try {
    f();
  } catch(const std::domain_error& e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST_CASE("edge_weight_2: surface of rotation closed form vs quadrature on random segments",
          "[Variational_minimization][edge_weight]")
{
  const VM::Surface_of_rotation_functional closed;
  const auto quadrature = VM::make_callable_functional(VM::Surface_of_rotation_functional());
  std::mt19937 rng(20260101);
  std::uniform_real_distribution<double> coordinate(-3, 3), width(1e-4, 2);
  int crossing = 0;
  for(int i = 0; i < 2000; ++i) {
    const double x0 = coordinate(rng), x1 = x0 + width(rng);
    const double y0 = coordinate(rng), y1 = coordinate(rng);
    const double k = (y1 - y0) / (x1 - x0);
    if(y0 * y1 < 0)
      ++crossing;
    const double wc = VM::edge_weight_2(closed, x0, y0, x1, y1, k);
    const double wq = VM::edge_weight_2(quadrature, x0, y0, x1, y1, k);
    INFO("segment (" << x0 << ", " << y0 << ") - (" << x1 << ", " << y1 << ")");
    REQUIRE(relative_difference(wc, wq) <= 1e-9);
  }
  CHECK(crossing > 500); // the kink at f = 0 is well exercised

  // Kinks within 0.43% of a panel end are invisible to Gauss-Kronrod nodes; the end-point check sees them
  // (plain boost::math::quadrature::gauss_kronrod was off by 1e-5 here).
  for(const double y0 : {-0.00651989, -1e-3, -1e-4}) {
    const double x0 = 2.97643, x1 = 4.71106, y1 = 2.78228, k = (y1 - y0) / (x1 - x0);
    CHECK(relative_difference(VM::edge_weight_2(closed, x0, y0, x1, y1, k),
                              VM::edge_weight_2(quadrature, x0, y0, x1, y1, k)) <= 1e-9);
    CHECK(relative_difference(VM::edge_weight_2(closed, x1, -y1, x0, -y0, k),
                              VM::edge_weight_2(quadrature, x1, -y1, x0, -y0, k)) <= 1e-9);
  }
}

TEST_CASE("edge_weight_2: arc length closed form vs quadrature", "[Variational_minimization][edge_weight]")
{
  const VM::Arc_length_functional closed;
  const auto quadrature = VM::make_callable_functional(VM::Arc_length_functional());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-10, 10), width(1e-6, 5);
  for(int i = 0; i < 500; ++i) {
    const double x0 = coordinate(rng), x1 = x0 + width(rng), y0 = coordinate(rng), y1 = coordinate(rng);
    const double k = (y1 - y0) / (x1 - x0);
    const double wc = VM::edge_weight_2(closed, x0, y0, x1, y1, k);
    REQUIRE(relative_difference(wc, VM::edge_weight_2(quadrature, x0, y0, x1, y1, k)) <= 1e-9);
    REQUIRE(relative_difference(wc, std::hypot(x1 - x0, y1 - y0)) <= 1e-12);
  }
}

TEST_CASE("edge_weight_2: closed form bypasses quadrature", "[Variational_minimization][edge_weight]")
{
  int count = 0;
  const Counting_functional counting{&count};
  CHECK(VM::edge_weight_2(counting, 0, 0, 3, 4, 4.0 / 3) == Approx(5).epsilon(1e-12));
  CHECK(count > 0); // no closed form: quadrature evaluated G
  CHECK(count <= 17); // smooth: one panel (15 nodes and the 2 end points)
  CHECK(VM::edge_weight_2(VM::Arc_length_functional(), 0, 0, 3, 4, 4.0 / 3) == Approx(5).epsilon(1e-15));
  // A tolerance below rounding noise must not bisect a smooth integrand down to the depth limit.
  count = 0;
  CHECK(VM::edge_weight_2(counting, 0, 0, 3, 4, 4.0 / 3, 1e-20) == Approx(5).epsilon(1e-14));
  CHECK(count <= 17);
}

TEST_CASE("edge_weight_2: quadrature of known integrals", "[Variational_minimization][edge_weight]")
{
  // int_0^1 x^2 dx along y = x.
  const auto square = VM::make_callable_functional([](double f, double, double) { return f * f; });
  CHECK(VM::edge_weight_2(square, 0, 0, 1, 1, 1) == Approx(1.0 / 3).epsilon(1e-13));
  // int_0^2 (x^2 + k^2) dx = 8/3 + 2 k^2 with k = 0.5.
  const auto mixed = VM::make_callable_functional([](double, double fp, double x) { return x * x + fp * fp; });
  CHECK(VM::edge_weight_2(mixed, 0, 1, 2, 2, 0.5) == Approx(8.0 / 3 + 0.5).epsilon(1e-13));
  // Density rho(x, f) = f along y = 2x + 1 on [0, 1]: sqrt(5) * int (2x + 1) = 2 sqrt(5).
  const auto density = VM::make_density_weighted_length_functional([](double, double f) { return f; });
  CHECK(VM::edge_weight_2(density, 0, 1, 1, 3, 2) == Approx(2 * std::sqrt(5.0)).epsilon(1e-13));
  // A rapidly varying integrand needs adaptive refinement: int_0^pi (1 + sin(40 x)) dx = pi.
  const auto wiggle = VM::make_callable_functional([](double, double, double x) { return 1 + std::sin(40 * x); });
  const double pi = 3.141592653589793238;
  CHECK(VM::edge_weight_2(wiggle, 0, 0, pi, 0, 0) == Approx(pi).epsilon(1e-10));
  // exp(x) along a horizontal line.
  const auto exponential = VM::make_density_weighted_length_functional([](double x, double) { return std::exp(x); });
  CHECK(VM::edge_weight_2(exponential, -1, 5, 2, 5, 0) == Approx(std::exp(2.0) - std::exp(-1.0)).epsilon(1e-13));
}

TEST_CASE("edge_weight_2: tolerance controls quadrature accuracy", "[Variational_minimization][edge_weight]")
{
  // |f| crossing zero: a kink that only adaptive bisection resolves.
  const auto kink = VM::make_callable_functional([](double f, double, double) { return std::fabs(f); });
  const double exact = 0.5 * (0.3 * 0.3 + 1.7 * 1.7); // two triangles on either side of x = 0
  const double loose = VM::edge_weight_2(kink, -0.3, -0.3, 1.7, 1.7, 1, 1e-3);
  const double standard = VM::edge_weight_2(kink, -0.3, -0.3, 1.7, 1.7, 1);
  // Past about 1e-11 the default depth (15) limits the resolution of the kink; a deeper cap lifts it.
  const double deep = VM::edge_weight_2(kink, -0.3, -0.3, 1.7, 1.7, 1, 1e-13, 30);
  CHECK(relative_difference(loose, exact) <= 1e-3);
  CHECK(relative_difference(standard, exact) <= 1e-10);
  CHECK(relative_difference(deep, exact) <= 1e-14);
}

TEST_CASE("edge_weight_2: vertical and degenerate segments", "[Variational_minimization][edge_weight]")
{
  const VM::Surface_of_rotation_functional closed;
  const auto quadrature = VM::make_callable_functional(VM::Surface_of_rotation_functional());
  CHECK(VM::edge_weight_2(closed, 1, 0, 1, 2, inf) == inf);
  CHECK(VM::edge_weight_2(closed, 1, 2, 1, 0, -inf) == inf);
  CHECK(VM::edge_weight_2(quadrature, 1, 0, 1, 2, inf) == inf);
  CHECK(VM::edge_weight_2(closed, 1, 0, 1, 2, VM::segment_slope_2(1, 0, 1, 2)) == inf);
  // Zero length, vertical or not.
  CHECK(VM::edge_weight_2(closed, 1, 2, 1, 2, inf) == 0);
  CHECK(VM::edge_weight_2(quadrature, 1, 2, 1, 2, 0.5) == 0);
  // Zero extent in x on a non-vertical line (rounded end points of a tiny edge).
  CHECK(VM::edge_weight_2(quadrature, 1, 2, 1, 2.0000001, 3) == 0);
  // Orientation does not matter.
  CHECK(VM::edge_weight_2(closed, 2, -1, 0, 1, -1) == Approx(VM::edge_weight_2(closed, 0, 1, 2, -1, -1)));
  CHECK(VM::edge_weight_2(quadrature, 2, -1, 0, 1, -1) == Approx(VM::edge_weight_2(closed, 0, 1, 2, -1, -1)));
}

TEST_CASE("segment_slope_2: values", "[Variational_minimization][edge_weight]")
{
  CHECK(VM::segment_slope_2(0, 0, 2, 1) == 0.5);
  CHECK(VM::segment_slope_2(1, 0, 1, 2) == inf);
  CHECK(VM::segment_slope_2(1, 2, 1, 0) == -inf);
  CHECK(VM::segment_slope_2(1, 2, 1, 2) == 0);
}

TEST_CASE("edge_weight_2: a negative or NaN functional throws", "[Variational_minimization][edge_weight]")
{
  // G = f is negative on the left half of the segment only.
  const auto signed_f = VM::make_callable_functional([](double f, double, double) { return f; });
  CHECK_THROWS_AS(VM::edge_weight_2(signed_f, 0, -1, 2, 1, 1), std::domain_error);
  const std::string message = domain_error_message([&] { VM::edge_weight_2(signed_f, 0, -1, 2, 1, 1); });
  CHECK(message.rfind("MDCS: the functional G must be >= 0 and finite; G(f=", 0) == 0);
  CHECK(message.find("f'=1") != std::string::npos);
  CHECK(message.find("x=") != std::string::npos);
  // Positive on another segment: fine.
  CHECK(VM::edge_weight_2(signed_f, 0, 1, 2, 1, 0) == Approx(2));

  // sqrt of a negative value is NaN.
  const auto root = VM::make_callable_functional([](double f, double, double) { return std::sqrt(f); });
  CHECK_THROWS_AS(VM::edge_weight_2(root, 0, -1, 1, -1, 0), std::domain_error);
  const auto always_nan = VM::make_callable_functional([](double, double, double) { return nan_value; });
  CHECK_THROWS_AS(VM::edge_weight_2(always_nan, 0, 0, 1, 0, 0), std::domain_error);
  const auto minus_inf = VM::make_callable_functional([](double, double, double) { return -inf; });
  CHECK_THROWS_AS(VM::edge_weight_2(minus_inf, 0, 0, 1, 0, 0), std::domain_error);

  // Closed forms are validated too.
  CHECK_THROWS_AS(VM::edge_weight_2(Bad_closed_form{-1}, 0, 0, 1, 0, 0), std::domain_error);
  CHECK_THROWS_AS(VM::edge_weight_2(Bad_closed_form{nan_value}, 0, 0, 1, 0, 0), std::domain_error);
  CHECK(VM::edge_weight_2(Bad_closed_form{inf}, 0, 0, 1, 0, 0) == inf);
}

TEST_CASE("edge_weight_2: an infinite functional gives an infinite weight", "[Variational_minimization][edge_weight]")
{
  // Forbidden region f > 0.5 (e.g. an obstacle).
  const auto obstacle = VM::make_callable_functional([](double f, double fp, double) {
    return f > 0.5 ? inf : std::hypot(1.0, fp);
  });
  CHECK(VM::edge_weight_2(obstacle, 0, 0, 1, 1, 1) == inf);
  CHECK(VM::edge_weight_2(obstacle, 0, 0, 1, 0.25, 0.25) == Approx(std::hypot(1.0, 0.25)));
  // An edge that only touches the closed forbidden region f >= 0.5 at its end point stays finite.
  const auto closed_obstacle = VM::make_callable_functional([](double f, double fp, double) {
    return f >= 0.5 ? inf : std::hypot(1.0, fp);
  });
  CHECK(VM::edge_weight_2(closed_obstacle, 0, 0, 1, 0.5, 0.5) == Approx(std::hypot(1.0, 0.5)).epsilon(1e-12));
  CHECK(VM::edge_weight_2(closed_obstacle, 0, 0.5, 1, 0.5, 0) == inf);
}

TEST_CASE("edge_weight_2: invalid arguments", "[Variational_minimization][edge_weight]")
{
  const VM::Arc_length_functional G;
  CHECK_THROWS_AS(VM::edge_weight_2(G, 0, 0, 1, 1, nan_value), std::invalid_argument);
  CHECK_THROWS_AS(VM::edge_weight_2(G, 0, nan_value, 1, 1, 1), std::invalid_argument);
  CHECK_THROWS_AS(VM::edge_weight_2(G, -inf, 0, 1, 1, 1), std::invalid_argument);
  CHECK_THROWS_AS(VM::edge_weight_2(G, 0, 0, 1, 1, 1, 0.0), std::invalid_argument);
  CHECK_THROWS_AS(VM::edge_weight_2(G, 0, 0, 1, 1, 1, -1e-3), std::invalid_argument);
}
