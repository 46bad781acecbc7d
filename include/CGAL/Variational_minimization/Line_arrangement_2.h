// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The exact arrangement of lines clipped to an axis-parallel box: the grid on which MDCS minimizes a
// curve functional. Our own compact structure, because CGAL::Arrangement_2 on an exact kernel is far
// too slow and too large for 10^4 lines (about 2*10^7 vertices).

#ifndef CGAL_VARIATIONAL_MINIMIZATION_LINE_ARRANGEMENT_2_H
#define CGAL_VARIATIONAL_MINIMIZATION_LINE_ARRANGEMENT_2_H

#include <CGAL/Bbox_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/MDCS/progress.h>
#include <CGAL/Variational_minimization/internal/line_arrangement_construction.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/// Points with double coordinates (the input of every line, and the approximations of vertices).
typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 Point_2;

/*!
  \ingroup PkgVariationalMinimizationGrid
  A line defined *exactly* as the line through two distinct points with double coordinates.
  No rounding happens anywhere: intersections of such lines are rationals in these doubles, and every
  combinatorial decision of `Line_arrangement_2` is taken on these exact values.
*/
struct Arrangement_line_2
{
  Point_2 p, q;
};

namespace internal {
template <class Arrangement, class Progress> class Line_arrangement_builder;
}

/*!
  \ingroup PkgVariationalMinimizationGrid
  \brief The exact planar arrangement of a set of lines clipped to a box `[xmin,xmax] x [ymin,ymax]`.

  The arrangement consists of
  - *vertices*: the intersections of two or more lines strictly inside the box (where k lines meet there is
    exactly one vertex), the points where lines meet the box boundary, the four box corners, and the
    wall marks;
  - *edges*: the pieces of the lines between consecutive vertices, and the pieces of the four walls;
  - *faces*: the bounded cells inside the box (the exterior of the box is not counted; in `Edge` it is
    `null_index`).

  Every combinatorial decision is exact (filtered predicates with an exact fallback), whatever the
  degeneracy: many lines through one point, lines through corners, parallel and duplicate lines, lines
  along a wall. Only `point()` is an approximation.

  **Orientation conventions.** Every edge is oriented: a non-vertical edge runs from left to right
  (its source is *exactly* left of its target), a vertical edge, and every edge of the side walls, from
  bottom to top. `left_face` and `right_face` are the faces on the left and right of the oriented edge
  (for a left-to-right edge: left = above, right = below). Wall edges have `null_index` on the outside
  of the box.

  **Dropped lines.** A line is not used when it misses the open box (including when it only touches a
  corner), when it lies on a wall (the wall is already there), or when it coincides with an earlier
  input line. See `is_line_used()`.

  **Storage.** 24 bytes per edge and 16 per vertex after construction (about 64 bytes per vertex of a
  random arrangement); faces are only indices.
*/
class Line_arrangement_2
{
public:
  typedef std::uint32_t Vertex_index;
  typedef std::uint32_t Edge_index;
  typedef std::uint32_t Face_index;
  typedef std::uint32_t Line_index;

  /// An invalid index; as a face, the exterior of the box.
  static constexpr std::uint32_t null_index = (std::numeric_limits<std::uint32_t>::max)();

  enum Edge_kind { LINE_EDGE, LEFT_WALL, RIGHT_WALL, BOTTOM_WALL, TOP_WALL };

  struct Edge
  {
    Vertex_index source, target;
    Line_index line;          ///< index of the input line; `null_index` on walls
    Edge_kind kind;
    Face_index left_face, right_face;
  };

  /*!
    Builds the arrangement of `lines` clipped to `box`.

    `left_wall_marks` and `right_wall_marks` are values `y` at which the left (`x = xmin`) and right
    (`x = xmax`) walls are split in any case, so that these points are vertices (the boundary values of a
    curve problem); a mark equal to `ymin` or `ymax` is the corresponding corner.

    `progress` is a callback `bool(const char* stage, double fraction)` (see `CGAL::MDCS::No_progress`),
    called with stage `"arrangement"`; returning `false` throws `CGAL::MDCS::Operation_cancelled`.

    \throws std::invalid_argument if the box is not finite with `xmin < xmax` and `ymin < ymax`, if a
    line has non-finite coordinates or `p == q`, or if a mark is non-finite or outside `[ymin, ymax]`.
    Zero usable lines is allowed (the box alone is one face).
  */
  template <class Progress = CGAL::MDCS::No_progress>
  Line_arrangement_2(const CGAL::Bbox_2& box, const std::vector<Arrangement_line_2>& lines,
                     const std::vector<double>& left_wall_marks = {},
                     const std::vector<double>& right_wall_marks = {}, Progress progress = Progress());

  std::size_t number_of_vertices() const { return points_.size(); }
  std::size_t number_of_edges() const { return edges_.size(); }
  /// The number of bounded faces (the cells inside the box); the exterior is not counted.
  std::size_t number_of_faces() const { return number_of_faces_; }

  /*!
    A double approximation of the exact vertex, inside the box. Each coordinate is the double formula
    when its a-priori error bound is below 2^-42 (|c| + box extent), and otherwise the exact value rounded
    to the nearest double; in practice a few units in the last place. Vertices on a wall, on a vertical
    or on a horizontal input line have that coordinate exactly.
  */
  const Point_2& point(Vertex_index v) const { return points_[v]; }
  const Edge& edge(Edge_index e) const { return edges_[e]; }

  /// Whether the edge is vertical (exact: the side walls and the edges of vertical input lines).
  bool is_vertical(Edge_index e) const
  {
    const Edge& ed = edges_[e];
    switch(ed.kind) {
      case LEFT_WALL:
      case RIGHT_WALL: return true;
      case BOTTOM_WALL:
      case TOP_WALL: return false;
      default: return lines_[ed.line].p.x() == lines_[ed.line].q.x();
    }
  }

  /*!
    The edges of one wall in order: the side walls from bottom to top, the floor and the ceiling from
    left to right. \throws std::invalid_argument for `LINE_EDGE`.
  */
  const std::vector<Edge_index>& wall_edges(Edge_kind wall) const
  {
    if(wall == LINE_EDGE || int(wall) > int(TOP_WALL))
      throw std::invalid_argument("MDCS: wall_edges() needs a wall kind, not LINE_EDGE");
    return wall_edges_[std::size_t(wall) - 1];
  }

  /// The vertex at `left_wall_marks[k]` (input order; equal marks give the same vertex).
  Vertex_index left_wall_mark_vertex(std::size_t k) const { return left_mark_vertices_.at(k); }
  /// The vertex at `right_wall_marks[k]`.
  Vertex_index right_wall_mark_vertex(std::size_t k) const { return right_mark_vertices_.at(k); }

  std::size_t number_of_input_lines() const { return lines_.size(); }
  /// Whether input line `i` contributes edges (see the class documentation for the dropped ones).
  bool is_line_used(Line_index i) const { return used_.at(i) != 0; }
  const Arrangement_line_2& line(Line_index i) const { return lines_.at(i); }
  const CGAL::Bbox_2& box() const { return box_; }

private:
  template <class Arrangement, class Progress> friend class internal::Line_arrangement_builder;

  CGAL::Bbox_2 box_;
  std::vector<Arrangement_line_2> lines_;
  std::vector<unsigned char> used_;
  std::vector<Point_2> points_;
  std::vector<Edge> edges_;
  std::array<std::vector<Edge_index>, 4> wall_edges_;   // LEFT, RIGHT, BOTTOM, TOP
  std::vector<Vertex_index> left_mark_vertices_, right_mark_vertices_;
  std::size_t number_of_faces_ = 0;
};

template <class Progress>
Line_arrangement_2::Line_arrangement_2(const CGAL::Bbox_2& box, const std::vector<Arrangement_line_2>& lines,
                                       const std::vector<double>& left_wall_marks,
                                       const std::vector<double>& right_wall_marks, Progress progress)
  : box_(box), lines_(lines)
{
  internal::Line_arrangement_builder<Line_arrangement_2, Progress> builder(*this, progress);
  builder.run(left_wall_marks, right_wall_marks);
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_LINE_ARRANGEMENT_2_H
