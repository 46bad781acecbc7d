// remove_source() of every geodesic distance class: one source removed, the others kept; the result equals a new
// object's given the remaining sources in the same order (vertex distances, nearest sources, point distances and
// paths, all compared with ==), also when removal and additions alternate, and the indices move down.
#include <catch2/catch.hpp>

#include <MDCS_test/geodesic_test_meshes.h>
#include <MDCS_test/mesh_generators.h>

#include <CGAL/Polyhedral_geodesics_3.h>

#include <stdexcept>
#include <vector>

namespace {

using namespace MDCS_test::Epick_surface_mesh;
namespace PG = CGAL::Polyhedral_geodesics_3;

// Vertex distances and nearest sources, exactly as computed.
template <class G>
std::pair<std::vector<double>, std::vector<std::size_t>> removal_vertex_results(G& g, const Mesh& m)
{
  std::pair<std::vector<double>, std::vector<std::size_t>> r;
  for(vertex_descriptor v : vertices(m)) {
    const auto ns = g.nearest_source(v);
    r.first.push_back(ns.first);
    r.second.push_back(ns.second);
  }
  return r;
}

template <class G, class... Args>
void check_removal(const Mesh& m, const std::vector<Source>& sources, bool full_field, Args... args)
{
  // sources 0..n-1, then remove 1, then remove the (new) last, then add the first one again
  G g(m, args...);
  add_sources(g, sources);
  g.compute();
  g.remove_source(1);
  CHECK(g.number_of_sources() == sources.size() - 1);
  std::vector<Source> rest = sources;
  rest.erase(rest.begin() + 1);
  {
    G fresh(m, args...);
    add_sources(fresh, rest);
    CHECK(removal_vertex_results(g, m) == removal_vertex_results(fresh, m));
    if(full_field) {
      for(face_descriptor f : faces(m)) {
        const typename G::Face_location loc(f, {{0.2, 0.3, 0.5}});
        CHECK(g.nearest_source(loc) == fresh.nearest_source(loc));
      }
      for(vertex_descriptor v : vertices(m)) {
        std::vector<Point_3> a, b;
        g.shortest_path_points(v, std::back_inserter(a));
        fresh.shortest_path_points(v, std::back_inserter(b));
        CHECK(a == b);
      }
    }
  }
  g.remove_source(g.number_of_sources() - 1);
  rest.pop_back();
  add_sources(g, {sources.front()});
  rest.push_back(sources.front());
  G fresh(m, args...);
  add_sources(fresh, rest);
  CHECK(removal_vertex_results(g, m) == removal_vertex_results(fresh, m));
  CHECK_THROWS_AS(g.remove_source(rest.size()), std::out_of_range);
  // removing every source one by one leaves an object that refuses queries, as a new one does
  while(g.number_of_sources() > 0) g.remove_source(0);
  CHECK_THROWS_AS(g.compute(), std::logic_error);
}

} // namespace

TEST_CASE("remove_source: every class equals a fresh run from the remaining sources", "[geodesics][remove_source]")
{
  const Mesh m = make_mesh(MDCS_test::icosphere<Point_3>(2));
  std::vector<vertex_descriptor> vs(vertices(m).begin(), vertices(m).end());
  const face_descriptor f = *std::next(faces(m).begin(), 17);
  const std::vector<Source> sources = {at(vs[3]), at(vs[40]), at({f, {{0.1, 0.6, 0.3}}}), at(vs[100]), at(vs[7])};
  SECTION("exact") { check_removal<PG::Exact_geodesic_distances_3<Mesh>>(m, sources, true); }
  SECTION("exact, distances only")
  {
    check_removal<PG::Exact_geodesic_distances_3<Mesh>>(m, sources, false, PG::Geodesic_memory_mode::distances_only);
  }
  SECTION("merged") { check_removal<PG::Merged_window_geodesic_distances_3<Mesh>>(m, sources, true, 0.01); }
  SECTION("flat-exact") { check_removal<PG::Flat_exact_geodesic_distances_3<Mesh>>(m, sources, true); }
  SECTION("fast marching") { check_removal<PG::Fast_marching_geodesic_distances_3<Mesh>>(m, sources, true); }
  SECTION("Dijkstra") { check_removal<PG::Dijkstra_geodesic_distances_3<Mesh>>(m, sources, true); }
}

TEST_CASE("remove_source: the nearest-source indices move down", "[geodesics][remove_source]")
{
  const Mesh m = make_mesh(MDCS_test::planar_grid<Point_3>(6, 6));
  std::vector<vertex_descriptor> vs(vertices(m).begin(), vertices(m).end());
  PG::Exact_geodesic_distances_3<Mesh> g(m);
  g.add_source(vs.front()); // (0, 0)
  g.add_source(vs[24]);     // (3/6, 3/6)
  g.add_source(vs.back());  // (1, 1)
  CHECK(g.nearest_source(vs.back()).second == 2);
  g.remove_source(1);
  CHECK(g.nearest_source(vs.back()) == std::make_pair(0.0, std::size_t(1)));
  CHECK(g.distance(vs[24]) == Approx(std::sqrt(0.5)).epsilon(1e-14));
}
