// The shared mesh generators produce valid closed / bounded triangle meshes of the expected size and
// topology, on several FaceGraph models.
#include <catch2/catch.hpp>

#include <MDCS_test/mesh_generators.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;

namespace {

template <class Mesh>
long euler_characteristic(const Mesh& m)
{
  return long(num_vertices(m)) - long(num_edges(m)) + long(num_faces(m));
}

} // namespace

TEMPLATE_TEST_CASE("mesh generators: sizes, topology, geometry", "[common][meshes]", Surface_mesh, Polyhedron)
{
  TestType grid, triangle, tetrahedron, sphere;
  MDCS_test::planar_grid<K::Point_3>(4, 3, 2.0, 1.5).to_mesh(grid);
  CHECK(num_vertices(grid) == 20);
  CHECK(num_faces(grid) == 24);
  CHECK(CGAL::is_triangle_mesh(grid));
  CHECK_FALSE(CGAL::is_closed(grid));
  CHECK(euler_characteristic(grid) == 1); // a disc
  CHECK(CGAL::Polygon_mesh_processing::area(grid) == Approx(3.0).epsilon(1e-12));

  MDCS_test::subdivided_triangle<K::Point_3>(5).to_mesh(triangle);
  CHECK(num_faces(triangle) == 25);
  CHECK(num_vertices(triangle) == 21);
  CHECK(CGAL::Polygon_mesh_processing::area(triangle) == Approx(std::sqrt(3.0) / 4).epsilon(1e-12));

  MDCS_test::regular_tetrahedron<K::Point_3>().to_mesh(tetrahedron);
  CHECK(CGAL::is_closed(tetrahedron));
  CHECK(euler_characteristic(tetrahedron) == 2);
  for(auto e : edges(tetrahedron))
    CHECK(CGAL::Polygon_mesh_processing::edge_length(halfedge(e, tetrahedron), tetrahedron) == Approx(1.0).epsilon(1e-12));
  CHECK(CGAL::Polygon_mesh_processing::volume(tetrahedron) > 0); // outward orientation

  MDCS_test::icosphere<K::Point_3>(2).to_mesh(sphere);
  CHECK(num_faces(sphere) == 320);
  CHECK(num_vertices(sphere) == 162);
  CHECK(CGAL::is_closed(sphere));
  CHECK(euler_characteristic(sphere) == 2);
  CHECK(CGAL::Polygon_mesh_processing::volume(sphere) > 0.9 * 4.18879);
  CHECK(CGAL::Polygon_mesh_processing::volume(sphere) < 4.18879);
}

TEST_CASE("mesh generators: bad sizes are rejected", "[common][meshes]")
{
  CHECK_THROWS_AS(MDCS_test::planar_grid<K::Point_3>(0, 3), std::invalid_argument);
  CHECK_THROWS_AS(MDCS_test::subdivided_triangle<K::Point_3>(0), std::invalid_argument);
}
