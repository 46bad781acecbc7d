// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Driver of the side-by-side benchmark for Danil Kirsanov's 2005 implementation of the exact MMP algorithm
// (Surazhsky et al. 2005; the "geodesic" library, as found for example inside the pygeodesic and gdist Python
// wrappers). run_side_by_side.py compiles it outside the repository with that library's folder on the include
// path; its sources never enter the repository. The library always keeps the whole field (every interval), so
// both modes run the same propagation; full_field also traces `--paths` shortest paths (trace_back).
//
// Timed: the library's mesh structure built from the arrays, the algorithm object, propagate({source}), every
// vertex distance read (best_source), and in full_field mode the paths.

#include "side_by_side_driver.h"

#include "geodesic_algorithm_exact.h"
#include "geodesic_mesh.h"

#include <cmath>

int main(int argc, char** argv)
{
  const side_by_side::Options o = side_by_side::Options::parse(argc, argv);
  if(o.threads != 1) {
    std::cerr << "kirsanov_driver: single thread only\n";
    return 2;
  }
  side_by_side::Mesh_arrays arrays;
  side_by_side::read_mesh_file(o.mesh, arrays);
  if(o.source >= arrays.vertices()) {
    std::cerr << "kirsanov_driver: source out of range\n";
    return 2;
  }
  std::vector<double> distances(arrays.vertices());
  double path_length_sum = 0;
  std::size_t path_points = 0;

  side_by_side::Timed_section timed;
  timed.start();
  {
    geodesic::Mesh mesh;
    mesh.initialize_mesh_data(arrays.points, arrays.faces);
    geodesic::GeodesicAlgorithmExact algorithm(&mesh);
    std::vector<geodesic::SurfacePoint> sources(1, geodesic::SurfacePoint(&mesh.vertices()[o.source]));
    algorithm.propagate(sources);
    for(std::size_t i = 0; i < distances.size(); ++i) {
      geodesic::SurfacePoint p(&mesh.vertices()[i]);
      double d = 0;
      algorithm.best_source(p, d);
      distances[i] = d;
    }
    if(o.mode == "full_field") {
      std::vector<geodesic::SurfacePoint> path;
      for(std::size_t t : side_by_side::path_targets(arrays.vertices(), o.paths)) {
        geodesic::SurfacePoint target(&mesh.vertices()[t]);
        algorithm.trace_back(target, path);
        path_points += path.size();
        for(std::size_t k = 1; k < path.size(); ++k)
          path_length_sum += path[k].distance(&path[k - 1]);
      }
    }
    timed.stop();
  }
  side_by_side::write_distances(o.distances_out, distances);
  side_by_side::Result_line()
    .add("library", "Kirsanov")
    .add("mode", o.mode)
    .add("vertices", arrays.vertices())
    .add("faces", arrays.number_of_faces())
    .add("source", o.source)
    .add("time_s", timed.seconds())
    .add("cpu_s", timed.cpu_seconds())
    .add("peak_mib", timed.peak_mib())
    .add("paths", o.mode == "full_field" ? o.paths : 0)
    .add("path_points", path_points)
    .add("path_length_sum", path_length_sum)
    .print();
  return 0;
}
