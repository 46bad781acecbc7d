// One geodesic object per thread on one shared, read-only surface (Geodesic_surface_3): on 1, 2, 3 and 8 threads
// (8 oversubscribes the 2-core machines on purpose), exact (distances_only) and flat-exact objects, each reused for
// several sources, give the same distances as one object after another, bit for bit. Named test_parallel_* so that
// the ThreadSanitizer build (MDCS_TSAN) runs it: no Catch assertion inside a thread, results checked afterwards.
#include <catch2/catch.hpp>

#include <MDCS_test/mesh_generators.h>
#include <MDCS_test/thread_counts.h>
#include <MDCS_test/geodesic_test_geometry.h>

#include <CGAL/Polyhedral_geodesics_3.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_surface_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/property_map.h>

#include <atomic>
#include <cstring>
#include <thread>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Point_3;
namespace PG = CGAL::Polyhedral_geodesics_3;
typedef PG::Triangle_soup Soup;

using MDCS_test::same_bits;

} // namespace

TEST_CASE("geodesic surface: one object per thread on a shared surface, 1, 2, 3 and 8 threads",
          "[geodesics][surface][parallel]")
{
  const MDCS_test::Triangle_soup<Point_3> soup = MDCS_test::icosphere<Point_3>(3);
  const auto surface = PG::make_geodesic_surface(soup.points, soup.triangles);
  const std::size_t nv = soup.points.size(), sources = 16;
  // one object after another
  std::vector<std::vector<double>> serial(sources), serial_flat(sources);
  for(std::size_t s = 0; s < sources; ++s) {
    PG::Exact_geodesic_distances_3<Soup> exact(surface, PG::Geodesic_memory_mode::distances_only);
    exact.add_source(s * 37 % nv);
    serial[s].resize(nv);
    exact.distances(CGAL::make_property_map(serial[s]));
    PG::Flat_exact_geodesic_distances_3<Soup> flat(surface);
    flat.add_source(s * 37 % nv);
    serial_flat[s].resize(nv);
    flat.distances(CGAL::make_property_map(serial_flat[s]));
  }
  for(std::size_t threads : MDCS_test::thread_counts) {
    INFO(threads << " threads");
    std::vector<std::vector<double>> rows(sources, std::vector<double>(nv)), flat_rows = rows;
    std::atomic<std::size_t> next(0);
    std::vector<std::thread> pool;
    for(std::size_t t = 0; t < threads; ++t)
      pool.emplace_back([&]() {
        // one solver per thread, reused for every source it takes
        PG::Exact_geodesic_distances_3<Soup> exact(surface, PG::Geodesic_memory_mode::distances_only);
        PG::Flat_exact_geodesic_distances_3<Soup> flat(surface);
        for(std::size_t s; (s = next++) < sources;) {
          exact.clear_sources();
          exact.add_source(s * 37 % nv);
          exact.distances(CGAL::make_property_map(rows[s]));
          flat.clear_sources();
          flat.add_source(s * 37 % nv);
          flat.distances(CGAL::make_property_map(flat_rows[s]));
        }
      });
    for(auto& t : pool)
      t.join();
    std::size_t differing = 0;
    for(std::size_t s = 0; s < sources; ++s)
      for(std::size_t v = 0; v < nv; ++v)
        if(!same_bits(rows[s][v], serial[s][v]) || !same_bits(flat_rows[s][v], serial_flat[s][v]))
          ++differing;
    CHECK(differing == 0);
  }
}

