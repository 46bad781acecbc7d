// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Issue 29, items 3 and 7: the MWT pipeline with CGAL::Parallel_tag gives the sequential result (triangles in the
// same order, weight and bounds to the last bit, status, certificate, every count) for 1, 2, 3 and 8 threads (8
// oversubscribes a 2-core machine on purpose), stage by stage (candidate edges, skeleton states) and in the end,
// on uniform, clustered, cocircular and wheel inputs; it equals the exhaustive oracle on small sets; progress
// comes from the calling thread only and cancellation works in every parallel stage; the parallel validation
// gives the same verdicts for every thread count. Tagged [parallel]: these cases also run under ThreadSanitizer
// (CMake option MDCS_TSAN). No Catch assertion runs inside a parallel body.

#if defined(MDCS_HAS_CLP) && defined(MDCS_HAS_GLPK)

#include "mwt_exhaustive_oracle.h"
#include <MDCS_test/thread_counts.h>

#include <CGAL/MDCS/concurrency.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <mutex>
#include <random>
#include <set>
#include <string>
#include <thread>
#include <vector>

using namespace mwt_test;

namespace {

using MDCS_test::thread_counts;

// The lattice points on the circle x^2 + y^2 = (5 * 13 * 17)^2 (every one exactly cocircular: 4 * 3^3 = 108),
// and random lattice points inside it.
std::vector<Point> cocircular_points(int inside, unsigned seed)
{
  const long long R = 5 * 13 * 17, R2 = R * R;
  std::vector<Point> p;
  for(long long x = -R; x <= R; ++x) {
    const long long y2 = R2 - x * x;
    const long long y = std::llround(std::sqrt(double(y2)));
    if(y * y != y2) continue;
    p.emplace_back(double(x), double(y));
    if(y != 0) p.emplace_back(double(x), double(-y));
  }
  std::mt19937 g(seed);
  std::uniform_int_distribution<long long> u(-R, R);
  std::set<std::pair<long long, long long>> taken;
  while(inside > 0) {
    const long long x = u(g), y = u(g);
    if(x * x + y * y >= R2 - 2 * R || !taken.insert(std::make_pair(x, y)).second) continue;
    p.emplace_back(double(x), double(y));
    --inside;
  }
  return p;
}

struct Run
{
  MWT::Mwt_result result;
  std::vector<std::pair<int, int>> candidate_edges;
  std::vector<char> skeleton;
};

// The stages one by one through the class (to compare their outputs), then the one-shot entry point.
template <class Tag>
Run run(const std::vector<Point>& p, MWT::Mwt_options o, std::size_t threads)
{
  o.threads = threads;
  Run r;
  {
    MWT::Minimum_weight_triangulation_lp_2<K, Tag> m(p, o);
    m.compute_candidate_edges();
    r.candidate_edges = m.candidate_edges();
    m.compute_empty_triangles();
    r.skeleton = m.lmt_edge_states();
  }
  r.result = MWT::minimum_weight_triangulation_2<Tag>(p, o);
  return r;
}

bool same_double(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

void check_identical(const Run& a, const Run& b)
{
  CHECK(a.candidate_edges == b.candidate_edges);
  CHECK(a.skeleton == b.skeleton);
  const MWT::Mwt_result &x = a.result, &y = b.result;
  CHECK(x.status == y.status);
  CHECK(x.triangles == y.triangles);   // same triangles in the same order
  CHECK(same_double(x.weight, y.weight));
  CHECK(same_double(x.lower_bound, y.lower_bound));
  CHECK(same_double(x.lp_objective, y.lp_objective));
  CHECK(x.lp_integral == y.lp_integral);
  CHECK(x.certificate_exact == y.certificate_exact);
  CHECK(x.certificate_support == y.certificate_support);
  CHECK(x.message == y.message);
  const MWT::Mwt_statistics &s = x.statistics, &t = y.statistics;
  CHECK(s.candidate_edges == t.candidate_edges);
  CHECK(s.empty_triangles == t.empty_triangles);
  CHECK(s.lp_columns == t.lp_columns);
  CHECK(s.lp_rows == t.lp_rows);
  CHECK(s.lmt_certain_edges == t.lmt_certain_edges);
  CHECK(s.lmt_possible_edges == t.lmt_possible_edges);
  CHECK(s.lmt_faces == t.lmt_faces);
  CHECK(s.lmt_solved_faces == t.lmt_solved_faces);
  CHECK(s.dp_triangles == t.dp_triangles);
  CHECK(s.lmt_largest_face == t.lmt_largest_face);
  CHECK(s.dp_exact_faces == t.dp_exact_faces);
  CHECK(s.dp_exact_decisions == t.dp_exact_decisions);
}

void check_all_thread_counts(const std::vector<Point>& p, const MWT::Mwt_options& o)
{
  const Run sequential = run<CGAL::Sequential_tag>(p, o, 8);   // the tag wins: one thread
  CHECK(sequential.result.statistics.threads == 1);
  REQUIRE(sequential.result.has_triangulation());
  CHECK(independent_triangulation_check(p, sequential.result.triangles));
  for(std::size_t threads : thread_counts) {
    INFO("threads " << threads);
    const Run parallel = run<CGAL::Parallel_tag>(p, o, threads);
    CHECK(parallel.result.statistics.threads == (CGAL::MDCS::has_parallel_support() ? threads : 1u));
    check_identical(sequential, parallel);
  }
}

} // namespace

TEST_CASE("parallel MWT pipeline: the same result for 1, 2, 3 and 8 threads", "[mwt][parallel]")
{
  MWT::Mwt_options o;
  o.use_lmt_skeleton = true;
  SECTION("uniform")
  {
    // several blocks in every stage (256 points per candidate block, 512 per triangle block)
    const auto p = uniform_points(2000, 29);
    check_all_thread_counts(p, o);
  }
  SECTION("clustered") { check_all_thread_counts(clustered_points(1200, 30), o); }
  SECTION("cocircular lattice points and points inside")
  {
    const auto p = cocircular_points(300, 31);
    REQUIRE(p.size() == 408);
    check_all_thread_counts(p, o);
  }
  SECTION("odd wheel: one face with one interior point, exact decisions")
  {
    const auto p = wheel(41);
    check_all_thread_counts(p, o);
    CHECK(MWT::minimum_weight_triangulation_2<CGAL::Parallel_tag>(p, o).statistics.dp_exact_decisions > 0);
  }
  SECTION("even wheel: the centre is collinear with antipodal pairs") { check_all_thread_counts(wheel(40), o); }
  SECTION("66 points in convex position and one inside: a face of 66 vertices (a long cycle of the face tracing)")
  {
    std::mt19937 g(36);
    std::uniform_real_distribution<double> u(0, 2 * M_PI);
    std::vector<Point> q{Point(0.1, 0.05)};
    for(int i = 0; i < 66; ++i) {
      const double a = u(g);
      q.emplace_back(2 * std::cos(a), std::sin(a));
    }
    check_all_thread_counts(q, o);
  }
}

TEST_CASE("parallel MWT, LP path: the same result for 1, 2, 3 and 8 threads", "[mwt][parallel]")
{
  MWT::Mwt_options o;   // diamond test, triangles, LP, exact support certificate (its skeleton and programs)
  check_all_thread_counts(uniform_points(500, 32), o);
  o.metric = MWT::Edge_metric::L1;   // every valid segment (the O(n^2) candidate loop in blocks)
  check_all_thread_counts(uniform_points(60, 33), o);
}

TEST_CASE("parallel MWT against the exhaustive oracle and brute force", "[mwt][parallel]")
{
  MWT::Mwt_options o;
  o.use_lmt_skeleton = true;
  o.threads = 3;
  for(unsigned seed = 0; seed < 8; ++seed) {
    const int n = 9 + int(seed % 6);
    const auto p = seed % 2 ? clustered_points(n, 100 + seed) : uniform_points(n, 100 + seed);
    const Exhaustive_mwt oracle = exhaustive_mwt(p);
    const auto r = MWT::minimum_weight_triangulation_2<CGAL::Parallel_tag>(p, o);
    INFO("seed " << seed << " n " << n);
    REQUIRE(r.has_triangulation());
    CHECK(r.weight == Approx(oracle.weight).epsilon(1e-12));
    CHECK(r.lower_bound <= oracle.weight * (1 + 1e-12));
  }
  for(unsigned seed = 0; seed < 6; ++seed) {
    const auto p = uniform_points(8, 200 + seed);
    o.threads = 8;
    const auto r = MWT::minimum_weight_triangulation_2<CGAL::Parallel_tag>(p, o);
    CHECK(r.weight == Approx(brute_force_mwt(p)).epsilon(1e-12));
  }
}

TEST_CASE("parallel MWT: progress from the calling thread, cancellation in every parallel stage", "[mwt][parallel]")
{
  const auto p = uniform_points(4000, 34);
  const std::thread::id caller = std::this_thread::get_id();
  for(std::size_t threads : {2u, 8u}) {
    MWT::Mwt_options o;
    o.use_lmt_skeleton = true;
    o.threads = threads;
    bool other_thread = false;
    std::map<std::string, std::vector<double>> seen;
    o.progress = [&](const char* stage, double f) {
      if(std::this_thread::get_id() != caller) other_thread = true;
      seen[stage].push_back(f);
      return true;
    };
    const auto r = MWT::minimum_weight_triangulation_2<CGAL::Parallel_tag>(p, o);
    CHECK(r.status == MWT::Mwt_status::certified_optimal);
    CHECK_FALSE(other_thread);
    for(const char* stage : {"candidate edges", "empty triangles", "LMT-skeleton", "face dynamic program", "certificate"}) {
      INFO(stage << ", threads " << threads);
      REQUIRE(seen.count(stage) == 1);
      const std::vector<double>& f = seen[stage];
      CHECK(f.front() == 0.0);
      CHECK(f.back() == 1.0);
      CHECK(std::is_sorted(f.begin(), f.end()));
    }
    // cancelled inside each stage: at its first report after the start (at its start when the uncancelled run
    // reported only the two ends). Not "strictly between 0 and 1": which fractions the calling thread reports
    // depends on how the workers are scheduled (8 threads on 2 cores may report none in between); a stage's last
    // report (1) comes from Parallel_progress::finish(), which throws when cancelled.
    for(const std::string stage : {"candidate edges", "empty triangles", "LMT-skeleton", "face dynamic program", "certificate"}) {
      INFO("cancel in " << stage << ", threads " << threads);
      const bool inside = seen[stage].size() > 2;
      o.progress = [&](const char* s, double f) { return !(s == stage && (inside ? f > 0 : true)); };
      CHECK_THROWS_AS(MWT::minimum_weight_triangulation_2<CGAL::Parallel_tag>(p, o), CGAL::MDCS::Operation_cancelled);
    }
  }
}

TEST_CASE("parallel Hilbert order and stable sort: the sequential order for every thread count", "[mwt][parallel]")
{
  // 40,000 points: above the size where the Hilbert sort's first levels run in parallel (2^15)
  std::vector<Point> p = uniform_points(40000, 37);
  for(int i = 0; i < 2000; ++i) p.emplace_back(0.5, double(i) / 2000);   // equal x coordinates (ties of the splits)
  // the reference: CGAL's sequential median Hilbert sort of the indices
  typedef CGAL::Spatial_sort_traits_adapter_2<K, CGAL::Pointer_property_map<Point>::const_type> Traits;
  std::vector<int> sequential(p.size());
  for(std::size_t i = 0; i < p.size(); ++i) sequential[i] = int(i);
  const std::vector<Point>& cp = p;
  CGAL::Hilbert_sort_median_2<Traits, CGAL::Sequential_tag> cgal_sort(Traits(CGAL::make_property_map(cp)));
  cgal_sort(sequential.begin(), sequential.end());
  CHECK(MWT::internal::hilbert_order(p) == sequential);
  std::vector<int> by_x(p.size());
  for(std::size_t i = 0; i < p.size(); ++i) by_x[i] = int(i);
  auto less_x = [&](int a, int b) { return p[std::size_t(a)].x() < p[std::size_t(b)].x(); };   // many ties
  std::vector<int> stable = by_x;
  std::stable_sort(stable.begin(), stable.end(), less_x);
  for(std::size_t threads : thread_counts) {
    INFO("threads " << threads);
    const MWT::internal::Parallel_stage par(threads);
    CHECK(MWT::internal::hilbert_order(p, par) == sequential);
    std::vector<int> v = by_x;
    MWT::internal::parallel_stable_sort(v, less_x, par);
    CHECK(v == stable);
  }
}

TEST_CASE("parallel validation: the same verdicts for every thread count", "[mwt][parallel]")
{
  const auto p = uniform_points(2000, 35);
  MWT::Mwt_options o;
  o.use_lmt_skeleton = true;
  const auto r = MWT::minimum_weight_triangulation_2(p, o);
  REQUIRE(r.has_triangulation());
  MWT::internal::Indexed_points_2<K> pts(p);
  MWT::internal::Point_grid_2 grid(pts);
  const auto hull = MWT::internal::checked_hull_boundary(pts);
  std::vector<std::vector<std::array<int, 3>>> broken;
  auto t = r.triangles;
  std::swap(t[7][1], t[7][2]);   // clockwise
  broken.push_back(t);
  t = r.triangles;
  t[5] = t[6];   // a triangle twice, one missing
  broken.push_back(t);
  t = r.triangles;
  t[9][0] = int(p.size());   // out of range
  broken.push_back(t);
  t = r.triangles;
  t.pop_back();   // too few
  broken.push_back(t);
  for(std::size_t threads : thread_counts) {
    const MWT::internal::Parallel_stage par(threads);
    CHECK(MWT::internal::validate_triangulation(pts, grid, hull, r.triangles, par).empty());
    for(const auto& b : broken) {
      const std::string one = MWT::internal::validate_triangulation(pts, grid, hull, b);
      CHECK_FALSE(one.empty());
      CHECK(MWT::internal::validate_triangulation(pts, grid, hull, b, par) == one);
    }
  }
}

#endif
