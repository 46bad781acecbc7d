// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// read_dimacs_max_flow(): a DIMACS max-flow file ("p max N M", "n ID s", "n ID t", "a U V CAP", "c ...")
// read by a reader that distrusts it; make_flow_network(): the Flow_network of the nodes the file mentions,
// so that memory follows the file's size whatever node count its 'p' line announces.

#ifndef CGAL_MIN_CUT_IO_READ_DIMACS_MAX_FLOW_H
#define CGAL_MIN_CUT_IO_READ_DIMACS_MAX_FLOW_H

#include <CGAL/MDCS/IO/Read_error.h>
#include <CGAL/MDCS/IO/internal/input_text.h>
#include <CGAL/Min_cut/Flow_network.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <istream>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace Min_cut {
namespace IO {

using CGAL::MDCS::IO::Read_error;

/// \ingroup PkgMinCutRef
/// An arc of a DIMACS max-flow file: from `tail` to `head` (DIMACS node ids, from 1), with its capacity.
struct Dimacs_arc
{
  std::uint64_t tail = 0, head = 0;
  double capacity = 0;
};

/*!
  \ingroup PkgMinCutRef
  \brief The content of a DIMACS max-flow file, as `read_dimacs_max_flow()` validated it.
*/
struct Dimacs_max_flow_problem
{
  std::uint64_t number_of_nodes = 0; ///< as announced by the 'p' line: node ids are 1 .. number_of_nodes
  std::uint64_t number_of_arcs = 0;  ///< as announced by the 'p' line; equals `arcs.size()`
  std::uint64_t source = 0, sink = 0; ///< node ids of the 'n ID s' and 'n ID t' lines
  std::vector<Dimacs_arc> arcs;       ///< in file order

  /// The ids of the nodes that some line mentions (the source, the sink, the ends of every arc), sorted
  /// and distinct. Every other node of `1 .. number_of_nodes` is isolated: it carries no flow and is on the
  /// sink side of every minimum cut.
  std::vector<std::uint64_t> mentioned_nodes() const
  {
    std::vector<std::uint64_t> ids;
    ids.reserve(2 * arcs.size() + 2);
    ids.push_back(source);
    ids.push_back(sink);
    for(const Dimacs_arc& a : arcs) {
      ids.push_back(a.tail);
      ids.push_back(a.head);
    }
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return ids;
  }
};

namespace internal {

inline Dimacs_max_flow_problem read_dimacs_max_flow_from_data(std::string_view data, const std::string& name)
{
  namespace in = CGAL::MDCS::IO::internal;
  using in::Number_status;
  Dimacs_max_flow_problem problem;
  in::Line_reader lines(data);
  std::string_view line, token;
  std::size_t p_line = 0, s_line = 0, t_line = 0;
  double total_capacity = 0;
  auto fail = [&](const std::string& message) { throw Read_error(name, lines.line(), "", message); };
  auto node = [&](std::string_view text, const char* what) {
    std::uint64_t id = 0;
    const Number_status status = in::parse_integer(text, id);
    if(status != Number_status::ok || id < 1 || id > problem.number_of_nodes)
      fail(std::string(what) + " " + in::printable(text) + " is not a node id (1 to " +
           std::to_string(problem.number_of_nodes) + ")");
    return id;
  };
  auto no_more = [&](in::Tokens& tokens, const char* after) {
    if(tokens.next(token)) fail("unexpected " + in::printable(token) + " after " + after);
  };
  if(data.empty()) throw Read_error(name, 0, "", "the file is empty: no 'p max' line");
  while(lines.next(line)) {
    in::Tokens tokens(line);
    if(!tokens.next(token)) continue; // empty or blank line
    if(token[0] == 'c') continue;     // comment
    if(token == "p") {
      if(p_line > 0) fail("a second 'p' line (the first is line " + std::to_string(p_line) + ")");
      std::string_view kind, n, m;
      if(!tokens.next(kind) || !tokens.next(n) || !tokens.next(m)) fail("expected 'p max NODES ARCS'");
      if(kind != "max") fail("the problem type is " + in::printable(kind) + ", not 'max' (a max-flow problem)");
      if(in::parse_integer(n, problem.number_of_nodes) != Number_status::ok || problem.number_of_nodes < 2)
        fail("the node count " + in::printable(n) + " is not an integer >= 2 in range");
      if(in::parse_integer(m, problem.number_of_arcs) != Number_status::ok)
        fail("the arc count " + in::printable(m) + " is not a non-negative integer in range");
      no_more(tokens, "the arc count");
      p_line = lines.line();
      // An arc line takes at least 8 bytes ("a 1 2 3\n"): reserve no more than the rest of the file holds.
      problem.arcs.reserve(std::size_t(std::min<std::uint64_t>(problem.number_of_arcs, lines.remaining() / 8 + 1)));
    } else if(token == "n") {
      if(p_line == 0) fail("an 'n' line before the 'p max' line");
      std::string_view id_text, which;
      if(!tokens.next(id_text) || !tokens.next(which)) fail("expected 'n ID s' or 'n ID t'");
      const std::uint64_t id = node(id_text, "the node");
      no_more(tokens, "the node designation");
      if(which == "s") {
        if(s_line > 0)
          fail("a second source (the source is node " + std::to_string(problem.source) + ", line " + std::to_string(s_line) + ")");
        problem.source = id;
        s_line = lines.line();
      } else if(which == "t") {
        if(t_line > 0)
          fail("a second sink (the sink is node " + std::to_string(problem.sink) + ", line " + std::to_string(t_line) + ")");
        problem.sink = id;
        t_line = lines.line();
      } else {
        fail("expected 's' or 't' after the node id, found " + in::printable(which));
      }
      if(s_line > 0 && t_line > 0 && problem.source == problem.sink)
        fail("node " + std::to_string(id) + " is both the source and the sink");
    } else if(token == "a") {
      if(p_line == 0) fail("an 'a' line before the 'p max' line");
      std::string_view u, v, c;
      if(!tokens.next(u) || !tokens.next(v) || !tokens.next(c)) fail("expected 'a FROM TO CAPACITY'");
      Dimacs_arc arc;
      arc.tail = node(u, "the arc's tail");
      arc.head = node(v, "the arc's head");
      const Number_status status = in::parse_real(c, arc.capacity);
      if(status == Number_status::not_a_number) fail("the capacity " + in::printable(c) + " is not a number");
      if(status == Number_status::out_of_range || !std::isfinite(arc.capacity))
        fail("the capacity " + in::printable(c) + " is not a finite number");
      if(arc.capacity < 0) fail("the capacity " + in::printable(c) + " is negative");
      no_more(tokens, "the capacity");
      // Every flow value stays below the total capacity, and the engines need 1 + 3 x the total to be a
      // double (Max_flow_problem's bound): a total up to a quarter of the largest double keeps both safe.
      total_capacity += arc.capacity;
      if(!(total_capacity <= std::numeric_limits<double>::max() / 4))
        fail("the capacities add up to more than the max-flow engines handle (a quarter of the largest double, about 4.5e307)");
      if(problem.arcs.size() == problem.number_of_arcs)
        fail("more arcs than the " + std::to_string(problem.number_of_arcs) + " the 'p' line (line " +
             std::to_string(p_line) + ") announces");
      problem.arcs.push_back(arc);
    } else {
      fail("unknown line type " + in::printable(token) + " (expected c, p, n or a)");
    }
  }
  if(p_line == 0) throw Read_error(name, 0, "", "no 'p max' line: not a DIMACS max-flow file");
  if(s_line == 0) throw Read_error(name, 0, "", "no source: the line 'n ID s' is missing");
  if(t_line == 0) throw Read_error(name, 0, "", "no sink: the line 'n ID t' is missing");
  if(problem.arcs.size() != problem.number_of_arcs)
    throw Read_error(name, 0, "", "the 'p' line announces " + std::to_string(problem.number_of_arcs) + " arcs, the file has " +
                     std::to_string(problem.arcs.size()) + " (truncated?)");
  return problem;
}

} // namespace internal

/*!
  \ingroup PkgMinCutRef
  \brief reads a DIMACS max-flow file, distrusting it.

  The format: comment lines starting with `c`; one line `p max NODES ARCS` before any `n` or `a` line;
  exactly one `n ID s` (the source) and one `n ID t` (the sink), different nodes; `ARCS` lines
  `a FROM TO CAPACITY` with node ids in 1..NODES and a finite capacity >= 0 (integer or real); blank lines
  are skipped. Every other line, a second `p` line, a second source or sink, trailing text on a line, and a
  number of arcs other than the one announced (a truncated file), and capacities whose sum exceeds a quarter
  of the largest double (so that every flow value, and the engines' arithmetic, stays finite) are errors. Nothing is allocated for the
  announced node count: memory follows the size of the file.

  \throws Read_error with the file name, the line and a message that names the problem
*/
inline Dimacs_max_flow_problem read_dimacs_max_flow(const std::string& file_name)
{
  const std::string data = CGAL::MDCS::IO::internal::load_file(file_name);
  return internal::read_dimacs_max_flow_from_data(data, file_name);
}

/// \ingroup PkgMinCutRef
/// Same as above from a stream (read to its end first); `name` names it in error messages.
inline Dimacs_max_flow_problem read_dimacs_max_flow(std::istream& in, const std::string& name)
{
  const std::string data = CGAL::MDCS::IO::internal::load_stream(in);
  return internal::read_dimacs_max_flow_from_data(data, name);
}

/*!
  \ingroup PkgMinCutRef
  \brief A `Flow_network` built from a DIMACS problem by `make_flow_network()`.

  Its nodes are the nodes the file mentions, other than the source and the sink, in increasing id order
  (`node_ids` gives the DIMACS id of each); the source and the sink are the network's terminals. Arcs from
  the source become source facets, arcs to the sink sink facets, other arcs interior facets with a zero
  reverse capacity; arcs into the source, out of the sink and loops, which carry no source-sink flow, are left
  out, and arcs from the source to the sink, always saturated, are summed in `source_to_sink`.
*/
template <class Capacity = double>
struct Dimacs_flow_network
{
  Flow_network<Capacity> network;
  std::vector<std::uint64_t> node_ids; ///< DIMACS id of each network node
  Capacity source_to_sink = 0;         ///< total capacity of the arcs from the source to the sink
};

/// \ingroup PkgMinCutRef
/// The flow network of a DIMACS problem (see `Dimacs_flow_network`); the max flow of the file is
/// `solve_min_cut(result.network).value + result.source_to_sink`.
/// \throws Read_error (without a line) if the file mentions more nodes than a `Flow_network` holds (2^32 - 2)
template <class Capacity = double>
Dimacs_flow_network<Capacity> make_flow_network(const Dimacs_max_flow_problem& problem, const std::string& name = std::string())
{
  typedef Flow_network<Capacity> Network;
  Dimacs_flow_network<Capacity> result;
  for(std::uint64_t id : problem.mentioned_nodes())
    if(id != problem.source && id != problem.sink) result.node_ids.push_back(id);
  if(result.node_ids.size() > Network::max_number_of_nodes())
    throw Read_error(name, 0, "", "the file mentions " + std::to_string(result.node_ids.size()) +
                     " nodes, more than a flow network holds (2^32 - 2)");
  auto index = [&](std::uint64_t id) {
    return typename Network::Node_index(std::lower_bound(result.node_ids.begin(), result.node_ids.end(), id) -
                                        result.node_ids.begin());
  };
  result.network.add_nodes(result.node_ids.size());
  for(const Dimacs_arc& a : problem.arcs) {
    if(a.tail == a.head || a.head == problem.source || a.tail == problem.sink) continue; // no source-sink flow
    if(a.tail == problem.source && a.head == problem.sink) result.source_to_sink += Capacity(a.capacity);
    else if(a.tail == problem.source) result.network.add_source_facet(index(a.head), Capacity(a.capacity), 0);
    else if(a.head == problem.sink) result.network.add_sink_facet(index(a.tail), Capacity(a.capacity), 0);
    else result.network.add_facet(index(a.tail), index(a.head), Capacity(a.capacity), 0, 0);
  }
  return result;
}

} // namespace IO
} // namespace Min_cut
} // namespace CGAL

#endif // CGAL_MIN_CUT_IO_READ_DIMACS_MAX_FLOW_H
