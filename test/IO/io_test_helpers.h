// Helpers of the reader tests: a scratch folder, the same small mesh written in every format the readers
// know (the seeds of the fuzz suite too), and a check that a reader fails with the expected message.
#ifndef MDCS_TEST_IO_TEST_HELPERS_H
#define MDCS_TEST_IO_TEST_HELPERS_H

#include <catch2/catch.hpp>

#include <CGAL/MDCS/IO/Read_error.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include <unistd.h>

namespace io_test {

// A folder of its own under the system's temporary folder, removed at the end.
class Scratch
{
public:
  // `in_memory`: in /dev/shm when the machine has it (the fuzz suite writes thousands of files: a disk
  // shared with builds makes that slow), else in the system's temporary folder.
  explicit Scratch(bool in_memory = false)
  {
    static int counter = 0;
    std::error_code ec;
    const std::filesystem::path base = in_memory && std::filesystem::is_directory("/dev/shm", ec) && ::access("/dev/shm", W_OK) == 0
                                         ? std::filesystem::path("/dev/shm")
                                         : std::filesystem::temp_directory_path();
    dir_ = base / ("mdcs-io-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::create_directories(dir_);
  }
  ~Scratch()
  {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;

  std::string write(const std::string& name, const std::string& bytes) const
  {
    const std::string path = (dir_ / name).string();
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    return path;
  }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

private:
  std::filesystem::path dir_;
};

typedef std::array<double, 3> Xyz;
typedef std::vector<std::size_t> Face;

// A closed octahedron: 6 vertices, 8 outward triangles.
inline std::vector<Xyz> octahedron_points()
{
  return {{{1, 0, 0}}, {{-1, 0, 0}}, {{0, 1, 0}}, {{0, -1, 0}}, {{0, 0, 1}}, {{0, 0, -1}}};
}
inline std::vector<Face> octahedron_faces()
{
  return {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
}

inline std::string number(double v)
{
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

inline std::string off_text(const std::vector<Xyz>& v, const std::vector<Face>& f, const std::string& header = "OFF")
{
  std::string s = header + "\n" + std::to_string(v.size()) + " " + std::to_string(f.size()) + " 0\n";
  for(const Xyz& p : v) s += number(p[0]) + " " + number(p[1]) + " " + number(p[2]) + "\n";
  for(const Face& face : f) {
    s += std::to_string(face.size());
    for(std::size_t i : face) s += " " + std::to_string(i);
    s += "\n";
  }
  return s;
}

inline std::string ply_ascii_text(const std::vector<Xyz>& v, const std::vector<Face>& f)
{
  std::string s = "ply\nformat ascii 1.0\ncomment MDCS test\nelement vertex " + std::to_string(v.size()) +
                  "\nproperty double x\nproperty double y\nproperty double z\nelement face " + std::to_string(f.size()) +
                  "\nproperty list uchar int vertex_indices\nend_header\n";
  for(const Xyz& p : v) s += number(p[0]) + " " + number(p[1]) + " " + number(p[2]) + "\n";
  for(const Face& face : f) {
    s += std::to_string(face.size());
    for(std::size_t i : face) s += " " + std::to_string(i);
    s += "\n";
  }
  return s;
}

template <class T>
void append_binary(std::string& s, T value, bool big_endian)
{
  unsigned char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  const std::uint16_t probe = 1;
  unsigned char first;
  std::memcpy(&first, &probe, 1);
  const bool host_big = first == 0;
  if(host_big != big_endian)
    for(std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
  s.append(reinterpret_cast<const char*>(b), sizeof(T));
}

// Binary PLY with an extra vertex property, an extra face property and an unused element with a list.
inline std::string ply_binary_text(const std::vector<Xyz>& v, const std::vector<Face>& f, bool big_endian)
{
  std::string s = std::string("ply\nformat binary_") + (big_endian ? "big" : "little") + "_endian 1.0\n" +
                  "element vertex " + std::to_string(v.size()) +
                  "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar quality\n" +
                  "element face " + std::to_string(f.size()) + "\nproperty list uchar int vertex_indices\nproperty short tag\n" +
                  "element extra 2\nproperty list ushort double values\nend_header\n";
  for(const Xyz& p : v) {
    for(double c : p) append_binary(s, float(c), big_endian);
    append_binary(s, std::uint8_t(9), big_endian);
  }
  for(const Face& face : f) {
    append_binary(s, std::uint8_t(face.size()), big_endian);
    for(std::size_t i : face) append_binary(s, std::int32_t(i), big_endian);
    append_binary(s, std::int16_t(-5), big_endian);
  }
  for(int e = 0; e < 2; ++e) {
    append_binary(s, std::uint16_t(2), big_endian);
    append_binary(s, 1.5, big_endian);
    append_binary(s, -2.5, big_endian);
  }
  return s;
}

inline std::string obj_text(const std::vector<Xyz>& v, const std::vector<Face>& f)
{
  std::string s = "# OBJ written by the MDCS tests\no mesh\n";
  for(const Xyz& p : v) s += "v " + number(p[0]) + " " + number(p[1]) + " " + number(p[2]) + "\n";
  s += "vt 0 0\nvn 0 0 1\n";
  for(const Face& face : f) {
    s += "f";
    for(std::size_t i : face) s += " " + std::to_string(i + 1) + "/1/1";
    s += "\n";
  }
  return s;
}

inline std::string stl_ascii_text(const std::vector<Xyz>& v, const std::vector<Face>& f)
{
  std::string s = "solid test\n";
  for(const Face& face : f) {
    s += " facet normal 0 0 0\n  outer loop\n";
    for(std::size_t i : face) s += "   vertex " + number(v[i][0]) + " " + number(v[i][1]) + " " + number(v[i][2]) + "\n";
    s += "  endloop\n endfacet\n";
  }
  return s + "endsolid test\n";
}

inline std::string stl_binary_text(const std::vector<Xyz>& v, const std::vector<Face>& f)
{
  std::string s(80, ' ');
  s.replace(0, 20, "binary STL MDCS test");
  append_binary(s, std::uint32_t(f.size()), false);
  for(const Face& face : f) {
    for(int i = 0; i < 3; ++i) append_binary(s, 0.0f, false);
    for(std::size_t i : face)
      for(double c : v[i]) append_binary(s, float(c), false);
    append_binary(s, std::uint16_t(0), false);
  }
  return s;
}

inline std::string off_binary_text(const std::vector<Xyz>& v, const std::vector<Face>& f)
{
  std::string s = "OFF BINARY\n";
  append_binary(s, std::int32_t(v.size()), true);
  append_binary(s, std::int32_t(f.size()), true);
  append_binary(s, std::int32_t(0), true);
  for(const Xyz& p : v)
    for(double c : p) append_binary(s, float(c), true);
  for(const Face& face : f) {
    append_binary(s, std::int32_t(face.size()), true);
    for(std::size_t i : face) append_binary(s, std::int32_t(i), true);
    append_binary(s, std::int32_t(0), true);
  }
  return s;
}

// Runs `read` and checks that it throws a Read_error whose message contains `text` (and, when given, on
// `line`); returns the error's full text.
template <class Read>
std::string expect_read_error(Read read, const std::string& text, std::size_t line = std::size_t(-1))
{
  try {
    read();
  } catch(const CGAL::MDCS::IO::Read_error& e) {
    INFO("message: " << e.what());
    CHECK(std::string(e.what()).find(text) != std::string::npos);
    if(line != std::size_t(-1)) CHECK(e.line() == line);
    return e.what();
  }
  FAIL("no Read_error (expected one containing '" << text << "')");
  return std::string();
}

} // namespace io_test

#endif // MDCS_TEST_IO_TEST_HELPERS_H
