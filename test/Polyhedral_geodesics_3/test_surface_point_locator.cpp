// Surface_point_locator_3: points and rays located on a mesh as Face_locations through an AABB tree built once.
// Oracles: brute force over every face (the closest point of each triangle; the nearest hit of the ray on each
// triangle), points exactly at vertices and on edges, rays that miss, a ray in the plane of the mesh (a segment
// hit), and the located point used as a geodesic source (Euclidean distances on a flat grid).
#include <catch2/catch.hpp>

#include <MDCS_test/geodesic_test_meshes.h>
#include <MDCS_test/mesh_generators.h>

#include <CGAL/Polyhedral_geodesics_3/Exact_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Surface_point_locator_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Random.h>
#include <CGAL/intersections.h>

#include <cmath>
#include <limits>
#include <vector>

namespace {

using namespace MDCS_test::Epick_surface_mesh;
namespace PG = CGAL::Polyhedral_geodesics_3;
typedef PG::Surface_point_locator_3<Mesh> Mesh_locator;
typedef K::Ray_3 Locator_ray;
typedef K::Triangle_3 Locator_triangle;

Locator_triangle locator_face_triangle(const Mesh& m, face_descriptor f)
{
  const halfedge_descriptor h = halfedge(f, m);
  return Locator_triangle(m.point(source(h, m)), m.point(target(h, m)), m.point(target(next(h, m), m)));
}

// The smallest squared distance from p to a face of m: brute force.
double locator_brute_squared_distance(const Mesh& m, const Point_3& p)
{
  double best = std::numeric_limits<double>::infinity();
  for(face_descriptor f : faces(m))
    best = std::min(best, CGAL::squared_distance(p, locator_face_triangle(m, f)));
  return best;
}

// The squared distance from the ray's source to its first hit on m (brute force over every face), or -1.
double locator_brute_first_hit(const Mesh& m, const Locator_ray& ray)
{
  double best = -1;
  for(face_descriptor f : faces(m)) {
    const auto hit = CGAL::intersection(ray, locator_face_triangle(m, f));
    if(!hit) continue;
    double d = -1;
    if(const Point_3* p = boost::get<Point_3>(&*hit)) d = CGAL::squared_distance(ray.source(), *p);
    else if(const K::Segment_3* s = boost::get<K::Segment_3>(&*hit))
      d = std::min(CGAL::squared_distance(ray.source(), s->source()), CGAL::squared_distance(ray.source(), s->target()));
    if(d >= 0 && (best < 0 || d < best)) best = d;
  }
  return best;
}

void check_valid_location(const Mesh_locator::Face_location& loc)
{
  for(double b : loc.second) CHECK(b >= 0);
  CHECK(loc.second[0] + loc.second[1] + loc.second[2] == Approx(1).epsilon(1e-14));
}

} // namespace

TEST_CASE("Surface_point_locator_3: closest points equal brute force over every face", "[geodesics][locate]")
{
  const Mesh m = make_mesh(MDCS_test::icosphere<Point_3>(2));
  const Mesh_locator locator(m);
  CGAL::Random rng(7);
  for(int k = 0; k < 300; ++k) {
    const Point_3 p(rng.get_double(-1.6, 1.6), rng.get_double(-1.6, 1.6), rng.get_double(-1.6, 1.6));
    const auto loc = locator.locate(p);
    check_valid_location(loc);
    const Point_3 q = locator.point(loc);
    // q lies on its face and is as close to p as the closest point of any face
    CHECK(CGAL::squared_distance(q, locator_face_triangle(m, loc.first)) <= 1e-28);
    CHECK(std::sqrt(CGAL::squared_distance(p, q)) == Approx(std::sqrt(locator_brute_squared_distance(m, p))).margin(1e-13));
  }
  // points of the surface itself locate to themselves
  for(face_descriptor f : faces(m)) {
    const Locator_triangle t = locator_face_triangle(m, f);
    const Point_3 p = CGAL::barycenter(t[0], 0.2, t[1], 0.3, t[2], 0.5);
    CHECK(CGAL::squared_distance(locator.point(locator.locate(p)), p) <= 1e-28);
  }
}

TEST_CASE("Surface_point_locator_3: points on vertices and on edges", "[geodesics][locate]")
{
  // A flat grid with dyadic coordinates: edge midpoints are exact, so they lie exactly on the edges.
  const Mesh m = make_mesh(MDCS_test::planar_grid<Point_3>(4, 4));
  const Mesh_locator locator(m);
  for(vertex_descriptor v : vertices(m)) {
    const auto loc = locator.locate(m.point(v));
    check_valid_location(loc);
    // one coordinate is exactly 1, at a corner that is v
    const halfedge_descriptor h = halfedge(loc.first, m);
    const vertex_descriptor corner[3] = {source(h, m), target(h, m), target(next(h, m), m)};
    int ones = 0;
    for(int i = 0; i < 3; ++i)
      if(loc.second[std::size_t(i)] == 1) {
        ++ones;
        CHECK(corner[i] == v);
      }
    CHECK(ones == 1);
  }
  for(halfedge_descriptor h : halfedges(m)) {
    if(is_border(h, m)) continue;
    const Point_3 mid = CGAL::midpoint(m.point(source(h, m)), m.point(target(h, m)));
    const auto loc = locator.locate(mid);
    check_valid_location(loc);
    CHECK(CGAL::squared_distance(locator.point(loc), mid) <= 1e-30);
    // the smallest coordinate (the corner opposite the edge) is zero up to rounding, the other two 1/2
    const double lo = std::min({loc.second[0], loc.second[1], loc.second[2]});
    const double hi = std::max({loc.second[0], loc.second[1], loc.second[2]});
    CHECK(lo <= 1e-15);
    CHECK(hi == Approx(0.5).margin(1e-15));
  }
}

TEST_CASE("Surface_point_locator_3: rays hit where brute force says, or miss", "[geodesics][locate]")
{
  const Mesh m = make_mesh(MDCS_test::icosphere<Point_3>(2));
  const Mesh_locator locator(m);
  CGAL::Random rng(11);
  int hits = 0, misses = 0;
  for(int k = 0; k < 200; ++k) {
    // from outside (a few rays from inside the sphere) in random directions
    const double r = (k % 10 == 0) ? 0.3 : 2.5;
    const Point_3 s(rng.get_double(-r, r), rng.get_double(-r, r), rng.get_double(-r, r));
    const K::Vector_3 d(rng.get_double(-1, 1), rng.get_double(-1, 1), rng.get_double(-1, 1));
    if(d.squared_length() < 1e-6) continue;
    const Locator_ray ray(s, d);
    const auto loc = locator.locate(ray);
    const double brute = locator_brute_first_hit(m, ray);
    REQUIRE(bool(loc) == (brute >= 0));
    if(!loc) {
      ++misses;
      continue;
    }
    ++hits;
    check_valid_location(*loc);
    const Point_3 q = locator.point(*loc);
    CHECK(std::sqrt(CGAL::squared_distance(s, q)) == Approx(std::sqrt(brute)).margin(1e-12));
    CHECK(CGAL::squared_distance(q, ray.supporting_line()) <= 1e-24);
  }
  CHECK(hits > 20);
  CHECK(misses > 20);
  // rays pointing away from the sphere, and one passing beside it
  CHECK_FALSE(locator.locate(Locator_ray(Point_3(0, 0, 2), K::Vector_3(0, 0, 1))));
  CHECK_FALSE(locator.locate(Locator_ray(Point_3(3, 0, 0), K::Vector_3(1, 0.2, 0))));
  CHECK_FALSE(locator.locate(Locator_ray(Point_3(0, 1.5, -3), K::Vector_3(0, 0, 1))));
}

TEST_CASE("Surface_point_locator_3: a ray in the plane of a flat mesh hits its border", "[geodesics][locate]")
{
  const Mesh m = make_mesh(MDCS_test::planar_grid<Point_3>(4, 4));
  const Mesh_locator locator(m);
  const auto loc = locator.locate(Locator_ray(Point_3(-1, 0.375, 0), K::Vector_3(1, 0, 0)));
  REQUIRE(loc);
  check_valid_location(*loc);
  CHECK(CGAL::squared_distance(locator.point(*loc), Point_3(0, 0.375, 0)) <= 1e-30);
  const auto down = locator.locate(Locator_ray(Point_3(0.3, 0.6, 1), K::Vector_3(0, 0, -1)));
  REQUIRE(down);
  CHECK(CGAL::squared_distance(locator.point(*down), Point_3(0.3, 0.6, 0)) <= 1e-30);
  CHECK_FALSE(locator.locate(Locator_ray(Point_3(-1, 0.375, 0), K::Vector_3(-1, 0, 0))));
  CHECK_FALSE(locator.locate(Locator_ray(Point_3(0.5, 0.5, 0.1), K::Vector_3(0, 0, 1))));
}

TEST_CASE("Surface_point_locator_3: a located point as a geodesic source; Polyhedron_3", "[geodesics][locate]")
{
  const Mesh m = make_mesh(MDCS_test::planar_grid<Point_3>(6, 6));
  const Mesh_locator locator(m);
  const Point_3 p(0.31, 0.47, 0.25); // above the grid: located at (0.31, 0.47, 0)
  PG::Exact_geodesic_distances_3<Mesh> g(m);
  g.add_source(locator.locate(p));
  for(vertex_descriptor v : vertices(m)) {
    const Point_3& q = m.point(v);
    CHECK(g.distance(v) == Approx(std::hypot(q.x() - 0.31, q.y() - 0.47)).margin(1e-13));
  }
  // A second mesh type (no internal indices): the same points as on the Surface_mesh of the same soup.
  typedef CGAL::Polyhedron_3<K> Polyhedron;
  Polyhedron poly;
  MDCS_test::icosphere<Point_3>(1).to_mesh(poly);
  const Mesh sphere = make_mesh(MDCS_test::icosphere<Point_3>(1));
  const PG::Surface_point_locator_3<Polyhedron> poly_locator(poly);
  const Mesh_locator sphere_locator(sphere);
  const Point_3 far(0.1, 0.2, 3);
  const auto loc = poly_locator.locate(far);
  CHECK(CGAL::squared_distance(poly_locator.point(loc), sphere_locator.point(sphere_locator.locate(far))) <= 1e-28);
  const Locator_ray down(far, K::Vector_3(0, 0, -1));
  const auto hit = poly_locator.locate(down);
  REQUIRE(hit);
  CHECK(CGAL::squared_distance(poly_locator.point(*hit), sphere_locator.point(*sphere_locator.locate(down))) <= 1e-28);
  CHECK(std::sqrt(CGAL::squared_distance(far, poly_locator.point(*hit))) ==
        Approx(std::sqrt(locator_brute_first_hit(sphere, down))).margin(1e-13));
  // no face, not a triangle mesh
  CHECK_THROWS_AS(Mesh_locator(Mesh()), std::invalid_argument);
  const Mesh quad = unit_square_quad();
  CHECK_THROWS_AS(Mesh_locator(quad), std::invalid_argument);
}
