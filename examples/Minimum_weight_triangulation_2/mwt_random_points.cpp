// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Minimum weight triangulation of random points (or of the points in argv[1], "x y" per line), with the
// status of the certificate; then the thesis's 13-wheel, whose LP optimum is fractional.
// Build: link GLPK and COIN-OR CLP and define MDCS_HAS_GLPK=1, MDCS_HAS_CLP=1 (the target mdcs_dev_options does).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Minimum_weight_triangulation_2.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <random>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;
namespace MWT = CGAL::Minimum_weight_triangulation_2;

int main(int argc, char** argv)
{
  std::vector<Point> points;
  if(argc > 1) {
    std::ifstream in(argv[1]);
    double x, y;
    while(in >> x >> y) points.emplace_back(x, y);
  } else {
    std::mt19937 g(42);
    std::uniform_real_distribution<double> u(0, 1);
    for(int i = 0; i < 500; ++i) points.emplace_back(u(g), u(g));
  }

  MWT::Mwt_result r = MWT::minimum_weight_triangulation_2(points);   // diamond test + CLP + certificate
  std::cout << points.size() << " points: " << MWT::to_string(r.status) << ", weight " << r.weight
            << ", rigorous lower bound " << r.lower_bound << ", " << r.triangles.size() << " triangles, "
            << r.statistics.candidate_edges << " candidate edges, " << r.statistics.time_total << " s\n";

  // The thesis's counterexample: a centre and 13 points on the unit circle.
  std::vector<Point> wheel{Point(0, 0)};
  for(int i = 0; i < 13; ++i) wheel.emplace_back(std::cos(2 * M_PI * i / 13), std::sin(2 * M_PI * i / 13));
  MWT::Mwt_options lp_only;
  lp_only.resolve_fractional = false;
  const MWT::Mwt_result f = MWT::minimum_weight_triangulation_2(wheel, lp_only);
  const MWT::Mwt_result w = MWT::minimum_weight_triangulation_2(wheel);   // branch and bound (GLPK)
  std::cout << "13-wheel: LP optimum " << f.lp_objective << " (" << MWT::to_string(f.status) << "), MWT "
            << w.weight << " (" << MWT::to_string(w.status) << ")\n";
  return r.has_triangulation() && w.has_triangulation() ? 0 : 1;
}
