// `mdcs curve`: globally minimal discrete curves (univariate variational problems).
#ifndef MDCS_CLI_CMD_CURVE_H
#define MDCS_CLI_CMD_CURVE_H

#include "cli_common.h"

#include <CGAL/Min_cut.h>
#include <CGAL/Variational_minimization.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>

namespace mdcs_cli {

namespace VM = CGAL::Variational_minimization;

inline const char* curve_usage()
{
  return
    "usage: mdcs curve [options]\n"
    "Minimise F(f) = integral of G(f, f', x) dx globally over the functions of a line arrangement (min-cut of the\n"
    "directed dual graph), check the result with the independent shortest-path oracle, and draw it.\n"
    "  --functional NAME   catenoid (surface of rotation, default) | arc-length | blobs (length weighted by a\n"
    "                      density of Gaussian blobs: many local minima)\n"
    "  --radius R          catenoid: rings of radius R at x = -1 and 1 (default 2); box [-1,1]x[0,R]\n"
    "  --box A,B,YMIN,YMAX domain [A,B] and value range (other functionals; default 0,1,0,1)\n"
    "  --left V|LO:HI      left end value, fixed or relaxed (default 0.5; catenoid: R)\n"
    "  --right V|LO:HI     right end value (default 0.5; catenoid: R)\n"
    "  --grid KIND         random (default) | regular (C_n, dynamic programming) | regular-pl (C_n^pl, cut)\n"
    "  --lines N           random lines (default 1600)\n"
    "  --n N               regular grids: C_n parameter (default 12 for regular, 2 for regular-pl)\n"
    "  --pencil-fraction F share of the random lines through each fixed end point (default 0.1)\n"
    "  --seed S            random seed (default 1)\n"
    "  --engine planar|pf|pr|bk  min-cut engine: the planar cut (default; a shortest path in the dual), or the\n"
    "                      max-flow engines pseudoflow, push-relabel or Boykov-Kolmogorov\n"
    "  --no-local          skip the local-descent comparison\n"
    "  --output DIR        output folder (default mdcs-output); files NAME.svg/.png/.csv/_summary.txt\n"
    "  --name NAME         base name of the output files (default curve)\n"
    "  --quiet             no progress bar\n";
}

struct Curve_settings
{
  std::string functional = "catenoid";
  double radius = 2;
  CGAL::Bbox_2 box = CGAL::Bbox_2(0, 0, 1, 1);
  VM::End_condition left = VM::End_condition::fixed(0.5), right = VM::End_condition::fixed(0.5);
  bool ends_given = false;
  std::string grid = "random";
  long lines = 1600;
  long n = -1;
  double pencil_fraction = 0.1;
  long seed = 1;
  std::string engine = "planar";
  bool local = true;
  std::string output = "mdcs-output";
  std::string name = "curve";
  bool quiet = false;
};

struct Curve_run
{
  VM::Curve_problem_2 problem;
  VM::Minimal_curve_2 curve;     // the cut (or C_n dynamic programming)
  double oracle_value = NAN;     // shortest path on the same grid (NaN for C_n)
  double exact = NAN;            // analytic optimum where known
  std::string exact_branch;
  double local_energy = NAN;     // local descent from the straight line / the catenoid
  std::size_t V = 0, E = 0, F = 0, lines_used = 0;
  double seconds_grid = 0, seconds_weights = 0, seconds_solve = 0, seconds_oracle = 0;
  std::string svg, csv, summary;
};

inline VM::End_condition parse_end(const std::string& s, const char* name)
{
  const auto colon = s.find(':');
  auto number = [&](const std::string& t) {
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if(t.empty() || *end != '\0') throw Usage_error(std::string("option --") + name + ": '" + s + "' is not V or LO:HI");
    return v;
  };
  if(colon == std::string::npos) return VM::End_condition::fixed(number(s));
  return VM::End_condition::range(number(s.substr(0, colon)), number(s.substr(colon + 1)));
}

inline Curve_settings parse_curve_settings(const Options& o)
{
  Curve_settings s;
  s.functional = o.text("functional", s.functional);
  if(s.functional != "catenoid" && s.functional != "arc-length" && s.functional != "blobs")
    throw Usage_error("--functional must be catenoid, arc-length or blobs (got '" + s.functional + "')");
  s.radius = o.number("radius", s.radius);
  const std::string box = o.text("box", "");
  if(!box.empty()) {
    double v[4];
    char c1, c2, c3;
    std::istringstream in(box);
    if(!(in >> v[0] >> c1 >> v[1] >> c2 >> v[2] >> c3 >> v[3]) || c1 != ',' || c2 != ',' || c3 != ',')
      throw Usage_error("--box must be A,B,YMIN,YMAX (got '" + box + "')");
    s.box = CGAL::Bbox_2(v[0], v[2], v[1], v[3]);
  }
  if(o.has("left")) s.left = parse_end(o.text("left", ""), "left"), s.ends_given = true;
  if(o.has("right")) s.right = parse_end(o.text("right", ""), "right"), s.ends_given = true;
  s.grid = o.text("grid", s.grid);
  if(s.grid != "random" && s.grid != "regular" && s.grid != "regular-pl")
    throw Usage_error("--grid must be random, regular or regular-pl (got '" + s.grid + "')");
  s.lines = o.integer("lines", s.lines, 1);
  s.n = o.integer("n", s.grid == "regular" ? 12 : 2, 1);
  s.pencil_fraction = o.number("pencil-fraction", s.pencil_fraction);
  if(!(s.pencil_fraction >= 0 && s.pencil_fraction <= 1)) throw Usage_error("--pencil-fraction must be in [0, 1]");
  s.seed = o.integer("seed", s.seed, 0);
  s.engine = o.text("engine", s.engine);
  if(s.engine != "planar" && s.engine != "pf" && s.engine != "pr" && s.engine != "bk")
    throw Usage_error("--engine must be planar, pf, pr or bk (got '" + s.engine + "')");
  s.local = !o.has("no-local");
  o.text("no-local", "");
  s.output = o.text("output", s.output);
  s.name = o.text("name", s.name);
  s.quiet = o.has("quiet");
  o.text("quiet", "");
  return s;
}

// Density of Gaussian blobs on the unit square (mapped onto the box) over a valley along mid-height: the
// channels between the blobs give the weighted length many local minima.
struct Blob_density
{
  CGAL::Bbox_2 box;
  std::vector<std::array<double, 3>> blobs; // centre x, centre y, height (unit-square coordinates)

  Blob_density(const CGAL::Bbox_2& b, unsigned seed) : box(b)
  {
    std::mt19937_64 random(seed * 7919 + 13);
    auto unit = [&] { return double(random() >> 11) * 0x1.0p-53; };
    for(int k = 0; k < 14; ++k) blobs.push_back({0.1 + 0.8 * unit(), 0.1 + 0.8 * unit(), 2 + 6 * unit()});
  }

  double operator()(double x, double f) const
  {
    const double u = (x - box.xmin()) / (box.xmax() - box.xmin()), v = (f - box.ymin()) / (box.ymax() - box.ymin());
    // Cheap in a band around mid-height, so that the optimum must pass between the blobs, not around them.
    double rho = 0.15 + 6 * (v - 0.5) * (v - 0.5);
    for(const auto& b : blobs) rho += b[2] * std::exp(-((u - b[0]) * (u - b[0]) + (v - b[1]) * (v - b[1])) / (2 * 0.07 * 0.07));
    return rho;
  }
};

template <class Functional>
Curve_run run_curve_with(const Curve_settings& s, const VM::Curve_problem_2& problem, const Functional& G,
                         Progress_bar& progress)
{
  problem.validate(); // before anything uses the end values (clear message for out-of-range ends)
  Curve_run run;
  run.problem = problem;
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<VM::Svg_segment> grid_segments;

  if(s.grid == "regular") {
    run.curve = VM::minimize_on_regular_grid_2(problem, G, std::size_t(s.n), progress);
    run.seconds_solve = seconds_since(t0);
    run.E = std::size_t(s.n) * (std::size_t(s.n * s.n) + 1) * (std::size_t(s.n * s.n) + 1);
  } else {
    std::vector<VM::Arrangement_line_2> lines;
    if(s.grid == "random") {
      VM::Random_lines_options options;
      if(problem.left.is_fixed()) options.pencil_points.push_back(VM::Point_2(problem.box.xmin(), problem.left.low));
      if(problem.right.is_fixed()) options.pencil_points.push_back(VM::Point_2(problem.box.xmax(), problem.right.low));
      options.pencil_fraction = options.pencil_points.empty() ? 0.0 : s.pencil_fraction;
      lines = VM::random_lines_2(problem.box, std::size_t(s.lines), std::uint64_t(s.seed), options);
    } else {
      lines = VM::regular_grid_lines_2(problem.box, std::size_t(s.n));
    }
    const VM::Line_arrangement_2 arrangement = VM::build_curve_arrangement_2(problem, lines, progress);
    run.seconds_grid = seconds_since(t0);
    run.V = arrangement.number_of_vertices();
    run.E = arrangement.number_of_edges();
    run.F = arrangement.number_of_faces();
    for(std::size_t i = 0; i < arrangement.number_of_input_lines(); ++i)
      run.lines_used += arrangement.is_line_used(VM::Line_arrangement_2::Line_index(i)) ? 1 : 0;
    const auto t1 = std::chrono::steady_clock::now();
    const std::vector<double> weights = VM::curve_edge_weights_2(arrangement, G, progress);
    run.seconds_weights = seconds_since(t1);
    const auto t2 = std::chrono::steady_clock::now();
    if(s.engine == "bk")
      run.curve = VM::minimize_curve_functional_2(arrangement, weights, problem, CGAL::Min_cut::Boykov_kolmogorov_max_flow(), progress);
    else if(s.engine == "pr")
      run.curve = VM::minimize_curve_functional_2(arrangement, weights, problem, CGAL::Min_cut::Push_relabel_max_flow(), progress);
    else if(s.engine == "pf")
      run.curve = VM::minimize_curve_functional_2(arrangement, weights, problem, CGAL::Min_cut::Pseudoflow_max_flow(), progress);
    else
      run.curve = VM::minimize_curve_functional_2(arrangement, weights, problem, CGAL::Min_cut::Planar_min_cut(), progress);
    run.seconds_solve = seconds_since(t2);
    const auto t3 = std::chrono::steady_clock::now();
    const VM::Minimal_curve_2 path = VM::directed_shortest_path_2(arrangement, weights, problem, progress);
    run.seconds_oracle = seconds_since(t3);
    run.oracle_value = path.solver_value;
    // Draw each line clipped to the box (from its first to its last vertex), not its many edges.
    std::vector<VM::Line_arrangement_2::Vertex_index> first(lines.size(), VM::Line_arrangement_2::null_index), last = first;
    for(std::size_t i = 0; i < arrangement.number_of_edges(); ++i) {
      const auto& e = arrangement.edge(VM::Line_arrangement_2::Edge_index(i));
      if(e.kind != VM::Line_arrangement_2::LINE_EDGE) continue;
      const auto& a = arrangement.point(e.source);
      const auto& b = arrangement.point(e.target);
      if(first[e.line] == VM::Line_arrangement_2::null_index || a < arrangement.point(first[e.line])) first[e.line] = e.source;
      if(last[e.line] == VM::Line_arrangement_2::null_index || arrangement.point(last[e.line]) < b) last[e.line] = e.target;
    }
    for(std::size_t l = 0; l < lines.size(); ++l)
      if(first[l] != VM::Line_arrangement_2::null_index) {
        const auto& a = arrangement.point(first[l]);
        const auto& b = arrangement.point(last[l]);
        grid_segments.push_back({a.x(), a.y(), b.x(), b.y()});
      }
  }

  // The analytic optimum of the catenoid problem: drawn dashed, and the start of the local descent.
  const VM::Surface_of_rotation_minimum exact_min =
    s.functional == "catenoid" ? VM::global_minimum_surface_of_rotation(s.radius) : VM::Surface_of_rotation_minimum();

  // Local descent, to show what a local method finds from a natural start.
  std::vector<VM::Svg_point> local_points;
  if(s.local && problem.left.is_fixed() && problem.right.is_fixed()) {
    const std::size_t m = 200;
    std::vector<double> start(m + 1);
    for(std::size_t i = 0; i <= m; ++i) {
      const double x = problem.box.xmin() + (problem.box.xmax() - problem.box.xmin()) * double(i) / double(m);
      const double t = double(i) / double(m);
      start[i] = (1 - t) * problem.left.low + t * problem.right.low;
      if(s.functional == "catenoid" && exact_min.catenoids.exists) start[i] = VM::catenoid_value(exact_min.catenoids.c_shallow, x);
    }
    VM::Local_descent_options options;
    options.ymin = problem.box.ymin();
    options.ymax = problem.box.ymax();
    const auto local = VM::local_descent_2(G, problem.box.xmin(), problem.box.xmax(), start, options);
    run.local_energy = local.energy;
    for(std::size_t i = 0; i <= m; ++i)
      local_points.push_back({problem.box.xmin() + (problem.box.xmax() - problem.box.xmin()) * double(i) / double(m), local.values[i]});
  }

  // Analytic optimum for the catenoid problem.
  std::vector<VM::Svg_point> analytic;
  if(s.functional == "catenoid") {
    const VM::Surface_of_rotation_minimum& m = exact_min;
    run.exact = m.energy;
    if(m.branch == VM::Surface_of_rotation_minimum::Branch::Catenoid) {
      run.exact_branch = "catenoid";
      for(int i = 0; i <= 200; ++i) {
        const double x = -1 + 2.0 * i / 200;
        analytic.push_back({x, VM::catenoid_value(m.catenoids.c_shallow, x)});
      }
    } else {
      run.exact_branch = "Goldschmidt";
      analytic = {{-1, s.radius}, {-1, 0}, {1, 0}, {1, s.radius}};
    }
  } else if(s.functional == "arc-length") {
    if(problem.left.is_fixed() && problem.right.is_fixed()) {
      run.exact = std::hypot(problem.box.xmax() - problem.box.xmin(), problem.right.low - problem.left.low);
      run.exact_branch = "straight line";
      analytic = {{problem.box.xmin(), problem.left.low}, {problem.box.xmax(), problem.right.low}};
    }
  }

  // Outputs.
  const std::filesystem::path folder = prepare_output_folder(s.output);
  VM::Svg_curve_plot plot;
  plot.xmin = problem.box.xmin();
  plot.xmax = problem.box.xmax();
  plot.ymin = problem.box.ymin();
  plot.ymax = problem.box.ymax();
  plot.preserve_aspect_ratio = false;
  plot.max_grid_segments = 4000;
  plot.legend_position = s.functional == "catenoid" ? VM::Svg_curve_plot::BOTTOM_RIGHT : VM::Svg_curve_plot::TOP_RIGHT;
  plot.grid_segments = std::move(grid_segments);
  for(const auto& p : run.curve.polyline) plot.solution.push_back({p.x(), p.y()});
  plot.solution_label = "global discrete minimum (" + std::string(s.grid == "regular" ? "C_n, dynamic programming" : "min-cut") + ")";
  plot.analytic = analytic;
  if(!analytic.empty()) plot.analytic_label = "exact optimum (" + run.exact_branch + ")";
  if(!local_points.empty()) {
    VM::Svg_curve c;
    c.points = local_points;
    c.label = "local descent (gradient, 200 intervals)";
    c.color = "#d95f02";
    plot.extra_curves.push_back(c);
  }
  std::ostringstream title;
  if(s.functional == "catenoid") title << "surface of rotation, R = " << s.radius << ": ";
  else title << s.functional << ": ";
  if(s.grid == "random") title << s.lines << " random lines";
  else if(s.grid == "regular") title << "regular grid C_" << s.n;
  else title << "C_" << s.n << "^pl";
  plot.title = title.str();
  std::ostringstream c1, c2;
  c1.precision(9);
  c1 << "discrete energy " << run.curve.energy;
  if(std::isfinite(run.exact)) c1 << ", exact " << run.exact << " (relative error " << std::setprecision(3) << (run.curve.energy - run.exact) / run.exact << ")";
  c2.precision(6);
  if(std::isfinite(run.local_energy)) c2 << "local descent energy " << run.local_energy << "; ";
  if(run.V) c2 << run.V << " vertices, " << run.E << " edges, " << run.F << " cells";
  plot.caption_lines = {c1.str(), c2.str()};

  run.svg = (folder / (s.name + ".svg")).string();
  VM::write_curve_svg(run.svg, plot);
  svg_to_png(run.svg);
  run.csv = (folder / (s.name + ".csv")).string();
  {
    std::ofstream csv(run.csv);
    csv.precision(17);
    csv << "x,f\n";
    for(const auto& p : run.curve.polyline) csv << p.x() << "," << p.y() << "\n";
  }
  std::ostringstream summary;
  summary.precision(10);
  summary << "problem: " << plot.title << ", box [" << problem.box.xmin() << ", " << problem.box.xmax() << "] x ["
          << problem.box.ymin() << ", " << problem.box.ymax() << "]\n";
  if(!run.curve.is_feasible) {
    summary << "INFEASIBLE: no function on this grid meets the end conditions (add lines through the end points)\n";
  } else {
    summary << "discrete energy: " << run.curve.energy << " (solver value " << run.curve.solver_value << ")\n";
    if(std::isfinite(run.oracle_value))
      summary << "shortest-path oracle: " << run.oracle_value << " (relative difference "
              << std::abs(run.oracle_value - run.curve.solver_value) / run.oracle_value << ")\n";
    if(std::isfinite(run.exact))
      summary << "exact optimum: " << run.exact << " (" << run.exact_branch << "), relative error "
              << (run.curve.energy - run.exact) / run.exact << "\n";
    if(std::isfinite(run.local_energy)) summary << "local descent (200 intervals) energy: " << run.local_energy << "\n";
    summary << "curve: " << run.curve.polyline.size() << " vertices, lowest value " << [&] {
      double m = INFINITY;
      for(const auto& p : run.curve.polyline) m = std::min(m, p.y());
      return m;
    }() << "\n";
  }
  if(run.V) summary << "arrangement: " << run.lines_used << " lines used, " << run.V << " vertices, " << run.E << " edges, " << run.F << " cells\n";
  summary << "time: grid " << run.seconds_grid << " s, weights " << run.seconds_weights << " s, solve (" << s.engine << ") "
          << run.seconds_solve << " s, oracle " << run.seconds_oracle << " s\n";
  summary << "files: " << run.svg << ", " << run.csv << "\n";
  run.summary = summary.str();
  std::ofstream((folder / (s.name + "_summary.txt")).string()) << run.summary;
  return run;
}

inline Curve_run run_curve(Curve_settings s, Progress_bar& progress)
{
  VM::Curve_problem_2 problem;
  if(s.functional == "catenoid") {
    if(!(s.radius > 0) || !std::isfinite(s.radius)) throw Usage_error("--radius must be positive");
    problem = VM::Curve_problem_2{CGAL::Bbox_2(-1, 0, 1, s.radius), VM::End_condition::fixed(s.radius),
                                  VM::End_condition::fixed(s.radius)};
    if(s.ends_given) problem.left = s.left, problem.right = s.right;
    return run_curve_with(s, problem, VM::Surface_of_rotation_functional(), progress);
  }
  problem = VM::Curve_problem_2{s.box, s.left, s.right};
  if(s.functional == "arc-length") return run_curve_with(s, problem, VM::Arc_length_functional(), progress);
  return run_curve_with(s, problem, VM::make_density_weighted_length_functional(Blob_density(s.box, unsigned(s.seed))), progress);
}

inline int command_curve(const Options& o)
{
  if(o.has("help")) {
    std::cout << curve_usage();
    return EXIT_OK;
  }
  const Curve_settings s = parse_curve_settings(o);
  o.reject_unknown();
  if(!o.positional().empty()) throw Usage_error("unexpected argument '" + o.positional().front() + "'");
  Progress_bar progress(s.quiet);
  const Curve_run run = run_curve(s, progress);
  std::cout << run.summary;
  return run.curve.is_feasible ? EXIT_OK : EXIT_INFEASIBLE;
}

} // namespace mdcs_cli

#endif // MDCS_CLI_CMD_CURVE_H
