// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The thesis's ch. 3.4.3 and 3.5: the six-point double covering of Fig. 3.3 (a feasible point of the triangle LP
// that is no union of two triangulations) and the random wheels of Fig. 3.5 (generator, and every result against
// the exhaustive oracle).

// Needs both LP solver models (found and defined by the build: MDCS_HAS_CLP, MDCS_HAS_GLPK).
#if defined(MDCS_HAS_CLP) && defined(MDCS_HAS_GLPK)

#include "mwt_exhaustive_oracle.h"
#include "mwt_test_helpers.h"

#include <MDCS_test/random_wheels.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <set>
#include <vector>

namespace random_wheel_test {

using namespace mwt_test;
typedef std::array<int, 3> Tri;

// Fig. 3.3: the centre (index 0) and a regular pentagon p_1..p_5 around it.
std::vector<Point> fig33_points()
{
  std::vector<Point> p{Point(0, 0)};
  for(int i = 0; i < 5; ++i) p.emplace_back(std::cos(M_PI / 2 + 2 * M_PI * i / 5), std::sin(M_PI / 2 + 2 * M_PI * i / 5));
  return p;
}

// Pentagon corner i (any integer) as a point index.
int fig33_corner(int i) { return 1 + ((i % 5) + 5) % 5; }

// The double covering of Fig. 3.3b/c: the pair (centre, p_i, p_i+2) and the ear (p_i, p_i+1, p_i+2), turned
// around the centre (the thesis turns the pair by 4 pi k / 5, i.e. i -> i + 2k, which reaches every i).
std::vector<Tri> fig33_double_covering()
{
  std::vector<Tri> d;
  for(int i = 0; i < 5; ++i) {
    d.push_back({0, fig33_corner(i), fig33_corner(i + 2)});
    d.push_back({fig33_corner(i), fig33_corner(i + 1), fig33_corner(i + 2)});
  }
  return d;
}

Tri sorted_triangle(Tri t)
{
  std::sort(t.begin(), t.end());
  return t;
}

// How many triangles of `tri` hold q in their interior; -1 when q is on the boundary of one of them.
int covering_number(const std::vector<Point>& p, const std::vector<Tri>& tri, const Point& q)
{
  int count = 0;
  for(const Tri& t : tri) {
    const CGAL::Bounded_side s = K::Triangle_2(p[t[0]], p[t[1]], p[t[2]]).bounded_side(q);
    if(s == CGAL::ON_BOUNDARY) return -1;
    count += s == CGAL::ON_BOUNDED_SIDE;
  }
  return count;
}

// Every empty triangle of p (no other point inside or on it), counter-clockwise, by brute force.
std::vector<Tri> all_empty_triangles(const std::vector<Point>& p)
{
  std::vector<Tri> out;
  const int n = int(p.size());
  for(int a = 0; a < n; ++a)
    for(int b = a + 1; b < n; ++b)
      for(int c = b + 1; c < n; ++c) {
        if(CGAL::collinear(p[a], p[b], p[c])) continue;
        const K::Triangle_2 t(p[a], p[b], p[c]);
        bool empty = true;
        for(int d = 0; d < n && empty; ++d)
          if(d != a && d != b && d != c && !t.has_on_unbounded_side(p[d])) empty = false;
        if(empty) out.push_back(CGAL::left_turn(p[a], p[b], p[c]) ? Tri{a, b, c} : Tri{a, c, b});
      }
  return out;
}

// The subsets of `tri` of `size` triangles that are triangulations of p (independent_triangulation_check).
std::vector<std::vector<Tri>> triangulations_among(const std::vector<Point>& p, const std::vector<Tri>& tri, std::size_t size)
{
  std::vector<std::vector<Tri>> out;
  std::vector<Tri> chosen;
  std::function<void(std::size_t)> pick = [&](std::size_t next) {
    if(chosen.size() == size) {
      if(independent_triangulation_check(p, chosen)) out.push_back(chosen);
      return;
    }
    for(std::size_t i = next; i + (size - chosen.size()) <= tri.size(); ++i) {
      chosen.push_back(tri[i]);
      pick(i + 1);
      chosen.pop_back();
    }
  };
  pick(0);
  return out;
}

} // namespace random_wheel_test

using namespace random_wheel_test;

TEST_CASE("mwt: the six-point double covering of thesis Fig. 3.3 is a feasible LP point, not two triangulations",
          "[mwt][thesis][double-covering]")
{
  const std::vector<Point> p = fig33_points();
  const std::vector<Tri> D = fig33_double_covering();
  REQUIRE(D.size() == 10);

  // A double covering: every sampled point strictly inside the pentagon lies in exactly two of its triangles
  // (the fan, a triangulation, covers it once: the check can tell).
  std::vector<Tri> fan;
  for(int i = 0; i < 5; ++i) fan.push_back({0, fig33_corner(i), fig33_corner(i + 1)});
  std::vector<Point> hull(p.begin() + 1, p.end());
  int sampled = 0;
  for(int i = 0; i <= 40; ++i)
    for(int j = 0; j <= 40; ++j) {
      const Point q(-1 + 0.0131 + i / 20.0, -1 + 0.0077 + j / 20.0);
      if(CGAL::bounded_side_2(hull.begin(), hull.end(), q) != CGAL::ON_BOUNDED_SIDE) continue;
      const int twice = covering_number(p, D, q), once = covering_number(p, fan, q);
      if(twice < 0 || once < 0) continue;   // on an edge
      ++sampled;
      INFO("q = " << q);
      CHECK(twice == 2);
      CHECK(once == 1);
    }
  CHECK(sampled > 800);

  // Not splittable into two triangulations: no 5 of its 10 triangles triangulate the points. All empty triangles
  // (15: 5 fan sectors, 5 pairs' centre triangles, 5 ears) do give the 11 triangulations (fan; the centre of
  // degree 4 with one ear, 5; of degree 3 with two ears, 5), so the enumeration finds triangulations where they are.
  CHECK(triangulations_among(p, D, 5).empty());
  const std::vector<Tri> empty = all_empty_triangles(p);
  CHECK(empty.size() == 15);
  CHECK(triangulations_among(p, empty, 5).size() == 11);

  // The library's LP over every empty triangle: x = 1/2 on D, 0 elsewhere, meets every row (hull edges = 1,
  // interior edges balanced), as the thesis argues.
  MWT::Mwt_options o;
  o.pruning = MWT::Pruning::none;
  MWT::Minimum_weight_triangulation_lp_2<K> stages(p, o);
  stages.compute_candidate_edges();
  stages.compute_empty_triangles();
  stages.build_linear_program();
  const MWT::Sparse_linear_program& lp = stages.linear_program();
  REQUIRE(lp.number_of_columns() == 15);
  CHECK(lp.number_of_rows == 15);   // 5 hull edges, 5 spokes, 5 diagonals
  std::set<Tri> in_D;
  for(const Tri& t : D) in_D.insert(sorted_triangle(t));
  std::vector<double> x(lp.number_of_columns(), 0.0);
  std::size_t found = 0;
  for(std::size_t j = 0; j < x.size(); ++j)
    if(in_D.count(sorted_triangle(stages.column_triangle(j)))) { x[j] = 0.5; ++found; }
  CHECK(found == 10);
  std::vector<double> row_value(lp.number_of_rows, 0.0);
  double objective = 0;
  for(std::size_t j = 0; j < x.size(); ++j) {
    objective += lp.cost[j] * x[j] * stages.scale();
    for(int k = lp.column_start[j]; k < lp.column_start[j + 1]; ++k) row_value[std::size_t(lp.row_index[std::size_t(k)])] += lp.value[std::size_t(k)] * x[j];
  }
  for(std::size_t r = 0; r < lp.number_of_rows; ++r) {
    INFO("row " << r);
    CHECK(row_value[r] >= lp.row_lower[r] - 1e-12);
    CHECK(row_value[r] <= lp.row_upper[r] + 1e-12);
  }
  // Its LP value: each hull side s once, each spoke (1) and diagonal d with the half of its two sides' sum 1/2.
  const double s = 2 * std::sin(M_PI / 5), d = 2 * std::sin(2 * M_PI / 5);
  CHECK(objective == Approx(5 * s + 2.5 * 1 + 2.5 * d).epsilon(1e-12));

  // With edge lengths the covering's long diagonals make it heavy (13.13 > 10.88): the library still returns
  // the true MWT, the fan, with an integral LP optimum, equal to the exhaustive oracle.
  const MWT::Mwt_result r = MWT::minimum_weight_triangulation_2(p, o);
  REQUIRE(r.has_triangulation());
  CHECK(r.lp_integral);
  CHECK(r.status == MWT::Mwt_status::certified_optimal);
  const Exhaustive_mwt oracle = exhaustive_mwt(p);
  CHECK(r.weight == Approx(oracle.weight).epsilon(1e-12));
  CHECK(r.weight == Approx(5 * s + 5).epsilon(1e-12));
  CHECK(r.lp_objective < objective - 1);
  CHECK(independent_triangulation_check(p, r.triangles));
}

TEST_CASE("mwt: with weights that favour the Fig. 3.3 double covering the LP optimum is fractional",
          "[mwt][thesis][double-covering]")
{
  // Thesis ch. 3.4.3: "a double-covering can be a solution of the triangle-based LP, if the weights of the
  // triangles of the double covering are small and the weights of all other triangles are large". Weight 1 on
  // D, 3 elsewhere. Every feasible x has sum x = 2n - h - 2 = 5 (the angles at the points add up), so the LP
  // optimum is 5, reached by x = 1/2 on D; no triangulation lies inside D, so no integral point reaches it.
  const std::vector<Point> p = fig33_points();
  std::set<Tri> in_D;
  for(const Tri& t : fig33_double_covering()) in_D.insert(sorted_triangle(t));
  auto index_of = [&p](double x, double y) {
    for(std::size_t i = 0; i < p.size(); ++i)
      if(p[i].x() == x && p[i].y() == y) return int(i);
    return -1;
  };
  MWT::Mwt_options o;
  o.triangle_weight = [&](double ax, double ay, double bx, double by, double cx, double cy) {
    return in_D.count(sorted_triangle({index_of(ax, ay), index_of(bx, by), index_of(cx, cy)})) ? 1.0 : 3.0;
  };
  const MWT::Mwt_result r = MWT::minimum_weight_triangulation_2(p, o);
  CHECK_FALSE(r.lp_integral);
  CHECK(r.lp_objective == Approx(5).epsilon(1e-9));
  CHECK(r.status == MWT::Mwt_status::optimal_after_branch_and_bound);
  // branch and bound against the best of the 11 triangulations (enumerated): 4 triangles of D and one sector
  double best = HUGE_VAL;
  for(const auto& T : triangulations_among(p, all_empty_triangles(p), 5)) {
    double w = 0;
    for(const Tri& t : T) w += in_D.count(sorted_triangle(t)) ? 1.0 : 3.0;
    best = std::min(best, w);
  }
  CHECK(best == 7);
  CHECK(r.weight == Approx(best).epsilon(1e-12));
}

TEST_CASE("mwt: random wheels (thesis Fig. 3.5): the generator's invariants", "[mwt][thesis][random-wheel]")
{
  // Every wheel: the centre first, k points on the unit circle that are the hull's corners, the centre strictly
  // inside; the same seed gives the same wheel.
  CGAL::Random rng(7), again(7);
  long redraws = 0;
  for(int k = 3; k <= 30; ++k) {
    const std::vector<Point> p = MDCS_test::random_wheel<Point>(k, rng, &redraws);
    INFO("k " << k);
    REQUIRE(int(p.size()) == k + 1);
    CHECK(p[0] == Point(0, 0));
    for(int i = 1; i <= k; ++i) CHECK(std::abs(CGAL::to_double(CGAL::squared_distance(p[0], p[i])) - 1) < 1e-15);
    std::vector<Point> hull;
    CGAL::convex_hull_2(p.begin(), p.end(), std::back_inserter(hull));
    CHECK(int(hull.size()) == k);
    CHECK(std::find(hull.begin(), hull.end(), p[0]) == hull.end());
    CHECK(CGAL::bounded_side_2(hull.begin(), hull.end(), p[0]) == CGAL::ON_BOUNDED_SIDE);
    CHECK(MDCS_test::random_wheel<Point>(k, again) == p);
  }
  CHECK_THROWS_AS(MDCS_test::random_wheel<Point>(2, rng), std::invalid_argument);

  // Uniform angles: a draw of k points misses the centre (all in a half circle) with probability k / 2^(k-1);
  // the mean number of redraws per wheel is then q / (1 - q). k = 4: q = 1/2, mean 1; k = 6: q = 3/16, mean
  // 3/13. 4,000 wheels each: standard errors 0.022 and 0.0085.
  for(int k : {4, 6}) {
    CGAL::Random seeded(1000 + unsigned(k));
    long r = 0;
    const int wheels = 4000;
    for(int i = 0; i < wheels; ++i) MDCS_test::random_wheel<Point>(k, seeded, &r);
    const double q = k / std::pow(2.0, k - 1), expected = q / (1 - q);
    INFO("k " << k << " redraws per wheel " << double(r) / wheels << " expected " << expected);
    CHECK(std::abs(double(r) / wheels - expected) < 5 * std::sqrt(q) / (1 - q) / std::sqrt(double(wheels)));
  }
  // Wilson's interval: 0 of 10 and 10 of 10 (closed forms z^2 / (n + z^2)), 50 of 100 symmetric.
  const auto none = MDCS_test::wilson_interval(0, 10), all = MDCS_test::wilson_interval(10, 10),
             half = MDCS_test::wilson_interval(50, 100);
  const double z2 = 1.96 * 1.96;
  CHECK(none.first == 0);
  CHECK(none.second == Approx(z2 / (10 + z2)).epsilon(1e-12));
  CHECK(all.first == Approx(10 / (10 + z2)).epsilon(1e-12));
  CHECK(all.second == 1);
  CHECK(half.first + half.second == Approx(1).epsilon(1e-12));
}

TEST_CASE("mwt: random wheels of up to 9 points against the exhaustive oracle", "[mwt][thesis][random-wheel][oracle]")
{
  // k = 4..8 points on the circle, 12 wheels each: the LP path (branch and bound when fractional) and the LMT
  // pipeline both give the oracle's weight; the certain edges of the skeleton are edges of the unique optimum.
  CGAL::Random rng(20261202);
  int lp_integral = 0, connected = 0, trials = 0;
  for(int k = 4; k <= 8; ++k)
    for(int i = 0; i < 12; ++i) {
      const std::vector<Point> p = MDCS_test::random_wheel<Point>(k, rng);
      const MDCS_test::Random_wheel_trial t = MDCS_test::random_wheel_trial(p, true);
      const Exhaustive_mwt oracle = exhaustive_mwt(p);
      INFO("k " << k << " wheel " << i);
      ++trials;
      lp_integral += t.lp_integral;
      connected += t.lmt_connected;
      CHECK(t.lp_weight == Approx(oracle.weight).epsilon(1e-12));
      CHECK(t.pipeline_weight == Approx(oracle.weight).epsilon(1e-12));
      CHECK(t.pipeline_without_lp);   // the one-interior-point program settles every wheel face
      if(t.lp_integral) CHECK(t.lp_objective == Approx(oracle.weight).epsilon(1e-9));
      else CHECK(t.lp_objective <= oracle.weight * (1 + 1e-9));   // a relaxation: never above the MWT
      if(oracle.unique) {
        MWT::Mwt_options o;
        o.use_lmt_skeleton = true;
        MWT::Minimum_weight_triangulation_lp_2<K> stages(p, o);
        stages.compute_candidate_edges();
        stages.compute_empty_triangles();
        for(std::size_t e = 0; e < stages.candidate_edges().size(); ++e)
          if(stages.lmt_edge_states()[e] == MWT::internal::lmt_certain) CHECK(oracle.edges.count(stages.candidate_edges()[e]));
      }
    }
  // the skeleton is connected and the LP integral on some of these small wheels
  INFO("LP integral " << lp_integral << ", skeleton connected " << connected << " of " << trials);
  CHECK(lp_integral > 0);
  CHECK(connected > 0);
}

#endif
