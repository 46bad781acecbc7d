// `mdcs mincut`: the Min_cut component on a DIMACS max-flow file.
#ifndef MDCS_CLI_CMD_MINCUT_H
#define MDCS_CLI_CMD_MINCUT_H

#include "cli_common.h"

#include <CGAL/Min_cut.h>
#include <CGAL/Min_cut/IO/read_dimacs_max_flow.h>
#include <CGAL/Variational_minimization.h>
#include <CGAL/Variational_minimization/internal/curve_dual_network_2.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <sstream>
#include <utility>

namespace mdcs_cli {

struct Mincut_report
{
  double value = 0;
  std::uint64_t nodes = 0; // as the 'p' line announces
  std::size_t arcs = 0, source_side = 0;
  double seconds = 0;
  // The side of every node some line of the file mentions (DIMACS id, 1: source side), in increasing id order.
  // The others (`nodes` minus these) are isolated and on the sink side: they are not listed, so that memory
  // and the --sides file follow the size of the input, not the node count the 'p' line announces.
  std::vector<std::pair<std::uint64_t, char>> sides;
};

// Reads a DIMACS max-flow file with the library's distrustful reader (CGAL::Min_cut::IO::read_dimacs_max_flow:
// exit 3 with the line and the problem for every malformed file) and solves it on the nodes the file mentions.
inline Mincut_report solve_dimacs_file(const std::string& path, const std::string& engine)
{
  namespace MIO = CGAL::Min_cut::IO;
  MIO::Dimacs_max_flow_problem problem;
  MIO::Dimacs_flow_network<double> flow;
  try {
    problem = MIO::read_dimacs_max_flow(path);
    flow = MIO::make_flow_network<double>(problem, path);
  } catch(const CGAL::MDCS::IO::Read_error& e) {
    throw Input_error(e.what());
  }
  Mincut_report report;
  report.nodes = problem.number_of_nodes;
  report.arcs = problem.arcs.size();
  const auto t0 = std::chrono::steady_clock::now();
  const auto& network = flow.network;
  const auto cut = engine == "bk"   ? CGAL::Min_cut::solve_min_cut(network, CGAL::Min_cut::Boykov_kolmogorov_max_flow())
                   : engine == "pr" ? CGAL::Min_cut::solve_min_cut(network, CGAL::Min_cut::Push_relabel_max_flow())
                                    : CGAL::Min_cut::solve_min_cut(network, CGAL::Min_cut::Pseudoflow_max_flow());
  report.seconds = seconds_since(t0);
  report.value = cut.value + flow.source_to_sink;
  // The mentioned nodes in id order: the network's nodes (sorted ids), the source and the sink.
  report.sides.reserve(flow.node_ids.size() + 2);
  for(std::size_t i = 0; i < flow.node_ids.size(); ++i) report.sides.emplace_back(flow.node_ids[i], cut.on_source_side[i]);
  report.sides.emplace_back(problem.source, char(1));
  report.sides.emplace_back(problem.sink, char(0));
  std::sort(report.sides.begin(), report.sides.end());
  for(const auto& side : report.sides) report.source_side += side.second ? 1 : 0;
  return report;
}

// Writes the directed dual network of the catenoid problem (R, `lines` random lines) as DIMACS; infinite
// capacities become the finite bound M of the network. Returns the curve solver's cut value.
inline double write_catenoid_dual_dimacs(double R, long lines, const std::string& path)
{
  namespace VM = CGAL::Variational_minimization;
  const VM::Curve_problem_2 problem{CGAL::Bbox_2(-1, 0, 1, R), VM::End_condition::fixed(R), VM::End_condition::fixed(R)};
  VM::Random_lines_options options;
  options.pencil_points = {VM::Point_2(-1, R), VM::Point_2(1, R)};
  const auto arrangement = VM::build_curve_arrangement_2(problem, VM::random_lines_2(problem.box, std::size_t(lines), 1, options));
  const auto weights = VM::curve_edge_weights_2(arrangement, VM::Surface_of_rotation_functional());
  const auto network = VM::internal::curve_dual_network_2(arrangement, weights, problem);
  const CGAL::Min_cut::Max_flow_problem<double> finite(network);
  const std::size_t n = network.number_of_nodes();
  const std::size_t s = n + 1, t = n + 2;
  Output_file out(path);
  std::size_t arc_count = 0;
  std::ostringstream arcs;
  arcs.precision(17);
  for(std::size_t k = 0; k < finite.number_of_arc_pairs(); ++k) {
    const auto a = finite.arc_pair(k);
    if(a.c_uv > 0) arcs << "a " << a.u + 1 << " " << a.v + 1 << " " << a.c_uv << "\n", ++arc_count;
    if(a.c_vu > 0) arcs << "a " << a.v + 1 << " " << a.u + 1 << " " << a.c_vu << "\n", ++arc_count;
  }
  for(std::size_t v = 0; v < n; ++v) {
    const auto node = CGAL::Min_cut::Flow_network<double>::Node_index(v);
    if(finite.source_capacity(node) > 0) arcs << "a " << s << " " << v + 1 << " " << finite.source_capacity(node) << "\n", ++arc_count;
    if(finite.sink_capacity(node) > 0) arcs << "a " << v + 1 << " " << t << " " << finite.sink_capacity(node) << "\n", ++arc_count;
  }
  out << "c directed dual network of the catenoid problem R = " << R << ", " << lines << " random lines (MDCS)\n"
      << "c infinite capacities are written as M = " << finite.infinite_capacity() << "\n"
      << "p max " << n + 2 << " " << arc_count << "\n"
      << "n " << s << " s\nn " << t << " t\n"
      << arcs.str();
  out.commit();
  return CGAL::Min_cut::solve_min_cut(network).value;
}

} // namespace mdcs_cli

#endif // MDCS_CLI_CMD_MINCUT_H
