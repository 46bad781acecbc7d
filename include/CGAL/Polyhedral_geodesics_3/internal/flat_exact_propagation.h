// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The flat-exact approximation of geodesic distances (thesis, chapters 4.2.1 and 4.3), on the compact mesh.
//
// - Distances live at the vertices only. The distance function of an edge is one "interval" whose
//   pseudo-source s is rebuilt from the distances of its two vertices with a zero offset: |s - v1| = D(v1),
//   |s - v2| = D(v2) (Heron's formula for the height). Of the two mirror images, the one on the side away from
//   the face the edge propagates into is used. |D(v1) - D(v2)| > L (no such point), zero-length edges and edges
//   whose ends have different nearest sources (no single pseudo-source explains both: rebuilding one would put
//   the vertices beyond the edge too close to both sources) propagate along the edges only.
// - One refinement of the thesis's rule, which keeps planar meshes exact: a vertex reached along an edge from a
//   saddle vertex or a reflex boundary vertex r (where shortest paths bend) starts a *window* rooted at r with
//   offset D(r), and an edge whose two ends belong to the same window (or whose end is the root of the other
//   end's window) rebuilds its pseudo-source with that offset: behind a hole's corner the pseudo-source is the
//   corner itself. Where two windows meet, the smaller of the two offsets is used (the flatter front; the
//   thesis's zero offset there made every vertex downstream of a meeting flat-fronted).
// - An edge propagates into each of its faces: the opposite vertex v3 gets D(s) at v3 when it sees s through the
//   edge (the quadrilateral s, v1, v3, v2 is convex), else min(D(v1) + |v1 v3|, D(v2) + |v2 v3|). When a vertex
//   is lowered, the edges around it get their new distance function and are (re)queued in an indexed binary
//   heap (one entry per edge, moved when its key changes) by the smallest value they give to an opposite vertex
//   that they lower (edges that lower neither are not queued); they propagate when they leave the heap. Every
//   value an edge gives is at least its key, so the distances below the key are final (Dijkstra order), which is
//   what the distance limit and the stop targets use; a vertex lowered again queues its edges again (label
//   correcting), which happens to few vertices with this key (1.0 - 1.2 lowerings per vertex on most of CGAL's
//   demo meshes, 2.8 on the needle triangles of mech-holes-shark, against 1.2 - 1.6 and 3.0 by the minimum of
//   the edge's distance function). Clusters of vertices that lower one another by ever smaller amounts are cut
//   short: a vertex's fourth and later values must change it by at least 1e-9 of its distance (see
//   lowering_tolerance() in flat_exact_field.h; mech-holes-shark 2.95 -> 1.74 values per vertex, the Loop
//   subdivision of mannequin-devil 2.64 -> 1.50).
// - Most edges around a lowered vertex cannot lower either opposite vertex (the upwind faces); a lower bound
//   of every value the edge gives, from its end distances, length and the heights of the opposite vertices,
//   says so without rebuilding the pseudo-source (can_lower()), and such an edge is not queued.
// - The dependence DAG has the edges as nodes. When v3 is lowered from the edge e12, e12 becomes the parent of
//   every edge around v3 (replacing the parent of v3's previous lowering): the "vertex links", stored as the
//   list of the vertices lowered from each edge. A lowering is accepted only if the DAG stays acyclic: neither
//   v1 nor v2 may be a descendant of v3 (a depth-first search of v3's descendants, which are few since v3 is on
//   the wavefront; none at all when v3 is reached for the first time).
// - The "side links" of the thesis (4.3.2), which let the back-tracing go from face to face, are only needed by
//   shortest paths: they are built with the first path query from the final distances. Each edge gets, of its
//   faces whose opposite vertex was reached before the edge got its final distances (the upstream faces), the
//   one whose pseudo-source best explains the distance of the opposite vertex (the Q234 / Q345 test); of the
//   two other edges of that face, those crossed by the segments from the edge to its pseudo-source become its
//   parents. Side links that close a cycle (inside a strongly connected component of the whole graph: rare and
//   local) are dropped, which keeps the DAG acyclic.
// - Shortest paths are traced back along the DAG only (from an edge to a parent edge straight toward the edge's
//   pseudo-source inside its side face, from a vertex toward the pseudo-source of the edge it was lowered from,
//   through a vertex where the propagation went along an edge), so they always end at a source.
//
// Files: flat_exact_field.h (the stored state and point queries), flat_exact_paths.h (side links, back-tracing),
// this file (sources, the edge queue, the propagation rules and the vertex updates under the DAG).

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_FLAT_EXACT_PROPAGATION_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_FLAT_EXACT_PROPAGATION_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Polyhedral_geodesics_3/internal/flat_exact_paths.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

template <class FT>
class Flat_exact_propagation : public Flat_exact_paths<FT>
{
  typedef Flat_exact_paths<FT> Base;

public:
  typedef typename Base::Mesh Mesh;
  typedef typename Base::Index Index;
  typedef typename Base::Path_node Path_node;
  typedef typename Base::Point_distance Point_distance;
  typedef typename Base::Queue_key Queue_key;
  typedef typename Base::Counters Counters;

  explicit Flat_exact_propagation(const Mesh& mesh) : Base(mesh) {}

  // ------------------------------------------------------------------------------------------------
  // Sources (applied by run())

  void add_vertex_source(Index v, Index id)
  {
    if(v < 0 || std::size_t(v) >= mesh_.number_of_vertices)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: source vertex not in the mesh");
    vertex_sources_.push_back({v, id});
  }

  void add_face_source(Index f, const std::array<FT, 3>& b, Index id)
  {
    if(f < 0 || std::size_t(f) >= mesh_.number_of_faces)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: source face not in the mesh");
    int zeros = 0;
    for(int k = 0; k < 3; ++k)
      if(b[std::size_t(k)] == FT(0))
        ++zeros;
    if(zeros >= 2) {
      for(int k = 0; k < 3; ++k)
        if(b[std::size_t(k)] != FT(0))
          return add_vertex_source(he_source(3 * f + k), id);
    }
    face_sources_.push_back(Face_source{f, b, id});
    if(zeros == 1) {
      // On an edge: also a source in the face on the other side.
      int k = 0;
      while(b[std::size_t((k + 2) % 3)] != FT(0))
        ++k;
      const Index g = 3 * f + k; // carries the point (corners k and k+1)
      const Index tw = he_[std::size_t(g)].twin;
      if(tw >= 0) {
        std::array<FT, 3> b2 = {FT(0), FT(0), FT(0)};
        b2[std::size_t(tw % 3)] = b[std::size_t((k + 1) % 3)];       // source(tw) == target(g)
        b2[std::size_t((tw % 3 + 1) % 3)] = b[std::size_t(k)];       // target(tw) == source(g)
        face_sources_.push_back(Face_source{Mesh::face_of(tw), b2, id});
      }
    }
  }

  // ------------------------------------------------------------------------------------------------
  // Propagation

  template <class Progress>
  void run(Progress& progress)
  {
    const char* stage = "flat-exact propagation";
    if(!progress(stage, 0.0))
      throw MDCS::Operation_cancelled(stage);
    initialize_sources();
    const std::size_t report_every = std::max<std::size_t>(mesh_.number_of_edges / 64, 256);
    std::size_t pops = 0, next_report = report_every;
    bool stop = !stop_targets_.empty() && stop_targets_final(FT(0));
    for(;;) {
      while(!stop && !heap_.empty()) {
        const Heap_entry top = heap_.front();
        front_ = top.key;
        if(has_limit_ && top.key > limit_) {
          stop = true;
          break;
        }
        if(!stop_targets_.empty() && (pops & 15) == 0 && stop_targets_final(top.key)) {
          stop = true;
          break;
        }
        pop_edge();
        propagate_edge(top.edge, top.key);
        ++counters_.edges_propagated;
        if(++pops >= next_report) {
          next_report = pops + report_every;
          if(!MDCS::internal::Reports_nothing<Progress>::value && !progress(stage, fraction_final(top.key)))
            throw MDCS::Operation_cancelled(stage);
        }
      }
      if(stop || !restart_from_stuck_vertices())
        break;
    }
    stopped_early_ = stop;
    if(stop)
      bound_ = has_limit_ && front_ > limit_ ? limit_ : front_;
    else
      bound_ = has_limit_ ? limit_ : unreached_;
    stats_.stopped_early = stopped_early_;
    stats_.windows_propagated = counters_.edges_propagated;
    stats_.stored_windows = mesh_.number_of_edges;
    note_memory();
    decltype(heap_)().swap(heap_);
    if(!progress(stage, 1.0))
      throw MDCS::Operation_cancelled(stage);
  }

private:
  typedef typename Base::Parent_kind Parent_kind;
  typedef typename Base::Vertex_source Vertex_source;
  typedef typename Base::Face_source Face_source;
  typedef typename Base::Heap_entry Heap_entry;
  typedef typename Base::Pseudo_source Pseudo_source;
  typedef typename Base::Incident_edge Incident_edge;
  typedef typename Base::Halfedge_data Halfedge_data;
  typedef typename Base::Vertex_state Vertex_state;
  using Base::ROOT_VERTEX;
  using Base::ROOT_FACE;
  using Base::EUCLID;
  using Base::ALONG_SOURCE;
  using Base::ALONG_TARGET;
  using Base::EDGE_NEIGHBOR;
  using Base::bound_;
  using Base::child_head_;
  using Base::child_next_;
  using Base::child_prev_;
  using Base::clock_;
  using Base::counters_;
  using Base::epsilon_;
  using Base::face_source_index_;
  using Base::face_sources_;
  using Base::first_reached_;
  using Base::front_;
  using Base::has_limit_;
  using Base::he_;
  using Base::he_opposite_vertex;
  using Base::he_source;
  using Base::he_target;
  using Base::heap_;
  using Base::heap_position_;
  using Base::lowering_tolerance;
  using Base::lowerings_;
  using Base::lowers;
  using Base::last_lowered_;
  using Base::length_2;
  using Base::limit_;
  using Base::mesh_;
  using Base::parent_edge;
  using Base::parent_he_;
  using Base::parent_kind_;
  using Base::peak_heap_;
  using Base::point_in_halfedge_frame;
  using Base::pseudo_source_ab;
  using Base::queue_key_;
  using Base::reached;
  using Base::recording_touched_;
  using Base::search_stamp_;
  using Base::source_through;
  using Base::stack_;
  using Base::stats_;
  using Base::stop_targets_;
  using Base::stopped_early_;
  using Base::touched_;
  using Base::unreached_;
  using Base::vedge_;
  using Base::vedge_begin_;
  using Base::vedge_other_;
  using Base::vertex_is_pseudo_source_;
  using Base::vertex_sources_;
  using Base::vertex_windows_;
  using Base::visit_vertex_;
  using Base::vs_;

  // The key of the edge from a to b of length L in the queue, given its distance function s (in its frame).
  FT queue_key(Index a, Index b, const FT& L, const Pseudo_source& s) const
  {
    const FT& c1 = vs_[std::size_t(a)].dist;
    const FT& c2 = vs_[std::size_t(b)].dist;
    switch(queue_key_) {
    case Queue_key::smaller_vertex:
      return (std::min)(c1, c2);
    case Queue_key::larger_vertex:
      return (std::max)(c1, c2);
    default:
      break;
    }
    if(s.valid && s.x > FT(0) && s.x < L)
      return (std::min)(s.sigma + s.y, (std::min)(c1, c2));
    return (std::min)(c1, c2);
  }

  void push_edge(Index e)
  {
    const Index h = mesh_.edge_halfedge[std::size_t(e)], tw = he_[std::size_t(h)].twin;
    push_edge(Incident_edge{e, h, he_source(h), he_target(h), he_opposite_vertex(h),
                            tw < 0 ? Index(-1) : he_opposite_vertex(tw), he_[std::size_t(h)].length});
  }

  // (Re)queues an edge after a change of the distance of one of its ends: its distance function is computed
  // here (and again, identical, when the edge propagates). The queue is a binary heap indexed by edge (a
  // changed key moves the entry: no stale entries). An edge that cannot lower either opposite vertex (every
  // candidate is at least the key) is not queued.
  void push_edge(const Incident_edge& ie)
  {
    if(!reached(ie.a) || !reached(ie.b))
      return;
    Index i = heap_position_[std::size_t(ie.edge)];
    // The candidate key: most edges around a lowered vertex cannot lower either opposite vertex (the upwind
    // faces), and a bound without the pseudo-source tells so (see can_lower()). Then the edge is not queued,
    // exactly as if its candidates had been computed, at the cost of a few comparisons.
    bool may_lower[2] = {false, false};
    if(queue_key_ == Queue_key::candidate) {
      const FT& c1 = vs_[std::size_t(ie.a)].dist;
      const FT& c2 = vs_[std::size_t(ie.b)].dist;
      const Index tw = he_[std::size_t(ie.h)].twin;
      may_lower[0] = can_lower(ie.y1, c1, c2, ie.length, he_[std::size_t(ie.h)].opposite.y);
      may_lower[1] = tw >= 0 && can_lower(ie.y2, c1, c2, ie.length, he_[std::size_t(tw)].opposite.y);
      if(!may_lower[0] && !may_lower[1]) {
        if(i >= 0)
          remove_from_heap(std::size_t(i));
        return;
      }
    }
    const Pseudo_source s = pseudo_source_ab(ie.a, ie.b, ie.length);
    FT key = queue_key(ie.a, ie.b, ie.length, s);
    if(queue_key_ == Queue_key::candidate) {
      // the smallest value the edge would give to an opposite vertex, if it lowers it
      key = unreached_;
      Pseudo_source sk = s;
      for(int k = 0; k < 2; ++k) {
        const Index y = k == 0 ? ie.y1 : ie.y2;
        if(y < 0)
          break;
        if(k == 1)
          sk.x = ie.length - s.x;
        if(!may_lower[k])
          continue;
        FT value, sigma;
        Parent_kind kind;
        Index root;
        evaluate_into_face(k == 0 ? ie.h : he_[std::size_t(ie.h)].twin, sk, value, kind, sigma, root);
        if(lowers(y, value) && value < key)
          key = value;
      }
      if(!(key < unreached_)) {
        if(i >= 0)
          remove_from_heap(std::size_t(i));
        return;
      }
    } else if(i < 0 && queue_key_ == Queue_key::function_minimum && !(key < vs_[std::size_t(ie.y1)].dist) &&
              (ie.y2 < 0 || !(key < vs_[std::size_t(ie.y2)].dist)))
      return;
    if(i < 0) {
      i = Index(heap_.size());
      heap_.push_back(Heap_entry{key, ie.edge});
      if(heap_.size() > peak_heap_)
        peak_heap_ = heap_.size();
      sift_up(std::size_t(i));
    } else {
      const FT old = heap_[std::size_t(i)].key;
      heap_[std::size_t(i)].key = key;
      if(key < old)
        sift_up(std::size_t(i));
      else
        sift_down(std::size_t(i));
    }
  }

  // Can the edge with end distances c1, c2 and length L lower y, whose height over the edge's line is h?
  // False only when it cannot: every value the edge gives to y is at least min((c1 + c2 - L) / 2, c1, c2) + h.
  // A straight value is sigma + |s q| + |q y| with q on the edge and |q y| >= h; the pseudo-source s is at
  // c1 - sigma from one end and c2 - sigma from the other, so |s q| >= (c1 + c2 - 2 sigma - L) / 2 (triangle
  // inequality at both ends). A value along an edge is at least min(c1, c2) + h, which also covers the ends
  // that no pseudo-source fits (|c1 - c2| > L, for instance while one end still waits for its own lowering).
  // The margin covers the rounding of the rebuilt pseudo-source (a few ulps of c1 + c2 + L).
  bool can_lower(Index y, const FT& c1, const FT& c2, const FT& L, const FT& h) const
  {
    if(y < 0)
      return false;
    const FT old = vs_[std::size_t(y)].dist;
    const FT bound = (std::min)((c1 + c2 - L) / FT(2), (std::min)(c1, c2)) + h;
    const FT margin = FT(1024) * epsilon_ * (c1 + c2 + L + h);
    return bound - margin < old - lowering_tolerance(y) * old;
  }

  void remove_from_heap(std::size_t i)
  {
    heap_position_[std::size_t(heap_[i].edge)] = -1;
    const Heap_entry last = heap_.back();
    heap_.pop_back();
    if(i == heap_.size())
      return;
    const FT old = heap_[i].key;
    heap_[i] = last;
    heap_position_[std::size_t(last.edge)] = Index(i);
    if(last.key < old)
      sift_up(i);
    else
      sift_down(i);
  }

  void pop_edge()
  {
    heap_position_[std::size_t(heap_.front().edge)] = -1;
    if(heap_.size() == 1) {
      heap_.pop_back();
      return;
    }
    heap_.front() = heap_.back();
    heap_.pop_back();
    sift_down(0);
  }

  void sift_up(std::size_t i)
  {
    const Heap_entry x = heap_[i];
    while(i > 0) {
      const std::size_t parent = (i - 1) / 2;
      if(!(x.key < heap_[parent].key))
        break;
      heap_[i] = heap_[parent];
      heap_position_[std::size_t(heap_[i].edge)] = Index(i);
      i = parent;
    }
    heap_[i] = x;
    heap_position_[std::size_t(x.edge)] = Index(i);
  }

  void sift_down(std::size_t i)
  {
    const Heap_entry x = heap_[i];
    const std::size_t n = heap_.size();
    for(;;) {
      std::size_t child = 2 * i + 1;
      if(child >= n)
        break;
      if(child + 1 < n && heap_[child + 1].key < heap_[child].key)
        ++child;
      if(!(heap_[child].key < x.key))
        break;
      heap_[i] = heap_[child];
      heap_position_[std::size_t(heap_[i].edge)] = Index(i);
      i = child;
    }
    heap_[i] = x;
    heap_position_[std::size_t(x.edge)] = Index(i);
  }

  // The value the edge of h gives to the vertex opposite h (in the face of h), how, and the window of the
  // vertex then (offset, root).
  void evaluate_into_face(Index h, const Pseudo_source& s, FT& value, Parent_kind& kind, FT& sigma, Index& root) const
  {
    using std::sqrt;
    const Index a = he_source(h), b = he_target(h);
    const FT& c1 = vs_[std::size_t(a)].dist;
    const FT& c2 = vs_[std::size_t(b)].dist;
    const FT L = he_[std::size_t(h)].length;
    const Point_2_ft<FT>& p = he_[std::size_t(h)].opposite;
    if(s.valid) {
      // the pseudo-source at (s.x, -s.y): the segment to p crosses the line y = 0 at t, 0 <= t <= L with
      // t * denom = s.x * p.y + p.x * s.y
      const FT denom = p.y + s.y;
      if(denom > FT(0)) {
        const FT t_denom = s.x * p.y + p.x * s.y;
        if(t_denom >= FT(0) && t_denom <= L * denom) {
          const FT dx = p.x - s.x;
          value = s.sigma + sqrt(dx * dx + denom * denom);
          kind = EUCLID;
          sigma = s.sigma;
          root = s.root;
          return;
        }
      }
    }
    const FT via_a = c1 + he_[std::size_t(Mesh::prev(h))].length;
    const FT via_b = c2 + he_[std::size_t(Mesh::next(h))].length;
    const Index through = via_a <= via_b ? a : b;
    value = via_a <= via_b ? via_a : via_b;
    kind = via_a <= via_b ? ALONG_SOURCE : ALONG_TARGET;
    window_through_vertex(through, sigma, root);
  }

  // The window of a vertex reached along an edge from `through`: rooted at `through` if shortest paths can
  // bend there (a saddle or a reflex boundary vertex), else the window of `through`.
  void window_through_vertex(Index through, FT& sigma, Index& root) const
  {
    if(vertex_windows_ && vertex_is_pseudo_source_[std::size_t(through)]) {
      sigma = vs_[std::size_t(through)].dist;
      root = through;
    } else {
      sigma = vs_[std::size_t(through)].offset;
      root = vs_[std::size_t(through)].root;
    }
  }

  void propagate_edge(Index e, const FT& key)
  {
    const Index h0 = mesh_.edge_halfedge[std::size_t(e)];
    // the edge's distance function: the same as when it was queued (a change at either end requeues it)
    Pseudo_source s = pseudo_source_ab(he_source(h0), he_target(h0), he_[std::size_t(h0)].length);
    for(int side = 0; side < 2; ++side) {
      const Index h = side == 0 ? h0 : he_[std::size_t(h0)].twin;
      if(h < 0)
        break;
      const Index v = he_opposite_vertex(h);
      // every candidate is at least the key (when the key is the minimum of the function)
      if((queue_key_ == Queue_key::function_minimum || queue_key_ == Queue_key::candidate) &&
         !(key < vs_[std::size_t(v)].dist))
        continue;
      FT value, sigma;
      Parent_kind kind;
      Index root;
      if(side == 1)
        s.x = he_[std::size_t(h0)].length - s.x; // the frame of the twin
      evaluate_into_face(h, s, value, kind, sigma, root);
      try_lower(v, value, h, kind, source_through(h, kind), sigma, root);
    }
  }

  // ------------------------------------------------------------------------------------------------
  // Sources

  void initialize_sources()
  {
    touched_.clear();
    recording_touched_ = true;
    for(const Vertex_source& s : vertex_sources_) {
      const std::size_t v = std::size_t(s.vertex);
      if(!(vs_[v].dist > FT(0)))
        continue;
      set_vertex(s.vertex, FT(0), s.id, -1, ROOT_VERTEX, FT(0), -1);
    }
    face_source_index_.clear();
    for(std::size_t i = 0; i < face_sources_.size(); ++i) {
      const Face_source& s = face_sources_[i];
      face_source_index_.push_back({s.face, Index(i)});
      for(int k = 0; k < 3; ++k) {
        const Index v = he_source(3 * s.face + k);
        const Point_2_ft<FT> p = point_in_halfedge_frame(s.face, s.barycentric, k);
        const FT d = length_2(p.x, p.y);
        if(d < vs_[std::size_t(v)].dist)
          set_vertex(v, d, s.id, Index(i), ROOT_FACE, FT(0), -1);
      }
    }
    std::sort(face_source_index_.begin(), face_source_index_.end());
    // The neighbours of a vertex source: along the edges (the pseudo-source of such an edge is its end).
    for(const Vertex_source& s : vertex_sources_)
      for(Index k = vedge_begin_[std::size_t(s.vertex)]; k < vedge_begin_[std::size_t(s.vertex) + 1]; ++k) {
        const Index e = vedge_[std::size_t(k)];
        const Index w = vedge_other_[std::size_t(k)];
        try_lower(w, vs_[std::size_t(s.vertex)].dist + he_[std::size_t(mesh_.edge_halfedge[std::size_t(e)])].length,
                  mesh_.edge_halfedge[std::size_t(e)], EDGE_NEIGHBOR, vs_[std::size_t(s.vertex)].source,
                  vs_[std::size_t(s.vertex)].dist, s.vertex);
      }
    // the queue once every source is in place
    for(Index v : touched_)
      for(Index k = vedge_begin_[std::size_t(v)]; k < vedge_begin_[std::size_t(v) + 1]; ++k)
        push_edge(vedge_[std::size_t(k)]);
    touched_.clear();
    recording_touched_ = false;
    clock_ = 1;
  }

  // After the queue ran dry: a vertex reached only through an edge whose other end is unreached (a pinched
  // vertex, or a fan behind a vertex touched only at a corner) starts a new propagation along the edge.
  bool restart_from_stuck_vertices()
  {
    bool any = false;
    for(std::size_t e = 0; e < mesh_.number_of_edges; ++e) {
      const Index h = mesh_.edge_halfedge[e];
      const Index a = he_source(h), b = he_target(h);
      if(reached(a) == reached(b))
        continue;
      const Index from = reached(a) ? a : b, to = reached(a) ? b : a;
      FT sigma;
      Index root;
      window_through_vertex(from, sigma, root);
      if(try_lower(to, vs_[std::size_t(from)].dist + he_[std::size_t(h)].length, h, EDGE_NEIGHBOR,
                   vs_[std::size_t(from)].source, sigma, root))
        any = true;
    }
    if(any)
      ++counters_.stuck_restarts;
    return any;
  }

  // ------------------------------------------------------------------------------------------------
  // Vertex updates and the dependence DAG

  // Lowers D(v) to `value` from the edge of h (kind of update `kind`) if it is lower by more than rounding
  // and the DAG stays acyclic; then queues the edges around v.
  bool try_lower(Index v, const FT& value, Index h, Parent_kind kind, Index source, const FT& sigma, Index root)
  {
    if(!lowers(v, value))
      return false;
    const Index e = he_[std::size_t(h)].edge;
    if(kind == EDGE_NEIGHBOR) {
      // the other end must not hang on v through the same edge
      const Index w = he_source(h) == v ? he_target(h) : he_source(h);
      if(parent_kind_[std::size_t(w)] == EDGE_NEIGHBOR && he_[std::size_t(parent_he_[std::size_t(w)])].edge == e) {
        ++stats_.updates_rejected_by_dag;
        return false;
      }
    }
    // a vertex reached for the first time has no descendants: nothing to search
    if(reached(v)) {
      const Index a = kind == EDGE_NEIGHBOR ? (he_source(h) == v ? he_target(h) : he_source(h)) : he_source(h);
      const Index b = kind == EDGE_NEIGHBOR ? a : he_target(h);
      if(is_descendant(v, a, b)) {
        ++stats_.updates_rejected_by_dag;
        return false;
      }
    }
    set_vertex(v, value, source, h, kind, sigma, root);
    ++stats_.vertex_updates;
    // the edges around v whose other end is reached (an edge with an unreached end is not queued: push_edge())
    for(Index k = vedge_begin_[std::size_t(v)]; k < vedge_begin_[std::size_t(v) + 1]; ++k)
      if(reached(vedge_other_[std::size_t(k)]))
        push_edge(vedge_[std::size_t(k)]);
    return true;
  }

  void set_vertex(Index v, const FT& value, Index source, Index he, Parent_kind kind, const FT& sigma, Index root)
  {
    // unlink v from the children list of its previous parent edge
    const Index old_parent = parent_edge(v);
    if(old_parent >= 0) {
      const Index p = child_prev_[std::size_t(v)], n = child_next_[std::size_t(v)];
      if(p >= 0) child_next_[std::size_t(p)] = n;
      else child_head_[std::size_t(old_parent)] = n;
      if(n >= 0) child_prev_[std::size_t(n)] = p;
    }
    child_prev_[std::size_t(v)] = child_next_[std::size_t(v)] = -1;
    if(!reached(v)) {
      first_reached_[std::size_t(v)] = clock_;
      if(recording_touched_)
        touched_.push_back(v);
    }
    last_lowered_[std::size_t(v)] = clock_;
    if(lowerings_[std::size_t(v)] < 255)
      ++lowerings_[std::size_t(v)];
    if(!recording_touched_)
      ++clock_; // the sources and their neighbours are all reached at time 0
    vs_[std::size_t(v)].dist = value;
    vs_[std::size_t(v)].source = source;
    parent_he_[std::size_t(v)] = he;
    parent_kind_[std::size_t(v)] = kind;
    vs_[std::size_t(v)].offset = sigma;
    vs_[std::size_t(v)].root = root;
    const Index parent = parent_edge(v);
    if(parent >= 0) {
      const Index n = child_head_[std::size_t(parent)];
      child_next_[std::size_t(v)] = n;
      if(n >= 0) child_prev_[std::size_t(n)] = v;
      child_head_[std::size_t(parent)] = v;
    }
  }

  // The vertex links of the DAG, seen from the vertices: w is a child of u when the edge w was lowered from
  // is incident to u (for a lowering along an edge from its other end: when u is that end). Calls
  // visit(w) for each child w of u until it returns false.
  template <class Visit>
  bool for_each_vertex_child(Index u, Visit visit) const
  {
    for(Index k = vedge_begin_[std::size_t(u)]; k < vedge_begin_[std::size_t(u) + 1]; ++k)
      for(Index w = child_head_[std::size_t(vedge_[std::size_t(k)])]; w >= 0; w = child_next_[std::size_t(w)])
        if(w != u && !visit(w))
          return false;
    return true;
  }

  // Is a or b a descendant of v (then lowering v from a, b would close a cycle)? Depth-first search over the
  // descendants of v, which are few: v is on the wavefront.
  bool is_descendant(Index v, Index a, Index b)
  {
    ++counters_.dag_searches;
    if(++search_stamp_ == 0) {
      std::fill(visit_vertex_.begin(), visit_vertex_.end(), 0u);
      search_stamp_ = 1;
    }
    const std::uint32_t stamp = search_stamp_;
    stack_.clear();
    stack_.push_back(v);
    visit_vertex_[std::size_t(v)] = stamp;
    bool found = false;
    while(!stack_.empty() && !found) {
      const Index u = stack_.back();
      stack_.pop_back();
      ++counters_.dag_search_visits;
      for_each_vertex_child(u, [&](Index w) {
        if(visit_vertex_[std::size_t(w)] == stamp)
          return true;
        if(w == a || w == b) {
          found = true;
          return false;
        }
        visit_vertex_[std::size_t(w)] = stamp;
        stack_.push_back(w);
        return true;
      });
    }
    return found;
  }

  // ------------------------------------------------------------------------------------------------
  // Stopping, progress, memory

  bool stop_targets_final(const FT& key) const
  {
    for(Index v : stop_targets_)
      if(!(vs_[std::size_t(v)].dist <= key))
        return false;
    return true;
  }

  double fraction_final(const FT& key) const
  {
    std::size_t n = 0;
    for(const Vertex_state& s : vs_)
      if(s.dist <= key)
        ++n;
    return vs_.empty() ? 1.0 : double(n) / double(vs_.size());
  }

  void note_memory()
  {
    // the propagation's arrays, without the compact mesh (the side links of the paths come on top: 5 bytes per
    // edge)
    const std::size_t nv = mesh_.number_of_vertices, ne = mesh_.number_of_edges;
    std::size_t bytes = nv * (2 * sizeof(FT) + 7 * sizeof(Index) + 2 + 3 * sizeof(std::uint32_t)) +
                        ne * 2 * sizeof(Index) + 2 * vedge_.size() * sizeof(Index) +
                        peak_heap_ * sizeof(Heap_entry) + stack_.capacity() * sizeof(Index);
    if(bytes > stats_.peak_memory_bytes)
      stats_.peak_memory_bytes = bytes;
  }
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_FLAT_EXACT_PROPAGATION_H
