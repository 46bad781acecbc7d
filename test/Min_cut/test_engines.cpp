// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The MaxFlowEngine models: Boykov-Kolmogorov and push-relabel agree (value and sides) on grids;
// Boost's Boykov-Kolmogorov black set is the residual-reachable set; a user engine written
// without Boost plugs into solve_min_cut; an engine that breaks its contract is reported.

#include <CGAL/Min_cut.h>

#include <MDCS_test/min_cut_networks.h>

#include <boost/graph/boykov_kolmogorov_max_flow.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

namespace {


namespace MC = CGAL::Min_cut;
typedef MC::Flow_network<double> Network;
using MDCS_test::inf;
using MDCS_test::grid_network;

void compare_engines(const Network& network, bool same_sides)
{
  const auto pr = MC::solve_min_cut(network, MC::Push_relabel_max_flow());
  const auto bk = MC::solve_min_cut(network, MC::Boykov_kolmogorov_max_flow());
  REQUIRE(pr.is_finite);
  REQUIRE(bk.is_finite);
  CHECK(std::abs(pr.value - bk.value) <= 1e-12 * bk.value);
  if(same_sides) {
    CHECK(pr.on_source_side == bk.on_source_side);
    CHECK(pr.chain.size() == bk.chain.size());
  }
}

// A MaxFlowEngine written without Boost: enumerates all partitions (small problems only) and returns
// the minimal optimal source side. Stateful, to check that engines need not be const.
struct Enumeration_engine
{
  int* calls;

  template <class Capacity>
  Capacity operator()(const MC::Max_flow_problem<Capacity>& problem, std::vector<char>& on_source_side)
  {
    ++*calls;
    const std::size_t n = problem.number_of_nodes();
    Capacity best = 0;
    std::uint32_t best_mask = 0;
    bool first = true;
    for(std::uint32_t mask = 0; mask < (1u << n); ++mask) {
      auto S = [mask](std::uint32_t i) { return ((mask >> i) & 1u) != 0; };
      Capacity c = 0;
      for(std::uint32_t i = 0; i < n; ++i) c += S(i) ? problem.sink_capacity(i) : problem.source_capacity(i);
      for(std::size_t k = 0; k < problem.number_of_arc_pairs(); ++k) {
        const auto p = problem.arc_pair(k);
        if(S(p.u) && !S(p.v)) c += p.c_uv;
        if(!S(p.u) && S(p.v)) c += p.c_vu;
      }
      if(first || c < best) {
        best = c;
        best_mask = mask;
        first = false;
      } else if(c == best) {
        best_mask &= mask;
      }
    }
    on_source_side.assign(n, 0);
    for(std::uint32_t i = 0; i < n; ++i) on_source_side[i] = char((best_mask >> i) & 1u);
    return best;
  }
};

struct Wrong_size_engine
{
  template <class Capacity>
  Capacity operator()(const MC::Max_flow_problem<Capacity>&, std::vector<char>& on_source_side) const
  {
    on_source_side.assign(1, 0);
    return 0;
  }
};

} // namespace

TEST_CASE("engines: Boykov-Kolmogorov and push-relabel give the same cut on grids", "[Min_cut]")
{
  for(unsigned seed = 1; seed <= 4; ++seed) {
    // Integer capacities: exact arithmetic, so the minimal source sides must coincide.
    compare_engines(grid_network(60, 60, false, true, seed), true);
    compare_engines(grid_network(60, 60, true, true, seed), true);
    // Real capacities: same value to rounding; the sides agree too unless rounding breaks a tie.
    compare_engines(grid_network(60, 60, false, false, seed), false);
    compare_engines(grid_network(60, 60, true, false, seed), false);
  }
}

TEST_CASE("engines: Boost's Boykov-Kolmogorov black set is the residual-reachable set", "[Min_cut]")
{
  // Runs BK exactly as Boykov_kolmogorov_max_flow does, then compares its colours with a search
  // over residual arcs from the source: the claim that lets that engine read the sides from colours.
  typedef MC::internal::Csr_flow_graph<double> Flow_graph;
  for(unsigned seed = 1; seed <= 8; ++seed) {
    const Network network = grid_network(40, 40, seed % 2 == 0, seed % 4 < 2, seed);
    const MC::Max_flow_problem<double> problem(network);
    Flow_graph flow_graph(problem);
    const std::size_t nv = num_vertices(flow_graph.graph());
    std::vector<Flow_graph::edge_descriptor> predecessor(nv);
    std::vector<boost::default_color_type> colour(nv);
    std::vector<std::uint32_t> distance(nv);
    const auto index = flow_graph.vertex_index_map();
    boost::boykov_kolmogorov_max_flow(flow_graph.graph(), flow_graph.capacity_map(),
                                      flow_graph.residual_capacity_map(), flow_graph.reverse_arc_map(),
                                      boost::make_iterator_property_map(predecessor.begin(), index),
                                      boost::make_iterator_property_map(colour.begin(), index),
                                      boost::make_iterator_property_map(distance.begin(), index), index,
                                      flow_graph.source(), flow_graph.sink());
    std::vector<char> reachable;
    flow_graph.source_side_by_residual_search(reachable);
    std::vector<char> black(problem.number_of_nodes());
    for(std::size_t i = 0; i < black.size(); ++i) black[i] = colour[i] == boost::black_color;
    CHECK(black == reachable);
  }
}

TEST_CASE("engines: a user engine without Boost plugs into solve_min_cut", "[Min_cut]")
{
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> capacity(0, 4);
  int calls = 0;
  for(int trial = 0; trial < 30; ++trial) {
    Network network;
    network.add_nodes(8);
    for(std::uint32_t k = 0; k < 14; ++k) {
      const auto u = Network::Node_index(rng() % 8), v = Network::Node_index(rng() % 8);
      if(u != v) network.add_facet(u, v, capacity(rng), trial % 3 == 0 && k % 5 == 0 ? inf : capacity(rng), k);
    }
    network.add_source_facet(0, inf, 100);
    network.add_source_facet(1, capacity(rng), 101);
    network.add_sink_facet(7, inf, 102);
    network.add_sink_facet(6, capacity(rng), 103);

    const auto user = MC::solve_min_cut(network, Enumeration_engine{&calls});
    const auto boost_result = MC::solve_min_cut(network);
    CHECK(user.is_finite == boost_result.is_finite);
    CHECK(user.value == boost_result.value);
    CHECK(user.on_source_side == boost_result.on_source_side);
  }
  CHECK(calls == 30);
}

TEST_CASE("engines: an engine returning the wrong number of sides is reported", "[Min_cut]")
{
  Network network;
  network.add_nodes(3);
  network.add_source_facet(0, 1, 0);
  try {
    MC::solve_min_cut(network, Wrong_size_engine());
    FAIL("no exception");
  } catch(const std::invalid_argument& e) {
    CHECK(std::string(e.what()).rfind("MDCS: ", 0) == 0);
  }
}

TEST_CASE("engines: Boykov-Kolmogorov and push-relabel agree on a 500 x 500 grid", "[Min_cut][.long]")
{
  compare_engines(grid_network(500, 500, false, true, 99), true);
  compare_engines(grid_network(500, 500, true, true, 99), true);
}
