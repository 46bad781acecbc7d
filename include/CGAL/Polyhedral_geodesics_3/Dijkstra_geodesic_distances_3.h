// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The simplest baseline of the package: shortest paths along the mesh edges (Dijkstra), behind the public
// interface of every geodesic distance class. The work is in internal/dijkstra_edge_propagation.h.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_DIJKSTRA_GEODESIC_DISTANCES_3_H
#define CGAL_POLYHEDRAL_GEODESICS_3_DIJKSTRA_GEODESIC_DISTANCES_3_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_types.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_distances_facade.h>
#include <CGAL/Polyhedral_geodesics_3/internal/dijkstra_edge_propagation.h>

#include <CGAL/boost/graph/properties.h>

#include <memory>
#include <utility>

namespace CGAL {
namespace Polyhedral_geodesics_3 {

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief Approximate geodesic distances by the lengths of the shortest paths along the mesh edges
  (Dijkstra's algorithm on the edge graph weighted by the edge lengths), with the interface of
  `Exact_geodesic_distances_3`.

  What is approximated: the distance from the sources to a vertex is the length of the shortest polyline
  that follows mesh edges. It is never smaller than the geodesic distance, equal to it where a shortest
  path happens to follow edges, and larger otherwise, by an amount that does not vanish when the mesh is
  refined (the edge graph has only a few directions): the mean relative error at the vertices is about 5%
  on planar grids, on CGAL's elephant and on its refined version alike, and single vertices are off by up
  to 40% (two grid edges instead of a missing diagonal). It is the fastest method
  (\f$ O(n \log n) \f$ on a mesh with \f$ n \f$ vertices) and the reference for how much the other classes
  improve on the edge graph.

  - A source at a surface point (`Face_location`) gives the corners of its face (and of the face on the
    other side when it lies on an edge) their straight distance to the point.
  - At a surface point the distance is the minimum over the corners `v` of its face of
    `d(v) + |p - v|`, and the straight distance to a source in the same face.
  - Shortest paths run along mesh edges: the query point, the vertices of the edge path, the source
    (a vertex, or the surface point). Their length equals the reported distance. With
    `set_path_shortening(true)` they are made locally shortest instead, across the faces (0.005 to 0.29%
    longer than the geodesics on the benchmark's 11 meshes, against 4 to 8% along the edges); their length
    is then at most the reported distance.
  - The memory mode only controls which queries are allowed (`distances_only` forbids point queries and
    paths); the engine keeps nothing but per-vertex arrays.
  - Distance limit: vertices farther than the limit report `+infinity`. Stop targets: the propagation
    stops as soon as every target is final; the vertices that are not final then report `+infinity`.
  - Progress: the stage is `"dijkstra"`, the fraction the share of vertices whose distance is final.

  \tparam TriangleMesh a model of `FaceGraph` whose faces are all triangles (checked: other faces are
          rejected with `std::invalid_argument`).
  \tparam FT_ the number type of the computation (`double` by default).
  \tparam VertexPointMap a readable property map from vertices to 3D points of any CGAL kernel.
*/
template <class TriangleMesh, class FT_ = double,
          class VertexPointMap = typename internal::Default_vertex_point_map<TriangleMesh>::type>
class Dijkstra_geodesic_distances_3
  : public internal::Geodesic_distances_facade<TriangleMesh, FT_, VertexPointMap,
                                               internal::Dijkstra_edge_propagation<FT_>>
{
  typedef internal::Geodesic_distances_facade<TriangleMesh, FT_, VertexPointMap,
                                              internal::Dijkstra_edge_propagation<FT_>> Base;

public:
  /// Precomputes the compact mesh. Throws `std::invalid_argument` on non-triangle faces.
  explicit Dijkstra_geodesic_distances_3(const TriangleMesh& tm,
                                         Geodesic_memory_mode mode = Geodesic_memory_mode::full_field)
    : Base(tm, get(CGAL::vertex_point, tm), mode)
  {}

  Dijkstra_geodesic_distances_3(const TriangleMesh& tm, VertexPointMap vpm,
                                Geodesic_memory_mode mode = Geodesic_memory_mode::full_field)
    : Base(tm, vpm, mode)
  {}

  /// On a prepared surface (see `Geodesic_surface_3`), shared with other objects: nothing is rebuilt.
  explicit Dijkstra_geodesic_distances_3(std::shared_ptr<const typename Base::Surface> surface,
                                         Geodesic_memory_mode mode = Geodesic_memory_mode::full_field)
    : Base(std::move(surface), mode)
  {}

  /// On a prepared surface that outlives the object.
  explicit Dijkstra_geodesic_distances_3(const typename Base::Surface& surface,
                                         Geodesic_memory_mode mode = Geodesic_memory_mode::full_field)
    : Base(surface, mode)
  {}
};

} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_DIJKSTRA_GEODESIC_DISTANCES_3_H
