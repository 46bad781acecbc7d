// The MDCS side of the side-by-side benchmark of exact geodesics (benchmark/Polyhedral_geodesics_3/side_by_side/
// run_side_by_side.py runs it interleaved with drivers for VTP and Kirsanov's library, which the script builds
// outside the repository):
//
//   bench_geodesics_side_by_side prepare --name NAME --out FILE [--mesh-dir DIR] [--extra-dir DIR]
//       writes the mesh NAME as the benchmark's binary mesh file. NAME is a mesh of the CGAL demo folder
//       (MDCS_CGAL_MESH_DIR or --mesh-dir) or of --extra-dir, by its file stem, optionally followed by -loopK
//       (K steps of Loop subdivision), e.g. armadillo-loop2. Faces are triangulated and isolated vertices removed.
//   bench_geodesics_side_by_side run --mesh FILE [--source I] [--mode distances_only|full_field|full_field_windows]
//       [--paths K] [--threads N] [--distances-out FILE]
//       Exact_geodesic_distances_3 on that mesh, timed like the other drivers (see side_by_side_driver.h): the
//       class's construction (the compact mesh), the propagation, every vertex distance read, and in the full_field
//       modes K shortest paths (to the vertices (2i+1)n/2K). Prints one RESULT line with the engine's counters.
#include <geodesic_bench_common.h>

#include "side_by_side/side_by_side_driver.h"

#include <CGAL/MDCS/concurrency.h>
#include <CGAL/Polyhedral_geodesics_3/Exact_geodesic_distances_3.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace PG = CGAL::Polyhedral_geodesics_3;
using namespace geodesic_bench;

namespace {

int usage()
{
  std::cerr << "usage: bench_geodesics_side_by_side prepare --name NAME[-loopK] --out FILE [--mesh-dir DIR] [--extra-dir DIR]\n"
               "       bench_geodesics_side_by_side run --mesh FILE [--source I] [--mode distances_only|full_field|full_field_windows]"
               " [--paths K] [--threads N] [--distances-out FILE]\n";
  return 2;
}

int prepare(int argc, char** argv)
{
  std::string name, out, mesh_dir = MDCS_CGAL_MESH_DIR, extra_dir;
  for(int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    const bool value = i + 1 < argc;
    if(a == "--name" && value) name = argv[++i];
    else if(a == "--out" && value) out = argv[++i];
    else if(a == "--mesh-dir" && value) mesh_dir = argv[++i];
    else if(a == "--extra-dir" && value) extra_dir = argv[++i];
    else return usage();
  }
  if(name.empty() || out.empty())
    return usage();
  Mesh_spec spec;
  spec.name = name;
  std::string stem = name;
  const std::size_t loop = name.rfind("-loop");
  if(loop != std::string::npos && loop + 5 < name.size()) {
    spec.loop_steps = std::atoi(name.c_str() + loop + 5);
    stem = name.substr(0, loop);
  }
  for(const std::string& dir : {mesh_dir, extra_dir}) {
    if(dir.empty())
      continue;
    for(const char* ext : {".off", ".obj", ".ply"}) {
      const std::filesystem::path p = std::filesystem::path(dir) / (stem + ext);
      if(spec.file.empty() && std::filesystem::exists(p))
        spec.file = p.string();
    }
  }
  if(spec.file.empty()) {
    std::cerr << "prepare: no mesh file " << stem << ".off/.obj/.ply in " << mesh_dir
              << (extra_dir.empty() ? "" : " or " + extra_dir) << "\n";
    return 3;
  }
  Mesh mesh;
  std::string message;
  if(!load_mesh(spec, mesh, message)) {
    std::cerr << "prepare: " << message << "\n";
    return 3;
  }
  std::vector<double> points;
  std::vector<std::uint32_t> faces;
  points.reserve(3 * mesh.number_of_vertices());
  for(Vertex v : vertices(mesh)) {
    const auto& p = mesh.point(v);
    points.insert(points.end(), {p.x(), p.y(), p.z()});
  }
  for(auto f : mesh.faces())
    for(Vertex v : vertices_around_face(mesh.halfedge(f), mesh))
      faces.push_back(std::uint32_t(v));
  side_by_side::write_mesh_file(out, points, faces);
  std::cout << "RESULT name=" << name << " vertices=" << mesh.number_of_vertices() << " faces=" << mesh.number_of_faces()
            << " notes=" << (message.empty() ? "-" : "\"" + message + "\"") << std::endl;
  return 0;
}

int run(int argc, char** argv)
{
  // Options::parse reads argv[1..]: skip the sub-command.
  std::vector<char*> args(argv, argv + argc);
  args.erase(args.begin() + 1);
  const side_by_side::Options o = side_by_side::Options::parse(int(args.size()), args.data());
  // full_field: the vertex-oriented schedule's records (set_vertex_oriented_full_field); full_field_windows: the
  // window propagation's full field (the class's default until the records are its default)
  const bool windows = o.mode == "full_field_windows";
  const bool full = o.mode == "full_field" || windows;
  if(!full && o.mode != "distances_only")
    return usage();
  side_by_side::Mesh_arrays arrays;
  side_by_side::read_mesh_file(o.mesh, arrays);
  Mesh mesh;
  mesh.reserve(Mesh::size_type(arrays.vertices()), Mesh::size_type(3 * arrays.number_of_faces() / 2),
               Mesh::size_type(arrays.number_of_faces()));
  for(std::size_t i = 0; i < arrays.vertices(); ++i)
    mesh.add_vertex(K::Point_3(arrays.points[3 * i], arrays.points[3 * i + 1], arrays.points[3 * i + 2]));
  for(std::size_t f = 0; f < arrays.number_of_faces(); ++f)
    if(mesh.add_face(Vertex(arrays.faces[3 * f]), Vertex(arrays.faces[3 * f + 1]), Vertex(arrays.faces[3 * f + 2])) ==
       Mesh::null_face()) {
      std::cerr << "run: face " << f << " cannot be added to a Surface_mesh (non-manifold input)\n";
      return 3;
    }
  arrays = side_by_side::Mesh_arrays();
  if(o.source >= mesh.number_of_vertices()) {
    std::cerr << "run: source out of range\n";
    return 2;
  }
  std::vector<double> distances(mesh.number_of_vertices());
  double path_length_sum = 0;
  std::size_t path_points = 0;
  PG::Geodesic_statistics stats;
  bool vertex_oriented = false;

  side_by_side::Timed_section timed;
  timed.start();
  {
    PG::Exact_geodesic_distances_3<Mesh> geodesics(
      mesh, full ? PG::Geodesic_memory_mode::full_field : PG::Geodesic_memory_mode::distances_only);
    geodesics.set_vertex_oriented_full_field(!windows);
    geodesics.add_source(Vertex(Mesh::size_type(o.source)));
    geodesics.compute();
    geodesics.distances(Distance_vector_map{&distances});
    if(full) {
      std::vector<K::Point_3> path;
      for(std::size_t t : side_by_side::path_targets(mesh.number_of_vertices(), o.paths)) {
        path.clear();
        geodesics.shortest_path_points(Vertex(Mesh::size_type(t)), std::back_inserter(path));
        path_points += path.size();
        for(std::size_t k = 1; k < path.size(); ++k)
          path_length_sum += std::sqrt(CGAL::squared_distance(path[k - 1], path[k]));
      }
    }
    timed.stop();
    stats = geodesics.statistics();
    vertex_oriented = geodesics.used_vertex_oriented_propagation();
  }
  side_by_side::write_distances(o.distances_out, distances);
  side_by_side::Result_line()
    .add("library", "MDCS")
    .add("mode", o.mode)
    .add("vertices", mesh.number_of_vertices())
    .add("faces", mesh.number_of_faces())
    .add("source", o.source)
    .add("threads", o.threads)
    .add("time_s", timed.seconds())
    .add("cpu_s", timed.cpu_seconds())
    .add("peak_mib", timed.peak_mib())
    .add("paths", full ? o.paths : 0)
    .add("path_points", path_points)
    .add("path_length_sum", path_length_sum)
    .add("vertex_oriented", vertex_oriented ? 1 : 0)
    .add("windows_created", stats.windows_created)
    .add("windows_propagated", stats.windows_propagated)
    .add("windows_pruned", stats.windows_pruned)
    .add("peak_live_windows", stats.peak_live_windows)
    .add("stored_windows", stats.stored_windows)
    .add("vertex_updates", stats.vertex_updates)
    .print();
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
    return usage();
  const std::string command = argv[1];
  try {
    if(command == "prepare")
      return prepare(argc, argv);
    if(command == "run")
      return run(argc, argv);
  } catch(const std::exception& e) {
    std::cerr << "bench_geodesics_side_by_side: " << e.what() << "\n";
    return 1;
  }
  return usage();
}
