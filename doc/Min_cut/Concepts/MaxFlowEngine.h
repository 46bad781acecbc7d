/*!
\ingroup PkgMinCutConcepts
\cgalConcept

A max-flow engine computes a maximum s-t flow of the network described by a `CGAL::Min_cut::Max_flow_problem`
and the minimal source side of a minimum cut. `CGAL::Min_cut::solve_min_cut()` calls it once, then derives the
cut value and the primal chain from the sides.

The input is a plain read-only view, independent of Boost: the number of nodes, per node the summed capacity
of the arcs source -> node and node -> sink, and the list of arc pairs (u, v, c_uv, c_vu). Infinite capacities
are already replaced by a finite bound M (`infinite_capacity()`), larger than the capacity of any finite cut.
So an external code (Kolmogorov's maxflow library, EIBFS, a GPU solver) is wrapped by copying the view into its
own structure: one node per view node, a terminal edge per node, an edge pair per arc pair.

\cgalHasModel `CGAL::Min_cut::Push_relabel_max_flow` (the default)
\cgalHasModel `CGAL::Min_cut::Boykov_kolmogorov_max_flow`
*/
class MaxFlowEngine
{
public:
  /*!
    Computes the maximum flow value and resizes `on_source_side` to `problem.number_of_nodes()`, setting
    `on_source_side[n]` to 1 exactly when node `n` is reachable from the source in the residual network of a
    maximum flow (the minimal source side, the same for every correct engine), and to 0 otherwise.
  */
  template <class Capacity>
  Capacity operator()(const CGAL::Min_cut::Max_flow_problem<Capacity>& problem, std::vector<char>& on_source_side);
};
