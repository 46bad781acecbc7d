// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The LMT-skeleton and the dynamic program on the faces it leaves (Mwt_options::use_lmt_skeleton):
// certain edges are in every brute-force MWT and impossible edges in none; convex position is settled by the
// dynamic program alone; on wheels the centre's face is left to the LP; the pipeline gives the same weight as
// the plain LP path and as brute force.

#if defined(MDCS_HAS_CLP) && defined(MDCS_HAS_GLPK)

#include "mwt_test_helpers.h"

#include <catch2/catch.hpp>

#include <map>
#include <set>
#include <functional>
#include <array>
#include <algorithm>

using namespace mwt_test;

namespace {

typedef std::pair<int, int> Seg;

// All minimum weight triangulations (edge sets) by enumeration of maximal non-crossing segment sets; n <= 8.
std::vector<std::set<Seg>> all_mwts(const std::vector<Point>& p)
{
  const std::vector<Seg> E = valid_segments(p);
  const std::size_t M = E.size();
  const std::vector<std::vector<char>> cross = crossing_matrix(p, E);
  std::vector<std::pair<double, std::set<Seg>>> found;
  std::vector<std::size_t> chosen;
  // maximal sets: after the recursion, every skipped edge must cross a chosen one
  std::function<void(std::size_t)> rec = [&](std::size_t i) {
    if(i == M) {
      for(std::size_t k = 0; k < M; ++k) {
        bool in = std::find(chosen.begin(), chosen.end(), k) != chosen.end(), blocked = in;
        for(std::size_t c : chosen) blocked = blocked || cross[k][c];
        if(!blocked) return;
      }
      double w = 0;
      std::set<Seg> s;
      for(std::size_t c : chosen) { w += length(p[E[c].first], p[E[c].second]); s.insert(E[c]); }
      found.emplace_back(w, s);
      return;
    }
    bool free = true;
    for(std::size_t c : chosen) free = free && !cross[i][c];
    if(free) { chosen.push_back(i); rec(i + 1); chosen.pop_back(); }
    rec(i + 1);
  };
  rec(0);
  double best = HUGE_VAL;
  for(const auto& f : found) best = std::min(best, f.first);
  std::vector<std::set<Seg>> out;
  for(const auto& f : found)
    if(f.first <= best * (1 + 1e-12)) out.push_back(f.second);
  return out;
}

MWT::Mwt_options lmt_options()
{
  MWT::Mwt_options o;
  o.use_lmt_skeleton = true;
  return o;
}

void check_skeleton_against_brute_force(const std::vector<Point>& p)
{
  MWT::Minimum_weight_triangulation_lp_2<K> m(p, lmt_options());
  m.compute_candidate_edges();
  m.compute_empty_triangles();
  const auto& E = m.candidate_edges();
  const auto& S = m.lmt_edge_states();
  REQUIRE(S.size() == E.size());
  const auto opt = all_mwts(p);
  REQUIRE(!opt.empty());
  for(std::size_t e = 0; e < E.size(); ++e) {
    const Seg s(std::min(E[e].first, E[e].second), std::max(E[e].first, E[e].second));
    for(const auto& T : opt) {
      INFO("edge " << s.first << "-" << s.second << " state " << int(S[e]));
      if(S[e] == 2) CHECK(T.count(s) == 1);
      if(S[e] == 0) CHECK(T.count(s) == 0);
    }
  }
}

} // namespace

TEST_CASE("lmt: certain edges are in every brute-force MWT, impossible ones in none", "[mwt][lmt][oracle]")
{
  for(unsigned seed = 1; seed <= 30; ++seed) {
    const auto p = uniform_points(5 + int(seed % 4), 100 + seed);   // 5..8 points
    INFO("seed " << seed);
    check_skeleton_against_brute_force(p);
  }
  // degenerate sets: collinear triples, grid, even wheel
  check_skeleton_against_brute_force({Point(0, 0), Point(2, 0), Point(0, 2), Point(2, 2), Point(1, 1)});
  check_skeleton_against_brute_force({Point(0, 0), Point(1, 0), Point(2, 0), Point(0, 1), Point(1, 1), Point(2, 1), Point(0, 2), Point(1, 2)});
  check_skeleton_against_brute_force(wheel(6));
  check_skeleton_against_brute_force(wheel(7));
}

TEST_CASE("lmt: the skeleton marks edges on random sets (not a no-op)", "[mwt][lmt]")
{
  const auto p = uniform_points(400, 7);
  MWT::Minimum_weight_triangulation_lp_2<K> m(p, lmt_options());
  m.compute_candidate_edges();
  m.compute_empty_triangles();
  const auto& st = m.statistics();
  // uniform points: most MWT edges certain (Beirouti-Snoeyink), far fewer possible edges than candidates
  CHECK(st.lmt_certain_edges > 2 * p.size());
  CHECK(st.lmt_certain_edges + st.lmt_possible_edges < st.candidate_edges);
  CHECK(st.lmt_solved_faces > 0);
  CHECK(st.dp_triangles > 0);
}

TEST_CASE("lmt: convex position is solved by the dynamic program and certified", "[mwt][lmt][oracle]")
{
  std::mt19937 g(5);
  std::uniform_real_distribution<double> u(0, 2 * M_PI);
  for(int n : {6, 12, 25}) {
    std::vector<double> a(n);
    for(double& x : a) x = u(g);
    std::sort(a.begin(), a.end());
    std::vector<Point> p;
    for(double x : a) p.emplace_back(3 * std::cos(x), 2 * std::sin(x));
    std::vector<std::array<int, 3>> tri;
    const double w_dp = MWT::convex_polygon_mwt_2(p, std::back_inserter(tri));
    MWT::Mwt_options o = lmt_options();
    o.convex_position_by_dynamic_program = false;   // the skeleton's face program, not the one-shot's convex program
    const auto r = MWT::minimum_weight_triangulation_2(p, o);
    INFO("n " << n);
    REQUIRE(r.status == MWT::Mwt_status::certified_optimal);
    CHECK(r.weight == Approx(w_dp).epsilon(1e-12));
    CHECK(edge_weight(p, tri) == Approx(w_dp).epsilon(1e-12));
    CHECK(r.statistics.lmt_solved_faces >= 1);
    CHECK(r.statistics.dp_triangles == std::size_t(n - 2));   // the whole polygon by the dynamic program
    CHECK(r.statistics.lp_columns == 0);                      // no LP needed
  }
}

TEST_CASE("lmt: odd wheels: hull edges certain, the centre's face solved by the one-point program", "[mwt][lmt][wheel]")
{
  for(int k : {13, 15, 21}) {
    const auto p = wheel(k);
    const auto plain = MWT::minimum_weight_triangulation_2(p);   // fractional LP + branch and bound
    const auto r = MWT::minimum_weight_triangulation_2(p, lmt_options());
    INFO("k " << k);
    REQUIRE(plain.status == MWT::Mwt_status::optimal_after_branch_and_bound);
    REQUIRE(r.status == MWT::Mwt_status::certified_optimal);
    CHECK(r.weight == Approx(plain.weight).epsilon(1e-12));
    CHECK(r.statistics.lmt_certain_edges == std::size_t(k));   // the hull only
    CHECK(r.statistics.lmt_faces == 2);                         // inside and outside the hull
    CHECK(r.statistics.lmt_solved_faces == 1);
    CHECK(r.statistics.dp_triangles == std::size_t(k));         // 2n - h - 2 = k triangles
    CHECK(independent_triangulation_check(p, r.triangles));
  }
  const auto r13 = MWT::minimum_weight_triangulation_2(wheel(13), lmt_options());
  CHECK(r13.weight == Approx(18.7989).epsilon(1e-5));
}

TEST_CASE("lmt: convex polygons with one interior point against brute force", "[mwt][lmt][oracle]")
{
  std::mt19937 g(11);
  std::uniform_real_distribution<double> u(0, 1);
  for(int rep = 0; rep < 12; ++rep) {
    const int k = 5 + rep % 3;   // 5..7 hull points + 1 inside
    std::vector<double> a(k);
    for(double& x : a) x = 2 * M_PI * u(g);
    std::sort(a.begin(), a.end());
    std::vector<Point> p{Point(0.3 * (u(g) - 0.5), 0.3 * (u(g) - 0.5))};
    for(double x : a) p.emplace_back(std::cos(x), std::sin(x));
    const auto r = MWT::minimum_weight_triangulation_2(p, lmt_options());
    INFO("rep " << rep);
    REQUIRE(r.has_triangulation());
    CHECK(r.weight == Approx(brute_force_mwt(p)).epsilon(1e-12));
    CHECK(independent_triangulation_check(p, r.triangles));
  }
}

TEST_CASE("lmt: pipeline equals brute force on small sets and the plain LP on random sets", "[mwt][lmt][oracle]")
{
  for(unsigned seed = 1; seed <= 20; ++seed) {
    const auto p = uniform_points(4 + int(seed % 5), 300 + seed);
    const auto r = MWT::minimum_weight_triangulation_2(p, lmt_options());
    INFO("seed " << seed);
    REQUIRE(r.has_triangulation());
    CHECK(r.weight == Approx(brute_force_mwt(p)).epsilon(1e-12));
    CHECK(independent_triangulation_check(p, r.triangles));
  }
  for(unsigned seed = 1; seed <= 8; ++seed) {
    const auto p = seed % 2 ? uniform_points(250, seed) : clustered_points(250, seed);
    const auto plain = MWT::minimum_weight_triangulation_2(p);
    const auto r = MWT::minimum_weight_triangulation_2(p, lmt_options());
    INFO("seed " << seed);
    REQUIRE(r.status == MWT::Mwt_status::certified_optimal);
    CHECK(r.weight == Approx(plain.weight).epsilon(1e-12));
    CHECK(r.lower_bound <= r.weight * (1 + 1e-12));
    CHECK(r.statistics.lp_columns < plain.statistics.lp_columns);
    CHECK(independent_triangulation_check(p, r.triangles));
  }
}

TEST_CASE("lmt: mixed instance: dynamic program on some faces, LP (with branch and bound) on the others", "[mwt][lmt][oracle]")
{
  // two odd wheels whose centres are replaced by two close points, inside a ring of random points
  std::mt19937 g(3);
  std::uniform_real_distribution<double> u(0, 1);
  for(int rep = 0; rep < 3; ++rep) {
    std::vector<Point> p;
    for(int w = 0; w < 2; ++w) {
      const double cx = 4.0 * w;
      p.emplace_back(cx - 0.05 + 0.01 * u(g), 0.01 * u(g));
      p.emplace_back(cx + 0.05 + 0.01 * u(g), 0.01 * u(g));
      for(int i = 0; i < 13; ++i) p.emplace_back(cx + std::cos(2 * M_PI * i / 13), std::sin(2 * M_PI * i / 13));
    }
    for(int i = 0; i < 120; ++i) {
      const double a = 2 * M_PI * u(g), rad = 2.5 + 2 * u(g);
      p.emplace_back(2 + 1.6 * rad * std::cos(a), rad * std::sin(a));
    }
    const auto plain = MWT::minimum_weight_triangulation_2(p);
    const auto r = MWT::minimum_weight_triangulation_2(p, lmt_options());
    INFO("rep " << rep << " " << r.message);
    REQUIRE(r.has_triangulation());
    CHECK(r.weight == Approx(plain.weight).epsilon(1e-12));
    CHECK(r.lower_bound <= r.weight * (1 + 1e-12));
    CHECK(r.lower_bound >= plain.lower_bound * (1 - 1e-9));   // fewer triangles: a bound at least as tight
    CHECK(r.statistics.dp_triangles > 0);
    CHECK(r.statistics.lp_columns > 0);            // the faces around the two-point centres need the LP
    CHECK(r.statistics.lp_columns < plain.statistics.lp_columns);
    CHECK(independent_triangulation_check(p, r.triangles));
  }
}

// The empty triangles are stored by their three edges only (12 bytes each, memory at 10^7 points): the vertices,
// sides and apexes derived from the edges must be those of the triangles, which must be exactly the empty
// triangles over the valid segments (brute force, exact orientations); the filtered edge index and compaction.
TEST_CASE("lmt: triangles stored by edges: vertices, sides, apexes against brute force", "[mwt][lmt][oracle]")
{
  std::vector<std::vector<Point>> sets{uniform_points(40, 71), clustered_points(40, 72)};
  std::vector<Point> grid_points;   // collinear triples: triangles with a point on an edge are not empty
  for(int i = 0; i < 6; ++i)
    for(int j = 0; j < 6; ++j) grid_points.emplace_back(i, j);
  sets.push_back(grid_points);
  for(const auto& p : sets) {
    MWT::internal::Indexed_points_2<K> pts(p);
    MWT::internal::Point_grid_2 grid(pts);
    std::function<bool(const char*, double)> progress = [](const char*, double) { return true; };
    const std::vector<std::pair<int, int>> edges = MWT::internal::all_valid_edges(pts, grid, progress);
    const MWT::internal::Edge_index index(edges, p.size());
    const MWT::internal::Triangle_set tri = MWT::internal::empty_triangles(pts, grid, index, edges, progress);
    std::set<std::array<int, 3>> found, expected;
    for(std::size_t t = 0; t < tri.size(); ++t) {
      const std::array<int, 3> v = tri.vertices(int(t));
      REQUIRE(CGAL::orientation(p[v[0]], p[v[1]], p[v[2]]) == CGAL::LEFT_TURN);
      for(int i = 0; i < 3; ++i) {
        CHECK(tri.edge(int(t), i) == index.find(v[i], v[(i + 1) % 3]));
        CHECK(tri.side(int(t), i) == (v[i] < v[(i + 1) % 3] ? 1 : -1));
        CHECK(tri.apex(int(t), tri.edge(int(t), i)) == v[(i + 2) % 3]);
        CHECK(tri.triangle(int(t)).side(i) == tri.side(int(t), i));
      }
      std::array<int, 3> s = v;
      std::sort(s.begin(), s.end());
      CHECK(found.insert(s).second);   // no triangle twice
    }
    const std::set<std::pair<int, int>> valid(edges.begin(), edges.end());
    const int n = int(p.size());
    for(int a = 0; a < n; ++a)
      for(int b = a + 1; b < n; ++b)
        for(int c = b + 1; c < n; ++c) {
          if(!valid.count({a, b}) || !valid.count({b, c}) || !valid.count({a, c})) continue;
          const CGAL::Orientation o = CGAL::orientation(p[a], p[b], p[c]);
          if(o == CGAL::COLLINEAR) continue;
          bool empty = true;
          for(int r = 0; r < n && empty; ++r)
            if(r != a && r != b && r != c && CGAL::orientation(p[a], p[b], p[r]) == o &&
               CGAL::orientation(p[b], p[c], p[r]) == o && CGAL::orientation(p[c], p[a], p[r]) == o)
              empty = false;
          if(empty) expected.insert({{a, b, c}});
        }
    CHECK(found == expected);
    CHECK(expected.size() > p.size());
    // round trip through Lp_triangle, and compaction keeps the order
    std::vector<MWT::internal::Lp_triangle> as_lp;
    for(std::size_t t = 0; t < tri.size(); ++t) as_lp.push_back(tri.triangle(int(t)));
    MWT::internal::Triangle_set back(edges, as_lp), odd(edges, as_lp);
    odd.compact([](int t) { return t % 2 == 1; });
    REQUIRE(back.size() == tri.size());
    REQUIRE(odd.size() == tri.size() / 2);
    for(std::size_t t = 0; t < tri.size(); ++t) CHECK(back.vertices(int(t)) == tri.vertices(int(t)));
    for(std::size_t t = 0; t < odd.size(); ++t) CHECK(odd.vertices(int(t)) == tri.vertices(int(2 * t + 1)));
    // the filtered edge index: the kept edges with their indices, -1 for the others
    const MWT::internal::Edge_index even(edges, p.size(), [](std::size_t e) { return e % 2 == 0; });
    for(std::size_t e = 0; e < edges.size(); ++e) {
      CHECK(even.find(edges[e].first, edges[e].second) == (e % 2 == 0 ? int(e) : -1));
      CHECK(index.find(edges[e].second, edges[e].first) == int(e));
    }
  }
}

TEST_CASE("lmt: other metrics are refused with a clear error", "[mwt][lmt][input]")
{
  auto o = lmt_options();
  o.metric = MWT::Edge_metric::L1;
  CHECK_THROWS_AS(MWT::minimum_weight_triangulation_2(uniform_points(10, 1), o), std::invalid_argument);
}

#endif
