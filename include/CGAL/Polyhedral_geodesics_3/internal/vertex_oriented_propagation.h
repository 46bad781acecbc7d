// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact geodesic distances at the vertices by vertex-oriented window propagation (the scheduling of Qin et
// al., "Fast and exact discrete geodesic computation based on triangle-oriented wavefront propagation",
// SIGGRAPH 2016), the engine of the distances_only memory mode.
//
// The window-ordered engine (exact_window_propagation.h) takes every window out of a priority queue and
// keeps the lower envelope of every edge; this one keeps no envelope and no window queue:
//
// - Windows wait in a list per halfedge: the windows on its edge that will cross the face of the halfedge.
// - A priority queue holds vertices by their tentative distance. The nearest one is settled; the lists of the
//   halfedges that touch it become ready, and ready lists are propagated in FIFO order. A list that receives a
//   window while its edge touches a settled vertex is ready at once; the others wait for their first settled
//   end point. So the front advances vertex by vertex and windows cross faces in batches.
// - A list crosses its face as a batch. Each window is trimmed where a vertex of the face (its distance plus a
//   straight segment) or another window of the batch beats it (every point beyond is then reached better
//   through that vertex or window). The batch's best path to the opposite vertex C splits the face: a window
//   part left of it can only be useful on the left edge, a part right of it on the right edge (shortest paths
//   do not cross). Each part maps to one child window, with the same pseudo-source, on the edge it reaches.
// - Saddle and boundary vertices (and sources) are pseudo-sources: when settled, they emit a window over the
//   opposite edge of every incident face and their distance along every incident edge.
// - Vertex distances only decrease. A settled pseudo-source whose distance drops later is settled again, so
//   the order is label-correcting: every value is the length of a real path, every pruning compares with real
//   path lengths, and the result is the exact distance once the lists are empty, whatever the order.
//
// Only vertex distances come out: no field is stored, so there are no point queries or paths (the facade
// requires full_field for those). A distance limit and stop targets need the window order (a vertex settled
// here may still improve) and use the window-ordered engine; see Exact_geodesic_engine.h.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_PROPAGATION_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_PROPAGATION_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_types.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>
#include <CGAL/Polyhedral_geodesics_3/internal/geodesic_window.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Quaternary_heap.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

template <class FT>
class Vertex_oriented_window_propagation
{
public:
  typedef Geodesic_mesh<FT> Mesh;
  typedef typename Mesh::Index Index;

  explicit Vertex_oriented_window_propagation(const Mesh& mesh) : mesh_(mesh)
  {
    unreached_ = FT(std::numeric_limits<double>::max() / 16);
    if(std::numeric_limits<FT>::is_specialized && std::numeric_limits<FT>::epsilon() > FT(0))
      relative_tolerance_ = FT(64) * FT(std::numeric_limits<FT>::epsilon());
    else
      relative_tolerance_ = FT(0);
    const std::size_t nv = mesh_.number_of_vertices, nh = 3 * mesh_.number_of_faces;
    build_vertex_star(mesh_, star_begin_, star_);
    // Pseudo-sources: saddle and boundary vertices, and the vertices of zero-length edges (their windows are
    // single points) and of zero-area faces. (Exact_geodesic_engine does not run this schedule on meshes with
    // zero-area faces, where it missed paths along their line; the handling of such faces here is kept for the fix.)
    pseudo_source_.assign(nv, 0);
    for(std::size_t v = 0; v < nv; ++v)
      pseudo_source_[v] = is_saddle_or_boundary_vertex(mesh_, v);
    // Of those, the ones where no shortest path bends (a flat interior vertex, a boundary vertex with at most a
    // straight angle) only emit "lobes": windows that never beat the others by more than rounding. Merging (see
    // merge_similar_windows) never lets a lobe replace another window, which keeps flat meshes exact.
    lobe_vertex_.assign(nv, 0);
    const double pi = 3.14159265358979323846;
    for(std::size_t v = 0; v < nv; ++v)
      lobe_vertex_[v] = pseudo_source_[v] &&
                        !(to_double_value(mesh_.vertex_angle_sum[v]) > (mesh_.vertex_on_boundary[v] ? 1 : 2) * pi + 1e-9);
    for(std::size_t h = 0; h < nh; ++h)
      if(mesh_.he[h].length == FT(0) || !(mesh_.he[h].opposite.y > FT(0))) {
        pseudo_source_[std::size_t(mesh_.source(Index(h)))] = pseudo_source_[std::size_t(mesh_.target(Index(h)))] = 1;
        lobe_vertex_[std::size_t(mesh_.source(Index(h)))] = lobe_vertex_[std::size_t(mesh_.target(Index(h)))] = 0;
      }
    clear();
  }

  void clear()
  {
    const std::size_t nv = mesh_.number_of_vertices, nh = 3 * mesh_.number_of_faces;
    dist_.assign(nv, unreached_);
    vertex_source_.assign(nv, -1);
    stamp_.assign(nv, 0);
    state_.assign(nv, OUTSIDE);
    is_source_.assign(nv, 0);
    settled_once_.assign(nv, 0);
    head_.assign(nh, -1);
    queued_.assign(nh, 0);
    pool_.clear();
    next_.clear();
    free_.clear();
    heap_.clear();
    fifo_.clear();
    live_ = 0;
    stats_ = Geodesic_statistics();
  }

  // The facade's options: this engine serves distances_only runs without a limit or stop targets only.
  void set_keep_windows(bool keep)
  {
    if(keep)
      throw std::logic_error("CGAL::Polyhedral_geodesics_3: the vertex-oriented engine keeps no field");
  }

  // Approximation by interval merging (absolute tolerance; 0: exact). See merge_similar_windows().
  void set_merge_tolerance(const FT& tolerance) { merge_tolerance_ = tolerance; }

  void add_vertex_source(Index v, Index id)
  {
    if(v < 0 || std::size_t(v) >= mesh_.number_of_vertices)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: source vertex not in the mesh");
    is_source_[std::size_t(v)] = 1;
    update_vertex(v, FT(0), id);
  }

  void add_face_source(Index f, const std::array<FT, 3>& b, Index id)
  {
    if(f < 0 || std::size_t(f) >= mesh_.number_of_faces)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: source face not in the mesh");
    int zeros = 0;
    for(int k = 0; k < 3; ++k)
      if(b[std::size_t(k)] == FT(0))
        ++zeros;
    if(zeros >= 2) {
      for(int k = 0; k < 3; ++k)
        if(b[std::size_t(k)] != FT(0))
          return add_vertex_source(mesh_.source(3 * f + k), id);
    }
    add_point_source_in_face(f, b, id);
    if(zeros == 1) {
      // On an edge: the point is also a source inside the face on the other side.
      int k = 0;
      while(b[std::size_t((k + 2) % 3)] != FT(0))
        ++k;
      const Index g = 3 * f + k;
      const Index tw = mesh_.he[std::size_t(g)].twin;
      if(tw >= 0) {
        std::array<FT, 3> b2 = {FT(0), FT(0), FT(0)};
        b2[std::size_t(tw % 3)] = b[std::size_t((k + 1) % 3)];       // source(tw) == target(g)
        b2[std::size_t((tw % 3 + 1) % 3)] = b[std::size_t(k)];       // target(tw) == source(g)
        add_point_source_in_face(Mesh::face_of(tw), b2, id);
      }
    }
  }

  template <class Progress>
  void run(Progress& progress)
  {
    const char* stage = "geodesic propagation";
    if(!progress(stage, 0.0))
      throw MDCS::Operation_cancelled(stage);
    std::size_t pops = 0, settled = 0;
    do {
      while(!heap_.empty()) {
        const Heap_entry top = heap_.pop();
        const std::size_t v = std::size_t(top.vertex);
        if(top.stamp != stamp_[v] || state_[v] == INSIDE)
          continue;
        if(!settled_once_[v]) {
          settled_once_[v] = 1;
          ++settled;
        }
        state_[v] = INSIDE;
        if(pseudo_source_[v] || is_source_[v])
          expand_vertex(top.vertex);
        for(Index k = star_begin_[v]; k < star_begin_[v + 1]; ++k) {
          const Index h = star_[std::size_t(k)];
          make_ready(h);
          make_ready(Mesh::prev(h));
        }
        while(fifo_head_ < fifo_.size())
          process_list(fifo_[fifo_head_++]);
        fifo_.clear();
        fifo_head_ = 0;
        if((++pops & 0x3FFF) == 0) {
          const double fraction = dist_.empty() ? 1.0 : double(settled) / double(dist_.size());
          if(!progress(stage, fraction < 1.0 ? fraction : 1.0))
            throw MDCS::Operation_cancelled(stage);
        }
      }
    } while(expand_stranded_neighbours());
    stats_.stored_windows = 0;
    note_memory();
    std::vector<Window>().swap(pool_);
    std::vector<Index>().swap(next_);
    std::vector<Index>().swap(free_);
    heap_.release();
    if(!progress(stage, 1.0))
      throw MDCS::Operation_cancelled(stage);
  }

  FT vertex_distance(Index v) const
  {
    return dist_[std::size_t(v)] >= unreached_ ? FT(std::numeric_limits<double>::infinity()) : dist_[std::size_t(v)];
  }

  Index vertex_source(Index v) const { return vertex_source_[std::size_t(v)]; }

  const Geodesic_statistics& statistics() const { return stats_; }

private:
  enum State : char { OUTSIDE = 0, FRONT = 1, INSIDE = 2 };

  // A window waiting on halfedge g: the interval [b0, b1] of g's edge and the pseudo-source in g's frame
  // (source(g) at the origin, target(g) at (L, 0), g's face on the side y >= 0, the pseudo-source below).
  struct Window
  {
    FT b0, b1, sx, sy, sigma;
    Index source;
    bool lobe; // emitted by a vertex where no shortest path bends (see lobe_vertex_), or a descendant of one
  };

  struct Heap_entry
  {
    FT key;
    Index vertex;
    std::uint32_t stamp;
  };

  // ------------------------------------------------------------------------------------------------
  // Vertices

  void update_vertex(Index v, const FT& d, Index source)
  {
    const std::size_t i = std::size_t(v);
    if(!(d < dist_[i]))
      return;
    dist_[i] = d;
    vertex_source_[i] = source;
    ++stats_.vertex_updates;
    if(state_[i] == INSIDE) {
      // Settled already: only a pseudo-source has to act on the lower value (emit its windows again).
      if(!(pseudo_source_[i] || is_source_[i]))
        return;
      state_[i] = FRONT;
    } else {
      state_[i] = FRONT;
    }
    heap_.push(Heap_entry{d, v, ++stamp_[i]});
  }

  // A safety net for merging (and for any rounding accident): a vertex left unreached next to a reached one.
  // With merging, the vertex values that trim the windows are upper bounds, not exact distances, so the
  // argument that a trimmed part is covered by another window no longer holds everywhere: measured, one vertex
  // of 37,706 at a tolerance of 1 edge length on bunny00 (never below 0.3). Its reached neighbours are then
  // expanded as pseudo-sources (real paths through them: the values stay upper bounds) and the propagation
  // goes on. Returns false if there was nothing to do (an exact run on a connected mesh: one scan).
  bool expand_stranded_neighbours()
  {
    const bool any = expand_reached_neighbours_of_unreached(mesh_, star_begin_, star_, dist_, unreached_,
                                                            [this](Index w) { expand_vertex(w); });
    if(any)
      ++stats_.stranded_expansions;
    return any;
  }

  // The vertex as a pseudo-source with its current distance: its distance along every incident edge, and a
  // window over the opposite edge of every incident face, crossing into the face beyond.
  void expand_vertex(Index v)
  {
    const FT d = dist_[std::size_t(v)];
    const Index id = vertex_source_[std::size_t(v)];
    for(Index k = star_begin_[std::size_t(v)]; k < star_begin_[std::size_t(v) + 1]; ++k) {
      const Index h = star_[std::size_t(k)]; // source(h) == v
      update_vertex(mesh_.target(h), d + mesh_.he[std::size_t(h)].length, id);
      const Index hp = Mesh::prev(h);
      update_vertex(mesh_.source(hp), d + mesh_.he[std::size_t(hp)].length, id);
      const Index g = Mesh::next(h);         // the edge opposite v in the face of h
      const Index t = mesh_.he[std::size_t(g)].twin;
      if(t < 0)
        continue;
      const FT L = mesh_.he[std::size_t(g)].length;
      const Point_2_ft<FT>& p = mesh_.he[std::size_t(g)].opposite; // v in g's frame
      add_window(t, FT(0), L, L - p.x, -p.y, d, id, lobe_vertex_[std::size_t(v)] && !is_source_[std::size_t(v)]);
    }
  }

  void add_point_source_in_face(Index f, const std::array<FT, 3>& b, Index id)
  {
    for(int k = 0; k < 3; ++k) {
      const Index g = 3 * f + k;
      const FT L = mesh_.he[std::size_t(g)].length;
      const Point_2_ft<FT>& c = mesh_.he[std::size_t(g)].opposite;
      // the point in g's frame: corners source(g) = k at (0,0), target(g) = k+1 at (L,0), k+2 at c
      const FT px = b[std::size_t((k + 1) % 3)] * L + b[std::size_t((k + 2) % 3)] * c.x;
      const FT py = b[std::size_t((k + 2) % 3)] * c.y;
      update_vertex(mesh_.source(g), distance_2(FT(0), FT(0), px, py), id);
      if(b[std::size_t((k + 2) % 3)] == FT(0))
        continue; // on this edge: its other side is a face source of its own (see add_face_source)
      const Index t = mesh_.he[std::size_t(g)].twin;
      if(t >= 0)
        add_window(t, FT(0), L, L - px, -py, FT(0), id, false);
    }
  }

  // ------------------------------------------------------------------------------------------------
  // Window lists

  void add_window(Index g, const FT& b0, const FT& b1, const FT& sx, const FT& sy, const FT& sigma, Index source,
                  bool lobe)
  {
    Index wi;
    if(!free_.empty()) {
      wi = free_.back();
      free_.pop_back();
    } else {
      wi = Index(pool_.size());
      pool_.emplace_back();
      next_.push_back(-1);
    }
    Window& w = pool_[std::size_t(wi)];
    w.b0 = b0;
    w.b1 = b1;
    w.sx = sx;
    w.sy = sy;
    w.sigma = sigma;
    w.source = source;
    w.lobe = lobe;
    next_[std::size_t(wi)] = head_[std::size_t(g)];
    head_[std::size_t(g)] = wi;
    ++stats_.windows_created;
    if(++live_ > stats_.peak_live_windows)
      stats_.peak_live_windows = live_;
    if(!queued_[std::size_t(g)] &&
       (state_[std::size_t(mesh_.source(g))] == INSIDE || state_[std::size_t(mesh_.target(g))] == INSIDE)) {
      queued_[std::size_t(g)] = 1;
      fifo_.push_back(g);
    }
  }

  void free_window(Index wi)
  {
    free_.push_back(wi);
    --live_;
  }

  void make_ready(Index g)
  {
    if(head_[std::size_t(g)] >= 0 && !queued_[std::size_t(g)]) {
      queued_[std::size_t(g)] = 1;
      fifo_.push_back(g);
    }
  }

  bool dominated(const FT& via, const FT& d) const { return via + relative_tolerance_ * d < d; }

  static FT value_at(const Window& w, const FT& x) { return window_distance_at(x, w.sx, w.sy, w.sigma); }

  // Removes the end parts of w beaten by the vertices of the face: A = (0, 0), B = (L, 0) and C, each with
  // its distance plus a straight segment. The beaten set of one vertex is an interval: only a prefix or a
  // suffix is cut. d0 and d1 are the window's values at its ends (kept current). False if nothing remains.
  bool trim_by_vertices(Window& w, const FT& L, const Point_2_ft<FT>& c, const FT& da, const FT& db, const FT& dc) const
  {
    FT d0 = value_at(w, w.b0), d1 = value_at(w, w.b1);
    if(da < unreached_ && !trim_by_vertex(w, FT(0), FT(0), da, da + w.b0, da + w.b1, d0, d1))
      return false;
    if(db < unreached_ && !trim_by_vertex(w, L, FT(0), db, db + (L - w.b0), db + (L - w.b1), d0, d1))
      return false;
    // C is at least its height c.y from every point of the edge: when that does not beat either end, the
    // exact test (two square roots) cannot either
    if(dc < unreached_ && (dominated(dc + c.y, d0) || dominated(dc + c.y, d1)) &&
       !trim_by_vertex(w, c.x, c.y, dc, dc + distance_2(c.x, c.y, w.b0, FT(0)), dc + distance_2(c.x, c.y, w.b1, FT(0)), d0, d1))
      return false;
    return true;
  }

  // One vertex (qx, qy) with distance dq; via0 / via1 are its values at the window's ends.
  bool trim_by_vertex(Window& w, const FT& qx, const FT& qy, const FT& dq, const FT& via0, const FT& via1,
                      FT& d0, FT& d1) const
  {
    const bool beaten0 = dominated(via0, d0), beaten1 = dominated(via1, d1);
    if(!beaten0 && !beaten1)
      return true;
    FT roots[2];
    const int n = window_crossings(w.sx, w.sy, w.sigma, qx, qy, dq, w.b0, w.b1, roots);
    if(beaten0 && beaten1)
      return n >= 2; // beaten everywhere, unless only the middle survives (then keep it whole)
    if(n == 0)
      return true;   // rounding: the ends disagree but no crossing was found
    if(beaten0) {
      w.b0 = roots[0];
      d0 = value_at(w, w.b0);
    } else {
      w.b1 = roots[n - 1];
      d1 = value_at(w, w.b1);
    }
    return w.b0 < w.b1;
  }

  // Removes from a and b the end parts where the other one is lower (on their overlap). The beaten part of
  // a window at one of its ends runs to the first crossing of the two functions (or to the end of the
  // overlap). Sets keep_a / keep_b to false when nothing of that window remains.
  void trim_pair(Window& a, Window& b, bool& keep_a, bool& keep_b) const
  {
    keep_a = keep_b = true;
    const FT lo = a.b0 > b.b0 ? a.b0 : b.b0;
    const FT hi = a.b1 < b.b1 ? a.b1 : b.b1;
    if(!(lo < hi))
      return;
    const FT a_lo = value_at(a, lo), b_lo = value_at(b, lo), a_hi = value_at(a, hi), b_hi = value_at(b, hi);
    const bool a0 = !(a.b0 < b.b0) && dominated(b_lo, a_lo), a1 = !(a.b1 > b.b1) && dominated(b_hi, a_hi);
    const bool b0 = !(b.b0 < a.b0) && dominated(a_lo, b_lo), b1 = !(b.b1 > a.b1) && dominated(a_hi, b_hi);
    if(!(a0 || a1 || b0 || b1))
      return;
    FT roots[2];
    const int n = window_crossings(a.sx, a.sy, a.sigma, b.sx, b.sy, b.sigma, lo, hi, roots);
    keep_a = cut_beaten_ends(a, a0, a1, n, roots, lo, hi);
    keep_b = cut_beaten_ends(b, b0, b1, n, roots, lo, hi);
  }

  // w is beaten at its start (beaten0) and/or at its end (beaten1), inside the overlap [lo, hi]; the two
  // functions cross at roots[0..n).
  static bool cut_beaten_ends(Window& w, bool beaten0, bool beaten1, int n, const FT roots[2], const FT& lo, const FT& hi)
  {
    if(beaten0 && beaten1)
      return n >= 2; // beaten everywhere, unless only the middle survives (then keep it whole)
    if(beaten0) {
      if(n > 0) w.b0 = roots[0];
      else if(hi < w.b1) w.b0 = hi;
      else return true; // rounding: the ends disagree but no crossing was found
    } else if(beaten1) {
      if(n > 0) w.b1 = roots[n - 1];
      else if(lo > w.b0) w.b1 = lo;
      else return true;
    }
    return w.b0 < w.b1;
  }

  bool same_function(const Window& a, const Window& b) const
  {
    using std::abs;
    const FT scale = abs(a.sx) + abs(a.sy) + a.sigma + (a.b1 - a.b0);
    const FT tol = FT(16) * relative_tolerance_ * scale;
    return abs(a.sx - b.sx) <= tol && abs(a.sy - b.sy) <= tol && abs(a.sigma - b.sigma) <= tol;
  }

  // The windows of list g cross the face of g.
  void process_list(Index g)
  {
    queued_[std::size_t(g)] = 0;
    batch_.clear();
    // the links live apart from the windows: walking them stays in cache, and the windows' own loads
    // (known indices) can then overlap
    for(Index wi = head_[std::size_t(g)]; wi >= 0; wi = next_[std::size_t(wi)])
      batch_.push_back(wi);
    head_[std::size_t(g)] = -1;

    const FT L = mesh_.he[std::size_t(g)].length;
    const Index va = mesh_.source(g), vb = mesh_.target(g), vc = mesh_.opposite_vertex(g);
    if(L == FT(0)) {
      // A zero-length edge is one point, an end point of both ends: the pseudo-source expansion of those
      // (see the constructor) carries every path through it.
      for(Index wi : batch_) {
        const Window& w = pool_[std::size_t(wi)];
        const FT d = value_at(w, FT(0));
        update_vertex(va, d, w.source);
        update_vertex(vb, d, w.source);
        free_window(wi);
      }
      return;
    }
    const Point_2_ft<FT> c = mesh_.he[std::size_t(g)].opposite;
    const FT tiny = relative_tolerance_ * L;

    // 1. The ends on the vertices, and the trimming by the three vertices of the face.
    std::size_t kept = 0;
    for(Index wi : batch_) {
      Window& w = pool_[std::size_t(wi)];
      if(w.b0 <= FT(0)) { w.b0 = FT(0); update_vertex(va, value_at(w, FT(0)), w.source); }
      if(w.b1 >= L) { w.b1 = L; update_vertex(vb, value_at(w, L), w.source); }
      if(trim_by_vertices(w, L, c, dist_[std::size_t(va)], dist_[std::size_t(vb)], dist_[std::size_t(vc)]) &&
         w.b1 - w.b0 > tiny) {
        batch_[kept++] = wi;
      } else {
        ++stats_.windows_pruned;
        free_window(wi);
      }
    }
    batch_.resize(kept);
    if(batch_.empty())
      return;

    // 2. The windows of the batch against each other: joins of one distance function, then trimming.
    if(batch_.size() > 1) {
      std::sort(batch_.begin(), batch_.end(),
                [&](Index a, Index b) { return pool_[std::size_t(a)].b0 < pool_[std::size_t(b)].b0; });
      for(std::size_t i = 0; i < batch_.size(); ++i) {
        if(batch_[i] < 0)
          continue;
        for(std::size_t j = i + 1; j < batch_.size(); ++j) {
          if(batch_[j] < 0)
            continue;
          Window& a = pool_[std::size_t(batch_[i])];
          Window& b = pool_[std::size_t(batch_[j])];
          if(b.b0 > a.b1)
            break; // sorted by b0: no later window overlaps a (up to the trims made so far)
          if(same_function(a, b)) {
            if(b.b0 < a.b0) a.b0 = b.b0;
            if(b.b1 > a.b1) a.b1 = b.b1;
            free_window(batch_[j]);
            batch_[j] = -1;
            continue;
          }
          bool keep_a, keep_b;
          trim_pair(a, b, keep_a, keep_b);
          keep_a = keep_a && a.b1 - a.b0 > tiny;
          keep_b = keep_b && b.b1 - b.b0 > tiny;
          if(!keep_b) {
            ++stats_.windows_pruned;
            free_window(batch_[j]);
            batch_[j] = -1;
          }
          if(!keep_a) {
            ++stats_.windows_pruned;
            free_window(batch_[i]);
            batch_[i] = -1;
            break;
          }
        }
      }
      kept = 0;
      for(Index wi : batch_)
        if(wi >= 0)
          batch_[kept++] = wi;
      batch_.resize(kept);
      if(merge_tolerance_ > FT(0))
        merge_similar_windows();
    }

    // 3. The value at C from each window (straight if the segment S-C crosses the window, else through the
    //    nearer end point) and the batch's best path to C, which splits the face.
    FT best = unreached_, split = FT(0);
    Index best_source = -1;
    crossing_.resize(batch_.size());
    for(std::size_t i = 0; i < batch_.size(); ++i) {
      const Window& w = pool_[std::size_t(batch_[i])];
      const FT denom = c.y - w.sy;
      // where the line from S to C crosses the edge's line; S on that line (a degenerate face): at S
      const FT xc = denom > FT(0) ? w.sx + (c.x - w.sx) * (-w.sy) / denom : w.sx;
      crossing_[i] = xc;
      FT dc, at;
      if(xc < w.b0) { dc = value_at(w, w.b0) + distance_2(w.b0, FT(0), c.x, c.y); at = w.b0; }
      else if(xc > w.b1) { dc = value_at(w, w.b1) + distance_2(w.b1, FT(0), c.x, c.y); at = w.b1; }
      else { dc = w.sigma + distance_2(w.sx, w.sy, c.x, c.y); at = xc; }
      if(dc < best) {
        best = dc;
        split = at;
        best_source = w.source;
      }
    }
    update_vertex(vc, best, best_source);

    // 4. Children: rays through [b0, min(xc, split)] reach the edge A-C, rays through [max(xc, split), b1]
    //    the edge B-C (only the parts on the side of the split that the rays reach are useful).
    const Index h_ca = Mesh::prev(g), h_bc = Mesh::next(g);
    const Index t_ac = mesh_.he[std::size_t(h_ca)].twin, t_bc = mesh_.he[std::size_t(h_bc)].twin;
    const FT len_ac = mesh_.he[std::size_t(h_ca)].length, len_bc = mesh_.he[std::size_t(h_bc)].length;
    // the frames of the targets: t_ac has A at the origin and C at (len_ac, 0); t_bc has C at the origin and
    // B at (len_bc, 0); the face of g is below both
    const bool to_ac = t_ac >= 0 && len_ac > FT(0), to_bc = t_bc >= 0 && len_bc > FT(0);
    const FT ac_x = to_ac ? c.x / len_ac : FT(0), ac_y = to_ac ? c.y / len_ac : FT(0);
    const FT bc_x = to_bc ? (L - c.x) / len_bc : FT(0), bc_y = to_bc ? -c.y / len_bc : FT(0);
    for(std::size_t i = 0; i < batch_.size(); ++i) {
      const Index wi = batch_[i];
      const Window w = pool_[std::size_t(wi)];
      free_window(wi);
      ++stats_.windows_propagated;
      const FT xc = crossing_[i];
      if(!(w.sy < FT(0)) && !(w.sx < w.b0) && !(w.sx > w.b1)) {
        // The pseudo-source is a point of the window itself (a source seen through a zero-area face): it
        // sees the whole face, and both other edges entirely.
        if(to_ac)
          emit_whole_edge(t_ac, len_ac, w, ac_x, ac_y, FT(0), FT(0));
        if(to_bc)
          emit_whole_edge(t_bc, len_bc, w, bc_x, bc_y, c.x, c.y);
        continue;
      }
      if(to_ac) {
        FT x1 = w.b1;
        if(xc < x1) x1 = xc;
        if(split < x1) x1 = split;
        if(x1 - w.b0 > tiny)
          emit_child(t_ac, len_ac, w, w.b0, x1, ac_x, ac_y, FT(0), FT(0));
      }
      if(to_bc) {
        FT x0 = w.b0;
        if(xc > x0) x0 = xc;
        if(split > x0) x0 = split;
        if(w.b1 - x0 > tiny)
          emit_child(t_bc, len_bc, w, x0, w.b1, bc_x, bc_y, c.x, c.y);
      }
    }
  }

  // Interval merging (thesis 4.2), for Merged_window_geodesic_distances_3: a window of the batch (sorted by
  // start) absorbs the next one when their intervals touch or overlap and one of the two distance functions,
  // extended over the other's interval, lies between that function and that function plus the tolerance; of
  // two candidates the one that deviates less is kept. A kept function is never below the one it replaces, and
  // every window's values stay at or above the exact distance (the children add straight segments), so every
  // distance stays at or above the exact one. Gaps are never bridged: no bound would hold there.
  void merge_similar_windows()
  {
    // the trimming moved starts: sort again, so that neighbours along the edge are neighbours in the batch
    std::sort(batch_.begin(), batch_.end(),
              [&](Index a, Index b) { return pool_[std::size_t(a)].b0 < pool_[std::size_t(b)].b0; });
    std::size_t kept = 0;
    for(std::size_t i = 0; i < batch_.size(); ++i) {
      const Index wi = batch_[i];
      if(kept > 0) {
        Window& a = pool_[std::size_t(batch_[kept - 1])];
        const Window& b = pool_[std::size_t(wi)];
        if(!(b.b0 > a.b1) && !(a.b0 > b.b1)) { // they touch or overlap (a gap is never bridged)
          // a lobe never replaces another window's function
          const FT a_over_b = a.lobe && !b.lobe ? FT(-1)
                              : window_merge_deviation(a.sx, a.sy, a.sigma, b.sx, b.sy, b.sigma, b.b0, b.b1,
                                                       merge_tolerance_, relative_tolerance_);
          const FT b_over_a = b.lobe && !a.lobe ? FT(-1)
                              : window_merge_deviation(b.sx, b.sy, b.sigma, a.sx, a.sy, a.sigma, a.b0, a.b1,
                                                       merge_tolerance_, relative_tolerance_);
          if(a_over_b >= FT(0) || b_over_a >= FT(0)) {
            const bool keep_a = !(b_over_a >= FT(0)) || (a_over_b >= FT(0) && !(b_over_a < a_over_b));
            if(!keep_a) {
              a.sx = b.sx;
              a.sy = b.sy;
              a.sigma = b.sigma;
              a.source = b.source;
              a.lobe = b.lobe;
            }
            if(b.b0 < a.b0) a.b0 = b.b0;
            if(b.b1 > a.b1) a.b1 = b.b1;
            free_window(wi);
            ++stats_.windows_merged;
            continue;
          }
        }
      }
      batch_[kept++] = wi;
    }
    batch_.resize(kept);
  }

  // The rays from the pseudo-source of w through [x0, x1] (on g's edge) cross into the target halfedge t,
  // whose frame has its origin at (ox, oy) of g's frame and its x axis along the unit vector (ex, ey).
  void emit_child(Index t, const FT& len, const Window& w, const FT& x0, const FT& x1, const FT& ex, const FT& ey,
                  const FT& ox, const FT& oy)
  {
    // a point (px, py) of g's frame in t's frame: x' = e . (p - o), y' = e x (p - o)
    const FT dx = w.sx - ox, dy = w.sy - oy;
    const FT sx = ex * dx + ey * dy, sy = ex * dy - ey * dx;
    if(!(sy < FT(0)))
      return; // the pseudo-source is not behind the target edge (a degenerate face): no ray crosses it
    auto hit = [&](const FT& x, bool& ok) -> FT {
      const FT qx = ex * (x - ox) - ey * oy, qy = -ex * oy - ey * (x - ox);
      const FT den = qy - sy;
      if(!(den > FT(0))) {
        ok = false;
        return FT(0);
      }
      return sx + (qx - sx) * (-sy) / den;
    };
    bool ok0 = true, ok1 = true;
    FT h0 = hit(x0, ok0), h1 = hit(x1, ok1);
    if(!ok0 || !ok1)
      return;
    if(h1 < h0)
      std::swap(h0, h1);
    if(h0 < FT(0)) h0 = FT(0);
    if(h1 > len) h1 = len;
    if(!(h1 - h0 > relative_tolerance_ * len))
      return;
    add_window(t, h0, h1, sx, sy, w.sigma, w.source, w.lobe);
  }

  void emit_whole_edge(Index t, const FT& len, const Window& w, const FT& ex, const FT& ey, const FT& ox, const FT& oy)
  {
    const FT dx = w.sx - ox, dy = w.sy - oy;
    const FT sx = ex * dx + ey * dy, sy = ex * dy - ey * dx;
    if(sy < FT(0))
      add_window(t, FT(0), len, sx, sy, w.sigma, w.source, w.lobe);
  }

  void note_memory()
  {
    const std::size_t bytes = pool_.capacity() * (sizeof(Window) + sizeof(Index)) + heap_.capacity() * sizeof(Heap_entry) +
                              head_.capacity() * sizeof(Index) + queued_.capacity() + fifo_.capacity() * sizeof(Index);
    if(bytes > stats_.peak_memory_bytes)
      stats_.peak_memory_bytes = bytes;
  }

  const Mesh& mesh_;
  FT unreached_, relative_tolerance_;
  FT merge_tolerance_ = FT(0);
  std::vector<Index> star_begin_, star_;
  std::vector<char> lobe_vertex_;
  std::vector<char> pseudo_source_, is_source_, settled_once_;
  std::vector<FT> dist_;
  std::vector<Index> vertex_source_;
  std::vector<std::uint32_t> stamp_;
  std::vector<char> state_;
  std::vector<Index> head_;   // per halfedge: its waiting windows (a singly linked list in pool_)
  std::vector<char> queued_;  // per halfedge: in the FIFO of ready lists
  std::vector<Window> pool_;
  std::vector<Index> next_;   // per pool window: the next window of its list
  std::vector<Index> free_;
  Quaternary_heap<Heap_entry> heap_;
  std::vector<Index> fifo_;
  std::size_t fifo_head_ = 0;
  std::vector<Index> batch_;
  std::vector<FT> crossing_;
  std::size_t live_ = 0;
  Geodesic_statistics stats_;
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_PROPAGATION_H
