// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The distance field that the window propagation leaves behind (windows on every edge, vertex distances
// and nearest sources, sources inside faces) and what is read from it: the distance and nearest source at
// any surface point, and shortest-path tracing. Exact_window_propagation (exact_window_propagation.h)
// derives from this class and fills the field.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_WINDOW_FIELD_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_WINDOW_FIELD_H

#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>
#include <CGAL/Polyhedral_geodesics_3/internal/geodesic_engine_types.h>
#include <CGAL/Polyhedral_geodesics_3/internal/geodesic_window.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Window_store.h>
#include <CGAL/Polyhedral_geodesics_3/internal/unit_roundoff.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

template <class FT>
class Window_field
{
public:
  typedef typename Geodesic_mesh<FT>::Index Index;
  typedef Geodesic_mesh<FT> Mesh;
  typedef Geodesic_window<FT> Window;
  typedef Geodesic_path_node<FT> Path_node;
  typedef Geodesic_point_distance<FT> Point_distance;

  explicit Window_field(const Mesh& mesh) : mesh_(mesh)
  {
    if(!mesh_.star_begin.empty()) {
      star_begin_ = mesh_.star_begin.data();
      star_ = mesh_.star.data();
    }
    // The sentinel of "no distance yet": large, but far from overflowing when a few lengths are added.
    unreached_ = FT(std::numeric_limits<double>::max() / 16);
    relative_tolerance_ = FT(64) * unit_roundoff<FT>();
  }

public:
  FT vertex_distance(Index v) const
  {
    return dist_[std::size_t(v)] >= unreached_ ? FT(std::numeric_limits<double>::infinity()) : dist_[std::size_t(v)];
  }

  Index vertex_source(Index v) const { return vertex_source_[std::size_t(v)]; }

  // A window of the stored field, as the queries read it: the interval and the pseudo-source in the frame of
  // the edge's canonical halfedge, the halfedge of the face on its pseudo-source's side (it propagates into the
  // faces of the other halfedges of the edge; -1 if none) and its source.
  struct Field_window_view
  {
    FT b0, b1, sx, sy, sigma;
    Index from_halfedge;
    Index source;
  };

  // Calls f(Field_window_view) for every stored window of edge e, in order along the edge (full field only).
  template <class F>
  void for_each_window_on_edge(Index e, F f) const
  {
    if(field_first_.empty())
      return;
    const Index first = field_first_[std::size_t(e)];
    if(first < 0)
      return;
    const Index h = mesh_.edge_halfedge[std::size_t(e)];
    for(Index k = 0; k < field_count_[std::size_t(e)]; ++k) {
      const Field_window& w = field_windows_[std::size_t(first + k)];
      const std::uint32_t tag = field_tags_[std::size_t(first + k)];
      const Index from = halfedge_of_rank(h, tag & field_rank_mask);
      f(Field_window_view{w.b0, w.b1, w.sx, w.sy, w.sigma, from, Index(tag >> field_rank_bits) - 1});
    }
  }

  // ------------------------------------------------------------------------------------------------
  // Queries (full field)

  Point_distance distance_at(Index f, const std::array<FT, 3>& b) const
  {
    Candidate c = best_candidate_in_face(f, b, -1, -1);
    if(c.kind == Candidate::NONE || !finite_answer(c.value))
      return {FT(std::numeric_limits<double>::infinity()), -1};
    return {c.value, c.source};
  }

  // Emits the path from the point (f, b) to its nearest source: the point itself, every edge crossing
  // and vertex, the source. Emits nothing if the point is unreachable.
  template <class Emit>
  void trace_path(Index f, const std::array<FT, 3>& b, Emit emit) const
  {
    Candidate first = best_candidate_in_face(f, b, -1, -1);
    if(first.kind == Candidate::NONE || !finite_answer(first.value))
      return;
    ensure_vertex_star();
    // The current point as a list of (face, barycentric) incarnations, plus what it is.
    std::vector<std::pair<Index, std::array<FT, 3>>> where;
    Index at_vertex = -1, on_halfedge = -1;
    int zeros = 0, nonzero = -1;
    for(int k = 0; k < 3; ++k) {
      if(b[k] == FT(0)) ++zeros;
      else nonzero = k;
    }
    if(zeros >= 2) {
      at_vertex = mesh_.source(3 * f + nonzero);
      emit(vertex_node(at_vertex));
      where = vertex_incarnations(at_vertex);
    } else {
      emit(face_node(f, b));
      where.push_back({f, b});
      if(zeros == 1) {
        int k = 0;
        while(b[(k + 2) % 3] != FT(0)) ++k;
        on_halfedge = 3 * f + k;
        add_twin_incarnation(on_halfedge, b[(k + 1) % 3], where);
      }
    }
    FT current = first.value;
    Visited visited;
    if(at_vertex >= 0)
      visited.add_vertex(coincident_vertices(at_vertex));
    const std::size_t max_steps = 8 * mesh_.number_of_faces + 64;
    for(std::size_t step = 0; step < max_steps; ++step) {
      if(at_vertex >= 0 && dist_[std::size_t(at_vertex)] == FT(0))
        return; // a source vertex
      Candidate best;
      for(const auto& inc : where) {
        Candidate c = best_candidate_in_face(inc.first, inc.second, at_vertex,
                                             on_halfedge < 0 ? -1 : mesh_.he[std::size_t(on_halfedge)].edge, &visited);
        if(c.kind != Candidate::NONE && (best.kind == Candidate::NONE || c.value < best.value))
          best = c;
      }
      if(best.kind == Candidate::NONE)
        throw std::runtime_error("CGAL::Polyhedral_geodesics_3: shortest path tracing lost the distance field");
      switch(best.kind) {
      case Candidate::FACE_SOURCE:
        emit(face_node(best.face, best.barycentric));
        return;
      case Candidate::VERTEX:
        at_vertex = best.vertex;
        on_halfedge = -1;
        visited.add_vertex(coincident_vertices(at_vertex));
        emit(vertex_node(at_vertex));
        where = vertex_incarnations(at_vertex);
        break;
      case Candidate::EDGE_POINT: {
        const Index g = best.halfedge;
        const FT len = mesh_.he[std::size_t(g)].length;
        const FT t = best.t;
        if(!(t > FT(0))) {
          at_vertex = mesh_.source(g);
          on_halfedge = -1;
          visited.add_vertex(coincident_vertices(at_vertex));
          emit(vertex_node(at_vertex));
          where = vertex_incarnations(at_vertex);
        } else if(!(t < len)) {
          at_vertex = mesh_.target(g);
          on_halfedge = -1;
          visited.add_vertex(coincident_vertices(at_vertex));
          emit(vertex_node(at_vertex));
          where = vertex_incarnations(at_vertex);
        } else {
          at_vertex = -1;
          on_halfedge = g;
          visited.add_edge_point(mesh_.he[std::size_t(g)].edge, runs_like_canonical(g) ? t : len - t);
          const FT r = t / len;
          emit(edge_node(g, r));
          const Index fg = Mesh::face_of(g);
          std::array<FT, 3> bg = {FT(0), FT(0), FT(0)};
          bg[g % 3] = FT(1) - r;
          bg[(g % 3 + 1) % 3] = r;
          where.clear();
          where.push_back({fg, bg});
          add_twin_incarnation(g, r, where);
        }
        break;
      }
      default:
        break;
      }
      if(!(best.value < current + current * FT(1e-9) + FT(1e-300)))
        throw std::runtime_error("CGAL::Polyhedral_geodesics_3: shortest path tracing did not descend");
      current = best.value;
    }
    throw std::runtime_error("CGAL::Polyhedral_geodesics_3: shortest path tracing did not reach a source");
  }

protected:
  // Whether h runs in the direction of its edge's canonical halfedge, whose frame the windows use (on an oriented
  // manifold edge: whether h is that halfedge).
  bool runs_like_canonical(Index h) const
  {
    const Geodesic_halfedge<FT>& r = mesh_.he[std::size_t(h)];
    const Index hc = mesh_.edge_halfedge[std::size_t(r.edge)];
    if(h == hc)
      return true;
    if(r.twin >= 0)
      return false; // the twin runs the other way
    return r.source == mesh_.he[std::size_t(hc)].source; // a halfedge of a non-manifold or reversed edge
  }

  // Whether a window with this from halfedge propagates into the face of h (a halfedge of its edge).
  static bool propagates_into(Index from, Index h) { return from >= 0 && from != h; }

  // The window seen from halfedge h of its edge: for propagating into h's face (h is not its from halfedge), the
  // pseudo-source below the edge in h's frame; from its from halfedge's face, above.
  Local_window<FT> local_window(const Window& w, Index h) const
  {
    return local_window(w.b0, w.b1, w.sx, w.sy, w.sigma, w.from_halfedge, h);
  }

  // The stored window (b0, b1, sx, sy) is in the canonical frame, with sy of the sign it has when its from
  // halfedge's frame is turned into the canonical one (x -> L - x, y -> -y if they run opposite ways; nothing if
  // they run the same way). Seen from h, x follows h's direction and sy is the height of the pseudo-source on the
  // from side: + in the from face's own frame, - in every other face, which is unfolded opposite it. On an
  // oriented manifold edge this is the mirror image x -> L - x, y -> -y between the two halfedges, as it has
  // always been (the same numbers, bit for bit); only halfedges of non-manifold and reversed edges need `from`.
  Local_window<FT> local_window(const FT& b0, const FT& b1, const FT& sx, const FT& sy, const FT& sigma, Index from,
                                Index h) const
  {
    const bool h_like = runs_like_canonical(h);
    FT local_sy = h_like ? sy : -sy;
    const Geodesic_halfedge<FT>& r = mesh_.he[std::size_t(h)];
    if(from >= 0 && r.twin < 0 && r.radial != h) {
      const FT sy_from = runs_like_canonical(from) ? sy : -sy;
      local_sy = from == h ? sy_from : -sy_from;
    }
    if(h_like)
      return Local_window<FT>{b0, b1, sx, local_sy, sigma};
    const FT L = r.length;
    return Local_window<FT>{L - b1, L - b0, L - sx, local_sy, sigma};
  }

  // The stored field tags each window with its source and the position of its from halfedge in its edge's cycle
  // (0: the canonical halfedge), `no_rank` when it propagates nowhere.
  static constexpr unsigned field_rank_bits = 5;
  static constexpr std::uint32_t field_rank_mask = (1u << field_rank_bits) - 1;
  static constexpr std::uint32_t no_rank = field_rank_mask; // build_geodesic_mesh.h: at most 31 faces per edge

  std::uint32_t rank_of_halfedge(Index hc, Index g) const
  {
    if(g < 0)
      return no_rank;
    std::uint32_t rank = 0;
    for(Index x = hc; x != g; x = mesh_.he[std::size_t(x)].radial)
      ++rank;
    return rank;
  }

  Index halfedge_of_rank(Index hc, std::uint32_t rank) const
  {
    if(rank == no_rank)
      return -1;
    Index x = hc;
    for(std::uint32_t k = 0; k < rank; ++k)
      x = mesh_.he[std::size_t(x)].radial;
    return x;
  }

  // ------------------------------------------------------------------------------------------------
  // The stored field (full-field mode). The propagation copies the windows of an edge here once the edge
  // is final (and the rest at the end of the run), in a compact form: 40 bytes of geometry and a 4-byte
  // tag instead of the 64 bytes of the propagation's store, whose links, stamps and flags a finished edge
  // no longer needs. The propagation's store then holds only the windows near the front, so the peak
  // memory of a full-field run is about 44 bytes per final window.

  struct Field_window
  {
    FT b0, b1, sx, sy, sigma;
  };

  void reset_field(bool keep)
  {
    field_windows_.release();
    field_tags_.release();
    if(keep) {
      field_first_.assign(mesh_.number_of_edges, -1);
      field_count_.assign(mesh_.number_of_edges, 0);
    } else {
      std::vector<Index>().swap(field_first_);
      std::vector<Index>().swap(field_count_);
    }
  }

  // Appends the windows of edge e (in order along the edge) to the stored field. Called once per edge.
  void store_edge_field(std::size_t e)
  {
    const Index h = mesh_.edge_halfedge[e];
    const Index first = Index(field_windows_.size());
    Index n = 0;
    for(Index wi = edge_first_[e]; wi >= 0; wi = windows_[std::size_t(wi)].next, ++n) {
      const Window& w = windows_[std::size_t(wi)];
      if(w.source < -1 || w.source >= Index(1 << (32 - field_rank_bits)) - 1)
        throw std::length_error("CGAL::Polyhedral_geodesics_3: too many sources for the stored field");
      const std::size_t i = field_windows_.emplace_back();
      field_windows_[i] = Field_window{w.b0, w.b1, w.sx, w.sy, w.sigma};
      field_tags_[field_tags_.emplace_back()] =
          (std::uint32_t(w.source + 1) << field_rank_bits) | rank_of_halfedge(h, w.from_halfedge);
    }
    field_first_[e] = n > 0 ? first : Index(-1);
    field_count_[e] = n;
  }

  std::size_t field_bytes() const
  {
    return field_windows_.capacity() * sizeof(Field_window) + field_tags_.capacity() * sizeof(std::uint32_t) +
           (field_first_.capacity() + field_count_.capacity()) * sizeof(Index);
  }

  bool finite_answer(const FT& value) const
  {
    if(!(value < unreached_))
      return false;
    if(stopped_early_) {
      const FT bound = has_limit_ && front_ > limit_ ? limit_ : front_;
      return value <= bound;
    }
    return !has_limit_ || value <= limit_;
  }

  // ------------------------------------------------------------------------------------------------
  // Sources inside faces

  struct Face_source
  {
    Index face;
    std::array<FT, 3> barycentric;
    Index id;
  };

  // The point with barycentric coordinates b of face f, in the frame of the face's halfedge 3f+k.
  Point_2_ft<FT> point_in_halfedge_frame(Index f, const std::array<FT, 3>& b, int k) const
  {
    const Index g = 3 * f + k;
    const auto& o = mesh_.he[std::size_t(g)].opposite;
    const FT len = mesh_.he[std::size_t(g)].length;
    const FT wt = b[std::size_t((k + 1) % 3)], wo = b[std::size_t((k + 2) % 3)];
    return Point_2_ft<FT>{wt * len + wo * o.x, wo * o.y};
  }

  // ------------------------------------------------------------------------------------------------
  // Vertex stars (for vertex sources and path tracing)

  // The mesh's vertex stars (built with it); a mesh made otherwise gets its own here.
  void ensure_vertex_star() const
  {
    if(star_begin_ != nullptr || mesh_.number_of_vertices == 0)
      return;
    build_vertex_star(mesh_, own_star_begin_, own_star_);
    star_begin_ = own_star_begin_.data();
    star_ = own_star_.data();
  }

  // ------------------------------------------------------------------------------------------------
  // Point queries and path tracing

  struct Candidate
  {
    enum Kind { NONE, VERTEX, EDGE_POINT, FACE_SOURCE };
    Kind kind = NONE;
    FT value = FT(0);
    Index source = -1;
    Index vertex = -1;
    Index halfedge = -1; // EDGE_POINT: the point is at abscissa t in this halfedge's frame
    FT t = FT(0);
    FT step = FT(0);     // length of the straight segment from the query point to the candidate point
    Index face = -1;
    std::array<FT, 3> barycentric;
  };

  // The places a traced path has already been: rounding in degenerate faces (zero-length edges, needles)
  // can make two places look equally good; never going back keeps the path finite.
  struct Visited
  {
    std::vector<Index> vertices;
    std::vector<std::pair<Index, FT>> edge_points; // (edge, abscissa in the canonical frame)

    void add_vertex(const std::vector<Index>& cluster) { vertices.insert(vertices.end(), cluster.begin(), cluster.end()); }
    void add_edge_point(Index e, const FT& x) { edge_points.push_back({e, x}); }

    template <class Field>
    bool allows(const Candidate& c, const Mesh& mesh, const Field& field) const
    {
      Index v = -1;
      if(c.kind == Candidate::VERTEX)
        v = c.vertex;
      else if(c.kind == Candidate::EDGE_POINT) {
        const FT len = mesh.he[std::size_t(c.halfedge)].length;
        if(!(c.t > FT(0))) v = mesh.source(c.halfedge);
        else if(!(c.t < len)) v = mesh.target(c.halfedge);
        else {
          const Index e = mesh.he[std::size_t(c.halfedge)].edge;
          const FT x = field.runs_like_canonical(c.halfedge) ? c.t : len - c.t;
          const FT tol = FT(1e-12) * len;
          for(const auto& p : edge_points)
            if(p.first == e && !(p.second - x > tol) && !(x - p.second > tol))
              return false;
          return true;
        }
      }
      if(v < 0)
        return true;
      return std::find(vertices.begin(), vertices.end(), v) == vertices.end();
    }
  };

  // The best way to reach the point (f, b) from the distance field: a vertex of f, a face source in f, or
  // a window on an edge of f. `skip_vertex` / `skip_edge`: the current point of a path (no zero step).
  Candidate best_candidate_in_face(Index f, const std::array<FT, 3>& b, Index skip_vertex, Index skip_edge,
                                   const Visited* visited = nullptr) const
  {
    Candidate best;
    auto offer = [&](const Candidate& c) {
      if(visited != nullptr && !visited->allows(c, mesh_, *this))
        return;
      if(best.kind == Candidate::NONE || c.value < best.value)
        best = c;
    };
    for(int k = 0; k < 3; ++k) {
      const Index g = 3 * f + k;
      const Index v = mesh_.source(g);
      if(v == skip_vertex || !(dist_[std::size_t(v)] < unreached_))
        continue;
      const Point_2_ft<FT> p = point_in_halfedge_frame(f, b, k);
      Candidate c;
      c.kind = Candidate::VERTEX;
      c.step = distance_2(FT(0), FT(0), p.x, p.y);
      c.value = dist_[std::size_t(v)] + c.step;
      c.source = vertex_source_[std::size_t(v)];
      c.vertex = v;
      offer(c);
    }
    for(const Face_source& s : face_sources_) {
      if(s.face != f)
        continue;
      const Point_2_ft<FT> p = point_in_halfedge_frame(f, b, 0);
      const Point_2_ft<FT> q = point_in_halfedge_frame(f, s.barycentric, 0);
      Candidate c;
      c.kind = Candidate::FACE_SOURCE;
      c.step = distance_2(p.x, p.y, q.x, q.y);
      c.value = c.step;
      c.source = s.id;
      c.face = f;
      c.barycentric = s.barycentric;
      offer(c);
    }
    if(field_first_.empty())
      return best;
    for(int k = 0; k < 3; ++k) {
      const Index g = 3 * f + k;
      const Index e = mesh_.he[std::size_t(g)].edge;
      if(e == skip_edge)
        continue;
      const Point_2_ft<FT> p = point_in_halfedge_frame(f, b, k);
      const bool on_edge = b[std::size_t((k + 2) % 3)] == FT(0);
      for_each_window_on_edge(e, [&](const Field_window_view& w) {
        const Local_window<FT> lw = local_window(w.b0, w.b1, w.sx, w.sy, w.sigma, w.from_halfedge, g);
        if(propagates_into(w.from_halfedge, g)) {
          // the point sees the window from its far side: straight to S if the segment crosses it
          FT x;
          const FT den = p.y - lw.sy;
          if(den > FT(0))
            x = lw.sx + (p.x - lw.sx) * (-lw.sy) / den;
          else
            x = p.x;
          if(x < lw.b0) x = lw.b0;
          if(x > lw.b1) x = lw.b1;
          if(!snap_to_end(g, x, skip_vertex))
            return;
          Candidate c;
          c.kind = Candidate::EDGE_POINT;
          c.step = distance_2(x, FT(0), p.x, p.y);
          c.value = window_distance_at(x, lw.sx, lw.sy, lw.sigma) + c.step;
          c.source = w.source;
          c.halfedge = g;
          c.t = x;
          offer(c);
        } else if(on_edge && !(p.x < lw.b0) && !(p.x > lw.b1)) {
          FT x = p.x;
          if(!snap_to_end(g, x, skip_vertex))
            return;
          Candidate c;
          c.kind = Candidate::EDGE_POINT;
          c.value = window_distance_at(x, lw.sx, lw.sy, lw.sigma);
          c.source = w.source;
          c.halfedge = g;
          c.t = x;
          offer(c);
        }
      });
    }
    return best;
  }

  // A crossing point within rounding of an end of the edge is that vertex. Returns false if that vertex is
  // the current point of a path (the step would not move).
  bool snap_to_end(Index g, FT& x, Index skip_vertex) const
  {
    const FT len = mesh_.he[std::size_t(g)].length;
    const FT tol = FT(1e-12) * len;
    if(!(x > tol)) {
      x = FT(0);
      return mesh_.source(g) != skip_vertex;
    }
    if(!(x < len - tol)) {
      x = len;
      return mesh_.target(g) != skip_vertex;
    }
    return true;
  }

  // The vertex and the vertices at the same place (joined to it by zero-length edges).
  std::vector<Index> coincident_vertices(Index v) const
  {
    std::vector<Index> cluster(1, v);
    for(std::size_t i = 0; i < cluster.size(); ++i) {
      const Index u = cluster[i];
      for(Index k = star_begin_[std::size_t(u)]; k < star_begin_[std::size_t(u) + 1]; ++k) {
        const Index h = star_[std::size_t(k)];
        const Index hp = Mesh::prev(h);
        const Index candidates[2] = {mesh_.he[std::size_t(h)].length == FT(0) ? mesh_.target(h) : Index(-1),
                                     mesh_.he[std::size_t(hp)].length == FT(0) ? mesh_.source(hp) : Index(-1)};
        for(Index w : candidates)
          if(w >= 0 && std::find(cluster.begin(), cluster.end(), w) == cluster.end())
            cluster.push_back(w);
      }
    }
    return cluster;
  }

  // The point at vertex v seen from every face around v and around the vertices at the same place.
  std::vector<std::pair<Index, std::array<FT, 3>>> vertex_incarnations(Index v) const
  {
    std::vector<std::pair<Index, std::array<FT, 3>>> out;
    for(Index u : coincident_vertices(v))
      for(Index k = star_begin_[std::size_t(u)]; k < star_begin_[std::size_t(u) + 1]; ++k) {
        const Index h = star_[std::size_t(k)];
        std::array<FT, 3> b = {FT(0), FT(0), FT(0)};
        b[std::size_t(h % 3)] = FT(1);
        out.push_back({Mesh::face_of(h), b});
      }
    return out;
  }

  // Adds the point at ratio r along halfedge g, seen from the faces of the other halfedges of g's edge.
  void add_twin_incarnation(Index g, const FT& r, std::vector<std::pair<Index, std::array<FT, 3>>>& where) const
  {
    mesh_.for_each_other_halfedge(g, [&](Index tw) {
      std::array<FT, 3> b = {FT(0), FT(0), FT(0)};
      if(mesh_.same_direction(tw, g)) {
        b[std::size_t(tw % 3)] = FT(1) - r;
        b[std::size_t((tw % 3 + 1) % 3)] = r;
      } else {
        b[std::size_t(tw % 3)] = r;                   // source(tw) == target(g)
        b[std::size_t((tw % 3 + 1) % 3)] = FT(1) - r; // target(tw) == source(g)
      }
      where.push_back({Mesh::face_of(tw), b});
    });
  }

  Path_node vertex_node(Index v) const { return vertex_path_node(mesh_, v); }

  Path_node edge_node(Index g, const FT& r) const { return edge_path_node(mesh_, g, r); }

  Path_node face_node(Index f, const std::array<FT, 3>& b) const { return face_path_node(mesh_, f, b); }

  // ------------------------------------------------------------------------------------------------
  // ------------------------------------------------------------------------------------------------
  // State shared with the propagation
  const Mesh& mesh_;
  Window_store<Window> windows_;   // the propagation's windows (released at the end of a run)
  std::vector<Index> edge_first_;
  Window_store<Field_window> field_windows_; // the stored field, edge by edge (full field only)
  Window_store<std::uint32_t> field_tags_;   // per stored window: (source + 1) << 2 | side, side 0: into the
                                             // canonical halfedge's face, 1: into the twin's, 2: none
  std::vector<Index> field_first_, field_count_; // per edge: its first stored window (-1: none) and count
  std::vector<FT> dist_;
  std::vector<Index> vertex_source_;
  std::vector<Face_source> face_sources_;
  mutable const Index* star_begin_ = nullptr; // the vertex stars: the mesh's, or own_* for a mesh without them
  mutable const Index* star_ = nullptr;
  mutable std::vector<Index> own_star_begin_, own_star_;
  FT unreached_;
  FT relative_tolerance_;
  FT limit_ = FT(0);
  FT front_ = FT(0);
  bool has_limit_ = false;
  bool stopped_early_ = false;
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_WINDOW_FIELD_H
