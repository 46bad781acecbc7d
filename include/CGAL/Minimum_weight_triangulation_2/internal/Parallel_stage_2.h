// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How the stages of the MWT pipeline run their loops in parallel, on the shared helper CGAL/MDCS/concurrency.h:
// a thread count, the time spent inside parallel loops (the rest of a stage is serial: the benchmark derives
// the serial fractions of an Amdahl projection from it), blocks whose outputs are appended in block order,
// and progress/cancellation from the calling thread only (CGAL::MDCS::Parallel_progress: the workers count
// finished items, a body returns early once the run is cancelled, and finish() throws after the loop).
//
// Every loop cuts its range into blocks that depend on the input size alone (never on the thread count), and
// every output is written per block and joined in block order, so the stages give bit-identical results for
// every thread count, including one.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_PARALLEL_STAGE_2_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_PARALLEL_STAGE_2_H

#include <CGAL/MDCS/concurrency.h>
#include <CGAL/MDCS/progress.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <ctime>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {
namespace internal {

/// Seconds of the stage clock: processor time of the process with MDCS_MWT_CPU_TIMERS (benchmarks on a shared
/// machine; summed over the threads), wall-clock time otherwise.
inline double stage_clock_seconds()
{
#if defined(MDCS_MWT_CPU_TIMERS)
  return double(std::clock()) / CLOCKS_PER_SEC;
#else
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
#endif
}

/*!
  An allocator whose `resize()` leaves new elements of trivial types uninitialised. The large arrays of the
  pipeline (hundreds of bytes per point) are then first written, and their pages first touched (and zeroed by
  the kernel), inside parallel loops instead of by a serial value-initialisation in the calling thread.
*/
template <class T>
struct Default_init_allocator : std::allocator<T>
{
  template <class U>
  struct rebind { typedef Default_init_allocator<U> other; };
  Default_init_allocator() = default;
  template <class U>
  Default_init_allocator(const Default_init_allocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value)
  {
    ::new(static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args)
  {
    ::new(static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

/// A vector whose resize() does not initialise (see Default_init_allocator).
template <class T>
using Uninit_vector = std::vector<T, Default_init_allocator<T>>;

/*!
  The thread count of a run and the clock of its parallel loops. `loop_time`, when given, receives the
  stage-clock seconds spent inside parallel loops (measured on the calling thread, so at one thread the
  stage's time minus this is its serial part).
*/
class Parallel_stage
{
public:
  explicit Parallel_stage(std::size_t threads = 1, double* loop_time = nullptr)
    : threads_(threads == 0 ? 1 : threads), loop_time_(loop_time)
  {}

  std::size_t threads() const { return threads_; }
  bool parallel() const { return threads_ > 1; }
  /// The same thread count, timing into another accumulator (one per stage).
  Parallel_stage timed(double* loop_time) const { return Parallel_stage(threads_, loop_time); }

  /// body(begin, end, block) over the blocks of [0, n) of `block` items (see CGAL::MDCS::parallel_for_blocks).
  template <class Body>
  void for_blocks(std::size_t n, std::size_t block, Body body) const
  {
    const double t0 = loop_time_ ? stage_clock_seconds() : 0;
    CGAL::MDCS::parallel_for_blocks(n, block, threads_, body);
    if(loop_time_)
      *loop_time_ += stage_clock_seconds() - t0;
  }

  /*!
    produce(begin, end, out) appends the results of the items [begin, end) to `out` (a vector of its own per
    block); the blocks' vectors are appended to `result` in block order, a window of blocks at a time so that
    the blocks' copies never hold more than one window (the outputs can be gigabytes: the empty triangles),
    each block copying its own part in parallel (with an Uninit_vector result, nothing is written serially).
    The result is the sequential loop's for every thread count. Reserve `result` beforehand when its size is
    known roughly (growing it copies it).
  */
  template <class T, class Alloc, class Produce>
  void append_in_order(std::size_t n, std::size_t block, std::vector<T, Alloc>& result, Produce produce) const
  {
    if(block == 0)
      block = 1;
    const std::size_t blocks = (n + block - 1) / block;
    if(!parallel()) {
      // one thread: straight into the result (no copies); same items in the same order
      const double t0 = loop_time_ ? stage_clock_seconds() : 0;
      for(std::size_t b = 0; b < blocks; ++b)
        produce(b * block, (std::min)(n, (b + 1) * block), result);
      if(loop_time_)
        *loop_time_ += stage_clock_seconds() - t0;
      return;
    }
    const std::size_t window = (std::max)(std::size_t(256), 16 * threads_);
    std::vector<std::vector<T, Alloc>> out;
    std::vector<std::size_t> offset;
    for(std::size_t w0 = 0; w0 < blocks; w0 += window) {
      const std::size_t w1 = (std::min)(blocks, w0 + window);
      out.assign(w1 - w0, std::vector<T, Alloc>());
      for_blocks((w1 - w0) * block, block, [&](std::size_t, std::size_t, std::size_t k) {
        const std::size_t b = w0 + k;
        produce(b * block, (std::min)(n, (b + 1) * block), out[k]);
      });
      offset.assign(out.size() + 1, result.size());
      for(std::size_t k = 0; k < out.size(); ++k) offset[k + 1] = offset[k] + out[k].size();
      result.resize(offset.back());
      for_blocks(out.size(), 1, [&](std::size_t k, std::size_t, std::size_t) {
        std::copy(out[k].begin(), out[k].end(), result.begin() + std::ptrdiff_t(offset[k]));
        std::vector<T, Alloc>().swap(out[k]);
      });
    }
  }

private:
  std::size_t threads_;
  double* loop_time_;
};

/*!
  Sorts `v` stably by `less` (the result is the unique stable order, the same for every thread count): blocks
  sorted in parallel, then merged pairwise in rounds, the pairs of a round in parallel.
*/
template <class T, class Less>
void parallel_stable_sort(std::vector<T>& v, Less less, const Parallel_stage& par)
{
  const std::size_t n = v.size(), block = 1 << 15;
  if(n <= block) {
    std::stable_sort(v.begin(), v.end(), less);
    return;
  }
  par.for_blocks(n, block, [&](std::size_t b0, std::size_t b1, std::size_t) {
    std::stable_sort(v.begin() + std::ptrdiff_t(b0), v.begin() + std::ptrdiff_t(b1), less);
  });
  std::vector<T> buffer(n);
  // (the merges count as serial work in the statistics: the last rounds have few pairs)
  const Parallel_stage merges = par.timed(nullptr);
  for(std::size_t run = block; run < n; run *= 2) {
    // merge the runs [k 2 run, k 2 run + run) and [k 2 run + run, (k + 1) 2 run)
    merges.for_blocks(n, 2 * run, [&](std::size_t b0, std::size_t b1, std::size_t) {
      const std::size_t mid = (std::min)(b0 + run, b1);
      std::merge(v.begin() + std::ptrdiff_t(b0), v.begin() + std::ptrdiff_t(mid), v.begin() + std::ptrdiff_t(mid),
                 v.begin() + std::ptrdiff_t(b1), buffer.begin() + std::ptrdiff_t(b0), less);
    });
    v.swap(buffer);
  }
}

/// `n` atomic counters set to zero in parallel (their pages first touched by the workers).
template <class Count>
std::unique_ptr<std::atomic<Count>[]> zeroed_counters(std::size_t n, const Parallel_stage& par)
{
  std::unique_ptr<std::atomic<Count>[]> c(new std::atomic<Count>[n]);
  par.for_blocks(n, 1 << 16, [&](std::size_t k0, std::size_t k1, std::size_t) {
    for(std::size_t k = k0; k < k1; ++k) c[k].store(0, std::memory_order_relaxed);
  });
  return c;
}

/*!
  Rows of integers, e.g. the neighbours of every vertex: `emit(k, add)` calls `add(row, value)` for the items of
  input k in [0, count) (it is called twice per k: to count, then to place). Every row comes out sorted, and
  without repeated values with `unique`; `start` has `rows + 1` offsets into `values`. Atomic counters, then a
  sort per row: the same arrays for every thread count.
*/
template <class Emit, class Values>
void build_sorted_rows(std::size_t rows, std::size_t count, Emit emit, bool unique, std::vector<std::size_t>& start,
                       Values& values, const Parallel_stage& par)
{
  const std::size_t item_block = 1 << 14, row_block = 1 << 14;
  const std::unique_ptr<std::atomic<std::size_t>[]> cursor = zeroed_counters<std::size_t>(rows, par);
  par.for_blocks(count, item_block, [&](std::size_t k0, std::size_t k1, std::size_t) {
    for(std::size_t k = k0; k < k1; ++k)
      emit(k, [&](int row, int) { cursor[std::size_t(row)].fetch_add(1, std::memory_order_relaxed); });
  });
  start.assign(rows + 1, 0);
  for(std::size_t r = 0; r < rows; ++r) {
    start[r + 1] = start[r] + cursor[r].load(std::memory_order_relaxed);
    cursor[r].store(0, std::memory_order_relaxed);
  }
  values.resize(start[rows]);
  par.for_blocks(count, item_block, [&](std::size_t k0, std::size_t k1, std::size_t) {
    for(std::size_t k = k0; k < k1; ++k)
      emit(k, [&](int row, int value) {
        values[start[std::size_t(row)] + cursor[std::size_t(row)].fetch_add(1, std::memory_order_relaxed)] = value;
      });
  });
  std::vector<std::size_t> kept(unique ? rows : 0);
  par.for_blocks(rows, row_block, [&](std::size_t r0, std::size_t r1, std::size_t) {
    for(std::size_t r = r0; r < r1; ++r) {
      const auto b = values.begin() + std::ptrdiff_t(start[r]), e = values.begin() + std::ptrdiff_t(start[r + 1]);
      std::sort(b, e);
      if(unique) kept[r] = std::size_t(std::unique(b, e) - b);
    }
  });
  if(!unique) return;
  std::vector<std::size_t> new_start(rows + 1, 0);
  for(std::size_t r = 0; r < rows; ++r) new_start[r + 1] = new_start[r] + kept[r];
  Values new_values(new_start[rows]);
  par.for_blocks(rows, row_block, [&](std::size_t r0, std::size_t r1, std::size_t) {
    for(std::size_t r = r0; r < r1; ++r)
      std::copy(values.begin() + std::ptrdiff_t(start[r]), values.begin() + std::ptrdiff_t(start[r] + kept[r]),
                new_values.begin() + std::ptrdiff_t(new_start[r]));
  });
  start.swap(new_start);
  values.swap(new_values);
}

} // namespace internal
} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_PARALLEL_STAGE_2_H
