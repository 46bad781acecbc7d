// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Building blocks of the MDCS readers: the whole file in memory (so that every count can be checked against
// the bytes that remain), lines and tokens of text formats, a bounds-checked binary cursor, and number
// parsing that never accepts trailing characters, overflow or (where it matters) a non-finite value.

#ifndef CGAL_MDCS_IO_INTERNAL_INPUT_TEXT_H
#define CGAL_MDCS_IO_INTERNAL_INPUT_TEXT_H

#include <CGAL/MDCS/IO/Read_error.h>

#include <cctype>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <iterator>
#include <limits>
#include <new>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace MDCS {
namespace IO {
namespace internal {

// A violated invariant of a reader itself (never caused by a file): an exception rather than a read out of bounds.
inline void check_reader_invariant(bool condition, const char* what)
{
  if(!condition) throw std::logic_error(std::string("MDCS reader invariant violated: ") + what);
}

// The whole file: readers check every count against the bytes that remain before they allocate anything.
// Only regular files: a FIFO or a device could be endless.
inline std::string load_file(const std::string& file_name)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(file_name, ec);
  if(ec || !fs::exists(status)) throw Read_error(file_name, 0, "", "cannot open the file: it does not exist");
  if(fs::is_directory(status)) throw Read_error(file_name, 0, "", "cannot read the file: it is a directory");
  if(!fs::is_regular_file(status)) throw Read_error(file_name, 0, "", "cannot read the file: it is not a regular file");
  const std::uintmax_t size = fs::file_size(file_name, ec);
  if(ec) throw Read_error(file_name, 0, "", "cannot read the file's size: " + ec.message());
  if(size > std::uintmax_t(std::numeric_limits<std::ptrdiff_t>::max()))
    throw Read_error(file_name, 0, "", "the file is too large for this machine's address space");
  std::ifstream in(file_name, std::ios::binary);
  if(!in) throw Read_error(file_name, 0, "", "cannot open the file (permissions?)");
  std::string data;
  try {
    data.resize(std::size_t(size));
  } catch(const std::bad_alloc&) {
    throw Read_error(file_name, 0, "", "not enough memory to hold the file (" + std::to_string(size) + " bytes)");
  }
  if(size > 0 && !in.read(&data[0], std::streamsize(size)))
    throw Read_error(file_name, 0, "", "cannot read the whole file (it changed or an I/O error occurred)");
  return data;
}

inline std::string load_stream(std::istream& in)
{
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// A token as it may be shown in a message: at most 40 bytes, non-printable bytes as \xNN.
inline std::string printable(std::string_view text, std::size_t max_length = 40)
{
  static const char* hex = "0123456789abcdef";
  std::string out;
  for(std::size_t i = 0; i < text.size(); ++i) {
    if(i == max_length) {
      out += "...";
      break;
    }
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if(c >= 32 && c < 127) {
      out += char(c);
    } else {
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return "'" + out + "'";
}

inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Lines of a text held in memory; the returned line has neither its '\n' nor a trailing '\r'.
class Line_reader
{
public:
  explicit Line_reader(std::string_view data, std::size_t first_line = 0)
    : data_(data), line_(first_line) {}

  bool next(std::string_view& line)
  {
    if(pos_ >= data_.size()) return false;
    const std::size_t end = data_.find('\n', pos_);
    const std::size_t stop = end == std::string_view::npos ? data_.size() : end;
    line = data_.substr(pos_, stop - pos_);
    if(!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos_ = end == std::string_view::npos ? data_.size() : end + 1;
    ++line_;
    return true;
  }

  /// The number of the line last returned (1-based).
  std::size_t line() const { return line_; }
  /// Bytes not yet returned.
  std::size_t remaining() const { return data_.size() - pos_; }
  /// Offset of the next line in the data.
  std::size_t offset() const { return pos_; }

private:
  std::string_view data_;
  std::size_t pos_ = 0;
  std::size_t line_;
};

// The part of a line before a comment character.
inline std::string_view strip_comment(std::string_view line, char comment = '#')
{
  const std::size_t hash = line.find(comment);
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

// Whitespace-separated tokens of one line.
class Tokens
{
public:
  Tokens() = default;
  explicit Tokens(std::string_view line) : rest_(line) {}

  bool next(std::string_view& token)
  {
    std::size_t i = 0;
    while(i < rest_.size() && is_space(rest_[i])) ++i;
    if(i == rest_.size()) {
      rest_ = std::string_view();
      return false;
    }
    std::size_t j = i;
    while(j < rest_.size() && !is_space(rest_[j])) ++j;
    token = rest_.substr(i, j - i);
    rest_ = rest_.substr(j);
    return true;
  }

  bool empty() const
  {
    for(char c : rest_)
      if(!is_space(c)) return false;
    return true;
  }

  std::size_t count() const
  {
    Tokens copy(*this);
    std::string_view t;
    std::size_t n = 0;
    while(copy.next(t)) ++n;
    return n;
  }

  std::string_view rest() const { return rest_; }

private:
  std::string_view rest_;
};

// Whitespace-separated tokens of a whole text across lines, with the line of the last token.
class Token_stream
{
public:
  Token_stream(std::string_view data, std::size_t first_line) : data_(data), line_(first_line) {}

  bool next(std::string_view& token)
  {
    while(pos_ < data_.size() && (is_space(data_[pos_]) || data_[pos_] == '\n')) {
      if(data_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if(pos_ == data_.size()) return false;
    const std::size_t start = pos_;
    while(pos_ < data_.size() && !is_space(data_[pos_]) && data_[pos_] != '\n') ++pos_;
    token = data_.substr(start, pos_ - start);
    token_line_ = line_;
    return true;
  }

  // Skips the rest of the current line (for example a name after a keyword).
  void skip_line()
  {
    while(pos_ < data_.size() && data_[pos_] != '\n') ++pos_;
  }

  /// The line of the token last returned.
  std::size_t line() const { return token_line_; }
  std::size_t remaining() const { return data_.size() - pos_; }

private:
  std::string_view data_;
  std::size_t pos_ = 0;
  std::size_t line_;
  std::size_t token_line_ = 0;
};

enum class Number_status { ok, not_a_number, out_of_range };

// Whether a decimal number token that from_chars found out of range is tiny (underflow) rather than huge.
inline bool decimal_underflows(const char* b, const char* e)
{
  if(b != e && (*b == '-' || *b == '+')) ++b;
  long long magnitude = 0; // decimal exponent of the first non-zero digit
  bool found = false;
  long long integer_digits = 0, position_after_point = 0;
  bool after_point = false;
  for(; b != e && (std::isdigit(static_cast<unsigned char>(*b)) || *b == '.'); ++b) {
    if(*b == '.') {
      after_point = true;
      continue;
    }
    if(!after_point) {
      if(found || *b != '0') {
        if(!found) found = true;
        ++integer_digits;
      }
    } else {
      ++position_after_point;
      if(!found && *b != '0') {
        found = true;
        magnitude = -position_after_point;
      }
    }
  }
  if(!found) return true; // all digits zero: cannot overflow
  if(integer_digits > 0) magnitude = integer_digits - 1;
  long long exponent = 0;
  if(b != e && (*b == 'e' || *b == 'E')) {
    ++b;
    bool negative = false;
    if(b != e && (*b == '-' || *b == '+')) negative = (*b++ == '-');
    for(; b != e && std::isdigit(static_cast<unsigned char>(*b)); ++b)
      if(exponent < 100000000) exponent = exponent * 10 + (*b - '0');
    if(negative) exponent = -exponent;
  }
  return magnitude + exponent < 0;
}

// A real number that is the whole token (a leading '+' allowed; "inf" and "nan" are numbers here, the
// callers decide whether they accept them). Numbers too small for a double become a signed zero; numbers
// too large are out of range.
inline Number_status parse_real(std::string_view token, double& value)
{
  const char* b = token.data();
  const char* e = b + token.size();
  if(b != e && *b == '+') {
    ++b;
    if(b != e && (*b == '+' || *b == '-')) return Number_status::not_a_number;
  }
  if(b == e) return Number_status::not_a_number;
  double v = 0;
  const std::from_chars_result r = std::from_chars(b, e, v);
  if(r.ec == std::errc::invalid_argument || r.ptr != e) return Number_status::not_a_number;
  if(r.ec == std::errc::result_out_of_range) {
    if(!decimal_underflows(b, e)) return Number_status::out_of_range;
    v = (*b == '-') ? -0.0 : 0.0;
  }
  value = v;
  return Number_status::ok;
}

// An integer that is the whole token (a leading '+' allowed), in the range of T.
template <class T>
Number_status parse_integer(std::string_view token, T& value)
{
  static_assert(std::is_integral<T>::value, "parse_integer needs an integer type");
  const char* b = token.data();
  const char* e = b + token.size();
  if(b != e && *b == '+') {
    ++b;
    if(b != e && (*b == '+' || *b == '-')) return Number_status::not_a_number;
  }
  if(b == e) return Number_status::not_a_number;
  T v = 0;
  const std::from_chars_result r = std::from_chars(b, e, v);
  if(r.ec == std::errc::invalid_argument || r.ptr != e) return Number_status::not_a_number;
  if(r.ec == std::errc::result_out_of_range) return Number_status::out_of_range;
  value = v;
  return Number_status::ok;
}

// A bounds-checked cursor over binary data in either byte order.
class Binary_reader
{
public:
  Binary_reader(std::string_view data, bool big_endian) : data_(data), big_endian_(big_endian) {}

  std::size_t remaining() const { return data_.size() - pos_; }
  std::size_t offset() const { return pos_; }
  bool can_read(std::size_t bytes) const { return bytes <= remaining(); }

  void skip(std::size_t bytes)
  {
    check_reader_invariant(bytes <= remaining(), "skip beyond the end");
    pos_ += bytes;
  }

  // The caller has checked can_read(sizeof(T)).
  template <class T>
  T read()
  {
    static_assert(std::is_arithmetic<T>::value, "read() needs an arithmetic type");
    check_reader_invariant(sizeof(T) <= remaining(), "read beyond the end");
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, data_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    if(big_endian_ != host_is_big_endian())
      for(std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
    T value;
    std::memcpy(&value, bytes, sizeof(T));
    return value;
  }

  static bool host_is_big_endian()
  {
    const std::uint16_t probe = 1;
    unsigned char first;
    std::memcpy(&first, &probe, 1);
    return first == 0;
  }

private:
  std::string_view data_;
  std::size_t pos_ = 0;
  bool big_endian_;
};

} // namespace internal
} // namespace IO
} // namespace MDCS
} // namespace CGAL

#endif // CGAL_MDCS_IO_INTERNAL_INPUT_TEXT_H
