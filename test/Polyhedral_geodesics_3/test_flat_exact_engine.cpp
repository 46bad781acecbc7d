// Tests of the flat-exact engine itself (internal::Flat_exact_propagation on the compact mesh):
//  - the dependence DAG is acyclic after every run and every traced path ends at a source, on planar, curved,
//    holed, degenerate and two-component meshes and CGAL's elephant, for vertex, face and mixed sources;
//  - a cluster of repeated lowerings (Loop subdivision of CGAL's mannequin-devil) settles with few values per
//    vertex and distances within 1e-7 of those with rounding-level lowerings only;
//  - where two windows meet on an edge, the smaller offset (default) against the thesis's zero offset: the same
//    distances without vertex windows, a lower error against the exact distances on curved meshes;
//  - the windows of the exact shortest paths given to the engine (set_window_roots(), a diagnosis): checked
//    input, an acyclic DAG, the given roots used instead of the tracked ones, a lower error, and on curved meshes
//    far more exact paths bent at a vertex than tracked windows rooted at one; with their exact offsets too
//    (set_window_root_offsets()), still an acyclic DAG and about the same error.
#include <catch2/catch.hpp>

#include <MDCS_test/cgal_meshes.h>
#include <MDCS_test/geodesic_oracles.h>
#include <MDCS_test/geodesic_test_meshes.h>
#include <MDCS_test/mesh_generators.h>

#include <CGAL/Polyhedral_geodesics_3/Exact_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/geodesic_distance_error.h>
#include <CGAL/Polyhedral_geodesics_3/internal/flat_exact_propagation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace MDCS_test::Epick_surface_mesh;
namespace PG = CGAL::Polyhedral_geodesics_3;
typedef PG::internal::Flat_exact_propagation<double> Engine;
typedef PG::internal::Geodesic_mesh<double> Compact_mesh;

// The compact mesh and the engine, for the DAG checks.
struct Engine_run
{
  Compact_mesh cm;
  std::vector<halfedge_descriptor> halfedge_of;
  std::unique_ptr<Engine> engine;

  explicit Engine_run(const Mesh& m)
  {
    PG::internal::build_geodesic_mesh(m, get(CGAL::vertex_point, m), CGAL::get_initialized_vertex_index_map(m),
                                      CGAL::get_initialized_face_index_map(m), cm, halfedge_of);
    engine.reset(new Engine(cm));
  }

  // Runs from the given vertex sources and face sources (face index, barycentric coordinates).
  void run(const std::vector<int>& vertex_sources, const std::vector<std::pair<int, std::array<double, 3>>>& face_sources)
  {
    engine->clear();
    int id = 0;
    for(int v : vertex_sources) engine->add_vertex_source(v, id++);
    for(const auto& f : face_sources) engine->add_face_source(f.first, f.second, id++);
    CGAL::MDCS::No_progress progress;
    engine->run(progress);
  }

  // Traces the path to every vertex with the engine: the number of paths that do not end at a source (a
  // vertex at distance 0 or a face node) or that throw.
  std::size_t lost_paths() const
  {
    std::size_t lost = 0;
    for(std::size_t v = 0; v < cm.number_of_vertices; ++v) {
      const int h = cm.vertex_halfedge[v];
      if(h < 0 || std::isinf(engine->vertex_distance(int(v))))
        continue;
      std::array<double, 3> b = {0, 0, 0};
      b[std::size_t(h % 3)] = 1;
      std::vector<PG::internal::Geodesic_path_node<double>> nodes;
      try {
        engine->trace_path(h / 3, b, [&](const PG::internal::Geodesic_path_node<double>& n) { nodes.push_back(n); });
      }
      catch(const std::exception&) {
        ++lost;
        continue;
      }
      if(nodes.empty()) {
        ++lost;
        continue;
      }
      const auto& last = nodes.back();
      const bool at_source = last.kind == PG::internal::Geodesic_path_node<double>::FACE ||
                             (last.kind == PG::internal::Geodesic_path_node<double>::VERTEX &&
                              engine->vertex_distance(last.index) == 0);
      if(!at_source) ++lost;
    }
    return lost;
  }
};

// Two curved meshes for the comparisons of window rules: a bumpy sphere and CGAL's elephant (when found).
void add_bumpy_sphere_and_elephant(std::vector<std::pair<std::string, Mesh>>& meshes)
{
  meshes.emplace_back("bumpy sphere", make_mesh(MDCS_test::bumpy_sphere<Point_3>(3, 0.1, 2)));
  Mesh elephant;
  if(MDCS_test::read_mesh(MDCS_test::cgal_demo_mesh("elephant.off"), elephant))
    meshes.emplace_back("elephant", elephant);
  else
    WARN("CGAL's demo meshes not found (MDCS_CGAL_MESH_DIR): the elephant is skipped");
}

} // namespace

TEST_CASE("flat-exact geodesics: the dependence DAG stays acyclic and every path reaches a source",
          "[geodesics][flat_exact]")
{
  std::array<std::size_t, 2> coincident;
  struct Case
  {
    std::string name;
    MDCS_test::Triangle_soup<Point_3> soup;
  };
  std::vector<Case> cases = {{"jittered grid", MDCS_test::jittered_planar_grid<Point_3>(20, 20, 1, 1, 0.2, 7)},
                             {"bumpy sphere", MDCS_test::bumpy_sphere<Point_3>(3, 0.15, 4)},
                             {"subdivided cube", MDCS_test::subdivided_cube<Point_3>(6)},
                             {"square with a hole", MDCS_test::square_with_hole<Point_3>(20, 6, 14, 8, 12)},
                             {"terrain", MDCS_test::height_field_grid<Point_3>(24, 0.3, 2)},
                             {"zero-length edge", MDCS_test::grid_with_zero_length_edge<Point_3>(8, coincident)},
                             {"two components", MDCS_test::two_grids<Point_3>(6)}};
  Mesh elephant;
  if(MDCS_test::read_mesh(MDCS_test::cgal_demo_mesh("elephant.off"), elephant))
    cases.push_back({"elephant", MDCS_test::Triangle_soup<Point_3>()});
  for(const Case& c : cases) {
    INFO(c.name);
    const Mesh m = c.soup.points.empty() ? elephant : make_mesh(c.soup);
    Engine_run run(m);
    const int nv = int(run.cm.number_of_vertices), nf = int(run.cm.number_of_faces);
    const std::vector<std::pair<std::vector<int>, std::vector<std::pair<int, std::array<double, 3>>>>> configurations = {
      {{0}, {}},
      {{nv / 2}, {}},
      {{nv / 3, (2 * nv) / 3 + 1}, {}},
      {{}, {{nf / 2, {0.2, 0.5, 0.3}}}},
      {{nv - 1}, {{nf / 5, {0.1, 0.1, 0.8}}, {(4 * nf) / 5, {0.5, 0.5, 0}}}}};
    for(std::size_t k = 0; k < configurations.size(); ++k) {
      INFO("source configuration " << k);
      run.run(configurations[k].first, configurations[k].second);
      CHECK(run.engine->dependence_graph_is_acyclic());
      CHECK(run.lost_paths() == 0);
    }
  }
}

TEST_CASE("flat-exact geodesics: a cluster of repeated lowerings settles (Loop subdivision of mannequin-devil)",
          "[geodesics][flat_exact]")
{
  // In strips of elongated faces the vertices lower one another in turn by ever smaller amounts (measured with
  // this source: 1.94 values per vertex; 2.64 with the thesis's zero offset where two windows meet). From a
  // vertex's fourth value on, a change must be at least 1e-9 of the distance (measured: 1.45 values per vertex,
  // 1.50 before; no distance changes by more than 1e-7 of itself).
  Mesh m;
  if(!MDCS_test::read_mesh(MDCS_test::cgal_demo_mesh("mannequin-devil.off"), m)) {
    WARN("CGAL's demo meshes not found (MDCS_CGAL_MESH_DIR): the case is skipped");
    return;
  }
  CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(1));
  Engine_run settled(m), creeping(m);
  creeping.engine->set_settle_tolerance(0);
  const int source = 17996;
  REQUIRE(std::size_t(source) < settled.cm.number_of_vertices);
  settled.run({source}, {});
  creeping.run({source}, {});
  const double nv = double(settled.cm.number_of_vertices);
  const double values_settled = double(settled.engine->statistics().vertex_updates) / nv;
  const double values_creeping = double(creeping.engine->statistics().vertex_updates) / nv;
  INFO("values per vertex: " << values_settled << " settled, " << values_creeping << " with rounding only");
  CHECK(values_creeping > 1.25 * values_settled);
  CHECK(values_settled < 1.6);
  double largest_change = 0;
  std::size_t unreached = 0;
  for(int v = 0; v < int(nv); ++v) {
    const double a = settled.engine->vertex_distance(v), b = creeping.engine->vertex_distance(v);
    if(std::isinf(a) || std::isinf(b)) {
      ++unreached;
      continue;
    }
    if(b > 0)
      largest_change = (std::max)(largest_change, std::abs(a - b) / b);
  }
  INFO("largest relative change " << largest_change);
  CHECK(unreached == 0);
  CHECK(largest_change < 1e-7);
  CHECK(settled.engine->dependence_graph_is_acyclic());
  CHECK(settled.lost_paths() == 0);
}

TEST_CASE("flat-exact geodesics: where two windows meet, the smaller offset beats the zero offset",
          "[geodesics][flat_exact]")
{
  // measured E (zero offset -> smaller offset), 2 sources: bumpy sphere 1.00% -> 0.91%, elephant 0.58% -> 0.52%
  std::vector<std::pair<std::string, Mesh>> meshes;
  add_bumpy_sphere_and_elephant(meshes);
  for(const auto& named : meshes) {
    INFO(named.first);
    const Mesh& m = named.second;
    Engine_run run(m);
    const int nv = int(run.cm.number_of_vertices);
    double error[2] = {0, 0}; // [0]: zero offset, [1]: smaller offset
    for(int source : {nv / 5, (3 * nv) / 4}) {
      PG::Exact_geodesic_distances_3<Mesh> exact(m, PG::Geodesic_memory_mode::distances_only);
      exact.add_source(*std::next(vertices(m).begin(), source));
      std::vector<double> reference(std::size_t(nv), 0.0);
      for(auto v : vertices(m))
        reference[std::size_t(v)] = exact.distance(v);
      std::vector<double> without_windows[2];
      for(int rule = 0; rule < 2; ++rule) {
        run.engine->set_window_meeting(rule == 0 ? Engine::Window_meeting::zero_offset
                                                 : Engine::Window_meeting::smaller_offset);
        run.engine->set_vertex_windows(false);
        run.run({source}, {});
        for(int v = 0; v < nv; ++v)
          without_windows[rule].push_back(run.engine->vertex_distance(v));
        run.engine->set_vertex_windows(true);
        run.run({source}, {});
        CHECK(run.engine->dependence_graph_is_acyclic());
        CHECK(run.lost_paths() == 0);
        std::vector<double> flat(static_cast<std::size_t>(nv));
        for(int v = 0; v < nv; ++v)
          flat[std::size_t(v)] = run.engine->vertex_distance(v);
        error[rule] += PG::geodesic_distance_error(m, CGAL::make_property_map(flat), CGAL::make_property_map(reference))
                         .mean_relative / 2;
      }
      // without vertex windows every offset is 0: the rule changes nothing
      CHECK(without_windows[0] == without_windows[1]);
    }
    INFO("E with the zero offset " << error[0] << ", with the smaller offset " << error[1]);
    CHECK(error[1] < 0.98 * error[0]);
    CHECK(error[1] > 0);
  }
}

namespace {

// Receives an exact shortest path (from the target to the source) and keeps its last bend: the first vertex
// after the target where a shortest path can bend (a saddle or a reflex boundary vertex). A path can also pass
// straight through another vertex (on a grid's diagonal), which does not start a window.
struct Last_bend
{
  const Engine& engine;
  int vertices_seen = 0;
  int bend = -1;
  void operator()(boost::graph_traits<Mesh>::vertex_descriptor v)
  {
    if(vertices_seen++ >= 1 && bend < 0 && engine.can_bend_at(int(v)))
      bend = int(v);
  }
  void operator()(halfedge_descriptor, double) {}
  void operator()(boost::graph_traits<Mesh>::face_descriptor, const std::array<double, 3>&) {}
};

} // namespace

TEST_CASE("flat-exact geodesics: the windows of the exact shortest paths given to the engine (diagnosis)",
          "[geodesics][flat_exact]")
{
  {
    const Mesh m = make_mesh(MDCS_test::planar_grid<Point_3>(3, 3));
    Engine_run run(m);
    const std::vector<int> wrong_size(3, -1);
    CHECK_THROWS_AS(run.engine->set_window_roots(&wrong_size), std::invalid_argument);
    std::vector<int> not_a_vertex(run.cm.number_of_vertices, -1);
    not_a_vertex[2] = int(run.cm.number_of_vertices);
    CHECK_THROWS_AS(run.engine->set_window_roots(&not_a_vertex), std::invalid_argument);
    not_a_vertex[2] = -2;
    CHECK_THROWS_AS(run.engine->set_window_roots(&not_a_vertex), std::invalid_argument);
    const std::vector<double> wrong_offsets(3, 0.0);
    CHECK_THROWS_AS(run.engine->set_window_root_offsets(&wrong_offsets), std::invalid_argument);
    std::vector<double> bad_offsets(run.cm.number_of_vertices, 0.0);
    bad_offsets[1] = -1.0;
    CHECK_THROWS_AS(run.engine->set_window_root_offsets(&bad_offsets), std::invalid_argument);
    bad_offsets[1] = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(run.engine->set_window_root_offsets(&bad_offsets), std::invalid_argument);
  }
  // measured (one source; exact paths bent at a saddle or reflex boundary vertex / tracked windows rooted at a
  // vertex; E tracked -> E with the exact windows): square with a hole 266 / 771 of 916 vertices, 0.033% ->
  // 0.020%; bumpy sphere 551 / 116 of 642, 0.96% -> 0.71%; elephant 2295 / 528 of 2775, 0.63% -> 0.53%
  std::vector<std::pair<std::string, Mesh>> meshes;
  meshes.emplace_back("square with a hole", make_mesh(MDCS_test::square_with_hole<Point_3>(30, 10, 20, 12, 18)));
  add_bumpy_sphere_and_elephant(meshes);
  for(const auto& named : meshes) {
    INFO(named.first);
    const Mesh& m = named.second;
    Engine_run run(m);
    const int nv = int(run.cm.number_of_vertices);
    const int source = nv / 3;
    PG::Exact_geodesic_distances_3<Mesh> exact(m);
    exact.add_source(*std::next(vertices(m).begin(), source));
    std::vector<double> reference(std::size_t(nv), 0.0);
    std::vector<int> roots(std::size_t(nv), -1);
    std::size_t bent = 0;
    for(auto v : vertices(m)) {
      reference[std::size_t(v)] = exact.distance(v);
      if(int(v) == source)
        continue;
      Last_bend last{*run.engine};
      exact.shortest_path_sequence(v, last);
      if(last.bend >= 0 && last.bend != source) {
        roots[std::size_t(v)] = last.bend;
        ++bent;
      }
    }
    auto distances = [&] {
      std::vector<double> d(static_cast<std::size_t>(nv));
      for(int v = 0; v < nv; ++v)
        d[std::size_t(v)] = run.engine->vertex_distance(v);
      return d;
    };
    auto error = [&](const std::vector<double>& d) {
      return PG::geodesic_distance_error(m, CGAL::make_property_map(d), CGAL::make_property_map(reference)).mean_relative;
    };
    // tracked windows (the default)
    run.run({source}, {});
    std::size_t tracked = 0;
    for(int v = 0; v < nv; ++v)
      tracked += run.engine->window_root(v) >= 0;
    const double e_tracked = error(distances());
    // the exact paths' windows: the DAG stays acyclic and every path reaches a source
    run.engine->set_window_roots(&roots);
    run.run({source}, {});
    CHECK(run.engine->dependence_graph_is_acyclic());
    CHECK(run.lost_paths() == 0);
    const std::vector<double> given = distances();
    const double e_given = error(given);
    // the same windows with their exact offsets (the exact distances of the roots): the DAG stays acyclic and
    // every path reaches a source, the offsets are used, and the error stays about the same: what the tracked
    // windows miss is where the paths bend, not how far their roots are
    run.engine->set_window_root_offsets(&reference);
    run.run({source}, {});
    CHECK(run.engine->dependence_graph_is_acyclic());
    CHECK(run.lost_paths() == 0);
    const std::vector<double> given_offsets = distances();
    const double e_given_offsets = error(given_offsets);
    if(named.first == "square with a hole") {
      // planar: the flat-exact distances of the roots are already exact, so nothing changes beyond rounding
      double largest_change = 0, largest = 0;
      for(int v = 0; v < nv; ++v) {
        largest_change = (std::max)(largest_change, std::abs(given_offsets[std::size_t(v)] - given[std::size_t(v)]));
        largest = (std::max)(largest, reference[std::size_t(v)]);
      }
      CHECK(largest_change <= 1e-12 * largest);
    } else {
      CHECK(given_offsets != given);
    }
    CHECK(e_given_offsets > 0.8 * e_given);
    // no window anywhere given: the same distances as without vertex windows, so the given roots replace the
    // tracked ones
    const std::vector<int> none(std::size_t(nv), -1);
    run.engine->set_window_roots(&none);
    run.run({source}, {});
    const std::vector<double> given_none = distances();
    run.engine->set_window_root_offsets(nullptr);
    run.run({source}, {});
    CHECK(distances() == given_none); // with no root anywhere, the offsets are not used
    run.engine->set_window_roots(nullptr);
    run.engine->set_vertex_windows(false);
    run.run({source}, {});
    CHECK(distances() == given_none);
    run.engine->set_vertex_windows(true);
    INFO("exact paths bent at a vertex: " << bent << " of " << nv << ", tracked windows rooted at a vertex: " << tracked
                                          << "; E tracked " << e_tracked << ", with the exact windows " << e_given
                                          << ", with their exact offsets too " << e_given_offsets);
    CHECK(e_given < e_tracked);
    // on curved meshes most exact paths bend at a saddle, and the tracked windows miss most of these bends
    if(named.first != "square with a hole")
      CHECK(bent > 2 * tracked);
  }
}
