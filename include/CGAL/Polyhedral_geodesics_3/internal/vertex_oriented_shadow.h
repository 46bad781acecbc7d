// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The angle tables of the vertex-oriented schedule's shadow pruning (vertex_oriented_propagation.h,
// set_shadow_pruning()).
//
// A settled saddle or boundary vertex emits windows only over the faces that a shortest path through it can enter.
// Such a path arrives and leaves with an angle of at least pi on both sides (on the surface's side only, at a
// boundary vertex), whatever shortest path to the vertex it arrived by (with another, the angle on one side would be
// below pi and the path could be shortened), so the faces outside that "shadow" of the direction the vertex got its
// value from carry no shortest path through it; without the rule their windows are created and then trimmed by the
// vertices around.
//
// Directions at a vertex v are angles around it, measured counterclockwise over its faces from the first halfedge
// of its star in that order (star_angle_: the angle of each halfedge leaving v; corner_angle_: the angle of its face
// at v; vertex_total_angle_: the sum). The tables are built once (build()) and only read during a propagation; the
// direction each vertex got its current value from (its "arrival", changing during a run) is kept by the
// propagation and passed in.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_SHADOW_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_SHADOW_H

#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

template <class FT>
class Vertex_shadow_angles
{
public:
  typedef Geodesic_mesh<FT> Mesh;
  typedef typename Mesh::Index Index;

  explicit Vertex_shadow_angles(const Mesh& mesh) : mesh_(mesh) {}

  // Builds the tables around the vertices where is_candidate(v) (the pseudo-sources), in the order of the vertex
  // star (star_begin, star: build_vertex_star()), and returns the vertices where the rule holds: one fan of faces
  // (a manifold vertex) around a saddle or boundary vertex, without a degenerate face.
  template <class Is_candidate>
  std::vector<Index> build(const std::vector<Index>& star_begin, const std::vector<Index>& star, Is_candidate is_candidate)
  {
    const std::size_t nv = mesh_.number_of_vertices, nh = 3 * mesh_.number_of_faces;
    corner_angle_.assign(nh, 0);
    star_angle_.assign(nh, 0);
    vertex_total_angle_.assign(nv, 0);
    std::vector<char> rule(nv, 0);
    for(std::size_t h = 0; h < nh; ++h) {
      const Point_2_ft<FT>& c = mesh_.he[h].opposite; // the corner at source(h) lies between (length, 0) and c
      corner_angle_[h] = std::atan2(to_double_value(c.y), to_double_value(c.x));
    }
    for(std::size_t v = 0; v < nv; ++v) {
      if(!is_candidate(v) || star_begin[v] == star_begin[v + 1])
        continue;
      // The first halfedge counterclockwise: one on the border (nothing clockwise of it), else any. The next one
      // counterclockwise leaves v along the other edge of the face: twin(prev(h)).
      Index first = star[std::size_t(star_begin[v])];
      for(Index k = star_begin[v]; k < star_begin[v + 1]; ++k)
        if(mesh_.he[std::size_t(star[std::size_t(k)])].twin < 0)
          first = star[std::size_t(k)];
      double angle = 0;
      Index h = first, count = 0;
      do {
        star_angle_[std::size_t(h)] = angle;
        angle += corner_angle_[std::size_t(h)];
        ++count;
        h = mesh_.he[std::size_t(Mesh::prev(h))].twin;
      } while(h >= 0 && h != first && count <= star_begin[v + 1] - star_begin[v]);
      vertex_total_angle_[v] = angle;
      // One fan of faces (a manifold vertex), not made a pseudo-source by a degenerate face: the rule holds.
      if(count == star_begin[v + 1] - star_begin[v] && (h < 0 || h == first) && is_saddle_or_boundary_vertex(mesh_, v) &&
         (h < 0) == bool(mesh_.vertex_on_boundary[v]))
        rule[v] = 1;
    }
    for(std::size_t h = 0; h < nh; ++h) // (a degenerate face at v: no rule there)
      if(mesh_.he[h].length == FT(0) || !(mesh_.he[h].opposite.y > FT(0)))
        for(Index v : {mesh_.source(Index(h)), mesh_.target(Index(h)), mesh_.opposite_vertex(Index(h))})
          rule[std::size_t(v)] = 0;
    std::vector<Index> with_rule;
    for(std::size_t v = 0; v < nv; ++v)
      if(rule[v])
        with_rule.push_back(Index(v));
    return with_rule;
  }

  // The direction of an edge of the face of h (leaving u) from u: h itself, or (far_side) the other edge of the
  // face at u, counterclockwise across the corner.
  double edge_direction(Index h, bool far_side) const
  {
    return star_angle_[std::size_t(h)] + (far_side ? corner_angle_[std::size_t(h)] : 0.0);
  }

  // The direction (an angle around v) back along the last segment of a path to v through a window of halfedge g
  // with pseudo-source (sx, sy) (in g's frame): from v to the pseudo-source when v is an end of g, to the point `at`
  // of g's edge when v is the opposite corner.
  double arrival_from_window(Index v, const FT& wsx, const FT& wsy, Index g, const FT& at) const
  {
    const double sx = to_double_value(wsx), sy = to_double_value(wsy);
    const Point_2_ft<FT>& c = mesh_.he[std::size_t(g)].opposite;
    const double cx = to_double_value(c.x), cy = to_double_value(c.y), L = to_double_value(mesh_.he[std::size_t(g)].length);
    if(v == mesh_.source(g)) // g leaves v: the direction's angle from g, clockwise into the face behind it if negative
      return star_angle_[std::size_t(g)] + std::atan2(sy, sx);
    if(v == mesh_.target(g)) { // next(g) leaves v towards c: counterclockwise from it over g's face, then beyond
      const Index n = Mesh::next(g);
      return star_angle_[std::size_t(n)] + angle_from(std::atan2(sy, sx - L) - std::atan2(cy, cx - L));
    }
    const Index p = Mesh::prev(g); // leaves v (the opposite corner) towards source(g); counterclockwise over g's face
    return star_angle_[std::size_t(p)] + angle_from(std::atan2(-cy, to_double_value(at) - cx) - std::atan2(-cy, -cx));
  }

  // A direction at v brought into the range of v's angles: clamped to [0, total] at a boundary vertex, taken
  // modulo the total angle around an interior one.
  double normalized_arrival(Index v, double angle) const
  {
    const double total = vertex_total_angle_[std::size_t(v)];
    if(mesh_.vertex_on_boundary[std::size_t(v)])
      angle = angle < 0 ? 0 : (angle > total ? total : angle);
    else {
      angle = std::fmod(angle, total);
      if(angle < 0) angle += total;
    }
    return angle;
  }

  // Whether the face of h (leaving v) meets the shadow of v's arrival direction `beta` (normalized_arrival()): the
  // directions at least pi from it on both sides (on the surface's side at a boundary vertex), widened by a margin
  // for rounding.
  bool face_in_shadow(Index v, Index h, double beta) const
  {
    const double pi = 3.14159265358979323846, margin = 1e-6;
    const double total = vertex_total_angle_[std::size_t(v)];
    const double a = star_angle_[std::size_t(h)], corner = corner_angle_[std::size_t(h)];
    if(mesh_.vertex_on_boundary[std::size_t(v)])
      return a <= beta - pi + margin || a + corner >= beta + pi - margin;
    // the face's directions as offsets from beta in [0, total), possibly wrapping past total
    double s0 = std::fmod(a - beta, total);
    if(s0 < 0) s0 += total;
    const double s1 = s0 + corner, lo = pi - margin, hi = total - pi + margin;
    if(!(lo <= hi))
      return false; // no bend possible (a flat vertex within the margin)
    if(s0 <= hi && s1 >= lo)
      return true;
    return s1 - total >= lo; // the wrapped part [0, s1 - total]
  }

private:
  static double angle_from(double a) // into [0, 2 pi)
  {
    const double two_pi = 6.28318530717958647692;
    while(a < 0) a += two_pi;
    while(a >= two_pi) a -= two_pi;
    return a;
  }

  const Mesh& mesh_;
  std::vector<double> corner_angle_, star_angle_; // per halfedge
  std::vector<double> vertex_total_angle_;        // per vertex
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_SHADOW_H
