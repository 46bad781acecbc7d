// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The engine behind Exact_geodesic_distances_3 (and Merged_window_geodesic_distances_3): it picks, per run, one of
// the two exact propagations.
//
// - Vertex-oriented (vertex_oriented_propagation.h): every exact run, in both memory modes, unless
//   set_vertex_oriented_full_field(false) keeps it to distances_only runs without a limit or stop targets. In
//   full_field mode it records how each vertex got its distance, and paths and point queries run from that record
//   (vertex_oriented_paths.h); distance limits and stop targets are its own.
// - Window-ordered (exact_window_propagation.h, the thesis's propagation with side lobes, which keeps the lower
//   envelope of every edge): when set_vertex_oriented_allowed(false) asks for it (the independent oracle of the
//   tests), on meshes with a zero-area face (where the vertex-oriented schedule missed paths along the line of such
//   faces), for full-field runs on meshes with a needle face (see the constructor), and for interval merging with
//   the full field, a limit or stop targets (Merged_window_geodesic_distances_3 keeps its earlier behaviour there).
//
// - The parallel schedule of the vertex-oriented engine (vertex_oriented_parallel.h): with set_parallel(true, n),
//   for the vertex-oriented runs without stop targets and without Parent records (distances_only, with or without a
//   limit); the other runs stay sequential.
//
// The facade calls clear(), then the option setters, then adds the sources: the choice is made at the first
// source, when every option is known. Both engines are built on first use only.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_EXACT_GEODESIC_ENGINE_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_EXACT_GEODESIC_ENGINE_H

#include <CGAL/Polyhedral_geodesics_3/Geodesic_types.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>
#include <CGAL/Polyhedral_geodesics_3/internal/exact_window_propagation.h>
#include <CGAL/Polyhedral_geodesics_3/internal/vertex_oriented_parallel.h>
#include <CGAL/Polyhedral_geodesics_3/internal/vertex_oriented_paths.h>
#include <CGAL/Polyhedral_geodesics_3/internal/vertex_oriented_propagation.h>

#include <array>
#include <memory>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

template <class FT>
class Exact_geodesic_engine
{
public:
  typedef Geodesic_mesh<FT> Mesh;
  typedef typename Mesh::Index Index;
  typedef Exact_window_propagation<FT> Window_engine;
  typedef Vertex_oriented_window_propagation<FT> Vertex_engine;

  explicit Exact_geodesic_engine(const Mesh& mesh) : mesh_(mesh)
  {
    // A face of zero area (three collinear corners, or a zero-length edge) makes the vertex-oriented schedule
    // miss shortest paths that run along the line of such faces: from vertex 2 of CGAL's degtri_sliding.off it
    // gave 3 at vertex 7, where the window propagation (and every small perturbation of the mesh) gives
    // sqrt(5). On such meshes every run uses the window propagation.
    has_zero_area_face_ = has_zero_area_face(mesh_);
    // The vertex-oriented schedule follows `twin` alone: an edge of three or more faces, or one whose two faces
    // run through it in the same direction (a non-orientable gluing), would be a border to it. The window
    // propagation crosses such edges into every other face (geodesic_window.h).
    has_special_edges_ = mesh_.has_special_edges();
    // Paths from the vertex-oriented records walk a straight line across faces, unfolding one face at a time;
    // through a needle (height below 1e-7 of an edge) that unfolding loses digits: on a grid with a column of
    // needles 1e-10 wide a path came out 1.8e-9 (relative) longer than its distance. The windows of the window
    // propagation keep each edge's pseudo-source instead, so full-field runs on such meshes use them.
    has_needle_face_ = has_needle_face(mesh_, FT(1e-7));
  }

  // Whether a face of `mesh` is lower than `ratio` times one of its edges.
  static bool has_needle_face(const Mesh& mesh, const FT& ratio)
  {
    for(const Geodesic_halfedge<FT>& r : mesh.he)
      if(r.opposite.y < ratio * r.length)
        return true;
    return false;
  }

  // Whether a face of `mesh` has zero area (the vertex-oriented schedule is then never used on it).
  static bool has_zero_area_face(const Mesh& mesh)
  {
    for(const Geodesic_halfedge<FT>& r : mesh.he)
      if(!(r.opposite.y > FT(0)) || r.length == FT(0))
        return true;
    return false;
  }

  void clear()
  {
    sources_.clear();
    points_from_windows_ = false;
    keep_windows_ = true;
    has_limit_ = false;
    stop_targets_.clear();
    chosen_ = false;
    use_vertex_engine_ = false;
  }

  void set_keep_windows(bool keep) { keep_windows_ = keep; }
  void set_distance_limit(FT limit) { limit_ = limit; has_limit_ = true; }
  void clear_distance_limit() { has_limit_ = false; }
  void set_stop_targets(const std::vector<Index>& targets) { stop_targets_ = targets; }
  // Interval merging (Merged_window_geodesic_distances_3): both engines merge with the same rule.
  void set_merge_tolerance(const FT& tolerance) { merge_tolerance_ = tolerance; }

  // false: every run uses the window-ordered engine (for comparisons and its statistics).
  void set_vertex_oriented_allowed(bool allowed) { vertex_oriented_allowed_ = allowed; }
  bool vertex_oriented_allowed() const { return vertex_oriented_allowed_; }
  // true (the default): the full field, distance limits and stop targets run on the vertex-oriented schedule too
  // (paths and point queries from its Parent records, vertex_oriented_paths.h). false: the window propagation
  // serves those runs (the tests' oracle and its statistics).
  void set_vertex_oriented_full_field(bool enable) { vertex_oriented_full_field_ = enable; }
  bool vertex_oriented_full_field() const { return vertex_oriented_full_field_; }
  // The parallel schedule (vertex_oriented_parallel.h) on `threads` threads (the effective count, >= 1) for the runs
  // it serves; false: the sequential schedule.
  void set_parallel(bool parallel, std::size_t threads)
  {
    parallel_ = parallel;
    threads_ = threads == 0 ? 1 : threads;
  }
  bool parallel() const { return parallel_; }
  std::size_t threads() const { return threads_; }
  // Rounds of the parallel schedule: set (> 0) before a run to change the lists per round (tests, benchmarks).
  void set_parallel_lists_per_round(std::size_t n) { lists_per_round_ = n; }
  // Measure the parallel runs (Vertex_oriented_parallel_profile, for the benchmark).
  void set_parallel_profile(bool profile) { profile_ = profile; }
  const Vertex_oriented_parallel_profile& parallel_profile() const { return parallel_profile_; }
  // Whether the last run used the parallel schedule.
  bool used_parallel_schedule() const { return used_parallel_; }

  // The engine of the last run (or of the run being prepared).
  bool uses_vertex_oriented_engine() const { return use_vertex_engine_; }

  void add_vertex_source(Index v, Index id)
  {
    choose();
    sources_.push_back(Added_source{v, {FT(0), FT(0), FT(0)}, id, true});
    if(use_vertex_engine_) vertex_engine().add_vertex_source(v, id);
    else window_engine().add_vertex_source(v, id);
  }

  void add_face_source(Index f, const std::array<FT, 3>& b, Index id)
  {
    choose();
    sources_.push_back(Added_source{f, b, id, false});
    if(use_vertex_engine_) vertex_engine().add_face_source(f, b, id);
    else window_engine().add_face_source(f, b, id);
  }

  template <class Progress>
  void run(Progress& progress)
  {
    choose();
    if(use_vertex_engine_) {
      if(paths_)
        paths_->invalidate();
      points_from_windows_ = false;
      used_parallel_ = parallel_ && !keep_windows_ && stop_targets_.empty();
      if(used_parallel_) {
        Vertex_oriented_parallel_runner<FT> runner(vertex_engine(), threads_);
        if(lists_per_round_ > 0)
          runner.set_lists_per_round(lists_per_round_);
        runner.set_profile(profile_);
        runner.run(progress);
        parallel_profile_ = runner.profile();
      } else {
        vertex_engine().run(progress);
      }
    } else {
      used_parallel_ = false;
      window_engine().run(progress);
    }
  }

  FT vertex_distance(Index v) const
  {
    return use_vertex_engine_ ? vertex_->vertex_distance(v) : windows_->vertex_distance(v);
  }

  Index vertex_source(Index v) const
  {
    return use_vertex_engine_ ? vertex_->vertex_source(v) : windows_->vertex_source(v);
  }

  // Point queries and paths (the facade checks the memory mode first).
  //
  // On the vertex-oriented records a point query runs a small second propagation (vertex_oriented_paths.h):
  // about 6 us each on 3k vertices and 0.5 ms on 38k, against 0.6-20 us from the window propagation's field,
  // which costs 3.5-13x the records run to build. So many point queries after one run pay "rent" until it would have bought the window
  // field: once the queries' windows exceed rent_factor times the run's own, the window propagation runs once
  // (same sources and options, no progress report) and answers every later point query and path to a point.
  // Vertex distances, nearest sources and paths to vertices stay those of the records. The switch depends on
  // counts only, never on time, so the answers do not depend on the machine. The point whose query made the
  // switch keeps its records answer (a distance and then a path or nearest source at one point agree bit for bit).
  Geodesic_point_distance<FT> distance_at(Index f, const std::array<FT, 3>& b)
  {
    if(!use_vertex_engine_ || (points_from_windows_ && !paths_->has_query_at(f, b)))
      return windows_->distance_at(f, b);
    const Geodesic_point_distance<FT> r = paths().distance_at(*vertex_, f, b);
    buy_window_field_when_due();
    return r;
  }

  template <class Emit>
  void trace_path(Index f, const std::array<FT, 3>& b, Emit emit)
  {
    if(!use_vertex_engine_ || (points_from_windows_ && !paths_->has_query_at(f, b))) {
      windows_->trace_path(f, b, emit);
      return;
    }
    paths().trace_path(*vertex_, f, b, emit);
    buy_window_field_when_due();
  }

  // Point queries may cost this many times the windows of the records run before the window field is built.
  static constexpr std::size_t rent_factor = 2;
  void set_point_queries_switch(bool enable) { point_queries_switch_ = enable; }
  // Whether point queries are now answered from the window field (see distance_at()).
  bool point_queries_from_windows() const { return use_vertex_engine_ && points_from_windows_; }

  const Geodesic_statistics& statistics() const
  {
    static const Geodesic_statistics none;
    if(use_vertex_engine_) return vertex_->statistics();
    return windows_ ? windows_->statistics() : none;
  }

  // The vertex-oriented engine of the last run, and the counters of the last point query's propagation (tests).
  const Vertex_engine* vertex_oriented_engine() const { return use_vertex_engine_ ? vertex_.get() : nullptr; }
  const Geodesic_statistics* last_point_query_statistics() const
  {
    return paths_ ? paths_->last_query_statistics() : nullptr;
  }

private:
  struct Added_source
  {
    Index index; // vertex or face
    std::array<FT, 3> barycentric;
    Index id;
    bool at_vertex;
  };

  void buy_window_field_when_due()
  {
    if(!point_queries_switch_ || points_from_windows_ || !paths_)
      return;
    const std::size_t run_windows = vertex_->statistics().windows_created + mesh_.number_of_vertices;
    if(paths_->query_windows_since_run() <= rent_factor * run_windows)
      return;
    Window_engine& w = prepared_window_engine(true);
    for(const Added_source& s : sources_) {
      if(s.at_vertex) w.add_vertex_source(s.index, s.id);
      else w.add_face_source(s.index, s.barycentric, s.id);
    }
    MDCS::No_progress quiet;
    w.run(quiet);
    points_from_windows_ = true;
  }

  void choose()
  {
    if(chosen_)
      return;
    chosen_ = true;
    const bool merging = merge_tolerance_ > FT(0);
    const bool needs_records = keep_windows_ || has_limit_ || !stop_targets_.empty();
    use_vertex_engine_ = vertex_oriented_allowed_ && !has_zero_area_face_ && !has_special_edges_ &&
                         !(needs_records && (merging || !vertex_oriented_full_field_)) &&
                         !(keep_windows_ && has_needle_face_);
    if(use_vertex_engine_) {
      Vertex_engine& v = vertex_engine();
      v.set_record_parents(keep_windows_);
      v.set_merge_tolerance(merge_tolerance_);
      if(has_limit_) v.set_distance_limit(limit_);
      else v.clear_distance_limit();
      v.set_stop_targets(stop_targets_);
      v.clear();
      return;
    }
    prepared_window_engine(keep_windows_);
  }

  // The window engine cleared and set to this run's options.
  Window_engine& prepared_window_engine(bool keep_windows)
  {
    Window_engine& w = window_engine();
    w.clear();
    w.set_merge_tolerance(merge_tolerance_);
    w.set_keep_windows(keep_windows);
    if(has_limit_) w.set_distance_limit(limit_);
    else w.clear_distance_limit();
    w.set_stop_targets(stop_targets_);
    return w;
  }

  Window_engine& window_engine()
  {
    if(!windows_)
      windows_.reset(new Window_engine(mesh_));
    return *windows_;
  }

  Vertex_engine& vertex_engine()
  {
    if(!vertex_)
      vertex_.reset(new Vertex_engine(mesh_));
    return *vertex_;
  }

  Vertex_oriented_paths<FT>& paths()
  {
    if(!paths_)
      paths_.reset(new Vertex_oriented_paths<FT>(mesh_));
    return *paths_;
  }

  const Mesh& mesh_;
  std::unique_ptr<Window_engine> windows_;
  std::unique_ptr<Vertex_engine> vertex_;
  std::unique_ptr<Vertex_oriented_paths<FT>> paths_;
  bool keep_windows_ = true, has_limit_ = false, chosen_ = false, use_vertex_engine_ = false;
  bool vertex_oriented_allowed_ = true, vertex_oriented_full_field_ = true;
  bool has_zero_area_face_ = false;
  bool has_needle_face_ = false;
  bool points_from_windows_ = false, point_queries_switch_ = true;
  std::vector<Added_source> sources_;
  bool has_special_edges_ = false;
  bool parallel_ = false, profile_ = false, used_parallel_ = false;
  std::size_t threads_ = 1, lists_per_round_ = 0;
  Vertex_oriented_parallel_profile parallel_profile_;
  FT limit_ = FT(0), merge_tolerance_ = FT(0);
  std::vector<Index> stop_targets_;
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_EXACT_GEODESIC_ENGINE_H
