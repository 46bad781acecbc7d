// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Benchmark of relaxation and adaptive refinement on polygonal domains (issue 6, items 4 and 6):
//   1. relaxation on the polygon's Delaunay meshes (levels 20, 40, 80, 160) from the discrete optimum: energy per
//      level, nodes, triangles, L-BFGS iterations, time (median of 3 repetitions); linear data gives the plane;
//   2. adaptive refinement (3 runs of N planes, seeds 1..3): run energies, refined energy, relaxed, the cells
//      merged into source and sink and left out, the network solved, time.
//
//   bench_surface_polygon_3 [--quick] [--csv-prefix PATH]
//
// CSV files: PATH_polygon_relax.csv, PATH_polygon_refine.csv (default PATH: surface).

#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/refine_surface_3.h>
#include <CGAL/Variational_minimization/relax_surface_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include "mdcs_bench.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace VM = CGAL::Variational_minimization;
using mdcs_bench::fmt;

namespace {

typedef std::vector<std::array<double, 2>> Polygon;

const Polygon L_shape = {{{0, 0}}, {{1, 0}}, {{1, 0.5}}, {{0.5, 0.5}}, {{0.5, 1}}, {{0, 1}}};
const Polygon hexagon = {{{0.25, 0}}, {{0.75, 0}}, {{1, 0.5}}, {{0.75, 1}}, {{0.25, 1}}, {{0, 0.5}}};
const Polygon u_shape = {{{0, 0}}, {{1, 0}}, {{1, 1}}, {{0.75, 1}}, {{0.75, 0.25}}, {{0.25, 0.25}}, {{0.25, 1}},
                         {{0, 1}}};

// Linear along each edge of the hexagon, heights alternating 0.3 / 0.7 at its vertices (a three-fold saddle).
double hexagon_saddle(double x, double y)
{
  double best = 1e300, value = 0.5;
  for(std::size_t e = 0; e < hexagon.size(); ++e) {
    const auto& a = hexagon[e];
    const auto& b = hexagon[(e + 1) % hexagon.size()];
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double t = std::max(0.0, std::min(1.0, ((x - a[0]) * dx + (y - a[1]) * dy) / (dx * dx + dy * dy)));
    const double d = std::hypot(a[0] + t * dx - x, a[1] + t * dy - y);
    if(d < best) {
      best = d;
      value = e % 2 == 0 ? 0.3 + 0.4 * t : 0.7 - 0.4 * t;
    }
  }
  return value;
}

double saddle(double x, double y) { return 0.5 + 1.2 * (x - 0.5) * (y - 0.5); }
double linear(double x, double y) { return 0.25 + 0.5 * x + 0.25 * y; }

struct Case
{
  const char* name;
  const Polygon* polygon;
  double (*g)(double, double);
};

VM::Surface_plane_options_3 plane_options(std::uint64_t seed)
{
  VM::Surface_plane_options_3 o;
  o.distribution = VM::Plane_distribution_3::slope_limited;
  o.pencil_fraction = 0.2;
  o.seed = seed;
  return o;
}

VM::Surface_problem_3 problem_for(const Case& c)
{
  VM::Surface_problem_3 P;
  P.boundary_segments_per_side = 4;
  P.lower_boundary = c.g;
  P.set_domain_polygon(*c.polygon);
  return P;
}

} // namespace

int main(int argc, char** argv)
{
  bool quick = false;
  std::string prefix = "surface";
  for(int i = 1; i < argc; ++i) {
    if(!std::strcmp(argv[i], "--quick")) quick = true;
    else if(!std::strcmp(argv[i], "--csv-prefix") && i + 1 < argc) prefix = argv[++i];
    else {
      std::fprintf(stderr, "usage: bench_surface_polygon_3 [--quick] [--csv-prefix PATH]\n");
      return 2;
    }
  }
  const std::vector<Case> cases = {{"L saddle", &L_shape, saddle},
                                   {"hexagon 3-saddle", &hexagon, hexagon_saddle},
                                   {"U saddle", &u_shape, saddle},
                                   {"L linear", &L_shape, linear}};
  const std::size_t planes = quick ? 60 : 120;
  const std::vector<int> levels = quick ? std::vector<int>{20, 40} : std::vector<int>{20, 40, 80, 160};

  std::printf("== 1. Relaxation on polygons: area, boundary data g, %zu slope-limited planes (20%% pencils, seed 1), "
              "then relaxation on Delaunay meshes of the polygon (levels 20..%d; a level-n mesh has edges <= the "
              "diagonal of the n x n grid's squares). Times: median of 3.\n",
              planes, levels.back());
  mdcs_bench::Table relax({"domain", "planes", "discrete_energy", "level", "nodes", "triangles", "start_energy",
                           "relaxed_energy", "iterations", "relax_s", "exact"});
  for(const Case& c : cases) {
    const VM::Surface_problem_3 P = problem_for(c);
    const VM::Plane_arrangement_3 A = VM::build_surface_arrangement_3(P, VM::surface_planes_3(P, planes, plane_options(1)));
    const VM::Minimal_surface_3 s = VM::minimize_surface_functional_3(A, P, VM::Area_functional_3());
    const double exact = c.g == linear ? std::sqrt(1 + 0.25 + 0.0625) * P.domain_area() : std::nan("");
    std::vector<int> grids;
    for(int n : levels) {
      grids.push_back(n);
      VM::Surface_relaxation_options_3 o;
      o.grids = grids;
      std::vector<double> times;
      VM::Relaxed_surface_3 r;
      for(int rep = 0; rep < 3; ++rep) {
        const double t0 = mdcs_bench::now_seconds();
        r = VM::relax_surface_3(P, VM::Area_functional_3(), s, o);
        times.push_back(mdcs_bench::now_seconds() - t0);
      }
      relax.add_row({c.name, std::to_string(planes), fmt(s.energy, "%.10g"), std::to_string(n),
                     std::to_string(r.nodes.size()), std::to_string(r.triangles.size()),
                     fmt(r.level_start_energies.back(), "%.10g"), fmt(r.energy, "%.10g"), std::to_string(r.iterations),
                     fmt(mdcs_bench::median(times)), std::isfinite(exact) ? fmt(exact, "%.10g") : "-"});
    }
  }
  relax.print();
  relax.write_csv(prefix + "_polygon_relax.csv");

  const std::size_t refine_planes = quick ? 60 : 100;
  std::printf("\n== 2. Adaptive refinement on polygons: 3 runs of %zu planes, margin 0, then the refined arrangement "
              "(%zu planes), relaxed (levels 20, 40, 80); seeds 1..3.\n",
              refine_planes, refine_planes);
  mdcs_bench::Table refine({"domain", "seed", "run_energies", "best_run", "refined_energy", "relaxed_energy", "cells",
                            "below", "above", "outside", "network_nodes", "refine_s", "relax_s"});
  for(const Case& c : cases)
    for(std::uint64_t seed = 1; seed <= (quick ? 1u : 3u); ++seed) {
      const VM::Surface_problem_3 P = problem_for(c);
      double t0 = mdcs_bench::now_seconds();
      const VM::Surface_refinement_result_3 R =
        VM::refine_surface_3(P, VM::Area_functional_3(), refine_planes, 3, plane_options(seed), 0.0);
      const double t_refine = mdcs_bench::now_seconds() - t0;
      t0 = mdcs_bench::now_seconds();
      const VM::Relaxed_surface_3 r = VM::relax_surface_3(P, VM::Area_functional_3(), R.surface);
      const double t_relax = mdcs_bench::now_seconds() - t0;
      std::string runs;
      for(double e : R.run_energies) runs += (runs.empty() ? "" : " ") + fmt(e, "%.8g");
      refine.add_row({c.name, std::to_string(seed), runs,
                      fmt(*std::min_element(R.run_energies.begin(), R.run_energies.end()), "%.10g"),
                      fmt(R.surface.energy, "%.10g"), fmt(r.energy, "%.10g"), std::to_string(R.cells),
                      std::to_string(R.cells_below), std::to_string(R.cells_above), std::to_string(R.cells_outside),
                      std::to_string(R.network_nodes), fmt(t_refine), fmt(t_relax)});
    }
  refine.print();
  refine.write_csv(prefix + "_polygon_refine.csv");
  return 0;
}
