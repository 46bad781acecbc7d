// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Read_error: the one exception type of the MDCS file readers (meshes, points, DIMACS max-flow files).

#ifndef CGAL_MDCS_IO_READ_ERROR_H
#define CGAL_MDCS_IO_READ_ERROR_H

#include <cstddef>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace MDCS {
namespace IO {

/*!
  \ingroup PkgMDCSIO
  \brief Thrown by every MDCS reader when a file cannot be used: it cannot be opened, it is not in the
  expected format, it is truncated, a count or an index is out of range, a number is not finite, or (for
  the mesh pipeline `read_triangle_mesh()`) the surface it describes is refused.

  The readers check every count and index against the size of the file before they allocate or index
  anything, so a hostile file ends in this exception and never in a crash or an unbounded allocation.

  `what()` reads `FILE:LINE: MESSAGE` for text formats, `FILE: LOCATION: MESSAGE` for binary ones
  (for example `mesh.ply: element 'face' item 12: vertex index 4000 is out of range (100 vertices)`) and
  `FILE: MESSAGE` when no single place is to blame.
*/
class Read_error : public std::runtime_error
{
public:
  /// `line` is 1-based, 0 when the error has no line (binary data, or the file as a whole);
  /// `location` names the binary element and item ("element 'face' item 12", "triangle 7"), or is empty.
  Read_error(const std::string& file_name, std::size_t line, const std::string& location, const std::string& message)
    : std::runtime_error(compose(file_name, line, location, message)),
      file_name_(file_name), line_(line), location_(location), message_(message)
  {}

  /// The file name as given to the reader (or the name given with a stream).
  const std::string& file_name() const { return file_name_; }
  /// The 1-based line of a text file the problem is on, 0 if none.
  std::size_t line() const { return line_; }
  /// The binary element / item the problem is in ("element 'vertex' item 3"), empty if none.
  const std::string& location() const { return location_; }
  /// The problem alone, without the file name and place.
  const std::string& message() const { return message_; }

private:
  static std::string compose(const std::string& file_name, std::size_t line, const std::string& location,
                             const std::string& message)
  {
    std::string text = file_name.empty() ? std::string("<input>") : file_name;
    if(line > 0) text += ":" + std::to_string(line);
    if(!location.empty()) text += ": " + location;
    return text + ": " + message;
  }

  std::string file_name_;
  std::size_t line_;
  std::string location_;
  std::string message_;
};

} // namespace IO
} // namespace MDCS
} // namespace CGAL

#endif // CGAL_MDCS_IO_READ_ERROR_H
