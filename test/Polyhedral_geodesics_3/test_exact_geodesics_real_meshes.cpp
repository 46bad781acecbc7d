// Exact geodesic distances on CGAL's demo meshes (libcgal-demo) against CGAL's Surface_mesh_shortest_path (an
// independent implementation of an exact algorithm): vertex distances from one and from three vertex sources,
// from a source inside a face, distances at random surface points, and the Dijkstra upper bound / Euclidean
// lower bound. Small meshes run by default; the large ones are hidden ([.long]).
#include <catch2/catch.hpp>

#include <MDCS_test/cgal_meshes.h>
#include <MDCS_test/geodesic_oracles.h>
#include <MDCS_test/geodesic_test_meshes.h>
#include <MDCS_test/geodesic_test_geometry.h>

#include <CGAL/Polyhedral_geodesics_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <exception>
#include <iterator>
#include <string>
#include <vector>

namespace {

using namespace MDCS_test::Epick_surface_mesh;
typedef CGAL::Polyhedral_geodesics_3::Exact_geodesic_distances_3<Mesh> Geodesics;
typedef Geodesics::Face_location Face_location;

using MDCS_test::tolerance;

// Compares the engine with Surface_mesh_shortest_path on CGAL's demo mesh `name`. Returns false (with a
// warning) when the mesh file is not available.
bool check_against_smsp(const std::string& name, std::size_t queries_per_run)
{
  const std::string path = MDCS_test::cgal_demo_mesh(name);
  Mesh m;
  if(path.empty() || !MDCS_test::read_mesh(path, m)) {
    WARN("CGAL demo mesh " << name << " not found (MDCS_CGAL_MESH_DIR = \"" << MDCS_test::cgal_demo_mesh_dir()
                           << "\"); test skipped");
    return false;
  }
  REQUIRE(CGAL::is_triangle_mesh(m));
  const double diag = MDCS_test::bbox_diagonal(m);
  const double floor_value = tolerance * diag;
  const auto queries = MDCS_test::random_face_locations(m, queries_per_run, 2024);

  for(int run = 0; run < 3; ++run) {
    Geodesics g(m);
    MDCS_test::Smsp_oracle<K, Mesh> smsp(m);
    std::vector<vertex_descriptor> vertex_sources;
    std::string what;
    if(run < 2) {
      vertex_sources = MDCS_test::spread_vertices(m, run == 0 ? 1 : 3, 17);
      for(auto s : vertex_sources) {
        g.add_source(s);
        smsp.add_source(s);
      }
      what = std::to_string(vertex_sources.size()) + " vertex source(s)";
    }
    else {
      const auto src = MDCS_test::random_face_locations(m, 1, 77)[0];
      g.add_source(Face_location(src.first, src.second));
      smsp.add_source(src.first, src.second);
      what = "a face-location source";
    }
    INFO(name << " (" << num_vertices(m) << " vertices), " << what);
    smsp.build();
    const auto t0 = std::chrono::steady_clock::now();
    g.compute();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    INFO("propagation time " << seconds << " s, windows created " << g.statistics().windows_created);

    std::vector<double> e, got;
    for(vertex_descriptor v : vertices(m)) {
      e.push_back(smsp.distance(v));
      got.push_back(g.distance(v));
    }
    const auto cmp = MDCS_test::compare_distances(e, got, floor_value);
    INFO("vertices vs Surface_mesh_shortest_path: " << cmp);
    if(!cmp.ok(tolerance) && cmp.worst != std::size_t(-1)) {
      // Which one is wrong? If the engine is longer, a valid surface path of Surface_mesh_shortest_path proves
      // the engine wrong; if the engine is shorter, the engine's own path must be a valid surface path.
      const vertex_descriptor w = *std::next(vertices(m).begin(), std::ptrdiff_t(cmp.worst));
      std::vector<Point_3> smsp_path = smsp.path_points(w), own_path;
      try {
        g.shortest_path_points(w, std::back_inserter(own_path));
      }
      catch(const std::exception& ex) {
        UNSCOPED_INFO("the engine's shortest_path_points threw: " << ex.what());
      }
      std::size_t bad_smsp = 0, bad_own = 0;
      const bool smsp_valid = MDCS_test::is_surface_path(m, smsp_path, 1e-9 * diag, &bad_smsp);
      const bool own_valid = MDCS_test::is_surface_path(m, own_path, 1e-9 * diag, &bad_own);
      UNSCOPED_INFO("worst vertex " << std::size_t(w) << ": Surface_mesh_shortest_path's path has " << smsp_path.size()
                    << " points, length " << MDCS_test::format(MDCS_test::path_length(smsp_path)) << ", on the surface: " << smsp_valid
                    << "; the engine's path has " << own_path.size() << " points, length "
                    << MDCS_test::format(MDCS_test::path_length(own_path)) << ", on the surface: " << own_valid);
    }
    CHECK(cmp.ok(tolerance));

    if(run < 2) {
      // Dijkstra over the edges is an upper bound, the straight 3D distance a lower bound
      const auto dij = MDCS_test::dijkstra_vertex_distances(m, vertex_sources);
      std::size_t above = 0, below = 0, i = 0;
      for(vertex_descriptor v : vertices(m)) {
        double euclid = MDCS_test::inf;
        for(auto s : vertex_sources)
          euclid = std::min(euclid, MDCS_test::dist(MDCS_test::vertex_vec3(m, v), MDCS_test::vertex_vec3(m, s)));
        if(got[i] > dij[i] * (1 + tolerance) + floor_value) ++above;
        if(got[i] < euclid * (1 - tolerance) - floor_value) ++below;
        ++i;
      }
      CHECK(above == 0);
      CHECK(below == 0);
    }

    std::vector<double> eq, gq;
    for(const auto& q : queries) {
      eq.push_back(smsp.distance(q.first, q.second));
      gq.push_back(g.distance(Face_location(q.first, q.second)));
    }
    const auto cmp_q = MDCS_test::compare_distances(eq, gq, floor_value);
    INFO("face locations vs Surface_mesh_shortest_path: " << cmp_q);
    CHECK(cmp_q.ok(tolerance));
  }
  return true;
}

} // namespace

TEST_CASE("exact geodesics vs Surface_mesh_shortest_path: elephant", "[geodesics][exact][smsp][real]")
{
  check_against_smsp("elephant.off", 200);
}

TEST_CASE("exact geodesics vs Surface_mesh_shortest_path: Chinese dragon 10k", "[geodesics][exact][smsp][real]")
{
  check_against_smsp("ChineseDragon-10kv.off", 100);
}

TEST_CASE("exact geodesics vs Surface_mesh_shortest_path: camel, armadillo, refined elephant, mannequin, bunny",
          "[.long][long][geodesics][exact][smsp][real]")
{
  for(const char* name : {"camel.off", "armadillo.off", "refined_elephant.off", "mannequin-devil.off", "bunny00.off"})
    check_against_smsp(name, 300);
}
