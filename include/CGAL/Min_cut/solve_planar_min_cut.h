// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// solve_planar_min_cut(): the minimum s-t cut of a planar Flow_network with both terminals on the outer face,
// as a shortest path in its directed dual (Hassin 1981).

#ifndef CGAL_MIN_CUT_SOLVE_PLANAR_MIN_CUT_H
#define CGAL_MIN_CUT_SOLVE_PLANAR_MIN_CUT_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Min_cut/Flow_network.h>
#include <CGAL/Min_cut/Planar_dual.h>
#include <CGAL/Min_cut/Pseudoflow_max_flow.h>
#include <CGAL/Min_cut/internal/planar_dual_shortest_path.h>
#include <CGAL/Min_cut/solve_min_cut.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Min_cut {

/*!
  \ingroup PkgMinCutRef
  \brief Tag that selects `solve_planar_min_cut()` where a function takes a max-flow engine and can supply the
  planar dual of its network (e.g. `CGAL::Variational_minimization::minimize_curve_functional_2()`). It is not
  a `MaxFlowEngine`: it needs the embedding.
*/
struct Planar_min_cut
{};

/*!
  \ingroup PkgMinCutRef
  \brief Computes a minimum s-t cut of a planar `network` whose source and sink lie on the outer face, as a
  shortest path in the directed dual graph given by `dual`.

  **Why.** In a planar network with both terminals on the outer face, the s-t cuts are exactly the paths of the
  dual graph that cross the outer face from the source's part of its boundary to the sink's part, and a cut
  costs what its dual path is long (Hassin 1981; the shortest-path distances are also the potentials of a
  maximum flow). Crossing facet `(u, v)` from `u` to `v` is walking its dual edge `a -> b`, of length `c_uv`;
  walking `b -> a` costs `c_vu`; infinite capacities give no dual arc. Dijkstra's algorithm from
  `dual.start_vertices` to the nearest of `dual.end_vertices` then replaces the max-flow engine: O(m log m)
  for m facets, against the super-linear growth of the general engines on these networks (the duals of line
  arrangements, where pseudoflow grows as about n^1.55; doc/Min_cut/Min_cut.md has the table).

  **Result.** The same `Min_cut_result` as `solve_min_cut()`: the value, each node's side and the chain, in the
  same order. The source side is the union of the connected pieces, once the path's facets are removed, that
  hold an uncut source facet; when several minimum cuts exist, the one returned follows the path Dijkstra
  found, which need not be the minimal source side that the max-flow engines return. If no dual path avoids
  the infinite capacities, the constraints conflict: the result is `is_finite == false`, and its sides and
  chain are those of `solve_min_cut()` with `Pseudoflow_max_flow` (a cut through an infinite facet, to locate
  the conflict).

  **Checks.** The cut that the path stands for is verified against the network: every uncut facet must join
  two nodes on the same side, every cut facet two nodes on its two sides in the walked direction. A dual that
  is not an embedding of the network (wrong orientation, a missing boundary piece) is reported rather than
  answered. These checks make the result a valid cut whose capacity is the path length; its minimality rests
  on the planarity that `dual` describes.

  \tparam Capacity a floating-point type
  \tparam Progress a callable `bool(const char* stage, double fraction)`; stages `"dual-graph"`,
          `"shortest-path"` and `"sides"`. Returning `false` cancels.

  \throws std::invalid_argument when `dual` does not match `network` (sizes, indices, no start or end
          vertex, more dual vertices than twice the dual edges plus the start and end vertices), or when the path
          found does not separate the source from the sink in `network`
  \throws std::domain_error when the sum of the finite capacities overflows `Capacity`
  \throws CGAL::MDCS::Operation_cancelled when `progress` returns false
*/
template <class Capacity, class Progress = CGAL::MDCS::No_progress>
Min_cut_result<Capacity> solve_planar_min_cut(const Flow_network<Capacity>& network, const Planar_dual& dual,
                                              Progress progress = Progress())
{
  typedef CGAL::MDCS::internal::Progress_reporter<Progress> Reporter;
  // The same bound as the max-flow engines' (Max_flow_problem): path lengths are sums of finite capacities, and
  // their sum must be finite for a finite cut value to mean anything (1e308 + 1e308 made a "finite" cut of +inf).
  {
    const Capacity inf = Flow_network<Capacity>::infinity();
    Capacity finite_sum = 0;
    auto add = [&](Capacity c) {
      if(c != inf) finite_sum += c;
    };
    for(const auto& f : network.facets()) { add(f.c_uv); add(f.c_vu); }
    for(const auto& f : network.source_facets()) add(f.capacity);
    for(const auto& f : network.sink_facets()) add(f.capacity);
    if(!(std::abs(double(finite_sum)) <= double((std::numeric_limits<Capacity>::max)())))
      throw std::domain_error("MDCS: solve_planar_min_cut: the finite capacities are too large (their sum overflows "
                              "the capacity type); scale them down");
  }
  internal::Planar_dual_shortest_path<Capacity> search(network, dual);
  {
    Reporter report(progress, "dual-graph", network.number_of_facets());
    search.build_arcs(report);
    report.finish();
  }
  bool found = false;
  {
    Reporter report(progress, "shortest-path", dual.number_of_vertices);
    found = search.run(report);
    report.finish();
  }
  if(!found) // every cut crosses an infinite capacity: let a max-flow engine describe such a cut
    return solve_min_cut(network, Pseudoflow_max_flow());

  // Mark the cut facets: 1 = crossed u->v (or terminal facet cut), 2 = crossed v->u.
  const std::size_t n_interior = network.number_of_facets();
  const std::size_t n_source = network.number_of_source_facets();
  std::vector<char> interior_cut(n_interior, 0), source_cut(n_source, 0),
    sink_cut(network.number_of_sink_facets(), 0);
  for(std::uint32_t code : search.path_codes()) {
    const bool reversed = (code & internal::planar_reversed_bit) != 0;
    const std::size_t k = code & ~internal::planar_reversed_bit;
    if(k < n_interior) interior_cut[k] = reversed ? 2 : 1;
    else if(k < n_interior + n_source) source_cut[k - n_interior] = 1;
    else sink_cut[k - n_interior - n_source] = 1;
  }
  search.release();

  Reporter report(progress, "sides", 3);
  Min_cut_result<Capacity> result;
  const std::size_t n = network.number_of_nodes();
  {
    internal::Node_partition pieces(n);
    for(std::size_t k = 0; k < n_interior; ++k)
      if(!interior_cut[k]) pieces.unite(network.facet(k).u, network.facet(k).v);
    report(1);
    std::vector<char> piece_on_source_side(n, 0);
    for(std::size_t k = 0; k < n_source; ++k)
      if(!source_cut[k]) piece_on_source_side[pieces.find(network.source_facet(k).node)] = 1;
    result.on_source_side.resize(n);
    for(std::size_t i = 0; i < n; ++i)
      result.on_source_side[i] = piece_on_source_side[pieces.find(std::uint32_t(i))];
  }
  report(2);

  const std::vector<char>& side = result.on_source_side;
  auto mismatch = [](const char* what, std::size_t k) {
    throw std::invalid_argument(std::string("MDCS: solve_planar_min_cut: the planar dual does not match the "
                                            "network: the shortest dual path does not separate the source from "
                                            "the sink (") + what + " " + std::to_string(k) +
                                "); check the orientation of the dual edges and the start and end vertices");
  };
  Capacity value = 0;
  for(std::size_t k = 0; k < n_interior; ++k) {
    const auto& f = network.facet(k);
    if(interior_cut[k] == 0) continue; // same piece by construction
    const bool forward = interior_cut[k] == 1;
    if(side[forward ? f.u : f.v] != 1 || side[forward ? f.v : f.u] != 0) mismatch("interior facet", k);
    result.chain.push_back(Cut_facet{f.id, forward});
    value += forward ? f.c_uv : f.c_vu;
  }
  for(std::size_t k = 0; k < n_source; ++k) {
    const auto& f = network.source_facet(k);
    if(source_cut[k] && side[f.node] != 0) mismatch("source facet", k);
    if(source_cut[k]) {
      result.chain.push_back(Cut_facet{f.id, true});
      value += f.capacity;
    }
  }
  for(std::size_t k = 0; k < sink_cut.size(); ++k) {
    const auto& f = network.sink_facet(k);
    if(bool(sink_cut[k]) != bool(side[f.node])) mismatch("sink facet", k);
    if(sink_cut[k]) {
      result.chain.push_back(Cut_facet{f.id, true});
      value += f.capacity;
    }
  }
  report.finish();
  result.is_finite = true;
  result.value = value;
  return result;
}

} // namespace Min_cut
} // namespace CGAL

#endif // CGAL_MIN_CUT_SOLVE_PLANAR_MIN_CUT_H
