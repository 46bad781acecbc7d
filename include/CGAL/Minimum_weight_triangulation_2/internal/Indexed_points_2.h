// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The input points with double coordinates (for grids and weights), the kernel's exact orientation
// predicate on indices, and a uniform grid for range queries.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_INDEXED_POINTS_2_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_INDEXED_POINTS_2_H

#include <CGAL/number_utils.h>
#include <CGAL/enum.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Hilbert_sort_base.h>
#include <CGAL/Hilbert_sort_median_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Parallel_stage_2.h>
#include <CGAL/property_map.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {
namespace internal {

template <class K>
class Indexed_points_2
{
public:
  typedef typename K::Point_2 Point_2;

  Indexed_points_2(const std::vector<Point_2>& p, const K& k = K())
    : points_(p), orientation_(k.orientation_2_object())
  {
    // with double coordinates (EPICK) the points are read directly (no copy: 16 bytes per point less)
    if(!direct) {
      x_.resize(p.size());
      y_.resize(p.size());
      for(std::size_t i = 0; i < p.size(); ++i) {
        x_[i] = CGAL::to_double(p[i].x());
        y_[i] = CGAL::to_double(p[i].y());
      }
    }
    exact_doubles_ = direct;
  }

  std::size_t size() const { return points_.size(); }
  double x(int i) const
  {
    if constexpr(direct) return points_[std::size_t(i)].x();
    else return x_[std::size_t(i)];
  }
  double y(int i) const
  {
    if constexpr(direct) return points_[std::size_t(i)].y();
    else return y_[std::size_t(i)];
  }
  const Point_2& point(int i) const { return points_[i]; }
  /// Whether x(i), y(i) are the kernel's coordinates exactly (then static filters on them are exact).
  bool has_exact_doubles() const { return exact_doubles_; }

  /// Exact sign of the orientation of (a, b, c): +1 left turn, -1 right turn, 0 collinear.
  int orientation(int a, int b, int c) const
  {
    if(exact_doubles_) {
      // Shewchuk's static filter (ccwerrboundA) on the double coordinates, which are the input's exactly
      const double l = (x(a) - x(c)) * (y(b) - y(c)), r = (y(a) - y(c)) * (x(b) - x(c));
      // (bound > 1e-300: an underflowed product's error, below 1e-323, is then covered; inf/NaN fall through)
      const double det = l - r, bound = 3.3306690738754716e-16 * (std::abs(l) + std::abs(r));
      if(bound > 1e-300) {
        if(det > bound) return 1;
        if(-det > bound) return -1;
      }
    }
    const CGAL::Orientation o = orientation_(points_[a], points_[b], points_[c]);
    return o == CGAL::LEFT_TURN ? 1 : (o == CGAL::RIGHT_TURN ? -1 : 0);
  }

  /// Same as orientation(a, b, c), with the coordinates (cx, cy) of c given (read from a grid cell).
  int orientation(int a, int b, int c, double cx, double cy) const
  {
    if(exact_doubles_) {
      const double l = (x(a) - cx) * (y(b) - cy), r = (y(a) - cy) * (x(b) - cx);
      const double det = l - r, bound = 3.3306690738754716e-16 * (std::abs(l) + std::abs(r));
      if(bound > 1e-300) {
        if(det > bound) return 1;
        if(-det > bound) return -1;
      }
    }
    return orientation(a, b, c);
  }

  /// Exact: c lies strictly inside the segment ab (a != b).
  bool strictly_between(int a, int b, int c) const
  {
    if(orientation(a, b, c) != 0) return false;
    const Point_2 &A = points_[a], &B = points_[b], &C = points_[c];
    if(A.x() != B.x())
      return (A.x() < C.x() && C.x() < B.x()) || (B.x() < C.x() && C.x() < A.x());
    return (A.y() < C.y() && C.y() < B.y()) || (B.y() < C.y() && C.y() < A.y());
  }

private:
  const std::vector<Point_2>& points_;
  typename K::Orientation_2 orientation_;
  static constexpr bool direct = std::is_same<typename K::FT, double>::value;
  std::vector<double> x_, y_;   // the coordinates as doubles when the kernel's are not doubles
  bool exact_doubles_ = false;   // the kernel's coordinates are these doubles (then a static filter is exact)
};

// CGAL's median Hilbert sort at run-time orientation: one split of [b, e) by coordinate x (0: x, 1: y), up or down
template <class Traits, class It>
It hilbert_split_at(const Traits& k, It b, It e, int x, bool up)
{
  switch(2 * x + (up ? 1 : 0)) {
    case 0: return CGAL::internal::hilbert_split(b, e, CGAL::internal::Hilbert_cmp_2<Traits, 0, false>(k));
    case 1: return CGAL::internal::hilbert_split(b, e, CGAL::internal::Hilbert_cmp_2<Traits, 0, true>(k));
    case 2: return CGAL::internal::hilbert_split(b, e, CGAL::internal::Hilbert_cmp_2<Traits, 1, false>(k));
    default: return CGAL::internal::hilbert_split(b, e, CGAL::internal::Hilbert_cmp_2<Traits, 1, true>(k));
  }
}

// ... and the sort of a whole subtree (CGAL's recursive_sort<x, upx, upy>)
template <class Sorter, class It>
void hilbert_subtree(const Sorter& sorter, It b, It e, int x, bool upx, bool upy)
{
  switch(4 * x + (upx ? 2 : 0) + (upy ? 1 : 0)) {
    case 0: sorter.template recursive_sort<0, false, false>(b, e); break;
    case 1: sorter.template recursive_sort<0, false, true>(b, e); break;
    case 2: sorter.template recursive_sort<0, true, false>(b, e); break;
    case 3: sorter.template recursive_sort<0, true, true>(b, e); break;
    case 4: sorter.template recursive_sort<1, false, false>(b, e); break;
    case 5: sorter.template recursive_sort<1, false, true>(b, e); break;
    case 6: sorter.template recursive_sort<1, true, false>(b, e); break;
    default: sorter.template recursive_sort<1, true, true>(b, e); break;
  }
}

/// Indices of the points in Hilbert-curve order (CGAL::hilbert_sort, median policy): neighbours in the plane
/// get close indices. Throws std::invalid_argument on a non-finite coordinate. In parallel (`par`): the first
/// levels of CGAL's recursion breadth-first (the splits of a level's sub-squares in parallel), then the
/// sub-squares' own recursions in parallel; the same splits in the same order, so the same order as CGAL's
/// sequential sort for every thread count.
template <class Point_2>
std::vector<int> hilbert_order(const std::vector<Point_2>& p, const Parallel_stage& par = Parallel_stage())
{
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel K;
  typedef CGAL::Spatial_sort_traits_adapter_2<K, typename CGAL::Pointer_property_map<Point_2>::const_type> Traits;
  for(std::size_t i = 0; i < p.size(); ++i)
    if(!std::isfinite(CGAL::to_double(p[i].x())) || !std::isfinite(CGAL::to_double(p[i].y())))
      throw std::invalid_argument("minimum_weight_triangulation_2: point " + std::to_string(i) + " has a non-finite coordinate");
  std::vector<int> order(p.size());
  for(std::size_t i = 0; i < p.size(); ++i) order[i] = int(i);
  if(p.empty()) return order;
  const Traits traits(CGAL::make_property_map(p));
  typedef CGAL::Hilbert_sort_median_2<Traits, CGAL::Sequential_tag> Sorter;
  const Sorter sort(traits);
  if(p.size() < 1 << 15) {
    sort(order.begin(), order.end());
    return order;
  }
  typedef std::vector<int>::iterator It;
  struct Frame { std::ptrdiff_t b, e; int x; bool upx, upy; };
  std::vector<Frame> level{Frame{0, std::ptrdiff_t(p.size()), 0, false, false}};
  // (the first two levels, one and four sub-squares, count as serial work in the statistics)
  const Parallel_stage untimed = par.timed(nullptr);
  while(level.size() < 256) {
    std::vector<Frame> next(4 * level.size());
    (level.size() < 16 ? untimed : par).for_blocks(level.size(), 1, [&](std::size_t i, std::size_t, std::size_t) {
      const Frame f = level[i];
      const int x = f.x, y = 1 - f.x;
      const It m0 = order.begin() + f.b, m4 = order.begin() + f.e;
      It m1 = m0, m2 = m0, m3 = m0;
      if(f.e - f.b > 1) {   // CGAL's recursive_sort stops at one point
        m2 = hilbert_split_at(traits, m0, m4, x, f.upx);
        m1 = hilbert_split_at(traits, m0, m2, y, f.upy);
        m3 = hilbert_split_at(traits, m2, m4, y, !f.upy);
      } else {
        m1 = m2 = m3 = m4;
      }
      auto at = [&](It it) { return std::ptrdiff_t(it - order.begin()); };
      next[4 * i] = Frame{at(m0), at(m1), y, f.upy, f.upx};
      next[4 * i + 1] = Frame{at(m1), at(m2), x, f.upx, f.upy};
      next[4 * i + 2] = Frame{at(m2), at(m3), x, f.upx, f.upy};
      next[4 * i + 3] = Frame{at(m3), at(m4), y, !f.upy, !f.upx};
    });
    level.swap(next);
  }
  par.for_blocks(level.size(), 1, [&](std::size_t i, std::size_t, std::size_t) {
    const Frame& f = level[i];
    hilbert_subtree(sort, order.begin() + f.b, order.begin() + f.e, f.x, f.upx, f.upy);
  });
  return order;
}

/// A uniform grid over the points' bounding box with about `per_cell` points per cell.
class Point_grid_2
{
public:
  template <class Points>
  Point_grid_2(const Points& P, double per_cell = 2.0)
  {
    const std::size_t n = P.size();
    xmin_ = ymin_ = HUGE_VAL;
    double xmax = -HUGE_VAL, ymax = -HUGE_VAL;
    for(std::size_t i = 0; i < n; ++i) {
      xmin_ = std::min(xmin_, P.x(int(i))); xmax = std::max(xmax, P.x(int(i)));
      ymin_ = std::min(ymin_, P.y(int(i))); ymax = std::max(ymax, P.y(int(i)));
    }
    const double w = std::max(xmax - xmin_, 1e-300), h = std::max(ymax - ymin_, 1e-300);
    const double cells = std::max(1.0, double(n) / per_cell);
    cell_ = std::sqrt(w * h / cells);
    if(!(cell_ > 0) || !std::isfinite(cell_)) cell_ = std::max(w, h);
    cell_ = std::max(cell_, std::max(w, h) / 4096.0);
    nx_ = std::max(1, std::min(4096, int(w / cell_) + 1));
    ny_ = std::max(1, std::min(4096, int(h / cell_) + 1));
    start_.assign(std::size_t(nx_) * ny_ + 1, 0);
    std::vector<int> cell_of(n);
    for(std::size_t i = 0; i < n; ++i) {
      cell_of[i] = cx(P.x(int(i))) + nx_ * cy(P.y(int(i)));
      ++start_[cell_of[i] + 1];
    }
    for(std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    items_.resize(n);
    xs_.resize(n);
    ys_.resize(n);
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for(std::size_t i = 0; i < n; ++i) {
      const int k = fill[cell_of[i]]++;
      items_[k] = int(i);
      xs_[k] = P.x(int(i));
      ys_[k] = P.y(int(i));
    }
  }

  int cx(double x) const { return std::max(0, std::min(nx_ - 1, int(std::floor((x - xmin_) / cell_)))); }
  int cy(double y) const { return std::max(0, std::min(ny_ - 1, int(std::floor((y - ymin_) / cell_)))); }
  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double cell_size() const { return cell_; }
  double x0() const { return xmin_; }
  double y0() const { return ymin_; }
  const int* begin(int i, int j) const { return items_.data() + start_[i + nx_ * j]; }
  const int* end(int i, int j) const { return items_.data() + start_[i + nx_ * j + 1]; }
  /// Position of the first item of cell (i, j) (first(i + 1, j) is one past its last); the item at a position
  /// and its coordinates.
  int first(int i, int j) const { return start_[i + nx_ * j]; }
  int item(int k) const { return items_[k]; }
  double item_x(int k) const { return xs_[k]; }
  double item_y(int k) const { return ys_[k]; }

  /// Calls f(point index) for the points of the cells meeting the box (slightly enlarged); stops when f returns true.
  template <class F>
  bool any_in_box(double x0, double y0, double x1, double y1, F f) const
  {
    const double pad = 1e-9 * cell_;
    const int i0 = cx(x0 - pad), i1 = cx(x1 + pad), j0 = cy(y0 - pad), j1 = cy(y1 + pad);
    for(int j = j0; j <= j1; ++j)
      for(int i = i0; i <= i1; ++i)
        for(const int* it = begin(i, j); it != end(i, j); ++it)
          if(f(*it)) return true;
    return false;
  }

  /// As any_in_box, calling f(point index, x, y) with the coordinates stored in the cell.
  template <class F>
  bool any_in_box_xy(double x0, double y0, double x1, double y1, F f) const
  {
    const double pad = 1e-9 * cell_;
    const int i0 = cx(x0 - pad), i1 = cx(x1 + pad), j0 = cy(y0 - pad), j1 = cy(y1 + pad);
    for(int j = j0; j <= j1; ++j) {
      const int k1 = start_[i1 + nx_ * j + 1];
      for(int k = start_[i0 + nx_ * j]; k < k1; ++k)   // the cells i0..i1 of row j are consecutive
        if(f(items_[k], xs_[k], ys_[k])) return true;
    }
    return false;
  }

private:
  double xmin_, ymin_, cell_;
  int nx_, ny_;
  std::vector<int> start_, items_;
  std::vector<double> xs_, ys_;   // coordinates of items_
};

} // namespace internal
} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_INDEXED_POINTS_2_H
