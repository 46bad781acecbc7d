// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Contraction of the nodes tied to a terminal: a smaller flow network with the same minimum cuts. Adaptive
// refinement of minimal surfaces uses it (thesis ch. 2.7, "cells above/below the envelope merged into sink/source").
#ifndef CGAL_MIN_CUT_INTERNAL_CONTRACT_TERMINAL_NODES_H
#define CGAL_MIN_CUT_INTERNAL_CONTRACT_TERMINAL_NODES_H

#include <CGAL/Min_cut/Flow_network.h>

#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Min_cut {
namespace internal {

// The network with every node of label 1 merged into the source and every node of label 2 into the sink (label
// 0: kept). An arc between two merged nodes of the same terminal disappears; an arc from the source side to the
// sink side is cut by every cut: its capacity goes to `constant` and its facet to `constant_facets` (an infinite
// one makes every cut infinite: `is_finite` false). A minimum cut of `network` plus `constant` is a minimum cut of
// the original network with the labelled nodes tied to their terminal by infinite arcs, with the same facets.
template <class Capacity>
struct Contracted_network
{
  CGAL::Min_cut::Flow_network<Capacity> network;
  std::vector<std::uint32_t> node;  // per original node: its new index, or a terminal (null)
  Capacity constant = 0;
  std::vector<std::uint32_t> constant_facets;
  bool is_finite = true;
};

template <class Capacity>
Contracted_network<Capacity> contract_terminal_nodes(const CGAL::Min_cut::Flow_network<Capacity>& full,
                                                         const std::vector<char>& label)
{
  typedef CGAL::Min_cut::Flow_network<Capacity> Network;
  const std::uint32_t none = (std::numeric_limits<std::uint32_t>::max)();
  const Capacity inf = Network::infinity();
  Contracted_network<Capacity> out;
  out.node.assign(full.number_of_nodes(), none);
  std::uint32_t kept = 0;
  for(std::size_t i = 0; i < label.size(); ++i)
    if(label[i] == 0) out.node[i] = kept++;
  out.network.reserve(kept, full.number_of_facets(), full.number_of_source_facets() + full.number_of_sink_facets());
  out.network.add_nodes(kept);
  // An arc that always crosses the cut (source side -> sink side).
  auto always = [&](Capacity c, std::uint32_t id) {
    if(c == inf) out.is_finite = false;
    else if(c > 0) {
      out.constant += c;
      out.constant_facets.push_back(id);
    }
  };
  for(const typename Network::Facet& f : full.facets()) {
    const char lu = label[f.u], lv = label[f.v];
    if(lu == 0 && lv == 0) out.network.add_facet(out.node[f.u], out.node[f.v], f.c_uv, f.c_vu, f.id);
    else if(lu == lv) continue;
    else if(lu == 0) { // v is a terminal
      if(lv == 1) { if(f.c_vu > 0) out.network.add_source_facet(out.node[f.u], f.c_vu, f.id); }
      else if(f.c_uv > 0) out.network.add_sink_facet(out.node[f.u], f.c_uv, f.id);
    } else if(lv == 0) { // u is a terminal
      if(lu == 1) { if(f.c_uv > 0) out.network.add_source_facet(out.node[f.v], f.c_uv, f.id); }
      else if(f.c_vu > 0) out.network.add_sink_facet(out.node[f.v], f.c_vu, f.id);
    } else if(lu == 1) always(f.c_uv, f.id); // u source, v sink
    else always(f.c_vu, f.id);               // u sink, v source
  }
  for(const typename Network::Terminal_facet& t : full.source_facets()) {
    if(label[t.node] == 0) out.network.add_source_facet(out.node[t.node], t.capacity, t.id);
    else if(label[t.node] == 2) always(t.capacity, t.id);
  }
  for(const typename Network::Terminal_facet& t : full.sink_facets()) {
    if(label[t.node] == 0) out.network.add_sink_facet(out.node[t.node], t.capacity, t.id);
    else if(label[t.node] == 1) always(t.capacity, t.id);
  }
  return out;
}

} // namespace internal
} // namespace Min_cut
} // namespace CGAL

#endif // CGAL_MIN_CUT_INTERNAL_CONTRACT_TERMINAL_NODES_H
