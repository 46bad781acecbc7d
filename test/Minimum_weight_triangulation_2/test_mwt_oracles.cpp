// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// minimum_weight_triangulation_2 against oracles: brute force on small sets (random, degenerate, other
// metrics), the thesis's wheel values, odd wheels fractional, pruning never changing the optimum,
// integrality on random uniform and clustered sets, an independent triangulation check.

// Needs both LP solver models (found and defined by the build: MDCS_HAS_CLP, MDCS_HAS_GLPK).
#if defined(MDCS_HAS_CLP) && defined(MDCS_HAS_GLPK)

#include "mwt_test_helpers.h"

#include <catch2/catch.hpp>

using namespace mwt_test;

TEST_CASE("mwt: brute force on random small sets", "[mwt][oracle]")
{
  for(unsigned seed = 1; seed <= 25; ++seed) {
    const int n = 4 + int(seed % 5);   // 4..8 points
    const auto p = uniform_points(n, seed);
    const auto r = MWT::minimum_weight_triangulation_2(p);
    INFO("seed " << seed << " n " << n << " status " << MWT::to_string(r.status));
    REQUIRE(r.has_triangulation());
    CHECK(r.status == MWT::Mwt_status::certified_optimal);
    CHECK(r.weight == Approx(brute_force_mwt(p)).epsilon(1e-12));
    CHECK(r.lower_bound <= r.weight + 1e-12);
    CHECK(independent_triangulation_check(p, r.triangles));
  }
}

TEST_CASE("mwt: brute force on degenerate sets (collinear triples, grid points)", "[mwt][oracle][degenerate]")
{
  std::vector<std::vector<Point>> sets;
  sets.push_back({Point(0, 0), Point(1, 0), Point(2, 0), Point(1, 1)});                       // collinear hull side
  sets.push_back({Point(0, 0), Point(2, 0), Point(0, 2), Point(2, 2), Point(1, 1)});          // centre on diagonals
  sets.push_back({Point(0, 0), Point(1, 0), Point(2, 0), Point(0, 1), Point(1, 1), Point(2, 1), Point(0, 2), Point(1, 2)});
  sets.push_back({Point(0, 0), Point(3, 0), Point(1, 1), Point(2, 2), Point(0, 3), Point(3, 3)});  // collinear interior
  sets.push_back(wheel(6));   // even wheel: the centre is collinear with antipodal pairs
  sets.push_back(wheel(8));
  for(std::size_t i = 0; i < sets.size(); ++i) {
    const auto& p = sets[i];
    INFO("set " << i);
    const auto r = MWT::minimum_weight_triangulation_2(p);
    REQUIRE(r.has_triangulation());
    CHECK(r.weight == Approx(brute_force_mwt(p)).epsilon(1e-12));
    CHECK(independent_triangulation_check(p, r.triangles));
    CHECK(r.weight == Approx(edge_weight(p, r.triangles)).epsilon(1e-14));
  }
}

TEST_CASE("mwt: L1 and Linf metrics against brute force", "[mwt][oracle][metric]")
{
  for(MWT::Edge_metric m : {MWT::Edge_metric::L1, MWT::Edge_metric::Linf}) {
    for(unsigned seed = 1; seed <= 8; ++seed) {
      const auto p = uniform_points(5 + int(seed % 3), 100 + seed);
      MWT::Mwt_options o;
      o.metric = m;
      const auto r = MWT::minimum_weight_triangulation_2(p, o);
      INFO("seed " << seed);
      REQUIRE(r.has_triangulation());
      CHECK(r.weight == Approx(brute_force_mwt(p, m)).epsilon(1e-12));
      CHECK(r.weight == Approx(edge_weight(p, r.triangles, m)).epsilon(1e-12));
    }
  }
}

TEST_CASE("mwt: user triangle weight equal to the alpha-weighted L2 weight gives the same MWT", "[mwt][metric]")
{
  const auto p = uniform_points(30, 7);
  const auto ref = MWT::minimum_weight_triangulation_2(p);
  // with the diamond test off, every triangle's weight from the user callable: use the perimeter, which
  // counts each interior edge twice -> total = 2 * weight - hull perimeter, same minimiser.
  MWT::Mwt_options o;
  o.triangle_weight = [](double ax, double ay, double bx, double by, double cx, double cy) {
    return std::hypot(bx - ax, by - ay) + std::hypot(cx - bx, cy - by) + std::hypot(ax - cx, ay - cy);
  };
  const auto r = MWT::minimum_weight_triangulation_2(p, o);
  REQUIRE(r.has_triangulation());
  std::vector<Point> hull;
  CGAL::convex_hull_2(p.begin(), p.end(), std::back_inserter(hull));
  double perimeter = 0;
  for(std::size_t i = 0; i < hull.size(); ++i) perimeter += length(hull[i], hull[(i + 1) % hull.size()]);
  CHECK(r.weight == Approx(2 * ref.weight - perimeter).epsilon(1e-12));   // the sum of the user weights
  CHECK(edge_weight(p, r.triangles) == Approx(ref.weight).epsilon(1e-12));
}

TEST_CASE("mwt: the thesis's 13-wheel: LP 18.7636 (fractional), MWT 18.7989", "[mwt][oracle][wheel]")
{
  const auto p = wheel(13);
  MWT::Mwt_options o;
  o.resolve_fractional = false;
  const auto lp_only = MWT::minimum_weight_triangulation_2(p, o);
  CHECK(lp_only.status == MWT::Mwt_status::fractional_bound_only);
  CHECK_FALSE(lp_only.lp_integral);
  CHECK(lp_only.lp_objective == Approx(18.7636).margin(5e-5));
  CHECK(lp_only.lower_bound == Approx(18.7636).margin(5e-5));
  CHECK_FALSE(lp_only.has_triangulation());
  const auto r = MWT::minimum_weight_triangulation_2(p);
  CHECK(r.status == MWT::Mwt_status::optimal_after_branch_and_bound);
  CHECK(r.weight == Approx(18.7989).margin(5e-5));
  CHECK(r.lower_bound <= r.weight);
  CHECK(independent_triangulation_check(p, r.triangles));
}

TEST_CASE("mwt: odd wheels k = 13, 15, 17 have fractional LP optima below the MWT", "[mwt][wheel]")
{
  for(int k : {13, 15, 17}) {
    const auto p = wheel(k);
    const auto r = MWT::minimum_weight_triangulation_2(p);
    INFO("k = " << k);
    CHECK_FALSE(r.lp_integral);
    CHECK(r.status == MWT::Mwt_status::optimal_after_branch_and_bound);
    CHECK(r.lp_objective < r.weight - 1e-3);
    CHECK(independent_triangulation_check(p, r.triangles));
  }
}

TEST_CASE("mwt: small wheels against brute force (even wheels are degenerate)", "[mwt][oracle][wheel]")
{
  for(int k : {5, 6, 7, 8}) {
    const auto p = wheel(k);
    const auto r = MWT::minimum_weight_triangulation_2(p);
    INFO("k = " << k);
    REQUIRE(r.has_triangulation());
    CHECK(r.weight == Approx(brute_force_mwt(p)).epsilon(1e-12));
  }
}

TEST_CASE("mwt: pruning never changes the optimum (diamond test vs all edges)", "[mwt][pruning]")
{
  for(unsigned seed = 1; seed <= 6; ++seed) {
    const auto p = seed % 2 ? uniform_points(40, seed) : clustered_points(40, seed);
    MWT::Mwt_options full;
    full.pruning = MWT::Pruning::none;
    const auto a = MWT::minimum_weight_triangulation_2(p);
    const auto b = MWT::minimum_weight_triangulation_2(p, full);
    INFO("seed " << seed);
    REQUIRE(a.has_triangulation());
    REQUIRE(b.has_triangulation());
    CHECK(a.weight == Approx(b.weight).epsilon(1e-12));
    CHECK(a.statistics.candidate_edges < b.statistics.candidate_edges);
  }
}

TEST_CASE("mwt: random uniform and clustered sets give integral, certified LP optima", "[mwt][integrality]")
{
  int integral = 0, total = 0;
  for(unsigned seed = 1; seed <= 10; ++seed) {
    for(int kind = 0; kind < 2; ++kind) {
      const auto p = kind ? clustered_points(150, seed) : uniform_points(150, seed);
      const auto r = MWT::minimum_weight_triangulation_2(p);
      ++total;
      integral += r.lp_integral;
      INFO("seed " << seed << " kind " << kind << ": " << r.message);
      CHECK(r.status == MWT::Mwt_status::certified_optimal);
      CHECK(r.lower_bound <= r.weight * (1 + 1e-12));
      CHECK(r.weight - r.lower_bound <= 1e-9 * r.weight);
    }
  }
  CHECK(integral == total);
}

TEST_CASE("mwt: the MWT is not heavier than the Delaunay triangulation", "[mwt][invariant]")
{
  const auto p = uniform_points(200, 3);
  const auto r = MWT::minimum_weight_triangulation_2(p);
  REQUIRE(r.has_triangulation());
  CHECK(independent_triangulation_check(p, r.triangles));
  CGAL::Delaunay_triangulation_2<K> dt(p.begin(), p.end());
  double w = 0;
  for(auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) w += std::sqrt(CGAL::to_double(dt.segment(*e).squared_length()));
  CHECK(r.weight <= w + 1e-12);
}

#endif // MDCS_HAS_CLP && MDCS_HAS_GLPK
