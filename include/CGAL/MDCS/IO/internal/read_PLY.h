// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// PLY (ascii, binary_little_endian, binary_big_endian 1.0) as a polygon soup: the element "vertex" (or
// "vertices") with scalar properties x, y, z of any type, the element "face" (or "faces") with a list
// property "vertex_indices" (or "vertex_index") of any integer count and index type; every other element and
// property is read past according to its declared type. Element counts are checked against the bytes left
// before anything is reserved (each item needs at least its fixed-size part), list counts against the bytes
// left, indices against the vertex count.

#ifndef CGAL_MDCS_IO_INTERNAL_READ_PLY_H
#define CGAL_MDCS_IO_INTERNAL_READ_PLY_H

#include <CGAL/MDCS/IO/Read_error.h>
#include <CGAL/MDCS/IO/internal/input_text.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace MDCS {
namespace IO {
namespace internal {

enum class PLY_type { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

inline bool parse_PLY_type(std::string_view word, PLY_type& type)
{
  if(word == "char" || word == "int8") type = PLY_type::int8;
  else if(word == "uchar" || word == "uint8") type = PLY_type::uint8;
  else if(word == "short" || word == "int16") type = PLY_type::int16;
  else if(word == "ushort" || word == "uint16") type = PLY_type::uint16;
  else if(word == "int" || word == "int32") type = PLY_type::int32;
  else if(word == "uint" || word == "uint32") type = PLY_type::uint32;
  else if(word == "float" || word == "float32") type = PLY_type::float32;
  else if(word == "double" || word == "float64") type = PLY_type::float64;
  else return false;
  return true;
}

inline std::size_t PLY_size(PLY_type t)
{
  switch(t) {
  case PLY_type::int8: case PLY_type::uint8: return 1;
  case PLY_type::int16: case PLY_type::uint16: return 2;
  case PLY_type::int32: case PLY_type::uint32: case PLY_type::float32: return 4;
  default: return 8;
  }
}

inline bool PLY_is_integer(PLY_type t) { return t != PLY_type::float32 && t != PLY_type::float64; }

inline void PLY_integer_range(PLY_type t, std::int64_t& low, std::int64_t& high)
{
  switch(t) {
  case PLY_type::int8: low = -128, high = 127; break;
  case PLY_type::uint8: low = 0, high = 255; break;
  case PLY_type::int16: low = -32768, high = 32767; break;
  case PLY_type::uint16: low = 0, high = 65535; break;
  case PLY_type::int32: low = -2147483648LL, high = 2147483647LL; break;
  default: low = 0, high = 4294967295LL; break;
  }
}

struct PLY_property
{
  std::string name;
  bool list = false;
  PLY_type type = PLY_type::float32;       // the scalar type, or the list's item type
  PLY_type count_type = PLY_type::uint8;   // lists only
};

struct PLY_element
{
  std::string name;
  std::uint64_t count = 0;
  std::size_t header_line = 0;
  std::vector<PLY_property> properties;
  // The bytes (binary) or characters (ascii) every item needs at least.
  std::size_t minimum_item_size(bool binary) const
  {
    std::size_t s = 0;
    for(const PLY_property& p : properties) s += binary ? PLY_size(p.list ? p.count_type : p.type) : 2;
    return s;
  }
};

// Reads the body of a PLY file, item by item; the value reading differs between ascii and binary.
template <class Output>
class PLY_body_reader
{
public:
  PLY_body_reader(const std::string& name, Output& out, std::vector<PLY_element>& elements, bool binary,
                  bool big_endian, std::string_view body, std::size_t body_first_line)
    : name_(name), out_(out), elements_(elements), binary_(binary),
      bin_(body, big_endian), text_(body, body_first_line)
  {}

  void read()
  {
    // Roles: the vertex element and its x, y, z; the face element and its index list.
    std::uint64_t number_of_vertices = 0;
    const PLY_element* vertex_element = nullptr;
    for(const PLY_element& e : elements_) {
      if(e.name == "vertex" || e.name == "vertices") {
        if(vertex_element) fail_header(e.header_line, "a second vertex element '" + e.name + "'");
        vertex_element = &e;
        number_of_vertices = e.count;
      }
    }
    bool face_seen = false;
    for(const PLY_element& e : elements_) {
      if(&e == vertex_element) {
        xyz_[0] = xyz_[1] = xyz_[2] = -1;
        for(std::size_t i = 0; i < e.properties.size(); ++i) {
          const PLY_property& p = e.properties[i];
          const int axis = p.name == "x" ? 0 : p.name == "y" ? 1 : p.name == "z" ? 2 : -1;
          if(axis < 0) continue;
          if(p.list) fail_header(e.header_line, "the vertex property '" + p.name + "' is a list, not a coordinate");
          xyz_[axis] = int(i);
        }
        if(xyz_[0] < 0 || xyz_[1] < 0 || xyz_[2] < 0)
          fail_header(e.header_line, "the vertex element lacks one of the properties x, y, z");
        out_.reserve_points(std::size_t(e.count));
        read_element(e, Role::vertex, number_of_vertices);
      } else if(e.name == "face" || e.name == "faces") {
        if(face_seen) fail_header(e.header_line, "a second face element '" + e.name + "'");
        face_seen = true;
        indices_ = -1;
        for(std::size_t i = 0; i < e.properties.size(); ++i) {
          const PLY_property& p = e.properties[i];
          if(p.name != "vertex_indices" && p.name != "vertex_index") continue;
          if(!p.list) fail_header(e.header_line, "the face property '" + p.name + "' is not a list");
          if(!PLY_is_integer(p.type)) fail_header(e.header_line, "the face property '" + p.name + "' does not hold integers");
          if(indices_ >= 0) fail_header(e.header_line, "two vertex index lists in the face element");
          indices_ = int(i);
        }
        if(indices_ < 0) fail_header(e.header_line, "the face element has no list 'vertex_indices' (or 'vertex_index')");
        out_.reserve_polygons(std::size_t(e.count));
        read_element(e, Role::face, number_of_vertices);
      } else {
        read_element(e, Role::other, number_of_vertices);
      }
    }
    if(binary_) {
      if(bin_.remaining() != 0)
        throw Read_error(name_, 0, "end of data", std::to_string(bin_.remaining()) + " unexpected bytes after the last element");
    } else {
      std::string_view token;
      if(text_.next(token))
        throw Read_error(name_, text_.line(), "", "unexpected " + printable(token) + " after the last element");
    }
  }

private:
  enum class Role { vertex, face, other };

  [[noreturn]] void fail_header(std::size_t line, const std::string& message) const
  {
    throw Read_error(name_, line, "", message);
  }

  [[noreturn]] void fail(const std::string& message) const
  {
    throw Read_error(name_, binary_ ? 0 : text_.line(), location(), message);
  }

  std::string location() const
  {
    return "element '" + element_->name + "' item " + std::to_string(item_);
  }

  std::string location_prefix_; // "element 'NAME' item" of the element being read

  // What a value is, for messages: a scalar property (item < 0), the count of a list (item == count_of_list)
  // or an item of a list.
  static constexpr std::int64_t count_of_list = -2;
  static std::string describe(const PLY_property& p, std::int64_t item)
  {
    if(item == count_of_list) return "the count of the list '" + p.name + "'";
    if(item < 0) return "the property '" + p.name + "'";
    return "item " + std::to_string(item) + " of the list '" + p.name + "'";
  }

  // One value of type `type`; integers come back exactly in `integer`, every value in `real`.
  void read_value(PLY_type type, const PLY_property& p, std::int64_t item, double& real, std::int64_t& integer)
  {
    if(binary_) {
      if(!bin_.can_read(PLY_size(type))) fail("the file ends inside " + describe(p, item) + " (truncated)");
      switch(type) {
      case PLY_type::int8: integer = bin_.read<std::int8_t>(); break;
      case PLY_type::uint8: integer = bin_.read<std::uint8_t>(); break;
      case PLY_type::int16: integer = bin_.read<std::int16_t>(); break;
      case PLY_type::uint16: integer = bin_.read<std::uint16_t>(); break;
      case PLY_type::int32: integer = bin_.read<std::int32_t>(); break;
      case PLY_type::uint32: integer = bin_.read<std::uint32_t>(); break;
      case PLY_type::float32: real = bin_.read<float>(); return;
      case PLY_type::float64: real = bin_.read<double>(); return;
      }
      real = double(integer);
      return;
    }
    std::string_view token;
    if(!text_.next(token)) fail("the file ends before " + describe(p, item) + " (truncated)");
    if(PLY_is_integer(type)) {
      std::int64_t low, high;
      PLY_integer_range(type, low, high);
      const Number_status status = parse_integer(token, integer);
      if(status == Number_status::not_a_number) fail(describe(p, item) + ": " + printable(token) + " is not an integer");
      if(status == Number_status::out_of_range || integer < low || integer > high)
        fail(describe(p, item) + ": " + printable(token) + " is out of the range of its type");
      real = double(integer);
    } else {
      const Number_status status = parse_real(token, real);
      if(status == Number_status::not_a_number) fail(describe(p, item) + ": " + printable(token) + " is not a number");
      if(status == Number_status::out_of_range) fail(describe(p, item) + ": " + printable(token) + " is out of the range of a double");
      if(type == PLY_type::float32 && std::isfinite(real)) {
        // The declared type: a float property holds the float nearest to the text, as a binary file would.
        if(std::abs(real) > double(std::numeric_limits<float>::max()))
          fail(describe(p, item) + ": " + printable(token) + " is out of the range of a float");
        real = double(float(real));
      }
    }
  }

  // The count of a list, checked against what the rest of the file can hold.
  std::size_t read_list_count(const PLY_property& p)
  {
    double real = 0;
    std::int64_t count = 0;
    read_value(p.count_type, p, count_of_list, real, count);
    if(count < 0) fail("the list '" + p.name + "' has a negative count " + std::to_string(count));
    const std::size_t item = binary_ ? PLY_size(p.type) : 2;
    const std::size_t left = binary_ ? bin_.remaining() : text_.remaining() + 1;
    if(std::uint64_t(count) > left / item)
      fail("the list '" + p.name + "' announces " + std::to_string(count) + " items, more than the " +
           std::to_string(left) + " bytes left can hold");
    return std::size_t(count);
  }

  void read_element(const PLY_element& e, Role role, std::uint64_t number_of_vertices)
  {
    element_ = &e;
    location_prefix_ = "element '" + e.name + "' item";
    if(e.properties.empty()) return; // items without data: nothing to read, whatever the count
    if(binary_ && role == Role::other) {
      bool fixed = true;
      for(const PLY_property& p : e.properties) fixed = fixed && !p.list;
      if(fixed) { // skipped at once (the header check bounded count * size by the file size)
        const std::size_t bytes = std::size_t(e.count) * e.minimum_item_size(true);
        item_ = 0;
        if(!bin_.can_read(bytes)) fail("the file ends inside this element (truncated)");
        bin_.skip(bytes);
        return;
      }
    }
    double coordinates[3] = {0, 0, 0};
    double real = 0;
    std::int64_t integer = 0;
    for(item_ = 0; item_ < e.count; ++item_) {
      for(std::size_t i = 0; i < e.properties.size(); ++i) {
        const PLY_property& p = e.properties[i];
        if(!p.list) {
          read_value(p.type, p, -1, real, integer);
          if(role == Role::vertex) {
            for(int axis = 0; axis < 3; ++axis) {
              if(int(i) != xyz_[axis]) continue;
              if(!std::isfinite(real)) fail("the coordinate '" + p.name + "' is not a finite number");
              coordinates[axis] = real;
            }
          }
          continue;
        }
        const std::size_t count = read_list_count(p);
        const bool indices = role == Role::face && int(i) == indices_;
        if(indices) {
          if(count < 3) fail("a face with " + std::to_string(count) + " corners (at least 3 needed)");
          corners_.clear();
        }
        if(binary_ && !indices) {
          bin_.skip(count * PLY_size(p.type)); // within the bytes left (read_list_count)
          continue;
        }
        for(std::size_t j = 0; j < count; ++j) {
          read_value(p.type, p, std::int64_t(j), real, integer);
          if(!indices) continue;
          if(integer < 0) fail("the vertex index " + std::to_string(integer) + " is negative");
          if(std::uint64_t(integer) >= number_of_vertices)
            fail("the vertex index " + std::to_string(integer) + " is out of range (" + std::to_string(number_of_vertices) +
                 " vertices)");
          corners_.push_back(std::size_t(integer));
        }
        if(indices) out_.add_polygon(corners_, binary_ ? 0 : text_.line(), location_prefix_.c_str(), item_);
      }
      if(role == Role::vertex) out_.add_point(coordinates[0], coordinates[1], coordinates[2]);
    }
  }

  const std::string& name_;
  Output& out_;
  std::vector<PLY_element>& elements_;
  bool binary_;
  Binary_reader bin_;
  Token_stream text_;
  const PLY_element* element_ = nullptr;
  std::uint64_t item_ = 0;
  int xyz_[3] = {-1, -1, -1};
  int indices_ = -1;
  std::vector<std::size_t> corners_;
};

template <class Output>
void read_PLY(std::string_view data, const std::string& name, Output& out)
{
  Line_reader lines(data);
  std::string_view line, token;
  auto fail = [&](const std::string& message) { throw Read_error(name, lines.line(), "", message); };
  if(!lines.next(line) || line != "ply") {
    if(lines.line() == 0) throw Read_error(name, 0, "", "the file is empty: no PLY header");
    fail("not a PLY file: the first line is " + printable(line) + " (expected 'ply')");
  }
  bool binary = false, big_endian = false, format_seen = false, end_seen = false;
  std::vector<PLY_element> elements;
  while(lines.next(line)) {
    Tokens tokens(line);
    if(!tokens.next(token)) continue;
    if(token == "comment" || token == "obj_info") continue;
    std::vector<std::string_view> words;
    std::string_view w;
    while(tokens.next(w)) words.push_back(w);
    if(token == "end_header") {
      if(!words.empty()) fail("unexpected " + printable(words[0]) + " after 'end_header'");
      end_seen = true;
      break;
    }
    if(token == "format") {
      if(format_seen) fail("a second 'format' line");
      if(!elements.empty()) fail("the 'format' line comes after an element");
      if(words.size() != 2) fail("expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
      if(words[0] == "ascii") binary = false;
      else if(words[0] == "binary_little_endian") binary = true, big_endian = false;
      else if(words[0] == "binary_big_endian") binary = true, big_endian = true;
      else fail("unknown PLY format " + printable(words[0]));
      if(words[1] != "1.0") fail("unsupported PLY version " + printable(words[1]) + " (1.0 is supported)");
      format_seen = true;
    } else if(token == "element") {
      if(!format_seen) fail("an element before the 'format' line");
      if(words.size() != 2) fail("expected 'element NAME COUNT'");
      PLY_element e;
      e.name = std::string(words[0]);
      e.header_line = lines.line();
      if(parse_integer(words[1], e.count) != Number_status::ok)
        fail("the element count " + printable(words[1]) + " is not a non-negative integer in range");
      for(const PLY_element& other : elements)
        if(other.name == e.name) fail("a second element '" + e.name + "'");
      elements.push_back(e);
    } else if(token == "property") {
      if(elements.empty()) fail("a property before any element");
      PLY_property p;
      if(!words.empty() && words[0] == "list") {
        if(words.size() != 4) fail("expected 'property list COUNT_TYPE ITEM_TYPE NAME'");
        p.list = true;
        if(!parse_PLY_type(words[1], p.count_type)) fail("unknown PLY type " + printable(words[1]));
        if(!PLY_is_integer(p.count_type)) fail("the count type of a list must be an integer type");
        if(!parse_PLY_type(words[2], p.type)) fail("unknown PLY type " + printable(words[2]));
        p.name = std::string(words[3]);
      } else {
        if(words.size() != 2) fail("expected 'property TYPE NAME'");
        if(!parse_PLY_type(words[0], p.type)) fail("unknown PLY type " + printable(words[0]));
        p.name = std::string(words[1]);
      }
      for(const PLY_property& other : elements.back().properties)
        if(other.name == p.name) fail("a second property '" + p.name + "' in the element '" + elements.back().name + "'");
      elements.back().properties.push_back(p);
    } else {
      fail("unknown PLY header line starting with " + printable(token));
    }
  }
  if(!end_seen) fail("the header has no 'end_header' line (truncated, or not a PLY file)");
  if(!format_seen) fail("the header has no 'format' line");

  // Every item needs at least its fixed part: the counts cannot announce more than the file can hold.
  const std::size_t body = lines.remaining() + (binary ? 0 : 1);
  std::size_t needed = 0;
  for(const PLY_element& e : elements) {
    const std::size_t item = e.minimum_item_size(binary);
    if(item == 0) continue;
    if(e.count > (body - needed) / item)
      throw Read_error(name, e.header_line, "", "the header announces " + std::to_string(e.count) + " items of the element '" +
                       e.name + "', more than the " + std::to_string(lines.remaining()) + " bytes of data can hold");
    needed += std::size_t(e.count) * item;
  }
  PLY_body_reader<Output> reader(name, out, elements, binary, big_endian, data.substr(lines.offset()), lines.line() + 1);
  reader.read();
}

} // namespace internal
} // namespace IO
} // namespace MDCS
} // namespace CGAL

#endif // CGAL_MDCS_IO_INTERNAL_READ_PLY_H
