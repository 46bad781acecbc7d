// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A sequence of views (the frames of a rotation, a camera path) on one Silhouette_simplifier_3, on several
// threads: the simplifier's preprocessed meshes are shared read-only, every thread has its own workspace, and the
// frames reach the caller in order (issue 29 item 5).

#ifndef CGAL_SILHOUETTE_SIMPLIFICATION_3_SILHOUETTE_FRAMES_H
#define CGAL_SILHOUETTE_SIMPLIFICATION_3_SILHOUETTE_FRAMES_H

#include <CGAL/MDCS/concurrency.h>
#include <CGAL/MDCS/progress.h>
#include <CGAL/Silhouette_simplification_3/Silhouette_simplifier_3.h>
#include <CGAL/Min_cut/solve_min_cut.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Silhouette_simplification_3 {

/*!
  \ingroup PkgSilhouetteSimplification3Ref
  \brief What `simplify_silhouette_frames()` computes for each view.
*/
struct Silhouette_frames_options
{
  bool pick = true;                   ///< method A: `Silhouette_simplifier_3::pick_loops()`
  bool map = true;                    ///< method B: `Silhouette_simplifier_3::map_loops()`
  Loop_picking_options picking;       ///< options of method A
  Loop_mapping_options mapping;       ///< options of method B
  /// Threads (0: all hardware threads); with `CGAL::Sequential_tag` or without TBB, 1.
  std::size_t threads = 0;
  /// Frames computed ahead of the one the caller receives (memory: one `Silhouette_frame` each, about 2 bytes per
  /// fine face plus the silhouettes); 0: four per thread.
  std::size_t frames_in_flight = 0;
};

namespace internal {

// The part of a frame the next frame's remedy reads: its picked loops and its mapped loops.
inline Silhouette_frame remedy_memory(const Silhouette_frame& f)
{
  Silhouette_frame m;
  for(std::uint32_t l : f.picked) {
    m.picked.push_back(std::uint32_t(m.fine_loops.size()));
    m.fine_loops.push_back(f.fine_loops[l]);
  }
  m.mapped = f.mapped;
  return m;
}

} // namespace internal

/*!
  \ingroup PkgSilhouetteSimplification3Ref
  \brief The simplified silhouettes of a sequence of views: for view `i` of `views`, `extract()`, then
  `pick_loops()` if `options.pick` and `map_loops()` if `options.map`, exactly as the per-view calls of `simplifier`
  compute them; `output(i, frame)` receives frame `i` (a `Silhouette_frame&` it may move from), in the order of the
  views, never two at a time (possibly from a worker thread: see `CGAL::MDCS::parallel_ordered_pipeline()`).

  The frames are computed on `options.threads` threads (`ConcurrencyTag`: `CGAL::Sequential_tag`,
  `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`; TBB needed): `simplifier`'s preprocessed meshes are
  shared read-only and every thread has its own `Silhouette_simplifier_3::Workspace`. The frames are taken in
  order by whichever thread is free, and at most `options.frames_in_flight` are held at a time, so the memory does
  not grow with the number of views.
  Every frame is the one the sequential calls give, whatever the thread count.

  With the temporal-coherence remedy (`previous_bias` below 1 in `options.picking` or `options.mapping`) frame `i`
  depends on frame `i - 1`: the extraction (and the unbiased method, if any) still runs in parallel, the biased
  method runs in view order just before the output (frame 0 without a previous frame), as a sequential loop passing
  the previous frame would.

  `progress` (`bool(const char*, double)`, stage `"silhouette frames"`, the fraction of frames computed) is called
  on the calling thread only; returning `false` stops the sequence (the frames before are still delivered) and
  throws `CGAL::MDCS::Operation_cancelled`.
  \throws std::invalid_argument for invalid picking or mapping options; any exception of a frame is rethrown, that
          of the lowest failing frame whatever the thread count.
  \tparam Engine a model of `MaxFlowEngine` for method B
*/
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class VertexPointMap, class FrameOutput,
          class Engine = CGAL::Min_cut::Default_max_flow_engine, class Progress = CGAL::MDCS::No_progress>
void simplify_silhouette_frames(
  const Silhouette_simplifier_3<TriangleMesh, VertexPointMap>& simplifier,
  const std::vector<typename Silhouette_simplifier_3<TriangleMesh, VertexPointMap>::View>& views,
  const Silhouette_frames_options& options, FrameOutput output, Engine engine = Engine(), Progress progress = Progress())
{
  typedef Silhouette_simplifier_3<TriangleMesh, VertexPointMap> Simplifier;
  typedef typename Simplifier::Workspace Workspace;
  if(options.pick) Simplifier::check_picking_options(options.picking);
  if(options.map) Simplifier::check_mapping_options(options.mapping);
  const std::size_t threads = CGAL::MDCS::effective_threads<ConcurrencyTag>(options.threads);
  const bool pick_in_order = options.pick && options.picking.previous_bias != 1.0;
  const bool map_in_order = options.map && options.mapping.previous_bias != 1.0;
  CGAL::MDCS::Parallel_progress<Progress> reporter(progress, "silhouette frames", views.size());
  CGAL::MDCS::Per_thread<Workspace> workspaces([&simplifier] { return simplifier.make_workspace(); });
  std::vector<Silhouette_frame> slots(options.frames_in_flight > 0 ? options.frames_in_flight : 4 * threads);
  Silhouette_frame previous; // what the remedy reads of the last frame delivered
  CGAL::MDCS::parallel_ordered_pipeline(
    views.size(), threads, slots,
    // The independent part of a frame, on any thread with that thread's workspace.
    [&](std::size_t i, Silhouette_frame& frame) {
      Workspace& ws = workspaces.local();
      simplifier.extract(views[i], frame, ws);
      if(options.pick && !pick_in_order) simplifier.pick_loops(frame, options.picking, nullptr, ws);
      if(options.map && !map_in_order) simplifier.map_loops(frame, options.mapping, nullptr, engine, ws);
      return reporter.advance();
    },
    // In view order, one frame at a time: the methods biased by the previous frame, then the output.
    [&](std::size_t i, Silhouette_frame& frame) {
      if(pick_in_order || map_in_order) {
        Workspace& ws = workspaces.local();
        const Silhouette_frame* prev = i > 0 ? &previous : nullptr;
        if(pick_in_order) simplifier.pick_loops(frame, options.picking, prev, ws);
        if(map_in_order) simplifier.map_loops(frame, options.mapping, prev, engine, ws);
        previous = internal::remedy_memory(frame);
      }
      output(i, frame);
    });
  reporter.finish();
}

/*!
  \ingroup PkgSilhouetteSimplification3Ref
  \brief The same, returning every frame (memory: all of them; prefer the version with an output for long
  sequences of large meshes), with the default max-flow engine.
*/
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class VertexPointMap>
std::vector<Silhouette_frame> simplify_silhouette_frames(
  const Silhouette_simplifier_3<TriangleMesh, VertexPointMap>& simplifier,
  const std::vector<typename Silhouette_simplifier_3<TriangleMesh, VertexPointMap>::View>& views,
  const Silhouette_frames_options& options = Silhouette_frames_options())
{
  std::vector<Silhouette_frame> out(views.size());
  simplify_silhouette_frames<ConcurrencyTag>(simplifier, views, options,
                                             [&out](std::size_t i, Silhouette_frame& f) { out[i] = std::move(f); });
  return out;
}

} // namespace Silhouette_simplification_3
} // namespace CGAL

#endif // CGAL_SILHOUETTE_SIMPLIFICATION_3_SILHOUETTE_FRAMES_H
