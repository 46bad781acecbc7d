// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bindings of Min_cut: a minimum s-t cut of a network given as arrays (interior edges with a capacity in each
// direction, terminal edges from the source and to the sink), with the engine of the caller's choice.

#include "common.h"

#include <CGAL/Min_cut.h>

#include <cmath>

namespace mdcs_python {
namespace {

namespace MC = CGAL::Min_cut;

// Capacities (k,) (the same both ways) or (k, 2) (forward, backward); >= 0, +inf allowed, never NaN.
std::vector<std::array<double, 2>> capacities_of(py::handle object, std::size_t k, const char* name)
{
  py::array probe = py::array::ensure(object);
  if(!probe) throw Value_error(std::string("mdcs: ") + name + " cannot be read as an array of numbers");
  const bool two = probe.ndim() == 2;
  const Double_array c = checked_doubles(object, name, two ? 2 : 1, two ? 2 : -1, false, two ? "(k, 2)" : "(k,)");
  if(std::size_t(c.shape(0)) != k)
    throw Value_error(std::string("mdcs: ") + name + " has " + std::to_string(c.shape(0)) + " rows for " +
                      std::to_string(k) + " edges");
  std::vector<std::array<double, 2>> out(k);
  for(std::size_t i = 0; i < k; ++i) {
    out[i] = two ? std::array<double, 2>{{c.data()[2 * i], c.data()[2 * i + 1]}}
                 : std::array<double, 2>{{c.data()[i], c.data()[i]}};
    for(double x : out[i])
      if(!(x >= 0))
        throw Value_error(std::string("mdcs: ") + name + " row " + std::to_string(i) +
                          " holds a negative or NaN capacity; capacities must be >= 0 (inf allowed)");
  }
  return out;
}

py::dict min_cut(std::size_t number_of_nodes, py::handle edges, py::handle capacities, py::handle source_nodes,
                 py::handle source_capacities, py::handle sink_nodes, py::handle sink_capacities,
                 const std::string& engine, py::object progress)
{
  if(number_of_nodes == 0) throw Value_error("mdcs: a network needs at least one node");
  if(number_of_nodes > MC::Flow_network<double>::max_number_of_nodes())
    throw Value_error("mdcs: too many nodes (32-bit node indices)");
  const std::int64_t n = std::int64_t(number_of_nodes);
  const Index_array E = checked_indices(edges, "edges", 2, 2, n, "(k, 2)", "nodes");
  const std::size_t k = std::size_t(E.shape(0));
  const auto cap = capacities_of(capacities, k, "capacities");
  const Index_array S = checked_indices(source_nodes, "source_nodes", 1, -1, n, "(s,)", "nodes");
  const Index_array T = checked_indices(sink_nodes, "sink_nodes", 1, -1, n, "(t,)", "nodes");
  auto terminal = [](py::handle c, std::size_t count, const char* name) {
    if(c.is_none()) return std::vector<double>(count, std::numeric_limits<double>::infinity());
    const Double_array a = checked_doubles(c, name, 1, -1, false, "(s,)");
    if(std::size_t(a.size()) != count)
      throw Value_error(std::string("mdcs: ") + name + " has " + std::to_string(a.size()) + " entries for " +
                        std::to_string(count) + " nodes");
    for(py::ssize_t i = 0; i < a.size(); ++i)
      if(!(a.data()[i] >= 0))
        throw Value_error(std::string("mdcs: ") + name + "[" + std::to_string(i) + "] must be >= 0 (inf allowed)");
    return std::vector<double>(a.data(), a.data() + a.size());
  };
  const std::vector<double> sc = terminal(source_capacities, std::size_t(S.size()), "source_capacities");
  const std::vector<double> tc = terminal(sink_capacities, std::size_t(T.size()), "sink_capacities");
  const std::size_t ids = k + std::size_t(S.size()) + std::size_t(T.size());
  if(ids > std::size_t(0xFFFFFFFFu)) throw Value_error("mdcs: too many edges (32-bit edge ids)");

  MC::Flow_network<double> network;
  network.reserve(number_of_nodes, k, std::size_t(S.size() + T.size()));
  network.add_nodes(number_of_nodes);
  for(std::size_t i = 0; i < k; ++i) {
    const std::int64_t u = E.data()[2 * i], v = E.data()[2 * i + 1];
    if(u == v) throw Value_error("mdcs: edges[" + std::to_string(i) + "] joins node " + std::to_string(u) + " to itself");
    network.add_facet(MC::Flow_network<double>::Node_index(u), MC::Flow_network<double>::Node_index(v), cap[i][0],
                      cap[i][1], std::uint32_t(i));
  }
  for(py::ssize_t i = 0; i < S.size(); ++i)
    network.add_source_facet(std::uint32_t(S.data()[i]), sc[std::size_t(i)], std::uint32_t(k + std::size_t(i)));
  for(py::ssize_t i = 0; i < T.size(); ++i)
    network.add_sink_facet(std::uint32_t(T.data()[i]), tc[std::size_t(i)],
                           std::uint32_t(k + std::size_t(S.size()) + std::size_t(i)));

  Progress_bridge bridge(progress);
  const MC::Min_cut_result<double> r = run_without_gil(bridge, [&] {
    if(engine == "pseudoflow") return MC::solve_min_cut(network, MC::Pseudoflow_max_flow(), std::ref(bridge));
    if(engine == "push_relabel") return MC::solve_min_cut(network, MC::Push_relabel_max_flow(), std::ref(bridge));
    if(engine == "boykov_kolmogorov") return MC::solve_min_cut(network, MC::Boykov_kolmogorov_max_flow(), std::ref(bridge));
    throw Value_error("mdcs: unknown engine '" + engine + "'; use 'pseudoflow', 'push_relabel' or 'boykov_kolmogorov'");
  });

  std::vector<std::uint8_t> side(r.on_source_side.begin(), r.on_source_side.end());
  std::vector<std::int64_t> cut_edges, cut_sources, cut_sinks;
  std::vector<std::uint8_t> forward;
  for(const auto& c : r.chain) {
    if(c.id < k) {
      cut_edges.push_back(c.id);
      forward.push_back(c.forward);
    } else if(c.id < k + std::size_t(S.size())) {
      cut_sources.push_back(std::int64_t(c.id - k));
    } else {
      cut_sinks.push_back(std::int64_t(c.id - k - std::size_t(S.size())));
    }
  }
  py::dict d;
  d["value"] = r.value;
  d["finite"] = r.is_finite;
  d["source_side"] = to_numpy(std::move(side));
  d["cut_edges"] = to_numpy(std::move(cut_edges));
  d["cut_forward"] = to_numpy(std::move(forward));
  d["cut_source_edges"] = to_numpy(std::move(cut_sources));
  d["cut_sink_edges"] = to_numpy(std::move(cut_sinks));
  return d;
}

} // namespace

void bind_min_cut(py::module_& m)
{
  py::module_ c = m.def_submodule("min_cut", "C++ core of mdcs.min_cut (use mdcs.min_cut)");
  c.def("min_cut", &min_cut, py::arg("number_of_nodes"), py::arg("edges"), py::arg("capacities"),
        py::arg("source_nodes"), py::arg("source_capacities"), py::arg("sink_nodes"), py::arg("sink_capacities"),
        py::arg("engine"), py::arg("progress"));
}

} // namespace mdcs_python
