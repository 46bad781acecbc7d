// `mdcs surface`: globally minimal discrete surfaces of bivariate variational problems (thesis ch. 2.6.2-2.7).
#ifndef MDCS_CLI_CMD_SURFACE_H
#define MDCS_CLI_CMD_SURFACE_H

#include "cli_common.h"

#include <CGAL/Min_cut/solve_min_cut.h>
#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/analytic_solutions_3.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
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

// Names of the options of `mdcs surface` that take no value.
inline std::vector<std::string> surface_flags() { return {"quiet", "help", "relax", "basin-search"}; }

inline const char* surface_usage()
{
  return
    "usage: mdcs surface [options]\n"
    "Minimise F(f) = double integral of G(f, f_x, f_y, x, y) globally over the functions made of facets of a random\n"
    "plane arrangement (BSP cell complex, exact predicates), by a min-cut of the directed dual graph of its cells;\n"
    "write the surface (PLY) and a height-coloured picture (SVG, PNG where rsvg-convert exists).\n"
    "  --problem NAME      saddle (area, boundary f = x y on [-1,1]^2; default) | membrane (heavy membrane on a\n"
    "                      wavy rim) | blobs (area weighted by a density with wells: many local minima, boundary\n"
    "                      free in [0,1]) | scherk (area, f = ln(cos y / cos x) on [-1.2,1.2]^2; exact area known)\n"
    "  --planes N          planes per arrangement (default 150)\n"
    "  --segments S        boundary segments per side (per polygon edge) of the domain (default 4)\n"
    "  --domain P          a polygonal domain instead of the problem's rectangle: \"x0,y0;x1,y1;...\" (a simple\n"
    "                      polygon; vertices rounded to 1/256 of its bounding box) or L (an L inside the rectangle)\n"
    "  --distribution D    slope (slope-limited, default) | isotropic\n"
    "  --max-slope S       slope bound of slope-limited planes (default 3)\n"
    "  --pencil-fraction F share of the planes through the boundary segments (default 0.2)\n"
    "  --plane-selection K plane selection with K iterations (default 1: a single solve)\n"
    "  --refine R          adaptive refinement: R runs give an envelope, a new arrangement of N planes keeps\n"
    "                      their optima's planes and adds planes inside it (default 0: off)\n"
    "  --tangent-rounds K  tangent-plane refinement: K more arrangements of N planes, each fitted to the previous\n"
    "                      optimum (tangent planes, boundary pencils with its slope); the best round is kept\n"
    "                      (default 0: off; for smooth minimisers such as scherk, with --segments 16)\n"
    "  --fit-radius R      radius of those fits, share of the domain's shorter side (default 0.2)\n"
    "  --relax             continue with local relaxation on 20^2, 40^2, 80^2 grids (L-BFGS; on a polygonal\n"
    "                      domain: on Delaunay meshes of the polygon with the edge lengths of those grids)\n"
    "  --basin-search      with --plane-selection K: relax every round optimum, then search neighbouring basins\n"
    "                      by constrained cuts tile by tile, kept when their relaxed energy is lower (rectangles;\n"
    "                      relaxed on 20^2, 40^2 grids; for many-minima problems such as blobs)\n"
    "  --descents N        also N local descents from random smooth starts (L-BFGS on 20^2, 40^2 grids from a\n"
    "                      bilinear function on a random 5 x 5 grid of heights), and a histogram of their\n"
    "                      relaxed energies against the global result relaxed the same way: NAME_histogram.svg\n"
    "                      (the thesis's Table 2.3 as a plot; rectangles only; default 0)\n"
    "  --engine pf|pr|bk   max-flow engine: pseudoflow (default), push-relabel, Boykov-Kolmogorov\n"
    "  --seed S            random seed (default 1)\n"
    "  --output DIR        output folder (default mdcs-output); files NAME.ply/.svg/.png/_summary.txt\n"
    "  --name NAME         base name of the output files (default: the problem name)\n"
    "  --quiet             no progress bar\n";
}

struct Surface_settings
{
  std::string problem = "saddle";
  std::string domain;
  long planes = 150;
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
  bool quiet = false;
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
  double seconds_build = 0, seconds_weights = 0, seconds_cut = 0, seconds_relax = 0, seconds_total = 0;
  std::string ply, svg, summary;
  // --descents: relaxed energies of the random-start local descents and of the global result (same relaxation)
  std::vector<double> descent_energies;
  double global_descent_energy = NAN, seconds_descents = 0;
  std::string histogram_svg;
};


// An oblique view of a triangulated surface, painter's order, coloured by height and shaded; the boundary in red.
inline void write_surface_svg(const std::string& path, const VM3::Minimal_surface_3& s, const VM3::Surface_problem_3& p,
                              const std::string& title, const std::vector<std::string>& caption)
{
  const double az = 0.6, el = 0.55;
  const double sx = p.domain.xmax() - p.domain.xmin(), sy = p.domain.ymax() - p.domain.ymin(), sz = p.zmax - p.zmin;
  auto norm = [&](const std::array<double, 3>& q) {
    return std::array<double, 3>{{(q[0] - p.domain.xmin()) / sx - 0.5, (q[1] - p.domain.ymin()) / sy - 0.5,
                                  (q[2] - p.zmin) / sz * 0.7 - 0.35}};
  };
  auto project = [&](const std::array<double, 3>& q, double& u, double& v, double& depth) {
    const auto n = norm(q);
    const double a = std::cos(az) * n[0] - std::sin(az) * n[1];
    const double b = std::sin(az) * n[0] + std::cos(az) * n[1];
    u = 400 + 420 * a;
    v = 380 - 420 * (n[2] * std::cos(el) + b * std::sin(el));
    depth = b * std::cos(el) - n[2] * std::sin(el);
  };
  struct Tri { double depth; std::string svg; };
  std::vector<Tri> tris;
  for(const auto& t : s.triangles) {
    double u[3], v[3], d[3];
    double zc = 0;
    for(int k = 0; k < 3; ++k) {
      project(s.points[t[k]], u[k], v[k], d[k]);
      zc += s.points[t[k]][2] / 3;
    }
    // Height colour (blue -> green -> yellow) and Lambert shading from the normal in normalised coordinates.
    const auto a = norm(s.points[t[0]]), b = norm(s.points[t[1]]), c = norm(s.points[t[2]]);
    double nx = (b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]);
    double ny = (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]);
    double nz = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
    if(len == 0) continue;
    if(nz < 0) { nx = -nx; ny = -ny; nz = -nz; }
    const double shade = 0.55 + 0.45 * std::max(0.0, (-0.4 * nx - 0.3 * ny + 0.87 * nz) / len);
    const double h = std::min(1.0, std::max(0.0, (zc - p.zmin) / sz));
    const double r = (h < 0.5 ? 0.15 + 0.3 * h : 0.3 + 1.3 * (h - 0.5)) , g = 0.25 + 0.6 * h, bl = 0.65 - 0.5 * h;
    auto c255 = [&](double x) { return int(std::min(255.0, std::max(0.0, 255 * x * shade))); };
    std::ostringstream o;
    o << std::fixed << std::setprecision(1) << "<polygon points='" << u[0] << ',' << v[0] << ' ' << u[1] << ','
      << v[1] << ' ' << u[2] << ',' << v[2] << "' fill='rgb(" << c255(r) << ',' << c255(g) << ',' << c255(bl)
      << ")' stroke='rgb(" << c255(r * 0.9) << ',' << c255(g * 0.9) << ',' << c255(bl * 0.9)
      << ")' stroke-width='0.25'/>\n";
    tris.push_back({(d[0] + d[1] + d[2]) / 3, o.str()});
  }
  std::sort(tris.begin(), tris.end(), [](const Tri& a, const Tri& b) { return a.depth > b.depth; });
  std::ofstream out(path);
  if(!out) throw std::runtime_error("cannot write " + path);
  out << "<svg xmlns='http://www.w3.org/2000/svg' width='800' height='" << 700 + 18 * caption.size()
      << "' viewBox='0 0 800 " << 700 + 18 * caption.size() << "'>\n<rect width='100%' height='100%' fill='white'/>\n";
  out << "<text x='20' y='28' font-family='sans-serif' font-size='18'>" << title << "</text>\n";
  // The domain's floor outline, then the surface, then the boundary curve.
  std::vector<std::array<double, 2>> outline = p.domain_polygon;
  if(!p.is_polygonal())
    outline = {{{p.domain.xmin(), p.domain.ymin()}}, {{p.domain.xmax(), p.domain.ymin()}},
               {{p.domain.xmax(), p.domain.ymax()}}, {{p.domain.xmin(), p.domain.ymax()}}};
  {
    out << "<polygon fill='none' stroke='#bbb' stroke-dasharray='4,3' points='";
    for(const auto& c : outline) {
      double u, v, d;
      project({{c[0], c[1], p.zmin}}, u, v, d);
      out << u << ',' << v << ' ';
    }
    out << "'/>\n";
  }
  for(const Tri& t : tris) out << t.svg;
  if(!p.is_relaxed()) {
    out << "<polyline fill='none' stroke='#d62728' stroke-width='2' points='";
    const int m = 100;
    for(std::size_t e = 0; e <= outline.size(); ++e) {
      const auto& a = outline[e % outline.size()];
      const auto& b = outline[(e + 1) % outline.size()];
      for(int i = 0; i < (e == outline.size() ? 1 : m); ++i) {
        const double f = double(i) / m, x = a[0] + f * (b[0] - a[0]), y = a[1] + f * (b[1] - a[1]);
        double u, v, d;
        project({{x, y, p.lower_boundary(x, y)}}, u, v, d);
        out << u << ',' << v << ' ';
      }
    }
    out << "'/>\n";
  }
  for(std::size_t i = 0; i < caption.size(); ++i)
    out << "<text x='20' y='" << 700 + 18 * i << "' font-family='sans-serif' font-size='13'>" << caption[i] << "</text>\n";
  out << "</svg>\n";
}

inline Surface_settings parse_surface_settings(const Options& o)
{
  Surface_settings s;
  s.problem = o.text("problem", s.problem);
  if(s.problem != "saddle" && s.problem != "membrane" && s.problem != "blobs" && s.problem != "scherk")
    throw Usage_error("--problem must be saddle, membrane, blobs or scherk");
  s.domain = o.text("domain", "");
  if(!s.domain.empty() && s.problem == "blobs") throw Usage_error("--domain is not available for --problem blobs");
  s.planes = o.integer("planes", s.planes, 1);
  s.segments = o.integer("segments", s.segments, 1);
  if(s.segments > 256) throw Usage_error("--segments must be <= 256");
  s.distribution = o.text("distribution", s.distribution);
  if(s.distribution != "slope" && s.distribution != "isotropic")
    throw Usage_error("--distribution must be slope or isotropic");
  s.max_slope = o.number("max-slope", s.max_slope);
  if(!(s.max_slope > 0)) throw Usage_error("--max-slope must be > 0");
  s.pencil_fraction = o.number("pencil-fraction", s.pencil_fraction);
  if(!(s.pencil_fraction >= 0 && s.pencil_fraction <= 1)) throw Usage_error("--pencil-fraction must be in [0, 1]");
  s.plane_selection = o.integer("plane-selection", s.plane_selection, 1);
  s.refine = o.integer("refine", s.refine, 0);
  if(s.refine > 0 && s.plane_selection > 1) throw Usage_error("--refine and --plane-selection exclude each other");
  s.tangent_rounds = o.integer("tangent-rounds", s.tangent_rounds, 0);
  if(s.tangent_rounds > 1000) throw Usage_error("--tangent-rounds must be <= 1000");
  if(s.tangent_rounds > 0 && (s.refine > 0 || s.plane_selection > 1))
    throw Usage_error("--tangent-rounds excludes --refine and --plane-selection");
  s.fit_radius = o.number("fit-radius", s.fit_radius);
  if(!(s.fit_radius > 0 && s.fit_radius <= 1)) throw Usage_error("--fit-radius must be in (0, 1]");
  s.relax = o.has("relax");
  o.text("relax", "");
  s.basin_search = o.has("basin-search");
  o.text("basin-search", "");
  if(s.basin_search && !s.domain.empty()) throw Usage_error("--basin-search needs the problem's rectangle (not --domain)");
  if(s.basin_search && s.refine > 0) throw Usage_error("--basin-search and --refine exclude each other");
  if(s.basin_search && s.tangent_rounds > 0) throw Usage_error("--basin-search and --tangent-rounds exclude each other");
  s.descents = o.integer("descents", s.descents, 0);
  if(s.descents > 10000) throw Usage_error("--descents must be <= 10000");
  if(s.descents > 0 && !s.domain.empty()) throw Usage_error("--descents needs the problem's rectangle (not --domain)");
  s.engine = o.text("engine", s.engine);
  if(s.engine != "pf" && s.engine != "pr" && s.engine != "bk") throw Usage_error("--engine must be pf, pr or bk");
  s.seed = o.integer("seed", s.seed, 0);
  s.output = o.text("output", s.output);
  s.name = o.text("name", s.problem);
  s.quiet = o.has("quiet");
  o.text("quiet", "");
  return s;
}

// The polygon of --domain: "x0,y0;x1,y1;..." or L (an L-shaped hexagon filling three quarters of `box`).
inline std::vector<std::array<double, 2>> parse_surface_domain(const std::string& text, const CGAL::Bbox_2& box)
{
  if(text == "L") {
    const double x0 = box.xmin(), y0 = box.ymin(), x1 = box.xmax(), y1 = box.ymax();
    const double xm = 0.5 * (x0 + x1), ym = 0.5 * (y0 + y1);
    return {{{x0, y0}}, {{x1, y0}}, {{x1, ym}}, {{xm, ym}}, {{xm, y1}}, {{x0, y1}}};
  }
  std::vector<std::array<double, 2>> out;
  std::stringstream all(text);
  std::string vertex;
  while(std::getline(all, vertex, ';')) {
    std::array<double, 2> v{{0, 0}};
    std::stringstream one(vertex);
    char comma = 0;
    if(!(one >> v[0] >> comma >> v[1]) || comma != ',' || !(one >> std::ws).eof())
      throw Usage_error("--domain: cannot read the vertex '" + vertex + "' (expected x,y; vertices separated by ';')");
    out.push_back(v);
  }
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
void run_surface_descents(const Surface_settings& s, const Functional& G, Surface_run& run, Progress_bar& progress)
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

// The histogram of the local descents' relaxed energies, the global result's energy marked (NAME_histogram.svg).
inline void write_descent_histogram_svg(const std::string& path, const std::vector<double>& energies, double global,
                                        const std::string& title)
{
  const int bins = 12;
  double lo = global, hi = global;
  for(double e : energies) { lo = (std::min)(lo, e); hi = (std::max)(hi, e); }
  if(!(hi > lo)) hi = lo + 1e-9 * (1 + std::abs(lo));
  const double width = (hi - lo) / bins;
  std::vector<int> count(bins, 0);
  for(double e : energies) ++count[std::size_t((std::min)(bins - 1, int((e - lo) / width)))];
  const int top = (std::max)(1, *std::max_element(count.begin(), count.end()));
  const double W = 720, H = 400, L = 60, R = 45, T = 50, B = 70, pw = W - L - R, ph = H - T - B;
  std::ofstream f(path);
  f << std::setprecision(6) << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"" << W / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">" << title << "</text>\n";
  for(int b = 0; b < bins; ++b) {
    const double h = ph * count[std::size_t(b)] / top, x = L + pw * b / bins;
    f << "<rect x=\"" << x + 1 << "\" y=\"" << T + ph - h << "\" width=\"" << pw / bins - 2 << "\" height=\"" << h
      << "\" fill=\"#7a9cc6\"/>\n";
    if(count[std::size_t(b)] > 0)
      f << "<text x=\"" << x + pw / bins / 2 << "\" y=\"" << T + ph - h - 4 << "\" text-anchor=\"middle\">"
        << count[std::size_t(b)] << "</text>\n";
  }
  f << "<line x1=\"" << L << "\" y1=\"" << T + ph << "\" x2=\"" << L + pw << "\" y2=\"" << T + ph
    << "\" stroke=\"black\"/>\n<line x1=\"" << L << "\" y1=\"" << T << "\" x2=\"" << L << "\" y2=\"" << T + ph
    << "\" stroke=\"black\"/>\n";
  for(int k = 0; k <= 4; ++k) {
    const double e = lo + (hi - lo) * k / 4, x = L + pw * k / 4;
    f << "<text x=\"" << x << "\" y=\"" << T + ph + 16 << "\" text-anchor=\"middle\">" << e << "</text>\n";
  }
  const double gx = L + pw * (global - lo) / (hi - lo);
  f << "<line x1=\"" << gx << "\" y1=\"" << T - 6 << "\" x2=\"" << gx << "\" y2=\"" << T + ph
    << "\" stroke=\"#c0392b\" stroke-width=\"3\"/>\n<text x=\"" << gx + 6 << "\" y=\"" << T - 10
    << "\" fill=\"#c0392b\">global (min-cut) " << global << "</text>\n"
    << "<text x=\"" << L + pw / 2 << "\" y=\"" << H - 28
    << "\" text-anchor=\"middle\">relaxed energy (L-BFGS on 20^2, 40^2 grids); bars: " << energies.size()
    << " local descents from random starts</text>\n"
    << "<text x=\"14\" y=\"" << T + ph / 2 << "\" transform=\"rotate(-90 14 " << T + ph / 2
    << ")\" text-anchor=\"middle\">runs</text>\n</svg>\n";
}

template <class Functional>
void run_surface_with(const Surface_settings& s, const Functional& G, Surface_run& run, Progress_bar& progress)
{
  VM3::Surface_plane_options_3 po;
  po.distribution = s.distribution == "slope" ? VM3::Plane_distribution_3::slope_limited
                                              : VM3::Plane_distribution_3::isotropic;
  po.max_slope = s.max_slope;
  po.pencil_fraction = s.pencil_fraction;
  po.seed = std::uint64_t(s.seed);
  run.pencils = VM3::surface_pencil_count_3(run.problem, std::size_t(s.planes), po);
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
    const std::vector<VM3::Lattice_plane_3> planes = VM3::surface_planes_3(run.problem, std::size_t(s.planes), po);
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

inline Surface_run run_surface(const Surface_settings& s, Progress_bar& progress)
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
  const std::filesystem::path folder = prepare_output_folder(s.output);
  std::ostringstream sum;
  sum << std::setprecision(10);
  sum << "problem           " << s.problem << " (" << functional << ")\n"
      << "planes            " << s.planes << " (" << run.pencils << " through the boundary segments, "
      << (s.distribution == "slope" ? "slope-limited |slope| <= " + (std::ostringstream() << s.max_slope).str()
                                    : std::string("isotropic"))
      << ", seed " << s.seed << ")\n"
      << "domain            " << (run.problem.is_polygonal() ? "polygon with " + std::to_string(run.problem.domain_polygon.size()) + " vertices, area " + (std::ostringstream() << run.problem.domain_area()).str() : std::string("rectangle")) << "\n"
      << "complex           " << run.cells << " cells, " << run.facets << " facets, " << run.vertices << " vertices\n";
  if(!run.surface.is_feasible) {
    sum << "result            INFEASIBLE: no function on this arrangement meets the boundary condition\n";
    run.summary = sum.str();
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
  run.ply = (folder / (s.name + ".ply")).string();
  VM3::write_surface_ply(run.ply, run.surface);
  const VM3::Minimal_surface_3& shown = run.has_relaxed ? VM3::grid_surface_mesh_3(run.problem, run.relaxed) : run.surface;
  if(run.has_relaxed) VM3::write_surface_ply((folder / (s.name + "_relaxed.ply")).string(), shown);
  run.svg = (folder / (s.name + ".svg")).string();
  std::ostringstream cap1, cap2;
  cap1 << std::setprecision(8) << run.cells << " cells from " << s.planes << " planes; discrete energy "
       << run.surface.energy << (run.has_relaxed ? ", relaxed " : "");
  if(run.has_relaxed) cap1 << run.relaxed.energy;
  const std::string relaxed_on = run.relaxed.triangles.empty()
                                   ? std::to_string(run.relaxed.n) + "^2 grid"
                                   : std::to_string(run.relaxed.triangles.size()) + "-triangle mesh";
  cap2 << (run.has_relaxed ? "relaxed surface shown (" + relaxed_on + ")" : "discrete surface shown")
       << (run.problem.is_relaxed() ? "; boundary free in the band" : "; boundary curve in red");
  write_surface_svg(run.svg, run.has_relaxed ? VM3::grid_surface_mesh_3(run.problem, run.relaxed) : run.surface,
                    run.problem, "mdcs surface: " + s.problem, {cap1.str(), cap2.str()});
  svg_to_png(run.svg);
  if(!run.descent_energies.empty()) {
    std::vector<double> sorted = run.descent_energies;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t lower = std::size_t(std::count_if(sorted.begin(), sorted.end(),
                                                        [&](double e) { return descent_is_lower(e, run.global_descent_energy); }));
    sum << std::setprecision(8) << "local descents    " << sorted.size() << " from random starts (20^2, 40^2): best "
        << sorted.front() << ", median " << sorted[sorted.size() / 2] << "; global result relaxed the same way "
        << run.global_descent_energy << " (" << lower << " of the descents lower by more than 1e-6 relative); " << std::setprecision(3)
        << run.seconds_descents << " s\n";
    run.histogram_svg = (folder / (s.name + "_histogram.svg")).string();
    write_descent_histogram_svg(run.histogram_svg, run.descent_energies, run.global_descent_energy,
                                "mdcs surface " + s.problem + ": local descents vs the global result");
    svg_to_png(run.histogram_svg);
  }
  sum << "files             " << run.ply << ", " << run.svg << (run.histogram_svg.empty() ? "" : ", " + run.histogram_svg)
      << "\n";
  run.summary = sum.str();
  std::ofstream((folder / (s.name + "_summary.txt")).string()) << run.summary;
  return run;
}

inline int command_surface(const Options& o)
{
  if(o.has("help")) {
    std::cout << surface_usage();
    return EXIT_OK;
  }
  const Surface_settings s = parse_surface_settings(o);
  o.reject_unknown();
  if(!o.positional().empty()) throw Usage_error("unexpected argument '" + o.positional().front() + "'");
  Progress_bar progress(s.quiet);
  const Surface_run run = run_surface(s, progress);
  std::cout << run.summary;
  return run.surface.is_feasible ? EXIT_OK : EXIT_INFEASIBLE;
}

// Part of `mdcs demo`: writes its pictures and files into folder, appends a section to the summary md;
// returns false when one of its consistency checks failed.
inline bool demo_surface(const std::filesystem::path& folder, bool quick, bool quiet, Progress_bar& progress, std::ostream& md)
{
  bool ok = true;
  md << "\n## Minimal surfaces (bivariate problems)\n\nEach surface is the min-cut of the directed dual graph of a random "
        "plane arrangement (BSP complex with exact predicates); the cut value must equal the surface energy and the "
        "surface must be single-valued over the domain.\n\n"
        "| problem | planes | cells | discrete energy | cut gap | relaxed | exact | time (s) | picture |\n"
        "|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
  struct Demo { const char* problem; long planes; long selection; bool relax; const char* domain; };
  const std::vector<Demo> runs = quick ? std::vector<Demo>{{"saddle", 60, 1, false, ""}, {"scherk", 60, 1, true, ""},
                                                           {"saddle", 60, 1, false, "L"}}
                                       : std::vector<Demo>{{"saddle", 120, 1, true, ""}, {"membrane", 120, 1, false, ""},
                                                           {"scherk", 140, 1, true, ""}, {"blobs", 90, 3, true, ""},
                                                           {"saddle", 120, 1, true, "L"}};
  std::ostringstream hist;
  for(const Demo& d : runs) {
    Surface_settings s;
    s.problem = d.problem;
    s.planes = d.planes;
    s.plane_selection = d.selection;
    s.relax = d.relax;
    s.domain = d.domain;
    if(std::string(d.problem) == "blobs") s.descents = 8; // the histogram of Table 2.3, at a small size
    s.output = folder.string();
    s.name = std::string("surface_") + d.problem + (s.domain.empty() ? "" : "_" + s.domain);
    s.quiet = quiet;
    const Surface_run r = run_surface(s, progress);
    std::cout << "== surface " << d.problem << "\n" << r.summary << "\n";
    if(!r.surface.is_feasible) {
      ok = false;
      md << "| " << d.problem << " | " << d.planes << " | " << r.cells << " | INFEASIBLE | | | | | |\n";
      continue;
    }
    const double gap = std::abs(r.surface.energy - r.surface.solver_value) / r.surface.energy;
    const double single = std::abs(r.surface.projected_area - r.problem.domain_area()) / r.problem.domain_area();
    if(gap > 1e-9 || single > 1e-9) ok = false;
    std::ostringstream row;
    row << std::setprecision(8) << "| " << d.problem << (s.domain.empty() ? "" : " (" + s.domain + "-shaped domain)") << (d.selection > 1 ? " (plane selection x" + std::to_string(d.selection) + ")" : "")
        << " | " << d.planes << " | " << r.cells << " | " << r.surface.energy << " | " << std::setprecision(2) << gap
        << " | " << std::setprecision(8);
    if(r.has_relaxed) row << r.relaxed.energy;
    else row << "-";
    row << " | ";
    if(std::isfinite(r.exact)) row << r.exact;
    else row << "-";
    row << " | " << std::setprecision(3) << r.seconds_total << " | [" << s.name << ".svg](" << s.name << ".svg) |\n";
    md << row.str();
    if(!r.histogram_svg.empty()) {
      std::size_t lower = 0;
      for(double e : r.descent_energies) lower += descent_is_lower(e, r.global_descent_energy) ? 1 : 0;
      hist << "\nBlob problem (thesis Table 2.3 as a plot): " << r.descent_energies.size()
           << " local descents from random smooth starts against the global result, all relaxed on 20^2, 40^2 grids: "
           << lower << " of them end lower than the global result. [" << s.name << "_histogram.svg](" << s.name
           << "_histogram.svg)\n";
    }
  }
  md << hist.str();
  (void)progress;
  return ok;
}

} // namespace mdcs_cli

#endif // MDCS_CLI_CMD_SURFACE_H
