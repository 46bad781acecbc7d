// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Surface queries of mdcs.geodesics that need no propagation: locating 3D points and rays on the mesh
// (Surface_point_locator_3, an AABB tree built once per mesh) and iso-distance curves of a vertex field
// (triangle_soup_iso_distance_curves). In their own translation unit: the AABB tree is slow to compile.

#include "geodesic_surface.h"

#include <CGAL/Polyhedral_geodesics_3/Surface_point_locator_3.h>
#include <CGAL/Polyhedral_geodesics_3/iso_distance_curves.h>

#include <cmath>
#include <limits>

namespace mdcs_python {

struct Point_locator
{
  explicit Point_locator(const Geo_mesh& mesh) : locator(mesh) {}
  CGAL::Polyhedral_geodesics_3::Surface_point_locator_3<Geo_mesh> locator;
};

std::shared_ptr<const Point_locator> make_point_locator(const Geodesic_surface& s)
{
  return std::make_shared<const Point_locator>(s.mesh());
}

namespace {

// A location of the mesh as the caller's face and barycentric coordinates (faces[f]'s corner order).
void write_location(const Geodesic_surface& s, const Geo_mesh::Face_index f, const std::array<double, 3>& mesh_b,
                    std::int64_t& face, double* barycentric)
{
  const std::size_t index = std::size_t(f);
  const std::array<double, 3> b = s.to_user_barycentric(index, mesh_b);
  face = std::int64_t(index);
  for(int k = 0; k < 3; ++k) barycentric[k] = b[std::size_t(k)];
}

} // namespace

void locate_points(const Geodesic_surface& s, const Point_locator& l, const double* points, std::size_t k,
                   std::int64_t* faces, double* barycentric)
{
  for(std::size_t i = 0; i < k; ++i) {
    const double* p = points + 3 * i;
    const auto location = l.locator.locate(Geo_point(p[0], p[1], p[2]));
    write_location(s, location.first, location.second, faces[i], barycentric + 3 * i);
  }
}

void locate_rays(const Geodesic_surface& s, const Point_locator& l, const double* origins, const double* directions,
                 std::size_t k, std::int64_t* faces, double* barycentric)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for(std::size_t i = 0; i < k; ++i) {
    const double* o = origins + 3 * i;
    const double* d = directions + 3 * i;
    const Geo_point source(o[0], o[1], o[2]);
    const auto location = l.locator.locate(Geo_kernel::Ray_3(source, Geo_kernel::Vector_3(d[0], d[1], d[2])));
    if(location) {
      write_location(s, location->first, location->second, faces[i], barycentric + 3 * i);
    } else {
      faces[i] = -1;
      for(int c = 0; c < 3; ++c) barycentric[3 * i + std::size_t(c)] = nan;
    }
  }
}

std::vector<Iso_curve> iso_curves(const double* vertices, std::size_t n, const std::int64_t* faces, std::size_t m,
                                  const double* distances, const std::vector<double>& levels)
{
  std::vector<Geo_point> points;
  points.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
    points.emplace_back(vertices[3 * i], vertices[3 * i + 1], vertices[3 * i + 2]);
  std::vector<std::array<std::size_t, 3>> triangles(m);
  for(std::size_t t = 0; t < m; ++t)
    for(int k = 0; k < 3; ++k) triangles[t][std::size_t(k)] = std::size_t(faces[3 * t + std::size_t(k)]);
  std::vector<CGAL::Polyhedral_geodesics_3::Iso_distance_curve<Geo_point>> curves;
  CGAL::Polyhedral_geodesics_3::triangle_soup_iso_distance_curves(points, triangles,
                                                                  std::vector<double>(distances, distances + n),
                                                                  levels, std::back_inserter(curves));
  std::vector<Iso_curve> out(curves.size());
  for(std::size_t c = 0; c < curves.size(); ++c) {
    out[c].level = curves[c].level;
    out[c].closed = curves[c].closed;
    out[c].points.reserve(3 * curves[c].points.size());
    for(const Geo_point& p : curves[c].points)
      for(int k = 0; k < 3; ++k) out[c].points.push_back(p[k]);
  }
  return out;
}

} // namespace mdcs_python
