// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one place where a Max_flow_problem becomes a Boost.Graph residual network: a
// compressed_sparse_row_graph with 32-bit vertex and edge indices, a source and a sink vertex,
// every arc next to its reverse arc, and the property maps that Boost's max-flow algorithms read.

#ifndef CGAL_MIN_CUT_INTERNAL_CSR_FLOW_GRAPH_H
#define CGAL_MIN_CUT_INTERNAL_CSR_FLOW_GRAPH_H

#include <CGAL/Min_cut/Flow_network.h>

#include <CGAL/assertions.h>

#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Min_cut {
namespace internal {

typedef boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, boost::no_property,
                                           boost::no_property, std::uint32_t, std::uint32_t>
  Csr_graph;

// Reverse-arc map computed on the fly: the reverse of u->v starts at v = target(e) and its index is
// stored, so one 32-bit index per arc replaces a stored edge descriptor (two indices).
class Reverse_arc_map
{
public:
  typedef boost::graph_traits<Csr_graph>::edge_descriptor key_type;
  typedef key_type value_type;
  typedef key_type reference;
  typedef boost::readable_property_map_tag category;

  Reverse_arc_map() = default;
  Reverse_arc_map(const Csr_graph* graph, const std::uint32_t* reverse) : graph_(graph), reverse_(reverse) {}

  friend value_type get(const Reverse_arc_map& map, const key_type& e)
  {
    return value_type(target(e, *map.graph_), map.reverse_[e.idx]);
  }

private:
  const Csr_graph* graph_ = nullptr;
  const std::uint32_t* reverse_ = nullptr;
};

// The arcs of the residual network in CSR order, with capacities, residual capacities and reverse arcs.
// Vertices 0..n-1 are the nodes of the problem, n is the source and n+1 the sink. An arc pair
// (u, v, c_uv, c_vu) becomes two arcs, each the other's reverse, carrying c_uv and c_vu: both
// Boykov-Kolmogorov and the push-relabel preflow phase accept capacity on reverse arcs, and this
// halves the arcs of two-way facets compared with giving every capacity its own zero-capacity twin.
// A terminal capacity becomes an arc with a zero-capacity reverse arc.
template <class Capacity>
class Csr_flow_graph
{
public:
  typedef Csr_graph Graph;
  typedef boost::graph_traits<Graph>::vertex_descriptor vertex_descriptor;
  typedef boost::graph_traits<Graph>::edge_descriptor edge_descriptor;
  typedef boost::property_map<Graph, boost::edge_index_t>::const_type Edge_index_map;
  typedef boost::property_map<Graph, boost::vertex_index_t>::const_type Vertex_index_map;
  typedef boost::iterator_property_map<Capacity*, Edge_index_map, Capacity, Capacity&> Capacity_map;

  explicit Csr_flow_graph(const Max_flow_problem<Capacity>& problem)
  {
    const std::size_t n = problem.number_of_nodes();
    // The terminals take indices n and n + 1, and Boost's CSR construction computes the vertex
    // count plus one in the 32-bit vertex type: n + 3 must fit.
    if(n > std::size_t(std::numeric_limits<std::uint32_t>::max()) - 3)
      throw std::invalid_argument("MDCS: the Boost.Graph max-flow engines handle at most 2^32 - 4 nodes "
                                  "(32-bit vertex indices); the network has " + std::to_string(n));
    source_ = vertex_descriptor(n);
    sink_ = vertex_descriptor(n + 1);
    const std::size_t nv = n + 2;

    // Pass 1: out-degrees. Counted in 64 bits to detect arc counts beyond 32-bit edge indices.
    std::vector<std::uint64_t> degree(nv + 1, 0);
    auto count_pair = [&](std::size_t a, std::size_t b) { ++degree[a]; ++degree[b]; };
    for(std::size_t i = 0; i < n; ++i) {
      if(problem.source_capacity(vertex_descriptor(i)) > 0) count_pair(source_, i);
      if(problem.sink_capacity(vertex_descriptor(i)) > 0) count_pair(i, sink_);
    }
    const std::size_t m = problem.number_of_arc_pairs();
    for(std::size_t k = 0; k < m; ++k) {
      const auto p = problem.arc_pair(k);
      if(p.c_uv > 0 || p.c_vu > 0) count_pair(p.u, p.v);
    }
    std::uint64_t total = 0;
    for(std::size_t x = 0; x < nv; ++x) {
      const std::uint64_t d = degree[x];
      degree[x] = total; // becomes the row start
      total += d;
    }
    degree[nv] = total;
    if(total > std::uint64_t(std::numeric_limits<std::uint32_t>::max()))
      throw std::invalid_argument("MDCS: the network has " + std::to_string(total) + " arcs; the Boost.Graph "
                                  "max-flow engines handle at most 2^32 - 1 (32-bit edge indices)");

    // Pass 2: place every arc next to its row; reverse indices are known as soon as both are placed.
    std::vector<std::uint32_t> row_start(degree.begin(), degree.end());
    std::vector<std::uint64_t>().swap(degree);
    std::vector<std::uint32_t> next(row_start.begin(), row_start.end() - 1);
    std::vector<std::uint32_t> column(total);
    capacity_.resize(total);
    residual_.resize(total);
    reverse_.resize(total);
    auto place = [&](std::size_t a, std::size_t b, Capacity c_ab, Capacity c_ba) {
      const std::uint32_t e = next[a]++, r = next[b]++;
      column[e] = std::uint32_t(b);
      column[r] = std::uint32_t(a);
      capacity_[e] = c_ab;
      capacity_[r] = c_ba;
      reverse_[e] = r;
      reverse_[r] = e;
    };
    // Terminal arcs first: Boykov-Kolmogorov looks up a node's sink arc by scanning its out-arcs.
    for(std::size_t i = 0; i < n; ++i) {
      const Capacity cs = problem.source_capacity(vertex_descriptor(i));
      const Capacity ct = problem.sink_capacity(vertex_descriptor(i));
      if(ct > 0) place(i, sink_, ct, Capacity(0));
      if(cs > 0) place(source_, i, cs, Capacity(0));
    }
    for(std::size_t k = 0; k < m; ++k) {
      const auto p = problem.arc_pair(k);
      if(p.c_uv > 0 || p.c_vu > 0) place(p.u, p.v, p.c_uv, p.c_vu);
    }
    std::vector<std::uint32_t>().swap(next);

    // The sorted-edges constructor copies the rows in order, so Boost's edge indices are ours.
    graph_ = Graph(boost::edges_are_sorted, Sorted_arc_iterator(row_start, column, 0),
                   Sorted_arc_iterator(row_start, column, nv), Graph::vertices_size_type(nv),
                   Graph::edges_size_type(total));
    CGAL_postcondition(num_edges(graph_) == total);
  }

  Csr_flow_graph(const Csr_flow_graph&) = delete;
  Csr_flow_graph& operator=(const Csr_flow_graph&) = delete;

  Graph& graph() { return graph_; }
  const Graph& graph() const { return graph_; }
  vertex_descriptor source() const { return source_; }
  vertex_descriptor sink() const { return sink_; }
  std::size_t number_of_arcs() const { return capacity_.size(); }

  Capacity_map capacity_map() { return Capacity_map(capacity_.data(), get(boost::edge_index, graph_)); }
  Capacity_map residual_capacity_map() { return Capacity_map(residual_.data(), get(boost::edge_index, graph_)); }
  Reverse_arc_map reverse_arc_map() const { return Reverse_arc_map(&graph_, reverse_.data()); }
  Vertex_index_map vertex_index_map() const { return get(boost::vertex_index, graph_); }

  // The nodes reachable over arcs with residual capacity > 0 from the source and from the nodes
  // with positive `excess` (if given), i.e. the minimal source side of a minimum cut once the
  // residual capacities hold a maximum flow, or a maximum preflow together with its excesses.
  // An excess below the rounding noise of its node (a few ulps of the capacities around it) is
  // ignored: in exact arithmetic it would be zero, and starting from it would add nodes that only
  // rounding ties to the source side.
  void source_side_by_residual_search(std::vector<char>& on_source_side,
                                      const std::vector<Capacity>* excess = nullptr) const
  {
    const std::size_t n = std::size_t(source_);
    std::vector<char> reached(n + 2, 0);
    std::vector<vertex_descriptor> stack;
    stack.push_back(source_);
    reached[source_] = 1;
    if(excess != nullptr)
      for(std::size_t x = 0; x < n; ++x)
        if((*excess)[x] > 0 && (*excess)[x] > rounding_noise(vertex_descriptor(x))) {
          reached[x] = 1;
          stack.push_back(vertex_descriptor(x));
        }
    while(!stack.empty()) {
      const vertex_descriptor x = stack.back();
      stack.pop_back();
      for(auto arcs = out_edges(x, graph_); arcs.first != arcs.second; ++arcs.first) {
        const edge_descriptor e = *arcs.first;
        const vertex_descriptor y = target(e, graph_);
        if(!reached[y] && residual_[e.idx] > 0) {
          reached[y] = 1;
          stack.push_back(y);
        }
      }
    }
    CGAL_postcondition(!reached[sink_]); // otherwise the (pre)flow was not maximum
    reached.resize(n);
    on_source_side.swap(reached);
  }

private:
  // 16 ulps of the total capacity of the arcs at x (in and out): a bound on the rounding error
  // of sums of flows through x.
  Capacity rounding_noise(vertex_descriptor x) const
  {
    Capacity total = 0;
    for(auto arcs = out_edges(x, graph_); arcs.first != arcs.second; ++arcs.first) {
      const std::uint32_t e = (*arcs.first).idx;
      total += capacity_[e] + capacity_[reverse_[e]];
    }
    return Capacity(16) * std::numeric_limits<Capacity>::epsilon() * total;
  }

  // Walks the rows of (row_start, column) as (source, target) pairs, in CSR order.
  class Sorted_arc_iterator
  {
  public:
    typedef std::forward_iterator_tag iterator_category;
    typedef std::pair<std::uint32_t, std::uint32_t> value_type;
    typedef std::ptrdiff_t difference_type;
    typedef const value_type* pointer;
    typedef const value_type& reference;

    Sorted_arc_iterator(const std::vector<std::uint32_t>& row_start, const std::vector<std::uint32_t>& column,
                        std::size_t vertex)
      : row_start_(&row_start), column_(&column), position_(vertex < row_start.size() - 1 ? row_start[vertex]
                                                                                            : row_start.back())
    {
      vertex_ = std::uint32_t(vertex);
      skip_empty_rows();
    }

    reference operator*() const { return current_; }
    pointer operator->() const { return &current_; }
    Sorted_arc_iterator& operator++()
    {
      ++position_;
      skip_empty_rows();
      return *this;
    }
    Sorted_arc_iterator operator++(int)
    {
      Sorted_arc_iterator old = *this;
      ++*this;
      return old;
    }
    bool operator==(const Sorted_arc_iterator& other) const { return position_ == other.position_; }
    bool operator!=(const Sorted_arc_iterator& other) const { return position_ != other.position_; }

  private:
    void skip_empty_rows()
    {
      const std::size_t rows = row_start_->size() - 1;
      while(vertex_ < rows && position_ >= (*row_start_)[vertex_ + 1]) ++vertex_;
      if(vertex_ < rows) current_ = value_type(vertex_, (*column_)[position_]);
    }

    const std::vector<std::uint32_t>* row_start_;
    const std::vector<std::uint32_t>* column_;
    std::uint32_t position_;
    std::uint32_t vertex_ = 0;
    value_type current_;
  };

  Graph graph_;
  vertex_descriptor source_ = 0, sink_ = 0;
  std::vector<Capacity> capacity_, residual_;
  std::vector<std::uint32_t> reverse_;
};

} // namespace internal
} // namespace Min_cut
} // namespace CGAL

#endif // CGAL_MIN_CUT_INTERNAL_CSR_FLOW_GRAPH_H
