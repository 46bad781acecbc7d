// Parallel single-source exact propagation (issue 31 item 3; internal/vertex_oriented_parallel.h):
//  - distances and nearest sources identical, bit for bit, for 1, 2, 3 and 8 threads;
//  - equal to the window propagation (full field, an independent schedule) and to the sequential vertex-oriented
//    schedule to 1e-12 relative;
//  - on a real mesh (CGAL's elephant when installed), a bumpy sphere, a flat mesh with a hole (exact: Euclidean
//    distances around the hole), several sources, a face-location source, a distance limit;
//  - runs it does not serve (stop targets) fall back to the sequential schedule; Sequential_tag stays sequential.
// Tagged [parallel]: the ThreadSanitizer build runs these cases alone.
#include <catch2/catch.hpp>

#include <MDCS_test/cgal_meshes.h>
#include <MDCS_test/geodesic_oracles.h>
#include <MDCS_test/geodesic_test_meshes.h>
#include <MDCS_test/mesh_generators.h>
#include <MDCS_test/thread_counts.h>
#include <MDCS_test/geodesic_test_geometry.h>

#include <CGAL/Polyhedral_geodesics_3/Exact_geodesic_distances_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace {

namespace PG = CGAL::Polyhedral_geodesics_3;
using namespace MDCS_test::Epick_surface_mesh;
typedef PG::Exact_geodesic_distances_3<Mesh> Single_source_geodesics;

struct Parallel_run
{
  std::vector<double> distances;
  std::vector<std::size_t> nearest;
  bool used_parallel = false;
};

// One distances_only run; threads 0: the sequential schedule (Sequential_tag).
Parallel_run parallel_run(const Mesh& m, const std::vector<Source>& sources, std::size_t threads, double limit = -1,
                          bool stop_target = false)
{
  Single_source_geodesics g(m, PG::Geodesic_memory_mode::distances_only);
  if(threads == 0)
    g.set_concurrency(CGAL::Sequential_tag());
  else
    g.set_concurrency(CGAL::Parallel_tag(), threads);
  if(limit >= 0) {
    g.set_vertex_oriented_full_field(true); // limits run on the vertex-oriented schedule then
    g.set_distance_limit(limit);
  }
  if(stop_target)
    g.set_stop_targets(std::vector<vertex_descriptor>{*vertices(m).begin()});
  add_sources(g, sources);
  Parallel_run r;
  for(vertex_descriptor v : vertices(m)) {
    const auto d = g.nearest_source(v);
    r.distances.push_back(d.first);
    r.nearest.push_back(d.second);
  }
  r.used_parallel = g.used_parallel_propagation();
  return r;
}

bool bitwise_equal(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

// The checks of every case: every thread count gives the 1-thread result bit for bit; it equals the sequential
// schedule and the window propagation to 1e-12 relative. Returns the 1-thread distances.
std::vector<double> check_parallel(const Mesh& m, const std::vector<Source>& sources, const std::string& what,
                                   double limit = -1)
{
  INFO(what);
  const Parallel_run one = parallel_run(m, sources, 1, limit);
  CHECK(one.used_parallel);
  for(std::size_t t : MDCS_test::thread_counts) {
    if(t == 1)
      continue;
    INFO("threads " << t);
    const Parallel_run r = parallel_run(m, sources, t, limit);
    CHECK(r.used_parallel);
    CHECK(bitwise_equal(one.distances, r.distances));
    CHECK(one.nearest == r.nearest);
  }
  const double floor_value = MDCS_test::tolerance * MDCS_test::bbox_diagonal(m);
  const Parallel_run sequential = parallel_run(m, sources, 0, limit);
  CHECK_FALSE(sequential.used_parallel);
  const auto vs_sequential = MDCS_test::compare_distances(sequential.distances, one.distances, floor_value);
  INFO("parallel vs sequential schedule: " << vs_sequential);
  CHECK(vs_sequential.ok(MDCS_test::tolerance));
  // the oracle: the window propagation (full field), cut at the limit
  Single_source_geodesics full(m);
  add_sources(full, sources);
  std::vector<double> oracle = MDCS_test::vertex_distances(full, m);
  if(limit >= 0)
    for(double& d : oracle)
      if(d > limit)
        d = std::numeric_limits<double>::infinity();
  const auto vs_windows = MDCS_test::compare_distances(oracle, one.distances, floor_value);
  INFO("parallel vs window propagation: " << vs_windows);
  CHECK(vs_windows.ok(MDCS_test::tolerance));
  return one.distances;
}

} // namespace

TEST_CASE("parallel single source: a real mesh, identical for every thread count", "[geodesics][parallel]")
{
  Mesh m;
  if(!MDCS_test::read_mesh(MDCS_test::cgal_demo_mesh("elephant.off"), m)) {
    WARN("CGAL's elephant.off not installed: a bumpy sphere instead");
    m = make_mesh(MDCS_test::bumpy_sphere<Point_3>(4, 0.2, 11));
  }
  check_parallel(m, {at(*vertices(m).begin())}, "elephant, one vertex source");
}

TEST_CASE("parallel single source: bumpy sphere, several sources, face-location source", "[geodesics][parallel]")
{
  const Mesh m = make_mesh(MDCS_test::bumpy_sphere<Point_3>(4, 0.25, 5));
  const auto v = [&](std::size_t i) { return *std::next(vertices(m).begin(), std::ptrdiff_t(i)); };
  check_parallel(m, {at(v(0))}, "bumpy sphere, one source");
  check_parallel(m, {at(v(3)), at(v(500)), at(v(2000))}, "bumpy sphere, three sources");
  const face_descriptor f = *std::next(faces(m).begin(), 123);
  check_parallel(m, {at(Single_source_geodesics::Face_location(f, {{0.2, 0.3, 0.5}}))}, "bumpy sphere, point in a face");
  check_parallel(m, {at(Single_source_geodesics::Face_location(f, {{0.0, 0.4, 0.6}}))}, "bumpy sphere, point on an edge");
}

TEST_CASE("parallel single source: flat square with a hole, exact around it", "[geodesics][parallel]")
{
  const Mesh m = make_mesh(MDCS_test::square_with_hole<Point_3>(40, 12, 28, 15, 22));
  const std::vector<double> d = check_parallel(m, {at(*vertices(m).begin())}, "square with a hole");
  // flat: the vertices that see the source straight have their Euclidean distance
  const Point_3 s = m.point(*vertices(m).begin());
  std::size_t i = 0, checked = 0;
  for(vertex_descriptor v : vertices(m)) {
    const Point_3& p = m.point(v);
    if(p.y() <= s.y() + 1e-12 || p.x() <= s.x() + 1e-12) { // along the two sides through the source corner
      CHECK(std::abs(d[i] - std::sqrt(CGAL::squared_distance(p, s))) <= 1e-12);
      ++checked;
    }
    ++i;
  }
  CHECK(checked > 0);
}

TEST_CASE("parallel single source: distance limit", "[geodesics][parallel]")
{
  const Mesh m = make_mesh(MDCS_test::bumpy_sphere<Point_3>(4, 0.2, 7));
  const std::vector<Source> sources = {at(*vertices(m).begin())};
  const std::vector<double> d = check_parallel(m, sources, "bumpy sphere, limit 1.2", 1.2);
  std::size_t reached = 0, beyond = 0;
  for(double x : d)
    (std::isinf(x) ? beyond : reached) += 1;
  CHECK(reached > 0);
  CHECK(beyond > 0);
}

TEST_CASE("parallel single source: stop targets and Sequential_tag run sequentially", "[geodesics][parallel]")
{
  const Mesh m = make_mesh(MDCS_test::bumpy_sphere<Point_3>(3, 0.2, 3));
  const std::vector<Source> sources = {at(*std::next(vertices(m).begin(), 100))};
  const Parallel_run stopped = parallel_run(m, sources, 2, -1, true);
  CHECK_FALSE(stopped.used_parallel);
  CHECK(std::isfinite(stopped.distances[0]));
  const Parallel_run sequential = parallel_run(m, sources, 0);
  CHECK_FALSE(sequential.used_parallel);
  Single_source_geodesics g(m, PG::Geodesic_memory_mode::distances_only);
  g.set_concurrency(CGAL::Parallel_tag(), 1);
  CHECK(g.threads() == 1);
  g.set_concurrency(CGAL::Sequential_tag(), 4);
  CHECK(g.threads() == 1);
}
