// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// read_points_2() / read_points_3(): text files of points, one per line, read by a reader that distrusts
// them (exactly two or three finite numbers per line, the line of every problem in the message).

#ifndef CGAL_MDCS_IO_READ_POINTS_H
#define CGAL_MDCS_IO_READ_POINTS_H

#include <CGAL/MDCS/IO/Read_error.h>
#include <CGAL/MDCS/IO/internal/input_text.h>
#include <CGAL/MDCS/IO/internal/soup_output.h>

#include <cmath>
#include <cstddef>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace MDCS {
namespace IO {
namespace internal {

// The fields of a points line: separated by a comma or a semicolon (spaces around them allowed) when the
// line has one, by blanks otherwise. Empty fields are kept (and refused by the caller).
inline void split_point_fields(std::string_view line, std::vector<std::string_view>& fields)
{
  fields.clear();
  const bool separated = line.find_first_of(",;") != std::string_view::npos;
  if(!separated) {
    Tokens tokens(line);
    std::string_view t;
    while(tokens.next(t)) fields.push_back(t);
    return;
  }
  std::size_t start = 0;
  for(;;) {
    const std::size_t end = line.find_first_of(",;", start);
    std::string_view field = line.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
    while(!field.empty() && is_space(field.front())) field.remove_prefix(1);
    while(!field.empty() && is_space(field.back())) field.remove_suffix(1);
    fields.push_back(field);
    if(end == std::string_view::npos) break;
    start = end + 1;
  }
}

// Calls add(coordinates) for each point of the text; `dimension` is 2 or 3.
template <class Add>
void read_points_from_data(std::string_view data, const std::string& name, std::size_t dimension, Add add)
{
  Line_reader lines(data);
  std::string_view line;
  std::vector<std::string_view> fields;
  bool first = true;
  double c[3] = {0, 0, 0};
  while(lines.next(line)) {
    line = strip_comment(line);
    if(Tokens(line).empty()) continue;
    split_point_fields(line, fields);
    auto fail = [&](const std::string& message) { throw Read_error(name, lines.line(), "", message); };
    // A header line ("x,y", "x y z") may come first: all its fields are words.
    if(first) {
      first = false;
      bool words = true;
      for(std::string_view f : fields) {
        double ignored;
        words = words && !f.empty() && parse_real(f, ignored) == Number_status::not_a_number &&
                !(std::isdigit(static_cast<unsigned char>(f[0])) || f[0] == '-' || f[0] == '+' || f[0] == '.');
      }
      if(words) continue;
    }
    for(std::string_view f : fields)
      if(f.empty()) fail("an empty field (two separators in a row, or one at the end of the line)");
    if(fields.size() != dimension)
      fail("expected " + std::to_string(dimension) + " coordinates, found " + std::to_string(fields.size()) + " fields");
    for(std::size_t i = 0; i < dimension; ++i) {
      const Number_status status = parse_real(fields[i], c[i]);
      if(status == Number_status::not_a_number) fail(printable(fields[i]) + " is not a number");
      if(status == Number_status::out_of_range || !std::isfinite(c[i]))
        fail("the coordinate " + printable(fields[i]) + " is not a finite number");
    }
    add(c);
  }
}

// Clears `points`, fills it with the points of `data` (dimension 2 or 3), and clears it again on an error.
template <std::size_t dimension, class PointRange>
void read_points_into(std::string_view data, const std::string& name, PointRange& points)
{
  typedef typename PointRange::value_type Point;
  points.clear();
  try {
    read_points_from_data(data, name, dimension, [&](const double* c) {
      if constexpr(dimension == 2) points.push_back(make_point_2<Point>(c[0], c[1]));
      else points.push_back(make_point_3<Point>(c[0], c[1], c[2]));
    });
  } catch(...) {
    points.clear();
    throw;
  }
}

} // namespace internal

/*!
  \ingroup PkgMDCSIO
  \brief reads points of the plane from a text file, distrusting it.

  The format (the *points file* of `mdcs mwt`): one point per line, its coordinates separated by blanks,
  or by a comma or a semicolon (`x y`, `x,y`, `x; y`); `#` starts a comment; blank lines are skipped; the
  first line may be a header of words (`x,y`), which is skipped. Every other line must hold exactly two
  finite numbers: a third coordinate, an empty field, `nan`, `inf`, a number beyond the range of a double or
  trailing text are errors.

  \tparam PointRange a back-insertion sequence of points constructible from two doubles (`Point_2`,
          `std::array<double, 2>`)
  \param points cleared, then filled in file order (cleared again on an error)
  \throws Read_error with the file name, the line and the problem
*/
template <class PointRange>
void read_points_2(const std::string& file_name, PointRange& points)
{
  internal::read_points_into<2>(internal::load_file(file_name), file_name, points);
}

/// \ingroup PkgMDCSIO
/// Same as `read_points_2()` from a stream (read to its end first); `name` names it in messages.
template <class PointRange>
void read_points_2(std::istream& in, const std::string& name, PointRange& points)
{
  internal::read_points_into<2>(internal::load_stream(in), name, points);
}

/// \ingroup PkgMDCSIO
/// Points in space: as `read_points_2()` with exactly three coordinates per line (`x y z`, `x,y,z`).
template <class PointRange>
void read_points_3(const std::string& file_name, PointRange& points)
{
  internal::read_points_into<3>(internal::load_file(file_name), file_name, points);
}

/// \ingroup PkgMDCSIO
/// Same as `read_points_3()` from a stream (read to its end first); `name` names it in messages.
template <class PointRange>
void read_points_3(std::istream& in, const std::string& name, PointRange& points)
{
  internal::read_points_into<3>(internal::load_stream(in), name, points);
}

} // namespace IO
} // namespace MDCS
} // namespace CGAL

#endif // CGAL_MDCS_IO_READ_POINTS_H
