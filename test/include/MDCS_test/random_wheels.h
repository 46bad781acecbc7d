// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The random wheels of the thesis's Fig. 3.5 (ch. 3.5: "N points are randomly placed on the circle around one
// central point"), and what settles one: the triangle LP alone (an integral optimum, no branch and bound) and the
// LMT-skeleton alone (its certain edges connect every point, so that every face left is a polygon without an
// input point inside, for the polygon program). Shared by the tests and by `bench_mwt --random-wheels`.
//
// Needs the LP solver models of the build (MDCS_HAS_CLP and MDCS_HAS_GLPK) for `random_wheel_trial()`.

#ifndef MDCS_TEST_RANDOM_WHEELS_H
#define MDCS_TEST_RANDOM_WHEELS_H

#include <CGAL/Minimum_weight_triangulation_2.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Random.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/point_generators_2.h>

#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace MDCS_test {

/*!
  A random wheel: the centre (0, 0) first, then `k` points on the unit circle, each at an angle drawn
  independently and uniformly from [0, 2 pi) (CGAL::Random_points_on_circle_2 with `rng`).

  The thesis leaves open what happens when the centre is not surrounded; such a draw is no wheel (the k + 1
  points are in convex position, which both methods settle trivially), so the whole wheel is drawn again until
  the hull of the k + 1 points has exactly the k circle points as its corners and the centre strictly inside
  (exact predicates; this also rejects the rare draws where rounding leaves a circle point off the hull or two
  circle points coincide). For uniform angles a draw is rejected with probability k / 2^(k-1) (all points in a
  half circle); `redraws`, when given, is increased by the number of rejected draws.
  \pre k >= 3 (else std::invalid_argument)
*/
template <class Point_2>
std::vector<Point_2> random_wheel(int k, CGAL::Random& rng, long* redraws = nullptr)
{
  if(k < 3) throw std::invalid_argument("random_wheel: a wheel needs at least 3 points on the circle");
  for(;;) {
    std::vector<Point_2> p{Point_2(0, 0)};
    CGAL::Random_points_on_circle_2<Point_2> on_circle(1.0, rng);
    for(int i = 0; i < k; ++i, ++on_circle) p.push_back(*on_circle);
    std::vector<Point_2> hull;
    CGAL::convex_hull_2(p.begin() + 1, p.end(), std::back_inserter(hull));
    if(int(hull.size()) == k &&
       CGAL::bounded_side_2(hull.begin(), hull.end(), p[0]) == CGAL::ON_BOUNDED_SIDE)
      return p;
    if(redraws) ++*redraws;
  }
}

/// Whether the certain edges (`state[e] == lmt_certain` for `edges[e]`) connect all `n` points.
inline bool certain_edges_connect(std::size_t n, const std::vector<std::pair<int, int>>& edges,
                                  const std::vector<char>& state)
{
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int v) {
    while(parent[std::size_t(v)] != v) v = parent[std::size_t(v)] = parent[std::size_t(parent[std::size_t(v)])];
    return v;
  };
  std::size_t components = n;
  for(std::size_t e = 0; e < edges.size(); ++e) {
    if(state[e] != CGAL::Minimum_weight_triangulation_2::internal::lmt_certain) continue;
    const int a = root(edges[e].first), b = root(edges[e].second);
    if(a != b) { parent[std::size_t(a)] = b; --components; }
  }
  return components == 1;
}

#if defined(MDCS_HAS_CLP) && defined(MDCS_HAS_GLPK)

/// What settled one wheel (see `random_wheel_trial()`).
struct Random_wheel_trial
{
  bool lp_integral = false;       ///< the LP over all empty triangles has an integral optimum
  double lp_objective = 0;        ///< its optimum
  double lp_weight = std::numeric_limits<double>::quiet_NaN();   ///< the MWT weight of the LP path (NaN: not resolved)
  bool lmt_connected = false;     ///< the LMT-skeleton's certain edges connect every point
  bool pipeline_without_lp = false;   ///< the library's LMT pipeline needed no LP (every face solved by its programs)
  double pipeline_weight = std::numeric_limits<double>::quiet_NaN();   ///< the MWT weight of the LMT pipeline
};

/*!
  Runs the two methods of Fig. 3.5 on the point set `p`:
  - the triangle LP alone: every empty triangle (no diamond test, no skeleton; `Pruning::none`) and CLP; a
    fractional optimum is resolved by branch and bound (GLPK) when `resolve_fractional`, for its weight only;
  - the LMT-skeleton alone (on the diamond test's candidate edges, as the library computes it): whether its
    certain edges connect all points, the thesis's condition for the polygon program to finish the job;
  - the library's whole LMT pipeline (skeleton, face programs including the one-interior-point program, LP on
    what is left), for an independent weight.
*/
template <class Point_2>
Random_wheel_trial random_wheel_trial(const std::vector<Point_2>& p, bool resolve_fractional)
{
  namespace MWT = CGAL::Minimum_weight_triangulation_2;
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel Kernel;
  Random_wheel_trial t;
  MWT::Mwt_options lp;
  lp.pruning = MWT::Pruning::none;
  lp.solver = MWT::Lp_solver_choice::clp;
  lp.resolve_fractional = resolve_fractional;
  const MWT::Mwt_result r = MWT::minimum_weight_triangulation_2(p, lp);
  t.lp_integral = r.lp_integral;
  t.lp_objective = r.lp_objective;
  if(r.has_triangulation()) t.lp_weight = r.weight;

  MWT::Mwt_options lmt;
  lmt.use_lmt_skeleton = true;
  {
    MWT::Minimum_weight_triangulation_lp_2<Kernel> stages(p, lmt);
    stages.compute_candidate_edges();
    stages.compute_empty_triangles();   // runs the skeleton
    t.lmt_connected = certain_edges_connect(p.size(), stages.candidate_edges(), stages.lmt_edge_states());
  }
  const MWT::Mwt_result q = MWT::minimum_weight_triangulation_2(p, lmt);
  t.pipeline_without_lp = q.has_triangulation() && q.statistics.lp_columns == 0;
  if(q.has_triangulation()) t.pipeline_weight = q.weight;
  return t;
}

#endif

/// Wilson's score interval of a binomial proportion (`successes` of `trials`) at `z` standard deviations
/// (1.96: 95 %); [0, 1] when there are no trials.
inline std::pair<double, double> wilson_interval(long successes, long trials, double z = 1.96)
{
  if(trials <= 0) return {0.0, 1.0};
  const double n = double(trials), f = double(successes) / n, z2 = z * z;
  const double centre = (f + z2 / (2 * n)) / (1 + z2 / n);
  const double half = z / (1 + z2 / n) * std::sqrt(f * (1 - f) / n + z2 / (4 * n * n));
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

} // namespace MDCS_test

#endif // MDCS_TEST_RANDOM_WHEELS_H
