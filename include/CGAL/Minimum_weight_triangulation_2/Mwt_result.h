// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Options, status and result record of minimum_weight_triangulation_2().

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_MWT_RESULT_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_MWT_RESULT_H

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {

/// Length of an edge: Euclidean (default), Manhattan, or maximum norm.
enum class Edge_metric { L2, L1, Linf };

/// Which edges may carry triangles. `diamond` is valid for the Euclidean metric only.
enum class Pruning { automatic, none, diamond };

/// Built-in LP solver models: `clp` (COIN-OR CLP's dual simplex), `glpk`, `exact` (GLPK's simplex verified
/// in rational arithmetic), `qp_solver` (CGAL's exact `QP_solver`: `QP_solver_linear_program_solver`, small
/// programs only, see `Mwt_options::qp_max_columns`).
enum class Lp_solver_choice { automatic, clp, glpk, exact, qp_solver };

/*!
  \brief Outcome of a run.

  - `certified_optimal`: the LP optimum is integral, the triangulation passed the exact validation, and a
    dual bound computed in interval arithmetic (costs are sums of square roots) proves that no
    triangulation is lighter by more than `certificate_tolerance` (relative). Where the optimum is unique
    and the duals separate it, the certificate is exact instead (`Mwt_result::certificate_exact`): any
    triangulation T differs from the optimum T* in as many triangles as T* differs from T, and its weight
    exceeds that of T* by the sum of the reduced costs of T \ T* minus that of T* \ T, which is positive
    when the smallest reduced cost outside T* exceeds the largest inside it. When the LP is dual degenerate (random
    sets), the exact certificate can still hold on the triangles of (near) zero reduced cost
    (`Mwt_result::certificate_support`): T* is then proven a minimum without tolerance. With `use_lmt_skeleton`, the
    faces solved by the dynamic program are optimal by the exact LMT-skeleton and an exhaustive program whose
    every decision is exact for the double coordinates (double sums with a forward error bound, an exact
    comparison of sums of square roots where that bound does not decide; no LP there, and when every face is
    solved no LP is built at all).
  - `optimal_after_branch_and_bound`: the LP optimum was fractional; the binary program solved by GLPK's
    branch and cut (floating point, gap 0) gave this triangulation, validated exactly. `lower_bound` is the
    rigorous LP bound.
  - `optimal_uncertified`: an integral LP optimum and a valid triangulation whose dual bound could not be
    certified (solver duals too inaccurate).
  - `fractional_bound_only`: the LP optimum is fractional and was not resolved; no triangulation,
    `lower_bound` holds.
  - `solver_failed`: the LP/MIP solver failed, or returned something unusable (a non-finite objective or value, a
    point that is no triangulation); `message` says how. No triangulation.
  - `time_limit_reached`: the LP solver stopped at `Mwt_options::lp_time_limit`; no triangulation, no bound.
    (Branch and bound stopped by its own limit gives `fractional_bound_only`, which keeps the LP bound.)

  A result with a triangulation always has a finite weight and a finite LP objective.
*/
enum class Mwt_status { certified_optimal, optimal_after_branch_and_bound, optimal_uncertified, fractional_bound_only, solver_failed,
                        time_limit_reached };

inline const char* to_string(Mwt_status s)
{
  switch(s) {
    case Mwt_status::certified_optimal: return "certified_optimal";
    case Mwt_status::optimal_after_branch_and_bound: return "optimal_after_branch_and_bound";
    case Mwt_status::optimal_uncertified: return "optimal_uncertified";
    case Mwt_status::fractional_bound_only: return "fractional_bound_only";
    case Mwt_status::time_limit_reached: return "time_limit_reached";
    default: return "solver_failed";
  }
}

/*!
  \brief The valid coordinate range of `minimum_weight_triangulation_2()` (checked up front; `std::invalid_argument`
  otherwise): every coordinate within [-2^500, 2^500] (about 3.3e150), and a bounding box whose larger side is at
  least 2^-400 (about 3.9e-121).

  Why: edge lengths are computed as sqrt(dx^2 + dy^2) in double precision (the weights, the LP costs, the interval
  certificate, the error bounds of the dynamic programs). Above 2^500 a squared coordinate difference can overflow
  (1e300 gave an infinite weight, a NaN LP optimum in GLPK and assertion failures inside CLP and GLPK); below
  2^-400 the squares approach the subnormal range, where lengths lose their relative precision (1e-160 gave a
  heavier, uncertified triangulation and 1e-200 a weight of 0). Scaling the points by a power of two keeps every
  coordinate and every orientation exact and scales the weight by the same factor.
*/
struct Mwt_coordinate_range
{
  static double max_abs_coordinate() { return std::ldexp(1.0, 500); }
  static double min_extent() { return std::ldexp(1.0, -400); }
};

/// Parameters of minimum_weight_triangulation_2().
struct Mwt_options
{
  Edge_metric metric = Edge_metric::L2;
  /// If set, replaces the metric: weight of the triangle (a, b, c), given as coordinates, must be > 0.
  /// The certificate then uses floating-point arithmetic only.
  std::function<double(double, double, double, double, double, double)> triangle_weight;
  Pruning pruning = Pruning::automatic;             ///< automatic: diamond for L2, none otherwise
  Lp_solver_choice solver = Lp_solver_choice::automatic;   ///< automatic: CLP, else GLPK
  bool resolve_fractional = true;                  ///< run branch and bound (GLPK) on a fractional LP optimum
  /// Seconds for the branch and bound of a fractional LP optimum (0: none). When it runs out, the status is
  /// `fractional_bound_only` with the LP bound. The progress callback can also stop it (stage "branch and bound").
  double branch_and_bound_time_limit = 300;
  /// Seconds (wall clock) for the LP solve of the built-in solver models (0: none, the default: the LP of 10^4
  /// uniform points takes about half a minute in CLP). When it runs out, the status is `time_limit_reached`. The
  /// solver asks the progress callback about once a second (stage "LP solve", fraction = elapsed part of the
  /// limit, 0 without one); returning false stops it and the run throws `CGAL::MDCS::Operation_cancelled`.
  double lp_time_limit = 0;
  /// `Lp_solver_choice::qp_solver` only: the largest LP (number of columns, i.e. empty triangles left in the LP)
  /// handed to CGAL's `QP_solver`; a larger one is refused before the solve with
  /// `Linear_program_too_large` (a `std::length_error`). 0: no limit. CGAL's solver runs its whole simplex in one
  /// call without callback, so neither `lp_time_limit` nor the progress callback can stop it once started; its
  /// processor time grows about like the cube of the columns or faster (the default: about 45 s or less on the
  /// measured sets, extrapolated; see the manual).
  std::size_t qp_max_columns = 600;
  /// `minimum_weight_triangulation_2()`: points in strictly convex position (every point a corner of the convex
  /// hull) are triangulated by the exact dynamic program of convex polygons (`convex_polygon_mwt_2()`, O(n^3)
  /// time, 12 n^2 bytes), without candidate edges, triangles or LP (whose n^3 / 6 columns made 64 cocircular
  /// points take minutes in GLPK). Off: the LP path as for any other set (tests compare the two).
  bool convex_position_by_dynamic_program = true;
  double certificate_tolerance = 1e-9;             ///< relative gap accepted by the certificate
  double integrality_tolerance = 1e-6;
  bool validate = true;                            ///< exact validation of the output triangulation
  /// Euclidean metric only: LMT-skeleton on the candidate edges, the dynamic program on the simple faces its
  /// certain edges leave, the triangle LP on the rest (the impossible edges removed from it).
  bool use_lmt_skeleton = false;
  /// LP path, Euclidean metric: when the duals do not separate the optimum, try the exact certificate on the
  /// triangles of (near) zero reduced cost (`Mwt_result::certificate_support`).
  bool exact_support_certificate = true;
  /// Progress/cancel callback `bool(const char* stage, double fraction)`; see CGAL/MDCS/progress.h. With
  /// several threads it is still called from the calling thread only.
  std::function<bool(const char*, double)> progress;
  /// Threads of a run with `CGAL::Parallel_tag` / `CGAL::Parallel_if_available_tag` (0: every hardware thread;
  /// ignored with `CGAL::Sequential_tag` or without TBB). The result does not depend on it.
  std::size_t threads = 0;
};

/// Sizes and timings (seconds) of the stages of one run.
struct Mwt_statistics
{
  std::size_t points = 0, hull_points = 0, candidate_edges = 0, empty_triangles = 0, lp_columns = 0,
              lp_rows = 0, lp_nonzeros = 0, fractional_variables = 0;
  long lp_iterations = 0;
  /// LMT-skeleton (when `use_lmt_skeleton`): certain/possible edges, faces of the certain edges, those solved
  /// by the dynamic program, its triangles, the largest face (vertices on its boundary walk).
  std::size_t lmt_certain_edges = 0, lmt_possible_edges = 0, lmt_faces = 0, lmt_solved_faces = 0, dp_triangles = 0,
              lmt_largest_face = 0;
  /// Faces of the dynamic programs where a decision was ambiguous in double precision (the winner's error
  /// bound overlapped another candidate's) and was taken by the exact comparison of sums of square roots;
  /// the number of such decisions.
  std::size_t dp_exact_faces = 0, dp_exact_decisions = 0;
  /// Faces solved by the dynamic program whose boundary walk repeats a vertex (weakly simple: a dangling
  /// certain edge, or a pinch vertex where two loops of the boundary touch); counted in `lmt_solved_faces` too.
  std::size_t dp_weakly_simple_faces = 0;
  double time_lmt = 0, time_face_dp = 0;
  /// input checks, convex hull and grid (and, in minimum_weight_triangulation_2(), the Hilbert sort of the points)
  double time_setup = 0;
  double time_candidates = 0, time_triangles = 0, time_lp_build = 0, time_lp_solve = 0, time_certificate = 0,
         time_branch_and_bound = 0, time_total = 0;
  /// Threads the run used (1: sequential).
  std::size_t threads = 1;
  /// The part of each stage's time spent inside its parallel loops (same clock; the rest of the stage is serial).
  double time_parallel_setup = 0, time_parallel_candidates = 0, time_parallel_triangles = 0, time_parallel_lmt = 0,
         time_parallel_face_dp = 0, time_parallel_certificate = 0;
};

/// Result of minimum_weight_triangulation_2().
struct Mwt_result
{
  Mwt_status status = Mwt_status::solver_failed;
  std::vector<std::array<int, 3>> triangles;   ///< counter-clockwise index triples into the input
  double weight = std::numeric_limits<double>::quiet_NaN();        ///< sum of edge lengths
  double lower_bound = -std::numeric_limits<double>::infinity();   ///< rigorous lower bound of the MWT weight
  double lp_objective = std::numeric_limits<double>::quiet_NaN();  ///< LP optimum, in input units
  bool lp_integral = false;
  bool lp_exact = false;                         ///< the LP optimum was verified in rational arithmetic
  /// The certificate needs no tolerance: with the solver's duals, every triangle outside the triangulation
  /// has a reduced cost larger than that of any triangle in it, in interval arithmetic (costs are sums of
  /// square roots), which proves it the unique minimum (see `Mwt_status`). Only on the LP path without faces
  /// solved by the dynamic programs.
  bool certificate_exact = false;
  /// When the duals do not separate the optimum (dual degenerate LP, e.g. random point sets), the exact
  /// certificate can still hold on the zero-reduced-cost support (`Mwt_options::exact_support_certificate`):
  /// the number of triangles of that support (0: not used or not proven). The optimum is then proven a
  /// minimum without tolerance, not necessarily the unique one.
  std::size_t certificate_support = 0;
  std::string solver, message;
  Mwt_statistics statistics;

  bool has_triangulation() const { return !triangles.empty(); }
};

} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_MWT_RESULT_H
