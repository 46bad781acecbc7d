// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The neighbourhood of a vertex as a compact mesh of its own: every face of a Geodesic_mesh within Euclidean distance
// R of the vertex (those reachable from its star through faces sharing a vertex), renumbered, with the halfedge records copied. A
// propagation limited to R runs on it at the cost of the neighbourhood: no array of the whole mesh is reset or
// scanned per run (the local distance matrix runs one such propagation from every vertex).
//
// Why it gives the distances of the whole mesh within R: a surface path of length <= R from the source stays in
// the Euclidean ball of radius R (every point of it is at geodesic, hence Euclidean, distance <= R), so it crosses
// only faces that meet the ball, consecutive ones sharing at least a vertex: the search from the star finds them all. The faces keep their order, the vertices and edges too, and each record
// is the original one (same frames, same lengths, bit for bit), so the engines see the same numbers; vertices on
// the cut are marked as boundary vertices, true of the submesh, and lie farther than R from the source.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_LOCAL_GEODESIC_SUBMESH_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_LOCAL_GEODESIC_SUBMESH_H

#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

// The squared distance from p to the triangle (a, b, c) (closest point by the regions of the triangle's plane).
inline double squared_distance_point_triangle_3(const std::array<double, 3>& p, const std::array<double, 3>& a,
                                                const std::array<double, 3>& b, const std::array<double, 3>& c)
{
  const auto sub = [](const std::array<double, 3>& u, const std::array<double, 3>& v) {
    return std::array<double, 3>{{u[0] - v[0], u[1] - v[1], u[2] - v[2]}};
  };
  const auto dot = [](const std::array<double, 3>& u, const std::array<double, 3>& v) {
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  };
  const auto dist2 = [&](const std::array<double, 3>& q) {
    const std::array<double, 3> d = sub(p, q);
    return dot(d, d);
  };
  const std::array<double, 3> ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if(d1 <= 0 && d2 <= 0) return dist2(a);
  const std::array<double, 3> bp = sub(p, b);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if(d3 >= 0 && d4 <= d3) return dist2(b);
  const double vc = d1 * d4 - d3 * d2;
  if(vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return dist2({{a[0] + v * ab[0], a[1] + v * ab[1], a[2] + v * ab[2]}});
  }
  const std::array<double, 3> cp = sub(p, c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if(d6 >= 0 && d5 <= d6) return dist2(c);
  const double vb = d5 * d2 - d1 * d6;
  if(vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return dist2({{a[0] + w * ac[0], a[1] + w * ac[1], a[2] + w * ac[2]}});
  }
  const double va = d3 * d6 - d5 * d4;
  if(va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return dist2({{b[0] + w * (c[0] - b[0]), b[1] + w * (c[1] - b[1]), b[2] + w * (c[2] - b[2])}});
  }
  const double sum = va + vb + vc;
  if(!(sum > 0)) // a degenerate triangle: the closest of its three edges' end points and the above
    return (std::min)({dist2(a), dist2(b), dist2(c)});
  const double v = vb / sum, w = vc / sum;
  return dist2({{a[0] + ab[0] * v + ac[0] * w, a[1] + ab[1] * v + ac[1] * w, a[2] + ab[2] * v + ac[2] * w}});
}

// One per thread: the stamps over the whole mesh are reused from one neighbourhood to the next (nothing of the
// whole mesh's size is cleared per neighbourhood; only the stamps' epoch advances).
class Local_geodesic_submesh
{
public:
  typedef Geodesic_mesh<double> Mesh;
  typedef Mesh::Index Index;

  explicit Local_geodesic_submesh(const Mesh& global)
    : g_(global), star_begin_(global.star_begin), star_(global.star), face_stamp_(global.number_of_faces, 0),
      face_in_(global.number_of_faces, 0), vertex_stamp_(global.number_of_vertices, 0),
      expanded_(global.number_of_vertices, 0), vertex_local_(global.number_of_vertices, 0)
  {}

  // The faces within Euclidean distance `radius` of vertex `source`, reached from its star.
  void build(Index source, double radius)
  {
    if(++epoch_ == 0) { // wrapped around: clear the stamps once
      std::fill(face_stamp_.begin(), face_stamp_.end(), 0u);
      std::fill(vertex_stamp_.begin(), vertex_stamp_.end(), 0u);
      std::fill(expanded_.begin(), expanded_.end(), 0u);
      epoch_ = 1;
    }
    const std::array<double, 3>& p = g_.points[std::size_t(source)];
    const double r2 = radius * radius;
    faces_.clear();
    // Breadth first across vertices (a path may pass from a face to any face around one of its vertices, also
    // around a pinched vertex); faces_ grows as faces are found inside.
    expanded_[std::size_t(source)] = epoch_;
    for(Index k = star_begin_[std::size_t(source)]; k < star_begin_[std::size_t(source) + 1]; ++k)
      visit(Mesh::face_of(star_[std::size_t(k)]), p, r2, true);
    for(std::size_t i = 0; i < faces_.size(); ++i) {
      const Index f = faces_[i];
      for(int c = 0; c < 3; ++c) {
        const Index v = g_.he[std::size_t(3 * f + c)].source;
        if(expanded_[std::size_t(v)] == epoch_) continue;
        expanded_[std::size_t(v)] = epoch_;
        for(Index k = star_begin_[std::size_t(v)]; k < star_begin_[std::size_t(v) + 1]; ++k)
          visit(Mesh::face_of(star_[std::size_t(k)]), p, r2, false);
      }
    }
    std::sort(faces_.begin(), faces_.end());
    assemble();
    source_ = vertex_local_[std::size_t(source)];
  }

  const Mesh& mesh() const { return m_; }
  Index local_source() const { return source_; }
  // The vertex of the whole mesh of local vertex v (increasing with v).
  Index global_vertex(Index v) const { return vertices_[std::size_t(v)]; }
  std::size_t number_of_faces() const { return faces_.size(); }

private:
  void visit(Index f, const std::array<double, 3>& p, double r2, bool inside)
  {
    if(face_stamp_[std::size_t(f)] == epoch_) return;
    face_stamp_[std::size_t(f)] = epoch_;
    if(!inside) {
      const Index h = 3 * f;
      inside = squared_distance_point_triangle_3(p, g_.points[std::size_t(g_.he[std::size_t(h)].source)],
                                                 g_.points[std::size_t(g_.he[std::size_t(h + 1)].source)],
                                                 g_.points[std::size_t(g_.he[std::size_t(h + 2)].source)]) <= r2;
    }
    face_in_[std::size_t(f)] = inside ? 1 : 0;
    if(inside) faces_.push_back(f);
  }

  bool included(Index f) const { return face_stamp_[std::size_t(f)] == epoch_ && face_in_[std::size_t(f)]; }

  // The compact mesh of faces_ (sorted), numbered as the builders of Geodesic_mesh number a mesh: halfedges, edges,
  // vertices and stars in the order of the whole mesh. An edge keeps the halfedges of its faces that are inside (the
  // twin, or the members of a non-manifold or reversed edge's cycle); an edge left with one halfedge is a border of
  // the neighbourhood (a cut, farther than R from the source: its vertices become boundary vertices).
  void assemble()
  {
    vertices_.clear();
    for(Index f : faces_)
      for(int k = 0; k < 3; ++k) {
        const Index v = g_.he[std::size_t(3 * f + k)].source;
        if(vertex_stamp_[std::size_t(v)] != epoch_) {
          vertex_stamp_[std::size_t(v)] = epoch_;
          vertices_.push_back(v);
        }
      }
    std::sort(vertices_.begin(), vertices_.end());
    for(std::size_t i = 0; i < vertices_.size(); ++i) vertex_local_[std::size_t(vertices_[i])] = Index(i);
    const std::size_t nf = faces_.size(), nh = 3 * nf, nv = vertices_.size();
    m_.number_of_vertices = nv;
    m_.number_of_faces = nf;
    m_.points.resize(nv);
    m_.vertex_angle_sum.resize(nv);
    m_.vertex_is_singular.assign(nv, 0);
    m_.number_of_pinched_vertices = m_.number_of_isolated_vertices = 0;
    for(std::size_t i = 0; i < nv; ++i) {
      const std::size_t g = std::size_t(vertices_[i]);
      m_.points[i] = g_.points[g];
      m_.vertex_angle_sum[i] = g_.vertex_angle_sum[g];
      if(!g_.vertex_is_singular.empty() && g_.vertex_is_singular[g]) {
        m_.vertex_is_singular[i] = 1;
        ++m_.number_of_pinched_vertices;
      }
    }
    // The local halfedge of a global one (its face inside): by binary search in the sorted faces_.
    const auto local_halfedge = [&](Index g) {
      const Index f = Mesh::face_of(g);
      return 3 * Index(std::lower_bound(faces_.begin(), faces_.end(), f) - faces_.begin()) + g % 3;
    };
    m_.he.resize(nh);
    for(std::size_t lf = 0; lf < nf; ++lf)
      for(int k = 0; k < 3; ++k) {
        const Index g = 3 * faces_[lf] + k, h = Index(3 * lf + std::size_t(k));
        Geodesic_halfedge<double> r = g_.he[std::size_t(g)];
        r.source = vertex_local_[std::size_t(r.source)];
        if(r.twin >= 0) { // an edge of an oriented manifold: the twin, if its face is inside
          r.twin = included(Mesh::face_of(r.twin)) ? local_halfedge(r.twin) : Index(-1);
          r.radial = r.twin >= 0 ? r.twin : h;
        } else {
          // a border, or a non-manifold or reversed edge: the next member of its cycle that is inside (the cycle
          // runs in increasing order, so it stays so among the members inside)
          Index next = r.radial;
          while(next != g && !included(Mesh::face_of(next))) next = g_.he[std::size_t(next)].radial;
          r.radial = next == g ? h : local_halfedge(next);
        }
        m_.he[std::size_t(h)] = r;
      }
    // Edges numbered in the order of their first halfedge, as the builders do.
    m_.edge_halfedge.clear();
    m_.number_of_border_edges = m_.number_of_nonmanifold_edges = m_.number_of_reversed_edges = 0;
    edge_done_.assign(nh, 0);
    for(std::size_t h = 0; h < nh; ++h) {
      if(edge_done_[h]) continue;
      const Index e = Index(m_.edge_halfedge.size());
      m_.edge_halfedge.push_back(Index(h));
      std::size_t members = 0;
      Index g = Index(h);
      do {
        m_.he[std::size_t(g)].edge = e;
        edge_done_[std::size_t(g)] = 1;
        ++members;
        g = m_.he[std::size_t(g)].radial;
      } while(g != Index(h));
      if(members == 1) ++m_.number_of_border_edges;
      else if(m_.he[h].twin < 0) (members >= 3 ? m_.number_of_nonmanifold_edges : m_.number_of_reversed_edges) += 1;
    }
    m_.number_of_edges = m_.edge_halfedge.size();
    // Stars (increasing halfedges per vertex, by a counting sort), one outgoing halfedge, boundary flags.
    m_.star_begin.assign(nv + 1, 0);
    for(std::size_t h = 0; h < nh; ++h) ++m_.star_begin[std::size_t(m_.he[h].source) + 1];
    for(std::size_t v = 0; v < nv; ++v) m_.star_begin[v + 1] += m_.star_begin[v];
    m_.star.resize(nh);
    for(std::size_t h = nh; h-- > 0;) m_.star[std::size_t(--m_.star_begin[std::size_t(m_.he[h].source) + 1])] = Index(h);
    for(std::size_t v = 0; v < nv; ++v) m_.star_begin[v] = m_.star_begin[v + 1];
    m_.star_begin[nv] = Index(nh);
    m_.vertex_halfedge.assign(nv, -1);
    m_.vertex_on_boundary.assign(nv, 0);
    for(std::size_t v = 0; v < nv; ++v) m_.vertex_halfedge[v] = m_.star[std::size_t(m_.star_begin[v])];
    for(std::size_t h = 0; h < nh; ++h)
      if(m_.he[h].radial == Index(h)) {
        m_.vertex_on_boundary[std::size_t(m_.he[h].source)] = 1;
        m_.vertex_on_boundary[std::size_t(m_.target(Index(h)))] = 1;
      }
  }

  const Mesh& g_;
  const Large_vector<Index>& star_begin_;
  const Large_vector<Index>& star_;
  std::vector<std::uint32_t> face_stamp_;
  std::vector<char> face_in_;
  std::vector<std::uint32_t> vertex_stamp_, expanded_;
  std::vector<Index> vertex_local_;
  std::uint32_t epoch_ = 0;
  std::vector<Index> faces_, vertices_;
  std::vector<char> edge_done_;
  Mesh m_;
  Index source_ = -1;
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_LOCAL_GEODESIC_SUBMESH_H
