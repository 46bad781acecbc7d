// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Storage of the windows of the exact propagation: an indexed sequence in fixed-size blocks. Unlike a
// std::vector it never moves its elements when it grows (a vector of millions of windows spends a large
// part of the propagation copying itself and faulting in the fresh pages of every reallocation, and needs
// the old and the new buffer at the same time at each growth), and indices stay valid.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_WINDOW_STORE_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_WINDOW_STORE_H

#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

template <class T>
class Window_store
{
  static constexpr std::size_t block_shift = 14; // 16384 elements per block
  static constexpr std::size_t block_size = std::size_t(1) << block_shift;
  static constexpr std::size_t block_mask = block_size - 1;

public:
  T& operator[](std::size_t i) { return blocks_[i >> block_shift][i & block_mask]; }
  const T& operator[](std::size_t i) const { return blocks_[i >> block_shift][i & block_mask]; }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  // The number of elements the allocated blocks hold.
  std::size_t capacity() const { return blocks_.size() * block_size; }

  // Appends a default-constructed element and returns its index.
  std::size_t emplace_back()
  {
    if(size_ == capacity())
      blocks_.emplace_back(new T[block_size]);
    T& slot = (*this)[size_];
    slot = T();
    return size_++;
  }

  // Forgets the elements, keeps the memory for reuse.
  void clear() { size_ = 0; }

  // Forgets the elements and frees the memory.
  void release()
  {
    std::vector<std::unique_ptr<T[]>>().swap(blocks_);
    size_ = 0;
  }

private:
  std::vector<std::unique_ptr<T[]>> blocks_;
  std::size_t size_ = 0;
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_WINDOW_STORE_H
