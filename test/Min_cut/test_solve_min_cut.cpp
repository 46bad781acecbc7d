// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// solve_min_cut on hand-made networks with known cuts, infeasible constraints, isolated nodes,
// progress reporting, and the "function graph" grid checked against a dynamic program.

#include <CGAL/Min_cut.h>

#include <MDCS_test/min_cut_networks.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace MC = CGAL::Min_cut;
typedef MC::Flow_network<double> Network;
using MDCS_test::inf;

// Runs the test body once per engine.
template <class Body>
void for_each_engine(Body body)
{
  SECTION("push-relabel") { body(MC::Push_relabel_max_flow()); }
  SECTION("Boykov-Kolmogorov") { body(MC::Boykov_kolmogorov_max_flow()); }
}

std::vector<char> sides(std::initializer_list<int> values)
{
  std::vector<char> s;
  for(int v : values) s.push_back(char(v));
  return s;
}

std::vector<std::pair<std::uint32_t, bool>> chain_of(const MC::Min_cut_result<double>& result)
{
  std::vector<std::pair<std::uint32_t, bool>> chain;
  for(const auto& c : result.chain) chain.emplace_back(c.id, c.forward);
  return chain;
}

typedef std::vector<std::pair<std::uint32_t, bool>> Chain;

} // namespace

TEST_CASE("solve_min_cut: one node between the terminals", "[Min_cut]")
{
  for_each_engine([](auto engine) {
    Network network;
    network.add_nodes(1);
    network.add_source_facet(0, 3.0, 100);
    network.add_sink_facet(0, 5.0, 200);
    const auto result = MC::solve_min_cut(network, engine);
    CHECK(result.is_finite);
    CHECK(result.value == 3.0);
    CHECK(result.on_source_side == sides({0}));
    CHECK(chain_of(result) == Chain{{100, true}});

    // Two source facets on the same node: cutting both (3.5) costs more than the sink facet (2.5).
    Network two;
    two.add_nodes(1);
    two.add_source_facet(0, 1.0, 1);
    two.add_source_facet(0, 2.5, 2);
    two.add_sink_facet(0, 2.5, 3);
    const auto r2 = MC::solve_min_cut(two, engine);
    CHECK(r2.value == 2.5);
    CHECK(r2.on_source_side == sides({1}));
    CHECK(chain_of(r2) == Chain{{3, true}});
  });
}

TEST_CASE("solve_min_cut: the classic 6-vertex network has max flow 23", "[Min_cut]")
{
  // Cormen et al., 3rd ed., Fig. 26.1: v1..v4 are nodes 0..3.
  for_each_engine([](auto engine) {
    Network network;
    network.add_nodes(4);
    network.add_source_facet(0, 16, 1);
    network.add_source_facet(1, 13, 2);
    network.add_facet(1, 0, 4, 0, 3);  // v2 -> v1
    network.add_facet(0, 2, 12, 0, 4); // v1 -> v3
    network.add_facet(1, 3, 14, 0, 5); // v2 -> v4
    network.add_facet(2, 1, 9, 0, 6);  // v3 -> v2
    network.add_facet(3, 2, 7, 0, 7);  // v4 -> v3
    network.add_sink_facet(2, 20, 8);
    network.add_sink_facet(3, 4, 9);
    const auto result = MC::solve_min_cut(network, engine);
    CHECK(result.is_finite);
    CHECK(result.value == 23);
    CHECK(result.on_source_side == sides({1, 1, 0, 1}));
    // v3 -> v2 crosses from the sink side to the source side: it is on the boundary of the source
    // region (backward, capacity 0) and belongs to the chain.
    CHECK(chain_of(result) == Chain{{4, true}, {6, false}, {7, true}, {9, true}});
  });
}

TEST_CASE("solve_min_cut: asymmetric capacities pick the direction of the cut", "[Min_cut]")
{
  for_each_engine([](auto engine) {
    // Cutting 0 -> 1 costs 1, cutting 1 -> 0 costs 100.
    Network forward;
    forward.add_nodes(2);
    forward.add_facet(0, 1, 1, 100, 5);
    forward.add_source_facet(0, 10, 6);
    forward.add_sink_facet(1, 10, 7);
    auto result = MC::solve_min_cut(forward, engine);
    CHECK(result.value == 1);
    CHECK(result.on_source_side == sides({1, 0}));
    CHECK(chain_of(result) == Chain{{5, true}});

    // With the terminals swapped the facet would cost 100: cheaper to cut a terminal facet.
    Network backward;
    backward.add_nodes(2);
    backward.add_facet(0, 1, 1, 100, 5);
    backward.add_source_facet(1, 10, 6);
    backward.add_sink_facet(0, 10, 7);
    result = MC::solve_min_cut(backward, engine);
    CHECK(result.value == 10);
    CHECK(result.is_finite);

    // Tied to the terminals, the facet must be cut backwards: forward == false, cost c_vu.
    Network tied;
    tied.add_nodes(2);
    tied.add_facet(0, 1, 1, 100, 5);
    tied.add_source_facet(1, inf, 6);
    tied.add_sink_facet(0, inf, 7);
    result = MC::solve_min_cut(tied, engine);
    CHECK(result.is_finite);
    CHECK(result.value == 100);
    CHECK(result.on_source_side == sides({0, 1}));
    CHECK(chain_of(result) == Chain{{5, false}});
  });
}

TEST_CASE("solve_min_cut: infeasible constraints give is_finite == false and value == +inf", "[Min_cut]")
{
  for_each_engine([](auto engine) {
    // An infinite path source -> 0 -> 1 -> 2 -> sink, with finite detours.
    Network network;
    network.add_nodes(4);
    network.add_source_facet(0, inf, 1);
    network.add_facet(0, 1, inf, 3.0, 2);
    network.add_facet(1, 2, inf, 0.0, 3);
    network.add_facet(1, 3, 2.0, 2.0, 4);
    network.add_sink_facet(2, inf, 5);
    network.add_sink_facet(3, 1.0, 6);
    const auto result = MC::solve_min_cut(network, engine);
    CHECK_FALSE(result.is_finite);
    CHECK(std::isinf(result.value));
    CHECK(result.value > 0);
    CHECK_FALSE(std::isnan(result.value));
    REQUIRE(result.on_source_side.size() == 4);
    // The returned cut crosses an infinite arc, which shows where the constraints conflict.
    bool crosses_infinite = false;
    for(const auto& c : result.chain)
      if(c.id == 1 || c.id == 2 || c.id == 3 || c.id == 5) crosses_infinite = true;
    CHECK(crosses_infinite);

    // A function constraint that cannot hold: the source is tied above the sink in one column.
    Network column;
    column.add_nodes(2); // 0 below 1
    column.add_facet(0, 1, 1.0, inf, 0);
    column.add_source_facet(1, inf, 1);
    column.add_sink_facet(0, inf, 2);
    const auto r2 = MC::solve_min_cut(column, engine);
    CHECK_FALSE(r2.is_finite);
    CHECK(r2.value == std::numeric_limits<double>::infinity());
  });
}

TEST_CASE("solve_min_cut: huge finite capacities next to infinite ones stay finite", "[Min_cut]")
{
  for_each_engine([](auto engine) {
    Network network;
    network.add_nodes(3);
    network.add_source_facet(0, inf, 1);
    network.add_facet(0, 1, 1e15, inf, 2);
    network.add_facet(1, 2, 0.125, inf, 3);
    network.add_sink_facet(2, inf, 4);
    const auto result = MC::solve_min_cut(network, engine);
    CHECK(result.is_finite);
    CHECK(result.value == 0.125);
    CHECK(chain_of(result) == Chain{{3, true}});
  });
}

TEST_CASE("solve_min_cut: isolated and dangling nodes", "[Min_cut]")
{
  for_each_engine([](auto engine) {
    Network network;
    network.add_nodes(6);
    network.add_source_facet(0, 2.0, 1);
    network.add_facet(0, 1, 1.0, 1.0, 2);
    network.add_sink_facet(1, 3.0, 3);
    // Node 3 hangs on the source only: the flow does not use it, and leaving it on the sink side
    // would cost 4, so it is on the source side. Nodes 2, 4, 5 are isolated: sink side.
    network.add_source_facet(3, 4.0, 4);
    // Node 4 hangs on the sink only: sink side, its facet is not cut.
    network.add_sink_facet(4, 5.0, 5);
    const auto result = MC::solve_min_cut(network, engine);
    CHECK(result.value == 1.0);
    CHECK(result.on_source_side == sides({1, 0, 0, 1, 0, 0}));
    CHECK(chain_of(result) == Chain{{2, true}});
  });
}

TEST_CASE("solve_min_cut: a network with no nodes, or no terminal facets", "[Min_cut]")
{
  for_each_engine([](auto engine) {
    const Network empty;
    const auto result = MC::solve_min_cut(empty, engine);
    CHECK(result.is_finite);
    CHECK(result.value == 0);
    CHECK(result.on_source_side.empty());
    CHECK(result.chain.empty());

    Network no_terminals;
    no_terminals.add_nodes(3);
    no_terminals.add_facet(0, 1, 1, 1, 0);
    no_terminals.add_facet(1, 2, inf, inf, 1);
    const auto r2 = MC::solve_min_cut(no_terminals, engine);
    CHECK(r2.is_finite);
    CHECK(r2.value == 0);
    CHECK(r2.on_source_side == sides({0, 0, 0}));
    CHECK(r2.chain.empty());
  });
}

TEST_CASE("solve_min_cut: float capacities", "[Min_cut]")
{
  MC::Flow_network<float> network;
  network.add_nodes(2);
  network.add_source_facet(0, MC::Flow_network<float>::infinity(), 0);
  network.add_facet(0, 1, 0.5f, 2.0f, 1);
  network.add_sink_facet(1, 0.75f, 2);
  const auto pr = MC::solve_min_cut(network);
  const auto bk = MC::solve_min_cut(network, MC::Boykov_kolmogorov_max_flow());
  CHECK(pr.value == 0.5f);
  CHECK(bk.value == 0.5f);
  CHECK(pr.on_source_side == bk.on_source_side);
}

TEST_CASE("solve_min_cut: progress stages and cancellation", "[Min_cut]")
{
  Network network;
  network.add_nodes(2);
  network.add_source_facet(0, 1, 0);
  network.add_facet(0, 1, 1, 1, 1);
  network.add_sink_facet(1, 1, 2);

  std::vector<std::pair<std::string, double>> calls;
  auto record = [&calls](const char* stage, double fraction) {
    calls.emplace_back(stage, fraction);
    return true;
  };
  const auto result = MC::solve_min_cut(network, MC::Push_relabel_max_flow(), record);
  CHECK(result.value == 1);
  const std::vector<std::pair<std::string, double>> expected = {
    {"network", 0.0}, {"network", 1.0}, {"max-flow", 0.0}, {"max-flow", 1.0}};
  CHECK(calls == expected);

  auto cancel_max_flow = [](const char* stage, double) { return std::string(stage) != "max-flow"; };
  CHECK_THROWS_AS(MC::solve_min_cut(network, MC::Boykov_kolmogorov_max_flow(), cancel_max_flow),
                  CGAL::MDCS::Operation_cancelled);
}

namespace {

// The function-graph grid: width x height cells, cell (x, y) = y * width + x, y upwards. Vertical
// neighbours: cutting below -> above costs up[x][y], above -> below is infinite. Horizontal
// neighbours: both directions finite. The bottom row is tied to the source, the top row to the sink.
struct Function_grid
{
  std::size_t width, height;
  std::vector<double> up, right, left; // up: (x, y) -> (x, y+1); right: (x, y) -> (x+1, y); left: reverse
  Network network;

  std::size_t cell(std::size_t x, std::size_t y) const { return y * width + x; }

  Function_grid(std::size_t w, std::size_t h, unsigned seed) : width(w), height(h)
  {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> cost(0.05, 1.0);
    up.assign(w * h, 0);
    right.assign(w * h, 0);
    left.assign(w * h, 0);
    network.add_nodes(w * h);
    for(std::size_t y = 0; y < h; ++y)
      for(std::size_t x = 0; x < w; ++x) {
        const auto i = Network::Node_index(cell(x, y));
        if(y + 1 < h) {
          up[i] = cost(rng);
          network.add_facet(i, Network::Node_index(cell(x, y + 1)), up[i], inf, Network::Facet_index(2 * i));
        }
        if(x + 1 < w) {
          right[i] = cost(rng);
          left[i] = cost(rng);
          network.add_facet(i, i + 1, right[i], left[i], Network::Facet_index(2 * i + 1));
        }
        if(y == 0) network.add_source_facet(i, inf, Network::Facet_index(2 * w * h + x));
        if(y + 1 == h) network.add_sink_facet(i, inf, Network::Facet_index(3 * w * h + x));
      }
  }

  // Minimum over height functions h(x) in [1, height - 1] (rows y < h(x) on the source side), by
  // dynamic programming over the columns: an oracle independent of max flow.
  double dynamic_programming_minimum() const
  {
    const std::size_t H = height;
    std::vector<double> best(H, std::numeric_limits<double>::infinity()), next(H);
    for(std::size_t h = 1; h < H; ++h) best[h] = up[cell(0, h - 1)];
    for(std::size_t x = 0; x + 1 < width; ++x) {
      for(std::size_t g = 1; g < H; ++g) {
        double m = std::numeric_limits<double>::infinity();
        for(std::size_t h = 1; h < H; ++h) {
          double jump = 0; // horizontal facets between columns x and x+1 that the curve crosses
          for(std::size_t y = g; y < h; ++y) jump += right[cell(x, y)]; // (x,y) source, (x+1,y) sink
          for(std::size_t y = h; y < g; ++y) jump += left[cell(x, y)];  // (x+1,y) source, (x,y) sink
          m = (std::min)(m, best[h] + jump);
        }
        next[g] = m + up[cell(x + 1, g - 1)];
      }
      best.swap(next);
    }
    return *std::min_element(best.begin() + 1, best.end());
  }
};

} // namespace

TEST_CASE("solve_min_cut: the cut of a function-constrained grid is a function graph", "[Min_cut]")
{
  for_each_engine([](auto engine) {
    for(unsigned seed = 1; seed <= 6; ++seed) {
      const Function_grid grid(14 + seed, 9 + seed % 4, seed);
      const auto result = MC::solve_min_cut(grid.network, engine);
      REQUIRE(result.is_finite);

      // Every column is a run of source cells from the bottom followed by sink cells.
      std::vector<std::size_t> height(grid.width);
      for(std::size_t x = 0; x < grid.width; ++x) {
        std::size_t h = 0;
        while(h < grid.height && result.on_source_side[grid.cell(x, h)]) ++h;
        for(std::size_t y = h; y < grid.height; ++y) CHECK_FALSE(result.on_source_side[grid.cell(x, y)]);
        CHECK(h >= 1);
        CHECK(h < grid.height);
        height[x] = h;
      }
      // The chain crosses every column exactly once through a vertical-neighbour facet (even id),
      // upwards, at that column's height; no terminal facet is cut.
      std::vector<int> crossings(grid.width, 0);
      for(const auto& c : result.chain) {
        REQUIRE(c.id < 2 * grid.width * grid.height);
        if(c.id % 2 == 0) {
          const std::size_t i = c.id / 2, x = i % grid.width, y = i / grid.width;
          CHECK(c.forward);
          CHECK(y + 1 == height[x]);
          ++crossings[x];
        }
      }
      CHECK(std::all_of(crossings.begin(), crossings.end(), [](int k) { return k == 1; }));

      const double expected = grid.dynamic_programming_minimum();
      CHECK(std::abs(result.value - expected) <= 1e-12 * expected);
    }
  });
}
