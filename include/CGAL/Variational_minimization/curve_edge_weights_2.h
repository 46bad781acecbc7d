// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Weights of the edges of a line arrangement for a curve functional: w(e) = ∫_e G(f, f', x) dx.

#ifndef CGAL_VARIATIONAL_MINIMIZATION_CURVE_EDGE_WEIGHTS_2_H
#define CGAL_VARIATIONAL_MINIMIZATION_CURVE_EDGE_WEIGHTS_2_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Variational_minimization/Line_arrangement_2.h>
#include <CGAL/Variational_minimization/edge_weight_2.h>

#include <limits>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

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
  typedef Line_arrangement_2::Edge Edge;
  const std::size_t n = arrangement.number_of_edges();
  std::vector<double> weights(n);
  CGAL::MDCS::internal::Progress_reporter<Progress> report(progress, "weights", n);
  for(std::size_t i = 0; i < n; ++i) {
    report(i);
    const Edge& e = arrangement.edge(Line_arrangement_2::Edge_index(i));
    if(e.kind == Line_arrangement_2::LEFT_WALL || e.kind == Line_arrangement_2::RIGHT_WALL ||
       arrangement.is_vertical(Line_arrangement_2::Edge_index(i))) {
      weights[i] = std::numeric_limits<double>::infinity();
      continue;
    }
    double slope = 0; // floor and ceiling
    if(e.kind == Line_arrangement_2::LINE_EDGE) {
      const Arrangement_line_2& l = arrangement.line(e.line);
      slope = (l.q.y() - l.p.y()) / (l.q.x() - l.p.x());
    }
    const auto& a = arrangement.point(e.source);
    const auto& b = arrangement.point(e.target);
    // Rounding may leave a tiny exact edge with reversed or equal x in doubles: it has (near) zero weight.
    if(!(a.x() < b.x())) {
      weights[i] = 0;
      continue;
    }
    weights[i] = edge_weight_2(G, a.x(), a.y(), b.x(), b.y(), slope);
  }
  report.finish();
  return weights;
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_CURVE_EDGE_WEIGHTS_2_H
