// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Single-source parallel propagation of the vertex-oriented schedule (vertex_oriented_propagation.h), in the
// spirit of PVTP (Du et al., "On the vertex-oriented triangle propagation (VTP) algorithm: parallelization and
// approximation", 2021): many window lists cross their faces at the same time.
//
// The run is a sequence of rounds (PVTP's bands), each in three steps:
//   1. Settle (sequential): vertices leave the queue in order of distance until at least `lists_per_round` lists
//      are ready, or the queue is empty. A settled pseudo-source's expansion becomes a task of the round.
//   2. Propagate (parallel): every ready list crosses its face as a batch (vertex_oriented_batch.h), every
//      expansion emits its windows. A task reads the vertex values as they were at the start of the round
//      (nothing writes them in this step) and its own values at the three vertices of its face, and writes only to
//      its block's output: vertex lowerings, child windows, chunks to free.
//   3. Merge (parallel, 9 independent streams): one applies the blocks' lowerings in block order; each of 8 others
//      appends the children bound for its fixed set of lists, in block order, with chunk ids reserved for it (a list
//      whose edge touches a vertex settled at the start of the merge becomes ready for the next round).
//
// Determinism. The round's tasks, their order and their blocks follow from the state alone (never from the number
// of threads), a task reads only the frozen state and writes only its own output, and the merge order is fixed:
// the distances are identical, bit for bit, for every thread count (1 thread runs the same rounds). They differ
// from the sequential schedule's (Sequential_tag) by rounding only: the lists are taken and trimmed at other
// moments, so a vertex may get its value from another, equally short window (4.3e-16 relative at most on
// armadillo Loop x2, 416k vertices). The schedule
// stays exact for the sequential one's reason: it is label-correcting (every value is the length of a real path,
// every pruning compares with real path lengths, a pseudo-source whose value drops is settled again).
//
// Cost. A round settles vertices before the lists around earlier ones have crossed, so a task sees values that
// may still drop (less pruning) and a list may be taken twice where the sequential schedule took it once: 0.14%
// more windows at 256 lists per round (armadillo Loop x2), 2.9x more tasks at 4,096. Settling and the merge's
// longest stream are the sequential part (10% of the 1-thread run there); see the package manual.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_PARALLEL_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_PARALLEL_H

#include <CGAL/MDCS/concurrency.h>
#include <CGAL/MDCS/progress.h>
#include <CGAL/Polyhedral_geodesics_3/internal/vertex_oriented_propagation.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <time.h>
#endif

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

// What a parallel run measured (only with set_profile(true); the figures of the manual and the benchmark). Times
// are CPU times of the thread that ran the step (so that a loaded machine does not count the waits for a core),
// except parallel_seconds, the wall time of the parallel steps.
struct Vertex_oriented_parallel_profile
{
  std::size_t rounds = 0, tasks = 0;
  double settle_seconds = 0, merge_seconds = 0, parallel_seconds = 0; // the three steps
  double merge_span_seconds = 0;           // the merge's longer stream (its time with two threads or more)
  double work_seconds = 0;                 // the tasks' time summed over every block (the parallel step's work)
  std::vector<double> thread_busy_seconds; // per thread that ran blocks: its time in blocks
  // For P = 1, 2, 4, 8, 16 threads: sum over rounds of max(work / P, longest block): a lower bound of the parallel
  // step's time with P threads (the span of a round is its longest block), and sum of work / P + longest block,
  // an upper bound for greedy scheduling. Projections; the sequential steps come on top.
  std::array<double, 5> projected_lower{}, projected_upper{};
  static constexpr std::array<int, 5> projected_threads() { return {{1, 2, 4, 8, 16}}; }
};

template <class FT>
class Vertex_oriented_parallel_runner
{
public:
  typedef Vertex_oriented_window_propagation<FT> Engine;
  typedef typename Engine::Mesh Mesh;
  typedef typename Engine::Index Index;
  typedef typename Engine::Window Window;
  typedef typename Engine::Batch Batch;
  typedef Vertex_oriented_parallel_profile Profile;

  // `threads`: the effective number of threads (see MDCS::effective_threads()).
  Vertex_oriented_parallel_runner(Engine& engine, std::size_t threads)
    : e_(engine), team_(threads), batches_([&engine] { return Batch(engine.mesh()); }), busy_([] { return 0.0; })
  {}

  // Lists per round: enough to keep the threads busy (a list is about a microsecond of work) and few enough that
  // the values a round's tasks read are nearly final. Part of the result's definition (not of the thread count).
  void set_lists_per_round(std::size_t n) { lists_per_round_ = n == 0 ? 1 : n; }
  // Tasks per block of the parallel loop (the unit of work of a thread, and of the merge order).
  void set_block_size(std::size_t n) { block_size_ = n == 0 ? 1 : n; }
  void set_profile(bool profile) { profile_ = profile; }
  const Profile& profile() const { return profile_data_; }

  // The run; the engine is prepared as for Engine::run() (clear(), options, sources), with no point query and no
  // stop targets (Exact_geodesic_engine runs those sequentially).
  template <class Progress>
  void run(Progress& progress)
  {
    CGAL_precondition(e_.query_ == nullptr && e_.stop_targets_.empty() && !e_.reuse_);
    const char* stage = "geodesic propagation";
    if(!progress(stage, 0.0))
      throw MDCS::Operation_cancelled(stage);
    profile_data_ = Profile();
    std::size_t settled = 0, rounds = 0;
    do {
      // the settled vertices (again after the safety net, which may have put some back into the queue)
      inside_.assign(e_.vertices_.size(), 0);
      for(std::size_t v = 0; v < e_.vertices_.size(); ++v)
        inside_[v] = e_.vertices_[v].state == Engine::INSIDE ? 1 : 0;
      for(;;) {
        const double t0 = profile_ ? now() : 0.0;
        settle(settled);
        if(e_.fifo_.empty() && tasks_expand_.empty())
          break; // the queue is empty
        if(profile_)
          profile_data_.settle_seconds += seconds(t0, now());
        propagate_round();
        if((++rounds & 0xFF) == 0) {
          const double fraction = e_.vertices_.empty() ? 1.0 : double(settled) / double(e_.vertices_.size());
          if(!progress(stage, fraction < 1.0 ? fraction : 1.0))
            throw MDCS::Operation_cancelled(stage);
        }
      }
      // The safety net (merging only, in practice) runs sequentially: its windows wait in the lists as usual.
    } while(!e_.has_limit_ && e_.expand_stranded_neighbours());
    e_.finish();
    profile_data_.rounds = rounds;
    if(profile_)
      busy_.for_each([&](double& t) { profile_data_.thread_busy_seconds.push_back(t); });
    if(!progress(stage, 1.0))
      throw MDCS::Operation_cancelled(stage);
  }

private:
  typedef typename Engine::Parent Parent;
  // CPU time of the calling thread (wall time where there is no such clock).
  static double now()
  {
#if defined(CLOCK_THREAD_CPUTIME_ID)
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
#else
    return wall();
#endif
  }
  static double wall()
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  }
  static double seconds(double a, double b) { return b - a; }

  // source: the nearest source of the path (an expansion's, read when the round started), or -2: the root's,
  // read when the lowering is applied (as the sequential schedule does).
  struct Lowering
  {
    FT d, sx, sy, at;
    Index vertex, halfedge, root, source;
  };

  struct Child
  {
    Window w;
    Index halfedge;
  };

  // What the tasks of one block produce, applied in the merge.
  // The merge's streams of children: a list belongs to the stream of its halfedge (runs of 32 halfedges, dealt
  // out in turn), a fixed number, whatever the number of threads.
  static constexpr std::size_t child_streams = 8;
  static std::size_t stream_of(Index g) { return (std::size_t(g) >> 5) % child_streams; }

  struct Block_output
  {
    std::vector<Lowering> lowerings;
    std::array<std::vector<Child>, child_streams> children; // per stream, in task order
    std::vector<Index> taken_chunks;
    std::size_t taken_windows = 0, propagated = 0, pruned = 0, merged = 0;
    double seconds = 0;

    void clear()
    {
      lowerings.clear();
      for(std::vector<Child>& c : children)
        c.clear();
      taken_chunks.clear();
      taken_windows = propagated = pruned = merged = 0;
      seconds = 0;
    }
  };

  // A batch's sink in a round (see vertex_oriented_batch.h): vertex values as they were at the start of the round,
  // plus the task's own lowerings of its face's vertices (a batch sees its own values at once, as in the
  // sequential schedule).
  struct Buffered_sink
  {
    const Engine& e;
    Block_output& out;
    Index overlay_vertex[3] = {-1, -1, -1};
    FT overlay_value[3];
    int overlay_size = 0;

    Buffered_sink(const Engine& engine, Block_output& o) : e(engine), out(o) {}

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
        CGAL_assertion(overlay_size < 3); // a batch lowers the three vertices of its face only
        ++overlay_size;
      }
      overlay_vertex[k] = v;
      overlay_value[k] = d;
      out.lowerings.push_back(Lowering{d, w.sx, w.sy, at, v, g, w.root, -2});
    }
    void child(Index t, const Window& w) { out.children[stream_of(t)].push_back(Child{w, t}); }
    void propagated(std::size_t n) { out.propagated += n; }
    void pruned() { ++out.pruned; }
    void merged() { ++out.merged; }
    bool has_bound() const { return false; }
    bool bound_trim(Index, Window&, const FT&) const { return true; }
    void face_sources_in(Index, const Window*, const Window*) {}
  };

  // Step 1: settles vertices until enough lists are ready (the sequential schedule's loop, without the draining).
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
      inside_[v] = 1;
      if((r.flags & (Engine::PSEUDO_SOURCE | Engine::IS_SOURCE)) && e_.expansion_useful(v)) {
        tasks_expand_.push_back(top.vertex);
        expand_values_.push_back(Expansion{r.dist, r.source, r.flags});
      }
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
    const std::size_t n_lists = tasks_lists_.size(), n = n_lists + tasks_expand_.size();
    const std::size_t blocks = (n + block_size_ - 1) / block_size_;
    if(outputs_.size() < blocks)
      outputs_.resize(blocks);
    const typename Batch::Settings s = e_.settings();
    const double t0 = profile_ ? now() : 0.0, w0 = profile_ ? wall() : 0.0;
    team_.for_blocks(n, block_size_, [&](std::size_t begin, std::size_t end, std::size_t b) {
      const double b0 = profile_ ? now() : 0.0;
      Block_output& out = outputs_[b];
      out.clear();
      Batch& batch = batches_.local();
      for(std::size_t i = begin; i < end; ++i) {
        Buffered_sink sink(e_, out);
        if(i < n_lists) {
          const Index g = tasks_lists_[i];
          std::vector<Window>& windows = batch.windows();
          e_.lists_.take_deferred(g, windows, out.taken_chunks);
          out.taken_windows += windows.size();
          batch.run(g, s, sink);
        } else {
          expand(tasks_expand_[i - n_lists], expand_values_[i - n_lists], out);
        }
      }
      if(profile_) {
        out.seconds = seconds(b0, now());
        busy_.local() += out.seconds;
      }
    });
    const double t1 = profile_ ? now() : 0.0, w1 = profile_ ? wall() : 0.0;
    tasks_expand_.clear();
    expand_values_.clear();
    // Step 3: the merge, in block order, as independent streams that may run at the same time: the lowerings
    // (vertex records, the queue), and the children of each of `child_streams` sets of lists (window lists, the
    // ready lists), each with chunk ids reserved for it. A child's list is ready when an end of its edge was
    // settled at the start of the merge (inside_; a lowering may reopen a settled pseudo-source meanwhile: its
    // list is then only taken earlier, which the label-correcting schedule allows). No stream reads what another
    // writes, and the ready lists are collected in stream order: the result does not depend on whether the
    // streams run one after the other or at the same time.
    for(std::size_t b = 0; b < blocks; ++b) {
      e_.lists_.free_chunks(outputs_[b].taken_chunks);
      e_.live_ -= outputs_[b].taken_windows;
    }
    for(std::size_t k = 0; k < child_streams; ++k) {
      std::size_t count = 0;
      for(std::size_t b = 0; b < blocks; ++b)
        count += outputs_[b].children[k].size();
      reserved_count_[k] = count;
      e_.lists_.reserve(count, reserved_[k]);
    }
    double stream_seconds[child_streams + 1] = {};
    team_.for_blocks(child_streams + 1, 1, [&](std::size_t, std::size_t, std::size_t stream) {
      const double m0 = profile_ ? now() : 0.0;
      if(stream == child_streams)
        merge_lowerings(blocks);
      else
        merge_children(blocks, stream);
      if(profile_)
        stream_seconds[stream] = seconds(m0, now());
    });
    for(std::size_t k = 0; k < child_streams; ++k) {
      e_.lists_.release_reserved(reserved_count_[k], reserved_[k]);
      e_.fifo_.insert(e_.fifo_.end(), ready_[k].begin(), ready_[k].end());
      ready_[k].clear();
      e_.live_ += reserved_count_[k];
      e_.stats_.windows_created += reserved_count_[k];
    }
    if(e_.live_ > e_.stats_.peak_live_windows)
      e_.stats_.peak_live_windows = e_.live_; // the merge only adds windows: its end is its peak
    for(Index v : reopened_)
      inside_[std::size_t(v)] = 0;
    reopened_.clear();
    for(std::size_t b = 0; b < blocks; ++b) {
      e_.stats_.windows_propagated += outputs_[b].propagated;
      e_.stats_.windows_pruned += outputs_[b].pruned;
      e_.stats_.windows_merged += outputs_[b].merged;
    }
    e_.lists_processed_ += n_lists;
    if(profile_) {
      const double t2 = now();
      (void)t0;
      profile_data_.parallel_seconds += seconds(w0, w1);
      (void)t2;
      (void)t1;
      double longest_stream = 0;
      for(double x : stream_seconds) {
        profile_data_.merge_seconds += x;
        longest_stream = (std::max)(longest_stream, x);
      }
      profile_data_.merge_span_seconds += longest_stream;
      profile_data_.tasks += n;
      double work = 0, longest = 0;
      for(std::size_t b = 0; b < blocks; ++b) {
        work += outputs_[b].seconds;
        longest = (std::max)(longest, outputs_[b].seconds);
      }
      profile_data_.work_seconds += work;
      const std::array<int, 5> ps = Profile::projected_threads();
      for(std::size_t k = 0; k < ps.size(); ++k) {
        profile_data_.projected_lower[k] += (std::max)(work / ps[k], longest);
        profile_data_.projected_upper[k] += work / ps[k] + (ps[k] > 1 ? longest : 0.0);
      }
    }
  }

  void merge_lowerings(std::size_t blocks)
  {
    for(std::size_t b = 0; b < blocks; ++b) {
      const std::vector<Lowering>& lowerings = outputs_[b].lowerings;
      const std::size_t nl = lowerings.size();
      for(std::size_t l = 0; l < nl; ++l) {
        if(l + prefetch_far < nl)
          prefetch_vertex(lowerings[l + prefetch_far].vertex);
        apply_lowering(lowerings[l]);
      }
    }
  }

  // The children of one stream. Their lists are spread over the whole mesh and another thread touched them last:
  // they are prefetched a few items ahead.
  void merge_children(std::size_t blocks, std::size_t k)
  {
    std::vector<Index>& ids = reserved_[k];
    std::vector<Index>& ready = ready_[k];
    for(std::size_t b = 0; b < blocks; ++b) {
      const std::vector<Child>& children = outputs_[b].children[k];
      const std::size_t nc = children.size();
      for(std::size_t c = 0; c < nc; ++c) {
        if(c + prefetch_far < nc) {
          const Index g = children[c + prefetch_far].halfedge;
          e_.lists_.prefetch_head(g);
          prefetch_address(&e_.queued_[std::size_t(g)]);
          prefetch_address(&e_.mesh_.he[std::size_t(g)]);
          prefetch_address(&e_.mesh_.he[std::size_t(Mesh::next(g))]);
        }
        if(c + prefetch_near < nc) {
          const Index g = children[c + prefetch_near].halfedge;
          e_.lists_.prefetch_newest_chunk(g);
          prefetch_address(&inside_[std::size_t(e_.mesh_.source(g))]);
          prefetch_address(&inside_[std::size_t(e_.mesh_.target(g))]);
        }
        const Index g = children[c].halfedge;
        e_.lists_.push_reserved(g, children[c].w, ids);
        if(!e_.queued_[std::size_t(g)] &&
           (inside_[std::size_t(e_.mesh_.source(g))] || inside_[std::size_t(e_.mesh_.target(g))])) {
          e_.queued_[std::size_t(g)] = 1;
          ready.push_back(g);
        }
      }
    }
  }

  static constexpr std::size_t prefetch_far = 16, prefetch_near = 6;
  static void prefetch_address(const void* p)
  {
#if defined(__GNUC__)
    __builtin_prefetch(p);
#else
    (void)p;
#endif
  }
  void prefetch_vertex(Index v) const { prefetch_address(&e_.vertices_[std::size_t(v)]); }

  void apply_lowering(const Lowering& x)
  {
    const Index source = x.source != -2 ? x.source : e_.source_of_root(x.root);
    typename Engine::Vertex_record& r = e_.vertices_[std::size_t(x.vertex)];
    const bool was_inside = r.state == Engine::INSIDE;
    if(!e_.update_vertex(x.vertex, x.d, source))
      return;
    if(e_.record_parents_)
      e_.parents_[std::size_t(x.vertex)] = Parent{x.sx, x.sy, x.at, x.halfedge, x.root};
    if(was_inside && r.state != Engine::INSIDE)
      reopened_.push_back(x.vertex); // a pseudo-source settled again later
  }

  struct Expansion
  {
    FT dist;
    Index source;
    std::uint8_t flags;
  };

  // A pseudo-source's expansion as a task: the windows and values of Engine::expand_vertex(), with the vertex's
  // value and source read when it was settled.
  void expand(Index v, const Expansion& r, Block_output& out)
  {
    const Mesh& mesh = e_.mesh_;
    const FT d = r.dist;
    const std::int32_t lobe = (r.flags & Engine::LOBE_VERTEX) && !(r.flags & Engine::IS_SOURCE) ? 1 : 0;
    for(Index k = e_.star_begin_[std::size_t(v)]; k < e_.star_begin_[std::size_t(v) + 1]; ++k) {
      const Index h = e_.star_[std::size_t(k)]; // source(h) == v
      const Index hp = Mesh::prev(h);
      out.lowerings.push_back(
        Lowering{FT(d + mesh.he[std::size_t(h)].length), FT(0), FT(0), FT(0), mesh.target(h), -1, v, r.source});
      out.lowerings.push_back(
        Lowering{FT(d + mesh.he[std::size_t(hp)].length), FT(0), FT(0), FT(0), mesh.source(hp), -1, v, r.source});
      const Index g = Mesh::next(h); // the edge opposite v in the face of h
      const Index t = mesh.he[std::size_t(g)].twin;
      if(t < 0 || (e_.has_limit_ && d > e_.limit_))
        continue;
      const FT L = mesh.he[std::size_t(g)].length;
      const Point_2_ft<FT>& p = mesh.he[std::size_t(g)].opposite; // v in g's frame
      out.children[stream_of(t)].push_back(Child{Window{FT(0), L, FT(L - p.x), FT(-p.y), d, v, lobe}, t});
    }
  }

  Engine& e_;
  MDCS::Parallel_team team_;
  MDCS::Per_thread<Batch> batches_;
  MDCS::Per_thread<double> busy_;
  std::size_t lists_per_round_ = 256, block_size_ = 4;
  bool profile_ = false;
  Profile profile_data_;
  std::vector<Index> tasks_lists_, tasks_expand_;
  std::vector<Expansion> expand_values_;
  std::vector<Block_output> outputs_;
  std::vector<char> inside_;   // per vertex: settled (the ready rule of the merge's children; see propagate_round)
  std::vector<Index> reopened_; // settled vertices a lowering of the merge put back into the queue
  std::array<std::vector<Index>, child_streams> reserved_, ready_; // per stream: chunk ids, lists made ready
  std::array<std::size_t, child_streams> reserved_count_{};
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_PARALLEL_H
