// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Fast marching on triangle meshes (Kimmel and Sethian, "Computing geodesic paths on manifolds", PNAS 1998),
// the engine of Fast_marching_geodesic_distances_3.
//
// - The distance T is known at the final vertices; a vertex C of a triangle (C, X, Y) whose two other
//   corners are final gets the value of the planar wavefront through (X, T_X) and (Y, T_Y) with a unit
//   gradient n, accepted only when the wave reaches C from inside the triangle (the ray from C in
//   direction -n lies between CX and CY: the upwind or causality condition) and does not lower C below
//   T_X or T_Y; otherwise only the one-sided updates T_X + |XC| and T_Y + |YC| along the edges apply
//   (they are applied from every final neighbour in any case).
// - With e_x = X - C, e_y = Y - C and Q the inverse of their Gram matrix, n = [e_x e_y] Q u with
//   u = (T_X - t, T_Y - t), so |n| = 1 is the quadratic u^T Q u = 1 in t = T_C and the causality
//   condition is Q u <= 0 componentwise. The update solves for s = t - T_X (no cancellation between large
//   distances).
// - Storage (precomputed once, contiguous): Q of the real triangle of every corner (indexed like the
//   compact halfedges), the corners around every vertex (the faces visited when it becomes final), and the
//   virtual triangles of the obtuse corners by support vertex. About 90 bytes per face; no allocation
//   during the propagation but the heap's growth.
// - Obtuse corners (Kimmel and Sethian's fix): the wavefront may reach an obtuse corner C from a
//   direction between CX and CY that the triangle cannot represent causally. The faces beyond the edge
//   XY are unfolded into the plane of (C, X, Y), one after the other along the strip that the sector at C
//   crosses, until a vertex D lies in the part of the sector where both angles XCD and DCY are acute (at
//   most `max_unfoldings` faces, giving up at the boundary). The corner then uses the two acute virtual
//   triangles (C, X, D) and (C, D, Y) with the unfolded position of D, in addition to the obtuse
//   triangle itself (its update, under the same checks, is still valid when X and Y are final first: this
//   happens near a point source, where the front is far from planar and D can be farther than C; keeping
//   it lowers the mean error on every mesh measured, e.g. 2.6% -> 2.3% on CGAL's elephant and it halves
//   the largest error on sheared grids).
// - A binary heap with lazy deletion holds the narrow band; a vertex is final when it is popped.
// - Paths descend the interpolated field across the faces (fast_marching_paths.h). The predecessor of a
//   vertex (the neighbour it was last lowered from; for a two-point update, the final one of X and Y with the
//   smaller value among the real mesh neighbours of C) is their way out where the descent stalls.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_FAST_MARCHING_PROPAGATION_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_FAST_MARCHING_PROPAGATION_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_types.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>
#include <CGAL/Polyhedral_geodesics_3/internal/dijkstra_edge_propagation.h>
#include <CGAL/Polyhedral_geodesics_3/internal/fast_marching_paths.h>
#include <CGAL/Polyhedral_geodesics_3/internal/geodesic_engine_types.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

template <class FT>
class Fast_marching_propagation : public Fast_marching_paths<FT>
{
  typedef Fast_marching_paths<FT> Base;

public:
  typedef typename Base::Mesh Mesh;
  typedef typename Base::Index Index;
  typedef typename Base::Point_distance Point_distance;
  typedef typename Base::Path_node Path_node;

  explicit Fast_marching_propagation(const Mesh& mesh, int max_unfoldings = 30) : Base(mesh)
  {
    build_update_triangles(max_unfoldings);
  }

  // counters of the preprocessing (tests and benchmarks)
  std::size_t number_of_obtuse_corners() const { return obtuse_corners_; }
  std::size_t number_of_unfolded_corners() const { return unfolded_corners_; }

  template <class Progress>
  void run(Progress& progress)
  {
    const Mesh& m = this->mesh_;
    CGAL::MDCS::internal::Progress_reporter<Progress> report(progress, "fast marching", m.number_of_vertices);
    this->begin_run();
    Index v = -1;
    FT key = FT(0);
    while(this->pop(v, key)) {
      if(this->make_final(v, key))
        break;
      report(this->final_count_);
      const std::size_t vi = std::size_t(v);
      const Index src = this->source_[vi];
      // the faces around v: v is the corner h, the two other corners c1 = next(h) and c2 = prev(h)
      const Index send = this->star_begin_[vi + 1];
      for(Index k = this->star_begin_[vi]; k < send; ++k) {
        const Index h = this->star_[std::size_t(k)];
        const Index c1 = Mesh::next(h), c2 = Mesh::prev(h);
        const Index v1 = m.he[std::size_t(c1)].source, v2 = m.he[std::size_t(c2)].source;
        // one-sided updates along the edges v -> v1 (halfedge h) and v2 -> v (halfedge c2)
        this->lower(v1, key + m.he[std::size_t(h)].length, src, v);
        this->lower(v2, key + m.he[std::size_t(c2)].length, src, v);
        // two-point updates: at corner c1 the supports are (A, B) = (v2, v), at corner c2 they are (v, v1)
        const std::array<FT, 3>& q1 = corner_q_[std::size_t(c1)];
        if(q1[0] > FT(0))
          two_point_update(v1, v, key, v2, q1[2], q1[1], q1[0], true);
        const std::array<FT, 3>& q2 = corner_q_[std::size_t(c2)];
        if(q2[0] > FT(0))
          two_point_update(v2, v, key, v1, q2[0], q2[1], q2[2], true);
      }
      // the virtual triangles of obtuse corners in which v is a support
      const Index vend = virtual_begin_[vi + 1];
      for(Index k = virtual_begin_[vi]; k < vend; ++k) {
        const Virtual_entry& e = virtual_[std::size_t(k)];
        const bool other_is_real = e.other >= 0;
        two_point_update(e.target, v, key, other_is_real ? e.other : ~e.other, e.qxx, e.qxy, e.qyy, other_is_real);
      }
    }
    this->finish_run(this->star_begin_.capacity() * sizeof(Index) + this->star_.capacity() * sizeof(Index) +
                     corner_q_.capacity() * sizeof(std::array<FT, 3>) + virtual_begin_.capacity() * sizeof(Index) +
                     virtual_.capacity() * sizeof(Virtual_entry));
    report.finish();
  }

  // The linear interpolation of the three corner values (exact at the vertices), or the straight distance to
  // a surface-point source in a face that contains the point when it is smaller.
  Point_distance distance_at(Index f, const std::array<FT, 3>& b) const
  {
    const std::array<FT, 3> p = this->point_in_face(f, b);
    bool have = true;
    FT value = FT(0);
    for(int k = 0; k < 3; ++k) {
      const Index v = this->mesh_.source(3 * f + k);
      if(b[std::size_t(k)] == FT(0))
        continue; // a point on the opposite edge, or at a vertex, does not need this corner
      if(!this->is_final(v)) {
        have = false;
        break;
      }
      value += b[std::size_t(k)] * this->dist_[std::size_t(v)];
    }
    Index source = -1;
    if(have) {
      typename Base::Candidate corner;
      this->corner_candidates(f, p, corner);
      source = this->candidate_source(corner);
    }
    typename Base::Candidate straight;
    this->face_source_candidates(f, b, p, straight);
    if(straight.face_source >= 0 && (!have || straight.value < value)) {
      have = true;
      value = straight.value;
      source = this->candidate_source(straight);
    }
    if(!have || !this->valid_answer(value))
      return {Base::infinity(), -1};
    return {value, source};
  }

  // The query point, then the steepest descent of the interpolated field down to the source
  // (fast_marching_paths.h), or straight to a surface-point source when that is the best candidate of the
  // query point (the one minimising T(v) + |p - v| over the corners, or the straight distance to the source).
  template <class Emit>
  void trace_path(Index f, const std::array<FT, 3>& b, Emit emit) const
  {
    if(distance_at(f, b).source < 0)
      return;
    const std::array<FT, 3> p = this->point_in_face(f, b);
    typename Base::Candidate first;
    this->corner_candidates(f, p, first);
    this->face_source_candidates(f, b, p, first);
    if(first.vertex < 0 && first.face_source < 0)
      return;
    this->trace_descent(f, b, first, emit);
  }

private:
  // Lowers `target` from the triangle (target, x, y) where x (value tx) has just become final and y may be: the
  // planar wavefront through (x, tx) and (y, T_y). q.. is the inverse Gram matrix of (x - target, y - target).
  // The predecessor is y when it is a real neighbour of the target (it became final first: T_y <= tx), else x.
  void two_point_update(Index target, Index x, const FT& tx, Index y, const FT& qxx, const FT& qxy, const FT& qyy,
                        bool y_is_real)
  {
    using std::sqrt;
    const std::size_t c = std::size_t(target), yi = std::size_t(y);
    if(this->final_[c] || !this->final_[yi])
      return;
    const FT& ty = this->dist_[yi];
    // s = t - tx solves a s^2 - 2 bq s + cq = 0 (see the header comment)
    const FT delta = ty - tx;
    const FT qx1 = qxx + qxy, qy1 = qxy + qyy;
    const FT a = qx1 + qy1;
    const FT bq = delta * qy1;
    const FT disc = bq * bq - a * (delta * delta * qyy - FT(1));
    if(!(disc >= FT(0)))
      return;
    const FT s = (bq + sqrt(disc)) / a;
    // causality: Q u <= 0 with u = (-s, delta - s)
    if(qxy * delta - s * qx1 > FT(0) || qyy * delta - s * qy1 > FT(0))
      return;
    const FT t = tx + s;
    if(t < tx || t < ty || !(t < this->dist_[c]))
      return;
    const Index pred = y_is_real ? y : x;
    this->lower(target, t, this->source_[std::size_t(pred)], pred);
  }

  // A virtual triangle (target, support, other) of an obtuse corner, stored at its support: `other` is the index
  // of the other support when it is a real neighbour of the target, ~index (negative) when it is the unfolded
  // vertex. q.. is the inverse Gram matrix of (support - target, other - target), support first.
  struct Virtual_entry
  {
    Index target;
    Index other;
    FT qxx, qxy, qyy;
  };

  struct Vec2
  {
    FT x, y;
  };
  static FT cross(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }
  static FT dot(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }

  // the inverse Gram matrix of (x, y), y counter-clockwise from x; false for a degenerate triangle (the
  // one-sided updates do the work there)
  static bool inverse_gram(const Vec2& x, const Vec2& y, std::array<FT, 3>& q)
  {
    using std::sqrt;
    const FT gxx = dot(x, x), gyy = dot(y, y), gxy = dot(x, y), cr = cross(x, y);
    if(!(cr > FT(1e-12) * sqrt(gxx * gyy)))
      return false;
    const FT det = cr * cr;
    q = {gyy / det, -gxy / det, gxx / det};
    return true;
  }

  // Per corner C (compact halfedge c, supports A = source(next(c)), B = source(prev(c))): the inverse Gram matrix
  // of (A - C, B - C), and for an obtuse corner the two virtual triangles (C, A, D) and (C, D, B).
  void build_update_triangles(int max_unfoldings)
  {
    const Mesh& m = this->mesh_;
    const std::size_t nv = m.number_of_vertices, nh = 3 * m.number_of_faces;
    obtuse_corners_ = 0;
    unfolded_corners_ = 0;
    corner_q_.assign(nh, std::array<FT, 3>{FT(0), FT(0), FT(0)});
    struct Virtual_triangle
    {
      Index target, x, y; // the real support is x for the first triangle of a corner, y for the second
      bool x_is_real;
      std::array<FT, 3> q;
    };
    std::vector<Virtual_triangle> virtuals;
    for(std::size_t ci = 0; ci < nh; ++ci) {
      const Index c = Index(ci);
      const Index C = m.he[ci].source;
      const Index h = Mesh::next(c); // A -> B, opposite to C
      const Index A = m.source(h), B = m.target(h);
      if(A == C || B == C || A == B)
        continue;
      const FT L = m.he[std::size_t(h)].length;
      const Point_2_ft<FT>& cp = m.he[std::size_t(h)].opposite;
      const Vec2 a{-cp.x, -cp.y}, b{L - cp.x, -cp.y};
      std::array<FT, 3> q;
      if(inverse_gram(a, b, q))
        corner_q_[ci] = q;
      if(!(dot(a, b) < FT(0)))
        continue;
      ++obtuse_corners_;
      Index D = -1;
      Vec2 d{FT(0), FT(0)};
      if(!unfold(h, cp, a, b, max_unfoldings, D, d) || D == A || D == B || D == C)
        continue;
      ++unfolded_corners_;
      if(inverse_gram(a, d, q))
        virtuals.push_back(Virtual_triangle{C, A, D, true, q});
      if(inverse_gram(d, b, q))
        virtuals.push_back(Virtual_triangle{C, D, B, false, q});
    }
    // every virtual triangle is stored once for each support
    virtual_begin_.assign(nv + 1, 0);
    for(const Virtual_triangle& t : virtuals) {
      ++virtual_begin_[std::size_t(t.x) + 1];
      ++virtual_begin_[std::size_t(t.y) + 1];
    }
    for(std::size_t v = 0; v < nv; ++v)
      virtual_begin_[v + 1] += virtual_begin_[v];
    virtual_.resize(std::size_t(virtual_begin_[nv]));
    std::vector<Index> fill(virtual_begin_.begin(), virtual_begin_.end() - 1);
    for(const Virtual_triangle& t : virtuals) {
      // at x, the other support is y: real iff x is not
      virtual_[std::size_t(fill[std::size_t(t.x)]++)] = Virtual_entry{t.target, t.x_is_real ? ~t.y : t.y, t.q[0], t.q[1], t.q[2]};
      virtual_[std::size_t(fill[std::size_t(t.y)]++)] = Virtual_entry{t.target, t.x_is_real ? t.x : ~t.x, t.q[2], t.q[1], t.q[0]};
    }
  }

  // Unfolds the faces beyond the edge of h (A -> B, in its frame A = (0,0), B = (L,0), C = c above) until a
  // vertex D lies where both angles ACD and DCB are acute; returns its index and D - C.
  bool unfold(Index h, const Point_2_ft<FT>& c, const Vec2& a, const Vec2& b, int max_unfoldings, Index& D,
              Vec2& d) const
  {
    using std::sqrt;
    const Mesh& m = this->mesh_;
    // the acute sub-sector lies between lo (perpendicular to CB, on the A side) and hi (perpendicular to CA)
    const Vec2 lo{b.y, -b.x}, hi{-a.y, a.x};
    Vec2 U{FT(0), FT(0)}, W{m.he[std::size_t(h)].length, FT(0)};
    Index g = h; // U -> W, the near face on its left
    for(int step = 0; step < max_unfoldings; ++step) {
      const Index t = m.he[std::size_t(g)].twin;
      if(t < 0)
        return false;
      const Vec2 ex{U.x - W.x, U.y - W.y};
      const FT len = sqrt(dot(ex, ex));
      if(!(len > FT(0)))
        return false;
      const Vec2 e{ex.x / len, ex.y / len}, r{-e.y, e.x};
      const Point_2_ft<FT>& o = m.he[std::size_t(t)].opposite; // in t's frame: W at the origin, U on the x axis
      const Vec2 P{W.x + o.x * e.x + o.y * r.x, W.y + o.x * e.y + o.y * r.y};
      const Vec2 p{P.x - c.x, P.y - c.y};
      if(cross(lo, p) < FT(0)) {
        U = P;
        g = Mesh::prev(t); // P -> W
      } else if(cross(p, hi) < FT(0)) {
        W = P;
        g = Mesh::next(t); // U -> P
      } else {
        D = m.opposite_vertex(t);
        d = p;
        return true;
      }
    }
    return false;
  }

  std::vector<std::array<FT, 3>> corner_q_; // per corner: inverse Gram matrix of its real triangle (0: degenerate)
  std::vector<Index> virtual_begin_;        // the virtual triangles by support
  std::vector<Virtual_entry> virtual_;
  std::size_t obtuse_corners_ = 0, unfolded_corners_ = 0;
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_FAST_MARCHING_PROPAGATION_H
