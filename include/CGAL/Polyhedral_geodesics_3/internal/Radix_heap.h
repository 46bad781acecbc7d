// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The event queue of the exact propagation with double keys: a radix heap (Ahuja, Mehlhorn, Orlin and Tarjan),
// a monotone priority queue. The propagation only pushes keys at or above the key last popped (a window's
// children and lobes are never nearer than the window; a vertex is reached through a window), so the queue can
// bucket entries by the highest bit in which their key differs from the last popped one: a push appends to a
// bucket, and a pop only scans and redistributes the lowest non-empty bucket, each entry moving down at most
// 64 times in all. Compared with a 4-ary heap over the same entries, a pop no longer sifts through the heap's
// levels with unpredictable comparisons, and the buckets are read and written sequentially.
//
// Keys are non-negative doubles, whose IEEE bit patterns order like the numbers. A key below the last popped one
// (rounding can make a child a few ulps nearer than its parent) is queued as if equal to it: it comes out next,
// as it should. Entries with equal keys come out in no particular order, as in any heap.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_RADIX_HEAP_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_RADIX_HEAP_H

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

template <class Entry>
class Radix_heap
{
public:
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }

  std::size_t capacity() const
  {
    std::size_t c = 0;
    for(const auto& b : buckets_) c += b.capacity();
    return c;
  }

  void clear()
  {
    for(auto& b : buckets_) b.clear();
    head_ = 0;
    size_ = 0;
    last_ = 0;
  }

  void release()
  {
    for(auto& b : buckets_) std::vector<Entry>().swap(b);
    head_ = 0;
    size_ = 0;
    last_ = 0;
  }

  void push(const Entry& x)
  {
    const std::uint64_t k = bits(x.key);
    // A clamped key equals last_: the entry goes to bucket 0 and is never redistributed, so the buckets above 0
    // hold only entries whose own key is their bucket's key.
    buckets_[k < last_ ? 0 : bucket(k)].push_back(x);
    ++size_;
  }

  // Removes and returns an entry with the smallest key (precondition: not empty).
  Entry pop()
  {
    if(head_ == buckets_[0].size()) {
      buckets_[0].clear();
      head_ = 0;
      std::size_t i = 1;
      while(buckets_[i].empty()) ++i;
      std::vector<Entry>& b = buckets_[i];
      std::uint64_t m = bits(b.front().key);
      for(const Entry& x : b) {
        const std::uint64_t k = bits(x.key);
        if(k < m) m = k;
      }
      last_ = m;
      // Every entry of bucket i agrees with the new minimum above bit i - 1, so each lands in a lower bucket.
      for(const Entry& x : b) buckets_[bucket(bits(x.key))].push_back(x);
      b.clear();
    }
    // First in, first out among equal keys: a window comes out before the children it had time to make.
    const Entry e = buckets_[0][head_++];
    --size_;
    return e;
  }

private:
  static std::uint64_t bits(double key)
  {
    if(!(key > 0)) return 0; // 0, -0 (and, defensively, NaN) first
    std::uint64_t u;
    std::memcpy(&u, &key, sizeof u);
    return u;
  }

  // 0 for k == last_, else 1 + the index of the highest bit where k and last_ differ.
  std::size_t bucket(std::uint64_t k) const
  {
    const std::uint64_t x = k ^ last_;
    if(x == 0) return 0;
#if defined(__GNUC__) || defined(__clang__)
    return std::size_t(64 - __builtin_clzll(x));
#else
    std::size_t n = 0;
    for(std::uint64_t y = x; y != 0; y >>= 1) ++n;
    return n;
#endif
  }

  std::array<std::vector<Entry>, 65> buckets_;
  std::uint64_t last_ = 0;
  std::size_t head_ = 0; // entries of bucket 0 before head_ are popped
  std::size_t size_ = 0;
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_RADIX_HEAP_H
