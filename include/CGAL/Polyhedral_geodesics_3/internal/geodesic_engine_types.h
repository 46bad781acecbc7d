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

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_GEODESIC_ENGINE_TYPES_H
