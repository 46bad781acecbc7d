// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Construction of Line_arrangement_2. The phases:
//  1. select the usable lines (they meet the open box and are not duplicates) and rank all slopes
//     exactly; the walls are supporting lines too;
//  2. the boundary: where each line enters and leaves the box, the marks and the corners, sorted along
//     the walls; these are the first vertices;
//  3. line by line, the intersections strictly inside the box, sorted along the line by a filtered key
//     (ties resolved exactly); equal parameters are one vertex. A vertex gets its index on the
//     lowest-numbered line through it, which posts it to the inboxes of the other lines through it
//     (no hashing, no union-find). Each line appends one *slot* per vertex along it to a workspace
//     that is the final edge array itself (the edge leaving a slot is that slot, so a line of k + 1
//     slots has k edges); the last line through a vertex links the slots of that vertex into a cycle
//     sorted by slope: the rotation system, since sorting the lines by slope sorts their outgoing
//     directions counterclockwise (out-edges, angles in (-90, 90], by slope, then reversed in-edges);
//  4. the faces, without walking face cycles (a chain of dependent cache misses): every bounded face
//     is born at its leftmost vertex, in the wedge between two consecutive out-edges, and the face
//     labels propagate along the lower chains (from the in-edge of smallest slope to the out-edge of
//     largest slope at each vertex) and along the upper chains (the reverse). One pass over the lines
//     by increasing slope, one by decreasing slope, each reading its sources from lines already done;
//     the reads are independent, so the memory system overlaps them;
//  5. compaction of the workspace into the edge array, in place.

#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_LINE_ARRANGEMENT_CONSTRUCTION_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_LINE_ARRANGEMENT_CONSTRUCTION_H

#include <CGAL/Variational_minimization/internal/line_arrangement_predicates.h>
#include <CGAL/Variational_minimization/internal/line_arrangement_sorting.h>

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
#if defined(__linux__)
#include <sys/mman.h>
#endif

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

  // Walls are supporting lines too, stored after the m usable input lines, in this order.
  enum Wall { BOTTOM = 0, RIGHT = 1, TOP = 2, LEFT = 3 };
  // The four corners are the vertices 0..3.
  enum Corner { BOTTOM_LEFT = 0, BOTTOM_RIGHT = 1, TOP_RIGHT = 2, TOP_LEFT = 3 };

  // While the faces are computed, the `target` field of a workspace slot holds a *link word*: the next
  // slot at the same vertex in increasing slope order (cyclically), whether that next slot has an
  // in-edge and an out-edge, whether this slot has the largest slope at its vertex ("wrap"), and whether
  // the vertex has exactly two slots ("pair", the common case, which needs no further reads).
  static constexpr int slot_bits = 28;
  static constexpr Index slot_mask = (Index(1) << slot_bits) - 1;
  static constexpr Index next_in_bit = Index(1) << 28;
  static constexpr Index next_out_bit = Index(1) << 29;
  static constexpr Index wrap_bit = Index(1) << 30;
  static constexpr Index pair_bit = Index(1) << 31;
  static constexpr std::size_t slot_limit = std::size_t(1) << slot_bits;

  // Progress units: the sweep takes the first 700 of 1000, the faces the rest.
  static constexpr std::size_t progress_total = 1000;
  static constexpr std::size_t progress_sweep = 700;

  typedef Point_along_line Keyed;

  // A vertex found on line `other`, posted to a line of larger index that passes through it. The vertex
  // itself is the `source` of that slot, read when the slot is linked anyway.
  struct Forward
  {
    Index other;    // the line of smaller index
    Index slot;     // the slot of the vertex on line `other`
  };

  // A slot at a vertex, with the slope rank of its line.
  struct Incidence
  {
    Index rank;
    Index slot;
    bool in, out;
  };

  static void prefetch(const void* p)
  {
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(p);
#else
    (void)p;
#endif
  }

public:
  Line_arrangement_builder(Arrangement& arr, Progress& progress)
    : arr_(arr), reporter_(progress, "arrangement", progress_total)
  {}

  void run(const std::vector<double>& left_marks, const std::vector<double>& right_marks)
  {
    check_input(left_marks, right_marks);
    select_lines();
    build_boundary(left_marks, right_marks);
    reserve_storage();
    sweep_lines();
    append_walls();
    link_boundary();
    build_faces();
    compact();
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
    // Index space: the wall items pack a line index with a flag and a tag into 32 bits.
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
    for(std::size_t k = 0; k < nc; ++k)
      if(keep[k]) {
        lines_.push_back(cand[k]);
        input_of_.push_back(cand_input[k]);
        rank_.push_back(cand_rank[k]);
        arr_.used_[cand_input[k]] = 1;
      }
    m_ = Index(lines_.size());
    for(int w = 0; w < 4; ++w) {
      lines_.push_back(cand[nc + w]);
      rank_.push_back(cand_rank[nc + w]);
    }
  }

  Index wall_line(int w) const { return m_ + Index(w); }

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
      sorter_.sort_and_group(base, lines_, items[w], [&](std::size_t first, std::size_t last) {
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
        // Marks, and vertical (horizontal) lines on the floor or ceiling (side walls), give the free
        // coordinate exactly; prefer them to the computed one.
        for(std::size_t k = first; k < last; ++k) {
          const Arr_line& o = lines_[items[w][k].other];
          if(items[w][k].aux & mark_tag) y = o.py;
          else if((w == BOTTOM || w == TOP) && is_vertical(o)) x = o.px;
          else if((w == LEFT || w == RIGHT) && is_horizontal(o)) y = o.py;
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
    boundary_vertices_ = arr_.points_.size();

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

  // The workspace and the points are allocated once, from an upper bound on the number of vertices:
  // one per pair of lines that may cross inside the box (the filter alone, no exact arithmetic). A
  // reserved but untouched tail costs address space only, not memory.
  void reserve_storage()
  {
    std::size_t pairs = 0;
    for(Index s = 0; s < m_; ++s) {
      const Arr_line& l = lines_[s];
      for(Index j = s + 1; j < m_; ++j) {
        double lo, hi;
        if(!approx_param(l, lines_[j], lo, hi) || !(hi <= in_lo_[s] || lo >= out_hi_[s]))
          ++pairs;
      }
    }
    std::size_t slots = 2 * pairs + 2 * std::size_t(m_);
    for(int w = 0; w < 4; ++w) slots += wall_seq_[w].size();
    arr_.edges_.clear();
    arr_.edges_.reserve((std::min)(slots, slot_limit));
    arr_.points_.reserve(arr_.points_.size() + pairs);
    advise_huge_pages(arr_.edges_.data(), arr_.edges_.capacity() * sizeof(Edge));
    advise_huge_pages(arr_.points_.data(), arr_.points_.capacity() * sizeof(Point));
  }

  // Page faults on the large fresh arrays are a good part of the construction time; on Linux, ask for
  // transparent huge pages (a hint: nothing changes where they are disabled).
  static void advise_huge_pages(void* data, std::size_t bytes)
  {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if(bytes < (std::size_t(8) << 20)) return;
    const std::uintptr_t page = 4096;
    const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(data) + page - 1) & ~(page - 1);
    const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(page - 1);
    if(end > begin)
      (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
    (void)data;
    (void)bytes;
#endif
  }

  void push_slot(Index vertex, Index line, typename Arrangement::Edge_kind kind)
  {
    std::vector<Edge>& ws = arr_.edges_;
    if(ws.size() >= slot_limit)
      throw std::length_error("MDCS: too many edges for Line_arrangement_2 (at most 2^28 - number of lines)");
    ws.push_back(Edge{ vertex, 0, line, kind, unset_face, unset_face });
  }

  // Links the slots of one vertex into a cycle by increasing slope rank.
  void link_cycle(std::vector<Incidence>& inc)
  {
    std::sort(inc.begin(), inc.end(), [](const Incidence& a, const Incidence& b) { return a.rank < b.rank; });
    const std::size_t k = inc.size();
    CGAL_assertion(k >= 1);
    for(std::size_t i = 0; i < k; ++i) {
      // Lines through one point have distinct slopes (parallel lines never meet, duplicates are gone).
      CGAL_assertion(i + 1 == k || inc[i].rank < inc[i + 1].rank);
      const Incidence& next = inc[i + 1 == k ? 0 : i + 1];
      arr_.edges_[inc[i].slot].target = next.slot | (next.in ? next_in_bit : 0) | (next.out ? next_out_bit : 0) |
                                        (i + 1 == k ? wrap_bit : 0) | (k == 2 ? pair_bit : 0);
    }
  }

  void sweep_lines()
  {
    const CGAL::Bbox_2& b = arr_.box_;
    const double scale_x = b.xmax() - b.xmin(), scale_y = b.ymax() - b.ymin();
    std::vector<Edge>& ws = arr_.edges_;
    // inbox[j]: the vertices on line j already found by lines of smaller index, in increasing order of
    // those lines; line j reads them all, then frees them.
    std::vector<std::vector<Forward>> inbox(m_);
    std::vector<Keyed> items;
    std::vector<Index> known;   // for lines of smaller index: the slot of the vertex on that line
    std::vector<Incidence> inc;
    slot_offset_.assign(std::size_t(m_) + 5, 0);

    for(Index s = 0; s < m_; ++s) {
      const Arr_line& l = lines_[s];
      const Index line = input_of_[s];
      items.clear();
      known.clear();
      // Lines of smaller index: the vertex is already known.
      for(const Forward& f : inbox[s]) {
        double lo, hi;
        param_interval(l, lines_[f.other], lo, hi);
        items.push_back(Keyed{ lo, hi, f.other, Index(known.size()) });
        known.push_back(f.slot);
        prefetch(ws.data() + f.slot);   // read for the vertex, written for the link
      }
      std::vector<Forward>().swap(inbox[s]);
      // Lines of larger index: test exactly whether they cross s strictly inside the box.
      for(Index j = s + 1; j < m_; ++j) {
        const Arr_line& o = lines_[j];
        double lo, hi;
        if(!approx_param(l, o, lo, hi)) {
          if(exact_cross_sign(l, o) == CGAL::ZERO)
            continue;   // parallel (and distinct, since duplicates are gone)
          param_interval(l, o, lo, hi);
        }
        if(strictly_inside(s, j, lo, hi))
          items.push_back(Keyed{ lo, hi, j, none });
      }

      slot_offset_[s] = Index(ws.size());
      push_slot(entry_vertex_[s], line, Arrangement::LINE_EDGE);
      sorter_.sort_and_group(l, lines_, items, [&](std::size_t first, std::size_t last) {
        const Index slot = Index(ws.size());
        Index v = none;
        bool last_line = true;   // s is the line of largest index through the vertex
        for(std::size_t k = first; k < last; ++k) {
          if(items[k].other < s) {
            CGAL_assertion(v == none || v == ws[known[items[k].aux]].source);
            v = ws[known[items[k].aux]].source;
          } else {
            last_line = false;
          }
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
        push_slot(v, line, Arrangement::LINE_EDGE);
        for(std::size_t k = first; k < last; ++k)
          if(items[k].other > s)
            inbox[items[k].other].push_back(Forward{ s, slot });
        if(last_line && last - first == 1) {
          // The common case: a vertex of exactly two lines.
          const Index other_slot = known[items[first].aux];
          const bool s_steeper = rank_[s] > rank_[items[first].other];
          CGAL_assertion(rank_[s] != rank_[items[first].other]);
          const Index both = next_in_bit | next_out_bit | pair_bit;
          ws[slot].target = other_slot | both | (s_steeper ? wrap_bit : 0);
          ws[other_slot].target = slot | both | (s_steeper ? 0 : wrap_bit);
        } else if(last_line) {
          inc.clear();
          inc.push_back(Incidence{ rank_[s], slot, true, true });
          for(std::size_t k = first; k < last; ++k)
            inc.push_back(Incidence{ rank_[items[k].other], known[items[k].aux], true, true });
          link_cycle(inc);
        }
      });
      push_slot(exit_vertex_[s], line, Arrangement::LINE_EDGE);
      reporter_(std::size_t(s + 1) * progress_sweep / (std::size_t(m_) + 1));
    }
    std::vector<double>().swap(in_lo_); std::vector<double>().swap(in_hi_);
    std::vector<double>().swap(out_lo_); std::vector<double>().swap(out_hi_);
  }

  // The walls become four more lines of slots.
  void append_walls()
  {
    static const typename Arrangement::Edge_kind kind[4] = { Arrangement::BOTTOM_WALL, Arrangement::RIGHT_WALL,
                                                            Arrangement::TOP_WALL, Arrangement::LEFT_WALL };
    for(int w = 0; w < 4; ++w) {
      slot_offset_[m_ + w] = Index(arr_.edges_.size());
      for(Index v : wall_seq_[w])
        push_slot(v, Arrangement::null_index, kind[w]);
    }
    slot_offset_[m_ + 4] = Index(arr_.edges_.size());
  }

  // The rotation system at the boundary vertices: the walls and the lines entering or leaving there.
  void link_boundary()
  {
    const std::size_t nb = boundary_vertices_;
    std::vector<Index> offset(nb + 1, 0);
    std::vector<Incidence> all;
    auto for_each_boundary_slot = [&](auto f) {
      for(Index s = 0; s < m_ + 4; ++s) {
        const Index first = slot_offset_[s], last = slot_offset_[s + 1] - 1;
        if(s < m_) {
          f(first, Incidence{ rank_[s], first, false, true });
          f(last, Incidence{ rank_[s], last, true, false });
        } else {
          for(Index g = first; g <= last; ++g)
            f(g, Incidence{ rank_[s], g, g > first, g < last });
        }
      }
    };
    for_each_boundary_slot([&](Index g, const Incidence&) { ++offset[arr_.edges_[g].source + 1]; });
    for(std::size_t v = 0; v < nb; ++v) offset[v + 1] += offset[v];
    all.resize(offset[nb]);
    {
      std::vector<Index> fill(offset.begin(), offset.end() - 1);
      for_each_boundary_slot([&](Index g, const Incidence& i) { all[fill[arr_.edges_[g].source]++] = i; });
    }
    std::vector<Incidence> inc;
    for(std::size_t v = 0; v < nb; ++v) {
      inc.assign(all.begin() + offset[v], all.begin() + offset[v + 1]);
      link_cycle(inc);
    }
    std::vector<Index>().swap(entry_vertex_);
    std::vector<Index>().swap(exit_vertex_);
    for(int w = 0; w < 4; ++w) std::vector<Index>().swap(wall_seq_[w]);
  }

  // ------------------------------------------------------------------------------------------------
  // Phase 4: the faces. left_face ("up" for a left-to-right edge) and right_face ("down") of the edge
  // leaving each slot.

  // The slots at the vertex of slot g in increasing slope order; returns the position of g.
  std::size_t gather(Index g, bool g_in, bool g_out, std::vector<Incidence>& buf) const
  {
    const std::vector<Edge>& ws = arr_.edges_;
    buf.clear();
    Index word = ws[g].target;
    if(word & pair_bit) {
      const Incidence self{ 0, g, g_in, g_out };
      const Incidence other{ 0, word & slot_mask, (word & next_in_bit) != 0, (word & next_out_bit) != 0 };
      if(word & wrap_bit) { buf.push_back(other); buf.push_back(self); return 1; }
      buf.push_back(self); buf.push_back(other); return 0;
    }
    // Walk the cycle from g; remember where the largest slope is, then rotate to start after it.
    buf.push_back(Incidence{ 0, g, g_in, g_out });
    std::size_t wrap_at = (word & wrap_bit) ? 0 : std::size_t(-1);
    for(;;) {
      const Index y = word & slot_mask;
      if(y == g) break;
      buf.push_back(Incidence{ 0, y, (word & next_in_bit) != 0, (word & next_out_bit) != 0 });
      word = ws[y].target;
      if(word & wrap_bit) wrap_at = buf.size() - 1;
      CGAL_assertion(buf.size() <= ws.size());
    }
    CGAL_assertion(wrap_at != std::size_t(-1));
    const std::size_t start = (wrap_at + 1) % buf.size();
    std::rotate(buf.begin(), buf.begin() + start, buf.end());
    return (buf.size() - start) % buf.size();
  }

  void build_faces()
  {
    std::vector<Edge>& ws = arr_.edges_;
    const Index lines = m_ + 4;
    // Exterior sides of the walls: below the floor, right of the right wall, above the ceiling, left
    // of the left wall. Only the corner (xmin, ymin), which has no in-edge, relies on this preset; the
    // propagation reproduces it everywhere else.
    for(int w = 0; w < 4; ++w) {
      const bool outside_left = (w == TOP || w == LEFT);
      for(Index g = slot_offset_[m_ + w]; g < slot_offset_[m_ + w + 1]; ++g)
        (outside_left ? ws[g].left_face : ws[g].right_face) = Arrangement::null_index;
    }

    std::vector<Index> order(lines);
    for(Index s = 0; s < lines; ++s) order[s] = s;
    std::stable_sort(order.begin(), order.end(), [&](Index a, Index c) { return rank_[a] < rank_[c]; });
    std::vector<Incidence> buf;
    Index faces = 0;
    const std::size_t total = 2 * std::size_t(lines);
    std::size_t done = 0;

    // Prefetching: the face of a slot depends on a slot at the same vertex on another line, a cache miss
    // that is known from the link word long before it is needed.
    constexpr Index distance = 16;
    auto prefetch_ahead = [&](Index g, Index last) {
      if(g + distance < last) {
        const Index y = ws[g + distance].target & slot_mask;
        prefetch(ws.data() + y);
        if(y > 0) prefetch(ws.data() + (y - 1));   // the in-edge of y
      }
    };

    // Up pass, by increasing slope: the face above an out-edge is new when a steeper out-edge leaves
    // the same vertex (the wedge between them is born here); otherwise it continues the face above the
    // in-edge of smallest slope at the vertex.
    auto new_face = [&]() {
      if(faces >= unset_face)
        throw std::length_error("MDCS: too many faces for Line_arrangement_2");
      return faces++;
    };
    for(Index s : order) {
      const Index first = slot_offset_[s], last = slot_offset_[s + 1] - 1;
      for(Index g = first; g < last; ++g) {
        prefetch_ahead(g, last);
        const bool g_in = g > first;
        const Index word = ws[g].target;
        Index f = unset_face;
        if(word & pair_bit) {
          const Index y = word & slot_mask;
          const bool y_in = (word & next_in_bit) != 0, y_out = (word & next_out_bit) != 0;
          if(!(word & wrap_bit) && y_out)   // y is steeper and leaves: g is the lower side of a new face
            f = new_face();
          else {
            // The in-edge of smallest slope: [y, g] when g is the steeper, else [g, y].
            const Index l_first = (word & wrap_bit) ? (y_in ? y : (g_in ? g : none)) : (g_in ? g : (y_in ? y : none));
            if(l_first != none) f = ws[l_first - 1].left_face;
          }
        } else {
          const std::size_t a = gather(g, g_in, true, buf);
          bool steeper_out = false;
          for(std::size_t k = a + 1; k < buf.size(); ++k) steeper_out = steeper_out || buf[k].out;
          if(steeper_out)
            f = new_face();
          else
            for(std::size_t k = 0; k < buf.size(); ++k)
              if(buf[k].in) { f = ws[buf[k].slot - 1].left_face; break; }
        }
        if(f != unset_face) {
          CGAL_assertion(ws[g].left_face == unset_face || ws[g].left_face == f);
          ws[g].left_face = f;
        }
        CGAL_assertion(ws[g].left_face != unset_face);
      }
      reporter_(progress_sweep + (++done) * (progress_total - progress_sweep) / (total + 1));
    }
    // Down pass, by decreasing slope: the face below an out-edge is the face above the next out-edge of
    // smaller slope (the wedge between them); without one, it continues the face below the in-edge of
    // largest slope.
    for(std::size_t i = lines; i-- > 0;) {
      const Index s = order[i];
      const Index first = slot_offset_[s], last = slot_offset_[s + 1] - 1;
      for(Index g = first; g < last; ++g) {
        prefetch_ahead(g, last);
        const bool g_in = g > first;
        const Index word = ws[g].target;
        Index f = unset_face;
        if(word & pair_bit) {
          const Index y = word & slot_mask;
          const bool y_in = (word & next_in_bit) != 0, y_out = (word & next_out_bit) != 0;
          if((word & wrap_bit) && y_out)   // y is less steep and leaves
            f = ws[y].left_face;
          else {
            // The in-edge of largest slope: [y, g] when g is the steeper, else [g, y].
            const Index l_last = (word & wrap_bit) ? (g_in ? g : (y_in ? y : none)) : (y_in ? y : (g_in ? g : none));
            if(l_last != none) f = ws[l_last - 1].right_face;
          }
        } else {
          const std::size_t a = gather(g, g_in, true, buf);
          for(std::size_t k = a; k-- > 0;)
            if(buf[k].out) { f = ws[buf[k].slot].left_face; break; }
          if(f == unset_face)
            for(std::size_t k = buf.size(); k-- > 0;)
              if(buf[k].in) { f = ws[buf[k].slot - 1].right_face; break; }
        }
        if(f != unset_face) {
          CGAL_assertion(ws[g].right_face == unset_face || ws[g].right_face == f);
          ws[g].right_face = f;
        }
        CGAL_assertion(ws[g].right_face != unset_face);
      }
      reporter_(progress_sweep + (++done) * (progress_total - progress_sweep) / (total + 1));
    }
    arr_.number_of_faces_ = faces;
  }

  // ------------------------------------------------------------------------------------------------
  // Phase 5: the slot of position k on a line becomes the edge from it to position k + 1. Edges move
  // only to lower indices, so this is done in place.
  void compact()
  {
    std::vector<Edge>& ws = arr_.edges_;
    std::size_t out = 0;
    for(Index s = 0; s < m_ + 4; ++s) {
      std::vector<Index>* wall = nullptr;
      if(s >= m_) {
        const typename Arrangement::Edge_kind kind = ws[slot_offset_[s]].kind;
        wall = &arr_.wall_edges_[std::size_t(kind) - 1];
        wall->clear();
      }
      for(Index g = slot_offset_[s]; g + 1 < slot_offset_[s + 1]; ++g) {
        Edge e = ws[g];
        e.target = ws[g + 1].source;
        if(wall) wall->push_back(Index(out));
        ws[out++] = e;
      }
    }
    ws.resize(out);
    std::vector<Index>().swap(slot_offset_);
    // Euler's formula for the connected plane graph (the walls connect everything): V - E + (F + 1) = 2.
    CGAL_assertion(arr_.points_.size() + arr_.number_of_faces_ == ws.size() + 1);
  }

  Arrangement& arr_;
  CGAL::MDCS::internal::Progress_reporter<Progress> reporter_;

  std::vector<Arr_line> lines_;        // [0, m): usable input lines, then the 4 walls
  std::vector<Index> input_of_;        // input index of lines_[s], s < m
  std::vector<Index> rank_;            // slope rank of lines_[s], s < m + 4
  Index m_ = 0;
  std::size_t boundary_vertices_ = 0;  // the boundary vertices are 0 .. boundary_vertices_ - 1

  std::vector<Index> entry_vertex_, exit_vertex_, entry_wall_, exit_wall_;
  std::vector<double> in_lo_, in_hi_, out_lo_, out_hi_;
  std::array<std::vector<Index>, 4> wall_seq_;
  std::vector<Index> slot_offset_;     // slots of line s (then of the walls): [offset[s], offset[s + 1])
  Points_along_line_sorter sorter_;   // keeps its scratch buffers between lines
};

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_LINE_ARRANGEMENT_CONSTRUCTION_H
