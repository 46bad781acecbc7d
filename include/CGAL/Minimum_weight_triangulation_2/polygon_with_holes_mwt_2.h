// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// polygon_with_holes_mwt_2(): the minimum weight triangulation of a polygonal domain with holes and isolated
// interior points (the general, NP-hard MWT problem once a hole or a point is inside): the triangle LP over the
// empty triangles of the domain (thesis ch. 3.2), certified by its dual bound when its optimum is integral,
// branch and bound (GLPK) when it is fractional. Without holes and points: simple_polygon_mwt_2() (the LP is
// integral there, Cor. 3.6.2, and the dynamic program polynomial).

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_POLYGON_WITH_HOLES_MWT_2_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_POLYGON_WITH_HOLES_MWT_2_H

#include <CGAL/Minimum_weight_triangulation_2/Mwt_result.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Polygonal_domain_2.h>
#include <CGAL/Minimum_weight_triangulation_2/minimum_weight_triangulation_2.h>
#include <CGAL/Minimum_weight_triangulation_2/simple_polygon_mwt_2.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <chrono>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {

/// The most vertices (outer ring, holes and interior points together) `polygon_with_holes_mwt_2()` accepts. The
/// worst case is a convex outer ring with one point inside: nearly every triple is an empty triangle, about
/// V^3 / 6 LP columns. At V = 200 (985,050 triangles) the enumeration took 0.15 s and the LP's construction
/// 0.11 s of processor time (peak 78 MB); 300 vertices took 0.57 + 0.37 s and 254 MB. The LP solve of such a case is
/// bounded by `Mwt_options::lp_time_limit` only; typical domains (points spread inside) have far fewer triangles.
inline std::size_t polygon_with_holes_mwt_max_vertices() { return 200; }

namespace internal {

// The LP and branch and bound of a checked domain with holes or interior points.
template <class K>
Mwt_result polygonal_domain_mwt(const Polygonal_domain_2<K>& d, const Mwt_options& options)
{
  typedef std::chrono::steady_clock Clock;
  auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  const auto start = Clock::now();
  Mwt_result r;
  r.statistics.points = d.size();
  r.statistics.hull_points = std::size_t(d.first_interior_point);
  auto t0 = Clock::now();
  const std::vector<std::array<int, 3>> triangles = d.empty_triangles(options.progress);
  r.statistics.empty_triangles = triangles.size();
  r.statistics.time_triangles = since(t0);
  t0 = Clock::now();
  const Domain_linear_program dlp(d, triangles, options.metric);
  r.statistics.lp_columns = dlp.lp.number_of_columns();
  r.statistics.lp_rows = dlp.lp.number_of_rows;
  r.statistics.lp_nonzeros = dlp.lp.number_of_nonzeros();
  r.statistics.time_lp_build = since(t0);
  auto finish = [&](Mwt_result& res) -> Mwt_result& {
    res.statistics.time_total = since(start);
    return res;
  };

  // the LP solver: options.solver as in minimum_weight_triangulation_2() (automatic: CLP, else GLPK)
  const Lp_solve_control control = internal::lp_solve_control(options);
  const Lp_solver_choice c = resolved_solver_choice(options.solver);
  if(options.progress && !options.progress("LP solve", 0)) throw CGAL::MDCS::Operation_cancelled("LP solve");
  t0 = Clock::now();
  Linear_program_solution sol;
  bool solved = false;
#if defined(MDCS_HAS_CLP)
  if(c == Lp_solver_choice::clp) {
    CLP_linear_program_solver clp;
    clp.set_control(control);
    sol = clp.solve(dlp.lp);
    r.solver = clp.name();
    solved = true;
  }
#endif
#if defined(MDCS_HAS_GLPK)
  if(c == Lp_solver_choice::glpk || c == Lp_solver_choice::exact) {
    GLPK_linear_program_solver glpk(c == Lp_solver_choice::exact);
    glpk.set_control(control);
    sol = glpk.solve(dlp.lp);
    r.solver = glpk.name();
    solved = true;
  }
#endif
  if(c == Lp_solver_choice::qp_solver) {   // CGAL's exact simplex: the size guard is checked before the solve
    QP_solver_linear_program_solver<> qp;
    qp.set_control(control);
    qp.set_max_columns(options.qp_max_columns);
    sol = qp.solve(dlp.lp);
    r.solver = qp.name();
    solved = true;
  }
  if(!solved)
    throw std::runtime_error("polygon_with_holes_mwt_2: the requested LP solver was not built in (a domain with holes "
                             "or interior points needs CLP or GLPK)");
  r.statistics.time_lp_solve = since(t0);
  r.statistics.lp_iterations = sol.iterations;
  if(sol.status == Lp_status::cancelled || sol.message.compare(0, 9, "cancelled") == 0)
    throw CGAL::MDCS::Operation_cancelled("LP solve");
  if(options.progress && !options.progress("LP solve", 1)) throw CGAL::MDCS::Operation_cancelled("LP solve");
  if(sol.status == Lp_status::time_limit) {
    r.status = Mwt_status::time_limit_reached;
    r.message = "the LP solver stopped at the time limit (" + sol.message + ")";
    return finish(r);
  }
  std::string unusable;
  if(!is_usable_optimum(dlp.lp, sol, &unusable)) {
    r.status = Mwt_status::solver_failed;
    r.message = "LP solver: " + unusable + " (" + sol.message + ")";
    return finish(r);
  }
  t0 = Clock::now();
  r.lp_objective = sol.objective;
  r.lp_exact = sol.exact;
  r.lower_bound = dlp.dual_lower_bound(d, triangles, sol.dual, options.metric);
  std::vector<std::size_t> chosen;
  std::size_t fractional = 0;
  for(std::size_t j = 0; j < sol.primal.size(); ++j) {
    const double x = sol.primal[j];
    if(std::abs(x - 1) <= options.integrality_tolerance) chosen.push_back(j);
    else if(std::abs(x) > options.integrality_tolerance) ++fractional;
  }
  r.statistics.fractional_variables = fractional;
  r.lp_integral = fractional == 0;

  // the weight of the chosen triangles: every distinct side once, in double and as a rigorous upper bound
  auto take = [&](const std::vector<std::size_t>& cols) {
    std::vector<std::pair<int, int>> edges;
    for(std::size_t j : cols) {
      const auto& t = triangles[j];
      r.triangles.push_back(t);
      for(int i = 0; i < 3; ++i)
        edges.emplace_back(std::min(t[i], t[(i + 1) % 3]), std::max(t[i], t[(i + 1) % 3]));
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    double w = 0;
    CGAL::Interval_nt<true> upper(0);
    for(const auto& e : edges) {
      w += d.length(e.first, e.second, options.metric);
      upper += d.interval_length(e.first, e.second, options.metric);
    }
    r.weight = w;
    return upper.sup();
  };

  if(r.lp_integral) {
    const std::string err = dlp.not_a_triangulation(d, triangles, chosen);
    if(!err.empty()) {
      r.status = Mwt_status::solver_failed;
      r.message = "the integral LP solution is not a triangulation: " + err;
    } else {
      const double upper = take(chosen);
      const bool ok = r.lower_bound >= upper - options.certificate_tolerance * std::abs(upper);
      r.status = ok ? Mwt_status::certified_optimal : Mwt_status::optimal_uncertified;
      r.message = ok ? "integral LP optimum, dual bound certified" : "integral LP optimum, dual bound not certified";
    }
    r.statistics.time_certificate = since(t0);
    return finish(r);
  }
  r.statistics.time_certificate = since(t0);
  r.message = "fractional LP optimum (" + std::to_string(fractional) + " fractional variables)";
  if(!options.resolve_fractional) {
    r.status = Mwt_status::fractional_bound_only;
    return finish(r);
  }
#if defined(MDCS_HAS_GLPK)
  if(options.progress && !options.progress("branch and bound", 0)) throw CGAL::MDCS::Operation_cancelled("branch and bound");
  t0 = Clock::now();
  std::function<bool(double)> keep_going;
  if(options.progress) {
    const auto progress = options.progress;
    keep_going = [progress](double f) { return progress("branch and bound", f); };
  }
  const Linear_program_solution mip =
    GLPK_linear_program_solver().solve_binary(dlp.lp, options.branch_and_bound_time_limit, keep_going);
  r.statistics.time_branch_and_bound = since(t0);
  if(GLPK_linear_program_solver::was_cancelled(mip)) throw CGAL::MDCS::Operation_cancelled("branch and bound");
  if(options.progress && !options.progress("branch and bound", 1)) throw CGAL::MDCS::Operation_cancelled("branch and bound");
  if(mip.status == Lp_status::time_limit) {
    r.status = Mwt_status::fractional_bound_only;
    r.message += "; branch and bound stopped at its time limit (" + mip.message + ")";
    return finish(r);
  }
  if(!is_usable_optimum(dlp.lp, mip, &unusable)) {
    r.status = Mwt_status::fractional_bound_only;
    r.message += "; branch and bound did not finish: " + unusable + " (" + mip.message + ")";
    return finish(r);
  }
  chosen.clear();
  for(std::size_t j = 0; j < mip.primal.size(); ++j)
    if(mip.primal[j] > 0.5) chosen.push_back(j);
  const std::string err = dlp.not_a_triangulation(d, triangles, chosen);
  if(!err.empty()) {
    r.status = Mwt_status::solver_failed;
    r.message += "; the branch-and-bound solution is not a triangulation: " + err;
    return finish(r);
  }
  take(chosen);
  r.status = Mwt_status::optimal_after_branch_and_bound;
  r.message += "; resolved by branch and bound";
#else
  r.status = Mwt_status::fractional_bound_only;
  r.message += "; not resolved: branch and bound needs GLPK (MDCS_HAS_GLPK)";
#endif
  return finish(r);
}

} // namespace internal

/*!
  \brief Minimum weight triangulation of a polygonal domain: the region inside the simple polygon `outer` and
  outside the simple polygons `holes`, with the `interior_points` as further vertices. The MWT of such a domain
  is NP-hard in general (a point set is the domain of its convex hull with the other points inside); the result
  is exact (up to `options.certificate_tolerance` where the status says so) or says why not.

  <b>Vertex numbering</b> of the output: the vertices of `outer` in their input order (0, 1, ...), then those of
  each hole in input order, hole after hole, then the interior points. Rings may be given in either orientation
  (each is used with the domain on its left); the triangles are counter-clockwise index triples. Consecutive
  collinear ring vertices are allowed (no triangle is flat).

  <b>Method.</b> Without holes and interior points: `simple_polygon_mwt_2()` (exact decisions, O(k^3)), status
  `certified_optimal`. Otherwise: every empty triangle of the domain (its sides run inside the domain, cross no
  boundary edge and contain no vertex but their ends; no vertex inside it; exact predicates) becomes a column of
  the triangle LP of the thesis (ch. 3.2): each boundary edge is covered exactly once from its inner side, each
  other edge has as many triangles on its left as on its right; the cost of a triangle is its boundary sides plus
  half its other sides, so the objective of a triangulation is its weight. The LP is solved by `options.solver`
  (automatic: CLP, else GLPK). An integral optimum is checked exactly to be a triangulation (Euler's count
  V + m + 2h - 2 of triangles for V vertices, m interior points and h holes; every row satisfied; areas summing to
  the domain's in rationals) and certified by the dual bound in interval arithmetic. A fractional optimum (possible
  now: the thesis's integrality holds for simple polygons only) is resolved by GLPK's branch and cut within
  `options.branch_and_bound_time_limit` seconds.

  <b>Status</b> (`Mwt_status`): `certified_optimal` (the dynamic program; or an integral LP optimum whose dual
  bound `lower_bound` is within `options.certificate_tolerance` of the weight), `optimal_uncertified` (integral,
  the bound not close enough), `optimal_after_branch_and_bound` (fractional LP, solved as a 0/1 program by GLPK,
  gap 0 in floating point; `lower_bound` is the LP's rigorous bound), `fractional_bound_only` (fractional and not
  resolved: `options.resolve_fractional` off, branch and bound out of time, or no GLPK built in (MDCS_HAS_GLPK
  undefined); no triangles, `lower_bound` holds), `time_limit_reached` (the LP stopped at
  `options.lp_time_limit`), `solver_failed`.

  Options used: `metric`, `solver`, `lp_time_limit`, `resolve_fractional`, `branch_and_bound_time_limit`,
  `certificate_tolerance`, `integrality_tolerance`, `progress` (stages "empty triangles", "LP solve",
  "branch and bound"; returning false throws `CGAL::MDCS::Operation_cancelled`). `triangle_weight` is refused;
  the others are ignored (the triangulation is always validated exactly).

  \tparam PointRange a range of `Point_2` of a CGAL kernel.
  \tparam HoleRange a range of ranges of `Point_2`.
  \tparam InteriorPointRange a range of `Point_2`.
  \throws std::invalid_argument when a ring has fewer than 3 vertices or zero area, is not simple, two rings
  cross or touch, a hole lies outside the outer ring or inside another hole, an interior point lies outside the
  outer ring, on a boundary or inside a hole, two vertices coincide, a coordinate is outside
  `Mwt_coordinate_range`, there are more than `polygon_with_holes_mwt_max_vertices()` vertices, or
  `options.triangle_weight` is set, or a time limit is negative or NaN.
  \throws std::runtime_error when the domain needs the LP and the requested solver (or any, without CLP and
  GLPK) is not built in.
*/
template <class PointRange, class HoleRange, class InteriorPointRange>
Mwt_result polygon_with_holes_mwt_2(const PointRange& outer, const HoleRange& holes,
                                    const InteriorPointRange& interior_points, const Mwt_options& options = Mwt_options())
{
  typedef typename std::iterator_traits<decltype(std::begin(outer))>::value_type Point_2;
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel K;
  const char* who = "polygon_with_holes_mwt_2";
  if(options.triangle_weight)
    throw std::invalid_argument(std::string(who) + ": sums edge lengths (no user triangle weight)");
  if(!(options.lp_time_limit >= 0) || !(options.branch_and_bound_time_limit >= 0))
    throw std::invalid_argument(std::string(who) + ": the time limits must be >= 0 seconds (0: none), not NaN");
  std::vector<std::vector<Point_2>> rings(1, std::vector<Point_2>(std::begin(outer), std::end(outer)));
  for(const auto& h : holes) rings.emplace_back(std::begin(h), std::end(h));
  const std::vector<Point_2> isolated(std::begin(interior_points), std::end(interior_points));
  std::size_t total = isolated.size();
  for(const auto& r : rings) total += r.size();
  if(total > polygon_with_holes_mwt_max_vertices())
    throw std::invalid_argument(std::string(who) + ": " + std::to_string(total) + " vertices; at most " +
                                std::to_string(polygon_with_holes_mwt_max_vertices()));
  const internal::Polygonal_domain_2<K> domain(rings, isolated, who);   // checks everything
  if(domain.holes() > 0 || domain.interior_points() > 0)
    return internal::polygonal_domain_mwt(domain, options);

  // a simple polygon: the exact dynamic program on the counter-clockwise walk, mapped back to the input order
  const auto start = std::chrono::steady_clock::now();
  const int k = int(domain.size());
  std::vector<int> walk(1, 0);
  for(int v = domain.next[0]; v != 0; v = domain.next[v]) walk.push_back(v);
  std::vector<Point_2> ccw;
  for(int v : walk) ccw.push_back(domain.points[std::size_t(v)]);
  Mwt_result r;
  std::size_t exact = 0;
  r.weight = simple_polygon_mwt_2(ccw, std::back_inserter(r.triangles), options.metric, &exact);
  for(auto& t : r.triangles)
    for(int& v : t) v = walk[std::size_t(v)];
  r.lower_bound = r.weight;   // the program's decisions are exact
  r.lp_objective = r.weight;
  r.lp_integral = true;
  r.status = Mwt_status::certified_optimal;
  r.solver = "simple polygon dynamic program";
  r.message = "no holes and no interior points: solved by the exact dynamic program of simple polygons (no LP)";
  r.statistics.points = r.statistics.hull_points = std::size_t(k);
  r.statistics.dp_triangles = r.triangles.size();
  r.statistics.dp_exact_decisions = exact;
  r.statistics.dp_exact_faces = exact > 0 ? 1 : 0;
  r.statistics.time_face_dp = r.statistics.time_total =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

/*!
  \brief `polygon_with_holes_mwt_2()` on a `CGAL::Polygon_with_holes_2`: its outer boundary, then its holes in
  the order of `holes_begin()`, then `interior_points`, numbered that way.
*/
template <class Kernel, class Container, class InteriorPointRange>
Mwt_result polygon_with_holes_mwt_2(const CGAL::Polygon_with_holes_2<Kernel, Container>& domain,
                                    const InteriorPointRange& interior_points, const Mwt_options& options = Mwt_options())
{
  typedef typename Kernel::Point_2 Point_2;
  const std::vector<Point_2> outer(domain.outer_boundary().vertices_begin(), domain.outer_boundary().vertices_end());
  std::vector<std::vector<Point_2>> holes;
  for(auto h = domain.holes_begin(); h != domain.holes_end(); ++h) holes.emplace_back(h->vertices_begin(), h->vertices_end());
  return polygon_with_holes_mwt_2(outer, holes, interior_points, options);
}

} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_POLYGON_WITH_HOLES_MWT_2_H
