// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The work of analyze_polygon_soup(): the soup in compressed rows, its edges sorted by their end points,
// union-finds for components, orientation (with parity) and the fans of faces around each vertex.

#ifndef CGAL_MDCS_INTERNAL_POLYGON_SOUP_ANALYSIS_H
#define CGAL_MDCS_INTERNAL_POLYGON_SOUP_ANALYSIS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace MDCS {
namespace internal {

// A polygon soup in compressed rows: the corners of polygon f are corners[offsets[f] .. offsets[f+1]).
struct Soup_rows
{
  std::vector<std::size_t> offsets{0};
  std::vector<std::size_t> corners;

  std::size_t number_of_polygons() const { return offsets.size() - 1; }
  std::size_t size(std::size_t f) const { return offsets[f + 1] - offsets[f]; }
  std::size_t corner(std::size_t f, std::size_t i) const { return corners[offsets[f] + i]; }
};

// Copies the caller's polygons, checking every index against the number of points.
template <class PolygonRange>
Soup_rows make_soup_rows(const PolygonRange& polygons, std::size_t number_of_points, const char* function)
{
  Soup_rows rows;
  std::size_t total = 0;
  for(const auto& p : polygons) total += std::size_t(std::distance(std::begin(p), std::end(p)));
  rows.corners.reserve(total);
  rows.offsets.reserve(std::size_t(std::distance(std::begin(polygons), std::end(polygons))) + 1);
  std::size_t f = 0;
  for(const auto& p : polygons) {
    for(const auto& c : p) {
      typedef std::remove_cv_t<std::remove_reference_t<decltype(c)>> Index;
      if constexpr(std::is_signed<Index>::value) {
        if(c < 0)
          throw std::invalid_argument(std::string("MDCS: ") + function + ": polygon " + std::to_string(f) +
                                      " has the negative point index " + std::to_string(c));
      }
      if(std::uint64_t(c) >= number_of_points)
        throw std::invalid_argument(std::string("MDCS: ") + function + ": polygon " + std::to_string(f) +
                                    " refers to point " + std::to_string(c) + ", but there are " +
                                    std::to_string(number_of_points) + " points");
      rows.corners.push_back(std::size_t(c));
    }
    rows.offsets.push_back(rows.corners.size());
    ++f;
  }
  return rows;
}

class Union_find
{
public:
  explicit Union_find(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), std::size_t(0)); }

  std::size_t find(std::size_t x)
  {
    std::size_t root = x;
    while(parent_[root] != root) root = parent_[root];
    while(parent_[x] != root) {
      const std::size_t next = parent_[x];
      parent_[x] = root;
      x = next;
    }
    return root;
  }

  void unite(std::size_t a, std::size_t b)
  {
    a = find(a), b = find(b);
    if(a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

private:
  std::vector<std::size_t> parent_;
};

// Union-find that keeps, for each element, whether it must be flipped relative to its root: uniting two
// faces with a relation that contradicts the known ones reveals a non-orientable part.
class Parity_union_find
{
public:
  explicit Parity_union_find(std::size_t n) : parent_(n), parity_(n, 0)
  {
    std::iota(parent_.begin(), parent_.end(), std::size_t(0));
  }

  std::pair<std::size_t, unsigned char> find(std::size_t x)
  {
    // Two passes: find the root and the parity of x, then compress the path with corrected parities.
    std::size_t root = x;
    unsigned char p = 0;
    while(parent_[root] != root) {
      p ^= parity_[root];
      root = parent_[root];
    }
    unsigned char q = p;
    while(parent_[x] != root) {
      const std::size_t next = parent_[x];
      const unsigned char own = parity_[x];
      parent_[x] = root;
      parity_[x] = q;
      q ^= own;
      x = next;
    }
    return {root, p};
  }

  // Requires flip(a) xor flip(b) == relation; returns false if that contradicts what is known.
  bool unite(std::size_t a, std::size_t b, unsigned char relation)
  {
    const auto ra = find(a), rb = find(b);
    if(ra.first == rb.first) return (ra.second ^ rb.second) == relation;
    const std::size_t child = std::max(ra.first, rb.first), root = std::min(ra.first, rb.first);
    parent_[child] = root;
    parity_[child] = ra.second ^ rb.second ^ relation;
    return true;
  }

private:
  std::vector<std::size_t> parent_;
  std::vector<unsigned char> parity_;
};

template <class T, class = void>
struct has_x_accessor : std::false_type {};
template <class T>
struct has_x_accessor<T, std::void_t<decltype(std::declval<const T&>().x())>> : std::true_type {};

// Coordinates of a point: CGAL points (x(), y(), z()) or indexable triples.
template <class Point>
std::array<double, 3> point_coordinates(const Point& p)
{
  if constexpr(has_x_accessor<Point>::value) {
    return {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  } else {
    return {{double(p[0]), double(p[1]), double(p[2])}};
  }
}

} // namespace internal
} // namespace MDCS
} // namespace CGAL

#endif // CGAL_MDCS_INTERNAL_POLYGON_SOUP_ANALYSIS_H
