// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// read_polygon_soup(): OFF, PLY, OBJ and STL files as a polygon soup (points + polygons of point indices),
// read by readers that distrust the file: every count, size and index is validated against the file's size
// before anything is allocated or indexed, and every problem ends in one exception type, Read_error.

#ifndef CGAL_MDCS_IO_READ_POLYGON_SOUP_H
#define CGAL_MDCS_IO_READ_POLYGON_SOUP_H

#include <CGAL/MDCS/IO/Read_error.h>
#include <CGAL/MDCS/IO/internal/input_text.h>
#include <CGAL/MDCS/IO/internal/read_OBJ.h>
#include <CGAL/MDCS/IO/internal/read_OFF.h>
#include <CGAL/MDCS/IO/internal/read_PLY.h>
#include <CGAL/MDCS/IO/internal/read_STL.h>
#include <CGAL/MDCS/IO/internal/soup_output.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <istream>
#include <string>
#include <string_view>

namespace CGAL {
namespace MDCS {
namespace IO {

/// \ingroup PkgMDCSIO
/// The mesh file formats of `read_polygon_soup()`.
enum class Mesh_file_format
{
  automatic, ///< from the file name's extension (`.off`, `.ply`, `.obj`, `.stl`, any case), else from the content
  off,       ///< Geomview OFF: [ST][C][N][4][n]OFF ascii, and plain `OFF BINARY`
  ply,       ///< PLY 1.0: ascii, binary_little_endian, binary_big_endian
  obj,       ///< Wavefront OBJ (v and f statements)
  stl        ///< STL, ascii or binary
};

/// \ingroup PkgMDCSIO
/// The name of a format ("OFF", "PLY", "OBJ", "STL", "automatic").
inline const char* to_string(Mesh_file_format f)
{
  switch(f) {
  case Mesh_file_format::off: return "OFF";
  case Mesh_file_format::ply: return "PLY";
  case Mesh_file_format::obj: return "OBJ";
  case Mesh_file_format::stl: return "STL";
  default: return "automatic";
  }
}

/// \ingroup PkgMDCSIO
/// The format a file name's extension names (case-insensitive), `automatic` when it names none.
inline Mesh_file_format mesh_file_format_from_extension(const std::string& file_name)
{
  const std::size_t dot = file_name.find_last_of('.');
  const std::size_t slash = file_name.find_last_of("/\\");
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash)) return Mesh_file_format::automatic;
  std::string ext = file_name.substr(dot + 1);
  for(char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if(ext == "off") return Mesh_file_format::off;
  if(ext == "ply") return Mesh_file_format::ply;
  if(ext == "obj") return Mesh_file_format::obj;
  if(ext == "stl") return Mesh_file_format::stl;
  return Mesh_file_format::automatic;
}

namespace internal {

// The format of a file whose name does not say: PLY and OFF have a keyword, ascii STL starts with "solid",
// binary STL has its exact size; OBJ is assumed when the text starts with an OBJ statement.
inline Mesh_file_format sniff_mesh_file_format(std::string_view data)
{
  Line_reader lines(data);
  std::string_view line, token;
  while(lines.next(line)) {
    Tokens t(strip_comment(line));
    if(!t.next(token)) continue;
    if(lines.line() == 1 && line == "ply") return Mesh_file_format::ply;
    OFF_header h;
    if(parse_OFF_keyword(token, h)) return Mesh_file_format::off;
    if(STL_keyword_is(token, "solid")) return Mesh_file_format::stl;
    if(token == "v" || token == "f" || token == "vt" || token == "vn" || token == "o" || token == "g" || token == "mtllib")
      return Mesh_file_format::obj;
    break;
  }
  if(data.size() >= 84) {
    Binary_reader header(data, false);
    header.skip(80);
    const std::uint64_t n = header.read<std::uint32_t>();
    if(84 + 50 * n == data.size()) return Mesh_file_format::stl;
  }
  return Mesh_file_format::automatic;
}

template <class PointRange, class PolygonRange>
Mesh_file_format read_polygon_soup_from_data(std::string_view data, const std::string& name, Mesh_file_format format,
                                             PointRange& points, PolygonRange& polygons)
{
  points.clear();
  polygons.clear();
  if(format == Mesh_file_format::automatic) format = mesh_file_format_from_extension(name);
  if(format == Mesh_file_format::automatic) format = sniff_mesh_file_format(data);
  if(format == Mesh_file_format::automatic)
    throw Read_error(name, 0, "", "unknown mesh format: neither the extension nor the content says OFF, PLY, OBJ or STL");
  Soup_output<PointRange, PolygonRange> out(points, polygons, name);
  try {
    switch(format) {
    case Mesh_file_format::off: read_OFF(data, name, out); break;
    case Mesh_file_format::ply: read_PLY(data, name, out); break;
    case Mesh_file_format::obj: read_OBJ(data, name, out); break;
    default: read_STL(data, name, out); break;
    }
  } catch(...) {
    points.clear();
    polygons.clear();
    throw;
  }
  return format;
}

} // namespace internal

/*!
  \ingroup PkgMDCSIO
  \brief reads a polygon soup from a mesh file (OFF, PLY, OBJ or STL), distrusting the file.

  The file is read as a whole into memory (its size bounds everything that follows), then parsed:
  - every count of a header (OFF vertex and face counts, PLY element counts, binary STL triangle count) is
    checked against the bytes left in the file *before* anything is reserved: a header cannot make the
    reader allocate more than the file can hold;
  - every face has at least 3 corners, and its size is bounded by what its line (or the bytes left) holds;
  - every vertex index is checked: negative, beyond the vertex count, 0 in OBJ (whose indices start at 1),
    relative OBJ indices that reach before the first vertex;
  - every coordinate is a finite number (no `nan`, `inf`, or a number beyond the range of a double);
  - truncation, trailing data after the last element and garbage are detected.

  Point indices are those of the file (0-based); STL vertices with equal coordinates become one point,
  numbered in order of first appearance. Colours, normals and texture coordinates are read past.

  \tparam PointRange a back-insertion sequence (`std::vector`, ...) of points constructible from three
          `double`s (`Point_3`, `std::array<double, 3>`, ...)
  \tparam PolygonRange a back-insertion sequence of polygons; a polygon is a sequence container of an
          integer type (`std::vector<std::size_t>`, ...) or a `std::array` (then every face must have that size)

  \param file_name the file
  \param points, polygons cleared, then filled (cleared again when an exception is thrown)
  \param format the format, by default from the extension (then from the content)
  \return the format that was read
  \throws Read_error for every problem: with the file name, the line (text formats) or the element and
          item (binary formats), and a message that names the problem.
*/
template <class PointRange, class PolygonRange>
Mesh_file_format read_polygon_soup(const std::string& file_name, PointRange& points, PolygonRange& polygons,
                                   Mesh_file_format format = Mesh_file_format::automatic)
{
  const std::string data = internal::load_file(file_name);
  return internal::read_polygon_soup_from_data(data, file_name, format, points, polygons);
}

/*!
  \ingroup PkgMDCSIO
  \brief reads a polygon soup from a stream (read to its end first); `name` names it in error messages and,
  with `Mesh_file_format::automatic`, its extension gives the format.
*/
template <class PointRange, class PolygonRange>
Mesh_file_format read_polygon_soup(std::istream& in, const std::string& name, PointRange& points,
                                   PolygonRange& polygons, Mesh_file_format format = Mesh_file_format::automatic)
{
  const std::string data = internal::load_stream(in);
  return internal::read_polygon_soup_from_data(data, name, format, points, polygons);
}

} // namespace IO
} // namespace MDCS
} // namespace CGAL

#endif // CGAL_MDCS_IO_READ_POLYGON_SOUP_H
