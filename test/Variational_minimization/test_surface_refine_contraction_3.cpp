// Adaptive refinement contracts the cells outside the envelope into the terminals: the contracted network has the
// same minimum cut value as the network with those cells tied to the terminals by infinite arcs (random networks,
// against solve_min_cut on the tied network), and refine_surface_3 solves a network with fewer nodes.
#include <catch2/catch.hpp>

#include <CGAL/Min_cut/solve_min_cut.h>
#include <CGAL/Variational_minimization/analytic_solutions_3.h>
#include <CGAL/Min_cut/internal/contract_terminal_nodes.h>
#include <CGAL/Variational_minimization/refine_surface_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>

#include <cmath>
#include <random>
#include <vector>

namespace VM = CGAL::Variational_minimization;
typedef CGAL::Min_cut::Flow_network<double> Network;

TEST_CASE("contract_terminal_nodes: same minimum cut as infinite ties", "[variational][surface][refinement]")
{
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0, 1);
  const double inf = Network::infinity();
  int finite = 0, infinite = 0;
  for(int trial = 0; trial < 300; ++trial) {
    const std::uint32_t n = 2 + std::uint32_t(rng() % 14);
    Network full;
    full.add_nodes(n);
    std::uint32_t id = 0;
    auto cap = [&] { const double r = U(rng); return r < 0.15 ? inf : (r < 0.25 ? 0.0 : U(rng)); };
    const int arcs = int(rng() % (3 * n + 1));
    for(int a = 0; a < arcs; ++a) {
      const std::uint32_t u = std::uint32_t(rng() % n), v = std::uint32_t(rng() % n);
      if(u == v) continue;
      full.add_facet(u, v, cap(), cap(), id++);
    }
    for(std::uint32_t k = 0; k < n; ++k) {
      if(U(rng) < 0.3) full.add_source_facet(k, U(rng) < 0.1 ? inf : U(rng), id++);
      if(U(rng) < 0.3) full.add_sink_facet(k, U(rng) < 0.1 ? inf : U(rng), id++);
    }
    std::vector<char> label(n);
    for(char& l : label) { const double r = U(rng); l = r < 0.6 ? 0 : (r < 0.8 ? 1 : 2); }
    Network tied = full;
    for(std::uint32_t k = 0; k < n; ++k) {
      if(label[k] == 1) tied.add_source_facet(k, inf, id++);
      if(label[k] == 2) tied.add_sink_facet(k, inf, id++);
    }
    const auto expected = CGAL::Min_cut::solve_min_cut(tied);
    const CGAL::Min_cut::internal::Contracted_network<double> c = CGAL::Min_cut::internal::contract_terminal_nodes(full, label);
    std::size_t kept = 0;
    for(char l : label) kept += l == 0 ? 1 : 0;
    CHECK(c.network.number_of_nodes() == kept);
    bool is_finite = c.is_finite;
    double value = c.constant;
    if(is_finite && kept > 0) {
      const auto cut = CGAL::Min_cut::solve_min_cut(c.network);
      is_finite = cut.is_finite;
      value += cut.value;
    }
    INFO("trial " << trial << ", " << n << " nodes, " << kept << " kept");
    REQUIRE(is_finite == expected.is_finite);
    if(is_finite) {
      ++finite;
      CHECK(std::abs(value - expected.value) <= 1e-9 * (1 + expected.value));
    } else
      ++infinite;
  }
  CHECK(finite > 50);
  CHECK(infinite > 20);
}

TEST_CASE("refine_surface_3: the contracted network is smaller", "[variational][surface][refinement]")
{
  const VM::Surface_problem_3 P = VM::scherk_surface_problem_3(4);
  VM::Surface_plane_options_3 o;
  o.distribution = VM::Plane_distribution_3::slope_limited;
  o.max_slope = 3;
  o.pencil_fraction = 0.2;
  const VM::Surface_refinement_result_3 R = VM::refine_surface_3(P, VM::Area_functional_3(), 70, 3, o, 0.0);
  REQUIRE(R.surface.is_feasible);
  CHECK(R.network_nodes + R.cells_below + R.cells_above == R.cells);
  CHECK(R.network_nodes < R.cells);
  CHECK(R.network_nodes > 0);
  CHECK(std::abs(R.surface.energy - R.surface.solver_value) <= 1e-9 * R.surface.energy);
}

TEST_CASE("Terminal_contraction: the contracted network built from the arrangement equals the contraction of the "
          "full network, with fewer weights computed",
          "[variational][surface][refinement]")
{
  typedef VM::Plane_arrangement_3 Arr;
  // A rectangle (Scherk) and an L-shaped polygon with a relaxed band; cells labelled by height bands.
  std::vector<VM::Surface_problem_3> problems;
  problems.push_back(VM::scherk_surface_problem_3(3));
  VM::Surface_problem_3 L;
  L.boundary_segments_per_side = 3;
  L.lower_boundary = [](double x, double y) { return 0.3 + 0.3 * x * y; };
  L.upper_boundary = [](double x, double y) { return 0.5 + 0.3 * x * y; };
  L.set_domain_polygon({{{0, 0}}, {{1, 0}}, {{1, 0.5}}, {{0.5, 0.5}}, {{0.5, 1}}, {{0, 1}}});
  problems.push_back(L);
  int finite_cuts = 0;
  for(const VM::Surface_problem_3& P : problems) {
    INFO((P.is_polygonal() ? "L" : "Scherk"));
    VM::Surface_plane_options_3 o;
    o.seed = 4;
    const Arr A(VM::surface_planes_3(P, 50, o));
    const std::vector<double> w = VM::surface_facet_weights_3(A, P, VM::Area_functional_3());
    // Label by the height of a cell's vertex mean: low cells to the source, high ones to the sink.
    std::vector<char> label(A.number_of_cells(), 0);
    for(std::size_t c = 0; c < A.number_of_cells(); ++c) {
      double z = 0;
      std::size_t k = 0;
      for(Arr::Facet_index f : A.cell_facets(Arr::Cell_index(c)))
        for(std::size_t i = 0; i < A.facet_degree(f); ++i, ++k) z += A.point(A.facet_vertex(f, i))[2];
      const double t = z / double(k) / double(Arr::lattice_size);
      label[c] = t < 0.3 ? 1 : (t > 0.7 ? 2 : 0);
    }
    const CGAL::Min_cut::internal::Contracted_network<double> expected =
      CGAL::Min_cut::internal::contract_terminal_nodes(VM::internal::surface_dual_network_3(A, w, P), label);
    std::size_t evaluations = 0;
    CGAL::Min_cut::internal::Terminal_contraction<double> builder(label);
    VM::internal::build_surface_dual_network_3(A, [&](Arr::Facet_index f) { ++evaluations; return w[f]; }, P, builder);
    const CGAL::Min_cut::internal::Contracted_network<double> direct = builder.release();
    REQUIRE(direct.is_finite == expected.is_finite);
    CHECK(direct.network.number_of_nodes() == expected.network.number_of_nodes());
    CHECK(direct.constant == expected.constant);
    CHECK(direct.constant_facets == expected.constant_facets);
    REQUIRE(direct.network.number_of_facets() == expected.network.number_of_facets());
    bool same = true;
    for(std::size_t i = 0; i < direct.network.number_of_facets(); ++i) {
      const auto& a = direct.network.facets()[i];
      const auto& b = expected.network.facets()[i];
      same = same && a.u == b.u && a.v == b.v && a.c_uv == b.c_uv && a.c_vu == b.c_vu && a.id == b.id;
    }
    CHECK(same);
    CHECK(direct.network.number_of_source_facets() == expected.network.number_of_source_facets());
    CHECK(direct.network.number_of_sink_facets() == expected.network.number_of_sink_facets());
    // The full network asks for every non-vertical facet's weight; the direct build only for those that matter.
    std::size_t full_evaluations = 0;
    {
      CGAL::Min_cut::Flow_network<double> network;
      network.add_nodes(A.number_of_cells());
      VM::internal::Full_network_builder all{network};
      VM::internal::build_surface_dual_network_3(A, [&](Arr::Facet_index f) { ++full_evaluations; return w[f]; }, P,
                                                 all);
    }
    INFO(evaluations << " of " << full_evaluations << " weights");
    CHECK(evaluations > 0);
    CHECK(evaluations < full_evaluations);
    // The cut of the contracted network plus its constant is the cut with the labelled cells tied: the optimum of
    // refine-like constraints, never below the unconstrained optimum.
    const auto cut = CGAL::Min_cut::solve_min_cut(direct.network);
    const VM::Minimal_surface_3 free = VM::minimize_surface_functional_3(A, w, P);
    REQUIRE(free.is_feasible);
    if(direct.is_finite && cut.is_finite) {
      ++finite_cuts;
      CHECK(cut.value + direct.constant >= free.solver_value * (1 - 1e-12));
    }
  }
  CHECK(finite_cuts >= 1);
}
