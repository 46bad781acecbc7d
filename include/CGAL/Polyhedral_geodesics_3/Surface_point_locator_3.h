// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Locating a 3D point (its closest point on the surface) or the first hit of a ray on a triangle mesh as a
// Face_location, through an AABB tree built once: the counterpart of Surface_mesh_shortest_path::locate() and
// Polygon_mesh_processing::locate_with_AABB_tree(), returning the location type of the geodesic distance classes.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_SURFACE_POINT_LOCATOR_3_H
#define CGAL_POLYHEDRAL_GEODESICS_3_SURFACE_POINT_LOCATOR_3_H

#include <CGAL/Polyhedral_geodesics_3/Geodesic_surface_3.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/variant/get.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

namespace CGAL {
namespace Polyhedral_geodesics_3 {

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief Locates points and rays on a triangle mesh as `Face_location`s, with an AABB tree of its faces built
  once in the constructor and reused by every query (as `Surface_mesh_shortest_path::locate()` with a tree
  from `build_aabb_tree()`).

  `locate(p)` returns the surface point closest to `p` (the point itself if it lies on the surface),
  `locate(ray)` the first point where the ray meets the surface (`std::nullopt` if it misses). The location is
  a face and barycentric coordinates with respect to `source(halfedge(f))`, `target(halfedge(f))`,
  `target(next(halfedge(f)))`, the order of `Polygon_mesh_processing::Face_location` and of the geodesic
  distance classes' `Face_location`, so the result can be passed to `add_source()`, `distance()`,
  `shortest_path_points()`, ... of any of them. The coordinates are non-negative and sum to 1: a surface point
  equal to a corner of the face gets exactly 1 there and 0 elsewhere, a point on an edge a zero for the opposite
  corner up to the rounding of the closest-point construction and of the coordinates (about 1e-16 relative with
  an inexact kernel; exactly zero on a flat mesh with small dyadic coordinates, as in the tests).
  Where several faces are closest (a point on an edge or a vertex, or equidistant faces) one of them is
  returned; every one of them names the same surface point.

  \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles.
  \tparam FT_ the number type of the barycentric coordinates (that of the geodesic class the locations go to).
  \tparam VertexPointMap a readable property map from vertices to the `Point_3` of a CGAL kernel; the tree and
          the queries use that kernel (exact predicates and constructions with EPECK).

  \warning The barycentric coordinates are converted to `FT_` from the kernel's numbers, so they are rounded
           when `FT_` is `double`, even with an exact kernel.
*/
template <class TriangleMesh, class FT_ = double,
          class VertexPointMap = typename internal::Default_vertex_point_map<TriangleMesh>::type>
class Surface_point_locator_3
{
public:
  typedef FT_ FT;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point_3;
  typedef typename Kernel_traits<Point_3>::Kernel Kernel;
  typedef typename Kernel::Ray_3 Ray_3;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  /// the location type of the geodesic distance classes with number type `FT_`
  typedef std::pair<face_descriptor, std::array<FT, 3>> Face_location;
  /// the AABB tree of the faces
  typedef CGAL::AABB_face_graph_triangle_primitive<TriangleMesh, VertexPointMap> Primitive;
  typedef CGAL::AABB_traits<Kernel, Primitive> AABB_traits;
  typedef CGAL::AABB_tree<AABB_traits> AABB_tree;

  /// Builds the tree of the faces of `tm` (which must outlive the locator and not change). Throws
  /// `std::invalid_argument` if `tm` has no face or a face that is not a triangle.
  explicit Surface_point_locator_3(const TriangleMesh& tm)
    : Surface_point_locator_3(tm, get(CGAL::vertex_point, tm))
  {}

  Surface_point_locator_3(const TriangleMesh& tm, VertexPointMap vpm)
    : tm_(tm), vpm_(vpm)
  {
    if(faces(tm).first == faces(tm).second)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3::Surface_point_locator_3: the mesh has no face");
    if(!CGAL::is_triangle_mesh(tm))
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3::Surface_point_locator_3: a face is not a triangle");
    tree_.insert(faces(tm).first, faces(tm).second, tm, vpm_);
    tree_.build();
    tree_.accelerate_distance_queries();
  }

  Surface_point_locator_3(const Surface_point_locator_3&) = delete;
  Surface_point_locator_3& operator=(const Surface_point_locator_3&) = delete;

  /// The location of the surface point closest to `p`.
  Face_location locate(const Point_3& p) const
  {
    const auto closest = tree_.closest_point_and_primitive(p);
    return location_in_face(closest.second, closest.first);
  }

  /// The location of the first point of the surface on `ray` (the one closest to its source), `std::nullopt`
  /// if the ray misses the surface. A ray that runs inside the plane of a face meets it along a segment; the
  /// segment's end closest to the ray's source is the hit.
  std::optional<Face_location> locate(const Ray_3& ray) const
  {
    const auto hit = tree_.first_intersection(ray);
    if(!hit)
      return std::nullopt;
    const face_descriptor f = hit->second;
    if(const Point_3* p = boost::get<Point_3>(&hit->first))
      return location_in_face(f, *p);
    if(const auto* s = boost::get<typename Kernel::Segment_3>(&hit->first)) {
      const Point_3& q = Kernel().compare_distance_3_object()(ray.source(), s->source(), s->target()) == CGAL::LARGER
                           ? s->target() : s->source();
      return location_in_face(f, q);
    }
    return std::nullopt;
  }

  /// The 3D point of a location (the barycentric combination of the face's corners).
  Point_3 point(const Face_location& location) const
  {
    const auto corners = face_corners(location.first);
    double c[3] = {0, 0, 0};
    for(int i = 0; i < 3; ++i)
      for(int k = 0; k < 3; ++k)
        c[k] += CGAL::to_double(location.second[std::size_t(i)]) * CGAL::to_double(corners[std::size_t(i)][k]);
    return Point_3(c[0], c[1], c[2]);
  }

  /// The tree, e.g. for other queries (`squared_distance()`, `any_intersected_primitive()`, ...).
  const AABB_tree& tree() const { return tree_; }

private:
  std::array<Point_3, 3> face_corners(face_descriptor f) const
  {
    const halfedge_descriptor h = halfedge(f, tm_);
    return {{get(vpm_, source(h, tm_)), get(vpm_, target(h, tm_)), get(vpm_, target(next(h, tm_), tm_))}};
  }

  // The barycentric coordinates of `q` (a point of face f or very close to its plane) in f: signed areas of
  // the sub-triangles against the face's normal, computed in double; negative values (rounding, or a point
  // outside the face) are clamped to 0 and the rest renormalised. A point at a corner gets exactly 1 there.
  Face_location location_in_face(face_descriptor f, const Point_3& q) const
  {
    const auto c = face_corners(f);
    double p[3][3], x[3];
    for(int k = 0; k < 3; ++k) {
      x[k] = CGAL::to_double(q[k]);
      for(int i = 0; i < 3; ++i)
        p[i][k] = CGAL::to_double(c[std::size_t(i)][k]);
    }
    auto cross_dot = [](const double* a, const double* b, const double* n) { // n . ((a) x (b))
      return n[0] * (a[1] * b[2] - a[2] * b[1]) + n[1] * (a[2] * b[0] - a[0] * b[2]) + n[2] * (a[0] * b[1] - a[1] * b[0]);
    };
    double e1[3], e2[3], n[3];
    for(int k = 0; k < 3; ++k) {
      e1[k] = p[1][k] - p[0][k];
      e2[k] = p[2][k] - p[0][k];
    }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    const double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    std::array<double, 3> b = {0, 0, 0};
    for(std::size_t i = 0; i < 3; ++i)
      if(x[0] == p[i][0] && x[1] == p[i][1] && x[2] == p[i][2]) { // exactly at a corner
        b[i] = 1;
        return {f, {{FT(b[0]), FT(b[1]), FT(b[2])}}};
      }
    if(nn > 0) {
      for(int i = 0; i < 3; ++i) {
        const double* u = p[(i + 1) % 3];
        const double* v = p[(i + 2) % 3];
        double a[3], bb[3];
        for(int k = 0; k < 3; ++k) {
          a[k] = u[k] - x[k];
          bb[k] = v[k] - x[k];
        }
        b[std::size_t(i)] = std::max(0.0, cross_dot(a, bb, n) / nn);
      }
    }
    double sum = b[0] + b[1] + b[2];
    if(!(sum > 0)) { // a degenerate face (no area): the nearest corner
      std::size_t best = 0;
      double best_d = -1;
      for(std::size_t i = 0; i < 3; ++i) {
        const double d = (p[i][0] - x[0]) * (p[i][0] - x[0]) + (p[i][1] - x[1]) * (p[i][1] - x[1]) +
                         (p[i][2] - x[2]) * (p[i][2] - x[2]);
        if(best_d < 0 || d < best_d) {
          best_d = d;
          best = i;
        }
      }
      b = {0, 0, 0};
      b[best] = 1;
      sum = 1;
    }
    return {f, {{FT(b[0] / sum), FT(b[1] / sum), FT(b[2] / sum)}}};
  }

  const TriangleMesh& tm_;
  VertexPointMap vpm_;
  AABB_tree tree_;
};

} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_SURFACE_POINT_LOCATOR_3_H
