// The options of `mdcs geodesics`: the method (--method), the settings of a run and the option table that
// drives both the parser and the help text.
#ifndef MDCS_CLI_GEODESICS_OPTIONS_H
#define MDCS_CLI_GEODESICS_OPTIONS_H

#include "cli_common.h"
#include "geodesic_render.h" // Geo_vec, number_text

#include <string>

namespace mdcs_cli {

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
    m.merge_eps = parse_real_text(eps, "--method merged:EPS (the tolerance in mean edge lengths)", 0, 1000);
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
  bool picture = true;
  bool export_data = true; // paths.json/.csv, isolines.csv (the demo's runs skip them)
  std::string threads;      // for the summary (empty: not printed)
  std::size_t thread_count = 1; // --threads, effective: the exact method's distances-only propagation runs on them
  bool repair = false;      // --repair: CGAL's soup repair on a file that is not a valid mesh
};

inline Command_spec geodesics_command_spec()
{
  Command_spec s;
  s.name = "geodesics";
  s.synopsis = "MESH --source SPEC [options]";
  s.description =
    "Geodesic distances on a triangle mesh from one or more sources (CGAL::Polyhedral_geodesics_3: exact interval\n"
    "propagation by default, or an approximate method), shortest paths to targets, a picture, and the results as\n"
    "data: every distance (PLY, 17 significant digits), the paths and the iso-distance lines (JSON, CSV).\n";
  s.positionals = {{"MESH", "OFF, PLY, OBJ or STL file, or @torus / @icosphere (generated meshes). A file that is not\n"
                            "an oriented manifold mesh (edges shared by 3 or more faces, pinched vertices, faces\n"
                            "oriented against each other, a Moebius strip) is used as given: edges connect the faces\n"
                            "that share their two vertex indices, paths cross into every face of an edge (exact,\n"
                            "merged:EPS and dijkstra, also --matrix; flat-exact and fmm also with pinched vertices\n"
                            "only; the heat method and --compare-cgal refuse it, exit 3, saying why); the summary\n"
                            "says so and counts the special edges and vertices. A malformed file (an index out of\n"
                            "range, ...) is refused (exit 3). Faces with more than three corners are triangulated\n"
                            "(with a note). Vertex indices are the file's; face indices the file's for a triangle\n"
                            "mesh (distances.ply lists the surface as used)."}};
  s.min_positionals = s.max_positionals = 1;
  s.options = {
    text_option("source", "SPEC", "", "comma-separated sources (required): vertex indices (0,17) and/or surface points\n"
                "f:FACE:B0:B1:B2 (weights of the face's corners in the order distances.ply lists them;\n"
                ">= 0, normalised); with --matrix: vertex indices or 'all'"),
    text_option("targets", "SPEC", "", "shortest paths to these points, same syntax (default: the farthest reachable vertex);\n"
                "with --matrix npy: the columns (vertex indices; default: every vertex)"),
    text_option("method", "M", "exact", "exact: interval (window) propagation, Exact_geodesic_distances_3\n"
                "flat-exact: one interval per edge (thesis ch. 4.3)\n"
                "merged:EPS: windows merged when their distances differ by at most EPS (0 to 1000)\n"
                "  times the mean edge length (thesis ch. 4.2; merged:0 is exact)\n"
                "fmm: fast marching (Kimmel-Sethian) | dijkstra: shortest paths along mesh edges\n"
                "heat, heat-idt: CGAL::Heat_method_3 (direct / intrinsic Delaunay), run on every\n"
                "  connected component that holds a source; vertex sources only, no paths, no --limit\n"
                "  or --stop-at-targets; meshes with degenerate (zero-area) faces are refused"),
    real_option("limit", "D", "", 0, 1e300, "stop the propagation at geodesic distance D (farther vertices: unreachable)"),
    flag_option("stop-at-targets", "stop as soon as the target distances are final (other vertices may stay unreachable)"),
    flag_option("shorten-paths", "make each path locally shortest (straight in every unfolding, bending only at saddle\n"
                "and border vertices; set_path_shortening): for the approximate methods"),
    text_option("memory", "MODE", "full", "full: the whole distance field, needed for paths | distances: vertex distances\n"
                "only, less memory, no paths", {"full", "distances"}),
    list_option("view", "X,Y,Z", "1,1,1", 3, 3, -HUGE_VAL, HUGE_VAL, "direction from the mesh towards the viewer (orthographic)"),
    list_option("up", "X,Y,Z", "0,1,0", 3, 3, -HUGE_VAL, HUGE_VAL, "direction drawn upwards"),
    integer_option("levels", "N", "20", 0, 1000, "about N iso-distance lines at round values (picture and isolines.csv; 0: none)"),
    flag_option("compare-exact", "also run the exact method (same sources and limits); report its time and the error of\n"
                "--method: mean relative error (thesis eq. 4.4.1), max relative and absolute error"),
    flag_option("compare-cgal", "also run CGAL::Surface_mesh_shortest_path; report the largest difference and both times"),
    text_option("matrix", "FORMAT", "", "distance matrix mode, rows = --source (parallel, --threads): npy: dense rows as\n"
                "DIR/distances.npy (NumPy float64, inf = unreachable or beyond --max-distance);\n"
                "mtx: the sparse matrix of the pairs within --max-distance as DIR/distances.mtx\n"
                "(Matrix Market, 1-based); no paths, no picture", {"npy", "mtx"}),
    real_option("max-distance", "D", "", 0, 1e300, "with --matrix: pairs farther than D (mesh units) are not computed; each\n"
                "source then costs what its neighbourhood costs (required by mtx)"),
    flag_option("symmetric", "with --matrix mtx --source all: a symmetric matrix, each pair the smaller of its two\n"
                "directions (equal for the exact method up to rounding; written as the lower triangle)"),
    flag_option("repair", "run CGAL's soup repair on a file that is not an oriented manifold mesh instead of using it\n"
                "as given; it changes the surface (merges, reorients, cuts non-manifold parts open and a\n"
                "Moebius strip across): said on stderr, in summary.txt and summary.json, and indices then\n"
                "refer to the repaired mesh"),
  };
  add_common_options(s, Common_options{"mdcs-output", true, true});
  s.notes =
    "Files in the output folder: distances.ply (ASCII: per vertex x y z and the distance, doubles with 17 significant\n"
    "digits, -1 for unreachable vertices, and the colour of the picture's map), paths.json (per target: distance,\n"
    "length, points, and the path as mesh locations: vertices, edge crossings, face points), paths.csv (the points),\n"
    "isolines.csv (iso-distance polylines: level, line, position, x, y, z), geodesics.svg/.png (not with\n"
    "--no-picture), summary.txt, summary.json.\n"
    "With --matrix: distances.npy or distances.mtx, summary.txt, summary.json.\n"
    "Exit codes: 2 for a malformed or out-of-range --source/--targets, an unknown --method or a surface-point source\n"
    "with the heat method; 3 for a mesh file that is malformed (the message names the line or element), has no\n"
    "face, or is a surface the method cannot handle (not an oriented manifold mesh: heat always, fmm and flat-exact\n"
    "with edges of 3+ faces or reversed gluings, --compare-cgal; degenerate faces: heat); 1 when a\n"
    "result fails its check (a distance that is not finite, a source not at 0).\n";
  return s;
}

inline Geodesics_settings parse_geodesics_settings(const Parsed_options& o)
{
  Geodesics_settings s;
  if(!o.given("matrix"))
    for(const char* name : {"max-distance", "symmetric"})
      if(o.given(name)) throw Usage_error(std::string("--") + name + " applies to --matrix only");
  if(o.text("source") == "all" && !o.given("matrix"))
    throw Usage_error("--source all needs --matrix (one distance field per source is a matrix)");
  if(!o.given("source")) throw Usage_error("--source is required (vertex indices such as 0,17 or face points f:FACE:B0:B1:B2)");
  s.sources = o.text("source");
  s.targets = o.text("targets");
  if(o.given("limit")) s.limit = o.real("limit");
  s.stop_at_targets = o.flag("stop-at-targets");
  s.full_field = o.text("memory") == "full";
  auto vector3 = [&](const char* name) {
    const std::vector<double> v = o.list(name);
    const Geo_vec g = {{v[0], v[1], v[2]}};
    const double n = geo_detail::dot(g, g);
    if(!(n > 0) || !std::isfinite(n)) throw Usage_error(std::string("--") + name + " must be a non-zero vector (got '" + o.text(name) + "')");
    return g;
  };
  s.view = vector3("view");
  s.up = vector3("up");
  s.levels = long(o.integer("levels"));
  s.method = parse_geo_method(o.text("method"));
  s.compare_exact = o.flag("compare-exact");
  s.compare_cgal = o.flag("compare-cgal");
  s.shorten_paths = o.flag("shorten-paths");
  if(s.shorten_paths && (s.method.is_heat() || !s.full_field))
    throw Usage_error("--shorten-paths needs paths: not with the heat method or --memory distances");
  s.output = o.text("output");
  s.picture = !o.flag("no-picture");
  s.repair = o.flag("repair");
  s.mesh = o.positional().front();
  return s;
}

} // namespace mdcs_cli

#endif // MDCS_CLI_GEODESICS_OPTIONS_H
