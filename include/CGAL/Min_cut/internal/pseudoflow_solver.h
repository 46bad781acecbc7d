// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The first phase of Hochbaum's highest-label pseudoflow algorithm (HPF) on contiguous arrays:
// it ends with a minimum cut, from which the minimal source side and the max-flow value follow.
// Written from D. S. Hochbaum, "The pseudoflow algorithm: a new algorithm for the maximum-flow
// problem", Oper. Res. 56(4), 2008, and Chandran & Hochbaum, "A computational study of the
// pseudoflow and push-relabel algorithms for the maximum flow problem", Oper. Res. 57(2), 2009.

#ifndef CGAL_MIN_CUT_INTERNAL_PSEUDOFLOW_SOLVER_H
#define CGAL_MIN_CUT_INTERNAL_PSEUDOFLOW_SOLVER_H

#include <CGAL/Min_cut/Flow_network.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Min_cut {
namespace internal {

// State and invariants (exact arithmetic; rounding only perturbs residuals and excesses):
//
// - Simple initialisation: every source and sink arc is saturated, every interior arc is empty,
//   so node v starts with excess e(v) = source_capacity(v) - sink_capacity(v). The terminals never
//   appear again: a saturated source arc has no residual capacity out of the source, a saturated
//   sink arc none into the sink.
// - A forest over the nodes (parent, parent arc, doubly linked child lists). Only roots carry
//   excess. A root is *strong* when it sits in a bucket (excess > 0, or excess 0 for the nodes
//   that start without deficit and for the tails of split arcs), *weak* otherwise (a node that
//   started with a deficit and still has excess <= 0); a node is strong or weak with its root.
//   Trees that a gap proves unable to reach any weak node are *dead*: their nodes get label
//   `dead_` and are never touched again.
// - (T) every tree arc x -> parent(x) has residual capacity > 0, so every node reaches its root.
// - (V) labels are valid: residual arc u -> v implies l(u) <= l(v) + 1.
// - (L) l(child) >= l(parent); a tree's root has its smallest label.
// - Weak roots are never relabelled and keep label 1 (a root leaves the buckets only to be
//   processed; a processed root either hangs itself under another tree or is relabelled).
// - The labels in use are contiguous from 1: they start so, only a relabel can empty a label,
//   and then the gap rule kills everything above it. Hence no label exceeds n while alive.
//
// Main loop: take a strong root r of highest label l (FIFO within a label). Search r's tree, depth
// first and only through nodes of label l, for a *merger arc*: a residual arc (v, w) with
// l(w) = l - 1 (w lies in another tree by (L); usually a weak one, but a strong tree of lower
// root label is as good: its root just gains excess). If one exists, re-root r's tree at v, hang it under
// w and push r's excess along the tree path r -> ... -> v -> w -> ... -> root; an arc that cannot
// take all of it is saturated and split off, its tail becoming a strong root that keeps the rest.
// Otherwise every searched node is relabelled to l + 1, in post-order so that (L) always holds.
// Gap: if that leaves no node with label l, every node above l lies in r's tree (a tree path can
// only step down one label at a time, and no other root is above l), so r's tree reaches no weak
// node and dies.
//
// At the end all strong nodes are dead, and the dead set S has no residual arc leaving it. Then
// every arc from S to the rest is saturated and every arc into S empty, so cap(S) equals the flow
// that a feasible flow would carry after returning the excesses to the source: S is a minimum cut.
// The minimal source side is the set R of nodes reachable over residual arcs from the nodes with
// positive excess: R lies in every minimum cut (each contains all excess and lets no residual arc
// out), and cap(R) = cap(S) - (the excess of S \ R) = cap(S).
template <class Capacity>
class Pseudoflow_solver
{
public:
  typedef std::uint32_t Index;

  explicit Pseudoflow_solver(const Max_flow_problem<Capacity>& problem) : problem_(problem) { build(); }

  Pseudoflow_solver(const Pseudoflow_solver&) = delete;
  Pseudoflow_solver& operator=(const Pseudoflow_solver&) = delete;

  // Runs the algorithm, fills the minimal source side and returns the max-flow value, computed
  // as the capacity of that cut in the problem's own capacities.
  Capacity run(std::vector<char>& on_source_side)
  {
    initialise();
    for(;;) {
      while(highest_ > 0 && bucket_head_[highest_] == none) --highest_;
      if(highest_ == 0) break;
      const Index r = bucket_head_[highest_];
      bucket_head_[highest_] = bucket_next_[r];
      if(bucket_head_[highest_] == none) bucket_tail_[highest_] = none;
      in_bucket_[r] = 0;
      process_root(r);
    }
    minimal_source_side(on_source_side);
    return cut_capacity(on_source_side);
  }

  std::size_t number_of_arcs() const { return head_.size(); }

private:
  static constexpr Index none = 0xFFFFFFFFu;

  void build()
  {
    const std::size_t n = problem_.number_of_nodes();
    // Labels run up to n + 1 and `none` must differ from every node index.
    if(n > std::size_t(0xFFFFFFFFu) - 2)
      throw std::invalid_argument("MDCS: Pseudoflow_max_flow handles at most 2^32 - 3 nodes (32-bit indices); "
                                  "the network has " + std::to_string(n));
    n_ = Index(n);
    const std::size_t m = problem_.number_of_arc_pairs();

    // Pass 1: degrees, in 64 bits to detect more arcs than 32-bit arc indices allow.
    std::vector<std::uint64_t> degree(n + 1, 0);
    for(std::size_t k = 0; k < m; ++k) {
      const auto p = problem_.arc_pair(k);
      if(p.c_uv > 0 || p.c_vu > 0) { ++degree[p.u]; ++degree[p.v]; }
    }
    std::uint64_t total = 0;
    for(std::size_t x = 0; x < n; ++x) {
      const std::uint64_t d = degree[x];
      degree[x] = total;
      total += d;
    }
    degree[n] = total;
    if(total >= std::uint64_t(none))
      throw std::invalid_argument("MDCS: the network has " + std::to_string(total) + " arcs; Pseudoflow_max_flow "
                                  "handles at most 2^32 - 2 (32-bit arc indices)");
    first_.assign(degree.begin(), degree.end());
    std::vector<std::uint64_t>().swap(degree);

    // Pass 2: every arc next to its row; `current_` serves as the fill cursor and is reset later.
    head_.resize(total);
    reverse_.resize(total);
    residual_.resize(total);
    current_.assign(first_.begin(), first_.end() - 1);
    for(std::size_t k = 0; k < m; ++k) {
      const auto p = problem_.arc_pair(k);
      if(!(p.c_uv > 0 || p.c_vu > 0)) continue;
      const Index a = current_[p.u]++, b = current_[p.v]++;
      head_[a] = p.v;
      head_[b] = p.u;
      residual_[a] = p.c_uv;
      residual_[b] = p.c_vu;
      reverse_[a] = b;
      reverse_[b] = a;
    }
  }

  void initialise()
  {
    const std::size_t n = n_;
    dead_ = Index(n + 1);
    excess_.resize(n);
    parent_.assign(n, none);
    parent_arc_.assign(n, none);
    first_child_.assign(n, none);
    next_sibling_.assign(n, none);
    previous_sibling_.assign(n, none);
    scan_.assign(n, none);
    bucket_next_.assign(n, none);
    in_bucket_.assign(n, 0);
    for(std::size_t x = 0; x < n; ++x) current_[x] = first_[x];
    bucket_head_.assign(n + 2, none);
    bucket_tail_.assign(n + 2, none);
    count_.assign(n + 2, 0);
    highest_ = 0;

    // Every node starts as a root: the deficit nodes are the weak roots, all others are strong
    // roots, with positive or zero excess. A zero-excess root merges like any other, pushing
    // nothing, which hangs it on a shortest residual path towards a deficit before excess arrives;
    // with label 1 everywhere instead (every zero-excess node a weak root), each unit of excess
    // advances one node per merge and the labels climb one by one: twice slower on the duals of
    // line arrangements.
    // Labels: 1 + the residual distance to the nearest deficit, by a breadth-first search
    // backwards over residual arcs (`scan_` is the queue). They are valid, and contiguous from 1,
    // which the gap rule relies on. Nodes that reach no deficit are dead from the start.
    label_.assign(n, dead_);
    std::size_t head = 0, tail = 0;
    for(Index x = 0; x < n_; ++x) {
      excess_[x] = problem_.source_capacity(x) - problem_.sink_capacity(x);
      if(excess_[x] < 0) {
        label_[x] = 1;
        scan_[tail++] = x;
      }
    }
    while(head < tail) {
      const Index x = scan_[head++];
      const Index next_label = label_[x] + 1;
      for(Index a = first_[x]; a < first_[x + 1]; ++a) {
        const Index y = head_[a];
        if(label_[y] == dead_ && residual_[reverse_[a]] > 0) {
          label_[y] = next_label;
          scan_[tail++] = y;
        }
      }
    }
    for(Index x = 0; x < n_; ++x) {
      if(label_[x] == dead_) continue;
      ++count_[label_[x]];
      if(excess_[x] >= 0) add_to_bucket(x);
    }
  }

  void add_to_bucket(Index x)
  {
    const Index l = label_[x];
    bucket_next_[x] = none;
    if(bucket_tail_[l] == none) bucket_head_[l] = x;
    else bucket_next_[bucket_tail_[l]] = x;
    bucket_tail_[l] = x;
    in_bucket_[x] = 1;
    if(l > highest_) highest_ = l;
  }

  void add_child(Index p, Index c)
  {
    parent_[c] = p;
    previous_sibling_[c] = none;
    next_sibling_[c] = first_child_[p];
    if(first_child_[p] != none) previous_sibling_[first_child_[p]] = c;
    first_child_[p] = c;
  }

  void remove_from_parent(Index c)
  {
    const Index p = parent_[c];
    if(previous_sibling_[c] != none) next_sibling_[previous_sibling_[c]] = next_sibling_[c];
    else first_child_[p] = next_sibling_[c];
    if(next_sibling_[c] != none) previous_sibling_[next_sibling_[c]] = previous_sibling_[c];
    parent_[c] = none;
    parent_arc_[c] = none;
  }

  // Looks for a merger arc out of x (label l >= 2), from x's current arc on; arcs before it were
  // not admissible since x's last relabel and cannot have become so (a residual arc x -> w appears
  // only by a push w -> x, which needs l(w) = l(x) + 1, and labels never decrease).
  bool find_merger(Index x, Index l, Index& arc)
  {
    const Index end = first_[x + 1];
    const Index target = l - 1;
    for(Index a = current_[x]; a < end; ++a)
      if(residual_[a] > 0 && label_[head_[a]] == target) {
        current_[x] = a;
        arc = a;
        return true;
      }
    current_[x] = end;
    return false;
  }

  void process_root(Index r)
  {
    const Index l = label_[r];
    Index arc = none;
    // Label 1 is the lowest label: no node has label 0, so there is nothing to merge into.
    const bool can_merge = l >= 2;
    Index x = r;
    scan_[r] = first_child_[r];
    if(can_merge && find_merger(r, l, arc)) {
      merge_and_push(r, r, arc);
      return;
    }
    for(;;) {
      Index c = scan_[x];
      while(c != none && label_[c] != l) c = next_sibling_[c];
      if(c != none) {
        scan_[x] = next_sibling_[c];
        x = c;
        scan_[x] = first_child_[x];
        if(can_merge && find_merger(x, l, arc)) {
          merge_and_push(r, x, arc);
          return;
        }
        continue;
      }
      // Post-order: x's children of label l have been relabelled, so (L) holds after this.
      --count_[l];
      label_[x] = l + 1;
      ++count_[l + 1];
      current_[x] = first_[x];
      if(x == r) break;
      x = parent_[x];
    }
    if(count_[l] == 0 || l + 1 > n_) kill_tree(r);
    else add_to_bucket(r);
  }

  // Re-roots r's tree at v, hangs it under w = head(arc) and pushes r's excess to the new root.
  void merge_and_push(Index r, Index v, Index arc)
  {
    Index x = v, new_parent = head_[arc], new_arc = arc;
    for(;;) {
      const Index old_parent = parent_[x], old_arc = parent_arc_[x];
      if(old_parent != none) remove_from_parent(x);
      add_child(new_parent, x);
      parent_arc_[x] = new_arc;
      if(old_parent == none) break; // x == r
      new_parent = x;
      new_arc = reverse_[old_arc];
      x = old_parent;
    }

    Capacity delta = excess_[r];
    excess_[r] = 0;
    x = r;
    const Index w = head_[arc];
    bool past_merger = false;
    while(parent_[x] != none) {
      // From w on, every tree arc has residual > 0 (T), so pushing nothing changes nothing: a
      // zero-excess root stops there instead of walking to the root.
      if(x == w) past_merger = true;
      if(past_merger && delta == 0) return;
      const Index a = parent_arc_[x], p = parent_[x];
      const Capacity available = residual_[a];
      if(delta >= available) {
        // Saturate and split: x keeps what the arc cannot take (exactly 0 when delta == available;
        // it is still made a strong root, so that weak roots keep label 1).
        residual_[a] = 0;
        residual_[reverse_[a]] += available;
        excess_[x] = delta - available;
        remove_from_parent(x);
        add_to_bucket(x);
        delta = available;
      } else {
        // delta < available, so the difference is positive: (T) holds on this arc afterwards.
        residual_[a] = available - delta;
        residual_[reverse_[a]] += delta;
      }
      x = p;
    }
    excess_[x] += delta;
    if(!in_bucket_[x] && excess_[x] > 0) add_to_bucket(x);
  }

  void kill_tree(Index r)
  {
    Index x = r;
    for(;;) {
      --count_[label_[x]];
      label_[x] = dead_;
      if(first_child_[x] != none) {
        x = first_child_[x];
        continue;
      }
      while(x != r && next_sibling_[x] == none) x = parent_[x];
      if(x == r) break;
      x = next_sibling_[x];
    }
  }

  // 16 ulps of the capacities around x: a bound on the rounding error of its excess.
  Capacity rounding_noise(Index x) const
  {
    Capacity total = problem_.source_capacity(x) + problem_.sink_capacity(x);
    for(Index a = first_[x]; a < first_[x + 1]; ++a) total += residual_[a] + residual_[reverse_[a]];
    return Capacity(16) * std::numeric_limits<Capacity>::epsilon() * total;
  }

  // Nodes reachable over residual arcs from the nodes with positive excess. An excess within the
  // rounding noise of its node would be zero in exact arithmetic and is not a start.
  void minimal_source_side(std::vector<char>& side)
  {
    side.assign(n_, 0);
    std::vector<Index>& stack = scan_; // free now; holds each node at most once
    std::size_t top = 0;
    for(Index x = 0; x < n_; ++x)
      if(excess_[x] > 0 && excess_[x] > rounding_noise(x)) {
        side[x] = 1;
        stack[top++] = x;
      }
    while(top > 0) {
      const Index x = stack[--top];
      for(Index a = first_[x]; a < first_[x + 1]; ++a) {
        const Index y = head_[a];
        if(!side[y] && residual_[a] > 0) {
          side[y] = 1;
          stack[top++] = y;
        }
      }
    }
  }

  Capacity cut_capacity(const std::vector<char>& side) const
  {
    Capacity value = 0;
    for(Index x = 0; x < n_; ++x) value += side[x] ? problem_.sink_capacity(x) : problem_.source_capacity(x);
    const std::size_t m = problem_.number_of_arc_pairs();
    for(std::size_t k = 0; k < m; ++k) {
      const auto p = problem_.arc_pair(k);
      if(side[p.u] && !side[p.v]) value += p.c_uv;
      else if(!side[p.u] && side[p.v]) value += p.c_vu;
    }
    return value;
  }

  const Max_flow_problem<Capacity>& problem_;
  Index n_ = 0, dead_ = 1, highest_ = 0;
  // Arcs in CSR order: 16 bytes per arc with double capacities.
  std::vector<Index> first_, head_, reverse_;
  std::vector<Capacity> residual_;
  // Per node.
  std::vector<Capacity> excess_;
  std::vector<Index> label_, parent_, parent_arc_, first_child_, next_sibling_, previous_sibling_, scan_,
    current_, bucket_next_;
  std::vector<char> in_bucket_;
  // Per label.
  std::vector<Index> bucket_head_, bucket_tail_, count_;
};

} // namespace internal
} // namespace Min_cut
} // namespace CGAL

#endif // CGAL_MIN_CUT_INTERNAL_PSEUDOFLOW_SOLVER_H
