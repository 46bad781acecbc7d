// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Many short lists of 32-bit indices in pooled storage: the facet polygons and the cells' facet lists of
// Plane_arrangement_3. While lists change (construction), they live in blocks of large chunks with free lists per
// block capacity (no allocation per list, no doubling copies of one huge array); `compact()` then packs them in
// compressed-row form (one offset per list), and the first change after that unpacks them again.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_POOLED_INDEX_LISTS_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_POOLED_INDEX_LISTS_3_H

#include <CGAL/Variational_minimization/internal/Growable_array_3.h>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

class Pooled_index_lists_3
{
public:
  /// Lists of up to 64 entries get blocks of a multiple of `granularity` entries, longer ones a power of two.
  explicit Pooled_index_lists_3(std::uint32_t granularity = 1) : granularity_(granularity) {}

  std::size_t size() const { return packed() ? offsets_.size() - 1 : heads_.size(); }

  std::size_t size(std::size_t i) const
  {
    return packed() ? std::size_t(offsets_[i + 1] - offsets_[i]) : std::size_t(heads_[i].size);
  }

  const std::uint32_t* begin(std::size_t i) const
  {
    return packed() ? packed_.data() + offsets_[i] : address(heads_[i].offset);
  }
  const std::uint32_t* end(std::size_t i) const { return begin(i) + size(i); }
  std::uint32_t at(std::size_t i, std::size_t k) const { return begin(i)[k]; }

  /// Appends an empty list; returns its index.
  std::size_t add_list()
  {
    unpack();
    heads_.push_back(Head{0, 0});
    return heads_.size() - 1;
  }

  void reserve_lists(std::size_t n)
  {
    if(!packed()) heads_.reserve(n);
  }

  /// Replaces list `i` by [b, e) (which must not point into this storage).
  void assign(std::size_t i, const std::uint32_t* b, const std::uint32_t* e)
  {
    unpack();
    Head& h = heads_[i];
    const std::uint32_t n = checked_size(std::size_t(e - b));
    if(capacity(n) != capacity(h.size)) {
      release(h);
      h.offset = allocate(capacity(n));
    }
    h.size = n;
    std::uint32_t* out = address(h.offset);
    for(std::uint32_t k = 0; k < n; ++k) out[k] = b[k];
  }

  void push_back(std::size_t i, std::uint32_t v)
  {
    unpack();
    Head& h = heads_[i];
    const std::uint32_t n = checked_size(std::size_t(h.size) + 1);
    if(capacity(n) != capacity(h.size)) {
      const std::uint32_t o = allocate(capacity(n));
      const std::uint32_t* from = address(h.offset);
      std::uint32_t* to = address(o);
      for(std::uint32_t k = 0; k < h.size; ++k) to[k] = from[k];
      release(h);
      h.offset = o;
    }
    address(h.offset)[h.size] = v;
    h.size = n;
  }

  /// Packs the lists, in order, into one array of exact size and frees the pool.
  void compact()
  {
    if(packed()) return;
    std::size_t total = 0;
    for(const Head& h : heads_) total += h.size;
    if(total >= std::size_t(0xFFFFFFFFu))
      throw std::invalid_argument("MDCS: Plane_arrangement_3: too many polygon or cell-list entries (32-bit offsets)");
    std::vector<std::uint32_t> offsets;
    offsets.reserve(heads_.size() + 1);
    std::vector<std::uint32_t> packed;
    packed.reserve(total);
    for(const Head& h : heads_) {
      offsets.push_back(std::uint32_t(packed.size()));
      const std::uint32_t* p = address(h.offset);
      packed.insert(packed.end(), p, p + h.size);
    }
    offsets.push_back(std::uint32_t(packed.size()));
    heads_.release();
    std::vector<Growable_array_3<std::uint32_t>>().swap(chunks_);
    std::vector<std::uint32_t>().swap(free_);
    used_ = 0;
    offsets_.swap(offsets);
    packed_.swap(packed);
  }

  std::size_t memory_bytes() const
  {
    return heads_.capacity() * sizeof(Head) + chunks_.size() * chunk_size * 4 + free_.capacity() * 4 +
           offsets_.capacity() * 4 + packed_.capacity() * 4;
  }

private:
  struct Head
  {
    std::uint32_t offset, size;
  };
  // Chunks of 32 MiB: above glibc's largest mmap threshold, so each is mapped on its own and given back to the
  // system when freed (smaller ones would stay as holes in the heap after compact()); pages never touched
  // cost no memory.
  static constexpr std::uint32_t chunk_bits = 23;
  static constexpr std::uint32_t chunk_size = std::uint32_t(1) << chunk_bits;
  static constexpr std::uint32_t none = 0xFFFFFFFFu;

  bool packed() const { return !offsets_.empty(); }

  std::uint32_t* address(std::uint32_t o)
  {
    return chunks_.empty() ? nullptr : chunks_[o >> chunk_bits].data() + (o & (chunk_size - 1));
  }
  const std::uint32_t* address(std::uint32_t o) const
  {
    return chunks_.empty() ? nullptr : chunks_[o >> chunk_bits].data() + (o & (chunk_size - 1));
  }

  static std::uint32_t checked_size(std::size_t n)
  {
    if(n > chunk_size / 2)
      throw std::invalid_argument("MDCS: Plane_arrangement_3: a facet polygon or a cell's facet list is too long");
    return std::uint32_t(n);
  }

  std::uint32_t capacity(std::uint32_t n) const
  {
    if(n == 0) return 0;
    if(n <= 64) return (n + granularity_ - 1) / granularity_ * granularity_;
    std::uint32_t c = 128;
    while(c < n) c *= 2;
    return c;
  }

  // Free lists: capacities up to 64 by value, longer ones by their logarithm.
  static std::size_t free_slot(std::uint32_t cap)
  {
    if(cap <= 64) return cap;
    std::size_t s = 64;
    while((std::uint32_t(1) << (s - 64 + 7)) < cap) ++s;
    return s + 1;
  }

  std::uint32_t allocate(std::uint32_t cap)
  {
    if(cap == 0) return 0;
    const std::size_t s = free_slot(cap);
    if(s < free_.size() && free_[s] != none) {
      const std::uint32_t o = free_[s];
      free_[s] = *address(o);
      return o;
    }
    std::size_t start = used_;
    if((start & (chunk_size - 1)) + cap > chunk_size) start = ((start >> chunk_bits) + 1) << chunk_bits;
    if(start + cap >= std::size_t(none))
      throw std::invalid_argument("MDCS: Plane_arrangement_3: too many polygon or cell-list entries (32-bit offsets)");
    while((start >> chunk_bits) >= chunks_.size()) {
      chunks_.emplace_back();
      chunks_.back().resize_uninitialized(chunk_size);
    }
    used_ = start + cap;
    return std::uint32_t(start);
  }

  void release(const Head& h)
  {
    const std::uint32_t cap = capacity(h.size);
    if(cap == 0) return;
    const std::size_t s = free_slot(cap);
    if(s >= free_.size()) free_.resize(s + 1, none);
    *address(h.offset) = free_[s];
    free_[s] = h.offset;
  }

  void unpack()
  {
    if(!packed()) return;
    std::vector<std::uint32_t> offsets, packed;
    offsets.swap(offsets_);
    packed.swap(packed_);
    heads_.assign(offsets.size() - 1, Head{0, 0});
    for(std::size_t i = 0; i + 1 < offsets.size(); ++i)
      assign(i, packed.data() + offsets[i], packed.data() + offsets[i + 1]);
  }

  std::uint32_t granularity_;
  // Unpacked form.
  Growable_array_3<Head> heads_;
  std::vector<Growable_array_3<std::uint32_t>> chunks_;
  std::vector<std::uint32_t> free_;
  std::size_t used_ = 0;
  // Packed form (compressed rows): list i is packed_[offsets_[i], offsets_[i + 1]).
  std::vector<std::uint32_t> offsets_;
  std::vector<std::uint32_t> packed_;
};

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_POOLED_INDEX_LISTS_3_H
