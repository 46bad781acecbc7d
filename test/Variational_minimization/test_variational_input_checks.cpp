// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Hostile options and functionals at the entry points of Variational_minimization (issue 28): slopes (inf looped
// for ever, 1e308 overflowed an integer and dropped every plane), counts that size an allocation (1e12 planes or
// lines grew without bound), ranges that overflow, and results that are never reported with a non-finite energy
// (functionals whose values are finite but add up beyond the double range).

#include <catch2/catch.hpp>

#include <MDCS_test/surface_problems.h>

#include <CGAL/Variational_minimization/Curve_problem_2.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/curve_edge_weights_2.h>
#include <CGAL/Variational_minimization/curve_functionals_2.h>
#include <CGAL/Variational_minimization/line_grids_2.h>
#include <CGAL/Variational_minimization/minimize_curve_functional_2.h>
#include <CGAL/Variational_minimization/minimize_on_regular_grid_2.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/relax_surface_3.h>
#include <CGAL/Variational_minimization/select_planes_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <MDCS_test/curve_problems.h>
#include <MDCS_test/test_numbers.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace VM = CGAL::Variational_minimization;

namespace {

using MDCS_test::inf;
const double qnan = std::numeric_limits<double>::quiet_NaN();

VM::Surface_problem_3 fine_saddle_problem() { return MDCS_test::saddle_problem(4); }

// A surface functional that is finite everywhere but so large that its integral over 25 units of area overflows.
struct Huge_functional_3
{
  double operator()(double, double, double, double, double) const { return 1e307; }
};

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace

TEST_CASE("variational checks: max_slope must be finite, positive and representable in the lattice", "[variational][checks]")
{
  const VM::Surface_problem_3 P = fine_saddle_problem();
  CHECK(VM::surface_max_slope_3(P) == Approx(std::ldexp(1.0, 20)));   // unit box, unit range
  for(VM::Plane_distribution_3 d : {VM::Plane_distribution_3::slope_limited, VM::Plane_distribution_3::isotropic}) {
    for(double bad : {inf, qnan, 0.0, -1.0, 1e308, 2.0 * std::ldexp(1.0, 20)}) {
      VM::Surface_plane_options_3 o;
      o.distribution = d;
      o.max_slope = bad;
      INFO("max_slope " << bad << ", distribution " << int(d));
      // `surface --max-slope inf` looped for ever; 1e308 overflowed an integer and dropped every plane
      const auto t0 = std::chrono::steady_clock::now();
      CHECK_THROWS_AS(VM::surface_planes_3(P, 40, o), std::invalid_argument);
      CHECK_THROWS_WITH(VM::surface_planes_3(P, 40, o), Catch::Contains("max_slope"));
      CHECK(seconds_since(t0) < 5);
    }
  }
  // the steepest allowed slope still gives non-vertical planes, every one of them used by the arrangement
  VM::Surface_plane_options_3 steep;
  steep.distribution = VM::Plane_distribution_3::slope_limited;
  steep.max_slope = VM::surface_max_slope_3(P);
  const std::vector<VM::Lattice_plane_3> planes = VM::surface_planes_3(P, 30, steep);
  REQUIRE(planes.size() == 30u);
  std::size_t non_vertical = 0;
  for(const auto& p : planes) non_vertical += p.c != 0;
  CHECK(non_vertical >= 20u);
  const VM::Plane_arrangement_3 A(planes);
  CHECK(A.number_of_cells() > 1u);
  // a modest slope solves the problem as usual
  steep.max_slope = 3;
  const VM::Plane_arrangement_3 B = VM::build_surface_arrangement_3(P, VM::surface_planes_3(P, 40, steep));
  const VM::Minimal_surface_3 s = VM::minimize_surface_functional_3(B, P, VM::Area_functional_3());
  CHECK(s.is_feasible);
  CHECK(std::isfinite(s.energy));
  // the other options
  VM::Surface_plane_options_3 o;
  o.pencil_fraction = qnan;
  CHECK_THROWS_AS(VM::surface_planes_3(P, 40, o), std::invalid_argument);
  o = VM::Surface_plane_options_3();
  o.selection_near_spread = inf;
  CHECK_THROWS_AS(VM::surface_planes_3(P, 40, o), std::invalid_argument);
  o = VM::Surface_plane_options_3();
  o.selection_near_fraction = qnan;
  CHECK_THROWS_AS(VM::select_planes_3(P, VM::Area_functional_3(), 40, 2, o), std::invalid_argument);
}

TEST_CASE("variational checks: counts that would size huge allocations are refused at once", "[variational][checks]")
{
  const VM::Surface_problem_3 P = fine_saddle_problem();
  const auto t0 = std::chrono::steady_clock::now();
  // `surface --planes 1e12` grew without bound
  CHECK_THROWS_WITH(VM::surface_planes_3(P, std::size_t(1e12)), Catch::Contains("planes"));
  CHECK_THROWS_AS(VM::surface_planes_3(P, VM::surface_max_planes_3() + 1), std::invalid_argument);
  CHECK_THROWS_AS(VM::select_planes_3(P, VM::Area_functional_3(), std::size_t(1e12), 2), std::invalid_argument);
  CHECK_THROWS_AS(VM::refine_surface_3(P, VM::Area_functional_3(), std::size_t(1e12), 2), std::invalid_argument);
  // lines and regular grids
  const CGAL::Bbox_2 box(0, 0, 1, 1);
  CHECK_THROWS_WITH(VM::random_lines_2(box, std::size_t(1e12), 1), Catch::Contains("lines"));
  CHECK_THROWS_AS(VM::random_lines_2(box, VM::max_random_lines_2() + 1, 1), std::invalid_argument);
  CHECK_THROWS_AS(VM::regular_grid_lines_2(box, 1000), std::length_error);
  const VM::Curve_problem_2 curve = MDCS_test::catenoid_problem(0.8);
  CHECK_THROWS_AS(VM::minimize_on_regular_grid_2(curve, VM::Surface_of_rotation_functional(), 65), std::invalid_argument);
  CHECK_THROWS_AS(VM::minimize_on_regular_grid_2(curve, VM::Surface_of_rotation_functional(), 1000), std::invalid_argument);
  CHECK(seconds_since(t0) < 5);
  // the limits themselves are usable sizes
  CHECK(VM::random_lines_2(box, 1000, 1).size() == 1000u);
  CHECK(VM::surface_planes_3(P, 2000).size() == 2000u);
}

TEST_CASE("variational checks: ranges whose width overflows are refused", "[variational][checks]")
{
  VM::Surface_problem_3 P = fine_saddle_problem();
  P.zmin = -1e308;
  P.zmax = 1e308;   // finite ends, infinite range: every height in the lattice would be NaN
  P.lower_boundary = [](double, double) { return 0.0; };
  CHECK_THROWS_WITH(P.validate(), Catch::Contains("overflow"));
  CHECK_THROWS_AS(VM::surface_planes_3(P, 40), std::invalid_argument);
  VM::Surface_problem_3 wide = fine_saddle_problem();
  wide.domain = CGAL::Bbox_2(-1e308, 0, 1e308, 1);
  CHECK_THROWS_AS(wide.validate(), std::invalid_argument);
}

TEST_CASE("variational checks: finite functional values that add up to infinity are never a feasible result", "[variational][checks]")
{
  // surfaces on a 5 x 5 domain: 1e307 per unit area is finite at every point; facets or their sum overflow
  VM::Surface_problem_3 P = fine_saddle_problem();
  P.domain = CGAL::Bbox_2(0, 0, 5, 5);
  P.lower_boundary = [](double x, double y) { return 0.5 + 0.02 * (x - 2.5) * (y - 2.5); };
  const VM::Plane_arrangement_3 A = VM::build_surface_arrangement_3(P, VM::surface_planes_3(P, 40));
  CHECK_THROWS_AS(VM::minimize_surface_functional_3(A, P, Huge_functional_3()), std::logic_error);
  CHECK_THROWS_AS(VM::minimize_surface_functional_3(A, P, Huge_functional_3(), 1, CGAL::Min_cut::Push_relabel_max_flow()),
                  std::logic_error);
  // a weight vector of finite entries of 1e307: every surface has more than 18 facets
  std::vector<double> w = VM::surface_facet_weights_3(A, P, VM::Area_functional_3());
  for(double& x : w)
    if(std::isfinite(x) && x > 0) x = 1e307;
  CHECK_THROWS_AS(VM::minimize_surface_functional_3(A, w, P), std::logic_error);
  CHECK_THROWS_AS(VM::minimize_surface_functional_3(A, w, P, CGAL::Min_cut::Boykov_kolmogorov_max_flow()), std::logic_error);
  // relaxation: the grid energy overflows as well
  VM::Surface_relaxation_options_3 ro;
  ro.grids = {4};
  CHECK_THROWS_AS(VM::relax_surface_3(P, Huge_functional_3(), [](double, double) { return 0.5; }, ro), std::invalid_argument);
  // relaxation options that size arrays or never stop (on the unit square)
  const VM::Surface_problem_3 U = fine_saddle_problem();
  ro.grids = {4};
  ro.memory = 0;
  CHECK_THROWS_AS(VM::relax_surface_3(U, VM::Area_functional_3(), [](double, double) { return 0.5; }, ro), std::invalid_argument);
  ro.memory = 1000000;
  CHECK_THROWS_AS(VM::relax_surface_3(U, VM::Area_functional_3(), [](double, double) { return 0.5; }, ro), std::invalid_argument);
  ro = VM::Surface_relaxation_options_3();
  ro.tolerance = qnan;
  CHECK_THROWS_AS(VM::relax_surface_3(U, VM::Area_functional_3(), [](double, double) { return 0.5; }, ro), std::invalid_argument);
  ro = VM::Surface_relaxation_options_3();
  ro.grids = {4};
  CHECK_THROWS_AS(VM::relax_surface_3(U, VM::Area_functional_3(), [](double, double) { return qnan; }, ro), std::invalid_argument);
  const VM::Relaxed_surface_3 ok = VM::relax_surface_3(U, VM::Area_functional_3(), [](double, double) { return 0.5; }, ro);
  CHECK(std::isfinite(ok.energy));

  // curves: weight vectors of finite entries of 5e307 (every curve has more than 3 edges), NaN or negative entries
  const VM::Curve_problem_2 curve = MDCS_test::catenoid_problem(0.8);
  const VM::Line_arrangement_2 L = VM::build_curve_arrangement_2(curve, MDCS_test::lines_for(curve, 60, 1));
  std::vector<double> cw = VM::curve_edge_weights_2(L, VM::Surface_of_rotation_functional());
  for(double& x : cw)
    if(std::isfinite(x) && x > 0) x = 5e307;
  CHECK_THROWS_AS(VM::minimize_curve_functional_2(L, cw, curve), std::logic_error);
  CHECK_THROWS_AS(VM::minimize_curve_functional_2(L, cw, curve, CGAL::Min_cut::Pseudoflow_max_flow()), std::logic_error);
  std::vector<double> bad = VM::curve_edge_weights_2(L, VM::Surface_of_rotation_functional());
  const VM::Minimal_curve_2 good = VM::minimize_curve_functional_2(L, bad, curve);
  CHECK(good.is_feasible);
  CHECK(std::isfinite(good.energy));
  bad[bad.size() / 2] = qnan;
  CHECK_THROWS_WITH(VM::minimize_curve_functional_2(L, bad, curve), Catch::Contains("NaN"));
  bad[bad.size() / 2] = -1;
  CHECK_THROWS_AS(VM::minimize_curve_functional_2(L, bad, curve), std::invalid_argument);
}
