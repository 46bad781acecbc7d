// End-to-end tests of the univariate solvers: the min-cut of the directed dual graph against the independent
// shortest-path oracle (duality), both max-flow engines, analytic answers, globality, relaxed ends, bad input.
#include <catch2/catch.hpp>

#include <MDCS_test/curve_problems.h>

#include <CGAL/Variational_minimization.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace VM = CGAL::Variational_minimization;
using MDCS_test::relative_difference;

namespace {

// Solves with the cut (the planar cut and all three max-flow engines) and the shortest path and checks the duality theorem on the way.
template <class Functional>
MDCS_test::Checked_solve solve_checked(const VM::Curve_problem_2& problem,
                                       const std::vector<VM::Arrangement_line_2>& lines, const Functional& G)
{
  const VM::Line_arrangement_2 arrangement = VM::build_curve_arrangement_2(problem, lines);
  const std::vector<double> weights = VM::curve_edge_weights_2(arrangement, G);
  MDCS_test::Checked_solve s = MDCS_test::solve_both_ways(problem, arrangement, weights);
  REQUIRE(s.cut.is_feasible == s.path.is_feasible);
  REQUIRE(s.cut.is_feasible == s.cut_pr.is_feasible);
  REQUIRE(s.cut.is_feasible == s.cut_bk.is_feasible);
  REQUIRE(s.cut.is_feasible == s.cut_pf.is_feasible);
  if(s.cut.is_feasible) {
    // Duality: cut value == shortest path length; the returned curve's energy is the cut value.
    CHECK(relative_difference(s.cut.solver_value, s.path.solver_value) <= 1e-9);
    CHECK(relative_difference(s.cut.energy, s.cut.solver_value) <= 1e-9);
    CHECK(relative_difference(s.path.energy, s.path.solver_value) <= 1e-9);
    CHECK(relative_difference(s.cut_pf.solver_value, s.cut.solver_value) <= 1e-9);
    CHECK(relative_difference(s.cut_pr.solver_value, s.cut.solver_value) <= 1e-9);
    CHECK(relative_difference(s.cut_bk.solver_value, s.cut.solver_value) <= 1e-9);
    CHECK(relative_difference(s.cut_pf.energy, s.cut_pf.solver_value) <= 1e-9);
    CHECK(s.cut_pr.edges == s.cut_pf.edges); // the max-flow engines return the same (minimal source side) cut
    CHECK(s.cut_bk.edges == s.cut_pf.edges);
    CHECK(s.cut.edges == s.cut_pf.edges); // no ties in these instances: the planar cut is that cut too
    // The curve is a function from the left wall to the right wall meeting the end conditions.
    REQUIRE(s.cut.polyline.size() >= 2);
    CHECK(s.cut.polyline.front().x() == problem.box.xmin());
    CHECK(s.cut.polyline.back().x() == problem.box.xmax());
    for(std::size_t i = 1; i < s.cut.polyline.size(); ++i)
      CHECK(s.cut.polyline[i - 1].x() <= s.cut.polyline[i].x());
    const double tol = 1e-12 * (problem.box.ymax() - problem.box.ymin());
    CHECK(s.cut.polyline.front().y() >= problem.left.low - tol);
    CHECK(s.cut.polyline.front().y() <= problem.left.high + tol);
    CHECK(s.cut.polyline.back().y() >= problem.right.low - tol);
    CHECK(s.cut.polyline.back().y() <= problem.right.high + tol);
  } else {
    CHECK(std::isinf(s.cut.energy));
    CHECK(s.cut.polyline.empty());
  }
  return s;
}

} // namespace

TEST_CASE("minimize_curve_functional_2: a straight line is found exactly", "[variational][curve]")
{
  // Arc length between (0, 0.2) and (1, 0.7): the segment is the global minimum and is in the grid.
  VM::Curve_problem_2 problem{CGAL::Bbox_2(0, 0, 1, 1), VM::End_condition::fixed(0.2), VM::End_condition::fixed(0.7)};
  std::vector<VM::Arrangement_line_2> lines = MDCS_test::lines_for(problem, 60, 7);
  lines.push_back({VM::Point_2(0, 0.2), VM::Point_2(1, 0.7)});
  const auto s = solve_checked(problem, lines, VM::Arc_length_functional());
  REQUIRE(s.cut.is_feasible);
  CHECK(s.cut.energy == Approx(std::hypot(1.0, 0.5)).epsilon(1e-12));
  for(const auto& p : s.cut.polyline)
    CHECK(std::abs(p.y() - (0.2 + 0.5 * p.x())) <= 1e-12);
}

TEST_CASE("minimize_curve_functional_2: cut == shortest path on random instances", "[variational][curve][duality]")
{
  const auto density = [](double x, double f) {
    return 0.3 + std::exp(-30 * ((x - 0.4) * (x - 0.4) + (f - 0.5) * (f - 0.5))) + 0.5 * std::sin(9 * x) * std::sin(9 * x);
  };
  for(std::uint64_t seed = 1; seed <= 6; ++seed) {
    VM::Curve_problem_2 problem{CGAL::Bbox_2(0, 0, 1, 1), VM::End_condition::fixed(0.1 * seed),
                                VM::End_condition::fixed(0.9 - 0.1 * seed)};
    const auto lines = MDCS_test::lines_for(problem, 40 + 20 * seed, seed, 0.25);
    INFO("seed " << seed);
    solve_checked(problem, lines, VM::Arc_length_functional());
    solve_checked(problem, lines, VM::make_density_weighted_length_functional(density));
  }
}

TEST_CASE("minimize_curve_functional_2: relaxed end conditions", "[variational][curve][relaxed]")
{
  // Arc length with overlapping relaxed ranges: a horizontal line inside both ranges has length b - a, the
  // global minimum; with the horizontal line y = 0.45 in the grid the solvers must find exactly 1.
  VM::Curve_problem_2 problem{CGAL::Bbox_2(0, 0, 1, 1), VM::End_condition::range(0.2, 0.8),
                              VM::End_condition::range(0.3, 0.6)};
  std::vector<VM::Arrangement_line_2> lines = VM::random_lines_2(problem.box, 80, 3);
  lines.push_back({VM::Point_2(0, 0.45), VM::Point_2(1, 0.45)});
  const auto s = solve_checked(problem, lines, VM::Arc_length_functional());
  REQUIRE(s.cut.is_feasible);
  CHECK(s.cut.energy == Approx(1.0).epsilon(1e-12));

  // Disjoint ranges: the optimum must go from [0, 0.1] to [0.8, 1]; cut and path agree, and the energy is at
  // least the straight-line lower bound between the ranges.
  VM::Curve_problem_2 apart{CGAL::Bbox_2(0, 0, 1, 1), VM::End_condition::range(0, 0.1), VM::End_condition::range(0.8, 1)};
  const auto t = solve_checked(apart, VM::random_lines_2(apart.box, 120, 4), VM::Arc_length_functional());
  REQUIRE(t.cut.is_feasible);
  CHECK(t.cut.energy >= std::hypot(1.0, 0.7) - 1e-12);
}

TEST_CASE("minimize_curve_functional_2: infeasible grid is reported, not guessed", "[variational][curve]")
{
  // No line passes through the fixed end point (0, 0.5): no discrete function meets the condition.
  VM::Curve_problem_2 problem{CGAL::Bbox_2(0, 0, 1, 1), VM::End_condition::fixed(0.5), VM::End_condition::fixed(0.5)};
  std::vector<VM::Arrangement_line_2> lines{{VM::Point_2(0, 0.1), VM::Point_2(1, 0.9)},
                                            {VM::Point_2(0, 0.8), VM::Point_2(1, 0.3)}};
  const auto s = solve_checked(problem, lines, VM::Arc_length_functional());
  CHECK_FALSE(s.cut.is_feasible);
  CHECK_FALSE(s.path.is_feasible);
}

TEST_CASE("minimize_curve_functional_2: vertical lines never enter the curve", "[variational][curve]")
{
  VM::Curve_problem_2 problem{CGAL::Bbox_2(0, 0, 1, 1), VM::End_condition::fixed(0.3), VM::End_condition::fixed(0.6)};
  std::vector<VM::Arrangement_line_2> lines = MDCS_test::lines_for(problem, 50, 11, 0.3);
  for(int i = 1; i < 10; ++i) lines.push_back({VM::Point_2(0.1 * i, 0), VM::Point_2(0.1 * i, 1)});
  const auto s = solve_checked(problem, lines, VM::Arc_length_functional());
  REQUIRE(s.cut.is_feasible);
  for(std::size_t i = 1; i < s.cut.polyline.size(); ++i)
    CHECK(s.cut.polyline[i - 1].x() < s.cut.polyline[i].x());
}

TEST_CASE("minimize_curve_functional_2: bad input gets a clear error", "[variational][curve][errors]")
{
  const VM::Curve_problem_2 ok{CGAL::Bbox_2(0, 0, 1, 1), VM::End_condition::fixed(0.5), VM::End_condition::fixed(0.5)};
  const auto lines = MDCS_test::lines_for(ok, 30, 1);

  // zero lines
  CHECK_THROWS_AS(VM::build_curve_arrangement_2(ok, {}), std::invalid_argument);
  // no line crosses the box
  std::vector<VM::Arrangement_line_2> outside{{VM::Point_2(0, 2), VM::Point_2(1, 3)}};
  CHECK_THROWS_AS(VM::build_curve_arrangement_2(ok, outside), std::invalid_argument);
  // end values outside the range, reversed range, empty box, NaN
  VM::Curve_problem_2 bad = ok;
  bad.left = VM::End_condition::fixed(1.5);
  CHECK_THROWS_AS(VM::build_curve_arrangement_2(bad, lines), std::invalid_argument);
  bad = ok;
  bad.right = VM::End_condition::range(0.7, 0.2);
  CHECK_THROWS_AS(VM::build_curve_arrangement_2(bad, lines), std::invalid_argument);
  bad = ok;
  bad.box = CGAL::Bbox_2(1, 0, 1, 1);
  CHECK_THROWS_AS(VM::build_curve_arrangement_2(bad, lines), std::invalid_argument);
  bad = ok;
  bad.left = VM::End_condition::fixed(std::nan(""));
  CHECK_THROWS_AS(VM::build_curve_arrangement_2(bad, lines), std::invalid_argument);
  try {
    bad = ok;
    bad.left = VM::End_condition::fixed(1.5);
    VM::build_curve_arrangement_2(bad, lines);
  } catch(const std::invalid_argument& e) {
    CHECK(std::string(e.what()).find("outside the range") != std::string::npos);
  }

  // G negative or NaN somewhere
  const VM::Line_arrangement_2 arrangement = VM::build_curve_arrangement_2(ok, lines);
  const auto negative = VM::make_callable_functional([](double f, double, double x) { return x > 0.7 ? -1.0 : f; });
  CHECK_THROWS_AS(VM::curve_edge_weights_2(arrangement, negative), std::domain_error);
  const auto not_a_number = VM::make_callable_functional([](double f, double, double) { return f > 0.9 ? std::nan("") : 1.0; });
  CHECK_THROWS_AS(VM::curve_edge_weights_2(arrangement, not_a_number), std::domain_error);
  // weights that do not belong to the arrangement
  CHECK_THROWS_AS(VM::minimize_curve_functional_2(arrangement, std::vector<double>(3, 1.0), ok), std::invalid_argument);
}

TEST_CASE("minimize_curve_functional_2: progress is reported and can cancel", "[variational][curve]")
{
  const VM::Curve_problem_2 problem{CGAL::Bbox_2(0, 0, 1, 1), VM::End_condition::fixed(0.5), VM::End_condition::fixed(0.5)};
  const auto lines = MDCS_test::lines_for(problem, 50, 2);
  int calls = 0;
  double last = -1;
  auto counting = [&](const char*, double f) { ++calls; last = f; return true; };
  const VM::Line_arrangement_2 arrangement = VM::build_curve_arrangement_2(problem, lines, counting);
  CHECK(calls > 0);
  CHECK(last == 1.0);
  auto cancel = [](const char* stage, double) { return std::string(stage) != "weights"; };
  CHECK_THROWS_AS(VM::curve_edge_weights_2(arrangement, VM::Arc_length_functional(), cancel), CGAL::MDCS::Operation_cancelled);
}

// ---------------------------------------------------------------------------------------------------------
// The catenoid: convergence of the discrete optimum and globality (thesis ch. 2.3, fig. 2.1).

namespace {

// Median over three seeds of the relative energy error of the discrete optimum with n random lines. The
// energies come from the shortest-path solver (exact and linear-time); `with_cut` also runs the min-cut with
// both engines and checks the duality on every instance (slow above ~500 lines: see the benchmark).
double catenoid_median_error(double R, std::size_t n, bool with_cut)
{
  const auto exact = VM::global_minimum_surface_of_rotation(R);
  const auto problem = MDCS_test::catenoid_problem(R);
  std::vector<double> errors;
  for(std::uint64_t seed = 1; seed <= 3; ++seed) {
    const auto lines = MDCS_test::lines_for(problem, n, seed);
    double energy;
    if(with_cut) {
      const auto s = solve_checked(problem, lines, VM::Surface_of_rotation_functional());
      REQUIRE(s.cut.is_feasible);
      energy = s.cut.energy;
    } else {
      const auto arrangement = VM::build_curve_arrangement_2(problem, lines);
      const auto weights = VM::curve_edge_weights_2(arrangement, VM::Surface_of_rotation_functional());
      const auto path = VM::directed_shortest_path_2(arrangement, weights, problem);
      REQUIRE(path.is_feasible);
      energy = path.energy;
    }
    CHECK(energy >= exact.energy * (1 - 1e-9)); // a discrete function is a function: never below the infimum
    errors.push_back((energy - exact.energy) / exact.energy);
  }
  std::sort(errors.begin(), errors.end());
  return errors[1];
}

} // namespace

TEST_CASE("catenoid: error falls as random lines are added; 1,600 lines within 3e-3", "[variational][catenoid]")
{
  REQUIRE(VM::global_minimum_surface_of_rotation(2.0).branch == VM::Surface_of_rotation_minimum::Branch::Catenoid);
  double previous = std::numeric_limits<double>::infinity();
  for(std::size_t n : {100, 400, 1600}) {
    const double error = catenoid_median_error(2.0, n, false);
    INFO(n << " lines: median relative error " << error);
    CHECK(error < previous);
    previous = error;
  }
  CHECK(previous <= 3e-3);
  // The cut itself (both engines, checked against the path) on the smaller grids.
  CHECK(catenoid_median_error(2.0, 200, true) < 1e-2);
}

TEST_CASE("catenoid: cut == path with both engines up to 1,600 lines", "[.long][long][variational][catenoid]")
{
  for(std::size_t n : {400, 800, 1600})
    CHECK(catenoid_median_error(2.0, n, true) <= (n == 1600 ? 3e-3 : 1e-2));
}

TEST_CASE("catenoid: the regular grid C_n converges; C_n^pl cut == path", "[variational][catenoid][regular]")
{
  const double R = 2.0;
  const double exact = VM::global_minimum_surface_of_rotation(R).energy;
  const auto problem = MDCS_test::catenoid_problem(R);
  double previous = std::numeric_limits<double>::infinity();
  for(std::size_t n : {2, 4, 8, 12}) {
    const auto curve = VM::minimize_on_regular_grid_2(problem, VM::Surface_of_rotation_functional(), n);
    REQUIRE(curve.is_feasible);
    const double error = (curve.energy - exact) / exact;
    INFO("C_" << n << ": relative error " << error);
    CHECK(error >= -1e-12);
    CHECK(error < previous);
    previous = error;
  }
  CHECK(previous < 0.02);
  // The planar version C_2^pl contains every C_2 function, so its optimum is at most C_2's.
  const auto c2 = VM::minimize_on_regular_grid_2(problem, VM::Surface_of_rotation_functional(), 2);
  const auto s = solve_checked(problem, VM::regular_grid_lines_2(problem.box, 2), VM::Surface_of_rotation_functional());
  REQUIRE(s.cut.is_feasible);
  CHECK(s.cut.energy <= c2.energy * (1 + 1e-12));
}

TEST_CASE("catenoid: the cut picks the global branch (Goldschmidt vs catenoid)", "[variational][catenoid][globality]")
{
  for(double R : {1.6, 1.7, 1.85, 1.95, 2.0, 2.2}) {
    const auto exact = VM::global_minimum_surface_of_rotation(R);
    const bool goldschmidt = exact.branch == VM::Surface_of_rotation_minimum::Branch::Goldschmidt;
    CHECK(goldschmidt == (R < 1.9));
    const auto problem = MDCS_test::catenoid_problem(R);
    // 400 lines, a fifth of them in the pencils: the steep lines through the end points approximate the
    // vertical drop of the Goldschmidt solution.
    const auto s = solve_checked(problem, MDCS_test::lines_for(problem, 400, 5, 0.2), VM::Surface_of_rotation_functional());
    REQUIRE(s.cut.is_feasible);
    const double lowest = MDCS_test::min_value(s.cut);
    INFO("R = " << R << ": discrete energy " << s.cut.energy << ", exact " << exact.energy << ", lowest point " << lowest);
    CHECK(s.cut.energy >= exact.energy * (1 - 1e-9));
    CHECK(s.cut.energy <= exact.energy * 1.015); // closer than the branches are apart (>= 2.1% here)
    if(goldschmidt)
      CHECK(lowest <= 0.05 * R); // the curve drops to the axis
    else
      CHECK(std::abs(lowest - exact.catenoids.c_shallow) <= 0.05 * R); // the catenoid's neck
  }
}

TEST_CASE("catenoid: at R = 1.7 local descent stays on the catenoid, the cut finds the lower Goldschmidt energy",
          "[variational][catenoid][globality]")
{
  const double R = 1.7;
  const auto exact = VM::global_minimum_surface_of_rotation(R);
  REQUIRE(exact.catenoids.exists);
  // Local descent (L-BFGS on 200 intervals) from the shallow catenoid: a local minimum.
  const auto local = VM::local_descent_2(VM::Surface_of_rotation_functional(), -1.0, 1.0, R, R, 200,
                                         [&](double x) { return VM::catenoid_value(exact.catenoids.c_shallow, x); });
  // The global discrete minimum on 400 random lines.
  const auto problem = MDCS_test::catenoid_problem(R);
  const auto s = solve_checked(problem, MDCS_test::lines_for(problem, 400, 5, 0.2), VM::Surface_of_rotation_functional());
  REQUIRE(s.cut.is_feasible);
  INFO("local descent " << local.energy << ", cut " << s.cut.energy << ", Goldschmidt " << exact.goldschmidt_energy);
  CHECK(local.energy == Approx(exact.catenoid_energy).epsilon(1e-3));
  CHECK(*std::min_element(local.values.begin(), local.values.end()) > 1.0); // never approaches the axis
  CHECK(s.cut.energy < local.energy - 1.0);                                  // the cut is globally better
}
