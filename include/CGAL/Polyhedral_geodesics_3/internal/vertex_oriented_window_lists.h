// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The windows waiting on the halfedges in the vertex-oriented schedule (vertex_oriented_propagation.h), stored in
// chunks of a few windows.
//
// Why chunks. A window waits on its halfedge from the moment its parent crosses the face behind it until the front
// reaches that halfedge; meanwhile the whole front is processed, so by the time the list is read its windows have
// left the processor's caches. With one window per slot and a linked list (the earlier layout), reading a list
// cost two dependent cache misses per window (the link, then the window): measured with perf on armadillo Loop x2
// (416k vertices), 44% of the batch processing stalled on these two loads, and the cost per window rose from 0.18
// to 0.27 microseconds between 150k and 600k vertices as the waiting windows outgrew the caches. Here a list is a
// stack of chunks of `capacity` windows, contiguous and aligned to cache lines; the links between chunks live in a
// small array of their own, so the whole chain of a list can be prefetched as soon as the list is known to be
// processed soon (prefetch()).

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_WINDOW_LISTS_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_WINDOW_LISTS_H

#include <CGAL/Polyhedral_geodesics_3/internal/Large_page_allocator.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

// A window of the vertex-oriented schedule, in the frame of the halfedge g it waits on: the interval [b0, b1] of
// g's edge (source(g) at 0, target(g) at L) and its pseudo-source (sx, sy), below the edge (g's face is above).
// `root` is the pseudo-source as a mesh element: a vertex (>= 0) or the point source number k inside a face
// (-1 - k). The nearest source of the window's points is the root's (vertex_source of the root vertex). `lobe`:
// emitted by a vertex where no shortest path bends, or a descendant of one (see merging).
template <class FT>
struct Vertex_oriented_window
{
  FT b0, b1, sx, sy, sigma;
  std::int32_t root;
  std::int32_t lobe;
};

template <class Window>
class Window_chunk_lists
{
public:
  typedef std::int32_t Index;
  // 5 windows of 48 bytes (FT = double) fill 4 cache lines.
  static constexpr int capacity = sizeof(Window) <= 48 ? 5 : 4;

  void reset(std::size_t halfedges)
  {
    head_.assign(halfedges, -1);
    chunk_next_.clear();
    chunk_count_.clear();
    free_.clear();
    blocks_.clear();
    live_chunks_ = 0;
    peak_chunks_ = 0;
  }

  // Empties the lists of `halfedges` (every list that may hold windows) and frees every chunk, keeping the blocks
  // and the arrays allocated: the next run costs what it touches, not the number of halfedges (reused engines).
  void clear_lists(const std::vector<Index>& halfedges)
  {
    for(Index g : halfedges)
      head_[std::size_t(g)] = -1;
    chunk_next_.clear();
    chunk_count_.clear();
    free_.clear();
    live_chunks_ = 0;
  }

  void release()
  {
    std::vector<Index>().swap(head_);
    std::vector<Index>().swap(chunk_next_);
    std::vector<std::uint8_t>().swap(chunk_count_);
    std::vector<Index>().swap(free_);
    blocks_.clear();
  }

  bool empty(Index g) const { return head_[std::size_t(g)] < 0; }

  void push(Index g, const Window& w)
  {
    Index c = head_[std::size_t(g)];
    if(c < 0 || chunk_count_[std::size_t(c)] == capacity) {
      const Index n = allocate_chunk();
      chunk_next_[std::size_t(n)] = c;
      head_[std::size_t(g)] = n;
      c = n;
    }
    std::uint8_t& count = chunk_count_[std::size_t(c)];
    chunk(c).w[count] = w;
    ++count;
  }

  // Moves the windows of list g to the end of `out` (the newest chunk first, each chunk in the order of its
  // pushes) and empties the list; its chunks are reused at once, while still in cache.
  template <class Vector>
  void take(Index g, Vector& out)
  {
    Index c = head_[std::size_t(g)];
    head_[std::size_t(g)] = -1;
    while(c >= 0) {
      const Chunk& ch = chunk(c);
      const int n = chunk_count_[std::size_t(c)];
      for(int k = 0; k < n; ++k)
        out.push_back(ch.w[k]);
      const Index next = chunk_next_[std::size_t(c)];
      free_chunk(c);
      c = next;
    }
  }

  // take() for the parallel schedule (vertex_oriented_parallel.h): several lists are taken at the same time, so
  // their chunks are not freed here but appended to `taken` (free_chunks() frees them afterwards, in a fixed order).
  // Reads the chunks and writes head_[g] only: takes of distinct lists may run concurrently.
  template <class Vector>
  void take_deferred(Index g, Vector& out, std::vector<Index>& taken)
  {
    Index c = head_[std::size_t(g)];
    head_[std::size_t(g)] = -1;
    while(c >= 0) {
      const Chunk& ch = chunk(c);
      const int n = chunk_count_[std::size_t(c)];
      for(int k = 0; k < n; ++k)
        out.push_back(ch.w[k]);
      taken.push_back(c);
      c = chunk_next_[std::size_t(c)];
    }
  }

  void free_chunks(const std::vector<Index>& taken)
  {
    for(Index c : taken)
      free_chunk(c);
  }

  // Asks the processor to load the windows of list g (a hint; nothing happens without GCC or Clang).
  void prefetch(Index g) const
  {
#if defined(__GNUC__)
    for(Index c = head_[std::size_t(g)]; c >= 0; c = chunk_next_[std::size_t(c)]) {
      const char* p = reinterpret_cast<const char*>(&chunk(c));
      for(std::size_t line = 0; line < sizeof(Chunk); line += 64)
        __builtin_prefetch(p + line);
    }
#else
    (void)g;
#endif
  }

  // Pushes from several threads at once (the parallel schedule's merge): reserve() hands out `count` chunk ids to a
  // stream (sequentially, before the streams run); push_reserved() then allocates from them only, so that streams
  // pushing onto disjoint sets of lists write disjoint memory; release_reserved() returns the unused ids and counts
  // the used ones (sequentially, after the streams, in a fixed order).
  void reserve(std::size_t count, std::vector<Index>& ids)
  {
    ids.clear();
    while(ids.size() < count && !free_.empty()) {
      ids.push_back(free_.back());
      free_.pop_back();
    }
    while(ids.size() < count) {
      const Index c = Index(chunk_next_.size());
      if(std::size_t(c) / block_chunks >= blocks_.size())
        blocks_.emplace_back(new_block());
      chunk_next_.push_back(-1);
      chunk_count_.push_back(0);
      ids.push_back(c);
    }
    std::reverse(ids.begin(), ids.end()); // push_reserved() takes them from the back: in the order reserved
  }

  void push_reserved(Index g, const Window& w, std::vector<Index>& ids)
  {
    Index c = head_[std::size_t(g)];
    if(c < 0 || chunk_count_[std::size_t(c)] == capacity) {
      const Index n = ids.back();
      ids.pop_back();
      chunk_count_[std::size_t(n)] = 0;
      chunk_next_[std::size_t(n)] = c;
      head_[std::size_t(g)] = n;
      c = n;
    }
    std::uint8_t& count = chunk_count_[std::size_t(c)];
    chunk(c).w[count] = w;
    ++count;
  }

  void release_reserved(std::size_t reserved, std::vector<Index>& ids)
  {
    live_chunks_ += reserved - ids.size();
    if(live_chunks_ > peak_chunks_)
      peak_chunks_ = live_chunks_;
    while(!ids.empty()) {
      free_.push_back(ids.back());
      ids.pop_back();
    }
  }

  // Hints for a push() onto list g soon (the parallel schedule's merge): first its head, then (once the head is
  // loaded) its newest chunk.
  void prefetch_head(Index g) const
  {
#if defined(__GNUC__)
    __builtin_prefetch(&head_[std::size_t(g)], 1);
#else
    (void)g;
#endif
  }
  void prefetch_newest_chunk(Index g) const
  {
#if defined(__GNUC__)
    const Index c = head_[std::size_t(g)];
    if(c >= 0) {
      __builtin_prefetch(&chunk_count_[std::size_t(c)], 1);
      const char* p = reinterpret_cast<const char*>(&chunk(c));
      for(std::size_t line = 0; line < sizeof(Chunk); line += 64)
        __builtin_prefetch(p + line, 1);
    }
#else
    (void)g;
#endif
  }

  std::size_t memory_bytes() const
  {
    return blocks_.size() * block_chunks * sizeof(Chunk) + head_.capacity() * sizeof(Index) +
           chunk_next_.capacity() * (sizeof(Index) + 1) + free_.capacity() * sizeof(Index);
  }

  std::size_t peak_chunks() const { return peak_chunks_; }

private:
  struct alignas(64) Chunk
  {
    Window w[capacity];
  };
  // Chunks live in blocks that never move (2 MiB with FT = double: huge pages, aligned to cache lines).
  static constexpr std::size_t block_chunks = (std::size_t(2) << 20) / sizeof(Chunk);

  // The chunks of a block are constructed and destroyed with it (a no-op with FT = double; needed for number
  // types with a constructor, such as the multiprecision ones).
  struct Block_deleter
  {
    void operator()(Chunk* p) const
    {
      for(std::size_t i = 0; i < block_chunks; ++i)
        p[i].~Chunk();
      Large_page_allocator<Chunk>().deallocate(p, block_chunks);
    }
  };

  static Chunk* new_block()
  {
    Chunk* p = Large_page_allocator<Chunk>().allocate(block_chunks);
    for(std::size_t i = 0; i < block_chunks; ++i)
      ::new(static_cast<void*>(p + i)) Chunk();
    return p;
  }

  Chunk& chunk(Index c) { return blocks_[std::size_t(c) / block_chunks].get()[std::size_t(c) % block_chunks]; }
  const Chunk& chunk(Index c) const
  {
    return blocks_[std::size_t(c) / block_chunks].get()[std::size_t(c) % block_chunks];
  }

  Index allocate_chunk()
  {
    Index c;
    if(!free_.empty()) {
      c = free_.back();
      free_.pop_back();
    } else {
      c = Index(chunk_next_.size());
      if(std::size_t(c) / block_chunks >= blocks_.size()) // the blocks kept by clear_lists() are reused
        blocks_.emplace_back(new_block());
      chunk_next_.push_back(-1);
      chunk_count_.push_back(0);
    }
    chunk_count_[std::size_t(c)] = 0;
    if(++live_chunks_ > peak_chunks_)
      peak_chunks_ = live_chunks_;
    return c;
  }

  void free_chunk(Index c)
  {
    free_.push_back(c);
    --live_chunks_;
  }

  std::vector<Index> head_;                 // per halfedge: its newest chunk, -1 if the list is empty
  std::vector<Index> chunk_next_;           // per chunk: the next (older) chunk of its list
  std::vector<std::uint8_t> chunk_count_;   // per chunk: windows in it
  std::vector<Index> free_;
  std::vector<std::unique_ptr<Chunk, Block_deleter>> blocks_;
  std::size_t live_chunks_ = 0, peak_chunks_ = 0;
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_WINDOW_LISTS_H
