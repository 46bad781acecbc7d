// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// QP_solver_linear_program_solver (CGAL's exact QP_solver as a LinearProgramSolver): tiny programs with known
// rational optima (objective, primal values and duals exact), ranged, free and infeasible/unbounded programs; the
// MWT programs of small point sets and of the 13-wheel (fractional optimum) against the exact GLPK model (same
// optimum), and whole MWT runs with it (certified, same weight as with GLPK).

#include "mwt_test_helpers.h"

#include <CGAL/Minimum_weight_triangulation_2/QP_solver_linear_program_solver.h>

#include <catch2/catch.hpp>

using namespace mwt_test;

namespace {

typedef MWT::QP_solver_linear_program_solver<> Qp_lp_solver;
typedef Qp_lp_solver::Exact_value Qp_exact;

Qp_exact qp_rational(long num, long den) { return Qp_exact(CGAL::Gmpzf(double(num)), CGAL::Gmpzf(double(den))); }

// Adds a column with its entries given as (row, value) pairs.
void qp_add_column(MWT::Sparse_linear_program& lp, double cost, double lo, double up,
                   std::vector<std::pair<int, double>> entries)
{
  std::vector<int> rows;
  std::vector<double> values;
  for(const auto& e : entries) {
    rows.push_back(e.first);
    values.push_back(e.second);
  }
  lp.add_column(cost, lo, up, rows.data(), values.data(), int(rows.size()));
}

} // namespace

TEST_CASE("QP_solver LP model: a tiny program with a rational optimum", "[mwt][solver][qp_solver]")
{
  // min -x - y  s.t.  2x + y <= 1,  x + 2y <= 1,  x, y >= 0:  x = y = 1/3, optimum -2/3, duals -1/3 each.
  const double inf = MWT::Sparse_linear_program::infinity();
  MWT::Sparse_linear_program lp;
  lp.add_row(-inf, 1);
  lp.add_row(-inf, 1);
  qp_add_column(lp, -1, 0, inf, {{0, 2}, {1, 1}});
  qp_add_column(lp, -1, 0, inf, {{0, 1}, {1, 2}});
  Qp_exact objective;
  std::vector<Qp_exact> primal;
  const auto s = Qp_lp_solver().solve(lp, objective, primal);
  REQUIRE(s.status == MWT::Lp_status::optimal);
  CHECK(s.exact);
  CHECK(objective == qp_rational(-2, 3));
  REQUIRE(primal.size() == 2);
  CHECK(primal[0] == qp_rational(1, 3));
  CHECK(primal[1] == qp_rational(1, 3));
  CHECK(s.objective == Approx(-2.0 / 3).epsilon(1e-15));
  REQUIRE(s.dual.size() == 2);
  CHECK(s.dual[0] == Approx(-1.0 / 3).epsilon(1e-15));
  CHECK(s.dual[1] == Approx(-1.0 / 3).epsilon(1e-15));
  REQUIRE(s.column_status.size() == 2);
  CHECK(s.column_status[0] == MWT::Basis_status::basic);
  CHECK(s.column_status[1] == MWT::Basis_status::basic);
  CHECK(MWT::is_usable_optimum(lp, s));
  CHECK(std::string(Qp_lp_solver().name()) == "qp-solver");
}

TEST_CASE("QP_solver LP model: ranged and equality rows, bounds, infeasible and unbounded", "[mwt][solver][qp_solver]")
{
  const double inf = MWT::Sparse_linear_program::infinity();
  {
    // min x + 2y + z  s.t.  1 <= x + y <= 2 (ranged),  y - z = 0.5,  x <= 0.25,  z free (-inf, inf):
    // y = 0.75 + ..., optimum: x = 0.25, y = 0.75, z = 0.25 -> 0.25 + 1.5 + 0.25 = 2
    MWT::Sparse_linear_program lp;
    lp.add_row(1, 2);
    lp.add_row(0.5, 0.5);
    lp.add_row(-inf, inf); // a free row: no constraint, dual 0
    qp_add_column(lp, 1, 0, 0.25, {{0, 1}, {2, 5}});
    qp_add_column(lp, 2, 0, inf, {{0, 1}, {1, 1}});
    qp_add_column(lp, 1, -inf, inf, {{1, -1}});
    const auto s = Qp_lp_solver().solve(lp);
    REQUIRE(s.status == MWT::Lp_status::optimal);
    CHECK(s.objective == 2);
    CHECK(s.primal == std::vector<double>{0.25, 0.75, 0.25});
    // reduced costs c - A^T dual: zero on the basic columns, >= 0 at a lower bound, <= 0 at an upper bound
    REQUIRE(s.dual.size() == 3);
    CHECK(s.dual[2] == 0);
    const double rc_y = 2 - (s.dual[0] + s.dual[1]), rc_z = 1 + s.dual[1], rc_x = 1 - (s.dual[0] + 5 * s.dual[2]);
    CHECK(rc_y == Approx(0).margin(1e-15));
    CHECK(rc_z == Approx(0).margin(1e-15));
    CHECK(rc_x <= 1e-15);
    CHECK(s.column_status[0] == MWT::Basis_status::at_upper);
  }
  {
    // x + y = 1 and x + y = 3 with 0 <= x, y <= 1: infeasible
    MWT::Sparse_linear_program lp;
    lp.add_row(1, 1);
    lp.add_row(3, 3);
    qp_add_column(lp, 1, 0, 1, {{0, 1}, {1, 1}});
    qp_add_column(lp, 2, 0, 1, {{0, 1}, {1, 1}});
    CHECK(Qp_lp_solver().solve(lp).status == MWT::Lp_status::infeasible);
  }
  {
    // min -x  s.t.  x - y <= 1,  x, y >= 0: unbounded
    MWT::Sparse_linear_program lp;
    lp.add_row(-inf, 1);
    qp_add_column(lp, -1, 0, inf, {{0, 1}});
    qp_add_column(lp, 0, 0, inf, {{0, -1}});
    CHECK(Qp_lp_solver().solve(lp).status == MWT::Lp_status::unbounded);
  }
  {
    // cancelled before the solve; a malformed program is refused
    MWT::Sparse_linear_program lp;
    lp.add_row(1, 1);
    qp_add_column(lp, 1, 0, 1, {{0, 1}});
    Qp_lp_solver solver;
    MWT::Lp_solve_control control;
    control.keep_going = [](double) { return false; };
    solver.set_control(control);
    CHECK(solver.solve(lp).status == MWT::Lp_status::cancelled);
    lp.row_index[0] = 4;
    CHECK_THROWS_AS(Qp_lp_solver().solve(lp), std::invalid_argument);
  }
}

#if defined(MDCS_HAS_GLPK)
TEST_CASE("QP_solver LP model: the MWT programs agree with exact GLPK", "[mwt][solver][qp_solver]")
{
  // small random sets (integral optima; brute force on the two smallest) and the 13-wheel (the thesis's
  // fractional optimum)
  const std::vector<std::vector<Point>> sets = {uniform_points(7, 21), uniform_points(8, 22), uniform_points(16, 4),
                                                clustered_points(14, 5), wheel(13)};
  for(std::size_t i = 0; i < sets.size(); ++i) {
    INFO("set " << i);
    MWT::Minimum_weight_triangulation_lp_2<K> m(sets[i]);
    m.build_linear_program();
    const auto glpk = MWT::GLPK_linear_program_solver(/*exact*/ true).solve(m.linear_program());
    Qp_exact objective;
    std::vector<Qp_exact> primal;
    const auto qp = Qp_lp_solver().solve(m.linear_program(), objective, primal);
    REQUIRE(glpk.status == MWT::Lp_status::optimal);
    REQUIRE(qp.status == MWT::Lp_status::optimal);
    CHECK(qp.exact);
    CHECK(qp.objective == Approx(glpk.objective).epsilon(1e-14));
    // the exact objective is the cost of the exact primal point
    Qp_exact cost = qp_rational(0, 1);
    for(std::size_t j = 0; j < primal.size(); ++j) cost += primal[j] * Qp_exact(CGAL::Gmpzf(m.linear_program().cost[j]));
    CHECK(cost == objective);
  }
  // whole runs: certified, with the weight of the exact GLPK model (the wheel: fractional, resolved by GLPK's
  // branch and bound in both, from the same LP bound)
  for(std::size_t i = 0; i < sets.size(); ++i) {
    INFO("set " << i);
    MWT::Mwt_options o;
    const auto with_glpk = MWT::minimum_weight_triangulation_2(sets[i], o, MWT::GLPK_linear_program_solver(true),
        [](const MWT::Sparse_linear_program& lp) { return MWT::GLPK_linear_program_solver().solve_binary(lp); });
    const auto with_qp = MWT::minimum_weight_triangulation_2(sets[i], o, Qp_lp_solver(),
        [](const MWT::Sparse_linear_program& lp) { return MWT::GLPK_linear_program_solver().solve_binary(lp); });
    INFO(with_qp.message);
    CHECK(with_qp.status == with_glpk.status);
    CHECK(with_qp.solver == std::string("qp-solver"));
    CHECK(with_qp.lp_exact);
    CHECK(with_qp.weight == Approx(with_glpk.weight).epsilon(1e-14));
    CHECK(with_qp.lp_objective == Approx(with_glpk.lp_objective).epsilon(1e-14));
    // the dual bound from the exact duals is at least as tight as from GLPK's (rounded) ones, and valid
    CHECK(with_qp.lower_bound >= with_glpk.lower_bound - 1e-12 * with_glpk.weight);
    CHECK(with_qp.lower_bound <= with_qp.weight);
    CHECK(with_qp.lower_bound == Approx(with_qp.lp_objective).epsilon(1e-12));
    CHECK(independent_triangulation_check(sets[i], with_qp.triangles));
    if(i < 2) CHECK(with_qp.weight == Approx(brute_force_mwt(sets[i])).epsilon(1e-12));
    if(i < 4) {
      CHECK(with_qp.status == MWT::Mwt_status::certified_optimal);
    } else {
      CHECK(with_qp.status == MWT::Mwt_status::optimal_after_branch_and_bound);
    }
  }
}
#endif

namespace {

// The triangles of a run as a sorted list, each rotated to start at its smallest index (orientation kept).
std::vector<std::array<int, 3>> qp_normalized(std::vector<std::array<int, 3>> t)
{
  for(auto& a : t) std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
  std::sort(t.begin(), t.end());
  return t;
}

MWT::Mwt_options qp_choice(std::size_t max_columns = MWT::Mwt_options().qp_max_columns)
{
  MWT::Mwt_options o;
  o.solver = MWT::Lp_solver_choice::qp_solver;
  o.qp_max_columns = max_columns;
  return o;
}

} // namespace

TEST_CASE("QP_solver choice: minimum_weight_triangulation_2(points, options) with Lp_solver_choice::qp_solver",
          "[mwt][solver][qp_solver]")
{
  CHECK(MWT::has_lp_solver(MWT::Lp_solver_choice::qp_solver));   // CGAL's own solver: always built in
#if defined(MDCS_HAS_GLPK)
  // Oracles: the exact GLPK choice (same triangles, weight, LP optimum) and brute force on the smallest sets; the
  // 13-wheel has a fractional LP optimum, resolved by GLPK's branch and bound after either solver.
  const std::vector<std::vector<Point>> sets = {uniform_points(7, 31), uniform_points(8, 32), uniform_points(12, 33),
                                                clustered_points(12, 34), wheel(13)};
  for(std::size_t i = 0; i < sets.size(); ++i) {
    INFO("set " << i);
    MWT::Mwt_options exact;
    exact.solver = MWT::Lp_solver_choice::exact;
    const MWT::Mwt_result ref = MWT::minimum_weight_triangulation_2(sets[i], exact);
    const MWT::Mwt_result r = MWT::minimum_weight_triangulation_2(sets[i], qp_choice());
    INFO(r.message);
    CHECK(r.solver == std::string("qp-solver"));
    CHECK(r.lp_exact);
    CHECK(r.status == ref.status);
    CHECK(r.lp_integral == ref.lp_integral);
    CHECK(r.lp_objective == Approx(ref.lp_objective).epsilon(1e-14));
    CHECK(r.weight == Approx(ref.weight).epsilon(1e-14));
    CHECK(qp_normalized(r.triangles) == qp_normalized(ref.triangles));
    CHECK(r.lower_bound <= r.weight);
    CHECK(independent_triangulation_check(sets[i], r.triangles));
    CHECK(r.statistics.lp_columns > 0);
    if(sets[i].size() <= 8) CHECK(r.weight == Approx(brute_force_mwt(sets[i])).epsilon(1e-12));
    if(i == 4) {
      CHECK(!r.lp_integral);
      CHECK(r.status == MWT::Mwt_status::optimal_after_branch_and_bound);
    } else {
      CHECK(r.status == MWT::Mwt_status::certified_optimal);
    }
  }
  // a fractional optimum without branch and bound: the exact LP bound only, as with the other solvers
  MWT::Mwt_options lp_only = qp_choice();
  lp_only.resolve_fractional = false;
  const MWT::Mwt_result frac = MWT::minimum_weight_triangulation_2(wheel(13), lp_only);
  CHECK(frac.status == MWT::Mwt_status::fractional_bound_only);
  CHECK(frac.lp_exact);
  CHECK(frac.lp_objective == Approx(18.7636).margin(5e-5));   // the thesis's LP value of the 13-wheel
#endif
  // the extremes of the coordinate range: the weight scales with the points, the triangles stay
  const std::vector<Point> unit = uniform_points(10, 36);
  const MWT::Mwt_result base = MWT::minimum_weight_triangulation_2(unit, qp_choice());
  REQUIRE(base.status == MWT::Mwt_status::certified_optimal);
  for(int e : {499, -399}) {
    INFO("exponent " << e);
    std::vector<Point> p;
    for(const Point& q : unit) p.emplace_back(std::ldexp(q.x(), e), std::ldexp(q.y(), e));
    const MWT::Mwt_result r = MWT::minimum_weight_triangulation_2(p, qp_choice());
    CHECK(r.status == MWT::Mwt_status::certified_optimal);
    CHECK(std::ldexp(r.weight, -e) == Approx(base.weight).epsilon(1e-12));
    CHECK(qp_normalized(r.triangles) == qp_normalized(base.triangles));
  }
}

TEST_CASE("QP_solver choice: the column limit refuses larger programs before the solve", "[mwt][solver][qp_solver]")
{
  const std::vector<Point> p = uniform_points(12, 37);
  const MWT::Mwt_result unlimited = MWT::minimum_weight_triangulation_2(p, qp_choice(0));   // 0: no limit
  REQUIRE(unlimited.status == MWT::Mwt_status::certified_optimal);
  const std::size_t columns = unlimited.statistics.lp_columns;
  REQUIRE(columns > 1);
  // exactly at the limit: solved, with the same answer
  const MWT::Mwt_result at_limit = MWT::minimum_weight_triangulation_2(p, qp_choice(columns));
  CHECK(at_limit.weight == unlimited.weight);
  // one column over: Linear_program_too_large (a std::length_error) with the sizes, and the solver never started
  bool lp_solve_asked = false;
  MWT::Mwt_options o = qp_choice(columns - 1);
  o.progress = [&lp_solve_asked](const char* stage, double) {
    if(std::string(stage) == "LP solve") lp_solve_asked = true;
    return true;
  };
  try {
    MWT::minimum_weight_triangulation_2(p, o);
    FAIL("no exception above the column limit");
  } catch(const MWT::Linear_program_too_large& e) {
    CHECK(e.columns() == columns);
    CHECK(e.limit() == columns - 1);
    CHECK(e.rows() == unlimited.statistics.lp_rows);
    CHECK_THAT(std::string(e.what()), Catch::Contains(std::to_string(columns) + " columns") &&
                         Catch::Contains("more than the limit of " + std::to_string(columns - 1)));
  }
  CHECK(lp_solve_asked);   // asked before the refusal, as before any solve
  CHECK_THROWS_AS(MWT::minimum_weight_triangulation_2(p, qp_choice(1)), std::length_error);
  // the same guard on the model itself; the other solver choices ignore the limit
  MWT::Minimum_weight_triangulation_lp_2<K> m(p);
  m.build_linear_program();
  Qp_lp_solver limited;
  limited.set_max_columns(columns - 1);
  CHECK(limited.max_columns() == columns - 1);
  CHECK_THROWS_AS(limited.solve(m.linear_program()), MWT::Linear_program_too_large);
#if defined(MDCS_HAS_GLPK)
  MWT::Mwt_options glpk;
  glpk.solver = MWT::Lp_solver_choice::glpk;
  glpk.qp_max_columns = 1;
  CHECK(MWT::minimum_weight_triangulation_2(p, glpk).weight == Approx(unlimited.weight).epsilon(1e-14));
#endif
  // the progress callback can still cancel just before the (uninterruptible) solve
  MWT::Mwt_options cancel = qp_choice();
  cancel.progress = [](const char* stage, double) { return std::string(stage) != "LP solve"; };
  CHECK_THROWS_AS(MWT::minimum_weight_triangulation_2(p, cancel), CGAL::MDCS::Operation_cancelled);
}
