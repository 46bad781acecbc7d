// Functional adaptors. Shifted_functional_3: a G bounded below but negative somewhere is rejected as such and
// solved once shifted, with the same optimum as the non-negative functional it equals up to the constant.
// Monte Carlo facet weights (Monte_carlo_functional_3): exact for integrands constant on a facet, within a few
// standard errors of the closed form for a linear one and of the Gauss rule for a smooth one, converging like
// 1/sqrt(samples), deterministic per facet (so a whole solve has energy == cut value), seed-dependent, and bad
// input rejected.
#include <MDCS_test/test_numbers.h>

#include <catch2/catch.hpp>

#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/monte_carlo_functional_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace VM = CGAL::Variational_minimization;

namespace {

using MDCS_test::relative_difference;

const std::vector<std::array<double, 2>> pentagon = {{{0, 0}}, {{1, 0}}, {{1.3, 0.6}}, {{0.5, 1.1}}, {{-0.2, 0.5}}};

// A smooth, non-polynomial integrand of (x, y) only.
struct Bump
{
  double operator()(double, double, double, double x, double y) const
  {
    return 1 + std::exp(-4 * ((x - 0.4) * (x - 0.4) + (y - 0.5) * (y - 0.5)));
  }
};

} // namespace

TEST_CASE("Monte Carlo weights: exact, unbiased, converging, deterministic", "[variational][surface][monte_carlo]")
{
  // Constant on the facet (area): exact whatever the samples.
  const VM::Area_functional_3 area;
  const double closed = VM::surface_polygon_integral_3(area, 0.3, -0.7, 0.2, pentagon);
  CHECK(relative_difference(VM::surface_polygon_integral_3(VM::make_monte_carlo_functional_3(area, 1), 0.3, -0.7, 0.2, pentagon),
            closed) <= 1e-12);
  CHECK(relative_difference(VM::surface_polygon_integral_3(VM::make_monte_carlo_functional_3(area, 37), 0.3, -0.7, 0.2, pentagon),
            closed) <= 1e-12);
  // Linear in f (membrane): against the closed form, within 4 standard errors (the deviation of G over the
  // pentagon is below 0.5, its area about 1.2).
  VM::Membrane_functional_3 membrane;
  membrane.k_g = 1;
  membrane.z_bottom = -2;
  const double exact_m = VM::surface_polygon_integral_3(membrane, 0.3, -0.7, 0.2, pentagon);
  for(unsigned n : {256u, 4096u, 65536u}) {
    const double mc = VM::surface_polygon_integral_3(VM::make_monte_carlo_functional_3(membrane, n), 0.3, -0.7, 0.2,
                                                     pentagon);
    INFO(n << " samples: " << mc << " against " << exact_m);
    CHECK(std::abs(mc - exact_m) <= 4 * 0.5 * 1.2 / std::sqrt(double(n)));
  }
  // Smooth (x, y) integrand: against the Gauss rule subdivided 5 times (converged to 1e-10); the error falls
  // about like 1/sqrt(samples): mean over 20 seeds of the absolute error, 256 against 16384 samples (ratio 8 expected).
  const Bump bump;
  const double gauss = VM::surface_polygon_integral_3(bump, 0.1, 0.2, 0.3, pentagon, 5);
  CHECK(relative_difference(gauss, VM::surface_polygon_integral_3(bump, 0.1, 0.2, 0.3, pentagon, 4)) <= 1e-10);
  double coarse = 0, fine = 0;
  for(std::uint64_t seed = 1; seed <= 20; ++seed) {
    coarse += std::abs(VM::surface_polygon_integral_3(VM::Monte_carlo_functional_3<Bump>(bump, 256, seed), 0.1, 0.2,
                                                      0.3, pentagon) - gauss) / 20;
    fine += std::abs(VM::surface_polygon_integral_3(VM::Monte_carlo_functional_3<Bump>(bump, 16384, seed), 0.1, 0.2,
                                                    0.3, pentagon) - gauss) / 20;
  }
  INFO("mean error 256 samples " << coarse << ", 16384 samples " << fine);
  CHECK(fine < coarse / 3);
  CHECK(fine < 2e-3 * gauss);
  // Deterministic per facet, different for another seed.
  const VM::Monte_carlo_functional_3<Bump> a(bump, 64, 5), b(bump, 64, 6);
  CHECK(a.facet_integral(0.1, 0.2, 0.3, pentagon) == a.facet_integral(0.1, 0.2, 0.3, pentagon));
  CHECK(a.facet_integral(0.1, 0.2, 0.3, pentagon) != b.facet_integral(0.1, 0.2, 0.3, pentagon));
  // Bad input.
  CHECK_THROWS_AS(VM::make_monte_carlo_functional_3(bump, 0), std::invalid_argument);
  const auto negative = [](double, double, double, double x, double) { return x - 0.5; };
  CHECK_THROWS_AS(VM::surface_polygon_integral_3(VM::make_monte_carlo_functional_3(negative, 64), 0.0, 0.0, 0.0,
                                                 pentagon),
                  std::invalid_argument);
}

TEST_CASE("Monte Carlo weights: a whole solve", "[variational][surface][monte_carlo]")
{
  VM::Surface_problem_3 P;
  P.lower_boundary = [](double x, double y) { return 0.5 + 0.6 * (x - 0.5) * (y - 0.5); };
  P.boundary_segments_per_side = 4;
  const auto G = [](double, double fx, double fy, double x, double y) {
    return std::sqrt(1 + fx * fx + fy * fy) * (1 + 0.5 * std::sin(3 * x) * std::cos(2 * y));
  };
  VM::Surface_plane_options_3 o;
  o.seed = 3;
  const VM::Plane_arrangement_3 A(VM::surface_planes_3(P, 60, o));
  const auto mc = VM::make_monte_carlo_functional_3(G, 32);
  // The lean path computes the surface's weights a second time: equal only if each facet's estimate is fixed.
  const VM::Minimal_surface_3 lean = VM::minimize_surface_functional_3(A, P, mc);
  REQUIRE(lean.is_feasible);
  CHECK(relative_difference(lean.energy, lean.solver_value) <= 1e-9);
  CHECK(relative_difference(lean.projected_area, P.domain_area()) <= 1e-9);
  // The weight vector path gives the same optimum value.
  const VM::Minimal_surface_3 vec = VM::minimize_surface_functional_3(A, VM::surface_facet_weights_3(A, P, mc), P);
  CHECK(relative_difference(vec.solver_value, lean.solver_value) <= 1e-9);
  // And it is close to the quadrature solve (32 samples per facet).
  const VM::Minimal_surface_3 gauss = VM::minimize_surface_functional_3(A, P, G);
  INFO("Monte Carlo " << lean.energy << ", Gauss " << gauss.energy);
  CHECK(relative_difference(lean.energy, gauss.energy) <= 0.02);
}

TEST_CASE("Shifted_functional_3: a functional bounded below", "[variational][surface][shift]")
{
  VM::Surface_problem_3 P;
  P.domain = CGAL::Bbox_2(0, 0, 2, 1);
  P.lower_boundary = [](double x, double y) { return 0.5 + 0.3 * (x - 1) * (y - 0.5); };
  P.boundary_segments_per_side = 4;
  VM::Surface_plane_options_3 o;
  o.seed = 9;
  const VM::Plane_arrangement_3 A(VM::surface_planes_3(P, 60, o));
  // Area minus 2: negative everywhere, bounded below by -1.
  const auto G = [](double, double fx, double fy, double, double) { return std::sqrt(1 + fx * fx + fy * fy) - 2; };
  CHECK_THROWS_AS(VM::minimize_surface_functional_3(A, P, G), std::invalid_argument);
  const VM::Minimal_surface_3 area = VM::minimize_surface_functional_3(A, P, VM::Area_functional_3());
  const VM::Minimal_surface_3 shifted = VM::minimize_surface_functional_3(A, P, VM::make_shifted_functional_3(G, 2.0));
  REQUIRE(area.is_feasible);
  REQUIRE(shifted.is_feasible);
  CHECK(relative_difference(shifted.energy, area.energy) <= 1e-9);
  CHECK(shifted.facets == area.facets);
  // The original functional's value of the optimum: the shifted energy minus shift |Ω|.
  CHECK(std::abs((shifted.energy - 2.0 * P.domain_area()) - (area.energy - 4.0)) <= 1e-9);
  // With a closed form (the area's), the shifted functional keeps one: the same weights.
  const VM::Shifted_functional_3<VM::Area_functional_3> closed(VM::Area_functional_3(), 0.25);
  CHECK(relative_difference(VM::surface_polygon_integral_3(closed, 0.3, -0.7, 0.2, pentagon),
            VM::surface_polygon_integral_3(VM::Area_functional_3(), 0.3, -0.7, 0.2, pentagon) +
              0.25 * std::abs(VM::internal::polygon_area_2(pentagon))) <= 1e-12);
  CHECK(closed(0.1, 0.3, -0.7, 0.5, 0.5) == VM::Area_functional_3()(0.1, 0.3, -0.7, 0.5, 0.5) + 0.25);
}
