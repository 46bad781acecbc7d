// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Issue 5, "tests with oracles: brute force for n <= 14": the exhaustive search of mwt_exhaustive_oracle.h
// (checked itself against the maximal-non-crossing-set enumeration on small sets) against the LMT pipeline,
// the plain LP path and the convex-polygon program on random sets of 9 to 14 points: uniform, clustered, with
// collinear triples, with cocircular points and in convex position. Weights agree to 1e-12 (relative); where
// the optimum is unique, the edge sets agree too.

#if defined(MDCS_HAS_CLP) && defined(MDCS_HAS_GLPK)

#include "mwt_exhaustive_oracle.h"

#include <catch2/catch.hpp>

#include <random>
#include <string>

using namespace mwt_test;

namespace {

std::set<std::pair<int, int>> edge_set(const std::vector<std::array<int, 3>>& tri)
{
  std::set<std::pair<int, int>> E;
  for(const auto& t : tri)
    for(int i = 0; i < 3; ++i) E.insert(std::minmax(t[i], t[(i + 1) % 3]));
  return E;
}

// points on a 5 x 5 integer grid (many collinear triples), distinct
std::vector<Point> grid_subset(int n, unsigned seed)
{
  std::mt19937 g(seed);
  std::vector<Point> all;
  for(int x = 0; x < 5; ++x)
    for(int y = 0; y < 5; ++y) all.emplace_back(x, y);
  std::shuffle(all.begin(), all.end(), g);
  std::vector<Point> p(all.begin(), all.begin() + n);
  return p;
}

// three random lines with collinear points on them, plus uniform points
std::vector<Point> collinear_mix(int n, unsigned seed)
{
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point> p;
  for(int l = 0; l < 2 && int(p.size()) < n; ++l) {
    // points a + t (b - a) with t = k/8: exactly collinear in double for dyadic a, b
    const double ax = std::floor(u(g) * 16) / 16, ay = std::floor(u(g) * 16) / 16;
    const double bx = std::floor(u(g) * 16) / 16, by = std::floor(u(g) * 16) / 16;
    if(ax == bx && ay == by) continue;
    for(int k = 0; k <= 8 && int(p.size()) < n && k < 4 + l; ++k) p.emplace_back(ax + k * (bx - ax) / 8, ay + k * (by - ay) / 8);
  }
  while(int(p.size()) < n) p.emplace_back(u(g), u(g));
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  while(int(p.size()) < n) p.emplace_back(u(g), u(g));
  return p;
}

// integer points on the circle x^2 + y^2 = 25 (exactly cocircular) plus random interior points
std::vector<Point> cocircular_mix(int n, unsigned seed)
{
  std::mt19937 g(seed);
  std::vector<Point> c{{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  std::shuffle(c.begin(), c.end(), g);
  const int on = std::min(n - 2, 8 + int(seed % 4));
  std::vector<Point> p(c.begin(), c.begin() + on);
  std::uniform_real_distribution<double> u(-3, 3);
  while(int(p.size()) < n) p.emplace_back(u(g), u(g));
  return p;
}

// convex position: random angles on an ellipse, counter-clockwise
std::vector<Point> convex_position(int n, unsigned seed)
{
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(0, 2 * M_PI);
  std::vector<double> a(static_cast<std::size_t>(n));
  for(double& x : a) x = u(g);
  std::sort(a.begin(), a.end());
  std::vector<Point> p;
  for(double x : a) p.emplace_back(2 * std::cos(x), std::sin(x));
  return p;
}

bool is_optimal(const MWT::Mwt_result& r)
{
  return r.status == MWT::Mwt_status::certified_optimal || r.status == MWT::Mwt_status::optimal_after_branch_and_bound;
}

// the pipeline and the plain LP path against the oracle; returns the oracle's weight
void check_against_oracle(const std::vector<Point>& p, const std::string& what, int* unique_count = nullptr)
{
  INFO(what << ", n = " << p.size());
  const Exhaustive_mwt o = exhaustive_mwt(p);
  REQUIRE(std::isfinite(o.weight));
  const MWT::Mwt_result a = MWT::minimum_weight_triangulation_2(p, lmt());
  const MWT::Mwt_result b = MWT::minimum_weight_triangulation_2(p);
  REQUIRE(is_optimal(a));
  REQUIRE(is_optimal(b));
  CHECK(a.weight == Approx(o.weight).epsilon(1e-12));
  CHECK(b.weight == Approx(o.weight).epsilon(1e-12));
  CHECK(a.lower_bound <= o.weight * (1 + 1e-12));
  CHECK(b.lower_bound <= o.weight * (1 + 1e-12));
  if(o.unique) {
    CHECK(edge_set(a.triangles) == o.edges);
    CHECK(edge_set(b.triangles) == o.edges);
    if(unique_count) ++*unique_count;
  }
}

} // namespace

TEST_CASE("exhaustive oracle equals the maximal-set enumeration on small sets", "[mwt][oracle14]")
{
  for(unsigned s = 0; s < 12; ++s) {
    const std::vector<Point> p = s % 3 == 0 ? uniform_points(5 + int(s % 4), 900 + s)
                               : s % 3 == 1 ? grid_subset(6 + int(s % 3), 900 + s)
                                            : cocircular_mix(7, 900 + s);
    INFO("set " << s);
    const Exhaustive_mwt o = exhaustive_mwt(p);
    CHECK(o.weight == Approx(brute_force_mwt(p)).epsilon(1e-12));
    // the returned edges form a triangulation of that weight
    double w = 0;
    for(const auto& e : o.edges) w += length(p[e.first], p[e.second]);
    CHECK(w == Approx(o.weight).epsilon(1e-12));
  }
  // the full 3 x 3 grid: many optimal triangulations (each unit square split either way)
  std::vector<Point> g;
  for(int x = 0; x < 3; ++x)
    for(int y = 0; y < 3; ++y) g.emplace_back(x, y);
  const Exhaustive_mwt o = exhaustive_mwt(g);
  CHECK(o.weight == Approx(12 + 4 * std::sqrt(2.0)).epsilon(1e-14));
  CHECK_FALSE(o.unique);
  CHECK(o.edges.size() == 16u);
}

TEST_CASE("9 to 14 points: pipeline and LP path equal the exhaustive oracle", "[mwt][oracle14]")
{
  int unique = 0, sets = 0;
  for(int n = 9; n <= 14; ++n)
    for(unsigned s = 0; s < 6; ++s) {
      const unsigned seed = 1000 * unsigned(n) + s;
      check_against_oracle(uniform_points(n, seed), "uniform", &unique);
      check_against_oracle(clustered_points(n, seed), "clustered", &unique);
      sets += 2;
    }
  for(int n = 9; n <= 14; ++n) {
    check_against_oracle(n <= 13 ? grid_subset(n, 77u + unsigned(n)) : collinear_mix(n, 77u + unsigned(n)), "collinear", &unique);
    check_against_oracle(cocircular_mix(n, 55u + unsigned(n)), "cocircular", &unique);
    sets += 2;
  }
  INFO("unique optima: " << unique << " of " << sets);
  CHECK(unique >= sets / 2);   // the edge sets were compared on most sets
}

TEST_CASE("convex position, 9 to 14 points: the convex program equals the oracle", "[mwt][oracle14]")
{
  for(int n = 9; n <= 14; ++n) {
    const std::vector<Point> p = convex_position(n, 300u + unsigned(n));
    INFO("n = " << n);
    const Exhaustive_mwt o = exhaustive_mwt(p);
    std::vector<std::array<int, 3>> tri;
    const double w = MWT::convex_polygon_mwt_2(p, std::back_inserter(tri));
    CHECK(w == Approx(o.weight).epsilon(1e-12));
    if(o.unique) CHECK(edge_set(tri) == o.edges);
    const MWT::Mwt_result a = MWT::minimum_weight_triangulation_2(p, lmt());
    CHECK(a.weight == Approx(o.weight).epsilon(1e-12));
  }
}

TEST_CASE("9 to 14 points, long sweep against the exhaustive oracle", "[mwt][oracle14][.long]")
{
  int unique = 0;
  for(int n = 9; n <= 14; ++n)
    for(unsigned s = 0; s < 50; ++s) {
      const unsigned seed = 50000 + 100 * unsigned(n) + s;
      check_against_oracle(uniform_points(n, seed), "uniform", &unique);
      check_against_oracle(clustered_points(n, seed), "clustered", &unique);
      check_against_oracle(collinear_mix(n, seed), "collinear", &unique);
      check_against_oracle(cocircular_mix(n, seed), "cocircular", &unique);
      const std::vector<Point> c = convex_position(n, seed);
      std::vector<std::array<int, 3>> tri;
      CHECK(MWT::convex_polygon_mwt_2(c, std::back_inserter(tri)) == Approx(exhaustive_mwt(c).weight).epsilon(1e-12));
    }
  CHECK(unique > 0);
}

#endif
