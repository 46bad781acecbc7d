// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Types exchanged between the public geodesic classes (through Geodesic_distances_facade) and the
// propagation engines: a node of a traced path and the answer of a point query.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_GEODESIC_ENGINE_TYPES_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_GEODESIC_ENGINE_TYPES_H

#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>

#include <array>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

// One point of a traced shortest path, in compact-mesh terms.
template <class FT>
struct Geodesic_path_node
{
  typedef typename Geodesic_mesh<FT>::Index Index;
  enum Kind { VERTEX, EDGE, FACE };
  Kind kind;
  Index index;                   // vertex, compact halfedge, or face
  FT t;                          // EDGE: the point is (1-t) source + t target of the halfedge
  std::array<FT, 3> barycentric; // FACE
  std::array<FT, 3> point;       // the 3D point
};

// The distance at a surface point and the source it comes from (-1: unreachable).
template <class FT>
struct Geodesic_point_distance
{
  FT distance;
  typename Geodesic_mesh<FT>::Index source;
};

// The 3D point with barycentric coordinates b in face f (corners source(3f), source(3f+1), source(3f+2)).
template <class FT>
std::array<FT, 3> point_in_face(const Geodesic_mesh<FT>& mesh, typename Geodesic_mesh<FT>::Index f,
                                const std::array<FT, 3>& b)
{
  std::array<FT, 3> p = {FT(0), FT(0), FT(0)};
  for(int k = 0; k < 3; ++k) {
    const auto& q = mesh.points[std::size_t(mesh.source(3 * f + k))];
    for(int i = 0; i < 3; ++i)
      p[std::size_t(i)] += b[std::size_t(k)] * q[std::size_t(i)];
  }
  return p;
}

// Path nodes shared by every engine's trace_path: at a vertex, at ratio r along halfedge g, inside a face.
template <class FT>
Geodesic_path_node<FT> vertex_path_node(const Geodesic_mesh<FT>& mesh, typename Geodesic_mesh<FT>::Index v)
{
  return Geodesic_path_node<FT>{Geodesic_path_node<FT>::VERTEX, v, FT(0), {FT(0), FT(0), FT(0)},
                                mesh.points[std::size_t(v)]};
}

template <class FT>
Geodesic_path_node<FT> edge_path_node(const Geodesic_mesh<FT>& mesh, typename Geodesic_mesh<FT>::Index g, const FT& r)
{
  const auto& a = mesh.points[std::size_t(mesh.source(g))];
  const auto& c = mesh.points[std::size_t(mesh.target(g))];
  std::array<FT, 3> p;
  for(int i = 0; i < 3; ++i)
    p[std::size_t(i)] = (FT(1) - r) * a[std::size_t(i)] + r * c[std::size_t(i)];
  return Geodesic_path_node<FT>{Geodesic_path_node<FT>::EDGE, g, r, {FT(0), FT(0), FT(0)}, p};
}

template <class FT>
Geodesic_path_node<FT> face_path_node(const Geodesic_mesh<FT>& mesh, typename Geodesic_mesh<FT>::Index f,
                                      const std::array<FT, 3>& b)
{
  return Geodesic_path_node<FT>{Geodesic_path_node<FT>::FACE, f, FT(0), b, point_in_face(mesh, f, b)};
}

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_GEODESIC_ENGINE_TYPES_H
