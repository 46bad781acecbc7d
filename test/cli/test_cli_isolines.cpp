// Iso-distance polylines of `mdcs geodesics` (examples/mdcs/geodesic_isolines.h): level sets of the linear
// interpolation, chained across edges into open and closed polylines; bounded by the levels asked for.
#include <catch2/catch.hpp>

#include "geodesic_isolines.h"

#include <cmath>
#include <limits>
#include <vector>

using namespace mdcs_cli;

TEST_CASE("cli isolines: a linear field on a grid gives straight open lines", "[cli][isolines]")
{
  // 3 x 3 grid on [0,1]^2, distance = x.
  std::vector<Geo_vec> points;
  std::vector<double> distance;
  for(int j = 0; j < 3; ++j)
    for(int i = 0; i < 3; ++i) {
      points.push_back({{0.5 * i, 0.5 * j, 0}});
      distance.push_back(0.5 * i);
    }
  std::vector<std::array<std::size_t, 3>> triangles;
  for(std::size_t j = 0; j < 2; ++j)
    for(std::size_t i = 0; i < 2; ++i) {
      const std::size_t a = 3 * j + i, b = a + 1, c = a + 3, d = a + 4;
      triangles.push_back({{a, b, d}});
      triangles.push_back({{a, d, c}});
    }
  const std::vector<Isoline> lines = compute_isolines(points, triangles, distance, 0.25, 1.0, 100);
  // levels 0.25, 0.5, 0.75, 1.0: one open line each, at x = level, from y = 0 to y = 1
  REQUIRE(lines.size() == 4);
  for(const Isoline& l : lines) {
    CHECK_FALSE(l.closed);
    REQUIRE(l.points.size() >= 2);
    double ymin = 1, ymax = 0;
    for(const Geo_vec& p : l.points) {
      CHECK(p[0] == Approx(l.level));
      ymin = std::min(ymin, p[1]);
      ymax = std::max(ymax, p[1]);
    }
    if(l.level < 1) { // the line x = 1 runs along the border, through vertices only
      CHECK(ymin == Approx(0));
      CHECK(ymax == Approx(1));
    }
  }
}

TEST_CASE("cli isolines: a radial field gives a closed loop", "[cli][isolines]")
{
  std::vector<Geo_vec> points = {{{0, 0, 0}}};
  std::vector<double> distance = {0};
  const int ring = 8;
  for(int k = 0; k < ring; ++k) {
    const double t = 2 * 3.14159265358979323846 * k / ring;
    points.push_back({{std::cos(t), std::sin(t), 0}});
    distance.push_back(1);
  }
  std::vector<std::array<std::size_t, 3>> triangles;
  for(std::size_t k = 0; k < ring; ++k) triangles.push_back({{0, 1 + k, 1 + (k + 1) % ring}});
  const std::vector<Isoline> lines = compute_isolines(points, triangles, distance, 0.5, 1.0, 10);
  REQUIRE(lines.size() == 2); // 0.5 (closed) and 1.0 (through the ring vertices)
  CHECK(lines[0].level == 0.5);
  CHECK(lines[0].closed);
  CHECK(lines[0].points.size() == std::size_t(ring));
  for(const Geo_vec& p : lines[0].points) CHECK(std::hypot(p[0], p[1]) == Approx(0.5));
}

TEST_CASE("cli isolines: absurd ranges and unreachable vertices", "[cli][isolines]")
{
  const std::vector<Geo_vec> points = {{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}};
  const std::vector<std::array<std::size_t, 3>> triangles = {{{0, 1, 2}}};
  const double inf = std::numeric_limits<double>::infinity();
  // a face with an unreachable corner draws nothing; no level is computed for non-finite ranges
  CHECK(compute_isolines(points, triangles, {0, 1, inf}, 0.5, 1, 10).empty());
  CHECK(compute_isolines(points, triangles, {0, 1, 1}, 0.5, inf, 10).empty());
  CHECK(compute_isolines(points, triangles, {0, 1, 1}, 0, 1, 10).empty());
  // the largest double with a tiny spacing: the number of levels stays within the bound asked for
  const double big = std::numeric_limits<double>::max();
  const auto lines = compute_isolines(points, triangles, {0, big, big}, 1e-300, big, 5);
  CHECK(lines.size() <= 5);
}
