// Tests of the basin search after plane selection (select_planes_relaxed_3, search_surface_basins_3) on a small
// blob problem: never a higher relaxed energy than plain plane selection with every round optimum relaxed,
// deterministic for a given seed, exactly plain plane selection without sweeps, and bad input rejected.
#include <catch2/catch.hpp>

#include <MDCS_test/surface_problems.h>

#include <CGAL/Variational_minimization/relax_surface_3.h>
#include <CGAL/Variational_minimization/search_surface_basins_3.h>
#include <CGAL/Variational_minimization/select_planes_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace VM = CGAL::Variational_minimization;
using MDCS_test::blob_planes;
using MDCS_test::blob_problem;

namespace {

VM::Surface_basin_search_options_3 small_search()
{
  VM::Surface_basin_search_options_3 so;
  so.tilings = {2, 3};
  so.relaxation.grids = {10};
  return so;
}

} // namespace

TEST_CASE("select_planes_relaxed_3: never worse than plane selection, deterministic",
          "[variational][surface][blobs][basin_search]")
{
  const VM::Surface_problem_3 P = blob_problem();
  const auto G = VM::random_blob_functional_3(P, 4, 3, 0.1, -1.5, 3);
  const VM::Surface_basin_search_options_3 so = small_search();
  std::size_t improved_runs = 0;
  for(std::uint64_t seed : {1u, 2u}) {
    const VM::Surface_plane_options_3 o = blob_planes(seed);
    // Plain plane selection, every round optimum relaxed on its own, the best kept.
    const VM::Plane_selection_result_3 plain = VM::select_planes_3(P, G, 60, 2, o);
    double plain_best = std::numeric_limits<double>::infinity();
    for(const VM::Minimal_surface_3& s : plain.surfaces)
      plain_best = std::min(plain_best, VM::relax_surface_3(P, G, s, so.relaxation).energy);
    const VM::Relaxed_plane_selection_result_3 R = VM::select_planes_relaxed_3(P, G, 60, 2, o, so);
    // The same plane selection inside.
    REQUIRE(R.selection.energies == plain.energies);
    REQUIRE(R.round_relaxed_energies.size() == 2);
    CHECK(*std::min_element(R.round_relaxed_energies.begin(), R.round_relaxed_energies.end()) == plain_best);
    CHECK(R.search.start_energy == plain_best);
    // Never worse than plain plane selection.
    CHECK(R.search.relaxed.energy <= plain_best);
    CHECK(R.search.moves > 0);
    CHECK(R.search.relaxed.heights.size() == std::size_t((R.search.relaxed.n + 1) * (R.search.relaxed.n + 1)));
    CHECK(R.search.discrete.is_feasible);
    improved_runs += R.search.relaxed.energy < plain_best ? 1 : 0;
    // The relaxed energy is the energy of the returned heights: relaxing them again on the same grid cannot
    // find a lower one by more than the relaxation's tolerance.
    VM::Surface_relaxation_options_3 again = so.relaxation;
    again.grids = {R.search.relaxed.n};
    const VM::Relaxed_surface_3& best = R.search.relaxed;
    const double re = VM::relax_surface_3(P, G, [&](double x, double y) {
                        return VM::internal::relaxed_height_3(P, best, x, y); }, again).energy;
    CHECK(re <= best.energy * (1 + 1e-12));
    CHECK(re >= best.energy * (1 - 1e-3));
    // Deterministic for a given seed.
    const VM::Relaxed_plane_selection_result_3 R2 = VM::select_planes_relaxed_3(P, G, 60, 2, o, so);
    CHECK(R2.search.relaxed.energy == R.search.relaxed.energy);
    CHECK(R2.search.relaxed.heights == R.search.relaxed.heights);
    CHECK(R2.search.moves == R.search.moves);
    CHECK(R2.search.improvements == R.search.improvements);
    // The wide second stage only adds moves after the first stage: never worse than the first stage alone.
    VM::Surface_basin_search_options_3 narrow = so;
    narrow.wide_tilings.clear();
    const VM::Relaxed_plane_selection_result_3 RN = VM::select_planes_relaxed_3(P, G, 60, 2, o, narrow);
    CHECK(R.search.relaxed.energy <= RN.search.relaxed.energy);
    CHECK(R.search.moves > RN.search.moves);
    // Without sweeps: exactly plain plane selection (the best relaxed round optimum).
    VM::Surface_basin_search_options_3 none = so;
    none.sweeps = 0;
    const VM::Relaxed_plane_selection_result_3 R0 = VM::select_planes_relaxed_3(P, G, 60, 2, o, none);
    CHECK(R0.search.relaxed.energy == plain_best);
    CHECK(R0.search.moves == 0);
  }
  INFO("runs improved by the basin search: " << improved_runs);
  CHECK(improved_runs >= 1);
}

TEST_CASE("search_surface_basins_3: bad input", "[variational][surface][basin_search]")
{
  const VM::Surface_problem_3 P = blob_problem();
  const auto G = VM::random_blob_functional_3(P, 4, 2, 0.12, -1.5, 3);
  const VM::Plane_arrangement_3 A(VM::surface_planes_3(P, 30, blob_planes(1)));
  const std::vector<double> w = VM::surface_facet_weights_3(A, P, G);
  const VM::Minimal_surface_3 s = VM::minimize_surface_functional_3(A, w, P);
  REQUIRE(s.is_feasible);
  VM::Surface_basin_search_options_3 so = small_search();
  so.tilings = {2};
  CHECK_NOTHROW(VM::search_surface_basins_3(A, w, P, G, {s}, so));
  CHECK_THROWS_AS(VM::search_surface_basins_3(A, std::vector<double>(3, 1.0), P, G, {s}, so), std::invalid_argument);
  CHECK_THROWS_AS(VM::search_surface_basins_3(A, w, P, G, {VM::Minimal_surface_3()}, so), std::invalid_argument);
  CHECK_THROWS_AS(VM::search_surface_basins_3(A, w, P, G, {}, so), std::invalid_argument);
  VM::Surface_basin_search_options_3 bad = so;
  bad.tilings = {0};
  CHECK_THROWS_AS(VM::search_surface_basins_3(A, w, P, G, {s}, bad), std::invalid_argument);
  bad = so;
  bad.shift = 0;
  CHECK_THROWS_AS(VM::search_surface_basins_3(A, w, P, G, {s}, bad), std::invalid_argument);
  bad.shift = std::nan("");
  CHECK_THROWS_AS(VM::search_surface_basins_3(A, w, P, G, {s}, bad), std::invalid_argument);
  bad = so;
  bad.wide_shift = -1;
  CHECK_THROWS_AS(VM::search_surface_basins_3(A, w, P, G, {s}, bad), std::invalid_argument);
  bad.wide_tilings = {0};
  CHECK_THROWS_AS(VM::search_surface_basins_3(A, w, P, G, {s}, bad), std::invalid_argument);
  VM::Surface_problem_3 Q = P;
  Q.set_domain_polygon({{0, 0}, {1, 0}, {1, 0.5}, {0.5, 0.5}, {0.5, 1}, {0, 1}});
  CHECK_THROWS_AS(VM::select_planes_relaxed_3(Q, G, 30, 1, blob_planes(1), so), std::invalid_argument);
}
