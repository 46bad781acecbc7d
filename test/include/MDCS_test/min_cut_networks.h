// Shared by the Min_cut tests: the capacity of a given cut (the brute-force oracle's building block), node
// sides as bit masks, and grid networks shaped like the duals of the variational problems.
#ifndef MDCS_TEST_MIN_CUT_NETWORKS_H
#define MDCS_TEST_MIN_CUT_NETWORKS_H

#include <CGAL/Min_cut/Flow_network.h>

#include <cstdint>
#include <random>
#include <vector>

namespace MDCS_test {

typedef CGAL::Min_cut::Flow_network<double> Network;

// Capacity of the cut whose source side is `in_source` (bit i = node i), +infinity if it crosses an infinite
// arc. Summed in the order solve_min_cut documents for its chain (facets, source facets, sink facets).
inline double cut_capacity(const Network& network, std::uint32_t in_source)
{
  const double inf = Network::infinity();
  auto S = [in_source](std::uint32_t i) { return ((in_source >> i) & 1u) != 0; };
  double value = 0;
  bool infinite = false;
  auto add = [&](double c) {
    if(c == inf) infinite = true;
    else value += c;
  };
  for(const auto& f : network.facets()) {
    if(S(f.u) && !S(f.v)) add(f.c_uv);
    else if(!S(f.u) && S(f.v)) add(f.c_vu);
  }
  for(const auto& f : network.source_facets())
    if(!S(f.node)) add(f.capacity);
  for(const auto& f : network.sink_facets())
    if(S(f.node)) add(f.capacity);
  return infinite ? inf : value;
}

// Node sides (1 = source side) as a bit mask (bit i = node i); at most 32 nodes.
inline std::uint32_t as_mask(const std::vector<char>& side)
{
  std::uint32_t mask = 0;
  for(std::size_t i = 0; i < side.size(); ++i)
    if(side[i]) mask |= 1u << i;
  return mask;
}

// A width x height grid shaped like the variational problems' duals: 4-connected, random capacities both
// ways, terminal facets only on the bottom (source) and top (sink) rows. `function` makes every downward arc
// infinite. Integer capacities keep the arithmetic exact, so minimal sides are unique.
inline Network grid_network(std::size_t width, std::size_t height, bool function, bool integer, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> small(0, 9);
  std::uniform_real_distribution<double> real(0.05, 1.0);
  auto cost = [&]() { return integer ? double(small(rng)) : real(rng); };
  Network network;
  network.add_nodes(width * height);
  std::uint32_t id = 0;
  for(std::size_t y = 0; y < height; ++y)
    for(std::size_t x = 0; x < width; ++x) {
      const auto i = Network::Node_index(y * width + x);
      if(x + 1 < width) network.add_facet(i, i + 1, cost(), cost(), id++);
      if(y + 1 < height) {
        const double up = cost(), down = cost();
        network.add_facet(i, Network::Node_index(i + width), up, function ? Network::infinity() : down, id++);
      }
      if(y == 0) network.add_source_facet(i, 3 * cost(), id++);
      if(y + 1 == height) network.add_sink_facet(i, 3 * cost(), id++);
    }
  return network;
}

} // namespace MDCS_test

#endif // MDCS_TEST_MIN_CUT_NETWORKS_H
