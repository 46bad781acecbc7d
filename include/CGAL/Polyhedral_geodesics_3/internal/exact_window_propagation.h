// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The exact interval ("window") propagation with side lobes (thesis, chapter 4.1), on the compact mesh.
//
// - Every edge holds the lower envelope of its windows: a doubly linked list sorted along the edge.
// - A window is propagated once, across the face on the far side from its pseudo-source S (across every such face
//   of an edge of three or more faces; each is unfolded on its own, see geodesic_window.h). On each of
//   the two other edges of that face a point y is reached either straight from S (the segment S-y
//   crosses the window: the *central* part) or through the nearer end point P0 or P1 of the window
//   (the *side lobes*, rooted at P0 and P1 with offsets sigma + |S P0|, sigma + |S P1|). A lobe rooted at
//   a saddle or boundary vertex is exactly the pseudo-source MMP needs there; a lobe rooted inside an edge
//   covers any numerical gap between neighbouring windows.
// - Windows come out of a radix heap (double keys; a 4-ary heap otherwise) by their minimal distance (lazy
//   deletion by a stamp); they are stored
//   in fixed-size blocks (Window_store.h) and freed windows are reused.
// - The windows of an edge leave the propagation's store as soon as the front has passed the edge's largest
//   value (a second heap of edges keyed by that value): the full-field mode first copies them, compacted,
//   into the stored field (window_field.h); the distances-only mode just frees them.
// - The stored field (windows, vertex distances) and its queries and path tracing are in window_field.h.
// - Pruning (Xin and Wang's filter): a window, or a new piece of one, is dropped when a known vertex
//   distance plus a straight segment beats it on its whole extent; vertex distances are kept current
//   from every window that reaches a vertex.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_EXACT_WINDOW_PROPAGATION_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_EXACT_WINDOW_PROPAGATION_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_types.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>
#include <CGAL/Polyhedral_geodesics_3/internal/geodesic_engine_types.h>
#include <CGAL/Polyhedral_geodesics_3/internal/geodesic_window.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Quaternary_heap.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Radix_heap.h>
#include <CGAL/Polyhedral_geodesics_3/internal/window_edge_envelope.h>
#include <CGAL/Polyhedral_geodesics_3/internal/window_field.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

template <class FT>
class Exact_window_propagation : public Window_edge_envelope<FT, Exact_window_propagation<FT>>
{
  typedef Window_edge_envelope<FT, Exact_window_propagation<FT>> Base;
  friend Base;
  typedef typename Base::Face_source Face_source;
  typedef typename Base::Interval Interval;
  using Base::mesh_;
  using Base::windows_;
  using Base::edge_first_;
  using Base::dist_;
  using Base::vertex_source_;
  using Base::face_sources_;
  using Base::star_begin_;
  using Base::star_;
  using Base::unreached_;
  using Base::relative_tolerance_;
  using Base::limit_;
  using Base::front_;
  using Base::has_limit_;
  using Base::stopped_early_;
  using Base::ensure_vertex_star;
  using Base::point_in_halfedge_frame;
  using Base::finite_answer;
  using Base::local_window;
  using Base::free_windows_;
  using Base::edge_hint_;
  using Base::unpropagated_;
  using Base::edge_closed_;
  using Base::stats_;
  using Base::live_windows_;
  using Base::merge_tolerance_;
  using Base::dominated;
  using Base::kill_window;
  using Base::insert_piece;
  using Base::insert_piece_no_propagation;
  using Base::absorb_similar_neighbours;
  using Base::append_interval;

public:
  typedef typename Base::Index Index;
  typedef typename Base::Mesh Mesh;
  typedef typename Base::Window Window;
  typedef typename Base::Path_node Path_node;
  typedef typename Base::Point_distance Point_distance;

  explicit Exact_window_propagation(const Mesh& mesh) : Base(mesh)
  {
    vertex_is_pseudo_source_.assign(mesh_.number_of_vertices, 0);
    for(std::size_t v = 0; v < mesh_.number_of_vertices; ++v)
      vertex_is_pseudo_source_[v] = is_saddle_or_boundary_vertex(mesh_, v);
    clear();
  }

  void clear()
  {
    this->reset_envelopes();
    heap_.clear();
    release_queued_.assign(mesh_.number_of_edges, 0);
    release_heap_.clear();
    since_release_ = 0;
    release_interval_ = mesh_.number_of_edges / 2 + 1024;
    dist_.assign(mesh_.number_of_vertices, unreached_);
    vertex_source_.assign(mesh_.number_of_vertices, -1);
    vertex_stamp_.assign(mesh_.number_of_vertices, 0);
    expanded_stamp_.assign(mesh_.number_of_vertices, std::uint32_t(-1));
    face_sources_.clear();
    this->reset_field(false);
    stats_ = Geodesic_statistics();
    front_ = FT(0);
    stopped_early_ = false;
  }

  void set_keep_windows(bool keep) { keep_windows_ = keep; }
  void set_distance_limit(FT limit) { limit_ = limit; has_limit_ = true; }
  void clear_distance_limit() { has_limit_ = false; }
  void set_stop_targets(const std::vector<Index>& targets) { stop_targets_ = targets; }
  // Side lobes at window ends on vertices (redundant with the vertex expansion) and at ends where the
  // neighbouring window continues the wavefront (redundant up to rounding). Both off by default.
  // Approximation by interval merging (thesis 4.2): before a window propagates, it absorbs neighbours
  // on its edge whose distance function it reproduces within `tolerance` (absolute). 0: exact.
  void set_merge_tolerance(const FT& tolerance) { merge_tolerance_ = tolerance; }

  void set_lobe_options(bool lobes_at_vertices, bool lobes_at_contiguous_ends)
  {
    lobes_at_vertices_ = lobes_at_vertices;
    lobes_at_contiguous_ends_ = lobes_at_contiguous_ends;
  }

  // ------------------------------------------------------------------------------------------------
  // Sources

  void add_vertex_source(Index v, Index id)
  {
    if(v < 0 || std::size_t(v) >= mesh_.number_of_vertices)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: source vertex not in the mesh");
    update_vertex(v, FT(0), id);
    expand_vertex(v);
  }

  void add_face_source(Index f, const std::array<FT, 3>& b, Index id)
  {
    if(f < 0 || std::size_t(f) >= mesh_.number_of_faces)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: source face not in the mesh");
    int zeros = 0;
    for(int k = 0; k < 3; ++k)
      if(b[k] == FT(0))
        ++zeros;
    if(zeros >= 2) {
      for(int k = 0; k < 3; ++k)
        if(b[k] != FT(0))
          return add_vertex_source(mesh_.source(3 * f + k), id);
    }
    add_point_source_in_face(f, b, id);
    if(zeros == 1) {
      // On an edge: the point is also a source inside the face on the other side, and the edge itself
      // carries the distance along it.
      int k = 0;
      while(b[(k + 2) % 3] != FT(0))
        ++k;
      const Index g = 3 * f + k;         // the halfedge carrying the point (corners k and k+1)
      const FT len = mesh_.he[g].length;
      const FT t = b[(k + 1) % 3] * len;
      insert_piece_no_propagation(g, FT(0), len, t, FT(0), FT(0), id);
      // every other face of the edge (the twin's on an oriented manifold edge)
      mesh_.for_each_other_halfedge(g, [&](Index tw) {
        std::array<FT, 3> b2 = {FT(0), FT(0), FT(0)};
        const bool same = mesh_.same_direction(tw, g);
        b2[std::size_t(tw % 3)] = same ? b[k] : b[(k + 1) % 3];             // the weight of source(tw)
        b2[std::size_t((tw % 3 + 1) % 3)] = same ? b[(k + 1) % 3] : b[k];   // the weight of target(tw)
        add_point_source_in_face(Mesh::face_of(tw), b2, id);
      });
    }
  }

  // ------------------------------------------------------------------------------------------------
  // Propagation

  template <class Progress>
  void run(Progress& progress)
  {
    const char* stage = "geodesic propagation";
    if(!progress(stage, 0.0))
      throw MDCS::Operation_cancelled(stage);
    this->reset_field(keep_windows_);
    std::size_t pops = 0;
    do {
      while(!heap_.empty()) {
        const Heap_entry top = heap_.pop();
        if(top.window < 0) {
          const Index v = -top.window - 1;
          if(top.stamp != vertex_stamp_[std::size_t(v)] || expanded_stamp_[std::size_t(v)] == top.stamp)
            continue;
          front_ = top.key;
          if(has_limit_ && top.key > limit_) {
            stopped_early_ = true;
            break;
          }
          expand_vertex(v, !is_bend_vertex(v));
          continue;
        }
        Window& w = windows_[std::size_t(top.window)];
        if(!w.alive || w.stamp != top.stamp || w.processed)
          continue;
        front_ = top.key;
        if(has_limit_ && top.key > limit_) {
          stopped_early_ = true;
          break;
        }
        if(!stop_targets_.empty() && (pops & 15) == 0 && stop_targets_final(top.key)) {
          stopped_early_ = true;
          break;
        }
        if(merge_tolerance_ > FT(0))
          absorb_similar_neighbours(top.window);
        windows_[std::size_t(top.window)].processed = true;
        const Index top_edge = windows_[std::size_t(top.window)].edge;
        --unpropagated_[std::size_t(top_edge)];
        propagate(top.window);
        ++stats_.windows_propagated;
        // Both modes release the edges behind the front; the full-field mode first copies them into the
        // stored field.
        if(unpropagated_[std::size_t(top_edge)] == 0)
          queue_edge_release(top_edge);
        release_passed_edges(top.key);
        if(++since_release_ >= release_interval_) {
          since_release_ = 0;
          release_final_edges(top.key);
          // a scan costs O(edges + windows): space the scans so that it stays O(1) per propagated window
          release_interval_ = mesh_.number_of_edges / 2 + live_windows_ + 1024;
        }
        if((++pops & 0xFFFF) == 0) {
          if(!MDCS::internal::Reports_nothing<Progress>::value && !progress(stage, fraction_final(top.key)))
            throw MDCS::Operation_cancelled(stage);
        }
      }
    } while(!stopped_early_ && expand_stranded_neighbours());
    if(stopped_early_) {
      // Only distances below the front are final; report the others as unreachable, never as a wrong value.
      const FT bound = has_limit_ && front_ > limit_ ? limit_ : front_;
      for(std::size_t v = 0; v < dist_.size(); ++v)
        if(dist_[v] > bound) {
          dist_[v] = unreached_;
          vertex_source_[v] = -1;
        }
      heap_.release();
    } else if(has_limit_) {
      for(std::size_t v = 0; v < dist_.size(); ++v)
        if(dist_[v] > limit_) {
          dist_[v] = unreached_;
          vertex_source_[v] = -1;
        }
    }
    stats_.stopped_early = stopped_early_;
    stats_.stored_windows = live_windows_;
    if(keep_windows_) {
      for(std::size_t e = 0; e < edge_first_.size(); ++e)
        if(edge_first_[e] >= 0)
          this->store_edge_field(e);
      stats_.stored_windows = this->field_windows_.size();
    }
    note_memory();
    this->release_envelopes();
    heap_.release();
    release_heap_.release();
    if(!progress(stage, 1.0))
      throw MDCS::Operation_cancelled(stage);
  }

  const Geodesic_statistics& statistics() const { return stats_; }

private:
  // ------------------------------------------------------------------------------------------------
  // Heap

  struct Heap_entry
  {
    FT key;
    Index window;
    std::uint32_t stamp;
  };

  void push(Index wi)
  {
    const Window& w = windows_[std::size_t(wi)];
    heap_.push(Heap_entry{window_min_distance(w.b0, w.b1, w.sx, w.sy, w.sigma), wi, w.stamp});
    note_memory();
  }

  void note_memory()
  {
    const std::size_t bytes = windows_.capacity() * sizeof(Window) +
                              (heap_.capacity() + release_heap_.capacity()) * sizeof(Heap_entry) +
                              this->field_bytes();
    if(bytes > stats_.peak_memory_bytes)
      stats_.peak_memory_bytes = bytes;
  }

  // The windows behind the front leave the store: an edge covered end to end by propagated windows whose
  // values all lie below the front will never change again (everything still to come is at least the
  // front), so its windows are released (copied into the stored field first in full-field mode) and later
  // candidates are rejected at once.
  //
  // The largest value on edge e if it is covered end to end by propagated windows, else -1.
  FT final_edge_bound(std::size_t e) const
  {
    Index wi = edge_first_[e];
    if(wi < 0 || edge_closed_[e])
      return FT(-1);
    const FT L = mesh_.he[std::size_t(mesh_.edge_halfedge[e])].length;
    // gaps up to `tiny` do not count: insert_piece drops pieces that narrow
    const FT tiny = relative_tolerance_ * L;
    FT covered = FT(0), bound = FT(0);
    for(; wi >= 0; wi = windows_[std::size_t(wi)].next) {
      const Window& w = windows_[std::size_t(wi)];
      if(w.b0 - covered > tiny || !w.processed)
        return FT(-1);
      // a window's distance is convex along the edge: its largest value is at an end
      const FT d0 = window_distance_at(w.b0, w.sx, w.sy, w.sigma), d1 = window_distance_at(w.b1, w.sx, w.sy, w.sigma);
      if(d0 > bound) bound = d0;
      if(d1 > bound) bound = d1;
      covered = w.b1;
    }
    return L - covered > tiny ? FT(-1) : bound;
  }

  void release_edge(std::size_t e)
  {
    if(keep_windows_)
      this->store_edge_field(e);
    while(edge_first_[e] >= 0)
      kill_window(edge_first_[e]);
    edge_closed_[e] = 1;
  }

  // Releases the edge if it is final below `front`.
  void release_if_final(std::size_t e, const FT& front)
  {
    const FT bound = final_edge_bound(e);
    if(!(bound < FT(0)) && bound < front)
      release_edge(e);
  }

  // A full scan, the fallback of the incremental release below (edges whose last unpropagated window died
  // instead of being propagated are not queued).
  void release_final_edges(const FT& front)
  {
    for(std::size_t e = 0; e < edge_first_.size(); ++e)
      release_if_final(e, front);
  }

  // Called when edge e has no unpropagated window left: queue it to be released when the front passes
  // its largest value. A window that arrives later has its own propagation re-queue the edge.
  // An edge has at most one entry; when it comes out and the edge gained windows meanwhile, it is queued
  // again with its new largest value.
  void queue_edge_release(Index e)
  {
    if(release_queued_[std::size_t(e)])
      return;
    const FT bound = final_edge_bound(std::size_t(e));
    if(bound < FT(0))
      return;
    release_queued_[std::size_t(e)] = 1;
    release_heap_.push(Heap_entry{bound, e, 0});
  }

  void release_passed_edges(const FT& front)
  {
    while(!release_heap_.empty() && release_heap_.top().key < front) {
      const Index e = release_heap_.pop().window;
      release_queued_[std::size_t(e)] = 0;
      const FT bound = final_edge_bound(std::size_t(e));
      if(bound < FT(0))
        continue;
      if(bound < front)
        release_edge(std::size_t(e));
      else
        queue_edge_release(e);
    }
  }

  bool stop_targets_final(const FT& key) const
  {
    for(Index v : stop_targets_)
      if(!(dist_[std::size_t(v)] <= key))
        return false;
    return true;
  }

  double fraction_final(const FT& key) const
  {
    std::size_t n = 0;
    for(const FT& d : dist_)
      if(d <= key)
        ++n;
    return dist_.empty() ? 1.0 : double(n) / double(dist_.size());
  }

  void update_vertex(Index v, const FT& d, Index source)
  {
    if(d < dist_[std::size_t(v)]) {
      dist_[std::size_t(v)] = d;
      vertex_source_[std::size_t(v)] = source;
      if(vertex_is_pseudo_source_[std::size_t(v)]) {
        // A shortest path may bend here: once this distance is final, the vertex emits its own windows.
        const std::uint32_t stamp = ++vertex_stamp_[std::size_t(v)];
        heap_.push(Heap_entry{d, -v - 1, stamp});
      }
    }
  }

  // A safety net for merging (and for any rounding accident): a vertex left unreached next to a reached one.
  // With merging, pruning compares with values that are upper bounds, not exact distances, so a trimmed part
  // may be the only cover of a vertex: measured, 2 vertices of 37,706 at a tolerance of 3 edge lengths on
  // bunny00 (none at 1 or below). Its reached neighbours are then expanded as pseudo-sources (real paths
  // through them: the values stay upper bounds) and the propagation goes on. Returns false if there was
  // nothing to do (an exact run on a connected mesh: one scan).
  bool expand_stranded_neighbours()
  {
    if(has_limit_)
      return false; // beyond the limit, +infinity is the answer
    ensure_vertex_star();
    const bool any = expand_reached_neighbours_of_unreached(mesh_, star_begin_, star_, dist_, unreached_,
                                                            [this](Index w) { expand_vertex(w); });
    if(any)
      ++stats_.stranded_expansions;
    return any;
  }

  // The vertex as a pseudo-source with its current distance: a window over the opposite edge of every
  // incident face (it sees that edge entirely), and the arc length along every incident edge. These are the
  // side lobes rooted at the vertex, emitted once, when its distance is final, instead of by every window
  // that ends there (those lobes would carry the window's own, possibly larger, value at the vertex; and
  // pruning may remove the window that would have carried the best one).
  // `filler`: the vertex is not one where shortest paths bend (see Window_edge_envelope::mergeable_over).
  void expand_vertex(Index v, bool filler = false)
  {
    ensure_vertex_star();
    expanded_stamp_[std::size_t(v)] = vertex_stamp_[std::size_t(v)];
    const FT d = dist_[std::size_t(v)];
    const Index id = vertex_source_[std::size_t(v)];
    for(Index k = star_begin_[std::size_t(v)]; k < star_begin_[std::size_t(v) + 1]; ++k) {
      const Index h = star_[std::size_t(k)];  // source(h) == v
      const Index g = Mesh::next(h);          // the edge opposite v in the face of h
      const auto& p = mesh_.he[std::size_t(g)].opposite;
      insert_piece(g, FT(0), mesh_.he[std::size_t(g)].length, p.x, p.y, d, id, filler);
      insert_piece_no_propagation(h, FT(0), mesh_.he[std::size_t(h)].length, FT(0), FT(0), d, id);
      const Index hp = Mesh::prev(h);
      insert_piece_no_propagation(hp, FT(0), mesh_.he[std::size_t(hp)].length, mesh_.he[std::size_t(hp)].length,
                                  FT(0), d, id);
    }
  }

  void add_point_source_in_face(Index f, const std::array<FT, 3>& b, Index id)
  {
    face_sources_.push_back(Face_source{f, b, id});
    for(int k = 0; k < 3; ++k) {
      const Index g = 3 * f + k;
      const Point_2_ft<FT> p = point_in_halfedge_frame(f, b, k);
      // the distance to the corner source(g)
      update_vertex(mesh_.source(g), distance_2(FT(0), FT(0), p.x, p.y), id);
      if(b[std::size_t((k + 2) % 3)] == FT(0))
        continue; // the point is on this edge: handled by the caller
      insert_piece(g, FT(0), mesh_.he[std::size_t(g)].length, p.x, p.y, FT(0), id);
    }
  }

  // A vertex where shortest paths can bend, strictly (for merging; the exact rule, is_saddle_or_boundary_vertex,
  // also takes flat vertices and every border vertex): a singular vertex, a saddle, or a border vertex whose angle
  // sum exceeds pi, with a margin of 1e-9 for rounding.
  bool is_bend_vertex(Index v) const
  {
    const double pi = 3.14159265358979323846;
    const std::size_t i = std::size_t(v);
    if(!mesh_.vertex_is_singular.empty() && mesh_.vertex_is_singular[i])
      return true;
    return to_double_value(mesh_.vertex_angle_sum[i]) > (mesh_.vertex_on_boundary[i] ? pi : 2 * pi) + 1e-9;
  }

  // ------------------------------------------------------------------------------------------------
  // Propagation of one window across the faces it looks into: the twin's face on an edge of an oriented manifold,
  // every face but the one it comes from on a non-manifold edge.

  void propagate(Index wi)
  {
    const Index from = windows_[std::size_t(wi)].from_halfedge;
    mesh_.for_each_other_halfedge(from, [&](Index h) { propagate_into(wi, h); });
  }

  void propagate_into(Index wi, Index h)
  {
    const Window& w = windows_[std::size_t(wi)];
    const Index source = w.source;
    const Local_window<FT> lw_in = local_window(w, h);
    const Index prev_w = w.prev, next_w = w.next;
    const bool canonical = this->runs_like_canonical(h);
    const FT L = mesh_.he[std::size_t(h)].length;
    const Point_2_ft<FT> c = mesh_.he[std::size_t(h)].opposite;
    const Index va = mesh_.source(h), vb = mesh_.target(h), vc = mesh_.opposite_vertex(h);

    // Xin-Wang filter, as trimming: the part of the window that A (along the edge), B (along the edge)
    // or C (straight) beats is not propagated, since every point beyond it is reached better through
    // that vertex (and a vertex a shortest path can pass through emits its own windows).
    Local_window<FT> lw = lw_in;
    const FT da = dist_[std::size_t(va)], db = dist_[std::size_t(vb)], dcv = dist_[std::size_t(vc)];
    bool trimmed0 = false, trimmed1 = false;
    if(!trim_by_vertex(lw, FT(0), FT(0), da, trimmed0, trimmed1) ||
       !trim_by_vertex(lw, L, FT(0), db, trimmed0, trimmed1) ||
       !trim_by_vertex(lw, c.x, c.y, dcv, trimmed0, trimmed1)) {
      ++stats_.windows_pruned;
      return;
    }
    const FT d_p0 = window_distance_at(lw.b0, lw.sx, lw.sy, lw.sigma);
    const FT d_p1 = window_distance_at(lw.b1, lw.sx, lw.sy, lw.sigma);
    const FT c_p0 = distance_2(c.x, c.y, lw.b0, FT(0)), c_p1 = distance_2(c.x, c.y, lw.b1, FT(0));

    // Where the segment from S to C crosses the line AB (the edge AC sees crossings from 0 to xc,
    // the edge BC from L to xc; crossings are monotone along each edge).
    const FT denom = c.y - lw.sy;
    const bool flat_source = !(denom > FT(0)); // S and C both on the line AB: a degenerate face
    const FT xc = flat_source ? lw.sx : lw.sx + (c.x - lw.sx) * (-lw.sy) / denom;

    // Which side lobes to emit. A lobe rooted at a window end inside the edge is only a gap filler; it is
    // useless when the neighbouring window on the same side continues the wavefront there.
    bool lobe0 = !trimmed0, lobe1 = !trimmed1;
    if(trimmed0) {
    } else if(lw.b0 == FT(0)) {
      lobe0 = lobes_at_vertices_;
    } else if(!lobes_at_contiguous_ends_) {
      lobe0 = !contiguous_neighbour(canonical ? prev_w : next_w, h, lw.b0, true);
    }
    if(trimmed1) {
    } else if(lw.b1 == L) {
      lobe1 = lobes_at_vertices_;
    } else if(!lobes_at_contiguous_ends_) {
      lobe1 = !contiguous_neighbour(canonical ? next_w : prev_w, h, lw.b1, false);
    }

    // The value at C, from the class C falls in.
    FT dc;
    if(xc < lw.b0) dc = d_p0 + c_p0;
    else if(xc > lw.b1) dc = d_p1 + c_p1;
    else dc = lw.sigma + distance_2(lw.sx, lw.sy, c.x, c.y);
    update_vertex(vc, dc, source);

    // Fillers (for merging): the children of a filler, and the side lobes rooted inside the edge (gap fillers) or at a
    // vertex where no path bends.
    const bool filler = windows_[std::size_t(wi)].filler;
    const bool lobe0_filler = lw.b0 > FT(0) || !is_bend_vertex(va);
    const bool lobe1_filler = lw.b1 < L || !is_bend_vertex(vb);
    const Propagation_data pd{lw, d_p0, d_p1, xc, flat_source, lobe0, lobe1, filler, lobe0_filler, lobe1_filler, source, h};
    // edge C->A (halfedge prev(h)), walked from A (u = 0) to C (u = 1)
    emit_pieces(pd, Mesh::prev(h), FT(0), FT(0), c, FT(0), true);
    // edge B->C (halfedge next(h)), walked from B (u = 0) to C (u = 1)
    emit_pieces(pd, Mesh::next(h), L, FT(0), c, L, false);
  }

  // Removes from the window the end parts where the vertex at (qx, qy) with distance dq beats it (dq plus
  // the straight segment to the window point). The beaten set is an interval (inside a branch of a
  // hyperbola); only a prefix or a suffix is cut, an inner part is left. Returns false if nothing remains.
  bool trim_by_vertex(Local_window<FT>& w, const FT& qx, const FT& qy, const FT& dq, bool& trimmed0, bool& trimmed1) const
  {
    if(!(dq < unreached_))
      return true;
    const bool beaten0 = dominated(dq + distance_2(qx, qy, w.b0, FT(0)), window_distance_at(w.b0, w.sx, w.sy, w.sigma));
    const bool beaten1 = dominated(dq + distance_2(qx, qy, w.b1, FT(0)), window_distance_at(w.b1, w.sx, w.sy, w.sigma));
    if(!beaten0 && !beaten1)
      return true;
    FT roots[2];
    const int n = window_crossings(w.sx, w.sy, w.sigma, qx, qy, dq, w.b0, w.b1, roots);
    if(beaten0 && beaten1) {
      if(n < 2)
        return false;            // beaten everywhere (no crossing inside, or only a tangency)
      return true;               // beaten at both ends, not in the middle: keep it whole (rare)
    }
    if(n == 0)
      return true;               // rounding: the ends disagree but no crossing was found
    if(beaten0) {
      w.b0 = roots[0];
      trimmed0 = true;
    } else {
      w.b1 = roots[n - 1];
      trimmed1 = true;
    }
    return w.b0 < w.b1;
  }

  // Is window `n` (a neighbour on the same edge) a continuation of the wavefront at the end point x?
  bool contiguous_neighbour(Index n, Index h, const FT& x, bool at_start) const
  {
    if(n < 0)
      return false;
    const Window& nw = windows_[std::size_t(n)];
    if(!this->propagates_into(nw.from_halfedge, h))
      return false;
    const Local_window<FT> ln = local_window(nw, h);
    return at_start ? ln.b1 == x : ln.b0 == x;
  }

  struct Propagation_data
  {
    Local_window<FT> w;
    FT d_p0, d_p1, xc;
    bool flat_source, lobe0, lobe1;
    bool filler, lobe0_filler, lobe1_filler;
    Index source, h;
  };

  // The target edge runs from P (at u = 0, on the line AB at abscissa x0) to C (u = 1). Splits it into the
  // lobe-0, central and lobe-1 parts and inserts them into the edge's envelope.
  void emit_pieces(const Propagation_data& pd, Index g, const FT& px, const FT& py, const Point_2_ft<FT>& c,
                   const FT& x0, bool reversed)
  {
    const Local_window<FT>& w = pd.w;
    const FT len = mesh_.he[std::size_t(g)].length;
    const FT x1 = pd.xc;
    // u where the crossing equals b (clamped to [0,1]); crossings run monotonically from x0 to x1.
    auto u_at = [&](const FT& b) -> FT {
      if(x1 > x0) {
        if(!(b > x0)) return FT(0);
        if(!(b < x1)) return FT(1);
      } else {
        if(!(b < x0)) return FT(0);
        if(!(b > x1)) return FT(1);
      }
      // the line from S through (b, 0) meets P + u (C - P) at u = sy (b - px) / ((b - sx) qy + sy qx)
      const FT qx = c.x - px, qy = c.y - py;
      const FT den = (b - w.sx) * qy + w.sy * qx;
      if(den == FT(0))
        return FT(0);
      FT u = w.sy * (b - px) / den;
      if(u < FT(0)) u = FT(0);
      if(u > FT(1)) u = FT(1);
      return u;
    };
    // classes along u: 0 = lobe at P0, 1 = central, 2 = lobe at P1
    FT ua, ub;      // the central part [ua, ub]
    FT l0a, l0b;    // lobe 0 part
    FT l1a, l1b;    // lobe 1 part
    if(pd.flat_source || x1 == x0) {
      const FT x = pd.flat_source ? w.sx : x0;
      const int cls = x < w.b0 ? 0 : (x > w.b1 ? 2 : 1);
      ua = ub = l0a = l0b = l1a = l1b = FT(0);
      if(cls == 0) l0b = FT(1);
      else if(cls == 1) ub = FT(1);
      else l1b = FT(1);
    } else {
      const FT u0 = u_at(w.b0), u1 = u_at(w.b1);
      if(x1 > x0) { l0a = FT(0); l0b = u0; ua = u0; ub = u1; l1a = u1; l1b = FT(1); }
      else        { l1a = FT(0); l1b = u1; ua = u1; ub = u0; l0a = u0; l0b = FT(1); }
    }
    // P is source(h) or target(h); in the frame of g the target-edge points are source(g) + t e.
    if(ub > ua || (len == FT(0) && ub == FT(1)))
      emit_one(pd, g, px, py, c, reversed, ua, ub, w.sx, w.sy, w.sigma, pd.filler);
    if(pd.lobe0 && (l0b > l0a || (len == FT(0) && l0b == FT(1))))
      emit_one(pd, g, px, py, c, reversed, l0a, l0b, w.b0, FT(0), pd.d_p0, pd.lobe0_filler);
    if(pd.lobe1 && (l1b > l1a || (len == FT(0) && l1b == FT(1))))
      emit_one(pd, g, px, py, c, reversed, l1a, l1b, w.b1, FT(0), pd.d_p1, pd.lobe1_filler);
  }

  // Inserts the part [ua, ub] of the target edge (P + u (C - P)) with pseudo-source (qx, qy) of the h
  // frame and offset sigma, converting to the frame of the target halfedge g.
  void emit_one(const Propagation_data& pd, Index g, const FT& px, const FT& py, const Point_2_ft<FT>& c,
                bool reversed, const FT& ua, const FT& ub, const FT& qx, const FT& qy, const FT& sigma, bool filler)
  {
    using std::sqrt;
    const FT len = mesh_.he[std::size_t(g)].length;
    // g runs from O to T: for the edge C->A, O = C and T = A = P; for B->C, O = B = P and T = C.
    const FT ox = reversed ? c.x : px, oy = reversed ? c.y : py;
    const FT tx = reversed ? px : c.x, ty = reversed ? py : c.y;
    const FT ex = tx - ox, ey = ty - oy;
    const FT elen = sqrt(ex * ex + ey * ey);
    FT sx, sy;
    if(elen > FT(0)) {
      const FT dx = qx - ox, dy = qy - oy;
      sx = (dx * ex + dy * ey) / elen;
      sy = (ex * dy - ey * dx) / elen;
    } else {
      sx = FT(0);
      sy = distance_2(ox, oy, qx, qy);
    }
    FT t0, t1;
    if(reversed) { t0 = len * (FT(1) - ub); t1 = len * (FT(1) - ua); }
    else         { t0 = len * ua; t1 = len * ub; }
    if(ua == FT(0)) { if(reversed) t1 = len; else t0 = FT(0); }
    if(ub == FT(1)) { if(reversed) t0 = FT(0); else t1 = len; }
    insert_piece(g, t0, t1, sx, sy, sigma, pd.source, filler);
  }


  // Events by distance: a radix heap for double keys (monotone: nothing is pushed below the front), a 4-ary heap
  // for other number types.
  typename std::conditional<std::is_same<FT, double>::value, Radix_heap<Heap_entry>, Quaternary_heap<Heap_entry>>::type
    heap_;
  Quaternary_heap<Heap_entry> release_heap_; // edges to release, by their largest value
  std::vector<char> release_queued_;         // per edge: has an entry in release_heap_
  std::size_t since_release_ = 0, release_interval_ = 1024;
  std::vector<char> vertex_is_pseudo_source_;
  std::vector<std::uint32_t> vertex_stamp_, expanded_stamp_;
  std::vector<Index> stop_targets_;
  bool keep_windows_ = true;
  bool lobes_at_vertices_ = false;
  bool lobes_at_contiguous_ends_ = false;
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_EXACT_WINDOW_PROPAGATION_H
