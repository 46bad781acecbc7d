// Iso-distance lines of a distance field on a triangle mesh, as polylines (isolines.csv of `mdcs geodesics`): the
// level set of the linear interpolation of the vertex distances on every face, chained across edges. The levels
// are round values (geodesic_render.h: nice_spacing) and their number is bounded by the spacing, whatever the
// distances are: no loop runs longer than the levels asked for.
#ifndef MDCS_CLI_GEODESIC_ISOLINES_H
#define MDCS_CLI_GEODESIC_ISOLINES_H

#include "geodesic_render.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace mdcs_cli {

struct Isoline
{
  double level = 0;
  bool closed = false;
  std::vector<Geo_vec> points;
};

namespace isoline_detail {

// A crossing point: the edge (smaller vertex first) and the level's number. Both faces of an edge compute the same
// point from the same ordered pair, so the chains meet exactly.
typedef std::pair<std::pair<std::size_t, std::size_t>, long> Crossing;

inline Geo_vec crossing_point(const std::vector<Geo_vec>& points, const std::vector<double>& distance, std::size_t a, std::size_t b,
                              double level)
{
  if(a > b) std::swap(a, b);
  const double s = (level - distance[a]) / (distance[b] - distance[a]);
  return {{points[a][0] + s * (points[b][0] - points[a][0]), points[a][1] + s * (points[b][1] - points[a][1]),
           points[a][2] + s * (points[b][2] - points[a][2])}};
}

} // namespace isoline_detail

// The iso-lines at `spacing`, 2 spacing, ... up to `max_distance` (at most `max_levels` levels), on the faces whose
// three distances are finite.
inline std::vector<Isoline> compute_isolines(const std::vector<Geo_vec>& points, const std::vector<std::array<std::size_t, 3>>& triangles,
                                             const std::vector<double>& distance, double spacing, double max_distance,
                                             long max_levels)
{
  using namespace isoline_detail;
  std::vector<Isoline> lines;
  if(!(spacing > 0) || !std::isfinite(spacing) || !std::isfinite(max_distance) || max_levels <= 0) return lines;
  const double top = std::floor(max_distance / spacing);
  if(!(top >= 1)) return lines;
  const long levels = long(std::min(top, double(max_levels)));
  // Segments per level, each joining two crossings.
  std::map<long, std::vector<std::pair<Crossing, Crossing>>> segments;
  for(const auto& t : triangles) {
    const double d[3] = {distance[t[0]], distance[t[1]], distance[t[2]]};
    if(!std::isfinite(d[0]) || !std::isfinite(d[1]) || !std::isfinite(d[2])) continue;
    const double lo = std::min({d[0], d[1], d[2]}), hi = std::max({d[0], d[1], d[2]});
    const long first = std::max(1L, long(std::ceil(std::min(lo / spacing, double(levels) + 1))));
    const long last = long(std::min(std::floor(hi / spacing), double(levels)));
    for(long k = first; k <= last; ++k) {
      const double level = double(k) * spacing;
      Crossing ends[2];
      int found = 0;
      for(int e = 0; e < 3 && found < 2; ++e) {
        const std::size_t a = t[std::size_t(e)], b = t[std::size_t((e + 1) % 3)];
        if((distance[a] >= level) == (distance[b] >= level)) continue;
        ends[found++] = Crossing(std::make_pair(std::min(a, b), std::max(a, b)), k);
      }
      if(found == 2 && ends[0] != ends[1]) segments[k].emplace_back(ends[0], ends[1]);
    }
  }
  // Chain the segments of each level: a crossing is shared by at most two segments on a manifold edge; where more
  // meet (a non-manifold edge) the chain simply stops there.
  for(auto& level_segments : segments) {
    const double level = double(level_segments.first) * spacing;
    auto& segs = level_segments.second;
    std::multimap<Crossing, std::size_t> at;
    for(std::size_t i = 0; i < segs.size(); ++i) {
      at.emplace(segs[i].first, i);
      at.emplace(segs[i].second, i);
    }
    std::vector<char> used(segs.size(), 0);
    auto next_segment = [&](const Crossing& c) -> long {
      const auto range = at.equal_range(c);
      for(auto it = range.first; it != range.second; ++it)
        if(!used[it->second]) return long(it->second);
      return -1;
    };
    auto other_end = [&](std::size_t i, const Crossing& c) { return segs[i].first == c ? segs[i].second : segs[i].first; };
    for(std::size_t start = 0; start < segs.size(); ++start) {
      if(used[start]) continue;
      used[start] = 1;
      std::vector<Crossing> chain = {segs[start].first, segs[start].second};
      for(long i; (i = next_segment(chain.back())) >= 0;) { // forwards
        used[std::size_t(i)] = 1;
        chain.push_back(other_end(std::size_t(i), chain.back()));
      }
      std::vector<Crossing> head = {segs[start].first};
      for(long i; (i = next_segment(head.back())) >= 0;) { // backwards
        used[std::size_t(i)] = 1;
        head.push_back(other_end(std::size_t(i), head.back()));
      }
      Isoline line;
      line.level = level;
      for(std::size_t k = head.size(); k-- > 1;)
        line.points.push_back(crossing_point(points, distance, head[k].first.first, head[k].first.second, level));
      for(const Crossing& c : chain) line.points.push_back(crossing_point(points, distance, c.first.first, c.first.second, level));
      line.closed = chain.size() > 2 && chain.front() == chain.back() && head.size() == 1;
      if(line.closed) line.points.pop_back(); // the first point once
      lines.push_back(std::move(line));
    }
  }
  return lines;
}

} // namespace mdcs_cli

#endif // MDCS_CLI_GEODESIC_ISOLINES_H
