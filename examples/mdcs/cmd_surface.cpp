// `mdcs surface`: its option table and its run (cmd_surface.h).
#include "cmd_surface.h"
#include "commands.h"

#include <iostream>

namespace mdcs_cli {

Surface_run run_surface(const Surface_settings& s, const Progress_bar& progress)
{
  const auto t_start = std::chrono::steady_clock::now();
  Surface_run run;
  run.problem = surface_problem_for(s.problem, int(s.segments));
  if(!s.domain.empty()) {
    run.problem.set_domain_polygon(parse_surface_domain(s.domain, run.problem.domain));
    run.problem.validate(); // a bad polygon: std::invalid_argument with the reason
  }
  std::string functional;
  if(s.problem == "membrane") {
    VM3::Membrane_functional_3 G;
    G.k_g = 1.5;
    G.z_bottom = run.problem.zmin;
    functional = "area + 1.5 f (heavy membrane)";
    run_surface_with(s, G, run, progress);
  } else if(s.problem == "blobs") {
    const auto G = VM3::random_blob_functional_3(run.problem, 9, 2, 0.1, -1.5, std::uint64_t(s.seed) + 4);
    functional = "density-weighted area, 9 x 2 wells";
    run_surface_with(s, G, run, progress);
  } else {
    functional = "area";
    run_surface_with(s, VM3::Area_functional_3(), run, progress);
    if(s.problem == "scherk" && s.domain.empty()) run.exact = VM3::scherk_surface_area(1.2, 80);
  }
  run.seconds_total = seconds_since(t_start);
  check_surface_result(run);
  const std::filesystem::path folder = prepare_output_folder(s.output);
  std::ostringstream planes_out;
  if(s.plane_grid > 0)
    planes_out << run.grid_planes << " (regular plane grid n = " << s.plane_grid << ", m = "
               << (s.grid_offset_steps == 0 ? s.plane_grid : s.grid_offset_steps) << ", max slope " << s.max_slope << ")";
  else
    planes_out << s.planes << " (" << run.pencils << " through the boundary segments, "
               << (s.distribution == "slope" ? "slope-limited |slope| <= " + (std::ostringstream() << s.max_slope).str()
                                             : std::string("isotropic"))
               << ", seed " << s.seed << ")";
  const std::string plane_text = planes_out.str();
  const std::size_t plane_count = s.plane_grid > 0 ? run.grid_planes : std::size_t(s.planes);
  std::ostringstream sum;
  sum << std::setprecision(10);
  sum << "problem           " << s.problem << " (" << functional << ")\n"
      << "planes            " << plane_text << "\n"
      << "domain            " << (run.problem.is_polygonal() ? "polygon with " + std::to_string(run.problem.domain_polygon.size()) + " vertices, area " + (std::ostringstream() << run.problem.domain_area()).str() : std::string("rectangle")) << "\n"
      << "complex           " << run.cells << " cells, " << run.facets << " facets, " << run.vertices << " vertices\n";
  run.summary_file = (folder / (s.name + "_summary.txt")).string();
  if(!run.surface.is_feasible) {
    sum << "result            INFEASIBLE: no function on this arrangement meets the boundary condition\n"
        << "files             " << run.summary_file << ", " << (folder / (s.name + "_summary.json")).string() << "\n";
    run.summary = sum.str();
    write_text_file(run.summary_file, run.summary);
    return run;
  }
  const double gap = std::abs(run.surface.energy - run.surface.solver_value) / run.surface.energy;
  const double single = std::abs(run.surface.projected_area - run.problem.domain_area()) / run.problem.domain_area();
  sum << "discrete energy   " << run.surface.energy << " (cut value " << run.surface.solver_value
      << ", relative gap " << std::setprecision(2) << gap << ")\n" << std::setprecision(10)
      << "single-valued     projected area / domain area - 1 = " << std::setprecision(2)
      << (run.surface.projected_area / run.problem.domain_area() - 1) << (single <= 1e-9 ? " (yes)" : " (NO)") << "\n"
      << std::setprecision(10) << "surface           " << run.surface.facets.size() << " facets on "
      << run.surface.planes.size() << " planes, " << run.surface.triangles.size() << " triangles\n";
  if(!run.selection_energies.empty()) {
    sum << "plane selection   energies";
    for(double e : run.selection_energies) sum << ' ' << e;
    sum << "\n";
  }
  if(!run.refine_energies.empty()) {
    sum << "refinement        run energies";
    for(double e : run.refine_energies) sum << ' ' << e;
    sum << "; refined arrangement: " << run.refine_below << " cells below the envelope merged into the source, "
        << run.refine_above << " above into the sink, ";
    if(run.problem.is_polygonal()) sum << run.refine_outside << " outside the domain left out, ";
    sum << run.refine_nodes << " cells left in the network\n";
  }
  if(!run.tangent_energies.empty()) {
    sum << "tangent rounds    energies (cells)";
    for(std::size_t i = 0; i < run.tangent_energies.size(); ++i)
      sum << ' ' << run.tangent_energies[i] << " (" << run.tangent_cells[i] << ")";
    sum << "; best: round " << run.tangent_best << "\n";
  }
  if(std::isfinite(run.exact))
    sum << "exact area        " << run.exact << " (relative error " << std::setprecision(3)
        << (run.surface.energy - run.exact) / run.exact << ")\n" << std::setprecision(10);
  if(run.has_relaxed) {
    sum << "relaxed energy    " << run.relaxed.energy;
    if(run.relaxed.triangles.empty()) sum << " on an " << run.relaxed.n << "^2 grid (";
    else
      sum << " on a mesh of the polygon, " << run.relaxed.triangles.size() << " triangles (level " << run.relaxed.n
          << ", ";
    sum << run.relaxed.iterations << " L-BFGS iterations)";
    if(std::isfinite(run.exact))
      sum << ", relative error " << std::setprecision(3) << (run.relaxed.energy - run.exact) / run.exact;
    sum << "\n" << std::setprecision(10);
  }
  sum << std::setprecision(3) << "time              build " << run.seconds_build << " s, weights " << run.seconds_weights
      << " s, cut " << run.seconds_cut << " s" << (run.has_relaxed ? ", relaxation " : "");
  if(run.has_relaxed) sum << run.seconds_relax << " s";
  sum << ", total " << run.seconds_total << " s\n";
  progress.begin("writing the outputs");
  run.ply = (folder / (s.name + ".ply")).string();
  write_surface_ply_checked(run.ply, run.surface);
  run.files.push_back(run.ply);
  const VM3::Minimal_surface_3 shown = run.has_relaxed ? VM3::grid_surface_mesh_3(run.problem, run.relaxed) : run.surface;
  if(run.has_relaxed) {
    run.relaxed_ply = (folder / (s.name + "_relaxed.ply")).string();
    write_surface_ply_checked(run.relaxed_ply, shown);
    run.files.push_back(run.relaxed_ply);
  }
  if(s.picture) {
    run.svg = (folder / (s.name + ".svg")).string();
    std::ostringstream cap1, cap2;
    cap1 << std::setprecision(8) << run.cells << " cells from " << plane_count << (s.plane_grid > 0 ? " grid" : "")
         << " planes; discrete energy "
         << run.surface.energy << (run.has_relaxed ? ", relaxed " : "");
    if(run.has_relaxed) cap1 << run.relaxed.energy;
    const std::string relaxed_on = run.relaxed.triangles.empty()
                                     ? std::to_string(run.relaxed.n) + "^2 grid"
                                     : std::to_string(run.relaxed.triangles.size()) + "-triangle mesh";
    cap2 << (run.has_relaxed ? "relaxed surface shown (" + relaxed_on + ")" : "discrete surface shown")
         << (run.problem.is_relaxed() ? "; boundary free in the band" : "; boundary curve in red");
    write_surface_svg(run.svg, shown, run.problem, "mdcs surface: " + s.problem, {cap1.str(), cap2.str()});
    run.files.push_back(run.svg);
    if(svg_to_png(run.svg)) run.files.push_back((folder / (s.name + ".png")).string());
  }
  if(!run.descent_energies.empty()) {
    std::vector<double> sorted = run.descent_energies;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t lower = std::size_t(std::count_if(sorted.begin(), sorted.end(),
                                                        [&](double e) { return descent_is_lower(e, run.global_descent_energy); }));
    sum << std::setprecision(8) << "local descents    " << sorted.size() << " from random starts (20^2, 40^2): best "
        << sorted.front() << ", median " << sorted[sorted.size() / 2] << "; global result relaxed the same way "
        << run.global_descent_energy << " (" << lower << " of the descents lower by more than 1e-6 relative); " << std::setprecision(3)
        << run.seconds_descents << " s\n";
    if(s.picture) {
      run.histogram_svg = (folder / (s.name + "_histogram.svg")).string();
      write_descent_histogram_svg(run.histogram_svg, run.descent_energies, run.global_descent_energy,
                                  "mdcs surface " + s.problem + ": local descents vs the global result");
      run.files.push_back(run.histogram_svg);
      if(svg_to_png(run.histogram_svg)) run.files.push_back((folder / (s.name + "_histogram.png")).string());
    }
  }
  if(!s.threads.empty()) sum << "threads           " << s.threads << "\n";
  progress.end();
  sum << "files             ";
  for(const std::string& f : run.files) sum << f << ", ";
  sum << run.summary_file << ", " << (folder / (s.name + "_summary.json")).string() << "\n";
  run.summary = sum.str();
  write_text_file(run.summary_file, run.summary);
  return run;
}

Command_spec surface_spec() { return surface_command_spec(); }

int run_surface_command(Invocation& run)
{
  Surface_settings s = parse_surface_settings(run.options);
  s.threads = threads_text(run.threads);
  const Surface_run r = run_surface(s, run.progress);
  const int code = r.surface.is_feasible ? EXIT_OK : EXIT_INFEASIBLE;
  write_surface_json(s, r, run, code);
  std::cout << r.summary;
  return code;
}

} // namespace mdcs_cli
