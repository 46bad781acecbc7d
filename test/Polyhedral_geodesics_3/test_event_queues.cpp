// The event queues of the exact propagation: the radix heap (double keys, monotone use) and the 4-ary heap
// (other number types), against a sorted reference on random monotone workloads: keys come out in nondecreasing
// order, every entry exactly once; a key pushed below the last popped one (rounding) comes out next; entries with
// equal keys come out first in, first out from the radix heap; clear() and release() allow reuse.
#include <catch2/catch.hpp>

#include <CGAL/Polyhedral_geodesics_3/internal/Quaternary_heap.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Radix_heap.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace PGI = CGAL::Polyhedral_geodesics_3::internal;

namespace {

struct Entry
{
  double key;
  int id;
  std::uint32_t stamp;
};

// A Dijkstra-like workload: each pop pushes 0-3 entries at or above the popped key (some exactly equal, some a
// few ulps below it, as rounding makes them); the popped sequence must be sorted up to those clamped keys.
template <class Heap>
void check_monotone_workload(Heap& heap, std::uint64_t seed, bool fifo_ties)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  std::vector<char> popped;
  std::vector<double> key_of;
  auto push = [&](double key) {
    heap.push(Entry{key, int(key_of.size()), 0});
    key_of.push_back(key);
    popped.push_back(0);
  };
  for(int i = 0; i < 20; ++i) push(U(rng) * 10);
  push(0.0);
  double last = 0;
  std::size_t pops = 0, below = 0, equal_pairs = 0;
  int last_equal_id = -1;
  double last_key = -1;
  while(!heap.empty()) {
    const Entry e = heap.pop();
    ++pops;
    REQUIRE(e.id >= 0);
    REQUIRE(std::size_t(e.id) < key_of.size());
    CHECK(popped[std::size_t(e.id)] == 0);
    popped[std::size_t(e.id)] = 1;
    CHECK(e.key == key_of[std::size_t(e.id)]);
    // Nondecreasing, except for keys pushed below the front, which come out at once.
    if(e.key < last) {
      ++below;
      CHECK(e.key >= last * (1 - 1e-12));
    } else
      last = e.key;
    if(fifo_ties && e.key == last_key) {
      ++equal_pairs;
      CHECK(e.id > last_equal_id); // pushed later, popped later
    }
    last_equal_id = e.id;
    last_key = e.key;
    if(key_of.size() < 20000) {
      const int children = int(rng() % 4);
      for(int c = 0; c < children; ++c) {
        const double r = U(rng);
        if(r < 0.15) push(e.key);                                     // a tie
        else if(r < 0.2) push(std::nextafter(e.key, 0.0) * (1 - 1e-15)); // a few ulps below the front
        else push(e.key + U(rng));
      }
    }
  }
  CHECK(pops == key_of.size());
  CHECK(std::count(popped.begin(), popped.end(), 1) == std::ptrdiff_t(key_of.size()));
  CHECK(below > 0);
  if(fifo_ties) CHECK(equal_pairs > 100);
}

} // namespace

TEST_CASE("Radix_heap: monotone workloads pop in order, clamped keys next, ties first in first out",
          "[geodesics][exact][queue]")
{
  PGI::Radix_heap<Entry> heap;
  for(std::uint64_t seed = 1; seed <= 5; ++seed) {
    check_monotone_workload(heap, seed, true);
    CHECK(heap.empty());
    CHECK(heap.size() == 0);
    if(seed % 2) heap.clear();
    else heap.release();
  }
  // Large and tiny keys, infinity and zero together.
  heap.push(Entry{1e300, 0, 0});
  heap.push(Entry{std::numeric_limits<double>::infinity(), 1, 0});
  heap.push(Entry{1e-300, 2, 0});
  heap.push(Entry{0.0, 3, 0});
  heap.push(Entry{1.0, 4, 0});
  std::vector<int> order;
  while(!heap.empty()) order.push_back(heap.pop().id);
  CHECK(order == std::vector<int>{3, 2, 4, 0, 1});
}

TEST_CASE("Quaternary_heap: the same workloads pop in order", "[geodesics][exact][queue]")
{
  PGI::Quaternary_heap<Entry> heap;
  for(std::uint64_t seed = 1; seed <= 3; ++seed) {
    check_monotone_workload(heap, seed, false);
    CHECK(heap.empty());
    heap.clear();
  }
}
