// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Construction of Plane_arrangement_3: the box cell, and the insertion of one plane, which splits every cell whose
// interior it crosses (candidates from the BSP tree, exact test on the cell's vertices), splitting the shared
// facets once and closing each pair of children with a new facet on the plane.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_PLANE_ARRANGEMENT_CONSTRUCTION_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_PLANE_ARRANGEMENT_CONSTRUCTION_3_H

#include <CGAL/MDCS/concurrency.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/internal/plane_arrangement_predicates_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

template <class Arrangement>
class Plane_arrangement_builder_3
{
  typedef typename Arrangement::Facet Facet;
  static constexpr std::uint32_t null = Arrangement::null_index;

public:
  // `threads`: for the bounding boxes of the cells an insertion creates (the independent part of an insertion).
  explicit Plane_arrangement_builder_3(Arrangement& a, std::size_t threads = 1) : a_(a), threads_(threads) {}

  void init_box()
  {
    const std::int64_t L = Arrangement::lattice_size;
    for(int t = 0; t < 3; ++t)
      for(int high = 0; high < 2; ++high) {
        Lattice_plane_3 p;
        (t == 0 ? p.a : (t == 1 ? p.b : p.c)) = 1;
        p.d = high ? -L : 0;
        a_.planes_.push_back(p);
        a_.used_.push_back(1);
        a_.plane_keys_.insert(std::array<std::int64_t, 4>{{p.a, p.b, p.c, p.d}});
      }
    for(std::uint32_t k = 0; k < 8; ++k) {
      const std::uint32_t i = k & 1, j = (k >> 1) & 1, l = (k >> 2) & 1;
      a_.vertex_planes_.push_back({{i, 2 + j, 4 + l}});
      a_.points_.push_back({{double(i * L), double(j * L), double(l * L)}});
      a_.side_epoch_.push_back(0);
      a_.side_cache_.push_back(0);
    }
    a_.cell_facets_.add_list();
    for(std::uint32_t t = 0; t < 3; ++t) {
      const std::uint32_t u = (t + 1) % 3, w = (t + 2) % 3;
      for(std::uint32_t high = 0; high < 2; ++high) {
        auto corner = [&](std::uint32_t cu, std::uint32_t cw) {
          return (high << t) | (cu << u) | (cw << w);
        };
        // Edges on the planes 2w, 2u+1, 2w+1, 2u in turn.
        std::vector<std::uint32_t> poly = {corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)};
        const std::uint32_t f = std::uint32_t(a_.facets_.size());
        a_.facets_.push_back(Facet{2 * t + high, high ? 0u : null, high ? null : 0u});
        a_.polygons_.assign(a_.polygons_.add_list(), poly.data(), poly.data() + poly.size());
        a_.cell_facets_.push_back(0, f);
      }
    }
    a_.nodes_.emplace_back();
    a_.node_of_cell_.push_back(0);
    set_leaf(0, 0);
  }

  bool insert(const Lattice_plane_3& input)
  {
    check_lattice_plane(input, a_.planes_.size() - Arrangement::number_of_walls);
    const Lattice_plane_3 p = normalized_plane(input);
    a_.planes_.push_back(p);
    a_.used_.push_back(0);
    if(!a_.plane_keys_.insert(std::array<std::int64_t, 4>{{p.a, p.b, p.c, p.d}}).second)
      return false; // a duplicate of an earlier plane or of a wall
    h_ = std::uint32_t(a_.planes_.size() - 1);
    ++a_.epoch_;
    if(a_.side_epoch_.size() < a_.vertex_planes_.size()) { // released after a construction
      a_.side_epoch_.resize(a_.vertex_planes_.size(), 0);
      a_.side_cache_.resize(a_.vertex_planes_.size(), 0);
    }
    if(a_.nodes_.empty()) rebuild_tree();
    std::vector<std::uint32_t> candidates;
    collect_candidates(p, candidates);
    bool used = false;
    for(std::uint32_t c : candidates)
      if(is_crossed(c)) {
        split_cell(c);
        used = true;
      }
    finish_leaves();
    a_.used_[h_] = used ? 1 : 0;
    split_vertices_.clear();
    return used;
  }

private:
  int side(std::uint32_t v)
  {
    if(a_.side_epoch_[v] != a_.epoch_) {
      a_.side_epoch_[v] = a_.epoch_;
      a_.side_cache_[v] = static_cast<signed char>(a_.side(v, a_.planes_[h_]));
    }
    return a_.side_cache_[v];
  }

  void collect_candidates(const Lattice_plane_3& p, std::vector<std::uint32_t>& out) const
  {
    const double c[3] = {double(p.a), double(p.b), double(p.c)};
    std::vector<std::uint32_t> stack(1, 0);
    while(!stack.empty()) {
      const typename Arrangement::Tree_node& n = a_.nodes_[stack.back()];
      stack.pop_back();
      double lo = double(p.d), hi = double(p.d);
      for(int k = 0; k < 3; ++k) {
        const double u = c[k] * double(n.lo[k]), w = c[k] * upper_bound(n.hi[k]);
        lo += (std::min)(u, w);
        hi += (std::max)(u, w);
      }
      if(lo > 0 || hi < 0) continue; // the region (inside the enlarged box) lies strictly on one side
      if(n.child[0] == null) out.push_back(n.child[1]);
      else {
        stack.push_back(n.child[0]);
        stack.push_back(n.child[1]);
      }
    }
  }

  bool is_crossed(std::uint32_t c)
  {
    bool pos = false, neg = false;
    for(const std::uint32_t* fi = a_.cell_facets_.begin(c); fi != a_.cell_facets_.end(c); ++fi) {
      const std::uint32_t* poly = a_.polygons_.begin(*fi);
      const std::size_t n = a_.polygons_.size(*fi);
      for(std::size_t k = 0; k < n; ++k) {
        const int s = side(poly[k]);
        pos = pos || s > 0;
        neg = neg || s < 0;
        if(pos && neg) return true;
      }
    }
    return false;
  }

  std::uint32_t split_vertex(std::uint32_t u, std::uint32_t v, std::uint32_t pf, std::uint32_t pe)
  {
    const std::uint64_t key = (std::uint64_t((std::min)(u, v)) << 32) | std::uint64_t((std::max)(u, v));
    auto it = split_vertices_.find(key);
    if(it != split_vertices_.end()) return it->second;
    const Exact_vertex_3 x = intersect_planes(a_.planes_[pf], a_.planes_[pe], a_.planes_[h_]);
    if(x.den == 0)
      throw std::logic_error("MDCS: Plane_arrangement_3: internal error: an edge crossed by a plane is parallel to it");
    check_size(a_.vertex_planes_.size(), "vertices");
    const std::uint32_t w = std::uint32_t(a_.vertex_planes_.size());
    a_.vertex_planes_.push_back({{pf, pe, h_}});
    a_.points_.push_back(approximate_point(x));
    a_.side_epoch_.push_back(a_.epoch_);
    a_.side_cache_.push_back(0);
    split_vertices_.emplace(key, w);
    return w;
  }

  static void check_size(std::size_t n, const char* what)
  {
    if(n + 2 >= std::size_t(null))
      throw std::invalid_argument(std::string("MDCS: Plane_arrangement_3: too many ") + what +
                                  " (32-bit indices); use fewer planes");
  }

  struct Chord
  {
    std::uint32_t a, b;
  };

  void add_chord(std::uint32_t a, std::uint32_t b)
  {
    for(const Chord& c : chords_)
      if((c.a == a && c.b == b) || (c.a == b && c.b == a)) return;
    chords_.push_back(Chord{a, b});
  }

  // A one-sided polygon adds its edge lying on the new plane, if it has one.
  void add_edge_chord(const std::vector<std::uint32_t>& poly)
  {
    const std::size_t n = poly.size();
    for(std::size_t k = 0; k < n; ++k) {
      const std::size_t j = (k + 1) % n;
      if(side(poly[k]) == 0 && side(poly[j]) == 0) add_chord(poly[k], poly[j]);
    }
  }

  void split_cell(std::uint32_t c)
  {
    check_size(a_.facets_.size() + a_.cell_facets_.size(c), "facets");
    check_size(a_.cell_facets_.size(), "cells");
    const std::uint32_t cp = std::uint32_t(a_.cell_facets_.size());
    a_.cell_facets_.add_list();
    const std::uint32_t nf = std::uint32_t(a_.facets_.size());
    a_.facets_.push_back(Facet{h_, c, cp});
    a_.polygons_.add_list();
    std::vector<std::uint32_t>& old = old_;
    old.assign(a_.cell_facets_.begin(c), a_.cell_facets_.end(c));
    std::vector<std::uint32_t>& neg = neg_;
    std::vector<std::uint32_t>& pos = pos_;
    neg.clear();
    pos.clear();
    chords_.clear();
    for(std::uint32_t f : old) {
      const std::uint32_t pf = a_.facets_[f].plane;
      poly_.assign(a_.polygons_.begin(f), a_.polygons_.end(f));
      const std::vector<std::uint32_t>& poly = poly_;
      const std::size_t n = poly.size();
      bool any_pos = false, any_neg = false;
      for(std::size_t k = 0; k < n; ++k) {
        const int s = side(poly[k]);
        any_pos = any_pos || s > 0;
        any_neg = any_neg || s < 0;
      }
      if(!any_neg || !any_pos) {
        if(!any_neg) {
          replace_cell(f, c, cp);
          pos.push_back(f);
        } else
          neg.push_back(f);
        add_edge_chord(poly);
        continue;
      }
      // Split: the polygon with the crossing vertices inserted, then its two sides.
      aug_.clear();
      for(std::size_t k = 0; k < n; ++k) {
        const std::uint32_t v = poly[k], u = poly[(k + 1) % n];
        const int s = side(v), t = side(u);
        aug_.push_back({{v, std::uint32_t(s + 1)}});
        if(s * t < 0) aug_.push_back({{split_vertex(v, u, pf, a_.common_plane(v, u, pf)), 1u}});
      }
      std::vector<std::uint32_t>& pn = pn_;
      std::vector<std::uint32_t>& pp = pp_;
      pn.clear();
      pp.clear();
      std::uint32_t zero[2] = {null, null};
      int zeros = 0;
      const std::size_t m = aug_.size();
      for(std::size_t k = 0; k < m; ++k) {
        const std::array<std::uint32_t, 2>& x = aug_[k];
        if(x[1] <= 1) pn.push_back(x[0]);
        if(x[1] >= 1) pp.push_back(x[0]);
        if(x[1] == 1) {
          if(zeros < 2) zero[zeros] = x[0];
          ++zeros;
        }
      }
      if(zeros != 2)
        throw std::logic_error("MDCS: Plane_arrangement_3: internal error: a split facet meets the plane in " +
                               std::to_string(zeros) + " vertices");
      add_chord(zero[0], zero[1]);
      const std::uint32_t g = std::uint32_t(a_.facets_.size());
      Facet piece = a_.facets_[f];
      const std::uint32_t other = piece.negative_cell == c ? piece.positive_cell : piece.negative_cell;
      if(piece.negative_cell == c) piece.negative_cell = cp;
      else piece.positive_cell = cp;
      a_.facets_.push_back(piece);
      a_.polygons_.assign(a_.polygons_.add_list(), pp.data(), pp.data() + pp.size());
      a_.polygons_.assign(f, pn.data(), pn.data() + pn.size());
      neg.push_back(f);
      pos.push_back(g);
      if(other != null) a_.cell_facets_.push_back(other, g);
    }
    // The new facet: the chords chained into a cycle.
    std::vector<std::uint32_t>& poly = poly_;
    poly.clear();
    std::vector<char> done(chords_.size(), 0);
    if(chords_.size() >= 3) {
      std::uint32_t first = chords_[0].a, next = chords_[0].b;
      poly.push_back(first);
      done[0] = 1;
      std::size_t count = 1;
      while(next != first) {
        std::size_t k = 0;
        while(k < chords_.size() && (done[k] || (chords_[k].a != next && chords_[k].b != next))) ++k;
        if(k == chords_.size()) break;
        done[k] = 1;
        ++count;
        poly.push_back(next);
        next = chords_[k].a == next ? chords_[k].b : chords_[k].a;
      }
      if(next != first || count != chords_.size()) poly.clear();
    }
    if(poly.size() < 3)
      throw std::logic_error("MDCS: Plane_arrangement_3: internal error: the section of a cell by a plane is not "
                             "a closed polygon");
    a_.polygons_.assign(nf, poly.data(), poly.data() + poly.size());
    neg.push_back(nf);
    pos.push_back(nf);
    a_.cell_facets_.assign(c, neg.data(), neg.data() + neg.size());
    a_.cell_facets_.assign(cp, pos.data(), pos.data() + pos.size());
    // The tree: the leaf of c becomes an inner node with two leaves.
    const std::uint32_t node = a_.node_of_cell_[c];
    const std::uint32_t ln = std::uint32_t(a_.nodes_.size());
    a_.nodes_.emplace_back();
    a_.nodes_.emplace_back();
    a_.nodes_[node].child[0] = ln;
    a_.nodes_[node].child[1] = ln + 1;
    a_.node_of_cell_[c] = ln;
    a_.node_of_cell_.push_back(ln + 1);
    defer_leaf(ln, c);
    defer_leaf(ln + 1, cp);
  }

  // The new leaves of an insertion get their boxes once every crossed cell is split (nothing reads them before the
  // next insertion): each box depends on its own cell only, so they are computed in parallel on large insertions,
  // with the same code and into their own nodes, hence the same tree for every thread count.
  void defer_leaf(std::uint32_t node, std::uint32_t cell)
  {
    typename Arrangement::Tree_node& n = a_.nodes_[node];
    n.child[0] = null;
    n.child[1] = cell;
    pending_leaves_.push_back({{node, cell}});
  }

  void finish_leaves()
  {
    const std::size_t n = pending_leaves_.size();
    const auto boxes = [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t k = begin; k < end; ++k) cell_box(pending_leaves_[k][1], a_.nodes_[pending_leaves_[k][0]]);
    };
    if(threads_ > 1 && n >= 1024) CGAL::MDCS::parallel_for_blocks(n, 256, threads_, boxes);
    else boxes(0, n, 0);
    pending_leaves_.clear();
  }

  void replace_cell(std::uint32_t f, std::uint32_t from, std::uint32_t to)
  {
    Facet& x = a_.facets_[f];
    if(x.negative_cell == from) x.negative_cell = to;
    else x.positive_cell = to;
  }

  // After a construction released the tree: a bounding-volume tree of the cells (median splits of their boxes'
  // centres along the longest axis). Any tree whose nodes' boxes contain their leaves' cells does.
  void rebuild_tree()
  {
    const std::size_t n = a_.cell_facets_.size();
    std::vector<std::array<std::uint16_t, 6>> boxes(n);
    for(std::size_t c = 0; c < n; ++c) {
      typename Arrangement::Tree_node t;
      cell_box(std::uint32_t(c), t);
      for(int i = 0; i < 3; ++i) {
        boxes[c][i] = t.lo[i];
        boxes[c][3 + i] = t.hi[i];
      }
    }
    std::vector<std::uint32_t> order(n);
    for(std::size_t c = 0; c < n; ++c) order[c] = std::uint32_t(c);
    a_.nodes_.clear();
    a_.nodes_.reserve(2 * n);
    a_.node_of_cell_.assign(n, null);
    build_subtree(order.data(), order.data() + n, boxes);
  }

  std::uint32_t build_subtree(std::uint32_t* b, std::uint32_t* e,
                              const std::vector<std::array<std::uint16_t, 6>>& boxes)
  {
    const std::uint32_t node = std::uint32_t(a_.nodes_.size());
    a_.nodes_.emplace_back();
    std::uint16_t lo[3] = {0xFFFF, 0xFFFF, 0xFFFF}, hi[3] = {0, 0, 0};
    for(const std::uint32_t* c = b; c != e; ++c)
      for(int i = 0; i < 3; ++i) {
        lo[i] = (std::min)(lo[i], boxes[*c][i]);
        hi[i] = (std::max)(hi[i], boxes[*c][3 + i]);
      }
    std::uint32_t child[2] = {null, *b};
    if(e - b == 1) a_.node_of_cell_[*b] = node;
    else {
      int axis = 0;
      for(int i = 1; i < 3; ++i)
        if(hi[i] - lo[i] > hi[axis] - lo[axis]) axis = i;
      std::uint32_t* mid = b + (e - b) / 2;
      std::nth_element(b, mid, e, [&](std::uint32_t x, std::uint32_t y) {
        const int cx = int(boxes[x][axis]) + int(boxes[x][3 + axis]), cy = int(boxes[y][axis]) + int(boxes[y][3 + axis]);
        return cx < cy || (cx == cy && x < y);
      });
      child[0] = build_subtree(b, mid, boxes);
      child[1] = build_subtree(mid, e, boxes);
    }
    typename Arrangement::Tree_node& t = a_.nodes_[node];
    for(int i = 0; i < 3; ++i) {
      t.lo[i] = lo[i];
      t.hi[i] = hi[i];
    }
    t.child[0] = child[0];
    t.child[1] = child[1];
    return node;
  }

  void set_leaf(std::uint32_t node, std::uint32_t cell)
  {
    typename Arrangement::Tree_node& n = a_.nodes_[node];
    cell_box(cell, n);
    n.child[0] = null;
    n.child[1] = cell;
  }

  // The bounding box of a cell, enlarged by half a lattice unit.
  void cell_box(std::uint32_t cell, typename Arrangement::Tree_node& n) const
  {
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for(const std::uint32_t* fi = a_.cell_facets_.begin(cell); fi != a_.cell_facets_.end(cell); ++fi) {
      const std::uint32_t* poly = a_.polygons_.begin(*fi);
      const std::size_t m = a_.polygons_.size(*fi);
      for(std::size_t k = 0; k < m; ++k)
        for(int i = 0; i < 3; ++i) {
          lo[i] = (std::min)(lo[i], a_.points_[poly[k]][i]);
          hi[i] = (std::max)(hi[i], a_.points_[poly[k]][i]);
        }
    }
    // Whole lattice units, rounded outwards from the half-unit margin, clamped to the box [0, L] that contains
    // every cell (65535 stands for L as an upper bound, see upper_bound()).
    for(int i = 0; i < 3; ++i) {
      n.lo[i] = static_cast<std::uint16_t>((std::min)(65535.0, (std::max)(0.0, std::floor(lo[i] - 0.5))));
      n.hi[i] = static_cast<std::uint16_t>((std::min)(65535.0, (std::max)(0.0, std::ceil(hi[i] + 0.5))));
    }
  }

  static double upper_bound(std::uint16_t h) { return h == 0xFFFF ? double(Arrangement::lattice_size) : double(h); }

  Arrangement& a_;
  std::size_t threads_;
  std::vector<std::array<std::uint32_t, 2>> pending_leaves_; // node, cell
  std::uint32_t h_ = 0;
  std::unordered_map<std::uint64_t, std::uint32_t> split_vertices_;
  std::vector<Chord> chords_;
  std::vector<std::array<std::uint32_t, 2>> aug_; // vertex, side + 1
  std::vector<std::uint32_t> poly_, old_, neg_, pos_, pn_, pp_; // reused buffers
};

} // namespace internal

inline Plane_arrangement_3::Plane_arrangement_3()
{
  internal::Plane_arrangement_builder_3<Plane_arrangement_3> builder(*this);
  builder.init_box();
}

template <class Progress>
Plane_arrangement_3::Plane_arrangement_3(const std::vector<Lattice_plane_3>& planes, Progress progress,
                                         std::size_t threads)
{
  internal::Plane_arrangement_builder_3<Plane_arrangement_3> builder(*this, CGAL::MDCS::effective_threads(threads, true));
  builder.init_box();
  CGAL::MDCS::internal::Progress_reporter<Progress> reporter(progress, "arrangement", planes.size());
  for(std::size_t i = 0; i < planes.size(); ++i) {
    reporter(i);
    builder.insert(planes[i]);
  }
  // Drop the scratch data and the tree (it only serves insertions: a later insert_plane() rebuilds one) first, so
  // that packing the lists does not raise the peak; then give back the slack of the containers (they grew by
  // doubling).
  side_epoch_.release();
  side_cache_.release();
  nodes_.release();
  node_of_cell_.release();
  polygons_.compact();
  cell_facets_.compact();
  facets_.shrink_to_fit();
  vertex_planes_.shrink_to_fit();
  points_.shrink_to_fit();
  reporter.finish();
}

inline Plane_arrangement_3::Plane_index Plane_arrangement_3::common_plane(Vertex_index u, Vertex_index v,
                                                                         Plane_index exclude) const
{
  const std::array<Plane_index, 3>& tu = vertex_planes_[u];
  const std::array<Plane_index, 3>& tv = vertex_planes_[v];
  for(Plane_index p : tu)
    if(p != exclude && (p == tv[0] || p == tv[1] || p == tv[2])) return p;
  for(Plane_index p : tu)
    if(p != exclude && side(v, p) == 0) return p;
  for(Plane_index p : tv)
    if(p != exclude && side(u, p) == 0) return p;
  for(std::size_t p = 0; p < planes_.size(); ++p)
    if(used_[p] && p != exclude && side(u, Plane_index(p)) == 0 && side(v, Plane_index(p)) == 0)
      return Plane_index(p);
  throw std::logic_error("MDCS: Plane_arrangement_3: internal error: no plane through an edge besides its facet's");
}

inline bool Plane_arrangement_3::insert_plane(const Lattice_plane_3& plane)
{
  internal::Plane_arrangement_builder_3<Plane_arrangement_3> builder(*this);
  return builder.insert(plane);
}

inline std::size_t Plane_arrangement_3::memory_bytes() const
{
  return planes_.capacity() * sizeof(Lattice_plane_3) + used_.capacity() + facets_.capacity() * sizeof(Facet) +
         polygons_.memory_bytes() + cell_facets_.memory_bytes() +
         vertex_planes_.capacity() * sizeof(std::array<Plane_index, 3>) +
         points_.capacity() * sizeof(std::array<double, 3>) + nodes_.capacity() * sizeof(Tree_node) +
         node_of_cell_.capacity() * 4 + side_epoch_.capacity() * 4 + side_cache_.capacity();
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_PLANE_ARRANGEMENT_CONSTRUCTION_3_H
