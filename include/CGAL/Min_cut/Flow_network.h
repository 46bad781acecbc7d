// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The flow network of the min-cut duality: nodes are the cells of an embedded complex, every facet
// between two cells is a pair of opposite arcs with independent capacities, every facet on the
// boundary of the complex is an arc to or from a terminal. Also the read-only view of such a network
// that max-flow engines receive (concept MaxFlowEngine, see doc/Min_cut/Min_cut.md).

#ifndef CGAL_MIN_CUT_FLOW_NETWORK_H
#define CGAL_MIN_CUT_FLOW_NETWORK_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Min_cut {

/*!
  \ingroup PkgMinCutRef
  \brief A directed flow network whose nodes are the cells of a complex and whose arcs come from its facets.

  - An *interior facet* between cells `u` and `v` is a pair of opposite arcs with independent
    capacities: cutting `u->v` (u on the source side, v on the sink side) costs `c_uv`, cutting `v->u`
    costs `c_vu`. Either may be `0` or `infinity()`; an infinite reverse capacity forbids the cut in that
    direction, which is how "the chain must stay a function" is expressed.
  - An *exterior facet* is an arc from the source to a node (`add_source_facet()`) or from a node to the
    sink (`add_sink_facet()`). An infinite capacity ties the node to that terminal. Boundary facets
    that a relaxed boundary condition removes are simply not added.

  Every facet carries the caller's id of the primal facet, which `solve_min_cut()` hands back in the chain.
  The network stores only the node count and the facets (no per-node storage), so nodes are cheap.

  \tparam Capacity_ a floating-point type (`float`, `double`, `long double`): infinity must be representable.
*/
template <class Capacity_ = double>
class Flow_network
{
  static_assert(std::is_floating_point<Capacity_>::value,
                "CGAL::Min_cut::Flow_network: the capacity type must be a floating-point type "
                "(infinite capacities are part of the interface)");

public:
  typedef Capacity_ Capacity;
  typedef std::uint32_t Node_index;
  typedef std::uint32_t Facet_index;

  /// An interior facet: arcs `u->v` (capacity `c_uv`) and `v->u` (capacity `c_vu`).
  struct Facet
  {
    Node_index u, v;
    Capacity c_uv, c_vu;
    Facet_index id;
  };

  /// An exterior facet: an arc source->`node` (source facets) or `node`->sink (sink facets).
  struct Terminal_facet
  {
    Node_index node;
    Capacity capacity;
    Facet_index id;
  };

  /// The most nodes a network may have. Two 32-bit indices stay free for the terminals that the
  /// engines add, so that every vertex of the max-flow graph has a 32-bit index.
  static constexpr std::size_t max_number_of_nodes() { return std::size_t(0xFFFFFFFFu) - 1; }

  static Capacity infinity() { return std::numeric_limits<Capacity>::infinity(); }

  void reserve(std::size_t nodes, std::size_t facets, std::size_t terminal_facets)
  {
    // Nodes have no storage of their own; the argument is accepted for symmetry with the builders.
    (void)nodes;
    facets_.reserve(facets);
    // The split between source and sink facets is unknown; boundaries are usually shared evenly.
    source_facets_.reserve(terminal_facets / 2 + 1);
    sink_facets_.reserve(terminal_facets / 2 + 1);
  }

  /// Adds `n` nodes and returns the index of the first one.
  Node_index add_nodes(std::size_t n)
  {
    if(n > max_number_of_nodes() - number_of_nodes_)
      throw std::invalid_argument("MDCS: Flow_network::add_nodes: a network has at most 2^32 - 2 nodes (32-bit "
                                  "node indices); " + std::to_string(number_of_nodes_) + " + " +
                                  std::to_string(n) + " requested");
    const Node_index first = Node_index(number_of_nodes_);
    number_of_nodes_ += n;
    return first;
  }

  std::size_t number_of_nodes() const { return number_of_nodes_; }

  /// Adds the interior facet `id` between cells `u` and `v`: cutting `u->v` costs `c_uv`, cutting `v->u` costs `c_vu`.
  void add_facet(Node_index u, Node_index v, Capacity c_uv, Capacity c_vu, Facet_index id)
  {
    check_node(u, "add_facet");
    check_node(v, "add_facet");
    if(u == v)
      throw std::invalid_argument("MDCS: Flow_network::add_facet: facet " + std::to_string(id) +
                                  " joins node " + std::to_string(u) + " to itself (u == v)");
    check_capacity(c_uv, "add_facet", id);
    check_capacity(c_vu, "add_facet", id);
    facets_.push_back(Facet{u, v, c_uv, c_vu, id});
  }

  /// Adds the exterior facet `id`: an arc from the source to `n`. `infinity()` ties `n` to the source side.
  void add_source_facet(Node_index n, Capacity c, Facet_index id)
  {
    check_node(n, "add_source_facet");
    check_capacity(c, "add_source_facet", id);
    source_facets_.push_back(Terminal_facet{n, c, id});
  }

  /// Adds the exterior facet `id`: an arc from `n` to the sink. `infinity()` ties `n` to the sink side.
  void add_sink_facet(Node_index n, Capacity c, Facet_index id)
  {
    check_node(n, "add_sink_facet");
    check_capacity(c, "add_sink_facet", id);
    sink_facets_.push_back(Terminal_facet{n, c, id});
  }

  std::size_t number_of_facets() const { return facets_.size(); }
  std::size_t number_of_source_facets() const { return source_facets_.size(); }
  std::size_t number_of_sink_facets() const { return sink_facets_.size(); }

  const Facet& facet(std::size_t i) const { return facets_[i]; }
  const Terminal_facet& source_facet(std::size_t i) const { return source_facets_[i]; }
  const Terminal_facet& sink_facet(std::size_t i) const { return sink_facets_[i]; }

  const std::vector<Facet>& facets() const { return facets_; }
  const std::vector<Terminal_facet>& source_facets() const { return source_facets_; }
  const std::vector<Terminal_facet>& sink_facets() const { return sink_facets_; }

  /// Removes every node and facet.
  void clear()
  {
    number_of_nodes_ = 0;
    facets_.clear();
    source_facets_.clear();
    sink_facets_.clear();
  }

private:
  void check_node(Node_index n, const char* function) const
  {
    if(n >= number_of_nodes_)
      throw std::invalid_argument(std::string("MDCS: Flow_network::") + function + ": node index " +
                                  std::to_string(n) + " is out of range (the network has " +
                                  std::to_string(number_of_nodes_) + " nodes)");
  }

  static void check_capacity(Capacity c, const char* function, Facet_index id)
  {
    // Written as !(c >= 0) so that NaN is rejected too.
    if(!(c >= Capacity(0)))
      throw std::invalid_argument(std::string("MDCS: Flow_network::") + function + ": facet " +
                                  std::to_string(id) + " has capacity " + std::to_string(double(c)) +
                                  "; capacities must be >= 0 (or infinity()) and not NaN");
  }

  std::size_t number_of_nodes_ = 0;
  std::vector<Facet> facets_;
  std::vector<Terminal_facet> source_facets_;
  std::vector<Terminal_facet> sink_facets_;
};

/*!
  \ingroup PkgMinCutRef
  \brief The read-only view of a `Flow_network` that a `MaxFlowEngine` receives.

  It has no infinite capacity left: every infinite capacity reads as the finite bound
  `infinite_capacity() = M = 1 + 2 * (sum of all finite capacities)`. Any cut that avoids the infinite
  arcs costs at most half of `M`, so a minimum cut crosses an arc of capacity `M` exactly when no finite
  cut exists, and then the maximum flow is at least `M`.

  Per node, the capacities of its source facets are summed into `source_capacity()`, those of its sink
  facets into `sink_capacity()` (a node with an infinite terminal facet reads `M`). Interior facets are
  visible one by one as arc pairs, in insertion order, unchanged apart from the infinities; a pair may
  have two zero capacities and parallel pairs may occur.

  The view is independent of Boost: an engine can feed it to any max-flow code (one `add_node`, then
  per node its two terminal capacities, per pair `add_edge(u, v, c_uv, c_vu)`).
  The view refers to the network, which must outlive it and stay unchanged.
*/
template <class Capacity_>
class Max_flow_problem
{
public:
  typedef Capacity_ Capacity;
  typedef std::uint32_t Node_index;

  struct Arc_pair
  {
    Node_index u, v;
    Capacity c_uv, c_vu;
  };

  /// \throws std::domain_error if the finite capacities are so large that `M` (or the total flow
  /// that `M` can carry) is not representable in `Capacity`.
  explicit Max_flow_problem(const Flow_network<Capacity>& network)
    : network_(&network)
  {
    const Capacity inf = Flow_network<Capacity>::infinity();
    Capacity finite_sum = 0;
    std::size_t infinite_arcs = 0;
    auto add = [&](Capacity c) {
      if(c == inf) ++infinite_arcs;
      else finite_sum += c;
    };
    for(const auto& f : network.facets()) { add(f.c_uv); add(f.c_vu); }
    for(const auto& f : network.source_facets()) add(f.capacity);
    for(const auto& f : network.sink_facets()) add(f.capacity);

    bound_ = Capacity(1) + Capacity(2) * finite_sum;
    // The flow through the network is at most the sum of all capacities, each infinite one read as M;
    // that sum must stay finite for the engines' arithmetic (and for "flow >= M") to mean anything.
    const Capacity total = finite_sum + Capacity(infinite_arcs + 1) * bound_;
    if(!std::isfinite(double(bound_)) || !(std::abs(total) <= std::numeric_limits<Capacity>::max()))
      throw std::domain_error("MDCS: solve_min_cut: the finite capacities are too large (their sum, or the "
                              "bound that replaces infinite capacities, overflows the capacity type); "
                              "scale them down");

    source_capacity_.assign(network.number_of_nodes(), Capacity(0));
    sink_capacity_.assign(network.number_of_nodes(), Capacity(0));
    // One infinite terminal facet is enough to tie a node, so a node's sum is capped at M: larger
    // values only cost precision in the engines.
    for(const auto& f : network.source_facets())
      source_capacity_[f.node] = (std::min)(bound_, source_capacity_[f.node] + finite(f.capacity));
    for(const auto& f : network.sink_facets())
      sink_capacity_[f.node] = (std::min)(bound_, sink_capacity_[f.node] + finite(f.capacity));
  }

  std::size_t number_of_nodes() const { return network_->number_of_nodes(); }

  /// Summed capacity of the arcs source->`n` (0 if none).
  Capacity source_capacity(Node_index n) const { return source_capacity_[n]; }

  /// Summed capacity of the arcs `n`->sink (0 if none).
  Capacity sink_capacity(Node_index n) const { return sink_capacity_[n]; }

  std::size_t number_of_arc_pairs() const { return network_->number_of_facets(); }

  /// The arc pair of the `k`-th interior facet, infinities replaced by `infinite_capacity()`.
  Arc_pair arc_pair(std::size_t k) const
  {
    const auto& f = network_->facet(k);
    return Arc_pair{f.u, f.v, finite(f.c_uv), finite(f.c_vu)};
  }

  /// The bound `M` that stands for an infinite capacity.
  Capacity infinite_capacity() const { return bound_; }

  const Flow_network<Capacity>& network() const { return *network_; }

private:
  Capacity finite(Capacity c) const { return c == Flow_network<Capacity>::infinity() ? bound_ : c; }

  const Flow_network<Capacity>* network_;
  Capacity bound_ = 1;
  std::vector<Capacity> source_capacity_, sink_capacity_;
};

} // namespace Min_cut
} // namespace CGAL

#endif // CGAL_MIN_CUT_FLOW_NETWORK_H
