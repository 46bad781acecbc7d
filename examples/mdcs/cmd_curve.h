// `mdcs curve`: globally minimal discrete curves (univariate variational problems): the option table, the run
// (arrangement, weights, min-cut, the shortest-path oracle, analytic optima where known, a local descent), its
// checks and its files (NAME.csv, NAME.svg/.png, NAME_summary.txt, NAME_summary.json).
#ifndef MDCS_CLI_CMD_CURVE_H
#define MDCS_CLI_CMD_CURVE_H

#include "cli_common.h"

#include <CGAL/Min_cut.h>
#include <CGAL/Variational_minimization.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <optional>
#include <random>
#include <sstream>

namespace mdcs_cli {

namespace VM = CGAL::Variational_minimization;

inline Command_spec curve_command_spec()
{
  Command_spec s;
  s.name = "curve";
  s.synopsis = "[options]";
  s.description =
    "Minimise F(f) = integral of G(f, f', x) dx globally over the functions of a line arrangement (min-cut of the\n"
    "directed dual graph), check the result with the independent shortest-path oracle, and draw it.\n";
  s.options = {
    text_option("functional", "NAME", "catenoid", "catenoid (surface of rotation) | arc-length | blobs (length weighted by\n"
                "a density of Gaussian blobs: many local minima)", {"catenoid", "arc-length", "blobs"}),
    real_option("radius", "R", "2", 0, 1e6, "catenoid: rings of radius R at x = -1 and 1; box [-1,1] x [0,R]", true),
    list_option("box", "A,B,YMIN,YMAX", "0,1,0,1", 4, 4, -1e9, 1e9, "arc-length, blobs: domain [A,B] and value range"),
    text_option("left", "V|LO:HI", "", "left end value, fixed (V) or free in [LO,HI] (default 0.5; catenoid: R; inside\n"
                "the value range)"),
    text_option("right", "V|LO:HI", "", "right end value (default 0.5; catenoid: R); each end keeps its default unless given"),
    text_option("grid", "KIND", "random", "random | regular (C_n, dynamic programming) | regular-pl (C_n^pl, cut)",
                {"random", "regular", "regular-pl"}),
    integer_option("lines", "N", "1600", 1, 10000, "random lines (the arrangement has about N^2/2 vertices, 125 bytes each:\n"
                   "10000 lines take about 6 GB)"),
    integer_option("n", "N", "", 1, 40, "regular grids: C_n parameter (default 12 for regular, at most 40: n^5 edges;\n"
                   "default 2 for regular-pl, at most 6: about n^5 lines)"),
    real_option("pencil-fraction", "F", "0.1", 0, 1, "random grid: share of the lines through each fixed end point"),
    integer_option("seed", "S", "1", 0, 4294967295.0, "random seed (of the lines and of the blob density)"),
    text_option("engine", "E", "planar", "min-cut engine: planar (a shortest path in the dual) | pf (pseudoflow) |\n"
                "pr (push-relabel) | bk (Boykov-Kolmogorov)", {"planar", "pf", "pr", "bk"}),
    flag_option("no-local", "skip the local-descent comparison"),
    text_option("name", "NAME", "curve", "base name of the output files (a plain file name)"),
  };
  add_common_options(s, Common_options{"mdcs-output", true, true});
  s.notes =
    "Files in the output folder: NAME.csv (the curve: x,f with 17 significant digits), NAME.svg (.png with\n"
    "rsvg-convert; not with --no-picture), NAME_summary.txt, NAME_summary.json.\n"
    "Exit code 4: no function on this grid meets the end conditions (add lines through the end points).\n";
  return s;
}

struct Curve_settings
{
  std::string functional = "catenoid";
  double radius = 2;
  CGAL::Bbox_2 box = CGAL::Bbox_2(0, 0, 1, 1);
  std::optional<VM::End_condition> left, right; // absent: the functional's default
  std::string grid = "random";
  long lines = 1600;
  long n = -1;
  double pencil_fraction = 0.1;
  unsigned long seed = 1;
  std::string engine = "planar";
  bool local = true;
  bool picture = true;
  std::string output = "mdcs-output";
  std::string name = "curve";
  std::string threads; // for the summary (empty: not printed)
};

struct Curve_run
{
  VM::Curve_problem_2 problem;
  VM::Minimal_curve_2 curve;     // the cut (or C_n dynamic programming)
  double oracle_value = NAN;     // shortest path on the same grid (NaN for C_n)
  double exact = NAN;            // analytic optimum where known
  std::string exact_branch, exact_note;
  double local_energy = NAN;     // local descent from the straight line / the catenoid
  std::size_t V = 0, E = 0, F = 0, lines_used = 0;
  double seconds_grid = 0, seconds_weights = 0, seconds_solve = 0, seconds_oracle = 0, seconds_output = 0;
  std::string svg, png, csv, summary_file, summary;
};

// "V" or "LO:HI", each a finite number inside the value range [ymin, ymax].
inline VM::End_condition parse_end(const std::string& text, const char* name, double ymin, double ymax)
{
  const std::string what = std::string("--") + name;
  const auto colon = text.find(':');
  VM::End_condition e;
  if(colon == std::string::npos) {
    e = VM::End_condition::fixed(parse_real_text(text, what, -1e300, 1e300));
  } else {
    e = VM::End_condition::range(parse_real_text(text.substr(0, colon), what, -1e300, 1e300),
                                 parse_real_text(text.substr(colon + 1), what, -1e300, 1e300));
    if(e.low > e.high) throw Usage_error(what + ": '" + text + "' has LO > HI");
  }
  if(e.low < ymin || e.high > ymax) {
    std::ostringstream m;
    m << what << ": '" << text << "' lies outside the range of values [" << ymin << ", " << ymax << "]";
    throw Usage_error(m.str());
  }
  return e;
}

inline Curve_settings parse_curve_settings(const Parsed_options& o)
{
  Curve_settings s;
  s.functional = o.text("functional");
  const bool catenoid = s.functional == "catenoid";
  if(catenoid && o.given("box")) throw Usage_error("--box is for arc-length and blobs (the catenoid's box is [-1,1] x [0,R])");
  if(!catenoid && o.given("radius")) throw Usage_error("--radius is for the catenoid functional");
  s.radius = o.real("radius");
  const std::vector<double> box = o.list("box");
  if(!(box[0] < box[1]) || !(box[2] < box[3])) throw Usage_error("--box must have A < B and YMIN < YMAX (got '" + o.text("box") + "')");
  s.box = CGAL::Bbox_2(box[0], box[2], box[1], box[3]);
  const double ymin = catenoid ? 0 : box[2], ymax = catenoid ? s.radius : box[3];
  if(o.given("left")) s.left = parse_end(o.text("left"), "left", ymin, ymax);
  if(o.given("right")) s.right = parse_end(o.text("right"), "right", ymin, ymax);
  s.grid = o.text("grid");
  if(s.grid != "random") {
    for(const char* name : {"lines", "pencil-fraction"})
      if(o.given(name)) throw Usage_error(std::string("--") + name + " applies to --grid random only");
    if(o.given("seed") && s.functional != "blobs") throw Usage_error("--seed applies to --grid random or --functional blobs");
  } else if(o.given("n")) {
    throw Usage_error("--n applies to --grid regular or regular-pl");
  }
  if(s.grid == "regular" && o.given("engine")) throw Usage_error("--grid regular is solved by dynamic programming (no --engine)");
  s.lines = long(o.integer("lines"));
  s.n = o.given("n") ? long(o.integer("n")) : s.grid == "regular" ? 12 : 2;
  if(s.grid == "regular-pl" && s.n > 6) throw Usage_error("--n must be <= 6 for --grid regular-pl (about n^5 lines)");
  s.pencil_fraction = o.real("pencil-fraction");
  s.seed = (unsigned long)o.integer("seed");
  s.engine = o.text("engine");
  s.local = !o.flag("no-local");
  s.picture = !o.flag("no-picture");
  s.output = o.text("output");
  s.name = checked_file_name(o.text("name"), "--name");
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

inline std::string describe_end(const VM::End_condition& e)
{
  std::ostringstream s;
  s.precision(10);
  if(e.is_fixed()) s << e.low;
  else s << "free in [" << e.low << ", " << e.high << "]";
  return s.str();
}

// The analytic optimum of the problem where one is known: the catenoid / Goldschmidt solution for equal fixed
// ends a > 0 (rings of radius a at x = -1 and 1), the straight line for arc length with fixed ends.
inline void find_exact_curve_optimum(const Curve_settings& s, const VM::Curve_problem_2& problem, Curve_run& run,
                                     VM::Surface_of_rotation_minimum& rotation, std::vector<VM::Svg_point>& analytic)
{
  const bool fixed = problem.left.is_fixed() && problem.right.is_fixed();
  if(s.functional == "catenoid") {
    if(!fixed || problem.left.low != problem.right.low || !(problem.left.low > 0)) {
      run.exact_note = "not known for these end conditions (the analytic optimum covers equal fixed ends a > 0)";
      return;
    }
    const double a = problem.left.low;
    rotation = VM::global_minimum_surface_of_rotation(a);
    run.exact = rotation.energy;
    if(rotation.branch == VM::Surface_of_rotation_minimum::Branch::Catenoid) {
      run.exact_branch = "catenoid";
      for(int i = 0; i <= 200; ++i) {
        const double x = -1 + 2.0 * i / 200;
        analytic.push_back({x, VM::catenoid_value(rotation.catenoids.c_shallow, x)});
      }
    } else {
      run.exact_branch = "Goldschmidt";
      analytic = {{-1, a}, {-1, 0}, {1, 0}, {1, a}};
    }
  } else if(s.functional == "arc-length") {
    if(!fixed) {
      run.exact_note = "not known for free ends";
      return;
    }
    run.exact = std::hypot(problem.box.xmax() - problem.box.xmin(), problem.right.low - problem.left.low);
    run.exact_branch = "straight line";
    analytic = {{problem.box.xmin(), problem.left.low}, {problem.box.xmax(), problem.right.low}};
  } else {
    run.exact_note = "not known for the blob density";
  }
}

// Refuses a result that is not a number, or whose cut value the shortest-path oracle contradicts.
inline void check_curve_result(const Curve_run& run)
{
  if(!run.curve.is_feasible) return;
  if(!std::isfinite(run.curve.energy) || !std::isfinite(run.curve.solver_value))
    throw Result_error("the minimal curve's energy is not finite (energy " + std::to_string(run.curve.energy) + ", solver value " +
                       std::to_string(run.curve.solver_value) + ")");
  for(const auto& p : run.curve.polyline)
    if(!std::isfinite(p.x()) || !std::isfinite(p.y())) throw Result_error("the minimal curve has a point that is not finite");
  if(std::isfinite(run.oracle_value) &&
     std::abs(run.oracle_value - run.curve.solver_value) > 1e-7 * std::max(1.0, std::abs(run.oracle_value))) {
    std::ostringstream m;
    m.precision(17);
    m << "the min-cut value " << run.curve.solver_value << " and the shortest-path oracle " << run.oracle_value
      << " disagree (they must be equal on the same arrangement)";
    throw Result_error(m.str());
  }
}

template <class Functional>
Curve_run run_curve_with(const Curve_settings& s, const VM::Curve_problem_2& problem, const Functional& G,
                         const Progress_bar& progress)
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
    if(s.picture) {
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
  }
  check_curve_result(run);

  VM::Surface_of_rotation_minimum rotation;
  std::vector<VM::Svg_point> analytic;
  find_exact_curve_optimum(s, problem, run, rotation, analytic);

  // Local descent, to show what a local method finds from a natural start (the catenoid where it exists).
  std::vector<VM::Svg_point> local_points;
  if(s.local && problem.left.is_fixed() && problem.right.is_fixed()) {
    progress.begin("local descent");
    const std::size_t m = 200;
    std::vector<double> start(m + 1);
    const bool from_catenoid = s.functional == "catenoid" && rotation.catenoids.exists;
    for(std::size_t i = 0; i <= m; ++i) {
      const double x = problem.box.xmin() + (problem.box.xmax() - problem.box.xmin()) * double(i) / double(m);
      const double t = double(i) / double(m);
      start[i] = from_catenoid ? VM::catenoid_value(rotation.catenoids.c_shallow, x) : (1 - t) * problem.left.low + t * problem.right.low;
    }
    VM::Local_descent_options options;
    options.ymin = problem.box.ymin();
    options.ymax = problem.box.ymax();
    const auto local = VM::local_descent_2(G, problem.box.xmin(), problem.box.xmax(), start, options);
    run.local_energy = local.energy;
    for(std::size_t i = 0; i <= m; ++i)
      local_points.push_back({problem.box.xmin() + (problem.box.xmax() - problem.box.xmin()) * double(i) / double(m), local.values[i]});
    progress.end();
  }

  // Outputs.
  const auto t_output = std::chrono::steady_clock::now();
  progress.begin("writing the outputs");
  const std::filesystem::path folder = prepare_output_folder(s.output);
  std::ostringstream title;
  if(s.functional == "catenoid") title << "surface of rotation, R = " << s.radius << ": ";
  else title << s.functional << ": ";
  if(s.grid == "random") title << s.lines << " random lines";
  else if(s.grid == "regular") title << "regular grid C_" << s.n;
  else title << "C_" << s.n << "^pl";
  if(s.picture) {
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
    {
      Output_file svg(run.svg);
      VM::write_curve_svg(svg.stream(), plot);
      svg.commit();
    }
    if(svg_to_png(run.svg)) run.png = (folder / (s.name + ".png")).string();
  }
  run.csv = (folder / (s.name + ".csv")).string();
  {
    Output_file csv(run.csv);
    csv << "x,f\n";
    for(const auto& p : run.curve.polyline) csv << p.x() << "," << p.y() << "\n";
    csv.commit();
  }
  run.seconds_output = seconds_since(t_output);
  progress.end();
  std::ostringstream summary;
  summary.precision(10);
  summary << "problem: " << title.str() << ", box [" << problem.box.xmin() << ", " << problem.box.xmax() << "] x ["
          << problem.box.ymin() << ", " << problem.box.ymax() << "], ends " << describe_end(problem.left) << " -> "
          << describe_end(problem.right) << "\n";
  if(!run.curve.is_feasible) {
    summary << "INFEASIBLE: no function on this grid meets the end conditions (add lines through the end points)\n";
  } else {
    summary << "discrete energy: " << run.curve.energy << " (solver value " << run.curve.solver_value << ")\n";
    if(std::isfinite(run.oracle_value))
      summary << "shortest-path oracle: " << run.oracle_value << " (relative difference "
              << std::abs(run.oracle_value - run.curve.solver_value) / std::max(1e-300, std::abs(run.oracle_value)) << ")\n";
    if(std::isfinite(run.exact))
      summary << "exact optimum: " << run.exact << " (" << run.exact_branch << "), relative error "
              << (run.curve.energy - run.exact) / run.exact << "\n";
    else
      summary << "exact optimum: " << run.exact_note << "\n";
    if(std::isfinite(run.local_energy)) summary << "local descent (200 intervals) energy: " << run.local_energy << "\n";
    summary << "curve: " << run.curve.polyline.size() << " vertices, lowest value " << [&] {
      double m = INFINITY;
      for(const auto& p : run.curve.polyline) m = std::min(m, p.y());
      return m;
    }() << "\n";
  }
  if(run.V) summary << "arrangement: " << run.lines_used << " lines used, " << run.V << " vertices, " << run.E << " edges, " << run.F << " cells\n";
  summary << "time: grid " << run.seconds_grid << " s, weights " << run.seconds_weights << " s, solve ("
          << (s.grid == "regular" ? "dynamic programming" : s.engine) << ") " << run.seconds_solve << " s, oracle "
          << run.seconds_oracle << " s, output " << run.seconds_output << " s\n";
  if(!s.threads.empty()) summary << "threads: " << s.threads << "\n";
  run.summary_file = (folder / (s.name + "_summary.txt")).string();
  summary << "files: " << run.csv << (run.svg.empty() ? "" : ", " + run.svg) << (run.png.empty() ? "" : ", " + run.png)
          << ", " << run.summary_file << ", " << (folder / (s.name + "_summary.json")).string() << "\n";
  run.summary = summary.str();
  write_text_file(run.summary_file, run.summary);
  return run;
}

// Defined in cmd_curve.cpp, so that it is compiled once: `mdcs demo` calls it too, and each translation unit that
// compiled the run instantiated every algorithm it uses again (under the sanitizers of CI, minutes of CPU).
Curve_run run_curve(const Curve_settings& s, const Progress_bar& progress);

// The run as data: NAME_summary.json.
inline void write_curve_json(const Curve_settings& s, const Curve_run& run, Invocation& inv, int exit_code)
{
  Run_summary_json j;
  j.inputs.add("functional", s.functional).add("grid", s.grid);
  j.timings.add("grid", run.seconds_grid).add("weights", run.seconds_weights).add("solve", run.seconds_solve)
    .add("oracle", run.seconds_oracle).add("output", run.seconds_output);
  Json_object box, ends;
  box.add("a", run.problem.box.xmin()).add("b", run.problem.box.xmax()).add("ymin", run.problem.box.ymin()).add("ymax", run.problem.box.ymax());
  ends.raw("left", json_numbers({run.problem.left.low, run.problem.left.high}))
    .raw("right", json_numbers({run.problem.right.low, run.problem.right.high}));
  j.results.add("box", box).add("ends_low_high", ends).add("feasible", bool(run.curve.is_feasible));
  if(run.curve.is_feasible) {
    j.results.add("energy", run.curve.energy).add("solver_value", run.curve.solver_value).add("oracle_value", run.oracle_value)
      .add("exact_optimum", run.exact).add("exact_branch", run.exact_branch).add("local_descent_energy", run.local_energy)
      .add("curve_vertices", (unsigned long long)run.curve.polyline.size()).add("curve_csv", run.csv);
  }
  Json_object arrangement;
  arrangement.add("lines_used", (unsigned long long)run.lines_used).add("vertices", (unsigned long long)run.V)
    .add("edges", (unsigned long long)run.E).add("cells", (unsigned long long)run.F);
  j.results.add("arrangement", arrangement);
  if(!run.exact_note.empty()) j.notes.push_back("exact optimum " + run.exact_note);
  j.files = {run.csv, run.summary_file};
  if(!run.svg.empty()) j.files.push_back(run.svg);
  if(!run.png.empty()) j.files.push_back(run.png);
  j.write((std::filesystem::path(s.output) / (s.name + "_summary.json")).string(), inv, exit_code);
}

} // namespace mdcs_cli

#endif // MDCS_CLI_CMD_CURVE_H
