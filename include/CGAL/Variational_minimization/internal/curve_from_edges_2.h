// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Turns an unordered set of arrangement edges that forms a function graph into a left-to-right curve.

#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_CURVE_FROM_EDGES_2_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_CURVE_FROM_EDGES_2_H

#include <CGAL/Variational_minimization/Line_arrangement_2.h>
#include <CGAL/Variational_minimization/Minimal_curve_2.h>

#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

// Fills curve.edges (ordered), curve.polyline and curve.energy. Every edge runs left to right, so the
// ordered curve starts at the only source vertex that is no edge's target. Anything else than one simple
// left-to-right chain is an internal error: the duality theorem says a finite cut cannot produce it.
inline void order_curve_edges(const Line_arrangement_2& arrangement, const std::vector<double>& weights,
                              const std::vector<Line_arrangement_2::Edge_index>& unordered,
                              Minimal_curve_2& curve)
{
  typedef Line_arrangement_2::Vertex_index Vertex_index;
  std::unordered_map<Vertex_index, Line_arrangement_2::Edge_index> out;
  std::unordered_map<Vertex_index, int> in_degree;
  out.reserve(2 * unordered.size());
  for(auto e : unordered) {
    const auto& edge = arrangement.edge(e);
    if(!out.emplace(edge.source, e).second)
      throw std::logic_error("MDCS: internal error: the minimal curve branches at a vertex");
    ++in_degree[edge.target];
  }
  Vertex_index start = Line_arrangement_2::null_index;
  for(auto e : unordered) {
    const Vertex_index s = arrangement.edge(e).source;
    if(in_degree.find(s) == in_degree.end()) {
      if(start != Line_arrangement_2::null_index && start != s)
        throw std::logic_error("MDCS: internal error: the minimal curve has several pieces");
      start = s;
    }
  }
  curve.edges.clear();
  curve.polyline.clear();
  curve.energy = 0;
  if(unordered.empty()) return;
  if(start == Line_arrangement_2::null_index)
    throw std::logic_error("MDCS: internal error: the minimal curve has no left end");
  Vertex_index v = start;
  curve.polyline.push_back(arrangement.point(v));
  for(std::size_t k = 0; k < unordered.size(); ++k) {
    auto it = out.find(v);
    if(it == out.end())
      throw std::logic_error("MDCS: internal error: the minimal curve has several pieces");
    curve.edges.push_back(it->second);
    curve.energy += weights[it->second];
    v = arrangement.edge(it->second).target;
    curve.polyline.push_back(arrangement.point(v));
  }
}

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_CURVE_FROM_EDGES_2_H
