// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// polygon_with_holes_mwt_2(): the MWT of a polygonal domain with holes and interior points against
//  (a) brute force over every triangulation of small random domains (<= 9 vertices; the domain's segments found
//      independently: no vertex on the open segment, no boundary edge crossed, the midpoint inside in rational
//      arithmetic), the minimum weight compared to 1e-12 relative;
//  (b) simple_polygon_mwt_2() on domains without holes and points (either orientation);
//  (c) minimum_weight_triangulation_2() on point sets given as their convex hull with the other points inside;
//  (d) the invariants of every result: V + m + 2h - 2 counter-clockwise empty triangles (Euler) whose areas sum to
//      the domain's in exact rationals, the returned weight equal to the sum of the distinct edges;
// the thesis's 13-wheel as a domain (fractional LP 18.7636, MWT 18.7989 after branch and bound), the
// Polygon_with_holes_2 overload, cancellation, and (e) every refused input.

#include "mwt_test_helpers.h"

#include <CGAL/Minimum_weight_triangulation_2/polygon_with_holes_mwt_2.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/convex_hull_2.h>

#include <catch2/catch.hpp>

#include <functional>
#include <random>
#include <set>

using namespace mwt_test;

namespace pwh_test {

typedef CGAL::Simple_cartesian<CGAL::Exact_rational> QK;

struct Domain
{
  std::vector<Point> outer;
  std::vector<std::vector<Point>> holes;
  std::vector<Point> inside;

  // the documented numbering: outer, holes in order, then the interior points
  std::vector<Point> all() const
  {
    std::vector<Point> p(outer);
    for(const auto& h : holes) p.insert(p.end(), h.begin(), h.end());
    p.insert(p.end(), inside.begin(), inside.end());
    return p;
  }
  // the boundary edges as index pairs in that numbering
  std::vector<std::pair<int, int>> boundary_edges() const
  {
    std::vector<std::pair<int, int>> e;
    int base = 0;
    auto ring = [&](std::size_t k) {
      for(std::size_t i = 0; i < k; ++i) e.emplace_back(base + int(i), base + int((i + 1) % k));
      base += int(k);
    };
    ring(outer.size());
    for(const auto& h : holes) ring(h.size());
    return e;
  }
};

QK::Point_2 exact(const Point& p) { return QK::Point_2(p.x(), p.y()); }

std::vector<QK::Point_2> exact(const std::vector<Point>& ring)
{
  std::vector<QK::Point_2> q;
  for(const auto& p : ring) q.push_back(exact(p));
  return q;
}

// Whether q lies strictly inside the domain (rational arithmetic).
bool strictly_inside(const Domain& d, const QK::Point_2& q)
{
  const auto o = exact(d.outer);
  if(CGAL::bounded_side_2(o.begin(), o.end(), q, QK()) != CGAL::ON_BOUNDED_SIDE) return false;
  for(const auto& h : d.holes) {
    const auto e = exact(h);
    if(CGAL::bounded_side_2(e.begin(), e.end(), q, QK()) != CGAL::ON_UNBOUNDED_SIDE) return false;
  }
  return true;
}

// The domain's segments other than its boundary edges, found independently of the library.
std::vector<std::pair<int, int>> diagonals(const Domain& d)
{
  const auto p = d.all();
  const auto be = d.boundary_edges();
  std::set<std::pair<int, int>> boundary;
  for(const auto& e : be) boundary.insert(std::minmax(e.first, e.second));
  std::vector<std::pair<int, int>> out;
  for(int a = 0; a < int(p.size()); ++a)
    for(int b = a + 1; b < int(p.size()); ++b) {
      if(boundary.count({a, b})) continue;
      const K::Segment_2 s(p[a], p[b]);
      bool ok = strictly_inside(d, CGAL::midpoint(exact(p[a]), exact(p[b])));
      for(int c = 0; ok && c < int(p.size()); ++c)
        if(c != a && c != b && s.has_on(p[c])) ok = false;
      for(const auto& e : be) {
        if(!ok) break;
        if(e.first == a || e.first == b || e.second == a || e.second == b) continue;
        if(CGAL::do_intersect(s, K::Segment_2(p[e.first], p[e.second]))) ok = false;
      }
      if(ok) out.emplace_back(a, b);
    }
  return out;
}

std::size_t euler_triangles(const Domain& d)
{
  return d.all().size() + d.inside.size() + 2 * d.holes.size() - 2;
}

// The minimum weight over every triangulation (every set of pairwise non-crossing diagonals of the size Euler's
// formula gives), and the number of triangulations.
std::pair<double, long> brute_force(const Domain& d)
{
  const auto p = d.all();
  const auto diag = diagonals(d);
  const auto be = d.boundary_edges();
  const std::size_t edges = (3 * euler_triangles(d) + be.size()) / 2, need = edges - be.size();
  double boundary = 0;
  for(const auto& e : be) boundary += length(p[e.first], p[e.second]);
  auto cross = [&](const std::pair<int, int>& u, const std::pair<int, int>& v) {
    if(u.first == v.first || u.first == v.second || u.second == v.first || u.second == v.second) return false;
    return CGAL::do_intersect(K::Segment_2(p[u.first], p[u.second]), K::Segment_2(p[v.first], p[v.second]));
  };
  double best = std::numeric_limits<double>::infinity();
  long count = 0;
  std::vector<std::size_t> chosen;
  std::function<void(std::size_t, double)> rec = [&](std::size_t next, double w) {
    if(chosen.size() == need) {
      ++count;
      best = std::min(best, boundary + w);
      return;
    }
    if(diag.size() - next < need - chosen.size()) return;
    for(std::size_t i = next; i < diag.size(); ++i) {
      bool free = true;
      for(std::size_t c : chosen) free = free && !cross(diag[c], diag[i]);
      if(!free) continue;
      chosen.push_back(i);
      rec(i + 1, w + length(p[diag[i].first], p[diag[i].second]));
      chosen.pop_back();
    }
  };
  rec(0, 0);
  return {best, count};
}

// Twice the area of a ring, exactly (positive counter-clockwise).
CGAL::Exact_rational twice_area(const std::vector<Point>& ring)
{
  CGAL::Exact_rational s(0);
  for(std::size_t i = 0; i < ring.size(); ++i) {
    const auto a = exact(ring[i]), b = exact(ring[(i + 1) % ring.size()]);
    s += a.x() * b.y() - b.x() * a.y();
  }
  return s;
}

// (d): Euler's count of distinct counter-clockwise triangles, none containing a vertex (inside or on a side but
// its corners), areas summing to the domain's exactly, every side a boundary edge or an independent diagonal,
// and the weight the sum of the distinct sides.
void check_triangulation(const Domain& d, const MWT::Mwt_result& r)
{
  const auto p = d.all();
  REQUIRE(r.has_triangulation());
  REQUIRE(r.triangles.size() == euler_triangles(d));
  std::set<std::pair<int, int>> allowed;
  for(const auto& e : d.boundary_edges()) allowed.insert(std::minmax(e.first, e.second));
  for(const auto& e : diagonals(d)) allowed.insert(e);
  std::set<std::array<int, 3>> distinct;
  std::set<std::pair<int, int>> edges;
  CGAL::Exact_rational area(0);
  for(const auto& t : r.triangles) {
    for(int v : t) REQUIRE((v >= 0 && v < int(p.size())));
    CHECK(CGAL::orientation(p[t[0]], p[t[1]], p[t[2]]) == CGAL::LEFT_TURN);
    std::array<int, 3> s = t;
    std::sort(s.begin(), s.end());
    distinct.insert(s);
    const K::Triangle_2 tri(p[t[0]], p[t[1]], p[t[2]]);
    for(int v = 0; v < int(p.size()); ++v)
      if(v != t[0] && v != t[1] && v != t[2]) CHECK(tri.bounded_side(p[v]) == CGAL::ON_UNBOUNDED_SIDE);
    for(int i = 0; i < 3; ++i) {
      const auto e = std::minmax(t[i], t[(i + 1) % 3]);
      CHECK(allowed.count(e) == 1);
      edges.insert(e);
      const auto a = exact(p[t[i]]), b = exact(p[t[(i + 1) % 3]]);
      area += a.x() * b.y() - b.x() * a.y();
    }
  }
  CHECK(distinct.size() == r.triangles.size());
  CGAL::Exact_rational domain = CGAL::abs(twice_area(d.outer));
  for(const auto& h : d.holes) domain -= CGAL::abs(twice_area(h));
  CHECK(area == domain);
  double w = 0;
  for(const auto& e : edges) w += length(p[e.first], p[e.second]);
  CHECK(w == Approx(r.weight).epsilon(1e-12));
  CHECK(r.lower_bound <= r.weight * (1 + 1e-9));
}

// A star-shaped ring around c: one angle in each k-th of the turn, radii in [rmin, rmax]; counter-clockwise.
std::vector<Point> star(int k, double cx, double cy, double rmin, double rmax, std::mt19937& g)
{
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Point> p;
  for(int i = 0; i < k; ++i) {
    const double a = 2 * M_PI * (i + 0.8 * u(g)) / k, r = rmin + (rmax - rmin) * u(g);
    p.emplace_back(cx + r * std::cos(a), cy + r * std::sin(a));
  }
  return p;
}

// A random domain: an outer star of radius 0.7..1, optionally a hole (a star of radius 0.08..0.2 around a point
// near the centre), and `points` random points strictly inside the domain.
Domain random_domain(int outer, int hole, int points, std::mt19937& g)
{
  std::uniform_real_distribution<double> u(-1, 1);
  Domain d;
  d.outer = star(outer, 0, 0, 0.7, 1.0, g);
  if(hole > 0) d.holes.push_back(star(hole, 0.1 * u(g), 0.1 * u(g), 0.08, 0.2, g));
  while(int(d.inside.size()) < points) {
    const Point q(0.9 * u(g), 0.9 * u(g));
    if(strictly_inside(d, exact(q))) d.inside.push_back(q);
  }
  return d;
}

MWT::Mwt_result solve(const Domain& d, const MWT::Mwt_options& o = MWT::Mwt_options())
{
  return MWT::polygon_with_holes_mwt_2(d.outer, d.holes, d.inside, o);
}

bool optimal(const MWT::Mwt_result& r)
{
  return r.status == MWT::Mwt_status::certified_optimal || r.status == MWT::Mwt_status::optimal_after_branch_and_bound;
}

} // namespace pwh_test

using namespace pwh_test;

TEST_CASE("polygon_with_holes_mwt_2: brute force over every triangulation of small domains", "[mwt][polygon_with_holes]")
{
  std::mt19937 g(30);
  // (outer, hole, points): a hole, points, both; at most 9 vertices
  const std::vector<std::array<int, 3>> shapes = {{4, 3, 0}, {5, 3, 0}, {6, 3, 0}, {5, 4, 0}, {4, 0, 1}, {5, 0, 2},
                                                  {6, 0, 3}, {4, 3, 1}, {5, 3, 1}, {4, 4, 1}, {4, 3, 2}};
  int cases = 0, holes = 0;
  for(const auto& s : shapes)
    for(int rep = 0; rep < 4; ++rep) {
      const Domain d = random_domain(s[0], s[1], s[2], g);
      // either orientation of the outer ring and the holes
      Domain given = d;
      if(rep % 2 == 1) std::reverse(given.outer.begin(), given.outer.end());
      if(rep >= 2)
        for(auto& h : given.holes) std::reverse(h.begin(), h.end());
      const auto r = solve(given);
      const auto bf = brute_force(given);
      INFO("shape " << s[0] << "/" << s[1] << "/" << s[2] << " rep " << rep << ": " << bf.second
                    << " triangulations, status " << MWT::to_string(r.status) << ", " << r.message);
      REQUIRE(bf.second >= 1);
      REQUIRE(optimal(r));
      CHECK(r.weight == Approx(bf.first).epsilon(1e-12));
      check_triangulation(given, r);
      ++cases;
      holes += !d.holes.empty();
    }
  CHECK(cases == 44);
  CHECK(holes == 32);
}

TEST_CASE("polygon_with_holes_mwt_2: without holes and points it is simple_polygon_mwt_2", "[mwt][polygon_with_holes]")
{
  std::mt19937 g(31);
  const std::vector<Point> none;
  const std::vector<std::vector<Point>> no_holes;
  for(int n : {3, 5, 9, 17, 30})
    for(int rep = 0; rep < 3; ++rep) {
      Domain d;
      d.outer = star(n, 0, 0, 0.2, 1.0, g);
      std::vector<std::array<int, 3>> tri;
      const double w = MWT::simple_polygon_mwt_2(d.outer, std::back_inserter(tri));
      if(rep == 1) std::reverse(d.outer.begin(), d.outer.end());   // clockwise: same weight, reversed numbering
      const auto r = MWT::polygon_with_holes_mwt_2(d.outer, no_holes, none);
      INFO("n " << n << " rep " << rep);
      CHECK(r.status == MWT::Mwt_status::certified_optimal);
      // the same program on the same polygon; reversed, on a rotation of it (another summation order)
      if(rep != 1) CHECK(r.weight == w);
      else CHECK(r.weight == Approx(w).epsilon(1e-12));
      check_triangulation(d, r);
      if(rep != 1) {
        std::set<std::array<int, 3>> a, b;
        for(auto t : tri) { std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end()); a.insert(t); }
        for(auto t : r.triangles) { std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end()); b.insert(t); }
        CHECK(a == b);
      }
    }
}

TEST_CASE("polygon_with_holes_mwt_2: a point set as its hull with the other points inside is "
          "minimum_weight_triangulation_2", "[mwt][polygon_with_holes]")
{
  int fractional = 0;
  for(unsigned seed = 0; seed < 6; ++seed) {
    const auto p = uniform_points(20 + 4 * int(seed), 700 + seed);
    Domain d;
    CGAL::convex_hull_2(p.begin(), p.end(), std::back_inserter(d.outer));
    const std::set<Point> hull(d.outer.begin(), d.outer.end());
    for(const auto& q : p)
      if(!hull.count(q)) d.inside.push_back(q);
    const auto r = solve(d);
    const auto ref = MWT::minimum_weight_triangulation_2(p);
    INFO("seed " << seed << ": " << r.message);
    REQUIRE(optimal(r));
    REQUIRE(optimal(ref));
    CHECK(r.weight == Approx(ref.weight).epsilon(1e-12));
    CHECK(r.lp_objective == Approx(ref.lp_objective).epsilon(1e-9));
    fractional += !r.lp_integral;
    check_triangulation(d, r);
  }
  CHECK(fractional == 0);   // uniform sets of this size have integral LP optima
}

TEST_CASE("polygon_with_holes_mwt_2: the thesis's 13-wheel as a domain: LP 18.7636 (fractional), MWT 18.7989",
          "[mwt][polygon_with_holes][wheel]")
{
  const auto w = wheel(13);
  Domain d;
  d.outer.assign(w.begin() + 1, w.end());
  d.inside.push_back(w[0]);
  MWT::Mwt_options o;
  o.resolve_fractional = false;
  const auto lp_only = solve(d, o);
  CHECK(lp_only.status == MWT::Mwt_status::fractional_bound_only);
  CHECK_FALSE(lp_only.has_triangulation());
  CHECK(lp_only.lp_objective == Approx(18.7636).margin(5e-5));
  CHECK(lp_only.lower_bound == Approx(18.7636).margin(5e-5));
#if defined(MDCS_HAS_GLPK)
  const auto r = solve(d);
  CHECK(r.status == MWT::Mwt_status::optimal_after_branch_and_bound);
  CHECK(r.weight == Approx(18.7989).margin(5e-5));
  CHECK(r.lower_bound <= r.weight);
  check_triangulation(d, r);
  // a hole instead of the centre point (a small triangle around it): still a valid optimum, checked by invariants
  Domain h;
  h.outer = d.outer;
  h.holes.push_back({Point(0.05, 0), Point(-0.025, 0.04), Point(-0.025, -0.04)});
  const auto rh = solve(h);
  REQUIRE(optimal(rh));
  check_triangulation(h, rh);
#endif
}

TEST_CASE("polygon_with_holes_mwt_2: Polygon_with_holes_2 overload, metrics, progress and cancellation",
          "[mwt][polygon_with_holes]")
{
  std::mt19937 g(32);
  const Domain d = random_domain(7, 4, 3, g);
  CGAL::Polygon_with_holes_2<K> pwh(CGAL::Polygon_2<K>(d.outer.begin(), d.outer.end()));
  pwh.add_hole(CGAL::Polygon_2<K>(d.holes[0].begin(), d.holes[0].end()));
  const auto a = solve(d), b = MWT::polygon_with_holes_mwt_2(pwh, d.inside);
  REQUIRE(optimal(a));
  CHECK(a.weight == b.weight);
  CHECK(a.triangles == b.triangles);
  // other metrics: the brute force of the L2 weight bounds the L1 optimum's L2 weight from below, and the L1
  // optimum is no heavier in L1 than the L2 optimum
  MWT::Mwt_options l1;
  l1.metric = MWT::Edge_metric::L1;
  const auto r1 = solve(d, l1);
  REQUIRE(optimal(r1));
  const auto p = d.all();
  auto l1_weight = [&](const MWT::Mwt_result& r) {
    std::set<std::pair<int, int>> e;
    for(const auto& t : r.triangles)
      for(int i = 0; i < 3; ++i) e.insert(std::minmax(t[i], t[(i + 1) % 3]));
    double s = 0;
    for(const auto& x : e) s += length(p[x.first], p[x.second], MWT::Edge_metric::L1);
    return s;
  };
  CHECK(r1.weight == Approx(l1_weight(r1)).epsilon(1e-12));
  CHECK(r1.weight <= l1_weight(a) * (1 + 1e-12));
  // progress: the stages are reported; returning false cancels
  std::set<std::string> stages;
  MWT::Mwt_options o;
  o.progress = [&](const char* s, double) { stages.insert(s); return true; };
  REQUIRE(optimal(solve(d, o)));
  CHECK(stages.count("empty triangles") == 1);
  CHECK(stages.count("LP solve") == 1);
  o.progress = [](const char*, double) { return false; };
  CHECK_THROWS_AS(solve(d, o), CGAL::MDCS::Operation_cancelled);
}

TEST_CASE("polygon_with_holes_mwt_2: refused input", "[mwt][polygon_with_holes][input]")
{
  const std::vector<Point> square = {Point(0, 0), Point(4, 0), Point(4, 4), Point(0, 4)};
  const std::vector<Point> hole = {Point(1, 1), Point(2, 1), Point(1, 2)};
  const std::vector<Point> none;
  typedef std::vector<std::vector<Point>> Holes;
  auto throws = [&](const std::vector<Point>& outer, const Holes& holes, const std::vector<Point>& inside,
                    const char* says) {
    INFO(says);
    try {
      MWT::polygon_with_holes_mwt_2(outer, holes, inside);
      FAIL("no exception");
    } catch(const std::invalid_argument& e) {
      INFO(e.what());
      CHECK(std::string(e.what()).find(says) != std::string::npos);
    }
  };
  // the valid domain first
  REQUIRE(optimal(MWT::polygon_with_holes_mwt_2(square, Holes{hole}, std::vector<Point>{Point(3, 3)})));
  throws({Point(0, 0), Point(1, 0)}, Holes{}, none, "at least 3");
  throws(square, Holes{{Point(1, 1), Point(2, 1)}}, none, "at least 3");
  throws({Point(0, 0), Point(1, 1), Point(2, 2)}, Holes{}, none, "zero area");
  throws(square, Holes{{Point(1, 1), Point(2, 2), Point(3, 3)}}, none, "zero area");
  throws({Point(0, 0), Point(2, 2), Point(2, 0), Point(0, 2)}, Holes{}, none, "not simple");   // a bow tie
  throws(square, Holes{{Point(1, 1), Point(2, 2), Point(2, 1), Point(1, 2)}}, none, "not simple");
  throws(square, Holes{{Point(3, 1), Point(5, 1), Point(3, 2)}}, none, "cross or touch");      // hole across the outer
  throws(square, Holes{{Point(4, 1), Point(3, 2), Point(3, 1)}}, none, "cross or touch");      // touching it
  throws(square, Holes{hole, {Point(1.5, 1.2), Point(3, 1.2), Point(3, 3)}}, none, "cross or touch");   // holes cross
  throws(square, Holes{{Point(5, 5), Point(6, 5), Point(5, 6)}}, none, "outside the outer");
  throws(square, Holes{{Point(0.5, 0.5), Point(3.5, 0.5), Point(0.5, 3.5)}, hole}, none, "inside hole 0");   // nested
  throws(square, Holes{hole}, {Point(5, 1)}, "outside the outer");
  throws(square, Holes{hole}, {Point(4, 1)}, "on the outer boundary");
  throws(square, Holes{hole}, {Point(1.5, 1)}, "on the boundary of hole 0");
  throws(square, Holes{hole}, {Point(1.2, 1.2)}, "inside hole 0");
  throws(square, Holes{hole}, {Point(3, 3), Point(3, 3)}, "coincide");
  throws({Point(0, 0), Point(4, 0), Point(4, 4), Point(4, 0)}, Holes{}, none, "coincide");
  throws(square, Holes{hole}, {Point(1, 1)}, "coincide");   // a point on a hole's vertex
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  throws({Point(0, 0), Point(nan, 0), Point(0, 1)}, Holes{}, none, "non-finite");
  throws(square, Holes{hole}, {Point(inf, 1)}, "non-finite");
  throws({Point(0, 0), Point(1e200, 0), Point(0, 1)}, Holes{}, none, "2^500");
  throws({Point(0, 0), Point(1e-130, 0), Point(0, 1e-130)}, Holes{}, none, "2^-400");
  // too many vertices
  std::vector<Point> big;
  const int n = int(MWT::polygon_with_holes_mwt_max_vertices()) + 1;
  for(int i = 0; i < n; ++i) big.emplace_back(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n));
  throws(big, Holes{}, none, "at most");
  MWT::Mwt_options o;
  o.triangle_weight = [](double, double, double, double, double, double) { return 1.0; };
  CHECK_THROWS_AS(MWT::polygon_with_holes_mwt_2(square, Holes{hole}, none, o), std::invalid_argument);
  o = MWT::Mwt_options();
  o.branch_and_bound_time_limit = -1;
  CHECK_THROWS_AS(MWT::polygon_with_holes_mwt_2(square, Holes{hole}, none, o), std::invalid_argument);
}
