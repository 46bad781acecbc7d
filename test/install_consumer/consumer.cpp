// Uses an installed MDCS: a two-cell min cut and a tiny curve problem.
#include <CGAL/Min_cut.h>
#include <CGAL/Variational_minimization.h>
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
  return (cut.value == 1.5 && std::abs(curve.energy - std::sqrt(2.0)) < 1e-12) ? 0 : 1;
}
