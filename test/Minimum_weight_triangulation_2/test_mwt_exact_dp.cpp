// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact decisions of the dynamic programs (issue 5: "faces solved by the Klincsek DP with interval arithmetic
// and an exact tie-break"): the exact comparison of sums of square roots, exact ties (squares, grids, a
// symmetric octagon), a near-tie that double precision decides wrongly, and random sets where no decision is
// ambiguous (the double-only program's answer is kept).

#if defined(MDCS_HAS_CLP) && defined(MDCS_HAS_GLPK)

#include "mwt_exhaustive_oracle.h"

#include <CGAL/Minimum_weight_triangulation_2/internal/Exact_length_sum_2.h>

#include <catch2/catch.hpp>

#include <random>

using namespace mwt_test;
namespace MI = CGAL::Minimum_weight_triangulation_2::internal;

namespace {

MI::Length_segment seg(double x0, double y0, double x1, double y1) { return MI::Length_segment{{x0, y0, x1, y1}}; }

// the double-only Klincsek program (the version before the exact decisions), for comparison
double double_only_convex_mwt(const std::vector<Point>& p, std::vector<int>* apex)
{
  const int k = int(p.size());
  auto len = [&](int a, int b) { return std::sqrt(CGAL::to_double(CGAL::squared_distance(p[a], p[b]))); };
  std::vector<double> D(std::size_t(k * k), 0.0);
  apex->assign(std::size_t(k * k), -1);
  for(int gap = 2; gap < k; ++gap)
    for(int i = 0; i + gap < k; ++i) {
      const int j = i + gap;
      double m = HUGE_VAL;
      for(int c = i + 1; c < j; ++c) {
        const double v = D[i * k + c] + D[c * k + j] + (c > i + 1 ? len(i, c) : 0.0) + (j > c + 1 ? len(c, j) : 0.0);
        if(v < m) { m = v; (*apex)[i * k + j] = c; }
      }
      D[i * k + j] = m;
    }
  double perimeter = 0;
  for(int i = 0; i < k; ++i) perimeter += len(i, (i + 1) % k);
  return perimeter + D[k - 1];
}

} // namespace

TEST_CASE("exact comparison of sums of lengths", "[mwt][exact_dp]")
{
  using MI::compare_length_sums;
  // sqrt(2) + sqrt(8) = sqrt(18): distinct radicands, equal sums (the rational-square classes decide)
  CHECK(compare_length_sums({seg(0, 0, 1, 1), seg(0, 0, 2, 2)}, {seg(0, 0, 3, 3)}) == 0);
  CHECK(compare_length_sums({seg(0, 0, 1, 1), seg(0, 0, 2, 2)}, {seg(0, 0, 3, 3.0000001)}) == -1);
  // sqrt(5) + sqrt(5) = sqrt(20) with different segments of equal length
  CHECK(compare_length_sums({seg(0, 0, 1, 2), seg(5, 5, 7, 6)}, {seg(1, 1, 3, 5)}) == 0);
  // common segments cancel, in any order and direction
  CHECK(compare_length_sums({seg(0, 0, 1, 3), seg(2, 2, 0, 0)}, {seg(0, 0, 2, 2), seg(1, 3, 0, 0)}) == 0);
  CHECK(compare_length_sums({}, {}) == 0);
  CHECK(compare_length_sums({seg(0, 0, 1, 0)}, {}) == 1);
  // a difference far below double precision: sqrt(8) < sqrt(8 + 2^-49)
  const double e = std::ldexp(1.0, -51);
  CHECK(compare_length_sums({seg(0, 0, 2, 2)}, {seg(2, 0, 0, 2 + e)}) == -1);
  CHECK(compare_length_sums({seg(2, 0, 0, 2 + e)}, {seg(0, 0, 2, 2)}) == 1);
  // sqrt(2) + sqrt(3) vs sqrt(10): 3.146... > 3.162...? no: 3.1462 < 3.1623
  CHECK(compare_length_sums({seg(0, 0, 1, 1), seg(0, 0, 1, std::sqrt(2.0))}, {seg(0, 0, 3, 1)}) == -1);
  // L1 and Linf are rational
  CHECK(compare_length_sums({seg(0, 0, 1, 2)}, {seg(0, 0, 3, 0)}, MWT::Edge_metric::L1) == 0);
  CHECK(compare_length_sums({seg(0, 0, 1, 2)}, {seg(0, 0, 2, 1.5)}, MWT::Edge_metric::Linf) == 0);
  CHECK(compare_length_sums({seg(0, 0, 0.1, 0.2)}, {seg(0, 0, 0.3, 0)}, MWT::Edge_metric::L1) != 0);   // 0.1 + 0.2 != 0.3 as doubles
  // random sums: the sign agrees with long double where the difference is large
  std::mt19937 g(5);
  std::uniform_real_distribution<double> u(0, 1);
  for(int it = 0; it < 200; ++it) {
    std::vector<MI::Length_segment> A, B;
    long double a = 0, b = 0;
    for(int i = 0; i < 1 + it % 7; ++i) {
      A.push_back(seg(u(g), u(g), u(g), u(g)));
      a += std::sqrt((long double)(A.back()[2] - A.back()[0]) * (A.back()[2] - A.back()[0]) +
                     (long double)(A.back()[3] - A.back()[1]) * (A.back()[3] - A.back()[1]));
    }
    for(int i = 0; i < 1 + it % 5; ++i) {
      B.push_back(seg(u(g), u(g), u(g), u(g)));
      b += std::sqrt((long double)(B.back()[2] - B.back()[0]) * (B.back()[2] - B.back()[0]) +
                     (long double)(B.back()[3] - B.back()[1]) * (B.back()[3] - B.back()[1]));
    }
    if(std::abs(a - b) > 1e-12) CHECK(compare_length_sums(A, B) == (a < b ? -1 : 1));
  }
}

TEST_CASE("error bound of the double sums", "[mwt][exact_dp]")
{
  const MI::Length_sum_error_bound err(10);
  CHECK(err.certainly_less(1.0, 1.0 + 1e-13));
  CHECK_FALSE(err.certainly_less(1.0, 1.0 + 1e-15));
  CHECK_FALSE(err.certainly_less(1.0, 1.0));
  CHECK_FALSE(err.certainly_less(2.0, 1.0));
}

TEST_CASE("convex program: exact ties and a near-tie decided exactly", "[mwt][exact_dp]")
{
  // unit square: both diagonals have length sqrt(2) exactly; the smallest apex wins the tie
  {
    const std::vector<Point> sq{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    std::vector<std::array<int, 3>> tri;
    std::size_t exact = 0;
    const double w = MWT::convex_polygon_mwt_2(sq, std::back_inserter(tri), MWT::Edge_metric::L2, &exact);
    CHECK(w == Approx(4 + std::sqrt(2.0)).epsilon(1e-15));
    CHECK(exact == 1);
    REQUIRE(tri.size() == 2u);
    CHECK(tri[0] == std::array<int, 3>{0, 1, 3});   // apex 1 for the chain 0..3: the diagonal 1-3
  }
  // a symmetric octagon with integer vertices: many exact ties; the weight equals the oracle
  {
    const std::vector<Point> oc{{1, 0}, {2, 0}, {3, 1}, {3, 2}, {2, 3}, {1, 3}, {0, 2}, {0, 1}};
    std::vector<std::array<int, 3>> tri;
    std::size_t exact = 0;
    const double w = MWT::convex_polygon_mwt_2(oc, std::back_inserter(tri), MWT::Edge_metric::L2, &exact);
    CHECK(exact > 0);
    CHECK(w == Approx(exhaustive_mwt(oc).weight).epsilon(1e-14));
    CHECK(independent_triangulation_check(oc, tri));
    // L1: the same polygon, rational exact ties
    tri.clear();
    const double w1 = MWT::convex_polygon_mwt_2(oc, std::back_inserter(tri), MWT::Edge_metric::L1, &exact);
    CHECK(exact > 0);
    CHECK(w1 == Approx(brute_force_mwt(oc, MWT::Edge_metric::L1)).epsilon(1e-14));
  }
  // near-tie: |p1 p3|^2 = 8 + 2^-49 + 2^-102 > |p0 p2|^2 = 8, but both lengths round to the same double.
  // The double-only program keeps the first apex (diagonal p1 p3, the longer one); the exact one takes p0 p2.
  {
    const double e = std::ldexp(1.0, -51);
    const std::vector<Point> q{{0, 0}, {2, 0}, {2, 2}, {0, 2 + e}};
    const double l02 = std::sqrt(CGAL::to_double(CGAL::squared_distance(q[0], q[2])));
    const double l13 = std::sqrt(CGAL::to_double(CGAL::squared_distance(q[1], q[3])));
    REQUIRE(l02 == l13);   // indistinguishable in double
    REQUIRE(CGAL::compare_distance(q[0], q[2], q[1], q[3]) == CGAL::SMALLER);   // exactly: p0 p2 is shorter
    std::vector<int> apex;
    double_only_convex_mwt(q, &apex);
    CHECK(apex[3] == 1);   // the double-only program takes the longer diagonal
    std::vector<std::array<int, 3>> tri;
    std::size_t exact = 0;
    MWT::convex_polygon_mwt_2(q, std::back_inserter(tri), MWT::Edge_metric::L2, &exact);
    CHECK(exact == 1);
    REQUIRE(tri.size() == 2u);
    CHECK(tri[0] == std::array<int, 3>{0, 2, 3});   // apex 2: the diagonal p0 p2
  }
}

TEST_CASE("face programs of the pipeline: exact ties on grids and wheels", "[mwt][exact_dp]")
{
  // grids: every unit square is a face with two diagonals of equal length
  for(int s : {2, 3, 4}) {
    std::vector<Point> g;
    for(int x = 0; x <= s; ++x)
      for(int y = 0; y <= s; ++y) g.emplace_back(x, y);
    INFO("grid " << s);
    const MWT::Mwt_result r = MWT::minimum_weight_triangulation_2(g, lmt());
    REQUIRE(r.status == MWT::Mwt_status::certified_optimal);
    CHECK(r.weight == Approx(2 * s * (s + 1) + s * s * std::sqrt(2.0)).epsilon(1e-14));
    CHECK(r.statistics.dp_exact_faces >= std::size_t(s * s));
    CHECK(r.statistics.dp_exact_decisions >= r.statistics.dp_exact_faces);
    CHECK(independent_triangulation_check(g, r.triangles));
  }
  // a face with exact ties and one interior point: a 3 x 3 grid of spacing 2 with the centre of one cell added
  {
    std::vector<Point> g;
    for(int x = 0; x <= 2; ++x)
      for(int y = 0; y <= 2; ++y) g.emplace_back(2 * x, 2 * y);
    g.emplace_back(1, 1);
    const MWT::Mwt_result r = MWT::minimum_weight_triangulation_2(g, lmt());
    CHECK(r.weight == Approx(exhaustive_mwt(g).weight).epsilon(1e-14));
    CHECK(r.statistics.dp_exact_faces > 0);
  }
  // odd wheels: the one-point program sees near-equal rotations; its answer equals the exhaustive oracle
  // (k = 13) and the LP path's branch and bound
  for(int k : {9, 11, 13}) {
    const std::vector<Point> w = wheel(k);
    INFO("wheel " << k);
    const MWT::Mwt_result a = MWT::minimum_weight_triangulation_2(w, lmt());
    const MWT::Mwt_result b = MWT::minimum_weight_triangulation_2(w);
    CHECK(a.weight == Approx(b.weight).epsilon(1e-12));
    CHECK(a.weight == Approx(exhaustive_mwt(w).weight).epsilon(1e-12));
  }
}

TEST_CASE("random sets: no ambiguous decision, the double-only answer is kept", "[mwt][exact_dp]")
{
  // convex position: the exact program's triangles equal the double-only program's
  for(unsigned s = 0; s < 20; ++s) {
    std::mt19937 g(700 + s);
    std::uniform_real_distribution<double> u(0, 2 * M_PI);
    std::vector<double> a(static_cast<std::size_t>(10 + 5 * (s % 8)));
    for(double& x : a) x = u(g);
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    std::vector<Point> p;
    for(double x : a) p.emplace_back(3 * std::cos(x), std::sin(x));
    std::vector<int> apex;
    const double w0 = double_only_convex_mwt(p, &apex);
    std::vector<std::array<int, 3>> tri;
    std::size_t exact = 0;
    const double w = MWT::convex_polygon_mwt_2(p, std::back_inserter(tri), MWT::Edge_metric::L2, &exact);
    CHECK(exact == 0);
    CHECK(w == Approx(w0).epsilon(1e-14));
    const int k = int(p.size());
    for(const auto& t : tri) CHECK(apex[t[0] * k + t[2]] == t[1]);
  }
  // the pipeline on random uniform and clustered sets: no exact decision needed
  for(unsigned s = 0; s < 6; ++s) {
    const std::vector<Point> p = s % 2 ? clustered_points(400, 60 + s) : uniform_points(400, 60 + s);
    const MWT::Mwt_result r = MWT::minimum_weight_triangulation_2(p, lmt());
    REQUIRE(r.status == MWT::Mwt_status::certified_optimal);
    CHECK(r.statistics.lmt_solved_faces > 0);
    CHECK(r.statistics.dp_exact_faces == 0);
    CHECK(r.statistics.dp_exact_decisions == 0);
  }
}

#endif

#if defined(MDCS_HAS_CLP) && defined(MDCS_HAS_GLPK)

TEST_CASE("exact certificate on the zero-reduced-cost support of dual degenerate LPs", "[mwt][exact_dp]")
{
  // small sets: whenever the support certificate holds, the triangulation has the oracle's weight
  int proven_small = 0, sets_small = 0;
  for(int n = 9; n <= 14; ++n)
    for(unsigned s = 0; s < 4; ++s) {
      const std::vector<Point> p = s % 2 ? clustered_points(n, 3000 + 10 * unsigned(n) + s) : uniform_points(n, 3000 + 10 * unsigned(n) + s);
      const MWT::Mwt_result r = MWT::minimum_weight_triangulation_2(p);
      if(r.status != MWT::Mwt_status::certified_optimal) continue;
      ++sets_small;
      if(r.certificate_support > 0) {
        ++proven_small;
        CHECK(r.certificate_exact);
        CHECK(r.weight == Approx(exhaustive_mwt(p).weight).epsilon(1e-12));
      }
    }
  INFO("small sets proven: " << proven_small << " of " << sets_small);
  CHECK(proven_small > 0);
  // random sets of 50 to 400 points: count; switched off: never
  int proven = 0, sets = 0;
  for(unsigned s = 0; s < 8; ++s) {
    const std::vector<Point> p = s % 2 ? clustered_points(50 + 50 * int(s), 4000 + s) : uniform_points(50 + 50 * int(s), 4000 + s);
    const MWT::Mwt_result r = MWT::minimum_weight_triangulation_2(p);
    REQUIRE(r.status == MWT::Mwt_status::certified_optimal);
    ++sets;
    proven += r.certificate_exact;
    if(r.certificate_support > 0) CHECK(r.certificate_support >= r.triangles.size());
    MWT::Mwt_options o;
    o.exact_support_certificate = false;
    const MWT::Mwt_result q = MWT::minimum_weight_triangulation_2(p, o);
    CHECK(q.certificate_support == 0);
    CHECK(q.weight == r.weight);
  }
  INFO("random sets proven exactly: " << proven << " of " << sets);
  CHECK(proven == sets);
}

#endif
