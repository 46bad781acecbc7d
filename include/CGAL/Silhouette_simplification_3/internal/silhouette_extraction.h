// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Silhouette edges of an indexed triangle mesh for one view, and their decomposition into loops
// without repeated vertices.

#ifndef CGAL_SILHOUETTE_SIMPLIFICATION_3_INTERNAL_SILHOUETTE_EXTRACTION_H
#define CGAL_SILHOUETTE_SIMPLIFICATION_3_INTERNAL_SILHOUETTE_EXTRACTION_H

#include <CGAL/Silhouette_simplification_3/internal/Indexed_mesh.h>

#include <cstdint>
#include <vector>

namespace CGAL {
namespace Silhouette_simplification_3 {

/*!
  \ingroup PkgSilhouetteSimplification3Ref
  \brief A loop of directed edges: `halfedges[i]` ends where `halfedges[i+1]` starts, no vertex repeats.
  `closed` says whether the last edge ends where the first starts (always the case for silhouettes,
  which are boundaries of the front-facing region; open chains only come from user edge sets).
*/
template <class Halfedge>
struct Silhouette_loop
{
  std::vector<Halfedge> halfedges;
  bool closed = true;
};

namespace internal {

// front[f] = 1 iff face f faces the viewer.
template <class Point_3, class View>
void classify_faces(const Indexed_mesh<Point_3>& im, const View& view, std::vector<char>& front)
{
  front.resize(im.faces.size());
  for(std::size_t f = 0; f < im.faces.size(); ++f) {
    const auto& t = im.faces[f];
    front[f] = view.is_front_facing(im.points[t[0]], im.points[t[1]], im.points[t[2]]) ? 1 : 0;
  }
}

// The boundary of the front-facing region: halfedges h whose face is front-facing and whose opposite
// face is back-facing or absent (mesh border), in increasing index order. The front face is on the
// left of every returned halfedge.
template <class Point_3>
void silhouette_from_faces(const Indexed_mesh<Point_3>& im, const std::vector<char>& front, std::vector<std::uint32_t>& out)
{
  out.clear();
  const std::uint32_t n = std::uint32_t(im.number_of_interior_halfedges());
  for(std::uint32_t h = 0; h < n; ++h) {
    if(!front[h / 3]) continue;
    const std::uint32_t o = im.opposite[h];
    if(o >= n || !front[o / 3]) out.push_back(h);
  }
}

// Splits directed edges into loops without repeated vertices: walk from an unused edge along unused
// edges (looked up by source vertex), snapping off a sub-loop whenever the walk meets a vertex already
// on its path. Reusable scratch arrays sized by the number of vertices, reset after each call.
class Loop_decomposer
{
public:
  template <class Point_3>
  void operator()(const Indexed_mesh<Point_3>& im, const std::vector<std::uint32_t>& edges,
                  std::vector<Silhouette_loop<std::uint32_t>>& loops)
  {
    loops.clear();
    const std::size_t nv = im.points.size();
    if(head_.size() != nv) { head_.assign(nv, NONE); pos_.assign(nv, NONE); }
    const std::uint32_t m = std::uint32_t(edges.size());
    next_.assign(m, NONE);
    used_.assign(m, 0);
    for(std::uint32_t i = m; i-- > 0;) {
      const std::uint32_t s = im.source[edges[i]];
      next_[i] = head_[s];
      head_[s] = i;
    }
    for(std::uint32_t i = 0; i < m; ++i) {
      if(used_[i]) continue;
      path_v_.clear();
      path_e_.clear();
      const std::uint32_t start = im.source[edges[i]];
      path_v_.push_back(start);
      pos_[start] = 0;
      std::uint32_t cur = i;
      for(;;) {
        used_[cur] = 1;
        path_e_.push_back(cur);
        const std::uint32_t v = im.target(edges[cur]);
        if(pos_[v] != NONE) {
          const std::uint32_t p = pos_[v];
          Silhouette_loop<std::uint32_t> loop;
          for(std::size_t k = p; k < path_e_.size(); ++k) loop.halfedges.push_back(edges[path_e_[k]]);
          loops.push_back(std::move(loop));
          for(std::size_t k = p + 1; k < path_v_.size(); ++k) pos_[path_v_[k]] = NONE;
          path_e_.resize(p);
          path_v_.resize(p + 1);
        } else {
          pos_[v] = std::uint32_t(path_v_.size());
          path_v_.push_back(v);
        }
        const std::uint32_t last = path_v_.back();
        cur = pop_unused(last);
        if(cur == NONE) {
          if(!path_e_.empty()) { // dead end: an open chain (only for edge sets that are not cycles)
            Silhouette_loop<std::uint32_t> loop;
            for(std::uint32_t e : path_e_) loop.halfedges.push_back(edges[e]);
            loop.closed = false;
            loops.push_back(std::move(loop));
          }
          break;
        }
      }
      for(std::uint32_t v : path_v_) pos_[v] = NONE;
    }
    for(std::uint32_t e : edges) head_[im.source[e]] = NONE;
  }

private:
  std::uint32_t pop_unused(std::uint32_t v)
  {
    std::uint32_t e = head_[v];
    while(e != NONE && used_[e]) e = next_[e];
    head_[v] = e == NONE ? NONE : next_[e];
    return e;
  }

  std::vector<std::uint32_t> head_, pos_, next_, path_v_, path_e_;
  std::vector<char> used_;
};

} // namespace internal
} // namespace Silhouette_simplification_3
} // namespace CGAL

#endif // CGAL_SILHOUETTE_SIMPLIFICATION_3_INTERNAL_SILHOUETTE_EXTRACTION_H
