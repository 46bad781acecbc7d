// End-to-end tests of the bivariate solver: linear boundary data gives the plane exactly, Scherk's surface
// converges, the cut value equals the surface energy, the surface is single-valued, all max-flow engines agree,
// membranes sag, relaxed boundaries, the weights (closed form against quadrature), output files and bad input.
#include <MDCS_test/test_numbers.h>

#include <catch2/catch.hpp>

#include <CGAL/Min_cut/solve_min_cut.h>
#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/analytic_solutions_3.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

namespace VM = CGAL::Variational_minimization;

namespace {

using MDCS_test::relative_difference;

template <class Functional, class Engine = CGAL::Min_cut::Default_max_flow_engine>
VM::Minimal_surface_3 solve(const VM::Surface_problem_3& P, const std::vector<VM::Lattice_plane_3>& planes,
                            const Functional& G, Engine engine = Engine())
{
  const VM::Plane_arrangement_3 A = VM::build_surface_arrangement_3(P, planes);
  const std::vector<double> w = VM::surface_facet_weights_3(A, P, G);
  VM::Minimal_surface_3 s = VM::minimize_surface_functional_3(A, w, P, engine);
  REQUIRE(s.is_feasible);
  // Duality: the cut value is the energy of the extracted surface; the surface is a function over the domain.
  CHECK(relative_difference(s.energy, s.solver_value) <= 1e-9);
  CHECK(relative_difference(s.projected_area, P.domain_area()) <= 1e-9);
  for(const auto& p : s.points) {
    CHECK(p[0] >= P.domain.xmin() - 1e-9);
    CHECK(p[0] <= P.domain.xmax() + 1e-9);
    CHECK(p[2] >= P.zmin - 1e-9);
    CHECK(p[2] <= P.zmax + 1e-9);
  }
  return s;
}

} // namespace

TEST_CASE("minimize_surface_functional_3: linear boundary data gives the plane", "[variational][surface]")
{
  // f = 0.25 + 0.5 x + 0.25 y on [0,1]^2: the lattice plane 2X + Y - 4Z + L = 0 holds the boundary samples exactly.
  VM::Surface_problem_3 P;
  P.boundary_segments_per_side = 8;
  P.lower_boundary = [](double x, double y) { return 0.25 + 0.5 * x + 0.25 * y; };
  for(std::uint64_t seed : {1u, 2u}) {
    VM::Surface_plane_options_3 o;
    o.seed = seed;
    std::vector<VM::Lattice_plane_3> planes = VM::surface_planes_3(P, 60, o);
    VM::Lattice_plane_3 exact;
    exact.a = 2; exact.b = 1; exact.c = -4; exact.d = VM::Plane_arrangement_3::lattice_size;
    planes.push_back(exact);
    const VM::Minimal_surface_3 s = solve(P, planes, VM::Area_functional_3());
    CHECK(relative_difference(s.energy, std::sqrt(1 + 0.25 + 0.0625)) <= 1e-9);
    for(const auto& p : s.points) CHECK(std::abs(p[2] - (0.25 + 0.5 * p[0] + 0.25 * p[1])) <= 1e-9);
  }
}

TEST_CASE("minimize_surface_functional_3: Scherk's surface, error falls with the cells", "[variational][surface]")
{
  const VM::Surface_problem_3 P = VM::scherk_surface_problem_3(4);
  const double exact = VM::scherk_surface_area(1.2, 60);
  CHECK(std::abs(exact - 9.9497) < 1e-3);
  VM::Surface_plane_options_3 o;
  o.distribution = VM::Plane_distribution_3::slope_limited;
  o.max_slope = 3;
  o.pencil_fraction = 0.2;
  o.seed = 3;
  const VM::Minimal_surface_3 coarse = solve(P, VM::surface_planes_3(P, 40, o), VM::Area_functional_3());
  const VM::Minimal_surface_3 fine = solve(P, VM::surface_planes_3(P, 160, o), VM::Area_functional_3());
  const double e0 = (coarse.energy - exact) / exact, e1 = (fine.energy - exact) / exact;
  INFO("relative errors " << e0 << " -> " << e1);
  CHECK(std::abs(e1) < std::abs(e0));
  CHECK(std::abs(e1) < 0.02);
  CHECK(fine.facets.size() > coarse.facets.size());
}

TEST_CASE("minimize_surface_functional_3: the max-flow engines agree", "[variational][surface]")
{
  const VM::Surface_problem_3 P = VM::scherk_surface_problem_3(4);
  const auto planes = VM::surface_planes_3(P, 40);
  const VM::Minimal_surface_3 pf = solve(P, planes, VM::Area_functional_3(), CGAL::Min_cut::Pseudoflow_max_flow());
  const VM::Minimal_surface_3 pr = solve(P, planes, VM::Area_functional_3(), CGAL::Min_cut::Push_relabel_max_flow());
  const VM::Minimal_surface_3 bk =
    solve(P, planes, VM::Area_functional_3(), CGAL::Min_cut::Boykov_kolmogorov_max_flow());
  CHECK(relative_difference(pf.solver_value, pr.solver_value) <= 1e-9);
  CHECK(relative_difference(pf.solver_value, bk.solver_value) <= 1e-9);
  CHECK(pf.facets == pr.facets);
  CHECK(pf.facets == bk.facets);
}

TEST_CASE("minimize_surface_functional_3: a membrane sags under gravity", "[variational][surface]")
{
  VM::Surface_problem_3 P;
  P.lower_boundary = [](double, double) { return 0.75; };
  P.boundary_segments_per_side = 2;
  VM::Surface_plane_options_3 o;
  o.distribution = VM::Plane_distribution_3::slope_limited;
  o.pencil_fraction = 0.3;
  const auto planes = VM::surface_planes_3(P, 80, o);
  VM::Membrane_functional_3 G;
  G.k_g = 2;
  G.z_bottom = P.zmin;
  const VM::Minimal_surface_3 s = solve(P, planes, G);
  // The flat membrane f = 0.75 costs 1 + 2 * 0.75; sagging must do better, and never rises above the rim.
  CHECK(s.energy < 2.5 - 1e-3);
  double lowest = 1;
  for(const auto& p : s.points) {
    CHECK(p[2] <= 0.75 + 1e-9);
    lowest = std::min(lowest, p[2]);
  }
  CHECK(lowest < 0.7);
  // Without gravity the flat membrane is optimal and in the arrangement (the boundary cone is flat).
  G.k_g = 0;
  CHECK(relative_difference(solve(P, planes, G).energy, 1.0) <= 1e-9);
}

TEST_CASE("minimize_surface_functional_3: relaxed boundary", "[variational][surface]")
{
  // Area with boundary values free in [0.2, 0.9]: any horizontal plane in the band is optimal (energy 1).
  VM::Surface_problem_3 P;
  P.lower_boundary = [](double x, double) { return 0.2 + 0.1 * x; };
  P.upper_boundary = [](double, double y) { return 0.8 + 0.1 * y; };
  const auto planes = VM::surface_planes_3(P, 50);
  VM::Lattice_plane_3 flat;
  flat.c = 1;
  flat.d = -VM::Plane_arrangement_3::lattice_size / 2;
  std::vector<VM::Lattice_plane_3> with_flat = planes;
  with_flat.push_back(flat);
  const VM::Minimal_surface_3 s = solve(P, with_flat, VM::Area_functional_3());
  CHECK(relative_difference(s.energy, 1.0) <= 1e-9);
  // The same band with a fixed boundary at the lower curve costs more.
  VM::Surface_problem_3 F = P;
  F.upper_boundary = nullptr;
  CHECK(solve(F, VM::surface_planes_3(F, 50), VM::Area_functional_3()).energy > 1.0 + 1e-6);
}

TEST_CASE("surface_facet_weights_3: closed forms agree with quadrature", "[variational][surface]")
{
  const VM::Surface_problem_3 P = VM::scherk_surface_problem_3(4);
  const VM::Plane_arrangement_3 A = VM::build_surface_arrangement_3(P, VM::surface_planes_3(P, 30));
  const auto area = VM::surface_facet_weights_3(A, P, VM::Area_functional_3());
  const auto quad = VM::surface_facet_weights_3(
    A, P, [](double f, double fx, double fy, double x, double y) { return VM::Area_functional_3()(f, fx, fy, x, y); },
    0);
  VM::Membrane_functional_3 M;
  M.k_g = 3;
  M.z_bottom = P.zmin;
  const auto mem = VM::surface_facet_weights_3(A, P, M);
  const auto memq = VM::surface_facet_weights_3(
    A, P, [M](double f, double fx, double fy, double x, double y) { return M(f, fx, fy, x, y); }, 0);
  std::size_t vertical = 0;
  for(std::size_t i = 0; i < area.size(); ++i) {
    if(std::isinf(area[i])) {
      ++vertical;
      CHECK(std::isinf(quad[i]));
      continue;
    }
    CHECK(std::abs(area[i] - quad[i]) <= 1e-12 * (1 + area[i]));
    CHECK(std::abs(mem[i] - memq[i]) <= 1e-11 * (1 + mem[i]));
  }
  CHECK(vertical == 0); // the generators draw no vertical plane
  // Quadrature converges for a non-polynomial integrand.
  const auto G = VM::random_blob_functional_3(P, 4, 2, 0.3, 2.0, 1);
  const auto b1 = VM::surface_facet_weights_3(A, P, G, 1);
  const auto b3 = VM::surface_facet_weights_3(A, P, G, 3);
  double s1 = 0, s3 = 0;
  for(std::size_t i = 0; i < b1.size(); ++i) {
    s1 += b1[i];
    s3 += b3[i];
  }
  CHECK(relative_difference(s1, s3) <= 1e-5);
}

TEST_CASE("minimize_surface_functional_3: output files", "[variational][surface]")
{
  VM::Surface_problem_3 P;
  P.lower_boundary = [](double x, double y) { return 0.5 + 0.3 * x * y; };
  const VM::Minimal_surface_3 s = solve(P, VM::surface_planes_3(P, 30), VM::Area_functional_3());
  CHECK(!s.triangles.empty());
  const std::string ply = "test_surface_3_output.ply", off = "test_surface_3_output.off";
  VM::write_surface_ply(ply, s);
  VM::write_surface_off(off, s);
  std::ifstream in(off);
  std::string magic;
  std::size_t nv = 0, nf = 0;
  in >> magic >> nv >> nf;
  CHECK(magic == "OFF");
  CHECK(nv == s.points.size());
  CHECK(nf == s.triangles.size());
  std::ifstream in2(ply);
  std::getline(in2, magic);
  CHECK(magic == "ply");
  std::remove(ply.c_str());
  std::remove(off.c_str());
}

TEST_CASE("minimize_surface_functional_3: bad input is reported clearly", "[variational][surface]")
{
  VM::Surface_problem_3 P;
  P.lower_boundary = [](double x, double) { return 1.5 * x; }; // leaves [0, 1]
  CHECK_THROWS_AS(P.validate(), std::invalid_argument);
  P.lower_boundary = [](double, double) { return std::nan(""); };
  CHECK_THROWS_AS(VM::surface_planes_3(P, 10), std::invalid_argument);
  P.lower_boundary = nullptr;
  CHECK_THROWS_AS(P.validate(), std::invalid_argument);
  P.lower_boundary = [](double, double) { return 0.5; };
  P.upper_boundary = [](double, double) { return 0.4; };
  CHECK_THROWS_AS(P.validate(), std::invalid_argument);
  P.upper_boundary = nullptr;
  P.domain = CGAL::Bbox_2(1, 0, 0, 1);
  CHECK_THROWS_AS(P.validate(), std::invalid_argument);
  P.domain = CGAL::Bbox_2(0, 0, 1, 1);
  P.zmin = 2;
  CHECK_THROWS_AS(P.validate(), std::invalid_argument);
  P.zmin = 0;
  P.boundary_segments_per_side = 0;
  CHECK_THROWS_AS(P.validate(), std::invalid_argument);
  P.boundary_segments_per_side = 4;
  const VM::Plane_arrangement_3 A = VM::build_surface_arrangement_3(P, VM::surface_planes_3(P, 20));
  // Negative and NaN functionals.
  CHECK_THROWS_AS(VM::surface_facet_weights_3(A, P, [](double, double, double, double, double) { return -1.0; }),
                  std::invalid_argument);
  CHECK_THROWS_AS(
    VM::surface_facet_weights_3(A, P, [](double, double, double, double, double) { return std::nan(""); }),
    std::invalid_argument);
  VM::Membrane_functional_3 M;
  M.k_g = 10;
  M.z_bottom = 0.5; // above the bottom of the range of values: negative on low facets
  CHECK_THROWS_AS(VM::surface_facet_weights_3(A, P, M), std::invalid_argument);
  // Wrong number of weights; a cancelled solve.
  CHECK_THROWS_AS(VM::minimize_surface_functional_3(A, std::vector<double>(3, 1.0), P), std::invalid_argument);
  const auto w = VM::surface_facet_weights_3(A, P, VM::Area_functional_3());
  CHECK_THROWS_AS(VM::minimize_surface_functional_3(A, w, P, CGAL::Min_cut::Pseudoflow_max_flow(),
                                                    [](const char*, double) { return false; }),
                  CGAL::MDCS::Operation_cancelled);
}
