// Properties every exact geodesic distance must have, checked on curved meshes with saddles and boundaries:
// symmetry, triangle inequality, Dijkstra upper bound and Euclidean lower bound, several sources = minimum of
// single sources, distance limit and stop targets (early stop never gives a wrong finite value), reuse of one
// object with other sources / options, independence of the FaceGraph model (Surface_mesh, Polyhedron_3 with and
// without ids), the distances_only memory mode, the one-shot function (also with a vertex point map), the
// progress callback and the statistics.
#include <catch2/catch.hpp>

#include <MDCS_test/cgal_meshes.h>
#include <MDCS_test/geodesic_oracles.h>
#include <MDCS_test/geodesic_test_meshes.h>
#include <MDCS_test/mesh_generators.h>
#include <MDCS_test/geodesic_test_geometry.h>

#include <CGAL/Polyhedral_geodesics_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace {

using namespace MDCS_test::Epick_surface_mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef CGAL::Polyhedron_3<K, CGAL::Polyhedron_items_with_id_3> Polyhedron_with_id;
namespace PG = CGAL::Polyhedral_geodesics_3;
typedef PG::Exact_geodesic_distances_3<Mesh> Geodesics;
typedef Geodesics::Face_location Face_location;
using MDCS_test::Vec3;

using MDCS_test::tolerance;
using MDCS_test::inf;

typedef MDCS_test::Named_soup<Point_3> Named_soup;

// Curved test meshes: closed with saddles, open terrain with saddles, convex closed, flat with a hole.
std::vector<Named_soup> curved_meshes()
{
  return {{"bumpy sphere 2", MDCS_test::bumpy_sphere<Point_3>(2, 0.2, 1)},
          {"terrain 10x10", MDCS_test::height_field_grid<Point_3>(10, 0.35, 4)},
          {"icosphere 2", MDCS_test::icosphere<Point_3>(2)},
          {"cube 3x3", MDCS_test::subdivided_cube<Point_3>(3)},
          {"square with a hole", MDCS_test::square_with_hole<Point_3>(10, 3, 7, 4, 6)}};
}

template <class M>
M make(const MDCS_test::Triangle_soup<Point_3>& soup)
{
  M m;
  soup.to_mesh(m);
  REQUIRE(num_faces(m) == soup.triangles.size());
  return m;
}

using MDCS_test::vertex_distances;

std::vector<double> single_source(const Mesh& m, vertex_descriptor s)
{
  Geodesics g(m);
  g.add_source(s);
  return vertex_distances(g, m);
}

using MDCS_test::index_of;

} // namespace

TEST_CASE("exact geodesics: symmetry, triangle inequality, Dijkstra and Euclidean bounds", "[geodesics][exact][invariants]")
{
  for(const Named_soup& ns : curved_meshes()) {
    INFO(ns.name);
    const Mesh m = make<Mesh>(ns.soup);
    const double diag = MDCS_test::bbox_diagonal(m);
    const double floor_value = tolerance * diag;
    const auto samples = MDCS_test::spread_vertices(m, 6, 1);
    std::vector<std::vector<double>> d; // d[i][v] = distance from samples[i]
    for(auto s : samples)
      d.push_back(single_source(m, s));

    std::size_t asymmetric = 0, triangle = 0, above_dijkstra = 0, below_euclid = 0, nan = 0;
    double worst_asym = 0;
    for(std::size_t i = 0; i < samples.size(); ++i) {
      const auto dij = MDCS_test::dijkstra_vertex_distances(m, std::vector<vertex_descriptor>{samples[i]});
      std::size_t k = 0;
      for(auto v : vertices(m)) {
        const double x = d[i][k];
        if(std::isnan(x)) ++nan;
        if(x > dij[k] * (1 + tolerance) + floor_value) ++above_dijkstra;
        if(x < MDCS_test::dist(MDCS_test::vertex_vec3(m, v), MDCS_test::vertex_vec3(m, samples[i])) * (1 - tolerance) - floor_value)
          ++below_euclid;
        ++k;
      }
      CHECK(d[i][index_of(m, samples[i])] == 0);
      for(std::size_t j = 0; j < samples.size(); ++j) {
        const double ab = d[i][index_of(m, samples[j])], ba = d[j][index_of(m, samples[i])];
        const double r = MDCS_test::relative_difference(ab, ba, floor_value);
        worst_asym = std::max(worst_asym, r);
        if(!(r <= tolerance)) ++asymmetric;
        // d(a, v) <= d(a, b) + d(b, v) for every vertex v
        for(std::size_t k2 = 0; k2 < d[i].size(); ++k2)
          if(d[i][k2] > (ab + d[j][k2]) * (1 + tolerance) + floor_value)
            ++triangle;
      }
    }
    INFO("worst relative asymmetry " << worst_asym);
    CHECK(nan == 0);
    CHECK(asymmetric == 0);
    CHECK(triangle == 0);
    CHECK(above_dijkstra == 0);
    CHECK(below_euclid == 0);
  }
}

TEST_CASE("exact geodesics: several sources are the minimum of single sources", "[geodesics][exact][invariants]")
{
  for(const Named_soup& ns : curved_meshes()) {
    INFO(ns.name);
    const Mesh m = make<Mesh>(ns.soup);
    const double floor_value = tolerance * MDCS_test::bbox_diagonal(m);
    const auto sources = MDCS_test::spread_vertices(m, 3, 5);
    REQUIRE(sources.size() == 3);
    std::vector<std::vector<double>> single;
    for(auto s : sources)
      single.push_back(single_source(m, s));
    Geodesics g(m);
    for(std::size_t i = 0; i < sources.size(); ++i)
      CHECK(g.add_source(sources[i]) == i);
    CHECK(g.number_of_sources() == 3);
    std::vector<double> expected, got;
    std::size_t wrong_source = 0, k = 0;
    for(auto v : vertices(m)) {
      std::vector<double> ds = {single[0][k], single[1][k], single[2][k]};
      const std::size_t arg = std::size_t(std::min_element(ds.begin(), ds.end()) - ds.begin());
      std::sort(ds.begin(), ds.end());
      expected.push_back(ds[0]);
      const auto ns_v = g.nearest_source(v);
      got.push_back(ns_v.first);
      CHECK(ns_v.first == g.distance(v));
      if(ds[1] - ds[0] > 1e-9 * std::max(1.0, ds[0]) && ns_v.second != arg)
        ++wrong_source;
      ++k;
    }
    const auto cmp = MDCS_test::compare_distances(expected, got, floor_value);
    INFO(cmp);
    CHECK(cmp.ok(tolerance));
    CHECK(wrong_source == 0);
    // the sources themselves
    for(std::size_t i = 0; i < sources.size(); ++i) {
      CHECK(g.distance(sources[i]) == 0);
      CHECK(g.nearest_source(sources[i]).second == i);
    }
  }
}

TEST_CASE("exact geodesics: distance limit and stop targets", "[geodesics][exact][invariants]")
{
  for(const Named_soup& ns : curved_meshes()) {
    INFO(ns.name);
    const Mesh m = make<Mesh>(ns.soup);
    const double floor_value = tolerance * MDCS_test::bbox_diagonal(m);
    const auto sources = MDCS_test::spread_vertices(m, 2, 3);
    Geodesics full(m);
    for(auto s : sources) full.add_source(s);
    const std::vector<double> d = vertex_distances(full, m);
    std::vector<double> sorted = d;
    std::sort(sorted.begin(), sorted.end());

    for(double fraction : {0.0, 0.3, 0.5, 0.9}) {
      const double limit = fraction == 0.0 ? 0.0 : sorted[std::size_t(fraction * double(sorted.size()))];
      INFO("distance limit " << limit << " (fraction " << fraction << ")");
      Geodesics g(m);
      for(auto s : sources) g.add_source(s);
      g.set_distance_limit(limit);
      std::size_t wrong_inside = 0, finite_outside = 0, wrong_finite = 0, k = 0;
      for(auto v : vertices(m)) {
        const double x = g.distance(v);
        if(d[k] < limit * (1 - 1e-9) && !(MDCS_test::relative_difference(x, d[k], floor_value) <= tolerance))
          ++wrong_inside;
        if(d[k] > limit * (1 + 1e-9) + floor_value && x != inf)
          ++finite_outside;
        if(x != inf && !(MDCS_test::relative_difference(x, d[k], floor_value) <= tolerance))
          ++wrong_finite;
        if(x == inf)
          CHECK(g.nearest_source(v).second == Geodesics::no_source);
        ++k;
      }
      CHECK(wrong_inside == 0);
      CHECK(finite_outside == 0);
      CHECK(wrong_finite == 0);
      for(auto s : sources) CHECK(g.distance(s) == 0);
      if(fraction < 0.9)
        CHECK(g.statistics().stopped_early);
      // the limit removed: the full result again, on the same object
      g.clear_distance_limit();
      const auto cmp = MDCS_test::compare_distances(d, vertex_distances(g, m), floor_value);
      INFO("after clear_distance_limit: " << cmp);
      CHECK(cmp.ok(tolerance));
    }

    // stop targets: the targets are exact, every other vertex is exact or +infinity
    const auto targets = MDCS_test::spread_vertices(m, 3, 11);
    Geodesics g(m);
    for(auto s : sources) g.add_source(s);
    g.set_stop_targets(targets);
    for(auto t : targets) {
      INFO("stop target " << std::size_t(t));
      CHECK(MDCS_test::relative_difference(g.distance(t), d[index_of(m, t)], floor_value) <= tolerance);
    }
    std::size_t wrong_finite = 0, k = 0;
    for(auto v : vertices(m)) {
      const double x = g.distance(v);
      if(x != inf && !(MDCS_test::relative_difference(x, d[k], floor_value) <= tolerance))
        ++wrong_finite;
      ++k;
    }
    CHECK(wrong_finite == 0);
    g.clear_stop_targets();
    const auto cmp = MDCS_test::compare_distances(d, vertex_distances(g, m), floor_value);
    INFO("after clear_stop_targets: " << cmp);
    CHECK(cmp.ok(tolerance));
  }
}

TEST_CASE("exact geodesics: an object reused with other sources equals a fresh one", "[geodesics][exact][invariants]")
{
  const Mesh m = make<Mesh>(MDCS_test::bumpy_sphere<Point_3>(2, 0.2, 8));
  const auto vs = MDCS_test::spread_vertices(m, 4, 2);
  const auto loc = MDCS_test::random_face_locations(m, 1, 3)[0];
  Geodesics g(m);
  g.add_source(vs[0]);
  g.compute();
  CHECK(g.is_computed());
  const auto first = vertex_distances(g, m);
  CHECK(first == single_source(m, vs[0]));
  CHECK(std::all_of(first.begin(), first.end(), [](double x) { return std::isfinite(x); })); // connected mesh

  g.clear_sources();
  CHECK_FALSE(g.is_computed());
  g.add_source(vs[1]);
  g.add_source(Face_location(loc.first, loc.second));
  Geodesics fresh(m);
  fresh.add_source(vs[1]);
  fresh.add_source(Face_location(loc.first, loc.second));
  CHECK(vertex_distances(g, m) == vertex_distances(fresh, m));
  const auto queries = MDCS_test::random_face_locations(m, 30, 4);
  for(const auto& q : queries)
    CHECK(g.distance(Face_location(q.first, q.second)) == fresh.distance(Face_location(q.first, q.second)));

  // adding a source to a computed object
  g.add_source(vs[2]);
  fresh.add_source(vs[2]);
  CHECK_FALSE(g.is_computed());
  CHECK(vertex_distances(g, m) == vertex_distances(fresh, m));

  // memory mode switch on the same object: the vertex-oriented schedule (the default of both modes) gives the
  // same values up to rounding, and so does the window propagation
  g.set_memory_mode(PG::Geodesic_memory_mode::distances_only);
  CHECK(g.memory_mode() == PG::Geodesic_memory_mode::distances_only);
  {
    const auto cmp = MDCS_test::compare_distances(vertex_distances(fresh, m), vertex_distances(g, m), 1e-14);
    INFO(cmp);
    CHECK(cmp.ok(1e-14));
    CHECK(g.used_vertex_oriented_propagation());
  }
  g.set_vertex_oriented_propagation(false);
  {
    const auto cmp = MDCS_test::compare_distances(vertex_distances(fresh, m), vertex_distances(g, m), 1e-14);
    INFO(cmp);
    CHECK(cmp.ok(1e-14));
  }
  CHECK_FALSE(g.used_vertex_oriented_propagation());
  CHECK_THROWS_AS(g.distance(Face_location(loc.first, loc.second)), std::logic_error);
  g.set_memory_mode(PG::Geodesic_memory_mode::full_field);
  CHECK(g.distance(Face_location(loc.first, loc.second)) == fresh.distance(Face_location(loc.first, loc.second)));
}

namespace {

// Vertex distances keyed by the vertex position (the meshes are built from the same soup, so positions are
// unique and identical).
template <class M>
std::map<std::tuple<double, double, double>, double> distances_by_point(const M& m, const Vec3& source_position,
                                                                       std::size_t& windows)
{
  typedef PG::Exact_geodesic_distances_3<M> G;
  G g(m);
  g.add_source(MDCS_test::nearest_vertex(m, source_position));
  std::map<std::tuple<double, double, double>, double> r;
  for(auto v : vertices(m)) {
    const Vec3 p = MDCS_test::vertex_vec3(m, v);
    r[std::make_tuple(p[0], p[1], p[2])] = g.distance(v);
  }
  windows = g.statistics().windows_created;
  // a path is available too
  std::vector<typename G::Point_3> path;
  g.shortest_path_points(*vertices(m).begin(), std::back_inserter(path));
  CHECK(!path.empty());
  return r;
}

} // namespace

TEST_CASE("exact geodesics: Surface_mesh, Polyhedron_3 and Polyhedron_3 with ids agree", "[geodesics][exact][invariants]")
{
  for(const Named_soup& ns : curved_meshes()) {
    INFO(ns.name);
    const Mesh sm = make<Mesh>(ns.soup);
    const Polyhedron ph = make<Polyhedron>(ns.soup);
    const Polyhedron_with_id phi = make<Polyhedron_with_id>(ns.soup);
    const Vec3 source_position = MDCS_test::to_vec3(ns.soup.points[ns.soup.points.size() / 3]);
    std::size_t w_sm = 0, w_ph = 0, w_phi = 0;
    const auto a = distances_by_point(sm, source_position, w_sm);
    const auto b = distances_by_point(ph, source_position, w_ph);
    const auto c = distances_by_point(phi, source_position, w_phi);
    REQUIRE(a.size() == num_vertices(sm));
    REQUIRE(b.size() == a.size());
    REQUIRE(c.size() == a.size());
    double worst_b = 0, worst_c = 0;
    for(const auto& kv : a) {
      REQUIRE(b.count(kv.first) == 1);
      REQUIRE(c.count(kv.first) == 1);
      worst_b = std::max(worst_b, MDCS_test::relative_difference(b.at(kv.first), kv.second, 1e-14));
      worst_c = std::max(worst_c, MDCS_test::relative_difference(c.at(kv.first), kv.second, 1e-14));
      CHECK(std::isfinite(kv.second));
    }
    INFO("max relative difference Surface_mesh vs Polyhedron_3: " << worst_b << ", vs Polyhedron_3 with ids: " << worst_c);
    CHECK(worst_b <= 1e-14);
    CHECK(worst_c <= 1e-14);
    CHECK(w_sm > 0);
    CHECK(w_ph > 0);
    CHECK(w_phi > 0);
  }
}

TEST_CASE("exact geodesics: distances_only mode", "[geodesics][exact][invariants]")
{
  for(const Named_soup& ns : curved_meshes()) {
    INFO(ns.name);
    const Mesh m = make<Mesh>(ns.soup);
    const auto sources = MDCS_test::spread_vertices(m, 2, 9);
    Geodesics full(m), light(m, PG::Geodesic_memory_mode::distances_only);
    CHECK(full.memory_mode() == PG::Geodesic_memory_mode::full_field);
    CHECK(light.memory_mode() == PG::Geodesic_memory_mode::distances_only);
    for(auto s : sources) {
      full.add_source(s);
      light.add_source(s);
    }
    const auto a = vertex_distances(full, m), b = vertex_distances(light, m);
    const auto cmp = MDCS_test::compare_distances(a, b, 1e-14);
    INFO(cmp);
    CHECK(cmp.ok(1e-14));
    std::size_t k = 0;
    std::vector<std::vector<double>> single;
    for(auto s : sources) single.push_back(single_source(m, s));
    for(auto v : vertices(m)) {
      // the same nearest source, unless another one reaches v at the same distance (up to rounding)
      const std::size_t ls = light.nearest_source(v).second, fs = full.nearest_source(v).second;
      if(ls != fs) {
        REQUIRE(ls < single.size());
        CHECK(std::abs(single[ls][k] - a[k]) <= 1e-12 * std::max(1.0, a[k]));
      }
      ++k;
    }
    const face_descriptor f = *faces(m).begin();
    const Face_location loc(f, {0.2, 0.3, 0.5});
    std::vector<Point_3> path;
    struct Visitor
    {
      void operator()(vertex_descriptor) {}
      void operator()(boost::graph_traits<Mesh>::halfedge_descriptor, double) {}
      void operator()(face_descriptor, const std::array<double, 3>&) {}
    } visitor;
    CHECK_THROWS_AS(light.distance(loc), std::logic_error);
    CHECK_THROWS_AS(light.nearest_source(loc), std::logic_error);
    CHECK_THROWS_AS(light.shortest_path_points(sources[0], std::back_inserter(path)), std::logic_error);
    CHECK_THROWS_AS(light.shortest_path_points(loc, std::back_inserter(path)), std::logic_error);
    CHECK_THROWS_AS(light.shortest_path_sequence(sources[0], visitor), std::logic_error);
    CHECK_THROWS_AS(light.shortest_path_sequence(loc, visitor), std::logic_error);
    CHECK(light.statistics().windows_created > 0);
    CHECK(full.statistics().windows_created > 0);
    CHECK(full.statistics().windows_propagated > 0);
    CHECK(full.statistics().peak_live_windows > 0);
    CHECK(full.statistics().stored_windows == 0); // the full field keeps per-vertex records, not windows
    CHECK(full.statistics().peak_memory_bytes > 0);
    CHECK_FALSE(full.statistics().stopped_early);
    CHECK(light.statistics().peak_live_windows <= full.statistics().peak_live_windows);
  }
}

// Both modes release an edge's windows from the propagation's store as soon as the front has passed its largest
// value (the full field copies them into its compact store first): the peak number of live windows is a thin band
// around the front, the same in both modes and far below the windows the full field keeps, and the vertex
// distances do not change.
TEST_CASE("exact geodesics: the propagation keeps only the windows near the front", "[geodesics][exact][invariants]")
{
  const Mesh m = make<Mesh>(MDCS_test::bumpy_sphere<Point_3>(4, 0.2, 3));
  REQUIRE(num_vertices(m) > 2000);
  Geodesics full(m), light(m, PG::Geodesic_memory_mode::distances_only);
  full.set_vertex_oriented_propagation(false); // this test is about the window propagation's store
  light.set_vertex_oriented_propagation(false);
  const vertex_descriptor s = *vertices(m).begin();
  full.add_source(s);
  light.add_source(s);
  const auto a = vertex_distances(full, m), b = vertex_distances(light, m);
  const auto cmp = MDCS_test::compare_distances(a, b, 1e-14);
  INFO(cmp);
  CHECK(cmp.ok(1e-14));
  CHECK_FALSE(light.used_vertex_oriented_propagation());
  const PG::Geodesic_statistics& fs = full.statistics();
  const PG::Geodesic_statistics& ls = light.statistics();
  INFO("full field: " << fs.peak_live_windows << " live windows at the peak, distances only: " << ls.peak_live_windows);
  CHECK(ls.windows_created == fs.windows_created);
  CHECK(ls.peak_live_windows == fs.peak_live_windows);
  CHECK(4 * fs.peak_live_windows < fs.stored_windows);
  CHECK(ls.stored_windows < ls.peak_live_windows);
}

TEST_CASE("exact geodesics: the one-shot function equals the class", "[geodesics][exact][invariants]")
{
  for(const Named_soup& ns : curved_meshes()) {
    INFO(ns.name);
    Mesh m = make<Mesh>(ns.soup);
    const double floor_value = tolerance * MDCS_test::bbox_diagonal(m);
    const auto sources = MDCS_test::spread_vertices(m, 3, 4);
    auto dmap = m.add_property_map<vertex_descriptor, double>("v:geodesic_test", -1.0).first;
    auto dmap1 = m.add_property_map<vertex_descriptor, double>("v:geodesic_test1", -1.0).first;
    PG::exact_geodesic_distances_3(m, sources, dmap);
    PG::exact_geodesic_distances_3(m, sources[0], dmap1);

    Geodesics g(m, PG::Geodesic_memory_mode::distances_only), g1(m);
    for(auto s : sources) g.add_source(s);
    g1.add_source(sources[0]);
    auto cmap = m.add_property_map<vertex_descriptor, double>("v:geodesic_class", -1.0).first;
    g.distances(cmap);
    std::size_t differ = 0, differ1 = 0;
    for(auto v : vertices(m)) {
      if(!(get(dmap, v) == g.distance(v))) ++differ;
      if(!(get(cmap, v) == g.distance(v))) ++differ;
      if(!(MDCS_test::relative_difference(get(dmap1, v), g1.distance(v), floor_value) <= 1e-14)) ++differ1;
    }
    CHECK(differ == 0);
    CHECK(differ1 == 0);

    // with a vertex point map: all points scaled by 2 (and translated) -> all distances doubled
    auto scaled = m.add_property_map<vertex_descriptor, Point_3>("v:scaled_point").first;
    for(auto v : vertices(m)) {
      const Point_3& p = m.point(v);
      put(scaled, v, Point_3(2 * p.x() + 1, 2 * p.y() - 3, 2 * p.z() + 0.5));
    }
    auto dmap2 = m.add_property_map<vertex_descriptor, double>("v:geodesic_scaled", -1.0).first;
    PG::exact_geodesic_distances_3(m, sources, dmap2, CGAL::parameters::vertex_point_map(scaled));
    PG::Exact_geodesic_distances_3<Mesh, double, decltype(scaled)> gs(m, scaled);
    for(auto s : sources) gs.add_source(s);
    std::size_t wrong_scale = 0, differ2 = 0;
    for(auto v : vertices(m)) {
      if(!(MDCS_test::relative_difference(get(dmap2, v), 2 * g.distance(v), 2 * floor_value) <= tolerance)) ++wrong_scale;
      if(!(MDCS_test::relative_difference(gs.distance(v), get(dmap2, v), 2 * floor_value) <= 1e-14)) ++differ2;
    }
    CHECK(wrong_scale == 0);
    CHECK(differ2 == 0);
    // the points of a path follow the vertex point map
    std::vector<Point_3> path;
    const vertex_descriptor far = MDCS_test::spread_vertices(m, 1, 123)[0];
    gs.shortest_path_points(far, std::back_inserter(path));
    REQUIRE(!path.empty());
    CHECK(CGAL::squared_distance(path.front(), get(scaled, far)) <= 1e-20);
    CHECK(MDCS_test::relative_difference(MDCS_test::path_length(path), gs.distance(far), 2 * floor_value) <= 1e-9);
  }
}

TEST_CASE("exact geodesics: progress callback and cancellation", "[geodesics][exact][invariants]")
{
  const Mesh m = make<Mesh>(MDCS_test::bumpy_sphere<Point_3>(3, 0.1, 2));
  const auto s = MDCS_test::spread_vertices(m, 1, 0)[0];
  const auto reference = single_source(m, s);

  Geodesics g(m);
  g.add_source(s);
  std::size_t calls = 0;
  double last = -1;
  bool monotone = true, in_range = true, stage_ok = true;
  g.compute([&](const char* stage, double fraction) {
    ++calls;
    if(std::string(stage) != "geodesic propagation") stage_ok = false;
    if(fraction < last) monotone = false;
    if(!(fraction >= 0 && fraction <= 1)) in_range = false;
    last = fraction;
    return true;
  });
  CHECK(calls >= 2);
  CHECK(calls <= 1000);
  CHECK(stage_ok);
  CHECK(monotone);
  CHECK(in_range);
  CHECK(last == 1.0);
  CHECK(vertex_distances(g, m) == reference);

  Geodesics c(m);
  c.add_source(s);
  std::size_t cancel_calls = 0;
  CHECK_THROWS_AS(c.compute([&](const char*, double f) { ++cancel_calls; return f < 0.3; }), CGAL::MDCS::Operation_cancelled);
  CHECK_FALSE(c.is_computed());
  // usable afterwards
  CHECK(vertex_distances(c, m) == reference);
}
