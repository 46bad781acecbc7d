// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One step of the vertex-oriented schedule (vertex_oriented_propagation.h): the windows waiting on a halfedge g
// cross g's face as a batch (the rules of Qin et al. 2016, see that file):
//
//   1. the ends on the vertices A = source(g) and B = target(g) give them a value; each window is trimmed where A,
//      B or the opposite vertex C (its distance plus a straight segment) beats it;
//   2. the windows of the batch are trimmed against each other (copies of one distance function are joined;
//      with a merge tolerance, similar functions are merged);
//   3. each window gives C a value (straight, or through its nearer end), and the best of them splits the face;
//   4. each window's part left of the split goes on to the edge A-C, its part right of it to the edge B-C, as one
//      child each, with the same pseudo-source.
//
// The batch does nothing itself: it reads vertex distances from a Sink and reports to it (vertex values with how
// they were reached, children, counters). The sequential schedule's sink acts at once; the parallel schedule's
// sink buffers, so that batches of one round can run on several threads and their results be applied afterwards
// in a fixed order. Both see the batch's own values at A, B and C at once, so one batch computes the same thing
// in both.
//
// A Sink provides
//   FT distance(Index v);                      // the current value of v (an upper bound of its distance)
//   void lower(Index v, const FT& d, const Window& w, Index g, const FT& at);
//                                              // v is reached with d: straight from v to the point `at` of g's edge,
//                                              // then straight to w's pseudo-source (the window, in g's frame)
//   void child(Index t, const Window& w);      // w now waits on halfedge t (in t's frame)
//   void propagated(std::size_t n); void pruned(); void merged();   // counters
//   bool has_bound(); void bound_trim(Index g, Window& w, const FT& L) // the point queries' extra trim (or no-op)
//   void face_sources_in(Index g, const Window* begin, const Window* end)  // ditto: candidates at face sources

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_BATCH_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_BATCH_H

#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>
#include <CGAL/Polyhedral_geodesics_3/internal/geodesic_window.h>
#include <CGAL/Polyhedral_geodesics_3/internal/vertex_oriented_window_lists.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

template <class FT>
class Vertex_oriented_batch
{
public:
  typedef Geodesic_mesh<FT> Mesh;
  typedef typename Mesh::Index Index;
  typedef Vertex_oriented_window<FT> Window;

  // The parameters shared by every batch of a run.
  struct Settings
  {
    FT unreached, relative_tolerance, merge_tolerance, limit;
    bool has_limit;
  };

  explicit Vertex_oriented_batch(const Mesh& mesh) : mesh_(mesh) {}

  // The windows to process; filled by the caller (Window_chunk_lists::take()).
  std::vector<Window>& windows() { return batch_; }

  static FT value_at(const Window& w, const FT& x) { return window_distance_at(x, w.sx, w.sy, w.sigma); }

  template <class Sink>
  void run(Index g, const Settings& s, Sink& sink)
  {
    const FT L = mesh_.he[std::size_t(g)].length;
    const Index va = mesh_.source(g), vb = mesh_.target(g), vc = mesh_.opposite_vertex(g);
    if(L == FT(0)) {
      // A zero-length edge is one point, an end point of both ends: the pseudo-source expansion of those (they
      // are pseudo-sources) carries every path through it.
      for(const Window& w : batch_) {
        const FT d = value_at(w, FT(0));
        sink.lower(va, d, w, g, FT(0));
        sink.lower(vb, d, w, g, FT(0));
      }
      batch_.clear();
      return;
    }
    const Point_2_ft<FT> c = mesh_.he[std::size_t(g)].opposite;
    const FT tiny = s.relative_tolerance * L;

    // 1. The ends on the vertices, and the trimming by the three vertices of the face (and by the limit).
    std::size_t kept = 0;
    for(std::size_t i = 0; i < batch_.size(); ++i) {
      Window w = batch_[i];
      if(w.b0 <= FT(0)) { w.b0 = FT(0); sink.lower(va, value_at(w, FT(0)), w, g, FT(0)); }
      if(w.b1 >= L) { w.b1 = L; sink.lower(vb, value_at(w, L), w, g, L); }
      bool keep = trim_by_vertices(w, L, c, sink.distance(va), sink.distance(vb), sink.distance(vc), s) &&
                  w.b1 - w.b0 > tiny;
      if(keep && s.has_limit && window_min_distance(w.b0, w.b1, w.sx, w.sy, w.sigma) > s.limit)
        keep = false; // every point it reaches is beyond the limit
      if(keep && sink.has_bound())
        keep = sink.bound_trim(g, w, L) && w.b1 - w.b0 > tiny;
      if(keep)
        batch_[kept++] = w;
      else
        sink.pruned();
    }
    batch_.resize(kept);
    if(batch_.empty())
      return;

    // 2. The windows of the batch against each other: joins of one distance function, then trimming.
    if(batch_.size() > 1) {
      std::sort(batch_.begin(), batch_.end(), [](const Window& a, const Window& b) { return a.b0 < b.b0; });
      dead_.assign(batch_.size(), 0);
      for(std::size_t i = 0; i < batch_.size(); ++i) {
        if(dead_[i])
          continue;
        for(std::size_t j = i + 1; j < batch_.size(); ++j) {
          if(dead_[j])
            continue;
          Window& a = batch_[i];
          Window& b = batch_[j];
          if(b.b0 > a.b1)
            break; // sorted by b0: no later window overlaps a (up to the trims made so far)
          if(same_function(a, b, s)) {
            if(b.b0 < a.b0) a.b0 = b.b0;
            if(b.b1 > a.b1) a.b1 = b.b1;
            dead_[j] = 1;
            continue;
          }
          bool keep_a, keep_b;
          trim_pair(a, b, keep_a, keep_b, s);
          keep_a = keep_a && a.b1 - a.b0 > tiny;
          keep_b = keep_b && b.b1 - b.b0 > tiny;
          if(!keep_b) {
            sink.pruned();
            dead_[j] = 1;
          }
          if(!keep_a) {
            sink.pruned();
            dead_[i] = 1;
            break;
          }
        }
      }
      kept = 0;
      for(std::size_t i = 0; i < batch_.size(); ++i)
        if(!dead_[i])
          batch_[kept++] = batch_[i];
      batch_.resize(kept);
      if(s.merge_tolerance > FT(0))
        merge_similar_windows(s, sink);
    }
    if(sink.has_bound())
      sink.face_sources_in(g, batch_.data(), batch_.data() + batch_.size());

    // 3. The value at C from each window (straight if the segment S-C crosses the window, else through the
    //    nearer end point) and the batch's best path to C, which splits the face.
    FT best = s.unreached, split = FT(0);
    std::size_t best_i = 0;
    crossing_.resize(batch_.size());
    for(std::size_t i = 0; i < batch_.size(); ++i) {
      const Window& w = batch_[i];
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
        best_i = i;
      }
    }
    if(best < s.unreached)
      sink.lower(vc, best, batch_[best_i], g, split);
    sink.propagated(batch_.size());

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
      const Window& w = batch_[i];
      const FT xc = crossing_[i];
      if(!(w.sy < FT(0)) && !(w.sx < w.b0) && !(w.sx > w.b1)) {
        // The pseudo-source is a point of the window itself (a source seen through a zero-area face): it
        // sees the whole face, and both other edges entirely.
        if(to_ac)
          emit_whole_edge(t_ac, len_ac, w, ac_x, ac_y, FT(0), FT(0), sink);
        if(to_bc)
          emit_whole_edge(t_bc, len_bc, w, bc_x, bc_y, c.x, c.y, sink);
        continue;
      }
      if(to_ac) {
        FT x1 = w.b1;
        if(xc < x1) x1 = xc;
        if(split < x1) x1 = split;
        if(x1 - w.b0 > tiny)
          emit_child(t_ac, len_ac, w, w.b0, x1, ac_x, ac_y, FT(0), FT(0), s, sink);
      }
      if(to_bc) {
        FT x0 = w.b0;
        if(xc > x0) x0 = xc;
        if(split > x0) x0 = split;
        if(w.b1 - x0 > tiny)
          emit_child(t_bc, len_bc, w, x0, w.b1, bc_x, bc_y, c.x, c.y, s, sink);
      }
    }
    batch_.clear();
  }

private:
  static bool dominated(const FT& via, const FT& d, const Settings& s) { return via + s.relative_tolerance * d < d; }

  // Removes the end parts of w beaten by the vertices of the face: A = (0, 0), B = (L, 0) and C, each with
  // its distance plus a straight segment. The beaten set of one vertex is an interval: only a prefix or a
  // suffix is cut. d0 and d1 are the window's values at its ends (kept current). False if nothing remains.
  static bool trim_by_vertices(Window& w, const FT& L, const Point_2_ft<FT>& c, const FT& da, const FT& db,
                               const FT& dc, const Settings& s)
  {
    FT d0 = value_at(w, w.b0), d1 = value_at(w, w.b1);
    if(da < s.unreached && !trim_by_vertex(w, FT(0), FT(0), da, da + w.b0, da + w.b1, d0, d1, s))
      return false;
    if(db < s.unreached && !trim_by_vertex(w, L, FT(0), db, db + (L - w.b0), db + (L - w.b1), d0, d1, s))
      return false;
    // C is at least its height c.y from every point of the edge: when that does not beat either end, the
    // exact test (two square roots) cannot either
    if(dc < s.unreached && (dominated(dc + c.y, d0, s) || dominated(dc + c.y, d1, s)) &&
       !trim_by_vertex(w, c.x, c.y, dc, dc + distance_2(c.x, c.y, w.b0, FT(0)), dc + distance_2(c.x, c.y, w.b1, FT(0)),
                       d0, d1, s))
      return false;
    return true;
  }

  // One vertex (qx, qy) with distance dq; via0 / via1 are its values at the window's ends.
  static bool trim_by_vertex(Window& w, const FT& qx, const FT& qy, const FT& dq, const FT& via0, const FT& via1,
                             FT& d0, FT& d1, const Settings& s)
  {
    const bool beaten0 = dominated(via0, d0, s), beaten1 = dominated(via1, d1, s);
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
  static void trim_pair(Window& a, Window& b, bool& keep_a, bool& keep_b, const Settings& s)
  {
    keep_a = keep_b = true;
    const FT lo = a.b0 > b.b0 ? a.b0 : b.b0;
    const FT hi = a.b1 < b.b1 ? a.b1 : b.b1;
    if(!(lo < hi))
      return;
    const FT a_lo = value_at(a, lo), b_lo = value_at(b, lo), a_hi = value_at(a, hi), b_hi = value_at(b, hi);
    const bool a0 = !(a.b0 < b.b0) && dominated(b_lo, a_lo, s), a1 = !(a.b1 > b.b1) && dominated(b_hi, a_hi, s);
    const bool b0 = !(b.b0 < a.b0) && dominated(a_lo, b_lo, s), b1 = !(b.b1 > a.b1) && dominated(a_hi, b_hi, s);
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

  static bool same_function(const Window& a, const Window& b, const Settings& s)
  {
    using std::abs;
    const FT scale = abs(a.sx) + abs(a.sy) + a.sigma + (a.b1 - a.b0);
    const FT tol = FT(16) * s.relative_tolerance * scale;
    return abs(a.sx - b.sx) <= tol && abs(a.sy - b.sy) <= tol && abs(a.sigma - b.sigma) <= tol;
  }

  // Interval merging (thesis 4.2), for Merged_window_geodesic_distances_3: a window of the batch (sorted by
  // start) absorbs the next one when their intervals touch or overlap and one of the two distance functions,
  // extended over the other's interval, lies between that function and that function plus the tolerance; of
  // two candidates the one that deviates less is kept. A kept function is never below the one it replaces, and
  // every window's values stay at or above the exact distance (the children add straight segments), so every
  // distance stays at or above the exact one. Gaps are never bridged: no bound would hold there.
  template <class Sink>
  void merge_similar_windows(const Settings& s, Sink& sink)
  {
    // the trimming moved starts: sort again, so that neighbours along the edge are neighbours in the batch
    std::sort(batch_.begin(), batch_.end(), [](const Window& a, const Window& b) { return a.b0 < b.b0; });
    std::size_t kept = 0;
    for(std::size_t i = 0; i < batch_.size(); ++i) {
      const Window b = batch_[i];
      if(kept > 0) {
        Window& a = batch_[kept - 1];
        if(!(b.b0 > a.b1) && !(a.b0 > b.b1)) { // they touch or overlap (a gap is never bridged)
          // a lobe never replaces another window's function
          const FT a_over_b = a.lobe && !b.lobe ? FT(-1)
                              : window_merge_deviation(a.sx, a.sy, a.sigma, b.sx, b.sy, b.sigma, b.b0, b.b1,
                                                       s.merge_tolerance, s.relative_tolerance);
          const FT b_over_a = b.lobe && !a.lobe ? FT(-1)
                              : window_merge_deviation(b.sx, b.sy, b.sigma, a.sx, a.sy, a.sigma, a.b0, a.b1,
                                                       s.merge_tolerance, s.relative_tolerance);
          if(a_over_b >= FT(0) || b_over_a >= FT(0)) {
            const bool keep_a = !(b_over_a >= FT(0)) || (a_over_b >= FT(0) && !(b_over_a < a_over_b));
            if(!keep_a) {
              a.sx = b.sx;
              a.sy = b.sy;
              a.sigma = b.sigma;
              a.root = b.root;
              a.lobe = b.lobe;
            }
            if(b.b0 < a.b0) a.b0 = b.b0;
            if(b.b1 > a.b1) a.b1 = b.b1;
            sink.merged();
            continue;
          }
        }
      }
      batch_[kept++] = b;
    }
    batch_.resize(kept);
  }

  // The rays from the pseudo-source of w through [x0, x1] (on g's edge) cross into the target halfedge t,
  // whose frame has its origin at (ox, oy) of g's frame and its x axis along the unit vector (ex, ey).
  template <class Sink>
  static void emit_child(Index t, const FT& len, const Window& w, const FT& x0, const FT& x1, const FT& ex,
                         const FT& ey, const FT& ox, const FT& oy, const Settings& s, Sink& sink)
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
    if(!(h1 - h0 > s.relative_tolerance * len))
      return;
    if(s.has_limit && window_min_distance(h0, h1, sx, sy, w.sigma) > s.limit) {
      sink.pruned(); // wholly beyond the limit: step 1 would drop it, after a trip through a window list
      return;
    }
    sink.child(t, Window{h0, h1, sx, sy, w.sigma, w.root, w.lobe});
  }

  template <class Sink>
  static void emit_whole_edge(Index t, const FT& len, const Window& w, const FT& ex, const FT& ey, const FT& ox,
                              const FT& oy, Sink& sink)
  {
    const FT dx = w.sx - ox, dy = w.sy - oy;
    const FT sx = ex * dx + ey * dy, sy = ex * dy - ey * dx;
    if(sy < FT(0))
      sink.child(t, Window{FT(0), len, sx, sy, w.sigma, w.root, w.lobe});
  }

  const Mesh& mesh_;
  std::vector<Window> batch_;
  std::vector<char> dead_;
  std::vector<FT> crossing_;
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_VERTEX_ORIENTED_BATCH_H
