// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The residual graph that the pseudoflow solver runs on when it is given a Max_flow_problem: arcs in
// compressed-row order, each with its head, its reverse arc and its residual capacity (16 bytes per arc
// with double capacities). Other residual graphs (for instance one that reads a cell complex directly,
// without any copy of its arcs) model the same interface; see pseudoflow_solver.h.

#ifndef CGAL_MIN_CUT_INTERNAL_PSEUDOFLOW_CSR_GRAPH_H
#define CGAL_MIN_CUT_INTERNAL_PSEUDOFLOW_CSR_GRAPH_H

#include <CGAL/Min_cut/Flow_network.h>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Min_cut {
namespace internal {

// Residual graph interface of Pseudoflow_solver (Index = std::uint32_t):
//   std::size_t number_of_nodes() const;
//   Index degree(Index x) const;                 // arcs out of x: positions 0 .. degree(x) - 1
//   Index arc(Index x, Index k) const;           // the arc at position k of x
//   Index head(Index x, Index a) const;          // the head of arc a out of x
//   Capacity residual(Index x, Index a) const;   // may be +infinity (an arc that can never saturate)
//   Index reverse(Index x, Index a) const;       // the arc head(x, a) -> x
//   void push(Index x, Index a, Capacity d);     // d < residual(x, a): moves d from a to its reverse
//   void saturate(Index x, Index a);             // moves all of residual(x, a) (finite) to the reverse
//   Capacity initial_excess(Index x) const;      // source capacity - sink capacity
//   Capacity capacity_scale(Index x) const;      // sum of the finite capacities at x (rounding noise)
template <class Capacity>
class Pseudoflow_csr_graph
{
public:
  typedef std::uint32_t Index;

  explicit Pseudoflow_csr_graph(const Max_flow_problem<Capacity>& problem) : problem_(problem)
  {
    const std::size_t n = problem.number_of_nodes();
    // Labels run up to n + 1 and the solver's `none` must differ from every node index.
    if(n > std::size_t(0xFFFFFFFFu) - 3)
      throw std::invalid_argument("MDCS: Pseudoflow_max_flow handles at most 2^32 - 4 nodes (32-bit indices); "
                                  "the network has " + std::to_string(n));
    const std::size_t m = problem.number_of_arc_pairs();

    // Pass 1: degrees, in 64 bits to detect more arcs than 32-bit arc indices allow.
    std::vector<std::uint64_t> degree(n + 1, 0);
    for(std::size_t k = 0; k < m; ++k) {
      const auto p = problem.arc_pair(k);
      if(p.c_uv > 0 || p.c_vu > 0) { ++degree[p.u]; ++degree[p.v]; }
    }
    std::uint64_t total = 0;
    for(std::size_t x = 0; x < n; ++x) {
      const std::uint64_t d = degree[x];
      degree[x] = total;
      total += d;
    }
    degree[n] = total;
    if(total >= std::uint64_t(0xFFFFFFFFu))
      throw std::invalid_argument("MDCS: the network has " + std::to_string(total) + " arcs; Pseudoflow_max_flow "
                                  "handles at most 2^32 - 2 (32-bit arc indices)");
    first_.assign(degree.begin(), degree.end());
    std::vector<std::uint64_t>().swap(degree);

    // Pass 2: every arc next to its row, with a fill cursor per node.
    head_.resize(total);
    reverse_.resize(total);
    residual_.resize(total);
    std::vector<Index> cursor(first_.begin(), first_.end() - 1);
    for(std::size_t k = 0; k < m; ++k) {
      const auto p = problem.arc_pair(k);
      if(!(p.c_uv > 0 || p.c_vu > 0)) continue;
      const Index a = cursor[p.u]++, b = cursor[p.v]++;
      head_[a] = p.v;
      head_[b] = p.u;
      residual_[a] = p.c_uv;
      residual_[b] = p.c_vu;
      reverse_[a] = b;
      reverse_[b] = a;
    }
  }

  std::size_t number_of_nodes() const { return problem_.number_of_nodes(); }
  std::size_t number_of_arcs() const { return head_.size(); }
  Index degree(Index x) const { return first_[x + 1] - first_[x]; }
  Index arc(Index x, Index k) const { return first_[x] + k; }
  Index head(Index, Index a) const { return head_[a]; }
  Capacity residual(Index, Index a) const { return residual_[a]; }
  Index reverse(Index, Index a) const { return reverse_[a]; }
  void push(Index, Index a, Capacity d)
  {
    residual_[a] -= d;
    residual_[reverse_[a]] += d;
  }
  void saturate(Index, Index a)
  {
    residual_[reverse_[a]] += residual_[a];
    residual_[a] = 0;
  }
  Capacity initial_excess(Index x) const { return problem_.source_capacity(x) - problem_.sink_capacity(x); }
  Capacity capacity_scale(Index x) const
  {
    // The two residuals of a pair always sum to its two capacities.
    Capacity total = problem_.source_capacity(x) + problem_.sink_capacity(x);
    for(Index a = first_[x]; a < first_[x + 1]; ++a) total += residual_[a] + residual_[reverse_[a]];
    return total;
  }

private:
  const Max_flow_problem<Capacity>& problem_;
  std::vector<Index> first_, head_, reverse_;
  std::vector<Capacity> residual_;
};

} // namespace internal
} // namespace Min_cut
} // namespace CGAL

#endif // CGAL_MIN_CUT_INTERNAL_PSEUDOFLOW_CSR_GRAPH_H
