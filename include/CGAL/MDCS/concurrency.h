// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one concurrency convention of MDCS: CGAL's concurrency tags plus a thread count, on TBB when the program is
// linked with it (CGAL::TBB_support defines CGAL_LINKED_WITH_TBB), sequential otherwise. Every package runs its
// parallel loops through this header; none carries its own thread pool.
//
// A second back end on std::thread exists for ThreadSanitizer builds only (MDCS_CONCURRENCY_STD_THREADS, set by
// the CMake option MDCS_TSAN, TBB not linked): Debian's TBB is not instrumented, so TSan sees none of its
// synchronisation and reports races inside TBB itself; on std::thread it checks the parallel bodies alone.

#ifndef CGAL_MDCS_CONCURRENCY_H
#define CGAL_MDCS_CONCURRENCY_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>
#elif defined(MDCS_CONCURRENCY_STD_THREADS)
#define CGAL_MDCS_CONCURRENCY_USES_STD_THREADS 1
#include <functional>
#include <memory>
#include <utility>
#endif

namespace CGAL {
namespace MDCS {

/*!
  \brief How many threads a call may use.

  MDCS entry points that can run in parallel take a `ConcurrencyTag` template parameter
  (`CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`, as in CGAL) and a thread
  count: `0` means every hardware thread, `1` runs sequentially, `n` at most `n` threads. Without TBB
  (`CGAL_LINKED_WITH_TBB` undefined) everything runs sequentially whatever the tag and the count.

  Results never depend on the thread count: the parallel loops below cut the work into blocks that depend only
  on the input (never on the number of threads), and every reduction combines the blocks' results in block order.
*/
inline std::size_t hardware_threads()
{
  const unsigned n = std::thread::hardware_concurrency();
  return n == 0 ? 1 : std::size_t(n);
}

/// Whether TBB is linked in, i.e. whether a parallel tag can run more than one thread.
constexpr bool has_parallel_support()
{
#if defined(CGAL_LINKED_WITH_TBB) || defined(CGAL_MDCS_CONCURRENCY_USES_STD_THREADS)
  return true;
#else
  return false;
#endif
}

/// Whether `ConcurrencyTag` asks for parallel execution (`CGAL::Parallel_tag`, or
/// `CGAL::Parallel_if_available_tag` when TBB is linked in).
template <class ConcurrencyTag>
struct Is_parallel_tag : std::is_same<ConcurrencyTag, CGAL::Parallel_tag>
{};

/// The number of threads a call with `ConcurrencyTag` and the requested count `requested` (0: all) runs on.
template <class ConcurrencyTag>
std::size_t effective_threads(std::size_t requested)
{
  static_assert(std::is_same<ConcurrencyTag, CGAL::Sequential_tag>::value ||
                  std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "ConcurrencyTag must be CGAL::Sequential_tag, CGAL::Parallel_tag or CGAL::Parallel_if_available_tag");
  if(!Is_parallel_tag<ConcurrencyTag>::value || !has_parallel_support())
    return 1;
  return requested == 0 ? hardware_threads() : requested;
}

/// The same for a run-time choice (the command-line tool and the Python layer): `threads` 0 means all.
inline std::size_t effective_threads(std::size_t requested, bool parallel)
{
  return parallel ? effective_threads<CGAL::Parallel_tag>(requested) : 1;
}

namespace internal {

// The blocks of [0, n): block b is [b * size, min(n, (b + 1) * size)). The size depends on n and the caller's
// choice only, so a body that writes per-block results sees the same blocks for every thread count.
struct Block_partition
{
  std::size_t n, size;
  std::size_t count() const { return size == 0 ? 0 : (n + size - 1) / size; }
  std::size_t begin(std::size_t b) const { return b * size; }
  std::size_t end(std::size_t b) const { return (std::min)(n, (b + 1) * size); }
};

} // namespace internal

/*!
  \brief Runs `body(begin, end, block)` on the blocks of `[0, n)` of `block_size` items (the last one may be
  shorter), on at most `threads` threads (see `effective_threads()`).

  The blocks are the same for every thread count; only which thread runs a block changes. A body that writes
  nothing but its own block's results therefore gives identical results for every thread count. An exception
  thrown by a body stops the loop and is rethrown in the calling thread (the first one, if several throw).
*/
template <class Body>
void parallel_for_blocks(std::size_t n, std::size_t block_size, std::size_t threads, Body body)
{
  if(block_size == 0)
    block_size = 1;
  const internal::Block_partition blocks{n, block_size};
  const std::size_t count = blocks.count();
  if(threads <= 1 || count <= 1 || !has_parallel_support()) {
    for(std::size_t b = 0; b < count; ++b)
      body(blocks.begin(b), blocks.end(b), b);
    return;
  }
#ifdef CGAL_LINKED_WITH_TBB
  // More threads than cores (tests oversubscribe on purpose): TBB's default limit is the number of cores, so it is
  // raised for the duration of the call. The smallest active limit wins, so a limit of the caller's still holds.
  const std::size_t used = (std::min)(threads, count);
  tbb::global_control allow(tbb::global_control::max_allowed_parallelism, (std::max)(used, hardware_threads()));
  tbb::task_arena arena(static_cast<int>(used));
  arena.execute([&] {
    // simple_partitioner with grain 1: every block is a task of its own, so the blocks stay those above
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for(std::size_t b = r.begin(); b != r.end(); ++b)
                          body(blocks.begin(b), blocks.end(b), b);
                      },
                      tbb::simple_partitioner());
  });
#elif defined(CGAL_MDCS_CONCURRENCY_USES_STD_THREADS)
  // threads - 1 workers and the caller take the next block from a counter; the first exception stops the loop
  const std::size_t used = (std::min)(threads, count);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr first;
  std::mutex first_mutex;
  auto work = [&] {
    for(;;) {
      if(failed.load())
        return;
      const std::size_t b = next.fetch_add(1);
      if(b >= count)
        return;
      try {
        body(blocks.begin(b), blocks.end(b), b);
      } catch(...) {
        std::lock_guard<std::mutex> lock(first_mutex);
        if(!first)
          first = std::current_exception();
        failed.store(true);
      }
    }
  };
  std::vector<std::thread> workers;
  workers.reserve(used - 1);
  for(std::size_t t = 1; t < used; ++t)
    workers.emplace_back(work);
  work();
  for(std::thread& t : workers)
    t.join();
  if(first)
    std::rethrow_exception(first);
#endif
}

/*!
  \brief `parallel_for_blocks()` whose error, if any, does not depend on the thread count: when bodies throw, the
  exception of the lowest failing block is rethrown (the one a sequential run meets first). Blocks above a failed
  one may be skipped; blocks below it always run to completion.
*/
template <class Body>
void parallel_for_blocks_lowest_error(std::size_t n, std::size_t block_size, std::size_t threads, Body body)
{
  if(block_size == 0)
    block_size = 1;
  const std::size_t count = internal::Block_partition{n, block_size}.count();
  const std::size_t none = std::size_t(-1);
  std::vector<std::exception_ptr> errors(count);
  std::atomic<std::size_t> lowest{none};
  parallel_for_blocks(n, block_size, threads, [&](std::size_t begin, std::size_t end, std::size_t b) {
    if(b > lowest.load(std::memory_order_relaxed))
      return; // its result would be discarded anyway
    try {
      body(begin, end, b);
    } catch(...) {
      errors[b] = std::current_exception();
      std::size_t seen = lowest.load(std::memory_order_relaxed);
      while(b < seen && !lowest.compare_exchange_weak(seen, b, std::memory_order_relaxed)) {
      }
    }
  });
  const std::size_t b = lowest.load();
  if(b != none)
    std::rethrow_exception(errors[b]);
}

/*!
  \brief An ordered pipeline: `compute(i, slot)` for every `i` in `[0, n)` on at most `threads` threads, then
  `deliver(i, slot)` for `i = 0, 1, 2, ...` in this order, with at most `slots.size()` items computed and not yet
  delivered (item `i` uses `slots[i % slots.size()]`; memory stays bounded however large `n` is).

  Items are taken in increasing order by whichever thread is free (no barrier between groups of items, so uneven
  items do not leave threads idle), and each is computed by `compute` alone: the delivered results do not depend
  on the thread count. `deliver` is never called twice at a time, always in item order, but it may be called from
  any thread of the loop (the one that completes the next item in order). `compute` returns `false` to stop the
  pipeline (cancellation): no further item is taken, the items before the stopping one that were computed are
  delivered. If `compute` or `deliver` throws for item `i`, the items before `i` are delivered, nothing after, and
  the exception of the lowest such item is rethrown (the one a sequential loop meets first).
  \return the number of items delivered.
*/
template <class Slot, class Compute, class Deliver>
std::size_t parallel_ordered_pipeline(std::size_t n, std::size_t threads, std::vector<Slot>& slots, Compute compute,
                                      Deliver deliver)
{
  if(slots.empty())
    throw std::invalid_argument("MDCS: parallel_ordered_pipeline: at least one slot is needed");
  const std::size_t capacity = slots.size();
  if(threads <= 1 || n <= 1 || capacity <= 1 || !has_parallel_support()) {
    for(std::size_t i = 0; i < n; ++i) {
      if(!compute(i, slots[i % capacity]))
        return i;
      deliver(i, slots[i % capacity]);
    }
    return n;
  }
  // Slot states: 0 free (or being computed), 1 ready. `delivered` and the slots' data are handed from the computing
  // thread to the delivering one through `ready` (release / acquire); only the holder of `delivering` delivers.
  std::unique_ptr<std::atomic<char>[]> ready(new std::atomic<char>[capacity]);
  for(std::size_t k = 0; k < capacity; ++k)
    ready[k].store(0);
  std::atomic<std::size_t> next{0}, delivered{0}, limit{n}; // limit: the lowest failed or stopping item
  std::atomic<bool> delivering{false}, stop{false};
  std::mutex error_mutex;
  std::exception_ptr error;
  std::size_t error_item = n;
  const auto fail = [&](std::size_t i, std::exception_ptr e) {
    std::lock_guard<std::mutex> lock(error_mutex);
    if(i < error_item) {
      error_item = i;
      error = e;
    }
    std::size_t seen = limit.load();
    while(i < seen && !limit.compare_exchange_weak(seen, i)) {
    }
    stop.store(true);
  };
  const auto try_deliver = [&] {
    for(;;) {
      if(delivering.exchange(true))
        return; // another thread delivers; it checks again for ready items once it is done
      for(;;) {
        const std::size_t d = delivered.load(std::memory_order_relaxed);
        if(d >= limit.load() || ready[d % capacity].load(std::memory_order_acquire) != 1)
          break;
        try {
          deliver(d, slots[d % capacity]);
        } catch(...) {
          fail(d, std::current_exception());
          break;
        }
        ready[d % capacity].store(0, std::memory_order_relaxed);
        delivered.store(d + 1, std::memory_order_release);
      }
      delivering.store(false);
      const std::size_t d = delivered.load();
      if(d >= limit.load() || ready[d % capacity].load() != 1)
        return;
    }
  };
  const auto claim = [&]() -> std::size_t {
    for(;;) {
      if(stop.load())
        return n;
      std::size_t i = next.load();
      if(i >= n)
        return n;
      if(i >= delivered.load(std::memory_order_acquire) + capacity) {
        try_deliver(); // the slot of item i is still taken: deliver if possible, else wait
        std::this_thread::yield();
        continue;
      }
      if(next.compare_exchange_weak(i, i + 1))
        return i;
    }
  };
  const std::size_t workers = (std::min)(threads, n);
  parallel_for_blocks(workers, 1, workers, [&](std::size_t, std::size_t, std::size_t) {
    for(std::size_t i = claim(); i < n; i = claim()) {
      bool go_on = false;
      try {
        go_on = compute(i, slots[i % capacity]);
      } catch(...) {
        fail(i, std::current_exception());
        continue;
      }
      if(!go_on) {
        // A stop request: item i and later are not delivered, the earlier ones are.
        std::size_t seen = limit.load();
        while(i < seen && !limit.compare_exchange_weak(seen, i)) {
        }
        stop.store(true);
        continue;
      }
      ready[i % capacity].store(1, std::memory_order_release);
      try_deliver();
    }
  });
  try_deliver(); // the items completed last
  if(error)
    std::rethrow_exception(error);
  return delivered.load();
}

/*!
  \brief `parallel_for_blocks()` for many short parallel steps in a row (one call per step, thousands of steps): the
  team keeps its threads' arena between the calls instead of setting it up each time. Same blocks and guarantees as
  `parallel_for_blocks()`: only which thread runs a block depends on the thread count. Not for nested use.
*/
class Parallel_team
{
public:
  /// `threads`: the effective number of threads (see `effective_threads()`).
  explicit Parallel_team(std::size_t threads) : threads_(threads == 0 ? 1 : threads)
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(threads_ > 1) {
      control_.reset(new tbb::global_control(tbb::global_control::max_allowed_parallelism,
                                             (std::max)(threads_, hardware_threads())));
      arena_.reset(new tbb::task_arena(static_cast<int>(threads_)));
    }
#endif
  }

  std::size_t threads() const { return threads_; }

  /// `body(begin, end, block)` for the blocks of `[0, n)` of `block_size` items.
  template <class Body>
  void for_blocks(std::size_t n, std::size_t block_size, Body body)
  {
    if(block_size == 0)
      block_size = 1;
    const internal::Block_partition blocks{n, block_size};
    const std::size_t count = blocks.count();
    if(threads_ <= 1 || count <= 1 || !has_parallel_support()) {
      for(std::size_t b = 0; b < count; ++b)
        body(blocks.begin(b), blocks.end(b), b);
      return;
    }
#ifdef CGAL_LINKED_WITH_TBB
    arena_->execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1),
                        [&](const tbb::blocked_range<std::size_t>& r) {
                          for(std::size_t b = r.begin(); b != r.end(); ++b)
                            body(blocks.begin(b), blocks.end(b), b);
                        },
                        tbb::simple_partitioner());
    });
#else
    parallel_for_blocks(n, block_size, threads_, body);
#endif
  }

private:
  std::size_t threads_;
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::global_control> control_;
  std::unique_ptr<tbb::task_arena> arena_;
#endif
};

/// `parallel_for_blocks()` with one block per item: `body(i)` for every `i` in `[0, n)`.
template <class Body>
void parallel_for_each_index(std::size_t n, std::size_t threads, Body body)
{
  parallel_for_blocks(n, 1, threads, [&](std::size_t begin, std::size_t, std::size_t) { body(begin); });
}

/*!
  \brief One object of type `T` per thread (a solver, a scratch buffer), created on first use by `make()`.

  The objects must not carry results from one block to the next that change what a later block computes;
  they are for workspace only (results go to per-block outputs).
*/
template <class T>
class Per_thread
{
public:
  template <class Make>
  explicit Per_thread(Make make)
#if defined(CGAL_LINKED_WITH_TBB)
    : storage_([make] { return make(); })
#elif defined(CGAL_MDCS_CONCURRENCY_USES_STD_THREADS)
    : make_(make)
#else
    : value_(make())
#endif
  {}

  T& local()
  {
#if defined(CGAL_LINKED_WITH_TBB)
    return storage_.local();
#elif defined(CGAL_MDCS_CONCURRENCY_USES_STD_THREADS)
    const std::thread::id me = std::this_thread::get_id();
    std::lock_guard<std::mutex> lock(mutex_);
    for(auto& o : objects_)
      if(o.first == me)
        return *o.second;
    objects_.emplace_back(me, std::unique_ptr<T>(new T(make_())));
    return *objects_.back().second;
#else
    return value_;
#endif
  }

  /// Calls `f(T&)` for every object created so far (after the parallel loop).
  template <class F>
  void for_each(F f)
  {
#if defined(CGAL_LINKED_WITH_TBB)
    for(T& t : storage_)
      f(t);
#elif defined(CGAL_MDCS_CONCURRENCY_USES_STD_THREADS)
    for(auto& o : objects_)
      f(*o.second);
#else
    f(value_);
#endif
  }

private:
#if defined(CGAL_LINKED_WITH_TBB)
  tbb::enumerable_thread_specific<T> storage_;
#elif defined(CGAL_MDCS_CONCURRENCY_USES_STD_THREADS)
  std::function<T()> make_;
  std::mutex mutex_;
  std::vector<std::pair<std::thread::id, std::unique_ptr<T>>> objects_;
#else
  T value_;
#endif
};

/*!
  \brief Progress and cancellation of a parallel loop: the workers count finished items with `advance()`
  (an atomic counter) and only the thread that created the reporter calls the user's callback, so a callback
  that prints or checks for signals is never called concurrently. When the callback returns `false`, every
  later `advance()` returns `false` (bodies should then return early) and `finish()` throws
  `Operation_cancelled`.
*/
template <class Progress>
class Parallel_progress
{
public:
  Parallel_progress(Progress& progress, const char* stage, std::size_t total)
    : progress_(progress), stage_(stage), total_(total == 0 ? 1 : total), owner_(std::this_thread::get_id())
  {
    step_ = total_ / 100 == 0 ? 1 : total_ / 100;
    next_ = 0;
    report(0);
  }

  /// Counts `k` finished items; returns `false` once the run is cancelled.
  bool advance(std::size_t k = 1)
  {
    const std::size_t done = done_.fetch_add(k, std::memory_order_relaxed) + k;
    if(std::this_thread::get_id() == owner_ && done >= next_) {
      next_ = done + step_;
      report(done);
    }
    return !cancelled_.load(std::memory_order_relaxed);
  }

  bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }

  /// After the loop: reports completion, or throws `Operation_cancelled` if the callback asked to stop.
  void finish()
  {
    if(!cancelled())
      report(total_);
    if(cancelled())
      throw Operation_cancelled(stage_);
  }

private:
  void report(std::size_t done)
  {
    if(cancelled())
      return;
    const double fraction = done >= total_ ? 1.0 : double(done) / double(total_);
    if(!progress_(stage_, fraction))
      cancelled_.store(true, std::memory_order_relaxed);
  }

  Progress& progress_;
  const char* stage_;
  std::size_t total_, step_, next_;
  std::thread::id owner_;
  std::atomic<std::size_t> done_{0};
  std::atomic<bool> cancelled_{false};
};

} // namespace MDCS
} // namespace CGAL

#endif // CGAL_MDCS_CONCURRENCY_H
