// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// solve_planar_min_cut (the cut as a shortest path in the planar dual) against brute force on small grids and
// against pseudoflow on larger ones; the returned sides, chain and value must describe one valid cut; a dual
// that does not embed the network is rejected.

#include <CGAL/Min_cut.h>

#include <MDCS_test/min_cut_networks.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace {

namespace MC = CGAL::Min_cut;
typedef MC::Flow_network<double> Network;
using MDCS_test::as_mask;
using MDCS_test::grid_dual;
using MDCS_test::cut_capacity;


// The chain, sides and value of `r` describe one cut of `network`.
void check_consistent(const Network& network, const MC::Min_cut_result<double>& r)
{
  REQUIRE(r.on_source_side.size() == network.number_of_nodes());
  double chain_value = 0;
  std::size_t expected_chain = 0;
  for(const auto& f : network.facets())
    if(r.on_source_side[f.u] != r.on_source_side[f.v]) {
      ++expected_chain;
      chain_value += r.on_source_side[f.u] ? f.c_uv : f.c_vu;
    }
  for(const auto& f : network.source_facets())
    if(!r.on_source_side[f.node]) { ++expected_chain; chain_value += f.capacity; }
  for(const auto& f : network.sink_facets())
    if(r.on_source_side[f.node]) { ++expected_chain; chain_value += f.capacity; }
  CHECK(r.chain.size() == expected_chain);
  CHECK(std::abs(chain_value - r.value) <= 1e-12 * (1 + r.value));
}

// The same grid with every cut direction that walks its dual edge upwards or leftwards made infinite: the dual
// arcs then point only right and down, a DAG, which solve_planar_min_cut solves in topological order.
Network acyclic_dual_grid(const Network& grid, std::size_t width)
{
  Network network;
  network.add_nodes(grid.number_of_nodes());
  for(const auto& f : grid.facets()) {
    const bool horizontal_neighbours = (f.v == f.u + 1 && f.u / width == f.v / width);
    network.add_facet(f.u, f.v, f.c_uv, horizontal_neighbours ? Network::infinity() : f.c_vu, f.id);
  }
  for(const auto& f : grid.source_facets()) network.add_source_facet(f.node, f.capacity, f.id);
  for(const auto& f : grid.sink_facets()) network.add_sink_facet(f.node, f.capacity, f.id);
  return network;
}

} // namespace

TEST_CASE("solve_planar_min_cut: acyclic duals (topological order) against brute force and pseudoflow",
          "[min_cut][planar]")
{
  for(unsigned seed = 1; seed <= 30; ++seed)
    for(bool function : {false, true}) {
      const std::size_t width = 2 + seed % 3, height = 12 / width;
      const Network network = acyclic_dual_grid(MDCS_test::grid_network(width, height, function, true, seed), width);
      const auto r = MC::solve_planar_min_cut(network, grid_dual(network, width, height));
      double best = Network::infinity();
      for(std::uint32_t mask = 0; mask < (1u << network.number_of_nodes()); ++mask)
        best = std::min(best, cut_capacity(network, mask));
      INFO("seed " << seed << ", function " << function);
      REQUIRE(r.is_finite == (best != Network::infinity()));
      if(r.is_finite) {
        CHECK(r.value == best);
        check_consistent(network, r);
      }
    }
  const Network large = acyclic_dual_grid(MDCS_test::grid_network(60, 40, true, false, 5), 60);
  const auto planar = MC::solve_planar_min_cut(large, grid_dual(large, 60, 40));
  const auto general = MC::solve_min_cut(large, MC::Pseudoflow_max_flow());
  REQUIRE(planar.is_finite);
  CHECK(std::abs(planar.value - general.value) <= 1e-12 * general.value);
  check_consistent(large, planar);
}

TEST_CASE("solve_planar_min_cut: brute force on small grids", "[min_cut][planar]")
{
  for(unsigned seed = 1; seed <= 40; ++seed)
    for(bool function : {false, true}) {
      const std::size_t width = 2 + seed % 3, height = 12 / width;
      const Network network = MDCS_test::grid_network(width, height, function, true, seed);
      const MC::Planar_dual dual = grid_dual(network, width, height);
      const auto r = MC::solve_planar_min_cut(network, dual);
      double best = Network::infinity();
      for(std::uint32_t mask = 0; mask < (1u << network.number_of_nodes()); ++mask)
        best = std::min(best, cut_capacity(network, mask));
      INFO("seed " << seed << ", function " << function << ", " << width << " x " << height);
      REQUIRE(r.is_finite);
      CHECK(r.value == best);
      CHECK(cut_capacity(network, as_mask(r.on_source_side)) == best);
      check_consistent(network, r);
    }
}

TEST_CASE("solve_planar_min_cut: equals pseudoflow on larger grids", "[min_cut][planar]")
{
  for(unsigned seed = 1; seed <= 6; ++seed)
    for(bool function : {false, true}) {
      const std::size_t width = 20 + 7 * seed, height = 15 + 3 * seed;
      const Network network = MDCS_test::grid_network(width, height, function, seed % 2 == 0, seed);
      const auto planar = MC::solve_planar_min_cut(network, grid_dual(network, width, height));
      const auto general = MC::solve_min_cut(network, MC::Pseudoflow_max_flow());
      INFO("seed " << seed << ", function " << function);
      REQUIRE(planar.is_finite);
      REQUIRE(general.is_finite);
      CHECK(std::abs(planar.value - general.value) <= 1e-12 * general.value);
      check_consistent(network, planar);
    }
}

TEST_CASE("solve_planar_min_cut: infeasible networks and progress", "[min_cut][planar]")
{
  // Every facet infinite: no finite cut exists; the result says so like solve_min_cut().
  Network network;
  network.add_nodes(4);
  const double inf = Network::infinity();
  network.add_facet(0, 1, inf, inf, 0);
  network.add_facet(2, 3, inf, inf, 1);
  network.add_facet(0, 2, inf, inf, 2);
  network.add_facet(1, 3, inf, inf, 3);
  network.add_source_facet(0, inf, 4);
  network.add_source_facet(1, inf, 5);
  network.add_sink_facet(2, inf, 6);
  network.add_sink_facet(3, inf, 7);
  const MC::Planar_dual dual = grid_dual(network, 2, 2);
  const auto r = MC::solve_planar_min_cut(network, dual);
  CHECK_FALSE(r.is_finite);
  CHECK(std::isinf(r.value));

  const Network grid = MDCS_test::grid_network(30, 20, true, false, 3);
  int calls = 0;
  const auto counted = MC::solve_planar_min_cut(grid, grid_dual(grid, 30, 20), [&](const char*, double) {
    ++calls;
    return true;
  });
  CHECK(counted.is_finite);
  CHECK(calls >= 6);
  CHECK_THROWS_AS(MC::solve_planar_min_cut(grid, grid_dual(grid, 30, 20), [](const char*, double) { return false; }),
                  CGAL::MDCS::Operation_cancelled);
}

TEST_CASE("solve_planar_min_cut: a dual that does not embed the network is rejected", "[min_cut][planar][errors]")
{
  const Network network = MDCS_test::grid_network(6, 5, false, true, 11);
  const MC::Planar_dual good = grid_dual(network, 6, 5);

  MC::Planar_dual missing = good;
  missing.edges.pop_back();
  CHECK_THROWS_AS(MC::solve_planar_min_cut(network, missing), std::invalid_argument);

  MC::Planar_dual out_of_range = good;
  out_of_range.sink_edges[0].b = MC::Planar_dual::Vertex_index(good.number_of_vertices);
  CHECK_THROWS_AS(MC::solve_planar_min_cut(network, out_of_range), std::invalid_argument);

  MC::Planar_dual no_start = good;
  no_start.start_vertices.clear();
  CHECK_THROWS_AS(MC::solve_planar_min_cut(network, no_start), std::invalid_argument);

  // Start and end swapped: the shortest path walks with the source on its left, which is no cut of this
  // network; the check finds it instead of returning a wrong answer.
  MC::Planar_dual swapped = good;
  std::swap(swapped.start_vertices, swapped.end_vertices);
  CHECK_THROWS_AS(MC::solve_planar_min_cut(network, swapped), std::invalid_argument);
}
