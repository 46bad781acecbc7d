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
  \brief Max-flow engine running Boost.Graph's push-relabel algorithm (highest label, global and gap
  relabelling; the algorithm of `boost::push_relabel_max_flow`).

  \cgalModels `MaxFlowEngine`

  The problem is copied into the same 32-bit `boost::compressed_sparse_row_graph` as for
  `Boykov_kolmogorov_max_flow`, except that every positive capacity gets an arc of its own with a
  zero-capacity reverse arc, as push-relabel requires: its second phase (turning the maximum preflow
  into a flow) sends excess back only along arcs of capacity 0.
  The source side is then found by a search from the source over arcs with residual capacity > 0:
  the minimal source side of a minimum cut, the same as `Boykov_kolmogorov_max_flow` returns.

  Implementation note: `boost::push_relabel_max_flow()` ends with `BOOST_ASSERT(is_flow())`, a check
  that compares floating-point sums of flows for exact equality. Rounding makes it fail on almost
  every network with non-integer capacities (every random 30x30 grid we tried), which aborts any
  program built without `NDEBUG`. This engine therefore runs the two phases of the class that
  `boost::push_relabel_max_flow()` wraps (`boost::detail::push_relabel`, unchanged since Boost 1.3x)
  itself and skips that check; the cut is then read from the residual capacities, where rounding
  leaves at most a relative error of the order of the machine epsilon times the number of arcs.
*/
class Push_relabel_max_flow
{
public:
  template <class Capacity>
  Capacity operator()(const Max_flow_problem<Capacity>& problem, std::vector<char>& on_source_side) const
  {
    typedef internal::Csr_flow_graph<Capacity> Flow_graph;
    typedef typename Flow_graph::Graph Graph;

    Flow_graph network(problem, internal::Reverse_arc_policy::split);
    boost::detail::push_relabel<Graph, typename Flow_graph::Capacity_map, typename Flow_graph::Capacity_map,
                                internal::Reverse_arc_map, typename Flow_graph::Vertex_index_map, Capacity>
      algorithm(network.graph(), network.capacity_map(), network.residual_capacity_map(),
                network.reverse_arc_map(), network.source(), network.sink(), network.vertex_index_map());
    const Capacity flow = algorithm.maximum_preflow();
    // The preflow's residual network does not determine the minimal source side (excess still
    // sits in nodes); the flow does.
    algorithm.convert_preflow_to_flow();
    network.source_side_by_residual_search(on_source_side);
    return flow;
  }
};

} // namespace Min_cut
} // namespace CGAL

#endif // CGAL_MIN_CUT_PUSH_RELABEL_MAX_FLOW_H
