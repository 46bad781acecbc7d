// Geodesic distance matrices (issue 29 item 2), for every method:
//  - dense rows equal single-source runs of the method's class (distances_only), bit for bit, to all vertices and to
//    given targets, for 1, 2, 3 and 8 threads, delivered in order and one at a time;
//  - the local sparse rows hold every vertex within max_distance and nothing beyond, with the distances of a run on
//    the whole mesh stopped at max_distance (exact methods and Dijkstra: equal up to 1e-12 relative; fast marching
//    and flat-exact: the same within their own error; exact: also equal to unlimited runs), identical for every
//    thread count; the vertex-oriented engine's shadow pruning gives the distances of runs without it;
//  - the symmetric matrix is symmetric, holds min of the two directions, and every pair within max_distance;
//  - Surface_mesh and Polyhedron_3 agree; invalid options are rejected; progress and cancellation;
//  - the .npy and Matrix Market writers round-trip.
// Tagged [parallel]: the ThreadSanitizer build runs these cases alone.
#include <catch2/catch.hpp>

#include <MDCS_test/geodesic_oracles.h>
#include <MDCS_test/geodesic_test_meshes.h>
#include <MDCS_test/mesh_generators.h>
#include <MDCS_test/thread_counts.h>
#include <MDCS_test/geodesic_test_geometry.h>

#include <CGAL/Polyhedral_geodesics_3/Dijkstra_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Exact_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Fast_marching_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Flat_exact_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/IO/distance_matrix_files.h>
#include <CGAL/Polyhedral_geodesics_3/Merged_window_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/geodesic_distance_matrix.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/Surface_mesh.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace MDCS_test::Epick_surface_mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
namespace PG = CGAL::Polyhedral_geodesics_3;
using MDCS_test::inf;
using MDCS_test::thread_counts;
const PG::Geodesic_method methods[] = {PG::Geodesic_method::exact, PG::Geodesic_method::merged_windows,
                                       PG::Geodesic_method::flat_exact, PG::Geodesic_method::fast_marching,
                                       PG::Geodesic_method::dijkstra};

Mesh bumpy() { return MDCS_test::mesh_from_soup<Mesh>(MDCS_test::bumpy_sphere<Point_3>(3, 0.15, 4)); }

// A mesh with a boundary and two components: a jittered grid and a small sphere apart.
Mesh grid_and_sphere()
{
  MDCS_test::Triangle_soup<Point_3> soup = MDCS_test::jittered_planar_grid<Point_3>(14, 10, 1.4, 1.0, 0.2, 3);
  const MDCS_test::Triangle_soup<Point_3> ball = MDCS_test::icosphere<Point_3>(1);
  const std::size_t offset = soup.points.size();
  for(const Point_3& p : ball.points) soup.points.push_back(Point_3(p.x() * 0.2 + 3, p.y() * 0.2, p.z() * 0.2));
  for(const auto& t : ball.triangles) soup.triangles.push_back({{t[0] + offset, t[1] + offset, t[2] + offset}});
  return MDCS_test::mesh_from_soup<Mesh>(soup);
}

using MDCS_test::mean_edge_length;

// The distances of a single-source run of the method's class, distances_only, optionally stopped at a limit.
template <class TM>
std::vector<double> single_source(const TM& tm, typename boost::graph_traits<TM>::vertex_descriptor s,
                                  PG::Geodesic_method method, double merge_tolerance, double limit = inf)
{
  const auto m = PG::Geodesic_memory_mode::distances_only;
  const auto vim = CGAL::get_initialized_vertex_index_map(tm);
  std::vector<double> d(num_vertices(tm), inf);
  auto run = [&](auto& g) {
    if(limit < inf) g.set_distance_limit(limit);
    g.add_source(s);
    for(auto v : vertices(tm)) d[get(vim, v)] = g.distance(v);
  };
  switch(method) {
  case PG::Geodesic_method::exact: { PG::Exact_geodesic_distances_3<TM> g(tm, m); run(g); break; }
  case PG::Geodesic_method::merged_windows: { PG::Merged_window_geodesic_distances_3<TM> g(tm, merge_tolerance, m); run(g); break; }
  case PG::Geodesic_method::flat_exact: { PG::Flat_exact_geodesic_distances_3<TM> g(tm, m); run(g); break; }
  case PG::Geodesic_method::fast_marching: { PG::Fast_marching_geodesic_distances_3<TM> g(tm, m); run(g); break; }
  case PG::Geodesic_method::dijkstra: { PG::Dijkstra_geodesic_distances_3<TM> g(tm, m); run(g); break; }
  }
  return d;
}

std::vector<vertex_descriptor> some_vertices(const Mesh& m, std::size_t step)
{
  std::vector<vertex_descriptor> out;
  std::size_t i = 0;
  for(auto v : vertices(m))
    if(i++ % step == 0) out.push_back(v);
  return out;
}

PG::Geodesic_matrix_options options_for(PG::Geodesic_method method, std::size_t threads, double max_distance = inf)
{
  PG::Geodesic_matrix_options o;
  o.method = method;
  o.merge_tolerance = 0.01;
  o.threads = threads;
  o.max_distance = max_distance;
  return o;
}

PG::Geodesic_sparse_matrix local_rows_matrix(const Mesh& m, const std::vector<vertex_descriptor>& sources,
                                             const PG::Geodesic_matrix_options& o)
{
  PG::Geodesic_sparse_matrix s;
  s.rows = sources.size();
  s.columns = num_vertices(m);
  bool in_order = true; // no Catch2 assertion inside the output: it may run on a worker thread
  PG::local_geodesic_distance_rows<CGAL::Parallel_tag>(
    m, sources, [&](std::size_t i, const std::vector<std::uint32_t>& c, const std::vector<double>& v) {
      in_order = in_order && i + 1 == s.row_begin.size();
      s.column.insert(s.column.end(), c.begin(), c.end());
      s.value.insert(s.value.end(), v.begin(), v.end());
      s.row_begin.push_back(s.column.size());
    }, o);
  CHECK(in_order);
  return s;
}

// One single-source run of a vertex-oriented engine, stopped at `limit` if it is finite.
void run_from_vertex(PG::internal::Vertex_oriented_window_propagation<double>& e, PG::internal::Matrix_index source,
                     double limit)
{
  if(limit < inf) e.set_distance_limit(limit);
  else e.clear_distance_limit();
  e.clear();
  e.add_vertex_source(source, 0);
  CGAL::MDCS::No_progress none;
  e.run(none);
}

bool same_matrix(const PG::Geodesic_sparse_matrix& a, const PG::Geodesic_sparse_matrix& b)
{
  return a.rows == b.rows && a.columns == b.columns && a.row_begin == b.row_begin && a.column == b.column &&
         a.value == b.value;
}

} // namespace

TEST_CASE("geodesic_distance_rows: every method, rows equal single-source runs, any thread count",
          "[geodesics][matrix][parallel]")
{
  const Mesh m = grid_and_sphere();
  const std::vector<vertex_descriptor> sources = some_vertices(m, 13);
  REQUIRE(sources.size() >= 8);
  std::vector<vertex_descriptor> targets = some_vertices(m, 7);
  targets.push_back(targets.front()); // a repeated target
  for(PG::Geodesic_method method : methods) {
    INFO(PG::geodesic_method_name(method));
    std::vector<std::vector<double>> expected;
    for(vertex_descriptor s : sources) expected.push_back(single_source(m, s, method, 0.01));
    for(std::size_t t : thread_counts) {
      INFO(t << " threads");
      std::vector<std::vector<double>> rows;
      std::atomic<int> inside{0};
      bool alone = true, in_order = true;
      PG::geodesic_distance_rows<CGAL::Parallel_tag>(m, sources, [&](std::size_t i, const std::vector<double>& row) {
        alone = alone && inside.fetch_add(1) == 0;
        in_order = in_order && i == rows.size();
        rows.push_back(row);
        inside.fetch_sub(1);
      }, options_for(method, t));
      CHECK(alone);
      CHECK(in_order);
      CHECK(rows == expected); // bit for bit: the same engine on the same compact mesh
      // To targets: the columns of the targets, in their order.
      std::size_t row_count = 0;
      bool targets_ok = true;
      PG::geodesic_distance_rows<CGAL::Parallel_tag>(m, sources, targets, [&](std::size_t i, const std::vector<double>& row) {
        targets_ok = targets_ok && row.size() == targets.size();
        for(std::size_t k = 0; targets_ok && k < targets.size(); ++k)
          targets_ok = row[k] == expected[i][std::size_t(targets[k])];
        ++row_count;
      }, options_for(method, t));
      CHECK(targets_ok);
      CHECK(row_count == sources.size());
    }
    // The other component is unreachable.
    bool unreachable = false;
    for(double d : expected[0]) unreachable = unreachable || d == inf;
    CHECK(unreachable);
  }
  // The one-vector matrix.
  const std::vector<double> dense = PG::geodesic_distance_matrix<CGAL::Parallel_tag>(m, sources, options_for(PG::Geodesic_method::exact, 3));
  REQUIRE(dense.size() == sources.size() * num_vertices(m));
  CHECK(std::vector<double>(dense.begin(), dense.begin() + std::ptrdiff_t(num_vertices(m))) ==
        single_source(m, sources[0], PG::Geodesic_method::exact, 0));
}

TEST_CASE("local_geodesic_distance_rows: every pair within max_distance, nothing beyond, as on the whole mesh",
          "[geodesics][matrix][local][parallel]")
{
  for(int mesh_kind = 0; mesh_kind < 2; ++mesh_kind) {
    const Mesh m = mesh_kind == 0 ? bumpy() : grid_and_sphere();
    const double r = 5 * mean_edge_length(m);
    const std::vector<vertex_descriptor> sources = some_vertices(m, 5);
    for(PG::Geodesic_method method : methods) {
      INFO((mesh_kind == 0 ? "bumpy sphere, " : "grid and sphere, ") << PG::geodesic_method_name(method));
      const PG::Geodesic_sparse_matrix one = local_rows_matrix(m, sources, options_for(method, 1, r));
      for(std::size_t t : thread_counts) {
        INFO(t << " threads");
        CHECK(same_matrix(local_rows_matrix(m, sources, options_for(method, t, r)), one));
      }
      // Against runs on the whole mesh stopped at r (exact: the unlimited run; merged windows: the unlimited
      // distances_only run, whose vertex-oriented schedule the neighbourhood runs too; the merges differ a little
      // between the two meshes, within the merge tolerance).
      const bool merged = method == PG::Geodesic_method::merged_windows;
      const double tolerance = method == PG::Geodesic_method::exact || method == PG::Geodesic_method::dijkstra ? 1e-12
                               : merged ? 0.05 : 1e-9;
      std::size_t missing = 0, extra = 0, differ = 0, pairs = 0, beyond = 0, unsorted = 0;
      double worst = 0;
      for(std::size_t i = 0; i < sources.size(); ++i) {
        // exact: the unlimited run (its distances up to the limit are final: no limit's own rounding involved)
        const bool unlimited = merged || method == PG::Geodesic_method::exact;
        const std::vector<double> whole = single_source(m, sources[i], method, 0.01, unlimited ? inf : r);
        std::vector<double> row(num_vertices(m), inf);
        for(std::size_t k = one.row_begin[i]; k < one.row_begin[i + 1]; ++k) {
          row[one.column[k]] = one.value[k];
          if(!(one.value[k] <= r)) ++beyond; // nothing beyond
          if(k > one.row_begin[i] && !(one.column[k - 1] < one.column[k])) ++unsorted;
        }
        CHECK(row[std::size_t(sources[i])] == 0);
        for(std::size_t v = 0; v < row.size(); ++v) {
          const bool in_whole = whole[v] <= r, in_local = row[v] <= r;
          if(!in_whole && !in_local) continue;
          // a pair at the limit up to rounding may fall on either side
          const bool borderline = std::abs((in_whole ? whole[v] : row[v]) - r) <= tolerance * r;
          if(in_whole && !in_local && !borderline) ++missing;
          if(!in_whole && in_local && !borderline) ++extra;
          if(in_whole && in_local) {
            ++pairs;
            const double e = std::abs(whole[v] - row[v]) / std::max(whole[v], 1e-300);
            worst = std::max(worst, e);
            if(e > tolerance) ++differ;
          }
        }
      }
      INFO(pairs << " pairs, worst relative difference to the whole-mesh run " << worst);
      CHECK(pairs > 20 * sources.size());
      CHECK(missing == 0);
      CHECK(extra == 0);
      CHECK(differ == 0);
      CHECK(beyond == 0);
      CHECK(unsorted == 0);
    }
  }
}

// The local matrix's exact rows run one vertex-oriented engine per thread on the whole mesh, reused from row to row
// (only what the last run touched is reset): every run must equal a run on a fresh engine, bit for bit, whatever
// ran before it (other sources, other limits, no limit, parents recorded or not).
TEST_CASE("vertex-oriented engine reused between runs: every run equals one on a fresh engine",
          "[geodesics][matrix][local]")
{
  typedef PG::internal::Vertex_oriented_window_propagation<double> Engine;
  for(int mesh_kind = 0; mesh_kind < 2; ++mesh_kind) {
    const Mesh m = mesh_kind == 0 ? bumpy() : grid_and_sphere();
    INFO((mesh_kind == 0 ? "bumpy sphere" : "grid and sphere"));
    const PG::Geodesic_surface_3<Mesh> surface(m);
    const PG::internal::Matrix_mesh& mesh = surface.compact_mesh();
    const double r = 5 * mean_edge_length(m);
    Engine reused(mesh);
    reused.set_reuse_between_runs(true);
    const double limits[] = {r, 2.5 * r, inf, 0.5 * r, r};
    std::size_t runs = 0, compared = 0, differ = 0, untracked = 0;
    for(std::size_t k = 0; k < 15; ++k) {
      const PG::internal::Matrix_index source = PG::internal::Matrix_index((k * 37) % mesh.number_of_vertices);
      const double limit = limits[k % 5];
      const bool parents = k >= 10; // the parents array appears: a full reset, then sparse ones again
      Engine fresh(mesh);
      for(Engine* e : {&reused, &fresh}) {
        e->set_record_parents(parents);
        run_from_vertex(*e, source, limit);
      }
      ++runs;
      std::vector<char> tracked(mesh.number_of_vertices, 0);
      for(PG::internal::Matrix_index v : reused.touched_vertices()) tracked[std::size_t(v)] = 1;
      for(std::size_t v = 0; v < mesh.number_of_vertices; ++v) {
        const PG::internal::Matrix_index i = PG::internal::Matrix_index(v);
        if(fresh.vertex_distance(i) < inf) {
          ++compared;
          if(!tracked[v]) ++untracked;
        }
        if(fresh.vertex_distance(i) != reused.vertex_distance(i) || fresh.vertex_source(i) != reused.vertex_source(i))
          ++differ;
        else if(parents && fresh.vertex_distance(i) < inf &&
                (fresh.parent(i).halfedge != reused.parent(i).halfedge || fresh.parent(i).root != reused.parent(i).root ||
                 fresh.parent(i).at != reused.parent(i).at))
          ++differ;
      }
    }
    INFO(runs << " runs, " << compared << " vertices with a distance");
    CHECK(compared > 15 * 20);
    CHECK(differ == 0);
    CHECK(untracked == 0); // every vertex with a distance is among those the next clear() resets
  }
}

// Shadow pruning (the local matrix's exact rows): a saddle or boundary vertex emits windows only over the faces a
// shortest path through it can enter. Oracle: the same engine without the rule, on surfaces where paths bend at
// saddles (a bumpy sphere, a terrain with a boundary) and around the reflex corners of a hole (boundary vertices of
// angle 3 pi / 2), unlimited and limited, equal to 1e-12 relative; and the rule must save windows.
TEST_CASE("vertex-oriented engine with shadow pruning: the distances of runs without it, with fewer windows",
          "[geodesics][matrix][local]")
{
  typedef PG::internal::Vertex_oriented_window_propagation<double> Engine;
  const Mesh meshes[] = {bumpy(), MDCS_test::mesh_from_soup<Mesh>(MDCS_test::height_field_grid<Point_3>(14, 0.25, 7)),
                         MDCS_test::mesh_from_soup<Mesh>(MDCS_test::square_with_hole<Point_3>(16, 5, 11, 6, 9))};
  const char* names[] = {"bumpy sphere", "terrain", "square with a hole"};
  for(int kind = 0; kind < 3; ++kind) {
    INFO(names[kind]);
    const PG::Geodesic_surface_3<Mesh> surface(meshes[kind]);
    const PG::internal::Matrix_mesh& mesh = surface.compact_mesh();
    const double r = 5 * mean_edge_length(meshes[kind]);
    Engine plain(mesh), pruned(mesh);
    pruned.set_shadow_pruning(true);
    pruned.set_reuse_between_runs(true);
    std::size_t compared = 0, differ = 0, reach_differs = 0, windows_plain = 0, windows_pruned = 0;
    double worst = 0;
    for(std::size_t k = 0; k < 12; ++k) {
      const PG::internal::Matrix_index source = PG::internal::Matrix_index((k * 53 + 7) % mesh.number_of_vertices);
      const double limit = k % 3 == 2 ? r : inf;
      for(Engine* e : {&plain, &pruned})
        run_from_vertex(*e, source, limit);
      windows_plain += plain.statistics().windows_created;
      windows_pruned += pruned.statistics().windows_created;
      for(std::size_t v = 0; v < mesh.number_of_vertices; ++v) {
        const double a = plain.vertex_distance(PG::internal::Matrix_index(v));
        const double b = pruned.vertex_distance(PG::internal::Matrix_index(v));
        if((a < inf) != (b < inf)) {
          // at the limit up to rounding a vertex may fall on either side
          if(!(std::abs((a < inf ? a : b) - limit) <= 1e-12 * limit)) ++reach_differs;
          continue;
        }
        if(a == inf) continue;
        ++compared;
        const double e = std::abs(a - b) / std::max(a, 1e-300);
        worst = std::max(worst, e);
        if(e > 1e-12) ++differ;
      }
    }
    INFO(compared << " distances, worst relative difference " << worst << "; windows " << windows_plain << " -> "
                  << windows_pruned);
    CHECK(compared > 12 * 50);
    CHECK(differ == 0);
    CHECK(reach_differs == 0);
    CHECK(windows_pruned < windows_plain);
  }
}

TEST_CASE("symmetric_local_geodesic_distance_matrix: symmetric by construction, the smaller direction kept",
          "[geodesics][matrix][local][parallel]")
{
  const Mesh m = MDCS_test::mesh_from_soup<Mesh>(MDCS_test::bumpy_sphere<Point_3>(2, 0.15, 4));
  const double r = 4 * mean_edge_length(m);
  for(PG::Geodesic_method method : {PG::Geodesic_method::exact, PG::Geodesic_method::fast_marching}) {
    INFO(PG::geodesic_method_name(method));
    const PG::Geodesic_sparse_matrix d = PG::local_geodesic_distance_matrix<CGAL::Parallel_tag>(m, options_for(method, 2, r));
    const PG::Geodesic_sparse_matrix s = PG::symmetric_local_geodesic_distance_matrix<CGAL::Parallel_tag>(m, options_for(method, 2, r));
    for(std::size_t t : thread_counts)
      CHECK(same_matrix(PG::symmetric_local_geodesic_distance_matrix<CGAL::Parallel_tag>(m, options_for(method, t, r)), s));
    CHECK(s.symmetric);
    REQUIRE(s.rows == num_vertices(m));
    std::size_t asymmetric = 0, wrong = 0, beyond = 0, one_way = 0;
    double largest_gap = 0;
    std::size_t diagonal = 0;
    for(std::size_t u = 0; u < s.rows; ++u) {
      if(s.at(u, u) == 0) ++diagonal;
      for(std::size_t k = s.row_begin[u]; k < s.row_begin[u + 1]; ++k) {
        const std::size_t v = s.column[k];
        if(s.at(v, u) != s.value[k]) ++asymmetric;
        const double a = d.at(u, v), b = d.at(v, u);
        if(s.value[k] != std::min(a, b)) ++wrong;
        if(s.value[k] > r) ++beyond;
        if((a == inf) != (b == inf)) ++one_way;
        if(a < inf && b < inf) largest_gap = std::max(largest_gap, std::abs(a - b) / std::max(a, 1e-300));
      }
      // every directed entry is in the symmetric matrix
      for(std::size_t k = d.row_begin[u]; k < d.row_begin[u + 1]; ++k)
        if(!(s.at(u, d.column[k]) <= d.value[k])) ++wrong;
    }
    CHECK(diagonal == s.rows);
    CHECK(asymmetric == 0);
    CHECK(wrong == 0);
    CHECK(beyond == 0);
    INFO("pairs found in one direction only: " << one_way << ", largest relative gap between directions " << largest_gap);
    if(method == PG::Geodesic_method::exact) {
      CHECK(largest_gap <= 1e-13); // the two directions of an exact method agree up to rounding
    }
    CHECK(s.number_of_entries() >= d.number_of_entries());
  }
}

TEST_CASE("geodesic distance matrix: Polyhedron_3 as Surface_mesh, bad input, progress, cancellation",
          "[geodesics][matrix][parallel]")
{
  const MDCS_test::Triangle_soup<Point_3> soup = MDCS_test::bumpy_sphere<Point_3>(2, 0.1, 9);
  const Mesh m = MDCS_test::mesh_from_soup<Mesh>(soup);
  Polyhedron p;
  soup.to_mesh(p);
  const double r = 4 * mean_edge_length(m);
  const PG::Geodesic_sparse_matrix a = PG::local_geodesic_distance_matrix<CGAL::Parallel_tag>(m, options_for(PG::Geodesic_method::exact, 2, r));
  const PG::Geodesic_sparse_matrix b = PG::local_geodesic_distance_matrix<CGAL::Parallel_tag>(p, options_for(PG::Geodesic_method::exact, 2, r));
  CHECK(same_matrix(a, b)); // the soup's vertex order in both

  const std::vector<vertex_descriptor> sources = some_vertices(m, 10);
  auto ignore = [](std::size_t, const std::vector<double>&) {};
  auto ignore_sparse = [](std::size_t, const std::vector<std::uint32_t>&, const std::vector<double>&) {};
  PG::Geodesic_matrix_options bad = options_for(PG::Geodesic_method::exact, 2);
  bad.max_distance = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(PG::geodesic_distance_rows<CGAL::Parallel_tag>(m, sources, ignore, bad), std::invalid_argument);
  CHECK_THROWS_AS(PG::local_geodesic_distance_rows<CGAL::Parallel_tag>(m, sources, ignore_sparse, options_for(PG::Geodesic_method::exact, 2)),
                  std::invalid_argument); // no max_distance
  bad = options_for(PG::Geodesic_method::merged_windows, 2, r);
  bad.merge_tolerance = -1;
  CHECK_THROWS_AS(PG::local_geodesic_distance_rows<CGAL::Parallel_tag>(m, sources, ignore_sparse, bad), std::invalid_argument);
  std::vector<vertex_descriptor> stranger = {vertex_descriptor(std::uint32_t(num_vertices(m) + 5))};
  CHECK_THROWS_AS(PG::geodesic_distance_rows<CGAL::Parallel_tag>(m, stranger, ignore, options_for(PG::Geodesic_method::exact, 2)),
                  std::invalid_argument);

  // Progress on the calling thread, ending at 1; cancellation stops with Operation_cancelled after delivering a prefix.
  for(std::size_t t : thread_counts) {
    double last = -1;
    const auto caller = std::this_thread::get_id();
    bool ok = true;
    PG::geodesic_distance_rows<CGAL::Parallel_tag>(m, sources, ignore, options_for(PG::Geodesic_method::dijkstra, t),
                                                   [&](const char*, double f) {
                                                     ok = ok && std::this_thread::get_id() == caller && f >= last;
                                                     last = f;
                                                     return true;
                                                   });
    CHECK(ok);
    CHECK(last == 1.0);
    // Cancelled at once (the first report, before any row): nothing is delivered, whatever the thread count.
    std::size_t delivered = 0;
    CHECK_THROWS_AS(PG::geodesic_distance_rows<CGAL::Parallel_tag>(
                      m, sources, [&](std::size_t, const std::vector<double>&) { ++delivered; },
                      options_for(PG::Geodesic_method::dijkstra, t), [&](const char*, double) { return false; }),
                    CGAL::MDCS::Operation_cancelled);
    CHECK(delivered == 0);
    // Cancelled later (at the calling thread's first row or at the end): what is delivered is a prefix, in order.
    delivered = 0;
    bool prefix = true;
    int calls = 0;
    CHECK_THROWS_AS(PG::geodesic_distance_rows<CGAL::Parallel_tag>(
                      m, sources, [&](std::size_t i, const std::vector<double>&) { prefix = prefix && i == delivered; ++delivered; },
                      options_for(PG::Geodesic_method::dijkstra, t), [&](const char*, double) { return ++calls < 2; }),
                    CGAL::MDCS::Operation_cancelled);
    CHECK(delivered <= sources.size());
    CHECK(prefix);
  }
}

TEST_CASE("distance matrix files: .npy and Matrix Market round trips", "[geodesics][matrix][io]")
{
  namespace IO = PG::IO;
  // .npy, streamed rows, with infinities.
  std::stringstream npy;
  IO::Npy_matrix_writer w(npy, 3, 4);
  const std::vector<std::vector<double>> rows = {{0, 1.5, inf, 1e-300}, {2, 0, 3, 4}, {inf, inf, 0.1, 0}};
  for(const auto& r : rows) w.write_row(r);
  w.close();
  CHECK(npy.str().size() % 64 == (3 * 4 * 8) % 64); // the header is padded to 64 bytes
  std::size_t nr = 0, nc = 0;
  const std::vector<double> back = IO::read_npy(npy, nr, nc);
  CHECK(nr == 3);
  CHECK(nc == 4);
  CHECK(back == std::vector<double>({0, 1.5, inf, 1e-300, 2, 0, 3, 4, inf, inf, 0.1, 0}));
  std::stringstream short_npy;
  IO::Npy_matrix_writer w2(short_npy, 2, 2);
  CHECK_THROWS_AS(w2.write_row({1, 2, 3}), std::invalid_argument);
  w2.write_row({1, 2});
  CHECK_THROWS_AS(w2.close(), std::logic_error);

  // Matrix Market: a local matrix, general and symmetric, and the streaming writer.
  const Mesh m = MDCS_test::mesh_from_soup<Mesh>(MDCS_test::bumpy_sphere<Point_3>(2, 0.1, 9));
  const double r = 3 * mean_edge_length(m);
  const PG::Geodesic_sparse_matrix d = PG::local_geodesic_distance_matrix<CGAL::Parallel_tag>(m, options_for(PG::Geodesic_method::exact, 2, r));
  const PG::Geodesic_sparse_matrix s = PG::symmetric_local_geodesic_distance_matrix<CGAL::Parallel_tag>(m, options_for(PG::Geodesic_method::exact, 2, r));
  for(const PG::Geodesic_sparse_matrix* x : {&d, &s}) {
    std::stringstream mm;
    IO::write_matrix_market(mm, *x, "geodesic distances\nmax_distance " + std::to_string(r));
    const PG::Geodesic_sparse_matrix y = IO::read_matrix_market(mm);
    CHECK(same_matrix(*x, y)); // 17 significant digits: bit for bit
    CHECK(y.symmetric == x->symmetric);
  }
  std::stringstream streamed;
  IO::Matrix_market_row_writer mw(streamed, d.rows, d.columns, "streamed");
  for(std::size_t u = 0; u < d.rows; ++u)
    mw.write_row(std::vector<std::uint32_t>(d.column.begin() + std::ptrdiff_t(d.row_begin[u]), d.column.begin() + std::ptrdiff_t(d.row_begin[u + 1])),
                 std::vector<double>(d.value.begin() + std::ptrdiff_t(d.row_begin[u]), d.value.begin() + std::ptrdiff_t(d.row_begin[u + 1])));
  mw.close();
  CHECK(same_matrix(IO::read_matrix_market(streamed), d));
  std::stringstream garbage("not a matrix");
  CHECK_THROWS_AS(IO::read_matrix_market(garbage), std::runtime_error);
}

TEST_CASE("distance matrices on a prepared triangle soup with a non-manifold edge", "[geodesics][matrix][local][parallel]")
{
  // Three sheets of a 12 x 8 grid sharing the edge on the z axis (the middle one oriented the other way).
  typedef PG::Geodesic_surface_3<PG::Triangle_soup> Surface;
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  const std::size_t nr = 12, nz = 8;
  for(std::size_t j = 0; j <= nz; ++j) points.push_back({0, 0, double(j) / double(nz)});
  for(int s = 0; s < 3; ++s) {
    const double phi = 2 * 3.14159265358979323846 * s / 3 + 0.1;
    const std::size_t first = points.size();
    for(std::size_t i = 1; i <= nr; ++i)
      for(std::size_t j = 0; j <= nz; ++j)
        points.push_back({double(i) / double(nr) * std::cos(phi), double(i) / double(nr) * std::sin(phi), double(j) / double(nz)});
    auto id = [&](std::size_t i, std::size_t j) { return i == 0 ? j : first + (i - 1) * (nz + 1) + j; };
    for(std::size_t i = 0; i < nr; ++i)
      for(std::size_t j = 0; j < nz; ++j) {
        std::array<std::size_t, 3> t1 = {id(i, j), id(i + 1, j), id(i + 1, j + 1)}, t2 = {id(i, j), id(i + 1, j + 1), id(i, j + 1)};
        if(s == 1) {
          std::swap(t1[1], t1[2]);
          std::swap(t2[1], t2[2]);
        }
        triangles.push_back(t1);
        triangles.push_back(t2);
      }
  }
  const Surface surface(points, triangles);
  REQUIRE(surface.number_of_nonmanifold_edges() > 0);
  const double r = 0.35;
  std::vector<std::size_t> sources;
  for(std::size_t v = 0; v < points.size(); v += 7) sources.push_back(v);
  for(PG::Geodesic_method method : {PG::Geodesic_method::exact, PG::Geodesic_method::dijkstra}) {
    INFO(PG::geodesic_method_name(method));
    std::vector<std::vector<std::pair<std::uint32_t, double>>> rows(sources.size());
    for(std::size_t t : thread_counts) {
      std::vector<std::vector<std::pair<std::uint32_t, double>>> got(sources.size());
      PG::local_geodesic_distance_rows<CGAL::Parallel_tag>(
        surface, sources,
        [&](std::size_t i, const std::vector<std::uint32_t>& c, const std::vector<double>& d) {
          for(std::size_t k = 0; k < c.size(); ++k) got[i].push_back({c[k], d[k]});
        },
        options_for(method, t, r));
      if(t == 1) rows = got;
      CHECK(got == rows);
    }
    // Against the class on the same surface, on the whole soup, stopped at r.
    std::size_t missing = 0, extra = 0, differ = 0, pairs = 0;
    for(std::size_t i = 0; i < sources.size(); ++i) {
      std::vector<double> whole(points.size(), inf);
      const auto m = PG::Geodesic_memory_mode::distances_only;
      auto run = [&](auto& g) {
        g.set_distance_limit(r);
        g.add_source(sources[i]);
        for(std::size_t v = 0; v < points.size(); ++v) whole[v] = g.distance(v);
      };
      if(method == PG::Geodesic_method::exact) {
        PG::Exact_geodesic_distances_3<PG::Triangle_soup> g(surface, m);
        run(g);
      } else {
        PG::Dijkstra_geodesic_distances_3<PG::Triangle_soup> g(surface, m);
        run(g);
      }
      std::vector<double> local(points.size(), inf);
      for(const auto& e : rows[i]) local[e.first] = e.second;
      for(std::size_t v = 0; v < points.size(); ++v) {
        const bool in_whole = whole[v] <= r, in_local = local[v] <= r;
        const bool borderline = std::abs((in_whole ? whole[v] : local[v]) - r) <= 1e-12 * r;
        if(in_whole && !in_local && !borderline) ++missing;
        if(!in_whole && in_local && !borderline) ++extra;
        if(in_whole && in_local) {
          ++pairs;
          if(std::abs(whole[v] - local[v]) > 1e-12 * std::max(whole[v], 1e-300)) ++differ;
        }
      }
    }
    CHECK(pairs > 10 * sources.size());
    CHECK(missing == 0);
    CHECK(extra == 0);
    CHECK(differ == 0);
  }
  // Dense rows on the surface equal the class's rows, bit for bit.
  std::vector<std::vector<double>> dense;
  PG::geodesic_distance_rows<CGAL::Parallel_tag>(surface, sources, [&](std::size_t, const std::vector<double>& row) {
    dense.push_back(row);
  }, options_for(PG::Geodesic_method::exact, 2));
  PG::Exact_geodesic_distances_3<PG::Triangle_soup> g(surface, PG::Geodesic_memory_mode::distances_only);
  g.add_source(sources[3]);
  bool same = dense.size() == sources.size();
  for(std::size_t v = 0; same && v < points.size(); ++v) same = dense[3][v] == g.distance(v);
  CHECK(same);
  // Flat-exact and fast marching refuse such surfaces, as their classes do.
  auto ignore = [](std::size_t, const std::vector<double>&) {};
  CHECK_THROWS_AS(PG::geodesic_distance_rows<CGAL::Parallel_tag>(surface, sources, ignore,
                                                                 options_for(PG::Geodesic_method::fast_marching, 2)),
                  std::invalid_argument);
  CHECK_THROWS_AS(PG::geodesic_distance_rows<CGAL::Parallel_tag>(surface, sources, ignore,
                                                                 options_for(PG::Geodesic_method::flat_exact, 2, r)),
                  std::invalid_argument);
}
