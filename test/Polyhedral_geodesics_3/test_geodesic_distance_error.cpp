// The error metric of approximate geodesic distances (thesis eq. 4.4.1) on hand-made values: the mean and the
// maxima, sources skipped, reachability mismatches counted apart, and other value types than double.
#include <catch2/catch.hpp>

#include <MDCS_test/test_numbers.h>

#include <CGAL/Polyhedral_geodesics_3/geodesic_distance_error.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace PG = CGAL::Polyhedral_geodesics_3;

using MDCS_test::inf;

// A mesh with n vertices (the metric only walks the vertices; faces do not matter).
Mesh mesh_with_vertices(std::size_t n)
{
  Mesh m;
  for(std::size_t i = 0; i < n; ++i)
    m.add_vertex(K::Point_3(double(i), 0, 0));
  return m;
}

// A readable vertex property map over a vector.
struct Vector_map
{
  typedef Vertex key_type;
  typedef double value_type;
  typedef double reference;
  typedef boost::readable_property_map_tag category;
  const std::vector<double>* values;
  friend double get(const Vector_map& m, Vertex v) { return (*m.values)[std::size_t(v)]; }
};

Vector_map vector_map(const std::vector<double>& values) { return Vector_map{&values}; }

} // namespace

TEST_CASE("geodesic_distance_error: mean and maxima of hand-made values", "[geodesics][error]")
{
  const Mesh m = mesh_with_vertices(5);
  //                               source  +10%   -20%  exact  +0.5 absolute
  const std::vector<double> exact  = {0.0,  1.0,  2.0,  4.0,  5.0};
  const std::vector<double> approx = {0.0,  1.1,  1.6,  4.0,  5.5};
  const PG::Geodesic_distance_error e = PG::geodesic_distance_error(m, vector_map(approx), vector_map(exact));
  CHECK(e.compared == 4);
  CHECK(e.skipped_sources == 1);
  CHECK(e.unreachable_mismatches == 0);
  CHECK(e.mean_relative == Approx((0.1 + 0.2 + 0.0 + 0.1) / 4).margin(1e-15));
  CHECK(e.max_relative == Approx(0.2).margin(1e-15));
  CHECK(e.max_absolute == Approx(0.5).margin(1e-15));
}

TEST_CASE("geodesic_distance_error: identical maps give zero error", "[geodesics][error]")
{
  const Mesh m = mesh_with_vertices(4);
  const std::vector<double> d = {0.0, 0.25, 3.0, inf};
  const PG::Geodesic_distance_error e = PG::geodesic_distance_error(m, vector_map(d), vector_map(d));
  CHECK(e.compared == 2);
  CHECK(e.skipped_sources == 1);
  CHECK(e.unreachable_mismatches == 0); // both infinite: ignored
  CHECK(e.mean_relative == 0);
  CHECK(e.max_relative == 0);
  CHECK(e.max_absolute == 0);
}

TEST_CASE("geodesic_distance_error: reachability mismatches and sources are left out of the mean", "[geodesics][error]")
{
  const Mesh m = mesh_with_vertices(6);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> exact  = {0.0, 0.0, 2.0, inf, 3.0, 10.0};
  const std::vector<double> approx = {0.0, 0.3, inf, 7.0, nan, 12.5};
  const PG::Geodesic_distance_error e = PG::geodesic_distance_error(m, vector_map(approx), vector_map(exact));
  CHECK(e.skipped_sources == 2);        // vertices 0 and 1 (exact distance 0)
  CHECK(e.unreachable_mismatches == 3); // vertices 2, 3 (finite in one only) and 4 (NaN counts as unreachable)
  CHECK(e.compared == 1);               // vertex 5
  CHECK(e.mean_relative == Approx(0.25).margin(1e-15));
  CHECK(e.max_relative == Approx(0.25).margin(1e-15));
  CHECK(e.max_absolute == Approx(2.5).margin(1e-15)); // includes the 0.3 at the second source, less than 2.5
}

TEST_CASE("geodesic_distance_error: nothing to compare", "[geodesics][error]")
{
  const Mesh m = mesh_with_vertices(3);
  const std::vector<double> exact = {0.0, inf, inf};
  const std::vector<double> approx = {0.0, inf, 1.0};
  const PG::Geodesic_distance_error e = PG::geodesic_distance_error(m, vector_map(approx), vector_map(exact));
  CHECK(e.compared == 0);
  CHECK(e.skipped_sources == 1);
  CHECK(e.unreachable_mismatches == 1);
  CHECK(e.mean_relative == 0);
  CHECK(e.max_relative == 0);
  CHECK(e.max_absolute == 0);
}

TEST_CASE("geodesic_distance_error: other value types and Surface_mesh property maps", "[geodesics][error]")
{
  Mesh m = mesh_with_vertices(3);
  auto exact = m.add_property_map<Vertex, double>("v:exact", 0.0).first;
  auto approx = m.add_property_map<Vertex, float>("v:approx", 0.0f).first;
  const Vertex v0(0), v1(1), v2(2);
  exact[v0] = 0.0, exact[v1] = 2.0, exact[v2] = 8.0;
  approx[v0] = 0.0f, approx[v1] = 2.5f, approx[v2] = 6.0f; // +25%, -25% (exact in float)
  const PG::Geodesic_distance_error e = PG::geodesic_distance_error(m, approx, exact);
  CHECK(e.compared == 2);
  CHECK(e.mean_relative == 0.25);
  CHECK(e.max_relative == 0.25);
  CHECK(e.max_absolute == 2.0);
}

TEST_CASE("geodesic_distance_error: a negative exact distance is rejected", "[geodesics][error]")
{
  const Mesh m = mesh_with_vertices(2);
  const std::vector<double> exact = {0.0, -1.0};
  const std::vector<double> approx = {0.0, 1.0};
  CHECK_THROWS_AS(PG::geodesic_distance_error(m, vector_map(approx), vector_map(exact)), std::invalid_argument);
}
