// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Line sets for Line_arrangement_2: random lines (with pencils through given points) and the planar
// regular grid C_n^pl.

#ifndef CGAL_VARIATIONAL_MINIMIZATION_LINE_GRIDS_2_H
#define CGAL_VARIATIONAL_MINIMIZATION_LINE_GRIDS_2_H

#include <CGAL/Variational_minimization/Line_arrangement_2.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/*!
  \ingroup PkgVariationalMinimizationGrid
  Options of `random_lines_2()`.
*/
struct Random_lines_options
{
  /// Points of the closed box through which pencils of lines pass exactly (for example the boundary
  /// points (a, A) and (b, B) of a curve problem).
  std::vector<Point_2> pencil_points;
  /// The fraction of the n lines that go into the pencils, split evenly among `pencil_points`
  /// (ignored when there are none).
  double pencil_fraction = 0.1;
  /// Add the line f = 0, that is y = 0 through (xmin, 0) and (xmax, 0), after the n lines, when
  /// ymin <= 0 <= ymax. When ymin == 0 (or ymax == 0) it lies on a wall and `Line_arrangement_2` drops it:
  /// the floor is then already made of wall edges.
  bool include_floor = false;
  /// Limit on |slope| of the random directions; 0 means unlimited. The angle stays uniform within the
  /// allowed cone.
  double max_abs_slope = 0;
};

namespace internal {

// Uniform double in [0, 1) from the top 53 bits; the same on every platform (std::uniform_real_distribution
// is not specified bit for bit).
inline double unit_random(std::mt19937_64& rng) { return double(rng() >> 11) * (1.0 / 9007199254740992.0); }

inline void check_generator_box(const CGAL::Bbox_2& box, const char* who)
{
  if(!(std::isfinite(box.xmin()) && std::isfinite(box.xmax()) && std::isfinite(box.ymin()) &&
       std::isfinite(box.ymax())) ||
     !(box.xmin() < box.xmax()) || !(box.ymin() < box.ymax()))
    throw std::invalid_argument(std::string("MDCS: ") + who +
                                ": the box must be finite with xmin < xmax and ymin < ymax");
}

// A direction (a, b) with a >= 0, uniform in angle within |b| <= max_abs_slope * a (all directions if 0):
// rejection sampling in the half disk, which uses only exactly rounded arithmetic.
inline std::pair<double, double> random_direction(std::mt19937_64& rng, double max_abs_slope)
{
  const double h = (max_abs_slope == 0 || max_abs_slope >= 1) ? 1.0 : max_abs_slope;
  for(;;) {
    const double a = unit_random(rng);
    const double b = h * (2 * unit_random(rng) - 1);
    const double r2 = a * a + b * b;
    if(r2 > 1 || r2 < 0.01) continue;   // the lower bound keeps q well away from p
    if(max_abs_slope != 0 && std::abs(b) > max_abs_slope * a) continue;
    return std::make_pair(a, b);
  }
}

// Whether the line through p and q meets the open box (two corners strictly on opposite sides); exact.
inline bool meets_open_box(const CGAL::Bbox_2& box, const Point_2& p, const Point_2& q)
{
  const Point_2 corner[4] = { Point_2(box.xmin(), box.ymin()), Point_2(box.xmax(), box.ymin()),
                              Point_2(box.xmax(), box.ymax()), Point_2(box.xmin(), box.ymax()) };
  bool pos = false, neg = false;
  for(const Point_2& c : corner) {
    const CGAL::Orientation o = CGAL::orientation(p, q, c);
    pos = pos || o == CGAL::LEFT_TURN;
    neg = neg || o == CGAL::RIGHT_TURN;
  }
  return pos && neg;
}

} // namespace internal

/// \ingroup PkgVariationalMinimizationGrid
/// The most lines `random_lines_2()` draws: 2^16 (the list of lines it sizes would otherwise be as large as asked).
inline std::size_t max_random_lines_2() { return std::size_t(1) << 16; }

/*!
  \ingroup PkgVariationalMinimizationGrid
  `n` random lines for `Line_arrangement_2`: each through a uniform random point of the box with a
  uniformly random direction (`q = p + L (a, b)`, L the box half-perimeter). A fraction
  `options.pencil_fraction` of them is split evenly among pencils through `options.pencil_points`: such a
  line has `p` equal to the pencil point, so it passes exactly through it, and its direction is drawn
  again until the line meets the open box (so never along the wall the point lies on, and never through
  a corner only). The pencil lines come after the free ones, the floor (see `Random_lines_options`) last.

  The result depends only on `seed` (std::mt19937_64 with our own mapping to [0, 1)).

  At most `max_random_lines_2()` lines: the arrangement of n random lines has about n^2 / 2 crossings, and
  `Line_arrangement_2` holds at most 2^28 edges, which runs out far below that count.

  \throws std::invalid_argument on a bad box, `n > max_random_lines_2()`, a pencil fraction outside [0, 1], a
  negative or non-finite `max_abs_slope`, or a pencil point outside the closed box.
*/
inline std::vector<Arrangement_line_2> random_lines_2(const CGAL::Bbox_2& box, std::size_t n, std::uint64_t seed,
                                                      const Random_lines_options& options = Random_lines_options())
{
  internal::check_generator_box(box, "random_lines_2");
  if(n > max_random_lines_2())
    throw std::invalid_argument("MDCS: random_lines_2: " + std::to_string(n) + " lines requested; at most " +
                                std::to_string(max_random_lines_2()) + " (their arrangement would exceed the 2^28 "
                                "edges of Line_arrangement_2: about n^2 / 2 crossings)");
  if(!(options.pencil_fraction >= 0 && options.pencil_fraction <= 1))
    throw std::invalid_argument("MDCS: random_lines_2: pencil_fraction must lie in [0, 1]");
  if(!(options.max_abs_slope >= 0) || !std::isfinite(options.max_abs_slope))
    throw std::invalid_argument("MDCS: random_lines_2: max_abs_slope must be finite and >= 0 (0 = unlimited)");
  for(const Point_2& c : options.pencil_points)
    if(!(c.x() >= box.xmin() && c.x() <= box.xmax() && c.y() >= box.ymin() && c.y() <= box.ymax()))
      throw std::invalid_argument("MDCS: random_lines_2: pencil points must lie in the closed box");

  std::mt19937_64 rng(seed);
  const double w = box.xmax() - box.xmin(), h = box.ymax() - box.ymin();
  const double length = w + h;
  const std::size_t n_pencil =
    options.pencil_points.empty() ? 0 : (std::min)(n, std::size_t(std::llround(options.pencil_fraction * double(n))));

  std::vector<Arrangement_line_2> lines;
  lines.reserve(n + 1);
  // A point in the closed box; rounding of xmin + u w may reach xmax, never beyond after the clamp.
  auto random_point = [&]() {
    const double x = (std::min)(box.xmin() + internal::unit_random(rng) * w, box.xmax());
    const double y = (std::min)(box.ymin() + internal::unit_random(rng) * h, box.ymax());
    return Point_2(x, y);
  };
  auto line_through = [&](const Point_2& p, bool must_meet_box) {
    // Bounded retries: for a point in the closed box more than half of all directions work, so failing
    // 10000 times in a row only happens for degenerate data (e.g. a box too far from the origin for
    // p + L (a, b) to differ from p).
    for(int attempt = 0; attempt < 10000; ++attempt) {
      const std::pair<double, double> d = internal::random_direction(rng, options.max_abs_slope);
      const Point_2 q(p.x() + length * d.first, p.y() + length * d.second);
      if(q == p) continue;
      if(must_meet_box && !internal::meets_open_box(box, p, q)) continue;
      return Arrangement_line_2{ p, q };
    }
    throw std::invalid_argument("MDCS: random_lines_2: cannot draw a line through a point of this box");
  };

  for(std::size_t i = 0; i + n_pencil < n; ++i)
    lines.push_back(line_through(random_point(), false));
  const std::size_t np = options.pencil_points.size();
  for(std::size_t k = 0; k < np; ++k) {
    const std::size_t count = n_pencil / np + (k < n_pencil % np ? 1 : 0);
    for(std::size_t i = 0; i < count; ++i)
      lines.push_back(line_through(options.pencil_points[k], true));
  }
  if(options.include_floor && box.ymin() <= 0 && box.ymax() >= 0)
    lines.push_back(Arrangement_line_2{ Point_2(box.xmin(), 0), Point_2(box.xmax(), 0) });
  return lines;
}

/// The x coordinate of column `i` of the regular grid C_n on `box` (i = 0..n): exactly xmin and xmax at
/// the ends, `xmin + (i (xmax - xmin)) / n` in between.
inline double regular_grid_x(const CGAL::Bbox_2& box, std::size_t n, std::size_t i)
{
  if(i == 0) return box.xmin();
  if(i >= n) return box.xmax();
  return box.xmin() + (double(i) * (box.xmax() - box.xmin())) / double(n);
}

/// The y coordinate of row `j` of C_n (j = 0..n^2): `ymin + (j (ymax - ymin)) / n^2`, exact at the ends.
inline double regular_grid_y(const CGAL::Bbox_2& box, std::size_t n, std::size_t j)
{
  const std::size_t rows = n * n;
  if(j == 0) return box.ymin();
  if(j >= rows) return box.ymax();
  return box.ymin() + (double(j) * (box.ymax() - box.ymin())) / double(rows);
}

/*!
  \ingroup PkgVariationalMinimizationGrid
  The lines of C_n^pl: every line through an edge of the regular grid C_n, which has n + 1 columns
  `regular_grid_x(box, n, i)` and n^2 + 1 rows `regular_grid_y(box, n, j)`, with an edge between any two
  vertices of adjacent columns.

  In grid units a line is row = c + Δ col with integers Δ = k - j and c = j - Δ i, so lines are
  deduplicated exactly on (Δ, c); they come sorted by (Δ, c). Each line is defined by its grid points in
  the first and the last column where it stays within the rows, so it passes exactly through these two
  grid points. It passes exactly through all its grid points when the grid coordinates are exact, e.g. a
  dyadic box with n a power of two, or the box [0, n] x [0, n^2]; otherwise the other grid points are
  only within rounding of the line, and the arrangement (still exact for the given lines) has clusters of
  nearby vertices instead of one vertex per grid point.

  The count grows like n^5: 4 lines for n = 1, 37 for n = 2, 200 for n = 3, 721 for n = 4,
  2028 for n = 5, 4789 for n = 6. The two lines on the floor and the ceiling are among them; `Line_arrangement_2` drops
  them (the walls are there).

  \throws std::invalid_argument for n == 0 or a bad box, std::length_error for n > 64.
*/
inline std::vector<Arrangement_line_2> regular_grid_lines_2(const CGAL::Bbox_2& box, std::size_t n)
{
  internal::check_generator_box(box, "regular_grid_lines_2");
  if(n == 0)
    throw std::invalid_argument("MDCS: regular_grid_lines_2: n must be at least 1");
  if(n > 64)
    throw std::length_error("MDCS: regular_grid_lines_2: n is too large (the line count grows like n^5)");
  const long long cols = (long long)(n), rows = cols * cols;
  // Key (Δ, c): the line row = c + Δ col. The edges (i, j) -> (i + 1, j + Δ) of one column i give the
  // consecutive range c = j - Δ i, j in [max(0, -Δ), min(rows, rows - Δ)]; merging these ranges over
  // the columns lists every line once, already sorted.
  std::vector<std::pair<long long, long long>> keys;
  std::vector<std::pair<long long, long long>> ranges;
  for(long long delta = -rows; delta <= rows; ++delta) {
    const long long jlo = (std::max)(0LL, -delta), jhi = (std::min)(rows, rows - delta);
    ranges.clear();
    for(long long i = 0; i < cols; ++i)
      ranges.emplace_back(jlo - delta * i, jhi - delta * i);
    std::sort(ranges.begin(), ranges.end());
    long long next = (std::numeric_limits<long long>::min)();
    for(const auto& r : ranges)
      for(long long c = (std::max)(r.first, next); c <= r.second; ++c)
        keys.emplace_back(delta, c), next = c + 1;
  }

  std::vector<Arrangement_line_2> lines;
  lines.reserve(keys.size());
  for(const auto& key : keys) {
    const long long delta = key.first, c = key.second;
    long long first = -1, last = -1;
    for(long long i = 0; i <= cols; ++i) {
      const long long r = c + delta * i;
      if(r >= 0 && r <= rows) {
        if(first < 0) first = i;
        last = i;
      }
    }
    const Point_2 p(regular_grid_x(box, n, std::size_t(first)), regular_grid_y(box, n, std::size_t(c + delta * first)));
    const Point_2 q(regular_grid_x(box, n, std::size_t(last)), regular_grid_y(box, n, std::size_t(c + delta * last)));
    lines.push_back(Arrangement_line_2{ p, q });
  }
  return lines;
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_LINE_GRIDS_2_H
