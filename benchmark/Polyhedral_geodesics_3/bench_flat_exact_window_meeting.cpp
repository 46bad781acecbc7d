// The flat-exact error with the two rules for an edge whose ends belong to different windows: the smaller of
// the two offsets (the library's default) and the thesis's zero offset. For every mesh and every one of
// --sources random source vertices (fixed seed), the mean relative error E (thesis eq. 4.4.1) and the mean
// signed relative error of both rules against Exact_geodesic_distances_3, and the values per vertex.
// No timing (bench_approximate_geodesics times the default rule against the other methods).
//
// --true-roots adds a diagnosis of the default rule: the windows it tracks against those of the exact shortest
// paths (where each path to a vertex last bends, at a saddle or boundary vertex), and E when the propagation is
// given the exact windows instead of tracking its own (the offsets still from its own distances), and given both
// the exact windows and their exact offsets (the exact distances of the roots). This traces the exact path to
// every vertex, which makes the run several times longer.
//
//   bench_flat_exact_window_meeting [--meshes a,b,c] [--sources K] [--seed S] [--true-roots] [--mesh-dir DIR]
//                                   [--extra-dir DIR] [--csv FILE] [--list]
//
// The built-in meshes are those of bench_approximate_geodesics below 60k vertices and CGAL demo meshes that it
// does not use (mechanical parts with holes and sharp edges among them).
#include <geodesic_bench_common.h>
#include <mdcs_bench.h>

#include <CGAL/Polyhedral_geodesics_3/Exact_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/internal/flat_exact_propagation.h>

#include <array>
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

// Where the exact shortest paths bend, summed over the sources of one mesh (--true-roots).
struct Root_sums
{
  double bent = 0;        // share of the reached vertices whose exact path passes through a vertex
  double tracked = 0;     // share that the default rule puts in a window rooted at a vertex
  double same_window = 0; // share whose tracked root is the exact one (both -1 included)
};

// Receives an exact shortest path (from the target to the source) and keeps its last bend: the first vertex
// after the target where shortest paths can bend (a saddle or a reflex boundary vertex, as the engine's windows;
// a path can also pass straight through another vertex, which starts no window).
struct Last_bend
{
  const Engine& engine;
  int vertices_seen = 0;
  std::size_t bend = std::size_t(-1);
  void operator()(Vertex v)
  {
    if(vertices_seen++ >= 1 && bend == std::size_t(-1) && engine.can_bend_at(int(std::size_t(v))))
      bend = std::size_t(v);
  }
  void operator()(Mesh::Halfedge_index, double) {}
  void operator()(Mesh::Face_index, const std::array<double, 3>&) {}
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
               "         [--true-roots] [--extra-dir DIR] [--csv FILE] [--list]\n";
}

} // namespace

int main(int argc, char** argv)
{
  Common_options o;
  o.csv = "flat_exact_window_meeting.csv";
  int sources = 3;
  std::uint64_t seed = 1;
  bool true_roots = false;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if(o.parse(argc, argv, i)) continue;
    if(a == "--sources" && has_value) sources = std::max(1, std::atoi(argv[++i]));
    else if(a == "--seed" && has_value) seed = std::strtoull(argv[++i], nullptr, 10);
    else if(a == "--true-roots") true_roots = true;
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
            << "mean of (flat - exact) / exact; below = the most negative relative error over all sources.\n";
  if(true_roots)
    std::cout << "--true-roots: bent = share of the vertices whose exact shortest path bends at a saddle or reflex\n"
              << "boundary vertex; tracked = share in a window rooted at a vertex under the default rule; same = share\n"
              << "whose tracked root is the exact path's last bend (or neither has one); E_true_roots etc. = the default\n"
              << "rule given the exact paths' windows; E_true_offsets etc. = given the exact windows and their exact\n"
              << "offsets (the exact distances of the roots).\n";
  std::cout << "\n";
  std::vector<std::string> columns = {"mesh", "vertices", "boundary_edges", "sources", "E_zero_pct", "E_smaller_pct",
                                      "ratio", "signed_zero_pct", "signed_smaller_pct", "below_zero_pct",
                                      "below_smaller_pct", "values_per_vertex_zero", "values_per_vertex_smaller"};
  if(true_roots)
    for(const char* c : {"bent_pct", "tracked_pct", "same_window_pct", "E_true_roots_pct", "signed_true_roots_pct",
                         "below_true_roots_pct", "E_true_offsets_pct", "signed_true_offsets_pct", "below_true_offsets_pct"})
      columns.push_back(c);
  mdcs_bench::Table table(columns);
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
    Error_sums sums[4]; // [0]: zero offset, [1]: smaller offset, [2]: smaller offset with the exact windows,
                        // [3]: the same with the exact offsets of those windows
    Root_sums roots_sums;
    std::mt19937_64 rng(seed);
    for(int k = 0; k < sources; ++k) {
      const Vertex source(Mesh::size_type(rng() % n));
      std::vector<double> exact(n, nan_), flat(n, nan_);
      // paths need the full field
      PG::Exact_geodesic_distances_3<Mesh> reference(mesh, true_roots ? PG::Geodesic_memory_mode::full_field
                                                                      : PG::Geodesic_memory_mode::distances_only);
      reference.add_source(source);
      reference.distances(Distance_vector_map{&exact});
      // the last bend of the exact path to every vertex (-1: straight from the source, or unreached)
      std::vector<int> exact_root(n, -1);
      if(true_roots)
        for(std::size_t v = 0; v < n; ++v) {
          if(!(exact[v] > 0) || !std::isfinite(exact[v]))
            continue;
          Last_bend bend{engine};
          reference.shortest_path_sequence(Vertex(Mesh::size_type(v)), bend);
          if(bend.bend != std::size_t(-1) && bend.bend != std::size_t(source))
            exact_root[v] = int(bend.bend);
        }
      for(int rule = 0; rule < (true_roots ? 4 : 2); ++rule) {
        engine.clear();
        engine.set_window_meeting(rule == 0 ? Window_meeting::zero_offset : Window_meeting::smaller_offset);
        engine.set_window_roots(rule >= 2 ? &exact_root : nullptr);
        engine.set_window_root_offsets(rule == 3 ? &exact : nullptr); // the exact distances (+inf only off the roots)
        engine.add_vertex_source(int(std::size_t(source)), 0);
        CGAL::MDCS::No_progress progress;
        engine.run(progress);
        for(std::size_t v = 0; v < n; ++v)
          flat[v] = engine.vertex_distance(int(v));
        add_errors(flat, exact, sums[rule]);
        if(rule == 1 && true_roots) {
          std::size_t reached = 0, bent = 0, tracked = 0, same = 0;
          for(std::size_t v = 0; v < n; ++v) {
            if(!(exact[v] > 0) || !std::isfinite(exact[v]))
              continue;
            ++reached;
            const int tracked_root = engine.window_root(int(v));
            bent += exact_root[v] >= 0;
            tracked += tracked_root >= 0;
            same += tracked_root == exact_root[v];
          }
          if(reached) {
            roots_sums.bent += double(bent) / double(reached);
            roots_sums.tracked += double(tracked) / double(reached);
            roots_sums.same_window += double(same) / double(reached);
          }
        }
        sums[rule].values_per_vertex += double(engine.statistics().vertex_updates) / double(n);
      }
    }
    const double K = double(sources);
    const double e0 = sums[0].mean_relative / K, e1 = sums[1].mean_relative / K;
    ++compared;
    if(e1 < e0) ++better;
    std::vector<std::string> row = {
        spec.name, std::to_string(n), std::to_string(count_boundary_edges(mesh)), std::to_string(sources),
        fmt(100 * e0, "%.4f"), fmt(100 * e1, "%.4f"), fmt(e0 > 0 ? e1 / e0 : nan_, "%.3f"),
        fmt(100 * sums[0].mean_signed / K, "%+.4f"), fmt(100 * sums[1].mean_signed / K, "%+.4f"),
        fmt(100 * sums[0].worst_below, "%.3f"), fmt(100 * sums[1].worst_below, "%.3f"),
        fmt(sums[0].values_per_vertex / K, "%.3f"), fmt(sums[1].values_per_vertex / K, "%.3f")};
    if(true_roots) {
      for(double share : {roots_sums.bent, roots_sums.tracked, roots_sums.same_window})
        row.push_back(fmt(100 * share / K, "%.1f"));
      row.push_back(fmt(100 * sums[2].mean_relative / K, "%.4f"));
      row.push_back(fmt(100 * sums[2].mean_signed / K, "%+.4f"));
      row.push_back(fmt(100 * sums[2].worst_below, "%.3f"));
      row.push_back(fmt(100 * sums[3].mean_relative / K, "%.4f"));
      row.push_back(fmt(100 * sums[3].mean_signed / K, "%+.4f"));
      row.push_back(fmt(100 * sums[3].worst_below, "%.3f"));
    }
    table.add_row(row);
    std::cout << spec.name << ": E " << fmt(100 * e0, "%.4f") << "% -> " << fmt(100 * e1, "%.4f") << "%";
    if(true_roots)
      std::cout << " (with the exact paths' windows " << fmt(100 * sums[2].mean_relative / K, "%.4f")
                << "%, and their exact offsets " << fmt(100 * sums[3].mean_relative / K, "%.4f") << "%)";
    std::cout << "\n" << std::flush;
  }
  std::cout << "\n";
  table.print();
  std::cout << "\nthe smaller offset has the lower E on " << better << " of " << compared << " meshes\n";
  write_table_csv(table, o.csv);
  return 0;
}
