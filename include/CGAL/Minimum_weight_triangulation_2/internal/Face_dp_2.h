// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The faces that the certain edges of the LMT-skeleton leave, and the dynamic program (Klincsek) on those
// whose boundary walk is weakly simple: W(i, j) = min_k W(i, k) + W(k, j) + the new diagonals, over the empty
// triangles whose edges are all possible and whose diagonals lie inside the face (exact in-cone tests). A face
// with an input point or an island inside has no such triangulation (every triangle must be empty), so the
// program fails there and the face is left to the LP. Face tracing sorts the certain edges around each
// vertex with exact orientations.
//
// Weakly simple faces. The walk around a face may repeat a vertex: the two sides of a dangling edge (a spike,
// walk ... a, b, a ...) or a pinch vertex where two loops of the boundary touch. The program then runs on the
// walk's positions ("corners"), not on its vertices: a position is a vertex together with the face's wedge
// there (from the direction to the next vertex of the walk counter-clockwise to the direction to the previous
// one; at a spike tip, every direction but the one back along the edge). The wedges of the occurrences of one
// vertex are disjoint. A diagonal joins two positions with different vertices and must leave both into their
// wedges. A possible edge crosses no certain edge and passes through no point, so once it leaves a corner into
// the face it stays inside until it reaches its other end, in exactly one of that vertex's wedges: the in-cone
// tests at both ends tell which occurrences it joins. Such a diagonal cuts the face (an open disc when there is
// no island) into the two faces of the sub-walks it closes, so Klincsek's recursion and its emptiness argument
// hold as for simple polygons.
//
// Every decision of the programs (which apex, which spoke) is exact for the double coordinates: the sums are
// compared in double with the forward error bound of Exact_length_sum_2.h; when the best candidate is not
// certainly below another one, the contenders are compared exactly (compare_length_sums: cancelled common
// edges, merged radicands, MPFR refinement) and the exact minimum is kept, ties broken by the smallest index.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_FACE_DP_2_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_FACE_DP_2_H

#include <CGAL/Minimum_weight_triangulation_2/internal/Exact_length_sum_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Lmt_skeleton_2.h>
#include <CGAL/Minimum_weight_triangulation_2/internal/Parallel_stage_2.h>
#include <CGAL/MDCS/concurrency.h>
#include <CGAL/MDCS/progress.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {
namespace internal {

/*!
  Faces of the certain edges, the dynamic program on the simple ones, and the face of every triangle.

  In parallel (`par`): the angular sorts, the face tracing (a face is the cycle of the next-half-edge map; it is
  numbered by its smallest half-edge, as the sequential walk numbers it) and the programs (blocks of faces, their
  triangles joined in face order). Every face's program is independent of the others.
*/
template <class P>
class Face_dp_2
{
public:
  /// `state`: the result of lmt_skeleton(); `tri`: the empty triangles (those with an impossible edge are
  /// ignored), `by_edge` their lists per edge; `max_face`: larger faces go to the LP (the programs take O(m^3)
  /// time, O(m^2) memory). `progress`, when given, hears the stage "face dynamic program" (from the calling
  /// thread only) and can cancel it (then CGAL::MDCS::Operation_cancelled is thrown).
  Face_dp_2(const P& pts, const std::vector<Edge>& edges, const Edge_index& index, const Triangle_set& tri,
            const Edge_triangles& by_edge, const std::vector<char>& state, std::size_t max_face = 400,
            const Parallel_stage& par = Parallel_stage(),
            const std::function<bool(const char*, double)>& progress = std::function<bool(const char*, double)>())
    : pts_(pts), edges_(edges), index_(index), tri_(tri), state_(state), n_(int(pts.size())), by_edge_(by_edge),
      nbr_start_(std::size_t(n_) + 1, 0)
  {
    // certain neighbours of every vertex, counter-clockwise from angle 0 (flat arrays)
    // (rows of neighbours in parallel, then sorted by angle: the directions from a vertex are distinct)
    build_sorted_rows(std::size_t(n_), edges.size(), [&](std::size_t e, auto&& add) {
      if(state[e] == lmt_certain) {
        add(edges[e].first, edges[e].second);
        add(edges[e].second, edges[e].first);
      }
    }, false, nbr_start_, nbr_, par);
    par.for_blocks(std::size_t(n_), 4096, [&](std::size_t v0, std::size_t v1, std::size_t) {
      for(int v = int(v0); v < int(v1); ++v)
        std::sort(nbr_.begin() + std::ptrdiff_t(nbr_start_[v]), nbr_.begin() + std::ptrdiff_t(nbr_start_[v + 1]),
                  [&](int a, int b) { return ccw_less(v, a, b); });
    });
    half_face_.assign(nbr_.size(), -1);
    trace_faces(par);
    // the face of each isolated point (no certain edge), found through a triangle at it: the (rare) live
    // triangles at isolated points are listed in parallel, then taken in triangle order
    std::vector<std::pair<int, int>> at_isolated;   // (triangle, isolated vertex)
    par.append_in_order(tri.size(), 1 << 14, at_isolated,
                        [&](std::size_t t0, std::size_t t1, std::vector<std::pair<int, int>>& out) {
                          for(std::size_t t = t0; t < t1; ++t) {
                            if(!is_live(int(t))) continue;
                            for(int r = 0; r < 3; ++r) {
                              const int u = tri.vertex(int(t), r);
                              if(nbr_start_[u] == nbr_start_[u + 1]) out.emplace_back(int(t), u);
                            }
                          }
                        });
    std::vector<int> inner_count(faces_.size(), 0), inner_point(faces_.size(), -1);
    std::vector<char> located(std::size_t(n_), 0);
    for(const auto& tu : at_isolated) {
      const int u = tu.second;
      if(located[u]) continue;
      const int f = face_of(tu.first);
      if(f < 0) continue;
      located[u] = 1;
      ++inner_count[f];
      inner_point[f] = u;
    }
    // the programs, blocks of faces in parallel; each block keeps its triangles and counts
    solved_.assign(faces_.size(), 0);
    struct Block_result
    {
      std::vector<int> dp_tri;
      std::size_t one_point_faces = 0, weakly_simple_faces = 0, exact_faces = 0, exact_decisions = 0;
    };
    const std::size_t face_block = 512;
    std::vector<Block_result> blocks((faces_.size() + face_block - 1) / face_block);
    const std::function<bool(const char*, double)> no_progress = [](const char*, double) { return true; };
    CGAL::MDCS::Parallel_progress<const std::function<bool(const char*, double)>> report(
      progress ? progress : no_progress, "face dynamic program", faces_.size());
    par.for_blocks(faces_.size(), face_block, [&](std::size_t f0, std::size_t f1, std::size_t b) {
      if(report.cancelled()) return;
      Face_program out{blocks[b].dp_tri, 0, 0, 0, false};
      for(std::size_t f = f0; f < f1; ++f)
        if(faces_[f].size() <= max_face) {
          out.exact = false;
          solved_[f] = solve_face(faces_[f], -1, out);
          if(!solved_[f] && inner_count[f] == 1) solved_[f] = solve_face(faces_[f], inner_point[f], out);
          if(out.exact) ++blocks[b].exact_faces;
        }
      blocks[b].one_point_faces = out.one_point_faces;
      blocks[b].weakly_simple_faces = out.weakly_simple_faces;
      blocks[b].exact_decisions = out.exact_decisions;
      report.advance(f1 - f0);
    });
    report.finish();
    std::size_t total = 0;
    for(const Block_result& r : blocks) total += r.dp_tri.size();
    dp_tri_.reserve(total);
    for(Block_result& r : blocks) {
      dp_tri_.insert(dp_tri_.end(), r.dp_tri.begin(), r.dp_tri.end());
      std::vector<int>().swap(r.dp_tri);
      one_point_faces_ += r.one_point_faces;
      weakly_simple_faces_ += r.weakly_simple_faces;
      exact_faces_ += r.exact_faces;
      exact_decisions_ += r.exact_decisions;
    }
  }

  std::size_t number_of_faces() const { return faces_.size(); }
  std::size_t number_of_solved_faces() const { return std::size_t(std::count(solved_.begin(), solved_.end(), 1)); }
  /// Triangles (indices into `tri`) chosen by the dynamic program in the solved faces.
  const std::vector<int>& dp_triangles() const { return dp_tri_; }
  std::size_t largest_face() const
  {
    std::size_t s = 0;
    for(const auto& f : faces_) s = std::max(s, f.size());
    return s;
  }

  /// Whether no edge of triangle t is impossible.
  bool is_live(int t) const
  {
    const auto& te = tri_.edges(t);
    return state_[te[0]] != lmt_impossible && state_[te[1]] != lmt_impossible && state_[te[2]] != lmt_impossible;
  }

  /// Whether triangle t (all of its edges possible) lies in a face solved by the dynamic program.
  bool in_solved_face(int t) const
  {
    const int f = face_of(t);
    return f >= 0 && solved_[f];
  }

  /// Number of faces solved with one interior point (a wheel-like face).
  std::size_t number_of_one_point_faces() const { return one_point_faces_; }
  /// Number of solved faces whose boundary walk repeats a vertex (dangling edges, pinch vertices).
  std::size_t number_of_weakly_simple_faces() const { return weakly_simple_faces_; }
  /// Faces where some decision of a program was ambiguous in double precision and taken exactly.
  std::size_t number_of_exact_faces() const { return exact_faces_; }
  /// Number of such exact decisions (all faces).
  std::size_t number_of_exact_decisions() const { return exact_decisions_; }

private:
  // the face of the certain edges that holds triangle t (all of its edges possible), -1 if all its vertices are isolated
  int face_of(int t) const
  {
    for(int r = 0; r < 3; ++r) {
      const int u = tri_.vertex(t, r), v = tri_.vertex(t, (r + 1) % 3);
      const std::size_t b0 = nbr_start_[u], b1 = nbr_start_[u + 1];
      if(b0 == b1) continue;
      // the last certain neighbour x at or before direction u->v in counter-clockwise order
      std::size_t x = b1 - 1;
      for(std::size_t k = b0; k < b1; ++k) {
        if(nbr_[k] == v || ccw_less(u, nbr_[k], v)) x = k;
        else break;
      }
      return half_face_[x];
    }
    return -1;
  }

  static int half(double dx, double dy) { return (dy > 0 || (dy == 0 && dx > 0)) ? 0 : 1; }
  // exact angular order of the directions v->a and v->b starting at angle 0
  bool ccw_less(int v, int a, int b) const
  {
    const int ha = half(pts_.x(a) - pts_.x(v), pts_.y(a) - pts_.y(v)), hb = half(pts_.x(b) - pts_.x(v), pts_.y(b) - pts_.y(v));
    if(ha != hb) return ha < hb;
    return pts_.orientation(v, a, b) > 0;
  }
  // position of the directed certain edge a -> b in the flat neighbour array
  std::size_t half_edge(int a, int b) const
  {
    for(std::size_t k = nbr_start_[a]; k < nbr_start_[a + 1]; ++k)
      if(nbr_[k] == b) return k;
    return nbr_.size();   // not reached: b is a certain neighbour of a
  }

  // The faces are the cycles of next(h): the half-edge after h = (a -> b) leaves b towards the certain neighbour
  // just before a in counter-clockwise order. A face is numbered by the rank of its smallest half-edge and its
  // vertex cycle starts there, which is what a walk over the half-edges in increasing order gives.
  void trace_faces(const Parallel_stage& par)
  {
    const std::size_t H = nbr_.size(), block = 1 << 14;
    Uninit_vector<std::size_t> next(H);   // written below for every half-edge
    Uninit_vector<int> source(H);
    par.for_blocks(std::size_t(n_), 4096, [&](std::size_t u0, std::size_t u1, std::size_t) {
      for(std::size_t u = u0; u < u1; ++u)
        for(std::size_t h = nbr_start_[u]; h < nbr_start_[u + 1]; ++h) {
          const int a = int(u), b = nbr_[h];
          const std::size_t k = half_edge(b, a), b0 = nbr_start_[b], b1 = nbr_start_[b + 1];
          next[h] = k == b0 ? b1 - 1 : k - 1;
          source[h] = a;
        }
    });
    // leaders: the smallest half-edge of each cycle; per block of half-edges, the leaders in increasing order.
    // A half-edge walks its cycle for at most `cap` steps: a smaller half-edge met means no leader, the start
    // met again means a leader. The other (long cycles only, e.g. around convex position) are settled
    // sequentially in increasing order: the first of a long cycle met is its smallest, whose walk marks it.
    const std::size_t cap = 64;
    std::vector<std::vector<std::size_t>> leaders((H + block - 1) / block), undecided(leaders.size());
    par.for_blocks(H, block, [&](std::size_t h0, std::size_t h1, std::size_t b) {
      for(std::size_t h = h0; h < h1; ++h) {
        std::size_t g = next[h], steps = 1;
        while(g != h && g > h && steps < cap) { g = next[g]; ++steps; }
        if(g == h) leaders[b].push_back(h);
        else if(g > h) undecided[b].push_back(h);
      }
    });
    for(std::size_t b = 0; b < undecided.size(); ++b) {
      bool added = false;
      for(std::size_t h : undecided[b]) {
        if(half_face_[h] != -1) continue;   // on a long cycle seen before
        std::size_t g = h;
        do { half_face_[g] = -2; g = next[g]; } while(g != h);
        leaders[b].push_back(h);
        added = true;
      }
      if(added) std::sort(leaders[b].begin(), leaders[b].end());
    }
    std::vector<std::size_t> first_id(leaders.size() + 1, 0);
    for(std::size_t b = 0; b < leaders.size(); ++b) first_id[b + 1] = first_id[b] + leaders[b].size();
    faces_.resize(first_id.back());
    par.for_blocks(leaders.size(), 1, [&](std::size_t b, std::size_t, std::size_t) {
      for(std::size_t k = 0; k < leaders[b].size(); ++k) {
        const int id = int(first_id[b] + k);
        std::vector<int>& cyc = faces_[std::size_t(id)];
        std::size_t h = leaders[b][k];
        do {
          half_face_[h] = id;
          cyc.push_back(source[h]);
          h = next[h];
        } while(h != leaders[b][k]);
      }
    });
  }

  // Whether the segment from the corner at position i of the walk F towards the vertex F[j] (F[j] != F[i])
  // starts inside the face's open wedge at that corner, which runs counter-clockwise from the direction to the
  // next vertex of the walk to the direction to the previous one. The wedge belongs to the position i, not to
  // the vertex: a vertex repeated on the walk has one (disjoint) wedge per occurrence. Exact orientations.
  bool in_cone(const std::vector<int>& F, std::size_t i, std::size_t j) const
  {
    const std::size_t m = F.size();
    const int a = F[i], b = F[j], prev = F[(i + m - 1) % m], next = F[(i + 1) % m];
    if(prev == next) {
      // spike tip (a has one certain edge, walked out and back): everything but the direction back along the
      // edge (a candidate edge passes through no point, so b is never on that ray; tested anyway)
      if(pts_.orientation(a, prev, b) != 0) return true;
      auto sign = [](double d) { return (d > 0) - (d < 0); };   // exact for differences of doubles
      return sign(pts_.x(b) - pts_.x(a)) != sign(pts_.x(prev) - pts_.x(a)) ||
             sign(pts_.y(b) - pts_.y(a)) != sign(pts_.y(prev) - pts_.y(a));
    }
    // convex corner, or straight (prev and next opposite: a half-plane): strictly between the two edges
    if(pts_.orientation(prev, a, next) >= 0) return pts_.orientation(a, b, prev) > 0 && pts_.orientation(b, a, next) > 0;
    // reflex corner: not in the closed convex angle outside the face
    return !(pts_.orientation(a, b, next) >= 0 && pts_.orientation(b, a, prev) >= 0);
  }

  // correctly rounded operations only (the error bound of Length_sum_error_bound relies on it)
  double len(int a, int b) const
  {
    const double dx = pts_.x(b) - pts_.x(a), dy = pts_.y(b) - pts_.y(a);
    return std::sqrt(dx * dx + dy * dy);
  }
  Length_segment segment(int a, int b) const { return Length_segment{{pts_.x(a), pts_.y(a), pts_.x(b), pts_.y(b)}}; }

  // alive empty counter-clockwise triangle (a, b, c), or -1
  int live_triangle(int a, int b, int c) const
  {
    const int e = index_.find(a, b);
    if(e < 0) return -1;
    // (a, b, c) counter-clockwise lies left of a -> b: side 0 of the edge when a < b, side 1 otherwise
    const int s = a < b ? 0 : 1;
    for(const int* t = by_edge_.begin(e, s); t != by_edge_.end(e, s); ++t) {
      if(tri_.apex(*t, e) != c) continue;   // c differs from a and b
      return is_live(*t) ? *t : -1;
    }
    return -1;
  }

  // The face F (its counter-clockwise boundary walk) without interior point (c < 0) or with the one interior
  // point c: Klincsek's program on the chains F[i..j] of walk positions (indices modulo m, i < j < i + m), then,
  // with c, a cyclic program over the spokes from c: consecutive spokes F[i], F[j] bound the triangle
  // (c, F[i], F[j]) and the chain F[i..j] closed by the chord F[i]F[j]. Without c the walk may be weakly simple
  // (repeated vertices, see the top of the file); the spoke program takes simple cycles only (a spoke to a
  // repeated vertex would need its own wedge test; such faces are left to the LP).
  // Where a program writes: its triangles (appended) and its counts (one per block of faces).
  struct Face_program
  {
    std::vector<int>& dp_tri;
    std::size_t one_point_faces, weakly_simple_faces, exact_decisions;
    bool exact;   // some decision of the current face was taken exactly
  };

  bool solve_face(const std::vector<int>& F, int c, Face_program& out) const
  {
    const std::size_t m = F.size();
    if(m < 3) return false;
    bool simple;
    {
      std::vector<int> s(F);
      std::sort(s.begin(), s.end());
      simple = std::adjacent_find(s.begin(), s.end()) == s.end();
      if(!simple && c >= 0) return false;   // the spoke program takes simple cycles only
      double area = 0;
      for(std::size_t i = 0; i < m; ++i)
        area += pts_.x(F[i]) * pts_.y(F[(i + 1) % m]) - pts_.x(F[(i + 1) % m]) * pts_.y(F[i]);
      if(!(area > 0)) return false;   // the outer face or an island's outline
    }
    const std::size_t L = 2 * m;   // chain (i, j): 0 <= i < m, i < j < i + m; stored at i * L + j
    auto id = [L](std::size_t i, std::size_t j) { return i * L + j; };
    auto at = [&](std::size_t i) { return F[i % m]; };
    std::vector<double> W(m * L, HUGE_VAL), dlen(m * L, -1);
    std::vector<int> K(m * L, -1);
    for(std::size_t i = 0; i < m; ++i) {
      W[id(i, i + 1)] = 0;
      dlen[id(i, i + 1)] = 0;
      for(std::size_t j = i + 2; j < i + m; ++j) {
        if(j == i + m - 1) { dlen[id(i, j)] = 0; continue; }   // the boundary edge F[i-1] F[i]
        if(at(i) == at(j)) continue;   // two occurrences of one vertex (weakly simple walk): no chord
        const int e = index_.find(at(i), at(j));
        if(e < 0 || state_[e] == lmt_impossible) continue;
        if(in_cone(F, i, j % m) && in_cone(F, j % m, i)) {
          dlen[id(i, j)] = len(at(i), at(j));
          if(!std::isfinite(dlen[id(i, j)])) return false;   // overflow: leave the face to the LP
        }
      }
    }
    // every value below is a sum of at most 2m + 2 computed lengths
    const Length_sum_error_bound err(2 * m + 2);
    // the diagonals of chain (i, j) as chosen (K final for it), appended to `out`
    auto chain_segments = [&](std::size_t i, std::size_t j, std::vector<Length_segment>& out) {
      std::vector<std::pair<std::size_t, std::size_t>> stack{{i, j}};
      while(!stack.empty()) {
        const auto ij = stack.back();
        stack.pop_back();
        if(ij.second - ij.first < 2) continue;
        if(ij.second - ij.first <= m - 2) out.push_back(segment(at(ij.first), at(ij.second)));   // else the boundary edge
        const std::size_t k = std::size_t(K[id(ij.first, ij.second)]);
        stack.emplace_back(ij.first, k);
        stack.emplace_back(k % m, k % m + (ij.second - k));
      }
    };
    // chains up to m - 1 steps (a chain of m steps would close the cycle)
    for(std::size_t d = 2; d < m; ++d)
      for(std::size_t i = 0; i < m; ++i) {
        const std::size_t j = i + d;
        if(dlen[id(i, j)] < 0) continue;
        double best = HUGE_VAL, second = HUGE_VAL;   // second: the least other live candidate near the best
        int bk = -1;
        for(std::size_t k = i + 1; k < j; ++k) {
          const std::size_t k0 = k % m;
          const std::size_t kj = k0 + (j - k);   // chain (k, j) re-based at k mod m
          if(dlen[id(i, k)] < 0 || dlen[id(k0, kj)] < 0) continue;
          const double w = W[id(i, k)] + W[id(k0, kj)];
          if(w < best) {
            if(live_triangle(at(i), at(k), at(j)) < 0) continue;
            second = best;
            best = w;
            bk = int(k);
          } else if(w < second && !err.certainly_less(best, w) && live_triangle(at(i), at(k), at(j)) >= 0)
            second = w;
        }
        if(bk >= 0 && second != HUGE_VAL && !err.certainly_less(best, second)) {
          // ambiguous in double: the exact minimum among the contenders, the smallest k on exact ties
          std::vector<Length_segment> cs, s;
          int ck = -1;
          double cw = HUGE_VAL;
          for(std::size_t k = i + 1; k < j; ++k) {
            const std::size_t k0 = k % m, kj = k0 + (j - k);
            if(dlen[id(i, k)] < 0 || dlen[id(k0, kj)] < 0) continue;
            const double w = W[id(i, k)] + W[id(k0, kj)];
            if(w == HUGE_VAL || err.certainly_less(best, w) || live_triangle(at(i), at(k), at(j)) < 0) continue;
            s.clear();
            chain_segments(i, k, s);
            chain_segments(k0, kj, s);
            if(ck < 0 || compare_length_sums(s, cs) < 0) { ck = int(k); cw = w; cs.swap(s); }
          }
          bk = ck;
          best = cw;
          out.exact = true;
          ++out.exact_decisions;
        }
        if(bk >= 0) { W[id(i, j)] = best + dlen[id(i, j)]; K[id(i, j)] = bk; }
      }
    auto emit = [&](std::size_t i, std::size_t j) {
      std::vector<std::pair<std::size_t, std::size_t>> stack{{i, j}};
      while(!stack.empty()) {
        const auto ij = stack.back();
        stack.pop_back();
        if(ij.second - ij.first < 2) continue;
        const std::size_t k = std::size_t(K[id(ij.first, ij.second)]);
        out.dp_tri.push_back(live_triangle(at(ij.first), at(k), at(ij.second)));
        stack.emplace_back(ij.first, k);
        stack.emplace_back(k % m, k % m + (ij.second - k));
      }
    };
    if(c < 0) {
      if(K[id(0, m - 1)] < 0) return false;
      emit(0, m - 1);
      if(!simple) ++out.weakly_simple_faces;
      return true;
    }
    // one interior point: spokes c F[i]; sector (i, j) = triangle (c, F[i], F[j]) + chain (i, j)
    auto sector = [&](std::size_t i, std::size_t j) {   // j - i in 1 .. m - 1
      if(W[id(i % m, i % m + (j - i))] == HUGE_VAL) return HUGE_VAL;
      if(live_triangle(c, at(i), at(j)) < 0) return HUGE_VAL;
      return W[id(i % m, i % m + (j - i))];
    };
    std::vector<double> spoke(m, -1);
    for(std::size_t i = 0; i < m; ++i) {
      const int e = index_.find(c, F[i]);
      if(e >= 0 && state_[e] != lmt_impossible) spoke[i] = len(c, F[i]);
      if(!std::isfinite(spoke[i])) return false;
    }
    // the edges of the spokes and sectors of the path 0 .. t from spoke s (prev final up to t)
    auto path_segments = [&](std::size_t s, const std::vector<int>& prev, std::size_t t, std::vector<Length_segment>& out) {
      out.push_back(segment(c, F[s]));
      while(t > 0) {
        const std::size_t u = std::size_t(prev[t]);
        if(t < m) out.push_back(segment(c, F[(s + t) % m]));
        chain_segments((s + u) % m, (s + u) % m + (t - u), out);
        t = u;
      }
    };
    double best = HUGE_VAL, best_second = HUGE_VAL;
    std::size_t best_s = 0;
    std::vector<double> D(m + 1), Dm(m, HUGE_VAL);
    std::vector<std::vector<int>> prevs(m);
    for(std::size_t s = 0; s < m; ++s) {   // s: the first spoke
      if(spoke[s] < 0) continue;
      std::vector<int>& prev = prevs[s];
      prev.assign(m + 1, -1);
      // D[t]: chain s .. s + t with spokes at both ends, t = 0 .. m
      std::fill(D.begin(), D.end(), HUGE_VAL);
      D[0] = spoke[s];
      auto step = [&](std::size_t u, std::size_t t) {
        if(D[u] == HUGE_VAL || (u == 0 && t == m)) return HUGE_VAL;
        const double w = sector(s + u, s + t);
        if(w == HUGE_VAL) return HUGE_VAL;
        return D[u] + w + (t == m ? 0 : spoke[(s + t) % m]);
      };
      for(std::size_t t = 1; t <= m; ++t) {
        if(spoke[(s + t) % m] < 0) continue;
        double second = HUGE_VAL;
        for(std::size_t u = 0; u < t; ++u) {
          const double v = step(u, t);
          if(v < D[t]) { second = D[t]; D[t] = v; prev[t] = int(u); }
          else if(v < second) second = v;
        }
        if(D[t] != HUGE_VAL && second != HUGE_VAL && !err.certainly_less(D[t], second)) {
          std::vector<Length_segment> cs, sg;
          int cu = -1;
          double cv = HUGE_VAL;
          for(std::size_t u = 0; u < t; ++u) {
            const double v = step(u, t);
            if(v == HUGE_VAL || err.certainly_less(D[t], v)) continue;
            sg.clear();
            path_segments(s, prev, u, sg);
            if(t < m) sg.push_back(segment(c, F[(s + t) % m]));
            chain_segments((s + u) % m, (s + u) % m + (t - u), sg);
            if(cu < 0 || compare_length_sums(sg, cs) < 0) { cu = int(u); cv = v; cs.swap(sg); }
          }
          prev[t] = cu;
          D[t] = cv;
          out.exact = true;
          ++out.exact_decisions;
        }
      }
      Dm[s] = D[m];
      if(D[m] < best) { best_second = best; best = D[m]; best_s = s; }
      else if(D[m] < best_second) best_second = D[m];
    }
    if(best == HUGE_VAL) return false;
    if(best_second != HUGE_VAL && !err.certainly_less(best, best_second)) {
      std::vector<Length_segment> cs, sg;
      int cs_s = -1;
      for(std::size_t s = 0; s < m; ++s) {
        if(Dm[s] == HUGE_VAL || err.certainly_less(best, Dm[s])) continue;
        sg.clear();
        path_segments(s, prevs[s], m, sg);
        if(cs_s < 0 || compare_length_sums(sg, cs) < 0) { cs_s = int(s); cs.swap(sg); }
      }
      best_s = std::size_t(cs_s);
      out.exact = true;
      ++out.exact_decisions;
    }
    const std::vector<int>& best_prev = prevs[best_s];
    for(std::size_t t = m; t > 0;) {
      const std::size_t u = std::size_t(best_prev[t]);
      const std::size_t i = best_s + u, j = best_s + t;
      out.dp_tri.push_back(live_triangle(c, at(i), at(j)));
      emit(i % m, i % m + (j - i));
      t = u;
    }
    ++out.one_point_faces;
    return true;
  }

  const P& pts_;
  const std::vector<Edge>& edges_;
  const Edge_index& index_;
  const Triangle_set& tri_;
  const std::vector<char>& state_;
  int n_;
  const Edge_triangles& by_edge_;
  std::vector<std::size_t> nbr_start_;
  Uninit_vector<int> nbr_;
  std::vector<int> half_face_;
  std::vector<std::vector<int>> faces_;
  std::vector<char> solved_;
  std::vector<int> dp_tri_;
  std::size_t one_point_faces_ = 0, weakly_simple_faces_ = 0, exact_faces_ = 0, exact_decisions_ = 0;
};

} // namespace internal
} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_FACE_DP_2_H
