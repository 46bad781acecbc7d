// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// minimum_weight_triangulation_2(): the one-shot entry point.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_MINIMUM_WEIGHT_TRIANGULATION_2_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_MINIMUM_WEIGHT_TRIANGULATION_2_H

#include <CGAL/Minimum_weight_triangulation_2/Minimum_weight_triangulation_lp_2.h>
#include <CGAL/Kernel_traits.h>
#if defined(MDCS_HAS_CLP)
#include <CGAL/Minimum_weight_triangulation_2/CLP_linear_program_solver.h>
#endif
#if defined(MDCS_HAS_GLPK)
#include <CGAL/Minimum_weight_triangulation_2/GLPK_linear_program_solver.h>
#endif

#include <iterator>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {

/// Whether a built-in solver model was compiled in (MDCS_HAS_CLP / MDCS_HAS_GLPK).
inline bool has_lp_solver(Lp_solver_choice c)
{
  switch(c) {
#if defined(MDCS_HAS_CLP)
    case Lp_solver_choice::clp: return true;
#endif
#if defined(MDCS_HAS_GLPK)
    case Lp_solver_choice::glpk: return true;
    case Lp_solver_choice::exact: return true;
#endif
    case Lp_solver_choice::automatic:
#if defined(MDCS_HAS_CLP) || defined(MDCS_HAS_GLPK)
      return true;
#else
      return false;
#endif
    default: return false;
  }
}

/*!
  \brief Minimum weight triangulation of a point set by the triangle-based LP with a user LP solver.

  \tparam PointRange a range of `Point_2` of a CGAL kernel.
  \tparam LpSolver a model of `LinearProgramSolver`.
  `binary_solver` (may be empty) solves the 0/1 version of an LP; it resolves fractional LP optima.
  \throws std::invalid_argument on bad input (fewer than 3 points, duplicates, non-finite, all collinear).
*/
template <class PointRange, class LpSolver>
Mwt_result minimum_weight_triangulation_2(const PointRange& points, const Mwt_options& options, const LpSolver& solver,
    std::function<Linear_program_solution(const Sparse_linear_program&)> binary_solver)
{
  typedef typename std::iterator_traits<decltype(std::begin(points))>::value_type Point_2;
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel Kernel;
  std::vector<Point_2> p(std::begin(points), std::end(points));
  Minimum_weight_triangulation_lp_2<Kernel> mwt(p, options);
  mwt.compute_candidate_edges();
  mwt.compute_empty_triangles();
  mwt.build_linear_program();
  return mwt.solve(solver, binary_solver);
}

/*!
  \brief Minimum weight triangulation of a point set, with the built-in solver chosen by `options.solver`
  (automatic: CLP's dual simplex when available, else GLPK). Fractional LP optima are resolved by GLPK's
  branch and cut when `options.resolve_fractional` and GLPK is available.

  \returns a `Mwt_result`: the triangles (index triples, counter-clockwise), the weight, the status and a
  rigorous lower bound.
  \throws std::invalid_argument on bad input, std::runtime_error when the requested solver is not built in.
*/
template <class PointRange>
Mwt_result minimum_weight_triangulation_2(const PointRange& points, const Mwt_options& options = Mwt_options())
{
  std::function<Linear_program_solution(const Sparse_linear_program&)> bb;
#if defined(MDCS_HAS_GLPK)
  const double limit = options.branch_and_bound_time_limit;
  bb = [limit](const Sparse_linear_program& lp) { return GLPK_linear_program_solver().solve_binary(lp, limit); };
#endif
  Lp_solver_choice c = options.solver;
  if(c == Lp_solver_choice::automatic) {
#if defined(MDCS_HAS_CLP)
    c = Lp_solver_choice::clp;
#else
    c = Lp_solver_choice::glpk;
#endif
  }
  switch(c) {
#if defined(MDCS_HAS_CLP)
    case Lp_solver_choice::clp: return minimum_weight_triangulation_2(points, options, CLP_linear_program_solver(), bb);
#endif
#if defined(MDCS_HAS_GLPK)
    case Lp_solver_choice::glpk: return minimum_weight_triangulation_2(points, options, GLPK_linear_program_solver(), bb);
    case Lp_solver_choice::exact: return minimum_weight_triangulation_2(points, options, GLPK_linear_program_solver(true), bb);
#endif
    default: break;
  }
  (void)bb;
  throw std::runtime_error("minimum_weight_triangulation_2: the requested LP solver was not built in (needs CLP or GLPK)");
}

} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_MINIMUM_WEIGHT_TRIANGULATION_2_H
