// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// STL (ascii and binary) as a triangle soup; vertices with the same coordinates (exactly, -0 = +0) become
// one point, numbered in order of first appearance (as CGAL's reader does). A file is binary when its size is
// exactly 84 + 50 N bytes for the N its header announces (binary files may start with "solid" too); ascii
// when it starts with "solid" and looks like text. Several solids in one ascii file are read one after the other.

#ifndef CGAL_MDCS_IO_INTERNAL_READ_STL_H
#define CGAL_MDCS_IO_INTERNAL_READ_STL_H

#include <CGAL/MDCS/IO/Read_error.h>
#include <CGAL/MDCS/IO/internal/input_text.h>

#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace MDCS {
namespace IO {
namespace internal {

// Numbers the distinct points of an STL file in order of first appearance.
class STL_point_index
{
public:
  template <class Output>
  std::size_t operator()(double x, double y, double z, Output& out)
  {
    const Key key = {{bits(x), bits(y), bits(z)}};
    const auto inserted = index_.emplace(key, index_.size());
    if(inserted.second) out.add_point(x, y, z);
    return inserted.first->second;
  }

private:
  typedef std::array<std::uint64_t, 3> Key;
  struct Hash
  {
    std::size_t operator()(const Key& k) const
    {
      std::uint64_t h = 1469598103934665603ull;
      for(std::uint64_t v : k) h = (h ^ v) * 1099511628211ull ^ (v >> 29);
      return std::size_t(h);
    }
  };
  static std::uint64_t bits(double v)
  {
    if(v == 0) v = 0; // -0 and +0 are the same point
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
  }
  std::unordered_map<Key, std::size_t, Hash> index_;
};

inline bool STL_keyword_is(std::string_view token, const char* keyword)
{
  const std::size_t n = std::strlen(keyword);
  if(token.size() != n) return false;
  for(std::size_t i = 0; i < n; ++i)
    if(std::tolower(static_cast<unsigned char>(token[i])) != keyword[i]) return false;
  return true;
}

template <class Output>
void read_STL_binary(std::string_view data, const std::string& name, Output& out)
{
  Binary_reader in(data, false);
  in.skip(80);
  const std::uint32_t n = in.read<std::uint32_t>();
  out.reserve_polygons(n); // the size was checked: 84 + 50 n bytes
  STL_point_index index;
  std::vector<std::size_t> corners(3);
  for(std::uint32_t t = 0; t < n; ++t) {
    in.skip(12); // the normal
    for(int j = 0; j < 3; ++j) {
      const double x = in.read<float>(), y = in.read<float>(), z = in.read<float>();
      if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
        throw Read_error(name, 0, "triangle " + std::to_string(t), "a vertex coordinate is not a finite number");
      corners[std::size_t(j)] = index(x, y, z, out);
    }
    in.skip(2); // the attribute byte count
    out.add_polygon(corners, 0, "triangle", t);
  }
}

template <class Output>
void read_STL_ascii(std::string_view data, const std::string& name, Output& out)
{
  Token_stream tokens(data, 1);
  std::string_view token;
  auto fail = [&](const std::string& message) { throw Read_error(name, tokens.line(), "", message); };
  auto expect = [&](const char* keyword, const char* context) {
    if(!tokens.next(token)) fail(std::string("the file ends before '") + keyword + "' " + context + " (truncated)");
    if(!STL_keyword_is(token, keyword)) fail(std::string("expected '") + keyword + "' " + context + ", found " + printable(token));
  };
  auto number = [&](const char* what, bool finite) {
    if(!tokens.next(token)) fail(std::string("the file ends inside ") + what + " (truncated)");
    double v = 0;
    const Number_status status = parse_real(token, v);
    if(status != Number_status::ok) fail(std::string(what) + ": " + printable(token) + " is not a number in range");
    if(finite && !std::isfinite(v)) fail(std::string(what) + ": " + printable(token) + " is not a finite number");
    return v;
  };
  STL_point_index index;
  std::vector<std::size_t> corners(3);
  std::size_t solids = 0;
  while(tokens.next(token)) {
    if(!STL_keyword_is(token, "solid"))
      fail(solids == 0 ? "not an ascii STL file: it does not start with 'solid'"
                       : "expected 'solid' or the end of the file after 'endsolid', found " + printable(token));
    tokens.skip_line(); // the solid's name
    ++solids;
    for(;;) {
      if(!tokens.next(token)) fail("the file ends inside a solid (no 'endsolid': truncated)");
      if(STL_keyword_is(token, "endsolid")) {
        tokens.skip_line();
        break;
      }
      if(!STL_keyword_is(token, "facet")) fail("expected 'facet' or 'endsolid', found " + printable(token));
      expect("normal", "after 'facet'");
      for(int j = 0; j < 3; ++j) number("the facet normal", false);
      expect("outer", "before the facet's vertices");
      expect("loop", "after 'outer'");
      for(int j = 0; j < 3; ++j) {
        if(!tokens.next(token)) fail("the file ends inside a facet (truncated)");
        if(STL_keyword_is(token, "endloop"))
          fail("a facet with " + std::to_string(j) + " vertices (STL facets are triangles)");
        if(!STL_keyword_is(token, "vertex")) fail("expected 'vertex', found " + printable(token));
        const double x = number("a vertex coordinate", true);
        const double y = number("a vertex coordinate", true);
        const double z = number("a vertex coordinate", true);
        corners[std::size_t(j)] = index(x, y, z, out);
      }
      if(!tokens.next(token)) fail("the file ends inside a facet (truncated)");
      if(STL_keyword_is(token, "vertex")) fail("a facet with more than 3 vertices (STL facets are triangles)");
      if(!STL_keyword_is(token, "endloop")) fail("expected 'endloop', found " + printable(token));
      expect("endfacet", "after 'endloop'");
      out.add_polygon(corners, tokens.line());
    }
  }
  if(solids == 0) throw Read_error(name, 0, "", "the file is empty: no STL solid");
}

template <class Output>
void read_STL(std::string_view data, const std::string& name, Output& out)
{
  std::uint64_t announced = 0;
  if(data.size() >= 84) {
    Binary_reader header(data, false);
    header.skip(80);
    announced = header.read<std::uint32_t>();
    if(84 + 50 * announced == data.size()) {
      read_STL_binary(data, name, out);
      return;
    }
  }
  // Text that starts with "solid": ascii. A binary header may start with "solid" too; bytes that no text
  // holds tell them apart when the size did not match.
  std::size_t i = 0;
  while(i < data.size() && (is_space(data[i]) || data[i] == '\n')) ++i;
  const bool starts_with_solid = data.size() - i >= 5 && STL_keyword_is(data.substr(i, 5), "solid");
  bool text = true;
  for(std::size_t j = 0; j < data.size() && j < 1024; ++j) {
    const unsigned char c = static_cast<unsigned char>(data[j]);
    if(c == 0 || (c < 32 && c != '\n' && c != '\r' && c != '\t' && c != '\f' && c != '\v')) text = false;
  }
  if(starts_with_solid && text) {
    read_STL_ascii(data, name, out);
    return;
  }
  if(data.size() >= 84)
    throw Read_error(name, 0, "header", "binary STL: the header announces " + std::to_string(announced) + " triangles (" +
                     std::to_string(84 + 50 * announced) + " bytes), but the file has " + std::to_string(data.size()) +
                     " bytes (truncated or not an STL file)");
  if(data.empty()) throw Read_error(name, 0, "", "the file is empty");
  throw Read_error(name, 0, "", "not an STL file: too short for binary STL and it does not start with 'solid'");
}

} // namespace internal
} // namespace IO
} // namespace MDCS
} // namespace CGAL

#endif // CGAL_MDCS_IO_INTERNAL_READ_STL_H
