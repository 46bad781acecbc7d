// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The geodesic engines on OpenMesh's TriMesh (through CGAL's graph traits for OpenMesh) give the same
// distances as on Surface_mesh built from the same triangles. Built only when CMake finds OpenMesh
// (MDCS_HAS_OPENMESH); otherwise one case reports the skip.

#include <catch2/catch.hpp>

#ifdef MDCS_HAS_OPENMESH

// OpenMesh's property storage appends default-constructed (uninitialised) vectors, which GCC reports when it
// inlines them here; the warning is about OpenMesh's code, not this test's.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include <MDCS_test/geodesic_oracles.h>
#include <MDCS_test/mesh_generators.h>

#include <CGAL/Polyhedral_geodesics_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Surface_mesh;

// Double-precision points: CGAL's point map for OpenMesh reads them as Epick points without rounding.
struct Double_traits : public OpenMesh::DefaultTraits
{
  typedef OpenMesh::Vec3d Point;
};
typedef OpenMesh::TriMesh_ArrayKernelT<Double_traits> Open_mesh;

namespace PG = CGAL::Polyhedral_geodesics_3;

typedef MDCS_test::Named_soup<Point_3> Named_soup;

std::vector<Named_soup> test_meshes()
{
  return {{"bumpy sphere 2", MDCS_test::bumpy_sphere<Point_3>(2, 0.2, 1)},
          {"terrain 10x10", MDCS_test::height_field_grid<Point_3>(10, 0.35, 4)},
          {"square with a hole", MDCS_test::square_with_hole<Point_3>(10, 3, 7, 4, 6)}};
}

// OpenMesh built through its own API, vertex i = soup point i.
Open_mesh open_mesh_from(const MDCS_test::Triangle_soup<Point_3>& soup)
{
  Open_mesh m;
  std::vector<Open_mesh::VertexHandle> v;
  for(const Point_3& p : soup.points) v.push_back(m.add_vertex(Open_mesh::Point(p.x(), p.y(), p.z())));
  for(const auto& t : soup.triangles) {
    const Open_mesh::FaceHandle f = m.add_face(v[t[0]], v[t[1]], v[t[2]]);
    REQUIRE(f.is_valid());
  }
  return m;
}

typedef std::map<std::tuple<double, double, double>, double> Distances_by_point;

// Distances from the vertex nearest to `source`, keyed by the vertex position (unique in these meshes).
template <class Engine, class Mesh>
Distances_by_point distances_by_point(const Mesh& m, const MDCS_test::Vec3& source)
{
  Engine g(m);
  g.add_source(MDCS_test::nearest_vertex(m, source));
  Distances_by_point r;
  for(auto v : vertices(m)) {
    const MDCS_test::Vec3 p = MDCS_test::vertex_vec3(m, v);
    r[std::make_tuple(p[0], p[1], p[2])] = CGAL::to_double(g.distance(v));
  }
  return r;
}

template <template <class...> class Engine>
void check_same_on_both(const char* engine_name)
{
  for(const Named_soup& ns : test_meshes()) {
    INFO(engine_name << " on " << ns.name);
    Surface_mesh sm;
    ns.soup.to_mesh(sm);
    const Open_mesh om = open_mesh_from(ns.soup);
    REQUIRE(num_faces(om) == num_faces(sm));
    REQUIRE(num_vertices(om) == num_vertices(sm));
    const MDCS_test::Vec3 source = MDCS_test::to_vec3(ns.soup.points[ns.soup.points.size() / 3]);
    const Distances_by_point a = distances_by_point<Engine<Surface_mesh>>(sm, source);
    const Distances_by_point b = distances_by_point<Engine<Open_mesh>>(om, source);
    REQUIRE(a.size() == b.size());
    double worst = 0;
    for(const auto& kv : a) {
      REQUIRE(b.count(kv.first) == 1);
      REQUIRE(std::isfinite(kv.second));
      worst = std::max(worst, MDCS_test::relative_difference(b.at(kv.first), kv.second, 1e-14));
    }
    INFO("max relative difference Surface_mesh vs OpenMesh: " << worst);
    CHECK(worst <= 1e-14);
  }
}

} // namespace

TEST_CASE("geodesics on OpenMesh: exact distances equal Surface_mesh's", "[geodesics][exact][openmesh]")
{
  check_same_on_both<PG::Exact_geodesic_distances_3>("exact");
}

TEST_CASE("geodesics on OpenMesh: flat-exact, fast marching and Dijkstra equal Surface_mesh's",
          "[geodesics][openmesh]")
{
  check_same_on_both<PG::Flat_exact_geodesic_distances_3>("flat-exact");
  check_same_on_both<PG::Fast_marching_geodesic_distances_3>("fast marching");
  check_same_on_both<PG::Dijkstra_geodesic_distances_3>("Dijkstra");
}

TEST_CASE("geodesics on OpenMesh: a path on the mesh has the length of its distance", "[geodesics][exact][openmesh]")
{
  const Open_mesh om = open_mesh_from(MDCS_test::bumpy_sphere<Point_3>(2, 0.2, 3));
  PG::Exact_geodesic_distances_3<Open_mesh> g(om);
  g.add_source(*vertices(om).begin());
  std::size_t checked = 0;
  for(auto v : vertices(om)) {
    if(checked++ % 7 != 0) continue;
    std::vector<Point_3> path;
    g.shortest_path_points(v, std::back_inserter(path));
    REQUIRE(!path.empty());
    double length = 0;
    for(std::size_t i = 1; i < path.size(); ++i) length += std::sqrt(CGAL::squared_distance(path[i - 1], path[i]));
    CHECK(std::abs(length - g.distance(v)) <= 1e-9 * (1 + g.distance(v)));
  }
}

#else

TEST_CASE("geodesics on OpenMesh: skipped (OpenMesh not found by CMake)", "[geodesics][openmesh]")
{
  WARN("OpenMesh (Debian's libopenmesh-dev) was not found: the OpenMesh cases were not built");
  SUCCEED();
}

#endif
