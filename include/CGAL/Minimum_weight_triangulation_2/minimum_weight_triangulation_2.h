// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// minimum_weight_triangulation_2(): the one-shot entry point.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_MINIMUM_WEIGHT_TRIANGULATION_2_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_MINIMUM_WEIGHT_TRIANGULATION_2_H

#include <CGAL/Minimum_weight_triangulation_2/Minimum_weight_triangulation_lp_2.h>
#include <CGAL/Minimum_weight_triangulation_2/QP_solver_linear_program_solver.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Coordinate_range_2.h>
#include <CGAL/Kernel_traits.h>
#if defined(MDCS_HAS_CLP)
#include <CGAL/Minimum_weight_triangulation_2/CLP_linear_program_solver.h>
#endif
#if defined(MDCS_HAS_GLPK)
#include <CGAL/Minimum_weight_triangulation_2/GLPK_linear_program_solver.h>
#endif

#include <chrono>
#include <ctime>
#include <iterator>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {

namespace internal {

// The solver of `options.solver` with `automatic` resolved: CLP when built in, else GLPK.
inline Lp_solver_choice resolved_solver_choice(Lp_solver_choice c)
{
  if(c != Lp_solver_choice::automatic) return c;
#if defined(MDCS_HAS_CLP)
  return Lp_solver_choice::clp;
#else
  return Lp_solver_choice::glpk;
#endif
}

// The time limit and the progress callback (stage "LP solve") of the options, for a built-in solver model.
inline Lp_solve_control lp_solve_control(const Mwt_options& options)
{
  Lp_solve_control control;
  control.time_limit = options.lp_time_limit;
  if(options.progress) {
    const auto progress = options.progress;
    control.keep_going = [progress](double f) { return progress("LP solve", f); };
  }
  return control;
}

} // namespace internal

/// Whether a built-in solver model was compiled in (MDCS_HAS_CLP / MDCS_HAS_GLPK; `qp_solver`, CGAL's own
/// exact solver, always is).
inline bool has_lp_solver(Lp_solver_choice c)
{
  switch(c) {
    case Lp_solver_choice::qp_solver: return true;
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

  \tparam ConcurrencyTag `CGAL::Sequential_tag` (default), `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`:
  the candidate edges, empty triangles, LMT-skeleton, face programs and validation then run on
  `options.threads` threads (0: all hardware threads; sequential without TBB). The triangles, the weight, the
  bounds and the status are the same for every thread count.
  \tparam PointRange a range of `Point_2` of a CGAL kernel.
  \tparam LpSolver a model of `LinearProgramSolver`.
  `binary_solver` (may be empty) solves the 0/1 version of an LP; it resolves fractional LP optima.
  Points in strictly convex position are triangulated by the exact convex-polygon program instead
  (`Mwt_options::convex_position_by_dynamic_program`); neither solver is called then.
  \throws std::invalid_argument on bad input (fewer than 3 points, duplicates, non-finite, all collinear,
  coordinates outside `Mwt_coordinate_range`).
  \throws CGAL::MDCS::Operation_cancelled when the progress callback returns false.
*/
template <class ConcurrencyTag = CGAL::Sequential_tag, class PointRange, class LpSolver>
Mwt_result minimum_weight_triangulation_2(const PointRange& points, const Mwt_options& options, const LpSolver& solver,
    std::function<Linear_program_solution(const Sparse_linear_program&)> binary_solver)
{
  typedef typename std::iterator_traits<decltype(std::begin(points))>::value_type Point_2;
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel Kernel;
  // The stages run on the points in Hilbert order (locality of the grids and of every per-point array); the
  // triangles are mapped back to the input indices. Bad input is reported with the input indices.
  std::vector<int> order;
#if defined(MDCS_MWT_CPU_TIMERS)
  const double t0 = double(std::clock()) / CLOCKS_PER_SEC;
#else
  const auto t0 = std::chrono::steady_clock::now();
#endif
  std::vector<Point_2> p;
  double sort_parallel_time = 0;
  {
    const std::vector<Point_2> input(std::begin(points), std::end(points));
    try {
      const internal::Parallel_stage par(CGAL::MDCS::effective_threads<ConcurrencyTag>(options.threads), &sort_parallel_time);
      order = internal::hilbert_order(input, par);
    } catch(const std::invalid_argument&) {
      internal::Indexed_points_2<Kernel> ip(input);
      internal::checked_hull_boundary(ip);   // throws with the input indices
      throw;
    }
    // the coordinate range, reported with the input indices
    internal::check_coordinate_range(internal::Indexed_points_2<Kernel>(input));
    p.resize(input.size());
    for(std::size_t i = 0; i < order.size(); ++i) p[i] = input[std::size_t(order[i])];
  }   // the copy in input order is released: the stages hold the points once (moved below)
#if defined(MDCS_MWT_CPU_TIMERS)
  const double sort_time = double(std::clock()) / CLOCKS_PER_SEC - t0;
#else
  const double sort_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
#endif
  Mwt_result r;
  try {
    Minimum_weight_triangulation_lp_2<Kernel, ConcurrencyTag> mwt(std::move(p), options);   // no second copy of the points
    if(options.convex_position_by_dynamic_program && !options.triangle_weight && mwt.in_strictly_convex_position() &&
       mwt.hull().size() <= convex_polygon_mwt_max_vertices()) {
      r = mwt.solve_in_convex_position();
    } else {
      mwt.compute_candidate_edges();
      mwt.compute_empty_triangles();
      mwt.build_linear_program();
      r = mwt.solve(solver, binary_solver);
    }
  } catch(const std::invalid_argument&) {
    const std::vector<Point_2> input(std::begin(points), std::end(points));
    internal::Indexed_points_2<Kernel> ip(input);
    internal::checked_hull_boundary(ip);   // input errors again, with the input indices
    throw;
  }
  for(auto& t : r.triangles)
    for(int& v : t) v = order[std::size_t(v)];
  r.statistics.time_setup += sort_time;
  r.statistics.time_parallel_setup += sort_parallel_time;
  r.statistics.time_total += sort_time;
  return r;
}

/*!
  \brief Minimum weight triangulation of a point set, with the built-in solver chosen by `options.solver`
  (automatic: CLP's dual simplex when available, else GLPK; `qp_solver`: CGAL's exact `QP_solver`, never chosen
  automatically). Fractional LP optima are resolved by GLPK's branch and cut when `options.resolve_fractional`
  and GLPK is available, whichever solver found them.

  The LP solve is bounded by `options.lp_time_limit` (status `time_limit_reached`), branch and bound by
  `options.branch_and_bound_time_limit` (status `fractional_bound_only`); both ask `options.progress` about once
  a second (stages "LP solve" and "branch and bound"), which can cancel them. Except `qp_solver`: CGAL's
  `QP_solver` cannot be stopped once started (see `QP_solver_linear_program_solver`), so the progress callback is
  asked just before its solve and the time limit is not enforced in it; an LP with more than
  `options.qp_max_columns` columns is refused instead (`Linear_program_too_large`, after the candidate edges and
  the triangles were computed: the LP's size is known only then).

  `ConcurrencyTag` and `options.threads` as above, e.g.
  `minimum_weight_triangulation_2<CGAL::Parallel_if_available_tag>(points, options)`.

  \returns a `Mwt_result`: the triangles (index triples, counter-clockwise), the weight, the status and a
  rigorous lower bound.
  \throws std::invalid_argument on bad input, std::runtime_error when the requested solver is not built in,
  CGAL::MDCS::Operation_cancelled when the progress callback returns false, `Linear_program_too_large` (a
  `std::length_error`) when `qp_solver` is asked for an LP of more than `options.qp_max_columns` columns.
*/
template <class ConcurrencyTag = CGAL::Sequential_tag, class PointRange>
Mwt_result minimum_weight_triangulation_2(const PointRange& points, const Mwt_options& options = Mwt_options())
{
  if(!(options.lp_time_limit >= 0) || !(options.branch_and_bound_time_limit >= 0))
    throw std::invalid_argument("minimum_weight_triangulation_2: the time limits must be >= 0 seconds (0: none), not NaN");
  const Lp_solve_control control = internal::lp_solve_control(options);
  std::function<Linear_program_solution(const Sparse_linear_program&)> bb;
#if defined(MDCS_HAS_GLPK)
  const double limit = options.branch_and_bound_time_limit;
  const auto progress = options.progress;
  bb = [limit, progress](const Sparse_linear_program& lp) {
    std::function<bool(double)> keep_going;
    if(progress) keep_going = [progress](double f) { return progress("branch and bound", f); };
    return GLPK_linear_program_solver().solve_binary(lp, limit, keep_going);
  };
#endif
  const Lp_solver_choice c = internal::resolved_solver_choice(options.solver);
  switch(c) {
#if defined(MDCS_HAS_CLP)
    case Lp_solver_choice::clp: {
      CLP_linear_program_solver clp;
      clp.set_control(control);
      return minimum_weight_triangulation_2<ConcurrencyTag>(points, options, clp, bb);
    }
#endif
#if defined(MDCS_HAS_GLPK)
    case Lp_solver_choice::glpk:
    case Lp_solver_choice::exact: {
      GLPK_linear_program_solver glpk(c == Lp_solver_choice::exact);
      glpk.set_control(control);
      return minimum_weight_triangulation_2<ConcurrencyTag>(points, options, glpk, bb);
    }
#endif
    case Lp_solver_choice::qp_solver: {
      QP_solver_linear_program_solver<> qp;
      qp.set_control(control);   // keep_going asked once, before the solve
      qp.set_max_columns(options.qp_max_columns);
      return minimum_weight_triangulation_2<ConcurrencyTag>(points, options, qp, bb);
    }
    default: break;
  }
  (void)bb;
  (void)control;
  throw std::runtime_error("minimum_weight_triangulation_2: the requested LP solver was not built in (needs CLP or GLPK)");
}

} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_MINIMUM_WEIGHT_TRIANGULATION_2_H
