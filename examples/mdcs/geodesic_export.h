// The results of `mdcs geodesics` as data: distances.ply (every vertex distance with 17 significant digits, so
// that the exact distances can be checked to 1e-12), paths.json / paths.csv (each shortest path as points and as
// mesh locations), isolines.csv (iso-distance polylines) and summary.json. Every file is written through a
// checked Output_file (a failed write is an error, never a truncated file).
#ifndef MDCS_CLI_GEODESIC_EXPORT_H
#define MDCS_CLI_GEODESIC_EXPORT_H

#include "cli_common.h"
#include "geodesic_isolines.h"
#include "geodesics_options.h"
#include "geodesics_results.h"

#include <array>
#include <cstdio>
#include <string>
#include <vector>

namespace mdcs_cli {

// ASCII PLY: per vertex x y z and the distance as doubles (%.17g: they read back to the same double; -1 for an
// unreachable vertex, which no viewer mistakes for a distance) and the colour of the picture's map.
inline void write_distance_ply(const std::string& file, const std::vector<Geo_vec>& points,
                               const std::vector<std::array<std::size_t, 3>>& triangles, const std::vector<double>& distance,
                               double max_distance, const std::string& what)
{
  Output_file out(file);
  out << "ply\nformat ascii 1.0\n"
      << "comment mdcs geodesics: " << what << " to the nearest source; distance -1 = unreachable; 17 significant digits\n"
      << "element vertex " << points.size() << "\n"
      << "property double x\nproperty double y\nproperty double z\nproperty double distance\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      << "element face " << triangles.size() << "\n"
      << "property list uchar int vertex_indices\nend_header\n";
  char buf[200];
  for(std::size_t i = 0; i < points.size(); ++i) {
    const Geo_vec& p = points[i];
    const double dv = distance[i];
    const bool reached = std::isfinite(dv);
    const auto c = reached && max_distance > 0 ? geo_detail::colour_map(dv / max_distance) : geo_detail::unreachable_colour();
    std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g %.17g %d %d %d\n", p[0], p[1], p[2], reached ? dv : -1.0,
                  int(std::lround(255 * c[0])), int(std::lround(255 * c[1])), int(std::lround(255 * c[2])));
    out << buf;
  }
  for(const auto& t : triangles) out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  out.commit();
}

inline std::string json_point(const Geo_point& p) { return json_numbers({p.x(), p.y(), p.z()}); }

inline std::string json_path_node(const Geo_path_node& n)
{
  Json_object o;
  if(n.kind == Geo_path_node::vertex) return "{\"vertex\": " + std::to_string(n.index) + "}";
  if(n.kind == Geo_path_node::edge)
    return "{\"edge\": [" + std::to_string(n.a) + ", " + std::to_string(n.b) + "], \"t\": " + json_number(n.t) + "}";
  return "{\"face\": " + std::to_string(n.index) + ", \"weights\": " + json_numbers({n.weights[0], n.weights[1], n.weights[2]}) + "}";
}

// paths.json: the sources, and per target its distance, the path's length, its points (target first, source last)
// and the same path as mesh locations ("vertex": v | "edge": [a, b], "t": t for the point (1-t) a + t b |
// "face": f, "weights": the corners' weights in listing order). Unreachable targets have distance null and no path.
template <class Surface>
void write_paths_json(const std::string& file, const Geodesics_run& run, const Surface& mesh)
{
  Output_file out(file);
  out << "{\n  \"mesh\": " << json_string(run.mesh_name) << ",\n  \"sources\": [";
  for(std::size_t i = 0; i < run.sources.size(); ++i)
    out << (i ? ", " : "") << "{\"spec\": " << json_string(run.sources[i].text) << ", \"point\": " << json_point(location_point(mesh, run.sources[i])) << "}";
  out << "],\n  \"paths\": [";
  for(std::size_t i = 0; i < run.targets.size(); ++i) {
    const auto& t = run.targets[i];
    out << (i ? "," : "") << "\n    {\"target\": " << json_string(t.where.text) << ", \"point\": " << json_point(location_point(mesh, t.where))
        << ", \"automatic\": " << (t.automatic ? "true" : "false") << ", \"distance\": " << json_number(t.distance)
        << ", \"length\": " << json_number(t.path_length);
    if(!t.path_error.empty()) out << ", \"error\": " << json_string(t.path_error);
    out << ",\n     \"points\": [";
    for(std::size_t k = 0; k < t.path.size(); ++k) out << (k ? "," : "") << json_point(t.path[k]);
    out << "],\n     \"sequence\": [";
    for(std::size_t k = 0; k < t.sequence.size(); ++k) out << (k ? ", " : "") << json_path_node(t.sequence[k]);
    out << "]}";
  }
  out << "\n  ]\n}\n";
  out.commit();
}

// paths.csv: target, position, x, y, z (one row per path point, target first).
inline void write_paths_csv(const std::string& file, const Geodesics_run& run)
{
  Output_file out(file);
  out << "target,position,x,y,z\n";
  for(std::size_t i = 0; i < run.targets.size(); ++i)
    for(std::size_t k = 0; k < run.targets[i].path.size(); ++k) {
      const Geo_point& p = run.targets[i].path[k];
      out << i << "," << k << "," << p.x() << "," << p.y() << "," << p.z() << "\n";
    }
  out.commit();
}

// isolines.csv: level, line, closed, position, x, y, z (one row per polyline point).
inline void write_isolines_csv(const std::string& file, const std::vector<Isoline>& lines)
{
  Output_file out(file);
  out << "level,line,closed,position,x,y,z\n";
  for(std::size_t i = 0; i < lines.size(); ++i)
    for(std::size_t k = 0; k < lines[i].points.size(); ++k) {
      const Geo_vec& p = lines[i].points[k];
      out << lines[i].level << "," << i << "," << (lines[i].closed ? 1 : 0) << "," << k << "," << p[0] << "," << p[1] << "," << p[2] << "\n";
    }
  out.commit();
}

inline Run_summary_json geodesics_summary_json(const Geodesics_settings& s, const Geodesics_run& run)
{
  Run_summary_json j;
  j.inputs.add("mesh", s.mesh).add("vertices", (unsigned long long)run.V).add("faces", (unsigned long long)run.F)
    .add("isolated_vertices", (unsigned long long)run.isolated);
  j.inputs.add("surface", run.surface.json()); // which surface the distances are for
  j.timings.add("read", run.seconds_read).add("setup", run.seconds_setup).add("compute", run.seconds_compute)
    .add("output", run.seconds_output);
  if(run.exact_compared) j.timings.add("exact_reference", run.exact_seconds);
  if(run.compared) j.timings.add("cgal_surface_mesh_shortest_path", run.cgal_seconds);
  std::vector<std::string> sources;
  for(const Geo_location& l : run.sources) sources.push_back(json_string(l.text));
  j.results.add("method", s.method.text).add("class", s.method.class_name()).raw("sources", json_array(sources))
    .add("reachable_vertices", (unsigned long long)run.reachable).add("max_distance", run.reachable ? run.max_distance : NAN)
    .add("farthest_vertex", (unsigned long long)run.farthest).add("distances_ply", run.ply);
  if(s.method.is_heat())
    j.results.add("components", (unsigned long long)run.components).add("components_with_sources", (unsigned long long)run.components_with_sources);
  std::vector<std::string> targets;
  for(const auto& t : run.targets) {
    Json_object o;
    o.add("target", t.where.text).add("automatic", t.automatic).add("distance", t.distance).add("path_length", t.path_length)
      .add("path_points", (unsigned long long)t.path_points);
    if(!t.path_error.empty()) o.add("path_error", t.path_error);
    if(!std::isnan(t.exact_distance)) o.add("exact_distance", t.exact_distance);
    if(!std::isnan(t.cgal_distance)) o.add("cgal_distance", t.cgal_distance);
    targets.push_back(o.text(4));
  }
  j.results.raw("targets", json_array(targets));
  if(run.exact_compared) {
    Json_object e;
    e.add("compared_vertices", (unsigned long long)run.error.compared).add("mean_relative", run.error.mean_relative)
      .add("max_relative", run.error.max_relative).add("max_absolute", run.error.max_absolute)
      .add("unreachable_mismatches", (unsigned long long)run.error.unreachable_mismatches);
    j.results.add("error_vs_exact", e);
  }
  if(run.compared) {
    Json_object c;
    c.add("compared_vertices", (unsigned long long)run.compared_vertices).add("max_relative_difference", run.max_relative_difference)
      .add("max_absolute_difference", run.max_absolute_difference).add("reachability_mismatches", (unsigned long long)run.reachability_mismatches);
    j.results.add("cgal_surface_mesh_shortest_path", c);
  }
  if(run.iso_spacing > 0) j.results.add("iso_spacing", run.iso_spacing).add("isolines", (unsigned long long)run.isolines);
  Json_object stats;
  stats.add("windows_created", (unsigned long long)run.stats.windows_created).add("vertex_updates", (unsigned long long)run.stats.vertex_updates)
    .add("peak_memory_bytes", (unsigned long long)run.stats.peak_memory_bytes).add("stopped_early", bool(run.stats.stopped_early));
  if(!s.method.is_heat()) j.results.add("statistics", stats);
  j.notes = run.notes;
  j.notes.push_back("distances: null in JSON = unreachable (+infinity); -1 in distances.ply");
  j.files = run.files;
  return j;
}

} // namespace mdcs_cli

#endif // MDCS_CLI_GEODESIC_EXPORT_H
