// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Planar_dual: the embedding of a planar Flow_network, as the dual edge of every facet.

#ifndef CGAL_MIN_CUT_PLANAR_DUAL_H
#define CGAL_MIN_CUT_PLANAR_DUAL_H

#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Min_cut {

/*!
  \ingroup PkgMinCutRef
  \brief The planar embedding of a `Flow_network` whose source and sink both lie on the outer face, given
  as the dual edge of every facet. It is what `solve_planar_min_cut()` needs besides the network.

  When the network is the dual graph of a planar complex (cells = nodes, facets = edges of the complex),
  the dual edge of a facet is simply the primal edge between the facet's two end vertices, and the dual
  vertices are the vertices of the complex. The orientation carries the direction of the cut:

  - an interior facet `(u, v)` of the network is the dual edge `a -> b` with node `u` on its **right**
    (so crossing it from `u` to `v`, the cut arc `u->v`, means walking `a -> b` with the source side on
    the right);
  - a source facet (source -> `node`) is the dual edge with the source on its right, i.e. `node` on its left;
  - a sink facet (`node` -> sink) is the dual edge with `node` on its right.

  The outer face is split in two by the terminals: its boundary runs from the source facets to the sink
  facets and back. `start_vertices` are the dual vertices where a cut may begin on one side (walking with
  the source side on the right), `end_vertices` where it ends; several of each when boundary facets were
  removed (relaxed boundaries: the dual vertices between removed facets are all admissible).
  For the dual of a line arrangement with a curve problem, the start vertices are the admissible points of
  the left wall and the end vertices those of the right wall.

  `edges`, `source_edges` and `sink_edges` are parallel to `Flow_network::facets()`, `source_facets()` and
  `sink_facets()`.
*/
struct Planar_dual
{
  typedef std::uint32_t Vertex_index;

  /// A dual edge, oriented as described above.
  struct Edge
  {
    Vertex_index a, b;
  };

  std::size_t number_of_vertices = 0;
  std::vector<Edge> edges;         ///< one per interior facet of the network, in the same order
  std::vector<Edge> source_edges;  ///< one per source facet
  std::vector<Edge> sink_edges;    ///< one per sink facet
  std::vector<Vertex_index> start_vertices;
  std::vector<Vertex_index> end_vertices;

  void clear()
  {
    number_of_vertices = 0;
    std::vector<Edge>().swap(edges);
    std::vector<Edge>().swap(source_edges);
    std::vector<Edge>().swap(sink_edges);
    start_vertices.clear();
    end_vertices.clear();
  }
};

} // namespace Min_cut
} // namespace CGAL

#endif // CGAL_MIN_CUT_PLANAR_DUAL_H
