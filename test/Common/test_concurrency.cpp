// The shared concurrency helper (CGAL/MDCS/concurrency.h): the same blocks and results for every thread count,
// exceptions and cancellation reach the caller, and without TBB everything runs sequentially. This file is
// also compiled without TBB (test_Common_sequential) to check the fallback.
#include <catch2/catch.hpp>

#include <CGAL/MDCS/concurrency.h>

#include <atomic>
#include <cmath>
#include <mutex>
#include <numeric>
#include <set>
#include <stdexcept>
#include <thread>
#include <type_traits>
#include <vector>

namespace MDCS = CGAL::MDCS;

TEST_CASE("concurrency: thread counts from the tag and the request", "[common][concurrency]")
{
  CHECK(MDCS::effective_threads<CGAL::Sequential_tag>(8) == 1);
  CHECK(MDCS::effective_threads<CGAL::Sequential_tag>(0) == 1);
  if(MDCS::has_parallel_support()) {
    CHECK(MDCS::effective_threads<CGAL::Parallel_tag>(3) == 3);
    CHECK(MDCS::effective_threads<CGAL::Parallel_tag>(0) == MDCS::hardware_threads());
    // CGAL makes Parallel_if_available_tag the sequential tag without TBB (the std::thread back end of TSan builds)
    CHECK(MDCS::effective_threads<CGAL::Parallel_if_available_tag>(2) ==
          (std::is_same<CGAL::Parallel_if_available_tag, CGAL::Parallel_tag>::value ? 2u : 1u));
    CHECK(MDCS::effective_threads(2, true) == 2);
  } else {
    CHECK(MDCS::effective_threads<CGAL::Parallel_tag>(3) == 1);
    CHECK(MDCS::effective_threads<CGAL::Parallel_if_available_tag>(0) == 1);
  }
  CHECK(MDCS::effective_threads(5, false) == 1);
  CHECK(MDCS::hardware_threads() >= 1);
}

TEST_CASE("concurrency: blocks and per-block results do not depend on the thread count", "[common][concurrency]")
{
  const std::size_t n = 10007, block = 97;
  // A floating-point sum per block, reduced in block order: bit-identical for every thread count.
  auto run = [&](std::size_t threads) {
    std::vector<double> partial((n + block - 1) / block, 0.0);
    std::vector<std::size_t> begins(partial.size(), 0), ends(partial.size(), 0);
    MDCS::parallel_for_blocks(n, block, threads, [&](std::size_t b, std::size_t e, std::size_t k) {
      begins[k] = b;
      ends[k] = e;
      double s = 0;
      for(std::size_t i = b; i < e; ++i)
        s += std::sin(double(i)) / double(i + 1);
      partial[k] = s;
    });
    for(std::size_t k = 0; k < partial.size(); ++k) {
      REQUIRE(begins[k] == k * block);
      REQUIRE(ends[k] == std::min(n, (k + 1) * block));
    }
    return std::accumulate(partial.begin(), partial.end(), 0.0);
  };
  const double one = run(1);
  for(std::size_t threads : {2u, 3u, 8u})
    CHECK(run(threads) == one); // exact equality on purpose
  // Every index visited exactly once.
  std::vector<std::atomic<int>> visits(n);
  MDCS::parallel_for_each_index(n, 3, [&](std::size_t i) { visits[i].fetch_add(1); });
  for(std::size_t i = 0; i < n; ++i)
    REQUIRE(visits[i].load() == 1);
  // Empty ranges and a zero block size are harmless.
  int calls = 0;
  MDCS::parallel_for_blocks(0, 10, 4, [&](std::size_t, std::size_t, std::size_t) { ++calls; });
  CHECK(calls == 0);
  MDCS::parallel_for_blocks(3, 0, 1, [&](std::size_t, std::size_t, std::size_t) { ++calls; });
  CHECK(calls == 3);
}

TEST_CASE("concurrency: a team runs many steps with the blocks of parallel_for_blocks", "[common][concurrency]")
{
  // Many short steps on one team (the parallel single-source propagation's rounds): every step sees the same
  // blocks, runs each once, and a per-block sum reduced in block order is identical for every thread count.
  const std::size_t steps = 300;
  auto run = [&](std::size_t threads) {
    MDCS::Parallel_team team(threads);
    CHECK(team.threads() == (threads == 0 ? 1 : threads));
    double total = 0;
    for(std::size_t step = 0; step < steps; ++step) {
      const std::size_t n = 1 + (step * 37) % 301, block = 4;
      std::vector<double> partial((n + block - 1) / block, 0.0);
      std::vector<int> runs(partial.size(), 0);
      std::vector<std::size_t> begins(partial.size(), 0), ends(partial.size(), 0);
      team.for_blocks(n, block, [&](std::size_t b, std::size_t e, std::size_t k) { // no Catch2 macro on a worker
        ++runs[k];
        begins[k] = b;
        ends[k] = e;
        for(std::size_t i = b; i < e; ++i)
          partial[k] += std::sin(double(i + step)) / double(i + 1);
      });
      for(std::size_t k = 0; k < runs.size(); ++k) {
        REQUIRE(runs[k] == 1);
        REQUIRE(begins[k] == k * block);
        REQUIRE(ends[k] == std::min(n, (k + 1) * block));
      }
      total = std::accumulate(partial.begin(), partial.end(), total);
    }
    return total;
  };
  const double one = run(1);
  for(std::size_t threads : {2u, 3u, 8u})
    CHECK(run(threads) == one); // exact equality on purpose
  MDCS::Parallel_team team(3);
  CHECK_THROWS_AS(team.for_blocks(40, 4, [](std::size_t b, std::size_t, std::size_t) {
    if(b == 20) throw std::runtime_error("block 5");
  }), std::runtime_error);
}

TEST_CASE("concurrency: an exception in a block reaches the caller", "[common][concurrency]")
{
  for(std::size_t threads : {1u, 2u, 8u})
    CHECK_THROWS_AS(MDCS::parallel_for_blocks(1000, 10, threads,
                                              [](std::size_t b, std::size_t, std::size_t) {
                                                if(b == 500)
                                                  throw std::runtime_error("block 50");
                                              }),
                    std::runtime_error);
}

TEST_CASE("concurrency: per-thread workspaces and thread use", "[common][concurrency]")
{
  MDCS::Per_thread<std::vector<int>> scratch([] { return std::vector<int>(16, 0); });
  std::set<std::thread::id> ids;
  std::mutex m;
  std::atomic<int> wrong_size{0};   // Catch's assertions are not thread-safe: none inside a parallel body
  MDCS::parallel_for_blocks(64, 1, 2, [&](std::size_t, std::size_t, std::size_t) {
    std::vector<int>& s = scratch.local();
    if(s.size() != 16) {
      wrong_size.fetch_add(1);
      return;
    }
    ++s[0];
    std::lock_guard<std::mutex> lock(m);
    ids.insert(std::this_thread::get_id());
  });
  CHECK(wrong_size.load() == 0);
  int total = 0, objects = 0;
  scratch.for_each([&](std::vector<int>& s) { total += s[0]; ++objects; });
  CHECK(total == 64);
  CHECK(objects >= 1);
  CHECK(std::size_t(objects) <= (MDCS::has_parallel_support() ? 2u : 1u));
  CHECK(ids.size() <= (MDCS::has_parallel_support() ? 2u : 1u));
}

TEST_CASE("concurrency: progress from one thread, cancellation stops the loop", "[common][concurrency]")
{
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<double> fractions;
  bool other_thread_called = false;
  auto record = [&](const char*, double f) {
    if(std::this_thread::get_id() != caller)
      other_thread_called = true;
    fractions.push_back(f);
    return true;
  };
  {
    MDCS::Parallel_progress<decltype(record)> progress(record, "test", 1000);
    MDCS::parallel_for_blocks(1000, 7, 3, [&](std::size_t b, std::size_t e, std::size_t) { progress.advance(e - b); });
    progress.finish();
  }
  CHECK_FALSE(other_thread_called);
  REQUIRE(fractions.size() >= 2);
  CHECK(fractions.front() == 0.0);
  CHECK(fractions.back() == 1.0);
  CHECK(std::is_sorted(fractions.begin(), fractions.end()));

  // The callback cancels at once: workers see it and the caller gets Operation_cancelled.
  std::atomic<std::size_t> bodies_after_cancel{0};
  int calls = 0;
  auto cancel = [&](const char*, double) { return ++calls < 2; }; // the start report passes, the next cancels
  MDCS::Parallel_progress<decltype(cancel)> progress(cancel, "cancel", 100000);
  MDCS::parallel_for_blocks(100000, 1, 2, [&](std::size_t, std::size_t, std::size_t) {
    if(progress.cancelled())
      return;
    if(!progress.advance())
      bodies_after_cancel.fetch_add(1);
  });
  CHECK(progress.cancelled());
  CHECK_THROWS_AS(progress.finish(), CGAL::MDCS::Operation_cancelled);
}
