// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Wavefront OBJ as a polygon soup: "v x y z" (a weight or a colour may follow), "f" with corners v, v/vt,
// v//vn or v/vt/vn, negative indices relative to the vertices read so far, '#' comments, '\' line
// continuation; every other statement (vt, vn, g, o, s, usemtl, l, p, ...) is ignored. A line must start
// with a statement keyword: binary garbage is refused. Vertex indices 0, before the first vertex or beyond
// the last one are refused with the line of the face.

#ifndef CGAL_MDCS_IO_INTERNAL_READ_OBJ_H
#define CGAL_MDCS_IO_INTERNAL_READ_OBJ_H

#include <CGAL/MDCS/IO/Read_error.h>
#include <CGAL/MDCS/IO/internal/input_text.h>

#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace MDCS {
namespace IO {
namespace internal {

inline bool is_OBJ_keyword(std::string_view word)
{
  if(word.empty() || !(std::isalpha(static_cast<unsigned char>(word[0])) || word[0] == '_')) return false;
  for(char c : word)
    if(!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

template <class Output>
void read_OBJ(std::string_view data, const std::string& name, Output& out)
{
  Line_reader lines(data);
  std::string_view raw, token;
  std::string joined;
  std::vector<std::size_t> corners;
  std::uint64_t vertices = 0;
  std::uint64_t largest_index = 0; // the largest positive (1-based) index, checked at the end
  std::size_t largest_index_line = 0;
  while(lines.next(raw)) {
    const std::size_t line_number = lines.line();
    std::string_view line = strip_comment(raw);
    // A '\' at the end of a line continues the statement on the next line.
    if(!line.empty() && line.back() == '\\') {
      joined.assign(line.substr(0, line.size() - 1));
      while(lines.next(raw)) {
        std::string_view more = strip_comment(raw);
        const bool again = !more.empty() && more.back() == '\\';
        joined += ' ';
        joined.append(more.substr(0, again ? more.size() - 1 : more.size()));
        if(!again) break;
      }
      line = joined;
    }
    auto fail = [&](const std::string& message) { throw Read_error(name, line_number, "", message); };
    Tokens tokens(line);
    if(!tokens.next(token)) continue;
    if(!is_OBJ_keyword(token)) fail("not an OBJ statement: " + printable(token));
    if(token == "v") {
      double c[3] = {0, 0, 0};
      std::size_t n = 0;
      while(tokens.next(token)) {
        double value = 0;
        const Number_status status = parse_real(token, value);
        if(status == Number_status::not_a_number) fail("vertex " + std::to_string(vertices + 1) + ": " + printable(token) + " is not a number");
        if(status == Number_status::out_of_range)
          fail("vertex " + std::to_string(vertices + 1) + ": " + printable(token) + " is out of the range of a double");
        if(n < 3) {
          if(!std::isfinite(value)) fail("vertex " + std::to_string(vertices + 1) + ": a coordinate is not a finite number");
          c[n] = value;
        }
        ++n;
      }
      if(n < 3 || n > 7)
        fail("vertex " + std::to_string(vertices + 1) + ": " + std::to_string(n) +
             " numbers (expected x y z, optionally followed by a weight or a colour)");
      out.add_point(c[0], c[1], c[2]);
      ++vertices;
    } else if(token == "f") {
      corners.clear();
      std::uint64_t face_largest = 0;
      while(tokens.next(token)) {
        // v, v/vt, v//vn or v/vt/vn: only v is used, the others must be integers when present.
        const std::size_t slash = token.find('/');
        const std::string_view v = token.substr(0, slash);
        if(slash != std::string_view::npos) {
          const std::string_view rest = token.substr(slash + 1);
          const std::size_t slash2 = rest.find('/');
          const std::string_view vt = rest.substr(0, slash2);
          const std::string_view vn = slash2 == std::string_view::npos ? std::string_view() : rest.substr(slash2 + 1);
          std::int64_t ignored;
          const bool vt_ok = vt.empty() ? slash2 != std::string_view::npos : parse_integer(vt, ignored) == Number_status::ok;
          const bool vn_ok = slash2 == std::string_view::npos || parse_integer(vn, ignored) == Number_status::ok;
          if(!vt_ok || !vn_ok) fail("the face corner " + printable(token) + " is not v, v/vt, v//vn or v/vt/vn");
        }
        std::int64_t index = 0;
        const Number_status status = parse_integer(v, index);
        if(status != Number_status::ok)
          fail("the face corner " + printable(token) + " does not start with an integer vertex index" +
               (status == Number_status::out_of_range ? " in range" : ""));
        if(index == 0) fail("vertex index 0 in a face (OBJ indices start at 1, or count back from -1)");
        if(index < 0) {
          // Relative: -1 is the last vertex read so far.
          if(std::uint64_t(-(index + 1)) >= vertices)
            fail("the relative vertex index " + std::to_string(index) + " reaches before the first vertex (" +
                 std::to_string(vertices) + " vertices so far)");
          corners.push_back(std::size_t(vertices - std::uint64_t(-(index + 1)) - 1));
        } else {
          // Checked against the vertex count at the end (vertices may follow the face); an index that not even
          // the whole file could reach is refused at once.
          if(std::uint64_t(index) > data.size())
            fail("the vertex index " + std::to_string(index) + " is out of range (the file cannot hold that many vertices)");
          corners.push_back(std::size_t(index - 1));
          if(std::uint64_t(index) > face_largest) face_largest = std::uint64_t(index);
        }
      }
      if(corners.size() < 3) fail("a face with " + std::to_string(corners.size()) + " corners (at least 3 needed)");
      if(face_largest > largest_index) {
        largest_index = face_largest;
        largest_index_line = line_number;
      }
      out.add_polygon(corners, line_number);
    }
    // Every other statement (vt, vn, vp, g, o, s, mtllib, usemtl, l, p, curves, ...) carries no surface.
  }
  if(largest_index > vertices)
    throw Read_error(name, largest_index_line, "", "the vertex index " + std::to_string(largest_index) +
                     " is out of range (the file has " + std::to_string(vertices) + " vertices)");
}

} // namespace internal
} // namespace IO
} // namespace MDCS
} // namespace CGAL

#endif // CGAL_MDCS_IO_INTERNAL_READ_OBJ_H
