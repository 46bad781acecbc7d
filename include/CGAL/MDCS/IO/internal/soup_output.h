// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where the mesh readers put what they read: the caller's point range and polygon range (any
// back-insertion sequences, polygons of any sequence type or std::array), with reservations that the
// readers have already bounded by the file size.

#ifndef CGAL_MDCS_IO_INTERNAL_SOUP_OUTPUT_H
#define CGAL_MDCS_IO_INTERNAL_SOUP_OUTPUT_H

#include <CGAL/MDCS/IO/Read_error.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace MDCS {
namespace IO {
namespace internal {

template <class T, class = void>
struct has_reserve : std::false_type {};
template <class T>
struct has_reserve<T, std::void_t<decltype(std::declval<T&>().reserve(std::size_t(0)))>> : std::true_type {};

template <class T>
struct is_std_array : std::false_type {};
template <class T, std::size_t N>
struct is_std_array<std::array<T, N>> : std::true_type {};

// A point from three coordinates: Point(x, y, z) (CGAL points, Eigen vectors) or, for aggregates such as
// std::array<double, 3>, element by element.
template <class Point>
Point make_point_3(double x, double y, double z)
{
  if constexpr(std::is_constructible<Point, double, double, double>::value) {
    return Point(x, y, z);
  } else {
    Point p{};
    p[0] = x;
    p[1] = y;
    p[2] = z;
    return p;
  }
}

template <class Point>
Point make_point_2(double x, double y)
{
  if constexpr(std::is_constructible<Point, double, double>::value) {
    return Point(x, y);
  } else {
    Point p{};
    p[0] = x;
    p[1] = y;
    return p;
  }
}

template <class Range>
void reserve_if_possible(Range& range, std::size_t n)
{
  if constexpr(has_reserve<Range>::value) range.reserve(n);
}

template <class PointRange, class PolygonRange>
class Soup_output
{
public:
  typedef typename PointRange::value_type Point;
  typedef typename PolygonRange::value_type Polygon;
  typedef std::remove_cv_t<std::remove_reference_t<decltype(*std::declval<Polygon&>().begin())>> Index;
  static_assert(std::is_integral<Index>::value, "the polygons' value type must be an integer type");

  Soup_output(PointRange& points, PolygonRange& polygons, const std::string& file_name)
    : points_(points), polygons_(polygons), file_name_(file_name)
  {}

  void reserve_points(std::size_t n) { reserve_if_possible(points_, n); }
  void reserve_polygons(std::size_t n) { reserve_if_possible(polygons_, n); }

  void add_point(double x, double y, double z)
  {
    points_.push_back(make_point_3<Point>(x, y, z));
    ++number_of_points_;
  }

  std::size_t number_of_points() const { return number_of_points_; }
  std::size_t number_of_polygons() const { return number_of_polygons_; }

  // `corners` are already checked against the number of points; `line`, or `location` and `item`
  // ("triangle" 12, "element 'face' item" 3), place errors (the text is only built for an error).
  void add_polygon(const std::vector<std::size_t>& corners, std::size_t line, const char* location = nullptr,
                   std::uint64_t item = 0)
  {
    auto where = [&]() { return location ? std::string(location) + " " + std::to_string(item) : std::string(); };
    for(std::size_t c : corners)
      if(c > std::size_t(std::numeric_limits<Index>::max()))
        throw Read_error(file_name_, line, where(), "vertex index " + std::to_string(c) +
                         " does not fit the polygon index type of the caller");
    if constexpr(is_std_array<Polygon>::value) {
      Polygon p{};
      if(corners.size() != p.size())
        throw Read_error(file_name_, line, where(), "a face with " + std::to_string(corners.size()) +
                         " corners does not fit the caller's polygon type (" + std::to_string(p.size()) + " corners)");
      for(std::size_t i = 0; i < corners.size(); ++i) p[i] = Index(corners[i]);
      polygons_.push_back(p);
    } else {
      Polygon p;
      reserve_if_possible(p, corners.size());
      for(std::size_t c : corners) p.insert(p.end(), Index(c));
      polygons_.push_back(std::move(p));
    }
    ++number_of_polygons_;
  }

  const std::string& file_name() const { return file_name_; }

private:
  PointRange& points_;
  PolygonRange& polygons_;
  const std::string& file_name_;
  std::size_t number_of_points_ = 0, number_of_polygons_ = 0;
};

} // namespace internal
} // namespace IO
} // namespace MDCS
} // namespace CGAL

#endif // CGAL_MDCS_IO_INTERNAL_SOUP_OUTPUT_H
