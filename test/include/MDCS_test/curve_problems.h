// Shared fixtures for the univariate tests, examples and benchmarks: standard problems and a checked solve
// that runs both the min-cut and the shortest-path oracle.
#ifndef MDCS_TEST_CURVE_PROBLEMS_H
#define MDCS_TEST_CURVE_PROBLEMS_H

#include <MDCS_test/test_numbers.h> // relative_difference

#include <CGAL/Min_cut.h>
#include <CGAL/Variational_minimization.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace MDCS_test {

namespace VM = CGAL::Variational_minimization;

// Surface of rotation between rings of radius R at x = -1 and x = 1; the floor f = 0 is the bottom wall, so
// the Goldschmidt solution (two discs) is reachable; the box top is R, where both ends sit.
inline VM::Curve_problem_2 catenoid_problem(double R)
{
  return VM::Curve_problem_2{CGAL::Bbox_2(-1, 0, 1, R), VM::End_condition::fixed(R), VM::End_condition::fixed(R)};
}

// Random lines with a fraction through each fixed end point (relaxed ends get no pencil).
inline std::vector<VM::Arrangement_line_2> lines_for(const VM::Curve_problem_2& problem, std::size_t n,
                                                     std::uint64_t seed, double pencil_fraction = 0.1)
{
  VM::Random_lines_options options;
  options.pencil_fraction = pencil_fraction;
  if(problem.left.is_fixed()) options.pencil_points.push_back(VM::Point_2(problem.box.xmin(), problem.left.low));
  if(problem.right.is_fixed()) options.pencil_points.push_back(VM::Point_2(problem.box.xmax(), problem.right.low));
  if(options.pencil_points.empty()) options.pencil_fraction = 0;
  return VM::random_lines_2(problem.box, n, seed, options);
}

struct Checked_solve
{
  VM::Minimal_curve_2 cut;          // default engine (planar: shortest path in the dual of the network)
  VM::Minimal_curve_2 cut_pf;       // pseudoflow
  VM::Minimal_curve_2 cut_pr;       // Boost push-relabel
  VM::Minimal_curve_2 cut_bk;       // Boost Boykov-Kolmogorov
  VM::Minimal_curve_2 path;         // directed shortest path (oracle)
};

inline Checked_solve solve_both_ways(const VM::Curve_problem_2& problem, const VM::Line_arrangement_2& arrangement,
                                     const std::vector<double>& weights)
{
  Checked_solve s;
  s.cut = VM::minimize_curve_functional_2(arrangement, weights, problem);
  s.cut_pf = VM::minimize_curve_functional_2(arrangement, weights, problem, CGAL::Min_cut::Pseudoflow_max_flow());
  s.cut_pr = VM::minimize_curve_functional_2(arrangement, weights, problem, CGAL::Min_cut::Push_relabel_max_flow());
  s.cut_bk = VM::minimize_curve_functional_2(arrangement, weights, problem, CGAL::Min_cut::Boykov_kolmogorov_max_flow());
  s.path = VM::directed_shortest_path_2(arrangement, weights, problem);
  return s;
}

inline double min_value(const VM::Minimal_curve_2& c)
{
  double m = std::numeric_limits<double>::infinity();
  for(const auto& p : c.polyline) m = std::min(m, p.y());
  return m;
}

} // namespace MDCS_test

#endif // MDCS_TEST_CURVE_PROBLEMS_H
