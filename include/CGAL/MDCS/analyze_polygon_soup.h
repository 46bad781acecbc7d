// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// analyze_polygon_soup(): what a polygon soup is (triangles or not, degenerate or duplicate faces, isolated
// or coincident points, edges shared by three or more faces, inconsistent orientation, non-orientable parts,
// pinched vertices, components), so that a program can say exactly why it refuses an input.

#ifndef CGAL_MDCS_ANALYZE_POLYGON_SOUP_H
#define CGAL_MDCS_ANALYZE_POLYGON_SOUP_H

#include <CGAL/MDCS/internal/polygon_soup_analysis.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace MDCS {

/*!
  \ingroup PkgMDCSIO
  \brief The classification of a polygon soup by `analyze_polygon_soup()`.

  Faces are the soup's polygons, numbered from 0 in the order given; points likewise. An *edge* is a pair of
  distinct points that are consecutive in some polygon; it is *interior* when exactly two polygons use it,
  in opposite directions (the polygons agree on the orientation), *boundary* when one polygon uses it.

  A soup is a valid oriented polygon mesh (`is_polygon_mesh()`, the condition of
  `CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh()`) when every polygon has at least three
  distinct corners, no edge is used by more than two polygons or twice in the same direction, and the
  polygons around every point form a single fan (no pinched vertex). Isolated points, coincident points,
  duplicate (opposite) faces, zero-area faces and several components are allowed in a mesh and reported.
*/
struct Polygon_soup_analysis
{
  static constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

  std::size_t number_of_points = 0;
  std::size_t number_of_polygons = 0;
  std::size_t smallest_polygon = 0; ///< the fewest corners of a polygon (0 without polygon)
  std::size_t largest_polygon = 0;  ///< the most corners of a polygon

  std::size_t polygons_with_too_few_corners = 0; ///< fewer than 3 corners
  std::size_t polygons_with_repeated_points = 0; ///< one point twice in the same polygon
  std::size_t duplicate_polygons = 0;            ///< the same point set as an earlier polygon
  std::size_t degenerate_polygons = 0;           ///< all corners on a line (zero area; exact predicate)
  std::size_t isolated_points = 0;               ///< used by no polygon
  std::size_t coincident_points = 0;             ///< the same coordinates as another, earlier point
  std::size_t non_finite_points = 0;             ///< a coordinate is NaN or infinite (then the geometric
                                                 ///< counts, degenerate and coincident, are not computed)

  std::size_t boundary_edges = 0;
  std::size_t interior_edges = 0;
  std::size_t non_manifold_edges = 0;   ///< used by three or more polygons, or twice by one polygon
  std::size_t inconsistent_edges = 0;   ///< used by two polygons in the same direction
  std::size_t non_manifold_vertices = 0; ///< the polygons around the point form more than one fan

  std::size_t connected_components = 0;   ///< of the polygons, through shared edges
  std::size_t non_orientable_components = 0; ///< of the polygons through two-polygon edges, that no choice of
                                              ///< orientations makes consistent (Möbius strips, Klein bottles)

  /// \name Examples of each defect, for messages (`none` when there is none)
  /// @{
  std::size_t example_small_polygon = none;
  std::size_t example_repeated_polygon = none, example_repeated_point = none;
  std::array<std::size_t, 2> example_duplicate_polygons{{none, none}};
  std::size_t example_degenerate_polygon = none;
  std::size_t example_isolated_point = none;
  std::array<std::size_t, 2> example_coincident_points{{none, none}};
  std::array<std::size_t, 2> example_non_manifold_edge{{none, none}};
  std::vector<std::size_t> example_non_manifold_edge_polygons; ///< (at most 8 listed)
  std::size_t example_non_manifold_edge_uses = 0;              ///< how many polygon sides run along it
  std::array<std::size_t, 2> example_inconsistent_edge{{none, none}};
  std::array<std::size_t, 2> example_inconsistent_polygons{{none, none}};
  std::array<std::size_t, 2> example_non_orientable_edge{{none, none}};
  std::array<std::size_t, 2> example_non_orientable_polygons{{none, none}};
  std::size_t example_non_manifold_vertex = none, example_non_manifold_vertex_fans = 0;
  /// @}

  /// Every polygon is a triangle (and there is at least one).
  bool all_triangles() const { return number_of_polygons > 0 && smallest_polygon == 3 && largest_polygon == 3; }

  /// A valid oriented manifold polygon mesh (possibly with boundary, several components, isolated points).
  bool is_polygon_mesh() const
  {
    return polygons_with_too_few_corners == 0 && polygons_with_repeated_points == 0 && non_manifold_edges == 0 &&
           inconsistent_edges == 0 && non_manifold_vertices == 0;
  }

  /// A valid oriented manifold triangle mesh with at least one face.
  bool is_triangle_mesh() const { return is_polygon_mesh() && all_triangles(); }

  /// Faces could be reoriented into a valid mesh: the only defect is orientation, and every part is orientable.
  bool is_orientable_polygon_mesh() const
  {
    return polygons_with_too_few_corners == 0 && polygons_with_repeated_points == 0 && non_manifold_edges == 0 &&
           non_manifold_vertices == 0 && non_orientable_components == 0;
  }

  /// The first reason why the soup is not a valid polygon mesh (most basic first), empty if it is one.
  std::string problem() const
  {
    auto n = [](std::size_t v) { return std::to_string(v); };
    auto more = [&](std::size_t count, const char* what) {
      return count > 1 ? " (" + n(count) + " such " + what + ")" : std::string();
    };
    if(polygons_with_too_few_corners > 0)
      return "face " + n(example_small_polygon) + " has fewer than 3 corners" + more(polygons_with_too_few_corners, "faces");
    if(polygons_with_repeated_points > 0)
      return "face " + n(example_repeated_polygon) + " uses vertex " + n(example_repeated_point) + " twice" +
             more(polygons_with_repeated_points, "faces");
    if(non_manifold_edges > 0) {
      std::string faces;
      for(std::size_t f : example_non_manifold_edge_polygons) faces += (faces.empty() ? "" : ", ") + n(f);
      if(example_non_manifold_edge_uses > example_non_manifold_edge_polygons.size()) faces += ", ...";
      return "edge (" + n(example_non_manifold_edge[0]) + ", " + n(example_non_manifold_edge[1]) + ") is shared by " +
             n(example_non_manifold_edge_uses) + " face sides (faces " + faces + "): the surface is not a manifold there" +
             more(non_manifold_edges, "edges");
    }
    if(non_orientable_components > 0)
      return "the surface is not orientable (like a Moebius strip): no choice of face orientations is consistent; faces " +
             n(example_non_orientable_polygons[0]) + " and " + n(example_non_orientable_polygons[1]) + " along edge (" +
             n(example_non_orientable_edge[0]) + ", " + n(example_non_orientable_edge[1]) + ") close the contradiction" +
             more(non_orientable_components, "parts");
    if(inconsistent_edges > 0)
      return "faces " + n(example_inconsistent_polygons[0]) + " and " + n(example_inconsistent_polygons[1]) +
             " run along edge (" + n(example_inconsistent_edge[0]) + ", " + n(example_inconsistent_edge[1]) +
             ") in the same direction: the faces are not consistently oriented (the surface is orientable)" +
             more(inconsistent_edges, "edges");
    if(non_manifold_vertices > 0)
      return "vertex " + n(example_non_manifold_vertex) + " is pinched: the faces around it form " +
             n(example_non_manifold_vertex_fans) + " separate fans" + more(non_manifold_vertices, "vertices");
    return std::string();
  }

  /// All counts in one line.
  std::string summary() const
  {
    auto n = [](std::size_t v) { return std::to_string(v); };
    std::string s = n(number_of_points) + " points, " + n(number_of_polygons) + " faces";
    if(number_of_polygons > 0)
      s += smallest_polygon == largest_polygon ? " of " + n(smallest_polygon) + " corners"
                                               : " of " + n(smallest_polygon) + " to " + n(largest_polygon) + " corners";
    s += ", " + n(connected_components) + (connected_components == 1 ? " component" : " components");
    s += ", " + n(boundary_edges) + " boundary edges";
    auto add = [&](std::size_t count, const char* what) {
      if(count > 0) s += ", " + n(count) + " " + what;
    };
    add(polygons_with_too_few_corners, "faces with fewer than 3 corners");
    add(polygons_with_repeated_points, "faces with a repeated vertex");
    add(non_manifold_edges, "edges shared by 3+ face sides");
    add(inconsistent_edges, "inconsistently oriented edges");
    add(non_orientable_components, "non-orientable parts");
    add(non_manifold_vertices, "pinched vertices");
    add(duplicate_polygons, "duplicate faces");
    add(degenerate_polygons, "zero-area faces");
    add(isolated_points, "isolated points");
    add(coincident_points, "coincident points");
    add(non_finite_points, "points with a non-finite coordinate");
    return s;
  }
};

namespace internal {

// The analysis of compressed rows; `coordinates` may be empty (then no geometric test is made).
inline Polygon_soup_analysis analyze_soup_rows(const Soup_rows& rows, std::size_t number_of_points,
                                               const std::vector<std::array<double, 3>>& coordinates)
{
  typedef Polygon_soup_analysis A;
  A a;
  a.number_of_points = number_of_points;
  const std::size_t nf = rows.number_of_polygons();
  a.number_of_polygons = nf;
  const std::size_t corners = rows.corners.size();

  // Polygon sizes, repeated points, isolated points.
  std::vector<unsigned char> used(number_of_points, 0);
  std::vector<std::size_t> sorted(rows.corners); // each polygon's corners sorted: repeated points, duplicates
  a.smallest_polygon = nf > 0 ? std::numeric_limits<std::size_t>::max() : 0;
  for(std::size_t f = 0; f < nf; ++f) {
    const std::size_t k = rows.size(f);
    a.smallest_polygon = std::min(a.smallest_polygon, k);
    a.largest_polygon = std::max(a.largest_polygon, k);
    if(k < 3) {
      if(a.polygons_with_too_few_corners++ == 0) a.example_small_polygon = f;
    }
    const auto b = sorted.begin() + std::ptrdiff_t(rows.offsets[f]), e = sorted.begin() + std::ptrdiff_t(rows.offsets[f + 1]);
    std::sort(b, e);
    const auto twice = std::adjacent_find(b, e);
    if(twice != e) {
      if(a.polygons_with_repeated_points++ == 0) {
        a.example_repeated_polygon = f;
        a.example_repeated_point = *twice;
      }
    }
    for(std::size_t i = rows.offsets[f]; i < rows.offsets[f + 1]; ++i) used[rows.corners[i]] = 1;
  }
  for(std::size_t v = 0; v < number_of_points; ++v)
    if(!used[v] && a.isolated_points++ == 0) a.example_isolated_point = v;

  // Duplicate polygons: equal sorted corner lists.
  {
    std::vector<std::size_t> order(nf);
    std::iota(order.begin(), order.end(), std::size_t(0));
    auto less = [&](std::size_t f, std::size_t g) {
      return std::lexicographical_compare(sorted.begin() + std::ptrdiff_t(rows.offsets[f]), sorted.begin() + std::ptrdiff_t(rows.offsets[f + 1]),
                                          sorted.begin() + std::ptrdiff_t(rows.offsets[g]), sorted.begin() + std::ptrdiff_t(rows.offsets[g + 1]));
    };
    std::stable_sort(order.begin(), order.end(), less);
    for(std::size_t i = 1; i < nf; ++i) {
      if(!less(order[i - 1], order[i]) && rows.size(order[i]) > 0) {
        if(a.duplicate_polygons++ == 0) a.example_duplicate_polygons = {{order[i - 1], order[i]}};
      }
    }
  }

  // Edges: one record per polygon side between distinct points, sorted by the edge's end points.
  struct Side
  {
    std::size_t lo, hi, corner; // the side runs from corners[corner] to the next corner of its polygon
  };
  std::vector<std::size_t> polygon_of_corner(corners);
  std::vector<Side> sides;
  sides.reserve(corners);
  for(std::size_t f = 0; f < nf; ++f) {
    const std::size_t k = rows.size(f);
    for(std::size_t i = 0; i < k; ++i) {
      const std::size_t c = rows.offsets[f] + i;
      polygon_of_corner[c] = f;
      if(k < 2) continue;
      const std::size_t p = rows.corners[c], q = rows.corner(f, (i + 1) % k);
      if(p != q) sides.push_back(Side{std::min(p, q), std::max(p, q), c});
    }
  }
  std::sort(sides.begin(), sides.end(), [](const Side& s, const Side& t) {
    return s.lo != t.lo ? s.lo < t.lo : s.hi != t.hi ? s.hi < t.hi : s.corner < t.corner;
  });
  auto next_corner = [&](std::size_t c) {
    const std::size_t f = polygon_of_corner[c];
    return c + 1 == rows.offsets[f + 1] ? rows.offsets[f] : c + 1;
  };
  auto forward = [&](const Side& s) { return rows.corners[s.corner] == s.lo; };

  Union_find components(nf);
  Union_find fans(corners);          // corners around a point joined through two-polygon edges
  Parity_union_find orientation(nf); // flip(f) xor flip(g) across two-polygon edges
  std::vector<std::size_t> contradiction_polygons;
  for(std::size_t i = 0; i < sides.size();) {
    std::size_t j = i + 1;
    while(j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi) ++j;
    const std::size_t uses = j - i;
    for(std::size_t m = i + 1; m < j; ++m)
      components.unite(polygon_of_corner[sides[i].corner], polygon_of_corner[sides[m].corner]);
    const std::size_t f = polygon_of_corner[sides[i].corner];
    const std::size_t g = uses >= 2 ? polygon_of_corner[sides[i + 1].corner] : f;
    if(uses == 1) {
      ++a.boundary_edges;
    } else if(uses == 2 && f != g) {
      const bool same_direction = forward(sides[i]) == forward(sides[i + 1]);
      if(same_direction) {
        if(a.inconsistent_edges++ == 0) {
          a.example_inconsistent_edge = {{sides[i].lo, sides[i].hi}};
          a.example_inconsistent_polygons = {{f, g}};
        }
      } else {
        ++a.interior_edges;
      }
      // Consistent orientation needs flip(f) == flip(g) when the sides run in opposite directions.
      if(!orientation.unite(f, g, same_direction ? 1 : 0)) {
        contradiction_polygons.push_back(f);
        if(a.example_non_orientable_polygons[0] == A::none) {
          a.example_non_orientable_edge = {{sides[i].lo, sides[i].hi}};
          a.example_non_orientable_polygons = {{f, g}};
        }
      }
      // The fans: the corners of f and g at each end of the edge are neighbours around that point.
      const std::size_t cf = sides[i].corner, cg = sides[i + 1].corner;
      const std::size_t cf_next = next_corner(cf), cg_next = next_corner(cg);
      if(same_direction) {
        fans.unite(cf, cg);
        fans.unite(cf_next, cg_next);
      } else {
        fans.unite(cf, cg_next);
        fans.unite(cf_next, cg);
      }
    } else {
      if(a.non_manifold_edges++ == 0) {
        a.example_non_manifold_edge = {{sides[i].lo, sides[i].hi}};
        a.example_non_manifold_edge_uses = uses;
        for(std::size_t m = i; m < j && a.example_non_manifold_edge_polygons.size() < 8; ++m)
          a.example_non_manifold_edge_polygons.push_back(polygon_of_corner[sides[m].corner]);
      }
    }
    i = j;
  }
  {
    std::vector<std::size_t> roots;
    roots.reserve(nf);
    for(std::size_t f = 0; f < nf; ++f) roots.push_back(components.find(f));
    std::sort(roots.begin(), roots.end());
    a.connected_components = std::size_t(std::unique(roots.begin(), roots.end()) - roots.begin());
    roots.clear();
    for(std::size_t f : contradiction_polygons) roots.push_back(orientation.find(f).first);
    std::sort(roots.begin(), roots.end());
    a.non_orientable_components = std::size_t(std::unique(roots.begin(), roots.end()) - roots.begin());
  }

  // Pinched points: the corners at a point belong to more than one fan.
  {
    std::vector<std::size_t> start(number_of_points + 1, 0), at(corners);
    for(std::size_t c = 0; c < corners; ++c) ++start[rows.corners[c] + 1];
    for(std::size_t v = 0; v < number_of_points; ++v) start[v + 1] += start[v];
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for(std::size_t c = 0; c < corners; ++c) at[fill[rows.corners[c]]++] = c;
    std::vector<std::size_t> roots;
    for(std::size_t v = 0; v < number_of_points; ++v) {
      if(start[v + 1] - start[v] < 2) continue;
      roots.clear();
      for(std::size_t i = start[v]; i < start[v + 1]; ++i) roots.push_back(fans.find(at[i]));
      std::sort(roots.begin(), roots.end());
      const std::size_t distinct = std::size_t(std::unique(roots.begin(), roots.end()) - roots.begin());
      if(distinct > 1 && a.non_manifold_vertices++ == 0) {
        a.example_non_manifold_vertex = v;
        a.example_non_manifold_vertex_fans = distinct;
      }
    }
  }

  // Geometry: zero-area polygons (exact predicates on the double coordinates) and coincident points.
  for(const auto& c : coordinates)
    if(!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2])) ++a.non_finite_points;
  if(!coordinates.empty() && a.non_finite_points == 0) {
    typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
    auto point = [&](std::size_t v) { return K::Point_3(coordinates[v][0], coordinates[v][1], coordinates[v][2]); };
    for(std::size_t f = 0; f < nf; ++f) {
      const std::size_t k = rows.size(f);
      if(k < 3) continue;
      const K::Point_3 p = point(rows.corner(f, 0));
      std::size_t j = 1;
      while(j < k && point(rows.corner(f, j)) == p) ++j;
      bool flat = true;
      if(j < k) {
        const K::Point_3 q = point(rows.corner(f, j));
        for(std::size_t m = j + 1; m < k && flat; ++m) flat = CGAL::collinear(p, q, point(rows.corner(f, m)));
      }
      if(flat && a.degenerate_polygons++ == 0) a.example_degenerate_polygon = f;
    }
    std::vector<std::size_t> order(number_of_points);
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t u, std::size_t v) { return coordinates[u] < coordinates[v]; });
    for(std::size_t i = 1; i < number_of_points; ++i) {
      if(coordinates[order[i]] == coordinates[order[i - 1]] && a.coincident_points++ == 0)
        a.example_coincident_points = {{order[i - 1], order[i]}};
    }
  }
  return a;
}

} // namespace internal

/*!
  \ingroup PkgMDCSIO
  \brief classifies a polygon soup: see `Polygon_soup_analysis`.

  Runs in O(S log S) time and O(S) memory for S polygon corners.

  \tparam PointRange a random access range of points with `x()`, `y()`, `z()` (CGAL points) or indexable
          triples (`std::array<double, 3>`)
  \tparam PolygonRange a range of polygons, each a range of integer point indices
  \throws std::invalid_argument if a polygon refers to a point that does not exist (a negative index or one
          beyond `points`): the soups of the MDCS readers never do
*/
template <class PointRange, class PolygonRange>
Polygon_soup_analysis analyze_polygon_soup(const PointRange& points, const PolygonRange& polygons)
{
  const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));
  const internal::Soup_rows rows = internal::make_soup_rows(polygons, n, "analyze_polygon_soup");
  std::vector<std::array<double, 3>> coordinates;
  coordinates.reserve(n);
  for(const auto& p : points) coordinates.push_back(internal::point_coordinates(p));
  return internal::analyze_soup_rows(rows, n, coordinates);
}

} // namespace MDCS
} // namespace CGAL

#endif // CGAL_MDCS_ANALYZE_POLYGON_SOUP_H
