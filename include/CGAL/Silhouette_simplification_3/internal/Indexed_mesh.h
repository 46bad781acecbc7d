// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A flat, index-based copy of a triangle face graph: the per-view stages (extraction, decomposition,
// picking, mapping) run on arrays, whatever the input data structure.

#ifndef CGAL_SILHOUETTE_SIMPLIFICATION_3_INTERNAL_INDEXED_MESH_H
#define CGAL_SILHOUETTE_SIMPLIFICATION_3_INTERNAL_INDEXED_MESH_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/MDCS/internal/bounding_box.h>
#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Silhouette_simplification_3 {
namespace internal {

constexpr std::uint32_t NONE = std::numeric_limits<std::uint32_t>::max();

// Halfedge 3f+k of face f runs from corner k to corner k+1 (the face lies on its left). Halfedges on the
// border of the mesh (whose face is null) get the indices 3F, 3F+1, ... .
template <class Point_3>
struct Indexed_mesh
{
  std::vector<Point_3> points;
  std::vector<std::array<std::uint32_t, 3>> faces;
  std::vector<std::uint32_t> source;   // per halfedge
  std::vector<std::uint32_t> opposite; // per halfedge (always defined)
  // Vertex -> incident faces (CSR).
  std::vector<std::uint32_t> vf_begin, vf;
  double diagonal = 0; // of the points' bounding box

  std::size_t number_of_faces() const { return faces.size(); }
  std::size_t number_of_interior_halfedges() const { return 3 * faces.size(); }
  std::size_t number_of_halfedges() const { return source.size(); }
  std::uint32_t face(std::uint32_t h) const { return h < 3 * faces.size() ? h / 3 : NONE; }
  std::uint32_t target(std::uint32_t h) const { return source[opposite[h]]; }
  std::uint32_t next_in_face(std::uint32_t h) const { return 3 * (h / 3) + (h % 3 + 1) % 3; }
  bool is_border(std::uint32_t h) const { return h >= 3 * faces.size(); }
  bool is_border_edge(std::uint32_t h) const { return is_border(h) || is_border(opposite[h]); }
  // The canonical halfedge of the edge of h (the smaller index).
  std::uint32_t edge(std::uint32_t h) const { return h < opposite[h] ? h : opposite[h]; }

  void build_vertex_faces()
  {
    vf_begin.assign(points.size() + 1, 0);
    for(const auto& f : faces)
      for(std::uint32_t v : f) ++vf_begin[v + 1];
    for(std::size_t i = 0; i < points.size(); ++i) vf_begin[i + 1] += vf_begin[i];
    vf.assign(vf_begin.back(), 0);
    std::vector<std::uint32_t> fill(vf_begin.begin(), vf_begin.end() - 1);
    for(std::uint32_t f = 0; f < faces.size(); ++f)
      for(std::uint32_t v : faces[f]) vf[fill[v]++] = f;
  }
};

// Copies `tm` into `im`. `halfedge_of` receives, per index, the halfedge descriptor; `face_of` the face
// descriptor per face index; `vertex_of` the vertex descriptor per vertex index.
// Throws std::invalid_argument when a face is not a triangle, the mesh has no face, a coordinate is not finite or
// the bounding box diagonal is outside [1e-30, 1e30].
template <class TriangleMesh, class VertexPointMap, class Point_3>
void build_indexed_mesh(const TriangleMesh& tm, VertexPointMap vpm, Indexed_mesh<Point_3>& im,
                        std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>& halfedge_of,
                        std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& face_of,
                        std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vertex_of,
                        const char* caller)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  im = Indexed_mesh<Point_3>();
  halfedge_of.clear();
  face_of.clear();
  vertex_of.clear();
  if(faces(tm).empty())
    throw std::invalid_argument(std::string("MDCS: ") + caller + ": the mesh has no face");

  auto vid = get(CGAL::dynamic_vertex_property_t<std::uint32_t>(), tm);
  auto hid = get(CGAL::dynamic_halfedge_property_t<std::uint32_t>(), tm);
  CGAL::Bbox_3 box;
  for(vertex_descriptor v : vertices(tm)) {
    const Point_3& p = get(vpm, v);
    const double c[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    for(int k = 0; k < 3; ++k)
      if(!std::isfinite(c[k]))
        throw std::invalid_argument(std::string("MDCS: ") + caller + ": vertex " + std::to_string(im.points.size()) +
                                    " has a coordinate that is not finite (NaN or infinity)");
    box += CGAL::Bbox_3(c[0], c[1], c[2], c[0], c[1], c[2]);
    put(vid, v, std::uint32_t(im.points.size()));
    im.points.push_back(p);
    vertex_of.push_back(v);
  }
  // The coarse mesh (CGAL's Lindstrom-Turk costs) and the normals and band weights work with products of
  // several lengths. CGAL's elephant scaled by powers of two gives the same coarse mesh and mapped loops from
  // 2^-120 to 2^130 (diagonals 1e-36 to 2e39); beyond, the mapped loops change, and at 1e-100 and 1e100 no edge
  // was collapsed. So the scale is a precondition, with a margin.
  im.diagonal = CGAL::MDCS::internal::bbox_diagonal(box);
  if(!(im.diagonal >= 1e-30 && im.diagonal <= 1e30)) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", im.diagonal);
    throw std::invalid_argument(std::string("MDCS: ") + caller + ": the bounding box diagonal, " + text +
                                ", must be in [1e-30, 1e30] (scale the mesh)");
  }
  const std::size_t nf = faces(tm).size();
  im.faces.reserve(nf);
  halfedge_of.reserve(3 * nf + 64);
  for(face_descriptor f : faces(tm)) {
    std::array<std::uint32_t, 3> tri;
    std::size_t k = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      if(k == 3)
        throw std::invalid_argument(std::string("MDCS: ") + caller + ": face " + std::to_string(im.faces.size()) +
                                    " is not a triangle (the algorithms need a triangle mesh)");
      tri[k] = get(vid, source(h, tm));
      put(hid, h, std::uint32_t(3 * im.faces.size() + k));
      halfedge_of.push_back(h);
      ++k;
    }
    if(k != 3)
      throw std::invalid_argument(std::string("MDCS: ") + caller + ": face " + std::to_string(im.faces.size()) +
                                  " has " + std::to_string(k) + " sides; the algorithms need a triangle mesh");
    im.faces.push_back(tri);
    face_of.push_back(f);
  }
  const std::uint32_t ni = std::uint32_t(3 * nf);
  im.source.resize(ni);
  im.opposite.resize(ni);
  for(std::uint32_t f = 0; f < nf; ++f)
    for(std::uint32_t k = 0; k < 3; ++k) im.source[3 * f + k] = im.faces[f][k];
  for(std::uint32_t h = 0; h < ni; ++h) {
    const halfedge_descriptor o = opposite(halfedge_of[h], tm);
    if(is_border(o, tm)) {
      const std::uint32_t b = std::uint32_t(im.source.size());
      im.source.push_back(get(vid, source(o, tm)));
      im.opposite.push_back(h);
      im.opposite[h] = b;
      halfedge_of.push_back(o);
    } else {
      im.opposite[h] = get(hid, o);
    }
  }
  im.build_vertex_faces();
}

} // namespace internal
} // namespace Silhouette_simplification_3
} // namespace CGAL

#endif // CGAL_SILHOUETTE_SIMPLIFICATION_3_INTERNAL_INDEXED_MESH_H
