// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// simple_polygon_mwt_2(): the MWT of a simple polygon (an interior face of a planar straight-line graph) against
// brute force over every triangulation of small polygons (n <= 9: all sets of n - 3 pairwise non-crossing
// diagonals, the diagonals found by an independent test: the midpoint inside by CGAL::Polygon_2, no boundary point
// on the open segment), the Catalan count on convex polygons, convex_polygon_mwt_2() on convex polygons, and the
// refusals (clockwise, self-crossing, repeated vertex); planar_graph_face_mwt_2() on a face given by graph indices.

#include "mwt_test_helpers.h"

#include <CGAL/Minimum_weight_triangulation_2/simple_polygon_mwt_2.h>
#include <CGAL/Polygon_2.h>

#include <catch2/catch.hpp>

#include <random>

using namespace mwt_test;

namespace {

// The diagonals of the simple polygon p, tested independently of the library: the open segment meets no vertex and
// crosses no edge, and its midpoint is inside.
std::vector<std::pair<int, int>> spm_diagonals(const std::vector<Point>& p)
{
  const int n = int(p.size());
  const CGAL::Polygon_2<K> poly(p.begin(), p.end());
  std::vector<std::pair<int, int>> d;
  for(int a = 0; a < n; ++a)
    for(int b = a + 2; b < n; ++b) {
      if(a == 0 && b == n - 1) continue;
      const K::Segment_2 s(p[a], p[b]);
      bool ok = poly.bounded_side(CGAL::midpoint(p[a], p[b])) == CGAL::ON_BOUNDED_SIDE;
      for(int c = 0; ok && c < n; ++c) {
        if(c != a && c != b && s.has_on(p[c])) ok = false;
        const int e = (c + 1) % n;
        if(c == a || c == b || e == a || e == b) continue;
        if(CGAL::do_intersect(s, K::Segment_2(p[c], p[e]))) ok = false;
      }
      if(ok) d.emplace_back(a, b);
    }
  return d;
}

bool spm_cross(const std::vector<Point>& p, const std::pair<int, int>& u, const std::pair<int, int>& v)
{
  if(u.first == v.first || u.first == v.second || u.second == v.first || u.second == v.second) return false;
  return CGAL::do_intersect(K::Segment_2(p[u.first], p[u.second]), K::Segment_2(p[v.first], p[v.second]));
}

// The minimum weight over every triangulation (sets of n - 3 pairwise non-crossing diagonals), and their number.
std::pair<double, long> spm_brute_force(const std::vector<Point>& p)
{
  const auto d = spm_diagonals(p);
  const int n = int(p.size()), need = n - 3;
  double perimeter = 0;
  for(int i = 0; i < n; ++i) perimeter += length(p[i], p[(i + 1) % n]);
  double best = std::numeric_limits<double>::infinity();
  long count = 0;
  std::vector<int> chosen;
  std::function<void(std::size_t, double)> rec = [&](std::size_t next, double w) {
    if(int(chosen.size()) == need) {
      ++count;
      best = std::min(best, perimeter + w);
      return;
    }
    for(std::size_t i = next; i < d.size(); ++i) {
      bool free = true;
      for(int c : chosen) free = free && !spm_cross(p, d[std::size_t(c)], d[i]);
      if(!free) continue;
      chosen.push_back(int(i));
      rec(i + 1, w + length(p[d[i].first], p[d[i].second]));
      chosen.pop_back();
    }
  };
  rec(0, 0);
  return {best, count};
}

// A random simple polygon: random radii at random angles around the origin, one angle in each n-th of the turn
// (so consecutive angles differ by less than pi: star-shaped around the origin, simple), counter-clockwise.
std::vector<Point> spm_random_star(int n, std::mt19937& g)
{
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> a;
  for(int i = 0; i < n; ++i) a.push_back(2 * M_PI * (i + u(g)) / n);
  std::vector<Point> p;
  for(double x : a) {
    const double r = 0.2 + u(g);
    p.emplace_back(r * std::cos(x), r * std::sin(x));
  }
  return p;
}

// Checks the triangles: n - 2 counter-clockwise triangles over the polygon's vertices whose areas add up to the
// polygon's, and the weight (boundary once, each diagonal once) equal to the returned one.
void spm_check_triangles(const std::vector<Point>& p, const std::vector<std::array<int, 3>>& tri, double weight)
{
  REQUIRE(tri.size() == p.size() - 2);
  const CGAL::Polygon_2<K> poly(p.begin(), p.end());
  double area = 0;
  for(const auto& t : tri) {
    CHECK(CGAL::orientation(p[t[0]], p[t[1]], p[t[2]]) == CGAL::LEFT_TURN);
    area += CGAL::area(p[t[0]], p[t[1]], p[t[2]]);
  }
  CHECK(area == Approx(poly.area()).epsilon(1e-12));
  CHECK(edge_weight(p, tri) == Approx(weight).epsilon(1e-12));
}

} // namespace

TEST_CASE("simple_polygon_mwt_2: brute force over every triangulation of small polygons", "[mwt][simple_polygon]")
{
  std::mt19937 g(2026);
  int polygons = 0, reflex = 0;
  for(int n = 4; n <= 9; ++n)
    for(int rep = 0; rep < 12; ++rep) {
      const auto p = spm_random_star(n, g); // simple: star-shaped around the origin
      ++polygons;
      bool convex = true;
      for(int i = 0; i < n; ++i) convex = convex && CGAL::left_turn(p[i], p[(i + 1) % n], p[(i + 2) % n]);
      reflex += !convex;
      std::vector<std::array<int, 3>> tri;
      const double w = MWT::simple_polygon_mwt_2(p, std::back_inserter(tri));
      const auto bf = spm_brute_force(p);
      INFO("n " << n << " rep " << rep << " triangulations " << bf.second);
      REQUIRE(bf.second >= 1);
      CHECK(w == Approx(bf.first).epsilon(1e-12));
      spm_check_triangles(p, tri, w);
    }
  CHECK(polygons == 72);
  CHECK(reflex >= 50); // most have a reflex vertex
  // an L-shaped and a comb-shaped polygon (reflex vertices, collinear vertices along the edges)
  const std::vector<std::vector<Point>> shapes = {
    {Point(0, 0), Point(2, 0), Point(2, 1), Point(1, 1), Point(1, 2), Point(0, 2)},
    {Point(0, 0), Point(1, 0), Point(2, 0), Point(2, 1), Point(1, 1), Point(1, 2), Point(0, 2), Point(0, 1)},
    {Point(0, 0), Point(4, 0), Point(4, 2), Point(3, 2), Point(3, 1), Point(2, 1), Point(2, 2), Point(1, 2), Point(1, 1)},
  };
  for(const auto& p : shapes) {
    std::vector<std::array<int, 3>> tri;
    const double w = MWT::simple_polygon_mwt_2(p, std::back_inserter(tri));
    CHECK(w == Approx(spm_brute_force(p).first).epsilon(1e-12));
    spm_check_triangles(p, tri, w);
  }
}

TEST_CASE("simple_polygon_mwt_2: convex polygons as convex_polygon_mwt_2, Catalan many triangulations",
          "[mwt][simple_polygon]")
{
  std::mt19937 g(7);
  const long catalan[] = {1, 1, 2, 5, 14, 42, 132, 429};
  for(int n = 3; n <= 9; ++n) {
    std::vector<Point> p;
    for(int i = 0; i < n; ++i) {
      const double a = 2 * M_PI * (i + 0.3 * std::uniform_real_distribution<double>(0, 1)(g)) / n;
      p.emplace_back(std::cos(a), std::sin(a));
    }
    const auto bf = spm_brute_force(p);
    CHECK(bf.second == catalan[n - 2]);
    std::vector<std::array<int, 3>> a, b;
    const double wa = MWT::simple_polygon_mwt_2(p, std::back_inserter(a));
    const double wb = MWT::convex_polygon_mwt_2(p, std::back_inserter(b));
    CHECK(wa == wb);
    CHECK(a == b);
    CHECK(wa == Approx(bf.first).epsilon(1e-12));
  }
  // larger convex polygons (no brute force): the same triangles and weight as the convex program, exact decisions
  // on the regular polygon (every candidate ties by symmetry)
  for(int n : {12, 25, 60}) {
    std::vector<Point> p;
    for(int i = 0; i < n; ++i) p.emplace_back(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n));
    std::vector<std::array<int, 3>> a, b;
    std::size_t ea = 0, eb = 0;
    const double wa = MWT::simple_polygon_mwt_2(p, std::back_inserter(a), MWT::Edge_metric::L2, &ea);
    const double wb = MWT::convex_polygon_mwt_2(p, std::back_inserter(b), MWT::Edge_metric::L2, &eb);
    CHECK(wa == wb);
    CHECK(a == b);
    CHECK(ea == eb);
  }
}

TEST_CASE("planar_graph_face_mwt_2: a face given by indices, in either orientation", "[mwt][simple_polygon]")
{
  // the graph's vertices: a comb-shaped face's boundary shuffled among other points of the graph (outside it)
  const std::vector<Point> comb = {Point(0, 0), Point(4, 0), Point(4, 2), Point(3, 2), Point(3, 1),
                                   Point(2, 1), Point(2, 2), Point(1, 2), Point(1, 1)};
  std::vector<Point> graph = {Point(10, 10), Point(-5, 3)};
  std::vector<int> face;
  for(const Point& q : comb) {
    face.push_back(int(graph.size()));
    graph.push_back(q);
    graph.push_back(Point(q.x() + 20, q.y())); // another vertex of the graph, not on this face
  }
  std::vector<std::array<int, 3>> a, b, local;
  const double wa = MWT::planar_graph_face_mwt_2(graph, face, std::back_inserter(a));
  const std::vector<int> reversed(face.rbegin(), face.rend()); // the clockwise walk of the same face
  const double wb = MWT::planar_graph_face_mwt_2(graph, reversed, std::back_inserter(b));
  const double wl = MWT::simple_polygon_mwt_2(comb, std::back_inserter(local));
  CHECK(wa == wl);
  CHECK(wb == Approx(wl).epsilon(1e-14)); // the same minimum from another start vertex
  CHECK(wa == Approx(spm_brute_force(comb).first).epsilon(1e-12));
  REQUIRE(a.size() == comb.size() - 2);
  REQUIRE(b.size() == comb.size() - 2);
  for(const auto& t : a) {
    for(int v : t) CHECK(std::find(face.begin(), face.end(), v) != face.end());
    CHECK(CGAL::orientation(graph[t[0]], graph[t[1]], graph[t[2]]) == CGAL::LEFT_TURN);
  }
  for(std::size_t i = 0; i < local.size(); ++i) // the same triangles, in graph indices
    CHECK(a[i] == (std::array<int, 3>{face[local[i][0]], face[local[i][1]], face[local[i][2]]}));
  CHECK_THROWS_AS(MWT::planar_graph_face_mwt_2(graph, std::vector<int>{0, 1, 99}, std::back_inserter(a)),
                  std::invalid_argument);
}

TEST_CASE("simple_polygon_mwt_2: refusals", "[mwt][simple_polygon]")
{
  std::vector<std::array<int, 3>> tri;
  auto out = std::back_inserter(tri);
  const std::vector<Point> ccw = {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)};
  const std::vector<Point> cw(ccw.rbegin(), ccw.rend());
  CHECK_THROWS_AS(MWT::simple_polygon_mwt_2(cw, out), std::invalid_argument);
  const std::vector<Point> bowtie = {Point(0, 0), Point(1, 1), Point(1, 0), Point(0, 1)};
  CHECK_THROWS_AS(MWT::simple_polygon_mwt_2(bowtie, out), std::invalid_argument);
  const std::vector<Point> repeated = {Point(0, 0), Point(1, 0), Point(1, 1), Point(1, 0), Point(0, 1)};
  CHECK_THROWS_AS(MWT::simple_polygon_mwt_2(repeated, out), std::invalid_argument);
  const std::vector<Point> touching = {Point(0, 0), Point(2, 0), Point(2, 2), Point(1, 0), Point(0, 2)}; // vertex on an edge
  CHECK_THROWS_AS(MWT::simple_polygon_mwt_2(touching, out), std::invalid_argument);
  CHECK_THROWS_AS(MWT::simple_polygon_mwt_2(std::vector<Point>{Point(0, 0), Point(1, 0)}, out), std::invalid_argument);
  CHECK(MWT::simple_polygon_mwt_2(ccw, out) == Approx(4 + std::sqrt(2.0)));
}
