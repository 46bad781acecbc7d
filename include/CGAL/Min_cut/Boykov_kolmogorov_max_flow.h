// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// MaxFlowEngine model: Boost.Graph's Boykov-Kolmogorov algorithm on a 32-bit CSR graph.

#ifndef CGAL_MIN_CUT_BOYKOV_KOLMOGOROV_MAX_FLOW_H
#define CGAL_MIN_CUT_BOYKOV_KOLMOGOROV_MAX_FLOW_H

#include <CGAL/Min_cut/Flow_network.h>
#include <CGAL/Min_cut/internal/Csr_flow_graph.h>

#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#include <boost/graph/properties.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstdint>
#include <vector>

namespace CGAL {
namespace Min_cut {

/*!
  \ingroup PkgMinCutRef
  \brief Max-flow engine running `boost::boykov_kolmogorov_max_flow`.

  \cgalModels `MaxFlowEngine`

  The problem is copied into a `boost::compressed_sparse_row_graph` with 32-bit vertex and edge
  indices, a source and a sink vertex, and for every facet two opposite arcs that are each other's
  reverse and carry the two capacities (Boykov-Kolmogorov accepts capacity on reverse arcs).
  Boost colours the source search tree black, the sink tree white and free vertices gray.

  The returned source side is the set of nodes reachable from the source in the final residual
  network, the minimal source side of a minimum cut. It is exactly Boost's black set: when the
  algorithm stops, the source tree is closed under residual arcs and every tree node hangs on a
  residual path from the source (checked against a residual search by test_engines.cpp). White and gray
  nodes are on the sink side. Both engines of this package therefore return the same sides.
*/
class Boykov_kolmogorov_max_flow
{
public:
  template <class Capacity>
  Capacity operator()(const Max_flow_problem<Capacity>& problem, std::vector<char>& on_source_side) const
  {
    typedef internal::Csr_flow_graph<Capacity> Flow_graph;
    typedef typename Flow_graph::edge_descriptor edge_descriptor;

    Flow_graph network(problem);
    const std::size_t nv = num_vertices(network.graph());
    std::vector<edge_descriptor> predecessor(nv);
    std::vector<boost::default_color_type> colour(nv);
    std::vector<std::uint32_t> distance(nv);
    const auto index = network.vertex_index_map();

    const Capacity flow = boost::boykov_kolmogorov_max_flow(
      network.graph(), network.capacity_map(), network.residual_capacity_map(), network.reverse_arc_map(),
      boost::make_iterator_property_map(predecessor.begin(), index),
      boost::make_iterator_property_map(colour.begin(), index),
      boost::make_iterator_property_map(distance.begin(), index), index, network.source(), network.sink());

    const std::size_t n = problem.number_of_nodes();
    on_source_side.assign(n, 0);
    for(std::size_t i = 0; i < n; ++i)
      on_source_side[i] = colour[i] == boost::black_color ? 1 : 0;
    return flow;
  }
};

} // namespace Min_cut
} // namespace CGAL

#endif // CGAL_MIN_CUT_BOYKOV_KOLMOGOROV_MAX_FLOW_H
