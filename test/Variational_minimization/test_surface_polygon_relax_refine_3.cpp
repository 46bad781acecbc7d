// Relaxation and adaptive refinement on polygonal domains: the polygon's relaxation meshes (boundary nodes on the
// edges, area of Ω, angles and edge lengths), the energy's gradient against finite differences, linear boundary
// data relaxed to the plane from a wavy start (analytic area), a non-trivial problem on a convex hexagon (relaxed
// <= discrete, decreasing with resolution, never increasing within a level), the polygon path against the
// rectangle's grid path on the box, G never evaluated outside Ω, and refinement (the plane on linear data, no
// worse than its runs, single-valued over Ω, the envelope only restricts).
#include <catch2/catch.hpp>

#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/internal/mesh_surface_3.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/refine_surface_3.h>
#include <CGAL/Variational_minimization/relax_surface_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <MDCS_test/polygon_geometry.h>
#include <MDCS_test/test_numbers.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace VM = CGAL::Variational_minimization;
typedef std::vector<std::array<double, 2>> Polygon;

namespace {

using MDCS_test::relative_difference;

using MDCS_test::pi;
const Polygon L_shaped_domain = {{{0, 0}}, {{1, 0}}, {{1, 0.5}}, {{0.5, 0.5}}, {{0.5, 1}}, {{0, 1}}};
const Polygon triangle = {{{0, 0}}, {{1, 0}}, {{0, 1}}};
const Polygon hexagon = {{{0.25, 0}}, {{0.75, 0}}, {{1, 0.5}}, {{0.75, 1}}, {{0.25, 1}}, {{0, 0.5}}};
const Polygon u_shape = {{{0, 0}}, {{1, 0}}, {{1, 1}}, {{0.75, 1}}, {{0.75, 0.25}}, {{0.25, 0.25}}, {{0.25, 1}},
                         {{0, 1}}};

using MDCS_test::boundary_distance;
using MDCS_test::in_polygon;

// Boundary data of the hexagon, linear along each edge, with heights alternating 0.3 / 0.7 at the vertices (a
// three-fold saddle): the discrete boundary curve through the edges' samples and the relaxation's boundary nodes
// represent it exactly, so the relaxed energies approach the continuous minimum from above.
double hexagon_saddle(double x, double y)
{
  std::size_t e = 0;
  boundary_distance(hexagon, x, y, &e);
  const auto& a = hexagon[e];
  const auto& b = hexagon[(e + 1) % hexagon.size()];
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double t = std::max(0.0, std::min(1.0, ((x - a[0]) * dx + (y - a[1]) * dy) / (dx * dx + dy * dy)));
  const double za = e % 2 == 0 ? 0.3 : 0.7, zb = e % 2 == 0 ? 0.7 : 0.3;
  return za + t * (zb - za);
}

VM::Minimal_surface_3 discrete_optimum(const VM::Surface_problem_3& P, std::size_t planes, std::uint64_t seed)
{
  VM::Surface_plane_options_3 o;
  o.seed = seed;
  o.distribution = VM::Plane_distribution_3::slope_limited;
  o.pencil_fraction = 0.2;
  const VM::Plane_arrangement_3 A = VM::build_surface_arrangement_3(P, VM::surface_planes_3(P, planes, o));
  VM::Minimal_surface_3 s = VM::minimize_surface_functional_3(A, VM::surface_facet_weights_3(A, P, VM::Area_functional_3()), P);
  REQUIRE(s.is_feasible);
  return s;
}

void check_relaxed_mesh(const VM::Surface_problem_3& P, const VM::Relaxed_surface_3& r)
{
  REQUIRE(!r.triangles.empty());
  REQUIRE(r.heights.size() == r.nodes.size());
  const VM::Minimal_surface_3 m = VM::grid_surface_mesh_3(P, r);
  CHECK(relative_difference(m.projected_area, P.domain_area()) <= 1e-12);
  for(const auto& p : m.points) {
    CHECK(in_polygon(P.domain_polygon, p[0], p[1]));
    CHECK(p[2] >= P.zmin);
    CHECK(p[2] <= P.zmax);
  }
  REQUIRE(r.level_energies.size() == r.level_start_energies.size());
  for(std::size_t i = 0; i < r.level_energies.size(); ++i) CHECK(r.level_energies[i] <= r.level_start_energies[i]);
  CHECK(r.energy == r.level_energies.back());
}

} // namespace

TEST_CASE("polygon_relaxation_mesh_3: boundary nodes on the edges, area, angles, edge lengths",
          "[variational][surface][polygon][relaxation]")
{
  for(const Polygon& poly : {L_shaped_domain, triangle, hexagon, u_shape})
    for(int n : {5, 20}) {
      VM::Surface_problem_3 P;
      P.lower_boundary = [](double, double) { return 0.5; };
      P.set_domain_polygon(poly);
      const VM::internal::Triangle_mesh_frame_3 m = VM::internal::polygon_relaxation_mesh_3(P, n);
      INFO(poly.size() << " vertices, level " << n);
      double area = 0, min_angle = pi, max_edge = 0;
      std::vector<char> used(m.size(), 0);
      for(std::size_t t = 0; t < m.triangles.size(); ++t) {
        area += m.area[t];
        CHECK(in_polygon(poly, m.centroid[t][0], m.centroid[t][1], 0));
        for(int k = 0; k < 3; ++k) {
          used[m.triangles[t][k]] = 1;
          const auto& a = m.nodes[m.triangles[t][k]];
          const auto& b = m.nodes[m.triangles[t][(k + 1) % 3]];
          const auto& c = m.nodes[m.triangles[t][(k + 2) % 3]];
          const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
          min_angle = std::min(min_angle, std::acos((ux * vx + uy * vy) / std::hypot(ux, uy) / std::hypot(vx, vy)));
          max_edge = std::max(max_edge, std::hypot(ux, uy));
        }
      }
      CHECK(relative_difference(area, P.domain_area()) <= 1e-13);
      CHECK(std::count(used.begin(), used.end(), 1) == std::ptrdiff_t(m.size()));
      // The mesher's guarantees: angles >= arcsin(sqrt(0.125)) = 20.7 degrees except at input vertices with a
      // smaller angle (none here: the smallest is 45), edges no longer than the grid square's diagonal.
      CHECK(min_angle >= 20.7 * pi / 180 - 1e-9);
      CHECK(max_edge <= std::sqrt(2.0) / n * (1 + 1e-12));
      // Boundary nodes: exactly the nodes on ∂Ω, and every polygon vertex is one.
      std::size_t boundary = 0;
      for(std::size_t k = 0; k < m.size(); ++k) {
        const bool on = boundary_distance(poly, m.nodes[k][0], m.nodes[k][1]) <= 1e-12;
        CHECK(bool(m.on_boundary[k]) == on);
        boundary += m.on_boundary[k];
      }
      for(const auto& v : poly) {
        bool found = false;
        for(const auto& q : m.nodes) found = found || (q[0] == v[0] && q[1] == v[1]);
        CHECK(found);
      }
      CHECK(boundary >= poly.size());
    }
}

TEST_CASE("mesh_energy_3: the gradient is the derivative of the energy", "[variational][surface][polygon][relaxation]")
{
  VM::Surface_problem_3 P;
  P.lower_boundary = [](double, double) { return 0.5; };
  P.set_domain_polygon(L_shaped_domain);
  const VM::internal::Triangle_mesh_frame_3 m = VM::internal::polygon_relaxation_mesh_3(P, 6);
  // A functional depending on f, the gradient and the position.
  auto G = [](double f, double fx, double fy, double x, double y) {
    return std::sqrt(1 + fx * fx + 2 * fy * fy) * (1 + x * y) + 0.7 * f * f + 0.1 * fx * y;
  };
  std::vector<double> f(m.size()), grad;
  for(std::size_t k = 0; k < m.size(); ++k) f[k] = 0.5 + 0.3 * std::sin(5 * m.nodes[k][0] + 3 * m.nodes[k][1]);
  VM::internal::mesh_energy_3(m, G, f, &grad);
  for(std::size_t k = 0; k < m.size(); k += 7) {
    std::vector<double> p = f, q = f;
    const double h = 1e-5;
    p[k] += h;
    q[k] -= h;
    const double fd = (VM::internal::mesh_energy_3(m, G, p, nullptr) - VM::internal::mesh_energy_3(m, G, q, nullptr)) / (2 * h);
    CHECK(std::abs(grad[k] - fd) <= 1e-6 * (1 + std::abs(fd)));
  }
  // Energy of the plane f = 0.2 + 0.3 x + 0.4 y for the area: sqrt(1 + 0.09 + 0.16) |Ω| (exact on any mesh).
  for(std::size_t k = 0; k < m.size(); ++k) f[k] = 0.2 + 0.3 * m.nodes[k][0] + 0.4 * m.nodes[k][1];
  CHECK(relative_difference(VM::internal::mesh_energy_3(m, VM::Area_functional_3(), f, nullptr), std::sqrt(1.25) * 0.75) <= 1e-13);
}

TEST_CASE("relax_surface_3: linear boundary data relaxes to the plane on L, triangle, hexagon and U domains",
          "[variational][surface][polygon][relaxation]")
{
  const std::vector<std::pair<Polygon, double>> domains = {{L_shaped_domain, 0.75}, {triangle, 0.5}, {hexagon, 0.75},
                                                           {u_shape, 0.625}};
  for(const auto& d : domains) {
    VM::Surface_problem_3 P;
    P.boundary_segments_per_side = 4;
    P.lower_boundary = [](double x, double y) { return 0.25 + 0.5 * x + 0.25 * y; };
    P.set_domain_polygon(d.first);
    INFO("domain with " << d.first.size() << " vertices");
    const double exact = std::sqrt(1 + 0.25 + 0.0625) * d.second;
    // From a wavy start (the optimiser must find the plane) on two levels.
    VM::Surface_relaxation_options_3 o;
    o.grids = {10, 20};
    const VM::Relaxed_surface_3 r = VM::relax_surface_3(
      P, VM::Area_functional_3(), [](double x, double y) { return 0.5 + 0.3 * std::sin(7 * x * y); }, o);
    check_relaxed_mesh(P, r);
    CHECK(r.n == 20);
    CHECK(relative_difference(r.energy, exact) <= 1e-9);
    CHECK(r.level_start_energies.front() > exact * (1 + 1e-3)); // the start was not the plane
    for(std::size_t k = 0; k < r.nodes.size(); ++k)
      CHECK(std::abs(r.heights[k] - (0.25 + 0.5 * r.nodes[k][0] + 0.25 * r.nodes[k][1])) <= 1e-4);
    // From the discrete optimum (the plane already) on the default levels 20, 40, 80.
    const VM::Relaxed_surface_3 s = VM::relax_surface_3(P, VM::Area_functional_3(), discrete_optimum(P, 40, 1));
    check_relaxed_mesh(P, s);
    CHECK(s.n == 80);
    CHECK(relative_difference(s.energy, exact) <= 1e-9);
    for(std::size_t k = 0; k < s.nodes.size(); ++k)
      CHECK(std::abs(s.heights[k] - (0.25 + 0.5 * s.nodes[k][0] + 0.25 * s.nodes[k][1])) <= 1e-9);
  }
}

TEST_CASE("relax_surface_3: a three-fold saddle on a convex hexagon", "[variational][surface][polygon][relaxation]")
{
  VM::Surface_problem_3 P;
  P.boundary_segments_per_side = 4;
  P.lower_boundary = hexagon_saddle;
  P.set_domain_polygon(hexagon);
  const VM::Minimal_surface_3 s = discrete_optimum(P, 80, 3);
  std::vector<double> energies;
  for(std::vector<int> grids : {std::vector<int>{20}, {20, 40}, {20, 40, 80}}) {
    VM::Surface_relaxation_options_3 o;
    o.grids = grids;
    const VM::Relaxed_surface_3 r = VM::relax_surface_3(P, VM::Area_functional_3(), s, o);
    check_relaxed_mesh(P, r);
    for(std::size_t k = 0; k < r.nodes.size(); ++k)
      if(boundary_distance(hexagon, r.nodes[k][0], r.nodes[k][1]) <= 1e-12)
        CHECK(std::abs(r.heights[k] - hexagon_saddle(r.nodes[k][0], r.nodes[k][1])) <= 1e-12);
    energies.push_back(r.energy);
  }
  INFO("discrete " << s.energy << ", relaxed " << energies[0] << ", " << energies[1] << ", " << energies[2]);
  // Not flat (the area of the hexagon is a strict lower bound), below the discrete optimum, decreasing with the
  // resolution, and the decrease slows down (second-order convergence of the piecewise linear energy).
  CHECK(energies[2] > 0.75 * 1.01);
  CHECK(energies[0] < s.energy);
  CHECK(energies[1] < energies[0]);
  CHECK(energies[2] < energies[1]);
  CHECK(energies[1] - energies[2] < energies[0] - energies[1]);
}

TEST_CASE("relax_surface_3: a polygon equal to the box agrees with the rectangle's grids",
          "[variational][surface][polygon][relaxation]")
{
  // Two discretisations of the same continuous problem: the rectangle's 80^2 grid and the polygon's meshes.
  VM::Surface_problem_3 R;
  R.lower_boundary = [](double x, double y) { return 0.5 + 0.8 * (x - 0.5) * (y - 0.5); };
  VM::Surface_problem_3 Q = R;
  Q.set_domain_polygon({{{0, 0}}, {{1, 0}}, {{1, 1}}, {{0, 1}}});
  auto start = [](double x, double y) { return 0.5 + 0.1 * std::sin(3 * x + y); };
  const VM::Relaxed_surface_3 a = VM::relax_surface_3(R, VM::Area_functional_3(), start);
  const VM::Relaxed_surface_3 b = VM::relax_surface_3(Q, VM::Area_functional_3(), start);
  CHECK(a.triangles.empty());
  check_relaxed_mesh(Q, b);
  INFO("grid " << a.energy << ", mesh " << b.energy);
  CHECK(relative_difference(a.energy, b.energy) <= 2e-5);
}

TEST_CASE("relax_surface_3: G is never evaluated outside a polygon; bad input throws",
          "[variational][surface][polygon][relaxation]")
{
  VM::Surface_problem_3 P;
  P.boundary_segments_per_side = 4;
  P.lower_boundary = [](double x, double y) { return 0.4 + 0.2 * x * y; };
  P.set_domain_polygon(L_shaped_domain);
  // Negative over the L's missing quarter: relax_surface_3 would throw if it evaluated G there.
  auto G = [](double f, double fx, double fy, double x, double y) {
    return x > 0.5 + 1e-12 && y > 0.5 + 1e-12 ? -1.0 : VM::Area_functional_3()(f, fx, fy, x, y);
  };
  VM::Surface_relaxation_options_3 o;
  o.grids = {10, 20};
  VM::Relaxed_surface_3 r;
  CHECK_NOTHROW(r = VM::relax_surface_3(P, G, [](double, double) { return 0.5; }, o));
  check_relaxed_mesh(P, r);
  // A relaxed band: nodes on ∂Ω stay within [g0, g1]; the flat f = 0.5 lies in the band: area 0.75.
  VM::Surface_problem_3 B = P;
  B.lower_boundary = [](double, double) { return 0.3; };
  B.upper_boundary = [](double, double) { return 0.7; };
  const VM::Relaxed_surface_3 band =
    VM::relax_surface_3(B, VM::Area_functional_3(), [](double x, double y) { return 0.2 + 0.6 * x * y; }, o);
  check_relaxed_mesh(B, band);
  CHECK(relative_difference(band.energy, 0.75) <= 1e-9);
  // Negative G inside Ω, and bad options, throw.
  CHECK_THROWS_AS(VM::relax_surface_3(P, [](double, double, double, double, double) { return -1.0; },
                                      [](double, double) { return 0.5; }, o),
                  std::invalid_argument);
  VM::Surface_relaxation_options_3 bad;
  bad.grids = {0};
  CHECK_THROWS_AS(VM::relax_surface_3(P, VM::Area_functional_3(), [](double, double) { return 0.5; }, bad),
                  std::invalid_argument);
  // Boundary data that is NaN between the boundary samples (validate() checks the samples only): the mesh's
  // boundary nodes between them are checked.
  VM::Surface_problem_3 N = P;
  N.lower_boundary = [](double x, double y) { return y == 0 && x > 0.05 && x < 0.2 ? std::nan("") : 0.5; };
  CHECK_NOTHROW(N.validate());
  CHECK_THROWS_WITH(VM::relax_surface_3(N, VM::Area_functional_3(), [](double, double) { return 0.5; }, o),
                    Catch::Contains("boundary data"));
  VM::Surface_problem_3 Z = P;
  Z.set_domain_polygon({{{0, 0}}, {{1, 0}}, {{0, 1}}, {{1, 1}}}); // bow tie
  CHECK_THROWS_AS(VM::relax_surface_3(Z, VM::Area_functional_3(), [](double, double) { return 0.5; }, o),
                  std::invalid_argument);
}

TEST_CASE("refine_surface_3 on polygons: the plane on linear data; no worse than its runs; single-valued",
          "[variational][surface][polygon][refinement]")
{
  VM::Surface_plane_options_3 o;
  o.distribution = VM::Plane_distribution_3::slope_limited;
  o.pencil_fraction = 0.2;
  {
    VM::Surface_problem_3 P;
    P.boundary_segments_per_side = 4;
    P.lower_boundary = [](double x, double y) { return 0.25 + 0.5 * x + 0.25 * y; };
    for(const Polygon& poly : {L_shaped_domain, u_shape}) {
      P.set_domain_polygon(poly);
      const VM::Surface_refinement_result_3 R = VM::refine_surface_3(P, VM::Area_functional_3(), 40, 2, o, 0.02);
      REQUIRE(R.surface.is_feasible);
      CHECK(relative_difference(R.surface.energy, std::sqrt(1.3125) * P.domain_area()) <= 1e-9);
      for(const auto& p : R.surface.points) CHECK(std::abs(p[2] - (0.25 + 0.5 * p[0] + 0.25 * p[1])) <= 1e-9);
    }
  }
  struct Case { Polygon polygon; double (*g)(double, double); };
  const std::vector<Case> cases = {
    {hexagon, hexagon_saddle},
    {L_shaped_domain, [](double x, double y) { return 0.5 + 1.2 * (x - 0.5) * (y - 0.5); }}};
  for(const Case& c : cases)
    for(double margin : {0.0, 0.05}) {
      VM::Surface_problem_3 P;
      P.boundary_segments_per_side = 4;
      P.lower_boundary = c.g;
      P.set_domain_polygon(c.polygon);
      INFO(c.polygon.size() << " vertices, margin " << margin);
      const VM::Surface_refinement_result_3 R = VM::refine_surface_3(P, VM::Area_functional_3(), 60, 3, o, margin);
      REQUIRE(R.surface.is_feasible);
      const double best_run = *std::min_element(R.run_energies.begin(), R.run_energies.end());
      CHECK(R.surface.energy <= best_run * (1 + 1e-9));
      CHECK(relative_difference(R.surface.energy, R.surface.solver_value) <= 1e-9);
      CHECK(relative_difference(R.surface.projected_area, P.domain_area()) <= 1e-9);
      for(const auto& p : R.surface.points) CHECK(in_polygon(c.polygon, p[0], p[1]));
      CHECK(R.cells_below > 0);
      CHECK(R.cells_above > 0);
      CHECK(R.cells_outside > 0);
      CHECK(R.cells_below + R.cells_above + R.cells_outside + R.network_nodes == R.cells);
      // The arrangement holds the edge planes, so every cell is inside or outside Ω; the outside count is the
      // independent classification's.
      const VM::Plane_arrangement_3 A(R.planes);
      REQUIRE(A.number_of_cells() == R.cells);
      const std::vector<char> inside = VM::internal::surface_domain_cells_3(A, P);
      CHECK(std::size_t(std::count(inside.begin(), inside.end(), 0)) == R.cells_outside);
      // Without the envelope, the same arrangement can only do better or equal.
      const VM::Minimal_surface_3 free_surface =
        VM::minimize_surface_functional_3(A, VM::surface_facet_weights_3(A, P, VM::Area_functional_3()), P);
      REQUIRE(free_surface.is_feasible);
      CHECK(free_surface.energy <= R.surface.energy * (1 + 1e-9));
    }
}
