// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of the line generators: random lines with pencils, and the planar regular grid C_n^pl.

#include <CGAL/Variational_minimization/Line_arrangement_2.h>
#include <CGAL/Variational_minimization/line_grids_2.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <random>
#include <set>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace VM = CGAL::Variational_minimization;

namespace {

typedef VM::Point_2 Grid_point;

bool same_lines(const std::vector<VM::Arrangement_line_2>& a, const std::vector<VM::Arrangement_line_2>& b)
{
  if(a.size() != b.size()) return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(a[i].p != b[i].p || a[i].q != b[i].q) return false;
  return true;
}

// Brute force: the distinct lines through two vertices of adjacent columns of C_n, as primitive integer
// triples (a, b, c) with a col + b row = c in grid units, normalized in sign.
std::size_t brute_force_grid_line_count(long long n)
{
  std::set<std::tuple<long long, long long, long long>> lines;
  const long long rows = n * n;
  for(long long i = 0; i < n; ++i)
    for(long long j = 0; j <= rows; ++j)
      for(long long k = 0; k <= rows; ++k) {
        // Through (i, j) and (i + 1, k): (k - j) col - row = (k - j) i - j.
        long long a = k - j, b = -1, c = (k - j) * i - j;
        long long g = std::gcd(std::gcd(std::abs(a), std::abs(b)), std::abs(c));
        a /= g; b /= g; c /= g;
        if(a < 0 || (a == 0 && b < 0)) { a = -a; b = -b; c = -c; }
        lines.emplace(a, b, c);
      }
  return lines.size();
}

} // namespace

TEST_CASE("random_lines_2: deterministic for a seed", "[Variational_minimization][line_grids]")
{
  const CGAL::Bbox_2 box(-1, 0, 1, 2);
  VM::Random_lines_options options;
  options.pencil_points = { Grid_point(-1, 2), Grid_point(1, 2) };
  const auto a = VM::random_lines_2(box, 500, 42, options);
  const auto b = VM::random_lines_2(box, 500, 42, options);
  const auto c = VM::random_lines_2(box, 500, 43, options);
  REQUIRE(a.size() == 500);
  CHECK(same_lines(a, b));
  CHECK_FALSE(same_lines(a, c));
  // The first line of seed 1 is pinned: the mapping to [0, 1) is ours, so this holds on every platform.
  const auto first = VM::random_lines_2(CGAL::Bbox_2(0, 0, 1, 1), 1, 1);
  std::mt19937_64 rng(1);
  const double x = double(rng() >> 11) * std::ldexp(1.0, -53);
  const double y = double(rng() >> 11) * std::ldexp(1.0, -53);
  CHECK(first[0].p == Grid_point(x, y));
  for(const auto& l : a) {
    CHECK(l.p != l.q);
  }
}

TEST_CASE("random_lines_2: pencils pass exactly through their points", "[Variational_minimization][line_grids]")
{
  const CGAL::Bbox_2 box(-1, 0, 1, 2);
  VM::Random_lines_options options;
  options.pencil_points = { Grid_point(-1, 0.5), Grid_point(1, 1.75), Grid_point(0, 0) };
  options.pencil_fraction = 0.25;
  const std::size_t n = 400;
  const auto lines = VM::random_lines_2(box, n, 7, options);
  REQUIRE(lines.size() == n);
  // 100 pencil lines: 34, 33, 33, after the 300 free ones.
  const std::size_t counts[3] = { 34, 33, 33 };
  std::size_t i = 300;
  for(int k = 0; k < 3; ++k)
    for(std::size_t c = 0; c < counts[k]; ++c, ++i) {
      const Grid_point& center = options.pencil_points[std::size_t(k)];
      CHECK(CGAL::orientation(lines[i].p, lines[i].q, center) == CGAL::COLLINEAR);
      CHECK(VM::internal::meets_open_box(box, lines[i].p, lines[i].q));
    }
  // Every line is used by the arrangement (no pencil line runs along its wall).
  const VM::Line_arrangement_2 arrangement(box, lines);
  for(std::size_t j = 0; j < n; ++j) {
    INFO("line " << j);
    CHECK(arrangement.is_line_used(VM::Line_arrangement_2::Line_index(j)));
  }
  // No pencil at all: all lines are free.
  options.pencil_points.clear();
  CHECK(VM::random_lines_2(box, 10, 7, options).size() == 10);
}

TEST_CASE("random_lines_2: floor and slope limit", "[Variational_minimization][line_grids]")
{
  VM::Random_lines_options options;
  options.include_floor = true;
  const CGAL::Bbox_2 box(0, -1, 1, 1);
  auto lines = VM::random_lines_2(box, 20, 3, options);
  REQUIRE(lines.size() == 21);
  CHECK(lines.back().p == Grid_point(0, 0));
  CHECK(lines.back().q == Grid_point(1, 0));
  // On a box with ymin = 0 the floor line is there, and the arrangement drops it (the wall is the floor).
  const CGAL::Bbox_2 up(0, 0, 1, 1);
  lines = VM::random_lines_2(up, 20, 3, options);
  REQUIRE(lines.size() == 21);
  const VM::Line_arrangement_2 arrangement(up, lines);
  CHECK_FALSE(arrangement.is_line_used(20));
  // Not in the box: not added.
  CHECK(VM::random_lines_2(CGAL::Bbox_2(0, 1, 1, 2), 5, 3, options).size() == 5);

  VM::Random_lines_options flat;
  flat.max_abs_slope = 0.01;
  for(const auto& l : VM::random_lines_2(box, 300, 4, flat)) {
    const double dx = l.q.x() - l.p.x(), dy = l.q.y() - l.p.y();
    CHECK(std::abs(dy) <= 0.01 * std::abs(dx) * (1 + 1e-12));
  }
  // The angle stays uniform within the cone: both signs, and some close to the limit.
  std::size_t positive = 0, steep = 0;
  for(const auto& l : VM::random_lines_2(box, 1000, 5, flat)) {
    const double slope = (l.q.y() - l.p.y()) / (l.q.x() - l.p.x());
    positive += slope > 0;
    steep += std::abs(slope) > 0.009;
  }
  CHECK(positive > 400);
  CHECK(positive < 600);
  CHECK(steep > 50);
}

TEST_CASE("random_lines_2: bad input throws", "[Variational_minimization][line_grids]")
{
  const CGAL::Bbox_2 box(0, 0, 1, 1);
  CHECK_THROWS_AS(VM::random_lines_2(CGAL::Bbox_2(1, 0, 0, 1), 3, 1), std::invalid_argument);
  VM::Random_lines_options options;
  options.pencil_fraction = 1.5;
  CHECK_THROWS_AS(VM::random_lines_2(box, 3, 1, options), std::invalid_argument);
  options.pencil_fraction = 0.5;
  options.max_abs_slope = -1;
  CHECK_THROWS_AS(VM::random_lines_2(box, 3, 1, options), std::invalid_argument);
  options.max_abs_slope = 0;
  options.pencil_points = { Grid_point(2, 0.5) };
  CHECK_THROWS_AS(VM::random_lines_2(box, 3, 1, options), std::invalid_argument);
  CHECK(VM::random_lines_2(box, 0, 1).empty());
}

TEST_CASE("regular_grid_lines_2: line counts against brute force", "[Variational_minimization][line_grids]")
{
  const CGAL::Bbox_2 unit(0, 0, 1, 1);
  const std::size_t expected[] = { 0, 4, 37, 200, 721 };
  for(std::size_t n = 1; n <= 4; ++n) {
    INFO("n = " << n);
    const auto lines = VM::regular_grid_lines_2(unit, n);
    CHECK(lines.size() == expected[n]);
    if(n <= 3) CHECK(lines.size() == brute_force_grid_line_count((long long)n));
  }
  CHECK_THROWS_AS(VM::regular_grid_lines_2(unit, 0), std::invalid_argument);
  CHECK_THROWS_AS(VM::regular_grid_lines_2(CGAL::Bbox_2(0, 0, 0, 1), 2), std::invalid_argument);
  CHECK_THROWS_AS(VM::regular_grid_lines_2(unit, 65), std::length_error);
}

TEST_CASE("regular_grid_lines_2: lines through grid points exactly", "[Variational_minimization][line_grids]")
{
  // On an exact grid, each line passes exactly through every grid point on it (in grid units), and
  // through no other grid point; the lines are distinct.
  for(std::size_t n : { 2, 3, 4 }) {
    INFO("n = " << n);
    const CGAL::Bbox_2 box = n == 3 ? CGAL::Bbox_2(0, 0, 3, 9) : CGAL::Bbox_2(-1, 0, 1, 2);
    const auto lines = VM::regular_grid_lines_2(box, n);
    const std::size_t rows = n * n;
    std::size_t incidences = 0;
    for(const auto& l : lines) {
      REQUIRE(l.p != l.q);
      std::size_t on = 0;
      for(std::size_t i = 0; i <= n; ++i)
        for(std::size_t j = 0; j <= rows; ++j) {
          const Grid_point g(VM::regular_grid_x(box, n, i), VM::regular_grid_y(box, n, j));
          on += CGAL::orientation(l.p, l.q, g) == CGAL::COLLINEAR;
        }
      CHECK(on >= 2);
      incidences += on;
    }
    // Each line passes through at least one grid point per column it spans (two at least), and the
    // grid points on it are exactly those of its key in grid units.
    CHECK(incidences >= 2 * lines.size());
    const VM::Line_arrangement_2 arrangement(box, lines);
    // All but the floor and the ceiling lines are used; no duplicates.
    std::size_t used = 0;
    for(std::size_t i = 0; i < lines.size(); ++i) used += arrangement.is_line_used(VM::Line_arrangement_2::Line_index(i));
    CHECK(used == lines.size() - 2);
    // Every grid point is a vertex.
    std::set<std::pair<double, double>> vertices;
    for(std::size_t v = 0; v < arrangement.number_of_vertices(); ++v) {
      const auto& p = arrangement.point(VM::Line_arrangement_2::Vertex_index(v));
      vertices.emplace(p.x(), p.y());
    }
    for(std::size_t i = 0; i <= n; ++i)
      for(std::size_t j = 0; j <= rows; ++j)
        CHECK(vertices.count(std::make_pair(VM::regular_grid_x(box, n, i), VM::regular_grid_y(box, n, j))) == 1);
  }
}
