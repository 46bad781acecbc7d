// The baseline geodesic distance classes: Dijkstra_geodesic_distances_3 (shortest paths along the mesh edges)
// and Fast_marching_geodesic_distances_3 (Kimmel and Sethian's fast marching).
//  - Dijkstra equals the independent edge-graph oracle, bounds the exact distances from above, and its
//    multi-source result is the minimum of the single-source ones, bit for bit.
//  - Fast marching is checked against what can be proved: on a convex planar mesh every update is at least the
//    Euclidean distance (the upwind point Z of a two-point update lies on the segment XY, and
//    t = |CZ| + lambda T_X + (1 - lambda) T_Y >= |CZ| + |Z - s| >= |C - s| by the convexity of |. - s|), and every
//    value is at most Dijkstra's (T(C) <= T(X) + |XC| for every neighbour X). Its error against the Euclidean
//    distance (planar grids) and against the exact distance (bumpy sphere, CGAL's elephant) is bounded by
//    measured values with a margin.
//  - Both: surface-point sources, distance limit and stop targets, FaceGraph models, invalid input, progress
//    and cancellation. Their paths: test_baseline_geodesic_paths.cpp.
#include <catch2/catch.hpp>

#include <MDCS_test/cgal_meshes.h>
#include <MDCS_test/geodesic_oracles.h>
#include <MDCS_test/geodesic_test_meshes.h>
#include <MDCS_test/mesh_generators.h>
#include <MDCS_test/geodesic_test_geometry.h>

#include <CGAL/Polyhedral_geodesics_3/Dijkstra_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Exact_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Fast_marching_geodesic_distances_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace {

using namespace MDCS_test::Epick_surface_mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
namespace PG = CGAL::Polyhedral_geodesics_3;
typedef PG::Dijkstra_geodesic_distances_3<Mesh> Dijkstra;
typedef PG::Fast_marching_geodesic_distances_3<Mesh> Fmm;
typedef PG::Exact_geodesic_distances_3<Mesh> Exact;
typedef Dijkstra::Face_location Face_location;
using MDCS_test::Vec3;

using MDCS_test::tolerance;
using MDCS_test::inf;

using MDCS_test::vertex_distances;

template <class G, class Sources>
std::vector<double> run(const Mesh& m, const Sources& sources)
{
  G g(m, PG::Geodesic_memory_mode::distances_only);
  for(auto s : sources)
    g.add_source(s);
  return vertex_distances(g, m);
}

using MDCS_test::index_of;

typedef MDCS_test::Named_soup<Point_3> Named_soup;

std::vector<Named_soup> assorted_meshes()
{
  return {{"planar grid 8x8", MDCS_test::planar_grid<Point_3>(8, 8)},
          {"jittered grid 12x12", MDCS_test::jittered_planar_grid<Point_3>(12, 12, 1.0, 1.0, 0.2, 42)},
          {"bumpy sphere", MDCS_test::bumpy_sphere<Point_3>(2, 0.1, 8)},
          {"square with a hole", MDCS_test::square_with_hole<Point_3>(10, 3, 6, 4, 7)},
          {"height field", MDCS_test::height_field_grid<Point_3>(12, 0.3, 5)},
          {"subdivided cube", MDCS_test::subdivided_cube<Point_3>(4)},
          {"two components", MDCS_test::two_grids<Point_3>(5)}};
}

// Mean and largest relative error of `got` against `expected` over the vertices with expected > min_distance,
// and the smallest ratio got / expected there.
struct Error_summary
{
  double mean = 0, max = 0, min_ratio = inf;
  std::size_t count = 0;
};

Error_summary relative_errors(const std::vector<double>& expected, const std::vector<double>& got, double min_distance)
{
  Error_summary s;
  for(std::size_t i = 0; i < got.size(); ++i) {
    if(!(expected[i] > min_distance) || !std::isfinite(expected[i]))
      continue;
    const double r = std::abs(got[i] - expected[i]) / expected[i];
    s.mean += r;
    s.max = std::max(s.max, r);
    s.min_ratio = std::min(s.min_ratio, got[i] / expected[i]);
    ++s.count;
  }
  if(s.count > 0)
    s.mean /= double(s.count);
  return s;
}

std::ostream& operator<<(std::ostream& os, const Error_summary& s)
{
  return os << "mean relative error " << s.mean << ", max " << s.max << ", min ratio " << s.min_ratio << " over "
            << s.count << " vertices";
}

// got[i] <= bound[i] (relative tolerance) everywhere; returns the number of violations
std::size_t count_above(const std::vector<double>& got, const std::vector<double>& bound, double floor_value)
{
  std::size_t n = 0;
  for(std::size_t i = 0; i < got.size(); ++i)
    if(got[i] > bound[i] * (1 + tolerance) + floor_value)
      ++n;
  return n;
}

} // namespace

// -------------------------------------------------------------------------------------------------------------
// Dijkstra

TEST_CASE("dijkstra geodesics: the edge-graph oracle, above the exact distances, several sources", "[geodesics][dijkstra]")
{
  for(const Named_soup& ns : assorted_meshes()) {
    const Mesh m = make_mesh(ns.soup);
    const double floor_value = tolerance * MDCS_test::bbox_diagonal(m);
    for(std::size_t count : {std::size_t(1), std::size_t(3)}) {
      const auto sources = MDCS_test::spread_vertices(m, count, 5);
      INFO(ns.name << ", " << sources.size() << " source(s)");
      const std::vector<double> oracle = MDCS_test::dijkstra_vertex_distances(m, sources);
      Dijkstra g(m);
      for(auto s : sources)
        g.add_source(s);
      const std::vector<double> got = vertex_distances(g, m);
      const auto cmp = MDCS_test::compare_distances(oracle, got, floor_value);
      INFO("vs the oracle: " << cmp);
      CHECK(cmp.ok(tolerance));
      CHECK(g.statistics().vertex_updates >= num_vertices(m) / 2);
      CHECK_FALSE(g.statistics().stopped_early);

      const std::vector<double> exact = run<Exact>(m, sources);
      CHECK(count_above(exact, got, floor_value) == 0);

      // several sources: the minimum of the single-source distances, bit for bit, and the argmin
      std::vector<std::vector<double>> single;
      for(auto s : sources)
        single.push_back(run<Dijkstra>(m, std::vector<vertex_descriptor>{s}));
      std::size_t differ = 0, wrong_source = 0, k = 0;
      for(vertex_descriptor v : vertices(m)) {
        double best = inf;
        for(const auto& d : single)
          best = std::min(best, d[k]);
        if(got[k] != best)
          ++differ;
        const auto ns_v = g.nearest_source(v);
        if(std::isfinite(best) ? (ns_v.second >= sources.size() || single[ns_v.second][k] != best || ns_v.first != best)
                               : ns_v.second != Dijkstra::no_source)
          ++wrong_source;
        ++k;
      }
      CHECK(differ == 0);
      CHECK(wrong_source == 0);
    }
  }
}

// -------------------------------------------------------------------------------------------------------------
// Fast marching

TEST_CASE("fast marching: a planar wavefront is exact, also across obtuse corners", "[geodesics][fmm]")
{
  // Sources on one side of the square: the distance is the distance to that side. The planar update is exact for a
  // planar front, provided that every vertex is updated from a triangle whose sector at the vertex contains the
  // upwind direction and whose two other corners are final first: on the jittered grid (about 1500 obtuse corners)
  // this needs the virtual triangles of the obtuse corners (without them the error reaches 0.006).
  for(const Named_soup& ns : {Named_soup{"planar grid 16x16", MDCS_test::planar_grid<Point_3>(16, 16)},
                              Named_soup{"jittered grid 24x24", MDCS_test::jittered_planar_grid<Point_3>(24, 24, 1.0, 1.0, 0.2, 3)}}) {
    const Mesh m = make_mesh(ns.soup);
    for(int side = 0; side < 4; ++side) {
      INFO(ns.name << ", sources on side " << side);
      const Vec3 corners[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
      const Vec3 a = corners[side], b = corners[(side + 1) % 4];
      Fmm g(m);
      for(vertex_descriptor v : vertices(m))
        if(MDCS_test::distance_to_segment(MDCS_test::vertex_vec3(m, v), a, b) < 1e-12)
          g.add_source(v);
      CHECK(g.number_of_sources() >= 17);
      double worst = 0;
      for(vertex_descriptor v : vertices(m))
        worst = std::max(worst, std::abs(g.distance(v) - MDCS_test::distance_to_segment(MDCS_test::vertex_vec3(m, v), a, b)));
      INFO("largest error " << worst);
      CHECK(worst <= 1e-14);
    }
  }
}

TEST_CASE("fast marching: planar grids, Euclidean distance from a corner, an interior vertex, a surface point",
          "[geodesics][fmm]")
{
  // Fast marching is first order: the front is approximated by a plane in every triangle, which overestimates the
  // distance where the front is strongly curved, i.e. on the first rings around a point source; that error is then
  // carried along (a relative error decaying like 1 / distance). Measured mean / largest relative error beyond 3
  // edge lengths from the source (vertex sources: the worse of the corner and the interior vertex):
  //   planar grid (right triangles)          vertex 1.5% / 4.0%   surface point 3.2% / 12.8%
  //   jittered grid (1543 obtuse corners)     vertex 1.7% / 5.4%   surface point 4.1% / 16.3%
  //   sheared grid (half the faces obtuse)    vertex 1.5% / 10.2%  surface point 3.3% / 21.2%
  //   equilateral triangles                   vertex 2.7% / 5.6%   surface point 3.6% / 9.6%
  // A surface-point source only initialises the three corners of its face, so more of the front is built from a
  // strongly curved start. The bounds below are the measured values plus 20 to 30%; Dijkstra's mean error, which
  // an engine whose two-point updates were never accepted would give, is 5 to 7% on these meshes (checked too).
  struct Case
  {
    Named_soup mesh;
    double edge, mean_vertex, max_vertex, mean_point, max_point;
  };
  const std::vector<Case> cases = {
      {{"planar grid 24x24", MDCS_test::planar_grid<Point_3>(24, 24)}, 1.0 / 24, 0.02, 0.05, 0.04, 0.16},
      {{"jittered grid 24x24", MDCS_test::jittered_planar_grid<Point_3>(24, 24, 1.0, 1.0, 0.2, 3)}, 1.0 / 24, 0.022, 0.07, 0.05, 0.2},
      {{"sheared grid 24x24", MDCS_test::sheared_planar_grid<Point_3>(24)}, 1.35 / 24, 0.02, 0.13, 0.04, 0.26},
      {{"subdivided triangle 24", MDCS_test::subdivided_triangle<Point_3>(24)}, 1.0 / 24, 0.033, 0.07, 0.045, 0.12}};
  for(const Case& c : cases) {
    const Mesh m = make_mesh(c.mesh.soup);
    const double floor_value = tolerance * MDCS_test::bbox_diagonal(m);
    const vertex_descriptor corner = MDCS_test::nearest_vertex(m, Vec3{0, 0, 0});
    const vertex_descriptor interior = MDCS_test::nearest_vertex(m, Vec3{0.55, 0.3, 0});
    const auto loc = MDCS_test::locate_point(m, Vec3{0.4137, 0.2219, 0});
    for(int kind = 0; kind < 3; ++kind) {
      const char* kinds[] = {"corner vertex", "interior vertex", "surface point"};
      INFO(c.mesh.name << ", source: " << kinds[kind]);
      Fmm g(m);
      Dijkstra dj(m);
      Vec3 s;
      if(kind < 2) {
        const vertex_descriptor v = kind == 0 ? corner : interior;
        g.add_source(v);
        dj.add_source(v);
        s = MDCS_test::vertex_vec3(m, v);
      } else {
        g.add_source(Face_location(loc.first, loc.second));
        dj.add_source(Face_location(loc.first, loc.second));
        s = MDCS_test::location_point(m, loc.first, loc.second);
      }
      std::vector<double> euclid;
      for(vertex_descriptor v : vertices(m))
        euclid.push_back(MDCS_test::dist(s, MDCS_test::vertex_vec3(m, v)));
      const std::vector<double> got = vertex_distances(g, m), dij = vertex_distances(dj, m);
      CHECK(count_above(euclid, got, floor_value) == 0); // never below the Euclidean distance (proved)
      CHECK(count_above(got, dij, floor_value) == 0);    // never above Dijkstra (proved)
      const Error_summary all = relative_errors(euclid, got, 1e-9);
      const Error_summary far = relative_errors(euclid, got, 3 * c.edge);
      INFO("all vertices: " << all << "; beyond 3 edges: " << far);
      const double mean_bound = kind < 2 ? c.mean_vertex : c.mean_point, max_bound = kind < 2 ? c.max_vertex : c.max_point;
      CHECK(all.mean < mean_bound);
      CHECK(far.max < max_bound);
      CHECK(all.min_ratio >= 1 - tolerance);
      // Dijkstra is worse on average (a sanity check of the comparison)
      CHECK(relative_errors(euclid, dij, 1e-9).mean > all.mean);

      // point queries: the interpolation stays within the same error; 0 at the source
      std::size_t below = 0;
      double worst_point = 0;
      for(const auto& q : MDCS_test::random_face_locations(m, 50, 9)) {
        const double e = MDCS_test::dist(s, MDCS_test::location_point(m, q.first, q.second));
        const double x = g.distance(Face_location(q.first, q.second));
        if(!(x >= e * (1 - tolerance) - floor_value))
          ++below;
        if(e > 3 * c.edge)
          worst_point = std::max(worst_point, (x - e) / e);
      }
      INFO("largest relative error at 50 random surface points beyond 3 edges: " << worst_point);
      CHECK(below == 0);
      CHECK(worst_point < max_bound);
      if(kind == 2)
        CHECK(g.distance(Face_location(loc.first, loc.second)) == 0);
    }
  }
}

TEST_CASE("fast marching vs exact geodesics: bumpy sphere and CGAL's elephant", "[geodesics][fmm]")
{
  // Measured mean relative error at the vertices (beyond 0.1% of the bounding box diagonal from the sources):
  //  - bumpy sphere (642 vertices, radial noise 10%): 2.5% (1 source), 3.4% (3 sources); Dijkstra 5.8%, 6.5%;
  //  - elephant (2775 vertices, a coarse mesh with many badly shaped triangles): 2.3%, 3.1%; Dijkstra 5.3%, 5.8%.
  // (On the refined elephant, 44k vertices, it is 0.9%: the error decreases with the edge length.) The bound 4%
  // leaves a margin of 20%; an engine without working two-point updates would be at Dijkstra's error.
  // Lower bounds: fast marching can go slightly below the exact distance on a curved surface (the planar update
  // does not see the curvature of the strip between X and Y; measured min ratio 0.994), and it stays far above the
  // straight 3D distance to the nearest source (the chord). Upper bound: Dijkstra's distance (proved).
  struct Case
  {
    std::string name;
    Mesh mesh;
    double mean_bound;
  };
  std::vector<Case> cases;
  cases.push_back({"bumpy sphere", make_mesh(MDCS_test::bumpy_sphere<Point_3>(3, 0.1, 5)), 0.04});
  {
    Mesh elephant;
    const std::string path = MDCS_test::cgal_demo_mesh("elephant.off");
    if(MDCS_test::read_mesh(path, elephant))
      cases.push_back({"elephant.off", elephant, 0.04});
    else
      WARN("CGAL demo mesh elephant.off not found (MDCS_CGAL_MESH_DIR = \"" << MDCS_test::cgal_demo_mesh_dir()
                                                                           << "\"); that part is skipped");
  }
  for(const Case& c : cases) {
    const Mesh& m = c.mesh;
    const double diag = MDCS_test::bbox_diagonal(m);
    const double floor_value = tolerance * diag;
    for(std::size_t count : {std::size_t(1), std::size_t(3)}) {
      const auto sources = MDCS_test::spread_vertices(m, count, 17);
      INFO(c.name << " (" << num_vertices(m) << " vertices), " << sources.size() << " source(s)");
      const std::vector<double> exact = run<Exact>(m, sources), fmm = run<Fmm>(m, sources),
                                dij = run<Dijkstra>(m, sources);
      const Error_summary e = relative_errors(exact, fmm, 1e-3 * diag), d = relative_errors(exact, dij, 1e-3 * diag);
      INFO("fast marching: " << e << "; Dijkstra: " << d);
      CHECK(e.mean < c.mean_bound);
      CHECK(e.mean < 0.6 * d.mean);
      CHECK(e.min_ratio > 0.97);
      CHECK(count_above(fmm, dij, floor_value) == 0);
      std::vector<double> chord;
      for(vertex_descriptor v : vertices(m)) {
        double x = inf;
        for(auto s : sources)
          x = std::min(x, MDCS_test::dist(MDCS_test::vertex_vec3(m, v), MDCS_test::vertex_vec3(m, s)));
        chord.push_back(x);
      }
      CHECK(count_above(chord, fmm, floor_value) == 0);
    }
  }
}

// -------------------------------------------------------------------------------------------------------------
// Both

TEST_CASE("baseline geodesics: sources at surface points", "[geodesics][dijkstra][fmm]")
{
  const Mesh m = make_mesh(MDCS_test::bumpy_sphere<Point_3>(2, 0.1, 3));
  const double floor_value = tolerance * MDCS_test::bbox_diagonal(m);
  const auto loc = MDCS_test::random_face_locations(m, 2, 5);
  const face_descriptor f = loc[0].first;
  const auto fv = MDCS_test::face_vertices(m, f);

  // Dijkstra from a point inside f (resp. on an edge of f): the minimum over the vertices of the face(s)
  // containing it of the straight distance plus Dijkstra's distance from there
  for(int on_edge = 0; on_edge < 2; ++on_edge) {
    INFO((on_edge ? "a source on an edge" : "a source inside a face"));
    const std::array<double, 3> b = on_edge ? std::array<double, 3>{0.3, 0.7, 0.0} : loc[0].second;
    const Vec3 s = MDCS_test::location_point(m, f, b);
    std::vector<vertex_descriptor> starts(fv.begin(), fv.end());
    if(on_edge) // the opposite corner of the face on the other side of the edge (fv[0], fv[1])
      starts.push_back(target(next(opposite(halfedge(f, m), m), m), m));
    std::vector<double> expected(num_vertices(m), inf);
    for(vertex_descriptor c : starts) {
      const auto d = MDCS_test::dijkstra_vertex_distances(m, std::vector<vertex_descriptor>{c});
      const double sc = MDCS_test::dist(s, MDCS_test::vertex_vec3(m, c));
      for(std::size_t i = 0; i < d.size(); ++i)
        expected[i] = std::min(expected[i], sc + d[i]);
    }
    Dijkstra g(m);
    g.add_source(Face_location(f, b));
    const auto cmp = MDCS_test::compare_distances(expected, vertex_distances(g, m), floor_value);
    INFO(cmp);
    CHECK(cmp.ok(tolerance));
    CHECK(g.distance(Face_location(f, b)) == 0);
    // in the source's face the distance is straight
    const std::array<double, 3> q = {0.1, 0.2, 0.7};
    CHECK(MDCS_test::relative_difference(g.distance(Face_location(f, q)), MDCS_test::dist(s, MDCS_test::location_point(m, f, q)),
                                         floor_value) <= tolerance);
    Fmm h(m);
    h.add_source(Face_location(f, b));
    CHECK(h.distance(Face_location(f, b)) == 0);
    CHECK(MDCS_test::relative_difference(h.distance(Face_location(f, q)), MDCS_test::dist(s, MDCS_test::location_point(m, f, q)),
                                         floor_value) <= tolerance);
    for(vertex_descriptor c : starts) // the corners are initialised with their straight distance
      CHECK(MDCS_test::relative_difference(h.distance(c), MDCS_test::dist(s, MDCS_test::vertex_vec3(m, c)), floor_value) <= tolerance);
    CHECK(count_above(vertex_distances(h, m), vertex_distances(g, m), floor_value) == 0);
  }

  // a point at a corner is that vertex; two sources: the nearest one
  for(int engine = 0; engine < 2; ++engine) {
    INFO((engine == 0 ? "Dijkstra" : "fast marching"));
    auto check = [&](auto& at_corner, auto& at_vertex, auto& two) {
      at_corner.add_source(Face_location(f, {0.0, 0.0, 1.0}));
      at_vertex.add_source(fv[2]);
      CHECK(vertex_distances(at_corner, m) == vertex_distances(at_vertex, m));
      two.add_source(fv[0]);
      two.add_source(Face_location(loc[1].first, loc[1].second));
      std::size_t wrong = 0;
      for(vertex_descriptor v : vertices(m)) {
        const auto r = two.nearest_source(v);
        if(!(r.second <= 1) || r.first != two.distance(v))
          ++wrong;
      }
      CHECK(wrong == 0);
      CHECK(two.nearest_source(fv[0]).second == 0);
      CHECK(two.nearest_source(Face_location(loc[1].first, loc[1].second)).second == 1);
      CHECK(two.nearest_source(Face_location(loc[1].first, loc[1].second)).first == 0);
    };
    if(engine == 0) {
      Dijkstra a(m), b(m), c(m);
      check(a, b, c);
    } else {
      Fmm a(m), b(m), c(m);
      check(a, b, c);
    }
  }
}

namespace {

// Below the limit and before the stop, everything is as in the full run, bit for bit. Point queries are finite
// only where their value is final; Dijkstra answers every point whose value is below the limit, fast marching may
// also answer +infinity where a corner of the face is beyond it (`points_complete` false).
template <class G>
void check_limit_and_targets(const Mesh& m, const std::string& name, bool points_complete)
{
  INFO(name);
  const auto sources = MDCS_test::spread_vertices(m, 2, 3);
  const auto queries = MDCS_test::random_face_locations(m, 40, 4);
  G full(m);
  for(auto s : sources)
    full.add_source(s);
  const std::vector<double> d = vertex_distances(full, m);
  std::vector<double> dq;
  for(const auto& q : queries)
    dq.push_back(full.distance(Face_location(q.first, q.second)));
  std::vector<double> sorted = d;
  std::sort(sorted.begin(), sorted.end());

  for(double fraction : {0.0, 0.3, 0.6}) {
    const double limit = fraction == 0.0 ? 0.0 : sorted[std::size_t(fraction * double(sorted.size()))];
    INFO("distance limit " << limit);
    G g(m);
    for(auto s : sources)
      g.add_source(s);
    g.set_distance_limit(limit);
    std::size_t wrong = 0, k = 0;
    for(vertex_descriptor v : vertices(m)) {
      const double x = g.distance(v);
      if(x != (d[k] <= limit ? d[k] : inf))
        ++wrong;
      if(x == inf && g.nearest_source(v).second != G::no_source)
        ++wrong;
      ++k;
    }
    CHECK(wrong == 0);
    std::size_t wrong_points = 0;
    for(std::size_t i = 0; i < queries.size(); ++i) {
      const double x = g.distance(Face_location(queries[i].first, queries[i].second));
      if(x != inf ? x != dq[i] || x > limit : points_complete && dq[i] <= limit * (1 - 1e-9))
        ++wrong_points;
    }
    CHECK(wrong_points == 0);
    CHECK(g.statistics().stopped_early);
    g.clear_distance_limit();
    CHECK(vertex_distances(g, m) == d);
  }

  const auto targets = MDCS_test::spread_vertices(m, 2, 11);
  G g(m);
  for(auto s : sources)
    g.add_source(s);
  g.set_stop_targets(targets);
  for(auto t : targets)
    CHECK(g.distance(t) == d[index_of(m, t)]);
  std::size_t wrong = 0, unreached = 0, k = 0;
  for(vertex_descriptor v : vertices(m)) {
    const double x = g.distance(v);
    if(x == inf)
      ++unreached;
    else if(x != d[k])
      ++wrong;
    ++k;
  }
  CHECK(wrong == 0);
  CHECK(unreached > 0);
  CHECK(g.statistics().stopped_early);
  std::size_t wrong_points = 0;
  for(std::size_t i = 0; i < queries.size(); ++i) {
    const double x = g.distance(Face_location(queries[i].first, queries[i].second));
    if(x != inf && x != dq[i])
      ++wrong_points;
  }
  CHECK(wrong_points == 0);
  g.clear_stop_targets();
  CHECK(vertex_distances(g, m) == d);
}

} // namespace

TEST_CASE("baseline geodesics: distance limit and stop targets", "[geodesics][dijkstra][fmm]")
{
  const Mesh m = make_mesh(MDCS_test::bumpy_sphere<Point_3>(3, 0.1, 2));
  check_limit_and_targets<Dijkstra>(m, "Dijkstra", true);
  check_limit_and_targets<Fmm>(m, "fast marching", false);
}

namespace {

template <template <class> class G, class M>
std::map<std::tuple<double, double, double>, double> distances_by_point(const M& m, const Vec3& source_position)
{
  G<M> g(m);
  g.add_source(MDCS_test::nearest_vertex(m, source_position));
  std::map<std::tuple<double, double, double>, double> r;
  for(auto v : vertices(m)) {
    const Vec3 p = MDCS_test::vertex_vec3(m, v);
    r[std::make_tuple(p[0], p[1], p[2])] = g.distance(v);
  }
  return r;
}

template <class M>
using Dijkstra_of = PG::Dijkstra_geodesic_distances_3<M>;
template <class M>
using Fmm_of = PG::Fast_marching_geodesic_distances_3<M>;

template <template <class> class G>
double worst_model_difference(const MDCS_test::Triangle_soup<Point_3>& soup)
{
  const Mesh sm = make_mesh(soup);
  const Polyhedron ph = MDCS_test::mesh_from_soup<Polyhedron>(soup);
  const Vec3 source_position = MDCS_test::to_vec3(soup.points[soup.points.size() / 3]);
  const auto a = distances_by_point<G>(sm, source_position);
  const auto b = distances_by_point<G>(ph, source_position);
  REQUIRE(a.size() == b.size());
  double worst = 0;
  for(const auto& kv : a) {
    REQUIRE(b.count(kv.first) == 1);
    CHECK(std::isfinite(kv.second));
    worst = std::max(worst, MDCS_test::relative_difference(b.at(kv.first), kv.second, 1e-14));
  }
  return worst;
}

} // namespace

TEST_CASE("baseline geodesics: Surface_mesh and Polyhedron_3 agree", "[geodesics][dijkstra][fmm]")
{
  for(const Named_soup& ns : {Named_soup{"bumpy sphere", MDCS_test::bumpy_sphere<Point_3>(2, 0.1, 4)},
                              Named_soup{"height field", MDCS_test::height_field_grid<Point_3>(10, 0.3, 2)},
                              Named_soup{"jittered grid", MDCS_test::jittered_planar_grid<Point_3>(9, 9, 1.0, 1.0, 0.2, 1)}}) {
    INFO(ns.name);
    const double dj = worst_model_difference<Dijkstra_of>(ns.soup);
    const double fm = worst_model_difference<Fmm_of>(ns.soup);
    INFO("max relative difference Surface_mesh vs Polyhedron_3: Dijkstra " << dj << ", fast marching " << fm);
    CHECK(dj <= 1e-14);
    CHECK(fm <= 1e-12);
  }
}

namespace {

template <class G>
void check_invalid_input_and_progress(const char* stage_name)
{
  INFO(stage_name);
  {
    const Mesh quad = unit_square_quad();
    CHECK_THROWS_AS(G(quad), std::invalid_argument);
  }
  const Mesh m = make_mesh(MDCS_test::bumpy_sphere<Point_3>(2, 0.1, 2));
  const face_descriptor f = *faces(m).begin();
  const vertex_descriptor s = *vertices(m).begin();
  {
    G g(m);
    CHECK_THROWS_AS(g.compute(), std::logic_error);
    CHECK_THROWS_AS(g.distance(s), std::logic_error);
    CHECK_THROWS_AS(g.add_source(Face_location(f, {0.5, 0.6, 0.1})), std::invalid_argument);
    CHECK_THROWS_AS(g.add_source(Face_location(f, {-0.5, 0.5, 1.0})), std::invalid_argument);
    CHECK_THROWS_AS(g.set_distance_limit(-1.0), std::invalid_argument);
    g.add_source(s);
    CHECK_THROWS_AS(g.distance(Face_location(f, {0.5, 0.6, 0.1})), std::invalid_argument);
    CHECK_THROWS_AS(g.distance(Face_location(f, {std::numeric_limits<double>::quiet_NaN(), 0.5, 0.5})), std::invalid_argument);
    CHECK(g.distance(s) == 0);
  }
  {
    G light(m, PG::Geodesic_memory_mode::distances_only);
    light.add_source(s);
    std::vector<Point_3> path;
    CHECK_THROWS_AS(light.distance(Face_location(f, {0.2, 0.3, 0.5})), std::logic_error);
    CHECK_THROWS_AS(light.shortest_path_points(s, std::back_inserter(path)), std::logic_error);
    CHECK(light.distance(s) == 0);
  }
  G reference(m);
  reference.add_source(s);
  const std::vector<double> expected = vertex_distances(reference, m);
  G g(m);
  g.add_source(s);
  std::size_t calls = 0;
  double last = -1;
  bool monotone = true, stage_ok = true;
  g.compute([&](const char* stage, double fraction) {
    ++calls;
    if(std::string(stage) != stage_name) stage_ok = false;
    if(fraction < last || fraction > 1) monotone = false;
    last = fraction;
    return true;
  });
  CHECK(calls >= 2);
  CHECK(calls <= 300);
  CHECK(stage_ok);
  CHECK(monotone);
  CHECK(last == 1.0);
  CHECK(g.statistics().peak_memory_bytes > 0);

  G c(m);
  c.add_source(s);
  CHECK_THROWS_AS(c.compute([&](const char*, double fraction) { return fraction < 0.3; }), CGAL::MDCS::Operation_cancelled);
  CHECK_FALSE(c.is_computed());
  CHECK(vertex_distances(c, m) == expected);
}

} // namespace

TEST_CASE("baseline geodesics: invalid input, progress and cancellation", "[geodesics][dijkstra][fmm]")
{
  check_invalid_input_and_progress<Dijkstra>("dijkstra");
  check_invalid_input_and_progress<Fmm>("fast marching");
}
