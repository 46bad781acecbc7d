// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Free functions on any triangle face graph: the silhouette halfedges of a view and their loops.

#ifndef CGAL_SILHOUETTE_SIMPLIFICATION_3_SILHOUETTE_EDGES_H
#define CGAL_SILHOUETTE_SIMPLIFICATION_3_SILHOUETTE_EDGES_H

#include <CGAL/Silhouette_simplification_3/View_3.h>
#include <CGAL/Silhouette_simplification_3/internal/Indexed_mesh.h>
#include <CGAL/Silhouette_simplification_3/internal/silhouette_extraction.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/properties.h>

#include <vector>

namespace CGAL {
namespace Silhouette_simplification_3 {

/*!
  \ingroup PkgSilhouetteSimplification3Ref
  \brief Writes to `out` the silhouette halfedges of `tm` for `view`: every halfedge whose face is
  front-facing (see `View_3`) and whose opposite halfedge is on the mesh border or has a back-facing
  face. The front face is on the left of each halfedge.

  The silhouette is the boundary of the front-facing region, so on any triangle mesh (closed or not;
  border edges of front-facing faces are part of it) every vertex has as many incoming as outgoing
  silhouette halfedges, and the silhouette splits into closed loops.

  \throws std::invalid_argument when a face is not a triangle or the mesh has no face
*/
template <class TriangleMesh, class View, class OutputIterator, class VertexPointMap>
OutputIterator silhouette_halfedges(const TriangleMesh& tm, const View& view, OutputIterator out, VertexPointMap vpm)
{
  internal::Indexed_mesh<typename boost::property_traits<VertexPointMap>::value_type> im;
  std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor> hd;
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> fd;
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> vd;
  internal::build_indexed_mesh(tm, vpm, im, hd, fd, vd, "silhouette_halfedges");
  std::vector<char> front;
  std::vector<std::uint32_t> sil;
  internal::classify_faces(im, view, front);
  internal::silhouette_from_faces(im, front, sil);
  for(std::uint32_t h : sil) *out++ = hd[h];
  return out;
}

/// Same with the mesh's internal vertex point map.
template <class TriangleMesh, class View, class OutputIterator>
OutputIterator silhouette_halfedges(const TriangleMesh& tm, const View& view, OutputIterator out)
{
  return silhouette_halfedges(tm, view, out, get(CGAL::vertex_point, tm));
}

/*!
  \ingroup PkgSilhouetteSimplification3Ref
  \brief Splits a set of directed halfedges of `tm` into loops without repeated vertices (thesis 5.2.1).

  The walk starts at the first unused halfedge, follows unused halfedges out of the current vertex
  (the first one in input order at a crossing) and snaps off a sub-loop whenever it reaches a vertex
  already on its path. When the input is a union of cycles (a silhouette) every loop is closed;
  otherwise the walk may stop at a vertex without unused outgoing halfedges, and the path is reported
  as an open chain (`closed == false`). Deterministic: the result depends only on the input order.
*/
template <class TriangleMesh, class HalfedgeRange>
std::vector<Silhouette_loop<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>>
decompose_into_loops(const TriangleMesh& tm, const HalfedgeRange& halfedges)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  auto vid = get(CGAL::dynamic_vertex_property_t<std::uint32_t>(), tm);
  // A small indexed view: only sources and opposites of the given halfedges are needed.
  internal::Indexed_mesh<int> im;
  std::uint32_t nv = 0;
  for(auto v : vertices(tm)) put(vid, v, nv++);
  im.points.assign(nv, 0);
  std::vector<halfedge_descriptor> hd;
  std::vector<std::uint32_t> edges;
  for(halfedge_descriptor h : halfedges) {
    const std::uint32_t i = std::uint32_t(im.source.size());
    im.source.push_back(get(vid, source(h, tm)));
    im.source.push_back(get(vid, target(h, tm)));
    im.opposite.push_back(i + 1);
    im.opposite.push_back(i);
    hd.push_back(h);
    hd.push_back(opposite(h, tm));
    edges.push_back(i);
  }
  std::vector<Silhouette_loop<std::uint32_t>> loops;
  internal::Loop_decomposer()(im, edges, loops);
  std::vector<Silhouette_loop<halfedge_descriptor>> result(loops.size());
  for(std::size_t l = 0; l < loops.size(); ++l) {
    result[l].closed = loops[l].closed;
    for(std::uint32_t h : loops[l].halfedges) result[l].halfedges.push_back(hd[h]);
  }
  return result;
}

} // namespace Silhouette_simplification_3
} // namespace CGAL

#endif // CGAL_SILHOUETTE_SIMPLIFICATION_3_SILHOUETTE_EDGES_H
