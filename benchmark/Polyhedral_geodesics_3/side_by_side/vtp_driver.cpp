// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Driver of the side-by-side benchmark for VTP (Qin et al., "Fast and exact discrete geodesic computation based on
// triangle-oriented wavefront propagation", SIGGRAPH 2016; the authors' code, github.com/YipengQin/VTP_source_code).
// run_side_by_side.py compiles it outside the repository with VTP's folder on the include path; VTP's sources
// never enter the repository. VTP computes the distances from one source vertex to every vertex (no paths, no
// point queries), so only the distances_only mode exists.
//
// Timed: VTP's mesh structure built from the arrays, the algorithm object, propagate(source), all distances read.

#include "side_by_side_driver.h"

// VTP's headers were written for MSVC (C++14 at the latest: std::auto_ptr, which they get through <memory>
// included elsewhere; the unused OBJ reader calls sscanf_s).
#include <cstdio>
#include <memory>
#define sscanf_s sscanf
#include "geodesic_algorithm_exact.h"
#include "geodesic_mesh.h"

int main(int argc, char** argv)
{
  const side_by_side::Options o = side_by_side::Options::parse(argc, argv);
  if(o.mode != "distances_only" || o.paths != 0 || o.threads != 1) {
    std::cerr << "vtp_driver: VTP computes vertex distances from one thread only (no full field, no paths)\n";
    return 2;
  }
  side_by_side::Mesh_arrays arrays;
  side_by_side::read_mesh_file(o.mesh, arrays);
  if(o.source >= arrays.vertices()) {
    std::cerr << "vtp_driver: source out of range\n";
    return 2;
  }
  std::vector<double> distances(arrays.vertices());
  std::string propagated = "-", peak = "-";

  side_by_side::Timed_section timed;
  timed.start();
  {
    geodesic::Mesh mesh;
    mesh.initialize_mesh_data(arrays.points, arrays.faces);
    geodesic::GeodesicAlgorithmExact algorithm(&mesh);
    algorithm.propagate(unsigned(o.source));
    for(std::size_t i = 0; i < distances.size(); ++i)
      distances[i] = mesh.vertices()[i].geodesic_distance();
    timed.stop();
    // VTP's counters, from its statistics printout: child windows computed (its "interval propagation number",
    // comparable with MDCS's windows_created) and the peak
    // number of windows on the wavefront.
    std::ostringstream text;
    std::streambuf* old = std::cout.rdbuf(text.rdbuf());
    algorithm.print_statistics();
    std::cout.rdbuf(old);
    std::istringstream lines(text.str());
    for(std::string line; std::getline(lines, line);) {
      const std::string last = line.substr(line.find_last_of(' ') + 1);
      if(line.find("total interval propagation number") != std::string::npos) propagated = last;
      if(line.find("Peak number of intervals") != std::string::npos) peak = last;
    }
  }
  side_by_side::write_distances(o.distances_out, distances);
  side_by_side::Result_line()
    .add("library", "VTP")
    .add("mode", o.mode)
    .add("vertices", arrays.vertices())
    .add("faces", arrays.number_of_faces())
    .add("source", o.source)
    .add("time_s", timed.seconds())
    .add("cpu_s", timed.cpu_seconds())
    .add("peak_mib", timed.peak_mib())
    .add("windows_created", propagated)
    .add("peak_live_windows", peak)
    .print();
  return 0;
}
