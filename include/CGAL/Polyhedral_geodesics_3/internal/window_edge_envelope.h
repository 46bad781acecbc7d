// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The windows of the exact propagation on each edge, kept as the lower envelope of their distance functions
// (thesis 4.1.4): window allocation and reuse, the doubly linked list along each edge, the insertion of a
// candidate piece (a sweep over the windows it overlaps: it survives in the gaps and where it is lower, and
// the old windows lose those parts), the joining of pieces of one distance function, and the interval
// merging of the approximate variant (thesis 4.2).
//
// Exact_window_propagation (exact_window_propagation.h) derives from this class (CRTP) and provides the two
// hooks the envelope calls: push(window), to (re)queue a window whose interval changed, and
// update_vertex(v, d, source), for a piece that reaches an end vertex of its edge.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_WINDOW_EDGE_ENVELOPE_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_WINDOW_EDGE_ENVELOPE_H

#include <CGAL/Polyhedral_geodesics_3/Geodesic_types.h>
#include <CGAL/Polyhedral_geodesics_3/internal/geodesic_window.h>
#include <CGAL/Polyhedral_geodesics_3/internal/window_field.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

template <class FT, class Propagation>
class Window_edge_envelope : public Window_field<FT>
{
  typedef Window_field<FT> Base;

public:
  typedef typename Base::Index Index;
  typedef typename Base::Mesh Mesh;
  typedef typename Base::Window Window;

protected:
  using Base::mesh_;
  using Base::windows_;
  using Base::edge_first_;
  using Base::dist_;
  using Base::relative_tolerance_;

  explicit Window_edge_envelope(const Mesh& mesh) : Base(mesh) {}

  Propagation& propagation() { return static_cast<Propagation&>(*this); }

  // Forgets every window; the edges are open again.
  void reset_envelopes()
  {
    windows_.clear();
    free_windows_.clear();
    edge_first_.assign(mesh_.number_of_edges, -1);
    edge_hint_.assign(mesh_.number_of_edges, -1);
    unpropagated_.assign(mesh_.number_of_edges, 0);
    edge_closed_.assign(mesh_.number_of_edges, 0);
    live_windows_ = 0;
  }

  // Frees the window storage (at the end of a run; the stored field has its own).
  void release_envelopes()
  {
    windows_.release();
    std::vector<Index>().swap(free_windows_);
    std::vector<Index>(mesh_.number_of_edges, -1).swap(edge_first_);
    std::vector<Index>().swap(edge_hint_);
  }

  // The path through a vertex (value `via`) beats the window (value `d`) by more than rounding.
  bool dominated(const FT& via, const FT& d) const { return via + relative_tolerance_ * d < d; }

  // ------------------------------------------------------------------------------------------------
  // Window storage and the lower envelope on an edge

  Index allocate_window()
  {
    ++live_windows_;
    if(live_windows_ > stats_.peak_live_windows)
      stats_.peak_live_windows = live_windows_;
    if(!free_windows_.empty()) {
      const Index i = free_windows_.back();
      free_windows_.pop_back();
      return i;
    }
    const std::size_t i = windows_.emplace_back();
    windows_[i].stamp = 0;
    windows_[i].filler = false;
    windows_[i].alive = false;
    windows_[i].processed = false;
    return Index(i);
  }

  void kill_window(Index wi)
  {
    Window& w = windows_[std::size_t(wi)];
    if(w.prev >= 0) windows_[std::size_t(w.prev)].next = w.next;
    else edge_first_[std::size_t(w.edge)] = w.next;
    if(w.next >= 0) windows_[std::size_t(w.next)].prev = w.prev;
    if(!w.processed)
      --unpropagated_[std::size_t(w.edge)];
    if(edge_hint_[std::size_t(w.edge)] == wi)
      edge_hint_[std::size_t(w.edge)] = w.prev >= 0 ? w.prev : w.next;
    w.alive = false;
    ++w.stamp;
    --live_windows_;
    free_windows_.push_back(wi);
  }

  // Links a new window after `after` (-1: at the front of the edge's list).
  Index create_window(Index edge, Index after, const FT& b0, const FT& b1, const FT& sx, const FT& sy,
                      const FT& sigma, Index from, Index source, bool processed, bool filler)
  {
    const Index wi = allocate_window();
    Window& w = windows_[std::size_t(wi)];
    w.b0 = b0;
    w.b1 = b1;
    w.next = w.prev = -1;
    w.sx = sx;
    w.sy = sy;
    w.sigma = sigma;
    w.edge = edge;
    w.from_halfedge = from;
    w.source = source;
    ++w.stamp;
    w.processed = processed || from < 0;
    w.filler = filler;
    w.alive = true;
    if(after < 0) {
      w.next = edge_first_[std::size_t(edge)];
      edge_first_[std::size_t(edge)] = wi;
    } else {
      w.prev = after;
      w.next = windows_[std::size_t(after)].next;
      windows_[std::size_t(after)].next = wi;
    }
    if(w.next >= 0)
      windows_[std::size_t(w.next)].prev = wi;
    edge_hint_[std::size_t(edge)] = wi;
    if(!w.processed)
      ++unpropagated_[std::size_t(edge)];
    ++stats_.windows_created;
    if(!w.processed)
      propagation().push(wi);
    return wi;
  }

  struct Interval
  {
    FT lo, hi;
  };

  // The sub-intervals of [lo, hi] where the new function (sw, aw, hw) is strictly below window v.
  void new_window_wins(const FT& aw, const FT& hw, const FT& sw, const Window& v, const FT& lo, const FT& hi,
                       std::vector<Interval>& out) const
  {
    FT roots[2];
    const int n = window_crossings(aw, hw, sw, v.sx, v.sy, v.sigma, lo, hi, roots);
    FT cuts[4];
    int m = 0;
    cuts[m++] = lo;
    for(int i = 0; i < n; ++i)
      cuts[m++] = roots[i];
    cuts[m++] = hi;
    for(int i = 0; i + 1 < m; ++i) {
      const FT a = cuts[i], c = cuts[i + 1];
      if(!(a < c))
        continue;
      const FT mid = (a + c) / FT(2);
      // win by more than rounding: two copies of the same distance function (one pseudo-source reached
      // through two unfoldings) must not fragment each other
      const FT old_value = window_distance_at(mid, v.sx, v.sy, v.sigma);
      if(window_distance_at(mid, aw, hw, sw) + relative_tolerance_ * old_value < old_value) {
        if(!out.empty() && out.back().hi == a)
          out.back().hi = c;
        else
          out.push_back(Interval{a, c});
      }
    }
  }

  // Inserts the candidate window [t0, t1] with pseudo-source (sx, sy) and offset sigma, given in the
  // frame of halfedge g (the pseudo-source on the side of g's face), into the lower envelope of g's edge. It
  // propagates into the faces of the other halfedges of the edge (none on a border edge).
  // `filler`: the piece's function is rooted at a point where no shortest path bends (see mergeable_over()).
  void insert_piece(Index g, FT t0, FT t1, FT sx, FT sy, const FT& sigma, Index source, bool filler = false)
  {
    insert_piece_impl(g, t0, t1, sx, sy, sigma, source, mesh_.he[std::size_t(g)].radial == g ? Index(-1) : g, filler);
  }

  void insert_piece_no_propagation(Index g, FT t0, FT t1, FT sx, FT sy, const FT& sigma, Index source)
  {
    insert_piece_impl(g, t0, t1, sx, sy, sigma, source, -1, false);
  }

  void insert_piece_impl(Index g, FT t0, FT t1, FT sx, FT sy, const FT& sigma, Index source, Index from, bool filler)
  {
    const Index e = mesh_.he[std::size_t(g)].edge;
    const Index hc = mesh_.edge_halfedge[std::size_t(e)];
    const FT L = mesh_.he[std::size_t(g)].length;
    if(!this->runs_like_canonical(g)) {
      // into the canonical frame (see Window_field::local_window for the sign of sy)
      const FT n0 = L - t1, n1 = L - t0;
      t0 = n0;
      t1 = n1;
      sx = L - sx;
      sy = -sy;
    }
    if(t0 < FT(0)) t0 = FT(0);
    if(t1 > L) t1 = L;
    if(t1 < t0) t1 = t0;
    const Index v0 = mesh_.source(hc), v1 = mesh_.target(hc);
    const FT d0 = window_distance_at(t0, sx, sy, sigma), d1 = window_distance_at(t1, sx, sy, sigma);
    // Xin-Wang filter on the new piece: the end vertices of the edge plus the edge beat it everywhere.
    if(dominated(dist_[std::size_t(v0)] + t1, d1) || dominated(dist_[std::size_t(v1)] + (L - t0), d0)) {
      ++stats_.windows_pruned;
      return;
    }
    if(t0 == FT(0)) propagation().update_vertex(v0, d0, source);
    if(t1 == L) propagation().update_vertex(v1, d1, source);
    if(edge_closed_[std::size_t(e)])
      return; // the edge's distance function is final and below everything that can still arrive

    if(L == FT(0)) {
      // A zero-length edge holds one point: keep the best window there.
      const Index old = edge_first_[std::size_t(e)];
      if(old >= 0) {
        const Window& o = windows_[std::size_t(old)];
        if(!(d0 < window_distance_at(FT(0), o.sx, o.sy, o.sigma)))
          return;
        kill_window(old);
      }
      create_window(e, -1, FT(0), FT(0), sx, sy, sigma, from, source, false, filler);
      return;
    }
    const FT tiny = relative_tolerance_ * L;
    if(!(t1 - t0 > tiny))
      return;

    // Sweep the windows overlapping (t0, t1): the new window survives in the gaps and where it wins.
    survive_.clear();
    changes_.clear();
    FT cursor = t0;
    // The sweep starts at the first window ending after t0, found from the edge's last touched window
    // (insertions on an edge tend to be close to each other) instead of from the edge's first window.
    Index last_before = -1; // the last window that ends at or before t0 (insertion point)
    Index start = edge_first_[std::size_t(e)];
    Index hint = edge_hint_[std::size_t(e)];
    if(hint >= 0) {
      if(windows_[std::size_t(hint)].b1 > t0) {
        for(Index p = windows_[std::size_t(hint)].prev; p >= 0 && windows_[std::size_t(p)].b1 > t0;
            p = windows_[std::size_t(p)].prev)
          hint = p;
        start = hint;
        last_before = windows_[std::size_t(hint)].prev;
      } else {
        for(Index n = windows_[std::size_t(hint)].next; n >= 0 && !(windows_[std::size_t(n)].b1 > t0);
            n = windows_[std::size_t(n)].next)
          hint = n;
        last_before = hint;
        start = windows_[std::size_t(hint)].next;
      }
    }
    for(Index vi = start; vi >= 0; vi = windows_[std::size_t(vi)].next) {
      const Window& v = windows_[std::size_t(vi)];
      if(!(v.b1 > t0)) {
        last_before = vi;
        continue;
      }
      if(!(v.b0 < t1))
        break;
      if(v.b0 > cursor)
        append_interval(survive_, cursor, v.b0);
      const FT lo = v.b0 > t0 ? v.b0 : t0;
      const FT hi = v.b1 < t1 ? v.b1 : t1;
      wins_.clear();
      new_window_wins(sx, sy, sigma, v, lo, hi, wins_);
      for(const Interval& iv : wins_)
        append_interval(survive_, iv.lo, iv.hi);
      if(!wins_.empty())
        changes_.push_back(Change{vi, std::size_t(changes_win_.size()), wins_.size()});
      changes_win_.insert(changes_win_.end(), wins_.begin(), wins_.end());
      if(v.b1 > cursor)
        cursor = v.b1;
    }
    if(cursor < t1)
      append_interval(survive_, cursor, t1);
    // drop slivers (they cannot matter beyond rounding; vertex distances were updated above)
    std::size_t kept = 0;
    for(const Interval& iv : survive_)
      if(iv.hi - iv.lo > tiny)
        survive_[kept++] = iv;
    survive_.resize(kept);
    if(survive_.empty()) {
      changes_win_.clear();
      return;
    }

    // Cut the losing parts out of the old windows.
    for(const Change& c : changes_) {
      Window& v = windows_[std::size_t(c.window)];
      remain_.clear();
      FT start = v.b0;
      for(std::size_t i = 0; i < c.count; ++i) {
        const Interval& iv = changes_win_[c.first + i];
        if(iv.lo - start > tiny)
          remain_.push_back(Interval{start, iv.lo});
        start = iv.hi;
      }
      if(v.b1 - start > tiny)
        remain_.push_back(Interval{start, v.b1});
      if(remain_.empty()) {
        kill_window(c.window);
        continue;
      }
      const bool changed = remain_.front().lo != v.b0 || remain_.front().hi != v.b1;
      const FT vsx = v.sx, vsy = v.sy, vsigma = v.sigma;
      const Index vfrom = v.from_halfedge, vsource = v.source;
      const bool vprocessed = v.processed, vfiller = v.filler;
      v.b0 = remain_.front().lo;
      v.b1 = remain_.front().hi;
      if(changed) {
        ++v.stamp;
        if(!v.processed)
          propagation().push(c.window);
      }
      Index after = c.window;
      for(std::size_t i = 1; i < remain_.size(); ++i)
        after = create_window(e, after, remain_[i].lo, remain_[i].hi, vsx, vsy, vsigma, vfrom, vsource, vprocessed,
                              vfiller);
    }
    changes_win_.clear();

    // Link the surviving pieces of the new window at their places.
    Index after = last_before;
    for(const Interval& iv : survive_) {
      Index next = after < 0 ? edge_first_[std::size_t(e)] : windows_[std::size_t(after)].next;
      while(next >= 0 && !(iv.lo < windows_[std::size_t(next)].b0)) {
        after = next;
        next = windows_[std::size_t(next)].next;
      }
      // A window split by a vertex meets itself again on the edges beyond: join the pieces of one
      // distance function instead of propagating them separately.
      if(after >= 0 && same_function(windows_[std::size_t(after)], sx, sy, sigma, from) &&
         windows_[std::size_t(after)].b1 == iv.lo) {
        Window& p = windows_[std::size_t(after)];
        p.b1 = iv.hi;
        p.filler = p.filler && filler; // the same function: as good as the better of the two
        ++p.stamp;
        ++stats_.windows_merged;
        merge_with_next(after);
        propagation().push(after);
        continue;
      }
      after = create_window(e, after, iv.lo, iv.hi, sx, sy, sigma, from, source, false, filler);
      merge_with_next(after);
    }
  }

  bool same_function(const Window& w, const FT& sx, const FT& sy, const FT& sigma, Index from) const
  {
    using std::abs;
    if(w.processed || w.from_halfedge != from)
      return false;
    const FT scale = abs(sx) + abs(sy) + sigma + (w.b1 - w.b0);
    const FT tol = FT(16) * relative_tolerance_ * scale;
    return abs(w.sx - sx) <= tol && abs(w.sy - sy) <= tol && abs(w.sigma - sigma) <= tol;
  }

  // Joins window wi with its successor if they continue each other with the same distance function.
  void merge_with_next(Index wi)
  {
    Window& w = windows_[std::size_t(wi)];
    const Index ni = w.next;
    if(ni < 0)
      return;
    const Window& n = windows_[std::size_t(ni)];
    if(n.b0 != w.b1 || !same_function(n, w.sx, w.sy, w.sigma, w.from_halfedge) || w.processed)
      return;
    const FT b1 = n.b1;
    const bool filler = w.filler && n.filler;
    kill_window(ni);
    Window& w2 = windows_[std::size_t(wi)];
    w2.b1 = b1;
    w2.filler = filler;
    ++w2.stamp;
    ++stats_.windows_merged;
    propagation().push(wi);
  }

  // ------------------------------------------------------------------------------------------------
  // Interval merging (approximation, thesis 4.2)
  //
  // Window wi is about to propagate. A contiguous neighbour n on the same edge, looking into the same
  // face and not yet propagated, is joined with it when one of the two distance functions, extended over
  // the other's interval, stays within [D_other, D_other + tolerance] there; when both do, the one that
  // deviates less is kept (so a side lobe, rooted at a window end, does not absorb the window of a real
  // source that reproduces it: flat regions stay exact). Two rules keep the thesis's dependence DAG
  // acyclic without storing it: only windows without children (not yet propagated) are merged, so a merge
  // joins two leaves; and merging never lowers a value, so every value remains a path-length bound (>= the
  // exact distance) and a window's descendants can never undercut it, which is what would close a cycle
  // (and stall path tracing).
  void absorb_similar_neighbours(Index wi)
  {
    for(int side = 0; side < 2; ++side) {
      for(;;) {
        const Window& w = windows_[std::size_t(wi)];
        const Index ni = side == 0 ? w.next : w.prev;
        if(ni < 0)
          break;
        const Window& n = windows_[std::size_t(ni)];
        if(n.processed || n.from_halfedge != w.from_halfedge || (side == 0 ? n.b0 != w.b1 : n.b1 != w.b0))
          break;
        const FT w_over_n = mergeable_over(w, n), n_over_w = mergeable_over(n, w);
        if(w_over_n < FT(0) && n_over_w < FT(0))
          break;
        const bool keep_w = !(n_over_w >= FT(0)) || (w_over_n >= FT(0) && !(n_over_w < w_over_n));
        const Window absorbed = n;
        kill_window(ni);
        Window& w2 = windows_[std::size_t(wi)];
        if(side == 0) w2.b1 = absorbed.b1;
        else w2.b0 = absorbed.b0;
        if(!keep_w) {
          w2.sx = absorbed.sx;
          w2.sy = absorbed.sy;
          w2.sigma = absorbed.sigma;
          w2.source = absorbed.source;
          w2.filler = absorbed.filler;
        }
        ++stats_.windows_merged;
      }
    }
  }

  // The largest excess of D_w over D_n on n's interval if D_n <= D_w <= D_n + tolerance there, else -1.
  FT merge_deviation(const Window& w, const Window& n) const
  {
    return window_merge_deviation(w.sx, w.sy, w.sigma, n.sx, n.sy, n.sigma, n.b0, n.b1, merge_tolerance_,
                                  relative_tolerance_);
  }

  // merge_deviation(w, n) if w may also replace n. A *filler* w (rooted at a point where no shortest path bends: a
  // side lobe at a gap inside an edge, the window of a flat vertex or of a border vertex of angle at most pi, or a
  // descendant of one) is a real path, but one that the wavefront through that point undercuts wherever that
  // wavefront can reach: it only fills in until a continuation of that wavefront arrives. It must not replace a
  // window n of another kind whose function, extended over w's interval, undercuts w there. Before this rule,
  // merging kept such fillers over the direct windows beside them, and on flat meshes (where the direct function is
  // the exact distance everywhere and every other function lies above it) 1 to 550 vertices rose by up to 0.66
  // tolerances above the straight-line distance in the window propagation (the manual, *Merged windows on flat
  // meshes*). With it, the direct windows of a flat mesh are never replaced, and the result there is exact.
  // Windows of saddles and of reflex border vertices are not fillers: the merges that make the approximation fast
  // on curved meshes (a shadow window behind a saddle with the direct window beside it) are unchanged.
  FT mergeable_over(const Window& w, const Window& n) const
  {
    const FT deviation = merge_deviation(w, n);
    if(deviation < FT(0) || !w.filler || n.filler)
      return deviation;
    const FT dw = window_min_distance(w.b0, w.b1, w.sx, w.sy, w.sigma);
    const FT undercut = window_min_difference(n.sx, n.sy, n.sigma, w.sx, w.sy, w.sigma, w.b0, w.b1);
    if(undercut + relative_tolerance_ * (dw + merge_tolerance_) < FT(0))
      return FT(-1);
    return deviation;
  }

  static void append_interval(std::vector<Interval>& list, const FT& lo, const FT& hi)
  {
    if(!(lo < hi))
      return;
    if(!list.empty() && list.back().hi == lo)
      list.back().hi = hi;
    else
      list.push_back(Interval{lo, hi});
  }

  struct Change
  {
    Index window;
    std::size_t first, count;
  };

  std::vector<Index> free_windows_;
  std::vector<Index> edge_hint_;     // a window of the edge (the last one created), -1 if none
  std::vector<Index> unpropagated_;  // per edge, the number of its windows not propagated yet
  std::vector<char> edge_closed_;    // per edge: final and released, later pieces are rejected at once
  Geodesic_statistics stats_;
  std::size_t live_windows_ = 0;
  FT merge_tolerance_ = FT(0);
  // scratch of insert_piece_impl
  std::vector<Interval> survive_, wins_, remain_, changes_win_;
  std::vector<Change> changes_;
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_WINDOW_EDGE_ENVELOPE_H
