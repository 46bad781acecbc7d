// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bad input gets a clear std::invalid_argument; the convex-polygon dynamic program against the LP and
// brute force; cancellation by the progress callback (also inside branch and bound).

// Needs both LP solver models (found and defined by the build: MDCS_HAS_CLP, MDCS_HAS_GLPK).
#if defined(MDCS_HAS_CLP) && defined(MDCS_HAS_GLPK)

#include "mwt_test_helpers.h"

#include <CGAL/MDCS/progress.h>

#include <catch2/catch.hpp>

#include <iterator>
#include <limits>

using namespace mwt_test;

TEST_CASE("mwt: bad input is rejected with a clear message", "[mwt][input]")
{
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  std::vector<std::vector<Point>> bad{
    {},
    {Point(0, 0), Point(1, 0)},
    {Point(0, 0), Point(1, 1), Point(2, 2), Point(3, 3)},
    {Point(0, 0), Point(1, 0), Point(0, 1), Point(1, 0)},
    {Point(0, 0), Point(1, 0), Point(nan, 1)},
    {Point(0, 0), Point(1, 0), Point(0, inf)},
  };
  for(std::size_t i = 0; i < bad.size(); ++i) {
    INFO("case " << i);
    CHECK_THROWS_AS(MWT::minimum_weight_triangulation_2(bad[i]), std::invalid_argument);
  }
  CHECK_THROWS_WITH(MWT::minimum_weight_triangulation_2(bad[2]), Catch::Contains("collinear"));
  CHECK_THROWS_WITH(MWT::minimum_weight_triangulation_2(bad[3]), Catch::Contains("duplicate"));
  CHECK_THROWS_WITH(MWT::minimum_weight_triangulation_2(bad[1]), Catch::Contains("at least 3"));
  MWT::Mwt_options o;
  o.metric = MWT::Edge_metric::L1;
  o.pruning = MWT::Pruning::diamond;
  CHECK_THROWS_AS(MWT::minimum_weight_triangulation_2(uniform_points(10, 1), o), std::invalid_argument);
  MWT::Mwt_options neg;
  neg.triangle_weight = [](double, double, double, double, double, double) { return -1.0; };
  CHECK_THROWS_AS(MWT::minimum_weight_triangulation_2(uniform_points(6, 1), neg), std::invalid_argument);
}

TEST_CASE("mwt: three points give one triangle", "[mwt][input]")
{
  const std::vector<Point> p{Point(0, 0), Point(1, 0), Point(0, 1)};
  const auto r = MWT::minimum_weight_triangulation_2(p);
  REQUIRE(r.triangles.size() == 1);
  CHECK(r.status == MWT::Mwt_status::certified_optimal);
  CHECK(r.weight == Approx(2 + std::sqrt(2.0)));
}

TEST_CASE("mwt: the progress callback can cancel", "[mwt][progress]")
{
  MWT::Mwt_options o;
  o.progress = [](const char* stage, double) { return std::string(stage) != "empty triangles"; };
  CHECK_THROWS_AS(MWT::minimum_weight_triangulation_2(uniform_points(50, 1), o), CGAL::MDCS::Operation_cancelled);
}

TEST_CASE("mwt: branch and bound has a default time limit and stops when the callback says so", "[mwt][progress]")
{
  CHECK(MWT::Mwt_options().branch_and_bound_time_limit > 0);
  // the 41-wheel's LP is fractional; the first "branch and bound" call comes before GLPK starts, later ones
  // from inside GLPK's branch and cut
  int calls = 0;
  MWT::Mwt_options o;
  o.progress = [&calls](const char* stage, double) { return std::string(stage) != "branch and bound" || ++calls < 2; };
  CHECK_THROWS_AS(MWT::minimum_weight_triangulation_2(wheel(41), o), CGAL::MDCS::Operation_cancelled);
  CHECK(calls == 2);
  // without cancellation the same run ends with the branch-and-bound optimum
  MWT::Mwt_options plain;
  int bb_calls = 0;
  plain.progress = [&bb_calls](const char* stage, double) { bb_calls += std::string(stage) == "branch and bound"; return true; };
  const auto r = MWT::minimum_weight_triangulation_2(wheel(41), plain);
  CHECK(r.status == MWT::Mwt_status::optimal_after_branch_and_bound);
  CHECK(bb_calls > 2);
}

TEST_CASE("convex_polygon_mwt_2: against brute force and the LP", "[mwt][convex][oracle]")
{
  std::mt19937 g(17);
  std::uniform_real_distribution<double> u(0, 2 * M_PI), rad(0.5, 2.0);
  for(int trial = 0; trial < 10; ++trial) {
    const int k = 4 + trial % 5;
    std::vector<double> a;
    for(int i = 0; i < k; ++i) a.push_back(u(g));
    std::sort(a.begin(), a.end());
    const double ex = rad(g), ey = rad(g);   // an ellipse: convex position
    std::vector<Point> p;
    for(double t : a) p.emplace_back(ex * std::cos(t), ey * std::sin(t));
    std::vector<std::array<int, 3>> tri;
    const double w = MWT::convex_polygon_mwt_2(p, std::back_inserter(tri));
    INFO("trial " << trial);
    CHECK(tri.size() == std::size_t(k - 2));
    CHECK(w == Approx(brute_force_mwt(p)).epsilon(1e-12));
    CHECK(w == Approx(edge_weight(p, tri)).epsilon(1e-12));
    CHECK(independent_triangulation_check(p, tri));
    MWT::Mwt_options lp_path;
    lp_path.convex_position_by_dynamic_program = false;   // the LP, not the convex program again
    const auto r = MWT::minimum_weight_triangulation_2(p, lp_path);
    CHECK(r.lp_integral);   // thesis lemma 3.6.1: convex position gives integral LP optima
    CHECK(r.weight == Approx(w).epsilon(1e-12));
  }
}

TEST_CASE("convex_polygon_mwt_2: larger convex polygons agree with the LP; bad polygons are rejected", "[mwt][convex]")
{
  std::vector<Point> p;
  std::mt19937 g(5);
  std::uniform_real_distribution<double> u(0, 2 * M_PI);
  std::vector<double> a;
  for(int i = 0; i < 40; ++i) a.push_back(u(g));
  std::sort(a.begin(), a.end());
  for(double t : a) p.emplace_back(3 * std::cos(t), std::sin(t));
  std::vector<std::array<int, 3>> tri;
  const double w = MWT::convex_polygon_mwt_2(p, std::back_inserter(tri));
  MWT::Mwt_options lp_path;
  lp_path.convex_position_by_dynamic_program = false;   // the LP, not the convex program again
  const auto r = MWT::minimum_weight_triangulation_2(p, lp_path);
  CHECK(r.lp_integral);
  CHECK(r.weight == Approx(w).epsilon(1e-12));
  std::vector<Point> cw(p.rbegin(), p.rend());
  CHECK_THROWS_AS(MWT::convex_polygon_mwt_2(cw, std::back_inserter(tri)), std::invalid_argument);
  std::vector<Point> star;
  for(int i = 0; i < 5; ++i) star.emplace_back(std::cos(4 * M_PI * i / 5), std::sin(4 * M_PI * i / 5));
  CHECK_THROWS_AS(MWT::convex_polygon_mwt_2(star, std::back_inserter(tri)), std::invalid_argument);
}

#endif // MDCS_HAS_CLP && MDCS_HAS_GLPK
