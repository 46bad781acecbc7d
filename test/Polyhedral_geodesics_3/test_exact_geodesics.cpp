// Exact geodesic distances against oracles that do not depend on the package: Euclidean distances on flat
// meshes (vertices and arbitrary surface points, vertex and surface-point sources), analytic unfoldings on the
// regular tetrahedron and the unit cube (each analytic oracle is itself cross-checked with CGAL's
// Surface_mesh_shortest_path), and Surface_mesh_shortest_path on an icosphere.
#include <catch2/catch.hpp>

#include <MDCS_test/geodesic_oracles.h>
#include <MDCS_test/geodesic_test_meshes.h>
#include <MDCS_test/mesh_generators.h>
#include <MDCS_test/geodesic_test_geometry.h>

#include <CGAL/Polyhedral_geodesics_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

using namespace MDCS_test::Epick_surface_mesh;
typedef CGAL::Polyhedral_geodesics_3::Exact_geodesic_distances_3<Mesh> Geodesics;
typedef Geodesics::Face_location Face_location;
using MDCS_test::Vec3;

using MDCS_test::tolerance;

Face_location location(face_descriptor f, const std::array<double, 3>& b) { return Face_location(f, b); }

// a face incident to v (the first one found)
face_descriptor face_of_vertex(const Mesh& m, vertex_descriptor v)
{
  for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m))
    if(!is_border(h, m))
      return face(h, m);
  FAIL("isolated vertex");
  return face_descriptor();
}

typedef MDCS_test::Named_soup<Point_3> Named_soup;

std::vector<Named_soup> flat_meshes()
{
  return {{"planar grid 8x8", MDCS_test::planar_grid<Point_3>(8, 8)},
          {"planar grid 7x5 on [0,2]x[0,1]", MDCS_test::planar_grid<Point_3>(7, 5, 2.0, 1.0)},
          {"jittered grid 10x9 on [0,1.3]x[0,1]", MDCS_test::jittered_planar_grid<Point_3>(10, 9, 1.3, 1.0, 0.2, 7)},
          {"jittered grid 12x12", MDCS_test::jittered_planar_grid<Point_3>(12, 12, 1.0, 1.0, 0.2, 42)},
          {"subdivided triangle 7", MDCS_test::subdivided_triangle<Point_3>(7)}};
}

} // namespace

TEST_CASE("exact geodesics: flat meshes give Euclidean distances everywhere", "[geodesics][exact][flat]")
{
  for(const Named_soup& ns : flat_meshes()) {
    const Mesh m = make_mesh(ns.soup);
    const double diag = MDCS_test::bbox_diagonal(m);
    const double floor_value = tolerance * diag;
    const auto queries = MDCS_test::random_face_locations(m, 60, 11);

    const vertex_descriptor corner = MDCS_test::nearest_vertex(m, Vec3{0, 0, 0});
    const vertex_descriptor interior = MDCS_test::nearest_vertex(m, Vec3{0.41 * diag / std::sqrt(2.0), 0.33 * diag / std::sqrt(2.0), 0});
    const face_descriptor f_inside = face_of_vertex(m, MDCS_test::nearest_vertex(m, Vec3{0.5 * diag / std::sqrt(2.0), 0.25 * diag / std::sqrt(2.0), 0}));
    const face_descriptor f_other = face_of_vertex(m, MDCS_test::nearest_vertex(m, Vec3{0.2 * diag / std::sqrt(2.0), 0.5 * diag / std::sqrt(2.0), 0}));
    const Face_location loc_inside = location(f_inside, {0.2, 0.3, 0.5});
    const Face_location loc_other = location(f_other, {0.6, 0.25, 0.15});

    for(int kind = 0; kind < 4; ++kind) {
      const char* kinds[] = {"corner vertex", "interior vertex", "interior face location", "two sources (vertex + face location)"};
      INFO("mesh: " << ns.name << ", source: " << kinds[kind]);
      Geodesics g(m);
      std::vector<Vec3> sources;
      switch(kind) {
      case 0:
        g.add_source(corner);
        sources.push_back(MDCS_test::vertex_vec3(m, corner));
        break;
      case 1:
        g.add_source(interior);
        sources.push_back(MDCS_test::vertex_vec3(m, interior));
        break;
      case 2:
        g.add_source(loc_inside);
        sources.push_back(MDCS_test::location_point(m, loc_inside.first, loc_inside.second));
        break;
      default:
        g.add_source(corner);
        g.add_source(loc_other);
        sources.push_back(MDCS_test::vertex_vec3(m, corner));
        sources.push_back(MDCS_test::location_point(m, loc_other.first, loc_other.second));
      }
      auto euclid = [&](const Vec3& p, std::size_t* argmin = nullptr) {
        double best = MDCS_test::inf;
        for(std::size_t i = 0; i < sources.size(); ++i)
          if(MDCS_test::dist(p, sources[i]) < best) {
            best = MDCS_test::dist(p, sources[i]);
            if(argmin) *argmin = i;
          }
        return best;
      };

      std::vector<double> expected;
      for(vertex_descriptor v : vertices(m))
        expected.push_back(euclid(MDCS_test::vertex_vec3(m, v)));
      const auto cmp = MDCS_test::compare_distances(expected, MDCS_test::vertex_distances(g, m), floor_value);
      INFO("vertices: " << cmp);
      CHECK(cmp.ok(tolerance));

      // nearest sources of the vertices (where the choice is not a near tie)
      std::size_t wrong_nearest = 0;
      for(vertex_descriptor v : vertices(m)) {
        std::size_t arg = 0;
        const Vec3 p = MDCS_test::vertex_vec3(m, v);
        euclid(p, &arg);
        double second = MDCS_test::inf;
        for(std::size_t i = 0; i < sources.size(); ++i)
          if(i != arg) second = std::min(second, MDCS_test::dist(p, sources[i]));
        if(second - euclid(p) > 1e-9 * diag && g.nearest_source(v).second != arg)
          ++wrong_nearest;
      }
      CHECK(wrong_nearest == 0);

      // arbitrary surface points
      std::vector<double> e_q, g_q;
      std::size_t inconsistent = 0;
      for(const auto& q : queries) {
        const Face_location ql = location(q.first, q.second);
        e_q.push_back(euclid(MDCS_test::location_point(m, q.first, q.second)));
        g_q.push_back(g.distance(ql));
        if(g.nearest_source(ql).first != g_q.back())
          ++inconsistent;
      }
      const auto cmp_q = MDCS_test::compare_distances(e_q, g_q, floor_value);
      INFO("face locations: " << cmp_q);
      CHECK(cmp_q.ok(tolerance));
      CHECK(inconsistent == 0);

      // at the source itself
      if(kind == 2)
        CHECK(std::abs(g.distance(loc_inside)) <= floor_value);
      CHECK(g.statistics().windows_created > 0);
    }
  }
}

TEST_CASE("exact geodesics: regular tetrahedron against unfoldings", "[geodesics][exact][analytic]")
{
  const Mesh m = make_mesh(MDCS_test::regular_tetrahedron<Point_3>());
  const auto queries = MDCS_test::random_face_locations(m, 200, 5);
  for(vertex_descriptor s : vertices(m)) {
    INFO("source vertex " << std::size_t(s));
    const Vec3 ps = MDCS_test::vertex_vec3(m, s);
    Geodesics g(m);
    g.add_source(s);
    for(vertex_descriptor v : vertices(m))
      CHECK(g.distance(v) == Approx(v == s ? 0.0 : 1.0).epsilon(tolerance).margin(tolerance));

    // analytic distance at a face point
    auto analytic = [&](face_descriptor f, const std::array<double, 3>& b) {
      const auto vs = MDCS_test::face_vertices(m, f);
      const Vec3 p = MDCS_test::location_point(m, f, b);
      if(vs[0] == s || vs[1] == s || vs[2] == s)
        return MDCS_test::dist(ps, p); // same face: straight segment
      return MDCS_test::tetrahedron_opposite_face_distance(ps, MDCS_test::vertex_vec3(m, vs[0]), MDCS_test::vertex_vec3(m, vs[1]),
                                                           MDCS_test::vertex_vec3(m, vs[2]), p);
    };

    // the centroid of the opposite face: unfolded across any of its edges, the path is the height of the
    // source's face plus the inradius-to-edge distance of the opposite face: sqrt(3)/2 + sqrt(3)/6 = 2/sqrt(3)
    for(face_descriptor f : faces(m)) {
      const auto vs = MDCS_test::face_vertices(m, f);
      if(vs[0] == s || vs[1] == s || vs[2] == s)
        continue;
      const std::array<double, 3> centroid = {1.0 / 3, 1.0 / 3, 1.0 / 3};
      CHECK(analytic(f, centroid) == Approx(2 / std::sqrt(3.0)).epsilon(1e-14)); // the oracle itself
      CHECK(g.distance(location(f, centroid)) == Approx(2 / std::sqrt(3.0)).epsilon(tolerance));
      // midpoints of the opposite face's edges: sqrt(3)/2 (height of the source's face)
      CHECK(g.distance(location(f, {0.5, 0.5, 0})) == Approx(std::sqrt(3.0) / 2).epsilon(tolerance));
      CHECK(g.distance(location(f, {0, 0.5, 0.5})) == Approx(std::sqrt(3.0) / 2).epsilon(tolerance));
    }

    MDCS_test::Smsp_oracle<K, Mesh> smsp(m);
    smsp.add_source(s);
    smsp.build();
    std::vector<double> e, got, ref;
    for(const auto& q : queries) {
      e.push_back(analytic(q.first, q.second));
      got.push_back(g.distance(location(q.first, q.second)));
      ref.push_back(smsp.distance(q.first, q.second));
    }
    const auto oracle_check = MDCS_test::compare_distances(ref, e, 1e-12);
    INFO("analytic oracle vs Surface_mesh_shortest_path (self-check of the test): " << oracle_check);
    REQUIRE(oracle_check.ok(1e-9));
    const auto cmp = MDCS_test::compare_distances(e, got, 1e-12);
    INFO("engine vs analytic: " << cmp);
    CHECK(cmp.ok(tolerance));
  }
}

TEST_CASE("exact geodesics: subdivided unit cube against unfoldings", "[geodesics][exact][analytic]")
{
  for(std::size_t n : {1, 2, 3, 4}) {
    const Mesh m = make_mesh(MDCS_test::subdivided_cube<Point_3>(n));
    REQUIRE(CGAL::is_closed(m));
    const auto queries = MDCS_test::random_face_locations(m, 100, unsigned(n));
    for(const Vec3 corner : {Vec3{0, 0, 0}, Vec3{1, 1, 1}, Vec3{1, 0, 1}}) {
      INFO("cube subdivided " << n << "x" << n << ", source corner (" << corner[0] << "," << corner[1] << "," << corner[2] << ")");
      // map a point so that the source corner becomes the origin
      auto to_origin = [&](const Vec3& p) {
        Vec3 q;
        for(int k = 0; k < 3; ++k)
          q[std::size_t(k)] = corner[std::size_t(k)] == 1 ? 1 - p[std::size_t(k)] : p[std::size_t(k)];
        return q;
      };
      auto analytic = [&](const Vec3& p) { return MDCS_test::cube_corner_distance(to_origin(p), 1e-12); };
      const vertex_descriptor s = MDCS_test::nearest_vertex(m, corner);
      REQUIRE(MDCS_test::dist(MDCS_test::vertex_vec3(m, s), corner) == 0);
      Geodesics g(m);
      g.add_source(s);

      std::vector<double> e;
      for(vertex_descriptor v : vertices(m))
        e.push_back(analytic(MDCS_test::vertex_vec3(m, v)));
      const auto smsp = MDCS_test::smsp_vertex_distances<K>(m, std::vector<vertex_descriptor>{s});
      const auto oracle_check = MDCS_test::compare_distances(smsp, e, 1e-12);
      INFO("analytic oracle vs Surface_mesh_shortest_path (self-check of the test): " << oracle_check);
      REQUIRE(oracle_check.ok(1e-9));
      const auto cmp = MDCS_test::compare_distances(e, MDCS_test::vertex_distances(g, m), 1e-12);
      INFO("vertices: " << cmp);
      CHECK(cmp.ok(tolerance));

      // named analytic values (p given relative to the source corner)
      const std::vector<std::pair<Vec3, double>> named = {
          {{1, 1, 1}, std::sqrt(5.0)},      // opposite corner: two faces unfolded into a 2 x 1 rectangle
          {{0.5, 0.5, 1}, std::sqrt(2.5)},  // centre of a far face: (0.5, 1.5) in the unfolding
          {{1, 0.5, 0.5}, std::sqrt(2.5)},
          {{0, 0.5, 0.5}, std::sqrt(0.5)},  // centre of a near face
          {{1, 1, 0}, std::sqrt(2.0)},      // corner of a near face
          {{1, 1, 0.5}, std::sqrt(3.25)},   // midpoint of a far edge: (1.5, 1) in the unfolding
          {{1, 0, 1}, std::sqrt(2.0)},
          {{1, 0.5, 1}, std::sqrt(3.25)}};  // (1.5, 1) across y = 0
      for(const auto& nv : named) {
        Vec3 p = to_origin(nv.first); // to_origin is an involution
        const auto loc = MDCS_test::locate_point(m, p);
        INFO("point (" << p[0] << ", " << p[1] << ", " << p[2] << ")");
        CHECK(analytic(p) == Approx(nv.second).epsilon(1e-14));
        CHECK(g.distance(location(loc.first, loc.second)) == Approx(nv.second).epsilon(tolerance));
      }

      std::vector<double> eq, gq;
      for(const auto& q : queries) {
        eq.push_back(analytic(MDCS_test::location_point(m, q.first, q.second)));
        gq.push_back(g.distance(location(q.first, q.second)));
      }
      const auto cmp_q = MDCS_test::compare_distances(eq, gq, 1e-12);
      INFO("face locations: " << cmp_q);
      CHECK(cmp_q.ok(tolerance));
    }
  }
}

TEST_CASE("exact geodesics: icosphere and bumpy sphere against Surface_mesh_shortest_path",
          "[geodesics][exact][smsp]")
{
  const std::vector<Named_soup> meshes = {{"icosphere 2", MDCS_test::icosphere<Point_3>(2)},
                                          {"bumpy sphere 2", MDCS_test::bumpy_sphere<Point_3>(2, 0.15, 3)},
                                          {"terrain 12x12", MDCS_test::height_field_grid<Point_3>(12, 0.3, 9)}};
  for(const Named_soup& ns : meshes) {
    const Mesh m = make_mesh(ns.soup);
    const double floor_value = tolerance * MDCS_test::bbox_diagonal(m);
    const auto queries = MDCS_test::random_face_locations(m, 80, 17);
    for(std::size_t count : {1, 3}) {
      const auto sources = MDCS_test::spread_vertices(m, count, 3);
      INFO(ns.name << ", " << sources.size() << " vertex source(s)");
      Geodesics g(m);
      MDCS_test::Smsp_oracle<K, Mesh> smsp(m);
      for(auto s : sources) {
        g.add_source(s);
        smsp.add_source(s);
      }
      smsp.build();
      std::vector<double> e;
      for(vertex_descriptor v : vertices(m))
        e.push_back(smsp.distance(v));
      const auto cmp = MDCS_test::compare_distances(e, MDCS_test::vertex_distances(g, m), floor_value);
      INFO("vertices: " << cmp);
      CHECK(cmp.ok(tolerance));
      std::vector<double> eq, gq;
      for(const auto& q : queries) {
        eq.push_back(smsp.distance(q.first, q.second));
        gq.push_back(g.distance(location(q.first, q.second)));
      }
      const auto cmp_q = MDCS_test::compare_distances(eq, gq, floor_value);
      INFO("face locations: " << cmp_q);
      CHECK(cmp_q.ok(tolerance));
    }
    {
      // a source inside a face
      const auto src = MDCS_test::random_face_locations(m, 1, 99)[0];
      INFO(ns.name << ", face-location source");
      Geodesics g(m);
      g.add_source(location(src.first, src.second));
      MDCS_test::Smsp_oracle<K, Mesh> smsp(m);
      smsp.add_source(src.first, src.second);
      smsp.build();
      std::vector<double> e;
      for(vertex_descriptor v : vertices(m))
        e.push_back(smsp.distance(v));
      const auto cmp = MDCS_test::compare_distances(e, MDCS_test::vertex_distances(g, m), floor_value);
      INFO("vertices: " << cmp);
      CHECK(cmp.ok(tolerance));
      std::vector<double> eq, gq;
      for(const auto& q : queries) {
        eq.push_back(smsp.distance(q.first, q.second));
        gq.push_back(g.distance(location(q.first, q.second)));
      }
      const auto cmp_q = MDCS_test::compare_distances(eq, gq, floor_value);
      INFO("face locations: " << cmp_q);
      CHECK(cmp_q.ok(tolerance));
    }
  }
}
