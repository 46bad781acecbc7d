// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Iso-distance curves of a distance field given at the vertices of a triangle mesh or soup, as polylines: the level
// sets of the linear interpolation of the vertex values on every face, chained across edges into open and closed
// polylines. Used by `mdcs geodesics` (isolines.csv).

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_ISO_DISTANCE_CURVES_H
#define CGAL_POLYHEDRAL_GEODESICS_3_ISO_DISTANCE_CURVES_H

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  One iso-distance curve: a polyline on the surface along which the linearly interpolated distance equals `level`.
  Every point lies on an edge of the mesh (or at a vertex whose value is the level).
*/
template <class Point_3>
struct Iso_distance_curve
{
  double level = 0;            ///< the distance value of the curve
  bool closed = false;         ///< a closed loop: the last point joins the first (which is not repeated)
  std::vector<Point_3> points; ///< the polyline's points in order, no two consecutive ones equal
};

namespace internal {

// A crossing: the edge (smaller vertex index first) and the number of the level. Both faces of an edge compute the
// same point from the same ordered pair, so the chains meet exactly.
typedef std::pair<std::pair<std::size_t, std::size_t>, std::size_t> Iso_crossing;

template <class Point_3>
Point_3 iso_crossing_point(const std::vector<Point_3>& points, const std::vector<double>& value, std::size_t a,
                           std::size_t b, double level)
{
  typedef typename Kernel_traits<Point_3>::Kernel::FT FT;
  if(a > b)
    std::swap(a, b);
  const double s = (level - value[a]) / (value[b] - value[a]);
  if(s == 0)
    return points[a];
  if(s == 1) // at b exactly (a + (b - a) may round)
    return points[b];
  return points[a] + (points[b] - points[a]) * FT(s);
}

// The curves of an indexed triangle soup; `levels` sorted, distinct and finite.
template <class Point_3, class TriangleRange, class OutputIterator>
OutputIterator iso_curves_of_soup(const std::vector<Point_3>& points, const TriangleRange& triangles,
                                  const std::vector<double>& value, const std::vector<double>& levels,
                                  OutputIterator out)
{
  if(levels.empty())
    return out;
  // Segments per level, each joining two crossings.
  std::map<std::size_t, std::vector<std::pair<Iso_crossing, Iso_crossing>>> segments;
  for(const auto& triangle : triangles) {
    std::array<std::size_t, 3> t;
    std::size_t corners = 0;
    for(const auto& index : triangle) {
      if(corners == 3)
        throw std::invalid_argument("CGAL::Polyhedral_geodesics_3::iso_distance_curves: a face is not a triangle");
      t[corners++] = std::size_t(index);
    }
    if(corners != 3)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3::iso_distance_curves: a face is not a triangle");
    for(std::size_t i : t)
      if(i >= value.size())
        throw std::invalid_argument("CGAL::Polyhedral_geodesics_3::iso_distance_curves: a vertex index is out of range");
    const double d[3] = {value[t[0]], value[t[1]], value[t[2]]};
    if(!std::isfinite(d[0]) || !std::isfinite(d[1]) || !std::isfinite(d[2]))
      continue; // a face with an unreachable corner has no curve
    const double lo = std::min({d[0], d[1], d[2]}), hi = std::max({d[0], d[1], d[2]});
    const std::size_t first = std::size_t(std::upper_bound(levels.begin(), levels.end(), lo) - levels.begin());
    const std::size_t last = std::size_t(std::upper_bound(levels.begin(), levels.end(), hi) - levels.begin());
    for(std::size_t k = first; k < last; ++k) {
      const double level = levels[k];
      Iso_crossing ends[2];
      int found = 0;
      for(std::size_t e = 0; e < 3 && found < 2; ++e) {
        const std::size_t a = t[e], b = t[(e + 1) % 3];
        if((value[a] >= level) == (value[b] >= level))
          continue;
        ends[found++] = Iso_crossing(std::make_pair(std::min(a, b), std::max(a, b)), k);
      }
      if(found == 2 && ends[0] != ends[1])
        segments[k].emplace_back(ends[0], ends[1]);
    }
  }
  // Chain the segments of each level: a crossing is shared by at most two segments on a manifold edge; where more
  // meet (a non-manifold edge) the chain simply stops there.
  for(auto& level_segments : segments) {
    const double level = levels[level_segments.first];
    auto& segs = level_segments.second;
    std::multimap<Iso_crossing, std::size_t> at;
    for(std::size_t i = 0; i < segs.size(); ++i) {
      at.emplace(segs[i].first, i);
      at.emplace(segs[i].second, i);
    }
    std::vector<char> used(segs.size(), 0);
    auto next_segment = [&](const Iso_crossing& c) -> long {
      const auto range = at.equal_range(c);
      for(auto it = range.first; it != range.second; ++it)
        if(!used[it->second])
          return long(it->second);
      return -1;
    };
    auto other_end = [&](std::size_t i, const Iso_crossing& c) {
      return segs[i].first == c ? segs[i].second : segs[i].first;
    };
    auto point = [&](const Iso_crossing& c) {
      return iso_crossing_point(points, value, c.first.first, c.first.second, level);
    };
    for(std::size_t start = 0; start < segs.size(); ++start) {
      if(used[start])
        continue;
      used[start] = 1;
      std::vector<Iso_crossing> chain = {segs[start].first, segs[start].second};
      for(long i; (i = next_segment(chain.back())) >= 0;) { // forwards
        used[std::size_t(i)] = 1;
        chain.push_back(other_end(std::size_t(i), chain.back()));
      }
      std::vector<Iso_crossing> head = {segs[start].first};
      for(long i; (i = next_segment(head.back())) >= 0;) { // backwards
        used[std::size_t(i)] = 1;
        head.push_back(other_end(std::size_t(i), head.back()));
      }
      Iso_distance_curve<Point_3> curve;
      curve.level = level;
      // A curve through a vertex whose value is the level crosses two of its edges there: one point.
      auto push = [&](const Point_3& p) {
        if(curve.points.empty() || !(curve.points.back() == p))
          curve.points.push_back(p);
      };
      for(std::size_t k = head.size(); k-- > 1;)
        push(point(head[k]));
      for(const Iso_crossing& c : chain)
        push(point(c));
      curve.closed = chain.size() > 2 && chain.front() == chain.back() && head.size() == 1;
      if(curve.closed && curve.points.size() > 1 && curve.points.front() == curve.points.back())
        curve.points.pop_back(); // the first point once
      *out++ = std::move(curve);
    }
  }
  return out;
}

// The finite levels, sorted, each once.
template <class LevelRange>
std::vector<double> iso_levels(const LevelRange& levels)
{
  std::vector<double> r;
  for(const auto& l : levels) {
    const double x = CGAL::to_double(l);
    if(std::isfinite(x))
      r.push_back(x);
  }
  std::sort(r.begin(), r.end());
  r.erase(std::unique(r.begin(), r.end()), r.end());
  return r;
}

} // namespace internal

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief Writes the iso-distance curves of a vertex distance field on an indexed triangle soup to `out`.

  On every triangle the distance is interpolated linearly between its corners; the curve of a level is that
  interpolation's level set, one segment per triangle that it crosses, chained across the shared edges into
  polylines. A curve is closed when it comes back to its start, open when it ends on the border of the surface
  (or on a non-manifold edge, or at a triangle with an unreachable corner). A corner counts as above a level when
  its value is at least the level, so a curve through a vertex is reported once, and a level equal to the
  smallest value of the field has no curve. Triangles with a non-finite corner value (`+infinity`: unreachable)
  have no curve. Curves come by increasing level.

  \tparam PointRange a range of `Point_3` of a CGAL kernel (the curve points are constructed in that kernel).
  \tparam TriangleRange a range of triangles, each a range of three vertex indices into `points`.
  \tparam DistanceRange a random-access range of numbers convertible with `CGAL::to_double()`, one per point
          (e.g. the distances read from a geodesic class, `+infinity` where unreachable).
  \tparam LevelRange a range of numbers: the levels (sorted and made distinct here; non-finite ones are ignored).
  \tparam OutputIterator an output iterator accepting `Iso_distance_curve<Point_3>`.

  Throws `std::invalid_argument` if a triangle does not have three corners or names a point that does not exist.
*/
template <class PointRange, class TriangleRange, class DistanceRange, class LevelRange, class OutputIterator>
OutputIterator triangle_soup_iso_distance_curves(const PointRange& points, const TriangleRange& triangles,
                                                 const DistanceRange& distances, const LevelRange& levels,
                                                 OutputIterator out)
{
  typedef typename std::iterator_traits<decltype(std::begin(points))>::value_type Point_3;
  const std::vector<Point_3> p(std::begin(points), std::end(points));
  std::vector<double> value;
  for(const auto& d : distances)
    value.push_back(CGAL::to_double(d));
  if(value.size() != p.size())
    throw std::invalid_argument("CGAL::Polyhedral_geodesics_3::iso_distance_curves: one distance per point is needed");
  return internal::iso_curves_of_soup(p, triangles, value, internal::iso_levels(levels), out);
}

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief Writes the iso-distance curves of the vertex distances `distance_map` on the triangle mesh `tm` to `out`,
  as `triangle_soup_iso_distance_curves()` does on the mesh's faces.

  \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles (others: `std::invalid_argument`).
  \tparam VertexDistanceMap a readable vertex property map of numbers (e.g. filled by `distances()` of a
          geodesic distance class; `+infinity` where unreachable).
  \tparam LevelRange a range of numbers: the levels.
  \tparam OutputIterator an output iterator accepting `Iso_distance_curve<Point_3>`, `Point_3` the value type of
          the vertex point map.

  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map} the 3D point of each vertex, default `get(CGAL::vertex_point, tm)` \cgalParamNEnd
    \cgalParamNBegin{vertex_index_map} an index of the vertices in [0, num_vertices(tm)), default: the mesh's
      own or one made for the call \cgalParamNEnd
  \cgalNamedParamsEnd
*/
template <class TriangleMesh, class VertexDistanceMap, class LevelRange, class OutputIterator,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
OutputIterator iso_distance_curves(const TriangleMesh& tm, VertexDistanceMap distance_map, const LevelRange& levels,
                                   OutputIterator out, const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point_3;
  const VPM vpm = choose_parameter(get_parameter(np, internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  std::vector<Point_3> points(num_vertices(tm));
  std::vector<double> value(num_vertices(tm), 0);
  for(auto v : vertices(tm)) {
    const std::size_t i = std::size_t(get(vim, v));
    points[i] = get(vpm, v);
    value[i] = CGAL::to_double(get(distance_map, v));
  }
  std::vector<std::array<std::size_t, 3>> triangles;
  triangles.reserve(num_faces(tm));
  for(auto f : faces(tm)) {
    const auto h = halfedge(f, tm);
    if(next(next(next(h, tm), tm), tm) != h)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3::iso_distance_curves: a face is not a triangle");
    triangles.push_back({{std::size_t(get(vim, source(h, tm))), std::size_t(get(vim, target(h, tm))),
                          std::size_t(get(vim, target(next(h, tm), tm)))}});
  }
  return internal::iso_curves_of_soup(points, triangles, value, internal::iso_levels(levels), out);
}

} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_ISO_DISTANCE_CURVES_H
