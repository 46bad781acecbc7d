// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Approximate geodesic distances and shortest paths on a triangle mesh by the flat-exact algorithm (one
// interval per edge, exact on planar meshes; thesis, chapter 4.3): the public class. The work is in
// internal/flat_exact_propagation.h.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_FLAT_EXACT_GEODESIC_DISTANCES_3_H
#define CGAL_POLYHEDRAL_GEODESICS_3_FLAT_EXACT_GEODESIC_DISTANCES_3_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_types.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_distances_facade.h>
#include <CGAL/Polyhedral_geodesics_3/internal/flat_exact_propagation.h>

#include <CGAL/boost/graph/properties.h>

#include <memory>
#include <utility>

namespace CGAL {
namespace Polyhedral_geodesics_3 {

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief Approximate geodesic distances, nearest sources and shortest paths on a triangle mesh by the
  *flat-exact* algorithm: one interval per edge, exact on planar meshes, at about the cost of fast marching
  (0.8 to 1.1 times on CGAL's demo meshes, construction included; up to 2 times where vertices are lowered
  repeatedly, e.g. next to boundaries of subdivided meshes).

  The algorithm is the simplified interval propagation of the thesis's chapter 4.3. Distances are kept at
  the vertices only; the distance function of an edge is rebuilt from the distances of its two vertices as
  the distance to a pseudo-source at zero offset (of its two mirror images, the one on the side away from the
  face the edge propagates into). Edges are propagated across their faces in the order of the smallest value
  they give: the opposite vertex gets the Euclidean distance to the pseudo-source when it sees it through the
  edge, otherwise the distance along one of the two other edges of the face. A vertex whose distance is
  lowered queues the edges around it again. One refinement keeps the planar exactness and helps around holes:
  behind a saddle vertex or a reflex boundary vertex (a hole's corner) the pseudo-sources are rebuilt with the
  offset of that vertex, so that the distance there is measured from the corner; where two such windows meet
  on an edge, the smaller of their offsets is used (the flatter of the two fronts).

  The propagation maintains a *dependence DAG* (thesis, 4.2.1 and 4.3.2) whose nodes are the edges: the edge a
  vertex was lowered from is a parent of every edge around that vertex, and an edge has as further parents
  edges of the adjacent face whose pseudo-source best explains the distance at its opposite vertex. A lowering
  that would close a cycle is refused, so the propagation terminates, and shortest paths, traced back from
  child to parent (from an edge to a parent edge straight toward the rebuilt pseudo-source, through a vertex
  where the distance came along an edge), always reach a source. The statistics count the lowerings
  (`vertex_updates`) and the refused ones (`updates_rejected_by_dag`).

  Accuracy:
  - On a planar mesh (a triangulation of a convex planar domain) the distances at the vertices and at any point,
    and the paths, are those of the plane up to rounding, from vertex or point sources. Exceptions: next to the
    bisector of two sources, an edge whose two vertices have different nearest sources propagates along its
    vertices only, which gives values a little too long (measured: 2% at most, never too short) just beyond it;
    a path that crosses a zero-area triangle bends at one of its corners (the distances stay exact).
  - On curved meshes every value is an approximation: one interval per edge cannot represent a distance
    function made of several windows, and the rebuilt pseudo-sources drift from step to step. Most exact
    shortest paths bend at saddle vertices (those to 36-99% of the vertices on 29 curved meshes), in wedges
    behind them too narrow for the edges to resolve, so the rebuilt fronts are flatter than the real ones and
    the values mostly a little too long (the manual, *What the tracked windows miss*). The error is
    largest where wavefronts meet behind an obstacle (a hole, a protrusion, the far side of a handle), where the
    single interval oversimplifies the field and the traced geodesics are visibly distorted; values can there be
    too short or too long. Measured mean relative errors against `Exact_geodesic_distances_3` on CGAL's demo
    meshes: 0.2% to 1.1% for the distances (2 to 5 times less than fast marching), 0.02% to 0.65% for the lengths
    of the traced paths (the measure of the thesis). `set_path_shortening(true)` makes the paths locally
    shortest (straight in every unfolding, through saddle and border vertices only): 0.0003% to 0.09% longer
    than the geodesics on the benchmark's 11 meshes of 8k-151k vertices, for a few hundred microseconds per
    path. For exact values use `Exact_geodesic_distances_3`.

  Usage: construct once per mesh, add sources, then query; the propagation runs on the first query (or
  explicitly with `compute()`) and again only after the sources or the options change. The progress stage is
  `"flat-exact propagation"`, its fraction the share of vertices whose distance is final. The data needed by
  shortest paths (the second kind of parents above) is built with the first path query.

  \tparam TriangleMesh a model of `FaceGraph` whose faces are all triangles (checked: other faces are rejected
          with `std::invalid_argument`). No internal indices are required.
  \tparam FT_ the number type of the computation (default `double`).
  \tparam VertexPointMap a readable property map from vertices to 3D points of any CGAL kernel.

  The memory mode is accepted for interface compatibility: the field (a distance per vertex and an interval per
  edge) is always kept, so both modes use the same memory; as for every distance class, point queries and
  shortest paths need `Geodesic_memory_mode::full_field` and throw `std::logic_error` with `distances_only`.
  Unreachable points (another connected component than every source, or farther than the distance limit) have
  distance `+infinity` and no nearest source (`std::size_t(-1)`); paths to them are empty. With a distance limit
  or stop targets, vertices whose distance is not final when the propagation stops report `+infinity`.
*/
template <class TriangleMesh, class FT_ = double,
          class VertexPointMap = typename internal::Default_vertex_point_map<TriangleMesh>::type>
class Flat_exact_geodesic_distances_3
  : public internal::Geodesic_distances_facade<TriangleMesh, FT_, VertexPointMap,
                                               internal::Flat_exact_propagation<FT_>>
{
  typedef internal::Geodesic_distances_facade<TriangleMesh, FT_, VertexPointMap,
                                              internal::Flat_exact_propagation<FT_>> Base;

public:
  /// Precomputes the compact mesh. Throws `std::invalid_argument` on non-triangle faces.
  explicit Flat_exact_geodesic_distances_3(const TriangleMesh& tm,
                                           Geodesic_memory_mode mode = Geodesic_memory_mode::full_field)
    : Base(tm, get(CGAL::vertex_point, tm), mode)
  {}

  Flat_exact_geodesic_distances_3(const TriangleMesh& tm, VertexPointMap vpm,
                                  Geodesic_memory_mode mode = Geodesic_memory_mode::full_field)
    : Base(tm, vpm, mode)
  {}

  /// On a prepared surface (see `Geodesic_surface_3`), shared with other objects: nothing is rebuilt.
  explicit Flat_exact_geodesic_distances_3(std::shared_ptr<const typename Base::Surface> surface,
                                           Geodesic_memory_mode mode = Geodesic_memory_mode::full_field)
    : Base(std::move(surface), mode, &special_edges_refusal)
  {}

  /// On a prepared surface that outlives the object.
  explicit Flat_exact_geodesic_distances_3(const typename Base::Surface& surface,
                                           Geodesic_memory_mode mode = Geodesic_memory_mode::full_field)
    : Base(surface, mode, &special_edges_refusal)
  {}

private:
  // A prepared surface with non-manifold or reversed edges is refused: the engine follows `twin` alone.
  static constexpr internal::Special_edges_refusal special_edges_refusal = {
      "Flat_exact_geodesic_distances_3",
      "flat-exact rebuilds the distance function of an edge on its two sides (a pseudo-source and its mirror "
      "image) and propagates it into the face on each side, which needs every edge to have at most two faces that "
      "run through it in opposite directions"};
};

} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_FLAT_EXACT_GEODESIC_DISTANCES_3_H
