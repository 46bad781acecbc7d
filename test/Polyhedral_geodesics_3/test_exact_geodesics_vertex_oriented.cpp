// The vertex-oriented schedule of the exact geodesics (internal/vertex_oriented_propagation.h), which serves
// distances_only runs: its vertex distances against the window propagation (full field, an independent
// schedule with lower envelopes), against Surface_mesh_shortest_path on CGAL's demo meshes, against Euclidean
// distances on flat meshes with degeneracies (zero-length edge, zero-area triangle, needles, a hole), with
// several components, face-location sources (inside a face, on an edge, at a vertex), in high precision, on
// Polyhedron_3; which runs use it; and progress / cancellation.
#include <catch2/catch.hpp>

#include <MDCS_test/cgal_meshes.h>
#include <MDCS_test/geodesic_oracles.h>
#include <MDCS_test/geodesic_test_meshes.h>
#include <MDCS_test/mesh_generators.h>
#include <MDCS_test/geodesic_test_geometry.h>

#include <CGAL/Polyhedral_geodesics_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpfr.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace MDCS_test::Epick_surface_mesh;
namespace PG = CGAL::Polyhedral_geodesics_3;
typedef PG::Exact_geodesic_distances_3<Mesh> Geodesics;
typedef Geodesics::Face_location Face_location;
using MDCS_test::Vec3;

using MDCS_test::tolerance;

// Runs the vertex-oriented schedule and the window propagation (full field) from the same sources and
// compares the vertex distances (relative 1e-12, absolute floor 1e-12 of the diagonal), the unreachable
// vertices, and the nearest sources where the sources are not tied. Returns the vertex-oriented distances.
// `zero_area_faces`: the mesh has a face of zero area, where distances_only runs use the window propagation too.
std::vector<double> check_against_windows(const Mesh& m, const std::vector<Source>& sources, const std::string& what,
                                          bool zero_area_faces = false)
{
  INFO(what);
  Geodesics fast(m, PG::Geodesic_memory_mode::distances_only), full(m);
  full.set_vertex_oriented_propagation(false); // the window propagation: the independent oracle
  add_sources(fast, sources);
  add_sources(full, sources);
  const std::vector<double> a = MDCS_test::vertex_distances(full, m), b = MDCS_test::vertex_distances(fast, m);
  CHECK(fast.used_vertex_oriented_propagation() == !zero_area_faces);
  CHECK_FALSE(full.used_vertex_oriented_propagation());
  const double floor_value = tolerance * MDCS_test::bbox_diagonal(m);
  const auto cmp = MDCS_test::compare_distances(a, b, floor_value);
  INFO("vertex-oriented vs window propagation: " << cmp);
  CHECK(cmp.ok(tolerance));
  // nearest sources: equal unless another source is within rounding of the same distance
  std::vector<std::vector<double>> single;
  if(sources.size() > 1)
    for(const Source& s : sources) {
      Geodesics gi(m, PG::Geodesic_memory_mode::distances_only);
      add_sources(gi, {s});
      single.push_back(MDCS_test::vertex_distances(gi, m));
    }
  std::size_t k = 0, wrong_source = 0;
  for(vertex_descriptor v : vertices(m)) {
    const std::size_t sf = fast.nearest_source(v).second, sw = full.nearest_source(v).second;
    if(std::isinf(a[k])) {
      if(sf != Geodesics::no_source) ++wrong_source;
    } else if(sf != sw) {
      // a tie: the source the fast run names must reach v at the same distance
      if(single.empty() || sf >= single.size() || !(std::abs(single[sf][k] - a[k]) <= 1e-9 * std::max(1.0, a[k])))
        ++wrong_source;
    }
    ++k;
  }
  CHECK(wrong_source == 0);
  return b;
}

void check_flat(const Mesh& m, const std::vector<Source>& sources, const std::vector<Vec3>& points, const std::string& what,
                bool zero_area_faces = false)
{
  const std::vector<double> d = check_against_windows(m, sources, what, zero_area_faces);
  INFO(what);
  std::vector<double> e;
  for(vertex_descriptor v : vertices(m)) {
    double best = MDCS_test::inf;
    for(const Vec3& p : points) best = std::min(best, MDCS_test::dist(MDCS_test::vertex_vec3(m, v), p));
    e.push_back(best);
  }
  const auto cmp = MDCS_test::compare_distances(e, d, tolerance * MDCS_test::bbox_diagonal(m));
  INFO("vertex-oriented vs Euclidean: " << cmp);
  CHECK(cmp.ok(tolerance));
}


} // namespace

TEST_CASE("vertex-oriented exact geodesics: equal to the window propagation on curved meshes", "[geodesics][exact][vertex_oriented]")
{
  const std::vector<std::pair<std::string, MDCS_test::Triangle_soup<Point_3>>> meshes = {
    {"bumpy sphere 3", MDCS_test::bumpy_sphere<Point_3>(3, 0.2, 1)},
    {"terrain 16x16", MDCS_test::height_field_grid<Point_3>(16, 0.35, 4)},
    {"icosphere 3", MDCS_test::icosphere<Point_3>(3)},
    {"cube 4x4", MDCS_test::subdivided_cube<Point_3>(4)},
    {"square with a hole", MDCS_test::square_with_hole<Point_3>(12, 3, 8, 4, 7)}};
  for(const auto& nm : meshes) {
    const Mesh m = make_mesh(nm.second);
    const auto vs = MDCS_test::spread_vertices(m, 3, 5);
    const auto locs = MDCS_test::random_face_locations(m, 2, 9);
    check_against_windows(m, {at(vs[0])}, nm.first + ": one vertex source");
    check_against_windows(m, {at(vs[0]), at(vs[1]), at(vs[2])}, nm.first + ": three vertex sources");
    check_against_windows(m, {at(Face_location(locs[0].first, locs[0].second))}, nm.first + ": a source inside a face");
    check_against_windows(m, {at(vs[1]), at(Face_location(locs[1].first, locs[1].second))}, nm.first + ": a vertex and a face source");
    // a source on an edge, given as a face location with one zero coordinate
    const face_descriptor f = locs[0].first;
    check_against_windows(m, {at(Face_location(f, {0.0, 0.35, 0.65}))}, nm.first + ": a source on an edge");
    check_against_windows(m, {at(Face_location(f, {0.0, 1.0, 0.0}))}, nm.first + ": a face location at a vertex");
  }
}

TEST_CASE("vertex-oriented exact geodesics: Surface_mesh_shortest_path on CGAL's demo meshes", "[geodesics][exact][vertex_oriented][smsp][real]")
{
  for(const char* name : {"elephant.off", "ChineseDragon-10kv.off"}) {
    const std::string path = MDCS_test::cgal_demo_mesh(name);
    Mesh m;
    if(path.empty() || !MDCS_test::read_mesh(path, m)) {
      WARN("CGAL demo mesh " << name << " not found; test skipped");
      continue;
    }
    INFO(name);
    const auto sources = MDCS_test::spread_vertices(m, 2, 31);
    Geodesics g(m, PG::Geodesic_memory_mode::distances_only);
    MDCS_test::Smsp_oracle<K, Mesh> smsp(m);
    for(auto s : sources) {
      g.add_source(s);
      smsp.add_source(s);
    }
    smsp.build();
    std::vector<double> e, got;
    for(vertex_descriptor v : vertices(m)) {
      e.push_back(smsp.distance(v));
      got.push_back(g.distance(v));
    }
    CHECK(g.used_vertex_oriented_propagation());
    const auto cmp = MDCS_test::compare_distances(e, got, tolerance * MDCS_test::bbox_diagonal(m));
    INFO("vertex-oriented vs Surface_mesh_shortest_path: " << cmp);
    CHECK(cmp.ok(tolerance));
    check_against_windows(m, {at(sources[0])}, std::string(name) + ": against the window propagation");
  }
}

TEST_CASE("vertex-oriented exact geodesics: degenerate flat meshes", "[geodesics][exact][vertex_oriented][robustness]")
{
  {
    std::array<std::size_t, 2> coincident;
    const Mesh m = make_mesh(MDCS_test::grid_with_zero_length_edge<Point_3>(6, coincident));
    const vertex_descriptor c0(static_cast<Mesh::size_type>(coincident[0]));
    check_flat(m, {at(vertex_descriptor(0))}, {Vec3{0, 0, 0}}, "zero-length edge, source at the corner", true);
    check_flat(m, {at(c0)}, {MDCS_test::vertex_vec3(m, c0)}, "zero-length edge, source at a coincident vertex", true);
    const auto loc = MDCS_test::random_face_locations(m, 1, 4)[0];
    check_flat(m, {at(Face_location(loc.first, loc.second))}, {MDCS_test::location_point(m, loc.first, loc.second)},
               "zero-length edge, source inside a face", true);
  }
  {
    const Mesh m = make_mesh(MDCS_test::grid_with_cap_triangle<Point_3>(6));
    for(const Vec3 sp : {Vec3{0, 0, 0}, Vec3{1, 1, 0}})
      check_flat(m, {at(MDCS_test::nearest_vertex(m, sp))}, {sp}, "zero-area triangle", true);
    const vertex_descriptor mid(static_cast<Mesh::size_type>(num_vertices(m) - 1));
    check_flat(m, {at(mid)}, {MDCS_test::vertex_vec3(m, mid)}, "zero-area triangle, source at its middle vertex", true);
  }
  for(double width : {1e-3, 1e-6, 1e-9}) {
    const Mesh m = make_mesh(MDCS_test::needle_strip<Point_3>(40, width));
    for(const Vec3 sp : {Vec3{0, 0, 0}, Vec3{0.5, 0, 0}, Vec3{1, width, 0}}) {
      const vertex_descriptor s = MDCS_test::nearest_vertex(m, sp);
      check_flat(m, {at(s)}, {MDCS_test::vertex_vec3(m, s)}, "needle strip of width " + std::to_string(width));
    }
  }
  for(double gap : {1e-6, 1e-10}) {
    const Mesh m = make_mesh(MDCS_test::grid_with_needle_column<Point_3>(8, 0.43, gap));
    for(const Vec3 sp : {Vec3{0, 0, 0}, Vec3{0.43, 0.5, 0}, Vec3{0.875, 0.25, 0}}) {
      const vertex_descriptor s = MDCS_test::nearest_vertex(m, sp);
      check_flat(m, {at(s)}, {MDCS_test::vertex_vec3(m, s)}, "needle column of width " + std::to_string(gap));
    }
  }
  {
    // a hole: boundary saddles; the analytic distance goes around the rectangle
    const Mesh m = make_mesh(MDCS_test::square_with_hole<Point_3>(10, 3, 7, 4, 6));
    const MDCS_test::Rectangle_hole_domain hole{0.3, 0.4, 0.7, 0.6};
    for(const Vec3 sp : {Vec3{0.5, 0.1, 0}, Vec3{0.3, 0.4, 0}, Vec3{0.8, 0.9, 0}}) {
      const std::vector<double> d = check_against_windows(m, {at(MDCS_test::nearest_vertex(m, sp))}, "square with a hole");
      std::vector<double> e;
      for(vertex_descriptor v : vertices(m)) e.push_back(hole.distance(sp, MDCS_test::vertex_vec3(m, v)));
      const auto cmp = MDCS_test::compare_distances(e, d, tolerance);
      INFO("square with a hole, vertex-oriented vs analytic: " << cmp);
      CHECK(cmp.ok(tolerance));
    }
  }
}

// CGAL's degtri_sliding.off (its 8 vertices and 8 faces, here so that the test needs no data): four faces of zero
// area stacked on the x axis join a lower and an upper triangle pair. A shortest path runs along their line:
// from vertex 2 to vertex 7 it is sqrt(5), from vertex 3 to vertex 5 it is 1. The vertex-oriented schedule gave 3
// and 3 there, so distances_only runs on a mesh with a zero-area face use the window propagation. Every small
// perturbation of the mesh (faces of positive area, where the vertex-oriented schedule runs) gives the same
// values to within the perturbation.
TEST_CASE("vertex-oriented exact geodesics: a stack of zero-area faces (degtri_sliding)",
          "[geodesics][exact][vertex_oriented][robustness]")
{
  MDCS_test::Triangle_soup<Point_3> soup;
  soup.points = {Point_3(4, -2, 0), Point_3(6, 0, 0), Point_3(4, 0, 0), Point_3(2, 0, 0),
                 Point_3(1, 0, 0),  Point_3(3, 0, 0), Point_3(5, 0, 0), Point_3(3, 2, 0)};
  soup.triangles = {{0, 1, 2}, {0, 2, 3}, {3, 2, 4}, {2, 1, 6}, {2, 6, 4}, {4, 6, 5}, {5, 6, 7}, {4, 5, 7}};
  const Mesh m = make_mesh(soup);
  REQUIRE(num_vertices(m) == 8);
  std::vector<std::vector<double>> by_source;
  for(vertex_descriptor s : vertices(m))
    by_source.push_back(check_against_windows(m, {at(s)}, "degtri_sliding, source " + std::to_string(std::size_t(s)), true));
  CHECK(std::abs(by_source[2][7] - std::sqrt(5.0)) <= 1e-12);
  CHECK(std::abs(by_source[3][5] - 1.0) <= 1e-12);
  // the same mesh with every coordinate moved by up to 1e-7: positive areas, the vertex-oriented schedule
  MDCS_test::Triangle_soup<Point_3> moved = soup;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-1e-7, 1e-7);
  for(Point_3& p : moved.points)
    p = Point_3(p.x() + jitter(rng), p.y() + jitter(rng), p.z() + jitter(rng));
  const Mesh mm = make_mesh(moved);
  for(vertex_descriptor s : vertices(mm)) {
    const std::vector<double> d = check_against_windows(mm, {at(s)}, "degtri_sliding moved by 1e-7", false);
    for(std::size_t v = 0; v < d.size(); ++v)
      CHECK(std::abs(d[v] - by_source[std::size_t(s)][v]) <= 1e-6);
  }
}

TEST_CASE("vertex-oriented exact geodesics: several components", "[geodesics][exact][vertex_oriented][robustness]")
{
  const Mesh m = make_mesh(MDCS_test::two_grids<Point_3>(5));
  const std::size_t first = 36;
  const vertex_descriptor s(8);
  Geodesics g(m, PG::Geodesic_memory_mode::distances_only);
  g.add_source(s);
  std::size_t wrong = 0;
  for(std::size_t i = 0; i < num_vertices(m); ++i) {
    const vertex_descriptor v(static_cast<Mesh::size_type>(i));
    const double d = g.distance(v);
    if(i < first) {
      if(!(std::abs(d - MDCS_test::dist(MDCS_test::vertex_vec3(m, v), MDCS_test::vertex_vec3(m, s))) <= 1e-12)) ++wrong;
      if(g.nearest_source(v).second != 0) ++wrong;
    } else {
      if(!(d == std::numeric_limits<double>::infinity())) ++wrong;
      if(g.nearest_source(v).second != Geodesics::no_source) ++wrong;
    }
  }
  CHECK(g.used_vertex_oriented_propagation());
  CHECK(wrong == 0);
}

TEST_CASE("vertex-oriented exact geodesics: which runs use it", "[geodesics][exact][vertex_oriented]")
{
  const Mesh m = make_mesh(MDCS_test::bumpy_sphere<Point_3>(2, 0.2, 1));
  const vertex_descriptor s = *vertices(m).begin();
  const vertex_descriptor t = *std::next(vertices(m).begin(), 7);
  Geodesics g(m, PG::Geodesic_memory_mode::distances_only);
  CHECK(g.vertex_oriented_propagation());
  g.add_source(s);
  const double d_fast = g.distance(t);
  CHECK(g.used_vertex_oriented_propagation());
  CHECK(g.statistics().windows_created > 0);
  CHECK(g.statistics().windows_propagated > 0);
  CHECK(g.statistics().peak_live_windows > 0);
  CHECK(g.statistics().peak_memory_bytes > 0);
  CHECK(g.statistics().stored_windows == 0);

  g.set_distance_limit(0.5); // limits and stop targets run on the vertex-oriented schedule too
  const double d_limit = g.distance(t);
  CHECK(g.used_vertex_oriented_propagation());
  CHECK((d_limit == d_fast || (d_fast > 0.5 && std::isinf(d_limit))));
  g.set_vertex_oriented_full_field(false); // ... or on the window order, when asked
  CHECK((g.distance(t) == d_limit || std::abs(g.distance(t) - d_limit) <= 1e-14 * d_limit));
  CHECK_FALSE(g.used_vertex_oriented_propagation());
  g.set_vertex_oriented_full_field(true);
  g.clear_distance_limit();
  g.set_stop_targets(std::vector<vertex_descriptor>{t});
  CHECK(std::abs(g.distance(t) - d_fast) <= 1e-14 * d_fast);
  CHECK(g.used_vertex_oriented_propagation());
  g.clear_stop_targets();
  g.set_vertex_oriented_propagation(false);
  CHECK_FALSE(g.vertex_oriented_propagation());
  CHECK(std::abs(g.distance(t) - d_fast) <= 1e-14 * d_fast);
  CHECK_FALSE(g.used_vertex_oriented_propagation());
  g.set_vertex_oriented_propagation(true);
  CHECK(g.distance(t) == d_fast);
  CHECK(g.used_vertex_oriented_propagation());
  g.set_memory_mode(PG::Geodesic_memory_mode::full_field);
  CHECK(g.distance(t) == d_fast); // the same schedule, keeping its records
  CHECK(g.used_vertex_oriented_propagation());
  g.set_vertex_oriented_full_field(false);
  CHECK(std::abs(g.distance(t) - d_fast) <= 1e-14 * d_fast);
  CHECK_FALSE(g.used_vertex_oriented_propagation());
}

TEST_CASE("vertex-oriented exact geodesics: progress and cancellation", "[geodesics][exact][vertex_oriented]")
{
  const Mesh m = make_mesh(MDCS_test::bumpy_sphere<Point_3>(4, 0.2, 3));
  Geodesics g(m, PG::Geodesic_memory_mode::distances_only);
  g.add_source(*vertices(m).begin());
  std::vector<double> fractions;
  g.compute([&](const char*, double f) { fractions.push_back(f); return true; });
  REQUIRE(fractions.size() >= 2);
  CHECK(fractions.front() == 0.0);
  CHECK(fractions.back() == 1.0);
  CHECK(std::is_sorted(fractions.begin(), fractions.end()));
  Geodesics h(m, PG::Geodesic_memory_mode::distances_only);
  h.add_source(*vertices(m).begin());
  CHECK_THROWS_AS(h.compute([](const char*, double f) { return f < 0.5; }), CGAL::MDCS::Operation_cancelled);
}

TEST_CASE("vertex-oriented exact geodesics: Polyhedron_3 equals Surface_mesh", "[geodesics][exact][vertex_oriented]")
{
  typedef CGAL::Polyhedron_3<K> Polyhedron;
  const auto soup = MDCS_test::height_field_grid<Point_3>(12, 0.35, 2);
  const Mesh m = make_mesh(soup);
  Polyhedron p;
  soup.to_mesh(p);
  PG::Exact_geodesic_distances_3<Polyhedron> gp(p, PG::Geodesic_memory_mode::distances_only);
  gp.add_source(*std::next(vertices(p).begin(), 17));
  Geodesics gm(m, PG::Geodesic_memory_mode::distances_only);
  gm.add_source(*std::next(vertices(m).begin(), 17));
  std::vector<double> a, b;
  for(auto v : vertices(p)) a.push_back(gp.distance(v));
  for(auto v : vertices(m)) b.push_back(gm.distance(v));
  CHECK(a == b);
}

TEST_CASE("vertex-oriented exact geodesics: high precision (Gmpfr, 170 bits)", "[geodesics][exact][vertex_oriented][number_types]")
{
  typedef CGAL::Gmpfr FT;
  const auto old_precision = CGAL::Gmpfr::get_default_precision();
  CGAL::Gmpfr::set_default_precision(170);
  {
    // cube with vertices at multiples of 1/4: corner to corner is sqrt(5), to the centre of a far face sqrt(5/2)
    const Mesh m = make_mesh(MDCS_test::subdivided_cube<Point_3>(4));
    PG::Exact_geodesic_distances_3<Mesh, FT> g(m, PG::Geodesic_memory_mode::distances_only);
    g.add_source(MDCS_test::nearest_vertex(m, Vec3{0, 0, 0}));
    const FT e1 = CGAL::abs(g.distance(MDCS_test::nearest_vertex(m, Vec3{1, 1, 1})) - CGAL::sqrt(FT(5)));
    const FT e2 = CGAL::abs(g.distance(MDCS_test::nearest_vertex(m, Vec3{0.5, 0.5, 1})) - CGAL::sqrt(FT(5) / FT(2)));
    INFO("errors " << CGAL::to_double(e1) << " " << CGAL::to_double(e2));
    CHECK(g.used_vertex_oriented_propagation());
    CHECK(e1 < FT(1e-40));
    CHECK(e2 < FT(1e-40));
    // agreement with double on a curved mesh
    const Mesh c = make_mesh(MDCS_test::bumpy_sphere<Point_3>(2, 0.2, 1));
    PG::Exact_geodesic_distances_3<Mesh, FT> gh(c, PG::Geodesic_memory_mode::distances_only);
    Geodesics gd(c, PG::Geodesic_memory_mode::distances_only);
    gh.add_source(*vertices(c).begin());
    gd.add_source(*vertices(c).begin());
    std::vector<double> a, b;
    for(auto v : vertices(c)) {
      a.push_back(CGAL::to_double(gh.distance(v)));
      b.push_back(gd.distance(v));
    }
    const auto cmp = MDCS_test::compare_distances(a, b, tolerance * MDCS_test::bbox_diagonal(c));
    INFO("double vs 170 bits: " << cmp);
    CHECK(cmp.ok(tolerance));
  }
  CGAL::Gmpfr::set_default_precision(old_precision);
}
