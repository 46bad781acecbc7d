// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// OFF (Geomview's Object File Format) as a polygon soup: the header keyword [ST][C][N][4][n]OFF, the counts
// on the keyword line or on the next lines, one vertex per line (coordinates, then normal, colour and
// texture coordinates as the keyword announces), one face per line (count, indices, an optional colour),
// '#' comments; and plain binary OFF ("OFF BINARY", big-endian). Counts are checked against the bytes left
// before anything is reserved, face sizes against the numbers on their line, indices against the vertex count.

#ifndef CGAL_MDCS_IO_INTERNAL_READ_OFF_H
#define CGAL_MDCS_IO_INTERNAL_READ_OFF_H

#include <CGAL/MDCS/IO/Read_error.h>
#include <CGAL/MDCS/IO/internal/input_text.h>

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

struct OFF_header
{
  bool texture = false, colour = false, normal = false, homogeneous = false, dimensional = false;
  std::string keyword;
};

// [ST][C][N][4][n]OFF, in this order (Geomview's and CGAL's convention).
inline bool parse_OFF_keyword(std::string_view word, OFF_header& h)
{
  h.keyword = std::string(word);
  std::size_t i = 0;
  if(word.substr(i, 2) == "ST") h.texture = true, i += 2;
  if(word.substr(i, 1) == "C") h.colour = true, ++i;
  if(word.substr(i, 1) == "N") h.normal = true, ++i;
  if(word.substr(i, 1) == "4") h.homogeneous = true, ++i;
  if(word.substr(i, 1) == "n") h.dimensional = true, ++i;
  return word.substr(i) == "OFF";
}

template <class Output>
void read_OFF_binary(std::string_view data, std::size_t start, const std::string& name, Output& out)
{
  Binary_reader in(data.substr(start), true);
  auto fail = [&](const std::string& location, const std::string& message) {
    throw Read_error(name, 0, location, message);
  };
  if(!in.can_read(12)) fail("header", "binary OFF: the file ends inside the counts");
  const std::int32_t nv = in.read<std::int32_t>(), nf = in.read<std::int32_t>(), ne = in.read<std::int32_t>();
  if(nv < 0 || nf < 0 || ne < 0) fail("header", "binary OFF: a negative count");
  // A vertex takes 12 bytes, a face at least 20 (count, three indices, colour count).
  if(std::size_t(nv) > in.remaining() / 12 || std::size_t(nf) > (in.remaining() - std::size_t(nv) * 12) / 20)
    fail("header", "binary OFF: the header announces " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                   " faces, more than the " + std::to_string(in.remaining()) + " bytes left can hold");
  out.reserve_points(std::size_t(nv));
  out.reserve_polygons(std::size_t(nf));
  for(std::int32_t i = 0; i < nv; ++i) {
    const double x = in.read<float>(), y = in.read<float>(), z = in.read<float>();
    if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
      fail("vertex " + std::to_string(i), "a coordinate is not a finite number");
    out.add_point(x, y, z);
  }
  std::vector<std::size_t> corners;
  for(std::int32_t f = 0; f < nf; ++f) {
    auto where = [f]() { return "face " + std::to_string(f); };
    if(!in.can_read(4)) fail(where(), "the file ends before this face (truncated)");
    const std::int32_t k = in.read<std::int32_t>();
    if(k < 3) fail(where(), "a face with " + std::to_string(k) + " corners (at least 3 needed)");
    if(std::size_t(k) + 1 > in.remaining() / 4) // the indices and the colour count
      fail(where(), "a face with " + std::to_string(k) + " corners, more than the bytes left can hold");
    corners.clear();
    for(std::int32_t j = 0; j < k; ++j) {
      const std::int32_t v = in.read<std::int32_t>();
      if(v < 0 || v >= nv)
        fail(where(), "vertex index " + std::to_string(v) + " is out of range (" + std::to_string(nv) + " vertices)");
      corners.push_back(std::size_t(v));
    }
    const std::int32_t colours = in.read<std::int32_t>();
    if(colours < 0 || colours > 4) fail(where(), "a colour with " + std::to_string(colours) + " components (0 to 4)");
    if(!in.can_read(std::size_t(colours) * 4)) fail(where(), "the file ends inside the face's colour (truncated)");
    in.skip(std::size_t(colours) * 4);
    out.add_polygon(corners, 0, "face", std::uint64_t(f));
  }
  if(in.remaining() != 0)
    fail("end", std::to_string(in.remaining()) + " unexpected bytes after the last face");
}

template <class Output>
void read_OFF(std::string_view data, const std::string& name, Output& out)
{
  Line_reader lines(data);
  std::string_view line, token;
  auto fail = [&](std::size_t line_number, const std::string& message) {
    throw Read_error(name, line_number, "", message);
  };
  // The next line that holds something other than blanks and comments.
  auto next_content_line = [&](Tokens& tokens) {
    while(lines.next(line)) {
      tokens = Tokens(strip_comment(line));
      if(!tokens.empty()) return true;
    }
    return false;
  };

  Tokens tokens;
  if(!next_content_line(tokens)) fail(0, "the file is empty: no OFF header");
  tokens.next(token);
  OFF_header header;
  if(!parse_OFF_keyword(token, header)) {
    if(token.size() >= 4 && token.substr(token.size() - 4) == "SKEL")
      fail(lines.line(), "a SKEL file (points and polylines) is not a polygon mesh");
    fail(lines.line(), "not an OFF file: the first word is " + printable(token) + " (expected OFF, COFF, NOFF, ...)");
  }
  const std::size_t keyword_line = lines.line();
  Tokens rest = tokens;
  std::string_view next_token;
  if(Tokens(rest).next(next_token) && next_token == "BINARY") {
    rest.next(next_token);
    if(!rest.empty()) fail(keyword_line, "unexpected text after 'BINARY'");
    if(header.keyword != "OFF")
      fail(keyword_line, "binary OFF with the header '" + header.keyword + "' is not supported (plain 'OFF BINARY' is)");
    read_OFF_binary(data, lines.offset(), name, out);
    return;
  }

  // The counts: [dimension] vertices faces [edges], on the keyword line or on the lines after it.
  const std::size_t needed = header.dimensional ? 3 : 2;
  std::vector<std::string_view> counts;
  std::size_t counts_line = keyword_line;
  for(;;) {
    while(rest.next(token)) counts.push_back(token);
    if(counts.size() >= needed) break;
    if(!next_content_line(rest)) fail(0, "the file ends inside the OFF header (the vertex and face counts are missing)");
    counts_line = lines.line();
  }
  if(counts.size() > needed + 1)
    fail(counts_line, "unexpected " + printable(counts[needed + 1]) + " after the counts (expected " +
                      (header.dimensional ? std::string("DIMENSION ") : std::string()) + "VERTICES FACES [EDGES])");
  std::uint64_t values[4] = {0, 0, 0, 0};
  for(std::size_t i = 0; i < counts.size(); ++i) {
    const Number_status status = parse_integer(counts[i], values[i]);
    if(status != Number_status::ok) {
      if(!counts[i].empty() && counts[i][0] == '-') fail(counts_line, "a negative count " + printable(counts[i]));
      fail(counts_line, "the count " + printable(counts[i]) + " is not a non-negative integer" +
                        (status == Number_status::out_of_range ? " in range" : ""));
    }
  }
  std::size_t dimension = 3;
  if(header.dimensional) {
    if(values[0] != 2 && values[0] != 3)
      fail(counts_line, "vertices of dimension " + std::to_string(values[0]) + " (2 and 3 are supported)");
    dimension = std::size_t(values[0]);
  }
  const std::uint64_t nv = values[header.dimensional ? 1 : 0], nf = values[header.dimensional ? 2 : 1];

  // Numbers on a vertex line: coordinates (+ w), normal (+ w), colour (0, 1, 3 or 4 numbers with C),
  // texture coordinates (+ w).
  const std::size_t h = header.homogeneous ? 1 : 0;
  const std::size_t coordinates = dimension + h;
  const std::size_t fixed = coordinates + (header.normal ? 3 + h : 0) + (header.texture ? 2 + h : 0);

  // Every vertex line holds at least 2 bytes per number, every face line at least 8 ("3 0 1 2\n").
  const std::size_t left = lines.remaining() + 1; // the last line may lack its newline
  if(nv > left / (2 * fixed)) {
    fail(counts_line, "the header announces " + std::to_string(nv) + " vertices, but the " +
                      std::to_string(lines.remaining()) + " bytes left can hold at most " +
                      std::to_string(left / (2 * fixed)));
  }
  if(nf > (left - std::size_t(nv) * 2 * fixed) / 8) {
    fail(counts_line, "the header announces " + std::to_string(nf) + " faces, but the bytes left after the vertices can hold at most " +
                      std::to_string((left - std::size_t(nv) * 2 * fixed) / 8));
  }
  out.reserve_points(std::size_t(nv));
  out.reserve_polygons(std::size_t(nf));

  double numbers[16];
  for(std::uint64_t i = 0; i < nv; ++i) {
    if(!next_content_line(tokens))
      fail(lines.line(), "the file ends after " + std::to_string(i) + " of " + std::to_string(nv) + " vertices (truncated)");
    std::size_t n = 0;
    while(tokens.next(token)) {
      double value = 0;
      const Number_status status = parse_real(token, value);
      if(status == Number_status::not_a_number)
        fail(lines.line(), "vertex " + std::to_string(i) + ": " + printable(token) + " is not a number");
      if(status == Number_status::out_of_range)
        fail(lines.line(), "vertex " + std::to_string(i) + ": " + printable(token) + " is out of the range of a double");
      if(n < 16) numbers[n] = value;
      ++n;
    }
    // A colour after the numbers the header announces: 0, 1 (a colour map index), 3 or 4 numbers with C; an
    // RGB or RGBA colour is tolerated without C too (writers that forget the prefix are common).
    const std::size_t colour = n >= fixed ? n - fixed : 0;
    const bool count_ok = n >= fixed && (colour == 0 || colour == 3 || colour == 4 || (header.colour && colour == 1));
    if(!count_ok)
      fail(lines.line(), "vertex " + std::to_string(i) + ": " + std::to_string(n) + " numbers on the line, expected " +
                         std::to_string(fixed) + (header.colour ? " plus a colour of 0, 1, 3 or 4 numbers" : " (or 3 or 4 more for a colour)") +
                         " for the header '" + header.keyword + "'");
    double x = numbers[0], y = numbers[1], z = dimension == 3 ? numbers[2] : 0.0;
    if(header.homogeneous) {
      const double w = numbers[dimension];
      if(w == 0 || !std::isfinite(w))
        fail(lines.line(), "vertex " + std::to_string(i) + ": the homogeneous weight is 0 or not finite");
      x /= w, y /= w, z /= w;
    }
    if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
      fail(lines.line(), "vertex " + std::to_string(i) + ": a coordinate is not a finite number");
    out.add_point(x, y, z);
  }

  std::vector<std::size_t> corners;
  for(std::uint64_t f = 0; f < nf; ++f) {
    if(!next_content_line(tokens))
      fail(lines.line(), "the file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces (truncated)");
    const std::size_t on_line = tokens.count();
    tokens.next(token);
    std::uint64_t k = 0;
    if(parse_integer(token, k) != Number_status::ok)
      fail(lines.line(), "face " + std::to_string(f) + ": the corner count " + printable(token) + " is not a non-negative integer");
    if(k < 3) fail(lines.line(), "face " + std::to_string(f) + " has " + std::to_string(k) + " corners (at least 3 needed)");
    if(k > on_line - 1)
      fail(lines.line(), "face " + std::to_string(f) + " announces " + std::to_string(k) + " corners, but the line holds only " +
                         std::to_string(on_line - 1) + " numbers after the count");
    const std::size_t colour = on_line - 1 - std::size_t(k);
    if(colour != 0 && colour != 1 && colour != 3 && colour != 4)
      fail(lines.line(), "face " + std::to_string(f) + ": " + std::to_string(k) + " corners and " + std::to_string(colour) +
                         " more numbers (a face colour has 1, 3 or 4)");
    corners.clear();
    for(std::uint64_t j = 0; j < k; ++j) {
      tokens.next(token);
      std::int64_t v = 0;
      const Number_status status = parse_integer(token, v);
      if(status != Number_status::ok)
        fail(lines.line(), "face " + std::to_string(f) + ": the vertex index " + printable(token) + " is not an integer" +
                           (status == Number_status::out_of_range ? " in range" : ""));
      if(v < 0) fail(lines.line(), "face " + std::to_string(f) + ": the vertex index " + std::to_string(v) + " is negative");
      if(std::uint64_t(v) >= nv)
        fail(lines.line(), "face " + std::to_string(f) + ": the vertex index " + std::to_string(v) + " is out of range (" +
                           std::to_string(nv) + " vertices)");
      corners.push_back(std::size_t(v));
    }
    while(tokens.next(token)) {
      double value;
      if(parse_real(token, value) != Number_status::ok)
        fail(lines.line(), "face " + std::to_string(f) + ": the colour component " + printable(token) + " is not a number");
    }
    out.add_polygon(corners, lines.line());
  }
  if(next_content_line(tokens)) {
    tokens.next(token);
    fail(lines.line(), "unexpected " + printable(token) + " after the last face (the header announces " +
                       std::to_string(nv) + " vertices and " + std::to_string(nf) + " faces)");
  }
}

} // namespace internal
} // namespace IO
} // namespace MDCS
} // namespace CGAL

#endif // CGAL_MDCS_IO_INTERNAL_READ_OFF_H
