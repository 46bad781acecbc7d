// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Hostile input and honest output (issue 28): the coordinate range (refused outside, exact power-of-two scaling
// inside), every solver answer checked before it becomes a result (NaN/inf objective or values, wrong sizes,
// time limit, cancellation), programs that would make CLP or GLPK abort refused, the LP time limit and progress
// of every built-in model, and points in convex position solved by the exact convex program without an LP.

#if defined(MDCS_HAS_CLP) && defined(MDCS_HAS_GLPK)

#include "mwt_test_helpers.h"

#include <CGAL/MDCS/progress.h>

#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <iterator>
#include <limits>
#include <string>

using namespace mwt_test;

namespace {

const MWT::Lp_solver_choice all_solvers[] = {MWT::Lp_solver_choice::clp, MWT::Lp_solver_choice::glpk,
                                              MWT::Lp_solver_choice::exact};

std::vector<Point> scaled(const std::vector<Point>& p, int exponent)
{
  std::vector<Point> q;
  for(const Point& a : p) q.emplace_back(std::ldexp(a.x(), exponent), std::ldexp(a.y(), exponent));
  return q;
}

// n points on the unit circle (strictly convex position)
std::vector<Point> circle(int n)
{
  std::vector<Point> p;
  for(int i = 0; i < n; ++i) p.emplace_back(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n));
  return p;
}

// n points on the unit circle and one inside: not convex position, an LP of about n^3 / 6 columns
std::vector<Point> near_circle(int n)
{
  std::vector<Point> p = circle(n);
  p.emplace_back(0.9, 0.01);
  return p;
}

// A LinearProgramSolver that returns a fixed answer (shaped by `edit` from the true optimum of CLP).
struct Scripted_solver
{
  std::function<void(MWT::Linear_program_solution&)> edit;
  const char* name() const { return "scripted"; }
  MWT::Linear_program_solution solve(const MWT::Sparse_linear_program& lp) const
  {
    MWT::Linear_program_solution s = MWT::CLP_linear_program_solver().solve(lp);
    edit(s);
    return s;
  }
};

MWT::Mwt_result run_scripted(const std::vector<Point>& p, std::function<void(MWT::Linear_program_solution&)> edit,
                             std::function<MWT::Linear_program_solution(const MWT::Sparse_linear_program&)> bb = nullptr)
{
  MWT::Mwt_options o;
  o.convex_position_by_dynamic_program = false;
  return MWT::minimum_weight_triangulation_2(p, o, Scripted_solver{edit}, bb);
}

MWT::Sparse_linear_program small_lp()
{
  // min x0 + 2 x1  s.t.  x0 + x1 = 1, x >= 0
  MWT::Sparse_linear_program lp;
  lp.add_row(1, 1);
  const int r[1] = {0};
  const double v[1] = {1};
  lp.add_column(1, 0, MWT::Sparse_linear_program::infinity(), r, v, 1);
  lp.add_column(2, 0, MWT::Sparse_linear_program::infinity(), r, v, 1);
  return lp;
}

} // namespace

TEST_CASE("mwt range: coordinates beyond 2^500 or a bounding box below 2^-400 are refused up front", "[mwt][checks][input]")
{
  const std::vector<Point> unit = uniform_points(20, 3);
  for(MWT::Lp_solver_choice c : all_solvers) {
    MWT::Mwt_options o;
    o.solver = c;
    INFO("solver " << int(c));
    // the reproducer of issue 28: near 1e300 CLP and GLPK aborted on assertions, GLPK gave weight inf and a NaN LP
    CHECK_THROWS_WITH(MWT::minimum_weight_triangulation_2(scaled(unit, 996), o), Catch::Contains("2^500"));
    CHECK_THROWS_AS(MWT::minimum_weight_triangulation_2(scaled(unit, 501), o), std::invalid_argument);
    // 1e-200 gave weight 0, 1e-160 a heavier uncertified triangulation
    CHECK_THROWS_WITH(MWT::minimum_weight_triangulation_2(scaled(unit, -664), o), Catch::Contains("2^-400"));
    CHECK_THROWS_AS(MWT::minimum_weight_triangulation_2(scaled(unit, -532), o), std::invalid_argument);
  }
  // one far point is enough, and the message names it by its input index
  std::vector<Point> one_far = unit;
  one_far[7] = Point(1e300, 0.5);
  CHECK_THROWS_WITH(MWT::minimum_weight_triangulation_2(one_far), Catch::Contains("point 7"));
  // the other entry points of the package check the same range
  std::vector<std::array<int, 3>> tri;
  CHECK_THROWS_WITH(MWT::convex_polygon_mwt_2(scaled(circle(8), 990), std::back_inserter(tri)), Catch::Contains("2^500"));
  CHECK_THROWS_AS(MWT::make_edge_based_lp_2(scaled(unit, -600)), std::invalid_argument);
  CHECK_THROWS_AS((MWT::Minimum_weight_triangulation_lp_2<K>(scaled(unit, 600))), std::invalid_argument);
}

TEST_CASE("mwt range: inside the range, scaling by a power of two scales the weight and keeps the triangles", "[mwt][checks][oracle]")
{
  const std::vector<Point> unit = uniform_points(25, 11);
  MWT::Mwt_options base;
  const MWT::Mwt_result ref = MWT::minimum_weight_triangulation_2(unit, base);
  REQUIRE(ref.status == MWT::Mwt_status::certified_optimal);
  // the extremes of the range: max |coordinate| <= 2^500 and a bounding box side >= 2^-400
  for(int e : {499, 300, -300, -399}) {
    for(MWT::Lp_solver_choice c : all_solvers) {
      MWT::Mwt_options o;
      o.solver = c;
      INFO("exponent " << e << ", solver " << int(c));
      const MWT::Mwt_result r = MWT::minimum_weight_triangulation_2(scaled(unit, e), o);
      REQUIRE(r.has_triangulation());
      CHECK(r.status == MWT::Mwt_status::certified_optimal);
      CHECK(std::isfinite(r.weight));
      CHECK(std::isfinite(r.lp_objective));
      CHECK(std::ldexp(r.weight, -e) == Approx(ref.weight).epsilon(1e-12));
      CHECK(std::ldexp(r.lower_bound, -e) <= ref.weight * (1 + 1e-12));
      auto sorted = [](std::vector<std::array<int, 3>> t) {
        for(auto& x : t) std::rotate(x.begin(), std::min_element(x.begin(), x.end()), x.end());
        std::sort(t.begin(), t.end());
        return t;
      };
      CHECK(sorted(r.triangles) == sorted(ref.triangles));
    }
  }
  // the exact limits themselves are inside
  std::vector<Point> corner{Point(std::ldexp(1.0, 500), 0), Point(0, std::ldexp(-1.0, 500)), Point(-std::ldexp(1.0, 500), 0)};
  CHECK(MWT::minimum_weight_triangulation_2(corner).status == MWT::Mwt_status::certified_optimal);
  std::vector<Point> tiny{Point(0, 0), Point(std::ldexp(1.0, -400), 0), Point(0, std::ldexp(1.0, -401))};
  const MWT::Mwt_result t = MWT::minimum_weight_triangulation_2(tiny);
  CHECK(t.status == MWT::Mwt_status::certified_optimal);
  CHECK(t.weight > 0);
}

TEST_CASE("mwt checks: a solver answer with NaN or infinite numbers never becomes a result", "[mwt][checks]")
{
  const std::vector<Point> p = uniform_points(30, 5);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const std::vector<std::pair<const char*, std::function<void(MWT::Linear_program_solution&)>>> edits{
    {"NaN objective", [nan](MWT::Linear_program_solution& s) { s.objective = nan; }},
    {"infinite objective", [inf](MWT::Linear_program_solution& s) { s.objective = inf; }},
    {"NaN primal value", [nan](MWT::Linear_program_solution& s) { s.primal[3] = nan; }},
    {"infinite primal value", [inf](MWT::Linear_program_solution& s) { s.primal.back() = -inf; }},
    {"too few primal values", [](MWT::Linear_program_solution& s) { s.primal.pop_back(); }},
    {"too many duals", [](MWT::Linear_program_solution& s) { s.dual.push_back(0); }},
    {"failed status", [](MWT::Linear_program_solution& s) { s.status = MWT::Lp_status::failed; }},
  };
  for(const auto& e : edits) {
    INFO(e.first);
    const MWT::Mwt_result r = run_scripted(p, e.second);
    CHECK(r.status == MWT::Mwt_status::solver_failed);
    CHECK_FALSE(r.has_triangulation());
    CHECK(r.message.find("LP solver") != std::string::npos);
  }
  // NaN duals only cost the certificate: the triangulation stays, the bound says nothing
  const MWT::Mwt_result d = run_scripted(p, [nan](MWT::Linear_program_solution& s) { s.dual.assign(s.dual.size(), nan); });
  REQUIRE(d.has_triangulation());
  CHECK(std::isfinite(d.weight));
  CHECK(d.lower_bound == -std::numeric_limits<double>::infinity());
  CHECK(d.status == MWT::Mwt_status::optimal_uncertified);
  // a time limit of the solver is a status, a cancellation an exception
  const MWT::Mwt_result t = run_scripted(p, [](MWT::Linear_program_solution& s) {
    s = MWT::Linear_program_solution();
    s.status = MWT::Lp_status::time_limit;
  });
  CHECK(t.status == MWT::Mwt_status::time_limit_reached);
  CHECK_FALSE(t.has_triangulation());
  CHECK(std::string(MWT::to_string(t.status)) == "time_limit_reached");
  CHECK_THROWS_AS(run_scripted(p, [](MWT::Linear_program_solution& s) { s.status = MWT::Lp_status::cancelled; }),
                  CGAL::MDCS::Operation_cancelled);
}

TEST_CASE("mwt checks: a binary solver answer with NaN is not a triangulation", "[mwt][checks][wheel]")
{
  const std::vector<Point> w = wheel(13);   // fractional LP optimum: the binary solver runs
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto keep = [](MWT::Linear_program_solution&) {};
  for(int kind = 0; kind < 3; ++kind) {
    INFO("kind " << kind);
    const MWT::Mwt_result r = run_scripted(w, keep, [kind, nan](const MWT::Sparse_linear_program& lp) {
      MWT::Linear_program_solution s = MWT::GLPK_linear_program_solver().solve_binary(lp);
      if(kind == 0) s.objective = nan;
      if(kind == 1) s.primal[0] = nan;
      if(kind == 2) s.status = MWT::Lp_status::time_limit;
      return s;
    });
    CHECK(r.status == MWT::Mwt_status::fractional_bound_only);
    CHECK_FALSE(r.has_triangulation());
    CHECK(std::isfinite(r.lower_bound));
    CHECK(r.lower_bound < 18.7637);   // the LP bound of the 13-wheel (18.763609)
  }
  const MWT::Mwt_result ok = run_scripted(w, keep, [](const MWT::Sparse_linear_program& lp) {
    return MWT::GLPK_linear_program_solver().solve_binary(lp);
  });
  CHECK(ok.status == MWT::Mwt_status::optimal_after_branch_and_bound);
  CHECK(ok.weight == Approx(18.798885).epsilon(1e-6));
}

TEST_CASE("mwt checks: programs that would abort CLP or GLPK are refused with an exception", "[mwt][checks][lp]")
{
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const MWT::Sparse_linear_program good = small_lp();
  for(const auto& s : {MWT::CLP_linear_program_solver().solve(good), MWT::GLPK_linear_program_solver().solve(good),
                       MWT::GLPK_linear_program_solver(true).solve(good)}) {
    REQUIRE(s.status == MWT::Lp_status::optimal);
    CHECK(s.objective == Approx(1));
    CHECK(MWT::is_usable_optimum(good, s));
  }
  std::vector<std::pair<const char*, std::function<void(MWT::Sparse_linear_program&)>>> bad{
    {"NaN cost", [nan](MWT::Sparse_linear_program& lp) { lp.cost[0] = nan; }},
    {"infinite cost", [inf](MWT::Sparse_linear_program& lp) { lp.cost[1] = inf; }},
    {"infinite matrix entry", [inf](MWT::Sparse_linear_program& lp) { lp.value[0] = inf; }},
    {"NaN bound", [nan](MWT::Sparse_linear_program& lp) { lp.row_upper[0] = nan; }},
    {"empty bounds", [](MWT::Sparse_linear_program& lp) { lp.col_lower[0] = 2; lp.col_upper[0] = 1; }},
    {"+inf lower bound", [inf](MWT::Sparse_linear_program& lp) { lp.col_lower[0] = inf; }},
    {"broken column_start", [](MWT::Sparse_linear_program& lp) { lp.column_start.back() = 7; }},
  };
  for(const auto& b : bad) {
    INFO(b.first);
    MWT::Sparse_linear_program lp = small_lp();
    b.second(lp);
    CHECK_THROWS_AS(lp.check(), std::invalid_argument);
    CHECK_THROWS_AS(MWT::CLP_linear_program_solver().solve(lp), std::invalid_argument);
    CHECK_THROWS_AS(MWT::GLPK_linear_program_solver().solve(lp), std::invalid_argument);
    CHECK_THROWS_AS(MWT::GLPK_linear_program_solver().solve_binary(lp), std::invalid_argument);
  }
  // CLP asserts on objective coefficients of 1e25: refused, GLPK takes them
  MWT::Sparse_linear_program huge = small_lp();
  huge.cost[1] = 1e30;
  CHECK_THROWS_WITH(MWT::CLP_linear_program_solver().solve(huge), Catch::Contains("1e20"));
  const auto g = MWT::GLPK_linear_program_solver().solve(huge);
  CHECK(g.status == MWT::Lp_status::optimal);
  CHECK(g.objective == Approx(1));
  // solution records: NaN, wrong sizes and non-optimal statuses are not usable
  MWT::Linear_program_solution s = MWT::CLP_linear_program_solver().solve(good);
  std::string why;
  s.objective = nan;
  CHECK_FALSE(MWT::is_usable_optimum(good, s, &why));
  CHECK(why.find("objective") != std::string::npos);
}

TEST_CASE("mwt checks: user triangle weights of any magnitude reach the LP scaled; an overflowing total is refused", "[mwt][checks][metric]")
{
  const std::vector<Point> p = uniform_points(12, 9);
  auto weight = [](double factor) {
    return [factor](double ax, double ay, double bx, double by, double cx, double cy) {
      const double per = std::hypot(bx - ax, by - ay) + std::hypot(cx - bx, cy - by) + std::hypot(ax - cx, ay - cy);
      return factor * (1 + per);
    };
  };
  MWT::Mwt_options o1;
  o1.triangle_weight = weight(1);
  const MWT::Mwt_result ref = MWT::minimum_weight_triangulation_2(p, o1);
  REQUIRE(ref.has_triangulation());
  for(MWT::Lp_solver_choice c : all_solvers) {
    INFO("solver " << int(c));
    MWT::Mwt_options o;
    o.solver = c;
    o.triangle_weight = weight(1e300);   // CLP aborted on LP costs of 1e25 before
    const MWT::Mwt_result r = MWT::minimum_weight_triangulation_2(p, o);
    REQUIRE(r.has_triangulation());
    CHECK(r.weight / 1e300 == Approx(ref.weight).epsilon(1e-12));
    CHECK(std::isfinite(r.lp_objective));
    o.triangle_weight = weight(1e307);   // each weight finite, their sum not
    CHECK_THROWS_WITH(MWT::minimum_weight_triangulation_2(p, o), Catch::Contains("not finite"));
  }
}

TEST_CASE("mwt convex position: solved by the exact convex program, equal to the LP and to brute force", "[mwt][checks][convex][oracle]")
{
  for(int n : {3, 4, 7, 9}) {
    const std::vector<Point> p = circle(n);
    const MWT::Mwt_result r = MWT::minimum_weight_triangulation_2(p);
    INFO("n " << n);
    REQUIRE(r.status == MWT::Mwt_status::certified_optimal);
    CHECK(r.statistics.lp_columns == 0);
    CHECK(r.statistics.dp_triangles == std::size_t(n - 2));
    CHECK(r.weight == Approx(brute_force_mwt(p)).epsilon(1e-12));
    CHECK(independent_triangulation_check(p, r.triangles));
  }
  // the 64 cocircular points (285 s in GLPK before): every solver choice, the LP path as the oracle
  const std::vector<Point> p = circle(64);
  MWT::Mwt_options lp_path;
  lp_path.convex_position_by_dynamic_program = false;
  const MWT::Mwt_result oracle = MWT::minimum_weight_triangulation_2(p, lp_path);   // CLP, a few seconds
  REQUIRE(oracle.has_triangulation());
  CHECK(oracle.statistics.lp_columns == 41664u);   // C(64, 3): every triangle is empty in convex position
  for(MWT::Lp_solver_choice c : all_solvers) {
    MWT::Mwt_options o;
    o.solver = c;
    INFO("solver " << int(c));
    const auto t0 = std::chrono::steady_clock::now();
    const MWT::Mwt_result r = MWT::minimum_weight_triangulation_2(p, o);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    REQUIRE(r.status == MWT::Mwt_status::certified_optimal);
    CHECK(r.triangles.size() == 62u);
    CHECK(r.statistics.lp_columns == 0);
    CHECK(r.weight == Approx(oracle.weight).epsilon(1e-12));
    CHECK(r.lower_bound <= r.weight);
    CHECK(r.lower_bound >= r.weight * (1 - 1e-12));
    CHECK(seconds < 30);   // a bound against regressions to the LP path (0.1 s measured under load)
  }
  // the program reports progress and can be cancelled
  int calls = 0;
  MWT::Mwt_options o;
  o.progress = [&calls](const char* stage, double) { return std::string(stage) != "convex dynamic program" || ++calls < 3; };
  CHECK_THROWS_AS(MWT::minimum_weight_triangulation_2(p, o), CGAL::MDCS::Operation_cancelled);
  CHECK(calls == 3);
  // collinear points on the hull are not strictly convex position: the LP path, still correct
  const std::vector<Point> square{Point(0, 0), Point(1, 0), Point(2, 0), Point(2, 1), Point(0, 1)};
  const MWT::Mwt_result s = MWT::minimum_weight_triangulation_2(square);
  CHECK(s.statistics.lp_columns > 0);
  CHECK(s.weight == Approx(brute_force_mwt(square)).epsilon(1e-12));
}

TEST_CASE("mwt time limit: every built-in LP model stops at the limit with a status", "[mwt][checks][progress]")
{
  CHECK(MWT::Mwt_options().lp_time_limit == 0);   // no limit by default
  // 64 points on a circle and one inside: an LP of 39,078 columns, a second (CLP) to seconds (GLPK) to solve
  const std::vector<Point> p = near_circle(64);
  for(MWT::Lp_solver_choice c : all_solvers) {
    MWT::Mwt_options o;
    o.solver = c;
    o.lp_time_limit = 0.02;
    INFO("solver " << int(c));
    const MWT::Mwt_result r = MWT::minimum_weight_triangulation_2(p, o);
    CHECK(r.status == MWT::Mwt_status::time_limit_reached);
    CHECK_FALSE(r.has_triangulation());
    CHECK(r.statistics.time_lp_solve < 2.0);
    CHECK(r.message.find("time limit") != std::string::npos);
  }
  MWT::Mwt_options bad;
  bad.lp_time_limit = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(MWT::minimum_weight_triangulation_2(p, bad), std::invalid_argument);
  bad.lp_time_limit = -1;
  CHECK_THROWS_AS(MWT::minimum_weight_triangulation_2(p, bad), std::invalid_argument);
}

TEST_CASE("mwt progress: the LP solvers report during the solve and can be cancelled", "[mwt][checks][progress]")
{
  const std::vector<Point> p = near_circle(64);
  // GLPK: slices of the simplex (a hundredth of the limit here); the solve takes seconds
  {
    std::vector<double> fractions;
    MWT::Mwt_options o;
    o.solver = MWT::Lp_solver_choice::glpk;
    o.lp_time_limit = 5;   // reports every 0.05 s
    o.progress = [&fractions](const char* stage, double f) {
      if(std::string(stage) == "LP solve") fractions.push_back(f);
      return fractions.size() < 4;   // the first call is before the solve, the last after it
    };
    CHECK_THROWS_AS(MWT::minimum_weight_triangulation_2(p, o), CGAL::MDCS::Operation_cancelled);
    REQUIRE(fractions.size() == 4);
    CHECK(fractions[0] == 0);
    for(std::size_t i = 1; i < fractions.size(); ++i) {
      CHECK(fractions[i] > 0);
      CHECK(fractions[i] < 1);
      CHECK(fractions[i] >= fractions[i - 1]);
    }
  }
  // every model through its control: the callback is asked during the solve and stops it
  const MWT::Sparse_linear_program lp = [&] {
    MWT::Minimum_weight_triangulation_lp_2<K> m(near_circle(64));
    m.build_linear_program();
    return m.linear_program();
  }();
  int calls = 0;
  MWT::Lp_solve_control control;
  control.time_limit = 2;   // asks every 0.05 s
  control.keep_going = [&calls](double) { return ++calls < 2; };
  MWT::CLP_linear_program_solver clp;
  clp.set_control(control);
  MWT::GLPK_linear_program_solver glpk, exact(true);
  glpk.set_control(control);
  exact.set_control(control);
  for(int model = 0; model < 3; ++model) {
    calls = 0;
    const MWT::Linear_program_solution s = model == 0 ? clp.solve(lp) : model == 1 ? glpk.solve(lp) : exact.solve(lp);
    INFO("model " << model << ": " << s.message);
    CHECK(s.status == MWT::Lp_status::cancelled);
    CHECK(calls == 2);   // once before the simplex, once from inside it
  }
  // branch and bound: time limit and cancellation through the same control
  MWT::Minimum_weight_triangulation_lp_2<K> w(wheel(13));
  w.build_linear_program();
  MWT::Lp_solve_control stop_at_once;
  stop_at_once.keep_going = [](double) { return false; };
  MWT::GLPK_linear_program_solver bb;
  bb.set_control(stop_at_once);
  const auto c = bb.solve_binary(w.linear_program());
  CHECK(c.status == MWT::Lp_status::cancelled);
  CHECK(MWT::GLPK_linear_program_solver::was_cancelled(c));
}

#endif // MDCS_HAS_CLP && MDCS_HAS_GLPK
