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
