// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The prepared surface of the geodesic classes: the compact mesh of a triangle FaceGraph or of a triangle soup,
// built once and read-only afterwards, so that any number of geodesic objects, of any class and on any number
// of threads, share it (several sources in a row, several methods, one solver per thread never rebuild it).
// The work is in internal/build_geodesic_mesh.h.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_GEODESIC_SURFACE_3_H
#define CGAL_POLYHEDRAL_GEODESICS_3_GEODESIC_SURFACE_3_H

#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

#include <array>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  Tag for the `TriangleMesh` parameter of the geodesic classes and of `Geodesic_surface_3`: the surface is a
  triangle soup (a range of points and a range of index triples), and the classes speak indices:
  - a vertex is its index (`std::size_t`), a face is the index of its triangle (`std::size_t`);
  - a `Face_location` is a triangle index with barycentric coordinates in the order of the triangle's corners;
  - a point of a path on an edge is reported as a `Triangle_soup_halfedge` (a triangle and the corner where the edge
    starts) and a ratio along it;
  - points are `std::array<double, 3>`, and `distances()` takes any writable property map keyed by the vertex
    index, e.g. `CGAL::make_property_map(std::vector<double>&)`.

  The soup need not be a manifold nor oriented: the edges come from the vertex indices (see `Geodesic_surface_3`).
*/
struct Triangle_soup
{};

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  An edge of a triangle soup as the geodesic classes report it in paths: corner `corner` of triangle `face`, to the
  next corner of that triangle. `source` and `target` are the vertex indices of the two ends.
*/
struct Triangle_soup_halfedge
{
  std::size_t face;
  int corner;
  std::size_t source, target;

  friend bool operator==(const Triangle_soup_halfedge& a, const Triangle_soup_halfedge& b)
  {
    return a.face == b.face && a.corner == b.corner;
  }
  friend bool operator!=(const Triangle_soup_halfedge& a, const Triangle_soup_halfedge& b) { return !(a == b); }
};

namespace internal {

// The default vertex point map of a geodesic class: that of the mesh, none for a soup.
template <class TriangleMesh>
struct Default_vertex_point_map
{
  typedef typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type type;
};

template <>
struct Default_vertex_point_map<Triangle_soup>
{
  typedef Triangle_soup type;
};

// Descriptor helpers: the surface's members face(), halfedge() and vertex() hide the free functions of the graph
// traits inside the class.
template <class TriangleMesh>
typename boost::graph_traits<TriangleMesh>::halfedge_descriptor
compact_halfedge_descriptor(typename boost::graph_traits<TriangleMesh>::face_descriptor f, int k, const TriangleMesh& tm)
{
  auto g = halfedge(f, tm);
  for(int i = 0; i < k; ++i)
    g = next(g, tm);
  return g;
}

template <class TriangleMesh>
typename boost::graph_traits<TriangleMesh>::vertex_descriptor
source_vertex_descriptor(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h, const TriangleMesh& tm)
{
  return source(h, tm);
}

} // namespace internal

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief The prepared surface of the geodesic classes: a compact, index-based copy of a triangle mesh (the
  halfedges of each face in one packed record with the edge length and the opposite corner in the halfedge's
  planar frame, the halfedges of every edge, the vertex stars, the angle sums), built once in a few passes over
  arrays, and read-only afterwards.

  Every geodesic class (`Exact_geodesic_distances_3`, `Merged_window_geodesic_distances_3`,
  `Flat_exact_geodesic_distances_3`, `Fast_marching_geodesic_distances_3`, `Dijkstra_geodesic_distances_3`) can be
  constructed from it, given as `std::shared_ptr<const Geodesic_surface_3>` (shared ownership) or as a reference
  (the surface must then outlive the object). Objects built on one surface share it and never rebuild it, and it
  is never modified after its constructor: one surface may serve any number of objects on any number of threads at
  the same time (one geodesic object per thread; a geodesic object itself is not thread-safe). The classes'
  constructors that take a mesh build a surface of their own.

  \tparam TriangleMesh a model of `FaceGraph` whose faces are triangles, or the tag `Triangle_soup` (see the
          specialization below).
  \tparam FT the number type of the computation (default `double`), as in the geodesic classes.
  \tparam VertexPointMap a readable property map from vertices to 3D points.

  The mesh must stay alive and unchanged as long as the surface (and any geodesic object on it) is used: the
  surface keeps a reference to it to translate descriptors. The edges are the mesh's own (through `opposite()`);
  a FaceGraph is always an oriented surface whose edges have at most two faces, but it may have *pinched*
  vertices (a vertex whose faces form several fans, e.g. two cones touching at their apex), which every class
  supports.

  Preconditions, checked (`std::invalid_argument` with a message that says what is wrong): triangle faces only,
  finite coordinates, no face with the same vertex at two corners, the mesh's scale (largest edge at least 1e-40,
  bounding box diagonal at most 1e40), index maps that are bijections, a `Surface_mesh` without uncollected
  garbage, and fewer than about 715 million faces (32-bit indices).
*/
template <class TriangleMesh, class FT = double,
          class VertexPointMap = typename internal::Default_vertex_point_map<TriangleMesh>::type>
class Geodesic_surface_3
{
  typedef boost::graph_traits<TriangleMesh> GT;

public:
  typedef TriangleMesh Triangle_mesh;
  typedef FT Number_type;
  typedef VertexPointMap Vertex_point_map;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point_3;
  typedef typename CGAL::GetInitializedVertexIndexMap<TriangleMesh>::const_type Vertex_index_map;
  typedef typename CGAL::GetInitializedFaceIndexMap<TriangleMesh>::const_type Face_index_map;
  typedef internal::Geodesic_mesh<FT> Compact_mesh;
  typedef typename Compact_mesh::Index Index;

  /// Builds the surface of `tm` with the vertex points of `get(CGAL::vertex_point, tm)`.
  explicit Geodesic_surface_3(const TriangleMesh& tm) : Geodesic_surface_3(tm, get(CGAL::vertex_point, tm)) {}

  /// Builds the surface of `tm` with the vertex points of `vpm`.
  Geodesic_surface_3(const TriangleMesh& tm, VertexPointMap vpm)
    : tm_(&tm), vpm_(vpm), vim_(CGAL::get_initialized_vertex_index_map(tm)),
      fim_(CGAL::get_initialized_face_index_map(tm))
  {
    face_of_.resize(num_faces(tm));
    internal::build_geodesic_mesh_from_face_graph(tm, vpm_, vim_, fim_, mesh_,
                                                  [this](std::size_t fi, face_descriptor f) { face_of_[fi] = f; });
  }

  /// Builds the surface of `tm`; the named parameter `vertex_point_map` gives the vertex points (default
  /// `get(CGAL::vertex_point, tm)`; its type must be `VertexPointMap`).
  template <class NamedParameters,
            std::enable_if_t<!std::is_convertible<NamedParameters, VertexPointMap>::value, int> = 0>
  Geodesic_surface_3(const TriangleMesh& tm, const NamedParameters& np)
    : Geodesic_surface_3(tm, VertexPointMap(CGAL::parameters::choose_parameter(
                                 CGAL::parameters::get_parameter(np, internal_np::vertex_point),
                                 get_const_property_map(CGAL::vertex_point, tm))))
  {}

  Geodesic_surface_3(const Geodesic_surface_3&) = delete;
  Geodesic_surface_3& operator=(const Geodesic_surface_3&) = delete;

  /// \name The surface
  /// @{
  const TriangleMesh& triangle_mesh() const { return *tm_; }
  VertexPointMap vertex_point_map() const { return vpm_; }
  std::size_t number_of_vertices() const { return mesh_.number_of_vertices; }
  std::size_t number_of_faces() const { return mesh_.number_of_faces; }
  std::size_t number_of_edges() const { return mesh_.number_of_edges; }
  std::size_t number_of_border_edges() const { return mesh_.number_of_border_edges; }
  /// Edges of three or more faces (always 0 for a FaceGraph).
  std::size_t number_of_nonmanifold_edges() const { return mesh_.number_of_nonmanifold_edges; }
  /// Edges whose two faces run through them in the same direction (always 0 for a FaceGraph).
  std::size_t number_of_reversed_edges() const { return mesh_.number_of_reversed_edges; }
  /// Vertices whose faces form several fans.
  std::size_t number_of_pinched_vertices() const { return mesh_.number_of_pinched_vertices; }
  /// Vertices of no face.
  std::size_t number_of_isolated_vertices() const { return mesh_.number_of_isolated_vertices; }
  /// Whether every edge has one or two faces, which run through it in opposite directions (true for a FaceGraph).
  bool has_oriented_manifold_edges() const { return !mesh_.has_special_edges(); }
  /// The bytes the surface holds (the compact mesh and the descriptor table).
  std::size_t memory_bytes() const { return internal::compact_mesh_bytes(mesh_) + face_of_.capacity() * sizeof(face_descriptor); }
  /// @}

  /// \name Translation between descriptors and the indices of the compact mesh (for the geodesic classes)
  /// @{
  const Compact_mesh& compact_mesh() const { return mesh_; }
  Index vertex_index(vertex_descriptor v) const { return Index(get(vim_, v)); }
  Index face_index(face_descriptor f) const
  {
    const std::size_t i = get(fim_, f);
    if(i >= mesh_.number_of_faces)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: face not in the mesh");
    return Index(i);
  }
  face_descriptor face(Index f) const { return face_of_[std::size_t(f)]; }
  halfedge_descriptor halfedge(Index h) const
  {
    return internal::compact_halfedge_descriptor(face_of_[std::size_t(h / 3)], int(h % 3), *tm_);
  }
  /// Throws for isolated vertices (they have no halfedge).
  vertex_descriptor vertex(Index v) const
  {
    const Index h = mesh_.vertex_halfedge[std::size_t(v)];
    if(h < 0)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: the vertex has no incident face");
    return internal::source_vertex_descriptor(halfedge(h), *tm_);
  }
  /// Calls `f(v, index)` for every vertex.
  template <class F>
  void for_each_vertex(F f) const
  {
    for(vertex_descriptor v : vertices(*tm_))
      f(v, Index(get(vim_, v)));
  }
  static Point_3 make_point(double x, double y, double z) { return Point_3(x, y, z); }
  /// @}

private:
  const TriangleMesh* tm_;
  VertexPointMap vpm_;
  Vertex_index_map vim_;
  Face_index_map fim_;
  Compact_mesh mesh_;
  std::vector<face_descriptor> face_of_;
};

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief The prepared surface of a triangle soup: points and index triples (see `Triangle_soup` for how the
  geodesic classes then speak indices).

  The edges come from the vertex indices: the halfedges that join the same two vertices form one edge, however
  many faces they belong to and whichever way they run. So the soup may be
  - non-manifold: an edge of three or more faces (windows cross from any of its faces into every other one),
    and pinched vertices (a vertex whose faces form several fans: paths may pass from any fan into any other);
  - non-orientable: two faces that run through their common edge in the same direction, as where a Moebius strip
    closes (the unfolding across an edge needs no global orientation);
  - with borders, several components and isolated vertices (unreachable from the others).
  Which class supports what is in the package manual (*Surfaces as given*); the exact, merged and Dijkstra classes
  support all of it, the others refuse what they cannot do with `std::invalid_argument`.

  Input, checked (`std::invalid_argument` with a message that names the triangle or point): every corner is a
  vertex index in [0, number of points) (negative values included), no triangle has the same vertex twice, every
  polygon has three corners, every coordinate is finite, the scale (largest edge at least 1e-40, bounding box
  diagonal at most 1e40), at most 31 triangles per edge, and fewer than about 715 million triangles (32-bit
  indices). The soup is copied: the ranges need not outlive the constructor.
*/
template <class FT, class VertexPointMap>
class Geodesic_surface_3<Triangle_soup, FT, VertexPointMap>
{
public:
  typedef Triangle_soup Triangle_mesh;
  typedef FT Number_type;
  typedef std::size_t vertex_descriptor;
  typedef Triangle_soup_halfedge halfedge_descriptor;
  typedef std::size_t face_descriptor;
  typedef std::array<double, 3> Point_3;
  typedef internal::Geodesic_mesh<FT> Compact_mesh;
  typedef typename Compact_mesh::Index Index;

  /// Builds the surface of the soup: `points` is a range of points (with `x()`, `y()`, `z()`, or three
  /// coordinates by `operator[]`), `triangles` a range of random-access containers of three integer vertex indices
  /// (`std::array<std::size_t, 3>`, `std::vector<int>`, ...).
  template <class PointRange, class TriangleRange>
  Geodesic_surface_3(const PointRange& points, const TriangleRange& triangles)
  {
    internal::build_geodesic_mesh_from_soup(points, triangles, mesh_);
  }

  /// Builds the surface of the soup given as arrays (e.g. NumPy's): `coordinates` holds x, y, z of each of the
  /// `number_of_points` points, `corners` the three vertex indices of each of the `number_of_triangles` triangles.
  template <class IndexType, std::enable_if_t<std::is_integral<IndexType>::value, int> = 0>
  Geodesic_surface_3(const double* coordinates, std::size_t number_of_points, const IndexType* corners,
                     std::size_t number_of_triangles)
  {
    internal::build_geodesic_mesh_from_soup_arrays(coordinates, number_of_points, corners, number_of_triangles, mesh_);
  }

  Geodesic_surface_3(const Geodesic_surface_3&) = delete;
  Geodesic_surface_3& operator=(const Geodesic_surface_3&) = delete;

  /// \name The surface (as in the FaceGraph version)
  /// @{
  std::size_t number_of_vertices() const { return mesh_.number_of_vertices; }
  std::size_t number_of_faces() const { return mesh_.number_of_faces; }
  std::size_t number_of_edges() const { return mesh_.number_of_edges; }
  std::size_t number_of_border_edges() const { return mesh_.number_of_border_edges; }
  std::size_t number_of_nonmanifold_edges() const { return mesh_.number_of_nonmanifold_edges; }
  std::size_t number_of_reversed_edges() const { return mesh_.number_of_reversed_edges; }
  std::size_t number_of_pinched_vertices() const { return mesh_.number_of_pinched_vertices; }
  std::size_t number_of_isolated_vertices() const { return mesh_.number_of_isolated_vertices; }
  bool has_oriented_manifold_edges() const { return !mesh_.has_special_edges(); }
  std::size_t memory_bytes() const { return internal::compact_mesh_bytes(mesh_); }
  /// The point of vertex `v` and the vertex at corner `k` of triangle `f`.
  Point_3 point(std::size_t v) const
  {
    const auto& p = mesh_.points[checked_vertex(v)];
    return {internal::to_double_value(p[0]), internal::to_double_value(p[1]), internal::to_double_value(p[2])};
  }
  std::size_t triangle_corner(std::size_t f, int k) const
  {
    return std::size_t(mesh_.source(Index(3 * face_index(f) + k)));
  }
  /// @}

  /// \name Translation between indices and the compact mesh (for the geodesic classes)
  /// @{
  const Compact_mesh& compact_mesh() const { return mesh_; }
  /// Throws `std::invalid_argument` for an index out of range.
  Index vertex_index(vertex_descriptor v) const { return Index(checked_vertex(v)); }
  Index face_index(face_descriptor f) const
  {
    if(f >= mesh_.number_of_faces)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: triangle index " + std::to_string(f) +
                                  " out of range (the soup has " + std::to_string(mesh_.number_of_faces) + " triangles)");
    return Index(f);
  }
  face_descriptor face(Index f) const { return std::size_t(f); }
  halfedge_descriptor halfedge(Index h) const
  {
    return Triangle_soup_halfedge{std::size_t(h / 3), int(h % 3), std::size_t(mesh_.source(h)),
                                  std::size_t(mesh_.target(h))};
  }
  vertex_descriptor vertex(Index v) const { return std::size_t(v); }
  template <class F>
  void for_each_vertex(F f) const
  {
    for(std::size_t v = 0; v < mesh_.number_of_vertices; ++v)
      f(v, Index(v));
  }
  static Point_3 make_point(double x, double y, double z) { return Point_3{x, y, z}; }
  /// @}

private:
  std::size_t checked_vertex(std::size_t v) const
  {
    if(v >= mesh_.number_of_vertices)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: vertex index " + std::to_string(v) +
                                  " out of range (the soup has " + std::to_string(mesh_.number_of_vertices) + " points)");
    return v;
  }

  Compact_mesh mesh_;
};

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  The prepared surface of a FaceGraph, shared: `std::make_shared<const Geodesic_surface_3<TriangleMesh>>(tm)`.
*/
template <class TriangleMesh>
std::shared_ptr<const Geodesic_surface_3<TriangleMesh>> make_geodesic_surface(const TriangleMesh& tm)
{
  return std::make_shared<const Geodesic_surface_3<TriangleMesh>>(tm);
}

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  The prepared surface of a triangle soup, shared.
*/
template <class PointRange, class TriangleRange>
std::shared_ptr<const Geodesic_surface_3<Triangle_soup>> make_geodesic_surface(const PointRange& points,
                                                                               const TriangleRange& triangles)
{
  return std::make_shared<const Geodesic_surface_3<Triangle_soup>>(points, triangles);
}

} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_GEODESIC_SURFACE_3_H
