// `mdcs demo`: every capability on default data; pictures and a summary in the output folder.
#ifndef MDCS_CLI_CMD_DEMO_H
#define MDCS_CLI_CMD_DEMO_H

#include "cli_common.h"
#include "cmd_curve.h"
#include "cmd_mincut.h"
#include "demo_sections.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace mdcs_cli {

// Runs every section into `output`; returns whether every consistency check passed. `summary` receives the
// checks for summary.json.
inline bool run_demo(const std::string& output, bool quick, const Progress_bar& progress, Json_object& summary)
{
  const std::filesystem::path folder = prepare_output_folder(output);
  const long lines = quick ? 300 : 1600;
  const auto t_start = std::chrono::steady_clock::now();

  std::ostringstream md;
  md << "# mdcs demo\n\nGlobally minimal discrete curves: each problem is solved by a minimum cut of the directed dual graph of a "
        "line arrangement and checked against the independent directed shortest path on the same arrangement "
        "(they must agree: the duality theorem).\n\n";
  md << "| run | grid | discrete energy | exact | relative error | cut vs path | local descent | time (s) | picture |\n";
  md << "|---|---|---:|---:|---:|---:|---:|---:|---|\n";
  bool all_ok = true;

  auto record = [&](const std::string& label, const Curve_settings& s, const Curve_run& r) {
    std::ostringstream row;
    row << std::setprecision(8);
    const double gap = std::isfinite(r.oracle_value) ? std::abs(r.oracle_value - r.curve.solver_value) / r.oracle_value : NAN;
    row << "| " << label << " | " << (s.grid == "random" ? std::to_string(s.lines) + " random lines" : "C_" + std::to_string(s.n))
        << " | " << r.curve.energy << " | " << (std::isfinite(r.exact) ? std::to_string(r.exact) : "-") << " | ";
    if(std::isfinite(r.exact)) row << std::setprecision(3) << (r.curve.energy - r.exact) / r.exact;
    else row << "-";
    row << " | " << (std::isfinite(gap) ? (std::ostringstream() << std::setprecision(2) << gap).str() : "-") << " | "
        << (std::isfinite(r.local_energy) ? (std::ostringstream() << std::setprecision(8) << r.local_energy).str() : "-")
        << " | " << std::setprecision(3) << r.seconds_grid + r.seconds_weights + r.seconds_solve << " | ["
        << s.name << ".svg](" << s.name << ".svg) |\n";
    md << row.str();
    if(!r.curve.is_feasible || (std::isfinite(gap) && gap > 1e-9)) all_ok = false;
    std::cout << "== " << label << "\n" << r.summary << "\n";
  };

  // 1. The catenoid.
  Curve_settings catenoid;
  catenoid.functional = "catenoid";
  catenoid.radius = 2;
  catenoid.lines = lines;
  catenoid.output = output;
  catenoid.name = "catenoid";
  const Curve_run cat = run_curve(catenoid, progress);
  record("catenoid R = 2", catenoid, cat);

  // 2. Goldschmidt: R = 1.7.
  Curve_settings gold = catenoid;
  gold.radius = 1.7;
  gold.name = "goldschmidt";
  const Curve_run gs = run_curve(gold, progress);
  record("surface of rotation R = 1.7 (Goldschmidt)", gold, gs);

  // 3. Blobs: fixed ends, then relaxed ends.
  Curve_settings blobs;
  blobs.functional = "blobs";
  blobs.left = VM::End_condition::fixed(0.2);
  blobs.right = VM::End_condition::fixed(0.8);
  blobs.lines = quick ? 300 : 600;
  blobs.output = output;
  blobs.name = "blobs";
  blobs.seed = 3;
  const Curve_run bl = run_curve(blobs, progress);
  record("blob density, fixed ends 0.2 -> 0.8", blobs, bl);
  Curve_settings relaxed = blobs;
  relaxed.left = VM::End_condition::range(0.1, 0.9);
  relaxed.right = VM::End_condition::range(0.4, 0.6);
  relaxed.name = "blobs_relaxed";
  const Curve_run rl = run_curve(relaxed, progress);
  record("blob density, relaxed ends [0.1,0.9] -> [0.4,0.6]", relaxed, rl);

  // 4. The regular grid C_n.
  Curve_settings regular = catenoid;
  regular.grid = "regular";
  regular.n = quick ? 8 : 12;
  regular.name = "regular";
  const Curve_run rg = run_curve(regular, progress);
  record("catenoid R = 2 on C_n", regular, rg);

  // 5. Convergence: energy error vs grid size.
  {
    const VM::Curve_problem_2 problem{CGAL::Bbox_2(-1, 0, 1, 2), VM::End_condition::fixed(2), VM::End_condition::fixed(2)};
    const double exact = VM::global_minimum_surface_of_rotation(2).energy;
    Output_file csv((folder / "convergence.csv").string());
    csv << "grid,size,edges,relative_error\n";
    VM::Svg_curve random_curve, regular_curve;
    random_curve.label = "random lines (100 .. 3200)";
    random_curve.color = "#1b9e77";
    regular_curve.label = "regular grid C_n (n = 2 .. 16)";
    regular_curve.color = "#7570b3";
    const std::vector<long> sizes = quick ? std::vector<long>{100, 200, 400} : std::vector<long>{100, 200, 400, 800, 1600, 3200};
    for(long n : sizes) {
      VM::Random_lines_options options;
      options.pencil_points = {VM::Point_2(-1, 2), VM::Point_2(1, 2)};
      const auto arrangement = VM::build_curve_arrangement_2(problem, VM::random_lines_2(problem.box, std::size_t(n), 1, options));
      const auto weights = VM::curve_edge_weights_2(arrangement, VM::Surface_of_rotation_functional());
      // The energy of the discrete optimum; the shortest path finds it in linear time (cut == path is checked
      // on every other run of the demo).
      const auto curve = VM::directed_shortest_path_2(arrangement, weights, problem);
      const double error = (curve.energy - exact) / exact;
      csv << "random," << n << "," << arrangement.number_of_edges() << "," << error << "\n";
      random_curve.points.push_back({std::log10(double(arrangement.number_of_edges())), std::log10(std::max(error, 1e-12))});
    }
    for(long n : {2L, 4L, 8L, 12L, 16L}) {
      if(quick && n > 8) break;
      const auto curve = VM::minimize_on_regular_grid_2(problem, VM::Surface_of_rotation_functional(), std::size_t(n));
      const double edges = double(n) * double(n * n + 1) * double(n * n + 1);
      const double error = (curve.energy - exact) / exact;
      csv << "C_n," << n << "," << edges << "," << error << "\n";
      regular_curve.points.push_back({std::log10(edges), std::log10(std::max(error, 1e-12))});
    }
    VM::Svg_curve_plot plot;
    plot.title = "catenoid R = 2: energy error vs grid size";
    plot.x_label = "log10 edges";
    plot.y_label = "log10 error";
    plot.xmin = 1;
    plot.xmax = 8;
    plot.ymin = -4;
    plot.ymax = 0;
    plot.preserve_aspect_ratio = false;
    plot.solution_label = "";
    plot.extra_curves = {random_curve, regular_curve};
    plot.caption_lines = {"one grid per point (random lines: seed 1, optimum by the shortest-path solver; C_n: dynamic programming)"};
    csv.commit();
    const std::string svg = (folder / "convergence.svg").string();
    {
      Output_file file(svg);
      VM::write_curve_svg(file.stream(), plot);
      file.commit();
    }
    svg_to_png(svg);
    md << "\nConvergence of the catenoid energy (see `convergence.csv`, [convergence.svg](convergence.svg)).\n";
  }

  // 6. The min-cut component on its own: the catenoid's dual network through the DIMACS reader.
  {
    const std::string dimacs = (folder / "catenoid_dual.max").string();
    const double cut_value = write_catenoid_dual_dimacs(2.0, 300, dimacs);
    const Mincut_report pf = solve_dimacs_file(dimacs, "pf");
    const Mincut_report pr = solve_dimacs_file(dimacs, "pr");
    const Mincut_report bk = solve_dimacs_file(dimacs, "bk");
    md << "\nMin-cut on the catenoid's dual network written as DIMACS (`catenoid_dual.max`, " << pr.nodes << " nodes, "
       << pr.arcs << " arcs): pseudoflow " << std::setprecision(10) << pf.value << " in " << std::setprecision(3) << pf.seconds
       << " s, push-relabel " << std::setprecision(10) << pr.value << " in " << std::setprecision(3)
       << pr.seconds << " s, Boykov-Kolmogorov " << std::setprecision(10) << bk.value << " in " << std::setprecision(3)
       << bk.seconds << " s; the curve solver's cut value was " << std::setprecision(10) << cut_value << ".\n";
    std::cout << "== min-cut on DIMACS: pseudoflow " << pf.value << " (" << pf.seconds << " s), push-relabel " << pr.value << " (" << pr.seconds << " s), BK " << bk.value << " ("
              << bk.seconds << " s), expected " << cut_value << "\n";
    for(const Mincut_report* r : {&pf, &pr, &bk})
      if(std::abs(r->value - cut_value) > 1e-9 * cut_value) all_ok = false;
  }

  // 7. Exact geodesic distances on a triangle mesh, checked against CGAL's Surface_mesh_shortest_path.
  const bool geodesics_ok = demo_geodesics(folder, quick, progress, md);
  // 8-10. Minimal surfaces, minimum weight triangulations, simplified silhouettes.
  const bool surface_ok = demo_surface(folder, quick, progress, md);
  const bool mwt_ok = demo_mwt(folder, quick, progress, md);
  const bool silhouette_ok = demo_silhouette(folder, quick, progress, md);
  summary.add("curves_and_min_cut", all_ok).add("geodesics", geodesics_ok).add("surfaces", surface_ok).add("mwt", mwt_ok)
    .add("silhouettes", silhouette_ok);
  all_ok = all_ok && geodesics_ok && surface_ok && mwt_ok && silhouette_ok;

  md << "\nTotal time " << std::setprecision(3) << seconds_since(t_start) << " s. Consistency checks: "
     << (all_ok ? "all passed" : "FAILED") << ".\n";
  write_text_file((folder / "summary.md").string(), md.str());
  std::cout << "summary: " << (folder / "summary.md").string() << (all_ok ? "" : "  (CONSISTENCY CHECK FAILED)") << "\n";
  return all_ok;
}

} // namespace mdcs_cli

#endif // MDCS_CLI_CMD_DEMO_H
