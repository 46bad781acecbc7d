// The cost of preparing a geodesic surface (Geodesic_surface_3: the compact mesh every geodesic class runs on)
// against the propagations it serves, in one run, interleaved: for each round and each mesh, four fresh processes
// (forked, so every array is new memory, as in a command-line run or a first call):
//   - build: the surface of the Surface_mesh (the FaceGraph path, descriptors kept);
//   - soup:  the surface of the same mesh as a triangle soup (arrays of points and index triples);
//   - exact: Exact_geodesic_distances_3 in distances_only mode, from one source (the surface built first, not timed);
//   - flat:  Flat_exact_geodesic_distances_3, from the same source (idem).
// Reported: medians over the rounds of the wall time and of the CPU time (user + system: the one-core cost
// without the time spent waiting for a core on a shared machine), the peak resident memory of each child above
// what it shares with the parent, the surface's own bytes, and the ratios build / flat and build / exact.
// The load average is printed (and written to the CSV) before and after.
//
// Usage: bench_geodesic_surface [--meshes a,b] [--runs N] [--csv FILE] [--mesh-dir DIR] [--extra-dir DIR] [--list]
// Default meshes: armadillo (26k vertices) and the Loop subdivisions refined_elephant-loop1 (178k) and
// bunny00-loop2 (603k) of CGAL's demo meshes.
#include <geodesic_bench_common.h>

#include <CGAL/Polyhedral_geodesics_3.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_surface_3.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace geodesic_bench;
namespace PG = CGAL::Polyhedral_geodesics_3;

struct Header
{
  std::int32_t ok = 0;
  double peak_mib = 0;
  std::uint64_t number_of_distances = 0;
  char error[512] = {0};
  double wall = 0, cpu = 0;
  double surface_mib = 0;
};

std::string load_average()
{
  std::ifstream in("/proc/loadavg");
  double a = 0, b = 0, c = 0;
  in >> a >> b >> c;
  return fmt(a, "%.2f") + " " + fmt(b, "%.2f") + " " + fmt(c, "%.2f");
}

void usage()
{
  std::cerr << "usage: bench_geodesic_surface [--meshes a,b] [--runs N] [--csv FILE] [--mesh-dir DIR] "
               "[--extra-dir DIR] [--timeout S] [--mem-limit-mib M] [--list]\n";
}

enum Task { BUILD, SOUP, EXACT, FLAT };

} // namespace

int main(int argc, char** argv)
{
  Common_options o;
  o.runs = 5;
  for(int i = 1; i < argc; ++i)
    if(!o.parse(argc, argv, i)) {
      usage();
      return 2;
    }
  const std::vector<Mesh_spec> builtin = {
    {"armadillo", o.in_mesh_dir("armadillo.off"), 0},
    {"refined_elephant", o.in_mesh_dir("refined_elephant.off"), 0},
    {"armadillo-loop1", o.in_mesh_dir("armadillo.off"), 1},
    {"bunny00-loop1", o.in_mesh_dir("bunny00.off"), 1},
    {"refined_elephant-loop1", o.in_mesh_dir("refined_elephant.off"), 1},
    {"bunny00-loop2", o.in_mesh_dir("bunny00.off"), 2}};
  if(o.selected.empty())
    o.selected = {"armadillo", "refined_elephant-loop1", "bunny00-loop2"};
  std::vector<Mesh_spec> specs;
  if(const int exit_code = select_or_list_meshes(builtin, o, specs, usage); exit_code >= 0)
    return exit_code;

  struct Loaded
  {
    Mesh_spec spec;
    Mesh mesh;
    std::vector<std::array<double, 3>> points;
    std::vector<std::array<std::int32_t, 3>> triangles;
    Vertex source;
    std::vector<double> times[4], cpus[4], peaks[4];
    double surface_mib = 0;
  };
  std::vector<Loaded> meshes;
  meshes.reserve(specs.size());
  for(const Mesh_spec& spec : specs) {
    meshes.emplace_back();
    Loaded& l = meshes.back();
    l.spec = spec;
    std::string message;
    if(!load_mesh(spec, l.mesh, message)) {
      std::cerr << spec.name << ": " << message << "\n";
      meshes.pop_back();
      continue;
    }
    for(auto v : vertices(l.mesh)) {
      const auto& p = l.mesh.point(v);
      l.points.push_back({p.x(), p.y(), p.z()});
    }
    for(auto f : faces(l.mesh)) {
      auto h = halfedge(f, l.mesh);
      l.triangles.push_back({std::int32_t(source(h, l.mesh)), std::int32_t(target(h, l.mesh)),
                             std::int32_t(target(next(h, l.mesh), l.mesh))});
    }
    l.source = Vertex(static_cast<Mesh::size_type>(num_vertices(l.mesh) / 3));
    std::cout << spec.name << ": " << num_vertices(l.mesh) << " vertices, " << num_faces(l.mesh) << " faces"
              << (message.empty() ? "" : " (" + message + ")") << "\n";
  }
  const std::string load_before = load_average();
  std::cout << "load average before: " << load_before << "\n";
  const double allowance = o.memory_allowance_mib();

  auto run = [&](Loaded& l, Task task) -> Forked_result<Header> {
    return run_forked<Header>([&](Header& h, std::vector<double>&) {
      const double w0 = mdcs_bench::now_seconds(), c0 = mdcs_bench::cpu_seconds();
      switch(task) {
      case BUILD: {
        PG::Geodesic_surface_3<Mesh> s(l.mesh);
        h.wall = mdcs_bench::now_seconds() - w0;
        h.cpu = mdcs_bench::cpu_seconds() - c0;
        h.surface_mib = double(s.memory_bytes()) / 1048576.0;
        break;
      }
      case SOUP: {
        PG::Geodesic_surface_3<PG::Triangle_soup> s(l.points, l.triangles);
        h.wall = mdcs_bench::now_seconds() - w0;
        h.cpu = mdcs_bench::cpu_seconds() - c0;
        h.surface_mib = double(s.memory_bytes()) / 1048576.0;
        break;
      }
      case EXACT:
      case FLAT: {
        const auto s = std::make_shared<const PG::Geodesic_surface_3<Mesh>>(l.mesh);
        double w1, c1;
        if(task == EXACT) {
          PG::Exact_geodesic_distances_3<Mesh> g(s, PG::Geodesic_memory_mode::distances_only);
          g.add_source(l.source);
          w1 = mdcs_bench::now_seconds();
          c1 = mdcs_bench::cpu_seconds();
          g.compute();
        } else {
          PG::Flat_exact_geodesic_distances_3<Mesh> g(s, PG::Geodesic_memory_mode::distances_only);
          g.add_source(l.source);
          w1 = mdcs_bench::now_seconds();
          c1 = mdcs_bench::cpu_seconds();
          g.compute();
        }
        h.wall = mdcs_bench::now_seconds() - w1;
        h.cpu = mdcs_bench::cpu_seconds() - c1;
        break;
      }
      }
    }, o.timeout_s, allowance);
  };

  const char* names[4] = {"build", "soup", "exact", "flat"};
  for(int round = 0; round < o.runs; ++round)
    for(Loaded& l : meshes)
      for(int t = 0; t < 4; ++t) {
        const Forked_result<Header> r = run(l, Task(t));
        if(!r.ok) {
          std::cerr << l.spec.name << " " << names[t] << ": " << r.failure << "\n";
          continue;
        }
        l.times[t].push_back(r.header.wall);
        l.cpus[t].push_back(r.header.cpu);
        l.peaks[t].push_back(r.header.peak_mib);
        if(t == BUILD)
          l.surface_mib = r.header.surface_mib;
      }
  const std::string load_after = load_average();
  std::cout << "load average after: " << load_after << "\n\n";

  mdcs_bench::Table table({"mesh", "vertices", "faces", "build_s", "build_cpu_s", "soup_s", "soup_cpu_s", "exact_s",
                           "exact_cpu_s", "flat_s", "flat_cpu_s", "build/flat", "build/exact", "build_cpu/flat_cpu",
                           "build_peak_mib", "soup_peak_mib", "surface_mib", "runs", "load_before", "load_after"});
  auto med = [](const std::vector<double>& v) { return v.empty() ? nan_ : mdcs_bench::median(v); };
  for(const Loaded& l : meshes) {
    const double b = med(l.times[BUILD]), bc = med(l.cpus[BUILD]), s = med(l.times[SOUP]), sc = med(l.cpus[SOUP]);
    const double e = med(l.times[EXACT]), ec = med(l.cpus[EXACT]), f = med(l.times[FLAT]), fc = med(l.cpus[FLAT]);
    table.add_row({l.spec.name, std::to_string(num_vertices(l.mesh)), std::to_string(num_faces(l.mesh)),
                   fmt(b), fmt(bc), fmt(s), fmt(sc), fmt(e), fmt(ec), fmt(f), fmt(fc), fmt(b / f, "%.3f"),
                   fmt(b / e, "%.4f"), fmt(bc / fc, "%.3f"), fmt(med(l.peaks[BUILD]), "%.1f"),
                   fmt(med(l.peaks[SOUP]), "%.1f"), fmt(l.surface_mib, "%.1f"), std::to_string(o.runs), load_before,
                   load_after});
  }
  table.print();
  write_table_csv(table, o.csv);
  return 0;
}
