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
#include <CGAL/Min_cut/internal/Pseudoflow_csr_graph.h>

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
//
// The solver runs on any residual graph with the interface described in Pseudoflow_csr_graph.h; an arc
// is named by its tail and an arc index of the graph (`parent_arc_[x]` is an arc out of x). A residual
// may be +infinity: such an arc never saturates, and pushes along it leave it infinite.
template <class Capacity, class Graph = Pseudoflow_csr_graph<Capacity> >
class Pseudoflow_solver
{
public:
  typedef std::uint32_t Index;

  explicit Pseudoflow_solver(Graph& graph) : g_(graph)
  {
    const std::size_t n = graph.number_of_nodes();
    // Labels run up to n + 1; `none` and `not_in_bucket` must differ from every node index.
    if(n > std::size_t(0xFFFFFFFFu) - 3)
      throw std::invalid_argument("MDCS: Pseudoflow_max_flow handles at most 2^32 - 4 nodes (32-bit indices); "
                                  "the network has " + std::to_string(n));
    n_ = Index(n);
  }

  Pseudoflow_solver(const Pseudoflow_solver&) = delete;
  Pseudoflow_solver& operator=(const Pseudoflow_solver&) = delete;

  // Runs the algorithm and fills the minimal source side (the caller computes the cut's capacity).
  void run(std::vector<char>& on_source_side)
  {
    initialise();
    for(;;) {
      while(highest_ > 0 && bucket_head_[highest_] == none) --highest_;
      if(highest_ == 0) break;
      const Index r = bucket_head_[highest_];
      bucket_head_[highest_] = bucket_next_[r];
      if(bucket_head_[highest_] == none) bucket_tail_[highest_] = none;
      bucket_next_[r] = not_in_bucket;
      process_root(r);
    }
    minimal_source_side(on_source_side);
  }

private:
  static constexpr Index none = 0xFFFFFFFFu;
  static constexpr Index not_in_bucket = 0xFFFFFFFEu;

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
    bucket_next_.assign(n, not_in_bucket);
    current_.assign(n, 0);
    // The per-label arrays grow with the highest label (labels only ever rise by one), which stays far
    // below n in practice.
    bucket_head_.assign(2, none);
    bucket_tail_.assign(2, none);
    count_.assign(2, 0);
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
      excess_[x] = g_.initial_excess(x);
      if(excess_[x] < 0) {
        label_[x] = 1;
        scan_[tail++] = x;
      }
    }
    while(head < tail) {
      const Index x = scan_[head++];
      const Index next_label = label_[x] + 1;
      const Index d = g_.degree(x);
      for(Index k = 0; k < d; ++k) {
        const Index a = g_.arc(x, k);
        const Index y = g_.head(x, a);
        if(label_[y] == dead_ && g_.residual(y, g_.reverse(x, a)) > 0) {
          label_[y] = next_label;
          scan_[tail++] = y;
        }
      }
    }
    if(tail > 0) ensure_label(label_[scan_[tail - 1]]); // the BFS ends with the highest label
    for(Index x = 0; x < n_; ++x) {
      if(label_[x] == dead_) continue;
      ++count_[label_[x]];
      if(excess_[x] >= 0) add_to_bucket(x);
    }
  }

  void ensure_label(Index l)
  {
    if(l < count_.size()) return;
    const std::size_t size = (std::min)(std::size_t(n_) + 2, (std::max)(std::size_t(l) + 1, 2 * count_.size()));
    bucket_head_.resize(size, none);
    bucket_tail_.resize(size, none);
    count_.resize(size, 0);
  }

  void add_to_bucket(Index x)
  {
    const Index l = label_[x];
    bucket_next_[x] = none;
    if(bucket_tail_[l] == none) bucket_head_[l] = x;
    else bucket_next_[bucket_tail_[l]] = x;
    bucket_tail_[l] = x;
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
    const Index end = g_.degree(x);
    const Index target = l - 1;
    for(Index k = current_[x]; k < end; ++k) {
      const Index a = g_.arc(x, k);
      if(label_[g_.head(x, a)] == target && g_.residual(x, a) > 0) {
        current_[x] = k;
        arc = a;
        return true;
      }
    }
    current_[x] = end;
    return false;
  }

  void process_root(Index r)
  {
    const Index l = label_[r];
    ensure_label(l + 1);
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
      current_[x] = 0;
      if(x == r) break;
      x = parent_[x];
    }
    if(count_[l] == 0 || l + 1 > n_) kill_tree(r);
    else add_to_bucket(r);
  }

  // Re-roots r's tree at v, hangs it under w = head(arc) and pushes r's excess to the new root.
  void merge_and_push(Index r, Index v, Index arc)
  {
    const Index w = g_.head(v, arc);
    Index x = v, new_parent = w, new_arc = arc;
    for(;;) {
      const Index old_parent = parent_[x], old_arc = parent_arc_[x];
      if(old_parent != none) remove_from_parent(x);
      add_child(new_parent, x);
      parent_arc_[x] = new_arc;
      if(old_parent == none) break; // x == r
      new_arc = g_.reverse(x, old_arc);
      new_parent = x;
      x = old_parent;
    }

    Capacity delta = excess_[r];
    excess_[r] = 0;
    x = r;
    bool past_merger = false;
    while(parent_[x] != none) {
      // From w on, every tree arc has residual > 0 (T), so pushing nothing changes nothing: a
      // zero-excess root stops there instead of walking to the root.
      if(x == w) past_merger = true;
      if(past_merger && delta == 0) return;
      const Index a = parent_arc_[x], p = parent_[x];
      const Capacity available = g_.residual(x, a);
      if(delta >= available) {
        // Saturate and split: x keeps what the arc cannot take (exactly 0 when delta == available;
        // it is still made a strong root, so that weak roots keep label 1). An infinite residual
        // never gets here: the excesses are finite.
        g_.saturate(x, a);
        excess_[x] = delta - available;
        remove_from_parent(x);
        add_to_bucket(x);
        delta = available;
      } else {
        // delta < available, so the difference is positive: (T) holds on this arc afterwards.
        g_.push(x, a, delta);
      }
      x = p;
    }
    excess_[x] += delta;
    if(bucket_next_[x] == not_in_bucket && excess_[x] > 0) add_to_bucket(x);
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
    return Capacity(16) * std::numeric_limits<Capacity>::epsilon() * g_.capacity_scale(x);
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
      const Index d = g_.degree(x);
      for(Index k = 0; k < d; ++k) {
        const Index a = g_.arc(x, k);
        const Index y = g_.head(x, a);
        if(!side[y] && g_.residual(x, a) > 0) {
          side[y] = 1;
          stack[top++] = y;
        }
      }
    }
  }

  Graph& g_;
  Index n_ = 0, dead_ = 1, highest_ = 0;
  // Per node: 44 bytes with double capacities. `current_` is a position among the node's arcs;
  // `bucket_next_` is `not_in_bucket` for a node outside the buckets.
  std::vector<Capacity> excess_;
  std::vector<Index> label_, parent_, parent_arc_, first_child_, next_sibling_, previous_sibling_, scan_,
    current_, bucket_next_;
  // Per label.
  std::vector<Index> bucket_head_, bucket_tail_, count_;
};

} // namespace internal
} // namespace Min_cut
} // namespace CGAL

#endif // CGAL_MIN_CUT_INTERNAL_PSEUDOFLOW_SOLVER_H
