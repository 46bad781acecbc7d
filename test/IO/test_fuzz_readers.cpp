// The fuzz suite of the readers (issue 28, item 8): seeded mutations of seed files of every format (bit flips,
// inserted and deleted bytes, numbers replaced by extremes such as 1e308, -1, 2^31, NaN, or by small integers,
// truncation, header counts changed, spliced, repeated and removed lines), each file run through exactly the
// path mdcs uses:
// read_triangle_mesh() into a Surface_mesh (without and with --repair), read_dimacs_max_flow() +
// make_flow_network() + the max flow, read_points_2(). Every file must give a valid result or a Read_error:
// any other exception, a crash, a hang (a file taking seconds), a leak or a sanitizer report fails the suite
// (the sanitizers report through the ASan+UBSan build of this test: -DMDCS_SANITIZE=ON).
// Default run: 200 files per format (a few seconds under ASan); "[.long]": 1,000 per format with the same seed
// and 20,000 per format with another.
#include "io_test_helpers.h"

#include <CGAL/MDCS/IO/read_points.h>
#include <CGAL/MDCS/IO/read_triangle_mesh.h>
#include <CGAL/Min_cut/IO/read_dimacs_max_flow.h>
#include <CGAL/Min_cut/solve_min_cut.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <typeinfo>

namespace MIO = CGAL::MDCS::IO;
namespace MCIO = CGAL::Min_cut::IO;
using namespace io_test;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

enum class Kind { mesh, dimacs, points };

struct Format
{
  const char* name;
  const char* extension;
  Kind kind;
  bool binary;
  std::vector<std::string> seeds;
};

// A prism over an L: two concave hexagons and six quads (the triangulation paths), beside the octahedron.
void l_prism(std::vector<Xyz>& v, std::vector<Face>& f)
{
  const double xy[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  v.clear();
  f.clear();
  for(double z : {0.0, 1.5})
    for(const auto& q : xy) v.push_back({{q[0], q[1], z}});
  f.push_back({5, 4, 3, 2, 1, 0});
  f.push_back({6, 7, 8, 9, 10, 11});
  for(std::size_t i = 0; i < 6; ++i) f.push_back({i, (i + 1) % 6, 6 + (i + 1) % 6, 6 + i});
}

std::vector<Format> formats()
{
  const auto ov = octahedron_points();
  const auto of = octahedron_faces();
  std::vector<Xyz> lv;
  std::vector<Face> lf;
  l_prism(lv, lf);
  const std::string dimacs = "c fuzz seed\np max 6 8\nn 1 s\nn 6 t\na 1 2 3\na 1 3 2.5\na 2 3 1\na 2 4 2\na 3 5 3\n"
                             "a 4 6 2\na 5 6 3\na 6 1 9\n";
  const std::string points = "# fuzz seed\nx,y\n0,0\n1,0\n1.25,0.75\n0.5 1.5\n-0.25;0.75\n0.5,0.5\n2 2\n3,0.1\n";
  return {
    {"OFF", "off", Kind::mesh, false, {off_text(ov, of), off_text(lv, lf, "COFF")}},
    {"OFF binary", "off", Kind::mesh, true, {off_binary_text(ov, of), off_binary_text(lv, lf)}},
    {"PLY ascii", "ply", Kind::mesh, false, {ply_ascii_text(ov, of), ply_ascii_text(lv, lf)}},
    {"PLY binary little endian", "ply", Kind::mesh, true, {ply_binary_text(ov, of, false), ply_binary_text(lv, lf, false)}},
    {"PLY binary big endian", "ply", Kind::mesh, true, {ply_binary_text(ov, of, true), ply_binary_text(lv, lf, true)}},
    {"OBJ", "obj", Kind::mesh, false, {obj_text(ov, of), obj_text(lv, lf)}},
    {"STL ascii", "stl", Kind::mesh, false, {stl_ascii_text(ov, of)}},
    {"STL binary", "stl", Kind::mesh, true, {stl_binary_text(ov, of)}},
    {"DIMACS", "max", Kind::dimacs, false, {dimacs}},
    {"points", "xy", Kind::points, false, {points}},
  };
}

// The mutations. Each file gets one to three of them.
class Mutator
{
public:
  explicit Mutator(std::uint64_t seed) : random_(seed) {}

  std::string operator()(const Format& format, std::string data)
  {
    const int count = 1 + int(random_() % 8 < 5 ? 0 : random_() % 3); // mostly one mutation, up to three
    for(int i = 0; i < count && !data.empty(); ++i) mutate(format, data);
    return data;
  }

private:
  std::size_t below(std::size_t n) { return n == 0 ? 0 : std::size_t(random_() % n); }

  static const std::vector<std::string>& extreme_numbers()
  {
    static const std::vector<std::string> v = {
      "0", "-1", "1", "-0", "3", "2147483647", "2147483648", "-2147483649", "4294967295", "4294967296",
      "9223372036854775807", "9223372036854775808", "18446744073709551616", "1000000000", "1e308", "-1e308", "1e309",
      "1e-400", "4.9e-324", "nan", "-nan", "inf", "-inf", "1.5", "0x10", "3.", "1e", "+", "-", "", "00000000000000000000001"};
    return v;
  }

  // `gentle`: a small integer instead of an extreme (indices stay mostly in range: the surface changes, the
  // file stays readable, and the analysis, refusal and repair paths run).
  void replace_number(std::string& data, bool header_only, bool gentle = false)
  {
    // A random numeric token (in the first lines when header_only): replaced by an extreme.
    std::vector<std::pair<std::size_t, std::size_t>> tokens;
    std::size_t lines = 0;
    for(std::size_t i = 0; i < data.size();) {
      if(data[i] == '\n' && ++lines >= 4 && header_only) break;
      const bool start = (std::isdigit(static_cast<unsigned char>(data[i])) || data[i] == '-' || data[i] == '.') &&
                         (i == 0 || std::isspace(static_cast<unsigned char>(data[i - 1])) || data[i - 1] == ',' || data[i - 1] == '/');
      if(!start) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while(j < data.size() && !std::isspace(static_cast<unsigned char>(data[j])) && data[j] != ',' && data[j] != '/') ++j;
      tokens.emplace_back(i, j - i);
      i = j;
    }
    if(tokens.empty()) return;
    const auto t = tokens[below(tokens.size())];
    const auto& e = extreme_numbers();
    data.replace(t.first, t.second, gentle ? std::to_string(below(13)) : e[below(e.size())]);
  }

  void overwrite_binary(std::string& data, std::size_t at)
  {
    static const std::uint32_t values[] = {0u, 1u, 3u, 0x7fffffffu, 0x80000000u, 0xffffffffu, 0xfffffffeu,
                                           0x7fc00000u /* NaN */, 0x7f800000u /* inf */, 0x7e967699u /* 1e38 */, 0x00ffffffu};
    if(at >= data.size()) return;
    std::uint32_t v = values[below(sizeof values / sizeof values[0])];
    const std::size_t n = std::min<std::size_t>(below(2) ? 4 : 1 + below(2), data.size() - at);
    std::memcpy(&data[at], &v, n);
  }

  void mutate(const Format& format, std::string& data)
  {
    static const char interesting[] = " \n\t-.e0123456789#/\\,;\x00\xff";
    switch(below(12)) {
    case 0: data[below(data.size())] ^= char(1 << below(8)); break;                                  // bit flip
    case 1: data.insert(below(data.size() + 1), 1, below(2) ? char(random_()) : interesting[below(sizeof interesting - 1)]); break;
    case 2: data.erase(below(data.size()), 1 + below(8)); break;                                      // deletion
    case 3:                                                                                           // a number
      if(format.binary) overwrite_binary(data, below(data.size()));
      else replace_number(data, false);
      break;
    case 4: data.resize(below(data.size())); break;                                                   // truncation
    case 5:                                                                                           // a header count
      if(!format.binary) {
        replace_number(data, true);
      } else if(std::string(format.extension) == "stl") {
        overwrite_binary(data, 80);
      } else if(std::string(format.extension) == "off") {
        overwrite_binary(data, 11 + 4 * below(3));
      } else { // PLY: the count of an element line
        const std::size_t element = data.find("element ", below(data.find("end_header") + 1));
        if(element != std::string::npos) {
          const std::size_t space = data.find(' ', element + 8), eol = data.find('\n', element);
          if(space != std::string::npos && eol != std::string::npos && space < eol)
            data.replace(space + 1, eol - space - 1, extreme_numbers()[below(extreme_numbers().size())]);
        }
      }
      break;
    case 6: { // a line repeated or removed
      const std::size_t a = data.rfind('\n', below(data.size()));
      const std::size_t start = a == std::string::npos ? 0 : a + 1, end = data.find('\n', start);
      const std::string line = data.substr(start, end == std::string::npos ? std::string::npos : end - start + 1);
      if(below(2)) data.insert(start, line);
      else data.erase(start, line.size());
      break;
    }
    case 7: { // a chunk copied elsewhere
      const std::size_t from = below(data.size()), length = 1 + below(std::min<std::size_t>(64, data.size() - from));
      data.insert(below(data.size() + 1), data.substr(from, length));
      break;
    }
    case 8: // bytes overwritten at random (text formats too)
      overwrite_binary(data, below(data.size()));
      break;
    default: // a number changed a little (text), or a byte (binary)
      if(format.binary) data[below(data.size())] = char(below(13));
      else replace_number(data, false, true);
      break;
    }
  }

  std::mt19937_64 random_;
};

struct Outcome
{
  std::size_t accepted = 0, refused = 0, other_exceptions = 0;
  double slowest = 0;
  std::string slowest_file;
};

// The reading path of mdcs for one file; throws only what the file may cause (Read_error) or a bug.
bool run_path(const Format& format, const std::string& path)
{
  if(format.kind == Kind::mesh) {
    bool any = false;
    for(bool repair : {false, true}) {
      Mesh m;
      MIO::Triangle_mesh_reading_options options;
      options.repair = repair;
      try {
        MIO::read_triangle_mesh(path, m, options);
      } catch(const MIO::Read_error&) {
        continue;
      }
      any = true;
      REQUIRE(m.number_of_faces() > 0);
      REQUIRE(m.is_valid(false));
      REQUIRE(CGAL::is_triangle_mesh(m));
    }
    if(!any) throw MIO::Read_error(path, 0, "", "refused");
    return true;
  }
  if(format.kind == Kind::dimacs) {
    const MCIO::Dimacs_max_flow_problem problem = MCIO::read_dimacs_max_flow(path);
    const MCIO::Dimacs_flow_network<double> flow = MCIO::make_flow_network<double>(problem, path);
    const double value = CGAL::Min_cut::solve_min_cut(flow.network, CGAL::Min_cut::Pseudoflow_max_flow()).value + flow.source_to_sink;
    REQUIRE(std::isfinite(value));
    REQUIRE(value >= 0);
    return true;
  }
  std::vector<K::Point_2> p;
  MIO::read_points_2(path, p);
  for(const K::Point_2& q : p) REQUIRE((std::isfinite(q.x()) && std::isfinite(q.y())));
  return true;
}

void fuzz(std::size_t files_per_format, std::uint64_t seed)
{
  Scratch dir(true);
  for(const Format& format : formats()) {
    Mutator mutate(seed ^ std::hash<std::string>()(format.name));
    Outcome outcome;
    const std::string path = dir.path(std::string("fuzz.") + format.extension);
    for(std::size_t i = 0; i < files_per_format; ++i) {
      const std::string data = mutate(format, format.seeds[i % format.seeds.size()]);
      dir.write(std::string("fuzz.") + format.extension, data);
      const auto t0 = std::chrono::steady_clock::now();
      try {
        run_path(format, path);
        ++outcome.accepted;
      } catch(const MIO::Read_error&) {
        ++outcome.refused;
      } catch(const std::exception& e) {
        ++outcome.other_exceptions;
        // Keep the file for the report: the fuzz suite must only ever see Read_error.
        const std::string kept = (std::filesystem::temp_directory_path() /
                                  ("mdcs-fuzz-failure-" + std::to_string(i) + "." + format.extension)).string();
        std::ofstream(kept, std::ios::binary) << data;
        FAIL_CHECK(format.name << " file " << i << " (seed " << seed << ", kept as " << kept << "): " << typeid(e).name()
                               << ": " << e.what());
      }
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if(seconds > outcome.slowest) outcome.slowest = seconds;
    }
    std::cout << "fuzz " << format.name << ": " << files_per_format << " files, " << outcome.accepted << " accepted, "
              << outcome.refused << " refused (Read_error), " << outcome.other_exceptions << " other exceptions, slowest "
              << outcome.slowest << " s\n";
    INFO(format.name << ": " << outcome.accepted << " accepted, " << outcome.refused << " refused, slowest file "
                     << outcome.slowest << " s");
    CHECK(outcome.other_exceptions == 0);
    CHECK(outcome.accepted + outcome.refused == files_per_format);
    // Both outcomes occur: the mutations reach past the first check, and they break files.
    CHECK(outcome.accepted > 0);
    CHECK(outcome.refused > 0);
    // No file takes long (tiny inputs: a slow one means work beyond the file's size). Generous for ASan.
    CHECK(outcome.slowest < 5.0);
  }
}

} // namespace

// The default run stays short (CI runs the suite under ASan+UBSan as well): 200 files per format. The [.long]
// cases give the figures of issue 28: 1,000 files per format with the same seed, and 20,000 with another one.
TEST_CASE("fuzz: 200 mutated files per format through the reading path of mdcs", "[io][fuzz]")
{
  fuzz(200, 28);
}

TEST_CASE("fuzz: 1000 mutated files per format (long)", "[io][fuzz][.long]")
{
  fuzz(1000, 28);
}

TEST_CASE("fuzz: 20000 mutated files per format (long)", "[io][fuzz][.long]")
{
  fuzz(20000, 20261201);
}
