// Tests of the extensions of the bivariate solver: relaxation (local L-BFGS on grids) against the exact Scherk
// area and the exact plane, plane selection (the energy never increases), and the blob problem with many local
// minima: the global solve (with plane selection, relaxed) is at least as good as the best of 100 random-start
// local descents. Adaptive refinement: never worse than its runs, and the envelope restriction only removes
// candidates.
#include <catch2/catch.hpp>

#include <MDCS_test/surface_problems.h>

#include <CGAL/Variational_minimization/analytic_solutions_3.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/refine_surface_3.h>
#include <CGAL/Variational_minimization/relax_surface_3.h>
#include <CGAL/Variational_minimization/select_planes_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace VM = CGAL::Variational_minimization;

namespace {

VM::Minimal_surface_3 solve(const VM::Surface_problem_3& P, std::size_t n, const VM::Surface_plane_options_3& o)
{
  const VM::Plane_arrangement_3 A = VM::build_surface_arrangement_3(P, VM::surface_planes_3(P, n, o));
  const auto w = VM::surface_facet_weights_3(A, P, VM::Area_functional_3());
  return VM::minimize_surface_functional_3(A, w, P);
}

} // namespace

TEST_CASE("relax_surface_3: Scherk's surface to 1e-4 after relaxation", "[variational][surface][relaxation]")
{
  const VM::Surface_problem_3 P = VM::scherk_surface_problem_3(4);
  const double a = 1.2;
  VM::Surface_plane_options_3 o;
  o.distribution = VM::Plane_distribution_3::slope_limited;
  o.max_slope = 3;
  o.pencil_fraction = 0.2;
  const VM::Minimal_surface_3 s = solve(P, 60, o);
  REQUIRE(s.is_feasible);
  const VM::Relaxed_surface_3 r = VM::relax_surface_3(P, VM::Area_functional_3(), s);
  const double exact = 9.94982; // Gauss-Legendre quadrature (test_minimize_surface_functional_3.cpp)
  CHECK(r.n == 80);
  CHECK(r.energy < s.energy);
  CHECK(std::abs(r.energy - exact) / exact < 1e-4);
  // The boundary nodes hold the exact boundary data.
  for(int i = 0; i <= r.n; ++i) {
    const double x = -a + 2 * a * i / r.n;
    CHECK(std::abs(r.heights[std::size_t(i)] - std::log(std::cos(-a) / std::cos(x))) < 1e-12);
  }
}

TEST_CASE("relax_surface_3: linear boundary data relaxes to the plane", "[variational][surface][relaxation]")
{
  VM::Surface_problem_3 P;
  P.lower_boundary = [](double x, double y) { return 0.2 + 0.3 * x + 0.4 * y; };
  const VM::Relaxed_surface_3 r =
    VM::relax_surface_3(P, VM::Area_functional_3(), [](double x, double y) { return 0.5 + 0.3 * std::sin(7 * x * y); });
  CHECK(std::abs(r.energy - std::sqrt(1 + 0.09 + 0.16)) < 1e-9);
  VM::Surface_relaxation_options_3 bad;
  bad.grids = {};
  CHECK_THROWS_AS(VM::relax_surface_3(P, VM::Area_functional_3(), [](double, double) { return 0.5; }, bad),
                  std::invalid_argument);
  CHECK_THROWS_AS(VM::relax_surface_3(P, VM::Area_functional_3(), VM::Minimal_surface_3()), std::invalid_argument);
}

TEST_CASE("select_planes_3: the energy never increases", "[variational][surface][selection]")
{
  VM::Surface_problem_3 P;
  P.domain = CGAL::Bbox_2(-1, -1, 1, 1);
  P.zmin = -1.1;
  P.zmax = 1.1;
  P.boundary_segments_per_side = 2;
  P.lower_boundary = [](double x, double y) { return x * y; };
  VM::Surface_plane_options_3 o;
  o.distribution = VM::Plane_distribution_3::slope_limited;
  o.pencil_fraction = 0.2;
  const VM::Plane_selection_result_3 r = VM::select_planes_3(P, VM::Area_functional_3(), 50, 5, o);
  REQUIRE(r.energies.size() == 5);
  for(std::size_t i = 1; i < r.energies.size(); ++i) CHECK(r.energies[i] <= r.energies[i - 1] * (1 + 1e-12));
  CHECK(r.energies.back() < r.energies.front()); // and in this run it improves
  CHECK(r.surface.energy == *std::min_element(r.energies.begin(), r.energies.end()));
  CHECK_THROWS_AS(VM::select_planes_3(P, VM::Area_functional_3(), 50, 0, o), std::invalid_argument);
}

TEST_CASE("refine_surface_3: no worse than its runs; the envelope only restricts", "[variational][surface][refinement]")
{
  const VM::Surface_problem_3 P = VM::scherk_surface_problem_3(4);
  VM::Surface_plane_options_3 o;
  o.distribution = VM::Plane_distribution_3::slope_limited;
  o.max_slope = 3;
  o.pencil_fraction = 0.2;
  for(double margin : {0.0, 0.05}) {
    const VM::Surface_refinement_result_3 R = VM::refine_surface_3(P, VM::Area_functional_3(), 70, 3, o, margin);
    REQUIRE(R.surface.is_feasible);
    REQUIRE(R.run_energies.size() == 3);
    const double best_run = *std::min_element(R.run_energies.begin(), R.run_energies.end());
    CHECK(R.surface.energy <= best_run * (1 + 1e-9));
    CHECK(std::abs(R.surface.energy - R.surface.solver_value) <= 1e-9 * R.surface.energy);
    CHECK(std::abs(R.surface.projected_area - P.domain_area()) <= 1e-9 * P.domain_area());
    CHECK(R.planes.size() == std::max<std::size_t>(70, R.kept_planes));
    CHECK(R.kept_planes > 0);
    CHECK(R.cells_below > 0);
    CHECK(R.cells_above > 0);
    CHECK(R.cells_below + R.cells_above < R.cells);
    // Without the envelope, the same arrangement can only do better or equal.
    const VM::Plane_arrangement_3 A(R.planes);
    CHECK(A.number_of_cells() == R.cells);
    const auto w = VM::surface_facet_weights_3(A, P, VM::Area_functional_3());
    const VM::Minimal_surface_3 free_surface = VM::minimize_surface_functional_3(A, w, P);
    CHECK(free_surface.energy <= R.surface.energy * (1 + 1e-9));
  }
  CHECK_THROWS_AS(VM::refine_surface_3(P, VM::Area_functional_3(), 40, 0, o), std::invalid_argument);
  CHECK_THROWS_AS(VM::refine_surface_3(P, VM::Area_functional_3(), 40, 2, o, -1.0), std::invalid_argument);
  CHECK_THROWS_AS(VM::refine_surface_3(P, VM::Area_functional_3(), 40, 2, o, std::nan("")), std::invalid_argument);
}

TEST_CASE("blob problem: the global solve beats 100 random-start local descents", "[variational][surface][blobs]")
{
  const VM::Surface_problem_3 P = MDCS_test::blob_problem();
  const auto G = VM::random_blob_functional_3(P, 4, 2, 0.12, -1.5, 3);
  VM::Surface_relaxation_options_3 ro;
  ro.grids = {8};
  VM::Surface_plane_options_3 o;
  o.distribution = VM::Plane_distribution_3::slope_limited;
  o.max_slope = 2;
  const VM::Plane_selection_result_3 global = VM::select_planes_3(P, G, 150, 2, o);
  REQUIRE(global.surface.is_feasible);
  const double relaxed_global = VM::relax_surface_3(P, G, global.surface, ro).energy;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(0, 1);
  double best_local = std::numeric_limits<double>::infinity();
  for(int s = 0; s < 100; ++s) {
    double c[4][4];
    for(auto& row : c)
      for(auto& v : row) v = U(rng);
    auto init = [&](double x, double y) {
      const double u = x * 3, v = y * 3;
      const int i = std::min(2, int(u)), j = std::min(2, int(v));
      const double a = u - i, b = v - j;
      return (1 - a) * (1 - b) * c[i][j] + a * (1 - b) * c[i + 1][j] + (1 - a) * b * c[i][j + 1] + a * b * c[i + 1][j + 1];
    };
    best_local = std::min(best_local, VM::relax_surface_3(P, G, init, ro).energy);
  }
  INFO("global (relaxed) " << relaxed_global << ", best local " << best_local);
  CHECK(relaxed_global <= best_local * (1 + 1e-6));
}
