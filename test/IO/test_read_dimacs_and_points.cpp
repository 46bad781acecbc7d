// read_dimacs_max_flow() and make_flow_network(): good files, every malformed line with its message and line,
// and on random networks the max flow through the file equals the max flow of the same network built
// directly on all announced nodes (an independent construction), whatever isolated nodes the 'p' line adds.
// read_points_2() / read_points_3(): separators, comments, header, and every malformed line.
#include "io_test_helpers.h"

#include <CGAL/MDCS/IO/read_points.h>
#include <CGAL/Min_cut/IO/read_dimacs_max_flow.h>
#include <CGAL/Min_cut/solve_min_cut.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <random>
#include <sstream>

namespace MC = CGAL::Min_cut;
namespace MCIO = CGAL::Min_cut::IO;
namespace MIO = CGAL::MDCS::IO;
using namespace io_test;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

namespace {

double max_flow_of_file(const std::string& path)
{
  const MCIO::Dimacs_max_flow_problem problem = MCIO::read_dimacs_max_flow(path);
  const MCIO::Dimacs_flow_network<double> flow = MCIO::make_flow_network<double>(problem);
  return MC::solve_min_cut(flow.network).value + flow.source_to_sink;
}

} // namespace

TEST_CASE("read_dimacs_max_flow: a good file", "[io][dimacs]")
{
  Scratch dir;
  const std::string text = "c a comment\n\n   \t\nc another\np max 6 8\nn 1 s\nn 6 t\na 1 2 3\na 1 3 2.5\na 2 3 1\n"
                           "a 2 4 2\na 3 5 3e0\na 4 6 +2\na 5 6 3\na 6 1 9\n";
  const std::string path = dir.write("g.max", text);
  const MCIO::Dimacs_max_flow_problem p = MCIO::read_dimacs_max_flow(path);
  CHECK(p.number_of_nodes == 6);
  CHECK(p.number_of_arcs == 8);
  CHECK(p.source == 1);
  CHECK(p.sink == 6);
  REQUIRE(p.arcs.size() == 8);
  CHECK(p.arcs[1].capacity == 2.5);
  CHECK(p.arcs[7].tail == 6);
  CHECK(p.mentioned_nodes() == std::vector<std::uint64_t>{1, 2, 3, 4, 5, 6});
  CHECK(max_flow_of_file(path) == Approx(5.0)); // the cut {4->6, 3->5}; the arc 6 -> 1 carries nothing
  std::istringstream in(text);
  CHECK(MCIO::read_dimacs_max_flow(in, "stream").arcs.size() == 8);
  // 300 million announced nodes and one arc: memory follows the file, the flow is the arc's capacity.
  const std::string huge = dir.write("h.max", "p max 300000000 2\nn 1 s\nn 300000000 t\na 1 300000000 7\na 1 5 1\n");
  const auto problem = MCIO::read_dimacs_max_flow(huge);
  const auto flow = MCIO::make_flow_network<double>(problem);
  CHECK(flow.network.number_of_nodes() == 1); // node 5 (the terminals are not network nodes)
  CHECK(flow.node_ids == std::vector<std::uint64_t>{5});
  CHECK(flow.source_to_sink == 7);
  CHECK(max_flow_of_file(huge) == 7);
}

TEST_CASE("read_dimacs_max_flow: malformed files", "[io][dimacs][errors]")
{
  Scratch dir;
  auto bad = [&](const std::string& text, const std::string& message, std::size_t line = std::size_t(-1)) {
    const std::string path = dir.write("bad.max", text);
    INFO(text);
    return expect_read_error([&] { MCIO::read_dimacs_max_flow(path); }, message, line);
  };
  const std::string head = "p max 4 2\nn 1 s\nn 4 t\n";
  bad("", "the file is empty");
  bad("c only a comment\n", "no 'p max' line", 0);
  bad(head + "a 1 2 1\np max 2 1\n", "a second 'p' line (the first is line 1)", 5);
  bad("p min 4 2\n", "the problem type is 'min'", 1);
  bad("p max 4\n", "expected 'p max NODES ARCS'", 1);
  bad("p max 1 0\n", "the node count '1' is not an integer >= 2", 1);
  bad("p max -5 0\n", "the node count '-5'", 1);
  bad("p max 99999999999999999999 0\n", "in range", 1);
  bad("p max 4 x\n", "the arc count 'x'", 1);
  bad("p max 4 2 7\n", "unexpected '7' after the arc count", 1);
  bad("n 1 s\n" + head, "an 'n' line before the 'p max' line", 1);
  bad("a 1 2 3\n" + head, "an 'a' line before the 'p max' line", 1);
  bad(head + "n 2 s\n", "a second source (the source is node 1, line 2)", 4);
  bad(head + "n 3 t\n", "a second sink (the sink is node 4, line 3)", 4);
  bad("p max 4 0\nn 1 s\nn 1 t\n", "node 1 is both the source and the sink", 3);
  bad("p max 4 0\nn 5 s\n", "the node '5' is not a node id (1 to 4)", 2);
  bad("p max 4 0\nn 0 s\n", "the node '0' is not a node id", 2);
  bad("p max 4 0\nn 1 x\n", "expected 's' or 't' after the node id, found 'x'", 2);
  bad("p max 4 0\nn 1\n", "expected 'n ID s' or 'n ID t'", 2);
  bad("p max 4 0\nn 1 s extra\n", "unexpected 'extra' after the node designation", 2);
  bad(head + "a 1 2\n", "expected 'a FROM TO CAPACITY'", 4);
  bad(head + "a 1 5 1\na 1 2 1\n", "the arc's head '5' is not a node id (1 to 4)", 4);
  bad(head + "a -1 2 1\na 1 2 1\n", "the arc's tail '-1' is not a node id", 4);
  bad(head + "a 1 2 inf\na 1 2 1\n", "the capacity 'inf' is not a finite number", 4);
  bad(head + "a 1 2 nan\na 1 2 1\n", "the capacity 'nan' is not a finite number", 4);
  bad(head + "a 1 2 1e999\na 1 2 1\n", "the capacity '1e999' is not a finite number", 4);
  bad(head + "a 1 2 -1\na 1 2 1\n", "the capacity '-1' is negative", 4);
  bad(head + "a 1 2 one\na 1 2 1\n", "the capacity 'one' is not a number", 4);
  bad(head + "a 1 2 1 2\na 1 2 1\n", "unexpected '2' after the capacity", 4);
  bad(head + "a 1 2 1e307\na 2 4 4e307\n", "the capacities add up to more than the max-flow engines handle", 5);
  bad(head + "a 1 2 1e308\na 2 4 1\n", "the capacities add up to more than the max-flow engines handle", 4);
  bad(head + "a 1 2 1\na 2 4 1\na 1 4 1\n", "more arcs than the 2 the 'p' line (line 1) announces", 6);
  bad(head + "a 1 2 1\n", "the 'p' line announces 2 arcs, the file has 1 (truncated?)", 0);
  bad("p max 4 0\nn 4 t\n", "no source", 0);
  bad("p max 4 0\nn 1 s\n", "no sink", 0);
  bad(head + "x 1 2 3\n", "unknown line type 'x' (expected c, p, n or a)", 4);
  bad(head + "pmax 4 2\n", "unknown line type 'pmax'", 4);
  bad(std::string("p max 4 0\nn 1 s\nn 4 t\n\x01\x02\n"), "unknown line type '\\x01\\x02'", 4);
  expect_read_error([&] { MCIO::read_dimacs_max_flow(dir.path("missing.max")); }, "does not exist");
}

// The oracle: the same random network built directly on all N nodes, solved by another engine.
TEST_CASE("read_dimacs_max_flow: the max flow of random files equals the network built directly", "[io][dimacs][oracle]")
{
  Scratch dir;
  std::mt19937 random(28);
  for(int round = 0; round < 40; ++round) {
    const std::size_t used = 3 + random() % 30;
    const std::size_t n = used + (round % 2 ? 0 : random() % 1000); // isolated nodes announced, never used
    const std::size_t arcs = random() % (4 * used);
    const std::uint64_t s = 1 + random() % used;
    std::uint64_t t = 1 + random() % used;
    if(t == s) t = s % used + 1;
    std::ostringstream file;
    file << "p max " << n << " " << arcs << "\nn " << s << " s\nn " << t << " t\n";
    MC::Flow_network<double> direct;
    direct.add_nodes(n);
    double source_to_sink = 0;
    for(std::size_t a = 0; a < arcs; ++a) {
      const std::uint64_t u = 1 + random() % used, v = 1 + random() % used;
      const double c = double(random() % 100) / 8;
      file << "a " << u << " " << v << " " << c << "\n";
      // The direct network: terminals as terminal facets, every other node a network node (id - 1).
      if(u == v || v == s || u == t) continue;
      if(u == s && v == t) source_to_sink += c;
      else if(u == s) direct.add_source_facet(MC::Flow_network<double>::Node_index(v - 1), c, 0);
      else if(v == t) direct.add_sink_facet(MC::Flow_network<double>::Node_index(u - 1), c, 0);
      else direct.add_facet(MC::Flow_network<double>::Node_index(u - 1), MC::Flow_network<double>::Node_index(v - 1), c, 0, 0);
    }
    const std::string path = dir.write("r.max", file.str());
    INFO("round " << round);
    const double expected = MC::solve_min_cut(direct, MC::Boykov_kolmogorov_max_flow()).value + source_to_sink;
    CHECK(max_flow_of_file(path) == Approx(expected).epsilon(1e-12).margin(1e-12));
  }
}

TEST_CASE("read_points_2 / read_points_3: separators, comments, header", "[io][points]")
{
  Scratch dir;
  std::vector<K::Point_2> p;
  MIO::read_points_2(dir.write("p.csv", "x,y\n# comment\n0,0\n1.5 , -2\n\n3;4 # trailing comment\n  5\t6\r\n+1e-3,.5\n"), p);
  REQUIRE(p.size() == 5);
  CHECK(p[1] == K::Point_2(1.5, -2));
  CHECK(p[2] == K::Point_2(3, 4));
  CHECK(p[3] == K::Point_2(5, 6));
  CHECK(p[4] == K::Point_2(0.001, 0.5));
  std::vector<std::array<double, 3>> q;
  MIO::read_points_3(dir.write("q.xyz", "x y z\n1 2 3\n4,5,6\n"), q);
  CHECK(q == std::vector<std::array<double, 3>>{{{1, 2, 3}}, {{4, 5, 6}}});
  std::istringstream in("1 2\n");
  MIO::read_points_2(in, "stream", p);
  CHECK(p.size() == 1);
  MIO::read_points_2(dir.write("e.xy", "# nothing\n\n"), p);
  CHECK(p.empty());
}

TEST_CASE("read_points_2 / read_points_3: malformed lines", "[io][points][errors]")
{
  Scratch dir;
  auto bad2 = [&](const std::string& text, const std::string& message, std::size_t line) {
    const std::string path = dir.write("bad.xy", text);
    std::vector<K::Point_2> p;
    INFO(text);
    expect_read_error([&] { MIO::read_points_2(path, p); }, message, line);
    CHECK(p.empty());
  };
  bad2("0 0\n1 0 0\n", "expected 2 coordinates, found 3 fields", 2);
  bad2("0 0\n1\n", "expected 2 coordinates, found 1 fields", 2);
  bad2("0 0\nnan 1\n", "the coordinate 'nan' is not a finite number", 2);
  bad2("0 0\n1 -inf\n", "the coordinate '-inf' is not a finite number", 2);
  bad2("0 0\n1 1e400\n", "the coordinate '1e400' is not a finite number", 2);
  bad2("0 0\n1 2x\n", "'2x' is not a number", 2);
  bad2("0,0\n1,,2\n", "an empty field", 2);
  bad2("0,0\n1,2,\n", "an empty field", 2);
  bad2("x y\nx y\n", "'x' is not a number", 2); // a header only as the first line
  bad2("1 x\n", "'x' is not a number", 1);      // a line with a number is no header
  bad2(std::string("0 0\n\x01\x02 3\n"), "'\\x01\\x02' is not a number", 2);
  std::vector<std::array<double, 3>> q;
  expect_read_error([&] { MIO::read_points_3(dir.write("b.xyz", "1 2 3\n1 2\n"), q); }, "expected 3 coordinates, found 2", 2);
  std::vector<K::Point_2> p;
  expect_read_error([&] { MIO::read_points_2(dir.path("missing.xy"), p); }, "does not exist");
}
