// The geodesics section of `mdcs demo` (cmd_demo.h, demo_sections.h): exact distances and paths checked against CGAL's
// Surface_mesh_shortest_path, and the flat-exact approximation with its error.
#include "demo_sections.h"
#include "cmd_geodesics.h"

#include <filesystem>
#include <iomanip>
#include <ostream>
#include <string>
#include <vector>

namespace mdcs_cli {

// ------------------------------------------------------------------------------------------------------------
// One row of the demo's method table: time, error against the exact run, picture.
inline void md_flat_row(std::ostream& md, const std::string& mesh, const std::string& method, const Geodesics_run& run,
                        const std::string& folder, const std::string& path_excess)
{
  const std::string link = folder + "/geodesics." + (run.png.empty() ? "svg" : "png");
  md << "| " << mesh << " | " << method << " | " << std::setprecision(3) << run.seconds_setup + run.seconds_compute << " | ";
  if(method == "exact") md << "0 (reference) | 0 (reference)";
  else if(run.error.compared == 0) md << "- | -";
  else md << geo_detail::number_text(100 * run.error.mean_relative, 3) << "% | " << geo_detail::number_text(100 * run.error.max_relative, 3) << "%";
  if(run.error.unreachable_mismatches) md << " (" << run.error.unreachable_mismatches << " vertices reachable in one only)";
  md << " | " << path_excess << " | [" << link << "](" << link << ") |\n";
}

// The geodesics section of `mdcs demo`: one vertex source and three targets on CGAL's elephant (a generated
// torus when CGAL's data is missing; with the dragon too unless --quick), compared with
// Surface_mesh_shortest_path, then the same with the flat-exact approximation (its time and its error against the
// exact run). Appends to summary.md; returns whether the checks passed.
bool demo_geodesics(const std::filesystem::path& folder, bool quick, const Progress_bar& progress, std::ostream& md)
{
  const std::string dir = MDCS_CGAL_MESH_DIR;
  std::vector<std::string> meshes;
  for(const char* name : {"elephant.off", "ChineseDragon-10kv.off"}) {
    const std::string path = dir.empty() ? std::string() : (std::filesystem::path(dir) / name).string();
    if(!path.empty() && std::filesystem::is_regular_file(path)) meshes.push_back(path);
    if(quick) break;
  }
  const bool fallback = meshes.empty();
  if(fallback) meshes.push_back("@torus");

  md << "\n## Exact geodesic distances\n\n"
        "Exact geodesic distances from one vertex by interval (window) propagation with side lobes "
        "(`CGAL::Polyhedral_geodesics_3::Exact_geodesic_distances_3`), shortest paths to three far vertices, and the same "
        "distances from CGAL's `Surface_mesh_shortest_path` (the Chen-Han / Xin-Wang algorithm) as an independent check "
        "on every vertex. The pictures colour the surface by distance with iso-distance lines; the paths are solid where "
        "visible and dashed behind the surface. `distances.ply` holds every vertex distance (-1: unreachable).";
  if(fallback) md << " CGAL's meshes are not installed (libcgal-demo), so a generated torus is used.";
  md << "\n\n| mesh | vertices | faces | propagation (s) | windows created | max distance | CGAL SMSP (s) | max relative difference | picture |\n"
        "|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
  std::ostringstream targets_md, flat_md;
  targets_md << "\n| mesh | target | distance | CGAL SMSP distance | path length | path points |\n|---|---|---:|---:|---:|---:|\n";
  flat_md << "\n| mesh | method | time (s) | mean relative error vs exact | max relative error vs exact | "
             "paths T1-T3, locally shortest: longest / exact - 1 | picture |\n"
             "|---|---|---:|---:|---:|---:|---|\n";
  bool flat_ok = true;
  bool ok = true;
  std::string pictures; // the first PNG, shown in summary.md
  for(const std::string& path : meshes) {
    Geo_mesh mesh;
    std::vector<std::string> notes;
    const auto t0 = std::chrono::steady_clock::now();
    load_geodesics_mesh(path, mesh, notes);
    const double seconds_read = seconds_since(t0);
    // The source and targets: extreme vertices of the default view, so that they are on the silhouette and visible.
    Geodesics_settings s;
    s.mesh = path;
    s.compare_cgal = true;
    s.export_data = false; // the demo shows pictures; the command writes the data files
    const std::string stem = path[0] == '@' ? path.substr(1) : std::filesystem::path(path).stem().string();
    // Three-quarter views that show the animals' sides (both are y-up), and the torus from above.
    s.view = stem == "elephant" ? Geo_vec{{0.45, 0.3, 1}} : stem == "ChineseDragon-10kv" ? Geo_vec{{1, 0.35, 0.75}} : Geo_vec{{0.3, 1, 0.8}};
    s.output = (folder / ("geodesics-" + stem)).string();
    const Geo_vec d = geo_detail::normalized(s.view);
    const Geo_vec right = geo_detail::normalized(geo_detail::cross(s.up, d)), up = geo_detail::cross(d, right);
    std::size_t imin = 0, imax = 0, itop = 0, ibottom = 0;
    double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
    for(Geo_mesh::Vertex_index v : mesh.vertices()) {
      if(mesh.is_isolated(v)) continue;
      const Geo_vec p = geo_detail::vec(mesh.point(v));
      const double x = geo_detail::dot(p, right), y = geo_detail::dot(p, up);
      if(x < xmin) xmin = x, imin = v.idx();
      if(x > xmax) xmax = x, imax = v.idx();
      if(y < ymin) ymin = y, ibottom = v.idx();
      if(y > ymax) ymax = y, itop = v.idx();
    }
    s.sources = std::to_string(imin);
    s.targets = std::to_string(imax) + "," + std::to_string(itop) + "," + std::to_string(ibottom);
    const std::string name = path[0] == '@' ? "torus (generated)" : std::filesystem::path(path).filename().string();
    const Geodesics_run run = run_geodesics_on(mesh, name, notes, seconds_read, s, progress);
    std::cout << "== geodesics on " << name << "\n" << run.summary << "\n";

    const bool close = run.compared_vertices > 0 && run.max_relative_difference <= 1e-6 && run.reachability_mismatches == 0;
    bool paths_ok = true;
    for(const auto& t : run.targets)
      if(!std::isfinite(t.distance) || t.path.empty() || !(std::abs(t.path_length - t.distance) <= 1e-6 * t.distance)) paths_ok = false;
    if(!close || !paths_ok || run.targets.size() != 3) ok = false;
    const std::string link = "geodesics-" + stem + "/geodesics." + (run.png.empty() ? "svg" : "png");
    md << "| " << name << " | " << run.V << " | " << run.F << " | " << std::setprecision(3) << run.seconds_compute << " | "
       << run.stats.windows_created << " | " << (run.reachable ? geo_detail::number_text(run.max_distance, 6) : std::string("- (none reachable)"))
       << " | " << std::setprecision(3) << run.cgal_seconds << " | "
       << (run.compared_vertices ? geo_detail::number_text(run.max_relative_difference, 2) : std::string("-"))
       << (run.reachability_mismatches ? " (" + std::to_string(run.reachability_mismatches) + " vertices reachable in one only)" : std::string())
       << " | [" << link << "](" << link << ") |\n";
    for(std::size_t i = 0; i < run.targets.size(); ++i) {
      const auto& t = run.targets[i];
      targets_md << "| " << name << " | T" << i + 1 << " = vertex " << t.where.index << " | " << geo_detail::number_text(t.distance, 10)
                 << " | " << geo_detail::number_text(t.cgal_distance, 10) << " | "
                 << (!t.path_error.empty() ? "tracing failed: " + t.path_error
                     : t.path.empty() ? std::string("no path") : geo_detail::number_text(t.path_length, 10))
                 << " | " << t.path_points << " |\n";
    }
    if(pictures.empty() && !run.png.empty()) pictures = link;

    // The same source and targets with the flat-exact approximation (thesis ch. 4.3), its error against the run above.
    Geodesics_settings f = s;
    f.method = parse_geo_method("flat-exact");
    f.compare_cgal = false;
    f.compare_exact = true;
    f.shorten_paths = true; // its paths made locally shortest (set_path_shortening), compared with the exact lengths
    f.output = (folder / ("geodesics-" + stem + "-flat-exact")).string();
    md_flat_row(flat_md, name, "exact", run, "geodesics-" + stem, "0 (reference)");
    try {
      const Geodesics_run flat = run_geodesics_on(mesh, name, notes, seconds_read, f, progress, &run);
      std::cout << "== flat-exact geodesics on " << name << "\n" << flat.summary << "\n";
      double worst = 0;
      bool all_paths = flat.targets.size() == run.targets.size();
      for(std::size_t i = 0; all_paths && i < flat.targets.size(); ++i) {
        const double exact = run.targets[i].distance, length = flat.targets[i].path_length;
        if(flat.targets[i].path.empty() || !(exact > 0) || !std::isfinite(length)) all_paths = false;
        else worst = std::max(worst, length / exact - 1);
      }
      md_flat_row(flat_md, name, "flat-exact", flat, "geodesics-" + stem + "-flat-exact",
                  all_paths ? geo_detail::number_text(100 * worst, 3) + "%" : std::string("-"));
      if(!(flat.error.compared > 0) || flat.error.unreachable_mismatches) flat_ok = false;
    } catch(const std::exception& e) { // reported in the table; the exact results above stay valid
      std::cerr << "mdcs demo: flat-exact geodesics on " << name << " failed: " << e.what() << "\n";
      flat_md << "| " << name << " | flat-exact | - | - | - | - | FAILED: " << e.what() << " |\n";
      flat_ok = false;
    }
  }
  md << targets_md.str();
  md << "\nSource: the leftmost vertex of the view; targets T1-T3: the rightmost, topmost and lowest vertices. "
        "Checks: every vertex distance within 1e-6 (relative) of CGAL's, and every path as long as its distance: "
     << (ok ? "passed" : "FAILED") << ".\n";
  if(!pictures.empty()) md << "\n![exact geodesic distances](" << pictures << ")\n";
  md << "\nThe flat-exact approximation (`Flat_exact_geodesic_distances_3`, one interval per edge, thesis ch. 4.3) from the "
        "same source, against the exact distances above; time = setup + propagation; errors over the vertices at positive "
        "distance (thesis eq. 4.4.1 for the mean). Its paths to T1-T3 are made locally shortest (`set_path_shortening`: "
        "straight in every unfolding of the faces they cross, through saddle and border vertices only), and their "
        "lengths compared with the exact distances.\n"
     << flat_md.str() << "\nFlat-exact ran on every mesh with every vertex reached: " << (flat_ok ? "yes" : "NO")
     << " (its accuracy is reported, not checked).\n";
  return ok;
}

} // namespace mdcs_cli

