// The meshes of the silhouette benchmarks: a file read as is, simplified to a face count by this package's
// half-edge collapses, or refined by Loop subdivisions.
#ifndef MDCS_SILHOUETTE_BENCH_MESHES_H
#define MDCS_SILHOUETTE_BENCH_MESHES_H

#include <CGAL/Silhouette_simplification_3/Coarse_mesh_3.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace mdcs_bench {

// One mesh of a silhouette benchmark.
struct Silhouette_bench_case
{
  std::string name, path;
  std::size_t fine_faces = 0; // 0: as read
  unsigned subdivisions = 0;
  std::size_t coarse_faces = 1000; // for the benchmarks that build a coarse mesh
};

// The three load averages of /proc/loadavg, to be reported with timings taken on a shared machine.
inline std::string load_average()
{
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

// Reads `path` into `mesh`; with `faces` > 0 simplifies it to that many faces (no smoothing), then applies
// `subdivisions` Loop subdivisions. Returns false (with a message) when the file gives no face.
template <class Mesh>
bool read_silhouette_bench_mesh(const std::string& path, std::size_t faces, unsigned subdivisions, Mesh& mesh)
{
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || num_faces(mesh) == 0) {
    std::fprintf(stderr, "cannot read %s, skipped\n", path.c_str());
    return false;
  }
  if(faces > 0 && num_faces(mesh) > faces) {
    CGAL::Silhouette_simplification_3::Coarse_mesh_options o;
    o.target_faces = faces;
    o.smoothing_iterations = 0;
    mesh = CGAL::Silhouette_simplification_3::build_coarse_mesh(mesh, o).mesh;
  }
  for(unsigned s = 0; s < subdivisions; ++s) CGAL::Subdivision_method_3::Loop_subdivision(mesh);
  return true;
}

} // namespace mdcs_bench

#endif // MDCS_SILHOUETTE_BENCH_MESHES_H
