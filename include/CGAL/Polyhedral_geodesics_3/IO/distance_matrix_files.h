// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Files that other tools read, for the distance matrices of geodesic_distance_matrix.h: NumPy's .npy (dense,
// float64, written row by row as the rows arrive) and Matrix Market coordinate files (sparse; SciPy's
// scipy.io.mmread, MATLAB, Julia), plus readers of both for tests and round trips.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_IO_DISTANCE_MATRIX_FILES_H
#define CGAL_POLYHEDRAL_GEODESICS_3_IO_DISTANCE_MATRIX_FILES_H

#include <CGAL/Polyhedral_geodesics_3/geodesic_distance_matrix.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <istream>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace IO {

namespace internal {

inline bool little_endian()
{
  const std::uint16_t one = 1;
  unsigned char b;
  std::memcpy(&b, &one, 1);
  return b == 1;
}

// Writes doubles as little-endian float64.
inline void write_float64(std::ostream& out, const double* v, std::size_t n)
{
  if(little_endian()) {
    out.write(reinterpret_cast<const char*>(v), std::streamsize(n * sizeof(double)));
    return;
  }
  for(std::size_t i = 0; i < n; ++i) {
    unsigned char b[8];
    std::memcpy(b, v + i, 8);
    for(int k = 0; k < 4; ++k) std::swap(b[k], b[7 - k]);
    out.write(reinterpret_cast<const char*>(b), 8);
  }
}

inline void check_stream(const std::ostream& out, const char* what)
{
  if(!out) throw std::runtime_error(std::string("CGAL::Polyhedral_geodesics_3::IO: writing the ") + what + " failed");
}

} // namespace internal

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief Writes a `rows` x `columns` matrix of float64 in NumPy's `.npy` format (version 1.0, C order), one row at a
  time: the header first (it holds the shape), then `write_row()` for each row in order; `close()` checks that every
  row was written. `numpy.load()` reads the file (unreachable pairs are `inf`).
  \throws std::invalid_argument for a row of the wrong length or too many rows; std::runtime_error when the stream
          fails (disk full, closed pipe).
*/
class Npy_matrix_writer
{
public:
  Npy_matrix_writer(std::ostream& out, std::size_t rows, std::size_t columns)
    : out_(out), rows_(rows), columns_(columns)
  {
    std::string dict = "{'descr': '<f8', 'fortran_order': False, 'shape': (" + std::to_string(rows) + ", " +
                       std::to_string(columns) + "), }";
    // magic (6) + version (2) + header length (2) + dict + padding + '\n': a multiple of 64 bytes.
    const std::size_t unpadded = 10 + dict.size() + 1;
    dict.append((64 - unpadded % 64) % 64, ' ');
    dict.push_back('\n');
    if(dict.size() > 65535) throw std::invalid_argument("CGAL::Polyhedral_geodesics_3::IO: .npy header too long");
    const unsigned char head[10] = {0x93, 'N', 'U', 'M', 'P', 'Y', 1, 0, static_cast<unsigned char>(dict.size() & 0xFF),
                                    static_cast<unsigned char>(dict.size() >> 8)};
    out_.write(reinterpret_cast<const char*>(head), 10);
    out_ << dict;
    internal::check_stream(out_, ".npy header");
  }

  void write_row(const std::vector<double>& row)
  {
    if(row.size() != columns_)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3::IO: .npy row of " + std::to_string(row.size()) +
                                  " values for " + std::to_string(columns_) + " columns");
    if(written_ == rows_) throw std::invalid_argument("CGAL::Polyhedral_geodesics_3::IO: more .npy rows than declared");
    internal::write_float64(out_, row.data(), row.size());
    internal::check_stream(out_, ".npy rows");
    ++written_;
  }

  /// Flushes; throws `std::logic_error` if fewer rows than declared were written.
  void close()
  {
    out_.flush();
    internal::check_stream(out_, ".npy file");
    if(written_ != rows_)
      throw std::logic_error("CGAL::Polyhedral_geodesics_3::IO: .npy file closed after " + std::to_string(written_) +
                             " of " + std::to_string(rows_) + " rows");
  }

  std::size_t rows_written() const { return written_; }

private:
  std::ostream& out_;
  std::size_t rows_, columns_, written_ = 0;
};

/// Writes a row-major `rows` x `columns` matrix as a `.npy` file.
inline void write_npy(std::ostream& out, std::size_t rows, std::size_t columns, const std::vector<double>& row_major)
{
  if(row_major.size() != rows * columns)
    throw std::invalid_argument("CGAL::Polyhedral_geodesics_3::IO: write_npy: rows * columns values are needed");
  Npy_matrix_writer w(out, rows, columns);
  internal::write_float64(out, row_major.data(), row_major.size());
  internal::check_stream(out, ".npy rows");
  out.flush();
  internal::check_stream(out, ".npy file");
}

/// Reads a `.npy` file of float64 in C order (what `Npy_matrix_writer` and `numpy.save()` of a float64 matrix
/// write). \throws std::runtime_error for anything else.
inline std::vector<double> read_npy(std::istream& in, std::size_t& rows, std::size_t& columns)
{
  unsigned char head[10];
  if(!in.read(reinterpret_cast<char*>(head), 10) || std::memcmp(head, "\x93NUMPY", 6) != 0)
    throw std::runtime_error("CGAL::Polyhedral_geodesics_3::IO: not a .npy file");
  std::size_t len = std::size_t(head[8]) | (std::size_t(head[9]) << 8);
  if(head[6] >= 2) { // version 2 and 3: a 4-byte header length
    unsigned char more[2];
    if(!in.read(reinterpret_cast<char*>(more), 2)) throw std::runtime_error("CGAL::Polyhedral_geodesics_3::IO: truncated .npy header");
    len |= (std::size_t(more[0]) << 16) | (std::size_t(more[1]) << 24);
  }
  std::string dict(len, ' ');
  if(!in.read(&dict[0], std::streamsize(len))) throw std::runtime_error("CGAL::Polyhedral_geodesics_3::IO: truncated .npy header");
  if(dict.find("'<f8'") == std::string::npos || dict.find("'fortran_order': False") == std::string::npos)
    throw std::runtime_error("CGAL::Polyhedral_geodesics_3::IO: only little-endian float64 C-order .npy files are read");
  const std::size_t open = dict.find('(', dict.find("'shape'"));
  const std::size_t close = dict.find(')', open);
  if(open == std::string::npos || close == std::string::npos)
    throw std::runtime_error("CGAL::Polyhedral_geodesics_3::IO: .npy header without a shape");
  std::istringstream shape(dict.substr(open + 1, close - open - 1));
  char comma = 0;
  if(!(shape >> rows >> comma >> columns) || comma != ',')
    throw std::runtime_error("CGAL::Polyhedral_geodesics_3::IO: only two-dimensional .npy files are read");
  std::vector<double> v(rows * columns);
  if(!in.read(reinterpret_cast<char*>(v.data()), std::streamsize(v.size() * sizeof(double))))
    throw std::runtime_error("CGAL::Polyhedral_geodesics_3::IO: truncated .npy data");
  if(!internal::little_endian())
    for(double& x : v) {
      unsigned char b[8];
      std::memcpy(b, &x, 8);
      for(int k = 0; k < 4; ++k) std::swap(b[k], b[7 - k]);
      std::memcpy(&x, b, 8);
    }
  return v;
}

namespace internal {

inline void write_mm_entry(std::ostream& out, std::size_t r, std::size_t c, double v)
{
  char text[64];
  std::snprintf(text, sizeof text, "%zu %zu %.17g\n", r + 1, c + 1, v); // 1-based, round-trip precision
  out << text;
}

} // namespace internal

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief Writes `m` as a Matrix Market coordinate file of reals (1-based indices, values to 17 significant
  digits): `symmetric` if `m.symmetric` (the entries with row >= column only, as the format wants), else `general`.
  `comment` lines (optional) go after the banner. `scipy.io.mmread()` reads it.
*/
inline void write_matrix_market(std::ostream& out, const Geodesic_sparse_matrix& m, const std::string& comment = "")
{
  std::size_t entries = 0;
  for(std::size_t r = 0; r < m.rows; ++r)
    for(std::size_t k = m.row_begin[r]; k < m.row_begin[r + 1]; ++k)
      if(!m.symmetric || m.column[k] <= r) ++entries;
  out << "%%MatrixMarket matrix coordinate real " << (m.symmetric ? "symmetric" : "general") << "\n";
  std::istringstream lines(comment);
  for(std::string line; std::getline(lines, line);) out << "% " << line << "\n";
  out << m.rows << " " << m.columns << " " << entries << "\n";
  for(std::size_t r = 0; r < m.rows; ++r)
    for(std::size_t k = m.row_begin[r]; k < m.row_begin[r + 1]; ++k)
      if(!m.symmetric || m.column[k] <= r) internal::write_mm_entry(out, r, m.column[k], m.value[k]);
  out.flush();
  internal::check_stream(out, "Matrix Market file");
}

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief Writes the rows of `local_geodesic_distance_rows()` as they arrive into a Matrix Market coordinate file
  (`general`), so that the matrix is never held in memory. The number of entries, unknown until the end, is written
  by `close()` into a fixed-width field of the size line: the stream must be seekable (a file, not a pipe).
*/
class Matrix_market_row_writer
{
public:
  Matrix_market_row_writer(std::ostream& out, std::size_t rows, std::size_t columns, const std::string& comment = "")
    : out_(out), rows_(rows)
  {
    out_ << "%%MatrixMarket matrix coordinate real general\n";
    std::istringstream lines(comment);
    for(std::string line; std::getline(lines, line);) out_ << "% " << line << "\n";
    out_ << rows << " " << columns << " ";
    size_field_ = out_.tellp();
    if(size_field_ < 0)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3::IO: Matrix_market_row_writer needs a seekable stream");
    out_ << std::string(20, ' ') << "\n"; // room for the number of entries
    internal::check_stream(out_, "Matrix Market header");
  }

  void write_row(const std::vector<std::uint32_t>& columns, const std::vector<double>& values)
  {
    if(columns.size() != values.size())
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3::IO: Matrix Market row with as many columns as values needed");
    if(row_ == rows_) throw std::invalid_argument("CGAL::Polyhedral_geodesics_3::IO: more Matrix Market rows than declared");
    for(std::size_t k = 0; k < columns.size(); ++k) internal::write_mm_entry(out_, row_, columns[k], values[k]);
    entries_ += columns.size();
    ++row_;
    internal::check_stream(out_, "Matrix Market rows");
  }

  /// Writes the number of entries and flushes; throws `std::logic_error` if fewer rows than declared were written.
  void close()
  {
    if(row_ != rows_)
      throw std::logic_error("CGAL::Polyhedral_geodesics_3::IO: Matrix Market file closed after " + std::to_string(row_) +
                             " of " + std::to_string(rows_) + " rows");
    const std::streampos end = out_.tellp();
    out_.seekp(size_field_);
    out_ << entries_;
    out_.seekp(end);
    out_.flush();
    internal::check_stream(out_, "Matrix Market file");
  }

private:
  std::ostream& out_;
  std::size_t rows_, row_ = 0, entries_ = 0;
  std::streampos size_field_;
};

/// Reads a Matrix Market coordinate file of reals (general or symmetric; a symmetric one is expanded to both
/// triangles) into a `Geodesic_sparse_matrix` with sorted rows. \throws std::runtime_error for other files.
inline Geodesic_sparse_matrix read_matrix_market(std::istream& in)
{
  std::string line;
  if(!std::getline(in, line) || line.rfind("%%MatrixMarket matrix coordinate real", 0) != 0)
    throw std::runtime_error("CGAL::Polyhedral_geodesics_3::IO: not a Matrix Market coordinate file of reals");
  const bool symmetric = line.find("symmetric") != std::string::npos;
  while(std::getline(in, line) && !line.empty() && line[0] == '%') {
  }
  std::istringstream size(line);
  Geodesic_sparse_matrix m;
  std::size_t entries = 0;
  if(!(size >> m.rows >> m.columns >> entries))
    throw std::runtime_error("CGAL::Polyhedral_geodesics_3::IO: Matrix Market size line expected");
  struct Triplet
  {
    std::size_t r, c;
    double v;
  };
  std::vector<Triplet> t;
  for(std::size_t k = 0; k < entries; ++k) {
    Triplet x;
    if(!(in >> x.r >> x.c >> x.v) || x.r < 1 || x.c < 1 || x.r > m.rows || x.c > m.columns)
      throw std::runtime_error("CGAL::Polyhedral_geodesics_3::IO: bad Matrix Market entry " + std::to_string(k + 1));
    --x.r;
    --x.c;
    t.push_back(x);
    if(symmetric && x.r != x.c) t.push_back(Triplet{x.c, x.r, x.v});
  }
  std::sort(t.begin(), t.end(), [](const Triplet& a, const Triplet& b) { return a.r < b.r || (a.r == b.r && a.c < b.c); });
  m.symmetric = symmetric;
  m.row_begin.assign(m.rows + 1, 0);
  for(const Triplet& x : t) {
    ++m.row_begin[x.r + 1];
    m.column.push_back(std::uint32_t(x.c));
    m.value.push_back(x.v);
  }
  for(std::size_t r = 0; r < m.rows; ++r) m.row_begin[r + 1] += m.row_begin[r];
  return m;
}

} // namespace IO
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_IO_DISTANCE_MATRIX_FILES_H
