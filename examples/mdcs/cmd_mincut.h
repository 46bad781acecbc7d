// `mdcs mincut`: the Min_cut component on a DIMACS max-flow file.
#ifndef MDCS_CLI_CMD_MINCUT_H
#define MDCS_CLI_CMD_MINCUT_H

#include "cli_common.h"

#include <CGAL/Min_cut.h>
#include <CGAL/Variational_minimization.h>
#include <CGAL/Variational_minimization/internal/curve_dual_network_2.h>

#include <fstream>
#include <iostream>
#include <sstream>

namespace mdcs_cli {

struct Mincut_report
{
  double value = 0;
  std::size_t nodes = 0, arcs = 0, source_side = 0;
  double seconds = 0;
  std::vector<char> on_source_side; // per DIMACS node (0-based)
};

inline Mincut_report solve_dimacs_file(const std::string& path, const std::string& engine)
{
  std::ifstream in(path);
  if(!in) throw Input_error("cannot open '" + path + "'");
  typedef CGAL::Min_cut::Flow_network<double> Network;
  Network network;
  long n = -1, m = -1, s = -1, t = -1, line_number = 0, arcs = 0;
  double direct = 0; // arcs source -> sink: always saturated
  struct Arc { long u, v; double c; };
  std::vector<Arc> pending;
  std::string line;
  auto fail = [&](const std::string& what) {
    throw Input_error(path + ":" + std::to_string(line_number) + ": " + what);
  };
  while(std::getline(in, line)) {
    ++line_number;
    if(line.empty() || line[0] == 'c') continue;
    std::istringstream ls(line);
    char kind;
    ls >> kind;
    if(kind == 'p') {
      std::string problem;
      if(!(ls >> problem >> n >> m) || problem != "max" || n < 2 || m < 0) fail("expected 'p max NODES ARCS'");
    } else if(kind == 'n') {
      long id;
      char which;
      if(n < 0) fail("'n' line before the 'p max' line");
      if(!(ls >> id >> which) || id < 1 || id > n || (which != 's' && which != 't')) fail("expected 'n ID s' or 'n ID t'");
      (which == 's' ? s : t) = id;
    } else if(kind == 'a') {
      long u, v;
      double c;
      if(n < 0) fail("'a' line before the 'p max' line");
      if(!(ls >> u >> v >> c) || u < 1 || u > n || v < 1 || v > n) fail("expected 'a U V CAPACITY' with 1 <= U, V <= " + std::to_string(n));
      if(!(c >= 0) || !std::isfinite(c)) fail("capacities must be finite and >= 0");
      pending.push_back({u, v, c});
      ++arcs;
    } else {
      fail(std::string("unknown line type '") + kind + "'");
    }
  }
  if(n < 0) throw Input_error(path + ": no 'p max' line: not a DIMACS max-flow file");
  if(s < 0 || t < 0) throw Input_error(path + ": the source ('n ID s') or the sink ('n ID t') is missing");
  if(s == t) throw Input_error(path + ": the source and the sink are the same node");
  if(arcs != m) std::cerr << "mdcs mincut: warning: the 'p' line announces " << m << " arcs, the file has " << arcs << "\n";

  network.add_nodes(std::size_t(n));
  for(const Arc& a : pending) {
    if(a.u == a.v || a.v == s || a.u == t) continue; // cannot carry s-t flow
    if(a.u == s && a.v == t) direct += a.c;
    else if(a.u == s) network.add_source_facet(Network::Node_index(a.v - 1), a.c, 0);
    else if(a.v == t) network.add_sink_facet(Network::Node_index(a.u - 1), a.c, 0);
    else network.add_facet(Network::Node_index(a.u - 1), Network::Node_index(a.v - 1), a.c, 0, 0);
  }
  Mincut_report report;
  report.nodes = std::size_t(n);
  report.arcs = std::size_t(arcs);
  const auto t0 = std::chrono::steady_clock::now();
  const auto cut = engine == "bk"   ? CGAL::Min_cut::solve_min_cut(network, CGAL::Min_cut::Boykov_kolmogorov_max_flow())
                   : engine == "pr" ? CGAL::Min_cut::solve_min_cut(network, CGAL::Min_cut::Push_relabel_max_flow())
                                    : CGAL::Min_cut::solve_min_cut(network, CGAL::Min_cut::Pseudoflow_max_flow());
  report.seconds = seconds_since(t0);
  report.value = cut.value + direct;
  report.on_source_side = cut.on_source_side;
  report.on_source_side[std::size_t(s - 1)] = 1;
  report.on_source_side[std::size_t(t - 1)] = 0;
  for(char c : report.on_source_side) report.source_side += c ? 1 : 0;
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
