// Tests of the compact mesh that every geodesic engine builds (internal/Geodesic_mesh.h):
//  - the angle sum of each vertex, accumulated as a product of complex corner directions with the whole turns
//    counted (Vertex_angle_accumulator), against the sum of the corner angles by atan2, on random corners with
//    exact 0, pi / 2 and pi among them, up to 2,000 corners (many turns) and lengths from 1e-150 to 1e150;
//  - against an independent oracle (acos of the normalised dot product, in long double) at the apex of fans
//    that are flat, convex cones and saddles;
//  - on a planar grid: 2 pi inside, pi on the sides, pi / 2 or pi at the corners, and the saddle test of the
//    engines (is_saddle_or_boundary_vertex) where it matters;
//  - the packed halfedge records (twins, edges, lengths, frames) and the vertex data, checked against the
//    original mesh on Surface_mesh and Polyhedron_3 (with and without ids), closed and with boundary, and on a
//    mesh whose faces were removed and re-added (faces not in the order of their halfedges);
//  - the twins by the halfedge index (models that have one) against the walk around the opposite face;
//  - a Surface_mesh with removed faces whose garbage is not collected is refused with a clear message.
#include <catch2/catch.hpp>

#include <MDCS_test/geodesic_oracles.h>
#include <MDCS_test/geodesic_test_meshes.h>
#include <MDCS_test/mesh_generators.h>
#include <MDCS_test/geodesic_test_geometry.h>

#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace {

using namespace MDCS_test::Epick_surface_mesh;
namespace PGI = CGAL::Polyhedral_geodesics_3::internal;

using MDCS_test::pi;

typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef CGAL::Polyhedron_3<K, CGAL::Polyhedron_items_with_id_3> Polyhedron_with_id;

PGI::Geodesic_mesh<double> compact(const Mesh& m)
{
  PGI::Geodesic_mesh<double> cm;
  std::vector<boost::graph_traits<Mesh>::halfedge_descriptor> halfedge_of;
  PGI::build_geodesic_mesh(m, get(CGAL::vertex_point, m), CGAL::get_initialized_vertex_index_map(m),
                           CGAL::get_initialized_face_index_map(m), cm, halfedge_of);
  return cm;
}

using MDCS_test::same_bits;

// Removes every `every`-th face, adds back every `back_every`-th of them in reverse order, collects the garbage:
// face and halfedge indices no longer follow each other.
void remove_and_add_back_faces(Mesh& m, std::size_t every, std::size_t back_every)
{
  std::vector<std::array<Mesh::Vertex_index, 3>> removed;
  std::size_t k = 0;
  for(auto f : std::vector<Mesh::Face_index>(faces(m).begin(), faces(m).end()))
    if(++k % every == 0) {
      auto h = halfedge(f, m);
      removed.push_back({source(h, m), target(h, m), target(next(h, m), m)});
      CGAL::Euler::remove_face(h, m);
    }
  for(std::size_t i = removed.size(); i >= back_every; i -= back_every)
    CGAL::Euler::add_face(std::vector<Mesh::Vertex_index>{removed[i - 1][0], removed[i - 1][1], removed[i - 1][2]}, m);
  m.collect_garbage();
}

// Every field of the packed halfedge records and of the vertex arrays, against the original mesh.
template <class TM>
void check_compact_mesh(const TM& tm)
{
  typedef boost::graph_traits<TM> GT;
  const auto vim = CGAL::get_initialized_vertex_index_map(tm);
  const auto fim = CGAL::get_initialized_face_index_map(tm);
  const auto vpm = get(CGAL::vertex_point, tm);
  PGI::Geodesic_mesh<double> cm;
  std::vector<typename GT::halfedge_descriptor> halfedge_of;
  PGI::build_geodesic_mesh(tm, vpm, vim, fim, cm, halfedge_of);
  typedef PGI::Geodesic_mesh<double> CM;
  const std::size_t nh = 3 * cm.number_of_faces;
  REQUIRE(cm.number_of_vertices == num_vertices(tm));
  REQUIRE(cm.number_of_faces == num_faces(tm));
  REQUIRE(cm.he.size() == nh);
  CHECK(cm.number_of_edges == num_edges(tm));
  CHECK(cm.edge_halfedge.size() == cm.number_of_edges);
  auto distance = [&](typename GT::vertex_descriptor a, typename GT::vertex_descriptor b) {
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, a), get(vpm, b))));
  };
  std::size_t failures = 0, previous_edge_halfedge = 0;
  std::vector<char> edge_seen(cm.number_of_edges, 0);
  for(std::size_t h = 0; h < nh; ++h) {
    const PGI::Geodesic_halfedge<double>& r = cm.he[h];
    const auto oh = halfedge_of[h];
    bool ok = std::size_t(get(fim, face(oh, tm))) == h / 3;                      // the face of the record
    ok = ok && r.source == CM::Index(get(vim, source(oh, tm)));
    ok = ok && cm.target(CM::Index(h)) == CM::Index(get(vim, target(oh, tm)));
    ok = ok && cm.opposite_vertex(CM::Index(h)) == CM::Index(get(vim, target(next(oh, tm), tm)));
    // the twin: the record of the mesh's opposite halfedge, -1 at the border, and an involution
    if(is_border(opposite(oh, tm), tm))
      ok = ok && r.twin == -1;
    else
      ok = ok && r.twin >= 0 && halfedge_of[std::size_t(r.twin)] == opposite(oh, tm) &&
           cm.he[std::size_t(r.twin)].twin == CM::Index(h);
    // the edge: shared with the twin, its canonical halfedge the first of the two, numbered in that order
    ok = ok && r.edge >= 0 && std::size_t(r.edge) < cm.number_of_edges;
    if(ok && r.twin >= 0)
      ok = cm.he[std::size_t(r.twin)].edge == r.edge;
    if(ok && !edge_seen[std::size_t(r.edge)]) {
      edge_seen[std::size_t(r.edge)] = 1;
      ok = cm.edge_halfedge[std::size_t(r.edge)] == CM::Index(h) && (r.edge == 0 || h > previous_edge_halfedge);
      previous_edge_halfedge = h;
    }
    // the length, the same bits on both sides, and the frame: the opposite corner at the lengths of the two
    // other edges from the ends, above the edge
    ok = ok && r.length == Approx(distance(source(oh, tm), target(oh, tm))).epsilon(1e-15);
    if(ok && r.twin >= 0)
      ok = same_bits(r.length, cm.he[std::size_t(r.twin)].length);
    const double a = cm.he[std::size_t(CM::prev(CM::Index(h)))].length; // from the opposite corner to the source
    const double b = cm.he[std::size_t(CM::next(CM::Index(h)))].length; // from the target to the opposite corner
    const double x = r.opposite.x, y = r.opposite.y;
    ok = ok && y >= 0 && std::hypot(x, y) == Approx(a).epsilon(1e-12).margin(1e-14) &&
         std::hypot(x - r.length, y) == Approx(b).epsilon(1e-12).margin(1e-14);
    if(!ok) {
      ++failures;
      if(failures < 5)
        FAIL_CHECK("compact halfedge " << h << " disagrees with the mesh");
    }
  }
  CHECK(failures == 0);
  for(auto v : vertices(tm)) {
    const std::size_t i = get(vim, v);
    INFO("vertex " << i);
    const CM::Index h = cm.vertex_halfedge[i];
    REQUIRE(h >= 0);
    CHECK(cm.source(h) == CM::Index(i));
    CHECK(bool(cm.vertex_on_boundary[i]) == CGAL::is_border(v, tm).has_value());
  }
}

} // namespace

TEST_CASE("geodesic mesh: angle sums from complex products agree with the sum of atan2", "[geodesics][mesh]")
{
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> angle(0, pi), log_length(-6, 6);
  double worst_scaled = 0; // largest |difference| / number of corners
  std::size_t wrong_turns = 0;
  for(int t = 0; t < 20000; ++t) {
    const bool many = t % 50 == 0;
    const int n = 1 + int(rng() % (many ? 2000 : 40));
    // extreme scales now and then, so that the product must be rescaled
    const double scale = t % 7 == 0 ? 1e-150 : (t % 7 == 1 ? 1e150 : 1.0);
    PGI::Vertex_angle_accumulator accumulator(1);
    double sum = 0;
    for(int k = 0; k < n; ++k) {
      const double length = scale * std::exp(log_length(rng));
      double x, y;
      switch(rng() % 8) {
      case 0: x = length; y = 0; break;  // angle 0
      case 1: x = -length; y = 0; break; // angle pi
      case 2: x = 0; y = length; break;  // angle pi / 2
      default: {
        const double a = angle(rng);
        x = length * std::cos(a);
        y = std::abs(length * std::sin(a));
      }
      }
      sum += std::atan2(y, x);
      accumulator.add(0, x, y);
    }
    const double difference = std::abs(sum - accumulator.sum(0));
    worst_scaled = (std::max)(worst_scaled, difference / n);
    if(difference > 1) // a whole turn missed or added
      ++wrong_turns;
  }
  INFO("largest difference per corner " << worst_scaled);
  CHECK(wrong_turns == 0);
  CHECK(worst_scaled < 1e-13);
  // a zero vector (zero-length edge) is no corner
  PGI::Vertex_angle_accumulator accumulator(1);
  accumulator.add(0, 0, 0);
  accumulator.add(0, 0, 1);
  CHECK(accumulator.sum(0) == Approx(pi / 2).epsilon(1e-15));
}

TEST_CASE("geodesic mesh: angle sums at the apex of flat fans, cones and saddles", "[geodesics][mesh]")
{
  // A closed fan of n triangles around an apex at the origin; rim vertex k at angle 2 pi k / n, radius 1 and
  // height heights[k]. The oracle: each corner angle by acos of the normalised dot product, in long double.
  auto check_fan = [](const std::vector<double>& heights) {
    const std::size_t n = heights.size();
    MDCS_test::Triangle_soup<Point_3> soup;
    soup.points.emplace_back(0, 0, 0);
    for(std::size_t k = 0; k < n; ++k)
      soup.points.emplace_back(std::cos(2 * pi * double(k) / double(n)), std::sin(2 * pi * double(k) / double(n)),
                               heights[k]);
    for(std::size_t k = 0; k < n; ++k)
      soup.triangles.push_back({0, 1 + k, 1 + (k + 1) % n});
    const Mesh m = MDCS_test::mesh_from_soup<Mesh>(soup);
    long double expected = 0;
    for(std::size_t k = 0; k < n; ++k) {
      const Point_3& a = soup.points[1 + k];
      const Point_3& b = soup.points[1 + (k + 1) % n];
      const long double dot = (long double)a.x() * b.x() + (long double)a.y() * b.y() + (long double)a.z() * b.z();
      const long double la = std::sqrt((long double)a.x() * a.x() + (long double)a.y() * a.y() + (long double)a.z() * a.z());
      const long double lb = std::sqrt((long double)b.x() * b.x() + (long double)b.y() * b.y() + (long double)b.z() * b.z());
      expected += std::acos(dot / (la * lb));
    }
    const PGI::Geodesic_mesh<double> cm = compact(m);
    INFO("fan of " << n << " triangles, expected angle sum " << double(expected));
    CHECK(cm.vertex_angle_sum[0] == Approx(double(expected)).epsilon(1e-13));
    return double(expected);
  };
  const double flat = check_fan(std::vector<double>(12, 0.0));
  CHECK(flat == Approx(2 * pi).epsilon(1e-15));
  CHECK(check_fan(std::vector<double>(7, -0.8)) < 2 * pi); // a convex cone
  std::vector<double> monkey(30), deep(400);
  for(std::size_t k = 0; k < monkey.size(); ++k)
    monkey[k] = 0.9 * std::cos(3 * 2 * pi * double(k) / 30.0); // three up, three down: a saddle
  CHECK(check_fan(monkey) > 2 * pi);
  for(std::size_t k = 0; k < deep.size(); ++k)
    deep[k] = 5 * std::cos(40 * 2 * pi * double(k) / 400.0); // 400 corners, the sum is several turns
  CHECK(check_fan(deep) > 6 * pi);
}

TEST_CASE("geodesic mesh: angle sums on a planar grid, and the saddle test", "[geodesics][mesh]")
{
  const std::size_t n = 9;
  const Mesh m = MDCS_test::mesh_from_soup<Mesh>(MDCS_test::planar_grid<Point_3>(n, n));
  const PGI::Geodesic_mesh<double> cm = compact(m);
  std::size_t checked = 0;
  for(std::size_t j = 0; j <= n; ++j)
    for(std::size_t i = 0; i <= n; ++i) {
      const std::size_t v = j * (n + 1) + i;
      const bool side_i = i == 0 || i == n, side_j = j == 0 || j == n;
      INFO("vertex " << i << ", " << j);
      if(side_i && side_j)
        CHECK(cm.vertex_angle_sum[v] == Approx(pi / 2).epsilon(1e-14)); // a corner: pi / 2 in one or two faces
      else if(side_i || side_j)
        CHECK(cm.vertex_angle_sum[v] == Approx(pi).epsilon(1e-14));
      else
        CHECK(cm.vertex_angle_sum[v] == Approx(2 * pi).epsilon(1e-14));
      CHECK(bool(cm.vertex_on_boundary[v]) == (side_i || side_j));
      // flat interior vertices count as saddles for the exact engines (a margin of 1e-9 below 2 pi)
      CHECK(PGI::is_saddle_or_boundary_vertex(cm, v));
      ++checked;
    }
  CHECK(checked == cm.number_of_vertices);
}

TEST_CASE("geodesic mesh: the packed halfedge records agree with the mesh", "[geodesics][mesh]")
{
  SECTION("closed Surface_mesh (icosphere)")
  {
    check_compact_mesh(MDCS_test::mesh_from_soup<Mesh>(MDCS_test::icosphere<Point_3>(2)));
  }
  SECTION("Surface_mesh with boundary (planar grid)")
  {
    check_compact_mesh(MDCS_test::mesh_from_soup<Mesh>(MDCS_test::planar_grid<Point_3>(7, 5)));
  }
  SECTION("Polyhedron_3, closed and with boundary")
  {
    check_compact_mesh(MDCS_test::mesh_from_soup<Polyhedron>(MDCS_test::icosphere<Point_3>(1)));
    check_compact_mesh(MDCS_test::mesh_from_soup<Polyhedron>(MDCS_test::subdivided_triangle<Point_3>(6)));
  }
  SECTION("Polyhedron_3 with ids, uninitialised (all 0) and initialised")
  {
    // ids all 0: the builder's index maps initialise them (get_initialized_*_index_map)
    check_compact_mesh(MDCS_test::mesh_from_soup<Polyhedron_with_id>(MDCS_test::icosphere<Point_3>(1)));
    Polyhedron_with_id p = MDCS_test::mesh_from_soup<Polyhedron_with_id>(MDCS_test::subdivided_triangle<Point_3>(6));
    CGAL::set_halfedgeds_items_id(p);
    check_compact_mesh(p);
  }
  SECTION("faces removed and re-added: face indices not in the order of the halfedges")
  {
    Mesh m = MDCS_test::mesh_from_soup<Mesh>(MDCS_test::icosphere<Point_3>(2));
    remove_and_add_back_faces(m, 3, 1);
    REQUIRE(CGAL::is_valid_polygon_mesh(m));
    REQUIRE(CGAL::is_closed(m));
    check_compact_mesh(m);
  }
}

// The twins through the halfedge index (Surface_mesh, Polyhedron_3 with ids) against the walk around the opposite
// halfedge's face, which every model can do: the same compact twin for every compact halfedge.
template <class TM>
void check_twins_by_index_against_walk(const TM& tm)
{
  typedef typename boost::graph_traits<TM>::halfedge_descriptor halfedge_descriptor;
  typedef PGI::Large_vector<std::int32_t> Twins;
  const auto fim = CGAL::get_initialized_face_index_map(tm);
  std::vector<halfedge_descriptor> halfedge_of(3 * num_faces(tm));
  for(auto f : faces(tm)) {
    halfedge_descriptor h = halfedge(f, tm);
    for(std::size_t k = 0; k < 3; ++k, h = next(h, tm))
      halfedge_of[3 * std::size_t(get(fim, f)) + k] = h;
  }
  Twins by_index(halfedge_of.size(), -7), by_walk(halfedge_of.size(), -7);
  PGI::Compact_twins<TM, decltype(fim), Twins, true>::compute(tm, fim, halfedge_of, by_index);
  PGI::Compact_twins<TM, decltype(fim), Twins, false>::compute(tm, fim, halfedge_of, by_walk);
  std::size_t boundary = 0;
  for(std::size_t h = 0; h < halfedge_of.size(); ++h) {
    INFO("compact halfedge " << h);
    REQUIRE(by_index[h] == by_walk[h]);
    if(by_walk[h] < 0)
      ++boundary;
  }
  CHECK(boundary == std::size_t(std::count_if(halfedges(tm).begin(), halfedges(tm).end(),
                                              [&](halfedge_descriptor h) { return is_border(h, tm); })));
}

TEST_CASE("geodesic mesh: twins by the halfedge index equal those by the face walk", "[geodesics][mesh]")
{
  check_twins_by_index_against_walk(MDCS_test::mesh_from_soup<Mesh>(MDCS_test::icosphere<Point_3>(2)));
  check_twins_by_index_against_walk(MDCS_test::mesh_from_soup<Mesh>(MDCS_test::planar_grid<Point_3>(6, 4)));
  check_twins_by_index_against_walk(MDCS_test::mesh_from_soup<Polyhedron_with_id>(MDCS_test::planar_grid<Point_3>(5, 5)));
  // faces removed and re-added, garbage collected: halfedge indices not in face order
  Mesh m = MDCS_test::mesh_from_soup<Mesh>(MDCS_test::planar_grid<Point_3>(6, 6));
  remove_and_add_back_faces(m, 4, 2); // half of the removed faces stay holes
  REQUIRE(CGAL::is_valid_polygon_mesh(m));
  REQUIRE(!CGAL::is_closed(m));
  check_twins_by_index_against_walk(m);
}

TEST_CASE("geodesic mesh: a Surface_mesh with uncollected garbage is refused with a clear message", "[geodesics][mesh]")
{
  Mesh m = MDCS_test::mesh_from_soup<Mesh>(MDCS_test::icosphere<Point_3>(1));
  CGAL::Euler::remove_face(halfedge(*std::next(faces(m).begin(), 3), m), m);
  REQUIRE(m.has_garbage());
  try {
    compact(m);
    FAIL("no exception");
  } catch(const std::invalid_argument& e) {
    CHECK(std::string(e.what()).find("collect_garbage") != std::string::npos);
  }
  m.collect_garbage();
  const PGI::Geodesic_mesh<double> cm = compact(m);
  CHECK(cm.number_of_faces == num_faces(m));
}
