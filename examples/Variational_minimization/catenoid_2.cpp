// The minimal surface of rotation between two rings (the catenoid problem), solved globally on a random
// line arrangement and compared with the analytic optimum.
//   catenoid_2 [R] [LINES]      (defaults: R = 2, 1600 lines)
#include <CGAL/Variational_minimization.h>

#include <cstdlib>
#include <iostream>

namespace VM = CGAL::Variational_minimization;

int main(int argc, char** argv)
{
  const double R = argc > 1 ? std::atof(argv[1]) : 2.0;
  const std::size_t n = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 1600;
  if(!(R > 0)) {
    std::cerr << "usage: catenoid_2 [R > 0] [LINES]\n";
    return 2;
  }

  // Rings of radius R at x = -1 and x = 1; the box floor is the axis f = 0.
  const VM::Curve_problem_2 problem{CGAL::Bbox_2(-1, 0, 1, R), VM::End_condition::fixed(R), VM::End_condition::fixed(R)};
  VM::Random_lines_options options;
  options.pencil_points = {VM::Point_2(-1, R), VM::Point_2(1, R)}; // 10% of the lines through the end points
  const auto lines = VM::random_lines_2(problem.box, n, /*seed*/ 1, options);

  const VM::Line_arrangement_2 arrangement = VM::build_curve_arrangement_2(problem, lines);
  const std::vector<double> weights = VM::curve_edge_weights_2(arrangement, VM::Surface_of_rotation_functional());
  const VM::Minimal_curve_2 curve = VM::minimize_curve_functional_2(arrangement, weights, problem);
  if(!curve.is_feasible) {
    std::cerr << "no discrete function meets the end conditions on this grid\n";
    return 1;
  }

  const VM::Surface_of_rotation_minimum exact = VM::global_minimum_surface_of_rotation(R);
  const bool catenoid = exact.branch == VM::Surface_of_rotation_minimum::Branch::Catenoid;
  double lowest = R;
  for(const auto& p : curve.polyline) lowest = std::min(lowest, p.y());
  std::cout.precision(8);
  std::cout << "arrangement: " << arrangement.number_of_vertices() << " vertices, " << arrangement.number_of_faces() << " cells\n"
            << "discrete global minimum: " << curve.energy << " (" << curve.polyline.size() << " vertices, lowest value "
            << lowest << ")\n"
            << "exact global minimum:    " << exact.energy << " (" << (catenoid ? "catenoid" : "Goldschmidt discs") << ")\n"
            << "relative error:          " << (curve.energy - exact.energy) / exact.energy << "\n";
  return 0;
}
