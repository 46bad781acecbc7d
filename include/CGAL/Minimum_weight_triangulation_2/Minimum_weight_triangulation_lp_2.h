// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The triangle-based LP for the minimum weight triangulation, stage by stage: candidate edges (diamond test),
// empty triangles, LP, solve, certificate, branch and bound. The weights with rigorous bounds and the certificates
// of an LP optimum are in internal/Lp_certificate_2.h.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_MINIMUM_WEIGHT_TRIANGULATION_LP_2_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_MINIMUM_WEIGHT_TRIANGULATION_LP_2_H

#include <CGAL/Minimum_weight_triangulation_2/Linear_program.h>
#include <CGAL/Minimum_weight_triangulation_2/Mwt_result.h>
#include <CGAL/Minimum_weight_triangulation_2/convex_polygon_mwt_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Candidate_edges_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Coordinate_range_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Empty_triangles_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Face_dp_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Lmt_skeleton_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Lp_certificate_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Parallel_stage_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Validation_2.h>
#include <CGAL/MDCS/concurrency.h>
#include <CGAL/MDCS/progress.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <ctime>
#include <cmath>
#include <functional>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {

/*!
  \brief Stage control for the triangle-based LP of the minimum weight triangulation.

  \tparam Kernel a CGAL kernel; with `Exact_predicates_inexact_constructions_kernel` every combinatorial
  decision (collinearity, emptiness, side of an edge, validation) is exact.
  \tparam ConcurrencyTag `CGAL::Sequential_tag` (default), `CGAL::Parallel_tag` or
  `CGAL::Parallel_if_available_tag`: with a parallel tag and TBB, the candidate edges, the empty triangles, the
  LMT-skeleton, the face programs and the validation run on `Mwt_options::threads` threads (0: all), over
  blocks fixed by the input, so that every result is the same for every thread count. The LP and branch and
  bound stay sequential.

  Usage: construct (checks the input, computes the hull), then `compute_candidate_edges()`,
  `compute_empty_triangles()`, `build_linear_program()`, `solve(solver)`; `minimum_weight_triangulation_2()`
  runs all of them. Every stage can be inspected (`candidate_edges()`, `linear_program()`, ...).
*/
template <class Kernel, class ConcurrencyTag = CGAL::Sequential_tag>
class Minimum_weight_triangulation_lp_2
{
public:
  typedef typename Kernel::Point_2 Point_2;
  typedef std::pair<int, int> Edge;

  /// \pre at least 3 distinct points with finite coordinates, not all collinear, within `Mwt_coordinate_range`
  /// (else std::invalid_argument).
  Minimum_weight_triangulation_lp_2(const std::vector<Point_2>& points, const Mwt_options& options = Mwt_options())
    : input_(points), pts_(input_), options_(options)
  {
    initialize();
  }

  /// As above, taking the points over (no copy).
  Minimum_weight_triangulation_lp_2(std::vector<Point_2>&& points, const Mwt_options& options = Mwt_options())
    : input_(std::move(points)), pts_(input_), options_(options)
  {
    initialize();
  }

  Minimum_weight_triangulation_lp_2(const Minimum_weight_triangulation_lp_2&) = delete;
  Minimum_weight_triangulation_lp_2& operator=(const Minimum_weight_triangulation_lp_2&) = delete;

private:
  void initialize()
  {
    const auto t0 = Stage_clock::now();
    if(!options_.progress) options_.progress = [](const char*, double) { return true; };
    par_ = internal::Parallel_stage(CGAL::MDCS::effective_threads<ConcurrencyTag>(options_.threads));
    stats_.threads = par_.threads();
    hull_ = internal::checked_hull_boundary(pts_, par_.timed(&stats_.time_parallel_setup));
    internal::check_coordinate_range(pts_);
    grid_.reset(new internal::Point_grid_2(pts_, 2.0));
    double xmin = HUGE_VAL, xmax = -HUGE_VAL, ymin = HUGE_VAL, ymax = -HUGE_VAL;
    for(std::size_t i = 0; i < pts_.size(); ++i) {
      xmin = std::min(xmin, pts_.x(int(i))); xmax = std::max(xmax, pts_.x(int(i)));
      ymin = std::min(ymin, pts_.y(int(i))); ymax = std::max(ymax, pts_.y(int(i)));
    }
    scale_ = std::hypot(xmax - xmin, ymax - ymin);
    if(!(scale_ > 0) || !std::isfinite(scale_))
      throw std::invalid_argument("minimum_weight_triangulation_2: the bounding box diagonal is not finite and positive");
    stats_.points = pts_.size();
    stats_.hull_points = hull_.size();
    stats_.time_setup = since(t0);
  }

public:
  const std::vector<int>& hull() const { return hull_; }
  const std::vector<Edge>& candidate_edges() const { return edges_; }
  const Sparse_linear_program& linear_program() const { return lp_; }
  /// Vertices (counter-clockwise) of the triangle of LP column `j`.
  std::array<int, 3> column_triangle(std::size_t j) const { return triangles_[j].v; }
  const Mwt_statistics& statistics() const { return stats_; }
  /// LP costs are the weights divided by this: the bounding box diagonal for the metrics, the largest triangle
  /// weight for a user weight (after build_linear_program(); LP costs then lie in (0, 1] whatever the weights' scale).
  double scale() const { return scale_; }

  /// Whether every point is a corner of the convex hull (strictly convex position: no three hull points collinear).
  bool in_strictly_convex_position() const
  {
    const std::size_t h = hull_.size();
    if(h != pts_.size()) return false;
    for(std::size_t i = 0; i < h; ++i)
      if(pts_.orientation(hull_[i], hull_[(i + 1) % h], hull_[(i + 2) % h]) <= 0) return false;
    return true;
  }

  /*!
    Points in strictly convex position (`in_strictly_convex_position()`): the MWT by the exact dynamic program of
    convex polygons (`convex_polygon_mwt_2()`) on the hull, without candidate edges, triangles or LP; validated
    exactly, status `certified_optimal` (every decision of the program is exact for the double coordinates).
    Metrics only (no user triangle weight). Progress stage "convex dynamic program".
    \throws std::invalid_argument when the points are not in strictly convex position, with a user triangle weight,
    or with more than `convex_polygon_mwt_max_vertices()` points.
  */
  Mwt_result solve_in_convex_position()
  {
    if(options_.triangle_weight)
      throw std::invalid_argument("minimum_weight_triangulation_2: the convex-position program sums edge lengths (no user triangle weight)");
    if(!in_strictly_convex_position())
      throw std::invalid_argument("minimum_weight_triangulation_2: the points are not in strictly convex position");
    const auto t0 = Stage_clock::now();
    std::vector<Point_2> polygon;
    polygon.reserve(hull_.size());
    for(int v : hull_) polygon.push_back(pts_.point(v));
    std::vector<std::array<int, 3>> tri;
    tri.reserve(hull_.size());
    std::size_t exact = 0;
    convex_polygon_mwt_2(polygon, std::back_inserter(tri), options_.metric, &exact, options_.progress);
    for(auto& t : tri)
      for(int& v : t) v = hull_[std::size_t(v)];
    Mwt_result r;
    r.solver = "convex dynamic program";
    stats_.dp_triangles = tri.size();
    stats_.dp_exact_decisions = exact;
    stats_.dp_exact_faces = exact > 0 ? 1 : 0;
    stats_.time_face_dp = since(t0);
    const auto t1 = Stage_clock::now();
    const std::string err = options_.validate ? internal::validate_triangulation(pts_, *grid_, hull_, tri) : std::string();
    if(!err.empty()) {
      r.status = Mwt_status::solver_failed;
      r.message = "the convex program's triangles are not a triangulation (internal error): " + err;
      return finish(r);
    }
    r.triangles = std::move(tri);
    r.weight = checked_weight(weight_of(r.triangles, &upper_weight_));
    r.lower_bound = weights().weight_lower_bound(r.triangles);
    r.lp_objective = r.weight;
    r.lp_integral = true;
    r.status = Mwt_status::certified_optimal;
    r.message = "strictly convex position: solved by the exact dynamic program of convex polygons (no LP needed)";
    stats_.time_certificate = since(t1);
    return finish(r);
  }

  bool uses_diamond_test() const
  {
    return options_.pruning == Pruning::diamond ||
           (options_.pruning == Pruning::automatic && options_.metric == Edge_metric::L2 && !options_.triangle_weight);
  }

  void compute_candidate_edges()
  {
    const auto t0 = Stage_clock::now();
    if(options_.pruning == Pruning::diamond && (options_.metric != Edge_metric::L2 || options_.triangle_weight))
      throw std::invalid_argument("minimum_weight_triangulation_2: the diamond test is valid for the Euclidean metric only");
    const internal::Parallel_stage par = par_.timed(&stats_.time_parallel_candidates);
    edges_ = uses_diamond_test() ? internal::diamond_candidate_edges(pts_, *grid_, options_.progress, par)
                                 : internal::all_valid_edges(pts_, *grid_, options_.progress, par);
    // hull edges are always candidates (one side is empty); make sure of it
    index_.reset();
    index_.reset(new internal::Edge_index(edges_, pts_.size(), par));
    const std::size_t found = edges_.size();
    for(std::size_t i = 0; i < hull_.size(); ++i) {
      const int a = hull_[i], b = hull_[(i + 1) % hull_.size()];
      if(index_->find(a, b) < 0) edges_.emplace_back(std::min(a, b), std::max(a, b));
    }
    if(edges_.size() != found) {
      index_.reset();
      index_.reset(new internal::Edge_index(edges_, pts_.size(), par));
    }
    is_hull_.assign(edges_.size(), 0);
    for(std::size_t i = 0; i < hull_.size(); ++i) is_hull_[index_->find(hull_[i], hull_[(i + 1) % hull_.size()])] = 1;
    stats_.candidate_edges = edges_.size();
    stats_.time_candidates = since(t0);
  }

  void compute_empty_triangles()
  {
    if(!index_) compute_candidate_edges();
    const auto t0 = Stage_clock::now();
    internal::Triangle_set all = [&] {
      // a finer grid for the emptiness tests of small triangles (fewer points in a triangle's box), freed after
      internal::Point_grid_2 fine(pts_, 0.5);
      return internal::empty_triangles(pts_, fine, *index_, edges_, options_.progress,
                                       par_.timed(&stats_.time_parallel_triangles));
    }();
    stats_.empty_triangles = all.size();
    stats_.time_triangles = since(t0);
    row_one_ = is_hull_;
    fixed_edge_.assign(edges_.size(), 0);
    fixed_.clear();
    if(options_.use_lmt_skeleton) triangles_ = internal::remove_unusable_triangles(lmt_and_face_dp(all), row_one_);
    else {
      std::vector<internal::Lp_triangle> v;
      v.reserve(all.size());
      for(std::size_t t = 0; t < all.size(); ++t) v.push_back(all.triangle(int(t)));
      all = internal::Triangle_set(edges_);
      triangles_ = internal::remove_unusable_triangles(v, row_one_);
    }
    triangles_done_ = true;
  }

  /// After compute_empty_triangles() with `use_lmt_skeleton`: the state of every candidate edge
  /// (0 impossible, 1 possible, 2 certain, see internal::Lmt_edge_state); empty otherwise.
  const std::vector<char>& lmt_edge_states() const { return lmt_state_; }

  /// Variables: the usable empty triangles; rows: hull edges (= 1) and interior edges (left - right = 0).
  void build_linear_program()
  {
    if(!triangles_done_) compute_empty_triangles();
    const auto t0 = Stage_clock::now();
    lp_ = Sparse_linear_program();
    row_of_edge_.resize(edges_.size());
    par_.for_blocks(edges_.size(), 1 << 16, [&](std::size_t e0, std::size_t e1, std::size_t) {
      std::fill(row_of_edge_.begin() + std::ptrdiff_t(e0), row_of_edge_.begin() + std::ptrdiff_t(e1), -1);
    });
    row_is_hull_.clear();
    for(const auto& t : triangles_)
      for(int i = 0; i < 3; ++i) {
        const int e = t.edge[i];
        if(row_of_edge_[e] < 0) {
          row_of_edge_[e] = row_one_[e] ? lp_.add_row(1, 1) : lp_.add_row(0, 0);
          row_is_hull_.push_back(row_one_[e]);
        }
      }
    for(std::size_t i = 0; i < hull_.size(); ++i)
      if(row_of_edge_[index_->find(hull_[i], hull_[(i + 1) % hull_.size()])] < 0 &&
         !fixed_edge_[index_->find(hull_[i], hull_[(i + 1) % hull_.size()])])
        throw std::runtime_error("minimum_weight_triangulation_2: a hull edge has no empty triangle (internal error)");
    if(options_.triangle_weight) {
      // user weights of any magnitude: the LP sees them divided by the largest (CLP aborts on costs of 1e25)
      double largest = 0;
      for(const auto& t : triangles_) largest = (std::max)(largest, triangle_cost(t));
      if(largest > 0) scale_ = largest;
    }
    for(const auto& t : triangles_) {
      int rows[3];
      double val[3];
      for(int i = 0; i < 3; ++i) {
        rows[i] = row_of_edge_[t.edge[i]];
        val[i] = row_one_[t.edge[i]] ? 1.0 : double(t.side(i));
      }
      lp_.add_column(triangle_cost(t) / scale_, 0, Sparse_linear_program::infinity(), rows, val, 3);
    }
    stats_.lp_columns = lp_.number_of_columns();
    stats_.lp_rows = lp_.number_of_rows;
    stats_.lp_nonzeros = lp_.number_of_nonzeros();
    stats_.time_lp_build = since(t0);
    lp_done_ = true;
  }

  /*!
    Solves the LP with `solver` (a model of `LinearProgramSolver`), checks integrality, validates and
    certifies. A fractional optimum is resolved with `binary_solver(lp)` when `options.resolve_fractional`
    and a binary solver is given (a callable returning a `Linear_program_solution` of the 0/1 program). A
    binary solver stopped by the progress callback returns a message starting with "cancelled"; `solve`
    then throws `CGAL::MDCS::Operation_cancelled`.
  */
  template <class LpSolver>
  Mwt_result solve(const LpSolver& solver,
                   std::function<Linear_program_solution(const Sparse_linear_program&)> binary_solver = nullptr)
  {
    if(!lp_done_) build_linear_program();
    Mwt_result r;
    r.solver = solver.name();
    if(lp_.number_of_columns() == 0 && !fixed_.empty()) return solved_by_dynamic_program(r);
    if(!options_.progress("LP solve", 0)) throw CGAL::MDCS::Operation_cancelled("LP solve");
    auto t0 = Stage_clock::now();
    const Linear_program_solution sol = solver.solve(lp_);
    stats_.time_lp_solve = since(t0);
    stats_.lp_iterations = sol.iterations;
    if(sol.status == Lp_status::cancelled || sol.message.compare(0, 9, "cancelled") == 0)
      throw CGAL::MDCS::Operation_cancelled("LP solve");
    if(!options_.progress("LP solve", 1)) throw CGAL::MDCS::Operation_cancelled("LP solve");
    if(sol.status == Lp_status::time_limit) {
      r.status = Mwt_status::time_limit_reached;
      r.message = "the LP solver stopped at the time limit after " + seconds(stats_.time_lp_solve) + " (" + sol.message + ")";
      return finish(r);
    }
    // Nothing of the solver's answer is used before it is checked: NaN or infinite objective and values included.
    std::string unusable;
    if(!is_usable_optimum(lp_, sol, &unusable)) {
      r.status = Mwt_status::solver_failed;
      r.message = std::string("LP solver: ") + unusable + " (" + sol.message + ")";
      return finish(r);
    }
    start_certificate_stage();
    t0 = Stage_clock::now();
    const double fixed_part = fixed_weight_lower_bound();   // faces solved by the dynamic program
    r.lp_objective = checked_weight(sol.objective * scale_ + fixed_part);   // finite objective, overflow by the scale
    r.lp_exact = sol.exact;
    r.lower_bound = certificate().dual_lower_bound(sol.dual) + fixed_part;
    std::size_t fractional = 0;
    std::vector<std::array<int, 3>> chosen(fixed_);
    for(std::size_t j = 0; j < sol.primal.size(); ++j) {
      const double x = sol.primal[j];
      if(std::abs(x - 1) <= options_.integrality_tolerance) chosen.push_back(triangles_[j].v);
      else if(std::abs(x) > options_.integrality_tolerance) ++fractional;
    }
    stats_.fractional_variables = fractional;
    r.lp_integral = fractional == 0;
    if(r.lp_integral) {
      const std::string err = validated(chosen);
      if(!err.empty()) {
        r.status = Mwt_status::solver_failed;
        r.message = "the integral LP solution is not a triangulation: " + err;
      } else {
        r.triangles = chosen;
        r.weight = checked_weight(weight_of(chosen, &upper_weight_));
        const bool ok = r.lower_bound >= upper_weight_ - options_.certificate_tolerance * std::abs(upper_weight_);
        r.certificate_exact = fixed_.empty() && certificate().reduced_costs_separate(sol.dual, sol.primal);
        if(!r.certificate_exact && fixed_.empty() && options_.exact_support_certificate) {
          r.certificate_support = certificate().support_certificate(sol.dual, sol.primal, chosen, *index_,
                                                                    par_.timed(&weight_loop_time_));
          r.certificate_exact = r.certificate_support > 0;
        }
        r.status = (ok || r.certificate_exact) ? Mwt_status::certified_optimal : Mwt_status::optimal_uncertified;
        r.message = r.certificate_support > 0 ? "integral LP optimum, proven a minimum without tolerance (exact certificate "
                                                "on the zero-reduced-cost support)"
                    : r.certificate_exact ? "integral LP optimum, proven the unique minimum (exact certificate)"
                    : ok                  ? "integral LP optimum, dual bound certified"
                                          : "integral LP optimum, dual bound not certified";
      }
      stats_.time_certificate = since(t0);
      return finish(r);
    }
    stats_.time_certificate = since(t0);
    r.message = "fractional LP optimum (" + std::to_string(fractional) + " fractional variables)";
    if(!options_.resolve_fractional || !binary_solver) {
      r.status = Mwt_status::fractional_bound_only;
      return finish(r);
    }
    if(!options_.progress("branch and bound", 0)) throw CGAL::MDCS::Operation_cancelled("branch and bound");
    t0 = Stage_clock::now();
    const Linear_program_solution mip = binary_solver(lp_);
    stats_.time_branch_and_bound = since(t0);
    // a binary solver stopped by the progress callback says so in its status or at the start of its message
    if(mip.status == Lp_status::cancelled || mip.message.compare(0, 9, "cancelled") == 0)
      throw CGAL::MDCS::Operation_cancelled("branch and bound");
    if(!options_.progress("branch and bound", 1)) throw CGAL::MDCS::Operation_cancelled("branch and bound");
    if(mip.status == Lp_status::time_limit) {
      r.status = Mwt_status::fractional_bound_only;
      r.message += "; branch and bound stopped at its time limit after " + seconds(stats_.time_branch_and_bound) +
                   " (" + mip.message + ")";
      return finish(r);
    }
    if(!is_usable_optimum(lp_, mip, &unusable)) {
      r.status = Mwt_status::fractional_bound_only;
      r.message += "; branch and bound did not finish: " + unusable + " (" + mip.message + ")";
      return finish(r);
    }
    chosen = fixed_;
    for(std::size_t j = 0; j < mip.primal.size(); ++j)
      if(mip.primal[j] > 0.5) chosen.push_back(triangles_[j].v);
    const std::string err = validated(chosen);
    if(!err.empty()) {
      r.status = Mwt_status::solver_failed;
      r.message += "; the branch-and-bound solution is not a triangulation: " + err;
      return finish(r);
    }
    r.triangles = chosen;
    r.weight = checked_weight(weight_of(chosen, &upper_weight_));
    r.status = Mwt_status::optimal_after_branch_and_bound;
    r.message += "; resolved by branch and bound";
    return finish(r);
  }

  /// Weight (sum of edge lengths) of a triangulation given by triangles; `upper` receives a rigorous upper bound.
  /// The edges are summed in increasing order (the same sum for every thread count).
  double weight_of(const std::vector<std::array<int, 3>>& tri, double* upper = nullptr) const
  {
    return weights().weight(tri, par_.timed(&weight_loop_time_), upper);
  }

private:
#if defined(MDCS_MWT_CPU_TIMERS)
  // stage times in processor time of the process (benchmarks on a shared machine)
  struct Stage_clock
  {
    static double now() { return double(std::clock()) / CLOCKS_PER_SEC; }
  };
  static double since(double t0) { return Stage_clock::now() - t0; }
#else
  typedef std::chrono::steady_clock Stage_clock;
  static double since(Stage_clock::time_point t0) { return std::chrono::duration<double>(Stage_clock::now() - t0).count(); }
#endif
  typedef internal::Triangulation_weights_2<internal::Indexed_points_2<Kernel>> Weights;

  // The lengths and weights of the metric over the points (internal/Lp_certificate_2.h).
  Weights weights() const { return Weights(pts_, options_); }

  // The certificates of an LP optimum, over the current stages (internal/Lp_certificate_2.h).
  internal::Lp_certificate_2<Kernel> certificate() const
  {
    return internal::Lp_certificate_2<Kernel>(pts_, options_, edges_, triangles_, lp_, row_one_, row_is_hull_, is_hull_,
                                              scale_);
  }

  static std::string seconds(double t)
  {
    std::ostringstream o;
    o.precision(3);
    o << t << " s";
    return o.str();
  }

  // A weight is only reported when finite: the coordinate range keeps the metrics' sums finite; user triangle
  // weights (each finite) may still add up to infinity.
  static double checked_weight(double w)
  {
    if(!std::isfinite(w))
      throw std::invalid_argument("minimum_weight_triangulation_2: the weight of the triangulation is not finite (the "
                                  "triangle weights add up beyond the double range); scale the weights down");
    return w;
  }

  // The stage "certificate" (validation, weights, bounds; 45 s at 10^7 points) for the progress callback.
  void start_certificate_stage()
  {
    if(!options_.progress("certificate", 0)) throw CGAL::MDCS::Operation_cancelled("certificate");
    certificate_reported_ = true;
  }

  Mwt_result finish(Mwt_result& r)
  {
    if(certificate_reported_) {
      options_.progress("certificate", 1);   // the work is done: a cancellation here changes nothing
      certificate_reported_ = false;
    }
    stats_.time_parallel_certificate += weight_loop_time_;
    weight_loop_time_ = 0;
    stats_.time_total = stats_.time_setup + stats_.time_candidates + stats_.time_triangles + stats_.time_lmt + stats_.time_face_dp + stats_.time_lp_build + stats_.time_lp_solve +
                        stats_.time_certificate + stats_.time_branch_and_bound;
    r.statistics = stats_;
    return r;
  }

  // LMT-skeleton, then the dynamic program on the simple faces of its certain edges; returns the triangles
  // left for the LP: those of the solved faces as chosen by the program, all possible ones elsewhere. `all`
  // (every empty triangle) is released. Memory: the edge index is not needed by the skeleton and is rebuilt
  // after it; the face programs see the live triangles only (no impossible edge), in the same order.
  std::vector<internal::Lp_triangle> lmt_and_face_dp(internal::Triangle_set& all)
  {
    if(options_.metric != Edge_metric::L2 || options_.triangle_weight)
      throw std::invalid_argument("minimum_weight_triangulation_2: the LMT-skeleton is implemented for the Euclidean metric only");
    auto t0 = Stage_clock::now();
    index_.reset();
    {
      const internal::Parallel_stage par = par_.timed(&stats_.time_parallel_lmt);
      const internal::Edge_triangles by_edge(all, edges_.size(), par);
      lmt_state_ = internal::lmt_skeleton(pts_, edges_, all, by_edge, is_hull_, options_.progress, par);
    }
    for(char c : lmt_state_) {
      if(c == internal::lmt_certain) ++stats_.lmt_certain_edges;
      if(c == internal::lmt_possible) ++stats_.lmt_possible_edges;
    }
    stats_.time_lmt = since(t0);
    if(!options_.progress("face dynamic program", 0)) throw CGAL::MDCS::Operation_cancelled("face dynamic program");
    t0 = Stage_clock::now();
    const internal::Parallel_stage par = par_.timed(&stats_.time_parallel_face_dp);
    all.compact([&](int t) {
      const auto& te = all.edges(t);
      return lmt_state_[te[0]] != internal::lmt_impossible && lmt_state_[te[1]] != internal::lmt_impossible &&
             lmt_state_[te[2]] != internal::lmt_impossible;
    }, par);
    // the index of the edges that are not impossible: all that the face programs and the LP rows look up
    index_.reset(new internal::Edge_index(edges_, pts_.size(),
                                          [&](std::size_t e) { return lmt_state_[e] != internal::lmt_impossible; }, par));
    const internal::Edge_triangles by_edge(all, edges_.size(), par);
    internal::Face_dp_2<internal::Indexed_points_2<Kernel>> dp(pts_, edges_, *index_, all, by_edge, lmt_state_, 400,
                                                               par, options_.progress);
    // the faces solved by the program leave the LP; their edges shared with other faces become rows "= 1";
    // the LP keeps the triangles without an impossible edge in the other faces
    std::vector<internal::Lp_triangle> out;
    fixed_.resize(dp.dp_triangles().size());
    par.for_blocks(fixed_.size(), 1 << 14, [&](std::size_t k0, std::size_t k1, std::size_t) {
      for(std::size_t k = k0; k < k1; ++k) fixed_[k] = all.vertices(dp.dp_triangles()[k]);
    });
    for(int t : dp.dp_triangles())
      for(int i = 0; i < 3; ++i) row_one_[all.edge(t, i)] = fixed_edge_[all.edge(t, i)] = 1;
    par.append_in_order(all.size(), 1 << 14, out,
                        [&](std::size_t t0, std::size_t t1, std::vector<internal::Lp_triangle>& o) {
                          for(std::size_t t = t0; t < t1; ++t)
                            if(dp.is_live(int(t)) && !dp.in_solved_face(int(t))) o.push_back(all.triangle(int(t)));
                        });
    stats_.lmt_faces = dp.number_of_faces();
    stats_.lmt_solved_faces = dp.number_of_solved_faces();
    stats_.dp_triangles = dp.dp_triangles().size();
    stats_.lmt_largest_face = dp.largest_face();
    stats_.dp_exact_faces = dp.number_of_exact_faces();
    stats_.dp_exact_decisions = dp.number_of_exact_decisions();
    stats_.dp_weakly_simple_faces = dp.number_of_weakly_simple_faces();
    all = internal::Triangle_set(edges_);
    stats_.time_face_dp = since(t0);
    return out;
  }

  // The exact validation (empty: valid, or not asked for), in parallel.
  std::string validated(const std::vector<std::array<int, 3>>& tri)
  {
    if(!options_.validate) return std::string();
    return internal::validate_triangulation(pts_, *grid_, hull_, tri, par_.timed(&stats_.time_parallel_certificate));
  }

  // Lower bound (input units) of the weight of the edges of the fixed triangles that are no LP row.
  double fixed_weight_lower_bound()
  {
    if(fixed_.empty()) return 0;
    const internal::Parallel_stage par = par_.timed(&stats_.time_parallel_certificate);
    std::vector<int> terms;   // the edges summed, in increasing order
    par.append_in_order(edges_.size(), 1 << 16, terms, [&](std::size_t e0, std::size_t e1, std::vector<int>& out) {
      for(std::size_t e = e0; e < e1; ++e)
        if(fixed_edge_[e] && (row_of_edge_.empty() || row_of_edge_[e] < 0)) out.push_back(int(e));
    });
    return internal::blocked_interval_sum(terms.size(), [&](std::size_t k) {
      return weights().interval_length(edges_[std::size_t(terms[k])].first, edges_[std::size_t(terms[k])].second);
    }, par).inf();
  }

  // Every face solved by the dynamic program: no LP; the triangulation is validated exactly.
  Mwt_result solved_by_dynamic_program(Mwt_result& r)
  {
    // the validation and the weights: a stage of its own for the progress callback (45 s at 10^7 points)
    start_certificate_stage();
    const auto t0 = Stage_clock::now();
    const std::string err = validated(fixed_);
    if(!err.empty()) {
      r.status = Mwt_status::solver_failed;
      r.message = "the dynamic program's triangles are not a triangulation (internal error): " + err;
      return finish(r);
    }
    r.triangles = fixed_;
    r.weight = checked_weight(weight_of(fixed_, &upper_weight_));
    r.lower_bound = fixed_weight_lower_bound();
    r.lp_objective = r.weight;
    r.lp_integral = true;
    r.status = Mwt_status::certified_optimal;
    r.message = "every face of the LMT-skeleton solved by the dynamic program (no LP needed)";
    stats_.time_certificate = since(t0);
    return finish(r);
  }

  double triangle_cost(const internal::Lp_triangle& t) const
  {
    if(options_.triangle_weight) return weights().user_weight(t.v[0], t.v[1], t.v[2]);
    double c = 0;
    for(int i = 0; i < 3; ++i)
      c += (row_one_[t.edge[i]] ? 1.0 : 0.5) * weights().length(edges_[t.edge[i]].first, edges_[t.edge[i]].second);
    return c;
  }

  std::vector<Point_2> input_;
  internal::Indexed_points_2<Kernel> pts_;
  Mwt_options options_;
  internal::Parallel_stage par_;   // the thread count (effective_threads of the tag and options_.threads)
  std::vector<int> hull_;
  std::unique_ptr<internal::Point_grid_2> grid_;
  double scale_ = 1, upper_weight_ = 0;
  // time in the parallel loops of the const member functions (weight_of, support_certificate), certificate stage
  mutable double weight_loop_time_ = 0;
  bool triangles_done_ = false, lp_done_ = false, certificate_reported_ = false;
  std::vector<Edge> edges_;
  std::unique_ptr<internal::Edge_index> index_;
  std::vector<char> is_hull_, row_is_hull_, lmt_state_;
  std::vector<char> row_one_;      // rows "sum = 1" (hull edges, edges of faces solved by the dynamic program)
  std::vector<char> fixed_edge_;   // edges of the triangles fixed by the dynamic program
  std::vector<std::array<int, 3>> fixed_;
  std::vector<internal::Lp_triangle> triangles_;
  internal::Uninit_vector<int> row_of_edge_;   // filled with -1 in parallel
  Sparse_linear_program lp_;
  Mwt_statistics stats_;
};

} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_MINIMUM_WEIGHT_TRIANGULATION_LP_2_H
