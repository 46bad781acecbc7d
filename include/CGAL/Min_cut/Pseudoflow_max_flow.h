// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// MaxFlowEngine model: Hochbaum's highest-label pseudoflow algorithm (HPF), first phase only.

#ifndef CGAL_MIN_CUT_PSEUDOFLOW_MAX_FLOW_H
#define CGAL_MIN_CUT_PSEUDOFLOW_MAX_FLOW_H

#include <CGAL/Min_cut/Flow_network.h>
#include <CGAL/Min_cut/internal/pseudoflow_solver.h>

#include <vector>

namespace CGAL {
namespace Min_cut {

/*!
  \ingroup PkgMinCutRef
  \brief Max-flow engine running the highest-label pseudoflow algorithm (HPF) of Hochbaum (2008),
  with FIFO buckets, as studied by Chandran and Hochbaum (2009). No Boost.

  \cgalModels `MaxFlowEngine`

  **Algorithm.** Every source and sink arc starts saturated, so each node starts with an excess
  (or a deficit) and no interior flow. The nodes form a forest of trees, each of which is *strong*
  (its root has excess) or *weak*. The strong root of highest label looks, in its tree, for a
  residual arc to a node one label lower; if it finds one it hangs its tree there and pushes its
  whole excess along the tree path to the other root, splitting the path wherever an arc saturates;
  otherwise its tree part of that label is relabelled. A gap in the labels, or a label above the
  number of nodes, proves that a tree can reach no weak node: it is frozen. When no strong tree is
  left the frozen trees form a minimum cut. Only this first phase runs (the cut does not need the
  flow itself); the engine then searches over residual arcs from the nodes with excess, which gives
  the same minimal source side as the other engines of this package (the nodes reachable from the
  source in the residual network of any maximum flow), and returns the capacity of that cut, which
  equals the maximum-flow value.

  **Complexity.** O(n^2 m) time in the worst case for this labelling variant (Hochbaum 2008), with n
  nodes and m arcs; it does not depend on the capacities, so it terminates with floating-point
  capacities too (pushes never create negative residuals: an arc that cannot take the whole excess
  is set to exactly 0). O(n + m) memory.

  **Why it suits closure-type networks.** On the duals of arrangements the terminals touch only the
  boundary cells, so augmenting paths are long and push-relabel moves excess one arc and one
  relabel at a time. Pseudoflow moves the whole excess of a tree along a tree path in one push and
  keeps the trees between rounds, so long paths are built once; Chandran and Hochbaum measured it
  fastest on such (closure, "vision", grid) instances.

  **Memory.** 16 bytes per arc (head and reverse index, 32-bit each, and a residual capacity, with
  `double`), two arcs per facet with a nonzero capacity, plus 53 bytes per node. The view's own
  copy of the terminal capacities is not counted.

  At most 2^32 - 3 nodes and 2^32 - 2 arcs (32-bit indices); beyond that it throws
  `std::invalid_argument`.
*/
class Pseudoflow_max_flow
{
public:
  template <class Capacity>
  Capacity operator()(const Max_flow_problem<Capacity>& problem, std::vector<char>& on_source_side) const
  {
    internal::Pseudoflow_solver<Capacity> solver(problem);
    return solver.run(on_source_side);
  }
};

} // namespace Min_cut
} // namespace CGAL

#endif // CGAL_MIN_CUT_PSEUDOFLOW_MAX_FLOW_H
