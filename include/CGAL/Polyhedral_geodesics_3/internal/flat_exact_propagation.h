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
//   corner itself. Where two windows meet, the zero offset of the thesis is used.
// - An edge propagates into each of its faces: the opposite vertex v3 gets D(s) at v3 when it sees s through the
//   edge (the quadrilateral s, v1, v3, v2 is convex), else min(D(v1) + |v1 v3|, D(v2) + |v2 v3|). When a vertex
//   is lowered, the edges around it get their new distance function and are (re)queued in an indexed binary
//   heap (one entry per edge, moved when its key changes) by the smallest value they give to an opposite vertex
//   that they lower (edges that lower neither are not queued); they propagate when they leave the heap. Every
//   value an edge gives is at least its key, so the distances below the key are final (Dijkstra order), which is
//   what the distance limit and the stop targets use; a vertex lowered again queues its edges again (label
//   correcting), which happens to few vertices with this key (1.0 - 1.2 lowerings per vertex on most of CGAL's
//   demo meshes, 2.8 on the needle triangles of mech-holes-shark, against 1.2 - 1.6 and 3.0 by the minimum of
//   the edge's distance function).
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

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_FLAT_EXACT_PROPAGATION_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_FLAT_EXACT_PROPAGATION_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_types.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>
#include <CGAL/Polyhedral_geodesics_3/internal/geodesic_engine_types.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

template <class FT>
class Flat_exact_propagation
{
public:
  typedef Geodesic_mesh<FT> Mesh;
  typedef typename Mesh::Index Index;
  typedef Geodesic_path_node<FT> Path_node;
  typedef Geodesic_point_distance<FT> Point_distance;

  // The order of the edge queue (tuning and measurements). With `candidate` and `function_minimum` every value an
  // edge gives is at least its key, so the distances below the front are final, which the distance limit and
  // the stop targets rely on; the two others are for comparisons only. Vertex lowerings per vertex measured on
  // CGAL's demo meshes (3 random sources each; mech-holes-shark in parentheses): candidate 1.00 - 1.19 (2.80),
  // with a third fewer edges queued, function_minimum 1.14 - 1.63 (3.04), smaller_vertex about the same,
  // larger_vertex 1.09 - 1.59 (3.24).
  enum class Queue_key
  {
    candidate,        // the smallest value the edge gives to an opposite vertex that it lowers (default); an edge
                      // that lowers neither is not queued
    function_minimum, // the minimum of the edge's distance function over the edge
    smaller_vertex,   // min(D(v1), D(v2))
    larger_vertex     // max(D(v1), D(v2))
  };

  // Counters beyond Geodesic_statistics (tests and tuning).
  struct Counters
  {
    std::size_t edges_propagated = 0;   // edges taken from the queue
    std::size_t dag_searches = 0;       // depth-first searches for cycles (lowerings of reached vertices)
    std::size_t dag_search_visits = 0;  // vertices visited by them
    std::size_t side_links = 0;         // edges with side links (built with the first path query)
    std::size_t side_links_refused = 0; // edges whose preferred side links would have closed a cycle
    std::size_t stuck_restarts = 0;     // restarts through an edge with one unreached vertex (pinched vertices)
  };

  explicit Flat_exact_propagation(const Mesh& mesh) : mesh_(mesh)
  {
    unreached_ = FT(std::numeric_limits<double>::max() / 16);
    if(std::numeric_limits<FT>::is_specialized && std::numeric_limits<FT>::epsilon() > FT(0))
      epsilon_ = FT(std::numeric_limits<FT>::epsilon());
    else
      epsilon_ = FT(0);
    improvement_ = FT(16) * epsilon_;
    build_halfedge_data();
    build_vertex_edges();
    vertex_is_pseudo_source_.assign(mesh_.number_of_vertices, 0);
    // vertices where shortest paths can bend: saddles (angle sum above 2 pi) and reflex boundary vertices
    for(std::size_t v = 0; v < mesh_.number_of_vertices; ++v)
      vertex_is_pseudo_source_[v] = to_double_value(mesh_.vertex_angle_sum[v]) >
                                    (mesh_.vertex_on_boundary[v] ? 1 : 2) * 3.14159265358979323846 + 1e-9;
    clear();
  }

  void clear()
  {
    const std::size_t nv = mesh_.number_of_vertices, ne = mesh_.number_of_edges;
    vs_.assign(nv, Vertex_state{unreached_, FT(0), -1, -1});
    parent_he_.assign(nv, -1);
    parent_kind_.assign(nv, NONE);
    first_reached_.assign(nv, 0);
    last_lowered_.assign(nv, 0);
    clock_ = 0;
    child_next_.assign(nv, -1);
    child_prev_.assign(nv, -1);
    child_head_.assign(ne, -1);
    side_he_.clear();
    side_mask_.clear();
    heap_position_.assign(ne, -1);
    edge_function_.assign(ne, Pseudo_source{false, FT(0), FT(0), FT(0), -1});
    visit_vertex_.assign(nv, 0);
    search_stamp_ = 0;
    heap_.clear();
    peak_heap_ = 0;
    vertex_sources_.clear();
    face_sources_.clear();
    face_source_index_.clear();
    stats_ = Geodesic_statistics();
    counters_ = Counters();
    front_ = FT(0);
    bound_ = unreached_;
    stopped_early_ = false;
  }

  void set_keep_windows(bool) {} // one interval per edge, always kept
  void set_distance_limit(FT limit) { limit_ = limit; has_limit_ = true; }
  void clear_distance_limit() { has_limit_ = false; }
  void set_stop_targets(const std::vector<Index>& targets) { stop_targets_ = targets; }
  void set_queue_key(Queue_key key) { queue_key_ = key; }
  // Windows rooted at saddle and reflex boundary vertices (default on; off: the thesis's rule everywhere).
  void set_vertex_windows(bool on) { vertex_windows_ = on; }

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
          if(!progress(stage, fraction_final(top.key)))
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
    std::vector<Heap_entry>().swap(heap_);
    if(!progress(stage, 1.0))
      throw MDCS::Operation_cancelled(stage);
  }

  FT vertex_distance(Index v) const
  {
    const FT& d = vs_[std::size_t(v)].dist;
    return final_value(d) ? d : FT(std::numeric_limits<double>::infinity());
  }

  Index vertex_source(Index v) const { return final_value(vs_[std::size_t(v)].dist) ? vs_[std::size_t(v)].source : -1; }

  const Geodesic_statistics& statistics() const { return stats_; }
  const Counters& counters() const { return counters_; }

  // The full check of the dependence DAG (vertex and side links; builds the side links), for tests: Kahn's
  // algorithm over all edges.
  bool dependence_graph_is_acyclic() const
  {
    ensure_sides();
    const std::size_t ne = mesh_.number_of_edges;
    std::vector<std::size_t> indegree(ne, 0);
    for(std::size_t x = 0; x < ne; ++x) {
      for_each_edge_child(Index(x), [&](Index y) { ++indegree[std::size_t(y)]; });
    }
    std::vector<Index> ready;
    for(std::size_t x = 0; x < ne; ++x)
      if(indegree[x] == 0)
        ready.push_back(Index(x));
    std::size_t done = 0;
    while(!ready.empty()) {
      const Index x = ready.back();
      ready.pop_back();
      ++done;
      for_each_edge_child(x, [&](Index y) {
        if(--indegree[std::size_t(y)] == 0)
          ready.push_back(y);
      });
    }
    if(done != ne)
      return false;
    // A vertex reached along an edge from its other end, whose other end was reached along the same edge
    // from it, is a cycle hidden from the edge graph (an edge is no parent of itself).
    for(std::size_t v = 0; v < mesh_.number_of_vertices; ++v)
      if(parent_kind_[v] == EDGE_NEIGHBOR) {
        const Index h = parent_he_[v];
        const Index w = he_source(h) == Index(v) ? he_target(h) : he_source(h);
        if(parent_kind_[std::size_t(w)] == EDGE_NEIGHBOR &&
           he_[std::size_t(parent_he_[std::size_t(w)])].edge == he_[std::size_t(h)].edge)
          return false;
      }
    return true;
  }

  // ------------------------------------------------------------------------------------------------
  // Queries

  Point_distance distance_at(Index f, const std::array<FT, 3>& b) const
  {
    const Candidate c = best_candidate(f, b);
    if(c.kind == Candidate::NONE)
      return {FT(std::numeric_limits<double>::infinity()), -1};
    return {c.value, c.source};
  }

  // Emits the path from the point (f, b) to its nearest source: the point, every edge crossing and vertex,
  // the source. Emits nothing if the point is unreachable.
  template <class Emit>
  void trace_path(Index f, const std::array<FT, 3>& b, Emit emit) const
  {
    if(best_candidate(f, b).kind == Candidate::NONE)
      return;
    ensure_sides();
    // the first step follows the DAG too: not through an edge whose distance comes from the query's side
    Candidate c = best_candidate(f, b, true);
    if(c.kind == Candidate::NONE)
      c = best_candidate(f, b);
    int zeros = 0, nonzero = 0;
    for(int k = 0; k < 3; ++k) {
      if(b[std::size_t(k)] == FT(0)) ++zeros;
      else nonzero = k;
    }
    Walker walker{-1, -1, FT(0)};
    if(zeros >= 2) {
      walker.vertex = he_source(3 * f + nonzero);
      emit(vertex_node(walker.vertex));
    } else {
      emit(face_node(f, b));
      switch(c.kind) {
      case Candidate::FACE_SOURCE:
        emit(face_node(c.face, face_sources_[std::size_t(c.index)].barycentric));
        return;
      case Candidate::CORNER:
        walker.vertex = c.index;
        emit(vertex_node(walker.vertex));
        break;
      case Candidate::EDGE: {
        // the segment from the point to the pseudo-source of the edge crosses it at c.t
        const Index h = c.index;
        const FT L = he_[std::size_t(h)].length;
        if(!(c.t > FT(0)) || !(c.t < L)) {
          walker.vertex = !(c.t > FT(0)) ? he_source(h) : he_target(h);
          emit(vertex_node(walker.vertex));
        } else {
          if(!c.on_edge)
            emit(edge_node(h, c.t / L));
          walker.halfedge = h;
          walker.t = c.t;
        }
        break;
      }
      default:
        return;
      }
    }
    const std::size_t max_steps = 2 * (mesh_.number_of_edges + mesh_.number_of_vertices) + 64;
    for(std::size_t step = 0; step < max_steps; ++step)
      if(!walk_step(walker, emit))
        return;
    throw std::runtime_error("CGAL::Polyhedral_geodesics_3: flat-exact path tracing did not reach a source "
                             "(the dependence graph was lost)");
  }

private:
  // ------------------------------------------------------------------------------------------------
  // Types

  enum Parent_kind : unsigned char
  {
    NONE,          // unreached
    ROOT_VERTEX,   // a vertex source
    ROOT_FACE,     // a corner of the face of a face source: parent_he_ is the index of the face source
    EUCLID,        // straight from the pseudo-source of the edge of parent_he_ (the vertex is opposite it)
    ALONG_SOURCE,  // along the edge from source(parent_he_) (the vertex is opposite parent_he_)
    ALONG_TARGET,  // along the edge from target(parent_he_)
    EDGE_NEIGHBOR  // along the edge of parent_he_ itself, from its other end (vertex sources, pinched vertices)
  };

  struct Vertex_source
  {
    Index vertex;
    Index id;
  };

  struct Face_source
  {
    Index face;
    std::array<FT, 3> barycentric;
    Index id;
  };

  struct Heap_entry
  {
    FT key;
    Index edge;
  };

  // The distance function of an edge: sigma + the distance to a pseudo-source (x, +-y), y >= 0, in the frame
  // of one of its halfedges; `root` is the vertex the window hangs from (-1: straight from a source).
  struct Pseudo_source
  {
    bool valid;
    FT x, y;
    FT sigma;
    Index root;
  };

  // An edge around a vertex: its ends (those of its canonical halfedge), the vertices opposite it (-1: none)
  // and its length.
  struct Incident_edge
  {
    Index edge, h, a, b, y1, y2; // h: the canonical halfedge, from a to b
    FT length;
  };

  struct Candidate
  {
    enum Kind { NONE, CORNER, EDGE, FACE_SOURCE };
    Kind kind = NONE;
    FT value = FT(0);
    Index source = -1;
    Index index = -1;  // corner vertex, halfedge (EDGE), or face source
    Index face = -1;   // FACE_SOURCE: its face
    FT t = FT(0);      // EDGE: where the segment to the pseudo-source crosses the halfedge (arc length)
    bool on_edge = false; // EDGE: the query point itself lies on that edge
  };

  // The state of the back-tracing: at a vertex, or on the edge of `halfedge` at arc length t from its source,
  // arrived from the face of `halfedge`.
  struct Walker
  {
    Index vertex;
    Index halfedge;
    FT t;
  };

  // ------------------------------------------------------------------------------------------------
  // Mesh helpers

  void build_vertex_edges()
  {
    const std::size_t nv = mesh_.number_of_vertices, ne = mesh_.number_of_edges;
    vedge_begin_.assign(nv + 1, 0);
    for(std::size_t e = 0; e < ne; ++e) {
      const Index h = mesh_.edge_halfedge[e];
      const Index a = he_source(h), b = he_target(h);
      ++vedge_begin_[std::size_t(a) + 1];
      if(b != a)
        ++vedge_begin_[std::size_t(b) + 1];
    }
    for(std::size_t v = 0; v < nv; ++v)
      vedge_begin_[v + 1] += vedge_begin_[v];
    vedge_.resize(std::size_t(vedge_begin_[nv]));
    std::vector<Index> fill(vedge_begin_.begin(), vedge_begin_.end() - 1);
    for(std::size_t e = 0; e < ne; ++e) {
      const Index h = mesh_.edge_halfedge[e], tw = he_[std::size_t(h)].twin;
      const Index a = he_source(h), b = he_target(h);
      const Incident_edge ie{Index(e), h, a, b, he_opposite_vertex(h), tw < 0 ? Index(-1) : he_opposite_vertex(tw),
                             he_[std::size_t(h)].length};
      vedge_[std::size_t(fill[std::size_t(a)]++)] = ie;
      if(b != a)
        vedge_[std::size_t(fill[std::size_t(b)]++)] = ie;
    }
  }

  // The mesh's data per halfedge, packed for the propagation (one cache line per face instead of six arrays).
  struct Halfedge_data
  {
    Point_2_ft<FT> opposite; // the opposite corner in the halfedge's frame
    FT length;
    Index source, twin, edge;
  };

  void build_halfedge_data()
  {
    const std::size_t nh = 3 * mesh_.number_of_faces;
    he_.resize(nh);
    for(std::size_t h = 0; h < nh; ++h)
      he_[h] = Halfedge_data{mesh_.he_opposite[h], mesh_.he_length[h], mesh_.he_source[h], mesh_.he_twin[h],
                             mesh_.he_edge[h]};
  }

  Index he_source(Index h) const { return he_[std::size_t(h)].source; }
  Index he_target(Index h) const { return he_[std::size_t(Mesh::next(h))].source; }
  Index he_opposite_vertex(Index h) const { return he_[std::size_t(Mesh::prev(h))].source; }

  Index other_end(Index e, Index v) const
  {
    const Index h = mesh_.edge_halfedge[std::size_t(e)];
    return he_source(h) == v ? he_target(h) : he_source(h);
  }

  bool reached(Index v) const { return vs_[std::size_t(v)].dist < unreached_; }

  bool final_value(const FT& d) const { return d < unreached_ && d <= bound_; }

  // ------------------------------------------------------------------------------------------------
  // The distance function of an edge

  // The pseudo-source at distances c1 from (0,0) and c2 from (L,0), with y >= 0 (Heron's formula for y,
  // accurate when the pseudo-source is close to the line of the edge). Invalid when no such point exists
  // (|c1 - c2| > L or c1 + c2 < L beyond rounding) or L == 0.
  Pseudo_source pseudo_source(const FT& c1, const FT& c2, const FT& L) const
  {
    using std::sqrt;
    Pseudo_source s{false, FT(0), FT(0), FT(0), -1};
    if(!(L > FT(0)))
      return s;
    const FT tol = FT(64) * epsilon_ * (c1 + c2 + L);
    FT f1 = L + c2 - c1, f2 = c1 + c2 - L, f3 = L + c1 - c2;
    if(f1 < -tol || f2 < -tol || f3 < -tol)
      return s;
    if(f1 < FT(0)) f1 = FT(0);
    if(f2 < FT(0)) f2 = FT(0);
    if(f3 < FT(0)) f3 = FT(0);
    const FT f4 = c1 + c2 + L;
    s.valid = true;
    const FT inverse = FT(1) / (FT(2) * L);
    s.x = (c1 - c2) * (c1 + c2) * inverse + L / FT(2);
    s.y = sqrt(f1 * f2 * f3 * f4) * inverse;
    return s;
  }

  // The window of the edge (a, b): the one both ends belong to, or the window of one end rooted at the other;
  // else (two windows meet on the edge) none: a pseudo-source at zero offset, the thesis's rule.
  void edge_window(Index a, Index b, FT& sigma, Index& root) const
  {
    const std::size_t ia = std::size_t(a), ib = std::size_t(b);
    if(vs_[ia].root == vs_[ib].root && vs_[ia].offset == vs_[ib].offset) {
      sigma = vs_[ia].offset;
      root = vs_[ia].root;
    } else if(vs_[ib].root == a && vs_[ib].offset == vs_[ia].dist) {
      sigma = vs_[ia].dist;
      root = a;
    } else if(vs_[ia].root == b && vs_[ia].offset == vs_[ib].dist) {
      sigma = vs_[ib].dist;
      root = b;
    } else {
      sigma = FT(0);
      root = -1;
    }
  }

  // The distance function of the edge of h in h's frame (pseudo-source with the magnitude of y).
  Pseudo_source pseudo_source_of(Index h) const
  {
    return pseudo_source_ab(he_source(h), he_target(h), he_[std::size_t(h)].length);
  }

  // The same for the edge from a to b of length L, in the frame where a is at (0,0) and b at (L,0).
  Pseudo_source pseudo_source_ab(Index a, Index b, const FT& L) const
  {
    // two sources meet on the edge: no single pseudo-source explains both ends (rebuilding one would put a
    // vertex beyond the edge too close to both), the edge propagates along its ends only
    if(vs_[std::size_t(a)].source != vs_[std::size_t(b)].source)
      return Pseudo_source{false, FT(0), FT(0), FT(0), -1};
    FT sigma;
    Index root;
    edge_window(a, b, sigma, root);
    Pseudo_source s = pseudo_source(vs_[std::size_t(a)].dist - sigma, vs_[std::size_t(b)].dist - sigma, L);
    s.sigma = sigma;
    s.root = root;
    return s;
  }

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
  // here and kept for its propagation. The queue is a binary heap indexed by edge (a changed key moves the
  // entry: no stale entries). An edge that cannot lower either opposite vertex (every candidate is at least
  // the key) is not queued.
  void push_edge(const Incident_edge& ie)
  {
    if(!reached(ie.a) || !reached(ie.b))
      return;
    const Pseudo_source s = pseudo_source_ab(ie.a, ie.b, ie.length);
    FT key = queue_key(ie.a, ie.b, ie.length, s);
    Index i = heap_position_[std::size_t(ie.edge)];
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
        FT value, sigma;
        Parent_kind kind;
        Index root;
        evaluate_into_face(k == 0 ? ie.h : he_[std::size_t(ie.h)].twin, sk, value, kind, sigma, root);
        const FT old = vs_[std::size_t(y)].dist;
        if(value < old - improvement_ * old && value < key)
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
    edge_function_[std::size_t(ie.edge)] = s;
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

  Index source_through(Index h, Parent_kind kind) const
  {
    const Index a = he_source(h), b = he_target(h);
    if(kind == ALONG_SOURCE) return vs_[std::size_t(a)].source;
    if(kind == ALONG_TARGET) return vs_[std::size_t(b)].source;
    if(vs_[std::size_t(a)].source == vs_[std::size_t(b)].source)
      return vs_[std::size_t(a)].source;
    const FT via_a = vs_[std::size_t(a)].dist + he_[std::size_t(Mesh::prev(h))].length;
    const FT via_b = vs_[std::size_t(b)].dist + he_[std::size_t(Mesh::next(h))].length;
    return via_a <= via_b ? vs_[std::size_t(a)].source : vs_[std::size_t(b)].source;
  }

  void propagate_edge(Index e, const FT& key)
  {
    const Index h0 = mesh_.edge_halfedge[std::size_t(e)];
    Pseudo_source s = edge_function_[std::size_t(e)];
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
        const Index e = vedge_[std::size_t(k)].edge;
        const Index w = other_end(e, s.vertex);
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
    const FT old = vs_[std::size_t(v)].dist;
    if(!(value < old - improvement_ * old))
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
    for(Index k = vedge_begin_[std::size_t(v)]; k < vedge_begin_[std::size_t(v) + 1]; ++k)
      push_edge(vedge_[std::size_t(k)]);
    return true;
  }

  Index parent_edge(Index v) const
  {
    const Parent_kind k = Parent_kind(parent_kind_[std::size_t(v)]);
    if(k == NONE || k == ROOT_VERTEX || k == ROOT_FACE)
      return -1;
    return he_[std::size_t(parent_he_[std::size_t(v)])].edge;
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
      for(Index w = child_head_[std::size_t(vedge_[std::size_t(k)].edge)]; w >= 0; w = child_next_[std::size_t(w)])
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

  // The children of edge x in the edge DAG: the edges around the vertices lowered from x (but x itself), and
  // the edges with side links from x.
  template <class Visit>
  void for_each_edge_child(Index x, Visit visit) const
  {
    for(Index w = child_head_[std::size_t(x)]; w >= 0; w = child_next_[std::size_t(w)])
      for(Index k = vedge_begin_[std::size_t(w)]; k < vedge_begin_[std::size_t(w) + 1]; ++k)
        if(vedge_[std::size_t(k)].edge != x)
          visit(vedge_[std::size_t(k)].edge);
    if(side_he_.empty())
      return;
    const Index h0 = mesh_.edge_halfedge[std::size_t(x)];
    for(int s = 0; s < 2; ++s) {
      const Index h = s == 0 ? h0 : he_[std::size_t(h0)].twin;
      if(h < 0)
        break;
      // y's side halfedge g: x is a parent through bit 0 if it is next(g), through bit 1 if it is prev(g)
      const Index gn = Mesh::next(h), gp = Mesh::prev(h);
      const Index yn = he_[std::size_t(gn)].edge, yp = he_[std::size_t(gp)].edge;
      if(yn != x && side_he_[std::size_t(yn)] == gn && (side_mask_[std::size_t(yn)] & 2))
        visit(yn);
      if(yp != x && side_he_[std::size_t(yp)] == gp && (side_mask_[std::size_t(yp)] & 1))
        visit(yp);
    }
  }

  // The side links (thesis 4.3.2), built with the first path query from the final distances. Each edge x
  // gets, of its faces whose opposite vertex is reached, the one where the pseudo-source of x (placed on
  // that face's side) best explains the distance of the opposite vertex (the Q234 / Q345 test); of the two
  // other edges of that face, those that the segments from x to the pseudo-source cross become parents of
  // x (the thesis takes both; two edges around the same vertex would then often be each other's parent).
  // The vertex links alone are acyclic; the side links inside a strongly connected component of the whole
  // graph (rare, local) are removed, which makes the DAG acyclic again. Back-tracing follows the DAG, hence
  // always ends.
  void ensure_sides() const
  {
    if(!side_he_.empty() || mesh_.number_of_edges == 0)
      return;
    const std::size_t ne = mesh_.number_of_edges;
    side_he_.assign(ne, -1);
    side_mask_.assign(ne, 0);
    for(std::size_t x = 0; x < ne; ++x)
      assign_side(Index(x));
    // the graph in compressed rows
    std::vector<Index> begin(ne + 1, 0), children;
    for(std::size_t x = 0; x < ne; ++x) {
      for_each_edge_child(Index(x), [&](Index y) { children.push_back(y); });
      begin[x + 1] = Index(children.size());
    }
    // Tarjan's strongly connected components, iteratively
    std::vector<Index> index(ne, -1), low(ne, 0), component(ne, -1), tarjan_stack, call_stack, next_child(ne, 0);
    std::vector<char> on_stack(ne, 0);
    Index counter = 0, components = 0;
    for(std::size_t root = 0; root < ne; ++root) {
      if(index[root] >= 0)
        continue;
      call_stack.push_back(Index(root));
      index[root] = low[root] = counter++;
      next_child[root] = begin[root];
      tarjan_stack.push_back(Index(root));
      on_stack[root] = 1;
      while(!call_stack.empty()) {
        const Index x = call_stack.back();
        if(next_child[std::size_t(x)] < begin[std::size_t(x) + 1]) {
          const Index y = children[std::size_t(next_child[std::size_t(x)]++)];
          if(index[std::size_t(y)] < 0) {
            index[std::size_t(y)] = low[std::size_t(y)] = counter++;
            next_child[std::size_t(y)] = begin[std::size_t(y)];
            tarjan_stack.push_back(y);
            on_stack[std::size_t(y)] = 1;
            call_stack.push_back(y);
          } else if(on_stack[std::size_t(y)]) {
            low[std::size_t(x)] = (std::min)(low[std::size_t(x)], index[std::size_t(y)]);
          }
          continue;
        }
        call_stack.pop_back();
        if(!call_stack.empty())
          low[std::size_t(call_stack.back())] = (std::min)(low[std::size_t(call_stack.back())], low[std::size_t(x)]);
        if(low[std::size_t(x)] == index[std::size_t(x)]) {
          Index y;
          do {
            y = tarjan_stack.back();
            tarjan_stack.pop_back();
            on_stack[std::size_t(y)] = 0;
            component[std::size_t(y)] = components;
          } while(y != x);
          ++components;
        }
      }
    }
    // side links within a component close cycles: drop them
    for(std::size_t x = 0; x < ne; ++x) {
      const Index g = side_he_[x];
      if(g < 0)
        continue;
      const Index p1 = he_[std::size_t(Mesh::next(g))].edge, p2 = he_[std::size_t(Mesh::prev(g))].edge;
      if(((side_mask_[x] & 1) && component[std::size_t(p1)] == component[x]) ||
         ((side_mask_[x] & 2) && component[std::size_t(p2)] == component[x])) {
        side_he_[x] = -1;
        side_mask_[x] = 0;
        --counters_.side_links;
        ++counters_.side_links_refused;
      }
    }
  }

  void assign_side(Index x) const
  {
    using std::sqrt;
    const Index h0 = mesh_.edge_halfedge[std::size_t(x)];
    if(!reached(he_source(h0)) || !reached(he_target(h0)))
      return;
    const Pseudo_source s = pseudo_source_of(h0);
    // no side for a pseudo-source on the line of the edge (an edge around a vertex source): the segments to
    // it run along the edge, back-tracing leaves the edge through its end
    const FT L = he_[std::size_t(h0)].length;
    if(!s.valid || !(s.y > FT(64) * epsilon_ * (s.sigma + L + vs_[std::size_t(he_source(h0))].dist)))
      return;
    const std::uint32_t established = (std::max)(last_lowered_[std::size_t(he_source(h0))],
                                                 last_lowered_[std::size_t(he_target(h0))]);
    Index hs[2] = {-1, -1};
    FT q[2] = {FT(0), FT(0)};
    int n = 0;
    for(int k = 0; k < 2; ++k) {
      const Index h = k == 0 ? h0 : he_[std::size_t(h0)].twin;
      if(h < 0)
        break;
      const Index y = he_opposite_vertex(h);
      // Only upstream faces: the opposite vertex was reached before the last lowering of an end of x (a
      // vertex reached later, or lowered from x, is downstream of x).
      if(!reached(y) || parent_edge(y) == x || !(first_reached_[std::size_t(y)] <= established))
        continue;
      // the pseudo-source in h's frame, on the side of h's face
      const FT sx = k == 0 ? s.x : L - s.x;
      const Point_2_ft<FT>& p = he_[std::size_t(h)].opposite;
      const FT dx = p.x - sx, dy = p.y - s.y;
      const FT fit = vs_[std::size_t(y)].dist - (s.sigma + sqrt(dx * dx + dy * dy));
      hs[n] = h;
      q[n] = fit < FT(0) ? -fit : fit;
      ++n;
    }
    if(n == 2 && q[1] < q[0]) {
      std::swap(hs[0], hs[1]);
      std::swap(q[0], q[1]);
    }
    if(n > 0) {
      const Index h = hs[0];
      side_he_[std::size_t(x)] = h;
      side_mask_[std::size_t(x)] = exit_mask(h, h == h0 ? s.x : L - s.x, s.y, has_face_source(Mesh::face_of(h)));
      ++counters_.side_links;
    }
  }

  // Which of the two other edges of the face of h the segments from the edge of h to the pseudo-source
  // (sx, sy) (in h's frame, on the face's side) leave the face through: bit 0 next(h), bit 1 prev(h). The
  // opposite corner z is left (cross > 0) or right of the segment from (t, 0), linearly in t.
  // 0 if the pseudo-source lies in the face (the segments end there, at a source in the face): in the closed
  // face if `closed` (the face holds a face source), else strictly inside beyond rounding (a pseudo-source at a
  // corner, e.g. a vertex source, is not inside: the back-tracing must be allowed to go there).
  unsigned char exit_mask(Index h, const FT& sx, const FT& sy, bool closed) const
  {
    const FT L = he_[std::size_t(h)].length;
    const Point_2_ft<FT>& z = he_[std::size_t(h)].opposite;
    const FT tol = FT(1024) * epsilon_ * (L * L + z.x * z.x + z.y * z.y + sx * sx + sy * sy);
    const FT o0 = sy * L, o1 = (z.x - L) * sy - z.y * (sx - L), o2 = (-z.x) * (sy - z.y) - (-z.y) * (sx - z.x);
    if(closed ? (o0 >= -tol && o1 >= -tol && o2 >= -tol) : (o0 > tol && o1 > tol && o2 > tol))
      return 0;
    const FT c0 = sx * z.y - sy * z.x;
    const FT c1 = (sx - L) * z.y - sy * (z.x - L);
    unsigned char mask = 0;
    if(c0 > FT(0) || c1 > FT(0)) mask |= 1;
    if(c0 < FT(0) || c1 < FT(0)) mask |= 2;
    return mask == 0 ? 3 : mask;
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
    // the propagation's arrays (the side links of the paths come on top: 5 bytes per edge)
    const std::size_t nv = mesh_.number_of_vertices, ne = mesh_.number_of_edges;
    std::size_t bytes = nv * (2 * sizeof(FT) + 7 * sizeof(Index) + 2 + 3 * sizeof(std::uint32_t)) +
                        ne * (2 * sizeof(Index) + sizeof(Pseudo_source) + sizeof(Halfedge_data) * 3 / 2) +
                        vedge_.size() * sizeof(Incident_edge) +
                        peak_heap_ * sizeof(Heap_entry) + stack_.capacity() * sizeof(Index);
    if(bytes > stats_.peak_memory_bytes)
      stats_.peak_memory_bytes = bytes;
  }

  // ------------------------------------------------------------------------------------------------
  // Points in faces

  static FT length_2(const FT& x, const FT& y)
  {
    using std::sqrt;
    return sqrt(x * x + y * y);
  }

  // The point with barycentric coordinates b of face f, in the frame of the face's halfedge 3f+k.
  Point_2_ft<FT> point_in_halfedge_frame(Index f, const std::array<FT, 3>& b, int k) const
  {
    const Index g = 3 * f + k;
    const auto& o = he_[std::size_t(g)].opposite;
    const FT len = he_[std::size_t(g)].length;
    const FT wt = b[std::size_t((k + 1) % 3)], wo = b[std::size_t((k + 2) % 3)];
    return Point_2_ft<FT>{wt * len + wo * o.x, wo * o.y};
  }

  bool usable(Index v) const { return reached(v) && (!stopped_early_ || vs_[std::size_t(v)].dist <= bound_); }

  bool has_face_source(Index f) const
  {
    auto it = std::lower_bound(face_source_index_.begin(), face_source_index_.end(), std::make_pair(f, Index(-1)));
    return it != face_source_index_.end() && it->first == f;
  }

  // The best way to reach the point (f, b): a face source in f, a corner, or the pseudo-source of an edge of f
  // seen through that edge. A point on an edge is also looked at from the face on the other side.
  // With `dag_only` (paths, side links built), an edge whose side links point to the query's face is skipped:
  // its distance does not come from across it (a tie in degenerate faces).
  Candidate best_candidate(Index f, const std::array<FT, 3>& b, bool dag_only = false) const
  {
    Candidate best;
    int zeros = 0, nonzero = 0;
    for(int k = 0; k < 3; ++k) {
      if(b[std::size_t(k)] == FT(0)) ++zeros;
      else nonzero = k;
    }
    if(zeros >= 2) {
      const Index v = he_source(3 * f + nonzero);
      if(usable(v) && final_value(vs_[std::size_t(v)].dist)) {
        best.kind = Candidate::CORNER;
        best.value = vs_[std::size_t(v)].dist;
        best.source = vs_[std::size_t(v)].source;
        best.index = v;
      }
      return best;
    }
    candidates_in_face(f, b, best, dag_only);
    if(zeros == 1) {
      int k = 0;
      while(b[std::size_t((k + 2) % 3)] != FT(0))
        ++k;
      const Index g = 3 * f + k;
      const Index tw = he_[std::size_t(g)].twin;
      if(tw >= 0) {
        std::array<FT, 3> b2 = {FT(0), FT(0), FT(0)};
        b2[std::size_t(tw % 3)] = b[std::size_t((k + 1) % 3)];
        b2[std::size_t((tw % 3 + 1) % 3)] = b[std::size_t(k)];
        candidates_in_face(Mesh::face_of(tw), b2, best, dag_only);
      }
    }
    if(best.kind != Candidate::NONE && !final_value(best.value))
      best.kind = Candidate::NONE;
    return best;
  }

  void consider(Candidate& best, const Candidate& c) const
  {
    if(best.kind == Candidate::NONE || c.value < best.value)
      best = c;
  }

  void candidates_in_face(Index f, const std::array<FT, 3>& b, Candidate& best, bool dag_only) const
  {
    using std::sqrt;
    // face sources
    auto it = std::lower_bound(face_source_index_.begin(), face_source_index_.end(), std::make_pair(f, Index(-1)));
    for(; it != face_source_index_.end() && it->first == f; ++it) {
      const Face_source& s = face_sources_[std::size_t(it->second)];
      const Point_2_ft<FT> p = point_in_halfedge_frame(f, b, 0), q = point_in_halfedge_frame(f, s.barycentric, 0);
      Candidate c;
      c.kind = Candidate::FACE_SOURCE;
      c.value = length_2(p.x - q.x, p.y - q.y);
      c.source = s.id;
      c.index = it->second;
      c.face = f;
      consider(best, c);
    }
    for(int k = 0; k < 3; ++k) {
      const Index h = 3 * f + k;
      const Index a = he_source(h), bv = he_target(h);
      const Point_2_ft<FT> p = point_in_halfedge_frame(f, b, k);
      if(usable(a)) {
        Candidate c;
        c.kind = Candidate::CORNER;
        c.value = vs_[std::size_t(a)].dist + length_2(p.x, p.y);
        c.source = vs_[std::size_t(a)].source;
        c.index = a;
        consider(best, c);
      }
      if(!usable(a) || !usable(bv))
        continue;
      if(dag_only && side_he_[std::size_t(he_[std::size_t(h)].edge)] == h)
        continue;
      const FT L = he_[std::size_t(h)].length;
      const Pseudo_source s = pseudo_source_of(h);
      if(!s.valid)
        continue;
      const FT py = p.y < FT(0) ? FT(0) : p.y;
      const FT denom = py + s.y;
      if(!(denom > FT(0)))
        continue;
      const FT t = s.x + (p.x - s.x) * s.y / denom;
      if(!(t >= FT(0) && t <= L))
        continue;
      Candidate c;
      c.kind = Candidate::EDGE;
      const FT dx = p.x - s.x;
      c.value = s.sigma + sqrt(dx * dx + denom * denom);
      c.source = source_through(h, EUCLID);
      c.index = h;
      c.t = t;
      c.on_edge = b[std::size_t((k + 2) % 3)] == FT(0);
      consider(best, c);
    }
  }

  // ------------------------------------------------------------------------------------------------
  // Back-tracing

  Path_node vertex_node(Index v) const { return vertex_path_node(mesh_, v); }

  Path_node edge_node(Index g, const FT& r) const { return edge_path_node(mesh_, g, r); }

  Path_node face_node(Index f, const std::array<FT, 3>& b) const { return face_path_node(mesh_, f, b); }

  template <class Emit>
  void go_to_vertex(Walker& w, Index v, Emit& emit) const
  {
    w.vertex = v;
    w.halfedge = -1;
    emit(vertex_node(v));
  }

  // Leaves a point of the edge of h (arc length t) for the end with the smaller D(end) + distance, or for a
  // source in one of its two faces (a face source, or an opposite corner that is a root of the DAG: the path
  // ends there). Returns false when the path ended.
  template <class Emit>
  bool leave_edge(Walker& w, Index h, const FT& t, Emit& emit) const
  {
    const FT L = he_[std::size_t(h)].length;
    const Index a = he_source(h), b = he_target(h);
    Index best = vs_[std::size_t(a)].dist + t <= vs_[std::size_t(b)].dist + (L - t) ? a : b;
    FT best_value = (std::min)(vs_[std::size_t(a)].dist + t, vs_[std::size_t(b)].dist + (L - t));
    Index best_face_source = -1;
    for(int k = 0; k < 2; ++k) {
      const Index g = k == 0 ? h : he_[std::size_t(h)].twin;
      if(g < 0)
        break;
      const FT tg = k == 0 ? t : L - t; // the point in g's frame: (tg, 0)
      const Index y = he_opposite_vertex(g);
      const Parent_kind kind = Parent_kind(parent_kind_[std::size_t(y)]);
      if(kind == ROOT_VERTEX || kind == ROOT_FACE) {
        const Point_2_ft<FT>& p = he_[std::size_t(g)].opposite;
        const FT value = vs_[std::size_t(y)].dist + length_2(p.x - tg, p.y);
        if(value < best_value) {
          best_value = value;
          best = y;
          best_face_source = -1;
        }
      }
      const Index f = Mesh::face_of(g);
      auto it = std::lower_bound(face_source_index_.begin(), face_source_index_.end(), std::make_pair(f, Index(-1)));
      for(; it != face_source_index_.end() && it->first == f; ++it) {
        const Point_2_ft<FT> q = point_in_halfedge_frame(f, face_sources_[std::size_t(it->second)].barycentric, int(g % 3));
        const FT value = length_2(q.x - tg, q.y);
        if(value < best_value) {
          best_value = value;
          best_face_source = it->second;
        }
      }
    }
    if(best_face_source >= 0) {
      const Face_source& fs = face_sources_[std::size_t(best_face_source)];
      emit(face_node(fs.face, fs.barycentric));
      return false;
    }
    go_to_vertex(w, best, emit);
    return true;
  }

  // One step of the back-tracing; false when a source is reached.
  template <class Emit>
  bool walk_step(Walker& w, Emit& emit) const
  {
    using std::sqrt;
    if(w.halfedge < 0) {
      const Index v = w.vertex;
      const Index h = parent_he_[std::size_t(v)];
      switch(Parent_kind(parent_kind_[std::size_t(v)])) {
      case ROOT_VERTEX:
        return false;
      case ROOT_FACE: {
        const Face_source& s = face_sources_[std::size_t(h)];
        emit(face_node(s.face, s.barycentric));
        return false;
      }
      case ALONG_SOURCE:
        go_to_vertex(w, he_source(h), emit);
        return true;
      case ALONG_TARGET:
        go_to_vertex(w, he_target(h), emit);
        return true;
      case EDGE_NEIGHBOR:
        go_to_vertex(w, he_source(h) == v ? he_target(h) : he_source(h), emit);
        return true;
      case EUCLID: {
        // straight toward the pseudo-source of the parent edge, on the side away from the face of h
        const FT L = he_[std::size_t(h)].length;
        const Pseudo_source s = pseudo_source_of(h);
        const Point_2_ft<FT>& p = he_[std::size_t(h)].opposite;
        FT t = FT(0);
        bool inside = false;
        if(s.valid && p.y + s.y > FT(0)) {
          t = s.x + (p.x - s.x) * s.y / (p.y + s.y);
          inside = t > FT(0) && t < L;
        }
        if(!inside) {
          // the parent edge is seen at an end (or the pseudo-source is lost): through that end
          const FT via_a = vs_[std::size_t(he_source(h))].dist + he_[std::size_t(Mesh::prev(h))].length;
          const FT via_b = vs_[std::size_t(he_target(h))].dist + he_[std::size_t(Mesh::next(h))].length;
          go_to_vertex(w, via_a <= via_b ? he_source(h) : he_target(h), emit);
          return true;
        }
        emit(edge_node(h, t / L));
        w.vertex = -1;
        w.halfedge = h;
        w.t = t;
        return true;
      }
      default:
        throw std::runtime_error("CGAL::Polyhedral_geodesics_3: flat-exact path tracing reached an unreached vertex");
      }
    }
    // On the edge of h at arc length t, coming from the face of h: go on into the face on the other side if
    // the DAG says that the edge's distance comes from there, else through an end of the edge.
    const Index h = w.halfedge;
    const Index tw = he_[std::size_t(h)].twin;
    const Index e = he_[std::size_t(h)].edge;
    if(tw < 0 || side_he_[std::size_t(e)] != tw) {
      return leave_edge(w, h, w.t, emit);
    }
    const FT L = he_[std::size_t(tw)].length;
    const Pseudo_source s = pseudo_source_of(tw); // in tw's frame; on the side of tw's face: (s.x, +s.y)
    if(!s.valid) {
      return leave_edge(w, h, w.t, emit);
    }
    const FT qx = L - w.t; // the point in tw's frame
    const Point_2_ft<FT>& z = he_[std::size_t(tw)].opposite;
    const FT dx = s.x - qx, dy = s.y;
    // which side of the ray q -> s is the opposite corner z on
    const FT cross = dx * z.y - dy * (z.x - qx);
    Index exit_he;
    FT ax, ay, bx, by; // the exit halfedge from (ax, ay) to (bx, by) in tw's frame
    if(cross > FT(0)) {
      exit_he = Mesh::next(tw); // from target(tw) = (L, 0) to z
      ax = L; ay = FT(0); bx = z.x; by = z.y;
    } else if(cross < FT(0)) {
      exit_he = Mesh::prev(tw); // from z to source(tw) = (0, 0)
      ax = z.x; ay = z.y; bx = FT(0); by = FT(0);
    } else {
      exit_he = -1;
      ax = ay = bx = by = FT(0);
    }
    const Index g = Mesh::face_of(tw);
    const Index zv = he_opposite_vertex(tw);
    // ray q + lambda (s - q) meets the exit edge a + mu (b - a)
    FT lambda, mu;
    if(exit_he < 0) {
      const FT zz = (z.x - qx) * (z.x - qx) + z.y * z.y;
      const FT ss = dx * dx + dy * dy;
      lambda = ss > FT(0) ? sqrt(zz / ss) : FT(2);
      mu = FT(1);
    } else {
      const FT ex = bx - ax, ey = by - ay;
      const FT det = dx * (-ey) - dy * (-ex);
      if(det == FT(0)) {
        return leave_edge(w, h, w.t, emit);
      }
      const FT rx = ax - qx, ry = ay;
      lambda = (rx * (-ey) - ry * (-ex)) / det;
      mu = (dx * ry - dy * rx) / det;
    }
    const unsigned char mask = side_mask_[std::size_t(e)];
    // (a pseudo-source on the boundary of the face, lambda = 1 up to rounding, is reached through the exit)
    if(mask == 0 || !(lambda <= FT(1) + FT(64) * epsilon_)) {
      // The pseudo-source lies in the face: a face source there, or the best corner (the opposite corner only
      // if the DAG has a link from an edge around it, i.e. the mask is not empty).
      Candidate best;
      std::array<FT, 3> bq = {FT(0), FT(0), FT(0)};
      bq[std::size_t(tw % 3)] = w.t / L;               // source(tw) == target(h): weight t / L
      bq[std::size_t((tw % 3 + 1) % 3)] = FT(1) - w.t / L;
      auto it = std::lower_bound(face_source_index_.begin(), face_source_index_.end(), std::make_pair(g, Index(-1)));
      for(; it != face_source_index_.end() && it->first == g; ++it) {
        const Face_source& fs = face_sources_[std::size_t(it->second)];
        const Point_2_ft<FT> p = point_in_halfedge_frame(g, bq, 0), q = point_in_halfedge_frame(g, fs.barycentric, 0);
        Candidate c;
        c.kind = Candidate::FACE_SOURCE;
        c.value = length_2(p.x - q.x, p.y - q.y);
        c.index = it->second;
        consider(best, c);
      }
      for(int k = 0; k < 3; ++k) {
        const Index corner = he_source(3 * g + k);
        if(mask == 0 && corner == zv)
          continue;
        const Point_2_ft<FT> p = point_in_halfedge_frame(g, bq, k);
        Candidate c;
        c.kind = Candidate::CORNER;
        c.value = vs_[std::size_t(corner)].dist + length_2(p.x, p.y);
        c.index = corner;
        consider(best, c);
      }
      if(best.kind == Candidate::FACE_SOURCE) {
        const Face_source& fs = face_sources_[std::size_t(best.index)];
        emit(face_node(fs.face, fs.barycentric));
        return false;
      }
      go_to_vertex(w, best.index, emit);
      return true;
    }
    // the DAG allows only the edges the segments from this edge cross (else the corner between them)
    if(exit_he >= 0 && !((exit_he == Mesh::next(tw) ? 1 : 2) & mask)) {
      go_to_vertex(w, zv, emit);
      return true;
    }
    if(exit_he < 0 || !(mu < FT(1))) {
      go_to_vertex(w, exit_he < 0 ? zv : he_target(exit_he), emit);
      return true;
    }
    if(!(mu > FT(0))) {
      go_to_vertex(w, he_source(exit_he), emit);
      return true;
    }
    emit(edge_node(exit_he, mu));
    w.halfedge = exit_he;
    w.t = mu * he_[std::size_t(exit_he)].length;
    return true;
  }

  // ------------------------------------------------------------------------------------------------
  // Data

  const Mesh& mesh_;
  FT unreached_;
  FT epsilon_;
  FT improvement_; // a lowering must beat the current distance by this relative amount (rounding)
  Queue_key queue_key_ = Queue_key::candidate;
  bool vertex_windows_ = true; // windows rooted at saddle and reflex boundary vertices

  // per vertex
  // the hot per-vertex data, together: the distance, the offset of the vertex's window (the distance of its
  // root), the nearest source, the root vertex of the window (-1: a source)
  struct Vertex_state
  {
    FT dist;
    FT offset;
    Index source;
    Index root;
  };
  std::vector<Vertex_state> vs_;
  std::vector<Index> parent_he_;            // see Parent_kind
  std::vector<unsigned char> parent_kind_;
  std::vector<char> vertex_is_pseudo_source_; // saddle or boundary vertex
  std::vector<std::uint32_t> first_reached_, last_lowered_; // lowering times (clock_)
  std::uint32_t clock_ = 0;
  std::vector<Index> child_next_, child_prev_; // the list of the vertices updated from the same edge
  std::vector<Index> vedge_begin_;
  std::vector<Incident_edge> vedge_;        // the edges around each vertex
  std::vector<Halfedge_data> he_;
  // per edge
  std::vector<Index> child_head_;           // first vertex updated from the edge
  // side links, built with the first path query (mutable: a cache)
  mutable std::vector<Index> side_he_;      // the halfedge of the edge in the face of its side links, -1: none
  mutable std::vector<unsigned char> side_mask_; // its side parents: bit 0 the edge of next(side_he_), bit 1 prev
  std::vector<Index> heap_position_;        // the edge's position in heap_, -1: not queued
  std::vector<Pseudo_source> edge_function_; // the distance function of a queued edge (canonical frame)
  // searches
  std::vector<std::uint32_t> visit_vertex_;
  std::vector<Index> stack_, starts_, touched_;
  std::uint32_t search_stamp_ = 0;
  bool recording_touched_ = false;

  std::vector<Heap_entry> heap_;
  std::size_t peak_heap_ = 0;
  std::vector<Vertex_source> vertex_sources_;
  std::vector<Face_source> face_sources_;
  std::vector<std::pair<Index, Index>> face_source_index_; // (face, face source), sorted

  std::vector<Index> stop_targets_;
  FT limit_ = FT(0);
  bool has_limit_ = false;
  FT front_ = FT(0);
  FT bound_ = FT(0);
  bool stopped_early_ = false;
  Geodesic_statistics stats_;
  mutable Counters counters_;
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_FLAT_EXACT_PROPAGATION_H
