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
#include <utility>
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

// Builds a Contracted_network from the facets of the full network, given one by one in the interface of
// Flow_network (add_facet, add_source_facet, add_sink_facet), so that the full network need not exist. A producer
// can ask first whether a facet matters (needs_*): a facet between two nodes merged into the same terminal, a
// source arc into a node merged into the source and a sink arc out of a node merged into the sink change no cut, so
// their capacities need not even be computed.
template <class Capacity>
class Terminal_contraction
{
  typedef CGAL::Min_cut::Flow_network<Capacity> Network;

public:
  typedef std::uint32_t Node_index;
  typedef std::uint32_t Facet_index;

  explicit Terminal_contraction(const std::vector<char>& label) : label_(label)
  {
    const std::uint32_t none = (std::numeric_limits<std::uint32_t>::max)();
    out_.node.assign(label.size(), none);
    std::uint32_t kept = 0;
    for(std::size_t i = 0; i < label.size(); ++i)
      if(label[i] == 0) out_.node[i] = kept++;
    out_.network.add_nodes(kept);
  }

  void reserve(std::size_t facets, std::size_t terminal_facets) { out_.network.reserve(0, facets, terminal_facets); }

  bool needs_facet(Node_index u, Node_index v) const { return label_[u] == 0 || label_[u] != label_[v]; }
  bool needs_source_facet(Node_index n) const { return label_[n] != 1; }
  bool needs_sink_facet(Node_index n) const { return label_[n] != 2; }

  void add_facet(Node_index u, Node_index v, Capacity c_uv, Capacity c_vu, Facet_index id)
  {
    const char lu = label_[u], lv = label_[v];
    if(lu == 0 && lv == 0) out_.network.add_facet(out_.node[u], out_.node[v], c_uv, c_vu, id);
    else if(lu == lv) return;
    else if(lu == 0) { // v is a terminal
      if(lv == 1) { if(c_vu > 0) out_.network.add_source_facet(out_.node[u], c_vu, id); }
      else if(c_uv > 0) out_.network.add_sink_facet(out_.node[u], c_uv, id);
    } else if(lv == 0) { // u is a terminal
      if(lu == 1) { if(c_uv > 0) out_.network.add_source_facet(out_.node[v], c_uv, id); }
      else if(c_vu > 0) out_.network.add_sink_facet(out_.node[v], c_vu, id);
    } else if(lu == 1) always(c_uv, id); // u source, v sink
    else always(c_vu, id);               // u sink, v source
  }

  void add_source_facet(Node_index n, Capacity c, Facet_index id)
  {
    if(label_[n] == 0) out_.network.add_source_facet(out_.node[n], c, id);
    else if(label_[n] == 2) always(c, id);
  }

  void add_sink_facet(Node_index n, Capacity c, Facet_index id)
  {
    if(label_[n] == 0) out_.network.add_sink_facet(out_.node[n], c, id);
    else if(label_[n] == 1) always(c, id);
  }

  Contracted_network<Capacity> release() { return std::move(out_); }

private:
  // An arc that always crosses the cut (source side -> sink side).
  void always(Capacity c, Facet_index id)
  {
    if(c == Network::infinity()) out_.is_finite = false;
    else if(c > 0) {
      out_.constant += c;
      out_.constant_facets.push_back(id);
    }
  }

  const std::vector<char>& label_;
  Contracted_network<Capacity> out_;
};

template <class Capacity>
Contracted_network<Capacity> contract_terminal_nodes(const CGAL::Min_cut::Flow_network<Capacity>& full,
                                                     const std::vector<char>& label)
{
  typedef CGAL::Min_cut::Flow_network<Capacity> Network;
  Terminal_contraction<Capacity> out(label);
  out.reserve(full.number_of_facets(), full.number_of_source_facets() + full.number_of_sink_facets());
  for(const typename Network::Facet& f : full.facets()) out.add_facet(f.u, f.v, f.c_uv, f.c_vu, f.id);
  for(const typename Network::Terminal_facet& t : full.source_facets()) out.add_source_facet(t.node, t.capacity, t.id);
  for(const typename Network::Terminal_facet& t : full.sink_facets()) out.add_sink_facet(t.node, t.capacity, t.id);
  return out.release();
}

} // namespace internal
} // namespace Min_cut
} // namespace CGAL

#endif // CGAL_MIN_CUT_INTERNAL_CONTRACT_TERMINAL_NODES_H
