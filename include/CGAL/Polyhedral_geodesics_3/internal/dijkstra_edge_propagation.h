// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The baseline engines that only know distances at vertices (Dijkstra on the mesh edges here, fast
// marching in fast_marching_propagation.h) share Vertex_front_propagation_base: per-vertex distance,
// nearest source and predecessor arrays, a binary heap with lazy deletion, sources at vertices and at
// surface points, the distance limit and the stop targets, and the tracing of a path along the
// predecessor chain. Dijkstra_edge_propagation is the engine of Dijkstra_geodesic_distances_3.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_DIJKSTRA_EDGE_PROPAGATION_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_DIJKSTRA_EDGE_PROPAGATION_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_types.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>
#include <CGAL/Polyhedral_geodesics_3/internal/geodesic_engine_types.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

// The common part of the engines that propagate a front of vertices (the engine concept is documented in
// Geodesic_distances_facade.h). A derived engine implements run() with begin_run(), pop(), make_final(),
// lower() and finish_run(), and distance_at() with the helpers below; trace_path() is shared.
//
// Predecessors: pred_[v] >= 0 is the vertex v was last lowered from, -1 means "none" (a vertex source, or
// unreached), pred_[v] <= -2 means that v was reached straight from the surface-point source number
// -pred_[v] - 2 (inside a face that contains both). A predecessor is always final before v is lowered from
// it, so the chain follows the order in which vertices became final and ends at a source.
template <class FT>
class Vertex_front_propagation_base
{
public:
  typedef Geodesic_mesh<FT> Mesh;
  typedef typename Mesh::Index Index;
  typedef Geodesic_path_node<FT> Path_node;
  typedef Geodesic_point_distance<FT> Point_distance;

  explicit Vertex_front_propagation_base(const Mesh& mesh) : mesh_(mesh)
  {
    // the sentinel of "no distance yet": large, but far from overflowing when a few lengths are added
    unreached_ = FT(std::numeric_limits<double>::max() / 16);
    clear();
  }

  void clear()
  {
    const std::size_t nv = mesh_.number_of_vertices;
    dist_.assign(nv, unreached_);
    source_.assign(nv, -1);
    pred_.assign(nv, -1);
    final_.assign(nv, 0);
    heap_.clear();
    face_sources_.clear();
    incarnations_.clear();
    stats_ = Geodesic_statistics();
    stopped_early_ = false;
    final_count_ = 0;
    bound_ = unreached_;
  }

  // no windows here: nothing to keep
  void set_keep_windows(bool) {}
  void set_distance_limit(FT limit)
  {
    limit_ = limit;
    has_limit_ = true;
  }
  void clear_distance_limit() { has_limit_ = false; }
  void set_stop_targets(const std::vector<Index>& targets) { stop_targets_ = targets; }

  void add_vertex_source(Index v, Index id)
  {
    if(v < 0 || std::size_t(v) >= mesh_.number_of_vertices)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: source vertex not in the mesh");
    lower(v, FT(0), id, -1);
  }

  // A point of face f (barycentric b): its corners (and, for a point on an edge, the opposite corner of the
  // face on the other side) get their straight distance to the point, inside a face that contains both.
  void add_face_source(Index f, const std::array<FT, 3>& b, Index id)
  {
    if(f < 0 || std::size_t(f) >= mesh_.number_of_faces)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: source face not in the mesh");
    int zeros = 0, nonzero = 0;
    for(int k = 0; k < 3; ++k) {
      if(b[std::size_t(k)] == FT(0))
        ++zeros;
      else
        nonzero = k;
    }
    if(zeros >= 2)
      return add_vertex_source(mesh_.source(3 * f + nonzero), id);
    Face_source s;
    s.face = f;
    s.barycentric = b;
    s.point = point_in_face(f, b);
    s.id = id;
    s.halfedge = zeros == 1 ? halfedge_of_edge_point(f, b) : Index(-1);
    const Index k = Index(face_sources_.size());
    face_sources_.push_back(s);
    incarnations_.push_back({f, k});
    if(s.halfedge >= 0)
      mesh_.for_each_other_halfedge(s.halfedge, [&](Index tw) { incarnations_.push_back({Mesh::face_of(tw), k}); });
    for_each_face_of_source(k, [&](Index g) {
      for(int c = 0; c < 3; ++c) {
        const Index u = mesh_.source(3 * g + c);
        lower(u, euclidean(s.point, mesh_.points[std::size_t(u)]), id, -2 - k);
      }
    });
  }

  FT vertex_distance(Index v) const
  {
    return dist_[std::size_t(v)] >= unreached_ ? infinity() : dist_[std::size_t(v)];
  }

  Index vertex_source(Index v) const { return dist_[std::size_t(v)] >= unreached_ ? Index(-1) : source_[std::size_t(v)]; }

  const Geodesic_statistics& statistics() const { return stats_; }

protected:
  struct Face_source
  {
    Index face;
    std::array<FT, 3> barycentric;
    std::array<FT, 3> point;
    Index id;
    Index halfedge; // the halfedge of face whose edge carries the point, -1 if the point is inside the face
  };

  struct Heap_entry
  {
    FT key;
    Index vertex;
  };
  struct Heap_order
  {
    bool operator()(const Heap_entry& a, const Heap_entry& b) const { return b.key < a.key; }
  };

  // The best way to reach a surface point: from a final vertex (`vertex` >= 0) or straight from a
  // surface-point source (`face_source` >= 0).
  struct Candidate
  {
    FT value = FT(0);
    Index vertex = -1;
    Index face_source = -1;
  };

  static FT infinity() { return FT(std::numeric_limits<double>::infinity()); }

  static FT euclidean(const std::array<FT, 3>& a, const std::array<FT, 3>& b)
  {
    using std::sqrt;
    return sqrt(squared_distance_3(a, b));
  }

  std::array<FT, 3> point_in_face(Index f, const std::array<FT, 3>& b) const { return internal::point_in_face(mesh_, f, b); }

  // b has exactly one zero coordinate: the halfedge of f between the two other corners
  static Index halfedge_of_edge_point(Index f, const std::array<FT, 3>& b)
  {
    int z = 0;
    while(b[std::size_t(z)] != FT(0))
      ++z;
    return 3 * f + (z + 1) % 3;
  }

  // Calls f(g) for the faces that contain the surface-point source k: its face, and for a point on an edge the
  // faces of the other halfedges of that edge.
  template <class F>
  void for_each_face_of_source(Index k, F f) const
  {
    const Face_source& s = face_sources_[std::size_t(k)];
    f(s.face);
    if(s.halfedge >= 0)
      mesh_.for_each_other_halfedge(s.halfedge, [&](Index tw) { f(Mesh::face_of(tw)); });
  }

  // ------------------------------------------------------------------------------------------------
  // The front

  // Lowers the tentative distance of a non-final vertex.
  bool lower(Index v, const FT& d, Index source, Index pred)
  {
    const std::size_t i = std::size_t(v);
    if(final_[i] || !(d < dist_[i]))
      return false;
    dist_[i] = d;
    source_[i] = source;
    pred_[i] = pred;
    ++stats_.vertex_updates;
    heap_.push_back(Heap_entry{d, v});
    std::push_heap(heap_.begin(), heap_.end(), Heap_order());
    return true;
  }

  void begin_run()
  {
    std::sort(incarnations_.begin(), incarnations_.end());
    target_mark_.assign(mesh_.number_of_vertices, 0);
    remaining_targets_ = 0;
    for(Index t : stop_targets_)
      if(t >= 0 && std::size_t(t) < mesh_.number_of_vertices && !target_mark_[std::size_t(t)]) {
        target_mark_[std::size_t(t)] = 1;
        ++remaining_targets_;
      }
    bound_ = has_limit_ ? limit_ : unreached_;
  }

  // The next vertex to become final and its distance (skipping stale heap entries); false when the heap is
  // empty. Stops (returns false, stopped_early) at the distance limit.
  bool pop(Index& v, FT& key)
  {
    while(!heap_.empty()) {
      std::pop_heap(heap_.begin(), heap_.end(), Heap_order());
      const Heap_entry top = heap_.back();
      heap_.pop_back();
      const std::size_t i = std::size_t(top.vertex);
      if(final_[i] || top.key != dist_[i])
        continue;
      if(has_limit_ && limit_ < top.key) {
        stopped_early_ = true;
        return false;
      }
      v = top.vertex;
      key = top.key;
      return true;
    }
    return false;
  }

  // Marks v final; returns true when the propagation should stop because every stop target is final.
  bool make_final(Index v, const FT& key)
  {
    final_[std::size_t(v)] = 1;
    ++final_count_;
    if(remaining_targets_ > 0 && target_mark_[std::size_t(v)] && --remaining_targets_ == 0) {
      // Everything still in the heap is at least `key`: a point value up to `key` is final.
      stopped_early_ = true;
      if(key < bound_)
        bound_ = key;
      return true;
    }
    return false;
  }

  // Vertices that are not final report +infinity; frees the heap. `extra_bytes`: the engine's own arrays.
  void finish_run(std::size_t extra_bytes)
  {
    const std::size_t nv = mesh_.number_of_vertices;
    std::size_t bytes = extra_bytes + heap_.capacity() * sizeof(Heap_entry) +
                        nv * (2 * sizeof(FT) + 2 * sizeof(Index) + 2) + neighbour_begin_.capacity() * sizeof(Index) +
                        neighbours_.capacity() * sizeof(Neighbour);
    if(bytes > stats_.peak_memory_bytes)
      stats_.peak_memory_bytes = bytes;
    for(std::size_t v = 0; v < nv; ++v)
      if(!final_[v]) {
        dist_[v] = unreached_;
        source_[v] = -1;
        pred_[v] = -1;
      }
    std::vector<Heap_entry>().swap(heap_);
    std::vector<char>().swap(target_mark_);
    stats_.stopped_early = stopped_early_;
  }

  bool is_final(Index v) const { return final_[std::size_t(v)] != 0; }

  // A value that may be reported: below the limit and, after a stop at the targets, below the front.
  bool valid_answer(const FT& value) const { return value < unreached_ && !(bound_ < value); }

  // The surface-point sources in the faces that contain the point (f, b): straight segments.
  void face_source_candidates(Index f, const std::array<FT, 3>& b, const std::array<FT, 3>& p, Candidate& best) const
  {
    if(incarnations_.empty())
      return;
    int zeros = 0;
    for(int k = 0; k < 3; ++k)
      if(b[std::size_t(k)] == FT(0))
        ++zeros;
    auto in_face = [&](Index g) {
      auto it = std::lower_bound(incarnations_.begin(), incarnations_.end(), std::pair<Index, Index>(g, Index(-1)));
      for(; it != incarnations_.end() && it->first == g; ++it) {
        const FT d = euclidean(p, face_sources_[std::size_t(it->second)].point);
        if(best.vertex < 0 && best.face_source < 0 ? true : d < best.value) {
          best.value = d;
          best.vertex = -1;
          best.face_source = it->second;
        }
      }
    };
    in_face(f);
    if(zeros == 1) // a point on an edge: also in the faces of the edge's other halfedges
      mesh_.for_each_other_halfedge(halfedge_of_edge_point(f, b), in_face);
  }

  // Final corners of f: d(v) + |p - v|.
  void corner_candidates(Index f, const std::array<FT, 3>& p, Candidate& best) const
  {
    for(int k = 0; k < 3; ++k) {
      const Index v = mesh_.source(3 * f + k);
      if(!final_[std::size_t(v)])
        continue;
      const FT d = dist_[std::size_t(v)] + euclidean(p, mesh_.points[std::size_t(v)]);
      if(best.vertex < 0 && best.face_source < 0 ? true : d < best.value) {
        best.value = d;
        best.vertex = v;
        best.face_source = -1;
      }
    }
  }

  Index candidate_source(const Candidate& c) const
  {
    if(c.face_source >= 0)
      return face_sources_[std::size_t(c.face_source)].id;
    return c.vertex >= 0 ? source_[std::size_t(c.vertex)] : Index(-1);
  }

  // The query point, the first vertex (or the surface-point source) from `first`, then the predecessor chain.
  template <class Emit>
  void trace_from(Index f, const std::array<FT, 3>& b, const Candidate& first, Emit& emit) const
  {
    const Index at_vertex = emit_query_node(f, b, emit);
    if(first.face_source >= 0) {
      if(first.value > FT(0)) // else the query point is the source
        emit(source_node(first.face_source));
      return;
    }
    if(first.vertex != at_vertex)
      emit(vertex_node(first.vertex));
    emit_predecessor_chain(first.vertex, emit);
  }

  // The node of the query point (f, b): a vertex, an edge point or a face point. Returns the vertex, or -1.
  template <class Emit>
  Index emit_query_node(Index f, const std::array<FT, 3>& b, Emit& emit) const
  {
    int zeros = 0, nonzero = 0;
    for(int k = 0; k < 3; ++k) {
      if(b[std::size_t(k)] == FT(0))
        ++zeros;
      else
        nonzero = k;
    }
    if(zeros >= 2) {
      const Index v = mesh_.source(3 * f + nonzero);
      emit(vertex_node(v));
      return v;
    }
    if(zeros == 1) {
      const Index g = halfedge_of_edge_point(f, b);
      emit(edge_node(g, b[std::size_t(Mesh::next(g) % 3)]));
    } else
      emit(face_node(f, b));
    return -1;
  }

  // The vertices after the final vertex v (already emitted) on its predecessor chain, down to a vertex source or
  // a surface-point source.
  template <class Emit>
  void emit_predecessor_chain(Index v, Emit& emit) const
  {
    for(std::size_t step = 0; step <= mesh_.number_of_vertices; ++step) {
      const Index p = pred_[std::size_t(v)];
      if(p == -1)
        return; // a vertex source
      if(p <= -2) {
        emit(source_node(-2 - p));
        return;
      }
      v = p;
      emit(vertex_node(v));
    }
    throw std::runtime_error("CGAL::Polyhedral_geodesics_3: the predecessor chain does not reach a source");
  }

  Path_node vertex_node(Index v) const { return vertex_path_node(mesh_, v); }

  Path_node edge_node(Index g, const FT& r) const { return edge_path_node(mesh_, g, r); }

  Path_node face_node(Index f, const std::array<FT, 3>& b) const { return face_path_node(mesh_, f, b); }

  // the surface-point source k: a FACE node, or an EDGE node for a point on an edge
  Path_node source_node(Index k) const
  {
    const Face_source& s = face_sources_[std::size_t(k)];
    if(s.halfedge < 0)
      return face_node(s.face, s.barycentric);
    Path_node n = edge_node(s.halfedge, s.barycentric[std::size_t(Mesh::next(s.halfedge) % 3)]);
    n.point = s.point;
    return n;
  }

  // ------------------------------------------------------------------------------------------------
  // Vertex neighbours (compressed rows): every edge once in each direction (built by the engines that use them).
  // A halfedge gives its own direction, and a border halfedge the other one too; an edge of three or more faces,
  // or a reversed one, gives both directions once, at its canonical halfedge.

  struct Neighbour
  {
    Index vertex;
    FT length;
  };

  void build_neighbours()
  {
    const std::size_t nv = mesh_.number_of_vertices, nh = 3 * mesh_.number_of_faces;
    neighbour_begin_.assign(nv + 1, 0);
    // 0: nothing, 1: source -> target, 2: both directions
    auto directions = [&](std::size_t h) -> int {
      const Geodesic_halfedge<FT>& r = mesh_.he[h];
      if(r.twin >= 0)
        return 1;
      if(r.radial == Index(h))
        return 2;
      return mesh_.edge_halfedge[std::size_t(r.edge)] == Index(h) ? 2 : 0;
    };
    for(std::size_t h = 0; h < nh; ++h) {
      const int d = directions(h);
      if(d >= 1)
        ++neighbour_begin_[std::size_t(mesh_.he[h].source) + 1];
      if(d == 2)
        ++neighbour_begin_[std::size_t(mesh_.target(Index(h))) + 1];
    }
    for(std::size_t v = 0; v < nv; ++v)
      neighbour_begin_[v + 1] += neighbour_begin_[v];
    neighbours_.assign(std::size_t(neighbour_begin_[nv]), Neighbour{-1, FT(0)});
    std::vector<Index> fill(neighbour_begin_.begin(), neighbour_begin_.end() - 1);
    for(std::size_t h = 0; h < nh; ++h) {
      const int d = directions(h);
      const Index a = mesh_.source(Index(h)), c = mesh_.target(Index(h));
      if(d >= 1)
        neighbours_[std::size_t(fill[std::size_t(a)]++)] = Neighbour{c, mesh_.he[h].length};
      if(d == 2)
        neighbours_[std::size_t(fill[std::size_t(c)]++)] = Neighbour{a, mesh_.he[h].length};
    }
  }

  const Mesh& mesh_;
  FT unreached_;
  std::vector<Index> neighbour_begin_;
  std::vector<Neighbour> neighbours_;

  std::vector<FT> dist_;
  std::vector<Index> source_;
  std::vector<Index> pred_;
  std::vector<char> final_;
  std::vector<Heap_entry> heap_;
  std::vector<Face_source> face_sources_;
  std::vector<std::pair<Index, Index>> incarnations_; // (face, surface-point source), sorted in begin_run()

  std::vector<Index> stop_targets_;
  std::vector<char> target_mark_;
  std::size_t remaining_targets_ = 0;
  FT limit_ = FT(0);
  bool has_limit_ = false;
  bool stopped_early_ = false;
  FT bound_;
  std::size_t final_count_ = 0;
  Geodesic_statistics stats_;
};

// Dijkstra's algorithm on the graph of the mesh edges, weighted by their lengths: the length of the shortest
// path along edges, an upper bound of the geodesic distance (exact only where a shortest path follows edges).
template <class FT>
class Dijkstra_edge_propagation : public Vertex_front_propagation_base<FT>
{
  typedef Vertex_front_propagation_base<FT> Base;

public:
  typedef typename Base::Mesh Mesh;
  typedef typename Base::Index Index;
  typedef typename Base::Point_distance Point_distance;
  typedef typename Base::Path_node Path_node;

  explicit Dijkstra_edge_propagation(const Mesh& mesh) : Base(mesh) { this->build_neighbours(); }

  template <class Progress>
  void run(Progress& progress)
  {
    CGAL::MDCS::internal::Progress_reporter<Progress> report(progress, "dijkstra", this->mesh_.number_of_vertices);
    this->begin_run();
    Index v = -1;
    FT key = FT(0);
    while(this->pop(v, key)) {
      if(this->make_final(v, key))
        break;
      report(this->final_count_);
      const Index src = this->source_[std::size_t(v)];
      const Index end = this->neighbour_begin_[std::size_t(v) + 1];
      for(Index k = this->neighbour_begin_[std::size_t(v)]; k < end; ++k) {
        const typename Base::Neighbour& n = this->neighbours_[std::size_t(k)];
        this->lower(n.vertex, key + n.length, src, v);
      }
    }
    this->finish_run(0);
    report.finish();
  }

  // min over the final corners v of f of d(v) + |p - v|, and the straight distance to a surface-point
  // source in a face that contains p
  Point_distance distance_at(Index f, const std::array<FT, 3>& b) const
  {
    const typename Base::Candidate c = best(f, b);
    if(c.vertex < 0 && c.face_source < 0)
      return {Base::infinity(), -1};
    return {c.value, this->candidate_source(c)};
  }

  // The query point, then the vertices of the shortest edge path down to the source (the last node is the
  // source vertex, or the surface-point source). Its length is the distance.
  template <class Emit>
  void trace_path(Index f, const std::array<FT, 3>& b, Emit emit) const
  {
    const typename Base::Candidate c = best(f, b);
    if(c.vertex < 0 && c.face_source < 0)
      return;
    this->trace_from(f, b, c, emit);
  }

private:
  typename Base::Candidate best(Index f, const std::array<FT, 3>& b) const
  {
    typename Base::Candidate c;
    const std::array<FT, 3> p = this->point_in_face(f, b);
    this->corner_candidates(f, p, c);
    this->face_source_candidates(f, b, p, c);
    if((c.vertex >= 0 || c.face_source >= 0) && !this->valid_answer(c.value))
      return typename Base::Candidate();
    return c;
  }
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_DIJKSTRA_EDGE_PROPAGATION_H
