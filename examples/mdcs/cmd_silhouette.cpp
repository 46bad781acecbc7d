// `mdcs silhouette`: its option table and its run (cmd_silhouette.h).
#include "cmd_silhouette.h"
#include "commands.h"

#include <cmath>
#include <iostream>

namespace mdcs_cli {

Command_spec silhouette_spec()
{
  Command_spec s;
  s.name = "silhouette";
  s.synopsis = "MESH [options]";
  s.description =
    "Simplified silhouette of a triangle mesh (thesis chapter 5). A coarse mesh (half-edge collapses, smoothing)\n"
    "guides the choice of fine silhouette loops (picking, method A) or the minimal-weight loops of fine edges that\n"
    "follow the coarse silhouette loops (mapping, method B, min cut).\n";
  s.positionals = {{"MESH", "OFF, PLY, OBJ or STL, a valid oriented manifold mesh (otherwise refused, exit 3, saying\n"
                            "why; larger faces are triangulated, with a note), or the generated @torus / @icosphere"}};
  s.min_positionals = s.max_positionals = 1;
  s.options = {
    list_option("view", "A,E", "30,20", 2, 2, -3600, 3600, "perspective eye at azimuth A and elevation E degrees (E in (-90, 90)),\n"
                "2.5 diagonals away"),
    text_option("up", "AXIS", "y", "the up axis of the orbit: x, y or z", {"x", "y", "z"}),
    flag_option("orthographic", "orthographic view along the same direction instead of the perspective eye"),
    text_option("method", "M", "both", "picking, mapping or both", {"picking", "mapping", "both"}),
    integer_option("coarse-faces", "N", "1000", 4, 10000000, "faces of the coarse mesh"),
    real_option("alpha", "A", "0.1", 0, 1, "weight factor of fine silhouette edges in loop mapping", true),
    integer_option("frames", "N", "0", 0, 3600, "also a rotation of N frames (frames.csv, frame_NNN.svg; computed in\n"
                   "parallel, --threads) and the temporal-coherence metric with and without the\n"
                   "previous-frame remedy"),
    flag_option("repair", "run CGAL's soup repair on a file that is not a valid mesh instead of refusing it (it\n"
                "changes the surface; said on stderr, in the summaries and in the pictures' titles)"),
  };
  add_common_options(s, Common_options{"silhouette_out", true, true});
  s.notes =
    "Files in the output folder: loops.csv (every loop of the view: set fine / coarse / picked / mapped, loop, closed,\n"
    "position, vertex, x, y, z), coarse.off (the coarse mesh the coarse loops index), silhouette.svg/.png (front\n"
    "and side views; not with --no-picture), frames.csv and frame_NNN.svg with --frames, summary.txt, summary.json.\n"
    "Exit code 1 when a consistency check fails (a loop that is not closed or not made of mesh edges).\n";
  return s;
}

int run_silhouette_command(Invocation& run)
{
  using namespace sil_detail;
  const Parsed_options& o = run.options;
  Run_parameters p;
  const std::vector<double> view = o.list("view");
  p.azimuth = view[0];
  p.elevation = view[1];
  if(!(std::abs(p.elevation) < 90)) throw Usage_error("--view: the elevation must be in (-90, 90) degrees (got '" + o.text("view") + "')");
  const std::string up = o.text("up");
  p.up = up == "x" ? 0 : up == "y" ? 1 : 2;
  const std::string method = o.text("method");
  p.picking = method != "mapping";
  p.mapping = method != "picking";
  p.coarse_faces = std::size_t(o.integer("coarse-faces"));
  p.alpha = o.real("alpha");
  p.frames = long(o.integer("frames"));
  p.orthographic = o.flag("orthographic");
  p.threads = run.threads.used();
  p.picture = run.picture();
  const std::string path = o.positional().front();
  p.name = path[0] == '@' ? path.substr(1) + " (generated)" : std::filesystem::path(path).filename().string();
  const auto t_read = std::chrono::steady_clock::now();
  bool repaired = false;
  const Mesh fine = read_triangle_mesh(path, o.flag("repair"), &repaired);
  if(repaired) p.name += " (repaired by CGAL's soup repair)";
  const double seconds_read = seconds_since(t_read);
  const auto folder = prepare_output_folder(o.text("output"));
  Run_summary sum = run_silhouette(fine, p, folder, run.progress);
  sum.report += "  threads: " + threads_text(run.threads) + "\n  summary: " + (folder / "summary.txt").string() + " " +
                (folder / "summary.json").string() + "\n";
  std::cout << sum.report;
  const int code = sum.consistent ? EXIT_OK : EXIT_FAILURE_RUNTIME;
  write_text_file((folder / "summary.txt").string(), sum.report);
  Run_summary_json json;
  json.files = sum.files;
  json.files.push_back((folder / "summary.txt").string());
  json.inputs.add("mesh", path).add("repaired", repaired).add("faces", (unsigned long long)sum.fine_faces).add("vertices", (unsigned long long)fine.number_of_vertices());
  json.timings.add("read", seconds_read).add("preprocessing", sum.preprocess_s).add("extraction", sum.extract_ms / 1e3)
    .add("picking", sum.picking_ms / 1e3).add("mapping", sum.mapping_ms / 1e3).add("rotation", sum.rotation_s)
    .add("temporal_coherence", sum.coherence_s).add("output", sum.output_s);
  Json_object edges, loops;
  edges.add("fine", (unsigned long long)sum.fine_edges).add("coarse", (unsigned long long)sum.coarse_edges)
    .add("picked", (unsigned long long)sum.picked_edges).add("mapped", (unsigned long long)sum.mapped_edges);
  loops.add("fine", (unsigned long long)sum.fine_loops).add("coarse", (unsigned long long)sum.coarse_loops)
    .add("picked", (unsigned long long)sum.picked_loops).add("mapped", (unsigned long long)sum.mapped_loops);
  json.results.add("coarse_faces", (unsigned long long)sum.coarse_faces).add("edges", edges).add("loops", loops)
    .add("loops_csv", (folder / "loops.csv").string()).add("consistent", sum.consistent);
  if(!sum.consistent) json.results.add("problem", sum.problems);
  if(p.frames > 1) {
    Json_object inc;
    const char* names[4] = {"picking", "picking_remedy", "mapping", "mapping_remedy"};
    for(int v = 0; v < 4; ++v)
      if(sum.incoherence[v] >= 0) inc.add(names[v], sum.incoherence[v]);
    json.results.add("temporal_incoherence", inc);
  }
  json.write((folder / "summary.json").string(), run, code);
  return code;
}

} // namespace mdcs_cli
