// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The edge-based LP (thesis ch. 3.2.1): its 0/1 optimum is the MWT (brute force), its LP optimum is a lower
// bound, and on some 5-point sets it is fractional while the triangle LP is integral (thesis figure 3.1).

// Needs both LP solver models (found and defined by the build: MDCS_HAS_CLP, MDCS_HAS_GLPK).
#if defined(MDCS_HAS_CLP) && defined(MDCS_HAS_GLPK)

#include "mwt_test_helpers.h"

#include <catch2/catch.hpp>

using namespace mwt_test;

TEST_CASE("edge-based LP: 0/1 optimum is the MWT, LP optimum a lower bound", "[mwt][edge_lp][oracle]")
{
  for(unsigned seed = 1; seed <= 8; ++seed) {
    const auto p = uniform_points(5 + int(seed % 3), 300 + seed);
    const auto e = MWT::make_edge_based_lp_2(p);
    const auto lp = MWT::GLPK_linear_program_solver().solve(e.lp);
    const auto ip = MWT::GLPK_linear_program_solver().solve_binary(e.lp);
    REQUIRE(lp.status == MWT::Lp_status::optimal);
    REQUIRE(ip.status == MWT::Lp_status::optimal);
    const double bf = brute_force_mwt(p);
    INFO("seed " << seed);
    CHECK(ip.objective == Approx(bf).epsilon(1e-9));
    CHECK(lp.objective <= bf + 1e-9);
  }
}

TEST_CASE("edge-based LP is fractional where the triangle LP is integral (5 points)", "[mwt][edge_lp]")
{
  int found = 0;
  for(unsigned seed = 1; seed <= 300 && found < 3; ++seed) {
    const auto p = uniform_points(5, 700 + seed);
    const auto e = MWT::make_edge_based_lp_2(p);
    const auto lp = MWT::CLP_linear_program_solver().solve(e.lp);
    REQUIRE(lp.status == MWT::Lp_status::optimal);
    const double bf = brute_force_mwt(p);
    if(lp.objective < bf - 1e-6) {
      ++found;
      const auto r = MWT::minimum_weight_triangulation_2(p);
      CHECK(r.lp_integral);
      CHECK(r.weight == Approx(bf).epsilon(1e-12));
    }
  }
  CHECK(found > 0);
}

#endif // MDCS_HAS_CLP && MDCS_HAS_GLPK
