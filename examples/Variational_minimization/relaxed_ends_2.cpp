// A path of least "cost" across a density field with relaxed end conditions: the curve may start anywhere in
// [0.1, 0.9] on the left and end anywhere in [0.6, 0.9] on the right. Writes relaxed_ends_2.svg.
//   relaxed_ends_2 [LINES]      (default 800)
#include <CGAL/Variational_minimization.h>

#include <cmath>
#include <cstdlib>
#include <iostream>

namespace VM = CGAL::Variational_minimization;

int main(int argc, char** argv)
{
  const std::size_t n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 800;

  // Cheap valley along f = 0.3 + 0.4 x, expensive hill in the middle.
  auto density = [](double x, double f) {
    const double valley = f - (0.3 + 0.4 * x);
    return 0.2 + 4 * valley * valley + 3 * std::exp(-40 * ((x - 0.5) * (x - 0.5) + (f - 0.5) * (f - 0.5)));
  };
  const VM::Curve_problem_2 problem{CGAL::Bbox_2(0, 0, 1, 1), VM::End_condition::range(0.1, 0.9),
                                    VM::End_condition::range(0.6, 0.9)};
  const auto lines = VM::random_lines_2(problem.box, n, /*seed*/ 2);
  const VM::Line_arrangement_2 arrangement = VM::build_curve_arrangement_2(problem, lines);
  const auto weights = VM::curve_edge_weights_2(arrangement, VM::make_density_weighted_length_functional(density));

  const VM::Minimal_curve_2 cut = VM::minimize_curve_functional_2(arrangement, weights, problem);
  const VM::Minimal_curve_2 path = VM::directed_shortest_path_2(arrangement, weights, problem); // the oracle
  if(!cut.is_feasible) {
    std::cerr << "infeasible\n";
    return 1;
  }
  std::cout.precision(10);
  std::cout << "min-cut energy " << cut.energy << ", shortest path " << path.energy << "\n"
            << "starts at f(0) = " << cut.polyline.front().y() << ", ends at f(1) = " << cut.polyline.back().y() << "\n";

  VM::Svg_curve_plot plot;
  plot.title = "relaxed ends: f(0) in [0.1, 0.9], f(1) in [0.6, 0.9]";
  for(std::size_t i = 0; i < arrangement.number_of_edges(); ++i) {
    const auto& e = arrangement.edge(VM::Line_arrangement_2::Edge_index(i));
    const auto &a = arrangement.point(e.source), &b = arrangement.point(e.target);
    plot.grid_segments.push_back({a.x(), a.y(), b.x(), b.y()});
  }
  for(const auto& p : cut.polyline) plot.solution.push_back({p.x(), p.y()});
  VM::write_curve_svg("relaxed_ends_2.svg", plot);
  std::cout << "wrote relaxed_ends_2.svg\n";
  return std::abs(cut.energy - path.energy) <= 1e-9 * path.energy ? 0 : 1;
}
