// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The adapter of CGAL's MixedIntegerProgramTraits (here CGAL::GLPK_mixed_integer_program_traits) as a
// LinearProgramSolver and as the binary solver: same triangulations as CLP, the 13-wheel resolved, and the
// documented status (no duals, so no certificate).

#if defined(MDCS_HAS_CLP) && defined(MDCS_HAS_GLPK)

#ifndef CGAL_USE_GLPK
#define CGAL_USE_GLPK
#endif
#include <CGAL/GLPK_mixed_integer_program_traits.h>

#include "mwt_test_helpers.h"

#include <CGAL/Minimum_weight_triangulation_2/Mixed_integer_program_linear_program_solver.h>

#include <catch2/catch.hpp>

using namespace mwt_test;

namespace {
typedef MWT::Mixed_integer_program_linear_program_solver<CGAL::GLPK_mixed_integer_program_traits<double>> Mip_solver;
}

TEST_CASE("MIP-traits adapter: the LP through CGAL's GLPK traits gives the MWT, uncertified", "[mwt][solver][mip_traits]")
{
  for(unsigned seed = 1; seed <= 4; ++seed) {
    const auto p = uniform_points(25 + 10 * int(seed), seed);
    const auto reference = MWT::minimum_weight_triangulation_2(p);
    const auto r = MWT::minimum_weight_triangulation_2(p, MWT::Mwt_options(), Mip_solver(), nullptr);
    INFO("seed " << seed << ": " << r.message);
    REQUIRE(r.has_triangulation());
    CHECK(r.status == MWT::Mwt_status::optimal_uncertified); // no duals from the traits: validated, not certified
    CHECK(std::string(r.solver) == "mip-traits");
    CHECK(r.weight == Approx(reference.weight).epsilon(1e-12));
    CHECK(independent_triangulation_check(p, r.triangles));
  }
}

TEST_CASE("MIP-traits adapter: as the binary solver it resolves the 13-wheel", "[mwt][solver][mip_traits][wheel]")
{
  const auto p = wheel(13);
  const Mip_solver mip;
  const auto r = MWT::minimum_weight_triangulation_2(p, MWT::Mwt_options(), MWT::CLP_linear_program_solver(),
                                                     [&](const MWT::Sparse_linear_program& lp) { return mip.solve_binary(lp); });
  CHECK(r.status == MWT::Mwt_status::optimal_after_branch_and_bound);
  CHECK(r.weight == Approx(18.7989).margin(5e-5));
  CHECK(r.lower_bound == Approx(18.7636).margin(5e-5));
  CHECK(independent_triangulation_check(p, r.triangles));
}

TEST_CASE("MIP-traits adapter: bad programs are reported, not thrown past the caller", "[mwt][solver][mip_traits]")
{
  // x0 + x1 = 1 and x0 + x1 = 3 with 0 <= x <= 1: infeasible.
  MWT::Sparse_linear_program lp;
  const int r0 = lp.add_row(1, 1), r1 = lp.add_row(3, 3);
  const int rows[2] = {r0, r1};
  const double ones[2] = {1, 1};
  lp.add_column(1, 0, 1, rows, ones, 2);
  lp.add_column(2, 0, 1, rows, ones, 2);
  const auto s = Mip_solver().solve(lp);
  CHECK(s.status != MWT::Lp_status::optimal);
  CHECK_FALSE(s.message.empty());
  MWT::Sparse_linear_program broken = lp;
  broken.row_index[0] = 7; // out of range
  CHECK_THROWS_AS(Mip_solver().solve(broken), std::invalid_argument);
}

#endif
