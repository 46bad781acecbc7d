// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// solve_min_cut on random small networks (<= 12 nodes, asymmetric capacities, some zero, some
// infinite) against the enumeration of all 2^n partitions of the nodes.

#include <CGAL/Min_cut.h>

#include <MDCS_test/min_cut_networks.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <vector>

namespace {

namespace MC = CGAL::Min_cut;
typedef MC::Flow_network<double> Network;
using MDCS_test::inf;
using MDCS_test::as_mask;
using MDCS_test::cut_capacity;

struct Brute_force
{
  double minimum;
  std::uint32_t minimal_source_side; // intersection of all optimal source sides
};

// With exact (integer) capacities, optimal source sides are closed under intersection, so their
// intersection is the unique minimal one.
Brute_force enumerate(const Network& network)
{
  const std::uint32_t n = std::uint32_t(network.number_of_nodes());
  Brute_force b{inf, 0};
  std::uint32_t intersection = (1u << n) - 1;
  for(std::uint32_t mask = 0; mask < (1u << n); ++mask) {
    const double c = cut_capacity(network, mask);
    if(c < b.minimum) {
      b.minimum = c;
      intersection = mask;
    } else if(c == b.minimum) {
      intersection &= mask;
    }
  }
  b.minimal_source_side = intersection;
  return b;
}

// Random network: asymmetric capacities, about 15% zero and, if `with_infinite`, 25% of the
// interior and 40% of the terminal capacities infinite (so that some networks are infeasible).
Network random_network(std::mt19937& rng, bool integer_capacities, bool with_infinite)
{
  std::uniform_int_distribution<int> node_count(1, 12);
  const int n = node_count(rng);
  std::uniform_int_distribution<int> node(0, n - 1), percent(0, 99), small(1, 6);
  std::uniform_real_distribution<double> real(0.01, 5.0);
  auto capacity = [&](int infinite_percent) {
    const int p = percent(rng);
    if(p < 15) return 0.0;
    if(with_infinite && p < 15 + infinite_percent) return inf;
    return integer_capacities ? double(small(rng)) : real(rng);
  };
  Network network;
  network.add_nodes(std::size_t(n));
  std::uint32_t id = 0;
  const int facets = std::uniform_int_distribution<int>(0, 3 * n)(rng);
  for(int k = 0; k < facets; ++k) {
    const int u = node(rng), v = node(rng);
    if(u == v) continue;
    network.add_facet(Network::Node_index(u), Network::Node_index(v), capacity(25), capacity(25), id++);
  }
  const int terminals = std::uniform_int_distribution<int>(1, n + 1)(rng);
  for(int k = 0; k < terminals; ++k) {
    if(percent(rng) < 50) network.add_source_facet(Network::Node_index(node(rng)), capacity(40), id++);
    else network.add_sink_facet(Network::Node_index(node(rng)), capacity(40), id++);
  }
  return network;
}

// The capacity of each chain facet, looked up by id (ids are unique in random_network).
double chain_capacity(const Network& network, const MC::Min_cut_result<double>& result)
{
  std::map<std::uint32_t, std::pair<double, double>> interior;
  std::map<std::uint32_t, double> terminal;
  for(const auto& f : network.facets()) interior[f.id] = {f.c_uv, f.c_vu};
  for(const auto& f : network.source_facets()) terminal[f.id] = f.capacity;
  for(const auto& f : network.sink_facets()) terminal[f.id] = f.capacity;
  double sum = 0;
  for(const auto& c : result.chain) {
    const auto it = interior.find(c.id);
    sum += it != interior.end() ? (c.forward ? it->second.first : it->second.second) : terminal.at(c.id);
  }
  return sum;
}

template <class Engine>
void check_against_brute_force(const Network& network, bool exact, const char* engine_name)
{
  INFO("engine " << engine_name << ", " << network.number_of_nodes() << " nodes, " << network.number_of_facets()
                 << " facets");
  const auto result = MC::solve_min_cut(network, Engine());
  const Brute_force brute = enumerate(network);
  REQUIRE(result.on_source_side.size() == network.number_of_nodes());
  CHECK_FALSE(std::isnan(result.value));

  if(brute.minimum == inf) {
    CHECK_FALSE(result.is_finite);
    CHECK(result.value == inf);
    return;
  }
  REQUIRE(result.is_finite);
  CHECK(std::abs(result.value - brute.minimum) <= 1e-12 * (std::max)(1.0, brute.minimum));
  // The sides are an optimal partition, and the value is the capacity of the chain.
  const double sides_value = cut_capacity(network, as_mask(result.on_source_side));
  CHECK(sides_value == result.value);
  CHECK(chain_capacity(network, result) == result.value);
  // The chain is exactly the set of facets crossing the cut.
  std::size_t crossing = 0;
  const auto& side = result.on_source_side;
  for(const auto& f : network.facets()) crossing += side[f.u] != side[f.v];
  for(const auto& f : network.source_facets()) crossing += !side[f.node];
  for(const auto& f : network.sink_facets()) crossing += side[f.node] != 0;
  CHECK(result.chain.size() == crossing);
  if(exact) CHECK(as_mask(result.on_source_side) == brute.minimal_source_side);
}

} // namespace

TEST_CASE("solve_min_cut: random small networks with integer capacities vs enumeration", "[Min_cut]")
{
  std::mt19937 rng(20260101);
  int infeasible = 0;
  for(int trial = 0; trial < 400; ++trial) {
    const Network network = random_network(rng, true, trial % 2 == 0);
    infeasible += enumerate(network).minimum == inf;
    check_against_brute_force<MC::Push_relabel_max_flow>(network, true, "push-relabel");
    check_against_brute_force<MC::Boykov_kolmogorov_max_flow>(network, true, "Boykov-Kolmogorov");
  }
  // The sample must exercise both outcomes.
  CHECK(infeasible > 20);
  CHECK(infeasible < 180);
}

TEST_CASE("solve_min_cut: random small networks with real capacities vs enumeration", "[Min_cut]")
{
  std::mt19937 rng(777);
  for(int trial = 0; trial < 400; ++trial) {
    const Network network = random_network(rng, false, trial % 3 == 0);
    check_against_brute_force<MC::Push_relabel_max_flow>(network, false, "push-relabel");
    check_against_brute_force<MC::Boykov_kolmogorov_max_flow>(network, false, "Boykov-Kolmogorov");
  }
}
