// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The face dynamic program (Face_dp_2) on weakly simple faces: faces of the certain edges whose boundary walk
// repeats a vertex (the two sides of a dangling edge, a pinch vertex where two loops of the boundary touch).
// - hand-built faces and random connected certain-edge sets on small point sets, the program run directly on
//   them, against the exhaustive oracle constrained to the same edges (no LP, no skeleton, no program);
// - random wheels (thesis Fig. 3.5) whose LMT-skeleton leaves exactly one certain spoke: the pipeline needs no
//   LP any more, and its weight is the triangle LP's (CLP, then GLPK's branch and bound if fractional);
// - identical results for every thread count, and the LP path's exact support certificate on the same wheels.

// Needs both LP solver models (found and defined by the build: MDCS_HAS_CLP, MDCS_HAS_GLPK).
#if defined(MDCS_HAS_CLP) && defined(MDCS_HAS_GLPK)

#include "mwt_exhaustive_oracle.h"
#include "mwt_test_helpers.h"

#include <CGAL/Minimum_weight_triangulation_2/internal/Face_dp_2.h>
#include <CGAL/Random.h>
#include <MDCS_test/random_wheels.h>
#include <MDCS_test/thread_counts.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <functional>
#include <numeric>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace weak_face_test {

using namespace mwt_test;
typedef std::array<int, 3> Tri;
typedef std::pair<int, int> Segment;

// What the face programs gave for a set of certain edges.
struct Face_programs
{
  std::vector<Tri> triangles;   // in the program's order
  std::size_t faces = 0, solved = 0, weakly_simple = 0;
};

bool segments_cross(const std::vector<Point>& p, const Segment& e, const Segment& f)
{
  const int a = e.first, b = e.second, c = f.first, d = f.second;
  if(a == c || a == d || b == c || b == d) return false;
  auto o = [&](int u, int v, int w) { return int(CGAL::orientation(p[u], p[v], p[w])); };
  return o(a, b, c) * o(a, b, d) < 0 && o(c, d, a) * o(c, d, b) < 0;
}

// The face programs run directly on the edges `certain` plus the hull edges: those are certain, the edges
// crossing one of them impossible (as the skeleton would make them), all others possible.
Face_programs run_face_programs(const std::vector<Point>& p, const std::vector<Segment>& certain, std::size_t threads)
{
  MWT::internal::Indexed_points_2<K> pts(p);
  MWT::internal::Point_grid_2 grid(pts);
  std::function<bool(const char*, double)> progress = [](const char*, double) { return true; };
  const std::vector<Segment> edges = MWT::internal::all_valid_edges(pts, grid, progress);
  const MWT::internal::Edge_index index(edges, p.size());
  const MWT::internal::Triangle_set tri = MWT::internal::empty_triangles(pts, grid, index, edges, progress);
  const MWT::internal::Edge_triangles by_edge(tri, edges.size());
  std::set<Segment> wanted;
  for(const Segment& e : certain) wanted.insert(std::minmax(e.first, e.second));
  std::vector<Segment> all_certain;
  std::vector<char> state(edges.size(), MWT::internal::lmt_possible);
  for(std::size_t e = 0; e < edges.size(); ++e)
    if(wanted.count(std::minmax(edges[e].first, edges[e].second)) || is_hull_segment(p, edges[e])) {
      state[e] = MWT::internal::lmt_certain;
      all_certain.push_back(edges[e]);
    }
  for(std::size_t e = 0; e < edges.size(); ++e)
    for(const Segment& c : all_certain)
      if(segments_cross(p, edges[e], c)) state[e] = MWT::internal::lmt_impossible;
  const MWT::internal::Face_dp_2<MWT::internal::Indexed_points_2<K>> dp(
    pts, edges, index, tri, by_edge, state, 400, MWT::internal::Parallel_stage(threads));
  Face_programs out;
  for(int t : dp.dp_triangles()) out.triangles.push_back(tri.vertices(t));
  out.faces = dp.number_of_faces();
  out.solved = dp.number_of_solved_faces();
  out.weakly_simple = dp.number_of_weakly_simple_faces();
  return out;
}

// The programs on `certain` must triangulate every bounded face (the certain edges connect all points, so no
// face holds an island or an isolated point), with the constrained oracle's weight, the same for every thread
// count. Returns the number of weakly simple faces solved.
std::size_t check_against_oracle(const std::vector<Point>& p, const std::vector<Segment>& certain)
{
  const Face_programs f = run_face_programs(p, certain, 1);
  CHECK(f.solved + 1 == f.faces);   // every face but the outer one
  REQUIRE(independent_triangulation_check(p, f.triangles));
  std::set<Segment> used;
  for(const Tri& t : f.triangles)
    for(int i = 0; i < 3; ++i) used.insert(std::minmax(t[i], t[(i + 1) % 3]));
  for(const Segment& e : certain) CHECK(used.count(std::minmax(e.first, e.second)) == 1);
  const Exhaustive_mwt oracle = exhaustive_mwt(p, certain);
  CHECK(edge_weight(p, f.triangles) == Approx(oracle.weight).epsilon(1e-12));
  for(std::size_t threads : MDCS_test::thread_counts) {
    if(threads == 1) continue;
    const Face_programs g = run_face_programs(p, certain, threads);
    CHECK(g.triangles == f.triangles);
    CHECK(g.solved == f.solved);
    CHECK(g.weakly_simple == f.weakly_simple);
  }
  return f.weakly_simple;
}

} // namespace weak_face_test

using namespace weak_face_test;

TEST_CASE("weak faces: dangling edges and pinch vertices, against the constrained exhaustive oracle",
          "[mwt][lmt][weak_faces][oracle]")
{
  // square, then interior points; every point is on a certain edge (no isolated point in a face)
  const std::vector<Point> square{Point(0, 0), Point(4, 0), Point(4, 4), Point(0, 4)};
  auto with = [&](std::vector<Point> extra) {
    std::vector<Point> p = square;
    p.insert(p.end(), extra.begin(), extra.end());
    return p;
  };
  SECTION("a dangling tree and a spike")
  {
    // a tree at corner 0: 0-4, branching at 4 to 5 and 6; a spike 2-7. The bounded face walks 0 twice,
    // 4 three times (its three wedges), 2 twice, and has three spike tips (5, 6, 7).
    const std::vector<Point> p = with({Point(1.3, 1.1), Point(2.7, 1.9), Point(1.1, 2.6), Point(3.0, 3.4)});
    CHECK(check_against_oracle(p, {{0, 4}, {4, 5}, {4, 6}, {2, 7}}) == 1);
  }
  SECTION("a dangling path whose middle corners are straight")
  {
    // the path 1-4-5-6 on the line x + y = 4: straight corners (a half-plane wedge on each side of the path)
    const std::vector<Point> p = with({Point(3, 1), Point(2, 2), Point(1, 3), Point(2.9, 2.6)});
    CHECK(check_against_oracle(p, {{1, 4}, {4, 5}, {5, 6}, {2, 7}}) == 1);
  }
  SECTION("a pinch at a hull corner")
  {
    // the triangle 0-4-5 on corner 0 splits the square into a triangle and a face that touches 0 twice (one
    // wedge on each side of the triangle); a spike 2-6 in that face
    const std::vector<Point> p = with({Point(2.2, 0.6), Point(0.7, 2.4), Point(3.2, 2.9)});
    CHECK(check_against_oracle(p, {{0, 4}, {4, 5}, {5, 0}, {2, 6}}) == 1);
  }
  SECTION("a bow tie hanging from a bridge")
  {
    // two triangles sharing vertex 4 (a pinch of the big face), hung from corner 0 by the bridge 0-6
    const std::vector<Point> p = with({Point(2, 2.1), Point(1.1, 2.9), Point(0.9, 1.8), Point(3.0, 1.2), Point(3.1, 2.3)});
    CHECK(check_against_oracle(p, {{4, 5}, {5, 6}, {6, 4}, {4, 7}, {7, 8}, {8, 4}, {0, 6}}) == 1);
  }
  SECTION("the same segment inside one occurrence's wedge and outside the other's")
  {
    // a star of three spikes at the centre 4: its three wedges; chords from 4 must enter the right one
    const std::vector<Point> p = with({Point(2, 2), Point(2, 3.3), Point(0.8, 1.3), Point(3.1, 1.1)});
    CHECK(check_against_oracle(p, {{4, 5}, {4, 6}, {4, 7}, {0, 6}}) == 1);
  }
}

TEST_CASE("weak faces: a face with an isolated point or an island is left to the LP", "[mwt][lmt][weak_faces]")
{
  // the emptiness argument: every triangle of the program is empty, so a face holding a point has none
  const std::vector<Point> p{Point(0, 0), Point(4, 0), Point(4, 4), Point(0, 4), Point(1.3, 1.1), Point(2.6, 2.2),
                             Point(2.9, 1.4), Point(2.2, 2.9)};
  // the triangle 4-6-7 hung from corner 0 by the bridge 0-4; point 5 (outside the triangle) isolated in the
  // weakly simple face around them: faces outer, triangle (solved), that face (not solved)
  const Face_programs isolated = run_face_programs(p, {{0, 4}, {4, 6}, {6, 7}, {7, 4}}, 1);
  CHECK(isolated.faces == 3);
  CHECK(isolated.solved == 1);
  CHECK(isolated.weakly_simple == 0);
  // the same triangle as an island, and the spike 0-5: the face around the island is refused
  const Face_programs island = run_face_programs(p, {{0, 5}, {4, 6}, {6, 7}, {7, 4}}, 1);
  CHECK(island.solved == 1);
  CHECK(island.weakly_simple == 0);
  // one isolated point: the spoke program solves a simple face, not a weakly simple one (simple faces only)
  const std::vector<Point> q{Point(0, 0), Point(4, 0), Point(4, 4), Point(0, 4), Point(2, 2.1), Point(1, 0.9)};
  const std::vector<Point> q_simple(q.begin(), q.end() - 1);
  const Face_programs simple = run_face_programs(q_simple, {}, 1);
  CHECK(simple.faces == 2);
  CHECK(simple.solved == 1);
  const Face_programs spiked = run_face_programs(q, {{0, 5}}, 1);
  CHECK(spiked.faces == 2);
  CHECK(spiked.solved == 0);
}

TEST_CASE("weak faces: random connected certain edges on small sets, against the constrained oracle",
          "[mwt][lmt][weak_faces][oracle]")
{
  // a random spanning tree of non-crossing valid segments (with a few extra edges closing cycles): the certain
  // edges connect every point, so every bounded face is a weakly simple walk and must be solved
  std::size_t weak = 0;
  for(unsigned seed = 0; seed < 12; ++seed) {
    const std::vector<Point> p = seed % 2 ? clustered_points(10, 700 + seed) : uniform_points(10, 700 + seed);
    std::vector<Segment> segments = valid_segments(p);
    std::mt19937 g(seed);
    std::shuffle(segments.begin(), segments.end(), g);
    std::vector<int> parent(p.size());
    std::iota(parent.begin(), parent.end(), 0);
    std::function<int(int)> root = [&](int v) { return parent[std::size_t(v)] == v ? v : root(parent[std::size_t(v)]); };
    std::vector<Segment> certain;
    int extra = int(seed % 3);
    for(const Segment& s : segments) {
      if(is_hull_segment(p, s)) continue;
      bool crosses = false;
      for(const Segment& c : certain) crosses = crosses || segments_cross(p, s, c);
      if(crosses) continue;
      const int a = root(s.first), b = root(s.second);
      if(a != b) parent[std::size_t(a)] = b;
      else if(extra-- <= 0) continue;
      certain.push_back(s);
    }
    INFO("seed " << seed << ", " << certain.size() << " certain edges");
    weak += check_against_oracle(p, certain);
  }
  CHECK(weak >= 6);
}

TEST_CASE("weak faces: random wheels with one certain spoke need no LP", "[mwt][lmt][weak_faces][wheels]")
{
  // the LMT-skeleton of some random wheels keeps exactly one spoke certain: the centre's face has a dangling
  // edge. The pipeline solves it by the program now; its weight is the triangle LP's over every empty triangle.
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 P;
  int found = 0;
  for(int k = 16; k <= 30; ++k) {
    CGAL::Random rng(20260000u + unsigned(k));   // the seeds of bench_mwt --random-wheels
    int found_k = 0;
    for(int trial = 0; trial < 40 && found_k < 1; ++trial) {
      const std::vector<P> p = MDCS_test::random_wheel<P>(k, rng);
      std::size_t spokes = 0;
      {
        MWT::Minimum_weight_triangulation_lp_2<K> stages(p, lmt());
        stages.compute_candidate_edges();
        stages.compute_empty_triangles();   // runs the skeleton
        const auto& edges = stages.candidate_edges();
        for(std::size_t e = 0; e < edges.size(); ++e)
          spokes += stages.lmt_edge_states()[e] == MWT::internal::lmt_certain && (edges[e].first == 0 || edges[e].second == 0);
      }
      if(spokes != 1) continue;
      ++found_k;
      INFO("k " << k << ", trial " << trial);
      const MWT::Mwt_result r = MWT::minimum_weight_triangulation_2(p, lmt());
      REQUIRE(r.has_triangulation());
      CHECK(r.statistics.lp_columns == 0);   // bench_mwt's pipeline_without_lp
      CHECK(r.statistics.lmt_solved_faces + 1 == r.statistics.lmt_faces);
      CHECK(r.statistics.dp_weakly_simple_faces >= 1);
      CHECK(independent_triangulation_check(p, r.triangles));
      MWT::Mwt_options lp;
      lp.pruning = MWT::Pruning::none;
      lp.solver = MWT::Lp_solver_choice::clp;
      const MWT::Mwt_result q = MWT::minimum_weight_triangulation_2(p, lp);
      REQUIRE(q.has_triangulation());
      CHECK(r.weight == Approx(q.weight).epsilon(1e-12));
      // every thread count gives the same triangles
      for(std::size_t threads : MDCS_test::thread_counts) {
        MWT::Mwt_options o = lmt();
        o.threads = threads;
        const MWT::Mwt_result s = MWT::minimum_weight_triangulation_2<CGAL::Parallel_tag>(p, o);
        CHECK(s.triangles == r.triangles);
        CHECK(s.weight == r.weight);
        CHECK(s.statistics.dp_weakly_simple_faces == r.statistics.dp_weakly_simple_faces);
      }
      // the LP path's exact support certificate (its skeleton on the support also runs the face programs)
      const MWT::Mwt_result c = MWT::minimum_weight_triangulation_2(p);
      CHECK(c.status == MWT::Mwt_status::certified_optimal);
      if(c.certificate_support > 0) CHECK(c.certificate_exact);
      CHECK(c.weight == Approx(q.weight).epsilon(1e-12));
    }
    found += found_k;
  }
  CHECK(found >= 5);
}

#endif // MDCS_HAS_CLP && MDCS_HAS_GLPK
