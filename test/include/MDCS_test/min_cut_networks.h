// Shared by the Min_cut tests: the capacity of a given cut (the brute-force oracle's building block), node
// sides as bit masks, and grid networks shaped like the duals of the variational problems.
#ifndef MDCS_TEST_MIN_CUT_NETWORKS_H
#define MDCS_TEST_MIN_CUT_NETWORKS_H

#include <CGAL/Min_cut/Flow_network.h>
#include <CGAL/Min_cut/Planar_dual.h>

#include <MDCS_test/test_numbers.h> // inf, which is Network::infinity()

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

// The planar dual of MDCS_test::grid_network(width, height, ...): node (x, y) is the unit square
// [x, x+1] x [y, y+1], dual vertices are the square corners, the source lies below the grid and the sink above
// it, and a cut runs from the left side (start) to the right side (end) with the source on its right.
inline CGAL::Min_cut::Planar_dual grid_dual(const Network& network, std::size_t width, std::size_t height)
{
  auto corner = [&](std::size_t X, std::size_t Y) { return CGAL::Min_cut::Planar_dual::Vertex_index(Y * (width + 1) + X); };
  CGAL::Min_cut::Planar_dual dual;
  dual.number_of_vertices = (width + 1) * (height + 1);
  for(const auto& f : network.facets()) {
    const std::size_t x = f.u % width, y = f.u / width;
    if(f.v == f.u + 1) // v right of u: the shared side is x + 1, walked downwards to keep u on the right
      dual.edges.push_back({corner(x + 1, y + 1), corner(x + 1, y)});
    else // v above u: the shared side is y + 1, walked to the right (u below, on the right)
      dual.edges.push_back({corner(x, y + 1), corner(x + 1, y + 1)});
  }
  for(const auto& f : network.source_facets()) // bottom side, walked to the right: the source below, on the right
    dual.source_edges.push_back({corner(f.node % width, 0), corner(f.node % width + 1, 0)});
  for(const auto& f : network.sink_facets()) // top side, walked to the right: the node below, on the right
    dual.sink_edges.push_back({corner(f.node % width, height), corner(f.node % width + 1, height)});
  for(std::size_t Y = 0; Y <= height; ++Y) {
    dual.start_vertices.push_back(corner(0, Y));
    dual.end_vertices.push_back(corner(width, Y));
  }
  return dual;
}

} // namespace MDCS_test

#endif // MDCS_TEST_MIN_CUT_NETWORKS_H
