// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shortest paths of the flat-exact approximation (thesis 4.3.2): the side links of the dependence DAG, built
// with the first path query from the final distances, the check that the whole DAG is acyclic, and the
// back-tracing along the DAG from a surface point to its source.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_FLAT_EXACT_PATHS_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_FLAT_EXACT_PATHS_H

#include <CGAL/Polyhedral_geodesics_3/internal/flat_exact_field.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

template <class FT>
class Flat_exact_paths : public Flat_exact_field<FT>
{
  typedef Flat_exact_field<FT> Base;

public:
  typedef typename Base::Mesh Mesh;
  typedef typename Base::Index Index;
  typedef typename Base::Path_node Path_node;
  typedef typename Base::Point_distance Point_distance;

  explicit Flat_exact_paths(const Mesh& mesh) : Base(mesh) {}

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

protected:
  typedef typename Base::Parent_kind Parent_kind;
  typedef typename Base::Face_source Face_source;
  typedef typename Base::Pseudo_source Pseudo_source;
  typedef typename Base::Candidate Candidate;
  typedef typename Base::Walker Walker;
  using Base::ROOT_VERTEX;
  using Base::ROOT_FACE;
  using Base::EUCLID;
  using Base::ALONG_SOURCE;
  using Base::ALONG_TARGET;
  using Base::EDGE_NEIGHBOR;
  using Base::best_candidate;
  using Base::child_head_;
  using Base::child_next_;
  using Base::consider;
  using Base::counters_;
  using Base::epsilon_;
  using Base::face_source_index_;
  using Base::face_sources_;
  using Base::first_reached_;
  using Base::has_face_source;
  using Base::he_;
  using Base::he_opposite_vertex;
  using Base::he_source;
  using Base::he_target;
  using Base::last_lowered_;
  using Base::length_2;
  using Base::mesh_;
  using Base::parent_edge;
  using Base::parent_he_;
  using Base::parent_kind_;
  using Base::point_in_halfedge_frame;
  using Base::pseudo_source_of;
  using Base::reached;
  using Base::side_he_;
  using Base::side_mask_;
  using Base::vedge_;
  using Base::vedge_begin_;
  using Base::vs_;

  // The children of edge x in the edge DAG: the edges around the vertices lowered from x (but x itself), and
  // the edges with side links from x.
  template <class Visit>
  void for_each_edge_child(Index x, Visit visit) const
  {
    for(Index w = child_head_[std::size_t(x)]; w >= 0; w = child_next_[std::size_t(w)])
      for(Index k = vedge_begin_[std::size_t(w)]; k < vedge_begin_[std::size_t(w) + 1]; ++k)
        if(vedge_[std::size_t(k)] != x)
          visit(vedge_[std::size_t(k)]);
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
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_FLAT_EXACT_PATHS_H
