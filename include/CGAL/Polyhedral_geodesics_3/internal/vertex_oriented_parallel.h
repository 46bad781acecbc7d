// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Single-source parallel propagation of the vertex-oriented schedule (vertex_oriented_propagation.h), in the
// spirit of PVTP (Du et al., "On the vertex-oriented triangle propagation (VTP) algorithm: parallelization and
// approximation", 2021): many window lists cross their faces at the same time.
//
// The run is a sequence of rounds, each in three steps:
//   1. Settle (sequential): vertices leave the queue in order of distance until at least `lists_per_round` lists
//      are ready (or the queue is empty). A settled pseudo-source's expansion becomes a task of the round.
//   2. Propagate (parallel): every ready list crosses its face as a batch (vertex_oriented_batch.h), every
//      expansion emits its windows. A task reads the vertex values as they were before the round (nothing writes
//      them in this step) and its own values at the three vertices of its face, and writes only to its block's
//      output: vertex lowerings, child windows, chunks to free.
//   3. Merge (sequential): the blocks' outputs are applied in block order, task by task: lowerings (with their
//      Parents), then children, appended to their lists (a list whose edge touches a settled vertex becomes ready
//      for the next round).
//
// The tasks of a round and their blocks depend only on the run, not on the number of threads, and the merge order
// is fixed, so the distances are identical, bit for bit, for every thread count (1 thread runs the same rounds).
// They differ from the sequential schedule's (Sequential_tag) by rounding only, about 1e-15 relative: the batches
// are formed and trimmed in another order. The schedule stays exact for the same reason as the sequential one
// (label-correcting: every value is a real path length, a pseudo-source whose value drops is settled again).
//
// Cost. A round settles more vertices than the sequential schedule would before their lists cross (their values
// may still drop), so it propagates a few percent more windows; the merge and the settling are the sequential part.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_PARALLEL_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_PARALLEL_H

#include <CGAL/MDCS/concurrency.h>
#include <CGAL/MDCS/progress.h>
#include <CGAL/Polyhedral_geodesics_3/internal/vertex_oriented_propagation.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

template <class FT>
class Vertex_oriented_parallel_runner
{
public:
  typedef Vertex_oriented_window_propagation<FT> Engine;
  typedef typename Engine::Mesh Mesh;
  typedef typename Engine::Index Index;
  typedef typename Engine::Window Window;
  typedef typename Engine::Batch Batch;

  // `threads`: the effective number of threads (see MDCS::effective_threads()).
  Vertex_oriented_parallel_runner(Engine& engine, std::size_t threads)
    : e_(engine), team_(threads), batches_([&engine] { return Batch(engine.mesh()); })
  {}

  // Tasks per round: enough to keep the threads busy (a list is a few microseconds of work) and few enough that the
  // values the round's tasks read are nearly final.
  void set_lists_per_round(std::size_t n) { lists_per_round_ = n == 0 ? 1 : n; }
  // Tasks per block of the parallel loop (the unit of work of one thread, and of the merge order).
  void set_block_size(std::size_t n) { block_size_ = n == 0 ? 1 : n; }

  template <class Progress>
  void run(Progress& progress)
  {
    const char* stage = "geodesic propagation";
    if(!progress(stage, 0.0))
      throw MDCS::Operation_cancelled(stage);
    std::size_t settled = 0, rounds = 0;
    do {
      for(;;) {
        if(!e_.stop_targets_.empty() && e_.fifo_.empty() && e_.stop_targets_final()) {
          e_.stopped_early_ = true;
          break;
        }
        settle(settled);
        if(e_.fifo_.empty() && tasks_expand_.empty())
          break; // the queue is empty
        propagate_round();
        if((++rounds & 0xFF) == 0) {
          const double fraction = e_.vertices_.empty() ? 1.0 : double(settled) / double(e_.vertices_.size());
          if(!progress(stage, fraction < 1.0 ? fraction : 1.0))
            throw MDCS::Operation_cancelled(stage);
        }
      }
    } while(!e_.stopped_early_ && !e_.query_ && !e_.has_limit_ && e_.expand_stranded_neighbours_deferred(*this));
    e_.finish();
    rounds_ = rounds;
    if(!progress(stage, 1.0))
      throw MDCS::Operation_cancelled(stage);
  }

  std::size_t rounds() const { return rounds_; }

  // For the engine's safety net: queue the expansion of a reached vertex as a task, run at the next round.
  void defer_expansion(Index v) { tasks_expand_.push_back(v); }

private:
  typedef typename Engine::Parent Parent;

  struct Lowering
  {
    FT d, sx, sy, at;
    Index vertex, halfedge, root;
  };

  struct Child
  {
    Window w;
    Index halfedge;
  };

  // What the tasks of one block produce, applied in the merge.
  struct Block_output
  {
    std::vector<std::size_t> task_end_lowerings, task_end_children; // per task: end of its part of the vectors
    std::vector<Lowering> lowerings;
    std::vector<Child> children;
    std::vector<Index> taken_chunks;
    std::size_t taken_windows = 0, propagated = 0, pruned = 0, merged = 0;

    void clear()
    {
      task_end_lowerings.clear();
      task_end_children.clear();
      lowerings.clear();
      children.clear();
      taken_chunks.clear();
      taken_windows = propagated = pruned = merged = 0;
    }
  };

  // A batch's sink in a round (see vertex_oriented_batch.h): vertex values as they were before the round, plus the
  // task's own lowerings of its face's vertices.
  struct Buffered_sink
  {
    const Engine& e;
    Block_output& out;
    Index overlay_vertex[3];
    FT overlay_value[3];
    int overlay_size = 0;

    const FT& distance(Index v) const
    {
      for(int k = 0; k < overlay_size; ++k)
        if(overlay_vertex[k] == v)
          return overlay_value[k];
      return e.vertices_[std::size_t(v)].dist;
    }
    void lower(Index v, const FT& d, const Window& w, Index g, const FT& at)
    {
      if(!(d < distance(v)))
        return;
      int k = 0;
      while(k < overlay_size && overlay_vertex[k] != v)
        ++k;
      if(k == overlay_size) {
        if(overlay_size == 3)
          k = 2; // a task touches its face's three vertices only; a fourth (never) would only lose an overlay
        else
          ++overlay_size;
      }
      overlay_vertex[k] = v;
      overlay_value[k] = d;
      out.lowerings.push_back(Lowering{d, w.sx, w.sy, at, v, g, w.root});
    }
    void child(Index t, const Window& w) { out.children.push_back(Child{w, t}); }
    void propagated(std::size_t n) { out.propagated += n; }
    void pruned() { ++out.pruned; }
    void merged() { ++out.merged; }
    bool has_bound() const { return false; }
    bool bound_trim(Index, Window&, const FT&) const { return true; }
    void face_sources_in(Index, const Window*, const Window*) {}
  };

  // Step 1: settles vertices until enough lists are ready.
  void settle(std::size_t& settled)
  {
    while(e_.fifo_.size() + tasks_expand_.size() < lists_per_round_ && !e_.heap_.empty()) {
      const typename Engine::Heap_entry top = e_.heap_.pop();
      const std::size_t v = std::size_t(top.vertex);
      typename Engine::Vertex_record& r = e_.vertices_[v];
      if(top.stamp != r.stamp || r.state == Engine::INSIDE)
        continue;
      if(!(r.flags & Engine::SETTLED_ONCE)) {
        r.flags |= Engine::SETTLED_ONCE;
        ++settled;
      }
      r.state = Engine::INSIDE;
      if((r.flags & (Engine::PSEUDO_SOURCE | Engine::IS_SOURCE)) && e_.expansion_useful(v))
        tasks_expand_.push_back(top.vertex);
      for(Index k = e_.star_begin_[v]; k < e_.star_begin_[v + 1]; ++k) {
        const Index h = e_.star_[std::size_t(k)];
        e_.make_ready(h);
        e_.make_ready(Mesh::prev(h));
      }
    }
  }

  // Steps 2 and 3.
  void propagate_round()
  {
    // the round's tasks: the ready lists (in the order they became ready), then the expansions
    tasks_lists_.assign(e_.fifo_.begin(), e_.fifo_.end());
    e_.fifo_.clear();
    e_.fifo_head_ = 0;
    for(Index g : tasks_lists_)
      e_.queued_[std::size_t(g)] = 0;
    // the expansions' values are read now: a task must not see another task's lowerings
    expand_values_.clear();
    for(Index v : tasks_expand_)
      expand_values_.push_back(e_.vertices_[std::size_t(v)]);
    const std::size_t n_lists = tasks_lists_.size(), n = n_lists + tasks_expand_.size();
    const std::size_t blocks = (n + block_size_ - 1) / block_size_;
    if(outputs_.size() < blocks)
      outputs_.resize(blocks);
    const typename Batch::Settings s = e_.settings();
    team_.for_blocks(n, block_size_, [&](std::size_t begin, std::size_t end, std::size_t b) {
      Block_output& out = outputs_[b];
      out.clear();
      Batch& batch = batches_.local();
      for(std::size_t i = begin; i < end; ++i) {
        Buffered_sink sink{e_, out, {-1, -1, -1}, {FT(0), FT(0), FT(0)}, 0};
        if(i < n_lists) {
          const Index g = tasks_lists_[i];
          std::vector<Window>& windows = batch.windows();
          e_.lists_.take_deferred(g, windows, out.taken_chunks);
          out.taken_windows += windows.size();
          batch.run(g, s, sink);
        } else {
          expand(tasks_expand_[i - n_lists], expand_values_[i - n_lists], sink);
        }
        out.task_end_lowerings.push_back(out.lowerings.size());
        out.task_end_children.push_back(out.children.size());
      }
    });
    tasks_expand_.clear();
    // Step 3: the merge, in block order.
    for(std::size_t b = 0; b < blocks; ++b) {
      Block_output& out = outputs_[b];
      e_.lists_.free_chunks(out.taken_chunks);
      e_.live_ -= out.taken_windows;
      e_.lists_processed_ += 0;
      e_.stats_.windows_propagated += out.propagated;
      e_.stats_.windows_pruned += out.pruned;
      e_.stats_.windows_merged += out.merged;
      std::size_t l = 0, c = 0;
      for(std::size_t t = 0; t < out.task_end_lowerings.size(); ++t) {
        for(; l < out.task_end_lowerings[t]; ++l) {
          const Lowering& x = out.lowerings[l];
          apply_lowering(x);
        }
        for(; c < out.task_end_children[t]; ++c)
          e_.add_window(out.children[c].halfedge, out.children[c].w);
      }
    }
    e_.lists_processed_ += n_lists;
  }

  void apply_lowering(const Lowering& x)
  {
    Index source;
    if(x.halfedge < 0 && x.root == x.vertex)
      source = e_.vertices_[std::size_t(x.vertex)].source;
    else
      source = e_.source_of_root(x.root);
    if(e_.update_vertex(x.vertex, x.d, source) && e_.record_parents_)
      e_.parents_[std::size_t(x.vertex)] = Parent{x.sx, x.sy, x.at, x.halfedge, x.root};
  }

  // A pseudo-source's expansion as a task (see Engine::expand_vertex; the same windows and values).
  void expand(Index v, const typename Engine::Vertex_record& r, Buffered_sink& sink)
  {
    const Mesh& mesh = e_.mesh_;
    const FT d = r.dist;
    const std::int32_t lobe = (r.flags & Engine::LOBE_VERTEX) && !(r.flags & Engine::IS_SOURCE) ? 1 : 0;
    for(Index k = e_.star_begin_[std::size_t(v)]; k < e_.star_begin_[std::size_t(v) + 1]; ++k) {
      const Index h = e_.star_[std::size_t(k)];
      const Index hp = Mesh::prev(h);
      sink.out.lowerings.push_back(
        Lowering{FT(d + mesh.he[std::size_t(h)].length), FT(0), FT(0), FT(0), mesh.target(h), -1, v});
      sink.out.lowerings.push_back(
        Lowering{FT(d + mesh.he[std::size_t(hp)].length), FT(0), FT(0), FT(0), mesh.source(hp), -1, v});
      const Index g = Mesh::next(h);
      const Index t = mesh.he[std::size_t(g)].twin;
      if(t < 0 || (e_.has_limit_ && d > e_.limit_))
        continue;
      const FT L = mesh.he[std::size_t(g)].length;
      const Point_2_ft<FT>& p = mesh.he[std::size_t(g)].opposite;
      sink.child(t, Window{FT(0), L, FT(L - p.x), FT(-p.y), d, v, lobe});
    }
  }

  Engine& e_;
  MDCS::Parallel_team team_;
  MDCS::Per_thread<Batch> batches_;
  std::size_t lists_per_round_ = 64, block_size_ = 4, rounds_ = 0;
  std::vector<Index> tasks_lists_, tasks_expand_;
  std::vector<typename Engine::Vertex_record> expand_values_;
  std::vector<Block_output> outputs_;
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_PARALLEL_H
