// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shortest paths and point queries of the vertex-oriented schedule (vertex_oriented_propagation.h), from what a
// full-field run keeps: every vertex's distance, nearest source and Parent (how it got its distance), 32 bytes
// per vertex with double, instead of the windows of every edge (which grow as n^1.45).
//
// Paths to vertices. A Parent says: straight from the vertex to a point of a halfedge's edge, then straight to a
// pseudo-source (a saddle or boundary vertex, a source vertex, or a point source) at a known place in that
// halfedge's frame. The path is traced by walking that straight line across the faces, unfolding one face at a
// time, until it reaches the pseudo-source; there the pseudo-source's own Parent takes over, down to a source.
// Where rounding brings the line within 1e-12 (relative) of a vertex that is not its end, the walk goes through
// that vertex and goes on with the vertex's own Parent: the path then has the length of the straight one up to
// that rounding, since the vertex's distance is exact.
//
// Point queries. The distance at a point p inside a face is min over vertices and point sources v of
// (geodesic distance from p to v) + d(v), and the minimum is reached at the first vertex of p's shortest path
// (or at its source point). A second propagation from p finds it (Backward_query): exact like the first one,
// but every window part where a lower bound of that sum exceeds the best sum found so far is trimmed, with the
// forward distances of the edge's ends as the lower bound of d. What remains is a band around p's shortest
// path, not the whole mesh. The path to p is that propagation's path from the best vertex back to p, reversed,
// followed by the best vertex's own path.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_PATHS_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_PATHS_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>
#include <CGAL/Polyhedral_geodesics_3/internal/geodesic_engine_types.h>
#include <CGAL/Polyhedral_geodesics_3/internal/geodesic_window.h>
#include <CGAL/Polyhedral_geodesics_3/internal/vertex_oriented_propagation.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

template <class FT>
class Vertex_oriented_paths
{
public:
  typedef Geodesic_mesh<FT> Mesh;
  typedef typename Mesh::Index Index;
  typedef Vertex_oriented_window_propagation<FT> Engine;
  typedef typename Engine::Parent Parent;
  typedef Geodesic_path_node<FT> Path_node;
  typedef Geodesic_point_distance<FT> Point_distance;

  explicit Vertex_oriented_paths(const Mesh& mesh) : mesh_(mesh) {}

  // Forgets the last point query (the forward run changed).
  void invalidate()
  {
    query_valid_ = false;
    query_windows_ = 0;
  }

  // Windows created by the point queries since the last invalidate(): what point queries have cost so far.
  std::size_t query_windows_since_run() const { return query_windows_; }
  // Whether the last point query was at (f, b) (its answer is kept).
  bool has_query_at(Index f, const std::array<FT, 3>& b) const
  {
    return query_valid_ && query_.face == f && query_.barycentric == b;
  }

  Point_distance distance_at(const Engine& forward, Index f, const std::array<FT, 3>& b)
  {
    const Index v = vertex_at(f, b);
    if(v >= 0) {
      const FT d = forward.vertex_distance(v);
      return {d, d < FT(std::numeric_limits<double>::infinity()) ? forward.vertex_source(v) : Index(-1)};
    }
    const Query& q = point_query(forward, f, b);
    if(!q.found)
      return {FT(std::numeric_limits<double>::infinity()), -1};
    return {q.distance, q.source};
  }

  // Emits the path from the point (f, b) to its nearest source: the point itself, every edge crossing and vertex,
  // the source. Emits nothing if the point is unreachable.
  template <class Emit>
  void trace_path(const Engine& forward, Index f, const std::array<FT, 3>& b, Emit emit)
  {
    const Index v = vertex_at(f, b);
    if(v >= 0) {
      if(!(forward.raw_distance(v) < forward.unreached()))
        return;
      emit(vertex_path_node(mesh_, v));
      walk_chain(forward, v, emit);
      return;
    }
    const Query& q = point_query(forward, f, b);
    if(!q.found)
      return;
    std::vector<Path_node> head; // from the end of the first part back to p, reversed below
    if(q.same_face_source >= 0) {
      head.push_back(face_node_of_source(forward, q.same_face_source));
      head.push_back(face_path_node(mesh_, f, b)); // p, straight from the source in the same face
    } else if(q.via_vertex >= 0) {
      head.push_back(vertex_path_node(mesh_, q.via_vertex));
#ifdef EXFF_DEBUG
      std::fprintf(stderr, "backward chain from %d\n", q.via_vertex);
#endif
      walk_chain(*backward_, q.via_vertex, [&](const Path_node& n) { head.push_back(n); });
    } else {
      // a forward point source reached by a window of the backward run: from it to the window's crossing, then
      // straight to p
      head.push_back(face_node_of_source(forward, q.via_face_source));
      const Index g = q.halfedge;
      const FT L = mesh_.he[std::size_t(g)].length;
      const FT x = q.window.b0;
      if(!(x > tolerance(L)) || !(x < L - tolerance(L))) {
        const Index u = !(x > tolerance(L)) ? mesh_.source(g) : mesh_.target(g);
        head.push_back(vertex_path_node(mesh_, u));
        walk_chain(*backward_, u, [&](const Path_node& n) { head.push_back(n); });
      } else {
        head.push_back(edge_path_node(mesh_, g, FT(x / L)));
        // the window's pseudo-source is p, or a saddle or boundary vertex of the backward run (then its chain
        // goes on to p), or a vertex the line passes within rounding of
        const Index u = walk_segment(*backward_, g, x, q.window.sx, q.window.sy, q.window.root,
                                     [&](const Path_node& n) { head.push_back(n); });
        if(u >= 0)
          walk_chain(*backward_, u, [&](const Path_node& n) { head.push_back(n); });
      }
    }
    // head ends at p (a face node of the backward run's source face): report the caller's location instead
    head.back() = face_path_node(mesh_, f, b);
    for(auto it = head.rbegin(); it != head.rend(); ++it)
      emit(*it);
    if(q.via_vertex >= 0)
      walk_chain(forward, q.via_vertex, emit);
  }

  // Statistics of the last point query's propagation (for tests and benchmarks).
  const Geodesic_statistics* last_query_statistics() const { return backward_ ? &backward_->statistics() : nullptr; }

private:
  struct Query
  {
    Index face = -1;
    std::array<FT, 3> barycentric;
    bool found = false;
    FT distance;
    Index source = -1;
    Index same_face_source = -1; // a forward point source in p's face, reached straight
    Index via_vertex = -1;       // or the first vertex of p's path
    Index via_face_source = -1;  // or a forward point source reached through a window
    Index halfedge = -1;
    typename Engine::Window window;
  };

  Index vertex_at(Index f, const std::array<FT, 3>& b) const
  {
    int zeros = 0, nonzero = -1;
    for(int k = 0; k < 3; ++k) {
      if(b[std::size_t(k)] == FT(0)) ++zeros;
      else nonzero = k;
    }
    return zeros >= 2 && nonzero >= 0 ? mesh_.source(3 * f + nonzero) : Index(-1);
  }

  static FT tolerance(const FT& length) { return FT(1e-12) * length; }

  Path_node face_node_of_source(const Engine& e, Index k) const
  {
    const auto& s = e.face_sources()[std::size_t(k)];
    return face_path_node(mesh_, s.face, s.barycentric);
  }

  // The point query at (f, b), computed once per point (a path after a distance query reuses it).
  const Query& point_query(const Engine& forward, Index f, const std::array<FT, 3>& b)
  {
    if(has_query_at(f, b))
      return query_;
    query_ = Query();
    query_.face = f;
    query_.barycentric = b;
    if(!backward_) {
      backward_.reset(new Engine(mesh_));
      backward_->set_record_parents(true);
      backward_->set_reuse_between_runs(true); // each query reaches a band of the mesh: reset only that
    }
    typename Engine::Backward_query bq;
    bq.forward = &forward;
    bq.best = forward.unreached();
    backward_->clear();
    backward_->set_backward_query(&bq);
    backward_->add_face_source(f, b, 0);
    // Forward point sources in a face of p: straight inside that face.
    for(const auto& inc : backward_->face_sources())
      for(std::size_t k = 0; k < forward.face_sources().size(); ++k) {
        const auto& s = forward.face_sources()[k];
        if(s.face != inc.face)
          continue;
        const FT d = distance_in_face(inc.face, inc.barycentric, s.barycentric);
        if(d < bq.best) {
          bq.best = d;
          bq.best_vertex = -1;
          bq.best_face_source = -1;
          query_.same_face_source = Index(k);
        }
      }
    MDCS::No_progress quiet;
    backward_->run(quiet);
    backward_->set_backward_query(nullptr);
    query_windows_ += backward_->statistics().windows_created;
    query_valid_ = true;
    if(!(bq.best < forward.unreached()) || bq.best > forward.final_bound())
      return query_;
    query_.found = true;
    query_.distance = bq.best;
    if(bq.best_vertex >= 0) {
      query_.same_face_source = -1;
      query_.via_vertex = bq.best_vertex;
      query_.source = forward.vertex_source(bq.best_vertex);
    } else if(bq.best_face_source >= 0) {
      query_.same_face_source = -1;
      query_.via_face_source = bq.best_face_source;
      query_.halfedge = bq.best_halfedge;
      query_.window = bq.best_window;
      query_.source = forward.face_sources()[std::size_t(bq.best_face_source)].id;
    } else {
      query_.source = forward.face_sources()[std::size_t(query_.same_face_source)].id;
    }
    return query_;
  }

  FT distance_in_face(Index f, const std::array<FT, 3>& a, const std::array<FT, 3>& b) const
  {
    const Index g = 3 * f;
    const FT L = mesh_.he[std::size_t(g)].length;
    const Point_2_ft<FT>& c = mesh_.he[std::size_t(g)].opposite;
    return distance_2(FT(a[1] * L + a[2] * c.x), FT(a[2] * c.y), FT(b[1] * L + b[2] * c.x), FT(b[2] * c.y));
  }

  // Emits the nodes after vertex v along the Parents of `e`, down to a source (a vertex source, or a point source,
  // whose face node is the last one).
  template <class Emit>
  void walk_chain(const Engine& e, Index v, Emit&& emit) const
  {
    const std::size_t max_steps = 8 * mesh_.number_of_faces + 64;
    for(std::size_t step = 0; step < max_steps; ++step) {
      if(e.is_source_vertex(v) && e.raw_distance(v) == FT(0))
        return;
      const Parent& p = e.parent(v);
      if(p.halfedge < 0) {
        if(p.root == v || p.root < 0)
          return; // a source
        v = p.root; // along an edge of the pseudo-source
        emit(vertex_path_node(mesh_, v));
        continue;
      }
      const Index g = p.halfedge;
#ifdef EXFF_DEBUG
      std::fprintf(stderr, "v %d parent g %d (%d %d opp %d) root %d s=(%g,%g) at %g L %g\n", v, g, g < 0 ? -1 : mesh_.source(g), g < 0 ? -1 : mesh_.target(g), g < 0 ? -1 : mesh_.opposite_vertex(g), p.root, p.sx, p.sy, p.at, g < 0 ? 0.0 : mesh_.he[g].length);
#endif
      if(!(p.sy < FT(0))) {
        // the root is a point source inside g's own face, seen straight
        if(p.root >= 0)
          throw std::runtime_error("CGAL::Polyhedral_geodesics_3: inconsistent path record");
        emit(face_node_of_source(e, -1 - p.root));
        return;
      }
      const FT L = mesh_.he[std::size_t(g)].length;
      const Index a = mesh_.source(g), b = mesh_.target(g);
      FT x = p.at;
      if(v != a && v != b) {
        // from the opposite vertex to the point `at` of g's edge; at an end, that end takes over
        if(!(x > tolerance(L)) || !(x < L - tolerance(L))) {
          v = !(x > tolerance(L)) ? a : b;
          emit(vertex_path_node(mesh_, v));
          continue;
        }
        emit(edge_path_node(mesh_, g, FT(x / L)));
      } else {
        x = v == a ? FT(0) : L;
      }
      const Index next = walk_segment(e, g, x, p.sx, p.sy, p.root, emit);
      if(next < 0)
        return; // reached a point source
      v = next;
    }
    throw std::runtime_error("CGAL::Polyhedral_geodesics_3: shortest path tracing did not reach a source");
  }

  // Walks the straight line from the point x of halfedge h's edge (in h's frame) to the point (tx, ty) of h's frame,
  // below the edge, across the faces beyond h, emitting every edge crossing and the vertex where it ends: the root
  // (returned), or a vertex the line passes within rounding of (returned, the caller goes on from it). Returns -1
  // after emitting the face node of a root that is a point source.
  template <class Emit>
  Index walk_segment(const Engine& e, Index h, FT x, FT tx, FT ty, Index root, Emit&& emit) const
  {
    const std::size_t max_steps = 4 * mesh_.number_of_faces + 64;
    for(std::size_t step = 0; step < max_steps; ++step) {
      FT L = mesh_.he[std::size_t(h)].length;
      Index t = mesh_.he[std::size_t(h)].twin;
      if(t < 0) {
        // rounding took the line out of the mesh at a boundary edge: its nearer end
        const Index u = x < L - x ? mesh_.source(h) : mesh_.target(h);
        emit(vertex_path_node(mesh_, u));
        return u;
      }
      // into t's frame (the mirror image): the face of t is above, the target beyond or inside it
      FT px = L - x;
      {
        const FT qx = L - tx, qy = -ty;
        tx = qx;
        ty = qy;
      }
      const bool at_a = !(px > tolerance(L)), at_b = !(px < L - tolerance(L));
      if(at_a || at_b) {
        // From a vertex: the line need not enter this face (a window ends at the vertex when its rays pass through
        // the vertex from another side); turn around the vertex, unfolding the target, to the face it enters.
        rotate_around_corner(t, at_a, tx, ty);
        L = mesh_.he[std::size_t(t)].length;
        px = at_a ? FT(0) : L;
      }
      const Index f = Mesh::face_of(t);
      const Point_2_ft<FT>& c = mesh_.he[std::size_t(t)].opposite;
      const Index va = mesh_.source(t), vb = mesh_.target(t), vc = mesh_.opposite_vertex(t);
      const FT scale = L + distance_2(px, FT(0), tx, ty);
      const FT arrive = FT(1e-9) * scale;
      if(root < 0) {
        const auto& s = e.face_sources()[std::size_t(-1 - root)];
        if(s.face == f) {
          emit(face_node_of_source(e, -1 - root));
          return -1;
        }
      } else {
        if(root == vc && distance_2(c.x, c.y, tx, ty) <= arrive) { emit(vertex_path_node(mesh_, vc)); return vc; }
        if(root == va && !at_a && distance_2(FT(0), FT(0), tx, ty) <= arrive) { emit(vertex_path_node(mesh_, va)); return va; }
        if(root == vb && !at_b && distance_2(L, FT(0), tx, ty) <= arrive) { emit(vertex_path_node(mesh_, vb)); return vb; }
      }
      // Which of the two other edges the line leaves through: B-C (halfedge next(t)) if C is on its left, else
      // C-A (prev(t)). From a corner, the opposite edge.
      const FT dx = tx - px, dy = ty;
      const FT side = dx * c.y - dy * (c.x - px); // > 0: C on the left of the line
      const FT dlen = distance_2(FT(0), FT(0), dx, dy), clen = distance_2(px, FT(0), c.x, c.y);
      if(!at_a && !at_b && abs_value(side) <= tolerance(FT(1)) * dlen * clen) {
        emit(vertex_path_node(mesh_, vc)); // the line passes through C (within rounding)
        return vc;
      }
      Index exit;
      if(at_b) exit = Mesh::prev(t);       // from B: through C-A
      else if(at_a) exit = Mesh::next(t);  // from A: through B-C
      else exit = side > FT(0) ? Mesh::next(t) : Mesh::prev(t);
      const FT ex_len = mesh_.he[std::size_t(exit)].length;
      if(!(ex_len > FT(0))) {
        const Index u = mesh_.source(exit);
        emit(vertex_path_node(mesh_, u));
        return u;
      }
      FT pex, pey, tex, tey;
      to_edge_frame(t, exit, px, FT(0), pex, pey);
      to_edge_frame(t, exit, tx, ty, tex, tey);
      FT xe;
      const FT den = pey - tey;
      if(den > FT(0))
        xe = pex + (tex - pex) * pey / den;
      else
        xe = tex; // the target is not beyond the exit edge (rounding): its foot
      if(!(xe > tolerance(ex_len)) || !(xe < ex_len - tolerance(ex_len))) {
        const Index u = !(xe > tolerance(ex_len)) ? mesh_.source(exit) : mesh_.target(exit);
        emit(vertex_path_node(mesh_, u));
        return u;
      }
      emit(edge_path_node(mesh_, exit, FT(xe / ex_len)));
      h = exit;
      x = xe;
      tx = tex;
      ty = tey;
    }
    throw std::runtime_error("CGAL::Polyhedral_geodesics_3: shortest path tracing did not reach the pseudo-source");
  }

  // The point (X, Y) of t's frame in the frame of `e`, one of the other halfedges of t's face: origin at source(e),
  // x axis along e, the face above.
  void to_edge_frame(Index t, Index e, const FT& X, const FT& Y, FT& X2, FT& Y2) const
  {
    const FT L = mesh_.he[std::size_t(t)].length;
    const Point_2_ft<FT>& c = mesh_.he[std::size_t(t)].opposite;
    const FT len = mesh_.he[std::size_t(e)].length;
    const bool is_next = e == Mesh::next(t); // B -> C, else C -> A
    const FT ox = is_next ? L : c.x, oy = is_next ? FT(0) : c.y;
    const FT ux = (is_next ? FT(c.x - L) : FT(-c.x)) / len, uy = (is_next ? c.y : FT(-c.y)) / len;
    const FT ddx = X - ox, ddy = Y - oy;
    X2 = ux * ddx + uy * ddy;
    Y2 = ux * ddy - uy * ddx;
  }

  // The line starts at corner A (source(t), at_a) or B (target(t)) of t's face towards (tx, ty). While the target
  // lies beyond the face's other edge at that corner, moves to the face across that edge (t becomes the halfedge of
  // that face with the same corner at the same place: A at the origin, or B at (length, 0)), target unfolded.
  void rotate_around_corner(Index& t, bool at_a, FT& tx, FT& ty) const
  {
    for(int turns = 0; turns < 1024; ++turns) {
      const FT L = mesh_.he[std::size_t(t)].length;
      const Point_2_ft<FT>& c = mesh_.he[std::size_t(t)].opposite;
      // the target beyond the edge A-C (left of A->C) or beyond B-C (right of B->C)
      const FT cross = at_a ? FT(c.x * ty - c.y * tx) : FT((c.x - L) * ty - c.y * (tx - L));
      const FT scale = distance_2(FT(0), FT(0), c.x, c.y) * distance_2(FT(0), FT(0), tx, ty) + L * L;
      if(at_a ? !(cross > tolerance(scale)) : !(cross < -tolerance(scale)))
        return;
      const Index e = at_a ? Mesh::prev(t) : Mesh::next(t);
      const Index tw = mesh_.he[std::size_t(e)].twin;
      const FT len = mesh_.he[std::size_t(e)].length;
      if(tw < 0 || !(len > FT(0)))
        return; // a boundary (or a zero-length edge): the walk leaves through the opposite edge, clamped
      FT ex, ey;
      to_edge_frame(t, e, tx, ty, ex, ey);
      tx = len - ex; // mirrored into tw's frame
      ty = -ey;
      t = tw;
    }
  }

  static FT abs_value(const FT& x) { return x < FT(0) ? -x : x; }

  const Mesh& mesh_;
  std::unique_ptr<Engine> backward_;
  Query query_;
  bool query_valid_ = false;
  std::size_t query_windows_ = 0;
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_PATHS_H
