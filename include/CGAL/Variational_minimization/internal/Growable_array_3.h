// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A minimal vector of trivially copyable elements that grows without copying. The arrays of Plane_arrangement_3
// reach hundreds of megabytes; std::vector grows by allocating a new block and copying, so for a moment the old
// and the new block are both resident (3 times the data with doubling), and blocks below the allocator's mmap
// threshold (up to 32 MiB with glibc, once a process has freed large blocks) leave holes in the heap. On Linux,
// blocks of 1 MiB and more are mapped directly and grown with mremap() (the pages move, nothing is copied, and
// freeing gives them back); elsewhere, and for small blocks, realloc().
#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_GROWABLE_ARRAY_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_GROWABLE_ARRAY_3_H

#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace CGAL {
namespace Variational_minimization {
namespace internal {

template <class T>
class Growable_array_3
{
  static_assert(std::is_trivially_copyable<T>::value, "Growable_array_3 holds trivially copyable types only");

public:
  typedef T value_type;

  Growable_array_3() = default;
  Growable_array_3(const Growable_array_3& o) { copy_from(o); }
  Growable_array_3(Growable_array_3&& o) noexcept { swap(o); }
  Growable_array_3& operator=(const Growable_array_3& o)
  {
    if(this != &o) {
      Growable_array_3 t(o);
      swap(t);
    }
    return *this;
  }
  Growable_array_3& operator=(Growable_array_3&& o) noexcept
  {
    if(this != &o) {
      release();
      swap(o);
    }
    return *this;
  }
  ~Growable_array_3() { deallocate(); }

  void swap(Growable_array_3& o) noexcept
  {
    std::swap(data_, o.data_);
    std::swap(size_, o.size_);
    std::swap(capacity_, o.capacity_);
    std::swap(mapped_bytes_, o.mapped_bytes_);
  }

  std::size_t size() const { return size_; }
  std::size_t capacity() const { return capacity_; }
  bool empty() const { return size_ == 0; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  T& back() { return data_[size_ - 1]; }

  void push_back(const T& x)
  {
    if(size_ == capacity_) {
      const T copy = x; // x may live in this array
      grow_to(capacity_ < 16 ? 16 : 2 * capacity_);
      data_[size_++] = copy;
    } else
      data_[size_++] = x;
  }
  void emplace_back() { push_back(T()); }

  void reserve(std::size_t n)
  {
    if(n > capacity_) grow_to(n);
  }
  void resize(std::size_t n, const T& value = T())
  {
    reserve(n);
    for(std::size_t i = size_; i < n; ++i) data_[i] = value;
    size_ = n;
  }
  /// Resizes without writing the new elements (their pages stay untouched, hence cost no memory, until written).
  void resize_uninitialized(std::size_t n)
  {
    reserve(n);
    size_ = n;
  }
  void assign(std::size_t n, const T& value)
  {
    size_ = 0;
    resize(n, value);
  }
  void clear() { size_ = 0; }
  void shrink_to_fit()
  {
    if(size_ == capacity_) return;
    if(size_ == 0) {
      release();
      return;
    }
    grow_to(size_);
  }
  /// Frees the storage.
  void release()
  {
    deallocate();
    data_ = nullptr;
    size_ = capacity_ = 0;
  }

private:
  static constexpr std::size_t map_threshold = std::size_t(1) << 20;
  static constexpr std::size_t page = 4096;

  void deallocate()
  {
#if defined(__linux__)
    if(mapped_bytes_ != 0) {
      ::munmap(static_cast<void*>(data_), mapped_bytes_);
      mapped_bytes_ = 0;
      return;
    }
#endif
    std::free(data_);
  }

  void grow_to(std::size_t n)
  {
    const std::size_t bytes = n * sizeof(T);
#if defined(__linux__)
    if(bytes >= map_threshold || mapped_bytes_ != 0) {
      const std::size_t rounded = (bytes + page - 1) / page * page;
      void* p = nullptr;
      if(mapped_bytes_ != 0)
        p = ::mremap(static_cast<void*>(data_), mapped_bytes_, rounded, MREMAP_MAYMOVE);
      else {
        p = ::mmap(nullptr, rounded, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if(p != MAP_FAILED && size_ > 0)
          std::memcpy(p, static_cast<const void*>(data_), size_ * sizeof(T));
        if(p != MAP_FAILED) std::free(data_);
      }
      if(p == MAP_FAILED) throw std::bad_alloc();
      data_ = static_cast<T*>(p);
      mapped_bytes_ = rounded;
      capacity_ = rounded / sizeof(T);
      return;
    }
#endif
    void* p = std::realloc(static_cast<void*>(data_), bytes);
    if(p == nullptr) throw std::bad_alloc();
    data_ = static_cast<T*>(p);
    capacity_ = n;
  }

  void copy_from(const Growable_array_3& o)
  {
    if(o.size_ == 0) return;
    grow_to(o.size_);
    std::memcpy(static_cast<void*>(data_), static_cast<const void*>(o.data_), o.size_ * sizeof(T));
    size_ = o.size_;
  }

  T* data_ = nullptr;
  std::size_t size_ = 0, capacity_ = 0;
  std::size_t mapped_bytes_ = 0; // > 0: data_ is a mapping of that many bytes
};

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_GROWABLE_ARRAY_3_H
