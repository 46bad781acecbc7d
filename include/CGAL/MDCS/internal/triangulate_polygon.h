// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One polygon of a soup split into triangles over its own corners: quadrilaterals by the better diagonal,
// larger polygons by a constrained Delaunay triangulation in their plane, then CGAL's hole filling for
// polygons whose projection self-intersects, then a fan. Every result is checked combinatorially (it must
// cover the polygon once, with the polygon's orientation) before it is accepted.

#ifndef CGAL_MDCS_INTERNAL_TRIANGULATE_POLYGON_H
#define CGAL_MDCS_INTERNAL_TRIANGULATE_POLYGON_H

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Projection_traits_3.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <exception>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace MDCS {
namespace internal {

enum class Polygon_triangulation_method { triangle, quadrilateral, constrained_delaunay, hole_filling, fan };

template <class T>
struct is_std_array_3 : std::false_type {};
template <class T>
struct is_std_array_3<std::array<T, 3>> : std::true_type {};

// Whether `triangles` (local corner numbers 0..k-1) triangulate a k-gon: k - 2 triangles of distinct corners,
// every side i -> i+1 used once forwards and never backwards, every other directed pair at most once and
// only together with its reverse (an inner diagonal).
inline bool covers_polygon(std::size_t k, const std::vector<std::array<std::size_t, 3>>& triangles)
{
  if(triangles.size() != k - 2) return false;
  std::vector<std::pair<std::size_t, std::size_t>> directed;
  directed.reserve(3 * triangles.size());
  for(const auto& t : triangles) {
    if(t[0] >= k || t[1] >= k || t[2] >= k || t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return false;
    for(int i = 0; i < 3; ++i) directed.emplace_back(t[std::size_t(i)], t[std::size_t((i + 1) % 3)]);
  }
  std::sort(directed.begin(), directed.end());
  if(std::adjacent_find(directed.begin(), directed.end()) != directed.end()) return false;
  std::size_t sides = 0;
  for(const auto& e : directed) {
    if(e.second == (e.first + 1) % k) {
      ++sides;
    } else if(e.first == (e.second + 1) % k) {
      return false; // a side run backwards
    } else if(!std::binary_search(directed.begin(), directed.end(), std::make_pair(e.second, e.first))) {
      return false; // a diagonal used once
    }
  }
  return sides == k;
}

// Accepts `triangles` if they cover the polygon, as given or with every triangle reversed.
inline bool accept_triangulation(std::size_t k, std::vector<std::array<std::size_t, 3>>& triangles)
{
  if(covers_polygon(k, triangles)) return true;
  for(auto& t : triangles) std::swap(t[1], t[2]);
  return covers_polygon(k, triangles);
}

typedef CGAL::Exact_predicates_inexact_constructions_kernel Triangulation_kernel;

inline bool constrained_delaunay_triangulation(const std::vector<Triangulation_kernel::Point_3>& p,
                                               const Triangulation_kernel::Vector_3& normal,
                                               std::vector<std::array<std::size_t, 3>>& out)
{
  typedef Triangulation_kernel K;
  typedef CGAL::Projection_traits_3<K> P;
  typedef CGAL::Triangulation_vertex_base_with_info_2<std::size_t, P> Vb;
  typedef CGAL::Triangulation_face_base_with_info_2<int, P> Fbi;
  typedef CGAL::Constrained_triangulation_face_base_2<P, Fbi> Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<P, Tds, CGAL::No_constraint_intersection_tag> CDT;
  const std::size_t k = p.size();
  try {
    CDT cdt{P(normal)};
    std::vector<typename CDT::Vertex_handle> v(k);
    for(std::size_t i = 0; i < k; ++i) {
      v[i] = cdt.insert(p[i]);
      v[i]->info() = i;
    }
    if(cdt.number_of_vertices() != k || cdt.dimension() != 2) return false; // coincident in projection, or flat
    for(std::size_t i = 0; i < k; ++i) cdt.insert_constraint(v[i], v[(i + 1) % k]);
    // Inside: an odd number of constraints crossed from the infinite face.
    for(auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
    std::queue<typename CDT::Face_handle> queue;
    cdt.infinite_face()->info() = 0;
    queue.push(cdt.infinite_face());
    while(!queue.empty()) {
      const auto f = queue.front();
      queue.pop();
      for(int i = 0; i < 3; ++i) {
        const auto g = f->neighbor(i);
        if(g->info() != -1) continue;
        g->info() = f->info() + (cdt.is_constrained(typename CDT::Edge(f, i)) ? 1 : 0);
        queue.push(g);
      }
    }
    for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
      if(f->info() % 2 == 1) out.push_back({{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()}});
  } catch(const std::exception&) {
    return false; // constraints that cross: the projected boundary self-intersects
  }
  return accept_triangulation(k, out);
}

inline bool hole_filling_triangulation(const std::vector<Triangulation_kernel::Point_3>& p,
                                       std::vector<std::array<std::size_t, 3>>& out)
{
  std::vector<CGAL::Triple<int, int, int>> patch;
  try {
    CGAL::Polygon_mesh_processing::triangulate_hole_polyline(p, std::back_inserter(patch));
  } catch(const std::exception&) {
    return false;
  }
  for(const auto& t : patch) {
    if(t.first < 0 || t.second < 0 || t.third < 0) return false;
    out.push_back({{std::size_t(t.first), std::size_t(t.second), std::size_t(t.third)}});
  }
  return accept_triangulation(p.size(), out);
}

// Triangles over the local corners 0..k-1 of the polygon `corners` (indices into `coordinates`).
inline Polygon_triangulation_method triangulate_polygon(const std::vector<std::array<double, 3>>& coordinates,
                                                        const std::vector<std::size_t>& corners,
                                                        std::vector<std::array<std::size_t, 3>>& out,
                                                        std::size_t hole_filling_limit)
{
  typedef Triangulation_kernel K;
  const std::size_t k = corners.size();
  out.clear();
  if(k == 3) {
    out.push_back({{0, 1, 2}});
    return Polygon_triangulation_method::triangle;
  }
  // Geometry is only trusted on distinct points with coordinates whose products stay finite.
  bool usable = true;
  for(std::size_t c : corners)
    for(double x : coordinates[c]) usable = usable && std::isfinite(x) && std::abs(x) <= 1e100;
  if(usable) { // distinct points (by coordinates, not only by index)
    std::vector<std::array<double, 3>> sorted;
    sorted.reserve(k);
    for(std::size_t c : corners) sorted.push_back(coordinates[c]);
    std::sort(sorted.begin(), sorted.end());
    usable = std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
  }
  std::vector<K::Point_3> p;
  if(usable) {
    p.reserve(k);
    for(std::size_t c : corners) p.emplace_back(coordinates[c][0], coordinates[c][1], coordinates[c][2]);
  }
  if(usable && k == 4) {
    // The diagonal whose two triangles have the larger dot product of (area-weighted) normals.
    const double p1p3 = CGAL::cross_product(p[2] - p[1], p[3] - p[2]) * CGAL::cross_product(p[0] - p[3], p[1] - p[0]);
    const double p0p2 = CGAL::cross_product(p[1] - p[0], p[1] - p[2]) * CGAL::cross_product(p[3] - p[2], p[3] - p[0]);
    if(p0p2 > p1p3) out = {{{0, 1, 2}}, {{0, 2, 3}}};
    else out = {{{1, 2, 3}}, {{1, 3, 0}}};
    return Polygon_triangulation_method::quadrilateral;
  }
  if(usable) {
    // Newell's normal: the polygon's orientation and plane, for concave polygons too.
    double nx = 0, ny = 0, nz = 0;
    for(std::size_t i = 0; i < k; ++i) {
      const auto& a = coordinates[corners[i]];
      const auto& b = coordinates[corners[(i + 1) % k]];
      nx += (a[1] - b[1]) * (a[2] + b[2]);
      ny += (a[2] - b[2]) * (a[0] + b[0]);
      nz += (a[0] - b[0]) * (a[1] + b[1]);
    }
    // A zero (or overflowing) normal: a polygon of zero area, which no geometric method triangulates better
    // than a fan.
    if(std::isfinite(nx) && std::isfinite(ny) && std::isfinite(nz) && (nx != 0 || ny != 0 || nz != 0)) {
      if(constrained_delaunay_triangulation(p, K::Vector_3(nx, ny, nz), out))
        return Polygon_triangulation_method::constrained_delaunay;
      out.clear();
      if(k <= hole_filling_limit) {
        if(hole_filling_triangulation(p, out)) return Polygon_triangulation_method::hole_filling;
        out.clear();
      }
    }
  }
  for(std::size_t i = 1; i + 1 < k; ++i) out.push_back({{0, i, i + 1}});
  return Polygon_triangulation_method::fan;
}

} // namespace internal
} // namespace MDCS
} // namespace CGAL

#endif // CGAL_MDCS_INTERNAL_TRIANGULATE_POLYGON_H
