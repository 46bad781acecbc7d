// Robustness of the exact geodesics on degenerate and special inputs: a zero-length edge (coincident vertices),
// a collinear (zero-area) triangle, needle triangles, a domain with a hole (boundary saddles), sources exactly
// at a vertex or on an edge given as face locations, several connected components, and the rejection of
// invalid input (non-triangle faces, invalid barycentric coordinates, queries without a source, bad limits).
// Every case must give finite, correct values (no NaN, no hang, no crash).
#include <catch2/catch.hpp>

#include <MDCS_test/geodesic_oracles.h>
#include <MDCS_test/geodesic_test_meshes.h>
#include <MDCS_test/mesh_generators.h>
#include <MDCS_test/geodesic_test_geometry.h>

#include <CGAL/Polyhedral_geodesics_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace MDCS_test::Epick_surface_mesh;
namespace PG = CGAL::Polyhedral_geodesics_3;
typedef PG::Exact_geodesic_distances_3<Mesh> Geodesics;
typedef Geodesics::Face_location Face_location;
using MDCS_test::Vec3;

using MDCS_test::tolerance;

// Vertex i of the mesh built from a soup is the i-th point (Surface_mesh keeps the order).
using MDCS_test::vertex_at;

// Checks the distance at every vertex and at random surface points against the Euclidean distance from
// the source points (the mesh must be a flat convex domain), and that the paths are finite and as long as the
// distance.
void check_flat(Geodesics& g, const Mesh& m, const std::vector<Vec3>& sources, double tol, const std::string& what)
{
  INFO(what);
  const double diag = MDCS_test::bbox_diagonal(m);
  auto euclid = [&](const Vec3& p) {
    double best = MDCS_test::inf;
    for(const auto& s : sources) best = std::min(best, MDCS_test::dist(p, s));
    return best;
  };
  std::vector<double> e, got;
  for(vertex_descriptor v : vertices(m)) {
    e.push_back(euclid(MDCS_test::vertex_vec3(m, v)));
    got.push_back(g.distance(v));
  }
  const auto cmp = MDCS_test::compare_distances(e, got, tolerance * diag);
  INFO("vertices: " << cmp);
  CHECK(cmp.ok(tol));
  std::vector<double> eq, gq;
  for(const auto& q : MDCS_test::random_face_locations(m, 100, 13)) {
    eq.push_back(euclid(MDCS_test::location_point(m, q.first, q.second)));
    gq.push_back(g.distance(Face_location(q.first, q.second)));
  }
  const auto cmp_q = MDCS_test::compare_distances(eq, gq, tolerance * diag);
  INFO("face locations: " << cmp_q);
  CHECK(cmp_q.ok(tol));
  std::size_t bad_paths = 0, exceptions = 0;
  double worst = 0;
  std::string first_exception;
  for(vertex_descriptor v : vertices(m)) {
    std::vector<Point_3> pts;
    try {
      g.shortest_path_points(v, std::back_inserter(pts));
    }
    catch(const std::exception& ex) {
      if(exceptions++ == 0) first_exception = ex.what();
      continue;
    }
    const double len = MDCS_test::path_length(pts);
    const double r = MDCS_test::relative_difference(len, g.distance(v), tolerance * diag);
    worst = std::max(worst, std::isnan(r) ? MDCS_test::inf : r);
    if(pts.empty() || !(r <= 1e-9)) ++bad_paths;
  }
  INFO("worst relative path length error " << worst << "; exceptions: " << exceptions << " (first: " << first_exception << ")");
  CHECK(bad_paths == 0);
  CHECK(exceptions == 0);
}

} // namespace

TEST_CASE("exact geodesics robustness: zero-length edge", "[geodesics][exact][robustness]")
{
  std::array<std::size_t, 2> coincident;
  const Mesh m = make_mesh(MDCS_test::grid_with_zero_length_edge<Point_3>(6, coincident));
  REQUIRE(MDCS_test::dist(MDCS_test::vertex_vec3(m, vertex_at(m, coincident[0])), MDCS_test::vertex_vec3(m, vertex_at(m, coincident[1]))) == 0);
  {
    Geodesics g(m);
    g.add_source(vertex_at(m, 0)); // corner (0, 0)
    check_flat(g, m, {Vec3{0, 0, 0}}, tolerance, "source at the corner");
    CHECK(g.distance(vertex_at(m, coincident[0])) == g.distance(vertex_at(m, coincident[1])));
  }
  for(std::size_t c : coincident) {
    Geodesics g(m);
    g.add_source(vertex_at(m, c));
    check_flat(g, m, {MDCS_test::vertex_vec3(m, vertex_at(m, c))}, tolerance, "source at one of the coincident vertices");
    CHECK(g.distance(vertex_at(m, coincident[0])) == 0);
    CHECK(g.distance(vertex_at(m, coincident[1])) == 0);
  }
  {
    Geodesics g(m);
    const auto loc = MDCS_test::random_face_locations(m, 1, 4)[0];
    g.add_source(Face_location(loc.first, loc.second));
    check_flat(g, m, {MDCS_test::location_point(m, loc.first, loc.second)}, tolerance, "source inside a face");
  }
  // a source inside a zero-area face: the face (a, m, c) with a == m
  for(face_descriptor f : faces(m)) {
    const auto vs = MDCS_test::face_vertices(m, f);
    bool degenerate = false;
    for(int i = 0; i < 3; ++i)
      if(MDCS_test::dist(MDCS_test::vertex_vec3(m, vs[std::size_t(i)]), MDCS_test::vertex_vec3(m, vs[std::size_t((i + 1) % 3)])) == 0)
        degenerate = true;
    if(!degenerate) continue;
    Geodesics g(m);
    const std::array<double, 3> b = {0.25, 0.25, 0.5};
    g.add_source(Face_location(f, b));
    check_flat(g, m, {MDCS_test::location_point(m, f, b)}, tolerance, "source inside a zero-area face");
    CHECK(g.distance(Face_location(f, {0.1, 0.6, 0.3})) == Approx(MDCS_test::dist(MDCS_test::location_point(m, f, b),
                                                                                    MDCS_test::location_point(m, f, std::array<double, 3>{0.1, 0.6, 0.3}))).margin(1e-12));
  }
}

TEST_CASE("exact geodesics robustness: collinear (zero-area) triangle", "[geodesics][exact][robustness]")
{
  const Mesh m = make_mesh(MDCS_test::grid_with_cap_triangle<Point_3>(6));
  REQUIRE(CGAL::is_valid_polygon_mesh(m));
  const vertex_descriptor mid = vertex_at(m, num_vertices(m) - 1);
  for(const Vec3 sp : {Vec3{0, 0, 0}, Vec3{1, 1, 0}, MDCS_test::vertex_vec3(m, mid)}) {
    Geodesics g(m);
    g.add_source(MDCS_test::nearest_vertex(m, sp));
    check_flat(g, m, {sp}, tolerance, "source at (" + std::to_string(sp[0]) + ", " + std::to_string(sp[1]) + ")");
  }
  {
    Geodesics g(m);
    g.add_source(g.vertex_location(vertex_at(m, 7)));
    g.add_source(Face_location(*faces(m).begin(), {0.3, 0.3, 0.4}));
    check_flat(g, m, {MDCS_test::vertex_vec3(m, vertex_at(m, 7)), MDCS_test::location_point(m, *faces(m).begin(), std::array<double, 3>{0.3, 0.3, 0.4})},
               tolerance, "two sources");
  }
}

TEST_CASE("exact geodesics robustness: needle triangles", "[geodesics][exact][robustness]")
{
  for(double width : {1e-3, 1e-6, 1e-9}) {
    const Mesh m = make_mesh(MDCS_test::needle_strip<Point_3>(40, width));
    for(const Vec3 sp : {Vec3{0, 0, 0}, Vec3{0.5, 0, 0}, Vec3{1, width, 0}}) {
      Geodesics g(m);
      const vertex_descriptor s = MDCS_test::nearest_vertex(m, sp);
      g.add_source(s);
      check_flat(g, m, {MDCS_test::vertex_vec3(m, s)}, tolerance,
                 "needle strip of width " + std::to_string(width) + ", source (" + std::to_string(sp[0]) + ", " + std::to_string(sp[1]) + ")");
    }
  }
  for(double gap : {1e-6, 1e-10}) {
    const Mesh m = make_mesh(MDCS_test::grid_with_needle_column<Point_3>(8, 0.43, gap));
    for(const Vec3 sp : {Vec3{0, 0, 0}, Vec3{0.43, 0.5, 0}, Vec3{0.875, 0.25, 0}}) {
      Geodesics g(m);
      const vertex_descriptor s = MDCS_test::nearest_vertex(m, sp);
      g.add_source(s);
      check_flat(g, m, {MDCS_test::vertex_vec3(m, s)}, tolerance,
                 "grid with a needle column of width " + std::to_string(gap) + ", source (" + std::to_string(sp[0]) + ", " + std::to_string(sp[1]) + ")");
    }
  }
}

TEST_CASE("exact geodesics robustness: square with a hole (boundary saddles)", "[geodesics][exact][robustness]")
{
  const Mesh m = make_mesh(MDCS_test::square_with_hole<Point_3>(10, 3, 7, 4, 6));
  const MDCS_test::Rectangle_hole_domain hole{0.3, 0.4, 0.7, 0.6};
  const double diag = MDCS_test::bbox_diagonal(m);
  const auto queries = MDCS_test::random_face_locations(m, 150, 3);
  for(const Vec3 sp : {Vec3{0.5, 0.1, 0}, Vec3{0.3, 0.4, 0}, Vec3{0.0, 0.5, 0}, Vec3{0.8, 0.9, 0}}) {
    INFO("vertex source (" << sp[0] << ", " << sp[1] << ")");
    const vertex_descriptor s = MDCS_test::nearest_vertex(m, sp);
    REQUIRE(MDCS_test::dist(MDCS_test::vertex_vec3(m, s), sp) < 1e-15);
    Geodesics g(m);
    g.add_source(s);
    MDCS_test::Smsp_oracle<K, Mesh> smsp(m);
    smsp.add_source(s);
    smsp.build();
    std::vector<double> e, got, ref;
    for(vertex_descriptor v : vertices(m)) {
      e.push_back(hole.distance(sp, MDCS_test::vertex_vec3(m, v)));
      got.push_back(g.distance(v));
      ref.push_back(smsp.distance(v));
    }
    const auto oracle_check = MDCS_test::compare_distances(e, ref, tolerance * diag);
    INFO("visibility-graph oracle vs Surface_mesh_shortest_path (self-check of the test): " << oracle_check);
    CHECK(oracle_check.ok(1e-9));
    const auto cmp = MDCS_test::compare_distances(e, got, tolerance * diag);
    INFO("vertices: " << cmp);
    CHECK(cmp.ok(tolerance));
    std::vector<double> eq, gq;
    for(const auto& q : queries) {
      eq.push_back(hole.distance(sp, MDCS_test::location_point(m, q.first, q.second)));
      gq.push_back(g.distance(Face_location(q.first, q.second)));
    }
    const auto cmp_q = MDCS_test::compare_distances(eq, gq, tolerance * diag);
    INFO("face locations: " << cmp_q);
    CHECK(cmp_q.ok(tolerance));
  }
  {
    // a source inside a face: the visibility-graph oracle again
    const auto loc = MDCS_test::locate_point(m, Vec3{0.52, 0.23, 0});
    const Vec3 sp = MDCS_test::location_point(m, loc.first, loc.second);
    Geodesics g(m);
    g.add_source(Face_location(loc.first, loc.second));
    std::vector<double> e, got;
    for(vertex_descriptor v : vertices(m)) {
      e.push_back(hole.distance(sp, MDCS_test::vertex_vec3(m, v)));
      got.push_back(g.distance(v));
    }
    const auto cmp = MDCS_test::compare_distances(e, got, tolerance * diag);
    INFO("face-location source, vertices: " << cmp);
    CHECK(cmp.ok(tolerance));
  }
}

TEST_CASE("exact geodesics robustness: sources at a vertex or on an edge given as face locations", "[geodesics][exact][robustness]")
{
  // flat: Euclidean
  {
    const Mesh m = make_mesh(MDCS_test::jittered_planar_grid<Point_3>(7, 7, 1.0, 1.0, 0.2, 5));
    const face_descriptor f = MDCS_test::locate_point(m, Vec3{0.52, 0.47, 0}).first;
    const auto vs = MDCS_test::face_vertices(m, f);
    const std::vector<std::array<double, 3>> corners = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for(std::size_t i = 0; i < 3; ++i) {
      INFO("corner " << i << " of a face as a face location");
      Geodesics g(m), gv(m);
      g.add_source(Face_location(f, corners[i]));
      gv.add_source(vs[i]);
      check_flat(g, m, {MDCS_test::vertex_vec3(m, vs[i])}, tolerance, "flat, source at a face corner");
      std::size_t differ = 0;
      for(vertex_descriptor v : vertices(m))
        if(!(MDCS_test::relative_difference(g.distance(v), gv.distance(v), 1e-12) <= 1e-12)) ++differ;
      CHECK(differ == 0);
      CHECK(g.distance(vs[i]) == 0);
    }
    for(const std::array<double, 3>& b : {std::array<double, 3>{0.5, 0.5, 0}, std::array<double, 3>{0, 0.5, 0.5},
                                          std::array<double, 3>{0.25, 0, 0.75}}) {
      Geodesics g(m);
      g.add_source(Face_location(f, b));
      check_flat(g, m, {MDCS_test::location_point(m, f, b)}, tolerance, "flat, source on an edge");
    }
  }
  // curved: the same point given as a vertex / through different faces, and against Surface_mesh_shortest_path
  {
    const Mesh m = make_mesh(MDCS_test::bumpy_sphere<Point_3>(2, 0.2, 12));
    const double floor_value = tolerance * MDCS_test::bbox_diagonal(m);
    const vertex_descriptor v0 = MDCS_test::spread_vertices(m, 1, 3)[0];
    Geodesics gv(m);
    gv.add_source(v0);
    const auto ref = [&] { std::vector<double> r; for(auto v : vertices(m)) r.push_back(gv.distance(v)); return r; }();
    for(auto h : CGAL::halfedges_around_target(halfedge(v0, m), m)) {
      // v0 as a corner of each incident face
      const face_descriptor f = face(h, m);
      const auto vs = MDCS_test::face_vertices(m, f);
      std::array<double, 3> b = {0, 0, 0};
      for(std::size_t i = 0; i < 3; ++i)
        if(vs[i] == v0) b[i] = 1;
      Geodesics g(m);
      g.add_source(Face_location(f, b));
      std::vector<double> got;
      for(auto v : vertices(m)) got.push_back(g.distance(v));
      const auto cmp = MDCS_test::compare_distances(ref, got, floor_value);
      INFO("bumpy sphere, vertex given as a corner of a face: " << cmp);
      CHECK(cmp.ok(tolerance));
    }
    // midpoint of an edge, given through both faces of the edge, vs Surface_mesh_shortest_path
    const halfedge_descriptor h = halfedge(v0, m);
    std::vector<std::vector<double>> runs;
    for(halfedge_descriptor hh : {h, opposite(h, m)}) {
      const face_descriptor f = face(hh, m);
      const auto vs = MDCS_test::face_vertices(m, f);
      std::array<double, 3> b = {0, 0, 0};
      for(std::size_t i = 0; i < 3; ++i)
        if(vs[i] == source(hh, m) || vs[i] == target(hh, m)) b[i] = 0.5;
      Geodesics g(m);
      g.add_source(Face_location(f, b));
      MDCS_test::Smsp_oracle<K, Mesh> smsp(m);
      smsp.add_source(f, b);
      smsp.build();
      std::vector<double> got, e;
      for(auto v : vertices(m)) {
        got.push_back(g.distance(v));
        e.push_back(smsp.distance(v));
      }
      const auto cmp = MDCS_test::compare_distances(e, got, floor_value);
      INFO("bumpy sphere, source at an edge midpoint, vs Surface_mesh_shortest_path: " << cmp);
      CHECK(cmp.ok(tolerance));
      runs.push_back(got);
    }
    const auto cmp = MDCS_test::compare_distances(runs[0], runs[1], floor_value);
    INFO("edge midpoint through one face vs through the other: " << cmp);
    CHECK(cmp.ok(tolerance));
  }
}

TEST_CASE("exact geodesics robustness: several connected components", "[geodesics][exact][robustness]")
{
  const Mesh m = make_mesh(MDCS_test::two_grids<Point_3>(5));
  const std::size_t first = 36; // (5+1)^2 vertices in the first component
  Geodesics g(m);
  const vertex_descriptor s = vertex_at(m, 8);
  g.add_source(s);
  std::size_t wrong = 0;
  for(std::size_t i = 0; i < num_vertices(m); ++i) {
    const vertex_descriptor v = vertex_at(m, i);
    const double d = g.distance(v);
    if(i < first) {
      if(!(std::abs(d - MDCS_test::dist(MDCS_test::vertex_vec3(m, v), MDCS_test::vertex_vec3(m, s))) <= 1e-12)) ++wrong;
      if(g.nearest_source(v).second != 0) ++wrong;
    }
    else {
      if(!(d == std::numeric_limits<double>::infinity())) ++wrong;
      const auto ns = g.nearest_source(v);
      if(ns.second != Geodesics::no_source || ns.first != std::numeric_limits<double>::infinity()) ++wrong;
      std::vector<Point_3> pts;
      g.shortest_path_points(v, std::back_inserter(pts));
      if(!pts.empty()) ++wrong;
    }
  }
  CHECK(wrong == 0);
  // a face location in the other component
  face_descriptor f_other;
  for(face_descriptor f : faces(m))
    if(std::size_t(MDCS_test::face_vertices(m, f)[0]) >= first) f_other = f;
  CHECK(g.distance(Face_location(f_other, {0.3, 0.3, 0.4})) == std::numeric_limits<double>::infinity());
  CHECK(g.nearest_source(Face_location(f_other, {0.3, 0.3, 0.4})).second == Geodesics::no_source);
  // sources in both components: each component is measured from its own source
  g.add_source(Face_location(f_other, {0.3, 0.3, 0.4}));
  const Vec3 other_point = MDCS_test::location_point(m, f_other, std::array<double, 3>{0.3, 0.3, 0.4});
  std::size_t wrong2 = 0;
  for(std::size_t i = 0; i < num_vertices(m); ++i) {
    const vertex_descriptor v = vertex_at(m, i);
    const Vec3 p = MDCS_test::vertex_vec3(m, v);
    const double expected = i < first ? MDCS_test::dist(p, MDCS_test::vertex_vec3(m, s)) : MDCS_test::dist(p, other_point);
    if(!(std::abs(g.distance(v) - expected) <= 1e-12)) ++wrong2;
    if(g.nearest_source(v).second != (i < first ? 0u : 1u)) ++wrong2;
  }
  CHECK(wrong2 == 0);
}

TEST_CASE("exact geodesics robustness: invalid input is rejected", "[geodesics][exact][robustness]")
{
  // a quad face
  {
    Mesh quad = unit_square_quad();
    const vertex_descriptor a = vertex_at(quad, 0), b = vertex_at(quad, 1), c = vertex_at(quad, 2);
    CHECK_THROWS_AS(Geodesics(quad), std::invalid_argument);
    std::vector<double> out(4);
    auto dmap = quad.add_property_map<vertex_descriptor, double>("v:d", 0).first;
    CHECK_THROWS_AS(PG::exact_geodesic_distances_3(quad, a, dmap), std::invalid_argument);
    // triangles plus one quad
    const auto e = quad.add_vertex(Point_3(2, 0, 0));
    quad.add_face(b, e, c);
    CHECK_THROWS_AS(Geodesics(quad), std::invalid_argument);
  }
  const Mesh m = make_mesh(MDCS_test::planar_grid<Point_3>(3, 3));
  const face_descriptor f = *faces(m).begin();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // queries without a source
  {
    Geodesics g(m);
    CHECK_THROWS_AS(g.compute(), std::logic_error);
    CHECK_THROWS_AS(g.distance(vertex_at(m, 0)), std::logic_error);
    CHECK_THROWS_AS(g.nearest_source(vertex_at(m, 0)), std::logic_error);
    CHECK_THROWS_AS(g.distance(Face_location(f, {0.2, 0.3, 0.5})), std::logic_error);
    std::vector<Point_3> pts;
    CHECK_THROWS_AS(g.shortest_path_points(vertex_at(m, 0), std::back_inserter(pts)), std::logic_error);
    g.add_source(vertex_at(m, 0));
    CHECK(g.distance(vertex_at(m, 0)) == 0);
    g.clear_sources();
    CHECK(g.number_of_sources() == 0);
    CHECK_THROWS_AS(g.distance(vertex_at(m, 1)), std::logic_error);
  }
  // invalid barycentric coordinates
  {
    Geodesics g(m);
    for(const std::array<double, 3>& b : {std::array<double, 3>{0.5, 0.6, 0.1}, std::array<double, 3>{-0.1, 0.6, 0.5},
                                          std::array<double, 3>{0, 0, 0}, std::array<double, 3>{nan, 0.5, 0.5},
                                          std::array<double, 3>{1.5, -0.25, -0.25}, std::array<double, 3>{0.3, 0.3, 0.3}}) {
      INFO("barycentric (" << b[0] << ", " << b[1] << ", " << b[2] << ")");
      CHECK_THROWS_AS(g.add_source(Face_location(f, b)), std::invalid_argument);
    }
    CHECK(g.number_of_sources() == 0);
    g.add_source(vertex_at(m, 0));
    std::vector<Point_3> pts;
    CHECK_THROWS_AS(g.distance(Face_location(f, {0.5, 0.6, 0.1})), std::invalid_argument);
    CHECK_THROWS_AS(g.nearest_source(Face_location(f, {-0.5, 0.5, 1.0})), std::invalid_argument);
    CHECK_THROWS_AS(g.shortest_path_points(Face_location(f, {nan, 0.5, 0.5}), std::back_inserter(pts)), std::invalid_argument);
    CHECK(pts.empty());
    // valid: on the face's boundary, or with a tiny rounding error
    CHECK_NOTHROW(g.distance(Face_location(f, {0, 0, 1})));
    CHECK_NOTHROW(g.distance(Face_location(f, {0.1, 0.2, 0.7 + 1e-12})));
  }
  // distance limits
  {
    Geodesics g(m);
    CHECK_THROWS_AS(g.set_distance_limit(-1.0), std::invalid_argument);
    CHECK_THROWS_AS(g.set_distance_limit(nan), std::invalid_argument);
    CHECK_NOTHROW(g.set_distance_limit(std::numeric_limits<double>::infinity()));
    g.add_source(vertex_at(m, 0));
    CHECK(g.distance(vertex_at(m, 15)) == Approx(std::sqrt(2.0)).epsilon(1e-12));
  }
  // a face of another mesh (index out of range)
  {
    const Mesh big = make_mesh(MDCS_test::planar_grid<Point_3>(6, 6));
    face_descriptor far_face = *(--faces(big).end());
    Geodesics g(m);
    CHECK_THROWS_AS(g.add_source(Face_location(far_face, {0.2, 0.3, 0.5})), std::invalid_argument);
  }
}

TEST_CASE("exact geodesics robustness: coincident sources and a source on the boundary", "[geodesics][exact][robustness]")
{
  const Mesh m = make_mesh(MDCS_test::jittered_planar_grid<Point_3>(6, 6, 1.0, 1.0, 0.2, 9));
  const vertex_descriptor s = vertex_at(m, 3); // on the boundary y = 0
  Geodesics g(m);
  g.add_source(s);
  g.add_source(s);
  g.add_source(g.vertex_location(s));
  check_flat(g, m, {MDCS_test::vertex_vec3(m, s)}, tolerance, "three sources at the same boundary vertex");
  for(vertex_descriptor v : vertices(m))
    CHECK(g.nearest_source(v).second < 3);
}
