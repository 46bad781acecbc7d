// How the exact distances_only propagation (Exact_geodesic_distances_3, vertex-oriented schedule) grows with
// the mesh size: a ladder of Loop subdivisions of CGAL's demo meshes (and of --extra-dir meshes), one row per
// mesh, and per variant the median CPU time of the propagation (thread CPU time, so that a loaded shared machine
// counts less), the windows per edge and the CPU nanoseconds per window. Variants, interleaved run by run in one
// process on the same loaded mesh:
//   - file:    the mesh as loaded (Loop subdivision appends the new vertices and faces at the end);
//   - hilbert: the same mesh copied with its vertices in Hilbert order (CGAL::hilbert_sort) and its faces sorted
//              by their smallest new vertex index: the locality a spatial order gives, measured outside the
//              library (the distances must be identical up to rounding);
//   - field:   the file order in full_field mode (the window propagation, which keeps the lower envelope of every
//              edge): its `stored` windows are the size of the exact field, what any envelope algorithm keeps.
// Timed: constructing the class on a prepared Geodesic_surface_3 (built once per variant, not timed), adding the
// source (the first vertex of the file order) and compute(). After the table: the growth exponents (least-squares
// slope of log(time) against log(vertices)) of each variant.
//
// Meshes: armadillo (26k vertices) and bunny00 (38k) of CGAL's demo data, diplodocus (24k, ../shared/data, with
// --extra-dir), and their Loop subdivisions x1, x2, x3 (named like armadillo-loop3: 1.66M vertices).
//
// Usage: bench_exact_geodesics_scale [--meshes a,b] [--runs N] [--csv FILE] [--mesh-dir DIR] [--extra-dir DIR]
//        [--variants file,hilbert,field] [--list]
#include <geodesic_bench_common.h>

#include <CGAL/Polyhedral_geodesics_3.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_surface_3.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <iostream>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

namespace {

using namespace geodesic_bench;
namespace PG = CGAL::Polyhedral_geodesics_3;
typedef PG::Geodesic_surface_3<Mesh> Surface;

double thread_cpu_seconds()
{
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

std::string load_average()
{
  std::ifstream in("/proc/loadavg");
  double a = 0, b = 0, c = 0;
  in >> a >> b >> c;
  return fmt(a, "%.2f") + " " + fmt(b, "%.2f") + " " + fmt(c, "%.2f");
}

// A copy of `mesh` with its vertices in Hilbert order and its faces sorted by their smallest new vertex;
// `new_of_old[v]` is the new index of old vertex v.
void hilbert_copy(const Mesh& mesh, Mesh& out, std::vector<std::size_t>& new_of_old)
{
  const std::size_t n = num_vertices(mesh);
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::vector<K::Point_3> points(n);
  for(Vertex v : vertices(mesh)) points[std::size_t(v)] = mesh.point(v);
  typedef CGAL::Spatial_sort_traits_adapter_3<K, CGAL::Pointer_property_map<K::Point_3>::type> Traits;
  CGAL::hilbert_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(points)));
  new_of_old.assign(n, 0);
  out.clear();
  for(std::size_t i = 0; i < n; ++i) {
    new_of_old[order[i]] = i;
    out.add_vertex(points[order[i]]);
  }
  std::vector<std::array<std::size_t, 4>> faces;
  for(auto f : CGAL::faces(mesh)) {
    std::array<std::size_t, 4> t;
    int k = 1;
    for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh)) t[k++] = new_of_old[std::size_t(v)];
    t[0] = std::min({t[1], t[2], t[3]});
    faces.push_back(t);
  }
  std::sort(faces.begin(), faces.end());
  for(const auto& t : faces) out.add_face(Vertex(Mesh::size_type(t[1])), Vertex(Mesh::size_type(t[2])), Vertex(Mesh::size_type(t[3])));
}

struct Run
{
  double cpu = 0, wall = 0;
  PG::Geodesic_statistics stats;
  std::vector<double> distances; // by file-order vertex index
};

Run run_once(const std::shared_ptr<const Surface>& surface, Vertex source, const std::vector<std::size_t>* new_of_old,
             PG::Geodesic_memory_mode mode)
{
  Run r;
  const auto w0 = std::chrono::steady_clock::now();
  const double c0 = thread_cpu_seconds();
  PG::Exact_geodesic_distances_3<Mesh> geo(surface, mode);
  geo.add_source(source);
  geo.compute();
  r.cpu = thread_cpu_seconds() - c0;
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  r.stats = geo.statistics();
  const Mesh& mesh = surface->triangle_mesh();
  r.distances.resize(num_vertices(mesh));
  for(std::size_t v = 0; v < r.distances.size(); ++v) {
    const std::size_t w = new_of_old ? (*new_of_old)[v] : v;
    r.distances[v] = CGAL::to_double(geo.distance(Vertex(Mesh::size_type(w))));
  }
  return r;
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? nan_ : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
}

double slope(const std::vector<double>& x, const std::vector<double>& y)
{
  const std::size_t n = x.size();
  if(n < 2) return nan_;
  double mx = 0, my = 0;
  for(std::size_t i = 0; i < n; ++i) { mx += std::log(x[i]); my += std::log(y[i]); }
  mx /= double(n); my /= double(n);
  double sxy = 0, sxx = 0;
  for(std::size_t i = 0; i < n; ++i) {
    sxy += (std::log(x[i]) - mx) * (std::log(y[i]) - my);
    sxx += (std::log(x[i]) - mx) * (std::log(x[i]) - mx);
  }
  return sxy / sxx;
}

} // namespace

int main(int argc, char** argv)
{
  Common_options o;
  o.runs = 3;
  std::vector<std::string> variants = {"file", "hilbert"};
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--variants" && i + 1 < argc) variants = split(argv[++i], ',');
    else if(!o.parse(argc, argv, i)) {
      std::cerr << "usage: bench_exact_geodesics_scale [--meshes a,b] [--runs N] [--csv FILE] [--mesh-dir DIR] "
                   "[--extra-dir DIR] [--variants file,hilbert,field] [--list]\n";
      return 2;
    }
  }
  std::vector<Mesh_spec> builtin;
  // The ladders: each base mesh and its Loop subdivisions x1..x3 (4x the vertices per step). diplodocus (24k
  // vertices) is in ../shared/data: its ladder is offered when --extra-dir holds it.
  std::vector<std::pair<std::string, std::string>> bases = {{"armadillo", o.in_mesh_dir("armadillo.off")},
                                                            {"bunny00", o.in_mesh_dir("bunny00.off")}};
  if(!o.extra_dir.empty())
    bases.push_back({"diplodocus", (std::filesystem::path(o.extra_dir) / "diplodocus.off").string()});
  for(int steps = 0; steps <= 3; ++steps)
    for(const auto& b : bases)
      builtin.push_back({steps ? b.first + "-loop" + std::to_string(steps) : b.first, b.second, steps});
  std::vector<Mesh_spec> specs;
  if(!select_meshes(builtin, o, specs)) return 2;
  if(o.list_only) {
    for(const auto& s : specs)
      std::cout << s.name << "  " << s.file << (s.loop_steps ? "  + Loop x" + std::to_string(s.loop_steps) : "") << "\n";
    return 0;
  }
  std::cout << "load average before: " << load_average() << "\n";
  std::ofstream csv;
  if(!o.csv.empty()) {
    csv.open(o.csv);
    csv << "mesh,vertices,edges,variant,cpu_s,wall_s,windows_created,windows_propagated,windows_pruned,"
           "windows_per_edge,ns_per_window,max_rel_diff_to_file,load_average\n";
  }
  std::printf("%-18s %9s %-8s %9s %9s %11s %9s %9s %11s %11s %11s\n", "mesh", "vertices", "variant", "cpu_s", "wall_s",
              "windows", "win/edge", "ns/win", "rel_diff", "propagated", "stored");
  std::vector<std::vector<double>> xs(variants.size()), ys(variants.size());
  for(const auto& spec : specs) {
    Mesh mesh;
    std::string message;
    if(!load_mesh(spec, mesh, message)) {
      std::cout << spec.name << ": " << message << "\n";
      continue;
    }
    std::vector<std::unique_ptr<Mesh>> meshes;
    std::vector<std::vector<std::size_t>> maps(variants.size());
    std::vector<std::shared_ptr<const Surface>> surfaces;
    for(std::size_t k = 0; k < variants.size(); ++k) {
      if(variants[k] == "hilbert") {
        meshes.emplace_back(new Mesh);
        hilbert_copy(mesh, *meshes.back(), maps[k]);
        surfaces.push_back(std::make_shared<const Surface>(*meshes.back()));
      } else {
        meshes.emplace_back(nullptr);
        surfaces.push_back(std::make_shared<const Surface>(mesh));
      }
    }
    const std::size_t n = num_vertices(mesh), ne = num_edges(mesh);
    std::vector<std::vector<double>> cpu(variants.size()), wall(variants.size());
    std::vector<Run> last(variants.size());
    for(int r = 0; r < o.runs; ++r)
      for(std::size_t k = 0; k < variants.size(); ++k) {
        const std::vector<std::size_t>* map = maps[k].empty() ? nullptr : &maps[k];
        const Vertex source(Mesh::size_type(map ? (*map)[0] : 0));
        const auto mode = variants[k] == "field" ? PG::Geodesic_memory_mode::full_field
                                                 : PG::Geodesic_memory_mode::distances_only;
        last[k] = run_once(surfaces[k], source, map, mode);
        cpu[k].push_back(last[k].cpu);
        wall[k].push_back(last[k].wall);
      }
    for(std::size_t k = 0; k < variants.size(); ++k) {
      double diff = 0;
      for(std::size_t v = 0; v < n; ++v) {
        const double a = last[k].distances[v], b = last[0].distances[v];
        if(a != b) diff = std::max(diff, std::abs(a - b) / std::max(std::abs(b), 1e-300));
      }
      const double c = median(cpu[k]), w = median(wall[k]);
      const auto& s = last[k].stats;
      const double per_edge = double(s.windows_created) / double(ne);
      const double ns = 1e9 * c / double(std::max<std::size_t>(1, s.windows_created));
      std::printf("%-18s %9zu %-8s %9.3f %9.3f %11zu %9.2f %9.1f %11.2e %11zu %11zu\n", spec.name.c_str(), n,
                  variants[k].c_str(), c, w, s.windows_created, per_edge, ns, diff, s.windows_propagated,
                  s.stored_windows);
      std::fflush(stdout);
      xs[k].push_back(double(n));
      ys[k].push_back(c);
      if(csv)
        csv << spec.name << "," << n << "," << ne << "," << variants[k] << "," << c << "," << w << ","
            << s.windows_created << "," << s.windows_propagated << "," << s.windows_pruned << "," << per_edge << ","
            << ns << "," << diff << "," << load_average() << "\n";
    }
  }
  for(std::size_t k = 0; k < variants.size(); ++k)
    std::cout << "growth exponent of CPU time, " << variants[k] << ": " << fmt(slope(xs[k], ys[k]), "%.3f") << "\n";
  std::cout << "load average after: " << load_average() << "\n";
  return 0;
}
