// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shortening of a traced path into a locally shortest one (a geodesic of the polyhedral surface), for the
// paths of the approximate classes: flat-exact follows its dependence DAG, fast marching descends its
// interpolated field, Dijkstra runs along the edges. Each of them is a real path on the surface, but it bends
// where a geodesic would not.
//
// The path is kept as a sequence of items: its two ends, the vertices it passes through, and the edges it
// crosses between them ("portals", each oriented so that the path enters the face of the halfedge). Two
// operations alternate, each of which can only shorten the path, until neither changes it:
// - Straightening: between two consecutive vertices (or ends), the faces the path crosses form a strip. The strip
//   is unfolded into the plane and the shortest path through its portals is found by the funnel algorithm (Lee
//   and Preparata; Chazelle): straight lines that bend only at portal end points, that is at mesh vertices. A
//   crossing that falls on an end point becomes a vertex of the path.
// - Opening a vertex: a shortest path can pass through a vertex only if the angle on both of its sides is at
//   least pi (Mitchell, Mount and Papadimitriou; Polthier and Schmies). At an interior vertex of the path where
//   one side measures less than pi and no border cuts that side, the edges of that side's faces become portals
//   and the strips on both sides are joined: the next straightening then passes beside the vertex, which is
//   strictly shorter. Neighbouring vertices are not opened in the same round, so that the joined strip stays one
//   strip.
// A traced point on an edge whose neighbours on the path lie in one face of that edge (a path running along the
// edge) is dropped first: the segment between the neighbours, inside that face, is shorter.
// The ends stay where they are; the result is locally shortest (not necessarily the shortest path overall: it
// keeps the way around the surface's features that the traced path took). Every round is checked: a strip that
// cannot be unfolded (the traced path is not a chain of faces), or a result that would be longer (beyond a
// relative 1e-12 of rounding in the first round, at all after it), keeps the last valid path, so the shortening
// never lengthens a path beyond rounding or loses its ends.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_PATH_SHORTENING_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_PATH_SHORTENING_H

#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>
#include <CGAL/Polyhedral_geodesics_3/internal/geodesic_engine_types.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

template <class FT>
class Geodesic_path_shortener
{
public:
  typedef Geodesic_mesh<FT> Mesh;
  typedef typename Mesh::Index Index;
  typedef Geodesic_path_node<FT> Node;

  explicit Geodesic_path_shortener(const Mesh& mesh) : mesh_(mesh) {}

  // How a shortening ended.
  enum Outcome {
    CONVERGED,        // no vertex of the path can be opened: the path is locally shortest
    NO_PROGRESS,      // a round shortened the path by less than a relative 1e-13 (rounding)
    NOT_A_FACE_CHAIN, // the traced path is not a chain of faces; it is kept
    UNFOLD_FAILED,    // a strip could not be unfolded or the funnel gave up; the last valid path is kept
    LONGER,           // a round would have lengthened the path beyond rounding; the last valid path is kept
    ROUND_BUDGET      // the round budget ran out
  };
  struct Result
  {
    Outcome outcome = CONVERGED;
    bool changed = false;
    std::size_t rounds = 0;
    std::size_t opened = 0; // vertices opened over all rounds
  };

  // Replaces `nodes` (query point first, source last, as trace_path emits them) by a locally shortest path with
  // the same ends.
  Result shorten(std::vector<Node>& nodes)
  {
    Result result;
    if(nodes.size() < 3)
      return result;
    ends_[0] = nodes.front();
    ends_[1] = nodes.back();
    std::vector<Item> items;
    if(!items_from_nodes(nodes, items)) {
      result.outcome = NOT_A_FACE_CHAIN;
      return result;
    }
    const FT start_length = path_length(items);
    FT length = start_length;
    // Rounding: a straightened path may come out longer by a few ulps than one that was straight already.
    const FT slack = start_length * FT(1e-12);
    std::vector<Item> work;
    bool straightened = false;
    // Each round opens at least one vertex and the length falls with it; the bound only guards against rounding
    // making the same vertex open again and again.
    const std::size_t max_rounds = 64 + 4 * items.size();
    result.outcome = ROUND_BUDGET;
    for(std::size_t r = 0; r < max_rounds; ++r) {
      result.rounds = r + 1;
      work = items;
      if(r > 0) {
        const std::size_t opened = open_vertices(work);
        if(opened == 0) {
          result.outcome = CONVERGED;
          break;
        }
        result.opened += opened;
      }
      if(!straighten(work)) {
        result.outcome = UNFOLD_FAILED;
        break;
      }
      const FT new_length = path_length(work);
      // The first straightening may take the slack; a later round that does not shorten changes nothing.
      if(!(new_length <= (r == 0 ? length + slack : length))) {
        result.outcome = r == 0 ? LONGER : NO_PROGRESS;
        break;
      }
      const bool progress = r == 0 || new_length < length - length * FT(1e-13);
      items.swap(work);
      length = new_length;
      straightened = true;
      if(!progress) {
        result.outcome = NO_PROGRESS;
        break;
      }
    }
    if(straightened) {
      nodes_from_items(items, nodes);
      result.changed = true;
    }
    return result;
  }

private:
  enum Kind { END, VERTEX, PORTAL };
  struct Item
  {
    Kind kind;
    Index index; // END: 0 (query point) or 1 (source); VERTEX: the vertex; PORTAL: the halfedge entered through
    FT t;        // PORTAL: the crossing, (1-t) source + t target of the halfedge
  };
  struct P2
  {
    FT x, y;
  };

  static FT cross(const P2& o, const P2& a, const P2& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

  // The slot (0, 1, 2) of vertex v among the corners of face f, -1 if v is not a corner.
  int corner_slot(Index f, Index v) const
  {
    for(int k = 0; k < 3; ++k)
      if(mesh_.source(3 * f + k) == v)
        return k;
    return -1;
  }

  // Whether the item (a vertex or an end) lies in face f. An end on an edge is not an anchor the strips can place.
  bool anchor_in_face(const Item& a, Index f) const
  {
    if(a.kind == VERTEX)
      return corner_slot(f, a.index) >= 0;
    const Node& n = ends_[std::size_t(a.index)];
    return n.kind != Node::EDGE && node_in_face(n, f);
  }

  // Whether a path item lies in face f: an anchor in it, or a portal into it.
  bool item_in_face(const Item& a, Index f) const
  {
    return a.kind == PORTAL ? Mesh::face_of(a.index) == f : anchor_in_face(a, f);
  }

  // Whether a traced node lies in face f (a corner, a point of one of its edges, a point inside it).
  bool node_in_face(const Node& n, Index f) const
  {
    switch(n.kind) {
    case Node::VERTEX:
      return corner_slot(f, n.index) >= 0;
    case Node::EDGE: {
      const Index tw = mesh_.he[std::size_t(n.index)].twin;
      return Mesh::face_of(n.index) == f || (tw >= 0 && Mesh::face_of(tw) == f);
    }
    default:
      for(int k = 0; k < 3; ++k)
        if(n.barycentric[std::size_t(k)] != FT(0) && corner_slot(f, mesh_.source(3 * n.index + k)) < 0)
          return false;
      return true;
    }
  }

  // The position of an anchor in face f, whose corners (by slot) are at pos.
  P2 anchor_position(const Item& a, Index f, const std::array<P2, 3>& pos) const
  {
    const Index v = a.kind == VERTEX ? a.index : ends_[std::size_t(a.index)].index;
    if(a.kind == VERTEX || ends_[std::size_t(a.index)].kind == Node::VERTEX)
      return pos[std::size_t(corner_slot(f, v))];
    const Node& n = ends_[std::size_t(a.index)];
    P2 p{FT(0), FT(0)};
    for(int k = 0; k < 3; ++k) {
      const FT& b = n.barycentric[std::size_t(k)];
      if(b == FT(0))
        continue;
      const P2& q = pos[std::size_t(corner_slot(f, mesh_.source(3 * n.index + k)))];
      p.x += b * q.x;
      p.y += b * q.y;
    }
    return p;
  }

  // The vertex an anchor stands for, -1 for an end inside a face.
  Index anchor_vertex(const Item& a) const
  {
    if(a.kind == VERTEX)
      return a.index;
    const Node& n = ends_[std::size_t(a.index)];
    return n.kind == Node::VERTEX ? n.index : Index(-1);
  }

  std::array<FT, 3> item_point(const Item& a) const
  {
    if(a.kind == END)
      return ends_[std::size_t(a.index)].point;
    if(a.kind == VERTEX)
      return mesh_.points[std::size_t(a.index)];
    return edge_path_node(mesh_, a.index, a.t).point;
  }

  FT path_length(const std::vector<Item>& items) const
  {
    using std::sqrt;
    FT sum(0);
    std::array<FT, 3> p = item_point(items.front());
    for(std::size_t i = 1; i < items.size(); ++i) {
      const std::array<FT, 3> q = item_point(items[i]);
      sum += sqrt(squared_distance_3(p, q));
      p = q;
    }
    return sum;
  }

  // The nodes as items; each edge crossing is oriented so that the path enters the face of its halfedge.
  // Fails (false) for a path that is not a chain of faces: a crossing of a border edge, a crossing whose side
  // is ambiguous (on an edge at the previous vertex), a face point in the middle.
  bool items_from_nodes(const std::vector<Node>& nodes, std::vector<Item>& items) const
  {
    items.clear();
    items.reserve(nodes.size());
    items.push_back(Item{END, 0, FT(0)});
    for(std::size_t i = 1; i + 1 < nodes.size(); ++i) {
      const Node& n = nodes[i];
      if(n.kind == Node::VERTEX) {
        if(items.back().kind == VERTEX && items.back().index == n.index)
          continue;
        items.push_back(Item{VERTEX, n.index, FT(0)});
        continue;
      }
      if(n.kind != Node::EDGE)
        return false;
      const Index g = n.index, tw = mesh_.he[std::size_t(g)].twin;
      const Item& prev = items.back();
      // A point on an edge whose neighbours on the path lie in one face of that edge (the path runs along the edge
      // there, as fast marching does in a valley or on the border): the segment between the neighbours, inside
      // that face, replaces it, which is shorter.
      bool skip = false;
      for(Index f : {Mesh::face_of(g), tw >= 0 ? Mesh::face_of(tw) : Index(-1)})
        skip = skip || (f >= 0 && item_in_face(prev, f) && node_in_face(nodes[i + 1], f));
      if(skip)
        continue;
      if(tw < 0)
        return false;
      bool ok_g, ok_tw;
      if(prev.kind == PORTAL) {
        const Index f = Mesh::face_of(prev.index);
        ok_g = Mesh::face_of(tw) == f;
        ok_tw = Mesh::face_of(g) == f;
      } else {
        ok_g = anchor_in_face(prev, Mesh::face_of(tw));
        ok_tw = anchor_in_face(prev, Mesh::face_of(g));
      }
      if(ok_g == ok_tw)
        return false;
      items.push_back(ok_g ? Item{PORTAL, g, n.t} : Item{PORTAL, tw, FT(1) - n.t});
    }
    items.push_back(Item{END, 1, FT(0)});
    return true;
  }

  void nodes_from_items(const std::vector<Item>& items, std::vector<Node>& nodes) const
  {
    nodes.clear();
    nodes.reserve(items.size());
    for(const Item& a : items) {
      if(a.kind == END)
        nodes.push_back(ends_[std::size_t(a.index)]);
      else if(a.kind == VERTEX)
        nodes.push_back(vertex_path_node(mesh_, a.index));
      else
        nodes.push_back(edge_path_node(mesh_, a.index, a.t));
    }
  }

  // Straightens every strip between two anchors (vertices or ends) with at least one portal.
  bool straighten(std::vector<Item>& items)
  {
    out_.clear();
    out_.push_back(items.front());
    std::size_t a = 0;
    while(a + 1 < items.size()) {
      std::size_t b = a + 1;
      while(items[b].kind == PORTAL)
        ++b;
      if(b == a + 1) {
        push_anchor(items[b]);
      } else if(!straighten_strip(items, a, b)) {
        return false;
      }
      a = b;
    }
    items.swap(out_);
    return true;
  }

  // Appends an anchor unless it repeats the vertex just before it.
  void push_anchor(const Item& a)
  {
    const Index v = anchor_vertex(a);
    if(v >= 0 && out_.back().kind != PORTAL && anchor_vertex(out_.back()) == v) {
      if(a.kind == END)
        out_.back() = a; // an end stays an end
      return;
    }
    out_.push_back(a);
  }

  // The strip from anchor items[a] through portals items[a+1 .. b-1] to anchor items[b], unfolded face by
  // face in the frames of the halfedges; then the funnel; then the crossings of the portals with its lines.
  bool straighten_strip(const std::vector<Item>& items, std::size_t a, std::size_t b)
  {
    using std::sqrt;
    const std::size_t k = b - a - 1;
    left_.resize(k + 2);
    right_.resize(k + 2);
    left_id_.resize(k + 2);
    right_id_.resize(k + 2);
    // The face before the first portal, in the first portal's frame turned by pi.
    const Index h1 = items[a + 1].index;
    const Geodesic_halfedge<FT>& r1 = mesh_.he[std::size_t(h1)];
    const Index tw1 = r1.twin;
    const Index f0 = Mesh::face_of(tw1);
    if(!anchor_in_face(items[a], f0))
      return false;
    std::array<P2, 3> pos;
    {
      const Geodesic_halfedge<FT>& rt = mesh_.he[std::size_t(tw1)];
      pos[std::size_t(tw1 % 3)] = P2{r1.length, FT(0)};
      pos[std::size_t(Mesh::next(tw1) % 3)] = P2{FT(0), FT(0)};
      pos[std::size_t(Mesh::prev(tw1) % 3)] = P2{r1.length - rt.opposite.x, -rt.opposite.y};
    }
    const P2 start = anchor_position(items[a], f0, pos);
    left_[0] = right_[0] = start;
    left_id_[0] = right_id_[0] = anchor_vertex(items[a]);
    Index f = f0;
    for(std::size_t i = 1; i <= k; ++i) {
      const Index h = items[a + i].index;
      const Index tw = mesh_.he[std::size_t(h)].twin;
      if(tw < 0 || Mesh::face_of(tw) != f)
        return false;
      // h runs from the twin's target to its source.
      const P2 s = pos[std::size_t(Mesh::next(tw) % 3)], t = pos[std::size_t(tw % 3)];
      left_[i] = s;
      right_[i] = t;
      left_id_[i] = mesh_.source(h);
      right_id_[i] = mesh_.target(h);
      // The face of h: its corners in the plane, the opposite one from h's frame.
      const Geodesic_halfedge<FT>& rh = mesh_.he[std::size_t(h)];
      FT ux = t.x - s.x, uy = t.y - s.y;
      const FT len = sqrt(ux * ux + uy * uy);
      if(len > FT(0)) {
        ux /= len;
        uy /= len;
      } else {
        ux = FT(1);
        uy = FT(0);
      }
      f = Mesh::face_of(h);
      pos[std::size_t(h % 3)] = s;
      pos[std::size_t(Mesh::next(h) % 3)] = t;
      pos[std::size_t(Mesh::prev(h) % 3)] =
          P2{s.x + rh.opposite.x * ux - rh.opposite.y * uy, s.y + rh.opposite.x * uy + rh.opposite.y * ux};
    }
    if(!anchor_in_face(items[b], f))
      return false;
    const P2 end = anchor_position(items[b], f, pos);
    left_[k + 1] = right_[k + 1] = end;
    left_id_[k + 1] = right_id_[k + 1] = anchor_vertex(items[b]);
    if(!funnel(k + 2))
      return false;

    // The portals next to a bend of the funnel path at a vertex, in one run with it (the fan of faces the path
    // turns through there), are crossed at that vertex; the others where the segment that spans them meets them.
    at_vertex_.assign(k + 2, Index(-1));
    auto has_end = [&](std::size_t i, Index v) { return left_id_[i] == v || right_id_[i] == v; };
    for(std::size_t m = 0; m < apex_.size(); ++m) {
      const Index v = apex_[m].vertex;
      if(v < 0)
        continue;
      const std::size_t j = apex_[m].portal;
      const std::size_t lo = m > 0 ? apex_[m - 1].portal : 0, hi = m + 1 < apex_.size() ? apex_[m + 1].portal : k + 1;
      for(std::size_t i = std::min(j, k); i > lo && i >= 1 && has_end(i, v); --i)
        at_vertex_[i] = v;
      for(std::size_t i = j + 1; i < hi && i <= k && has_end(i, v); ++i)
        at_vertex_[i] = v;
    }
    std::size_t seg = 0;
    for(std::size_t i = 1; i <= k; ++i) {
      while(seg + 2 < apex_.size() && apex_[seg + 1].portal < i)
        ++seg;
      const Apex& p = apex_[seg];
      const Apex& q = apex_[seg + 1];
      const Index h = items[a + i].index;
      FT t;
      if(at_vertex_[i] >= 0) {
        t = at_vertex_[i] == left_id_[i] ? FT(0) : FT(1);
      } else {
        // l + t (r - l) = p + u (q - p): t = cross(p - l, q - p) / cross(r - l, q - p).
        const P2& l = left_[i];
        const P2& r = right_[i];
        const FT dx = q.p.x - p.p.x, dy = q.p.y - p.p.y;
        const FT den = (r.x - l.x) * dy - (r.y - l.y) * dx;
        const FT num = (p.p.x - l.x) * dy - (p.p.y - l.y) * dx;
        t = den != FT(0) ? num / den : FT(0.5);
        if(!(t > FT(0)))
          t = FT(0);
        if(!(t < FT(1)))
          t = FT(1);
      }
      const FT eps(1e-12);
      if(t <= eps)
        push_anchor(Item{VERTEX, mesh_.source(h), FT(0)});
      else if(t >= FT(1) - eps)
        push_anchor(Item{VERTEX, mesh_.target(h), FT(0)});
      else
        out_.push_back(Item{PORTAL, h, t});
    }
    push_anchor(items[b]);
    return true;
  }

  struct Apex
  {
    P2 p;
    Index vertex;       // -1 for an end inside a face
    std::size_t portal; // the portal whose end point it is (0: the start, n-1: the end)
  };

  // The funnel over portals 0..n-1 (the first and the last are the anchors): the bends of the shortest path
  // through the portals, in apex_, from the start to the end. Left and right are seen along the path.
  bool funnel(std::size_t n)
  {
    apex_.clear();
    Apex ap{left_[0], left_id_[0], 0}, pl = ap, pr = ap;
    apex_.push_back(ap);
    // Each restart moves the apex to a later portal; the budget only guards against rounding.
    std::size_t budget = 4 * n * n + 64;
    auto same = [](const Apex& u, const Apex& w) {
      return (u.vertex >= 0 && u.vertex == w.vertex) || (u.p.x == w.p.x && u.p.y == w.p.y);
    };
    for(std::size_t i = 1; i < n; ++i) {
      if(budget-- == 0)
        return false;
      const Apex l{left_[i], left_id_[i], i}, r{right_[i], right_id_[i], i};
      // A new end point on one side tightens the funnel, unless it passes over the other side: then the other
      // side's end point is a bend of the path, the new apex, and the scan restarts after its portal.
      const Apex* bend = nullptr;
      if(cross(ap.p, pr.p, r.p) >= FT(0)) {
        if(same(ap, pr) || same(ap, pl) || cross(ap.p, pl.p, r.p) < FT(0))
          pr = r;
        else
          bend = &pl;
      }
      if(!bend && cross(ap.p, pl.p, l.p) <= FT(0)) {
        if(same(ap, pl) || same(ap, pr) || cross(ap.p, pr.p, l.p) > FT(0))
          pl = l;
        else
          bend = &pr;
      }
      if(bend) {
        ap = *bend;
        apex_.push_back(ap);
        pl = pr = ap;
        i = ap.portal;
      }
    }
    if(apex_.back().portal != n - 1)
      apex_.push_back(Apex{left_[n - 1], left_id_[n - 1], n - 1});
    return true;
  }

  // --- Opening vertices ---------------------------------------------------------------------------------

  // A direction at vertex v: inside the corner c of a face (source(c) == v), at angle `offset` from the
  // direction of edge c.
  struct Direction
  {
    Index corner;
    double offset;
  };

  double corner_angle(Index c) const
  {
    const auto& o = mesh_.he[std::size_t(c)].opposite;
    return std::atan2(to_double_value(o.y), to_double_value(o.x));
  }

  // The compact halfedges of the edge between v and w: g from v to w and e from w to v (-1 where the edge has no
  // such halfedge, on the border). Both -1 if v and w are not joined by an edge.
  void edge_between(Index v, Index w, Index& g, Index& e)
  {
    if(star_begin_.empty())
      build_vertex_star(mesh_, star_begin_, star_);
    g = e = -1;
    for(Index k = star_begin_[std::size_t(v)]; k < star_begin_[std::size_t(v) + 1]; ++k)
      if(mesh_.target(star_[std::size_t(k)]) == w)
        g = star_[std::size_t(k)];
    for(Index k = star_begin_[std::size_t(w)]; k < star_begin_[std::size_t(w) + 1]; ++k)
      if(mesh_.target(star_[std::size_t(k)]) == v)
        e = star_[std::size_t(k)];
  }

  // The direction from v towards the point p of face f (v a corner of f).
  Direction direction_to_point(Index v, Index f, const std::array<FT, 3>& p) const
  {
    const Index c = 3 * f + corner_slot(f, v);
    const auto& o = mesh_.points[std::size_t(v)];
    const auto& e = mesh_.points[std::size_t(mesh_.target(c))];
    double u[3], w[3];
    for(int i = 0; i < 3; ++i) {
      u[i] = to_double_value(e[std::size_t(i)]) - to_double_value(o[std::size_t(i)]);
      w[i] = to_double_value(p[std::size_t(i)]) - to_double_value(o[std::size_t(i)]);
    }
    const double cx = u[1] * w[2] - u[2] * w[1], cy = u[2] * w[0] - u[0] * w[2], cz = u[0] * w[1] - u[1] * w[0];
    const double dot = u[0] * w[0] + u[1] * w[1] + u[2] * w[2];
    return Direction{c, std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), dot)};
  }

  // The direction from vertex v (the path's item i) towards its neighbour item j, as the start (`from`) or the
  // end of a turn; counter-clockwise (ccw) or clockwise. A direction along an edge is placed in the face that
  // lets the turn avoid crossing that edge. Returns false if it cannot be placed.
  bool neighbour_direction(const std::vector<Item>& items, std::size_t i, std::size_t j, bool from, bool ccw,
                           Direction& d)
  {
    const Index v = items[i].index;
    const Item& n = items[j];
    const Index w = n.kind == PORTAL ? Index(-1) : anchor_vertex(n);
    if(w >= 0) {
      Index g, e;
      edge_between(v, w, g, e);
      // Turning ccw, a start along the edge is the start of corner g, an end is the end of the corner after e
      // (next(e)); turning cw, the other way round. On a border edge only one of them exists.
      if(g >= 0 && (from == ccw || e < 0))
        d = Direction{g, 0.0};
      else if(e >= 0)
        d = Direction{Mesh::next(e), corner_angle(Mesh::next(e))};
      else
        return false;
      return true;
    }
    Index f;
    if(n.kind == PORTAL)
      f = Mesh::face_of(j < i ? n.index : mesh_.he[std::size_t(n.index)].twin);
    else
      f = ends_[std::size_t(n.index)].index; // an end inside face f
    if(corner_slot(f, v) < 0)
      return false;
    d = direction_to_point(v, f, item_point(n));
    return true;
  }

  // Turns around v from direction `in` to `out`, counter-clockwise or clockwise, collecting the edges crossed
  // (as portals entered). Returns the angle swept, +infinity if a border blocks the turn.
  double turn(const Direction& in, const Direction& out, bool ccw, std::vector<Index>& portals) const
  {
    portals.clear();
    const double inf = std::numeric_limits<double>::infinity();
    Index c = in.corner;
    double angle = 0;
    if(ccw) {
      double a0 = in.offset;
      for(std::size_t guard = 0; guard < 4096; ++guard) {
        if(c == out.corner && out.offset >= a0)
          return angle + (out.offset - a0);
        angle += corner_angle(c) - a0;
        const Index t = mesh_.he[std::size_t(Mesh::prev(c))].twin;
        if(t < 0)
          return inf;
        portals.push_back(t);
        c = t;
        a0 = 0;
        if(c == in.corner && c != out.corner)
          return inf; // all the way round without meeting `out`
      }
    } else {
      double a0 = in.offset; // the angle left to the start of corner c
      for(std::size_t guard = 0; guard < 4096; ++guard) {
        if(c == out.corner && out.offset <= a0)
          return angle + (a0 - out.offset);
        angle += a0;
        const Index t = mesh_.he[std::size_t(c)].twin;
        if(t < 0)
          return inf;
        portals.push_back(t);
        c = Mesh::next(t);
        a0 = corner_angle(c);
        if(c == in.corner && c != out.corner)
          return inf;
      }
    }
    return inf;
  }

  // Opens every interior vertex of the path with a side of angle below pi (not two neighbours in one round).
  // Returns how many it opened.
  std::size_t open_vertices(std::vector<Item>& items)
  {
    const double pi = 3.14159265358979323846;
    out_.clear();
    out_.push_back(items.front());
    std::size_t opened = 0;
    bool last_opened = false;
    for(std::size_t i = 1; i + 1 < items.size(); ++i) {
      const Item& it = items[i];
      if(it.kind != VERTEX || last_opened) {
        out_.push_back(it);
        last_opened = false;
        continue;
      }
      // The side with the smaller angle below pi; its fan of edges becomes portals.
      double best = pi - 1e-9;
      bool found = false;
      for(bool ccw : {true, false}) {
        Direction in, out;
        if(!neighbour_direction(items, i, i - 1, true, ccw, in) || !neighbour_direction(items, i, i + 1, false, ccw, out))
          continue;
        const double angle = turn(in, out, ccw, fan_);
        if(angle < best) {
          best = angle;
          best_fan_.swap(fan_);
          found = true;
        }
      }
      if(!found) {
        out_.push_back(it);
        continue;
      }
      // Start the new portals at the vertex's side of each edge: the next straightening moves them.
      for(Index h : best_fan_)
        out_.push_back(Item{PORTAL, h, mesh_.source(h) == it.index ? FT(0) : FT(1)});
      ++opened;
      last_opened = true;
    }
    out_.push_back(items.back());
    items.swap(out_);
    return opened;
  }

  const Mesh& mesh_;
  std::array<Node, 2> ends_;
  std::vector<Item> out_;
  std::vector<P2> left_, right_;
  std::vector<Index> left_id_, right_id_, at_vertex_;
  std::vector<Apex> apex_;
  std::vector<Index> fan_, best_fan_;
  std::vector<Index> star_begin_, star_; // the outgoing halfedges of each vertex, built on the first use
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_PATH_SHORTENING_H
