// The range of input coordinates that every geodesic class accepts (the checks are in the construction of the
// compact mesh, internal/Geodesic_mesh.h, shared by all five classes):
//  - a NaN or infinite coordinate is refused with std::invalid_argument naming the vertex (before the check, the
//    exact class never returned: the vertex stayed unreachable and its neighbours were expanded forever);
//  - a mesh whose largest edge is below 1e-40 or whose bounding box diagonal is above 1e40 is refused (before: no
//    end at 1e-90 times CGAL's elephant, distances off by up to 5% at 2^-170 and 2^190, overflowing frames at
//    1e100);
//  - inside the range the distances scale with the mesh: scaled by 2^-125 and 2^125 (exact in binary floating
//    point, close to both limits), every class gives its unit-scale distances times the scale, to 1e-12.
#include <catch2/catch.hpp>

#include <MDCS_test/geodesic_oracles.h>
#include <MDCS_test/geodesic_test_meshes.h>
#include <MDCS_test/mesh_generators.h>

#include <CGAL/Polyhedral_geodesics_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/transform.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace MDCS_test::Epick_surface_mesh;
namespace PG = CGAL::Polyhedral_geodesics_3;

// The vertex distances of one class from the first vertex; `unit` is the mesh's scale (merged's tolerance is
// absolute, so it scales with the mesh).
typedef std::function<std::vector<double>(const Mesh&, double unit)> Method;

template <class Geodesics, class... Args>
std::vector<double> distances_from_first_vertex(const Mesh& m, Args... args)
{
  Geodesics g(m, args...);
  g.add_source(*vertices(m).begin());
  std::vector<double> d;
  for(vertex_descriptor v : vertices(m))
    d.push_back(g.distance(v));
  return d;
}

std::vector<std::pair<std::string, Method>> all_methods()
{
  return {
    {"exact", [](const Mesh& m, double) { return distances_from_first_vertex<PG::Exact_geodesic_distances_3<Mesh>>(m); }},
    {"merged", [](const Mesh& m, double unit) {
       return distances_from_first_vertex<PG::Merged_window_geodesic_distances_3<Mesh>>(m, 0.01 * unit);
     }},
    {"flat-exact", [](const Mesh& m, double) { return distances_from_first_vertex<PG::Flat_exact_geodesic_distances_3<Mesh>>(m); }},
    {"fast marching", [](const Mesh& m, double) { return distances_from_first_vertex<PG::Fast_marching_geodesic_distances_3<Mesh>>(m); }},
    {"Dijkstra", [](const Mesh& m, double) { return distances_from_first_vertex<PG::Dijkstra_geodesic_distances_3<Mesh>>(m); }},
  };
}

Mesh scaled(const Mesh& m, double s)
{
  Mesh r = m;
  CGAL::Polygon_mesh_processing::transform(K::Aff_transformation_3(CGAL::SCALING, s), r);
  return r;
}

// Runs `method` and returns the message of the std::invalid_argument it throws ("" if none).
std::string invalid_argument_message(const Method& method, const Mesh& m)
{
  try {
    method(m, 1.0);
  } catch(const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST_CASE("geodesic input range: a NaN or infinite coordinate is refused by every class", "[geodesics][robustness]")
{
  const Mesh base = MDCS_test::mesh_from_soup<Mesh>(MDCS_test::bumpy_sphere<Point_3>(2, 0.1, 3));
  for(double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                    -std::numeric_limits<double>::infinity()}) {
    Mesh m = base;
    const vertex_descriptor v = *std::next(vertices(m).begin(), 7);
    m.point(v) = Point_3(m.point(v).x(), bad, m.point(v).z());
    for(const auto& method : all_methods()) {
      INFO(method.first << ", coordinate " << bad);
      const std::string message = invalid_argument_message(method.second, m);
      CHECK(message.find("not finite") != std::string::npos);
      CHECK(message.find("vertex 7") != std::string::npos);
    }
  }
}

TEST_CASE("geodesic input range: a mesh far from unit scale is refused by every class", "[geodesics][robustness]")
{
  const Mesh base = MDCS_test::mesh_from_soup<Mesh>(MDCS_test::bumpy_sphere<Point_3>(2, 0.1, 3));
  for(double scale : {std::ldexp(1.0, -140), 1e-150, std::ldexp(1.0, 140), 1e200}) {
    const Mesh m = scaled(base, scale);
    for(const auto& method : all_methods()) {
      INFO(method.first << ", scale " << scale);
      CHECK(invalid_argument_message(method.second, m).find("scale is out of range") != std::string::npos);
    }
  }
  // A single vertex far away: the bounding box is beyond the range.
  Mesh m = base;
  const vertex_descriptor v = *std::next(vertices(m).begin(), 3);
  m.point(v) = Point_3(1e200, 0, 0);
  CHECK(invalid_argument_message(all_methods()[0].second, m).find("scale is out of range") != std::string::npos);
}

TEST_CASE("geodesic input range: inside the range the distances scale with the mesh", "[geodesics][robustness]")
{
  const Mesh base = MDCS_test::mesh_from_soup<Mesh>(MDCS_test::bumpy_sphere<Point_3>(2, 0.1, 3));
  for(const auto& method : all_methods()) {
    const std::vector<double> unit = method.second(base, 1.0);
    for(int exponent : {-125, 125}) {
      const double s = std::ldexp(1.0, exponent); // a power of two: the scaled coordinates are exact
      const std::vector<double> d = method.second(scaled(base, s), s);
      REQUIRE(d.size() == unit.size());
      double worst = 0;
      for(std::size_t i = 0; i < d.size(); ++i) {
        REQUIRE(std::isfinite(d[i]));
        worst = (std::max)(worst, std::abs(d[i] / s - unit[i]) / (std::max)(unit[i], 1e-300));
      }
      INFO(method.first << ", scale 2^" << exponent << ", largest relative difference " << worst);
      CHECK(worst < 1e-12);
    }
  }
}
