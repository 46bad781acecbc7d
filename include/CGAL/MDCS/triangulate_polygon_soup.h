// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// triangulate_polygon_soup(): the polygons of a soup split into triangles that keep each polygon's boundary
// and orientation, robust for concave and non-planar polygons.

#ifndef CGAL_MDCS_TRIANGULATE_POLYGON_SOUP_H
#define CGAL_MDCS_TRIANGULATE_POLYGON_SOUP_H

#include <CGAL/MDCS/internal/polygon_soup_analysis.h>
#include <CGAL/MDCS/internal/triangulate_polygon.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace MDCS {

/// \ingroup PkgMDCSIO
/// How `triangulate_polygon_soup()` split the polygons.
struct Polygon_soup_triangulation_report
{
  std::size_t triangles_kept = 0;           ///< polygons that were triangles already
  std::size_t quadrilaterals = 0;           ///< split along the diagonal of the better pair of triangles
  std::size_t by_constrained_delaunay = 0;  ///< larger polygons: constrained Delaunay triangulation in their plane
  std::size_t by_hole_filling = 0;          ///< polygons that self-intersect in projection (non-planar): CGAL's
                                            ///< `triangulate_hole_polyline()` on the 3D boundary
  std::size_t by_fan = 0;                   ///< degenerate polygons (zero area, repeated or non-finite points),
                                            ///< or too large for hole filling: a fan from the first corner
  std::size_t triangles = 0;                ///< triangles written

  std::size_t polygons_split() const { return quadrilaterals + by_constrained_delaunay + by_hole_filling + by_fan; }
};

/*!
  \ingroup PkgMDCSIO
  \brief splits every polygon of a soup into triangles that cover it.

  Each polygon of k corners becomes k - 2 triangles over its own corners (no point is added), which use every
  side of the polygon once in the polygon's direction and every diagonal once in each direction: the
  triangles keep the polygon's boundary and orientation, so a valid oriented polygon mesh stays one (unless
  a diagonal coincides with an edge of another polygon). The method, per polygon:
  - triangles are copied;
  - quadrilaterals are split along the diagonal whose two triangles have the larger dot product of normals
    (the rule of `CGAL::Polygon_mesh_processing::triangulate_faces()`);
  - larger polygons: a constrained Delaunay triangulation in the plane of their Newell normal; if the
    projected boundary self-intersects (strongly non-planar polygons), CGAL's
    `Polygon_mesh_processing::triangulate_hole_polyline()` on the 3D boundary (up to
    `hole_filling_limit` corners);
  - what remains (zero-area polygons, repeated points, coordinates beyond 1e100 or not finite, and
    self-intersecting polygons that are too large for hole filling or that it cannot fill): a fan from the
    first corner, counted in the report.

  \tparam TriangleRange a back-insertion sequence of triangles: `std::array<I, 3>` or sequence containers
  \param triangle_to_polygon if not null, receives for each triangle the index of its polygon
  \throws std::invalid_argument if a polygon has fewer than 3 corners or refers to a point that does not exist
*/
template <class PointRange, class PolygonRange, class TriangleRange>
Polygon_soup_triangulation_report triangulate_polygon_soup(const PointRange& points, const PolygonRange& polygons,
                                                           TriangleRange& triangles,
                                                           std::vector<std::size_t>* triangle_to_polygon = nullptr,
                                                           std::size_t hole_filling_limit = 300)
{
  typedef typename TriangleRange::value_type Triangle;
  const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));
  const internal::Soup_rows rows = internal::make_soup_rows(polygons, n, "triangulate_polygon_soup");
  std::vector<std::array<double, 3>> coordinates;
  coordinates.reserve(n);
  for(const auto& p : points) coordinates.push_back(internal::point_coordinates(p));

  Polygon_soup_triangulation_report report;
  std::vector<std::size_t> corners;
  std::vector<std::array<std::size_t, 3>> local;
  for(std::size_t f = 0; f < rows.number_of_polygons(); ++f) {
    const std::size_t k = rows.size(f);
    if(k < 3)
      throw std::invalid_argument("MDCS: triangulate_polygon_soup: polygon " + std::to_string(f) + " has " +
                                  std::to_string(k) + " corners");
    corners.assign(rows.corners.begin() + std::ptrdiff_t(rows.offsets[f]), rows.corners.begin() + std::ptrdiff_t(rows.offsets[f + 1]));
    local.clear();
    switch(internal::triangulate_polygon(coordinates, corners, local, hole_filling_limit)) {
    case internal::Polygon_triangulation_method::triangle: ++report.triangles_kept; break;
    case internal::Polygon_triangulation_method::quadrilateral: ++report.quadrilaterals; break;
    case internal::Polygon_triangulation_method::constrained_delaunay: ++report.by_constrained_delaunay; break;
    case internal::Polygon_triangulation_method::hole_filling: ++report.by_hole_filling; break;
    case internal::Polygon_triangulation_method::fan: ++report.by_fan; break;
    }
    for(const auto& t : local) {
      Triangle out{};
      if constexpr(internal::is_std_array_3<Triangle>::value) {
        for(int i = 0; i < 3; ++i) out[std::size_t(i)] = typename Triangle::value_type(corners[t[std::size_t(i)]]);
      } else {
        for(int i = 0; i < 3; ++i) out.insert(out.end(), typename Triangle::value_type(corners[t[std::size_t(i)]]));
      }
      triangles.push_back(out);
      if(triangle_to_polygon) triangle_to_polygon->push_back(f);
      ++report.triangles;
    }
  }
  return report;
}

} // namespace MDCS
} // namespace CGAL

#endif // CGAL_MDCS_TRIANGULATE_POLYGON_SOUP_H
