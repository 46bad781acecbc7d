// `mdcs surface`: globally minimal discrete surfaces of bivariate variational problems (thesis ch. 2.6.2-2.7).
#ifndef MDCS_CLI_CMD_SURFACE_H
#define MDCS_CLI_CMD_SURFACE_H

#include "cli_common.h"
#include "surface_pictures.h"

#include <CGAL/Min_cut/solve_min_cut.h>
#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/analytic_solutions_3.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/plane_grids_3.h>
#include <CGAL/Variational_minimization/relax_surface_3.h>
#include <CGAL/Variational_minimization/search_surface_basins_3.h>
#include <CGAL/Variational_minimization/refine_surface_3.h>
#include <CGAL/Variational_minimization/refine_surface_by_tangent_planes_3.h>
#include <CGAL/Variational_minimization/select_planes_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <random>
#include <array>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace mdcs_cli {

namespace VM3 = CGAL::Variational_minimization;

inline Command_spec surface_command_spec()
{
  Command_spec s;
  s.name = "surface";
  s.synopsis = "[options]";
  s.description =
    "Minimise F(f) = double integral of G(f, f_x, f_y, x, y) globally over the functions made of facets of a random\n"
    "plane arrangement or of the regular plane grid (BSP cell complex, exact predicates), by a min-cut of the\n"
    "directed dual graph of its cells;\n"
    "write the surface (PLY) and a height-coloured picture (SVG, PNG where rsvg-convert exists).\n";
  s.options = {
    text_option("problem", "NAME", "saddle", "saddle (area, boundary f = x y on [-1,1]^2) | membrane (heavy membrane on a\n"
                "wavy rim) | blobs (area weighted by a density with wells: many local minima, boundary free\n"
                "in [0,1]) | scherk (area, f = ln(cos y / cos x) on [-1.2,1.2]^2; exact area known)",
                {"saddle", "membrane", "blobs", "scherk"}),
    integer_option("planes", "N", "150", 1, 1000, "planes per arrangement (cells grow like N^3: 420 planes make 3.9M cells\n"
                   "and 0.9 GB; 1000 planes about 50M cells and 12 GB)"),
    integer_option("plane-grid", "N", "0", 0, 63, "the regular plane grid G_N instead of random planes (1 to 63; 0: random\n"
                   "planes): gradients --max-slope (i, j) / N, |i|, |j| <= N, at heights spaced (zmax - zmin) / M,\n"
                   "and the pencils of slopes --max-slope t / N (t = -N..N) through every boundary segment; at\n"
                   "most 16384 planes (otherwise exit 2); the problem's rectangle only (not --domain); excludes\n"
                   "--planes, --distribution, --pencil-fraction, --seed (but for blobs) and the multi-solve methods"),
    integer_option("grid-offset-steps", "M", "0", 0, 16384, "with --plane-grid: heights per range of the grid's planes (0: M = N;\n"
                   "M = 1 makes far fewer cells)"),
    integer_option("segments", "S", "4", 1, 256, "boundary segments per side (per polygon edge) of the domain"),
    text_option("domain", "P", "", "a polygonal domain instead of the problem's rectangle: \"x0,y0;x1,y1;...\" (a simple\n"
                "polygon, at most 1000 vertices; rounded to 1/256 of its bounding box) or L (an L inside\n"
                "the rectangle)"),
    text_option("distribution", "D", "slope", "slope (slope-limited) | isotropic", {"slope", "isotropic"}),
    real_option("max-slope", "S", "3", 0, 1000, "slope bound of slope-limited planes, or the largest gradient component of\n"
                "--plane-grid (steeper planes are nearly vertical over the domain)", true),
    real_option("pencil-fraction", "F", "0.2", 0, 1, "share of the planes through the boundary segments"),
    integer_option("plane-selection", "K", "1", 1, 1000, "plane selection with K iterations (1: a single solve)"),
    integer_option("refine", "R", "0", 0, 100, "adaptive refinement: R runs give an envelope, a new arrangement of N planes\n"
                   "keeps their optima's planes and adds planes inside it (0: off)"),
    integer_option("tangent-rounds", "K", "0", 0, 1000, "tangent-plane refinement: K more arrangements of N planes, each fitted\n"
                   "to the previous optimum; the best round is kept (0: off; for smooth minimisers such as\n"
                   "scherk, with --segments 16)"),
    real_option("fit-radius", "R", "0.2", 0, 1, "radius of those fits, share of the domain's shorter side", true),
    flag_option("relax", "continue with local relaxation on 20^2, 40^2, 80^2 grids (L-BFGS; on a polygonal domain:\n"
                "on Delaunay meshes of the polygon with the edge lengths of those grids)"),
    flag_option("basin-search", "with --plane-selection K: relax every round optimum, then search neighbouring basins by\n"
                "constrained cuts tile by tile (rectangles; for many-minima problems such as blobs)"),
    integer_option("descents", "N", "0", 0, 10000, "also N local descents from random smooth starts and a histogram of their\n"
                   "relaxed energies against the global result: NAME_histogram.svg (rectangles only)"),
    text_option("engine", "E", "pf", "max-flow engine: pf (pseudoflow), pr (push-relabel), bk (Boykov-Kolmogorov)", {"pf", "pr", "bk"}),
    integer_option("seed", "S", "1", 0, 4294967295.0, "random seed"),
    text_option("name", "NAME", "", "base name of the output files (a plain file name; default: the problem name)"),
  };
  add_common_options(s, Common_options{"mdcs-output", true, true});
  s.notes =
    "Files in the output folder: NAME.ply (the discrete surface, 17 significant digits), NAME_relaxed.ply (--relax),\n"
    "NAME.svg/.png and NAME_histogram.svg (not with --no-picture), NAME_summary.txt, NAME_summary.json.\n"
    "Exit code 4: no function on this arrangement meets the boundary condition.\n";
  return s;
}

struct Surface_settings
{
  std::string problem = "saddle";
  std::string domain;
  long planes = 150;
  long plane_grid = 0;        // > 0: the regular plane grid of that order instead of random planes
  long grid_offset_steps = 0; // its height steps m (0: m = plane_grid)
  long segments = 4;
  std::string distribution = "slope";
  double max_slope = 3;
  double pencil_fraction = 0.2;
  long plane_selection = 1;
  long refine = 0;
  long tangent_rounds = 0;
  double fit_radius = 0.2;
  bool relax = false;
  bool basin_search = false;
  long descents = 0;
  std::string engine = "pf";
  long seed = 1;
  std::string output = "mdcs-output";
  std::string name;
  bool picture = true;
  std::string threads; // for the summary (empty: not printed)
};

struct Surface_run
{
  VM3::Surface_problem_3 problem;
  VM3::Minimal_surface_3 surface;
  VM3::Relaxed_surface_3 relaxed;
  bool has_relaxed = false;
  std::vector<double> selection_energies;
  std::vector<double> refine_energies;
  std::vector<double> tangent_energies;
  std::vector<std::size_t> tangent_cells;
  int tangent_best = 0;
  std::size_t refine_below = 0, refine_above = 0, refine_nodes = 0, refine_outside = 0;
  double exact = NAN;
  std::size_t cells = 0, facets = 0, vertices = 0, pencils = 0;
  std::size_t grid_planes = 0; // --plane-grid: the planes of the grid (walls not counted)
  double seconds_build = 0, seconds_weights = 0, seconds_cut = 0, seconds_relax = 0, seconds_total = 0;
  std::string ply, relaxed_ply, svg, summary, summary_file;
  std::vector<std::string> files; // written, in order
  // --descents: relaxed energies of the random-start local descents and of the global result (same relaxation)
  std::vector<double> descent_energies;
  double global_descent_energy = NAN, seconds_descents = 0;
  std::string histogram_svg;
};


inline Surface_settings parse_surface_settings(const Parsed_options& o)
{
  Surface_settings s;
  s.problem = o.text("problem");
  s.domain = o.text("domain");
  if(!s.domain.empty() && s.problem == "blobs") throw Usage_error("--domain is not available for --problem blobs");
  s.planes = long(o.integer("planes"));
  s.plane_grid = long(o.integer("plane-grid"));
  s.grid_offset_steps = long(o.integer("grid-offset-steps"));
  if(s.plane_grid == 0 && o.given("grid-offset-steps")) throw Usage_error("--grid-offset-steps applies to --plane-grid only");
  if(s.plane_grid > 0) {
    // The grid is deterministic and replaces the random planes: their options would be silently ignored.
    for(const char* random_option : {"planes", "distribution", "pencil-fraction"})
      if(o.given(random_option))
        throw Usage_error(std::string("--plane-grid replaces the random planes: it excludes --") + random_option);
    if(o.given("seed") && s.problem != "blobs")
      throw Usage_error("--plane-grid is deterministic: --seed applies to random planes (and the blobs functional) only");
    if(!s.domain.empty()) throw Usage_error("--plane-grid needs the problem's rectangle (not --domain)");
  }
  s.segments = long(o.integer("segments"));
  s.distribution = o.text("distribution");
  if(s.distribution != "slope" && o.given("max-slope")) throw Usage_error("--max-slope applies to --distribution slope only");
  s.max_slope = o.real("max-slope");
  s.pencil_fraction = o.real("pencil-fraction");
  s.plane_selection = long(o.integer("plane-selection"));
  s.refine = long(o.integer("refine"));
  if(s.refine > 0 && s.plane_selection > 1) throw Usage_error("--refine and --plane-selection exclude each other");
  s.tangent_rounds = long(o.integer("tangent-rounds"));
  if(s.tangent_rounds > 0 && (s.refine > 0 || s.plane_selection > 1))
    throw Usage_error("--tangent-rounds excludes --refine and --plane-selection");
  if(o.given("fit-radius") && s.tangent_rounds == 0) throw Usage_error("--fit-radius applies to --tangent-rounds only");
  s.fit_radius = o.real("fit-radius");
  s.relax = o.flag("relax");
  s.basin_search = o.flag("basin-search");
  if(s.basin_search && !s.domain.empty()) throw Usage_error("--basin-search needs the problem's rectangle (not --domain)");
  if(s.basin_search && s.refine > 0) throw Usage_error("--basin-search and --refine exclude each other");
  if(s.basin_search && s.tangent_rounds > 0) throw Usage_error("--basin-search and --tangent-rounds exclude each other");
  if(s.plane_grid > 0 && (s.plane_selection > 1 || s.refine > 0 || s.tangent_rounds > 0))
    throw Usage_error("--plane-grid excludes --plane-selection, --refine and --tangent-rounds (they draw random planes)");
  s.descents = long(o.integer("descents"));
  if(s.descents > 0 && !s.domain.empty()) throw Usage_error("--descents needs the problem's rectangle (not --domain)");
  s.engine = o.text("engine");
  s.seed = long(o.integer("seed"));
  s.output = o.text("output");
  s.name = checked_file_name(o.given("name") ? o.text("name") : s.problem, "--name");
  s.picture = !o.flag("no-picture");
  return s;
}

// The polygon of --domain: "x0,y0;x1,y1;..." (3 to 1000 vertices, finite coordinates) or L (an L-shaped hexagon
// filling three quarters of `box`). Whether it is simple is checked by the problem (exit code 3 if not).
inline std::vector<std::array<double, 2>> parse_surface_domain(const std::string& text, const CGAL::Bbox_2& box)
{
  if(text == "L") {
    const double x0 = box.xmin(), y0 = box.ymin(), x1 = box.xmax(), y1 = box.ymax();
    const double xm = 0.5 * (x0 + x1), ym = 0.5 * (y0 + y1);
    return {{{x0, y0}}, {{x1, y0}}, {{x1, ym}}, {{xm, ym}}, {{xm, y1}}, {{x0, y1}}};
  }
  std::vector<std::array<double, 2>> out;
  std::size_t start = 0;
  while(start <= text.size()) {
    const std::size_t end = std::min(text.find(';', start), text.size());
    const std::string vertex = text.substr(start, end - start);
    if(out.size() == 1000) throw Usage_error("--domain: more than 1000 vertices");
    const std::vector<double> v = parse_real_list_text(vertex, "--domain (vertex " + std::to_string(out.size()) + ", expected x,y)",
                                                       2, 2, -1e9, 1e9);
    out.push_back({{v[0], v[1]}});
    start = end + 1;
  }
  if(out.size() < 3) throw Usage_error("--domain: a polygon needs at least 3 vertices \"x0,y0;x1,y1;x2,y2\" (or L)");
  return out;
}

inline VM3::Surface_problem_3 surface_problem_for(const std::string& name, int segments)
{
  VM3::Surface_problem_3 P;
  P.boundary_segments_per_side = segments;
  if(name == "saddle") {
    P.domain = CGAL::Bbox_2(-1, -1, 1, 1);
    P.zmin = -1.1;
    P.zmax = 1.1;
    P.lower_boundary = [](double x, double y) { return x * y; };
  } else if(name == "membrane") {
    P.lower_boundary = [](double x, double y) { return 0.8 + 0.08 * std::sin(2 * M_PI * x) * std::cos(M_PI * y); };
  } else if(name == "blobs") {
    P.lower_boundary = [](double, double) { return 0.0; };
    P.upper_boundary = [](double, double) { return 1.0; };
  } else {
    P = VM3::scherk_surface_problem_3(segments);
  }
  return P;
}

// --descents: local descents (projected L-BFGS on 20^2 then 40^2) from random smooth starts -- bilinear on a
// random 5 x 5 grid of heights in [zmin, zmax] -- and the global result relaxed the same way, so that the
// energies are comparable (the thesis's Table 2.3: how often local optimisation finds the global basin).
template <class Functional>
void run_surface_descents(const Surface_settings& s, const Functional& G, Surface_run& run, const Progress_bar& progress)
{
  const auto t0 = std::chrono::steady_clock::now();
  VM3::Surface_relaxation_options_3 ro;
  ro.grids = {20, 40};
  run.global_descent_energy = s.basin_search ? run.relaxed.energy // the basin search relaxes on 20^2, 40^2
                                             : VM3::relax_surface_3(run.problem, G, run.surface, ro).energy;
  const VM3::Surface_problem_3& P = run.problem;
  const double x0 = P.domain.xmin(), y0 = P.domain.ymin();
  const double wx = P.domain.xmax() - x0, wy = P.domain.ymax() - y0;
  std::mt19937_64 rng(std::uint64_t(s.seed) * 7919u + 17u);
  std::uniform_real_distribution<double> height(P.zmin, P.zmax);
  run.descent_energies.clear();
  for(long k = 0; k < s.descents; ++k) {
    std::array<double, 25> c;
    for(double& v : c) v = height(rng);
    auto start = [&](double x, double y) {
      const double u = (std::min)(4.0, (std::max)(0.0, (x - x0) / wx * 4)),
                   v = (std::min)(4.0, (std::max)(0.0, (y - y0) / wy * 4));
      const int i = (std::min)(3, int(u)), j = (std::min)(3, int(v));
      const double a = u - i, e = v - j;
      return (1 - a) * (1 - e) * c[5 * i + j] + a * (1 - e) * c[5 * (i + 1) + j] + (1 - a) * e * c[5 * i + j + 1] +
             a * e * c[5 * (i + 1) + j + 1];
    };
    run.descent_energies.push_back(VM3::relax_surface_3(P, G, start, ro).energy);
    if(!progress("local descents", double(k + 1) / double(s.descents))) break;
  }
  run.seconds_descents = seconds_since(t0);
}

// A descent ends lower than the global result when it is lower by more than the relaxation's own spread (1e-6
// relative): equal energies to that precision are the same basin.
inline bool descent_is_lower(double descent, double global) { return descent < global - 1e-6 * std::abs(global); }

// The planes of --plane-grid. The grid's refusals (more than 16384 planes, a --max-slope too small for the lattice
// at this N) are about the option values, so they are usage errors (exit 2), not bad input data.
inline std::vector<VM3::Lattice_plane_3> regular_grid_planes(const Surface_settings& s, Surface_run& run)
{
  VM3::Regular_surface_plane_options_3 options;
  options.max_slope = s.max_slope;
  options.offset_steps = std::size_t(s.grid_offset_steps);
  std::vector<VM3::Lattice_plane_3> planes;
  try {
    planes = VM3::regular_surface_planes_3(run.problem, std::size_t(s.plane_grid), options);
  } catch(const std::invalid_argument& e) {
    throw Usage_error(std::string("--plane-grid ") + std::to_string(s.plane_grid) + ": " + e.what());
  }
  run.grid_planes = planes.size();
  return planes;
}

template <class Functional>
void run_surface_with(const Surface_settings& s, const Functional& G, Surface_run& run, const Progress_bar& progress)
{
  VM3::Surface_plane_options_3 po;
  po.distribution = s.distribution == "slope" ? VM3::Plane_distribution_3::slope_limited
                                              : VM3::Plane_distribution_3::isotropic;
  po.max_slope = s.max_slope;
  po.pencil_fraction = s.pencil_fraction;
  po.seed = std::uint64_t(s.seed);
  if(s.plane_grid == 0) run.pencils = VM3::surface_pencil_count_3(run.problem, std::size_t(s.planes), po);
  // The counts of the complex a multi-solve method ended on (only its planes come back): built once more.
  auto record_complex = [&](const std::vector<VM3::Lattice_plane_3>& planes) {
    const VM3::Plane_arrangement_3 A(planes);
    run.cells = A.number_of_cells();
    run.facets = A.number_of_facets();
    run.vertices = A.number_of_vertices();
  };
  auto solve_once = [&](auto engine) {
    if(s.tangent_rounds > 0) {
      const auto t0 = std::chrono::steady_clock::now();
      VM3::Tangent_refinement_options_3 to;
      to.rounds = int(s.tangent_rounds);
      to.fit_radius = s.fit_radius;
      const VM3::Tangent_refinement_result_3 r = VM3::refine_surface_by_tangent_planes_3(
        run.problem, G, std::size_t(s.planes), to, po, 1, engine, std::ref(progress));
      run.seconds_cut = seconds_since(t0);
      run.surface = r.surface;
      run.tangent_energies = r.round_energies;
      run.tangent_cells = r.round_cells;
      run.tangent_best = r.best_round;
      record_complex(r.planes);
      return;
    }
    if(s.refine > 0) {
      const auto t0 = std::chrono::steady_clock::now();
      const VM3::Surface_refinement_result_3 r = VM3::refine_surface_3(
        run.problem, G, std::size_t(s.planes), int(s.refine), po, 0.0, 1, engine, std::ref(progress));
      run.seconds_cut = seconds_since(t0);
      run.surface = r.surface;
      run.refine_energies = r.run_energies;
      run.refine_below = r.cells_below;
      run.refine_above = r.cells_above;
      run.refine_nodes = r.network_nodes;
      run.refine_outside = r.cells_outside;
      record_complex(r.planes);
      return;
    }
    if(s.basin_search) {
      const auto t0 = std::chrono::steady_clock::now();
      const VM3::Relaxed_plane_selection_result_3 r = VM3::select_planes_relaxed_3(
        run.problem, G, std::size_t(s.planes), int(s.plane_selection), po, VM3::Surface_basin_search_options_3(),
        engine, std::ref(progress));
      run.seconds_cut = seconds_since(t0);
      run.surface = r.selection.surface;
      run.selection_energies = r.selection.energies;
      run.relaxed = r.search.relaxed;
      run.has_relaxed = true;
      record_complex(r.selection.planes);
      run.cells = r.selection.cells.back();
      return;
    }
    if(s.plane_selection > 1) {
      const auto t0 = std::chrono::steady_clock::now();
      const VM3::Plane_selection_result_3 r =
        VM3::select_planes_3(run.problem, G, std::size_t(s.planes), int(s.plane_selection), po, 1, engine,
                             std::ref(progress));
      run.seconds_cut = seconds_since(t0);
      run.surface = r.surface;
      run.selection_energies = r.energies;
      record_complex(r.planes);
      run.cells = r.cells.back();
      return;
    }
    auto t0 = std::chrono::steady_clock::now();
    const std::vector<VM3::Lattice_plane_3> planes =
      s.plane_grid > 0 ? regular_grid_planes(s, run) : VM3::surface_planes_3(run.problem, std::size_t(s.planes), po);
    const VM3::Plane_arrangement_3 A = VM3::build_surface_arrangement_3(run.problem, planes, std::ref(progress));
    run.seconds_build = seconds_since(t0);
    run.cells = A.number_of_cells();
    run.facets = A.number_of_facets();
    run.vertices = A.number_of_vertices();
    t0 = std::chrono::steady_clock::now();
    const std::vector<double> w = VM3::surface_facet_weights_3(A, run.problem, G, 1, std::ref(progress));
    run.seconds_weights = seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    run.surface = VM3::minimize_surface_functional_3(A, w, run.problem, engine, std::ref(progress));
    run.seconds_cut = seconds_since(t0);
  };
  if(s.engine == "pr") solve_once(CGAL::Min_cut::Push_relabel_max_flow());
  else if(s.engine == "bk") solve_once(CGAL::Min_cut::Boykov_kolmogorov_max_flow());
  else solve_once(CGAL::Min_cut::Pseudoflow_max_flow());
  if(s.relax && !s.basin_search && run.surface.is_feasible) {
    const auto t0 = std::chrono::steady_clock::now();
    run.relaxed = VM3::relax_surface_3(run.problem, G, run.surface, VM3::Surface_relaxation_options_3(),
                                       std::ref(progress));
    run.has_relaxed = true;
    run.seconds_relax = seconds_since(t0);
  }
  if(s.descents > 0 && run.surface.is_feasible) run_surface_descents(s, G, run, progress);
}

// Refuses a surface whose energy or points are not finite.
inline void check_surface_result(const Surface_run& run)
{
  if(!run.surface.is_feasible) return;
  if(!std::isfinite(run.surface.energy) || !std::isfinite(run.surface.solver_value))
    throw Result_error("the minimal surface's energy is not finite (energy " + std::to_string(run.surface.energy) +
                       ", cut value " + std::to_string(run.surface.solver_value) + ")");
  for(const auto& p : run.surface.points)
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) throw Result_error("the minimal surface has a point that is not finite");
  if(run.has_relaxed && !std::isfinite(run.relaxed.energy)) throw Result_error("the relaxed energy is not finite");
}

// The surface as an ASCII PLY file (x, y, z with 17 significant digits; triangles oriented upwards).
inline void write_surface_ply_checked(const std::string& path, const VM3::Minimal_surface_3& s)
{
  Output_file out(path);
  out << "ply\nformat ascii 1.0\ncomment MDCS minimal discrete surface, energy " << s.energy
      << "\nelement vertex " << s.points.size() << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "element face " << s.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for(const auto& p : s.points) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for(const auto& t : s.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  out.commit();
}

// Defined in cmd_surface.cpp, so that it is compiled once: `mdcs demo` calls it too, and each translation unit that
// compiled the run instantiated every algorithm it uses again (under the sanitizers of CI, minutes of CPU).
Surface_run run_surface(const Surface_settings& s, const Progress_bar& progress);

// The run as data: NAME_summary.json.
inline void write_surface_json(const Surface_settings& s, const Surface_run& run, Invocation& inv, int exit_code)
{
  Run_summary_json j;
  j.inputs.add("problem", s.problem).add("domain", s.domain.empty() ? std::string("rectangle") : s.domain);
  if(s.plane_grid > 0)
    j.inputs.add("plane_grid", (unsigned long long)s.plane_grid)
      .add("grid_offset_steps", (unsigned long long)(s.grid_offset_steps == 0 ? s.plane_grid : s.grid_offset_steps))
      .add("grid_planes", (unsigned long long)run.grid_planes);
  j.timings.add("build", run.seconds_build).add("weights", run.seconds_weights).add("cut", run.seconds_cut)
    .add("relaxation", run.seconds_relax).add("descents", run.seconds_descents);
  Json_object complex;
  complex.add("cells", (unsigned long long)run.cells).add("facets", (unsigned long long)run.facets)
    .add("vertices", (unsigned long long)run.vertices).add("pencil_planes", (unsigned long long)run.pencils);
  j.results.add("complex", complex).add("feasible", bool(run.surface.is_feasible));
  if(run.surface.is_feasible) {
    j.results.add("energy", run.surface.energy).add("cut_value", run.surface.solver_value)
      .add("projected_area_over_domain_area", run.surface.projected_area / run.problem.domain_area())
      .add("surface_facets", (unsigned long long)run.surface.facets.size())
      .add("surface_triangles", (unsigned long long)run.surface.triangles.size()).add("exact_area", run.exact)
      .add("surface_ply", run.ply);
    if(run.has_relaxed) j.results.add("relaxed_energy", run.relaxed.energy).add("relaxed_ply", run.relaxed_ply);
    if(!run.selection_energies.empty()) j.results.raw("plane_selection_energies", json_numbers(run.selection_energies));
    if(!run.refine_energies.empty()) j.results.raw("refinement_run_energies", json_numbers(run.refine_energies));
    if(!run.tangent_energies.empty())
      j.results.raw("tangent_round_energies", json_numbers(run.tangent_energies)).add("tangent_best_round", run.tangent_best);
    if(!run.descent_energies.empty())
      j.results.raw("descent_energies", json_numbers(run.descent_energies)).add("global_relaxed_like_descents", run.global_descent_energy);
  }
  j.files = run.files;
  if(!run.summary_file.empty()) j.files.push_back(run.summary_file);
  j.write((std::filesystem::path(s.output) / (s.name + "_summary.json")).string(), inv, exit_code);
}

} // namespace mdcs_cli

#endif // MDCS_CLI_CMD_SURFACE_H
