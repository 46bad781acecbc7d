// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The rigorous part of Minimum_weight_triangulation_lp_2: weights of triangulations with interval bounds, and
// the certificates of an LP optimum (the dual lower bound, the exact separation of the reduced costs, the exact
// certificate on the zero-reduced-cost support). Interval sums are taken in blocks of 4096 terms, in a fixed
// order, so every bound is the same for every thread count.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_LP_CERTIFICATE_2_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_LP_CERTIFICATE_2_H

#include <CGAL/Minimum_weight_triangulation_2/Linear_program.h>
#include <CGAL/Minimum_weight_triangulation_2/Mwt_result.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Empty_triangles_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Exact_length_sum_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Face_dp_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Indexed_points_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Lmt_skeleton_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Parallel_stage_2.h>
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {
namespace internal {

// Interval sum of many terms, in blocks of 4096: the outward rounding of an addition grows with the partial
// sum, so one running sum of the 3 * 10^7 edge lengths of a triangulation of 10^7 points widens by about
// up to n u |sum| (measured: 1.2e-9 relative, more than the certificate tolerance 1e-9); with blocks by
// about (4096 + n / 4096) u |sum| (about 1e-12 relative).
struct Blocked_interval_sum
{
  typedef CGAL::Interval_nt<true> Interval;

  Interval total = Interval(0), block = Interval(0);
  int count = 0;
  void add(const Interval& x)
  {
    block += x;
    if(++count == 4096) { total += block; block = Interval(0); count = 0; }
  }
  Interval value() const { return total + block; }
};

// The value of a Blocked_interval_sum of term(0), ..., term(count - 1), its blocks of 4096 terms summed in
// parallel: the same additions in the same order, so the same interval for every thread count. term(k) may
// write per-term results (each k is called once).
template <class Term>
CGAL::Interval_nt<true> blocked_interval_sum(std::size_t count, Term term, const Parallel_stage& par)
{
  typedef CGAL::Interval_nt<true> Interval;
  const std::size_t B = 4096, full = count / B;
  std::vector<Interval> part(full + 1, Interval(0));
  par.for_blocks(count, B, [&](std::size_t k0, std::size_t k1, std::size_t b) {
    Interval sum(0);
    for(std::size_t k = k0; k < k1; ++k) sum += term(k);
    part[b] = sum;
  });
  Interval total(0);
  for(std::size_t b = 0; b < full; ++b) total += part[b];
  return total + (count % B != 0 ? part[full] : Interval(0));
}

// Edge lengths of the metric (in double and as intervals), the user's triangle weight (checked), and the weight of
// a triangulation with rigorous bounds, over the points `pts` with the options of the run.
template <class Points>
class Triangulation_weights_2
{
public:
  typedef CGAL::Interval_nt<true> Interval;

  Triangulation_weights_2(const Points& points, const Mwt_options& run_options) : pts(points), options(run_options) {}

  double length(int a, int b) const
  {
    const double dx = pts.x(b) - pts.x(a), dy = pts.y(b) - pts.y(a);
    switch(options.metric) {
      case Edge_metric::L1: return std::abs(dx) + std::abs(dy);
      case Edge_metric::Linf: return std::max(std::abs(dx), std::abs(dy));
      default: return std::sqrt(dx * dx + dy * dy);
    }
  }

  Interval interval_length(int a, int b) const
  {
    const Interval dx = Interval(pts.x(b)) - Interval(pts.x(a)), dy = Interval(pts.y(b)) - Interval(pts.y(a));
    switch(options.metric) {
      case Edge_metric::L1: return CGAL::abs(dx) + CGAL::abs(dy);
      case Edge_metric::Linf: {
        const Interval ax = CGAL::abs(dx), ay = CGAL::abs(dy);
        return Interval((std::max)(ax.inf(), ay.inf()), (std::max)(ax.sup(), ay.sup()));
      }
      default: return CGAL::sqrt(CGAL::square(dx) + CGAL::square(dy));
    }
  }

  double user_weight(int a, int b, int c) const
  {
    const double w = options.triangle_weight(pts.x(a), pts.y(a), pts.x(b), pts.y(b), pts.x(c), pts.y(c));
    if(!(w > 0) || !std::isfinite(w))
      throw std::invalid_argument("minimum_weight_triangulation_2: the user triangle weight must be finite and > 0");
    return w;
  }

  // Weight (sum of edge lengths, or of the user's triangle weights) of a triangulation given by triangles; `upper`
  // receives a rigorous upper bound. The edges are summed in increasing order (the same sum for every thread count).
  double weight(const std::vector<std::array<int, 3>>& tri, const Parallel_stage& par, double* upper) const
  {
    if(options.triangle_weight) {
      // The user's weights are taken as exact doubles; their interval sum bounds the rounding of the double sum
      // whatever the number of triangles (a fixed relative slack would not).
      double s = 0;
      Blocked_interval_sum I;
      for(const auto& t : tri) {
        const double w = user_weight(t[0], t[1], t[2]);
        s += w;
        I.add(Interval(w));
      }
      if(upper) *upper = I.value().sup();
      return s;
    }
    // the edges (a < b) as rows per a, sorted and unique: in increasing order when read row by row
    for(const auto& t : tri)
      for(int v : t)
        if(v < 0 || std::size_t(v) >= pts.size()) throw std::invalid_argument("weight_of: vertex index out of range");
    std::vector<std::size_t> start;
    Uninit_vector<int> other;
    build_sorted_rows(pts.size(), tri.size(), [&](std::size_t k, auto&& add) {
      for(int i = 0; i < 3; ++i) add(std::min(tri[k][i], tri[k][(i + 1) % 3]), std::max(tri[k][i], tri[k][(i + 1) % 3]));
    }, true, start, other, par);
    Uninit_vector<int> first(other.size());   // the row of every entry
    par.for_blocks(pts.size(), 4096, [&](std::size_t a0, std::size_t a1, std::size_t) {
      for(std::size_t a = a0; a < a1; ++a)
        std::fill(first.begin() + std::ptrdiff_t(start[a]), first.begin() + std::ptrdiff_t(start[a + 1]), int(a));
    });
    Uninit_vector<double> len(other.size());
    const Interval I = blocked_interval_sum(other.size(), [&](std::size_t k) {
      len[k] = length(first[k], other[k]);
      return interval_length(first[k], other[k]);
    }, par);
    double s = 0;
    for(double l : len) s += l;   // in order: the sum of the sequential loop
    if(upper) *upper = I.sup();
    return s;
  }

  // Rigorous lower bound of the weight of a triangulation (interval sum of its edge lengths).
  double weight_lower_bound(const std::vector<std::array<int, 3>>& tri) const
  {
    std::vector<std::pair<int, int>> e;
    e.reserve(3 * tri.size());
    for(const auto& t : tri)
      for(int i = 0; i < 3; ++i) e.emplace_back(std::min(t[i], t[(i + 1) % 3]), std::max(t[i], t[(i + 1) % 3]));
    std::sort(e.begin(), e.end());
    e.erase(std::unique(e.begin(), e.end()), e.end());
    Blocked_interval_sum I;
    for(const auto& ed : e) I.add(interval_length(ed.first, ed.second));
    return I.value().inf();
  }

protected:
  const Points& pts;
  const Mwt_options& options;
};

// The certificates of an LP optimum of Minimum_weight_triangulation_lp_2, from the stages it ran: the candidate
// edges, the LP's triangles (its columns) and rows, and the scale of the LP costs.
template <class Kernel>
class Lp_certificate_2 : public Triangulation_weights_2<Indexed_points_2<Kernel>>
{
  typedef Triangulation_weights_2<Indexed_points_2<Kernel>> Base;
  using Base::interval_length;
  using Base::options;
  using Base::pts;
  using Base::user_weight;

public:
  typedef typename Base::Interval Interval;

  Lp_certificate_2(const Indexed_points_2<Kernel>& points, const Mwt_options& run_options,
                   const std::vector<std::pair<int, int>>& candidate_edges, const std::vector<Lp_triangle>& columns,
                   const Sparse_linear_program& program, const std::vector<char>& rows_one,
                   const std::vector<char>& rows_of_hull_edges, const std::vector<char>& hull_edges, double cost_scale)
    : Base(points, run_options), edges(candidate_edges), triangles(columns), lp(program), row_one(rows_one),
      row_is_hull(rows_of_hull_edges), is_hull(hull_edges), scale(cost_scale)
  {}

  // Interval enclosure of the reduced cost of column j for the duals y (costs are sums of square roots).
  Interval reduced_cost(std::size_t j, const std::vector<double>& y) const
  {
    const auto& t = triangles[j];
    Interval c(0);
    if(options.triangle_weight) {
      const double w = user_weight(t.v[0], t.v[1], t.v[2]) / scale;
      c = Interval(w * (1 - 1e-12), w * (1 + 1e-12));
    } else {
      for(int i = 0; i < 3; ++i)
        c += (row_one[t.edge[i]] ? Interval(1) : Interval(0.5)) * interval_length(t.v[i], t.v[(i + 1) % 3]);
      c /= Interval(scale);
    }
    for(int k = lp.column_start[j]; k < lp.column_start[j + 1]; ++k)
      c -= Interval(lp.value[k]) * Interval(y[lp.row_index[k]]);
    return c;
  }

  // The exact certificate: every triangulation T of the LP region satisfies the equality rows, so
  // w(T) = y.b + sum over T of the reduced costs, and T and the optimum T* differ in equally many triangles
  // (all triangulations of a region have the same count). If the smallest reduced cost outside T* exceeds the
  // largest inside it, w(T) > w(T*) for every T != T*: T* is the unique minimum, with no tolerance.
  bool reduced_costs_separate(const std::vector<double>& y, const std::vector<double>& x) const
  {
    if(y.size() != lp.number_of_rows || x.size() != triangles.size() || options.triangle_weight) return false;
    for(double v : y)
      if(!std::isfinite(v)) return false;
    double inside_max = -HUGE_VAL, outside_min = HUGE_VAL;
    for(std::size_t j = 0; j < triangles.size(); ++j) {
      const Interval d = reduced_cost(j, y);
      if(x[j] > 0.5) inside_max = std::max(inside_max, d.sup());
      else outside_min = std::min(outside_min, d.inf());
    }
    return outside_min > inside_max;
  }

  // The exact certificate of a dual degenerate optimum T* (chosen = its triangles). With the reduced costs d
  // (intervals) of the duals y: eps = max over T* of d.sup, eps2 = max(0, -min over all of d.inf), N = |T*|,
  // tau = 2 N (eps + eps2) (at least 1e-12); the support Z = {t : d_t.inf <= tau} holds T*. A triangulation T
  // with k >= 1 triangles outside Z (reduced cost > tau each) and r = |T \ T*| <= N satisfies
  // w(T) - w(T*) = sum_{T \ T*} d - sum_{T* \ T} d >= k tau - r eps2 - r eps > 0: strictly heavier.
  // If T* is not a minimum, an MWT M is strictly lighter, so M uses triangles of Z only. M is locally minimal,
  // so the LMT-skeleton computed on the triangles of Z keeps M's edges possible, and its certain edges (possible
  // edges crossed by no other) are in M (a triangulation is a maximal non-crossing set). They cut the hull into
  // faces, solved over the triangles of Z by the exact face programs (Face_dp_2): the programs' total is at
  // most w(M) < w(T*). So if every face is solved and the total equals w(T*) exactly (compare_length_sums), T*
  // is a minimum, with no tolerance. Returns |Z| on success, 0 otherwise.
  std::size_t support_certificate(const std::vector<double>& y, const std::vector<double>& x,
                                  const std::vector<std::array<int, 3>>& chosen, const Edge_index& index,
                                  const Parallel_stage& par) const
  {
    if(y.size() != lp.number_of_rows || x.size() != triangles.size() || options.triangle_weight ||
       options.metric != Edge_metric::L2)
      return 0;
    for(double v : y)
      if(!std::isfinite(v)) return 0;
    std::vector<double> lo(triangles.size());
    double eps = 0, eps2 = 0;
    std::size_t N = 0;
    for(std::size_t j = 0; j < triangles.size(); ++j) {
      const Interval d = reduced_cost(j, y);
      lo[j] = d.inf();
      eps2 = std::max(eps2, -d.inf());
      if(x[j] > 0.5) { eps = std::max(eps, d.sup()); ++N; }
    }
    const double tau = std::max(1e-12, 2 * double(N) * (eps + eps2) * (1 + 1e-9));
    if(!(tau < 1e-3)) return 0;   // duals too inaccurate for a useful support
    std::vector<Lp_triangle> Z;
    for(std::size_t j = 0; j < triangles.size(); ++j)
      if(x[j] > 0.5 || lo[j] <= tau) Z.push_back(triangles[j]);
    // the LMT-skeleton on the triangles of Z: an MWT inside Z is locally minimal with triangles of Z
    const Triangle_set Zs(edges, Z);
    const Edge_triangles by_edge(Zs, edges.size(), par);
    std::function<bool(const char*, double)> progress = options.progress;
    const std::vector<char> state = lmt_skeleton(pts, edges, Zs, by_edge, is_hull, progress, par);
    Face_dp_2<Indexed_points_2<Kernel>> dp(pts, edges, index, Zs, by_edge, state, 400, par);
    if(dp.number_of_solved_faces() + 1 != dp.number_of_faces()) return 0;   // all but the outer face
    std::vector<Length_segment> A, B;
    std::vector<std::pair<int, int>> ea, eb;
    for(int t : dp.dp_triangles())
      for(int i = 0; i < 3; ++i) ea.emplace_back(std::minmax(Z[t].v[i], Z[t].v[(i + 1) % 3]));
    for(const auto& t : chosen)
      for(int i = 0; i < 3; ++i) eb.emplace_back(std::minmax(t[i], t[(i + 1) % 3]));
    for(auto* E : {&ea, &eb}) {
      std::sort(E->begin(), E->end());
      E->erase(std::unique(E->begin(), E->end()), E->end());
    }
    // the programs' triangles must cover the hull once: as many as T* and the same hull edges
    if(dp.dp_triangles().size() != chosen.size() || ea.size() != eb.size()) return 0;
    auto seg = [&](const std::pair<int, int>& e) {
      return Length_segment{{pts.x(e.first), pts.y(e.first), pts.x(e.second), pts.y(e.second)}};
    };
    for(const auto& e : ea) A.push_back(seg(e));
    for(const auto& e : eb) B.push_back(seg(e));
    return compare_length_sums(A, B) == 0 ? Z.size() : 0;
  }

  // Rigorous lower bound (input units) of every triangulation over the candidate edges from any dual
  // vector y: for feasible x (0 <= x_t <= 1), c.x = b.y + d.x >= b.y + sum_t min(0, d_t), d = c - A^T y.
  double dual_lower_bound(const std::vector<double>& y) const
  {
    if(y.size() != lp.number_of_rows) return -HUGE_VAL;
    Interval lb(0);
    for(std::size_t i = 0; i < y.size(); ++i) {
      if(!std::isfinite(y[i])) return -HUGE_VAL;
      if(row_is_hull[i]) lb += Interval(y[i]);
    }
    for(std::size_t j = 0; j < triangles.size(); ++j) {
      const Interval d = reduced_cost(j, y);
      if(d.inf() < 0) lb += Interval(d.inf());
    }
    return (lb * Interval(scale)).inf();
  }

private:
  const std::vector<std::pair<int, int>>& edges;
  const std::vector<Lp_triangle>& triangles;
  const Sparse_linear_program& lp;
  const std::vector<char>& row_one;       // rows "sum = 1" (hull edges, edges of faces solved by the dynamic program)
  const std::vector<char>& row_is_hull;   // per LP row
  const std::vector<char>& is_hull;       // per candidate edge
  double scale;                           // LP costs are the weights divided by this
};

} // namespace internal
} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_LP_CERTIFICATE_2_H
