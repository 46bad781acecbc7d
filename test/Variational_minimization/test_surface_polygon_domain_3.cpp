// Polygonal domains of the bivariate solver: validation of the polygon (each bad case gets its message), the plane
// over L-shaped and triangular domains (analytic area), duality and single-valuedness over the polygon, agreement
// of the polygon path with the rectangle path on the same arrangement, the engines, relaxed boundaries, and G
// never evaluated outside the domain.
#include <catch2/catch.hpp>

#include <CGAL/Min_cut/solve_min_cut.h>
#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/relax_surface_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <MDCS_test/polygon_geometry.h>
#include <MDCS_test/test_numbers.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace VM = CGAL::Variational_minimization;
typedef std::vector<std::array<double, 2>> Polygon;

namespace {

using MDCS_test::relative_difference;

const Polygon L_shape = {{{0, 0}}, {{1, 0}}, {{1, 0.5}}, {{0.5, 0.5}}, {{0.5, 1}}, {{0, 1}}};

using MDCS_test::in_polygon;

template <class Functional, class Engine = CGAL::Min_cut::Default_max_flow_engine>
VM::Minimal_surface_3 solve_on_polygon(const VM::Surface_problem_3& P, const std::vector<VM::Lattice_plane_3>& planes,
                            const Functional& G, Engine engine = Engine())
{
  const VM::Plane_arrangement_3 A = VM::build_surface_arrangement_3(P, planes);
  const std::vector<double> w = VM::surface_facet_weights_3(A, P, G);
  VM::Minimal_surface_3 s = VM::minimize_surface_functional_3(A, w, P, engine);
  REQUIRE(s.is_feasible);
  CHECK(relative_difference(s.energy, s.solver_value) <= 1e-9);
  CHECK(relative_difference(s.projected_area, P.domain_area()) <= 1e-9);
  for(const auto& p : s.points) {
    CHECK(in_polygon(P.domain_polygon, p[0], p[1]));
    CHECK(p[2] >= P.zmin - 1e-9);
    CHECK(p[2] <= P.zmax + 1e-9);
  }
  return s;
}

void check_invalid(const Polygon& polygon, const std::string& message)
{
  VM::Surface_problem_3 P;
  P.lower_boundary = [](double, double) { return 0.5; };
  P.set_domain_polygon(polygon);
  INFO("expected: " << message);
  CHECK_THROWS_AS(P.validate(), std::invalid_argument);
  CHECK_THROWS_WITH(P.validate(), Catch::Contains(message));
  CHECK_THROWS_AS(VM::surface_planes_3(P, 20), std::invalid_argument);
}

} // namespace

TEST_CASE("Surface_problem_3: bad domain polygons get a clear error", "[variational][surface][polygon]")
{
  check_invalid({{{0, 0}}, {{1, 0}}}, "at least 3 are needed");
  check_invalid({{{0, 0}}, {{1, 0}}, {{1, 1}}, {{1, 0}}}, "coincide");
  check_invalid({{{0, 0}}, {{1, 0}}, {{1, 1e-5}}, {{0, 1}}}, "coincide");        // equal once rounded to 1/256
  check_invalid({{{0, 0}}, {{0.5, 0.5}}, {{1, 1}}}, "collinear");                 // all on one line
  check_invalid({{{0, 0}}, {{1, 0}}, {{2, 0}}}, "zero area");                     // a flat bounding box
  check_invalid({{{0, 0}}, {{1, 0}}, {{2, 0}}, {{1, 1}}}, "collinear");            // a straight angle
  check_invalid({{{0, 0}}, {{1, 1}}, {{1, 0}}, {{0, 1}}}, "self-intersecting");    // a bow tie
  check_invalid({{{0, 0}}, {{2, 0}}, {{2, 2}}, {{1, 2}}, {{1, -1}}, {{0, 1}}}, "self-intersecting");
  check_invalid({{{0, 0}}, {{1, 0}}, {{0.5, 0}}, {{0.5, 1}}}, "collinear");        // an edge folding back
  check_invalid({{{0, 0}}, {{1, 0}}, {{1, 0}}, {{0, 1}}}, "coincide");
  check_invalid({{{0, 0}}, {{std::numeric_limits<double>::quiet_NaN(), 0}}, {{0, 1}}}, "not finite");
  check_invalid({{{0, 0}}, {{std::numeric_limits<double>::infinity(), 0}}, {{0, 1}}}, "not finite");
  check_invalid({{{-1e308, 0}}, {{1e308, 0}}, {{0, 1}}}, "too large");
  // The domain rectangle must be the polygon's bounding box.
  VM::Surface_problem_3 P;
  P.lower_boundary = [](double, double) { return 0.5; };
  P.domain_polygon = L_shape;
  P.domain = CGAL::Bbox_2(0, 0, 2, 2);
  CHECK_THROWS_WITH(P.validate(), Catch::Contains("bounding box"));
  P.set_domain_polygon(L_shape);
  CHECK_NOTHROW(P.validate());
  // Either orientation is accepted.
  Polygon cw(L_shape.rbegin(), L_shape.rend());
  P.set_domain_polygon(cw);
  CHECK_NOTHROW(P.validate());
  CHECK(relative_difference(P.domain_area(), 0.75) <= 1e-15);
}

TEST_CASE("minimize_surface_functional_3: linear boundary data gives the plane on L-shaped and triangular domains",
          "[variational][surface][polygon]")
{
  // f = 0.25 + 0.5 x + 0.25 y: the lattice plane 2X + Y - 4Z + L = 0 holds the boundary samples exactly, and the
  // planes of the triangulated boundary loop are that plane (duplicates are dropped): the surface is the plane.
  const Polygon triangle = {{{0, 0}}, {{1, 0}}, {{0, 1}}};
  const Polygon hexagon = {{{0.25, 0}}, {{0.75, 0}}, {{1, 0.5}}, {{0.75, 1}}, {{0.25, 1}}, {{0, 0.5}}};
  const Polygon u_shape = {{{0, 0}}, {{1, 0}}, {{1, 1}}, {{0.75, 1}}, {{0.75, 0.25}}, {{0.25, 0.25}}, {{0.25, 1}},
                           {{0, 1}}};
  const std::vector<std::pair<Polygon, double>> domains = {{L_shape, 0.75}, {triangle, 0.5}, {hexagon, 0.75},
                                                           {u_shape, 0.625}};
  for(const auto& d : domains)
    for(std::uint64_t seed : {1u, 2u}) {
      VM::Surface_problem_3 P;
      P.boundary_segments_per_side = 4;
      P.lower_boundary = [](double x, double y) { return 0.25 + 0.5 * x + 0.25 * y; };
      P.set_domain_polygon(d.first);
      CHECK(relative_difference(P.domain_area(), d.second) <= 1e-15);
      VM::Surface_plane_options_3 o;
      o.seed = seed;
      o.distribution = seed == 1 ? VM::Plane_distribution_3::isotropic : VM::Plane_distribution_3::slope_limited;
      const VM::Minimal_surface_3 s = solve_on_polygon(P, VM::surface_planes_3(P, 50, o), VM::Area_functional_3());
      INFO("domain with " << d.first.size() << " vertices, seed " << seed);
      CHECK(relative_difference(s.energy, std::sqrt(1 + 0.25 + 0.0625) * d.second) <= 1e-9);
      for(const auto& p : s.points) CHECK(std::abs(p[2] - (0.25 + 0.5 * p[0] + 0.25 * p[1])) <= 1e-9);
    }
}

TEST_CASE("minimize_surface_functional_3: a polygon equal to the box gives the rectangle's optimum",
          "[variational][surface][polygon]")
{
  // Independent paths: the polygon network (cells classified, ties through the edge curves, generic Flow_network)
  // against the rectangle's lean pseudoflow path, on the same arrangement and the same boundary loop.
  VM::Surface_problem_3 R;
  R.boundary_segments_per_side = 4;
  R.lower_boundary = [](double x, double y) { return 0.5 + (x - 0.5) * (y - 0.5); };
  VM::Surface_problem_3 Q = R;
  Q.set_domain_polygon({{{0, 0}}, {{1, 0}}, {{1, 1}}, {{0, 1}}});
  CHECK(R.boundary_loop(false) == Q.boundary_loop(false));
  VM::Surface_plane_options_3 o;
  o.seed = 5;
  const std::vector<VM::Lattice_plane_3> planes = VM::surface_planes_3(Q, 90, o);
  const VM::Plane_arrangement_3 A(planes);
  const VM::Minimal_surface_3 r = VM::minimize_surface_functional_3(A, R, VM::Area_functional_3());
  const VM::Minimal_surface_3 q = VM::minimize_surface_functional_3(A, Q, VM::Area_functional_3());
  REQUIRE(r.is_feasible);
  REQUIRE(q.is_feasible);
  CHECK(relative_difference(r.energy, q.energy) <= 1e-9);
  CHECK(relative_difference(q.energy, q.solver_value) <= 1e-9);
  CHECK(r.energy >= 1.117); // at least the minimal area spanning the boundary loop
}

TEST_CASE("minimize_surface_functional_3: L-shaped domain, duality, single-valuedness, engines agree",
          "[variational][surface][polygon]")
{
  VM::Surface_problem_3 P;
  P.boundary_segments_per_side = 4;
  P.lower_boundary = [](double x, double y) { return 0.5 + 0.8 * (x - 0.5) * (y - 0.5); };
  P.set_domain_polygon(L_shape);
  VM::Surface_plane_options_3 o;
  o.seed = 3;
  o.pencil_fraction = 0.3;
  const std::vector<VM::Lattice_plane_3> planes = VM::surface_planes_3(P, 100, o);
  const VM::Minimal_surface_3 pf = solve_on_polygon(P, planes, VM::Area_functional_3());
  const VM::Minimal_surface_3 pr = solve_on_polygon(P, planes, VM::Area_functional_3(), CGAL::Min_cut::Push_relabel_max_flow());
  const VM::Minimal_surface_3 bk = solve_on_polygon(P, planes, VM::Area_functional_3(), CGAL::Min_cut::Boykov_kolmogorov_max_flow());
  CHECK(relative_difference(pf.energy, pr.energy) <= 1e-9);
  CHECK(relative_difference(pf.energy, bk.energy) <= 1e-9);
  // The functional path (no weight vector given) gives the same optimum.
  const VM::Plane_arrangement_3 A(planes);
  const VM::Minimal_surface_3 lean = VM::minimize_surface_functional_3(A, P, VM::Area_functional_3());
  CHECK(relative_difference(lean.energy, pf.energy) <= 1e-9);
  // The area lies between the flat area (a lower bound) and the optimum on the first planes only (the edges, the
  // triangulated boundary loop and the pencils): more planes, more candidate functions.
  const std::vector<VM::Lattice_plane_3> first(planes.begin(),
                                               planes.begin() + std::ptrdiff_t(VM::surface_pencil_count_3(P, 100, o)));
  const VM::Minimal_surface_3 coarse = solve_on_polygon(P, first, VM::Area_functional_3());
  INFO("energies " << coarse.energy << " (" << first.size() << " planes) -> " << pf.energy);
  CHECK(pf.energy > 0.75);
  CHECK(pf.energy <= coarse.energy * (1 + 1e-12));
  CHECK(pf.energy < coarse.energy * 0.999);
}

TEST_CASE("minimize_surface_functional_3: relaxed boundary on a polygon, G not evaluated outside",
          "[variational][surface][polygon]")
{
  // 0.3 <= f <= 0.7 on the boundary of the L: the flat surface z = 0.3 (the planes of the triangulated lower loop)
  // is optimal, area 0.75.
  VM::Surface_problem_3 P;
  P.boundary_segments_per_side = 2;
  P.lower_boundary = [](double, double) { return 0.3; };
  P.upper_boundary = [](double, double) { return 0.7; };
  P.set_domain_polygon(L_shape);
  VM::Surface_plane_options_3 o;
  o.seed = 9;
  // G is negative outside the L (the square [0.5, 1]^2): it must never be evaluated there.
  const auto G = [](double, double fx, double fy, double x, double y) {
    return (x > 0.5 + 1e-12 && y > 0.5 + 1e-12) ? -1.0 : std::sqrt(1 + fx * fx + fy * fy);
  };
  const VM::Minimal_surface_3 s = solve_on_polygon(P, VM::surface_planes_3(P, 60, o), G);
  CHECK(relative_difference(s.energy, 0.75) <= 1e-9);
  for(const auto& p : s.points) {
    CHECK(p[2] >= 0.3 - 1e-9);
    CHECK(p[2] <= 0.7 + 1e-9);
  }
  // A fixed boundary with a bump: the surface leaves the plane, still over the L only.
  P.upper_boundary = nullptr;
  P.lower_boundary = [](double x, double y) { return 0.3 + 0.4 * x * y; };
  const VM::Minimal_surface_3 b = solve_on_polygon(P, VM::surface_planes_3(P, 60, o), G);
  CHECK(b.energy > 0.75);
}

TEST_CASE("Surface_problem_3: polygon boundary samples lie on the grid points of the edges",
          "[variational][surface][polygon]")
{
  VM::Surface_problem_3 P;
  P.boundary_segments_per_side = 8;
  P.lower_boundary = [](double, double) { return 0.5; };
  // Edge (1, 0) -> (0, 1) in a box of side 1: 257 grid points, 8 samples per edge. The edge (1, 1) -> (0, 1/3),
  // (-256, -171) in grid units (gcd 1), has only its first endpoint as a sample.
  P.set_domain_polygon({{{0, 0}}, {{1, 0}}, {{0, 1}}});
  CHECK(P.polygon_samples().size() == 24);
  P.set_domain_polygon({{{0, 0}}, {{1, 0}}, {{1, 1}}, {{0, 1.0 / 3}}});
  const auto s = P.polygon_samples();
  std::size_t per_edge[4] = {0, 0, 0, 0};
  for(const auto& q : s) ++per_edge[q[2]];
  CHECK(per_edge[0] == 8);
  CHECK(per_edge[1] == 8);
  CHECK(per_edge[2] == 1);
  CHECK(per_edge[3] == 8);
  for(const auto& q : s) {
    CHECK(q[0] % 256 == 0);
    CHECK(q[1] % 256 == 0);
  }
  // Relaxation works on polygons (test_surface_polygon_relax_refine_3.cpp): this polygon's mesh has its
  // boundary nodes fixed to the data.
  VM::Surface_relaxation_options_3 o;
  o.grids = {4};
  const VM::Relaxed_surface_3 r = VM::relax_surface_3(P, VM::Area_functional_3(), [](double, double) { return 0.5; }, o);
  CHECK(!r.triangles.empty());
  CHECK(std::abs(r.energy - P.domain_area()) <= 1e-12);
}
