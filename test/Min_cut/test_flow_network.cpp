// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Flow_network (storage, input validation) and Max_flow_problem (the engines' view: infinities
// replaced by M, terminal capacities summed per node).

#include <CGAL/Min_cut/Flow_network.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace {

typedef CGAL::Min_cut::Flow_network<double> Network;
typedef CGAL::Min_cut::Max_flow_problem<double> Problem;

// The message of the std::invalid_argument that `f` throws, or "" if it throws nothing.
template <class F>
std::string invalid_argument_message(F f)
{
  try {
    f();
  } catch(const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST_CASE("Flow_network: nodes and facets are stored as given", "[Min_cut]")
{
  Network network;
  network.reserve(5, 4, 2);
  CHECK(network.number_of_nodes() == 0);
  CHECK(network.add_nodes(3) == 0);
  CHECK(network.add_nodes(2) == 3);
  CHECK(network.number_of_nodes() == 5);

  network.add_facet(0, 1, 1.5, 0.0, 10);
  network.add_facet(4, 2, Network::infinity(), 2.0, 11);
  network.add_source_facet(3, 7.0, 20);
  network.add_sink_facet(4, Network::infinity(), 21);
  network.add_sink_facet(4, 0.5, 22);

  REQUIRE(network.number_of_facets() == 2);
  REQUIRE(network.number_of_source_facets() == 1);
  REQUIRE(network.number_of_sink_facets() == 2);
  CHECK(network.facet(1).u == 4);
  CHECK(network.facet(1).v == 2);
  CHECK(std::isinf(network.facet(1).c_uv));
  CHECK(network.facet(1).c_vu == 2.0);
  CHECK(network.facet(1).id == 11);
  CHECK(network.source_facet(0).node == 3);
  CHECK(network.source_facet(0).capacity == 7.0);
  CHECK(network.sink_facets()[1].id == 22);
  CHECK(network.facets().size() == 2);

  network.clear();
  CHECK(network.number_of_nodes() == 0);
  CHECK(network.number_of_facets() == 0);
  CHECK(network.number_of_sink_facets() == 0);
}

TEST_CASE("Flow_network: bad input throws std::invalid_argument with a clear message", "[Min_cut]")
{
  Network network;
  network.add_nodes(3);
  const double nan = std::numeric_limits<double>::quiet_NaN();

  std::string message = invalid_argument_message([&] { network.add_facet(0, 3, 1, 1, 7); });
  CHECK(message.rfind("MDCS: ", 0) == 0);
  CHECK(message.find("out of range") != std::string::npos);
  CHECK(message.find("3") != std::string::npos);

  message = invalid_argument_message([&] { network.add_facet(5, 0, 1, 1, 7); });
  CHECK(message.find("out of range") != std::string::npos);

  message = invalid_argument_message([&] { network.add_facet(1, 1, 1, 1, 7); });
  CHECK(message.rfind("MDCS: ", 0) == 0);
  CHECK(message.find("u == v") != std::string::npos);

  message = invalid_argument_message([&] { network.add_facet(0, 1, -1, 1, 7); });
  CHECK(message.rfind("MDCS: ", 0) == 0);
  CHECK(message.find(">= 0") != std::string::npos);

  message = invalid_argument_message([&] { network.add_facet(0, 1, 1, nan, 7); });
  CHECK(message.find("NaN") != std::string::npos);

  message = invalid_argument_message([&] { network.add_source_facet(3, 1, 8); });
  CHECK(message.find("add_source_facet") != std::string::npos);
  CHECK(message.find("out of range") != std::string::npos);

  message = invalid_argument_message([&] { network.add_sink_facet(0, -Network::infinity(), 9); });
  CHECK(message.find("add_sink_facet") != std::string::npos);

  message = invalid_argument_message([&] { network.add_source_facet(0, nan, 9); });
  CHECK(message.find("NaN") != std::string::npos);

  // Nothing was stored by the failed calls.
  CHECK(network.number_of_facets() == 0);
  CHECK(network.number_of_source_facets() == 0);
  CHECK(network.number_of_sink_facets() == 0);

  // Zero and infinite capacities are valid.
  CHECK_NOTHROW(network.add_facet(0, 1, 0, Network::infinity(), 1));
  CHECK_NOTHROW(network.add_source_facet(2, 0, 2));
}

TEST_CASE("Flow_network: at most 2^32 - 2 nodes", "[Min_cut]")
{
  // Nodes have no storage, so the limit can be reached without memory.
  Network network;
  const std::size_t limit = std::size_t(0xFFFFFFFFu) - 1;
  CHECK(Network::max_number_of_nodes() == limit);
  network.add_nodes(limit - 1);
  CHECK_NOTHROW(network.add_nodes(1));
  CHECK(network.number_of_nodes() == limit);
  const std::string message = invalid_argument_message([&] { network.add_nodes(1); });
  CHECK(message.rfind("MDCS: ", 0) == 0);
  CHECK(message.find("2^32 - 2") != std::string::npos);
  CHECK(network.number_of_nodes() == limit);

  Network other;
  CHECK_THROWS_AS(other.add_nodes(limit + 1), std::invalid_argument);
  CHECK(other.number_of_nodes() == 0);
}

TEST_CASE("Max_flow_problem: infinities become M = 1 + 2 * (sum of finite capacities)", "[Min_cut]")
{
  Network network;
  network.add_nodes(4);
  network.add_facet(0, 1, 1.0, Network::infinity(), 0);
  network.add_facet(1, 2, 2.0, 0.5, 1);
  network.add_facet(2, 3, 0.0, 0.0, 2);
  network.add_source_facet(0, Network::infinity(), 3);
  network.add_source_facet(1, 1.5, 4);
  network.add_source_facet(1, 2.5, 5);
  network.add_sink_facet(3, 3.0, 6);
  network.add_sink_facet(3, Network::infinity(), 7);
  network.add_sink_facet(2, 0.25, 8);

  const Problem problem(network);
  const double finite_sum = 1.0 + 2.0 + 0.5 + 1.5 + 2.5 + 3.0 + 0.25;
  const double M = 1 + 2 * finite_sum;
  CHECK(problem.infinite_capacity() == M);
  CHECK(problem.number_of_nodes() == 4);
  REQUIRE(problem.number_of_arc_pairs() == 3);

  const auto p0 = problem.arc_pair(0);
  CHECK(p0.u == 0);
  CHECK(p0.v == 1);
  CHECK(p0.c_uv == 1.0);
  CHECK(p0.c_vu == M);
  const auto p2 = problem.arc_pair(2);
  CHECK(p2.c_uv == 0.0);
  CHECK(p2.c_vu == 0.0);

  CHECK(problem.source_capacity(0) == M);
  CHECK(problem.source_capacity(1) == 4.0); // two source facets summed
  CHECK(problem.source_capacity(2) == 0.0);
  CHECK(problem.sink_capacity(2) == 0.25);
  CHECK(problem.sink_capacity(3) == M); // a finite and an infinite facet: capped at M
  CHECK(problem.sink_capacity(0) == 0.0);
}

TEST_CASE("Max_flow_problem: capacities whose sum overflows are refused", "[Min_cut]")
{
  Network network;
  network.add_nodes(2);
  network.add_facet(0, 1, 1e308, 1e308, 0);
  CHECK_THROWS_AS(Problem(network), std::domain_error);

  // Finite sum, but M times the number of infinite arcs overflows.
  Network other;
  other.add_nodes(2);
  other.add_facet(0, 1, 4e307, Network::infinity(), 0);
  other.add_source_facet(0, Network::infinity(), 1);
  try {
    Problem problem(other);
    FAIL("no exception");
  } catch(const std::domain_error& e) {
    CHECK(std::string(e.what()).rfind("MDCS: ", 0) == 0);
  }

  // Large but safe capacities are accepted.
  Network safe;
  safe.add_nodes(2);
  safe.add_facet(0, 1, 1e300, Network::infinity(), 0);
  CHECK_NOTHROW(Problem(safe));
}

TEST_CASE("Max_flow_problem: an empty network", "[Min_cut]")
{
  Network network;
  const Problem problem(network);
  CHECK(problem.number_of_nodes() == 0);
  CHECK(problem.number_of_arc_pairs() == 0);
  CHECK(problem.infinite_capacity() == 1.0);
}
