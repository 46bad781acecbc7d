// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// simple_polygon_mwt_2(): the minimum weight triangulation of a simple polygon (the interior face of a planar
// straight-line graph, thesis ch. 3.6, Cor. 3.6.2), by the O(k^3) dynamic program of Klincsek restricted to the
// diagonals that lie inside the polygon (exact predicates). Its choices are exact for the double coordinates, as
// those of convex_polygon_mwt_2(): double sums with a forward error bound, exact comparison where it does not
// separate the best candidate. planar_graph_face_mwt_2(): the same for a face of a graph given by vertex indices.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_SIMPLE_POLYGON_MWT_2_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_SIMPLE_POLYGON_MWT_2_H

#include <CGAL/Minimum_weight_triangulation_2/Mwt_result.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Coordinate_range_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Polygon_dp_2.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {

/// The largest polygon `simple_polygon_mwt_2()` accepts: O(k^3) time (the diagonal tests included) and 13 k^2
/// bytes of tables.
inline std::size_t simple_polygon_mwt_max_vertices() { return 4096; }

namespace internal {

// Whether the segment (a, b) between two non-adjacent vertices of the simple counter-clockwise polygon p is a
// diagonal: it leaves a and b into the interior (in-cone tests) and meets the boundary nowhere else (no vertex on
// it, no edge crossing it). Exact with the kernel's orientation.
template <class Point_2, class Orientation_2>
bool is_polygon_diagonal(const std::vector<Point_2>& p, int a, int b, const Orientation_2& orient)
{
  const int k = int(p.size());
  auto left = [&](int u, int v, int w) { return orient(p[u], p[v], p[w]) == CGAL::LEFT_TURN; };
  auto left_on = [&](int u, int v, int w) { return orient(p[u], p[v], p[w]) != CGAL::RIGHT_TURN; };
  auto in_cone = [&](int u, int v) {
    const int next = (u + 1) % k, prev = (u + k - 1) % k;
    if(left_on(u, next, prev)) // convex (or flat) corner at u
      return left(u, v, prev) && left(v, u, next);
    return !(left_on(u, v, next) && left_on(v, u, prev)); // reflex corner
  };
  if(!in_cone(a, b) || !in_cone(b, a))
    return false;
  for(int c = 0; c < k; ++c) {
    if(c == a || c == b)
      continue;
    // a vertex on the closed segment
    if(orient(p[a], p[b], p[c]) == CGAL::COLLINEAR && CGAL::collinear_are_ordered_along_line(p[a], p[c], p[b]))
      return false;
    const int d = (c + 1) % k;
    if(d == a || d == b)
      continue;
    // an edge (c, d) without a or b that crosses the segment (touching is the vertex case above)
    const auto o1 = orient(p[a], p[b], p[c]), o2 = orient(p[a], p[b], p[d]);
    const auto o3 = orient(p[c], p[d], p[a]), o4 = orient(p[c], p[d], p[b]);
    if(o1 != CGAL::COLLINEAR && o2 != CGAL::COLLINEAR && o1 != o2 && o3 != CGAL::COLLINEAR &&
       o4 != CGAL::COLLINEAR && o3 != o4)
      return false;
  }
  return true;
}

} // namespace internal

/*!
  \brief Minimum weight triangulation of a simple polygon given by its vertices in counter-clockwise order (the
  interior face of a planar straight-line graph, whose triangle LP the thesis proves integral, Cor. 3.6.2), by
  dynamic programming over the diagonals inside the polygon, in O(k^3) time and O(k^2) memory.

  Writes the k-2 triangles (index triples into the input, counter-clockwise) to `out` and returns the weight (sum
  of all edge lengths, boundary included). A segment between two vertices is a diagonal when it runs inside the
  polygon and meets its boundary at its ends only (exact orientation tests; a vertex on the segment excludes it).
  Consecutive collinear vertices are allowed (no triangle is flat). As in `convex_polygon_mwt_2()`, every choice of
  the program is exact for the double coordinates (a minimum of exact sums of lengths, ties broken by the smallest
  apex index); `exact_decisions`, if given, receives the number of exact comparisons made. On a convex polygon the
  result is that of `convex_polygon_mwt_2()`.

  \tparam PointRange a range of `Point_2` of a CGAL kernel.
  \throws std::invalid_argument when fewer than 3 or more than `simple_polygon_mwt_max_vertices()` vertices are
  given, a coordinate is outside `Mwt_coordinate_range`, two vertices coincide, two edges cross or touch away from
  their shared vertex (not simple), or the polygon is clockwise (or of zero area).
*/
template <class PointRange, class OutputIterator>
double simple_polygon_mwt_2(const PointRange& polygon, OutputIterator out, Edge_metric metric = Edge_metric::L2,
                            std::size_t* exact_decisions = nullptr)
{
  typedef typename std::iterator_traits<decltype(std::begin(polygon))>::value_type Point_2;
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel K;
  const char* who = "simple_polygon_mwt_2";
  const std::vector<Point_2> p(std::begin(polygon), std::end(polygon));
  const std::size_t size = p.size();
  if(size < 3)
    throw std::invalid_argument(std::string(who) + ": needs at least 3 vertices");
  if(size > simple_polygon_mwt_max_vertices())
    throw std::invalid_argument(std::string(who) + ": " + std::to_string(size) + " vertices; at most " +
                                std::to_string(simple_polygon_mwt_max_vertices()));
  const int k = int(size);
  {
    struct Doubles
    {
      const std::vector<Point_2>& p;
      std::size_t size() const { return p.size(); }
      double x(int i) const { return CGAL::to_double(p[std::size_t(i)].x()); }
      double y(int i) const { return CGAL::to_double(p[std::size_t(i)].y()); }
    } doubles{p};
    internal::check_coordinate_range(doubles, who);
  }
  const typename K::Orientation_2 orient = K().orientation_2_object();
  // simple: distinct vertices, no two edges meeting except consecutive ones at their shared vertex
  for(int i = 0; i < k; ++i)
    for(int j = i + 1; j < k; ++j)
      if(p[i] == p[j])
        throw std::invalid_argument(std::string(who) + ": vertices " + std::to_string(i) + " and " + std::to_string(j) +
                                    " coincide");
  for(int i = 0; i < k; ++i)
    for(int j = i + 1; j < k; ++j) {
      const int i1 = (i + 1) % k, j1 = (j + 1) % k;
      const typename K::Segment_2 a(p[i], p[i1]), b(p[j], p[j1]);
      if(j == i1 || i == j1) { // consecutive: they may only share the vertex (no overlap)
        const int shared = j == i1 ? j : i, u = j == i1 ? i : j, w = j == i1 ? j1 : i1;
        if(orient(p[u], p[shared], p[w]) == CGAL::COLLINEAR &&
           !CGAL::collinear_are_ordered_along_line(p[u], p[shared], p[w]))
          throw std::invalid_argument(std::string(who) + ": the polygon is not simple (edges " + std::to_string(i) +
                                      " and " + std::to_string(j) + " overlap)");
        continue;
      }
      if(CGAL::do_intersect(a, b))
        throw std::invalid_argument(std::string(who) + ": the polygon is not simple (edges " + std::to_string(i) +
                                    " and " + std::to_string(j) + " meet)");
    }
  {
    // orientation: the lowest-leftmost vertex is a strictly convex corner (no two edges touch, so it is not flat
    // unless its neighbours are collinear with it, which they cannot be on both sides of a lowest point)
    int m = 0;
    for(int i = 1; i < k; ++i)
      if(CGAL::compare_xy(p[i], p[m]) == CGAL::SMALLER)
        m = i;
    const auto o = orient(p[(m + k - 1) % k], p[m], p[(m + 1) % k]);
    if(o != CGAL::LEFT_TURN)
      throw std::invalid_argument(std::string(who) + (o == CGAL::RIGHT_TURN ? ": the polygon is clockwise"
                                                                             : ": the polygon has no area"));
  }
  auto len = [&](int a, int b) {
    const double dx = CGAL::to_double(p[b].x()) - CGAL::to_double(p[a].x());
    const double dy = CGAL::to_double(p[b].y()) - CGAL::to_double(p[a].y());
    switch(metric) {
      case Edge_metric::L1: return std::abs(dx) + std::abs(dy);
      case Edge_metric::Linf: return std::max(std::abs(dx), std::abs(dy));
      default: return std::sqrt(dx * dx + dy * dy);
    }
  };
  std::vector<double> x(size, 0.0), y(size, 0.0);
  for(int i = 0; i < k; ++i) {
    x[i] = CGAL::to_double(p[i].x());
    y[i] = CGAL::to_double(p[i].y());
  }
  // usable[i][j] (i < j): (i, j) is an edge of the polygon or a diagonal
  std::vector<char> usable(size * size, 0);
  for(int i = 0; i < k; ++i)
    for(int j = i + 1; j < k; ++j)
      usable[i * k + j] = (j == i + 1 || (i == 0 && j == k - 1)) ? 1 : char(internal::is_polygon_diagonal(p, i, j, orient));
  auto chord_usable = [&](int i, int j) { return usable[i * k + j] != 0; };
  auto apex_usable = [&](int i, int c, int j) {
    return usable[i * k + c] && usable[c * k + j] && orient(p[i], p[c], p[j]) == CGAL::LEFT_TURN;
  };
  auto no_progress = [](int) {};
  const double diagonals =
    internal::polygon_min_weight_dp(k, x, y, len, chord_usable, apex_usable, no_progress, metric, out, exact_decisions);
  if(!(diagonals < std::numeric_limits<double>::infinity())) // cannot happen: every simple polygon has one
    throw std::logic_error(std::string(who) + ": no triangulation found");
  double perimeter = 0;
  for(int i = 0; i < k; ++i)
    perimeter += len(i, (i + 1) % k);
  return perimeter + diagonals;
}

/*!
  \brief Minimum weight triangulation of a bounded face of a planar straight-line graph whose boundary is a simple
  cycle: `face` lists the indices (into `points`, the graph's vertices) of the boundary in either orientation, as a
  face walk gives them. Writes the `face.size() - 2` triangles as index triples into `points` (counter-clockwise)
  to `out` and returns the weight, boundary included (`simple_polygon_mwt_2()` on the boundary, turned
  counter-clockwise if needed). The other vertices of the graph are ignored: the face must contain none of them
  and no hole (the thesis's Cor. 3.6.2 setting: its triangle LP is integral, and this program gives its optimum).

  \tparam PointRange a random-access range of `Point_2` of a CGAL kernel.
  \tparam IndexRange a range of integer indices into `points`.
  \throws std::invalid_argument for an index out of range, or a boundary that `simple_polygon_mwt_2()` refuses
  (not simple, a repeated vertex, fewer than 3 vertices, zero area).
*/
template <class PointRange, class IndexRange, class OutputIterator>
double planar_graph_face_mwt_2(const PointRange& points, const IndexRange& face, OutputIterator out,
                               Edge_metric metric = Edge_metric::L2, std::size_t* exact_decisions = nullptr)
{
  typedef typename std::iterator_traits<decltype(std::begin(points))>::value_type Point_2;
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel K;
  const std::vector<Point_2> all(std::begin(points), std::end(points));
  std::vector<int> index;
  for(const auto& i : face) {
    if(i < 0 || std::size_t(i) >= all.size())
      throw std::invalid_argument("planar_graph_face_mwt_2: a face index is out of range");
    index.push_back(int(i));
  }
  if(index.size() < 3)
    throw std::invalid_argument("planar_graph_face_mwt_2: a face needs at least 3 vertices");
  // counter-clockwise: the lowest-leftmost vertex is a left turn (checked again, exactly, by the polygon program)
  std::size_t m = 0;
  for(std::size_t i = 1; i < index.size(); ++i)
    if(CGAL::compare_xy(all[std::size_t(index[i])], all[std::size_t(index[m])]) == CGAL::SMALLER)
      m = i;
  const std::size_t n = index.size();
  if(K().orientation_2_object()(all[std::size_t(index[(m + n - 1) % n])], all[std::size_t(index[m])],
                                all[std::size_t(index[(m + 1) % n])]) == CGAL::RIGHT_TURN)
    std::reverse(index.begin(), index.end());
  std::vector<Point_2> polygon;
  for(int i : index)
    polygon.push_back(all[std::size_t(i)]);
  std::vector<std::array<int, 3>> local;
  const double w = simple_polygon_mwt_2(polygon, std::back_inserter(local), metric, exact_decisions);
  for(const auto& t : local)
    *out++ = std::array<int, 3>{index[std::size_t(t[0])], index[std::size_t(t[1])], index[std::size_t(t[2])]};
  return w;
}

} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_SIMPLE_POLYGON_MWT_2_H
