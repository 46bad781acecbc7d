// Hierarchical silhouette extraction (issue 30, item 6): Silhouette_edge_hierarchy_3 against the scan of every
// face (classify_faces + silhouette_from_faces, what Silhouette_simplifier_3::extract_silhouettes() runs), on
// the same views, interleaved view by view: time per view (medians), speed-up, edges and nodes examined per
// view, build time and memory of the tree. Every view's two results are compared (they must be equal).
//
// usage: bench_silhouette_hierarchy [--csv FILE] [--views N] [--rounds N] [--leaf N] [--position-weight W]
//                                   [--no-large] [--mesh FILE]...
//   Default meshes (CGAL's demo data, MDCS_CGAL_MESH_DIR): bunny00.off simplified to 20,000 faces (the thesis's
//   bunny), bunny00.off (75k faces), after one Loop subdivision (302k) and after two (1.2M; --no-large skips it).
//   Views: N random directions (default 100); per direction a perspective eye 2.5 bounding-box diagonals from
//   the centre (as in bench_silhouette) and an orthographic view along it. Each view is timed --rounds times
//   (default 3), alternating scan and hierarchy. Times are CPU times of the process (the one-core cost, without
//   waiting for a core on a shared machine; the wall-clock medians are in the *_wall_ms columns).
#include <mdcs_bench.h>
#include <silhouette_bench_meshes.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Silhouette_simplification_3/Silhouette_edge_hierarchy_3.h>
#include <CGAL/Silhouette_simplification_3/internal/silhouette_extraction.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#ifndef MDCS_CGAL_MESH_DIR
#define MDCS_CGAL_MESH_DIR ""
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
namespace SS = CGAL::Silhouette_simplification_3;
typedef SS::View_3<K> View;

typedef mdcs_bench::Silhouette_bench_case Case;

// A deterministic pseudo-random number in [0, 1).
static double hash01(std::uint64_t i)
{
  i = (i ^ (i >> 30)) * 0xbf58476d1ce4e5b9ULL;
  i = (i ^ (i >> 27)) * 0x94d049bb133111ebULL;
  i ^= i >> 31;
  return double(i >> 11) / double(1ULL << 53);
}

int main(int argc, char** argv)
{
  std::string csv = "silhouette_hierarchy.csv";
  std::size_t directions = 100;
  int rounds = 3;
  bool large = true;
  SS::Silhouette_hierarchy_options options;
  std::vector<Case> cases;
  const std::string dir = MDCS_CGAL_MESH_DIR;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--csv" && i + 1 < argc) csv = argv[++i];
    else if(a == "--views" && i + 1 < argc) directions = std::stoul(argv[++i]);
    else if(a == "--rounds" && i + 1 < argc) rounds = std::max(1, std::atoi(argv[++i]));
    else if(a == "--leaf" && i + 1 < argc) options.leaf_edges = std::stoul(argv[++i]);
    else if(a == "--position-weight" && i + 1 < argc) options.position_weight = std::stod(argv[++i]);
    else if(a == "--no-large") large = false;
    else if(a == "--mesh" && i + 1 < argc) { Case c; c.path = argv[++i]; c.name = c.path.substr(c.path.find_last_of('/') + 1); cases.push_back(c); }
    else {
      std::fprintf(stderr, "usage: %s [--csv FILE] [--views N] [--rounds N] [--leaf N] [--position-weight W] [--no-large] "
                           "[--mesh FILE]...\n", argv[0]);
      return 2;
    }
  }
  if(cases.empty()) {
    if(dir.empty()) { std::fprintf(stderr, "no CGAL demo meshes (MDCS_CGAL_MESH_DIR is empty): give --mesh FILE\n"); return 2; }
    Case b20; b20.name = "bunny 20k"; b20.path = dir + "/bunny00.off"; b20.fine_faces = 20000;
    Case b75; b75.name = "bunny 75k"; b75.path = dir + "/bunny00.off";
    Case b300; b300.name = "bunny Loop x1"; b300.path = dir + "/bunny00.off"; b300.subdivisions = 1;
    cases = {b20, b75, b300};
    if(large) { Case big; big.name = "bunny Loop x2"; big.path = dir + "/bunny00.off"; big.subdivisions = 2; cases.push_back(big); }
  }

  std::printf("Silhouette extraction: bounding-cone hierarchy (leaf %zu edges, position weight %g) against the scan of "
              "every face; %zu directions x (perspective at 2.5 diagonals, orthographic), %d interleaved rounds, "
              "per-view medians of CPU time. Machine shared with other jobs: absolute times are noisy, ratios are what count.\n\n",
              options.leaf_edges, options.position_weight, directions, rounds);
  mdcs_bench::Table table({"mesh", "faces", "edges", "views", "scan_ms", "hierarchy_ms", "speedup", "scan_wall_ms",
                           "hierarchy_wall_ms", "edges_tested",
                           "tested_fraction", "nodes_visited", "silhouette_edges", "mismatches", "construct_s", "tree_build_s",
                           "tree_MiB", "mesh_copy_MiB", "nodes", "edges_outside_tree", "load"});
  for(const Case& c : cases) {
    Mesh mesh;
    if(!mdcs_bench::read_silhouette_bench_mesh(c.path, c.fine_faces, c.subdivisions, mesh)) continue;
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);

    // Build (CPU seconds): the flat copy and the tree together (the constructor), then the tree alone on that copy.
    double t0 = mdcs_bench::cpu_seconds();
    const SS::Silhouette_edge_hierarchy_3<Mesh> hierarchy(mesh, options);
    const double construct = mdcs_bench::cpu_seconds() - t0;
    const auto& im = hierarchy.index_mesh();
    SS::internal::Edge_cone_hierarchy tree;
    t0 = mdcs_bench::cpu_seconds();
    tree.build(im, options);
    const double tree_build = mdcs_bench::cpu_seconds() - t0;
    const double mesh_mib = double(im.points.size() * sizeof(Point_3) + im.faces.size() * sizeof(im.faces[0]) +
                                   (im.source.size() + im.opposite.size() + im.vf.size() + im.vf_begin.size()) * 4) /
                            (1 << 20);

    const Point_3 centre((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2, (box.zmin() + box.zmax()) / 2);
    const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                      CGAL::square(box.zmax() - box.zmin()));
    for(int kind = 0; kind < 2; ++kind) {
      std::vector<View> views;
      for(std::size_t i = 0; i < directions; ++i) {
        const double a = 6.283185307179586 * hash01(2 * i + 17), z = 2 * hash01(2 * i + 18) - 1, s = std::sqrt(1 - z * z);
        const Vector_3 d(s * std::cos(a), s * std::sin(a), z);
        views.push_back(kind == 0 ? View::perspective(centre + 2.5 * diagonal * d) : View::orthographic(-d));
      }
      std::vector<double> scan_ms, tree_ms, scan_wall, tree_wall, tested, visited, silhouette;
      std::size_t mismatches = 0;
      std::vector<char> front;
      std::vector<std::uint32_t> by_scan, by_tree;
      for(int r = 0; r < rounds; ++r)
        for(const View& view : views) {
          const double a = mdcs_bench::cpu_seconds(), wa = mdcs_bench::now_seconds();
          SS::internal::classify_faces(im, view, front);
          SS::internal::silhouette_from_faces(im, front, by_scan);
          const double b = mdcs_bench::cpu_seconds(), wb = mdcs_bench::now_seconds();
          SS::Silhouette_hierarchy_statistics stats;
          tree.query(im, view, by_tree, &stats);
          const double d = mdcs_bench::cpu_seconds(), wd = mdcs_bench::now_seconds();
          scan_ms.push_back(1e3 * (b - a));
          tree_ms.push_back(1e3 * (d - b));
          scan_wall.push_back(1e3 * (wb - wa));
          tree_wall.push_back(1e3 * (wd - wb));
          if(by_tree != by_scan) ++mismatches;
          if(r == 0) {
            tested.push_back(double(stats.edges_tested));
            visited.push_back(double(stats.nodes_visited));
            silhouette.push_back(double(by_scan.size()));
          }
        }
      using mdcs_bench::fmt;
      using mdcs_bench::median;
      const double ms_scan = median(scan_ms), ms_tree = median(tree_ms);
      table.add_row({"\"" + c.name + (kind == 0 ? " persp" : " ortho") + "\"", std::to_string(num_faces(mesh)),
                     std::to_string(num_edges(mesh)), std::to_string(views.size()), fmt(ms_scan, "%.4f"), fmt(ms_tree, "%.4f"),
                     fmt(ms_scan / ms_tree, "%.2f"), fmt(median(scan_wall), "%.4f"), fmt(median(tree_wall), "%.4f"),
                     fmt(median(tested), "%.0f"),
                     fmt(median(tested) / double(num_edges(mesh)), "%.4f"), fmt(median(visited), "%.0f"),
                     fmt(median(silhouette), "%.0f"), std::to_string(mismatches), fmt(construct, "%.3f"),
                     fmt(tree_build, "%.3f"), fmt(double(tree.memory_bytes()) / (1 << 20), "%.1f"), fmt(mesh_mib, "%.1f"),
                     std::to_string(tree.number_of_nodes()), std::to_string(tree.number_of_edges_outside_the_tree()),
                     mdcs_bench::load_average()});
      std::printf("  %s %s: scan %.4f ms, hierarchy %.4f ms (x%.2f), %0.f edges tested of %zu, %zu mismatches\n",
                  c.name.c_str(), kind == 0 ? "perspective" : "orthographic", ms_scan, ms_tree, ms_scan / ms_tree,
                  median(tested), std::size_t(num_edges(mesh)), mismatches);
      std::fflush(stdout);
    }
  }
  table.print();
  if(!table.write_csv(csv)) { std::fprintf(stderr, "cannot write %s\n", csv.c_str()); return 1; }
  std::printf("\nCSV written to %s\n", csv.c_str());
  return 0;
}
