// `mdcs geodesics`: geodesic distances and shortest paths on a triangle mesh (Polyhedral_geodesics_3: exact, or an
// approximate method of the package, or CGAL's heat method; --compare-exact measures the error). The distances are
// checked (geodesics_results.h) before anything is reported, then drawn (geodesic_render.h) and written as data
// (geodesic_export.h). The options are in geodesics_options.h.
#ifndef MDCS_CLI_CMD_GEODESICS_H
#define MDCS_CLI_CMD_GEODESICS_H

#include "cli_common.h"
#include "geodesic_export.h"
#include "geodesic_heat.h"
#include "geodesic_isolines.h"
#include "geodesic_locations.h"
#include "geodesic_render.h"
#include "geodesics_options.h"
#include "geodesics_results.h"
#include "geodesic_soup.h"
#include "mesh_input.h"

#include <CGAL/Polyhedral_geodesics_3.h>
#include <CGAL/Polyhedral_geodesics_3/Dijkstra_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Fast_marching_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Flat_exact_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Merged_window_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/geodesic_distance_error.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <boost/iterator/function_output_iterator.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace mdcs_cli {

// Records a shortest path as mesh locations (a GeodesicPathVisitor).
struct Path_sequence_recorder
{
  const Geo_mesh& mesh;
  std::vector<Geo_path_node>& nodes;

  void operator()(Geo_mesh::Vertex_index v)
  {
    Geo_path_node n;
    n.kind = Geo_path_node::vertex;
    n.index = v.idx();
    nodes.push_back(n);
  }
  void operator()(Geo_mesh::Halfedge_index h, double t)
  {
    Geo_path_node n;
    n.kind = Geo_path_node::edge;
    n.a = mesh.source(h).idx();
    n.b = mesh.target(h).idx();
    n.t = t;
    nodes.push_back(n);
  }
  void operator()(Geo_mesh::Face_index f, const std::array<double, 3>& b)
  {
    // Face_location order (source(h), target(h), target(next(h)) of h = halfedge(f)) is corners 2, 0, 1 of the
    // listing order (face_corners()).
    Geo_path_node n;
    n.kind = Geo_path_node::face;
    n.index = f.idx();
    n.weights = {{b[1], b[2], b[0]}};
    nodes.push_back(n);
  }
};

// The same for a soup (the visitor of Triangle_soup: vertex indices, soup half-edges, faces with their weights
// in the order of the triangle's corners, which is the listing order).
struct Soup_path_recorder
{
  std::vector<Geo_path_node>& nodes;

  void operator()(std::size_t v)
  {
    Geo_path_node n;
    n.kind = Geo_path_node::vertex;
    n.index = v;
    nodes.push_back(n);
  }
  void operator()(const PG::Triangle_soup_halfedge& h, double t)
  {
    Geo_path_node n;
    n.kind = Geo_path_node::edge;
    n.a = h.source;
    n.b = h.target;
    n.t = t;
    nodes.push_back(n);
  }
  void operator()(std::size_t f, const std::array<double, 3>& b)
  {
    Geo_path_node n;
    n.kind = Geo_path_node::face;
    n.index = f;
    n.weights = b;
    nodes.push_back(n);
  }
};

// What the geodesic classes need from each kind of surface: the mesh type they are templated on, what their
// constructors take, vertex descriptors, face locations, the vertex index map, and the path visitor.
template <class Surface> struct Geo_surface_traits
{
  typedef Geo_mesh Triangle_mesh;
  static const Geo_mesh& solver_input(const Geo_mesh& m) { return m; }
  static Geo_mesh::Vertex_index vertex(std::size_t i) { return Geo_mesh::Vertex_index(Geo_mesh::size_type(i)); }
  // Face_location coordinates refer to source(h), target(h), target(next(h)) of h = halfedge(f).
  static std::pair<Geo_mesh::Face_index, std::array<double, 3>> face_location(const Geo_location& loc)
  {
    return {Geo_mesh::Face_index(Geo_mesh::size_type(loc.index)), face_location_weights(loc)};
  }
  static auto index_map(const Geo_mesh& m) { return get(boost::vertex_index, m); }
  static Path_sequence_recorder recorder(const Geo_mesh& m, std::vector<Geo_path_node>& nodes) { return {m, nodes}; }
};
template <> struct Geo_surface_traits<Geo_soup>
{
  typedef PG::Triangle_soup Triangle_mesh;
  static const auto& solver_input(const Geo_soup& s) { return s.surface; }
  static std::size_t vertex(std::size_t i) { return i; }
  static std::pair<std::size_t, std::array<double, 3>> face_location(const Geo_location& loc) { return {loc.index, loc.weights}; }
  static boost::typed_identity_property_map<std::size_t> index_map(const Geo_soup&) { return {}; }
  static Soup_path_recorder recorder(const Geo_soup&, std::vector<Geo_path_node>& nodes) { return {nodes}; }
};

inline Geo_point geo_to_point(const Geo_point& p) { return p; }
inline Geo_point geo_to_point(const std::array<double, 3>& p) { return Geo_point(p[0], p[1], p[2]); }

// The distances of one method of the package (every class shares the facade's interface): sources, limits,
// propagation, vertex distances (checked), and the distances and shortest paths of the targets, into `run`.
// The exact method's distances-only propagation runs on the parallel schedule with every thread count, 1 included,
// so that its distances do not depend on --threads (bit for bit); the other classes have no such option.
template <class Geodesics>
void set_geodesics_threads(Geodesics&, std::size_t)
{}
template <class TM, class FT, class VPM>
void set_geodesics_threads(PG::Exact_geodesic_distances_3<TM, FT, VPM>& geodesics, std::size_t threads)
{
  if(CGAL::MDCS::has_parallel_support())
    geodesics.set_concurrency(CGAL::Parallel_tag(), threads);
}

template <class Geodesics, class Make, class Surface>
void run_geodesic_class(Make make, const Surface& mesh, const Geodesics_settings& s, const std::vector<Geo_location>& targets,
                        Geodesics_run& run, const Progress_bar& progress)
{
  typedef Geo_surface_traits<Surface> Traits;
  const double inf = std::numeric_limits<double>::infinity();
  auto vertex = [](std::size_t i) { return Traits::vertex(i); };
  auto face_location = [](const Geo_location& loc) { return typename Geodesics::Face_location(Traits::face_location(loc)); };

  // The propagation.
  const auto t_setup = std::chrono::steady_clock::now();
  progress.begin("setup");
  Geodesics geodesics = make(s.full_field ? PG::Geodesic_memory_mode::full_field : PG::Geodesic_memory_mode::distances_only);
  set_geodesics_threads(geodesics, s.thread_count);
  for(const Geo_location& loc : run.sources) {
    if(loc.at_vertex) geodesics.add_source(vertex(loc.index));
    else geodesics.add_source(face_location(loc));
  }
  if(s.limit >= 0) geodesics.set_distance_limit(s.limit);
  if(s.stop_at_targets) {
    std::vector<typename Geodesics::vertex_descriptor> stop;
    for(const Geo_location& loc : targets) {
      if(loc.at_vertex) stop.push_back(vertex(loc.index));
      else for(std::size_t c : geo_triangle(mesh, loc.index)) stop.push_back(vertex(c));
    }
    geodesics.set_stop_targets(stop);
  }
  run.seconds_setup = seconds_since(t_setup);
  const auto t_compute = std::chrono::steady_clock::now();
  geodesics.compute([&](const char* stage, double fraction) { return progress(stage, fraction); });
  progress.end();
  run.seconds_compute = seconds_since(t_compute);
  run.stats = geodesics.statistics();

  std::vector<double> field(run.V, inf);
  geodesics.distances(boost::make_iterator_property_map(field.begin(), Traits::index_map(mesh)));
  run.distance = field;
  check_geodesic_distances(mesh, run, s.method.class_name());
  run.find_farthest();

  // Targets: distances and shortest paths.
  geodesics.set_path_shortening(s.shorten_paths);
  for(const Geo_location& loc : run.wanted_targets(targets)) {
    Geodesic_target_report r;
    r.where = loc;
    r.automatic = targets.empty();
    if(loc.at_vertex) r.distance = run.distance[loc.index];
    else r.distance = s.full_field ? double(geodesics.distance(face_location(loc))) : NAN;
    if(!std::isnan(r.distance) && !(r.distance >= 0))
      throw Result_error(s.method.class_name() + " returned the distance " + std::to_string(r.distance) + " at " + describe_location(loc));
    if(s.full_field && std::isfinite(r.distance)) {
      // A failure of the path tracing is reported for this target; the distances and the other paths stay useful.
      try {
        auto recorder = Traits::recorder(mesh, r.sequence);
        auto points = boost::make_function_output_iterator([&r](const auto& p) { r.path.push_back(geo_to_point(p)); });
        if(loc.at_vertex) {
          geodesics.shortest_path_points(vertex(loc.index), points);
          if(s.export_data) geodesics.shortest_path_sequence(vertex(loc.index), recorder);
        } else {
          geodesics.shortest_path_points(face_location(loc), points);
          if(s.export_data) geodesics.shortest_path_sequence(face_location(loc), recorder);
        }
      } catch(const std::exception& e) {
        r.path.clear();
        r.sequence.clear();
        r.path_error = e.what();
        std::cerr << "mdcs geodesics: warning: no path to " << describe_location(loc) << ": " << e.what() << "\n";
      }
      r.path_points = r.path.size();
      if(!r.path.empty()) {
        r.path_length = 0;
        for(std::size_t i = 0; i + 1 < r.path.size(); ++i) r.path_length += std::sqrt(CGAL::squared_distance(r.path[i], r.path[i + 1]));
      }
    }
    run.targets.push_back(r);
  }
}

// CGAL's heat method on every connected component that holds a source (geodesic_heat.h): vertex distances only
// (no paths, no limits). The precomputation (matrices and their factorisations, and the intrinsic Delaunay
// triangulation for heat-idt) is the setup time.
template <class Mode>
void run_heat_method(const Geo_mesh& mesh, const Geodesics_settings& s, const std::vector<Geo_location>& targets,
                     Geodesics_run& run, const Progress_bar& progress)
{
  std::vector<std::size_t> sources;
  for(const Geo_location& loc : run.sources) sources.push_back(loc.index);
  const Heat_result heat = heat_distances_per_component<Mode>(mesh, sources, progress);
  run.seconds_setup = heat.seconds_setup;
  run.seconds_compute = heat.seconds_compute;
  run.components = heat.components;
  run.components_with_sources = heat.components_with_sources;
  run.distance = heat.distance;
  check_geodesic_distances(mesh, run, s.method.class_name());
  run.find_farthest();
  for(const Geo_location& loc : run.wanted_targets(targets)) {
    Geodesic_target_report r;
    r.where = loc;
    r.automatic = targets.empty();
    r.distance = loc.at_vertex ? run.distance[loc.index] : NAN; // no distances inside faces
    run.targets.push_back(r);
  }
}

// The files of a run (distances.ply, paths, iso-lines, the picture, summary.txt) and the summary text.
template <class Surface>
void write_geodesics_outputs(const Surface& mesh, const Geodesics_settings& s, Geodesics_run& run, const Progress_bar& progress)
{
  progress.begin("writing the outputs");
  const Geo_method& method = s.method;
  const std::string& mesh_name = run.mesh_name;
  const auto t_output = std::chrono::steady_clock::now();
  const std::filesystem::path folder = prepare_output_folder(s.output);
  Geodesic_picture pic;
  pic.points.resize(run.V);
  for(std::size_t v = 0; v < run.V; ++v) pic.points[v] = geo_detail::vec(geo_vertex_point(mesh, v));
  for(std::size_t f = 0; f < run.F; ++f) pic.triangles.push_back(geo_triangle(mesh, f));
  pic.distance = run.distance;
  pic.max_distance = run.max_distance;
  run.ply = (folder / "distances.ply").string();
  const std::string what = method.description();
  write_distance_ply(run.ply, pic.points, pic.triangles, run.distance, run.max_distance,
                     what.substr(0, what.find(" distances")) + " distance"); // "exact geodesic distance", ...
  run.files.push_back(run.ply);
  run.iso_spacing = run.max_distance > 0 ? geo_detail::nice_spacing(run.max_distance, s.levels) : 0;
  if(s.export_data) {
    const std::string paths_json = (folder / "paths.json").string(), paths_csv = (folder / "paths.csv").string(),
                      isolines_csv = (folder / "isolines.csv").string();
    write_paths_json(paths_json, run, mesh);
    write_paths_csv(paths_csv, run);
    const std::vector<Isoline> lines =
      compute_isolines(pic.points, pic.triangles, run.distance, run.iso_spacing, run.max_distance, 3 * s.levels + 3);
    run.isolines = lines.size();
    write_isolines_csv(isolines_csv, lines);
    run.files.insert(run.files.end(), {paths_json, paths_csv, isolines_csv});
  }
  if(s.picture) {
    for(const Geo_location& loc : run.sources) pic.sources.push_back(geo_detail::vec(location_point(mesh, loc)));
    for(const auto& t : run.targets) {
      pic.targets.push_back(geo_detail::vec(location_point(mesh, t.where)));
      std::vector<Geo_vec> path;
      for(const Geo_point& p : t.path) path.push_back(geo_detail::vec(p));
      pic.paths.push_back(path);
    }
    pic.view = s.view;
    pic.up = s.up;
    pic.levels = s.levels;
    std::ostringstream title, c1, c2;
    title << method.description() << " on " << mesh_name;
    c1 << run.V << " vertices, " << run.F << " faces; " << run.sources.size() << (run.sources.size() == 1 ? " source" : " sources")
       << std::setprecision(3);
    if(method.is_heat()) c1 << "; precomputation " << run.seconds_setup << " s, solve " << run.seconds_compute << " s";
    else if(method.has_windows()) c1 << "; propagation " << run.seconds_compute << " s, " << run.stats.windows_created << " windows created";
    else c1 << "; propagation " << run.seconds_compute << " s, " << run.stats.vertex_updates << " vertex updates";
    if(run.reachable == 0) c2 << "no vertex reachable";
    else c2 << "max distance " << std::setprecision(6) << run.max_distance << " (" << run.reachable << " of " << run.V << " vertices reachable)";
    for(std::size_t i = 0; i < run.targets.size() && i < 4; ++i)
      c2 << (i == 0 ? "; " : ", ") << "T" << i + 1 << " " << std::setprecision(5) << run.targets[i].distance;
    if(run.exact_compared && !method.is_exact() && run.error.compared > 0)
      c2 << "; mean error vs exact " << std::setprecision(3) << 100 * run.error.mean_relative << "%";
    pic.title = title.str();
    pic.caption_lines = {c1.str(), c2.str()};
    run.svg = (folder / "geodesics.svg").string();
    write_geodesic_svg(run.svg, pic);
    run.files.push_back(run.svg);
    if(svg_to_png(run.svg)) {
      run.png = (folder / "geodesics.png").string();
      run.files.push_back(run.png);
    }
  }
  run.seconds_output = seconds_since(t_output);
  progress.end();

  // Summary.
  std::ostringstream sum;
  sum.precision(10);
  sum << "mesh: " << mesh_name << " (" << run.V << " vertices, " << run.F << " faces";
  if(run.isolated) sum << ", " << run.isolated << " isolated vertices";
  sum << ")\n";
  sum << run.surface.text();
  for(const std::string& note : run.notes) sum << "note: " << note << "\n";
  sum << "sources: " << run.sources.size() << " (";
  for(std::size_t i = 0; i < run.sources.size() && i < 8; ++i) sum << (i ? ", " : "") << describe_location(run.sources[i]);
  if(run.sources.size() > 8) sum << ", ...";
  sum << ")\n";
  sum << "method: " << method.text << ": " << method.description() << " (" << method.class_name() << ")";
  if(method.kind == Geo_method_kind::merged)
    sum << ", merge tolerance " << method.merge_eps << " x mean edge length " << std::setprecision(4) << run.mean_edge_length << " = "
        << run.merge_tolerance << std::setprecision(10);
  sum << "\n";
  if(s.limit >= 0) sum << "distance limit: " << s.limit << "\n";
  if(!method.is_heat())
    sum << "memory mode: " << (s.full_field ? "full field" : "distances only") << (s.stop_at_targets ? ", stop at targets" : "") << "\n";
  sum << std::setprecision(4) << "time: read " << run.seconds_read << " s, " << (method.is_heat() ? "precomputation " : "setup ")
      << run.seconds_setup << " s, " << (method.is_heat() ? "solve " : "propagation ") << run.seconds_compute << " s, output "
      << run.seconds_output << " s\n";
  if(method.has_windows())
    sum << "windows: created " << run.stats.windows_created << ", propagated " << run.stats.windows_propagated << ", pruned "
        << run.stats.windows_pruned << (method.kind == Geo_method_kind::merged ? ", merged " + std::to_string(run.stats.windows_merged) : std::string())
        << ", peak live " << run.stats.peak_live_windows << ", stored " << run.stats.stored_windows
        << ", peak memory " << std::setprecision(3) << double(run.stats.peak_memory_bytes) / (1024.0 * 1024.0) << " MiB"
        << (run.stats.stopped_early ? ", stopped early" : "") << "\n";
  else if(!method.is_heat())
    sum << "vertex updates: " << run.stats.vertex_updates << ", rejected by the dependence DAG " << run.stats.updates_rejected_by_dag
        << (run.stats.stopped_early ? ", stopped early" : "") << "\n";
  sum << std::setprecision(10);
  if(run.reachable == 0) sum << "distances: no vertex is reachable (every distance is +infinity)\n";
  else sum << "distances: " << run.reachable << " of " << run.V << " vertices reachable, max distance " << run.max_distance
           << " at vertex " << run.farthest << "\n";
  for(std::size_t i = 0; i < run.targets.size(); ++i) {
    const auto& t = run.targets[i];
    sum << "target T" << i + 1 << " " << describe_location(t.where) << (t.automatic ? " (farthest vertex)" : "") << ": ";
    if(std::isnan(t.distance))
      sum << (method.is_heat() ? "distance n/a (face point: the heat method gives vertex distances only)"
                               : "distance n/a (face point: needs --memory full)");
    else if(!std::isfinite(t.distance)) sum << "unreachable";
    else sum << "distance " << t.distance;
    if(!std::isnan(t.exact_distance) && !method.is_exact()) sum << " (exact: " << t.exact_distance << ")";
    if(!std::isnan(t.cgal_distance)) sum << " (CGAL: " << t.cgal_distance << ")";
    if(method.is_heat()) sum << ", no path (the heat method gives no paths)";
    else if(!s.full_field) sum << ", no path (--memory distances)";
    else if(!t.path_error.empty()) sum << ", path tracing FAILED: " << t.path_error;
    else if(t.path.empty()) sum << ", no path";
    else sum << ", path length " << t.path_length << (s.shorten_paths ? " (made locally shortest)" : "") << " ("
             << t.path_points << " points, relative difference to the distance "
             << std::setprecision(3) << std::abs(t.path_length - t.distance) / std::max(t.distance, 1e-300) << std::setprecision(10) << ")";
    sum << "\n";
  }
  if(run.targets.empty()) sum << "targets: none (no vertex is reachable at a positive distance)\n";
  if(run.exact_compared) {
    sum << std::setprecision(4) << "error vs exact (Exact_geodesic_distances_3, " << run.exact_seconds << " s; this method: "
        << run.seconds_setup + run.seconds_compute << " s";
    if(method.is_exact()) sum << "; the method is exact";
    sum << "): over " << run.error.compared << " vertices mean relative error " << std::setprecision(4) << 100 * run.error.mean_relative
        << "%, max relative error " << 100 * run.error.max_relative << "%, max absolute error " << std::setprecision(3) << run.error.max_absolute;
    if(run.error.skipped_sources)
      sum << "; " << run.error.skipped_sources << (run.error.skipped_sources == 1 ? " vertex" : " vertices") << " at distance 0 skipped";
    if(run.error.unreachable_mismatches)
      sum << "; " << run.error.unreachable_mismatches << " vertices reachable in one and not in the other"
          << (s.limit >= 0 || s.stop_at_targets ? " (expected near the limit / the stopped front)" : "");
    sum << "\n";
  }
  if(run.compared) {
    sum << std::setprecision(4) << "CGAL Surface_mesh_shortest_path: " << run.cgal_seconds << " s (ours: " << run.seconds_setup + run.seconds_compute
        << " s); over " << run.compared_vertices << " vertices max relative difference " << std::setprecision(3) << run.max_relative_difference
        << ", max absolute difference " << run.max_absolute_difference;
    if(run.reachability_mismatches) sum << "; " << run.reachability_mismatches << " vertices reachable in one and not in the other";
    sum << "\n";
  }
  if(method.is_heat() && run.components > 1)
    sum << "components: " << run.components << " connected components, the heat method ran on the " << run.components_with_sources
        << " holding a source (the others are unreachable)\n";
  if(run.iso_spacing > 0)
    sum << "iso-lines: every " << geo_detail::number_text(run.iso_spacing) << ", " << run.isolines << " polylines\n";
  if(!s.threads.empty()) sum << "threads: " << s.threads << "\n";
  run.summary_file = (folder / "summary.txt").string();
  sum << "files:";
  for(const std::string& f : run.files) sum << " " << f;
  sum << " " << run.summary_file << " " << (folder / "summary.json").string() << "\n";
  run.summary = sum.str();
  write_text_file(run.summary_file, run.summary);
  run.files.push_back(run.summary_file);
}

// Runs everything on a mesh that is already loaded (the demo loads it to choose its sources). With
// --compare-exact, `exact_reference` (when given: a run of the exact method on the same mesh and settings)
// saves the second propagation.
template <class Surface>
Geodesics_run run_geodesics_on(const Surface& mesh, const std::string& mesh_name, const std::vector<std::string>& notes,
                               double seconds_read, const Geodesics_settings& s, const Progress_bar& progress,
                               const Geodesics_run* exact_reference = nullptr, bool repaired = false)
{
  typedef Geo_surface_traits<Surface> Traits;
  typedef typename Traits::Triangle_mesh TM;
  const auto& input = Traits::solver_input(mesh);
  const double inf = std::numeric_limits<double>::infinity();
  const Geo_method& method = s.method;
  Geodesics_run run;
  run.mesh_name = mesh_name;
  run.notes = notes;
  run.seconds_read = seconds_read;
  run.surface = geo_surface_shape(mesh, repaired);
  run.V = geo_vertex_count(mesh);
  run.F = geo_face_count(mesh);
  for(std::size_t v = 0; v < run.V; ++v) run.isolated += geo_is_isolated(mesh, v) ? 1 : 0;
  refuse_unsupported_on_soup(mesh, s);

  if(s.sources.empty()) throw Usage_error("--source is required (vertex indices such as 0,17 or face points f:FACE:B0:B1:B2)");
  run.sources = parse_geo_locations(s.sources, "source");
  validate_geo_locations(mesh, run.sources, "source");
  const std::vector<Geo_location> targets = parse_geo_locations(s.targets, "targets");
  validate_geo_locations(mesh, targets, "targets");
  if(s.stop_at_targets && targets.empty()) throw Usage_error("--stop-at-targets needs --targets");
  if(method.is_heat()) {
    for(const Geo_location& loc : run.sources)
      if(!loc.at_vertex)
        throw Usage_error("--method " + method.text + ": the heat method takes vertex sources only ('" + loc.text + "' is a surface point)");
    if(s.limit >= 0) throw Usage_error("--method " + method.text + ": the heat method has no --limit");
    if(s.stop_at_targets) throw Usage_error("--method " + method.text + ": the heat method has no --stop-at-targets");
    if(run.isolated)
      throw Input_error("the heat method needs a mesh without isolated vertices (" + std::to_string(run.isolated) + " found)");
  }

  run.mean_edge_length = geo_edge_lengths(mesh).mean();
  run.merge_tolerance = method.merge_eps * run.mean_edge_length;

  // The distances.
  typedef PG::Geodesic_memory_mode Mode;
  switch(method.kind) {
  case Geo_method_kind::exact:
    run_geodesic_class<PG::Exact_geodesic_distances_3<TM>>(
      [&](Mode mode) { return PG::Exact_geodesic_distances_3<TM>(input, mode); }, mesh, s, targets, run, progress);
    break;
  case Geo_method_kind::merged:
    run_geodesic_class<PG::Merged_window_geodesic_distances_3<TM>>(
      [&](Mode mode) { return PG::Merged_window_geodesic_distances_3<TM>(input, run.merge_tolerance, mode); }, mesh, s, targets, run,
      progress);
    break;
  case Geo_method_kind::flat_exact:
    run_geodesic_class<PG::Flat_exact_geodesic_distances_3<TM>>(
      [&](Mode mode) { return PG::Flat_exact_geodesic_distances_3<TM>(input, mode); }, mesh, s, targets, run, progress);
    break;
  case Geo_method_kind::fmm:
    run_geodesic_class<PG::Fast_marching_geodesic_distances_3<TM>>(
      [&](Mode mode) { return PG::Fast_marching_geodesic_distances_3<TM>(input, mode); }, mesh, s, targets, run, progress);
    break;
  case Geo_method_kind::dijkstra:
    run_geodesic_class<PG::Dijkstra_geodesic_distances_3<TM>>(
      [&](Mode mode) { return PG::Dijkstra_geodesic_distances_3<TM>(input, mode); }, mesh, s, targets, run, progress);
    break;
  case Geo_method_kind::heat:
  case Geo_method_kind::heat_idt:
    if constexpr(std::is_same<Surface, Geo_mesh>::value) { // refused on soups above
      if(method.kind == Geo_method_kind::heat) run_heat_method<CGAL::Heat_method_3::Direct>(mesh, s, targets, run, progress);
      else run_heat_method<CGAL::Heat_method_3::Intrinsic_Delaunay>(mesh, s, targets, run, progress);
    }
    break;
  }

  // The exact method on the same sources and limits, for the error of this one.
  if(s.compare_exact) {
    std::vector<double> exact;
    if(method.is_exact()) {
      exact = run.distance;
      run.exact_seconds = run.seconds_setup + run.seconds_compute;
    } else if(exact_reference) {
      exact = exact_reference->distance;
      run.exact_seconds = exact_reference->seconds_setup + exact_reference->seconds_compute;
    } else {
      const auto t_exact = std::chrono::steady_clock::now();
      typedef PG::Exact_geodesic_distances_3<TM> Exact;
      Exact geodesics(input, PG::Geodesic_memory_mode::distances_only);
      set_geodesics_threads(geodesics, s.thread_count);
      for(const Geo_location& loc : run.sources) {
        if(loc.at_vertex) geodesics.add_source(Traits::vertex(loc.index));
        else geodesics.add_source(typename Exact::Face_location(Traits::face_location(loc)));
      }
      if(s.limit >= 0) geodesics.set_distance_limit(s.limit);
      if(s.stop_at_targets) {
        std::vector<typename Exact::vertex_descriptor> stop;
        for(const Geo_location& loc : targets) {
          if(loc.at_vertex) stop.push_back(Traits::vertex(loc.index));
          else for(std::size_t c : geo_triangle(mesh, loc.index)) stop.push_back(Traits::vertex(c));
        }
        geodesics.set_stop_targets(stop);
      }
      geodesics.compute([&](const char*, double fraction) { return progress("exact propagation (--compare-exact)", fraction); });
      progress.end();
      exact.assign(run.V, inf);
      geodesics.distances(boost::make_iterator_property_map(exact.begin(), Traits::index_map(mesh)));
      run.exact_seconds = seconds_since(t_exact);
    }
    run.exact_compared = true;
    const auto index = Traits::index_map(mesh);
    run.error = PG::geodesic_distance_error(mesh, boost::make_iterator_property_map(run.distance.cbegin(), index),
                                            boost::make_iterator_property_map(exact.cbegin(), index));
    for(auto& t : run.targets)
      if(t.where.at_vertex) t.exact_distance = exact[t.where.index];
  }

  // CGAL's Surface_mesh_shortest_path on the same sources, for comparison (refused on soups above).
  if constexpr(std::is_same<Surface, Geo_mesh>::value)
  if(s.compare_cgal) {
    typedef CGAL::Surface_mesh_shortest_path_traits<Geo_kernel, Geo_mesh> Smsp_traits;
    typedef CGAL::Surface_mesh_shortest_path<Smsp_traits> Smsp;
    const auto t_cgal = std::chrono::steady_clock::now();
    progress.begin("CGAL Surface_mesh_shortest_path (--compare-cgal)");
    Smsp cgal(mesh);
    for(const Geo_location& loc : run.sources) {
      if(loc.at_vertex) cgal.add_source_point(Geo_mesh::Vertex_index(Geo_mesh::size_type(loc.index)));
      else {
        const auto w = face_location_weights(loc);
        cgal.add_source_point(Geo_mesh::Face_index(Geo_mesh::size_type(loc.index)), Smsp::Barycentric_coordinates{{w[0], w[1], w[2]}});
      }
    }
    cgal.build_sequence_tree();
    std::vector<double> reference(run.V, inf);
    for(Geo_mesh::Vertex_index v : mesh.vertices()) {
      if(mesh.is_isolated(v)) continue;
      const double r = CGAL::to_double(cgal.shortest_distance_to_source_points(v).first);
      if(r >= 0) reference[v.idx()] = r;
    }
    run.cgal_seconds = seconds_since(t_cgal);
    progress.end();
    run.compared = true;
    for(auto& t : run.targets) {
      const double r = t.where.at_vertex ? reference[t.where.index]
        : CGAL::to_double(cgal.shortest_distance_to_source_points(Geo_mesh::Face_index(Geo_mesh::size_type(t.where.index)),
                                                                  face_location_weights(t.where)).first);
      t.cgal_distance = r >= 0 ? r : inf;
    }
    CGAL::Bbox_3 box;
    for(Geo_mesh::Vertex_index v : mesh.vertices()) box += mesh.point(v).bbox();
    const double diag = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) + CGAL::square(box.zmax() - box.zmin()));
    const bool partial = s.limit >= 0 || s.stop_at_targets; // unreachable by choice
    for(std::size_t i = 0; i < run.V; ++i) {
      const double a = run.distance[i], b = reference[i];
      if(std::isfinite(a) && std::isfinite(b)) {
        ++run.compared_vertices;
        run.max_absolute_difference = std::max(run.max_absolute_difference, std::abs(a - b));
        run.max_relative_difference = std::max(run.max_relative_difference, std::abs(a - b) / std::max(b, 1e-9 * diag));
      } else if(std::isfinite(a) != std::isfinite(b) && !(partial && !std::isfinite(a))) {
        ++run.reachability_mismatches;
      }
    }
  }

  write_geodesics_outputs(mesh, s, run, progress);
  return run;
}
// The two runs are compiled once each, in their own translation units (cmd_geodesics.cpp: meshes,
// cmd_geodesics_soup.cpp: soups), not in every file that calls them (the demo does): each instantiates every
// geodesic class with its paths and outputs, the largest compile of the tool, and two units build in parallel.
extern template Geodesics_run run_geodesics_on<Geo_mesh>(const Geo_mesh&, const std::string&,
                                                         const std::vector<std::string>&, double,
                                                         const Geodesics_settings&, const Progress_bar&,
                                                         const Geodesics_run*, bool);
extern template Geodesics_run run_geodesics_on<Geo_soup>(const Geo_soup&, const std::string&,
                                                         const std::vector<std::string>&, double,
                                                         const Geodesics_settings&, const Progress_bar&,
                                                         const Geodesics_run*, bool);

inline Geodesics_run run_geodesics(const Geodesics_settings& s, const Progress_bar& progress)
{
  // Parse the sources and targets before reading the mesh, so that a malformed command line fails at once.
  parse_geo_locations(s.sources, "source");
  parse_geo_locations(s.targets, "targets");
  const auto t0 = std::chrono::steady_clock::now();
  Geo_mesh mesh;
  Geo_soup soup;
  std::vector<std::string> notes;
  progress.begin("reading the mesh");
  const Geo_input_kind kind = load_geodesics_input(s.mesh, mesh, soup, notes, s.repair);
  progress.end();
  for(const std::string& note : notes) std::cerr << "mdcs geodesics: note: " << note << "\n";
  const double seconds_read = seconds_since(t0);
  const std::string file = std::filesystem::path(s.mesh).filename().string();
  if(kind == Geo_input_kind::soup)
    return run_geodesics_on(soup, file + " (as given: not an oriented manifold mesh)", notes, seconds_read, s, progress);
  const std::string name = s.mesh[0] == '@' ? s.mesh.substr(1) + " (generated)"
                           : file + (kind == Geo_input_kind::repaired_mesh ? " (repaired by CGAL's soup repair)" : "");
  return run_geodesics_on(mesh, name, notes, seconds_read, s, progress, nullptr, kind == Geo_input_kind::repaired_mesh);
}

} // namespace mdcs_cli

#endif // MDCS_CLI_CMD_GEODESICS_H
