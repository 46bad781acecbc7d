// `mdcs geodesics`: geodesic distances and shortest paths on a triangle mesh (Polyhedral_geodesics_3: exact, or an
// approximate method of the package, or CGAL's heat method; --compare-exact measures the error), drawn as a shaded
// picture with iso-distance lines (geodesic_render.h) and written as a PLY file with the distance of every vertex.
#ifndef MDCS_CLI_CMD_GEODESICS_H
#define MDCS_CLI_CMD_GEODESICS_H

#include "cli_common.h"
#include "cmd_mincut.h" // Input_error
#include "geodesic_locations.h"
#include "geodesic_render.h"
#include "mesh_input.h"

#include <CGAL/Polyhedral_geodesics_3.h>
#include <CGAL/Polyhedral_geodesics_3/Dijkstra_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Fast_marching_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Flat_exact_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Merged_window_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/geodesic_distance_error.h>

#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#ifndef MDCS_CGAL_MESH_DIR
#define MDCS_CGAL_MESH_DIR ""
#endif

namespace mdcs_cli {

namespace PG = CGAL::Polyhedral_geodesics_3;

inline const char* geodesics_usage()
{
  return
    "usage: mdcs geodesics MESH --source SPEC [options]\n"
    "Geodesic distances on a triangle mesh from one or more sources (CGAL::Polyhedral_geodesics_3: exact interval\n"
    "propagation by default, or an approximate method), shortest paths to targets, a picture and a PLY file with\n"
    "every distance.\n"
    "  MESH               OFF, PLY, OBJ or STL file, or @torus / @icosphere (generated meshes). The file must be a\n"
    "                     valid oriented manifold mesh: otherwise mdcs refuses it (exit 3) and says why (an edge\n"
    "                     shared by 3 faces, a pinched vertex, inconsistent orientation, a Moebius strip, ...).\n"
    "                     Faces with more than three corners are triangulated (with a note). Vertex indices are\n"
    "                     the file's; face indices the file's for a triangle mesh (distances.ply lists the mesh).\n"
    "  --repair           run CGAL's soup repair on a file that is not a valid mesh instead of refusing it; it\n"
    "                     changes the surface (merges, reorients, cuts non-manifold parts open): said on stderr\n"
    "                     and in summary.txt, and indices then refer to the repaired mesh\n"
    "  --source SPEC      comma-separated sources: vertex indices (0,17) and/or surface points f:FACE:B0:B1:B2\n"
    "                     (weights of the face's corners in the order distances.ply lists them; >= 0, normalised)\n"
    "  --targets SPEC     shortest paths to these points, same syntax (default: the farthest reachable vertex)\n"
    "  --method M         exact (default): interval (window) propagation, Exact_geodesic_distances_3\n"
    "                     flat-exact: one interval per edge (thesis ch. 4.3), Flat_exact_geodesic_distances_3\n"
    "                     merged:EPS: windows merged when their distances differ by at most EPS times the mean\n"
    "                       edge length (thesis ch. 4.2; merged:0 is exact), Merged_window_geodesic_distances_3\n"
    "                     fmm: fast marching (Kimmel-Sethian), Fast_marching_geodesic_distances_3\n"
    "                     dijkstra: shortest paths along mesh edges, Dijkstra_geodesic_distances_3\n"
    "                     heat, heat-idt: CGAL::Heat_method_3 (direct / intrinsic Delaunay); vertex sources only,\n"
    "                       no paths, no --limit or --stop-at-targets\n"
    "  --limit D          stop the propagation at geodesic distance D (farther vertices: unreachable)\n"
    "  --stop-at-targets  stop as soon as the target distances are final (other vertices may stay unreachable)\n"
    "  --shorten-paths    make each path locally shortest (straight in every unfolding, bending only at saddle\n"
    "                     and border vertices; set_path_shortening): for the approximate methods, whose traced\n"
    "                     paths bend where a geodesic does not\n"
    "  --memory MODE      full (default): the whole distance field, needed for paths | distances: vertex\n"
    "                     distances only, less memory, no paths\n"
    "  --view X,Y,Z       direction from the mesh towards the viewer (default 1,1,1; orthographic projection)\n"
    "  --up X,Y,Z         direction drawn upwards (default 0,1,0)\n"
    "  --levels N         about N iso-distance lines at round values (default 20; 0: none)\n"
    "  --compare-exact    also run the exact method (same sources and limits); report its time and the error of\n"
    "                     --method: mean relative error (thesis eq. 4.4.1), max relative and absolute error\n"
    "  --compare-cgal     also run CGAL::Surface_mesh_shortest_path; report the largest difference and both times\n"
    "  --output DIR       output folder (default mdcs-output): distances.ply, geodesics.svg (.png with\n"
    "                     rsvg-convert), summary.txt\n"
    "  --quiet            no progress bar\n"
    "distances.ply is ASCII: per vertex x y z, 'float distance' (-1 for unreachable vertices, which no viewer\n"
    "mistakes for a distance) and the colour of the picture's map (grey: unreachable).\n"
    "A malformed or out-of-range --source/--targets, an unknown --method or a surface-point source with the heat\n"
    "method is a command-line error (exit 2); a mesh that cannot be read, has no face or cannot be triangulated is\n"
    "bad input (exit 3).\n";
}

// The distance method of `--method`.
enum class Geo_method_kind { exact, flat_exact, merged, fmm, dijkstra, heat, heat_idt };

struct Geo_method
{
  Geo_method_kind kind = Geo_method_kind::exact;
  double merge_eps = 0; // merged: the tolerance in units of the mean edge length
  std::string text = "exact";

  bool is_heat() const { return kind == Geo_method_kind::heat || kind == Geo_method_kind::heat_idt; }
  bool is_exact() const { return kind == Geo_method_kind::exact; }
  bool has_windows() const { return kind == Geo_method_kind::exact || kind == Geo_method_kind::merged; }
  // A short description, e.g. for the picture's title: "<description> on MESH".
  std::string description() const
  {
    switch(kind) {
    case Geo_method_kind::exact: return "exact geodesic distances";
    case Geo_method_kind::flat_exact: return "flat-exact geodesic distances";
    case Geo_method_kind::merged: return "merged-window geodesic distances (tolerance " + geo_detail::number_text(merge_eps, 3) + " x mean edge)";
    case Geo_method_kind::fmm: return "fast marching geodesic distances";
    case Geo_method_kind::dijkstra: return "Dijkstra distances along edges";
    case Geo_method_kind::heat: return "heat method distances (CGAL, direct)";
    case Geo_method_kind::heat_idt: return "heat method distances (CGAL, intrinsic Delaunay)";
    }
    return text;
  }
  // The class that computes it.
  std::string class_name() const
  {
    switch(kind) {
    case Geo_method_kind::exact: return "CGAL::Polyhedral_geodesics_3::Exact_geodesic_distances_3";
    case Geo_method_kind::flat_exact: return "CGAL::Polyhedral_geodesics_3::Flat_exact_geodesic_distances_3";
    case Geo_method_kind::merged: return "CGAL::Polyhedral_geodesics_3::Merged_window_geodesic_distances_3";
    case Geo_method_kind::fmm: return "CGAL::Polyhedral_geodesics_3::Fast_marching_geodesic_distances_3";
    case Geo_method_kind::dijkstra: return "CGAL::Polyhedral_geodesics_3::Dijkstra_geodesic_distances_3";
    case Geo_method_kind::heat: return "CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<Direct>";
    case Geo_method_kind::heat_idt: return "CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<Intrinsic_Delaunay>";
    }
    return text;
  }
};

inline Geo_method parse_geo_method(const std::string& text)
{
  Geo_method m;
  m.text = text;
  if(text == "exact") m.kind = Geo_method_kind::exact;
  else if(text == "flat-exact") m.kind = Geo_method_kind::flat_exact;
  else if(text == "fmm") m.kind = Geo_method_kind::fmm;
  else if(text == "dijkstra") m.kind = Geo_method_kind::dijkstra;
  else if(text == "heat") m.kind = Geo_method_kind::heat;
  else if(text == "heat-idt") m.kind = Geo_method_kind::heat_idt;
  else if(text.compare(0, 7, "merged:") == 0) {
    m.kind = Geo_method_kind::merged;
    const std::string eps = text.substr(7);
    char* end = nullptr;
    m.merge_eps = std::strtod(eps.c_str(), &end);
    if(eps.empty() || *end != '\0' || !std::isfinite(m.merge_eps) || m.merge_eps < 0)
      throw Usage_error("--method merged:EPS needs a finite number EPS >= 0 (the tolerance in mean edge lengths; got '" + eps + "')");
  } else {
    throw Usage_error("--method must be exact, flat-exact, merged:EPS, fmm, dijkstra, heat or heat-idt (got '" + text + "')");
  }
  return m;
}

struct Geodesics_settings
{
  std::string mesh;
  std::string sources, targets;
  double limit = -1; // < 0: none
  bool stop_at_targets = false;
  bool full_field = true;
  Geo_vec view = {{1, 1, 1}}, up = {{0, 1, 0}};
  long levels = 20;
  Geo_method method;
  bool compare_exact = false;
  bool compare_cgal = false;
  bool shorten_paths = false;
  std::string output = "mdcs-output";
  bool quiet = false;
  bool repair = false; // --repair: CGAL's soup repair on a file that is not a valid mesh
};

struct Geodesic_target_report
{
  Geo_location where;
  double distance = std::numeric_limits<double>::infinity();
  double path_length = NAN;
  std::size_t path_points = 0;
  std::vector<Geo_point> path; // from the target to its nearest source
  bool automatic = false;      // the farthest vertex, chosen because no target was given
  std::string path_error;      // why the path tracing failed (empty when it did not)
  double cgal_distance = NAN;  // Surface_mesh_shortest_path's distance (with --compare-cgal)
  double exact_distance = NAN; // the exact method's distance at a vertex target (with --compare-exact)
};

struct Geodesics_run
{
  std::string mesh_name;
  std::size_t V = 0, F = 0, isolated = 0;
  std::vector<std::string> notes; // repairs, triangulation
  std::vector<Geo_location> sources;
  std::vector<double> distance; // per vertex, +inf when unreachable
  double max_distance = 0;      // largest finite distance (0 when none)
  std::size_t farthest = 0, reachable = 0;
  PG::Geodesic_statistics stats;
  double seconds_read = 0, seconds_setup = 0, seconds_compute = 0, seconds_output = 0;
  std::vector<Geodesic_target_report> targets;
  double iso_spacing = 0;
  // CGAL::Surface_mesh_shortest_path on the same input (with --compare-cgal)
  bool compared = false;
  double cgal_seconds = 0, max_relative_difference = 0, max_absolute_difference = 0;
  std::size_t compared_vertices = 0, reachability_mismatches = 0;
  // the exact method on the same input (with --compare-exact)
  bool exact_compared = false;
  double exact_seconds = 0;
  PG::Geodesic_distance_error error;
  double mean_edge_length = 0, merge_tolerance = 0; // merged:EPS: EPS x the mean edge length
  std::string ply, svg, png, summary_file, summary;

  // Counts the reachable vertices and finds the farthest one, from `distance`.
  void find_farthest()
  {
    for(std::size_t i = 0; i < V; ++i)
      if(std::isfinite(distance[i])) {
        ++reachable;
        if(distance[i] > max_distance || reachable == 1) max_distance = std::max(max_distance, distance[i]), farthest = i;
      }
  }

  // The targets of the paths: those given, else the farthest vertex (if any is reachable at a positive distance).
  std::vector<Geo_location> wanted_targets(const std::vector<Geo_location>& given) const
  {
    std::vector<Geo_location> wanted = given;
    if(wanted.empty() && reachable > 0 && max_distance > 0) {
      Geo_location far;
      far.index = farthest;
      far.text = std::to_string(farthest);
      wanted.push_back(far);
    }
    return wanted;
  }
};


// ------------------------------------------------------------------------------------------------------------

inline Geodesics_settings parse_geodesics_settings(const Options& o)
{
  Geodesics_settings s;
  s.sources = o.text("source", "");
  s.targets = o.text("targets", "");
  if(o.has("limit")) {
    s.limit = o.number("limit", -1);
    if(!(s.limit >= 0) || !std::isfinite(s.limit)) throw Usage_error("--limit must be a finite number >= 0");
  }
  s.stop_at_targets = o.has("stop-at-targets");
  o.text("stop-at-targets", "");
  const std::string memory = o.text("memory", "full");
  if(memory != "full" && memory != "distances") throw Usage_error("--memory must be full or distances (got '" + memory + "')");
  s.full_field = memory == "full";
  auto vector3 = [&](const char* name, Geo_vec fallback) {
    const std::string t = o.text(name, "");
    if(t.empty()) return fallback;
    Geo_vec v;
    char c1 = 0, c2 = 0;
    std::istringstream in(t);
    if(!(in >> v[0] >> c1 >> v[1] >> c2 >> v[2]) || c1 != ',' || c2 != ',' || !(in >> std::ws).eof())
      throw Usage_error(std::string("--") + name + " must be X,Y,Z (got '" + t + "')");
    if(!(geo_detail::dot(v, v) > 0) || !std::isfinite(geo_detail::dot(v, v)))
      throw Usage_error(std::string("--") + name + " must be a non-zero finite vector");
    return v;
  };
  s.view = vector3("view", s.view);
  s.up = vector3("up", s.up);
  s.levels = o.integer("levels", s.levels, 0);
  s.method = parse_geo_method(o.text("method", "exact"));
  s.compare_exact = o.has("compare-exact");
  o.text("compare-exact", "");
  s.compare_cgal = o.has("compare-cgal");
  o.text("compare-cgal", "");
  s.shorten_paths = o.has("shorten-paths");
  o.text("shorten-paths", "");
  s.output = o.text("output", s.output);
  s.quiet = o.has("quiet");
  o.text("quiet", "");
  s.repair = o.has("repair");
  o.text("repair", "");
  return s;
}

// The distances of one method of the package (every class shares the facade's interface): sources, limits,
// propagation, vertex distances, and the distances and shortest paths of the targets, written into `run`.
template <class Geodesics, class Make>
void run_geodesic_class(Make make, const Geo_mesh& mesh, const Geodesics_settings& s, const std::vector<Geo_location>& targets,
                        Geodesics_run& run, Progress_bar& progress)
{
  const double inf = std::numeric_limits<double>::infinity();
  auto vertex = [](std::size_t i) { return Geo_mesh::Vertex_index(Geo_mesh::size_type(i)); };
  auto face_location = [](const Geo_location& loc) {
    const auto w = face_location_weights(loc);
    return typename Geodesics::Face_location(Geo_mesh::Face_index(Geo_mesh::size_type(loc.index)), {{w[0], w[1], w[2]}});
  };

  // The propagation.
  const auto t_setup = std::chrono::steady_clock::now();
  Geodesics geodesics = make(s.full_field ? PG::Geodesic_memory_mode::full_field : PG::Geodesic_memory_mode::distances_only);
  for(const Geo_location& loc : run.sources) {
    if(loc.at_vertex) geodesics.add_source(vertex(loc.index));
    else geodesics.add_source(face_location(loc));
  }
  if(s.limit >= 0) geodesics.set_distance_limit(s.limit);
  if(s.stop_at_targets) {
    std::vector<Geo_mesh::Vertex_index> stop;
    for(const Geo_location& loc : targets) {
      if(loc.at_vertex) stop.push_back(vertex(loc.index));
      else for(auto c : face_corners(mesh, Geo_mesh::Face_index(Geo_mesh::size_type(loc.index)))) stop.push_back(c);
    }
    geodesics.set_stop_targets(stop);
  }
  run.seconds_setup = seconds_since(t_setup);
  const auto t_compute = std::chrono::steady_clock::now();
  geodesics.compute([&](const char* stage, double fraction) { return progress(stage, fraction); });
  run.seconds_compute = seconds_since(t_compute);
  run.stats = geodesics.statistics();

  std::vector<double> field(run.V, inf);
  geodesics.distances(boost::make_iterator_property_map(field.begin(), get(boost::vertex_index, mesh)));
  run.distance = field;
  run.find_farthest();

  // Targets: distances and shortest paths.
  geodesics.set_path_shortening(s.shorten_paths);
  for(const Geo_location& loc : run.wanted_targets(targets)) {
    Geodesic_target_report r;
    r.where = loc;
    r.automatic = targets.empty();
    if(loc.at_vertex) r.distance = run.distance[loc.index];
    else r.distance = s.full_field ? double(geodesics.distance(face_location(loc))) : NAN;
    if(s.full_field) {
      // A failure of the path tracing is reported for this target; the distances and the other paths stay useful.
      try {
        if(loc.at_vertex) geodesics.shortest_path_points(vertex(loc.index), std::back_inserter(r.path));
        else geodesics.shortest_path_points(face_location(loc), std::back_inserter(r.path));
      } catch(const std::exception& e) {
        r.path.clear();
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

// CGAL's heat method: vertex distances only (sources at vertices; no paths, no limits). The precomputation
// (matrices and their factorisations, and the intrinsic Delaunay triangulation for heat-idt) is the setup time.
template <class Mode>
void run_heat_method(const Geo_mesh& mesh, const std::vector<Geo_location>& targets, Geodesics_run& run, Progress_bar& progress)
{
  typedef CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<Geo_mesh, Mode> Heat;
  progress("heat method", 0.0);
  const auto t_setup = std::chrono::steady_clock::now();
  Heat heat(mesh);
  for(const Geo_location& loc : run.sources) heat.add_source(Geo_mesh::Vertex_index(Geo_mesh::size_type(loc.index)));
  run.seconds_setup = seconds_since(t_setup);
  const auto t_compute = std::chrono::steady_clock::now();
  std::vector<double> field(run.V, std::numeric_limits<double>::infinity());
  heat.estimate_geodesic_distances(boost::make_iterator_property_map(field.begin(), get(boost::vertex_index, mesh)));
  run.seconds_compute = seconds_since(t_compute);
  progress("heat method", 1.0);
  run.distance = field;
  run.find_farthest();
  for(const Geo_location& loc : run.wanted_targets(targets)) {
    Geodesic_target_report r;
    r.where = loc;
    r.automatic = targets.empty();
    r.distance = loc.at_vertex ? run.distance[loc.index] : NAN; // no distances inside faces
    run.targets.push_back(r);
  }
}

// Runs everything on a mesh that is already loaded (the demo loads it to choose its sources). With
// --compare-exact, `exact_reference` (when given: a run of the exact method on the same mesh and settings)
// saves the second propagation.
inline Geodesics_run run_geodesics_on(const Geo_mesh& mesh, const std::string& mesh_name, const std::vector<std::string>& notes,
                                      double seconds_read, const Geodesics_settings& s, Progress_bar& progress,
                                      const Geodesics_run* exact_reference = nullptr)
{
  const double inf = std::numeric_limits<double>::infinity();
  const Geo_method& method = s.method;
  Geodesics_run run;
  run.mesh_name = mesh_name;
  run.notes = notes;
  run.seconds_read = seconds_read;
  run.V = mesh.number_of_vertices();
  run.F = mesh.number_of_faces();
  for(Geo_mesh::Vertex_index v : mesh.vertices()) run.isolated += mesh.is_isolated(v) ? 1 : 0;

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

  for(Geo_mesh::Edge_index e : mesh.edges()) run.mean_edge_length += std::sqrt(CGAL::squared_distance(mesh.point(mesh.vertex(e, 0)), mesh.point(mesh.vertex(e, 1))));
  if(mesh.number_of_edges() > 0) run.mean_edge_length /= double(mesh.number_of_edges());
  run.merge_tolerance = method.merge_eps * run.mean_edge_length;

  // The distances.
  typedef PG::Geodesic_memory_mode Mode;
  switch(method.kind) {
  case Geo_method_kind::exact:
    run_geodesic_class<PG::Exact_geodesic_distances_3<Geo_mesh>>(
      [&](Mode mode) { return PG::Exact_geodesic_distances_3<Geo_mesh>(mesh, mode); }, mesh, s, targets, run, progress);
    break;
  case Geo_method_kind::merged:
    run_geodesic_class<PG::Merged_window_geodesic_distances_3<Geo_mesh>>(
      [&](Mode mode) { return PG::Merged_window_geodesic_distances_3<Geo_mesh>(mesh, run.merge_tolerance, mode); }, mesh, s, targets, run,
      progress);
    break;
  case Geo_method_kind::flat_exact:
    run_geodesic_class<PG::Flat_exact_geodesic_distances_3<Geo_mesh>>(
      [&](Mode mode) { return PG::Flat_exact_geodesic_distances_3<Geo_mesh>(mesh, mode); }, mesh, s, targets, run, progress);
    break;
  case Geo_method_kind::fmm:
    run_geodesic_class<PG::Fast_marching_geodesic_distances_3<Geo_mesh>>(
      [&](Mode mode) { return PG::Fast_marching_geodesic_distances_3<Geo_mesh>(mesh, mode); }, mesh, s, targets, run, progress);
    break;
  case Geo_method_kind::dijkstra:
    run_geodesic_class<PG::Dijkstra_geodesic_distances_3<Geo_mesh>>(
      [&](Mode mode) { return PG::Dijkstra_geodesic_distances_3<Geo_mesh>(mesh, mode); }, mesh, s, targets, run, progress);
    break;
  case Geo_method_kind::heat:
    run_heat_method<CGAL::Heat_method_3::Direct>(mesh, targets, run, progress);
    break;
  case Geo_method_kind::heat_idt:
    run_heat_method<CGAL::Heat_method_3::Intrinsic_Delaunay>(mesh, targets, run, progress);
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
      PG::Exact_geodesic_distances_3<Geo_mesh> geodesics(mesh, PG::Geodesic_memory_mode::distances_only);
      for(const Geo_location& loc : run.sources) {
        const auto w = face_location_weights(loc);
        if(loc.at_vertex) geodesics.add_source(Geo_mesh::Vertex_index(Geo_mesh::size_type(loc.index)));
        else geodesics.add_source(PG::Exact_geodesic_distances_3<Geo_mesh>::Face_location(Geo_mesh::Face_index(Geo_mesh::size_type(loc.index)), {{w[0], w[1], w[2]}}));
      }
      if(s.limit >= 0) geodesics.set_distance_limit(s.limit);
      if(s.stop_at_targets) {
        std::vector<Geo_mesh::Vertex_index> stop;
        for(const Geo_location& loc : targets) {
          if(loc.at_vertex) stop.push_back(Geo_mesh::Vertex_index(Geo_mesh::size_type(loc.index)));
          else for(auto c : face_corners(mesh, Geo_mesh::Face_index(Geo_mesh::size_type(loc.index)))) stop.push_back(c);
        }
        geodesics.set_stop_targets(stop);
      }
      geodesics.compute([&](const char*, double fraction) { return progress("exact propagation (--compare-exact)", fraction); });
      exact.assign(run.V, inf);
      geodesics.distances(boost::make_iterator_property_map(exact.begin(), get(boost::vertex_index, mesh)));
      run.exact_seconds = seconds_since(t_exact);
    }
    run.exact_compared = true;
    const auto index = get(boost::vertex_index, mesh);
    run.error = PG::geodesic_distance_error(mesh, boost::make_iterator_property_map(run.distance.cbegin(), index),
                                            boost::make_iterator_property_map(exact.cbegin(), index));
    for(auto& t : run.targets)
      if(t.where.at_vertex) t.exact_distance = exact[t.where.index];
  }

  // CGAL's Surface_mesh_shortest_path on the same sources, for comparison.
  if(s.compare_cgal) {
    typedef CGAL::Surface_mesh_shortest_path_traits<Geo_kernel, Geo_mesh> Smsp_traits;
    typedef CGAL::Surface_mesh_shortest_path<Smsp_traits> Smsp;
    const auto t_cgal = std::chrono::steady_clock::now();
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

  // Outputs.
  const auto t_output = std::chrono::steady_clock::now();
  const std::filesystem::path folder = prepare_output_folder(s.output);
  Geodesic_picture pic;
  pic.points.resize(run.V);
  for(Geo_mesh::Vertex_index v : mesh.vertices()) pic.points[v.idx()] = geo_detail::vec(mesh.point(v));
  for(Geo_mesh::Face_index f : mesh.faces()) {
    const auto c = face_corners(mesh, f);
    pic.triangles.push_back({{c[0].idx(), c[1].idx(), c[2].idx()}});
  }
  pic.distance = run.distance;
  pic.max_distance = run.max_distance;
  for(const Geo_location& loc : run.sources) pic.sources.push_back(geo_detail::vec(location_point(mesh, loc)));
  for(const auto& t : run.targets) {
    pic.targets.push_back(geo_detail::vec(location_point(mesh, t.where)));
    std::vector<Geo_vec> path;
    for(const Geo_point& p : t.path) path.push_back(geo_detail::vec(p));
    pic.paths.push_back(path);
  }
  run.ply = (folder / "distances.ply").string();
  const std::string what = method.description();
  write_distance_ply(run.ply, pic.points, pic.triangles, run.distance, run.max_distance,
                     what.substr(0, what.find(" distances")) + " distance"); // "exact geodesic distance", ...
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
  run.iso_spacing = pic.iso_spacing;
  if(svg_to_png(run.svg)) run.png = (folder / "geodesics.png").string();
  run.seconds_output = seconds_since(t_output);

  // Summary.
  std::ostringstream sum;
  sum.precision(10);
  sum << "mesh: " << mesh_name << " (" << run.V << " vertices, " << run.F << " faces";
  if(run.isolated) sum << ", " << run.isolated << " isolated vertices";
  sum << ")\n";
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
  if(run.iso_spacing > 0) sum << "picture: iso-lines every " << geo_detail::number_text(run.iso_spacing) << "\n";
  run.summary_file = (folder / "summary.txt").string();
  sum << "files: " << run.ply << ", " << run.svg << (run.png.empty() ? "" : ", " + run.png) << ", " << run.summary_file << "\n";
  run.summary = sum.str();
  std::ofstream(run.summary_file) << run.summary;
  return run;
}

inline Geodesics_run run_geodesics(const Geodesics_settings& s, Progress_bar& progress)
{
  // Parse the sources and targets before reading the mesh, so that a malformed command line fails at once.
  parse_geo_locations(s.sources, "source");
  parse_geo_locations(s.targets, "targets");
  const auto t0 = std::chrono::steady_clock::now();
  Geo_mesh mesh;
  std::vector<std::string> notes;
  load_geodesics_mesh(s.mesh, mesh, notes, s.repair);
  for(const std::string& note : notes) std::cerr << "mdcs geodesics: note: " << note << "\n";
  const double seconds_read = seconds_since(t0);
  const std::string name = s.mesh[0] == '@' ? s.mesh.substr(1) + " (generated)" : std::filesystem::path(s.mesh).filename().string();
  return run_geodesics_on(mesh, name, notes, seconds_read, s, progress);
}

inline int command_geodesics(const Options& o)
{
  if(o.has("help")) {
    std::cout << geodesics_usage();
    return EXIT_OK;
  }
  Geodesics_settings s = parse_geodesics_settings(o);
  o.reject_unknown();
  if(o.positional().size() != 1) throw Usage_error("mdcs geodesics needs exactly one mesh (a file, @torus or @icosphere)");
  s.mesh = o.positional().front();
  if(s.sources.empty()) throw Usage_error("--source is required");
  Progress_bar progress(s.quiet);
  const Geodesics_run run = run_geodesics(s, progress);
  std::cout << run.summary;
  return EXIT_OK;
}

} // namespace mdcs_cli

#endif // MDCS_CLI_CMD_GEODESICS_H
