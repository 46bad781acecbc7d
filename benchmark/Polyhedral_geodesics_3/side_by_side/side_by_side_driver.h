// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the drivers of the side-by-side benchmark (run_side_by_side.py) share: the binary mesh file that the MDCS
// benchmark writes once per mesh and every driver reads, the command line, the peak memory of the timed section,
// and the one result line the script parses. The drivers for third-party libraries (VTP, Kirsanov's geodesic
// library) are built by the script outside the repository, against sources the user placed in a folder of their
// own; this header and the drivers themselves are MDCS code and include nothing of those libraries.
//
// Mesh file: 8 bytes "MDCSMSH1", uint64 vertices, uint64 faces, 3 doubles per vertex, 3 uint32 per face
// (counter-clockwise, 0-based).
//
// Result line (stdout): "RESULT key=value key=value ..." with at least
//   time_s        wall seconds of the timed section: the library's own mesh structure built from the arrays, the
//                 propagation from the source, all vertex distances read out, and (full field) the paths
//   cpu_s         the process's CPU seconds in that section (all threads)
//   peak_mib      the process's peak resident set during the timed section minus its resident set before it
//   vertices, faces, source, mode
// and optional counters (windows, paths_length_sum, ...).

#ifndef MDCS_SIDE_BY_SIDE_DRIVER_H
#define MDCS_SIDE_BY_SIDE_DRIVER_H

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <time.h>

namespace side_by_side {

struct Mesh_arrays
{
  std::vector<double> points;   // 3 per vertex
  std::vector<unsigned> faces;  // 3 per face
  std::size_t vertices() const { return points.size() / 3; }
  std::size_t number_of_faces() const { return faces.size() / 3; }
};

inline void read_mesh_file(const std::string& file, Mesh_arrays& m)
{
  std::ifstream in(file, std::ios::binary);
  if(!in)
    throw std::runtime_error("cannot open the mesh file " + file);
  char magic[8];
  std::uint64_t counts[2];
  in.read(magic, 8);
  in.read(reinterpret_cast<char*>(counts), sizeof counts);
  if(!in || std::memcmp(magic, "MDCSMSH1", 8) != 0)
    throw std::runtime_error(file + " is not a mesh file of the side-by-side benchmark");
  if(counts[0] > (std::uint64_t(1) << 31) || counts[1] > (std::uint64_t(1) << 31))
    throw std::runtime_error(file + ": implausible vertex or face count");
  m.points.resize(std::size_t(3 * counts[0]));
  std::vector<std::uint32_t> f(std::size_t(3 * counts[1]));
  in.read(reinterpret_cast<char*>(m.points.data()), std::streamsize(m.points.size() * sizeof(double)));
  in.read(reinterpret_cast<char*>(f.data()), std::streamsize(f.size() * sizeof(std::uint32_t)));
  if(!in)
    throw std::runtime_error(file + " is truncated");
  m.faces.assign(f.begin(), f.end());
  for(unsigned i : m.faces)
    if(i >= counts[0])
      throw std::runtime_error(file + ": a face refers to a vertex that does not exist");
}

inline void write_mesh_file(const std::string& file, const std::vector<double>& points,
                            const std::vector<std::uint32_t>& faces)
{
  std::ofstream out(file, std::ios::binary);
  const std::uint64_t counts[2] = {points.size() / 3, faces.size() / 3};
  out.write("MDCSMSH1", 8);
  out.write(reinterpret_cast<const char*>(counts), sizeof counts);
  out.write(reinterpret_cast<const char*>(points.data()), std::streamsize(points.size() * sizeof(double)));
  out.write(reinterpret_cast<const char*>(faces.data()), std::streamsize(faces.size() * sizeof(std::uint32_t)));
  if(!out)
    throw std::runtime_error("cannot write " + file);
}

inline void write_distances(const std::string& file, const std::vector<double>& d)
{
  if(file.empty())
    return;
  std::ofstream out(file, std::ios::binary);
  out.write(reinterpret_cast<const char*>(d.data()), std::streamsize(d.size() * sizeof(double)));
  if(!out)
    throw std::runtime_error("cannot write " + file);
}

inline double status_mib(const char* field)
{
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::size_t n = std::strlen(field);
  while(std::getline(in, line))
    if(line.compare(0, n, field) == 0)
      return std::atof(line.c_str() + n) / 1024.0;
  return 0.0;
}

inline double process_cpu_seconds()
{
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// The timed section: wall clock, the process's CPU time (all threads), and the peak resident set above the
// resident set at its start (the kernel's high-water mark is reset first, so what the input loading allocated and
// freed does not count).
class Timed_section
{
public:
  void start()
  {
    std::ofstream("/proc/self/clear_refs") << "5";
    base_mib_ = status_mib("VmRSS:");
    cpu0_ = process_cpu_seconds();
    t0_ = std::chrono::steady_clock::now();
  }
  void stop()
  {
    seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    cpu_seconds_ = process_cpu_seconds() - cpu0_;
    peak_mib_ = status_mib("VmHWM:") - base_mib_;
  }
  double seconds() const { return seconds_; }
  double cpu_seconds() const { return cpu_seconds_; }
  double peak_mib() const { return peak_mib_; }
  double base_mib() const { return base_mib_; }

private:
  std::chrono::steady_clock::time_point t0_;
  double seconds_ = 0, cpu_seconds_ = 0, cpu0_ = 0, peak_mib_ = 0, base_mib_ = 0;
};

struct Options
{
  std::string mesh, distances_out, mode = "distances_only";
  std::size_t source = 0, paths = 0, threads = 1;

  static Options parse(int argc, char** argv)
  {
    Options o;
    for(int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      const bool value = i + 1 < argc;
      if(a == "--mesh" && value) o.mesh = argv[++i];
      else if(a == "--source" && value) o.source = std::strtoul(argv[++i], nullptr, 10);
      else if(a == "--mode" && value) o.mode = argv[++i];
      else if(a == "--paths" && value) o.paths = std::strtoul(argv[++i], nullptr, 10);
      else if(a == "--threads" && value) o.threads = std::strtoul(argv[++i], nullptr, 10);
      else if(a == "--distances-out" && value) o.distances_out = argv[++i];
      else {
        std::cerr << "usage: " << argv[0]
                  << " --mesh FILE [--source I] [--mode distances_only|full_field] [--paths K] [--threads N]"
                     " [--distances-out FILE]\n";
        std::exit(2);
      }
    }
    if(o.mesh.empty()) {
      std::cerr << argv[0] << ": --mesh is required\n";
      std::exit(2);
    }
    return o;
  }
};

// The path targets: K vertices spread over the vertex list (the same for every driver).
inline std::vector<std::size_t> path_targets(std::size_t vertices, std::size_t k)
{
  std::vector<std::size_t> t;
  for(std::size_t i = 0; i < k; ++i)
    t.push_back((2 * i + 1) * vertices / (2 * k));
  return t;
}

class Result_line
{
public:
  Result_line() { out_.precision(12); }
  template <class T>
  Result_line& add(const std::string& key, const T& value)
  {
    out_ << ' ' << key << '=' << value;
    return *this;
  }
  void print() const { std::cout << "RESULT" << out_.str() << std::endl; }

private:
  std::ostringstream out_;
};

} // namespace side_by_side

#endif // MDCS_SIDE_BY_SIDE_DRIVER_H
