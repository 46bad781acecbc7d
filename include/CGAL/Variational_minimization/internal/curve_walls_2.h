// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where the end conditions cut the side walls of a line arrangement.

#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_CURVE_WALLS_2_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_CURVE_WALLS_2_H

#include <CGAL/Variational_minimization/Curve_problem_2.h>
#include <CGAL/Variational_minimization/Line_arrangement_2.h>

#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

// Position of a side-wall edge relative to the end condition on that wall.
enum Wall_edge_position { BELOW_END_RANGE, INSIDE_END_RANGE, ABOVE_END_RANGE };

struct Side_wall_classification
{
  std::vector<Wall_edge_position> edge_position;        // parallel to wall_edges(wall)
  std::vector<Line_arrangement_2::Vertex_index> admissible_vertices; // wall vertices in [low, high], bottom to top
};

// The marks of the arrangement are the end values ({low} or {low, high}); the wall edges are ordered bottom to
// top, so one walk over them classifies every edge combinatorially (no coordinate comparison).
inline Side_wall_classification classify_side_wall(const Line_arrangement_2& arrangement,
                                                   Line_arrangement_2::Edge_kind wall,
                                                   const End_condition& end)
{
  typedef Line_arrangement_2::Vertex_index Vertex_index;
  const bool left = (wall == Line_arrangement_2::LEFT_WALL);
  auto mark = [&](std::size_t k) {
    return left ? arrangement.left_wall_mark_vertex(k) : arrangement.right_wall_mark_vertex(k);
  };
  const Vertex_index low = mark(0);
  const Vertex_index high = end.is_fixed() ? low : mark(1);

  const std::vector<Line_arrangement_2::Edge_index>& edges = arrangement.wall_edges(wall);
  Side_wall_classification result;
  result.edge_position.reserve(edges.size());
  Wall_edge_position state = BELOW_END_RANGE;
  if(!edges.empty() && arrangement.edge(edges.front()).source == low) {
    state = (low == high) ? ABOVE_END_RANGE : INSIDE_END_RANGE;
    result.admissible_vertices.push_back(low);
  }
  for(Line_arrangement_2::Edge_index e : edges) {
    const auto& edge = arrangement.edge(e);
    result.edge_position.push_back(state);
    const Vertex_index v = edge.target;
    if(state == BELOW_END_RANGE && v == low) {
      state = (low == high) ? ABOVE_END_RANGE : INSIDE_END_RANGE;
      result.admissible_vertices.push_back(v);
    } else if(state == INSIDE_END_RANGE) {
      result.admissible_vertices.push_back(v);
      if(v == high) state = ABOVE_END_RANGE;
    }
  }
  if(result.admissible_vertices.empty() || (end.is_fixed() && result.admissible_vertices.size() != 1))
    throw std::logic_error("MDCS: internal error: the end-condition marks were not found on the side wall; "
                           "build the arrangement with build_curve_arrangement_2()");
  return result;
}

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_CURVE_WALLS_2_H
