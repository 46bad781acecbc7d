// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Regular plane grids against random planes (thesis ch. 2.5.3; issue 30 item 2): the error of the minimal discrete
// energy, and of the surface's heights, against the number of planes, on two problems with a known minimum:
//   membrane: sagging_membrane_problem() (unit square, rim at 0.75, area + 2 f); reference: relaxation on 20^2..160^2
//             grids (the minimiser is unique; the relaxed function is also the reference of the heights);
//   scherk:   Scherk's surface on [-1.2, 1.2]^2, 4 boundary segments per side; reference energy: the minimal area
//             spanning the piecewise linear boundary curve (what the discrete energies converge to), by relaxation;
//             heights against the analytic surface ln(cos y / cos x).
// Sources: the regular grid regular_surface_planes_3(n) with m = 1 and m = n offset steps (m = n for n = 2, 3 on the
// membrane, n = 2 on Scherk), and slope-limited random planes (surface_planes_3, 20% pencils, the same max_slope) with
// as many planes as the grid of each n with m = 1, several seeds (median, min, max; at most 3 on Scherk).
//
//   bench_surface_plane_grids_3 [--quick] [--seeds K] [--problem membrane|scherk|both] [--csv PATH] [--svg PATH]
//
// Defaults: 5 seeds, both problems, benchmark/results/surface_plane_grids.csv and
// doc/Variational_minimization/surface_plane_grids.svg (paths relative to the working directory).

#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/analytic_solutions_3.h>
#include <CGAL/Variational_minimization/internal/surface_height_3.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/plane_grids_3.h>
#include <CGAL/Variational_minimization/relax_surface_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include "mdcs_bench.h"
#include <MDCS_test/surface_problems.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace VM = CGAL::Variational_minimization;
using mdcs_bench::fmt;

namespace {

struct Experiment
{
  std::string name;
  VM::Surface_problem_3 problem;
  std::function<std::vector<double>(const VM::Plane_arrangement_3&)> weights;
  double max_slope = 1;
  std::vector<std::size_t> grid_steps; // the n of the regular grids
  std::size_t largest_n_with_m_n = 0;  // the grids with m = n are run for 2 <= n <= this
  int seeds = 5;
  double reference_energy = 0;
  std::function<double(double, double)> reference_height;
};

struct Run
{
  std::size_t planes = 0, cells = 0;
  double energy = 0, energy_error = 0, height_error = 0, seconds = 0, cpu_seconds = 0;
};

// The discrete minimum on `planes`, its energy error relative to the reference, and the RMS of its height error at
// the 39 x 39 interior points of a 40 x 40 grid over the domain.
Run solve(const Experiment& e, const std::vector<VM::Lattice_plane_3>& planes)
{
  Run r;
  const double t0 = mdcs_bench::now_seconds(), c0 = mdcs_bench::cpu_seconds();
  const VM::Plane_arrangement_3 A(planes);
  const VM::Minimal_surface_3 s = VM::minimize_surface_functional_3(A, e.weights(A), e.problem);
  r.seconds = mdcs_bench::now_seconds() - t0;
  r.cpu_seconds = mdcs_bench::cpu_seconds() - c0;
  r.planes = planes.size();
  r.cells = A.number_of_cells();
  r.energy = s.energy;
  r.energy_error = (s.energy - e.reference_energy) / e.reference_energy;
  const VM::internal::Surface_height_3 height(s);
  const CGAL::Bbox_2& D = e.problem.domain;
  double sum = 0;
  int count = 0;
  for(int i = 1; i < 40; ++i)
    for(int j = 1; j < 40; ++j) {
      const double x = D.xmin() + (D.xmax() - D.xmin()) * i / 40.0, y = D.ymin() + (D.ymax() - D.ymin()) * j / 40.0;
      const double d = height(x, y) - e.reference_height(x, y);
      sum += d * d;
      ++count;
    }
  r.height_error = std::sqrt(sum / count);
  return r;
}

// The relaxed function of `r` (level n) at (x, y): linear on the two triangles of each grid square.
double relaxed_height(const VM::Surface_problem_3& P, const VM::Relaxed_surface_3& r, double x, double y)
{
  const CGAL::Bbox_2& D = P.domain;
  const double u = (x - D.xmin()) / (D.xmax() - D.xmin()) * r.n, v = (y - D.ymin()) / (D.ymax() - D.ymin()) * r.n;
  const int i = std::min(r.n - 1, std::max(0, int(std::floor(u)))), j = std::min(r.n - 1, std::max(0, int(std::floor(v))));
  const double s = u - i, t = v - j;
  auto h = [&](int a, int b) { return r.heights[std::size_t(b) * std::size_t(r.n + 1) + std::size_t(a)]; };
  // Any split of the square interpolates within the grid's own error; the mean of both splits is symmetric.
  const double lower = s + t <= 1 ? h(i, j) + s * (h(i + 1, j) - h(i, j)) + t * (h(i, j + 1) - h(i, j))
                                  : h(i + 1, j + 1) + (1 - s) * (h(i, j + 1) - h(i + 1, j + 1)) +
                                      (1 - t) * (h(i + 1, j) - h(i + 1, j + 1));
  const double upper = s >= t ? h(i, j) + s * (h(i + 1, j) - h(i, j)) + t * (h(i + 1, j + 1) - h(i + 1, j))
                              : h(i, j) + t * (h(i, j + 1) - h(i, j)) + s * (h(i + 1, j + 1) - h(i, j + 1));
  return 0.5 * (lower + upper);
}

struct Series
{
  std::string label, colour;
  std::vector<double> x, y, lo, hi; // lo/hi: the spread (random planes), else equal to y
};

// A log-log plot of the energy errors of both problems, one panel each.
void write_svg(const std::string& path, const std::vector<std::string>& titles,
               const std::vector<std::vector<Series>>& panels)
{
  std::ofstream out(path);
  if(!out) {
    std::fprintf(stderr, "cannot write %s\n", path.c_str());
    return;
  }
  const double pw = 360, ph = 280, left = 60, top = 30, gap = 40;
  const double width = left + panels.size() * (pw + gap), height = top + ph + 60;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for(std::size_t p = 0; p < panels.size(); ++p) {
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for(const Series& s : panels[p])
      for(std::size_t i = 0; i < s.x.size(); ++i) {
        x0 = std::min(x0, s.x[i]); x1 = std::max(x1, s.x[i]);
        y0 = std::min(y0, std::max(s.lo[i], 1e-6)); y1 = std::max(y1, s.hi[i]);
      }
    const double lx0 = std::floor(std::log10(x0) * 5) / 5, lx1 = std::ceil(std::log10(x1) * 5) / 5;
    const double ly0 = std::floor(std::log10(y0)), ly1 = std::ceil(std::log10(y1));
    const double ox = left + p * (pw + gap);
    auto X = [&](double v) { return ox + (std::log10(v) - lx0) / (lx1 - lx0) * pw; };
    auto Y = [&](double v) { return top + ph - (std::log10(std::max(v, 1e-6)) - ly0) / (ly1 - ly0) * ph; };
    out << "<rect x=\"" << ox << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
        << "\" fill=\"none\" stroke=\"black\"/>\n";
    out << "<text x=\"" << ox + pw / 2 << "\" y=\"" << top - 10 << "\" text-anchor=\"middle\">" << titles[p] << "</text>\n";
    for(double e = ly0; e <= ly1 + 1e-9; e += 1)
      out << "<line x1=\"" << ox << "\" x2=\"" << ox + pw << "\" y1=\"" << Y(std::pow(10, e)) << "\" y2=\""
          << Y(std::pow(10, e)) << "\" stroke=\"#ddd\"/><text x=\"" << ox - 4 << "\" y=\"" << Y(std::pow(10, e)) + 4
          << "\" text-anchor=\"end\">1e" << int(e) << "</text>\n";
    for(double v : {20.0, 50.0, 100.0, 200.0, 500.0, 1000.0})
      if(std::log10(v) >= lx0 && std::log10(v) <= lx1)
        out << "<line x1=\"" << X(v) << "\" x2=\"" << X(v) << "\" y1=\"" << top << "\" y2=\"" << top + ph
            << "\" stroke=\"#ddd\"/><text x=\"" << X(v) << "\" y=\"" << top + ph + 14 << "\" text-anchor=\"middle\">"
            << v << "</text>\n";
    out << "<text x=\"" << ox + pw / 2 << "\" y=\"" << top + ph + 30 << "\" text-anchor=\"middle\">planes</text>\n";
    if(p == 0)
      out << "<text transform=\"translate(14," << top + ph / 2 << ") rotate(-90)\" text-anchor=\"middle\">relative "
          << "energy error</text>\n";
    for(std::size_t k = 0; k < panels[p].size(); ++k) {
      const Series& s = panels[p][k];
      out << "<polyline fill=\"none\" stroke=\"" << s.colour << "\" stroke-width=\"1.5\" points=\"";
      for(std::size_t i = 0; i < s.x.size(); ++i) out << X(s.x[i]) << "," << Y(s.y[i]) << " ";
      out << "\"/>\n";
      for(std::size_t i = 0; i < s.x.size(); ++i) {
        if(s.hi[i] > s.lo[i])
          out << "<line x1=\"" << X(s.x[i]) << "\" x2=\"" << X(s.x[i]) << "\" y1=\"" << Y(s.lo[i]) << "\" y2=\""
              << Y(s.hi[i]) << "\" stroke=\"" << s.colour << "\"/>\n";
        out << "<circle cx=\"" << X(s.x[i]) << "\" cy=\"" << Y(s.y[i]) << "\" r=\"3\" fill=\"" << s.colour << "\"/>\n";
      }
      out << "<text x=\"" << ox + 10 + double(k) * 120 << "\" y=\"" << top + ph + 46 << "\" fill=\"" << s.colour
          << "\">" << s.label << "</text>\n";
    }
  }
  out << "</svg>\n";
}

} // namespace

int main(int argc, char** argv)
{
  bool quick = false;
  int seeds = 5;
  std::string which = "both", csv = "benchmark/results/surface_plane_grids.csv",
              svg = "doc/Variational_minimization/surface_plane_grids.svg";
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--quick") quick = true;
    else if(a == "--seeds" && i + 1 < argc) seeds = std::max(1, std::atoi(argv[++i]));
    else if(a == "--problem" && i + 1 < argc) which = argv[++i];
    else if(a == "--csv" && i + 1 < argc) csv = argv[++i];
    else if(a == "--svg" && i + 1 < argc) svg = argv[++i];
    else {
      std::fprintf(stderr, "usage: %s [--quick] [--seeds K] [--problem membrane|scherk|both] [--csv PATH] [--svg PATH]\n",
                   argv[0]);
      return 2;
    }
  }

  std::vector<Experiment> experiments;
  VM::Surface_relaxation_options_3 fine;
  fine.grids = {20, 40, 80, 160};
  if(which == "membrane" || which == "both") {
    Experiment e;
    e.name = "membrane";
    e.problem = MDCS_test::sagging_membrane_problem();
    const VM::Membrane_functional_3 G = MDCS_test::sagging_membrane_functional();
    e.weights = [G, P = e.problem](const VM::Plane_arrangement_3& A) { return VM::surface_facet_weights_3(A, P, G); };
    e.max_slope = 1;
    e.largest_n_with_m_n = 3;
    e.seeds = seeds;
    e.grid_steps = quick ? std::vector<std::size_t>{1, 2, 3} : std::vector<std::size_t>{1, 2, 3, 4, 5};
    const auto relaxed = std::make_shared<VM::Relaxed_surface_3>(
      VM::relax_surface_3(e.problem, G, [](double, double) { return 0.75; }, fine));
    e.reference_energy = relaxed->energy;
    e.reference_height = [relaxed, P = e.problem](double x, double y) { return relaxed_height(P, *relaxed, x, y); };
    experiments.push_back(e);
  }
  if(which == "scherk" || which == "both") {
    Experiment e;
    e.name = "scherk";
    e.problem = VM::scherk_surface_problem_3(4);
    e.weights = [P = e.problem](const VM::Plane_arrangement_3& A) {
      return VM::surface_facet_weights_3(A, P, VM::Area_functional_3());
    };
    e.max_slope = 3;
    e.largest_n_with_m_n = 2;
    e.seeds = std::min(seeds, 3); // about 2.5M cells per random arrangement at n = 3
    e.grid_steps = quick ? std::vector<std::size_t>{1, 2} : std::vector<std::size_t>{1, 2, 3};
    e.reference_energy = VM::relax_surface_3(MDCS_test::scherk_piecewise_linear_boundary_problem(4),
                                             VM::Area_functional_3(), VM::scherk_surface_height, fine).energy;
    e.reference_height = VM::scherk_surface_height;
    experiments.push_back(e);
  }

  std::printf("Regular plane grids against random planes (build + weights + cut per row; wall-clock and CPU seconds:\n"
              "the machine may be shared).\n");
  mdcs_bench::Table table({"problem", "source", "n", "m", "seed", "planes", "cells", "energy", "reference_energy",
                           "energy_rel_error", "height_rms_error", "seconds", "cpu_seconds"});
  std::vector<std::string> titles;
  std::vector<std::vector<Series>> panels;
  for(const Experiment& e : experiments) {
    std::printf("\n== %s: reference energy %.10f, max_slope %g\n", e.name.c_str(), e.reference_energy, e.max_slope);
    Series grid1{"grid, m = 1", "#1f77b4", {}, {}, {}, {}}, gridn{"grid, m = n", "#2ca02c", {}, {}, {}, {}},
      random{"random (median, range)", "#d62728", {}, {}, {}, {}};
    auto add = [&](const char* source, std::size_t n, std::size_t m, const std::string& seed, const Run& r) {
      table.add_row({e.name, source, n ? std::to_string(n) : "", m ? std::to_string(m) : "", seed,
                     std::to_string(r.planes), std::to_string(r.cells), fmt(r.energy, "%.10g"),
                     fmt(e.reference_energy, "%.10g"), fmt(r.energy_error, "%.4e"), fmt(r.height_error, "%.4e"),
                     fmt(r.seconds, "%.3g"), fmt(r.cpu_seconds, "%.3g")});
      std::printf("  %-6s n=%zu m=%zu seed=%s planes=%zu cells=%zu error=%.4e height=%.4e (%.2f s)\n", source, n, m,
                  seed.c_str(), r.planes, r.cells, r.energy_error, r.height_error, r.seconds);
      std::fflush(stdout);
    };
    for(std::size_t n : e.grid_steps) {
      VM::Regular_surface_plane_options_3 o;
      o.max_slope = e.max_slope;
      o.offset_steps = 1;
      const Run r1 = solve(e, VM::regular_surface_planes_3(e.problem, n, o));
      add("grid", n, 1, "", r1);
      grid1.x.push_back(double(r1.planes)); grid1.y.push_back(r1.energy_error);
      grid1.lo.push_back(r1.energy_error); grid1.hi.push_back(r1.energy_error);
      if(n > 1 && n <= e.largest_n_with_m_n) {
        o.offset_steps = n;
        const Run rn = solve(e, VM::regular_surface_planes_3(e.problem, n, o));
        add("grid", n, n, "", rn);
        gridn.x.push_back(double(rn.planes)); gridn.y.push_back(rn.energy_error);
        gridn.lo.push_back(rn.energy_error); gridn.hi.push_back(rn.energy_error);
      }
      // Random planes, as many as the grid with m = 1.
      std::vector<double> errors;
      for(int seed = 1; seed <= e.seeds; ++seed) {
        VM::Surface_plane_options_3 ro;
        ro.distribution = VM::Plane_distribution_3::slope_limited;
        ro.max_slope = e.max_slope;
        ro.pencil_fraction = 0.2;
        ro.seed = std::uint64_t(seed);
        const Run r = solve(e, VM::surface_planes_3(e.problem, r1.planes, ro));
        add("random", 0, 0, std::to_string(seed), r);
        errors.push_back(r.energy_error);
      }
      random.x.push_back(double(r1.planes));
      random.y.push_back(mdcs_bench::median(errors));
      random.lo.push_back(*std::min_element(errors.begin(), errors.end()));
      random.hi.push_back(*std::max_element(errors.begin(), errors.end()));
    }
    titles.push_back(e.name == "membrane" ? "heavy membrane (area + 2 f), max_slope 1"
                                          : "Scherk, 4 segments per side, max_slope 3");
    panels.push_back({grid1, gridn, random});
  }
  std::printf("\n");
  table.print();
  if(!table.write_csv(csv)) std::fprintf(stderr, "cannot write %s\n", csv.c_str());
  write_svg(svg, titles, panels);
  return 0;
}
