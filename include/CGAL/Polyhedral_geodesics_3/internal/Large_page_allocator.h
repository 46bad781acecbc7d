// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// An allocator for the large per-halfedge and per-vertex arrays of the geodesic engines. On Linux, blocks of at
// least `large_block_bytes` are aligned to 2 MiB and advised as transparent huge pages (madvise MADV_HUGEPAGE),
// so that filling a fresh array costs one page fault per 2 MiB instead of one per 4 KiB. On the project's
// virtual machines a 4 KiB page fault costs about 12 microseconds (36 ms for 12 MiB, 1 to 18 ms with huge
// pages), which was half the construction time of the compact mesh at 44k vertices. Elsewhere, or for small
// blocks, or when the kernel refuses, it behaves as std::allocator (the advice is only a hint).

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_LARGE_PAGE_ALLOCATOR_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_LARGE_PAGE_ALLOCATOR_H

#include <cstddef>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

template <class T>
struct Large_page_allocator
{
  typedef T value_type;

  static constexpr std::size_t huge_page_bytes = std::size_t(2) << 20;
  static constexpr std::size_t large_block_bytes = std::size_t(1) << 20;

  Large_page_allocator() noexcept {}
  template <class U>
  Large_page_allocator(const Large_page_allocator<U>&) noexcept {}

  T* allocate(std::size_t n)
  {
    if(n > std::size_t(-1) / sizeof(T))
      throw std::bad_alloc();
    const std::size_t bytes = n * sizeof(T);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if(bytes >= large_block_bytes) {
      const std::size_t rounded = (bytes + huge_page_bytes - 1) / huge_page_bytes * huge_page_bytes;
      void* p = nullptr;
      if(posix_memalign(&p, huge_page_bytes, rounded) != 0 || p == nullptr)
        throw std::bad_alloc();
      madvise(p, rounded, MADV_HUGEPAGE); // a hint: failure leaves ordinary pages
      return static_cast<T*>(p);
    }
#endif
    void* p = std::malloc(bytes == 0 ? 1 : bytes);
    if(p == nullptr)
      throw std::bad_alloc();
    return static_cast<T*>(p);
  }

  void deallocate(T* p, std::size_t) noexcept { std::free(p); }
};

template <class T, class U>
bool operator==(const Large_page_allocator<T>&, const Large_page_allocator<U>&) noexcept { return true; }
template <class T, class U>
bool operator!=(const Large_page_allocator<T>&, const Large_page_allocator<U>&) noexcept { return false; }

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_LARGE_PAGE_ALLOCATOR_H
