// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The directed dual flow network of a line arrangement for the univariate problem (thesis ch. 2.6.1).

#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_CURVE_DUAL_NETWORK_2_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_CURVE_DUAL_NETWORK_2_H

#include <CGAL/Min_cut/Flow_network.h>
#include <CGAL/Min_cut/Planar_dual.h>
#include <CGAL/Variational_minimization/Curve_problem_2.h>
#include <CGAL/Variational_minimization/Line_arrangement_2.h>
#include <CGAL/Variational_minimization/internal/curve_walls_2.h>

#include <vector>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

// Cells are nodes. A non-vertical edge separates the cell below from the cell above: the arc below->above costs
// the edge weight, the arc above->below is infinite, so every finite cut is the graph of a function (the source
// side is everything under the curve). Vertical edges are infinite both ways. Exterior edges tie their cell to
// a terminal: floor edges to the source and ceiling edges to the sink with the edge weight (the curve may run
// along them), side-wall edges below the end range to the source and above it to the sink with infinite
// capacity, and side-wall edges inside a relaxed end range get no arc at all (thesis fig. 2.5).
//
// When `dual` is given it receives the planar embedding of the network for solve_planar_min_cut(): the dual
// edge of a facet is the arrangement edge itself, oriented with the facet's "from" node (or the source) on its
// right; the curve runs from the admissible left-wall vertices (start) to the admissible right-wall ones (end).
inline CGAL::Min_cut::Flow_network<double> curve_dual_network_2(const Line_arrangement_2& arrangement,
                                                                const std::vector<double>& weights,
                                                                const Curve_problem_2& problem,
                                                                CGAL::Min_cut::Planar_dual* dual = nullptr)
{
  typedef CGAL::Min_cut::Flow_network<double> Network;
  typedef CGAL::Min_cut::Planar_dual Dual;
  typedef Line_arrangement_2 Arr;
  const double inf = Network::infinity();

  Network network;
  network.reserve(arrangement.number_of_faces(), arrangement.number_of_edges(), 0);
  network.add_nodes(arrangement.number_of_faces());
  if(dual != nullptr) {
    dual->clear();
    dual->number_of_vertices = arrangement.number_of_vertices();
    dual->edges.reserve(arrangement.number_of_edges());
  }
  // The edge's own direction if `right_node` lies on its right, else the reverse.
  auto dual_edge = [&](const Arr::Edge& e, Arr::Face_index right_node) {
    return right_node == e.right_face ? Dual::Edge{e.source, e.target} : Dual::Edge{e.target, e.source};
  };

  for(std::size_t i = 0; i < arrangement.number_of_edges(); ++i) {
    const Arr::Edge& e = arrangement.edge(Arr::Edge_index(i));
    const Network::Facet_index id = Network::Facet_index(i);
    switch(e.kind) {
    case Arr::LINE_EDGE:
      if(arrangement.is_vertical(Arr::Edge_index(i))) {
        network.add_facet(e.left_face, e.right_face, inf, inf, id);
        if(dual != nullptr) dual->edges.push_back(dual_edge(e, e.left_face));
      } else { // left-to-right edge: the right face is below, the left face above
        network.add_facet(e.right_face, e.left_face, weights[i], inf, id);
        if(dual != nullptr) dual->edges.push_back(dual_edge(e, e.right_face));
      }
      break;
    case Arr::BOTTOM_WALL: // the source lies outside, below: on the right of the edge, the cell on its left
      network.add_source_facet(e.left_face, weights[i], id);
      if(dual != nullptr) dual->source_edges.push_back(dual_edge(e, e.right_face));
      break;
    case Arr::TOP_WALL:
      network.add_sink_facet(e.right_face, weights[i], id);
      if(dual != nullptr) dual->sink_edges.push_back(dual_edge(e, e.right_face));
      break;
    default:
      break; // side walls below
    }
  }

  for(Arr::Edge_kind wall : {Arr::LEFT_WALL, Arr::RIGHT_WALL}) {
    const End_condition& end = (wall == Arr::LEFT_WALL) ? problem.left : problem.right;
    const Side_wall_classification c = classify_side_wall(arrangement, wall, end);
    const std::vector<Arr::Edge_index>& edges = arrangement.wall_edges(wall);
    for(std::size_t k = 0; k < edges.size(); ++k) {
      const Arr::Edge& e = arrangement.edge(edges[k]);
      // Bottom-to-top wall edges: the box interior is right of the left wall and left of the right wall.
      const Arr::Face_index inside = (wall == Arr::LEFT_WALL) ? e.right_face : e.left_face;
      const Arr::Face_index outside = (wall == Arr::LEFT_WALL) ? e.left_face : e.right_face;
      if(c.edge_position[k] == BELOW_END_RANGE) {
        network.add_source_facet(inside, inf, edges[k]);
        if(dual != nullptr) dual->source_edges.push_back(dual_edge(e, outside));
      } else if(c.edge_position[k] == ABOVE_END_RANGE) {
        network.add_sink_facet(inside, inf, edges[k]);
        if(dual != nullptr) dual->sink_edges.push_back(dual_edge(e, inside));
      }
    }
    if(dual != nullptr)
      (wall == Arr::LEFT_WALL ? dual->start_vertices : dual->end_vertices) = c.admissible_vertices;
  }
  return network;
}

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_CURVE_DUAL_NETWORK_2_H
