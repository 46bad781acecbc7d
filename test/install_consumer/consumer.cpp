// Uses an installed MDCS: a two-cell min cut, a tiny curve problem and, with the LP solvers of
// MDCS::LP_solvers, the minimum weight triangulation of a square and its centre.
#include <CGAL/Min_cut.h>
#include <CGAL/Variational_minimization.h>
#if defined(MDCS_HAS_CLP) || defined(MDCS_HAS_GLPK)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Minimum_weight_triangulation_2.h>
#endif
#include <cmath>
#include <iostream>

int main()
{
  CGAL::Min_cut::Flow_network<double> network;
  const auto first = network.add_nodes(2);
  network.add_source_facet(first, 3.0, 0);
  network.add_facet(first, first + 1, 1.5, CGAL::Min_cut::Flow_network<double>::infinity(), 1);
  network.add_sink_facet(first + 1, 2.0, 2);
  const auto cut = CGAL::Min_cut::solve_min_cut(network);

  namespace VM = CGAL::Variational_minimization;
  VM::Curve_problem_2 problem{CGAL::Bbox_2(0, 0, 1, 1), VM::End_condition::fixed(0), VM::End_condition::fixed(1)};
  std::vector<VM::Arrangement_line_2> lines{{VM::Point_2(0, 0), VM::Point_2(1, 1)}};
  const auto arrangement = VM::build_curve_arrangement_2(problem, lines);
  const auto weights = VM::curve_edge_weights_2(arrangement, VM::Arc_length_functional());
  const auto curve = VM::minimize_curve_functional_2(arrangement, weights, problem);

  std::cout << "cut " << cut.value << ", diagonal " << curve.energy << "\n";
  bool ok = cut.value == 1.5 && std::abs(curve.energy - std::sqrt(2.0)) < 1e-12;
#if defined(MDCS_HAS_CLP) || defined(MDCS_HAS_GLPK)
  // The centre is collinear with both diagonals: the only triangulation joins it to the four corners.
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 Point;
  const std::vector<Point> square{Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1), Point(0.5, 0.5)};
  const auto mwt = CGAL::Minimum_weight_triangulation_2::minimum_weight_triangulation_2(square);
  std::cout << "square + centre: MWT weight " << mwt.weight << ", " << mwt.triangles.size() << " triangles\n";
  ok = ok && mwt.has_triangulation() && mwt.triangles.size() == 4 && std::abs(mwt.weight - (4 + 2 * std::sqrt(2.0))) < 1e-9;
#endif
  return ok ? 0 : 1;
}
