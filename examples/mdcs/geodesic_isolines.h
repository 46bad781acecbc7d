// Iso-distance lines of a distance field on a triangle mesh, as polylines (isolines.csv of `mdcs geodesics`): the
// library's CGAL::Polyhedral_geodesics_3::triangle_soup_iso_distance_curves() (the level set of the linear
// interpolation of the vertex distances on every face, chained across edges) at round levels (geodesic_render.h:
// nice_spacing), whose number is bounded by the spacing, whatever the distances are: no loop runs longer than the
// levels asked for.
#ifndef MDCS_CLI_GEODESIC_ISOLINES_H
#define MDCS_CLI_GEODESIC_ISOLINES_H

#include "geodesic_render.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedral_geodesics_3/iso_distance_curves.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <utility>
#include <vector>

namespace mdcs_cli {

struct Isoline
{
  double level = 0;
  bool closed = false;
  std::vector<Geo_vec> points;
};

// The iso-lines at `spacing`, 2 spacing, ... up to `max_distance` (at most `max_levels` levels), on the faces whose
// three distances are finite.
inline std::vector<Isoline> compute_isolines(const std::vector<Geo_vec>& points, const std::vector<std::array<std::size_t, 3>>& triangles,
                                             const std::vector<double>& distance, double spacing, double max_distance,
                                             long max_levels)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Point_3;
  std::vector<Isoline> lines;
  if(!(spacing > 0) || !std::isfinite(spacing) || !std::isfinite(max_distance) || max_levels <= 0) return lines;
  const double top = std::floor(max_distance / spacing);
  if(!(top >= 1)) return lines;
  const long count = long(std::min(top, double(max_levels)));
  std::vector<double> levels;
  for(long k = 1; k <= count; ++k) levels.push_back(double(k) * spacing);
  std::vector<Point_3> p;
  p.reserve(points.size());
  for(const Geo_vec& q : points) p.emplace_back(q[0], q[1], q[2]);
  std::vector<CGAL::Polyhedral_geodesics_3::Iso_distance_curve<Point_3>> curves;
  CGAL::Polyhedral_geodesics_3::triangle_soup_iso_distance_curves(p, triangles, distance, levels, std::back_inserter(curves));
  for(const auto& c : curves) {
    Isoline line;
    line.level = c.level;
    line.closed = c.closed;
    for(const Point_3& q : c.points) line.points.push_back({{q.x(), q.y(), q.z()}});
    lines.push_back(std::move(line));
  }
  return lines;
}

} // namespace mdcs_cli

#endif // MDCS_CLI_GEODESIC_ISOLINES_H
