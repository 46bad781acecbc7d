// The results of one run of `mdcs geodesics` (cmd_geodesics.h), and their check before anything is reported: every
// distance finite (or +infinity where unreachable) and >= 0, every vertex source at 0, and no distance beyond the
// total length of the mesh's edges (no geodesic is longer than the shortest edge path, which is shorter).
#ifndef MDCS_CLI_GEODESICS_RESULTS_H
#define MDCS_CLI_GEODESICS_RESULTS_H

#include "cli_common.h"
#include "geodesic_locations.h"
#include "geodesic_soup.h"
#include "mesh_input.h"

#include <CGAL/Polyhedral_geodesics_3/Geodesic_types.h>
#include <CGAL/Polyhedral_geodesics_3/geodesic_distance_error.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace mdcs_cli {

namespace PG = CGAL::Polyhedral_geodesics_3;

// One node of a shortest path as a mesh location (the GeodesicPathVisitor's calls): a vertex, a crossing of the edge
// (a, b) at (1 - t) a + t b, or a point of a face with barycentric weights of its corners in listing order.
struct Geo_path_node
{
  enum Kind { vertex, edge, face } kind = vertex;
  std::size_t index = 0, a = 0, b = 0; // vertex or face index; the edge's end vertices
  double t = 0;
  std::array<double, 3> weights = {{0, 0, 0}};
};

struct Geodesic_target_report
{
  Geo_location where;
  double distance = std::numeric_limits<double>::infinity();
  double path_length = NAN;
  std::size_t path_points = 0;
  std::vector<Geo_point> path; // from the target to its nearest source
  std::vector<Geo_path_node> sequence; // the same path as mesh locations
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
  std::vector<std::string> files; // every file written, in order
  std::size_t components = 0, components_with_sources = 0; // the heat method: connected components
  std::size_t isolines = 0;                                 // polylines in isolines.csv
  Geo_surface_shape surface; // as given (and its shape report), or repaired (geodesic_soup.h)

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


// Refuses distances that cannot be right (see the file comment); `method` names the method in the message.
template <class Surface>
void check_geodesic_distances(const Surface& mesh, const Geodesics_run& run, const std::string& method)
{
  const Geo_edge_stats edges = geo_edge_lengths(mesh);
  const double total_length = edges.total, longest = edges.longest;
  const double bound = total_length * (1 + 1e-9) + longest; // a face-point source adds at most one edge length
  auto refuse = [&](std::size_t v, const std::string& what) {
    std::ostringstream m;
    m.precision(17);
    m << method << " returned " << what << " at vertex " << v << " (distance " << run.distance[v] << ")";
    if(run.distance[v] >= std::numeric_limits<double>::max())
      m << "; the largest double is what CGAL's heat method returns where it fails";
    throw Result_error(m.str());
  };
  for(std::size_t v = 0; v < run.distance.size(); ++v) {
    const double d = run.distance[v];
    if(std::isnan(d)) refuse(v, "NaN");
    if(d == std::numeric_limits<double>::infinity()) continue; // unreachable
    if(!std::isfinite(d) || d < -1e-12 * bound) refuse(v, "a distance that is not a finite number >= 0");
    if(d > bound) refuse(v, "a distance longer than all the mesh's edges together");
  }
  // A vertex source at 0 exactly; the heat method's values are approximate: within 1e-3 mean edge lengths.
  const double mean_edge = edges.mean();
  const double tolerance = method.find("heat") != std::string::npos ? 1e-3 * mean_edge : 0;
  for(const Geo_location& s : run.sources)
    if(s.at_vertex && !(std::abs(run.distance[s.index]) <= tolerance)) refuse(s.index, "a source that is not at distance 0");
}

} // namespace mdcs_cli

#endif // MDCS_CLI_GEODESICS_RESULTS_H
