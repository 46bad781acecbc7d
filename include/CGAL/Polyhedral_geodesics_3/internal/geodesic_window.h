// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Windows (intervals of optimality) of the exact geodesic propagation and the few formulas that act on
// them: the distance along the edge, its minimum, the change of frame between an edge's two sides, and
// the split points where two distance functions cross (thesis section 4.1.4, a quadratic).
//
// Frames. Every compact halfedge h has a planar frame: source(h) at (0,0), target(h) at (L,0), the face
// of h on the side y >= 0. A window is stored in the frame of its edge's canonical halfedge; the frame of
// the twin is the mirror image x -> L - x, y -> -y.
//
// Sides. A window lies on one side of its edge: its pseudo-source is on the side of the face of its
// `from_halfedge` (the face it crossed, or the face of the vertex or point it comes from), and it propagates into
// the face of every other halfedge of the edge: the twin on an edge of an oriented manifold, every other face of a
// non-manifold edge. Each of those faces is unfolded on its own across the edge, opposite the from face, so no
// global orientation is needed: where two faces run through the edge in the same direction (a reversed edge, as
// where a Moebius strip closes), the unfolding is the reflection y -> -y alone. Window_field::local_window()
// gives a window in the frame of any halfedge of its edge.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_GEODESIC_WINDOW_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_GEODESIC_WINDOW_H

#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

// The fields read by the sweep along an edge (b0, b1, next) come first; with FT = double a window fills
// exactly one 64-byte cache line.
template <class FT>
struct alignas(64) Geodesic_window
{
  typedef std::int32_t Index;

  FT b0, b1;     // the interval [b0, b1] on the edge, 0 <= b0 <= b1 <= L
  Index next, prev;       // neighbours on the edge, sorted by b0; -1 at the ends
  FT sx, sy;     // the pseudo-source in the edge frame
  FT sigma;      // the distance from the source to the pseudo-source
  Index edge;
  Index from_halfedge;    // the window propagates into the faces of the other halfedges of its edge; -1: into none
  Index source;           // index of the source the window's paths start from
  std::uint32_t stamp : 29; // incremented whenever the window changes or dies (lazy deletion in the queue)
  std::uint32_t filler : 1; // rooted at a point where no shortest path bends (see Window_edge_envelope::mergeable)
  std::uint32_t processed : 1; // already propagated
  std::uint32_t alive : 1;
};

// A window seen from a given halfedge's frame (a value type, no links).
template <class FT>
struct Local_window
{
  FT b0, b1, sx, sy, sigma;
};

template <class FT>
inline FT window_distance_at(const FT& x, const FT& sx, const FT& sy, const FT& sigma)
{
  using std::sqrt;
  const FT dx = x - sx;
  return sigma + sqrt(dx * dx + sy * sy);
}

// The smallest distance on the window: the foot of the pseudo-source if it falls inside, else the nearer end.
template <class FT>
inline FT window_min_distance(const FT& b0, const FT& b1, const FT& sx, const FT& sy, const FT& sigma)
{
  using std::abs;
  if(sx < b0)
    return window_distance_at(b0, sx, sy, sigma);
  if(sx > b1)
    return window_distance_at(b1, sx, sy, sigma);
  return sigma + abs(sy);
}

// Interval merging (thesis 4.2): the largest excess of the distance function w = (w_sx, w_sy, w_sigma) over
// the function n = (n_sx, n_sy, n_sigma) on n's interval [n_b0, n_b1] if n <= w <= n + tolerance there (up to
// the relative rounding allowance), else -1. The extremes of w - n are at the interval's ends or where both
// pseudo-sources are seen under the same angle: |x - a_w| |h_n| = |x - a_n| |h_w|, two linear equations. So the
// bounds are checked exactly (up to rounding), not sampled.
template <class FT>
FT window_merge_deviation(const FT& w_sx, const FT& w_sy, const FT& w_sigma, const FT& n_sx, const FT& n_sy,
                          const FT& n_sigma, const FT& n_b0, const FT& n_b1, const FT& tolerance,
                          const FT& relative_tolerance)
{
  using std::abs;
  FT xs[4];
  int count = 0;
  xs[count++] = n_b0;
  xs[count++] = n_b1;
  const FT hw = abs(w_sy), hn = abs(n_sy);
  for(int sign = -1; sign <= 1; sign += 2) {
    const FT den = hn + FT(sign) * hw;
    if(den != FT(0)) {
      const FT x = (w_sx * hn + FT(sign) * n_sx * hw) / den;
      if(n_b0 < x && x < n_b1)
        xs[count++] = x;
    }
  }
  FT worst = FT(0);
  for(int k = 0; k < count; ++k) {
    const FT dn = window_distance_at(xs[k], n_sx, n_sy, n_sigma);
    const FT diff = window_distance_at(xs[k], w_sx, w_sy, w_sigma) - dn;
    if(diff + relative_tolerance * dn < FT(0) || diff > tolerance)
      return FT(-1);
    if(diff > worst)
      worst = diff;
  }
  return worst;
}

// The smallest value of D_a - D_b on [lo, hi] for two window functions a = (a_sx, a_sy, a_sigma) and b: as above, the
// extremes of the difference are at the interval's ends or where both pseudo-sources are seen under the same angle.
template <class FT>
FT window_min_difference(const FT& a_sx, const FT& a_sy, const FT& a_sigma, const FT& b_sx, const FT& b_sy,
                         const FT& b_sigma, const FT& lo, const FT& hi)
{
  using std::abs;
  FT xs[4];
  int count = 0;
  xs[count++] = lo;
  xs[count++] = hi;
  const FT ha = abs(a_sy), hb = abs(b_sy);
  for(int sign = -1; sign <= 1; sign += 2) {
    const FT den = hb + FT(sign) * ha;
    if(den != FT(0)) {
      const FT x = (a_sx * hb + FT(sign) * b_sx * ha) / den;
      if(lo < x && x < hi)
        xs[count++] = x;
    }
  }
  FT smallest = window_distance_at(xs[0], a_sx, a_sy, a_sigma) - window_distance_at(xs[0], b_sx, b_sy, b_sigma);
  for(int k = 1; k < count; ++k) {
    const FT diff = window_distance_at(xs[k], a_sx, a_sy, a_sigma) - window_distance_at(xs[k], b_sx, b_sy, b_sigma);
    if(diff < smallest)
      smallest = diff;
  }
  return smallest;
}

template <class FT>
inline FT distance_2(const FT& ax, const FT& ay, const FT& bx, const FT& by)
{
  using std::sqrt;
  const FT dx = bx - ax, dy = by - ay;
  return sqrt(dx * dx + dy * dy);
}

// The candidate split points in (lo, hi) where sigma_w + |S_w x| = sigma_v + |S_v x| (x on the edge):
// squaring twice gives a quadratic; spurious roots are harmless because the caller decides the winner
// between consecutive split points by evaluating both functions. Writes at most two roots, returns the count.
template <class FT>
int window_crossings(const FT& aw, const FT& hw, const FT& sw, const FT& av, const FT& hv, const FT& sv,
                     const FT& lo, const FT& hi, FT roots[2])
{
  using std::sqrt;
  using std::abs;
  const FT D = sv - sw;
  const FT alpha = FT(2) * (av - aw);
  const FT beta = aw * aw + hw * hw - av * av - hv * hv;
  int n = 0;
  auto keep = [&](const FT& r) {
    if(lo < r && r < hi)
      roots[n++] = r;
  };
  if(D == FT(0)) {
    if(alpha != FT(0))
      keep(-beta / alpha);
    return n;
  }
  const FT D2 = D * D;
  const FT bd = beta - D2;
  const FT A = alpha * alpha - FT(4) * D2;
  const FT B = FT(2) * alpha * bd + FT(8) * D2 * av;
  const FT C = bd * bd - FT(4) * D2 * (av * av + hv * hv);
  if(A == FT(0)) {
    if(B != FT(0))
      keep(-C / B);
    return n;
  }
  FT disc = B * B - FT(4) * A * C;
  if(disc < FT(0)) {
    // A double root lost to rounding shows up as a slightly negative discriminant; its position
    // -B/2A is still a useful split point (the midpoint tests decide), so keep it.
    keep(-B / (FT(2) * A));
    return n;
  }
  const FT sq = sqrt(disc);
  const FT q = B >= FT(0) ? FT(-0.5) * (B + sq) : FT(-0.5) * (B - sq);
  if(q != FT(0)) {
    const FT r1 = q / A, r2 = C / q;
    if(r1 <= r2) { keep(r1); keep(r2); }
    else { keep(r2); keep(r1); }
  } else {
    keep(FT(0));
  }
  return n;
}

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_GEODESIC_WINDOW_H
