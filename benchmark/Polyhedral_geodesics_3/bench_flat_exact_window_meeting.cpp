// The flat-exact error with the two rules for an edge whose ends belong to different windows: the smaller of
// the two offsets (the library's default) and the thesis's zero offset. For every mesh and every one of
// --sources random source vertices (fixed seed), the mean relative error E (thesis eq. 4.4.1) and the mean
// signed relative error of both rules against Exact_geodesic_distances_3, and the values per vertex.
// No timing (bench_approximate_geodesics times the default rule against the other methods).
//
//   bench_flat_exact_window_meeting [--meshes a,b,c] [--sources K] [--seed S] [--mesh-dir DIR] [--extra-dir DIR]
//                                   [--csv FILE] [--list]
//
// The built-in meshes are those of bench_approximate_geodesics below 60k vertices and CGAL demo meshes that it
// does not use (mechanical parts with holes and sharp edges among them).
#include <geodesic_bench_common.h>
#include <mdcs_bench.h>

#include <CGAL/Polyhedral_geodesics_3/Exact_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/internal/flat_exact_propagation.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace PG = CGAL::Polyhedral_geodesics_3;
using mdcs_bench::fmt;

namespace {

using namespace geodesic_bench;

typedef PG::internal::Flat_exact_propagation<double> Engine;
typedef Engine::Window_meeting Window_meeting;

struct Error_sums // over the sources of one mesh and one rule
{
  double mean_relative = 0, mean_signed = 0, values_per_vertex = 0;
  double worst_below = 0; // the most negative relative error
};

// E and the signed mean of `approx` against `exact` over the vertices at positive, finite exact distance.
void add_errors(const std::vector<double>& approx, const std::vector<double>& exact, Error_sums& sums)
{
  double e = 0, s = 0;
  std::size_t n = 0;
  for(std::size_t v = 0; v < exact.size(); ++v) {
    if(!(exact[v] > 0) || !std::isfinite(exact[v]) || !std::isfinite(approx[v]))
      continue;
    const double r = (approx[v] - exact[v]) / exact[v];
    e += std::abs(r);
    s += r;
    sums.worst_below = std::min(sums.worst_below, r);
    ++n;
  }
  if(n) {
    sums.mean_relative += e / double(n);
    sums.mean_signed += s / double(n);
  }
}

void usage()
{
  std::cerr << "usage: bench_flat_exact_window_meeting [--meshes a,b,c] [--sources K] [--seed S] [--mesh-dir DIR]\n"
               "         [--extra-dir DIR] [--csv FILE] [--list]\n";
}

} // namespace

int main(int argc, char** argv)
{
  Common_options o;
  o.csv = "flat_exact_window_meeting.csv";
  int sources = 3;
  std::uint64_t seed = 1;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if(o.parse(argc, argv, i)) continue;
    if(a == "--sources" && has_value) sources = std::max(1, std::atoi(argv[++i]));
    else if(a == "--seed" && has_value) seed = std::strtoull(argv[++i], nullptr, 10);
    else {
      usage();
      return 2;
    }
  }
  std::vector<Mesh_spec> builtin;
  for(const char* name : {"ChineseDragon-10kv", "mannequin-devil", "armadillo", "bunny00", "refined_elephant",
                          "diplodocus", "mushroom", "elephant-with-holes", "triceratops", "cow", "femur", "dino", "holes",
                          "homer", "mech-holes-shark", "bull", "fandisk", "lion", "blade", "camel", "bear", "man",
                          "turbine", "cheese"})
    builtin.push_back({name, o.in_mesh_dir(std::string(name) + ".off"), 0});
  builtin.push_back({"mannequin-devil-loop1", o.in_mesh_dir("mannequin-devil.off"), 1});
  std::vector<Mesh_spec> specs;
  if(const int exit_code = select_or_list_meshes(builtin, o, specs, usage); exit_code >= 0)
    return exit_code;

  std::cout << "Flat-exact where two windows meet on an edge: the smaller offset (default) against the thesis's zero\n"
            << "offset. " << sources << " random source vertices per mesh (seed " << seed << "); E = mean relative error\n"
            << "(thesis eq. 4.4.1) against Exact_geodesic_distances_3, in percent, averaged over the sources; signed = the\n"
            << "mean of (flat - exact) / exact; below = the most negative relative error over all sources.\n\n";
  mdcs_bench::Table table({"mesh", "vertices", "boundary_edges", "sources", "E_zero_pct", "E_smaller_pct", "ratio",
                           "signed_zero_pct", "signed_smaller_pct", "below_zero_pct", "below_smaller_pct",
                           "values_per_vertex_zero", "values_per_vertex_smaller"});
  std::size_t better = 0, compared = 0;
  for(const Mesh_spec& spec : specs) {
    Mesh mesh;
    std::string message;
    if(!load_mesh(spec, mesh, message)) {
      std::cout << "skipping " << spec.name << ": " << message << "\n" << std::flush;
      continue;
    }
    const std::size_t n = mesh.number_of_vertices();
    PG::internal::Geodesic_mesh<double> cm;
    std::vector<Mesh::Halfedge_index> halfedge_of;
    PG::internal::build_geodesic_mesh(mesh, get(CGAL::vertex_point, mesh), get(CGAL::vertex_index, mesh),
                                      get(CGAL::face_index, mesh), cm, halfedge_of);
    Engine engine(cm);
    Error_sums sums[2]; // [0]: zero offset, [1]: smaller offset
    std::mt19937_64 rng(seed);
    for(int k = 0; k < sources; ++k) {
      const Vertex source(Mesh::size_type(rng() % n));
      std::vector<double> exact(n, nan_), flat(n, nan_);
      PG::Exact_geodesic_distances_3<Mesh> reference(mesh, PG::Geodesic_memory_mode::distances_only);
      reference.add_source(source);
      reference.distances(Distance_vector_map{&exact});
      for(int rule = 0; rule < 2; ++rule) {
        engine.clear();
        engine.set_window_meeting(rule == 0 ? Window_meeting::zero_offset : Window_meeting::smaller_offset);
        engine.add_vertex_source(int(std::size_t(source)), 0);
        CGAL::MDCS::No_progress progress;
        engine.run(progress);
        for(std::size_t v = 0; v < n; ++v)
          flat[v] = engine.vertex_distance(int(v));
        add_errors(flat, exact, sums[rule]);
        sums[rule].values_per_vertex += double(engine.statistics().vertex_updates) / double(n);
      }
    }
    const double K = double(sources);
    const double e0 = sums[0].mean_relative / K, e1 = sums[1].mean_relative / K;
    ++compared;
    if(e1 < e0) ++better;
    table.add_row({spec.name, std::to_string(n), std::to_string(count_boundary_edges(mesh)), std::to_string(sources),
                   fmt(100 * e0, "%.4f"), fmt(100 * e1, "%.4f"), fmt(e0 > 0 ? e1 / e0 : nan_, "%.3f"),
                   fmt(100 * sums[0].mean_signed / K, "%+.4f"), fmt(100 * sums[1].mean_signed / K, "%+.4f"),
                   fmt(100 * sums[0].worst_below, "%.3f"), fmt(100 * sums[1].worst_below, "%.3f"),
                   fmt(sums[0].values_per_vertex / K, "%.3f"), fmt(sums[1].values_per_vertex / K, "%.3f")});
    std::cout << spec.name << ": E " << fmt(100 * e0, "%.4f") << "% -> " << fmt(100 * e1, "%.4f") << "%\n" << std::flush;
  }
  std::cout << "\n";
  table.print();
  std::cout << "\nthe smaller offset has the lower E on " << better << " of " << compared << " meshes\n";
  write_table_csv(table, o.csv);
  return 0;
}
