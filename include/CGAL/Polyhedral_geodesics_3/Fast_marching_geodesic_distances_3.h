// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The classical approximate baseline of the package: fast marching on triangle meshes (Kimmel and Sethian
// 1998), behind the public interface of every geodesic distance class. The work is in
// internal/fast_marching_propagation.h.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_FAST_MARCHING_GEODESIC_DISTANCES_3_H
#define CGAL_POLYHEDRAL_GEODESICS_3_FAST_MARCHING_GEODESIC_DISTANCES_3_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_types.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_distances_facade.h>
#include <CGAL/Polyhedral_geodesics_3/internal/fast_marching_propagation.h>

#include <CGAL/boost/graph/properties.h>

#include <memory>
#include <utility>

namespace CGAL {
namespace Polyhedral_geodesics_3 {

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief Approximate geodesic distances by fast marching on the triangle mesh (Kimmel and Sethian,
  "Computing geodesic paths on manifolds", 1998), with the interface of `Exact_geodesic_distances_3`.

  What is approximated: the solution of the eikonal equation \f$ |\nabla T| = 1 \f$ on the surface,
  discretised at the vertices. A vertex is updated from two final corners of a triangle by the planar
  wavefront through them, if the wavefront reaches it from inside the triangle (causality), and otherwise
  along the edges; obtuse corners also use two acute virtual triangles made by unfolding neighbouring
  faces (Kimmel and Sethian's fix, at most 30 unfoldings, none across the boundary). A binary heap orders the
  narrow band: \f$ O(n \log n) \f$ on a mesh with \f$ n \f$ vertices.

  Error expectations: the method is first order. The front is approximated by a plane in every
  triangle, which overestimates the distance where the front is strongly curved, on the first rings of
  vertices around a point source (errors of 10 to 20% there), and that error is carried along. The mean
  relative error at the vertices was measured at 1 to 3% on planar grids and on a noisy sphere, 2.3% on
  CGAL's elephant (2775 vertices) and 0.9% on its refined version (44k vertices), against about 5% for
  `Dijkstra_geodesic_distances_3`. A source at a surface point initialises only the three corners of its
  face and gives somewhat larger errors (3 to 4% on planar grids). Guarantees: the values never exceed
  Dijkstra's distances along the edges; a planar front (sources along a straight boundary of a planar
  mesh) is reproduced to rounding, also on irregular meshes with obtuse triangles (thanks to the
  unfoldings); on a convex planar mesh the distance from one source is never underestimated. On a curved surface the values can be slightly below the geodesic
  distance (by less than 1% on the meshes measured).

  - A source at a surface point (`Face_location`) gives the corners of its face (and of the face on the
    other side when it lies on an edge) their straight distance to the point.
  - At a surface point the distance is the linear interpolation of the three corner values, or the
    straight distance to a source in the same face where that is smaller.
  - Shortest paths descend the field. Inside a face a path runs against the gradient of the interpolated
    values (a straight segment up to the face's border); it goes on into the next face while that face's
    descent leaves the shared edge, follows the edge down where both faces descend towards it (a valley or a
    border edge), and leaves a vertex in its steepest descent (into a face or along an edge). Near a source it
    goes straight to it (inside the face that holds it, or across one edge) when that segment is not longer than
    the value where it starts. A path stays with the nearest source of its query point, ends there, and is a
    path on the surface: its length is at least the geodesic distance. Where the descent cannot go on (a face
    beyond the front of a run stopped at a limit or at targets, a degenerate face) it continues along the chain
    of neighbours each vertex was updated from, which always ends at the source. Measured on 11 meshes of
    8k-151k vertices (`bench_approximate_geodesics --path-error 2000`), the paths are 0.06 to 0.88% longer
    than the geodesics on average (along the predecessor chain, as before this rule, 7 to 15%); on mechanical
    parts with needle triangles and many holes, where the values are poor too, up to 6 to 8% (CGAL's cheese,
    boeing, oblong). Those of `Flat_exact_geodesic_distances_3` are closer still (0.01 to 0.56% on the 11
    meshes, 1.5 to 8 times less). `set_path_shortening(true)` makes them locally shortest (0.0002 to 0.076%
    on the 11 meshes).
  - The memory mode only controls which queries are allowed (`distances_only` forbids point queries and
    paths); the engine keeps nothing but per-vertex arrays and the per-corner update triangles.
  - Distance limit: vertices whose value exceeds the limit report `+infinity`. Stop targets: the
    propagation stops as soon as every target is final; the vertices that are not final then report
    `+infinity`, and so does a surface point whose interpolation needs such a vertex.
  - Progress: the stage is `"fast marching"`, the fraction the share of vertices whose value is final.

  \tparam TriangleMesh a model of `FaceGraph` whose faces are all triangles (checked: other faces are
          rejected with `std::invalid_argument`).
  \tparam FT_ the number type of the computation (`double` by default).
  \tparam VertexPointMap a readable property map from vertices to 3D points of any CGAL kernel.
*/
template <class TriangleMesh, class FT_ = double,
          class VertexPointMap = typename internal::Default_vertex_point_map<TriangleMesh>::type>
class Fast_marching_geodesic_distances_3
  : public internal::Geodesic_distances_facade<TriangleMesh, FT_, VertexPointMap,
                                               internal::Fast_marching_propagation<FT_>>
{
  typedef internal::Geodesic_distances_facade<TriangleMesh, FT_, VertexPointMap,
                                              internal::Fast_marching_propagation<FT_>> Base;

public:
  /// Precomputes the compact mesh and the update triangles of every corner. Throws
  /// `std::invalid_argument` on non-triangle faces.
  explicit Fast_marching_geodesic_distances_3(const TriangleMesh& tm,
                                              Geodesic_memory_mode mode = Geodesic_memory_mode::full_field)
    : Base(tm, get(CGAL::vertex_point, tm), mode)
  {}

  Fast_marching_geodesic_distances_3(const TriangleMesh& tm, VertexPointMap vpm,
                                     Geodesic_memory_mode mode = Geodesic_memory_mode::full_field)
    : Base(tm, vpm, mode)
  {}

  /// On a prepared surface (see `Geodesic_surface_3`), shared with other objects: nothing is rebuilt.
  explicit Fast_marching_geodesic_distances_3(std::shared_ptr<const typename Base::Surface> surface,
                                              Geodesic_memory_mode mode = Geodesic_memory_mode::full_field)
    : Base(std::move(surface), mode, &special_edges_refusal)
  {}

  /// On a prepared surface that outlives the object.
  explicit Fast_marching_geodesic_distances_3(const typename Base::Surface& surface,
                                              Geodesic_memory_mode mode = Geodesic_memory_mode::full_field)
    : Base(surface, mode, &special_edges_refusal)
  {}

private:
  // A prepared surface with non-manifold or reversed edges is refused: the engine follows `twin` alone.
  static constexpr internal::Special_edges_refusal special_edges_refusal = {
      "Fast_marching_geodesic_distances_3",
      "fast marching unfolds obtuse corners across an edge into its twin's face and descends its paths from face "
      "to face across edges, which needs every edge to have at most two faces that run through it in opposite "
      "directions"};
};

} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_FAST_MARCHING_GEODESIC_DISTANCES_3_H
