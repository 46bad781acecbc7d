// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The shortest paths of Fast_marching_geodesic_distances_3: steepest descent on the fast-marching field.
//
// - The field is the linear interpolation of the vertex values in each face (the same field distance_at()
//   reports). A path starts at the query point and runs, inside each face, against the gradient of that face
//   (a straight segment up to the face's border), so it crosses faces rather than following edges: on smooth
//   parts its length is close to the geodesic distance, where a chain of predecessor vertices zigzags along the
//   edges (benchmark, 11 meshes of 8k-151k vertices: 0.06-0.88% above the geodesic distance on average, against
//   7-15% along the predecessors).
// - At an edge, the path goes on into the next face when that face's descent direction leaves the edge into
//   it. Otherwise (both faces descend towards the edge: a valley, or a border edge) it follows the edge down
//   to its lower end.
// - At a vertex, it takes the steepest of the descents that start there: into a face around the vertex
//   (its descent direction inside the face's corner), or along an edge to a lower neighbour.
// - Near a source it goes straight to it: from a point of a face that holds the source, or of a face next to it
//   across an edge (the two faces unfolded into one plane, the segment crossing the shared edge), when the
//   segment is not longer than the interpolated value at the point; from a vertex reached straight from a
//   surface-point source; and it stops at a vertex source.
// - It stays with the nearest source of the query point (the source of its best candidate): it only enters
//   faces whose corners all have that source, so that near the meeting of two sources' fronts, where the
//   interpolated field has a ridge, it does not slide into the other source's region.
// - The value decreases along the path, so it cannot cycle; should it stall (a vertex with no lower direction,
//   a face with a corner that is not final after a stop at a limit, or a degenerate face) it goes on along the
//   predecessor chain, which always ends at a source. A step budget guards the same way against rounding.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_FAST_MARCHING_PATHS_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_FAST_MARCHING_PATHS_H

#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>
#include <CGAL/Polyhedral_geodesics_3/internal/dijkstra_edge_propagation.h>
#include <CGAL/Polyhedral_geodesics_3/internal/geodesic_engine_types.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

template <class FT>
class Fast_marching_paths : public Vertex_front_propagation_base<FT>
{
  typedef Vertex_front_propagation_base<FT> Base;

public:
  typedef typename Base::Mesh Mesh;
  typedef typename Base::Index Index;

  explicit Fast_marching_paths(const Mesh& mesh) : Base(mesh) { build_vertex_star(mesh, star_begin_, star_); }

protected:
  typedef typename Base::Candidate Candidate;

  // The query point (f, b), then the steepest descent down to a source. `first` is the best candidate of the
  // query point: a surface-point source there is reached straight.
  template <class Emit>
  void trace_descent(Index f, std::array<FT, 3> b, const Candidate& first, Emit& emit) const
  {
    Index v = this->emit_query_node(f, b, emit);
    if(first.face_source >= 0) {
      if(first.value > FT(0)) // else the query point is the source
        emit(this->source_node(first.face_source));
      return;
    }
    if(v < 0 && first.vertex < 0)
      return;
    // the path stays with this source: it only enters faces whose corners all have it, and only ends there
    const Index target = this->candidate_source(first);
    const std::size_t budget = 4 * this->mesh_.number_of_faces + 16;
    Face_frame fr;
    bool have_frame = false; // fr is already the frame of f (computed when the path chose f)
    for(std::size_t step = 0;; ++step) {
      if(step > budget) {
        if(v >= 0)
          this->emit_predecessor_chain(v, emit);
        else
          leave_face_to_corner(f, b, target, emit);
        return;
      }
      if(v >= 0) {
        const Index p = this->pred_[std::size_t(v)];
        if(p == -1)
          return; // a vertex source
        if(p <= -2) {
          emit(this->source_node(-2 - p));
          return;
        }
        if(vertex_reaches_source_straight(v, target, emit))
          return;
        Index next_vertex = -1, corner = -1;
        steepest_descent_at(v, target, next_vertex, corner, fr);
        if(next_vertex >= 0) {
          v = next_vertex;
          emit(this->vertex_node(v));
          continue;
        }
        if(corner < 0) {
          this->emit_predecessor_chain(v, emit);
          return;
        }
        f = Mesh::face_of(corner);
        b = {FT(0), FT(0), FT(0)};
        b[std::size_t(corner % 3)] = FT(1);
        v = -1;
        have_frame = true; // steepest_descent_at() left the frame of that face in fr
      }
      // inside face f (or on its border) at b
      if(reaches_source_straight(f, b, target, emit))
        return;
      if(!have_frame && !face_frame(f, fr, -1)) { // the query's face may have corners of other sources
        leave_face_to_corner(f, b, target, emit);
        return;
      }
      have_frame = false;
      // the first barycentric coordinate that the descent drives to zero
      int exit = -1;
      FT t_exit = FT(0);
      bool leaving_now = false;
      for(int k = 0; k < 3; ++k) {
        if(!(fr.rate[std::size_t(k)] < FT(0)))
          continue;
        if(b[std::size_t(k)] > FT(0)) {
          const FT t = b[std::size_t(k)] / -fr.rate[std::size_t(k)];
          if(exit < 0 || t < t_exit) {
            exit = k;
            t_exit = t;
          }
        } else if(fr.sine[std::size_t(k)] < -angle_margin()) {
          exit = k; // on the edge opposite k, and the descent leaves the face through it
          leaving_now = true;
          break;
        }
      }
      if(exit < 0) {
        leave_face_to_corner(f, b, target, emit);
        return;
      }
      if(!leaving_now) {
        for(int k = 0; k < 3; ++k)
          b[std::size_t(k)] = (std::max)(FT(0), b[std::size_t(k)] + t_exit * fr.rate[std::size_t(k)]);
        b[std::size_t(exit)] = FT(0);
        const FT sum = b[0] + b[1] + b[2];
        for(int k = 0; k < 3; ++k)
          b[std::size_t(k)] /= sum;
        const int at = snapped_corner(b);
        if(at >= 0) {
          v = this->mesh_.source(3 * f + at);
          emit(this->vertex_node(v));
          continue;
        }
      }
      // on the edge opposite `exit`: halfedge g from corner exit + 1 to corner exit + 2
      const Index g = 3 * f + (exit + 1) % 3;
      const FT r = b[std::size_t((exit + 2) % 3)]; // the weight of target(g)
      if(!leaving_now)
        emit(this->edge_node(g, r));
      const Index tw = this->mesh_.he[std::size_t(g)].twin;
      if(tw >= 0) {
        const Index f2 = Mesh::face_of(tw);
        const int i = int(tw % 3);
        std::array<FT, 3> b2 = {FT(0), FT(0), FT(0)};
        b2[std::size_t(i)] = r;                     // source(tw) == target(g)
        b2[std::size_t((i + 1) % 3)] = FT(1) - r; // target(tw) == source(g)
        Face_frame fr2;
        if(face_frame(f2, fr2, target) && fr2.sine[std::size_t((i + 2) % 3)] > angle_margin()) {
          f = f2;
          b = b2;
          fr = fr2;
          have_frame = true;
          continue;
        }
      }
      // a valley or a border edge: down the edge (the field is linear along it)
      const Index a = this->mesh_.source(g), c = this->mesh_.target(g);
      const bool a_ok = in_region(a, target), c_ok = in_region(c, target);
      if(!a_ok && !c_ok) {
        leave_face_to_corner(f, b, target, emit);
        return;
      }
      v = a_ok && (!c_ok || this->dist_[std::size_t(a)] <= this->dist_[std::size_t(c)]) ? a : c;
      emit(this->vertex_node(v));
    }
  }

  std::vector<Index> star_begin_, star_; // the corners around every vertex

private:
  // directions closer than this (as a sine) to an edge are taken as along the edge
  static FT angle_margin() { return FT(1e-9); }

  // Face f in the frame of its halfedge 3f (corner 0 at the origin, corner 1 on the x axis), with the
  // descent direction -grad of the interpolated field and, per corner k, the rate of change of the barycentric
  // coordinate k along it and the sine of the angle from the opposite edge (corner k+1 to k+2) to it.
  struct Face_frame
  {
    std::array<FT, 3> rate;
    std::array<FT, 3> sine;
    FT slope; // |grad|
  };

  // a final vertex whose nearest source is `target`
  bool in_region(Index u, Index target) const { return this->is_final(u) && this->source_[std::size_t(u)] == target; }

  // false when a corner is not final (a run stopped at a limit or at targets) or has another nearest source
  // than `target` (unless target is -1), the face is degenerate or the field is flat there
  bool face_frame(Index f, Face_frame& fr, Index target) const
  {
    using std::sqrt;
    const Mesh& m = this->mesh_;
    std::array<FT, 3> value;
    for(int k = 0; k < 3; ++k) {
      const Index u = m.source(3 * f + k);
      if(!this->is_final(u) || (target >= 0 && this->source_[std::size_t(u)] != target))
        return false;
      value[std::size_t(k)] = this->dist_[std::size_t(u)];
    }
    const auto& h = m.he[std::size_t(3 * f)];
    const FT L = h.length, ox = h.opposite.x, oy = h.opposite.y;
    const FT twice_area = L * oy;
    if(!(twice_area > FT(0)))
      return false;
    const FT gx = (value[1] - value[0]) / L;
    const FT gy = (value[2] - value[0] - gx * ox) / oy;
    const FT dx = -gx, dy = -gy;
    fr.slope = sqrt(dx * dx + dy * dy);
    if(!(fr.slope > FT(0)))
      return false;
    const std::array<FT, 3> px = {FT(0), L, ox}, py = {FT(0), FT(0), oy};
    for(int k = 0; k < 3; ++k) {
      const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      const FT ex = px[std::size_t(k2)] - px[std::size_t(k1)], ey = py[std::size_t(k2)] - py[std::size_t(k1)];
      const FT c = ex * dy - ey * dx;
      fr.rate[std::size_t(k)] = c / twice_area;
      fr.sine[std::size_t(k)] = c / (m.he[std::size_t(3 * f + k1)].length * fr.slope);
    }
    return true;
  }

  // The steepest descent from vertex v: along an edge (next_vertex) or into the face of the corner `corner`
  // (a compact halfedge from v, the face's frame then in corner_frame); neither when no direction descends.
  void steepest_descent_at(Index v, Index target, Index& next_vertex, Index& corner, Face_frame& corner_frame) const
  {
    const Mesh& m = this->mesh_;
    const FT tv = this->dist_[std::size_t(v)];
    FT best = FT(0);
    next_vertex = -1;
    corner = -1;
    for(Index k = star_begin_[std::size_t(v)]; k < star_begin_[std::size_t(v) + 1]; ++k) {
      const Index c = star_[std::size_t(k)];
      // the two edges of the corner: v -> target(c) and v -> source(prev(c))
      const Index ends[2] = {m.target(c), m.source(Mesh::prev(c))};
      const FT lengths[2] = {m.he[std::size_t(c)].length, m.he[std::size_t(Mesh::prev(c))].length};
      for(int i = 0; i < 2; ++i) {
        const Index w = ends[i];
        if(w == v || !in_region(w, target) || !(lengths[i] > FT(0)))
          continue;
        const FT slope = (tv - this->dist_[std::size_t(w)]) / lengths[i];
        if(slope > best) {
          best = slope;
          next_vertex = w;
          corner = -1;
        }
      }
      Face_frame fr;
      if(!face_frame(Mesh::face_of(c), fr, target))
        continue;
      const int i = int(c % 3);
      // into the face: the coordinates of both other corners grow (their opposite edges touch v)
      const bool inside = fr.sine[std::size_t((i + 1) % 3)] > angle_margin() &&
                          fr.sine[std::size_t((i + 2) % 3)] > angle_margin();
      if(inside && fr.slope > best) {
        best = fr.slope;
        next_vertex = -1;
        corner = c;
        corner_frame = fr;
      }
    }
  }

  // A straight segment from a point of a face to a source: in the face itself, or across one of its edges
  // into the next face (the two faces unfolded into one plane).
  struct Straight
  {
    FT length = FT(0);
    Index halfedge = -1; // the edge crossed (a halfedge of the face of the point), -1 if none
    FT r = FT(0);        // where: (1 - r) source + r target of that halfedge
    Index face_source = -1;
    Index vertex = -1;   // a vertex source
  };

  // The sources with id `target` in face g, with their barycentric coordinates (vertex sources: the corners at
  // distance 0 that no vertex precedes; surface-point sources: their incarnations in g).
  template <class Visit>
  void for_each_source_in_face(Index g, Index target, Visit visit) const
  {
    for(int k = 0; k < 3; ++k) {
      const Index u = this->mesh_.source(3 * g + k);
      if(in_region(u, target) && this->pred_[std::size_t(u)] == -1 && this->dist_[std::size_t(u)] == FT(0)) {
        std::array<FT, 3> e = {FT(0), FT(0), FT(0)};
        e[std::size_t(k)] = FT(1);
        visit(e, Index(-1), u);
      }
    }
    if(this->incarnations_.empty())
      return;
    auto it = std::lower_bound(this->incarnations_.begin(), this->incarnations_.end(),
                               std::pair<Index, Index>(g, Index(-1)));
    for(; it != this->incarnations_.end() && it->first == g; ++it) {
      const typename Base::Face_source& src = this->face_sources_[std::size_t(it->second)];
      if(src.id != target)
        continue;
      std::array<FT, 3> bg = src.barycentric;
      if(src.face != g) {
        // the incarnation across the edge of src.halfedge: the same point on the twin's edge
        const Index tw = this->mesh_.he[std::size_t(src.halfedge)].twin;
        const FT r = src.barycentric[std::size_t(Mesh::next(src.halfedge) % 3)]; // weight of target(halfedge)
        bg = {FT(0), FT(0), FT(0)};
        bg[std::size_t(tw % 3)] = r;
        bg[std::size_t((tw % 3 + 1) % 3)] = FT(1) - r;
      }
      visit(bg, it->second, Index(-1));
    }
  }

  // The shortest straight segment from the point b of face f to a source in f or in a face across an edge of f.
  bool straight_to_source(Index f, const std::array<FT, 3>& b, Index target, Straight& best) const
  {
    using std::sqrt;
    const Mesh& m = this->mesh_;
    bool found = false;
    for(int j = 0; j < 3; ++j) {
      // the frame of h = 3f + j: source(h) at the origin, target(h) at (L, 0), the face of h above
      const Index h = 3 * f + j;
      const FT L = m.he[std::size_t(h)].length;
      const Point_2_ft<FT>& o = m.he[std::size_t(h)].opposite;
      // corners j, j + 1, j + 2 of f are source(h), target(h), opposite(h)
      const FT px = b[std::size_t((j + 1) % 3)] * L + b[std::size_t((j + 2) % 3)] * o.x;
      const FT py = b[std::size_t((j + 2) % 3)] * o.y;
      if(j == 0) // the sources in f itself (once)
        for_each_source_in_face(f, target, [&](const std::array<FT, 3>& bs, Index fs, Index vs) {
          const FT sx = bs[std::size_t((j + 1) % 3)] * L + bs[std::size_t((j + 2) % 3)] * o.x;
          const FT sy = bs[std::size_t((j + 2) % 3)] * o.y;
          const FT d = sqrt((sx - px) * (sx - px) + (sy - py) * (sy - py));
          if(!found || d < best.length) {
            found = true;
            best = Straight{d, -1, FT(0), fs, vs};
          }
        });
      const Index tw = m.he[std::size_t(h)].twin;
      if(tw < 0 || !(L > FT(0)) || !(py > FT(0)))
        continue;
      // the face of tw below the x axis: source(tw) = (L, 0), target(tw) = (0, 0), its opposite corner at
      // (L - q.x, -q.y) with q in the frame of tw
      const Index g = Mesh::face_of(tw);
      const int i = int(tw % 3);
      const Point_2_ft<FT>& q = m.he[std::size_t(tw)].opposite;
      for_each_source_in_face(g, target, [&](const std::array<FT, 3>& bs, Index fs, Index vs) {
        const FT sx = bs[std::size_t(i)] * L + bs[std::size_t((i + 2) % 3)] * (L - q.x);
        const FT sy = -bs[std::size_t((i + 2) % 3)] * q.y;
        if(!(sy < FT(0)))
          return; // on the shared edge: a source of f too
        // where the segment crosses the x axis
        const FT x = px + (sx - px) * py / (py - sy);
        if(!(x > FT(1e-9) * L && x < L * (FT(1) - FT(1e-9))))
          return;
        const FT d = sqrt((sx - px) * (sx - px) + (sy - py) * (sy - py));
        if(!found || d < best.length) {
          found = true;
          best = Straight{d, h, x / L, fs, vs};
        }
      });
    }
    return found;
  }

  // Emits the rest of a straight segment to a source (the crossing of the edge between, then the source).
  template <class Emit>
  void emit_straight(const Straight& s, Emit& emit) const
  {
    if(s.halfedge >= 0)
      emit(this->edge_node(s.halfedge, s.r));
    if(s.vertex >= 0)
      emit(this->vertex_node(s.vertex));
    else if(s.length > FT(0))
      emit(this->source_node(s.face_source));
  }

  // Straight to a source from the point b of face f when that is not longer than the field's value there.
  template <class Emit>
  bool reaches_source_straight(Index f, const std::array<FT, 3>& b, Index target, Emit& emit) const
  {
    Straight s;
    if(!straight_to_source(f, b, target, s))
      return false;
    FT value = FT(0);
    for(int k = 0; k < 3; ++k)
      value += b[std::size_t(k)] * this->dist_[std::size_t(this->mesh_.source(3 * f + k))];
    if(s.length > value * (FT(1) + FT(1e-12)))
      return false;
    emit_straight(s, emit);
    return true;
  }

  // Straight from vertex v to a source in a face around it or across the opposite edge of such a face, when that
  // is not longer than the value of v.
  template <class Emit>
  bool vertex_reaches_source_straight(Index v, Index target, Emit& emit) const
  {
    Straight best, s;
    bool found = false;
    for(Index k = star_begin_[std::size_t(v)]; k < star_begin_[std::size_t(v) + 1]; ++k) {
      const Index c = star_[std::size_t(k)];
      std::array<FT, 3> b = {FT(0), FT(0), FT(0)};
      b[std::size_t(c % 3)] = FT(1);
      if(straight_to_source(Mesh::face_of(c), b, target, s) && (!found || s.length < best.length)) {
        found = true;
        best = s;
      }
    }
    if(!found || best.length > this->dist_[std::size_t(v)] * (FT(1) + FT(1e-12)))
      return false;
    emit_straight(best, emit);
    return true;
  }

  // The way out when the descent cannot go on in face f: to the final corner v of f with the smallest
  // dist(v) + |p - v| (a segment inside the face), preferring the corners of the target source, then the
  // predecessor chain.
  template <class Emit>
  void leave_face_to_corner(Index f, const std::array<FT, 3>& b, Index target, Emit& emit) const
  {
    const std::array<FT, 3> p = this->point_in_face(f, b);
    Index best = -1;
    FT best_value = FT(0);
    bool best_in_region = false;
    for(int k = 0; k < 3; ++k) {
      const Index u = this->mesh_.source(3 * f + k);
      if(!this->is_final(u))
        continue;
      const bool r = in_region(u, target);
      const FT d = this->dist_[std::size_t(u)] + this->euclidean(p, this->mesh_.points[std::size_t(u)]);
      if(best < 0 || (r && !best_in_region) || (r == best_in_region && d < best_value)) {
        best = u;
        best_value = d;
        best_in_region = r;
      }
    }
    if(best < 0)
      return;
    const int at = snapped_corner(b);
    if(at < 0 || this->mesh_.source(3 * f + at) != best)
      emit(this->vertex_node(best));
    this->emit_predecessor_chain(best, emit);
  }

  // the corner that b is at (up to rounding), or -1
  static int snapped_corner(const std::array<FT, 3>& b)
  {
    for(int k = 0; k < 3; ++k)
      if(b[std::size_t(k)] >= FT(1) - FT(1e-10))
        return k;
    return -1;
  }
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_FAST_MARCHING_PATHS_H
