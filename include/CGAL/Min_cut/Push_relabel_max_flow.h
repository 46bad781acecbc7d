// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// MaxFlowEngine model: Boost.Graph's push-relabel algorithm on a 32-bit CSR graph.

#ifndef CGAL_MIN_CUT_PUSH_RELABEL_MAX_FLOW_H
#define CGAL_MIN_CUT_PUSH_RELABEL_MAX_FLOW_H

#include <CGAL/Min_cut/Flow_network.h>
#include <CGAL/Min_cut/internal/Csr_flow_graph.h>

#include <boost/graph/push_relabel_max_flow.hpp>

#include <vector>

namespace CGAL {
namespace Min_cut {

/*!
  \ingroup PkgMinCutRef
  \brief Max-flow engine running Boost.Graph's push-relabel algorithm (highest label first, with
  global and gap relabelling: the algorithm behind `boost::push_relabel_max_flow`).

  \cgalModels `MaxFlowEngine`

  The problem is copied into the same 32-bit `boost::compressed_sparse_row_graph` as for
  `Boykov_kolmogorov_max_flow` (one arc per direction of a facet, each the other's reverse).
  Only the first phase of push-relabel runs: it yields a maximum *preflow*, whose flow value is
  the excess at the sink. The source side is then found by a search over arcs with residual
  capacity > 0 that starts from the source and from every node left with excess. This is the
  minimal source side of a minimum cut, the same set as `Boykov_kolmogorov_max_flow` returns:
  for any minimum cut (S, T) the preflow value equals cap(S, T), which forces every excess node
  into S and leaves no residual arc from S to T, so the search stays inside S; and the searched
  set is itself a cut whose capacity is the flow value.

  Why not `boost::push_relabel_max_flow()` itself:
  - its second phase (preflow to flow) returns excess only along arcs of capacity 0, so it needs a
    zero-capacity twin for every arc (twice the arcs of a two-way facet), and the cut does not
    need that phase at all (above);
  - it ends with `BOOST_ASSERT(is_flow())`, which compares floating-point sums for exact equality:
    rounding makes it fail on nearly every network with non-integer capacities (every random
    30x30 grid we tried), aborting programs built without `NDEBUG`.
  The engine therefore runs the preflow phase of the class that function wraps,
  `boost::detail::push_relabel` (unchanged since Boost 1.3x), directly.
*/
class Push_relabel_max_flow
{
public:
  template <class Capacity>
  Capacity operator()(const Max_flow_problem<Capacity>& problem, std::vector<char>& on_source_side) const
  {
    typedef internal::Csr_flow_graph<Capacity> Flow_graph;
    typedef typename Flow_graph::Graph Graph;

    Flow_graph network(problem);
    boost::detail::push_relabel<Graph, typename Flow_graph::Capacity_map, typename Flow_graph::Capacity_map,
                                internal::Reverse_arc_map, typename Flow_graph::Vertex_index_map, Capacity>
      algorithm(network.graph(), network.capacity_map(), network.residual_capacity_map(),
                network.reverse_arc_map(), network.source(), network.sink(), network.vertex_index_map());
    const Capacity flow = algorithm.maximum_preflow();
    network.source_side_by_residual_search(on_source_side, &algorithm.excess_flow_data);
    return flow;
  }
};

} // namespace Min_cut
} // namespace CGAL

#endif // CGAL_MIN_CUT_PUSH_RELABEL_MAX_FLOW_H
