// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact geodesic distances by vertex-oriented window propagation (the scheduling of Qin et al., "Fast and exact
// discrete geodesic computation based on triangle-oriented wavefront propagation", SIGGRAPH 2016): the engine of
// Exact_geodesic_distances_3 in both memory modes.
//
// The window-ordered engine (exact_window_propagation.h) takes every window out of a priority queue and keeps the
// lower envelope of every edge; this one keeps no envelope and no window queue:
//
// - Windows wait in a list per halfedge: the windows on its edge that will cross the face of the halfedge
//   (vertex_oriented_window_lists.h).
// - A priority queue holds vertices by their tentative distance. The nearest one is settled; the lists of the
//   halfedges that touch it become ready, and ready lists are propagated in FIFO order. A list that receives a
//   window while its edge touches a settled vertex is ready at once; the others wait for their first settled
//   end point. So the front advances vertex by vertex and windows cross faces in batches (vertex_oriented_batch.h).
// - Saddle and boundary vertices (and sources) are pseudo-sources: when settled, they emit a window over the
//   opposite edge of every incident face and their distance along every incident edge.
// - Vertex distances only decrease. A settled pseudo-source whose distance drops later is settled again, so
//   the order is label-correcting: every value is the length of a real path, every pruning compares with real
//   path lengths, and the result is the exact distance once the lists are empty, whatever the order.
//
// The full field is not stored (its windows grow as n^1.45: 264 M at 1.66 M vertices, 11 GB). Instead, with
// set_record_parents(true), every vertex keeps how it got its distance (its Parent: the halfedge frame, the
// pseudo-source and where the last segment crosses that halfedge); a shortest path to a vertex is then a walk
// along straight segments from parent to parent (vertex_oriented_paths.h), and a point query runs a second,
// small propagation from the query point bounded by these distances (set_backward_query()).
//
// A distance limit prunes the windows beyond it; stop targets stop the run once every target is below the
// front: the smallest value of the vertices in the queue and of the windows waiting in lists that are not ready
// (tracked in a second queue only when there are stop targets). With set_shadow_pruning(true), a settled saddle
// or boundary vertex emits windows only over the faces a shortest path through it can enter
// (vertex_oriented_shadow.h).

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_PROPAGATION_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_PROPAGATION_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_types.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>
#include <CGAL/Polyhedral_geodesics_3/internal/geodesic_window.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Quaternary_heap.h>
#include <CGAL/Polyhedral_geodesics_3/internal/vertex_oriented_batch.h>
#include <CGAL/Polyhedral_geodesics_3/internal/vertex_oriented_shadow.h>
#include <CGAL/Polyhedral_geodesics_3/internal/vertex_oriented_window_lists.h>
#include <CGAL/Polyhedral_geodesics_3/internal/unit_roundoff.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

template <class FT>
class Vertex_oriented_parallel_runner;

template <class FT>
class Vertex_oriented_window_propagation
{
  friend class Vertex_oriented_parallel_runner<FT>; // the parallel schedule (vertex_oriented_parallel.h)

public:
  typedef Geodesic_mesh<FT> Mesh;
  typedef typename Mesh::Index Index;
  typedef Vertex_oriented_window<FT> Window;
  typedef Vertex_oriented_batch<FT> Batch;

  // How a vertex got its distance. The path leaves the vertex in a straight line to the point `at` of halfedge
  // g's edge (in g's frame; the vertex itself when it is an end of g), then runs straight to the pseudo-source
  // (sx, sy) of g's frame, which is `root` (a vertex, or the point source -1 - k inside a face). halfedge -1: the
  // vertex is a source (root is the vertex itself), or it lies on an edge of the pseudo-source root (the path is
  // that edge).
  struct Parent
  {
    FT sx, sy, at;
    Index halfedge, root;
  };

  struct Face_source
  {
    Index face;
    std::array<FT, 3> barycentric;
    Index id;
  };

  // For point queries (vertex_oriented_paths.h): this run starts at the query point and looks for the vertex or
  // source point v that minimises (this run's distance from the query point to v) + (the forward run's distance
  // of v). Window parts where a lower bound of that sum exceeds the best so far are trimmed.
  struct Backward_query
  {
    const Vertex_oriented_window_propagation* forward = nullptr;
    FT best;                 // the best sum so far (the answer when the run ends)
    Index best_vertex = -1;  // the vertex where it was found, or -1
    Index best_face_source = -1; // or the forward run's point source (its index in face_sources())
    Index best_halfedge = -1;    // for a point source: the halfedge frame of the window that reached it
    Window best_window;          // ... and that window
  };

  explicit Vertex_oriented_window_propagation(const Mesh& mesh) : mesh_(mesh), shadow_angles_(mesh), batch_(mesh)
  {
    unreached_ = FT(std::numeric_limits<double>::max() / 16);
    relative_tolerance_ = FT(64) * unit_roundoff<FT>();
    const std::size_t nv = mesh_.number_of_vertices, nh = 3 * mesh_.number_of_faces;
    build_vertex_star(mesh_, star_begin_, star_);
    // Pseudo-sources: saddle and boundary vertices, and the vertices of zero-length edges (their windows are
    // single points) and of zero-area faces. (Exact_geodesic_engine does not run this schedule on meshes with
    // zero-area faces, where it missed paths along their line; the handling of such faces here is kept for the fix.)
    vertex_flags_.assign(nv, 0);
    for(std::size_t v = 0; v < nv; ++v)
      if(is_saddle_or_boundary_vertex(mesh_, v))
        vertex_flags_[v] |= PSEUDO_SOURCE;
    // Of those, the ones where no shortest path bends (a flat interior vertex, a boundary vertex with at most a
    // straight angle) only emit "lobes": windows that never beat the others by more than rounding. Merging (see
    // merge_similar_windows) never lets a lobe replace another window, which keeps flat meshes exact.
    const double pi = 3.14159265358979323846;
    for(std::size_t v = 0; v < nv; ++v)
      if((vertex_flags_[v] & PSEUDO_SOURCE) &&
         !(to_double_value(mesh_.vertex_angle_sum[v]) > (mesh_.vertex_on_boundary[v] ? 1 : 2) * pi + 1e-9))
        vertex_flags_[v] |= LOBE_VERTEX;
    for(std::size_t h = 0; h < nh; ++h)
      if(mesh_.he[h].length == FT(0) || !(mesh_.he[h].opposite.y > FT(0)))
        for(Index v : {mesh_.source(Index(h)), mesh_.target(Index(h))}) {
          vertex_flags_[std::size_t(v)] |= PSEUDO_SOURCE;
          vertex_flags_[std::size_t(v)] &= std::uint8_t(~LOBE_VERTEX);
        }
    clear();
  }

  // Forgets the sources and the results; the options stay.
  void clear()
  {
    const std::size_t nv = mesh_.number_of_vertices, nh = 3 * mesh_.number_of_faces;
    if(reuse_ && reuse_ready_) {
      // Only what the last run changed (see set_reuse_between_runs()).
      for(Index v : touched_vertices_) {
        vertices_[std::size_t(v)] = Vertex_record{unreached_, -1, 0, OUTSIDE, vertex_flags_[std::size_t(v)]};
        if(record_parents_)
          parents_[std::size_t(v)] = Parent{FT(0), FT(0), FT(0), -1, -1};
      }
      for(Index g : used_lists_)
        queued_[std::size_t(g)] = 0;
      lists_.clear_lists(used_lists_);
    } else {
      vertices_.assign(nv, Vertex_record{unreached_, -1, 0, OUTSIDE, 0});
      for(std::size_t v = 0; v < nv; ++v)
        vertices_[v].flags = vertex_flags_[v];
      if(record_parents_)
        parents_.assign(nv, Parent{FT(0), FT(0), FT(0), -1, -1});
      else
        std::vector<Parent>().swap(parents_);
      lists_.reset(nh);
      queued_.assign(nh, 0);
      reuse_ready_ = reuse_;
    }
    touched_vertices_.clear();
    used_lists_.clear();
    heap_.clear();
    pending_.clear();
    fifo_.clear();
    fifo_head_ = 0;
    face_sources_.clear();
    live_ = 0;
    front_ = FT(0);
    stopped_early_ = false;
    lists_processed_ = 0;
    stats_ = Geodesic_statistics();
  }

  // distances_only runs need no parents (32 bytes per vertex with double).
  void set_record_parents(bool record)
  {
    if(record != record_parents_)
      reuse_ready_ = false; // the parents array changes size: the next clear() is a full one
    record_parents_ = record;
  }
  // Many runs on one mesh, each reaching a small part of it (a limited run from every vertex: the local distance
  // matrix): the run then keeps its lists, queue and arrays allocated, records the vertices and window lists it
  // changes, and clear() resets only those, so that a run costs what it reaches, not the size of the mesh. The
  // results are those of a run after a full clear(). Takes effect at the next clear().
  void set_reuse_between_runs(bool reuse)
  {
    if(reuse != reuse_)
      reuse_ready_ = false;
    reuse_ = reuse;
  }
  // Shadow pruning (exact runs of this sequential schedule; not merging, not the parallel schedule): a settled
  // saddle or boundary vertex emits windows only over the faces that a shortest path through it can enter, those
  // in the "shadow" of the direction it got its value from (why that is safe, the angle tables and the test:
  // vertex_oriented_shadow.h). The direction is recorded with every lowering of such a vertex. Takes effect at the
  // next clear().
  void set_shadow_pruning(bool on)
  {
    if(on == shadow_)
      return;
    shadow_ = on;
    reuse_ready_ = false; // the vertex flags change: the next clear() is a full one
    if(on) {
      const std::vector<Index> with_rule = shadow_angles_.build(
          star_begin_, star_, [this](std::size_t v) { return (vertex_flags_[v] & PSEUDO_SOURCE) != 0; });
      for(Index v : with_rule)
        vertex_flags_[std::size_t(v)] |= SHADOW_RULE;
      arrival_.assign(mesh_.number_of_vertices, 0);
    } else
      for(std::uint8_t& flags : vertex_flags_)
        flags &= std::uint8_t(~SHADOW_RULE);
  }
  // With reuse: every vertex whose record the last run changed (each once, in the order reached); a superset of
  // the vertices with a distance.
  const std::vector<Index>& touched_vertices() const { return touched_vertices_; }
  bool records_parents() const { return record_parents_; }
  // Approximation by interval merging (absolute tolerance; 0: exact). See Vertex_oriented_batch.
  void set_merge_tolerance(const FT& tolerance) { merge_tolerance_ = tolerance; }
  void set_distance_limit(const FT& limit) { limit_ = limit; has_limit_ = true; }
  void clear_distance_limit() { has_limit_ = false; }
  void set_stop_targets(const std::vector<Index>& targets) { stop_targets_ = targets; }
  // A point query run (see Backward_query), or nullptr for an ordinary run.
  void set_backward_query(Backward_query* query) { query_ = query; }

  void add_vertex_source(Index v, Index id)
  {
    if(v < 0 || std::size_t(v) >= mesh_.number_of_vertices)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: source vertex not in the mesh");
    Vertex_record& r = vertices_[std::size_t(v)];
    touch(r, v);
    r.flags |= IS_SOURCE;
    if(FT(0) < r.dist) {
      r.dist = FT(0);
      r.source = id;
      ++stats_.vertex_updates;
      if(record_parents_)
        parents_[std::size_t(v)] = Parent{FT(0), FT(0), FT(0), -1, v};
      if(query_)
        offer_candidate(v, FT(0));
      r.state = FRONT;
      heap_.push(Heap_entry{FT(0), v, ++r.stamp});
    }
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
          return add_vertex_source(mesh_.source(3 * f + k), id);
    }
    add_point_source_in_face(f, b, id);
    if(zeros == 1) {
      // On an edge: the point is also a source inside the face on the other side.
      int k = 0;
      while(b[std::size_t((k + 2) % 3)] != FT(0))
        ++k;
      const Index g = 3 * f + k;
      const Index tw = mesh_.he[std::size_t(g)].twin;
      if(tw >= 0) {
        std::array<FT, 3> b2 = {FT(0), FT(0), FT(0)};
        b2[std::size_t(tw % 3)] = b[std::size_t((k + 1) % 3)];       // source(tw) == target(g)
        b2[std::size_t((tw % 3 + 1) % 3)] = b[std::size_t(k)];       // target(tw) == source(g)
        add_point_source_in_face(Mesh::face_of(tw), b2, id);
      }
    }
  }

  template <class Progress>
  void run(Progress& progress)
  {
    const char* stage = "geodesic propagation";
    if(!progress(stage, 0.0))
      throw MDCS::Operation_cancelled(stage);
    std::size_t pops = 0, settled = 0;
    do {
      while(!heap_.empty()) {
        if(!stop_targets_.empty() && (pops & 15) == 0 && stop_targets_final()) {
          stopped_early_ = true;
          break;
        }
        const Heap_entry top = heap_.pop();
        const std::size_t v = std::size_t(top.vertex);
        Vertex_record& r = vertices_[v];
        if(top.stamp != r.stamp || r.state == INSIDE)
          continue;
        if(!(r.flags & SETTLED_ONCE)) {
          r.flags |= SETTLED_ONCE;
          ++settled;
        }
        r.state = INSIDE;
        if((r.flags & (PSEUDO_SOURCE | IS_SOURCE)) && expansion_useful(v))
          expand_vertex(top.vertex);
        for(Index k = star_begin_[v]; k < star_begin_[v + 1]; ++k) {
          const Index h = star_[std::size_t(k)];
          make_ready(h);
          make_ready(Mesh::prev(h));
        }
        drain_ready_lists();
        if((++pops & 0x3FFF) == 0) {
          const double fraction = vertices_.empty() ? 1.0 : double(settled) / double(vertices_.size());
          if(!progress(stage, fraction < 1.0 ? fraction : 1.0))
            throw MDCS::Operation_cancelled(stage);
        }
      }
    } while(!stopped_early_ && !query_ && !has_limit_ && expand_stranded_neighbours());
    finish();
    if(!progress(stage, 1.0))
      throw MDCS::Operation_cancelled(stage);
  }

  // ------------------------------------------------------------------------------------------------
  // Results

  FT vertex_distance(Index v) const
  {
    const FT& d = vertices_[std::size_t(v)].dist;
    return d >= unreached_ ? FT(std::numeric_limits<double>::infinity()) : d;
  }

  Index vertex_source(Index v) const { return vertices_[std::size_t(v)].source; }

  const Geodesic_statistics& statistics() const { return stats_; }

  // The value of v during and after the run (the `unreached()` sentinel when it has none).
  const FT& raw_distance(Index v) const { return vertices_[std::size_t(v)].dist; }
  const FT& unreached() const { return unreached_; }
  bool is_source_vertex(Index v) const { return (vertices_[std::size_t(v)].flags & IS_SOURCE) != 0; }
  const Parent& parent(Index v) const { return parents_[std::size_t(v)]; }
  const std::vector<Face_source>& face_sources() const { return face_sources_; }
  const Mesh& mesh() const { return mesh_; }
  const FT& relative_tolerance() const { return relative_tolerance_; }

  // The source a window's points come from (its root's).
  Index source_of_root(Index root) const
  {
    return root >= 0 ? vertices_[std::size_t(root)].source : face_sources_[std::size_t(-1 - root)].id;
  }

  // Values up to this bound are final (and reported); the others are +infinity. +infinity after a full run.
  FT final_bound() const
  {
    if(stopped_early_)
      return has_limit_ && limit_ < front_ ? limit_ : front_;
    if(has_limit_)
      return limit_;
    return FT(std::numeric_limits<double>::infinity());
  }

  bool stopped_early() const { return stopped_early_; }

  // A lower bound of the exact distance of v: its value when final, else the bound above which it lies.
  FT distance_lower_bound(Index v) const
  {
    const FT& d = vertices_[std::size_t(v)].dist;
    if(stopped_early_ || has_limit_) {
      const FT bound = final_bound();
      return d < bound ? d : bound;
    }
    return d;
  }

  std::size_t lists_processed() const { return lists_processed_; }


private:
  enum State : std::uint8_t { OUTSIDE = 0, FRONT = 1, INSIDE = 2 };
  enum Flag : std::uint8_t { PSEUDO_SOURCE = 1, LOBE_VERTEX = 2, IS_SOURCE = 4, SETTLED_ONCE = 8, TOUCHED = 16,
                             SHADOW_RULE = 32,    // a pseudo-source where shadow pruning applies
                             ARRIVAL_KNOWN = 64 }; // arrival_ holds the direction of its current value

  // What the propagation keeps per vertex, in one record: a batch reads and writes its three vertices, one cache
  // line each.
  struct Vertex_record
  {
    FT dist;
    Index source;
    std::uint32_t stamp;
    std::uint8_t state, flags;
  };

  // With reuse between runs: records v (once per run) as one that clear() has to reset.
  void touch(Vertex_record& r, Index v)
  {
    if(reuse_ && !(r.flags & TOUCHED)) {
      r.flags |= TOUCHED;
      touched_vertices_.push_back(v);
    }
  }

  struct Heap_entry
  {
    FT key;
    Index vertex;
    std::uint32_t stamp;
  };

  struct Pending_entry // a window waiting in a list that is not ready: its smallest value (stop targets only)
  {
    FT key;
    Index halfedge;
    std::uint32_t unused;
  };

  typename Batch::Settings settings() const
  {
    return typename Batch::Settings{unreached_, relative_tolerance_, merge_tolerance_, limit_, has_limit_};
  }

  // ------------------------------------------------------------------------------------------------
  // The sequential sink of a batch (see vertex_oriented_batch.h): everything acts at once.

  friend class Sequential_sink;
  struct Sequential_sink
  {
    Vertex_oriented_window_propagation& e;
    const FT& distance(Index v) const { return e.vertices_[std::size_t(v)].dist; }
    void lower(Index v, const FT& d, const Window& w, Index g, const FT& at) { e.lower_vertex(v, d, w, g, at); }
    void child(Index t, const Window& w) { e.add_window(t, w); }
    void propagated(std::size_t n) { e.stats_.windows_propagated += n; }
    void pruned() { ++e.stats_.windows_pruned; }
    void merged() { ++e.stats_.windows_merged; }
    bool has_bound() const { return e.query_ != nullptr; }
    bool bound_trim(Index g, Window& w, const FT& L) const { return e.trim_by_query_bound(g, w, L); }
    void face_sources_in(Index g, const Window* begin, const Window* end) { e.query_face_sources(g, begin, end); }
  };

  // ------------------------------------------------------------------------------------------------
  // Vertices

  // Lowers v to d if that is lower; returns whether it did. A settled vertex stays settled unless it is a
  // pseudo-source (then it emits its windows again with the lower value).
  bool update_vertex(Index v, const FT& d, Index source)
  {
    Vertex_record& r = vertices_[std::size_t(v)];
    if(!(d < r.dist))
      return false;
    touch(r, v);
    r.dist = d;
    r.source = source;
    ++stats_.vertex_updates;
    if(query_)
      offer_candidate(v, d);
    if(r.state == INSIDE && !(r.flags & (PSEUDO_SOURCE | IS_SOURCE)))
      return true;
    r.state = FRONT;
    heap_.push(Heap_entry{d, v, ++r.stamp});
    return true;
  }

  void lower_vertex(Index v, const FT& d, const Window& w, Index g, const FT& at)
  {
    if(!update_vertex(v, d, source_of_root(w.root)))
      return;
    if(record_parents_)
      parents_[std::size_t(v)] = Parent{w.sx, w.sy, at, g, w.root};
    if(vertices_[std::size_t(v)].flags & SHADOW_RULE)
      note_arrival(v, shadow_angles_.arrival_from_window(v, w.sx, w.sy, g, at));
  }

  // v was lowered by a path that arrives from the direction `angle` (see vertex_oriented_shadow.h).
  void note_arrival(Index v, double angle)
  {
    Vertex_record& r = vertices_[std::size_t(v)];
    arrival_[std::size_t(v)] = shadow_angles_.normalized_arrival(v, angle);
    r.flags |= ARRIVAL_KNOWN;
  }

  // A safety net for merging (and for any rounding accident): a vertex left unreached next to a reached one.
  // With merging, the vertex values that trim the windows are upper bounds, not exact distances, so the
  // argument that a trimmed part is covered by another window no longer holds everywhere: measured, one vertex
  // of 37,706 at a tolerance of 1 edge length on bunny00 (never below 0.3). Its reached neighbours are then
  // expanded as pseudo-sources (real paths through them: the values stay upper bounds) and the propagation
  // goes on. Returns false if there was nothing to do (an exact run on a connected mesh: one scan).
  bool expand_stranded_neighbours()
  {
    bool any = false;
    for(std::size_t u = 0; u < vertices_.size(); ++u) {
      if(vertices_[u].dist < unreached_)
        continue;
      for(Index k = star_begin_[u]; k < star_begin_[u + 1]; ++k) {
        const Index h = star_[std::size_t(k)]; // source(h) == u
        for(Index w : {mesh_.target(h), mesh_.source(Mesh::prev(h))})
          if(vertices_[std::size_t(w)].dist < unreached_) {
            expand_vertex(w);
            any = true;
          }
      }
    }
    if(any)
      ++stats_.stranded_expansions;
    return any;
  }

  // The vertex as a pseudo-source with its current distance: its distance along every incident edge, and a
  // window over the opposite edge of every incident face, crossing into the face beyond.
  void expand_vertex(Index v)
  {
    const Vertex_record r = vertices_[std::size_t(v)];
    const FT d = r.dist;
    const std::int32_t lobe = (r.flags & LOBE_VERTEX) && !(r.flags & IS_SOURCE) ? 1 : 0;
    const bool shadow = (r.flags & (SHADOW_RULE | ARRIVAL_KNOWN | IS_SOURCE)) == (SHADOW_RULE | ARRIVAL_KNOWN) &&
                        merge_tolerance_ == FT(0);
    for(Index k = star_begin_[std::size_t(v)]; k < star_begin_[std::size_t(v) + 1]; ++k) {
      const Index h = star_[std::size_t(k)]; // source(h) == v
      const Index hn = Mesh::next(h), hp = Mesh::prev(h);
      // the directions back to v: from target(h), the far side of the corner of hn; from source(hp), hp itself
      if(lower_along_edge(mesh_.target(h), d + mesh_.he[std::size_t(h)].length, r.source, v))
        note_edge_arrival(mesh_.target(h), hn, true);
      if(lower_along_edge(mesh_.source(hp), d + mesh_.he[std::size_t(hp)].length, r.source, v))
        note_edge_arrival(mesh_.source(hp), hp, false);
      const Index g = Mesh::next(h);         // the edge opposite v in the face of h
      const Index t = mesh_.he[std::size_t(g)].twin;
      if(t < 0)
        continue;
      const FT L = mesh_.he[std::size_t(g)].length;
      if(has_limit_ && d > limit_)
        continue;
      if(shadow && !shadow_angles_.face_in_shadow(v, h, arrival_[std::size_t(v)]))
        continue;
      const Point_2_ft<FT>& p = mesh_.he[std::size_t(g)].opposite; // v in g's frame
      add_window(t, Window{FT(0), L, L - p.x, -p.y, d, v, lobe});
    }
  }

  bool lower_along_edge(Index u, const FT& d, Index source, Index from)
  {
    if(!update_vertex(u, d, source))
      return false;
    if(record_parents_)
      parents_[std::size_t(u)] = Parent{FT(0), FT(0), FT(0), -1, from};
    return true;
  }

  // u was lowered along an edge: halfedge h (leaving u), or (far_side) the other edge of h's face at u. (The
  // direction is looked up only for a vertex with the rule: the tables are empty while pruning was never on.)
  void note_edge_arrival(Index u, Index h, bool far_side)
  {
    if(vertices_[std::size_t(u)].flags & SHADOW_RULE)
      note_arrival(u, shadow_angles_.edge_direction(h, far_side));
  }

  // Whether a settled pseudo-source should emit its windows: always, except beyond the limit or, in a point
  // query, where no path through it can beat the best one found.
  bool expansion_useful(std::size_t v) const
  {
    const FT& d = vertices_[v].dist;
    if(has_limit_ && d > limit_)
      return false;
    if(query_) {
      const FT lb = query_->forward->distance_lower_bound(Index(v));
      if(d + lb > query_->best + relative_tolerance_ * query_->best)
        return false;
    }
    return true;
  }

  void add_point_source_in_face(Index f, const std::array<FT, 3>& b, Index id)
  {
    const Index k_source = Index(face_sources_.size());
    face_sources_.push_back(Face_source{f, b, id});
    const Index root = -1 - k_source;
    for(int k = 0; k < 3; ++k) {
      const Index g = 3 * f + k;
      const FT L = mesh_.he[std::size_t(g)].length;
      const Point_2_ft<FT>& c = mesh_.he[std::size_t(g)].opposite;
      // the point in g's frame: corners source(g) = k at (0,0), target(g) = k+1 at (L,0), k+2 at c
      const FT px = b[std::size_t((k + 1) % 3)] * L + b[std::size_t((k + 2) % 3)] * c.x;
      const FT py = b[std::size_t((k + 2) % 3)] * c.y;
      // the corner source(g), straight from the point inside the face (the pseudo-source is above the edge: the
      // path tracing recognises a point of g's own face)
      const Window straight{FT(0), FT(0), px, py, FT(0), root, 0};
      lower_vertex(mesh_.source(g), distance_2(FT(0), FT(0), px, py), straight, g, FT(0));
      if(b[std::size_t((k + 2) % 3)] == FT(0))
        continue; // on this edge: its other side is a face source of its own (see add_face_source)
      const Index t = mesh_.he[std::size_t(g)].twin;
      if(t >= 0)
        add_window(t, Window{FT(0), L, L - px, -py, FT(0), root, 0});
    }
  }

  // ------------------------------------------------------------------------------------------------
  // Window lists

  void add_window(Index g, const Window& w)
  {
    if(reuse_ && lists_.empty(g))
      used_lists_.push_back(g); // (again after each take(): at most once per window)
    lists_.push(g, w);
    ++stats_.windows_created;
    if(++live_ > stats_.peak_live_windows)
      stats_.peak_live_windows = live_;
    if(!queued_[std::size_t(g)]) {
      if(vertices_[std::size_t(mesh_.source(g))].state == INSIDE || vertices_[std::size_t(mesh_.target(g))].state == INSIDE) {
        queued_[std::size_t(g)] = 1;
        fifo_.push_back(g);
      } else if(!stop_targets_.empty()) {
        pending_.push(Pending_entry{window_min_distance(w.b0, w.b1, w.sx, w.sy, w.sigma), g, 0});
      }
    }
  }

  void make_ready(Index g)
  {
    if(!lists_.empty(g) && !queued_[std::size_t(g)]) {
      queued_[std::size_t(g)] = 1;
      fifo_.push_back(g);
    }
  }

  // Propagates the ready lists in FIFO order (including those that become ready meanwhile). The windows of the
  // list after next are prefetched: their loads then overlap with the work on the current list.
  void drain_ready_lists()
  {
    const typename Batch::Settings s = settings();
    Sequential_sink sink{*this};
    while(fifo_head_ < fifo_.size()) {
      if(fifo_head_ + 2 < fifo_.size())
        lists_.prefetch(fifo_[fifo_head_ + 2]);
      const Index g = fifo_[fifo_head_++];
      queued_[std::size_t(g)] = 0;
      std::vector<Window>& batch = batch_.windows();
      lists_.take(g, batch);
      live_ -= batch.size();
      ++lists_processed_;
      batch_.run(g, s, sink);
    }
    fifo_.clear();
    fifo_head_ = 0;
  }

  // ------------------------------------------------------------------------------------------------
  // Stop targets

  // Whether every stop target is final: at most the front, the smallest value still to come (the queue's top
  // and the smallest window waiting in a list that is not ready; the ready lists are empty here).
  bool stop_targets_final()
  {
    while(!pending_.empty() && lists_.empty(pending_.top().halfedge))
      pending_.pop(); // that list was processed (an entry of a list refilled since is stale but smaller: safe)
    FT front = heap_.empty() ? unreached_ : heap_.top().key;
    if(!pending_.empty() && pending_.top().key < front)
      front = pending_.top().key;
    for(Index v : stop_targets_)
      if(!(vertices_[std::size_t(v)].dist <= front))
        return false;
    front_ = front;
    return true;
  }

  void finish()
  {
    stats_.stopped_early = stopped_early_;
    stats_.stored_windows = 0;
    const std::size_t bytes = lists_.memory_bytes() + heap_.capacity() * sizeof(Heap_entry) +
                              queued_.capacity() + fifo_.capacity() * sizeof(Index) +
                              vertices_.capacity() * sizeof(Vertex_record) + parents_.capacity() * sizeof(Parent);
    if(bytes > stats_.peak_memory_bytes)
      stats_.peak_memory_bytes = bytes;
    if(!reuse_) {
      lists_.release();
      std::vector<char>().swap(queued_);
      heap_.release();
      pending_.release();
      std::vector<Index>().swap(fifo_);
    }
    if(stopped_early_ || has_limit_) {
      // Only values up to the front (or the limit) are final; the others are reported as unreachable, never as a
      // wrong value (distance_lower_bound() then says that they lie beyond the bound).
      const FT bound = final_bound();
      bool cut_any = false;
      const auto cut = [&](Vertex_record& r) {
        if(r.dist > bound) {
          r.dist = unreached_;
          r.source = -1;
          cut_any = true;
        }
      };
      if(reuse_) // the others still have no value
        for(Index v : touched_vertices_)
          cut(vertices_[std::size_t(v)]);
      else
        for(Vertex_record& r : vertices_)
          cut(r);
      // A limit stopped the run if it cut a value, or if a vertex within it has a neighbour that no window reached
      // (windows wholly beyond the limit are never created): statistics().stopped_early says so, as the window
      // engine's does. (stopped_early_ itself stays false: it means "stopped at the front", see final_bound().)
      if(has_limit_ && !stopped_early_)
        stats_.stopped_early = cut_any || limit_left_a_neighbour_unreached();
    }
  }

  bool limit_left_a_neighbour_unreached() const
  {
    const auto check = [&](std::size_t v) {
      if(!(vertices_[v].dist < unreached_))
        return false;
      for(Index k = star_begin_[v]; k < star_begin_[v + 1]; ++k) {
        const Index h = star_[std::size_t(k)];
        if(!(vertices_[std::size_t(mesh_.target(h))].dist < unreached_) ||
           !(vertices_[std::size_t(mesh_.source(Mesh::prev(h)))].dist < unreached_))
          return true;
      }
      return false;
    };
    if(reuse_) {
      for(Index v : touched_vertices_)
        if(check(std::size_t(v)))
          return true;
    } else {
      for(std::size_t v = 0; v < vertices_.size(); ++v)
        if(check(v))
          return true;
    }
    return false;
  }

  // ------------------------------------------------------------------------------------------------
  // Point queries (see Backward_query)

  void offer_candidate(Index v, const FT& d)
  {
    const FT& forward = query_->forward->raw_distance(v);
    if(!(forward < query_->forward->unreached()))
      return;
    const FT sum = d + forward;
    if(sum < query_->best) {
      query_->best = sum;
      query_->best_vertex = v;
      query_->best_face_source = -1;
    }
  }

  // Trims w (on halfedge g, length L) to the part where the lower bound of (this run's value at the point x) +
  // (the forward distance of x) is at most the best sum found: with LB(x) = max(dA - x, dB - (L - x)) (the
  // forward distances of the ends, minus the way along the edge), the prefix where dA - x + w(x) > best and the
  // suffix where dB - (L - x) + w(x) > best go (the first sum decreases with x, the second increases). No path
  // through a trimmed point beats `best`: the forward distance of any point beyond it is at least its own minus
  // the way there. False if nothing remains.
  bool trim_by_query_bound(Index g, Window& w, const FT& L) const
  {
    const FT bound = query_->best + relative_tolerance_ * query_->best;
    const FT da = query_->forward->distance_lower_bound(mesh_.source(g));
    const FT db = query_->forward->distance_lower_bound(mesh_.target(g));
    auto fa = [&](const FT& x) { return da - x + Batch::value_at(w, x); };
    auto fb = [&](const FT& x) { return db - (L - x) + Batch::value_at(w, x); };
    if(fa(w.b1) > bound || fb(w.b0) > bound)
      return false;
    if(fa(w.b0) > bound) {
      // sqrt((x - sx)^2 + sy^2) = K + x, K = bound - sigma - da: linear after squaring
      const FT K = bound - w.sigma - da;
      const FT den = FT(2) * (K + w.sx);
      if(den != FT(0)) {
        const FT x = (w.sx * w.sx + w.sy * w.sy - K * K) / den;
        if(x > w.b0 && x < w.b1)
          w.b0 = x;
      }
    }
    if(fb(w.b1) > bound) {
      // sqrt((x - sx)^2 + sy^2) = K - x, K = bound - sigma - db + L
      const FT K = bound - w.sigma - db + L;
      const FT den = FT(2) * (K - w.sx);
      if(den != FT(0)) {
        const FT x = (K * K - w.sx * w.sx - w.sy * w.sy) / den;
        if(x > w.b0 && x < w.b1)
          w.b1 = x;
      }
    }
    return w.b0 < w.b1;
  }

  // The forward run's point sources in the face of g, reached by the batch's windows: straight through the
  // window, or through its nearer end.
  void query_face_sources(Index g, const Window* begin, const Window* end)
  {
    const std::vector<Face_source>& sources = query_->forward->face_sources();
    if(sources.empty())
      return;
    const Index f = Mesh::face_of(g);
    for(std::size_t k = 0; k < sources.size(); ++k) {
      if(sources[k].face != f)
        continue;
      const int corner = int(g % 3);
      const std::array<FT, 3>& b = sources[k].barycentric;
      const FT L = mesh_.he[std::size_t(g)].length;
      const Point_2_ft<FT>& c = mesh_.he[std::size_t(g)].opposite;
      const FT px = b[std::size_t((corner + 1) % 3)] * L + b[std::size_t((corner + 2) % 3)] * c.x;
      const FT py = b[std::size_t((corner + 2) % 3)] * c.y;
      for(const Window* w = begin; w != end; ++w) {
        const FT den = py - w->sy;
        FT x = den > FT(0) ? w->sx + (px - w->sx) * (-w->sy) / den : px;
        if(x < w->b0) x = w->b0;
        if(x > w->b1) x = w->b1;
        const FT d = Batch::value_at(*w, x) + distance_2(x, FT(0), px, py);
        if(d < query_->best) {
          query_->best = d;
          query_->best_vertex = -1;
          query_->best_face_source = Index(k);
          query_->best_halfedge = g;
          query_->best_window = *w;
          query_->best_window.b0 = query_->best_window.b1 = x; // where the path crosses g
        }
      }
    }
  }

  const Mesh& mesh_;
  FT unreached_, relative_tolerance_;
  FT merge_tolerance_ = FT(0);
  FT limit_ = FT(0), front_ = FT(0);
  bool has_limit_ = false, stopped_early_ = false, record_parents_ = false;
  bool reuse_ = false, reuse_ready_ = false; // reuse between runs; ready: the arrays are sized and reset
  bool shadow_ = false;                      // shadow pruning (set_shadow_pruning())
  Vertex_shadow_angles<FT> shadow_angles_;   // ditto: its angle tables, built once, read-only while running
  std::vector<double> arrival_;              // ditto, per vertex: the direction of its current value (ARRIVAL_KNOWN)
  std::vector<Index> touched_vertices_, used_lists_;
  std::vector<Index> stop_targets_;
  Backward_query* query_ = nullptr;
  std::vector<Index> star_begin_, star_;
  std::vector<std::uint8_t> vertex_flags_;  // PSEUDO_SOURCE, LOBE_VERTEX (from the mesh)
  std::vector<Vertex_record> vertices_;
  std::vector<Parent> parents_;
  std::vector<Face_source> face_sources_;
  Window_chunk_lists<Window> lists_;
  std::vector<char> queued_;  // per halfedge: in the FIFO of ready lists
  Quaternary_heap<Heap_entry> heap_;
  Quaternary_heap<Pending_entry> pending_;
  std::vector<Index> fifo_;
  std::size_t fifo_head_ = 0;
  Batch batch_;
  std::size_t live_ = 0, lists_processed_ = 0;
  Geodesic_statistics stats_;
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_PROPAGATION_H
