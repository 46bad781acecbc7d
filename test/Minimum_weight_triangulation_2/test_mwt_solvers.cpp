// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The LP solver models agree (CLP dual, GLPK, GLPK exact); the dual bound is rigorous; the stage class
// exposes a consistent LP; the validator rejects broken triangulations.

// Needs both LP solver models (found and defined by the build: MDCS_HAS_CLP, MDCS_HAS_GLPK).
#if defined(MDCS_HAS_CLP) && defined(MDCS_HAS_GLPK)

#include "mwt_test_helpers.h"

#include <catch2/catch.hpp>

using namespace mwt_test;

namespace {

// A solver model that perturbs the duals (CLP's duals times 1.5): the recomputed bound drops below the weight.
struct Bad_duals
{
  const char* name() const { return "bad"; }
  MWT::Linear_program_solution solve(const MWT::Sparse_linear_program& lp) const
  {
    auto s = MWT::CLP_linear_program_solver().solve(lp);
    for(double& y : s.dual) y *= 1.5;
    return s;
  }
};

} // namespace

TEST_CASE("mwt: CLP, GLPK and the exact GLPK model agree", "[mwt][solver]")
{
  for(unsigned seed = 1; seed <= 4; ++seed) {
    const auto p = uniform_points(60, 40 + seed);
    std::vector<double> w;
    for(MWT::Lp_solver_choice c : {MWT::Lp_solver_choice::clp, MWT::Lp_solver_choice::glpk, MWT::Lp_solver_choice::exact}) {
      if(!MWT::has_lp_solver(c)) continue;
      MWT::Mwt_options o;
      o.solver = c;
      const auto r = MWT::minimum_weight_triangulation_2(p, o);
      INFO("seed " << seed << " solver " << r.solver << ": " << r.message);
      CHECK(r.status == MWT::Mwt_status::certified_optimal);
      if(c == MWT::Lp_solver_choice::exact) CHECK(r.lp_exact);
      w.push_back(r.weight);
      CHECK(r.lp_objective == Approx(r.weight).epsilon(1e-9));
    }
    REQUIRE(w.size() >= 2);
    for(double x : w) CHECK(x == Approx(w[0]).epsilon(1e-12));
  }
}

TEST_CASE("mwt: GLPK branch and bound agrees with the LP on an integral instance", "[mwt][solver]")
{
  const auto p = uniform_points(40, 5);
  MWT::Minimum_weight_triangulation_lp_2<K> m(p);
  m.build_linear_program();
  const auto lp = MWT::GLPK_linear_program_solver().solve(m.linear_program());
  const auto ip = MWT::GLPK_linear_program_solver().solve_binary(m.linear_program());
  REQUIRE(lp.status == MWT::Lp_status::optimal);
  REQUIRE(ip.status == MWT::Lp_status::optimal);
  CHECK(lp.objective == Approx(ip.objective).epsilon(1e-9));
}

TEST_CASE("mwt: the LP has one row per used edge and hull rows equal to one", "[mwt][lp]")
{
  const auto p = uniform_points(50, 9);
  MWT::Minimum_weight_triangulation_lp_2<K> m(p);
  m.build_linear_program();
  const auto& lp = m.linear_program();
  REQUIRE(lp.number_of_columns() > 0);
  std::size_t hull_rows = 0;
  for(std::size_t i = 0; i < lp.number_of_rows; ++i) hull_rows += lp.row_lower[i] == 1;
  CHECK(hull_rows == m.hull().size());
  for(std::size_t j = 0; j < lp.number_of_columns(); ++j) {
    CHECK(lp.column_start[j + 1] - lp.column_start[j] == 3);
    const auto t = m.column_triangle(j);
    CHECK(CGAL::orientation(p[t[0]], p[t[1]], p[t[2]]) == CGAL::LEFT_TURN);
    CHECK(lp.cost[j] > 0);
  }
}

TEST_CASE("mwt: a wrong dual vector gives no certificate, the right one does", "[mwt][certificate]")
{
  const auto p = uniform_points(30, 11);
  MWT::Mwt_options o;
  const auto bad = MWT::minimum_weight_triangulation_2(p, o, Bad_duals(), nullptr);
  CHECK(bad.status == MWT::Mwt_status::optimal_uncertified);
  CHECK(bad.lower_bound < bad.weight);
  const auto good = MWT::minimum_weight_triangulation_2(p, o, MWT::CLP_linear_program_solver(), nullptr);
  CHECK(good.status == MWT::Mwt_status::certified_optimal);
  CHECK(good.weight == Approx(bad.weight).epsilon(1e-12));
}

TEST_CASE("mwt: the exact certificate (separated reduced costs) where the optimum is non-degenerate", "[mwt][certificate]")
{
  // Wheels with 5 to 7 rim points have a unique MWT and duals that separate it: proven without tolerance.
  for(int k : {5, 6, 7}) {
    const auto p = wheel(k);
    const auto r = MWT::minimum_weight_triangulation_2(p);
    INFO("k = " << k << ": " << r.message);
    CHECK(r.certificate_exact);
    CHECK(r.status == MWT::Mwt_status::certified_optimal);
    CHECK(r.weight == Approx(brute_force_mwt(p)).epsilon(1e-12));
  }
  // The certificate holds for any dual vector: whenever one is given, also with perturbed duals, it agrees
  // with brute force; on 30 points the perturbed duals do not separate.
  for(unsigned seed = 1; seed <= 10; ++seed) {
    const auto p = uniform_points(4 + int(seed % 5), seed);
    const auto bad = MWT::minimum_weight_triangulation_2(p, MWT::Mwt_options(), Bad_duals(), nullptr);
    const auto good = MWT::minimum_weight_triangulation_2(p);
    INFO("seed " << seed);
    const double brute = brute_force_mwt(p);
    if(bad.certificate_exact) CHECK(bad.weight == Approx(brute).epsilon(1e-12));
    if(good.certificate_exact) CHECK(good.weight == Approx(brute).epsilon(1e-12));
  }
  const auto bad30 = MWT::minimum_weight_triangulation_2(uniform_points(30, 11), MWT::Mwt_options(), Bad_duals(), nullptr);
  CHECK_FALSE(bad30.certificate_exact);
  CHECK(bad30.status == MWT::Mwt_status::optimal_uncertified);
}

TEST_CASE("mwt: the validator rejects broken triangulations", "[mwt][validation]")
{
  const auto p = uniform_points(20, 13);
  const auto r = MWT::minimum_weight_triangulation_2(p);
  REQUIRE(r.has_triangulation());
  MWT::internal::Indexed_points_2<K> pts(p);
  MWT::internal::Point_grid_2 grid(pts);
  const auto hull = MWT::internal::checked_hull_boundary(pts);
  CHECK(MWT::internal::validate_triangulation(pts, grid, hull, r.triangles).empty());
  auto missing = r.triangles;
  missing.pop_back();
  CHECK_FALSE(MWT::internal::validate_triangulation(pts, grid, hull, missing).empty());
  auto doubled = r.triangles;
  doubled.back() = doubled.front();
  CHECK_FALSE(MWT::internal::validate_triangulation(pts, grid, hull, doubled).empty());
  auto flipped = r.triangles;
  std::swap(flipped[0][1], flipped[0][2]);
  CHECK_FALSE(MWT::internal::validate_triangulation(pts, grid, hull, flipped).empty());
}

TEST_CASE("mwt: fraction of integral LP optima over random sets", "[mwt][integrality][.long]")
{
  int integral = 0, total = 0;
  for(unsigned seed = 1; seed <= 200; ++seed) {
    const auto p = uniform_points(10 + int(seed % 4) * 20, 1000 + seed);
    const auto r = MWT::minimum_weight_triangulation_2(p);
    ++total;
    integral += r.lp_integral;
    CHECK(r.status == MWT::Mwt_status::certified_optimal);
  }
  CHECK(integral == total);
}

#endif // MDCS_HAS_CLP && MDCS_HAS_GLPK
