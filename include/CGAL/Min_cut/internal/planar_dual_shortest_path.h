// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The work behind solve_planar_min_cut(): the directed dual graph of a planar flow network, Dijkstra on it
// from the start to the end vertices, and the node sides of the cut that the shortest path stands for.

#ifndef CGAL_MIN_CUT_INTERNAL_PLANAR_DUAL_SHORTEST_PATH_H
#define CGAL_MIN_CUT_INTERNAL_PLANAR_DUAL_SHORTEST_PATH_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Min_cut/Flow_network.h>
#include <CGAL/Min_cut/Planar_dual.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Min_cut {
namespace internal {

// Facets are numbered interior first, then source facets, then sink facets; the top bit of a code marks a
// walk against the dual edge's orientation (b -> a), which crosses an interior facet from v to u.
constexpr std::uint32_t planar_reversed_bit = 0x80000000u;

template <class Capacity>
class Planar_dual_shortest_path
{
public:
  typedef Planar_dual::Vertex_index Vertex_index;

  Planar_dual_shortest_path(const Flow_network<Capacity>& network, const Planar_dual& dual)
    : network_(network), dual_(dual)
  {
    validate();
  }

  // Builds the dual arcs in compressed rows: a facet crossed in a direction of finite capacity is an arc of
  // that length; infinite capacities give no arc (the cut can never cross them that way).
  template <class Reporter>
  void build_arcs(Reporter& report)
  {
    const std::size_t nv = dual_.number_of_vertices;
    first_.assign(nv + 1, 0);
    const Capacity inf = Flow_network<Capacity>::infinity();
    auto for_each_arc = [&](auto&& emit) {
      const auto& facets = network_.facets();
      for(std::size_t k = 0; k < facets.size(); ++k) {
        const Planar_dual::Edge& e = dual_.edges[k];
        if(facets[k].c_uv != inf) emit(e.a, e.b, std::uint32_t(k), facets[k].c_uv);
        if(facets[k].c_vu != inf) emit(e.b, e.a, std::uint32_t(k) | planar_reversed_bit, facets[k].c_vu);
        if((k & 0xFFFFF) == 0) report(k);
      }
      const std::uint32_t source_base = std::uint32_t(facets.size());
      for(std::size_t k = 0; k < network_.source_facets().size(); ++k)
        if(network_.source_facet(k).capacity != inf)
          emit(dual_.source_edges[k].a, dual_.source_edges[k].b, source_base + std::uint32_t(k),
               network_.source_facet(k).capacity);
      const std::uint32_t sink_base = source_base + std::uint32_t(network_.source_facets().size());
      for(std::size_t k = 0; k < network_.sink_facets().size(); ++k)
        if(network_.sink_facet(k).capacity != inf)
          emit(dual_.sink_edges[k].a, dual_.sink_edges[k].b, sink_base + std::uint32_t(k),
               network_.sink_facet(k).capacity);
    };
    std::size_t count = 0;
    for_each_arc([&](Vertex_index a, Vertex_index, std::uint32_t, Capacity) {
      ++first_[a + 1];
      ++count;
    });
    if(count >= std::numeric_limits<std::uint32_t>::max())
      throw std::invalid_argument("MDCS: solve_planar_min_cut: more than 2^32 - 1 dual arcs");
    for(std::size_t v = 0; v < nv; ++v) first_[v + 1] += first_[v];
    arcs_.reset(new Arc[count]); // no value-initialisation: every slot is written below
    arcs_size_ = count;
    std::vector<std::uint32_t> fill(first_.begin(), first_.end() - 1);
    for_each_arc([&](Vertex_index a, Vertex_index b, std::uint32_t code, Capacity c) {
      arcs_[fill[a]++] = Arc{b, code, c};
    });
  }

  // The shortest path from the start vertices (distance 0) to the nearest end vertex. Returns false when no
  // end vertex can be reached (every cut crosses an infinite capacity).
  //
  // When the dual arcs form a DAG (as for networks whose infinite reverse capacities keep the cut a function:
  // every finite dual arc then points one way), one pass in topological order (Kahn) computes the distances
  // with no heap; the pass itself detects a cycle, and only then does Dijkstra run.
  template <class Reporter>
  bool run(Reporter& report)
  {
    if(run_topological(report)) return target_ != none_;
    return run_dijkstra(report);
  }

  // The facet codes of the shortest path, from the end vertex back to its start vertex.
  std::vector<std::uint32_t> path_codes() const
  {
    std::vector<std::uint32_t> codes;
    for(Vertex_index v = target_; predecessor_arc_[v] != none_; v = predecessor_vertex_[v])
      codes.push_back(arcs_[predecessor_arc_[v]].facet);
    return codes;
  }

  Capacity path_length() const { return distance_[target_]; }

  // Frees the dual graph and the search state (the sides need only the network and the path).
  void release()
  {
    arcs_.reset();
    arcs_size_ = 0;
    std::vector<std::uint32_t>().swap(first_);
    std::vector<Capacity>().swap(distance_);
    std::vector<std::uint32_t>().swap(predecessor_arc_);
    std::vector<Vertex_index>().swap(predecessor_vertex_);
  }

private:
  void reset_search()
  {
    const std::size_t nv = dual_.number_of_vertices;
    distance_.assign(nv, std::numeric_limits<Capacity>::infinity());
    predecessor_arc_.assign(nv, none_);
    predecessor_vertex_.assign(nv, none_);
    for(Vertex_index s : dual_.start_vertices) distance_[s] = 0;
    target_ = none_;
  }

  // Kahn's algorithm; false if the arcs contain a cycle. Sets target_ (none_ when no end vertex is reachable).
  template <class Reporter>
  bool run_topological(Reporter& report)
  {
    const std::size_t nv = dual_.number_of_vertices;
    std::vector<std::uint32_t> in_degree(nv, 0);
    for(std::size_t i = 0; i < arcs_size_; ++i) ++in_degree[arcs_[i].head];
    reset_search();
    std::vector<Vertex_index> ready;
    for(std::size_t v = 0; v < nv; ++v)
      if(in_degree[v] == 0) ready.push_back(Vertex_index(v));
    std::size_t processed = 0;
    while(!ready.empty()) {
      const Vertex_index v = ready.back();
      ready.pop_back();
      report(++processed);
      const Capacity dv = distance_[v];
      for(std::uint32_t i = first_[v]; i < first_[v + 1]; ++i) {
        const Arc& arc = arcs_[i];
        const Capacity d = dv + arc.length;
        if(d < distance_[arc.head]) {
          distance_[arc.head] = d;
          predecessor_arc_[arc.head] = i;
          predecessor_vertex_[arc.head] = v;
        }
        if(--in_degree[arc.head] == 0) ready.push_back(arc.head);
      }
    }
    if(processed != nv) return false;
    for(Vertex_index t : dual_.end_vertices)
      if(distance_[t] != std::numeric_limits<Capacity>::infinity() && (target_ == none_ || distance_[t] < distance_[target_]))
        target_ = t;
    return true;
  }

  // Dijkstra with a binary heap and lazy deletion, until the first end vertex is settled.
  template <class Reporter>
  bool run_dijkstra(Reporter& report)
  {
    const std::size_t nv = dual_.number_of_vertices;
    reset_search();
    std::vector<char> is_end(nv, 0);
    for(Vertex_index t : dual_.end_vertices) is_end[t] = 1;
    typedef std::pair<Capacity, Vertex_index> Entry;
    std::vector<Entry> heap;
    const std::greater<Entry> later;
    for(Vertex_index s : dual_.start_vertices) heap.push_back(Entry(0, s));
    std::make_heap(heap.begin(), heap.end(), later);
    std::size_t settled = 0;
    while(!heap.empty()) {
      std::pop_heap(heap.begin(), heap.end(), later);
      const Entry top = heap.back();
      heap.pop_back();
      const Vertex_index v = top.second;
      if(top.first > distance_[v]) continue; // stale entry (lazy deletion)
      if(is_end[v]) {
        target_ = v;
        return true;
      }
      report(++settled);
      for(std::uint32_t i = first_[v]; i < first_[v + 1]; ++i) {
        const Arc& arc = arcs_[i];
        const Capacity d = top.first + arc.length;
        if(d < distance_[arc.head]) {
          distance_[arc.head] = d;
          predecessor_arc_[arc.head] = i;
          predecessor_vertex_[arc.head] = v;
          heap.push_back(Entry(d, arc.head));
          std::push_heap(heap.begin(), heap.end(), later);
        }
      }
    }
    return false;
  }

  struct Arc
  {
    Vertex_index head;
    std::uint32_t facet; // code, see planar_reversed_bit
    Capacity length;
  };

  void validate() const
  {
    const std::string where = "MDCS: solve_planar_min_cut: ";
    if(dual_.edges.size() != network_.number_of_facets() ||
       dual_.source_edges.size() != network_.number_of_source_facets() ||
       dual_.sink_edges.size() != network_.number_of_sink_facets())
      throw std::invalid_argument(where + "the planar dual needs one dual edge per facet of the network (" +
                                  std::to_string(network_.number_of_facets()) + " interior, " +
                                  std::to_string(network_.number_of_source_facets()) + " source, " +
                                  std::to_string(network_.number_of_sink_facets()) + " sink facets; got " +
                                  std::to_string(dual_.edges.size()) + ", " + std::to_string(dual_.source_edges.size()) +
                                  ", " + std::to_string(dual_.sink_edges.size()) + ")");
    const std::size_t total =
      network_.number_of_facets() + network_.number_of_source_facets() + network_.number_of_sink_facets();
    if(total >= planar_reversed_bit || dual_.number_of_vertices >= std::numeric_limits<std::uint32_t>::max())
      throw std::invalid_argument(where + "the network is too large for 31-bit facet codes");
    const std::size_t nv = dual_.number_of_vertices;
    // Every dual vertex that matters ends a dual edge or starts/ends the path: a count far beyond sizes the
    // distance arrays (20 bytes per vertex) for nothing, and a wrong count is the likely cause.
    const std::size_t useful = 2 * total + dual_.start_vertices.size() + dual_.end_vertices.size();
    if(nv > useful)
      throw std::invalid_argument(where + "the planar dual has " + std::to_string(nv) + " vertices, more than twice its " +
                                  std::to_string(total) + " dual edges plus its start and end vertices: most would "
                                  "belong to no edge");
    auto check = [&](const std::vector<Planar_dual::Edge>& edges, const char* what) {
      for(std::size_t k = 0; k < edges.size(); ++k)
        if(edges[k].a >= nv || edges[k].b >= nv)
          throw std::invalid_argument(where + "the dual edge of " + what + " facet " + std::to_string(k) +
                                      " has a vertex index out of range (" + std::to_string(nv) + " dual vertices)");
    };
    check(dual_.edges, "interior");
    check(dual_.source_edges, "source");
    check(dual_.sink_edges, "sink");
    if(dual_.start_vertices.empty() || dual_.end_vertices.empty())
      throw std::invalid_argument(where + "the planar dual needs at least one start and one end vertex");
    for(const auto* list : {&dual_.start_vertices, &dual_.end_vertices})
      for(Vertex_index v : *list)
        if(v >= nv)
          throw std::invalid_argument(where + "a start or end vertex index is out of range");
  }

  const Flow_network<Capacity>& network_;
  const Planar_dual& dual_;
  std::vector<std::uint32_t> first_;
  std::unique_ptr<Arc[]> arcs_;
  std::size_t arcs_size_ = 0;
  std::vector<Capacity> distance_;
  std::vector<std::uint32_t> predecessor_arc_;
  std::vector<Vertex_index> predecessor_vertex_;
  static constexpr Vertex_index none_ = std::numeric_limits<Vertex_index>::max();
  Vertex_index target_ = none_;
};

// Union-find over the network's nodes with path halving; the roots' ranks are not kept (the trees stay flat
// enough in practice, and union by index keeps it deterministic).
class Node_partition
{
public:
  explicit Node_partition(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), std::uint32_t(0)); }

  std::uint32_t find(std::uint32_t x)
  {
    while(parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }

  void unite(std::uint32_t a, std::uint32_t b)
  {
    a = find(a);
    b = find(b);
    if(a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

private:
  std::vector<std::uint32_t> parent_;
};

} // namespace internal
} // namespace Min_cut
} // namespace CGAL

#endif // CGAL_MIN_CUT_INTERNAL_PLANAR_DUAL_SHORTEST_PATH_H
