// Tests of the memory-lean surface path: pseudoflow run straight on the arrangement (Surface_residual_graph_3),
// with a weight vector or with the weights computed on the fly, against the generic Flow_network path of the three
// engines; the edge planes recovered from the vertices; the realloc-grown arrays of the arrangement.
#include <catch2/catch.hpp>

#include <CGAL/Min_cut/solve_min_cut.h>
#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/analytic_solutions_3.h>
#include <CGAL/Variational_minimization/internal/Growable_array_3.h>
#include <CGAL/Variational_minimization/internal/surface_dual_network_3.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/select_planes_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <MDCS_test/polygon_geometry.h>
#include <MDCS_test/surface_problems.h>
#include <MDCS_test/test_numbers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace VM = CGAL::Variational_minimization;

namespace {

using MDCS_test::relative_difference;

// The energy of the generic path with a given engine (Flow_network + solve_min_cut).
template <class Engine>
VM::Minimal_surface_3 generic(const VM::Plane_arrangement_3& A, const std::vector<double>& w,
                              const VM::Surface_problem_3& P, Engine engine)
{
  VM::Minimal_surface_3 s;
  CGAL::MDCS::No_progress progress;
  VM::internal::Surface_cut_3 cut = VM::internal::surface_min_cut_3(A, w, P, engine, progress);
  if(!cut.is_finite) return s;
  s.is_feasible = true;
  s.solver_value = cut.value;
  s.facets = cut.facets;
  return s;
}

} // namespace

TEST_CASE("minimize_surface_functional_3: pseudoflow on the arrangement agrees with the Flow_network path",
          "[variational][surface][min_cut]")
{
  struct Case
  {
    const char* name;
    VM::Surface_problem_3 problem;
    VM::Plane_distribution_3 distribution;
    std::size_t planes;
  };
  std::vector<Case> cases;
  cases.push_back({"Scherk, slope-limited", VM::scherk_surface_problem_3(4), VM::Plane_distribution_3::slope_limited, 60});
  const VM::Surface_problem_3 saddle = MDCS_test::saddle_problem(3);
  cases.push_back({"saddle, isotropic", saddle, VM::Plane_distribution_3::isotropic, 50});
  VM::Surface_problem_3 relaxed;
  relaxed.boundary_segments_per_side = 2;
  relaxed.lower_boundary = [](double x, double) { return 0.2 + 0.3 * x; };
  relaxed.upper_boundary = [](double x, double) { return 0.6 + 0.3 * x; };
  cases.push_back({"relaxed boundary band", relaxed, VM::Plane_distribution_3::isotropic, 50});
  for(const Case& c : cases) {
    INFO(c.name);
    VM::Surface_plane_options_3 o;
    o.distribution = c.distribution;
    o.pencil_fraction = 0.2;
    o.seed = 5;
    const VM::Plane_arrangement_3 A(VM::surface_planes_3(c.problem, c.planes, o));
    const std::vector<double> w = VM::surface_facet_weights_3(A, c.problem, VM::Area_functional_3());
    // Oracle: the generic path (Flow_network, solve_min_cut) with push-relabel and Boykov-Kolmogorov.
    const VM::Minimal_surface_3 pr = generic(A, w, c.problem, CGAL::Min_cut::Push_relabel_max_flow());
    const VM::Minimal_surface_3 bk = generic(A, w, c.problem, CGAL::Min_cut::Boykov_kolmogorov_max_flow());
    REQUIRE(pr.is_feasible);
    REQUIRE(bk.is_feasible);
    // Pseudoflow on the arrangement, with the weight vector and with the weights computed on the fly.
    const VM::Minimal_surface_3 pf = VM::minimize_surface_functional_3(A, w, c.problem);
    const VM::Minimal_surface_3 lean = VM::minimize_surface_functional_3(A, c.problem, VM::Area_functional_3());
    REQUIRE(pf.is_feasible);
    REQUIRE(lean.is_feasible);
    CHECK(relative_difference(pf.solver_value, pr.solver_value) <= 1e-9);
    CHECK(relative_difference(pf.solver_value, bk.solver_value) <= 1e-9);
    CHECK(pf.facets == pr.facets); // the same minimal source side
    CHECK(lean.facets == pf.facets);
    CHECK(lean.solver_value == pf.solver_value);
    CHECK(lean.energy == pf.energy);
    CHECK(relative_difference(lean.energy, lean.solver_value) <= 1e-12);
    // Another engine through the functional overload takes the generic path.
    const VM::Minimal_surface_3 lean_pr =
      VM::minimize_surface_functional_3(A, c.problem, VM::Area_functional_3(), 1, CGAL::Min_cut::Push_relabel_max_flow());
    CHECK(lean_pr.facets == pr.facets);
  }
}

TEST_CASE("minimize_surface_functional_3: pseudoflow on the arrangement of a polygonal domain agrees with the "
          "Flow_network path",
          "[variational][surface][min_cut][polygon]")
{
  typedef MDCS_test::Polygon Polygon;
  struct Case
  {
    const char* name;
    Polygon polygon;
    bool relaxed;
    std::size_t planes;
  };
  // Non-convex (L, U), convex (hexagon, triangle), touching the box (L, U) and not (hexagon, triangle), fixed and
  // relaxed boundaries.
  const std::vector<Case> cases = {
    {"L, fixed", {{{0, 0}}, {{1, 0}}, {{1, 0.5}}, {{0.5, 0.5}}, {{0.5, 1}}, {{0, 1}}}, false, 70},
    {"U, fixed", {{{0, 0}}, {{1, 0}}, {{1, 1}}, {{0.7, 1}}, {{0.7, 0.35}}, {{0.3, 0.35}}, {{0.3, 1}}, {{0, 1}}}, false, 70},
    {"hexagon, relaxed", {{{0.2, 0.1}}, {{0.8, 0.1}}, {{0.95, 0.5}}, {{0.8, 0.9}}, {{0.2, 0.9}}, {{0.05, 0.5}}}, true, 60},
    {"triangle, fixed", {{{0.1, 0.1}}, {{0.9, 0.2}}, {{0.4, 0.9}}}, false, 60}};
  for(const Case& c : cases) {
    INFO(c.name);
    VM::Surface_problem_3 P;
    P.boundary_segments_per_side = 3;
    P.lower_boundary = [](double x, double y) { return 0.5 + 0.8 * (x - 0.5) * (y - 0.5); };
    if(c.relaxed) {
      P.lower_boundary = [](double x, double y) { return 0.25 + 0.3 * x * y; };
      P.upper_boundary = [](double x, double y) { return 0.55 + 0.3 * x * y; };
    }
    P.set_domain_polygon(c.polygon);
    VM::Surface_plane_options_3 o;
    o.seed = 7;
    o.pencil_fraction = 0.3;
    const VM::Plane_arrangement_3 A(VM::surface_planes_3(P, c.planes, o));
    // G is NaN outside the polygon as rounded to the lattice: it must not be evaluated there by either path.
    Polygon rounded;
    for(const auto& q : P.lattice_polygon()) {
      const std::array<double, 3> p = P.to_world({{double(q[0]), double(q[1]), 0.0}});
      rounded.push_back({{p[0], p[1]}});
    }
    const auto G = [&](double, double fx, double fy, double x, double y) {
      return MDCS_test::in_polygon(rounded, x, y) ? std::sqrt(1 + fx * fx + fy * fy) : std::nan("");
    };
    const std::vector<double> w = VM::surface_facet_weights_3(A, P, G);
    // Oracle: the generic path (build_polygon_dual_network_3, solve_min_cut) with push-relabel and Boykov-Kolmogorov.
    const VM::Minimal_surface_3 pr = generic(A, w, P, CGAL::Min_cut::Push_relabel_max_flow());
    const VM::Minimal_surface_3 bk = generic(A, w, P, CGAL::Min_cut::Boykov_kolmogorov_max_flow());
    REQUIRE(pr.is_feasible);
    REQUIRE(bk.is_feasible);
    const VM::Minimal_surface_3 pf = VM::minimize_surface_functional_3(A, w, P);
    const VM::Minimal_surface_3 lean = VM::minimize_surface_functional_3(A, P, G);
    REQUIRE(pf.is_feasible);
    REQUIRE(lean.is_feasible);
    CHECK(relative_difference(pf.solver_value, pr.solver_value) <= 1e-9);
    CHECK(relative_difference(pf.solver_value, bk.solver_value) <= 1e-9);
    // (The facet sets may differ from push-relabel's by facets of weight ~1e-10: polygon pencils make slivers,
    // and ties within rounding go either way.)
    CHECK(lean.facets == pf.facets);
    CHECK(lean.energy == pf.energy);
    CHECK(relative_difference(lean.energy, lean.solver_value) <= 1e-12);
    CHECK(relative_difference(lean.projected_area, P.domain_area()) <= 1e-9);
    // With fixed saddle data the surface is not flat: the cut really crosses interior facets over the polygon.
    if(!c.relaxed) CHECK(lean.energy > P.domain_area() * (1 + 1e-6));
  }
}

TEST_CASE("minimize_surface_functional_3: pseudoflow on the arrangement reports progress and rejects bad weights",
          "[variational][surface][min_cut]")
{
  const VM::Surface_problem_3 P = VM::scherk_surface_problem_3(2);
  const VM::Plane_arrangement_3 A(VM::surface_planes_3(P, 30));
  std::vector<std::string> stages;
  auto progress = [&](const char* stage, double) {
    if(stages.empty() || stages.back() != stage) stages.push_back(stage);
    return true;
  };
  const VM::Minimal_surface_3 s = VM::minimize_surface_functional_3(A, P, VM::Area_functional_3(), 1,
                                                                    CGAL::Min_cut::Pseudoflow_max_flow(), progress);
  CHECK(s.is_feasible);
  CHECK(stages == std::vector<std::string>{"weights", "max-flow"});
  auto cancel = [](const char* stage, double) { return std::string(stage) != "max-flow"; };
  CHECK_THROWS_AS(VM::minimize_surface_functional_3(A, P, VM::Area_functional_3(), 1,
                                                    CGAL::Min_cut::Pseudoflow_max_flow(), cancel),
                  CGAL::MDCS::Operation_cancelled);

  std::vector<double> w = VM::surface_facet_weights_3(A, P, VM::Area_functional_3());
  std::size_t interior = 0;
  while(A.facet(VM::Plane_arrangement_3::Facet_index(interior)).plane < 6 ||
        !std::isfinite(w[interior]))
    ++interior;
  std::vector<double> bad = w;
  bad[interior] = -1;
  CHECK_THROWS_AS(VM::minimize_surface_functional_3(A, bad, P), std::invalid_argument);
  bad[interior] = std::nan("");
  CHECK_THROWS_AS(VM::minimize_surface_functional_3(A, bad, P), std::invalid_argument);
  bad.pop_back();
  CHECK_THROWS_AS(VM::minimize_surface_functional_3(A, bad, P), std::invalid_argument);
  CHECK_THROWS_AS(VM::minimize_surface_functional_3(A, P, VM::Area_functional_3(), 9), std::invalid_argument);
}

TEST_CASE("Plane_arrangement_3: the edge planes recovered from the vertices contain the edges",
          "[variational][surface][arrangement]")
{
  // Pencils make many vertices lie on more than three planes (the degenerate case of common_plane()).
  VM::Surface_problem_3 P;
  P.boundary_segments_per_side = 2;
  P.lower_boundary = [](double x, double y) { return 0.3 + 0.4 * x * y; };
  VM::Surface_plane_options_3 o;
  o.pencil_fraction = 0.5;
  const VM::Plane_arrangement_3 A(VM::surface_planes_3(P, 40, o));
  std::size_t bad = 0, edges = 0;
  for(std::size_t i = 0; i < A.number_of_facets(); ++i) {
    const auto f = VM::Plane_arrangement_3::Facet_index(i);
    const std::size_t n = A.facet_degree(f);
    for(std::size_t k = 0; k < n; ++k) {
      const auto e = A.facet_edge_plane(f, k);
      ++edges;
      if(e == A.facet(f).plane || A.side(A.facet_vertex(f, k), e) != 0 || A.side(A.facet_vertex(f, (k + 1) % n), e) != 0)
        ++bad;
    }
  }
  CHECK(edges > 1000);
  CHECK(bad == 0);
}

TEST_CASE("Growable_array_3: matches std::vector through growth, copies, moves and shrinking",
          "[variational][surface][arrangement]")
{
  VM::internal::Growable_array_3<std::array<std::uint32_t, 3>> a;
  std::vector<std::array<std::uint32_t, 3>> r;
  std::mt19937 rng(3);
  for(int step = 0; step < 200000; ++step) { // 2.4 MB: past the 1 MiB at which blocks are mapped directly
    const std::uint32_t v = rng();
    if(step % 10000 == 9999) {
      a.shrink_to_fit();
      CHECK(a.capacity() >= a.size());
      CHECK(a.capacity() * sizeof(a[0]) < a.size() * sizeof(a[0]) + 4096); // mapped blocks: whole pages
    }
    if(!a.empty() && v % 7 == 0) a.push_back(a[v % a.size()]), r.push_back(r[v % r.size()]); // self-reference
    else a.push_back({{v, v + 1, v + 2}}), r.push_back({{v, v + 1, v + 2}});
  }
  REQUIRE(a.size() == r.size());
  CHECK(std::equal(r.begin(), r.end(), a.begin()));
  VM::internal::Growable_array_3<std::array<std::uint32_t, 3>> b(a), c;
  c = b;
  CHECK(std::equal(r.begin(), r.end(), c.begin()));
  VM::internal::Growable_array_3<std::array<std::uint32_t, 3>> d(std::move(b));
  CHECK(b.empty());
  CHECK(d.size() == r.size());
  d.resize(5);
  CHECK(d.size() == 5);
  CHECK(d[4] == r[4]);
  d.assign(3, {{1, 2, 3}});
  CHECK(d.size() == 3);
  CHECK(d[2] == (std::array<std::uint32_t, 3>{{1, 2, 3}}));
  d.release();
  CHECK(d.capacity() == 0);
  // Arrangements are copyable values.
  const VM::Plane_arrangement_3 A(VM::surface_planes_3(VM::scherk_surface_problem_3(2), 20));
  const VM::Plane_arrangement_3 B = A;
  CHECK(B.number_of_facets() == A.number_of_facets());
  CHECK(B.point(B.number_of_vertices() - 1) == A.point(A.number_of_vertices() - 1));
}

TEST_CASE("select_planes_3: planes near the optimum keep the energy non-increasing and are reproducible",
          "[variational][surface]")
{
  const VM::Surface_problem_3 P = MDCS_test::blob_problem();
  const VM::Density_weighted_area_functional_3 G = VM::random_blob_functional_3(P, 4, 2, 0.1, -1.5, 3);
  VM::Surface_plane_options_3 o;
  o.distribution = VM::Plane_distribution_3::slope_limited;
  o.selection_near_fraction = 0.5;
  o.seed = 4;
  const VM::Plane_selection_result_3 a = VM::select_planes_3(P, G, 40, 4, o);
  const VM::Plane_selection_result_3 b = VM::select_planes_3(P, G, 40, 4, o);
  REQUIRE(a.energies.size() == 4);
  REQUIRE(a.surfaces.size() == 4);
  double best = a.energies[0];
  for(std::size_t i = 0; i < a.energies.size(); ++i) {
    CHECK(a.surfaces[i].energy == a.energies[i]);
    best = std::min(best, a.energies[i]);
  }
  CHECK(a.surface.energy == best);
  CHECK(a.energies == b.energies); // same seed, same run
  // Every iteration keeps the best surface representable: no iteration's optimum is worse than the best so far,
  // up to the quadrature error of the weights (the kept surface's facets are cut into smaller facets whose
  // Gauss-rule weights do not sum exactly to the old ones: measured 7e-8 relative here).
  double so_far = a.energies[0];
  for(double e : a.energies) {
    CHECK(e <= so_far * (1 + 1e-5));
    so_far = std::min(so_far, e);
  }
  VM::Surface_plane_options_3 bad = o;
  bad.selection_near_fraction = 1.5;
  CHECK_THROWS_AS(VM::select_planes_3(P, G, 40, 2, bad), std::invalid_argument);
}
