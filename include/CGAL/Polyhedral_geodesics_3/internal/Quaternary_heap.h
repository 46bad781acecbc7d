// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The event queue of the exact propagation: a min-heap with four children per node, on entries with a
// `key` member. Compared with a binary heap it has half the depth, and the four children of a node are
// adjacent in memory, so a pop touches about half as many cache lines.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_QUATERNARY_HEAP_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_QUATERNARY_HEAP_H

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

template <class Entry>
class Quaternary_heap
{
public:
  bool empty() const { return data_.empty(); }
  std::size_t size() const { return data_.size(); }
  std::size_t capacity() const { return data_.capacity(); }
  const Entry& top() const { return data_.front(); }
  void clear() { data_.clear(); }
  void release() { std::vector<Entry>().swap(data_); }

  void push(const Entry& x)
  {
    std::size_t i = data_.size();
    data_.push_back(x);
    while(i > 0) {
      const std::size_t parent = (i - 1) / 4;
      if(!(x.key < data_[parent].key))
        break;
      data_[i] = data_[parent];
      i = parent;
    }
    data_[i] = x;
  }

  // Removes and returns the entry with the smallest key.
  Entry pop()
  {
    const Entry result = data_.front();
    const Entry x = data_.back();
    data_.pop_back();
    const std::size_t n = data_.size();
    if(n == 0)
      return result;
    std::size_t i = 0;
    for(;;) {
      const std::size_t first = 4 * i + 1;
      if(first >= n)
        break;
      const std::size_t last = first + 4 < n ? first + 4 : n;
      std::size_t best = first;
      for(std::size_t c = first + 1; c < last; ++c)
        if(data_[c].key < data_[best].key)
          best = c;
      if(!(data_[best].key < x.key))
        break;
      data_[i] = data_[best];
      i = best;
    }
    data_[i] = x;
    return result;
  }

private:
  std::vector<Entry> data_;
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_QUATERNARY_HEAP_H
