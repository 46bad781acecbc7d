// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Absurd capacities and sizes at the entry points of Min_cut (issue 28): NaN, negative and -infinite capacities are
// refused when added; finite capacities whose sum overflows are refused by every engine and by the planar cut
// (which summed 1e308 + 1e308 into a "finite" cut of +inf before); a planar dual with far more vertices than edges is
// refused before anything is allocated; an engine that runs out of memory is reported as such.

#include <CGAL/Min_cut.h>

#include <MDCS_test/min_cut_networks.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <new>
#include <stdexcept>
#include <vector>

namespace {

namespace MC = CGAL::Min_cut;
typedef MC::Flow_network<double> Network;

using MDCS_test::grid_dual;


// The grid with every capacity multiplied by `factor`.
Network scaled(const Network& g, double factor)
{
  Network n;
  n.add_nodes(g.number_of_nodes());
  auto s = [factor](double c) { return c == Network::infinity() ? c : c * factor; };
  for(const auto& f : g.facets()) n.add_facet(f.u, f.v, s(f.c_uv), s(f.c_vu), f.id);
  for(const auto& f : g.source_facets()) n.add_source_facet(f.node, s(f.capacity), f.id);
  for(const auto& f : g.sink_facets()) n.add_sink_facet(f.node, s(f.capacity), f.id);
  return n;
}

struct Out_of_memory_engine
{
  template <class Capacity>
  Capacity operator()(const MC::Max_flow_problem<Capacity>&, std::vector<char>&) const
  {
    throw std::bad_alloc();
  }
};

} // namespace

TEST_CASE("min cut checks: NaN, negative and -inf capacities are refused when added", "[min_cut][checks]")
{
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for(double bad : {nan, -1.0, -inf, -1e-300}) {
    INFO("capacity " << bad);
    Network n;
    n.add_nodes(2);
    CHECK_THROWS_AS(n.add_facet(0, 1, bad, 1, 0), std::invalid_argument);
    CHECK_THROWS_AS(n.add_facet(0, 1, 1, bad, 0), std::invalid_argument);
    CHECK_THROWS_AS(n.add_source_facet(0, bad, 1), std::invalid_argument);
    CHECK_THROWS_AS(n.add_sink_facet(1, bad, 2), std::invalid_argument);
    CHECK(n.number_of_facets() + n.number_of_source_facets() + n.number_of_sink_facets() == 0);
  }
  Network n;
  n.add_nodes(2);
  CHECK_NOTHROW(n.add_facet(0, 1, inf, 0, 0));   // +inf is part of the interface
  CHECK_THROWS_AS(n.add_facet(0, 5, 1, 1, 0), std::invalid_argument);
  CHECK_THROWS_AS(n.add_nodes(std::size_t(1) << 33), std::invalid_argument);
}

TEST_CASE("min cut checks: capacities whose sum overflows are refused by every engine and the planar cut", "[min_cut][checks][planar]")
{
  const Network grid = MDCS_test::grid_network(6, 5, false, false, 3);
  const MC::Planar_dual dual = grid_dual(grid, 6, 5);
  const Network huge = scaled(grid, 1e308);   // every capacity finite, their sum is not
  CHECK_THROWS_AS(MC::solve_min_cut(huge, MC::Pseudoflow_max_flow()), std::domain_error);
  CHECK_THROWS_AS(MC::solve_min_cut(huge, MC::Push_relabel_max_flow()), std::domain_error);
  CHECK_THROWS_AS(MC::solve_min_cut(huge, MC::Boykov_kolmogorov_max_flow()), std::domain_error);
  CHECK_THROWS_WITH(MC::solve_planar_min_cut(huge, dual), Catch::Contains("too large"));
  // the same network scaled into range: every solver agrees with the unscaled one, scaled
  const auto reference = MC::solve_min_cut(grid);
  for(double factor : {1e-300, 1e300}) {
    const Network ok = scaled(grid, factor);
    const auto flow = MC::solve_min_cut(ok);
    const auto planar = MC::solve_planar_min_cut(ok, dual);
    INFO("factor " << factor);
    REQUIRE(flow.is_finite);
    REQUIRE(planar.is_finite);
    CHECK(std::isfinite(flow.value));
    CHECK(flow.value / factor == Approx(reference.value).epsilon(1e-12));
    CHECK(planar.value / factor == Approx(reference.value).epsilon(1e-12));
  }
}

TEST_CASE("min cut checks: a planar dual with absurd sizes is refused before allocating", "[min_cut][checks][planar]")
{
  const Network grid = MDCS_test::grid_network(4, 3, false, true, 1);
  MC::Planar_dual dual = grid_dual(grid, 4, 3);
  CHECK(MC::solve_planar_min_cut(grid, dual).is_finite);
  dual.number_of_vertices = std::size_t(3) << 30;   // 3 * 2^30 vertices for a few dozen edges: 60 GB of distances
  CHECK_THROWS_WITH(MC::solve_planar_min_cut(grid, dual), Catch::Contains("vertices"));
  dual.number_of_vertices = std::numeric_limits<std::size_t>::max();
  CHECK_THROWS_AS(MC::solve_planar_min_cut(grid, dual), std::invalid_argument);
}

TEST_CASE("min cut checks: an engine out of memory is reported with the network's size", "[min_cut][checks]")
{
  const Network grid = MDCS_test::grid_network(4, 3, false, true, 1);
  CHECK_THROWS_AS(MC::solve_min_cut(grid, Out_of_memory_engine()), std::length_error);
  CHECK_THROWS_WITH(MC::solve_min_cut(grid, Out_of_memory_engine()), Catch::Contains("12 nodes"));
}
