// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Weights of the edges of a line arrangement for a curve functional: w(e) = ∫_e G(f, f', x) dx.

#ifndef CGAL_VARIATIONAL_MINIMIZATION_CURVE_EDGE_WEIGHTS_2_H
#define CGAL_VARIATIONAL_MINIMIZATION_CURVE_EDGE_WEIGHTS_2_H

#include <CGAL/MDCS/concurrency.h>
#include <CGAL/MDCS/progress.h>
#include <CGAL/Variational_minimization/Line_arrangement_2.h>
#include <CGAL/Variational_minimization/edge_weight_2.h>

#include <limits>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

namespace internal {

// The weight of edge i (see curve_edge_weights_2()).
template <class Functional>
double curve_edge_weight_2(const Line_arrangement_2& arrangement, const Functional& G, std::size_t i)
{
  typedef Line_arrangement_2::Edge Edge;
  const Edge& e = arrangement.edge(Line_arrangement_2::Edge_index(i));
  if(e.kind == Line_arrangement_2::LEFT_WALL || e.kind == Line_arrangement_2::RIGHT_WALL ||
     arrangement.is_vertical(Line_arrangement_2::Edge_index(i)))
    return std::numeric_limits<double>::infinity();
  double slope = 0; // floor and ceiling
  if(e.kind == Line_arrangement_2::LINE_EDGE) {
    const Arrangement_line_2& l = arrangement.line(e.line);
    slope = (l.q.y() - l.p.y()) / (l.q.x() - l.p.x());
  }
  const auto& a = arrangement.point(e.source);
  const auto& b = arrangement.point(e.target);
  // Rounding may leave a tiny exact edge with reversed or equal x in doubles: it has (near) zero weight.
  if(!(a.x() < b.x())) return 0;
  return edge_weight_2(G, a.x(), a.y(), b.x(), b.y(), slope);
}

template <class Functional, class Progress>
std::vector<double> curve_edge_weights_impl_2(const Line_arrangement_2& arrangement, const Functional& G,
                                              std::size_t threads, Progress& progress)
{
  const std::size_t n = arrangement.number_of_edges();
  std::vector<double> weights(n);
  if(threads <= 1) {
    CGAL::MDCS::internal::Progress_reporter<Progress> report(progress, "weights", n);
    for(std::size_t i = 0; i < n; ++i) {
      report(i);
      weights[i] = curve_edge_weight_2(arrangement, G, i);
    }
    report.finish();
    return weights;
  }
  // Fixed blocks, each writing its own edges' weights with the sequential code: identical for every thread count.
  CGAL::MDCS::Parallel_progress<Progress> report(progress, "weights", n);
  CGAL::MDCS::parallel_for_blocks_lowest_error(n, 1024, threads, [&](std::size_t begin, std::size_t end, std::size_t) {
    if(report.cancelled()) return;
    for(std::size_t i = begin; i < end; ++i) weights[i] = curve_edge_weight_2(arrangement, G, i);
    report.advance(end - begin);
  });
  report.finish();
  return weights;
}

} // namespace internal

/*!
  \brief Computes the weight of every edge of `arrangement` for the functional `G`.

  The weight of a non-vertical edge from (x0, y0) to (x1, y1) on a line of slope k is
  ∫_{x0}^{x1} G(y(x), k, x) dx: closed form when `G` provides one, adaptive Gauss–Kronrod quadrature
  otherwise (see `edge_weight_2()`). The slope is taken from the exact supporting line, the end points are
  the rounded vertices. Vertical edges (the side walls, and edges of vertical lines) get +infinity:
  a function cannot contain them. Floor and ceiling edges are ordinary horizontal edges.

  \tparam Functional a model of `CurveFunctional_2`.
  \tparam Progress a progress callback (`bool(const char*, double)`), stage `"weights"`.
  \throws std::domain_error when G is negative or NaN somewhere along an edge.
*/
template <class Functional, class Progress = CGAL::MDCS::No_progress>
std::vector<double> curve_edge_weights_2(const Line_arrangement_2& arrangement, const Functional& G,
                                         Progress progress = Progress())
{
  return internal::curve_edge_weights_impl_2(arrangement, G, 1, progress);
}

/*!
  \brief `curve_edge_weights_2()` on several threads: `ConcurrencyTag` (`CGAL::Sequential_tag`,
  `CGAL::Parallel_tag`, `CGAL::Parallel_if_available_tag`) and `threads` (0: all hardware threads). The weights are
  identical for every thread count (fixed blocks of edges, the sequential code per edge), and so is the error, if
  any (that of the lowest failing edge). `G` is called from several threads at once: it must be safe for concurrent
  calls on a const object. `progress` is called from the calling thread only.
*/
template <class ConcurrencyTag, class Functional, class Progress = CGAL::MDCS::No_progress>
std::vector<double> curve_edge_weights_2(const Line_arrangement_2& arrangement, const Functional& G,
                                         std::size_t threads, Progress progress = Progress())
{
  return internal::curve_edge_weights_impl_2(arrangement, G, CGAL::MDCS::effective_threads<ConcurrencyTag>(threads),
                                             progress);
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_CURVE_EDGE_WEIGHTS_2_H
