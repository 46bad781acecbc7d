// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Hierarchical silhouette extraction: a tree over the edges of a triangle face graph, built once, that finds
// the silhouette of each view without classifying every face (thesis 5.1, after Sander et al. 2000).

#ifndef CGAL_SILHOUETTE_SIMPLIFICATION_3_SILHOUETTE_EDGE_HIERARCHY_3_H
#define CGAL_SILHOUETTE_SIMPLIFICATION_3_SILHOUETTE_EDGE_HIERARCHY_3_H

#include <CGAL/Silhouette_simplification_3/View_3.h>
#include <CGAL/Silhouette_simplification_3/internal/Edge_cone_hierarchy.h>
#include <CGAL/Silhouette_simplification_3/internal/Indexed_mesh.h>

#include <CGAL/boost/graph/properties.h>

#include <cstdint>
#include <vector>

namespace CGAL {
namespace Silhouette_simplification_3 {

/*!
  \ingroup PkgSilhouetteSimplification3Ref
  \brief A bounding-cone hierarchy over the edges of a triangle mesh for fast silhouette extraction.

  The constructor copies the mesh into flat arrays and groups its edges in a binary tree (median splits of
  the edges by midpoint and normal). Each node bounds the normals of the faces next to its edges by a cone
  and their supporting planes by a range of offsets, which proves for a view that all these faces face the
  same way: the node holds no silhouette edge and is skipped. The leaves classify the faces with the exact
  predicate of `View_3`, so `silhouette_halfedges()` returns exactly the halfedges of the free function
  `silhouette_halfedges(tm, view, out)`, in the same order (by increasing index in the flat copy), for every
  perspective or orthographic view. Faces whose floating-point normal is not reliable (zero-area faces,
  slivers) stay out of the tree; their edges are tested at every query.

  The mesh must not change after construction. Queries are `const` and may run concurrently.

  \tparam TriangleMesh a model of `FaceListGraph` with triangle faces
  \tparam VertexPointMap its vertex point map; the kernel is deduced from its value type
*/
template <class TriangleMesh,
          class VertexPointMap = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>
class Silhouette_edge_hierarchy_3
{
public:
  typedef typename boost::property_traits<VertexPointMap>::value_type Point_3;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  /// \throws std::invalid_argument when a face is not a triangle, the mesh has no face, a coordinate is not
  /// finite, the bounding box diagonal is outside [1e-30, 1e30], or the options are invalid
  explicit Silhouette_edge_hierarchy_3(const TriangleMesh& tm,
                                       const Silhouette_hierarchy_options& options = Silhouette_hierarchy_options())
  {
    init(tm, get(CGAL::vertex_point, tm), options);
  }

  Silhouette_edge_hierarchy_3(const TriangleMesh& tm, VertexPointMap vpm,
                              const Silhouette_hierarchy_options& options = Silhouette_hierarchy_options())
  {
    init(tm, vpm, options);
  }

  /// Writes the silhouette halfedges for `view` to `out` (front face on the left); `stats`, if given,
  /// receives the number of nodes and edges examined.
  template <class View, class OutputIterator>
  OutputIterator silhouette_halfedges(const View& view, OutputIterator out,
                                      Silhouette_hierarchy_statistics* stats = nullptr) const
  {
    std::vector<std::uint32_t> sil;
    tree_.query(mesh_, view, sil, stats);
    for(std::uint32_t h : sil) *out++ = halfedge_[h];
    return out;
  }

  /// The same as indices of the flat copy (see `index_mesh()`), into a reused vector.
  template <class View>
  void silhouette_indices(const View& view, std::vector<std::uint32_t>& out,
                          Silhouette_hierarchy_statistics* stats = nullptr) const
  {
    tree_.query(mesh_, view, out, stats);
  }

  /// The halfedge descriptor of index `h` of the flat copy.
  halfedge_descriptor halfedge(std::uint32_t h) const { return halfedge_[h]; }
  /// The flat copy of the mesh.
  const internal::Indexed_mesh<Point_3>& index_mesh() const { return mesh_; }
  std::size_t number_of_nodes() const { return tree_.number_of_nodes(); }
  /// Edges next to faces without a reliable normal, tested at every query.
  std::size_t number_of_edges_outside_the_tree() const { return tree_.number_of_edges_outside_the_tree(); }
  /// Bytes held by the tree (not counting the flat copy of the mesh).
  std::size_t tree_memory_bytes() const { return tree_.memory_bytes(); }

private:
  void init(const TriangleMesh& tm, VertexPointMap vpm, const Silhouette_hierarchy_options& options)
  {
    std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> fd;
    std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> vd;
    internal::build_indexed_mesh(tm, vpm, mesh_, halfedge_, fd, vd, "Silhouette_edge_hierarchy_3");
    tree_.build(mesh_, options);
  }

  internal::Indexed_mesh<Point_3> mesh_;
  std::vector<halfedge_descriptor> halfedge_;
  internal::Edge_cone_hierarchy tree_;
};

} // namespace Silhouette_simplification_3
} // namespace CGAL

#endif // CGAL_SILHOUETTE_SIMPLIFICATION_3_SILHOUETTE_EDGE_HIERARCHY_3_H
