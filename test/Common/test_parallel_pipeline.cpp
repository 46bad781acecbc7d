// The ordered pipeline and the deterministic-error loop of CGAL/MDCS/concurrency.h: every item computed once,
// delivered in order and one at a time with a bounded number in flight; errors and stop requests leave exactly
// the prefix a sequential loop leaves, and the same exception, for 1, 2, 3 and 8 threads. Also compiled without
// TBB (test_Common_sequential). Tagged [parallel]: the ThreadSanitizer build runs these cases.
#include <catch2/catch.hpp>

#include <CGAL/MDCS/concurrency.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace MDCS = CGAL::MDCS;

namespace {

// Uneven work: item i costs about (i % 7) units.
double work(std::size_t i)
{
  double s = 0;
  for(std::size_t k = 0; k < 2000 * (i % 7 + 1); ++k) s += std::sin(double(k + i));
  return s;
}

} // namespace

TEST_CASE("parallel_ordered_pipeline: results in order, bounded, one delivery at a time",
          "[common][concurrency][parallel]")
{
  const std::size_t n = 203;
  std::vector<double> expected(n);
  for(std::size_t i = 0; i < n; ++i) expected[i] = work(i);
  for(std::size_t threads : {1u, 2u, 3u, 8u})
    for(std::size_t capacity : {1u, 2u, 5u, 64u}) {
      INFO(threads << " threads, " << capacity << " slots");
      struct Slot
      {
        std::size_t item = std::size_t(-1);
        double value = 0;
      };
      std::vector<Slot> slots(capacity);
      std::vector<double> got;
      std::vector<std::size_t> order;
      std::atomic<int> delivering{0};
      std::atomic<std::size_t> computed{0}, delivered{0};
      bool alone = true;               // written by the deliveries only, never two at a time
      std::atomic<bool> bounded{true}; // written by the computations, on any thread
      const std::size_t count = MDCS::parallel_ordered_pipeline(
        n, threads, slots,
        [&](std::size_t i, Slot& s) {
          s.item = i;
          s.value = work(i);
          // Items computed and not delivered never exceed the slots.
          if(computed.fetch_add(1) + 1 > delivered.load() + capacity + threads) bounded.store(false);
          return true;
        },
        [&](std::size_t i, Slot& s) {
          alone = alone && delivering.fetch_add(1) == 0;
          order.push_back(i);
          got.push_back(s.item == i ? s.value : -1e300);
          delivered.fetch_add(1);
          delivering.fetch_sub(1);
        });
      CHECK(count == n);
      CHECK(alone);
      CHECK(bounded.load());
      REQUIRE(order.size() == n);
      bool in_order = true;
      for(std::size_t i = 0; i < n; ++i) in_order = in_order && order[i] == i;
      CHECK(in_order);
      CHECK(got == expected); // bit for bit: each item computed by the same code
    }
}

TEST_CASE("parallel_ordered_pipeline: errors and stops leave the sequential prefix", "[common][concurrency][parallel]")
{
  const std::size_t n = 120;
  for(std::size_t threads : {1u, 2u, 3u, 8u}) {
    INFO(threads << " threads");
    std::vector<int> slots(4);
    std::vector<std::size_t> order;
    // Items 50 and 70 throw; 50 is the one reported, items 0..49 are delivered.
    try {
      MDCS::parallel_ordered_pipeline(
        n, threads, slots,
        [&](std::size_t i, int&) {
          work(i);
          if(i == 50 || i == 70) throw std::runtime_error("item " + std::to_string(i));
          return true;
        },
        [&](std::size_t i, int&) { order.push_back(i); });
      FAIL("no exception");
    } catch(const std::runtime_error& e) {
      CHECK(std::string(e.what()) == "item 50");
    }
    CHECK(order.size() == 50);
    // The delivery throws at item 30.
    order.clear();
    CHECK_THROWS_WITH(MDCS::parallel_ordered_pipeline(
                        n, threads, slots, [&](std::size_t i, int&) { return work(i) < 1e300; },
                        [&](std::size_t i, int&) {
                          if(i == 30) throw std::runtime_error("deliver 30");
                          order.push_back(i);
                        }),
                      "deliver 30");
    CHECK(order.size() == 30);
    // A stop request at item 40 (cancellation): 0..39 delivered, no exception.
    order.clear();
    const std::size_t count = MDCS::parallel_ordered_pipeline(
      n, threads, slots, [&](std::size_t i, int&) { return i != 40; },
      [&](std::size_t i, int&) { order.push_back(i); });
    CHECK(count == 40);
    CHECK(order.size() == 40);
  }
  std::vector<int> none;
  CHECK_THROWS_AS(MDCS::parallel_ordered_pipeline(3, 2, none, [](std::size_t, int&) { return true; },
                                                  [](std::size_t, int&) {}),
                  std::invalid_argument);
}

TEST_CASE("parallel_for_blocks_lowest_error: the sequential loop's error for every thread count",
          "[common][concurrency][parallel]")
{
  for(std::size_t threads : {1u, 2u, 3u, 8u}) {
    std::vector<char> done(100, 0);
    try {
      MDCS::parallel_for_blocks_lowest_error(1000, 10, threads, [&](std::size_t b, std::size_t, std::size_t k) {
        if(k == 80) std::this_thread::sleep_for(std::chrono::milliseconds(2)); // let higher blocks fail first
        if(k == 17 || k == 80 || k == 95) throw std::runtime_error("block " + std::to_string(b / 10));
        done[k] = 1;
      });
      FAIL("no exception");
    } catch(const std::runtime_error& e) {
      CHECK(std::string(e.what()) == "block 17");
    }
    bool prefix = true;
    for(std::size_t k = 0; k < 17; ++k) prefix = prefix && done[k];
    CHECK(prefix); // every block below the failing one ran
  }
}
