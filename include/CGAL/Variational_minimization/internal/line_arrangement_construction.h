// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Construction of Line_arrangement_2. The phases, each freeing its temporaries before the next one
// allocates:
//  1. select the usable lines (meet the open box, not a duplicate) and rank all slopes exactly;
//  2. the boundary: where each line enters and leaves the box, the marks, the corners, sorted along
//     the walls; these are the first vertices;
//  3. line by line, the intersections strictly inside the box, sorted along the line by a filtered
//     key (ties resolved exactly); equal parameters are one vertex. A vertex gets its index on the
//     lowest-numbered line through it; later lines find that index through a per-line cursor, so no
//     hashing and no union-find are needed;
//  4. the edges, numbered line after line (so the edges of one line are consecutive), then the walls;
//  5. the rotation system (lines through a vertex in slope order) and the faces as cycles of
//     half-edges.

#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_LINE_ARRANGEMENT_CONSTRUCTION_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_LINE_ARRANGEMENT_CONSTRUCTION_H

#include <CGAL/Variational_minimization/internal/line_arrangement_predicates.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/MDCS/progress.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

template <class Arrangement, class Progress>
class Line_arrangement_builder
{
  typedef typename Arrangement::Edge Edge;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 Point;
  typedef std::uint32_t Index;

  static constexpr Index none = (std::numeric_limits<Index>::max)();
  static constexpr Index unset_face = none - 1;

  // Walls are supporting lines too, stored after the m usable input lines.
  enum Wall { BOTTOM = 0, RIGHT = 1, TOP = 2, LEFT = 3 };
  // The four corners are the vertices 0..3.
  enum Corner { BOTTOM_LEFT = 0, BOTTOM_RIGHT = 1, TOP_RIGHT = 2, TOP_LEFT = 3 };

  // Progress units: the line sweep takes the first 800 of 1000, the faces the rest.
  static constexpr std::size_t progress_total = 1000;
  static constexpr std::size_t progress_lines = 800;

  // A point along a line: enclosing interval of its parameter, the other line, and an auxiliary index.
  struct Keyed
  {
    double lo, hi;
    Index other;
    Index aux;
  };

  // Where line s meets a line of larger index: filled when s is processed, read once by that line.
  struct Forward
  {
    Index other;
    Index vertex;
  };

public:
  Line_arrangement_builder(Arrangement& arr, Progress& progress)
    : arr_(arr), reporter_(progress, "arrangement", progress_total)
  {}

  void run(const std::vector<double>& left_marks, const std::vector<double>& right_marks)
  {
    check_input(left_marks, right_marks);
    select_lines();
    build_boundary(left_marks, right_marks);
    sweep_lines();
    build_edges();
    build_faces();
    reporter_.finish();
  }

private:
  // ------------------------------------------------------------------------------------------------
  // Input validation: everything is checked before any work.
  void check_input(const std::vector<double>& left_marks, const std::vector<double>& right_marks)
  {
    const CGAL::Bbox_2& b = arr_.box_;
    if(!(std::isfinite(b.xmin()) && std::isfinite(b.xmax()) && std::isfinite(b.ymin()) && std::isfinite(b.ymax())))
      throw std::invalid_argument("MDCS: the arrangement box must be finite");
    if(!(b.xmin() < b.xmax()) || !(b.ymin() < b.ymax()))
      throw std::invalid_argument("MDCS: the arrangement box must have xmin < xmax and ymin < ymax");
    for(std::size_t i = 0; i < arr_.lines_.size(); ++i) {
      const Point& p = arr_.lines_[i].p;
      const Point& q = arr_.lines_[i].q;
      if(!(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(q.x()) && std::isfinite(q.y())))
        throw std::invalid_argument("MDCS: line " + std::to_string(i) + " has a non-finite coordinate");
      if(p.x() == q.x() && p.y() == q.y())
        throw std::invalid_argument("MDCS: line " + std::to_string(i) + " is defined by two equal points");
    }
    // Index space: 32-bit indices, and the rotation system packs an edge index with two flags.
    if(arr_.lines_.size() >= (std::size_t(1) << 30))
      throw std::invalid_argument("MDCS: too many lines for Line_arrangement_2");
    auto check_marks = [&](const std::vector<double>& marks, const char* side) {
      for(double y : marks)
        if(!std::isfinite(y) || y < b.ymin() || y > b.ymax()) {
          std::ostringstream os;
          os.precision(17);
          os << "MDCS: " << side << " wall mark " << y << " is not a finite value in [" << b.ymin() << ", "
             << b.ymax() << "]";
          throw std::invalid_argument(os.str());
        }
    };
    check_marks(left_marks, "left");
    check_marks(right_marks, "right");
  }

  // ------------------------------------------------------------------------------------------------
  // Phase 1: usable lines and slope ranks.
  void select_lines()
  {
    const CGAL::Bbox_2& b = arr_.box_;
    const std::size_t n = arr_.lines_.size();
    const Point corner[4] = { Point(b.xmin(), b.ymin()), Point(b.xmax(), b.ymin()), Point(b.xmax(), b.ymax()),
                              Point(b.xmin(), b.ymax()) };

    // A line meets the open box iff two corners lie strictly on opposite sides. This drops lines that
    // miss the box, touch only a corner, or run along a wall (CGAL::orientation on Epick is exact).
    std::vector<Arr_line> cand;
    std::vector<Index> cand_input;
    for(std::size_t i = 0; i < n; ++i) {
      const Point& p = arr_.lines_[i].p;
      const Point& q = arr_.lines_[i].q;
      bool pos = false, neg = false;
      for(const Point& c : corner) {
        const CGAL::Orientation o = CGAL::orientation(p, q, c);
        pos = pos || o == CGAL::LEFT_TURN;
        neg = neg || o == CGAL::RIGHT_TURN;
      }
      if(pos && neg) {
        cand.push_back(make_arr_line(p.x(), p.y(), q.x(), q.y()));
        cand_input.push_back(Index(i));
      }
    }
    const std::size_t nc = cand.size();
    // The walls join the slope ranking (they are never equal to a candidate: those cross the open box).
    cand.push_back(make_arr_line(b.xmin(), b.ymin(), b.xmax(), b.ymin()));
    cand.push_back(make_arr_line(b.xmax(), b.ymin(), b.xmax(), b.ymax()));
    cand.push_back(make_arr_line(b.xmin(), b.ymax(), b.xmax(), b.ymax()));
    cand.push_back(make_arr_line(b.xmin(), b.ymin(), b.xmin(), b.ymax()));

    // Exact sort by (slope, signed offset): equal neighbours are the same line.
    std::vector<Index> order(cand.size());
    for(std::size_t k = 0; k < order.size(); ++k) order[k] = Index(k);
    auto compare_lines = [&](Index a, Index c) -> int {
      const CGAL::Comparison_result s = compare_slopes(cand[a], cand[c]);
      if(s != CGAL::EQUAL) return int(s);
      // Parallel with the same normalized direction: c on the left of a means c comes after a.
      const CGAL::Orientation o = CGAL::orientation(Point(cand[a].px, cand[a].py), Point(cand[a].qx, cand[a].qy),
                                                    Point(cand[c].px, cand[c].py));
      return o == CGAL::LEFT_TURN ? -1 : (o == CGAL::RIGHT_TURN ? 1 : 0);
    };
    // Ties keep the input order, so the first of equal lines comes first in its run.
    std::stable_sort(order.begin(), order.end(), [&](Index a, Index c) { return compare_lines(a, c) < 0; });

    std::vector<unsigned char> keep(nc, 0);
    std::vector<Index> cand_rank(cand.size());
    Index rank = 0;
    for(std::size_t k = 0; k < order.size(); ++k) {
      bool duplicate = false;
      if(k > 0) {
        const int c = compare_lines(order[k - 1], order[k]);
        CGAL_assertion(c <= 0);
        duplicate = (c == 0);
        if(c != 0 && compare_slopes(cand[order[k - 1]], cand[order[k]]) != CGAL::EQUAL)
          ++rank;
      }
      cand_rank[order[k]] = rank;
      if(order[k] < nc && !duplicate)
        keep[order[k]] = 1;
    }

    arr_.used_.assign(n, 0);
    rank_by_input_.assign(n, none);
    for(std::size_t k = 0; k < nc; ++k)
      if(keep[k]) {
        lines_.push_back(cand[k]);
        input_of_.push_back(cand_input[k]);
        rank_.push_back(cand_rank[k]);
        arr_.used_[cand_input[k]] = 1;
        rank_by_input_[cand_input[k]] = cand_rank[k];
      }
    m_ = Index(lines_.size());
    for(int w = 0; w < 4; ++w) {
      lines_.push_back(cand[nc + w]);
      rank_.push_back(cand_rank[nc + w]);
    }
  }

  Index wall_line(int w) const { return m_ + Index(w); }

  // ------------------------------------------------------------------------------------------------
  // Sorting points along a base line: sort by the lower ends of the parameter intervals; then runs of
  // overlapping intervals ("clusters") are sorted exactly. Any element after a cluster has its lower end
  // above every upper end of the cluster, so the result is exactly sorted. Calls group(first, last) for
  // each run of exactly equal parameters.
  template <class Group>
  void sort_and_group(const Arr_line& base, std::vector<Keyed>& items, Group group)
  {
    std::sort(items.begin(), items.end(), [](const Keyed& a, const Keyed& b) { return a.lo < b.lo; });
    const std::size_t count = items.size();
    std::size_t k = 0;
    while(k < count) {
      std::size_t end = k + 1;
      double reach = items[k].hi;
      while(end < count && items[end].lo <= reach) {
        reach = (std::max)(reach, items[end].hi);
        ++end;
      }
      if(end == k + 1) {
        group(k, end);
      } else {
        std::sort(items.begin() + k, items.begin() + end, [&](const Keyed& a, const Keyed& b) {
          return compare_params_exact(base, lines_[a.other], lines_[b.other]) == CGAL::SMALLER;
        });
        std::size_t g = k;
        for(std::size_t j = k + 1; j <= end; ++j)
          if(j == end || compare_params_exact(base, lines_[items[g].other], lines_[items[j].other]) != CGAL::EQUAL) {
            group(g, j);
            g = j;
          }
      }
      k = end;
    }
  }

  Index add_vertex(double x, double y)
  {
    const CGAL::Bbox_2& b = arr_.box_;
    // The exact vertex lies in the closed box, so clamping never moves the approximation away from it.
    x = (std::min)((std::max)(x, b.xmin()), b.xmax());
    y = (std::min)((std::max)(y, b.ymin()), b.ymax());
    if(arr_.points_.size() >= std::size_t(unset_face))
      throw std::length_error("MDCS: too many vertices for 32-bit indices in Line_arrangement_2");
    arr_.points_.push_back(Point(x, y));
    return Index(arr_.points_.size() - 1);
  }

  // ------------------------------------------------------------------------------------------------
  // Phase 2: the boundary.
  void build_boundary(const std::vector<double>& left_marks, const std::vector<double>& right_marks)
  {
    const CGAL::Bbox_2& b = arr_.box_;
    add_vertex(b.xmin(), b.ymin());
    add_vertex(b.xmax(), b.ymin());
    add_vertex(b.xmax(), b.ymax());
    add_vertex(b.xmin(), b.ymax());

    entry_vertex_.assign(m_, none);
    exit_vertex_.assign(m_, none);
    entry_wall_.assign(m_, none);
    exit_wall_.assign(m_, none);
    // Items on each wall; aux = 2 s (entry of s), 2 s + 1 (exit of s), or mark_tag | k.
    std::array<std::vector<Keyed>, 4> items;
    const Index mark_tag = Index(1) << 31;

    auto on_wall = [&](Index s, int w, bool entry) {
      double lo, hi;
      param_interval(lines_[wall_line(w)], lines_[s], lo, hi);
      items[w].push_back(Keyed{ lo, hi, s, 2 * s + (entry ? 0 : 1) });
    };
    for(Index s = 0; s < m_; ++s) {
      const Arr_line& l = lines_[s];
      int entry_w, exit_w;                  // wall of the entry / exit point
      int entry_c = -1, exit_c = -1;        // corner, if the line passes through one
      if(is_vertical(l)) {
        entry_w = BOTTOM;
        exit_w = TOP;
      } else if(is_horizontal(l)) {
        entry_w = LEFT;
        exit_w = RIGHT;
      } else if(l.qy > l.py) {
        // Rising: enters at max(t_left, t_bottom), leaves at min(t_right, t_top).
        const CGAL::Comparison_result c_in = compare_params(l, lines_[wall_line(LEFT)], lines_[wall_line(BOTTOM)]);
        entry_w = c_in == CGAL::SMALLER ? BOTTOM : LEFT;
        if(c_in == CGAL::EQUAL) entry_c = BOTTOM_LEFT;
        const CGAL::Comparison_result c_out = compare_params(l, lines_[wall_line(RIGHT)], lines_[wall_line(TOP)]);
        exit_w = c_out == CGAL::LARGER ? TOP : RIGHT;
        if(c_out == CGAL::EQUAL) exit_c = TOP_RIGHT;
      } else {
        // Falling: enters at max(t_left, t_top), leaves at min(t_right, t_bottom).
        const CGAL::Comparison_result c_in = compare_params(l, lines_[wall_line(LEFT)], lines_[wall_line(TOP)]);
        entry_w = c_in == CGAL::SMALLER ? TOP : LEFT;
        if(c_in == CGAL::EQUAL) entry_c = TOP_LEFT;
        const CGAL::Comparison_result c_out = compare_params(l, lines_[wall_line(RIGHT)], lines_[wall_line(BOTTOM)]);
        exit_w = c_out == CGAL::LARGER ? BOTTOM : RIGHT;
        if(c_out == CGAL::EQUAL) exit_c = BOTTOM_RIGHT;
      }
      entry_wall_[s] = wall_line(entry_w);
      exit_wall_[s] = wall_line(exit_w);
      if(entry_c >= 0) entry_vertex_[s] = Index(entry_c); else on_wall(s, entry_w, true);
      if(exit_c >= 0) exit_vertex_[s] = Index(exit_c); else on_wall(s, exit_w, false);
    }

    // Marks: virtual horizontal lines, used only to sort and merge them with the hits on a side wall.
    auto add_marks = [&](const std::vector<double>& marks, int w, std::vector<Index>& out) {
      out.assign(marks.size(), none);
      for(std::size_t k = 0; k < marks.size(); ++k) {
        if(marks[k] == b.ymin()) out[k] = (w == LEFT ? BOTTOM_LEFT : BOTTOM_RIGHT);
        else if(marks[k] == b.ymax()) out[k] = (w == LEFT ? TOP_LEFT : TOP_RIGHT);
        else {
          lines_.push_back(make_arr_line(b.xmin(), marks[k], b.xmax(), marks[k]));
          const Index s = Index(lines_.size() - 1);
          double lo, hi;
          param_interval(lines_[wall_line(w)], lines_[s], lo, hi);
          items[w].push_back(Keyed{ lo, hi, s, mark_tag | Index(k) });
        }
      }
    };
    add_marks(left_marks, LEFT, arr_.left_mark_vertices_);
    add_marks(right_marks, RIGHT, arr_.right_mark_vertices_);

    // Sort along each wall; each group of equal points is one vertex.
    static const Index wall_start[4] = { BOTTOM_LEFT, BOTTOM_RIGHT, TOP_LEFT, BOTTOM_LEFT };
    static const Index wall_end[4] = { BOTTOM_RIGHT, TOP_RIGHT, TOP_RIGHT, TOP_LEFT };
    for(int w = 0; w < 4; ++w) {
      const Arr_line& base = lines_[wall_line(w)];
      std::vector<Index>& seq = wall_seq_[w];
      seq.push_back(wall_start[w]);
      sort_and_group(base, items[w], [&](std::size_t first, std::size_t last) {
        double x, y;
        const Keyed& rep = items[w][first];
        if(rep.aux & mark_tag) {
          x = (w == LEFT ? b.xmin() : b.xmax());
          y = lines_[rep.other].py;
        } else {
          intersection_point(lines_[rep.other], base, b.xmax() - b.xmin(), b.ymax() - b.ymin(), x, y);
          if(w == LEFT) x = b.xmin();
          else if(w == RIGHT) x = b.xmax();
          else if(w == BOTTOM) y = b.ymin();
          else y = b.ymax();
        }
        for(std::size_t k = first; k < last; ++k) {
          if(items[w][k].aux & mark_tag) {
            y = lines_[items[w][k].other].py;   // a mark is exact; prefer it
            x = (w == LEFT ? b.xmin() : b.xmax());
          }
        }
        const Index v = add_vertex(x, y);
        for(std::size_t k = first; k < last; ++k) {
          const Index aux = items[w][k].aux;
          if(aux & mark_tag) (w == LEFT ? arr_.left_mark_vertices_ : arr_.right_mark_vertices_)[aux & ~mark_tag] = v;
          else if(aux & 1) exit_vertex_[aux >> 1] = v;
          else entry_vertex_[aux >> 1] = v;
        }
        seq.push_back(v);
      });
      seq.push_back(wall_end[w]);
      std::vector<Keyed>().swap(items[w]);
    }
    lines_.resize(m_ + 4);   // the mark lines are no longer needed

    // Parameter intervals of the entry and exit points: the bounds of the in-box filter.
    in_lo_.resize(m_); in_hi_.resize(m_); out_lo_.resize(m_); out_hi_.resize(m_);
    for(Index s = 0; s < m_; ++s) {
      param_interval(lines_[s], lines_[entry_wall_[s]], in_lo_[s], in_hi_[s]);
      param_interval(lines_[s], lines_[exit_wall_[s]], out_lo_[s], out_hi_[s]);
      CGAL_assertion(entry_vertex_[s] != none && exit_vertex_[s] != none);
    }
  }

  // Is the intersection of s and j (j not parallel to s) strictly inside the box? Exact.
  bool strictly_inside(Index s, Index j, double lo, double hi) const
  {
    if(lo > in_hi_[s] && hi < out_lo_[s]) return true;
    if(hi <= in_lo_[s] || lo >= out_hi_[s]) return false;
    const Arr_line& l = lines_[s];
    return compare_params_exact(l, lines_[entry_wall_[s]], lines_[j]) == CGAL::SMALLER &&
           compare_params_exact(l, lines_[j], lines_[exit_wall_[s]]) == CGAL::SMALLER;
  }

  // ------------------------------------------------------------------------------------------------
  // Phase 3: the interior intersections, line by line.
  void sweep_lines()
  {
    const CGAL::Bbox_2& b = arr_.box_;
    const double scale_x = b.xmax() - b.xmin(), scale_y = b.ymax() - b.ymin();
    std::vector<std::vector<Forward>> forward(m_);
    std::vector<Index> cursor(m_, 0);
    std::vector<Keyed> items;
    seq_offset_.assign(m_ + 1, 0);
    seq_.reserve(std::size_t(2) * m_ + 16);

    for(Index s = 0; s < m_; ++s) {
      const Arr_line& l = lines_[s];
      items.clear();
      // Lines of smaller index: exactly those whose cursor points at s; the vertex is already known.
      for(Index j = 0; j < s; ++j) {
        std::vector<Forward>& f = forward[j];
        if(cursor[j] < f.size() && f[cursor[j]].other == s) {
          double lo, hi;
          param_interval(l, lines_[j], lo, hi);
          items.push_back(Keyed{ lo, hi, j, f[cursor[j]].vertex });
          if(++cursor[j] == f.size())
            std::vector<Forward>().swap(f);   // fully consumed
        }
      }
      // Lines of larger index: test exactly whether they cross s strictly inside the box.
      std::vector<Forward>& fs = forward[s];
      for(Index j = s + 1; j < m_; ++j) {
        const Arr_line& o = lines_[j];
        double lo, hi;
        if(!approx_param(l, o, lo, hi)) {
          if(exact_cross_sign(l, o) == CGAL::ZERO)
            continue;   // parallel (distinct, since duplicates are gone)
          param_interval(l, o, lo, hi);
        }
        if(strictly_inside(s, j, lo, hi)) {
          items.push_back(Keyed{ lo, hi, j, Index(fs.size()) });
          fs.push_back(Forward{ j, none });
        }
      }

      seq_.push_back(entry_vertex_[s]);
      sort_and_group(l, items, [&](std::size_t first, std::size_t last) {
        Index v = none;
        for(std::size_t k = first; k < last; ++k)
          if(items[k].other < s) {
            CGAL_assertion(v == none || v == items[k].aux);
            v = items[k].aux;
          }
        if(v == none) {
          double x, y;
          intersection_point(l, lines_[items[first].other], scale_x, scale_y, x, y);
          // Vertical and horizontal lines give one coordinate exactly.
          if(is_vertical(l)) x = l.px;
          if(is_horizontal(l)) y = l.py;
          for(std::size_t k = first; k < last; ++k) {
            const Arr_line& o = lines_[items[k].other];
            if(is_vertical(o)) x = o.px;
            if(is_horizontal(o)) y = o.py;
          }
          v = add_vertex(x, y);
        }
        for(std::size_t k = first; k < last; ++k)
          if(items[k].other > s)
            fs[items[k].aux].vertex = v;
        seq_.push_back(v);
      });
      seq_.push_back(exit_vertex_[s]);
      seq_offset_[s + 1] = Index(seq_.size());
      if(seq_.size() >= std::size_t(1) << 30)
        throw std::length_error("MDCS: too many edges for Line_arrangement_2");
      reporter_(std::size_t(s + 1) * progress_lines / (m_ + 1));
    }
#ifndef CGAL_NO_ASSERTIONS
    for(Index j = 0; j < m_; ++j)
      CGAL_assertion(cursor[j] == forward[j].size() || forward[j].empty());
#endif
    std::vector<Keyed>().swap(items);
    std::vector<double>().swap(in_lo_); std::vector<double>().swap(in_hi_);
    std::vector<double>().swap(out_lo_); std::vector<double>().swap(out_hi_);
  }

  // ------------------------------------------------------------------------------------------------
  // Phase 4: edges. The edges of a line (and of a wall) are consecutive, which the rotation system uses.
  void build_edges()
  {
    std::size_t count = seq_.size() - m_;
    for(int w = 0; w < 4; ++w) count += wall_seq_[w].size() - 1;
    if(count >= (std::size_t(1) << 30))
      throw std::length_error("MDCS: too many edges for Line_arrangement_2");
    std::vector<Edge>& edges = arr_.edges_;
    edges.clear();
    edges.reserve(count);
    for(Index s = 0; s < m_; ++s)
      for(Index k = seq_offset_[s]; k + 1 < seq_offset_[s + 1]; ++k)
        edges.push_back(Edge{ seq_[k], seq_[k + 1], input_of_[s], Arrangement::LINE_EDGE, unset_face, unset_face });
    std::vector<Index>().swap(seq_);
    std::vector<Index>().swap(seq_offset_);

    // Walls: the outside of the box is the exterior face (null_index).
    static const typename Arrangement::Edge_kind kind[4] = { Arrangement::BOTTOM_WALL, Arrangement::RIGHT_WALL,
                                                            Arrangement::TOP_WALL, Arrangement::LEFT_WALL };
    for(int w = 0; w < 4; ++w) {
      std::vector<Index>& out = arr_.wall_edges_[std::size_t(kind[w]) - 1];
      out.clear();
      const std::vector<Index>& seq = wall_seq_[w];
      // Outside = below the floor, right of the right wall (both on the right), above the ceiling and
      // left of the left wall (on the left).
      const bool outside_left = (w == TOP || w == LEFT);
      for(std::size_t k = 0; k + 1 < seq.size(); ++k) {
        out.push_back(Index(edges.size()));
        edges.push_back(Edge{ seq[k], seq[k + 1], Arrangement::null_index, kind[w],
                              outside_left ? Arrangement::null_index : unset_face,
                              outside_left ? unset_face : Arrangement::null_index });
      }
      std::vector<Index>().swap(wall_seq_[w]);
    }
    CGAL_assertion(edges.size() == count);
  }

  // Slope rank of the supporting line of an edge.
  Index edge_rank(Index e) const
  {
    const Edge& ed = arr_.edges_[e];
    switch(ed.kind) {
      case Arrangement::BOTTOM_WALL: return rank_[wall_line(BOTTOM)];
      case Arrangement::RIGHT_WALL: return rank_[wall_line(RIGHT)];
      case Arrangement::TOP_WALL: return rank_[wall_line(TOP)];
      case Arrangement::LEFT_WALL: return rank_[wall_line(LEFT)];
      default: return rank_by_input_[ed.line];
    }
  }

  // ------------------------------------------------------------------------------------------------
  // Phase 5: the rotation system and the faces.
  //
  // At a vertex, each supporting line through it has an out-edge (leaving to the right, or upwards),
  // an in-edge (arriving from the left, or from below), or both. An incidence packs
  //   (x << 2) | (has_out << 1) | has_in,  x = the out-edge if any, else the in-edge;
  // with both, the in-edge is x - 1 because the edges of a line are consecutive. Sorting the lines by
  // slope sorts the outgoing directions counterclockwise: the out-edges (angles in (-90, 90]) by rank,
  // then the reversed in-edges (angles in (90, 270]) by rank.
  static Index in_edge_of(Index inc) { return (inc & 2) ? (inc >> 2) - 1 : (inc >> 2); }

  void build_rotation_system()
  {
    const std::vector<Edge>& edges = arr_.edges_;
    const std::size_t nv = arr_.points_.size(), ne = edges.size();
    inc_offset_.assign(nv + 1, 0);
    // A run of consecutive edges on one supporting line: edge e starts a run if e - 1 is on another line.
    auto starts_run = [&](std::size_t e) {
      return e == 0 || edges[e - 1].kind != edges[e].kind || edges[e - 1].line != edges[e].line ||
             edges[e - 1].target != edges[e].source;
    };
    auto ends_run = [&](std::size_t e) { return e + 1 == ne || starts_run(e + 1); };
    for(std::size_t e = 0; e < ne; ++e) {
      ++inc_offset_[edges[e].source + 1];
      if(ends_run(e)) ++inc_offset_[edges[e].target + 1];
    }
    for(std::size_t v = 0; v < nv; ++v) inc_offset_[v + 1] += inc_offset_[v];
    inc_.assign(inc_offset_[nv], 0);
    {
      std::vector<Index> fill(inc_offset_.begin(), inc_offset_.end() - 1);
      for(std::size_t e = 0; e < ne; ++e) {
        const Index has_in = starts_run(e) ? 0 : 1;
        inc_[fill[edges[e].source]++] = (Index(e) << 2) | 2 | has_in;
        if(ends_run(e)) inc_[fill[edges[e].target]++] = (Index(e) << 2) | 1;
      }
    }
    for(std::size_t v = 0; v < nv; ++v) {
      Index* first = inc_.data() + inc_offset_[v];
      Index* last = inc_.data() + inc_offset_[v + 1];
      CGAL_assertion(last - first >= 1);   // a mark alone on a wall has one (the wall)
      if(last - first == 2) {
        if(edge_rank(first[1] >> 2) < edge_rank(first[0] >> 2)) std::swap(first[0], first[1]);
      } else {
        std::sort(first, last, [&](Index a, Index c) { return edge_rank(a >> 2) < edge_rank(c >> 2); });
      }
#ifndef CGAL_NO_ASSERTIONS
      // Lines through one point have distinct slopes (parallel lines never meet, duplicates are gone).
      for(Index* p = first; p + 1 < last; ++p)
        CGAL_assertion(edge_rank(p[0] >> 2) < edge_rank(p[1] >> 2));
#endif
    }
  }

  // Half-edge 2e runs along e (its face is left_face), 2e + 1 against it (right_face). The next
  // half-edge of the face on the left is the clockwise predecessor of the twin around the target.
  Index next_halfedge(Index h) const
  {
    const Index e = h >> 1;
    const bool along = (h & 1) == 0;
    const Edge& ed = arr_.edges_[e];
    const Index v = along ? ed.target : ed.source;
    const Index* b = inc_.data() + inc_offset_[v];
    const Index count = inc_offset_[v + 1] - inc_offset_[v];
    Index a = 0;
    if(along) {   // e is the in-edge of its line at v; the twin is that line's reversed in-edge
      while(a < count && !((b[a] & 1) && in_edge_of(b[a]) == e)) ++a;
    } else {      // e is the out-edge; the twin is that out-edge
      while(a < count && !((b[a] & 2) && (b[a] >> 2) == e)) ++a;
    }
    CGAL_assertion(a < count);
    // Cyclic order: out-edges by rank, then reversed in-edges by rank.
    const Index twin_flag = along ? 1 : 2, other_flag = along ? 2 : 1;
    auto half = [&](Index inc, Index flag) { return flag == 2 ? 2 * (inc >> 2) : 2 * in_edge_of(inc) + 1; };
    for(Index k = a; k-- > 0;)
      if(b[k] & twin_flag) return half(b[k], twin_flag);
    for(Index k = count; k-- > 0;)
      if(b[k] & other_flag) return half(b[k], other_flag);
    for(Index k = count; k-- > 0;)
      if(b[k] & twin_flag) return half(b[k], twin_flag);
    CGAL_assertion(false);
    return h;
  }

  Index& face_of(Index h) { return (h & 1) ? arr_.edges_[h >> 1].right_face : arr_.edges_[h >> 1].left_face; }

  void build_faces()
  {
    build_rotation_system();
#ifdef MDCS_ARR_DEBUG
    for(std::size_t e = 0; e < arr_.edges_.size(); ++e) { const Edge& d = arr_.edges_[e]; std::cerr << "e" << e << ": " << d.source << "->" << d.target << " line " << d.line << " kind " << d.kind << " L " << d.left_face << " R " << d.right_face << "\n"; }
    for(std::size_t v = 0; v + 1 < inc_offset_.size(); ++v) { std::cerr << "v" << v << " (" << arr_.points_[v] << "):"; for(Index k = inc_offset_[v]; k < inc_offset_[v+1]; ++k) std::cerr << " " << (inc_[k] >> 2) << "/" << (inc_[k] & 3); std::cerr << "\n"; }
#endif
    std::vector<Edge>& edges = arr_.edges_;
    const std::size_t ne = edges.size();
    Index faces = 0;
    const std::size_t report_step = ne / 50 + 1;
    for(std::size_t e = 0; e < ne; ++e) {
      for(Index side = 0; side < 2; ++side) {
        const Index h = Index(2 * e + side);
        if(face_of(h) != unset_face) continue;
        // Guard against an endless walk: a bounded face has at most ne half-edges.
        std::size_t steps = 0;
        Index x = h;
        do {
          CGAL_assertion(face_of(x) == unset_face);
          face_of(x) = faces;
          x = next_halfedge(x);
          if(++steps > ne)
            throw std::logic_error("MDCS: internal error, a face of Line_arrangement_2 does not close");
        } while(x != h);
        ++faces;
      }
      if(e % report_step == 0)
        reporter_(progress_lines + e * (progress_total - progress_lines) / (ne + 1));
    }
    std::vector<Index>().swap(inc_);
    std::vector<Index>().swap(inc_offset_);
    arr_.number_of_faces_ = faces;
    // Euler's formula for the connected plane graph (the walls connect everything): V - E + (F + 1) = 2.
    CGAL_assertion(arr_.points_.size() + faces == ne + 1);
  }

  Arrangement& arr_;
  CGAL::MDCS::internal::Progress_reporter<Progress> reporter_;

  std::vector<Arr_line> lines_;        // [0, m): usable input lines, then the 4 walls
  std::vector<Index> input_of_;        // input index of lines_[s], s < m
  std::vector<Index> rank_;            // slope rank of lines_[s], s < m + 4
  std::vector<Index> rank_by_input_;   // slope rank by input index (none if unused)
  Index m_ = 0;

  std::vector<Index> entry_vertex_, exit_vertex_, entry_wall_, exit_wall_;
  std::vector<double> in_lo_, in_hi_, out_lo_, out_hi_;
  std::array<std::vector<Index>, 4> wall_seq_;

  std::vector<Index> seq_, seq_offset_;   // vertices along each line
  std::vector<Index> inc_, inc_offset_;   // rotation system
};

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_LINE_ARRANGEMENT_CONSTRUCTION_H
