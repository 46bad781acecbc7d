// `mdcs silhouette`: its option table and its run (cmd_silhouette.h).
#include "cmd_silhouette.h"
#include "commands.h"

#include <cmath>
#include <iostream>

namespace mdcs_cli {

namespace sil_detail {

Run_summary run_silhouette(const Mesh& fine, const Run_parameters& p, const std::filesystem::path& folder, const Progress_bar& progress)
{
  Run_summary sum;
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(fine);
  auto t0 = std::chrono::steady_clock::now();
  SS::Coarse_mesh_options co;
  co.target_faces = p.coarse_faces;
  const auto coarse = SS::build_coarse_mesh(fine, get(CGAL::vertex_point, fine), co, std::ref(progress));
  progress.begin("silhouette preprocessing");
  Simplifier s(fine, coarse.mesh, coarse.coarse_face_of_fine_face);
  if(p.hierarchy) s.build_silhouette_hierarchy();
  progress.end();
  sum.preprocess_s = seconds_since(t0);
  sum.fine_faces = num_faces(fine);
  sum.coarse_faces = num_faces(coarse.mesh);

  SS::Loop_mapping_options mo;
  mo.alpha = p.alpha;
  Camera cam = orbit_camera(box, p.azimuth, p.elevation, p.up);
  cam.perspective = !p.orthographic;
  auto view_of = [&](const Camera& c) { return p.orthographic ? View::orthographic(c.f) : View::perspective(c.eye); };
  SS::Silhouette_frame frame;
  t0 = std::chrono::steady_clock::now();
  s.extract(view_of(cam), frame);
  sum.extract_ms = ms_since(t0);
  if(p.picking) { t0 = std::chrono::steady_clock::now(); s.pick_loops(frame); sum.picking_ms = ms_since(t0); }
  if(p.mapping) { t0 = std::chrono::steady_clock::now(); s.map_loops(frame, mo); sum.mapping_ms = ms_since(t0); }
  check_frame(s, frame, sum);
  sum.fine_edges = frame.fine_silhouette.size();
  sum.coarse_edges = frame.coarse_silhouette.size();
  sum.picked_edges = frame.picked_halfedges().size();
  sum.mapped_edges = frame.mapped_halfedges().size();
  sum.fine_loops = frame.fine_loops.size();
  sum.coarse_loops = frame.coarse_loops.size();
  sum.picked_loops = frame.picked.size();
  sum.mapped_loops = frame.mapped.size();

  t0 = std::chrono::steady_clock::now();
  const std::string loops_csv = (folder / "loops.csv").string(), coarse_off = (folder / "coarse.off").string();
  write_loops_csv(loops_csv, s, frame, p);
  write_off_checked(coarse_off, coarse.mesh);
  sum.files = {loops_csv, coarse_off};
  const std::string svg = (folder / "silhouette.svg").string();
  if(p.picture) {
    std::vector<Edge_set> sets;
    sets.push_back({"fine silhouette, " + std::to_string(sum.fine_edges) + " edges", "#444", frame.fine_silhouette, 0.8});
    sets.push_back({"coarse silhouette, " + std::to_string(sum.coarse_edges) + " edges", "#1f77b4", frame.coarse_silhouette, 1.2});
    if(p.picking) sets.push_back({"picked (A), " + std::to_string(sum.picked_edges) + " edges", "#2ca02c", frame.picked_halfedges(), 1.0});
    if(p.mapping) sets.push_back({"mapped (B), " + std::to_string(sum.mapped_edges) + " edges", "#d62728", frame.mapped_halfedges(), 1.0});
    write_svg(svg, s, {cam, side_camera(cam)}, {"front", "side"}, sets,
              p.name + ": " + std::to_string(sum.fine_faces) + " faces, coarse " + std::to_string(sum.coarse_faces) + " faces");
    sum.files.push_back(svg);
    if(svg_to_png(svg)) sum.files.push_back((folder / "silhouette.png").string());
  }
  sum.output_s = seconds_since(t0);

  if(p.frames > 1) {
    t0 = std::chrono::steady_clock::now();
    const std::string frames_csv = (folder / "frames.csv").string();
    Output_file csv(frames_csv);
    csv << "frame,azimuth_deg,fine_edges,picked_edges,mapped_edges\n";
    // The rotation: its frames in parallel (simplify_silhouette_frames; every frame equals the per-view calls),
    // delivered in order, one at a time, possibly on a worker thread: no thread-local state below.
    std::vector<View> views;
    std::vector<Camera> cameras;
    for(long t = 0; t < p.frames; ++t) {
      Camera c = orbit_camera(box, p.azimuth + 360.0 * double(t) / double(p.frames), p.elevation, p.up);
      c.perspective = !p.orthographic;
      cameras.push_back(c);
      views.push_back(view_of(c));
    }
    SS::Silhouette_frames_options fo;
    fo.pick = p.picking;
    fo.map = p.mapping;
    fo.mapping = mo;
    fo.threads = p.threads;
    auto stage = [&progress](const char* name, double f) { return progress(name, f); };
    SS::simplify_silhouette_frames<CGAL::Parallel_if_available_tag>(
      s, views, fo,
      [&](std::size_t t, SS::Silhouette_frame& cur) {
        const double az = p.azimuth + 360.0 * double(t) / double(p.frames);
        check_frame(s, cur, sum);
        if(p.picture) {
          std::vector<Edge_set> fs = {{"fine, " + std::to_string(cur.fine_silhouette.size()) + " edges", "#444", cur.fine_silhouette, 0.8}};
          if(p.picking) fs.push_back({"picked, " + std::to_string(cur.picked_halfedges().size()) + " edges", "#2ca02c", cur.picked_halfedges(), 1.0});
          if(p.mapping) fs.push_back({"mapped, " + std::to_string(cur.mapped_halfedges().size()) + " edges", "#d62728", cur.mapped_halfedges(), 1.0});
          std::ostringstream name;
          name << "frame_" << std::setw(p.frames > 1000 ? 4 : 3) << std::setfill('0') << t << ".svg";
          write_svg((folder / name.str()).string(), s, {cameras[t]}, {"front"}, fs, p.name + ", azimuth " + std::to_string(int(az)) + " deg");
        }
        csv << t << "," << az << "," << cur.fine_silhouette.size() << "," << cur.picked_halfedges().size() << ","
            << cur.mapped_halfedges().size() << "\n";
      },
      CGAL::Min_cut::Default_max_flow_engine(), stage);
    csv.commit();
    sum.files.push_back(frames_csv);
    if(p.picture) sum.files.push_back((folder / "frame_*.svg").string());
    sum.rotation_s = seconds_since(t0);
    // Temporal coherence over small steps (0.5 degree), both methods, with and without the remedy (frame t biased
    // by frame t - 1: simplify_silhouette_frames runs the biased method in view order, the extraction in parallel).
    t0 = std::chrono::steady_clock::now();
    std::vector<View> steps;
    for(long t = 0; t < 40; ++t) steps.push_back(view_of(orbit_camera(box, p.azimuth + 0.5 * double(t), p.elevation, p.up)));
    for(int variant = 0; variant < 4; ++variant) {
      const bool mapping = variant >= 2, remedy = variant % 2 == 1;
      if((mapping && !p.mapping) || (!mapping && !p.picking)) continue;
      std::vector<std::vector<std::uint32_t>> fsets, ssets;
      SS::Silhouette_frames_options co = fo;
      co.pick = !mapping;
      co.map = mapping;
      if(remedy) { co.picking.previous_bias = p.remedy_bias; co.mapping.previous_bias = p.remedy_bias; }
      auto step_progress = [&progress, variant](const char*, double f) { return progress("temporal coherence", (variant + f) / 4.0); };
      SS::simplify_silhouette_frames<CGAL::Parallel_if_available_tag>(
        s, steps, co,
        [&](std::size_t, SS::Silhouette_frame& cur) {
          std::vector<std::uint32_t> f, e;
          for(std::uint32_t h : cur.fine_silhouette) f.push_back(s.fine().edge(h));
          for(std::uint32_t h : mapping ? cur.mapped_halfedges() : cur.picked_halfedges()) e.push_back(s.fine().edge(h));
          fsets.push_back(std::move(f));
          ssets.push_back(std::move(e));
        },
        CGAL::Min_cut::Default_max_flow_engine(), step_progress);
      sum.incoherence[variant] = SS::temporal_incoherence(ssets, fsets);
    }
    progress("temporal coherence", 1.0);
    sum.coherence_s = seconds_since(t0);
  }
  std::ostringstream r;
  r << p.name << ": fine " << sum.fine_faces << " faces, coarse " << sum.coarse_faces << " faces (preprocessing "
    << std::setprecision(3) << sum.preprocess_s << " s)\n"
    << "  silhouette: fine " << sum.fine_edges << " edges in " << sum.fine_loops << " loops, coarse " << sum.coarse_edges
    << " edges in " << sum.coarse_loops << " loops (extraction + decomposition " << sum.extract_ms << " ms"
    << (p.hierarchy ? ", fine silhouette through the edge hierarchy" : "") << ")\n";
  if(p.picking) r << "  loop picking: " << sum.picked_loops << " loops, " << sum.picked_edges << " edges, " << sum.picking_ms << " ms\n";
  if(p.mapping) r << "  loop mapping: " << sum.mapped_loops << " loops, " << sum.mapped_edges << " edges, " << sum.mapping_ms << " ms\n";
  if(p.frames > 1) {
    r << "  temporal incoherence (simplified change / true change, 40 steps of 0.5 deg):";
    const char* names[4] = {"picking", "picking+remedy", "mapping", "mapping+remedy"};
    for(int v = 0; v < 4; ++v)
      if(sum.incoherence[v] >= 0) r << " " << names[v] << " " << sum.incoherence[v];
    r << "\n";
  }
  r << "  checks (closed loops of mesh edges, picked edges on the fine silhouette): "
    << (sum.consistent ? "passed" : "FAILED: " + sum.problems) << "\n";
  r << "  files:";
  for(const std::string& f : sum.files) r << " " << f;
  r << "\n";
  sum.report = r.str();
  return sum;
}

} // namespace sil_detail

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
    flag_option("hierarchy", "find the fine silhouettes through a bounding-cone hierarchy over the fine mesh's edges,\n"
                "built once in the preprocessing (identical silhouettes; quicker per view on large meshes,\n"
                "e.g. with --frames)"),
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
  p.hierarchy = o.flag("hierarchy");
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
  json.inputs.add("mesh", path).add("repaired", repaired).add("hierarchy", p.hierarchy).add("faces", (unsigned long long)sum.fine_faces).add("vertices", (unsigned long long)fine.number_of_vertices());
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
