// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The stored state of the flat-exact approximation (see flat_exact_propagation.h for the algorithm): the
// distance, nearest source, window and DAG parent of every vertex, the mesh data packed for the propagation, the
// distance function of an edge rebuilt from its two vertex distances, and the point queries (the distance at a
// surface point, its nearest source). Path tracing (flat_exact_paths.h) and the propagation
// (flat_exact_propagation.h) derive from it.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_FLAT_EXACT_FIELD_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_FLAT_EXACT_FIELD_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_types.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>
#include <CGAL/Polyhedral_geodesics_3/internal/geodesic_engine_types.h>
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
class Flat_exact_field
{
public:
  typedef Geodesic_mesh<FT> Mesh;
  typedef typename Mesh::Index Index;
  typedef Geodesic_path_node<FT> Path_node;
  typedef Geodesic_point_distance<FT> Point_distance;

  // The order of the edge queue (tuning and measurements). With `candidate` and `function_minimum` every value an
  // edge gives is at least its key, so the distances below the front are final, which the distance limit and
  // the stop targets rely on; the two others are for comparisons only. Vertex lowerings per vertex measured on
  // CGAL's demo meshes (3 random sources each; mech-holes-shark in parentheses): candidate 1.00 - 1.19 (2.80),
  // with a third fewer edges queued, function_minimum 1.14 - 1.63 (3.04), smaller_vertex about the same,
  // larger_vertex 1.09 - 1.59 (3.24).
  // The offset of an edge whose two ends belong to different windows (see edge_window()).
  enum class Window_meeting
  {
    smaller_offset, // the smaller of the two ends' offsets: the flatter of the two fronts (default)
    zero_offset     // offset 0, as the thesis rebuilds every edge (the rule of MDCS up to November 2026)
  };

  enum class Queue_key
  {
    candidate,        // the smallest value the edge gives to an opposite vertex that it lowers (default); an edge
                      // that lowers neither is not queued
    function_minimum, // the minimum of the edge's distance function over the edge
    smaller_vertex,   // min(D(v1), D(v2))
    larger_vertex     // max(D(v1), D(v2))
  };

  // Counters beyond Geodesic_statistics (tests and tuning).
  struct Counters
  {
    std::size_t edges_propagated = 0;   // edges taken from the queue
    std::size_t dag_searches = 0;       // depth-first searches for cycles (lowerings of reached vertices)
    std::size_t dag_search_visits = 0;  // vertices visited by them
    std::size_t side_links = 0;         // edges with side links (built with the first path query)
    std::size_t side_links_refused = 0; // edges whose preferred side links would have closed a cycle
    std::size_t stuck_restarts = 0;     // restarts through an edge with one unreached vertex (pinched vertices)
  };

  explicit Flat_exact_field(const Mesh& mesh) : mesh_(mesh), he_(mesh.he)
  {
    unreached_ = FT(std::numeric_limits<double>::max() / 16);
    epsilon_ = unit_roundoff<FT>();
    improvement_ = FT(16) * epsilon_;
    build_vertex_edges();
    vertex_is_pseudo_source_.assign(mesh_.number_of_vertices, 0);
    // vertices where shortest paths can bend: saddles (angle sum above 2 pi) and reflex boundary vertices
    for(std::size_t v = 0; v < mesh_.number_of_vertices; ++v)
      vertex_is_pseudo_source_[v] = to_double_value(mesh_.vertex_angle_sum[v]) >
                                    (mesh_.vertex_on_boundary[v] ? 1 : 2) * 3.14159265358979323846 + 1e-9;
    clear();
  }

  void clear()
  {
    const std::size_t nv = mesh_.number_of_vertices, ne = mesh_.number_of_edges;
    vs_.assign(nv, Vertex_state{unreached_, FT(0), -1, -1});
    parent_he_.assign(nv, -1);
    parent_kind_.assign(nv, NONE);
    lowerings_.assign(nv, 0);
    first_reached_.assign(nv, 0);
    last_lowered_.assign(nv, 0);
    clock_ = 0;
    child_next_.assign(nv, -1);
    child_prev_.assign(nv, -1);
    child_head_.assign(ne, -1);
    side_he_.clear();
    side_mask_.clear();
    heap_position_.assign(ne, -1);
    visit_vertex_.assign(nv, 0);
    search_stamp_ = 0;
    heap_.clear();
    peak_heap_ = 0;
    vertex_sources_.clear();
    face_sources_.clear();
    face_source_index_.clear();
    stats_ = Geodesic_statistics();
    counters_ = Counters();
    front_ = FT(0);
    bound_ = unreached_;
    stopped_early_ = false;
  }

  void set_keep_windows(bool) {} // one interval per edge, always kept
  void set_distance_limit(FT limit) { limit_ = limit; has_limit_ = true; }
  void clear_distance_limit() { has_limit_ = false; }
  void set_stop_targets(const std::vector<Index>& targets) { stop_targets_ = targets; }
  void set_queue_key(Queue_key key) { queue_key_ = key; }
  // Windows rooted at saddle and reflex boundary vertices (default on; off: the thesis's rule everywhere).
  void set_vertex_windows(bool on) { vertex_windows_ = on; }
  // Where two windows meet on an edge (default: the smaller offset). Comparisons and tests.
  void set_window_meeting(Window_meeting rule) { window_meeting_ = rule; }
  // Comparisons only (bench_flat_exact_window_meeting --true-roots): the window of each vertex given by the
  // caller instead of tracked. roots[v] is the vertex where the shortest path to v last bends (-1: straight
  // from its source), for instance from the exact shortest paths; the offset of a window is then the flat-exact
  // distance of its root, and an edge whose ends have different roots takes the meeting rule. Null: tracked
  // (default). The vector must outlive the runs.
  void set_window_roots(const std::vector<Index>* roots)
  {
    if(roots != nullptr) {
      if(roots->size() != mesh_.number_of_vertices)
        throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: one window root per vertex expected");
      for(Index r : *roots)
        if(r < -1 || r >= Index(mesh_.number_of_vertices))
          throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: a window root is not a vertex of the mesh");
    }
    given_roots_ = roots;
  }
  // Comparisons only, with set_window_roots(): the offset of the window rooted at r is offsets[r] (for instance
  // the exact distance of r) instead of the flat-exact distance of r. Null: the flat-exact distances (default).
  // Ignored without given roots. The vector must outlive the runs.
  void set_window_root_offsets(const std::vector<FT>* offsets)
  {
    if(offsets != nullptr) {
      if(offsets->size() != mesh_.number_of_vertices)
        throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: one window offset per vertex expected");
      for(const FT& sigma : *offsets)
        if(!(sigma >= FT(0))) // also NaN
          throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: a window offset is negative or not a number");
    }
    given_offsets_ = offsets;
  }
  // The root of the window of v as tracked (-1: straight from a source, a meeting of two windows, or unreached).
  Index window_root(Index v) const { return vs_[std::size_t(v)].root; }
  // Can shortest paths bend at v (a saddle or a reflex boundary vertex), so that v roots a window?
  bool can_bend_at(Index v) const { return vertex_is_pseudo_source_[std::size_t(v)] != 0; }
  // The relative change that a vertex's fourth and later values must make (default 1e-9, see
  // lowering_tolerance(); 0: only rounding, as for the first three). Tuning and tests.
  void set_settle_tolerance(FT t) { settle_tolerance_ = t > improvement_ ? t : improvement_; }

  FT vertex_distance(Index v) const
  {
    const FT& d = vs_[std::size_t(v)].dist;
    return final_value(d) ? d : FT(std::numeric_limits<double>::infinity());
  }

  Index vertex_source(Index v) const { return final_value(vs_[std::size_t(v)].dist) ? vs_[std::size_t(v)].source : -1; }

  const Geodesic_statistics& statistics() const { return stats_; }
  const Counters& counters() const { return counters_; }

  // ------------------------------------------------------------------------------------------------
  // Queries

  Point_distance distance_at(Index f, const std::array<FT, 3>& b) const
  {
    const Candidate c = best_candidate(f, b);
    if(c.kind == Candidate::NONE)
      return {FT(std::numeric_limits<double>::infinity()), -1};
    return {c.value, c.source};
  }

protected:
  // ------------------------------------------------------------------------------------------------
  // Types

  enum Parent_kind : unsigned char
  {
    NONE,          // unreached
    ROOT_VERTEX,   // a vertex source
    ROOT_FACE,     // a corner of the face of a face source: parent_he_ is the index of the face source
    EUCLID,        // straight from the pseudo-source of the edge of parent_he_ (the vertex is opposite it)
    ALONG_SOURCE,  // along the edge from source(parent_he_) (the vertex is opposite parent_he_)
    ALONG_TARGET,  // along the edge from target(parent_he_)
    EDGE_NEIGHBOR  // along the edge of parent_he_ itself, from its other end (vertex sources, pinched vertices)
  };

  struct Vertex_source
  {
    Index vertex;
    Index id;
  };

  struct Face_source
  {
    Index face;
    std::array<FT, 3> barycentric;
    Index id;
  };

  struct Heap_entry
  {
    FT key;
    Index edge;
  };

  // The distance function of an edge: sigma + the distance to a pseudo-source (x, +-y), y >= 0, in the frame
  // of one of its halfedges; `root` is the vertex the window hangs from (-1: straight from a source).
  struct Pseudo_source
  {
    bool valid;
    FT x, y;
    FT sigma;
    Index root;
  };

  // An edge around a vertex: its ends (those of its canonical halfedge), the vertices opposite it (-1: none)
  // and its length.
  struct Incident_edge
  {
    Index edge, h, a, b, y1, y2; // h: the canonical halfedge, from a to b
    FT length;
  };

  struct Candidate
  {
    enum Kind { NONE, CORNER, EDGE, FACE_SOURCE };
    Kind kind = NONE;
    FT value = FT(0);
    Index source = -1;
    Index index = -1;  // corner vertex, halfedge (EDGE), or face source
    Index face = -1;   // FACE_SOURCE: its face
    FT t = FT(0);      // EDGE: where the segment to the pseudo-source crosses the halfedge (arc length)
    bool on_edge = false; // EDGE: the query point itself lies on that edge
  };

  // The state of the back-tracing: at a vertex, or on the edge of `halfedge` at arc length t from its source,
  // arrived from the face of `halfedge`.
  struct Walker
  {
    Index vertex;
    Index halfedge;
    FT t;
  };

  // ------------------------------------------------------------------------------------------------
  // Mesh helpers

  // The edges around each vertex (CSR: vedge_begin_, vedge_), as edge indices.
  void build_vertex_edges()
  {
    const std::size_t nv = mesh_.number_of_vertices, ne = mesh_.number_of_edges;
    vedge_begin_.assign(nv + 1, 0);
    for(std::size_t e = 0; e < ne; ++e) {
      const Index h = mesh_.edge_halfedge[e];
      const Index a = he_source(h), b = he_target(h);
      ++vedge_begin_[std::size_t(a) + 1];
      if(b != a)
        ++vedge_begin_[std::size_t(b) + 1];
    }
    for(std::size_t v = 0; v < nv; ++v)
      vedge_begin_[v + 1] += vedge_begin_[v];
    vedge_.resize(std::size_t(vedge_begin_[nv]));
    vedge_other_.resize(std::size_t(vedge_begin_[nv]));
    std::vector<Index> fill(vedge_begin_.begin(), vedge_begin_.end() - 1);
    for(std::size_t e = 0; e < ne; ++e) {
      const Index h = mesh_.edge_halfedge[e];
      const Index a = he_source(h), b = he_target(h);
      const std::size_t ka = std::size_t(fill[std::size_t(a)]++);
      vedge_[ka] = Index(e);
      vedge_other_[ka] = b;
      if(b != a) {
        const std::size_t kb = std::size_t(fill[std::size_t(b)]++);
        vedge_[kb] = Index(e);
        vedge_other_[kb] = a;
      }
    }
  }

  // The mesh's packed data per halfedge (he_[h].length, .opposite, .source, .twin, .edge).
  typedef Geodesic_halfedge<FT> Halfedge_data;

  Index he_source(Index h) const { return he_[std::size_t(h)].source; }
  Index he_target(Index h) const { return he_[std::size_t(Mesh::next(h))].source; }
  Index he_opposite_vertex(Index h) const { return he_[std::size_t(Mesh::prev(h))].source; }

  bool reached(Index v) const { return vs_[std::size_t(v)].dist < unreached_; }

  // The relative amount by which a new value must beat the distance of v. A vertex's first three values only
  // need to beat rounding. A vertex lowered more often is in a cluster whose values creep down together: in
  // strips of elongated faces, a pseudo-source rebuilt from two close vertices and extended to a farther one
  // amplifies a change of the ends, so the vertices of the strip lower one another in turn by ever smaller
  // amounts (on the Loop subdivision of mannequin-devil: up to 1,647 values for one vertex, most changes below
  // 1e-9 of the distance, 2.6 values per vertex in all). From its fourth value on, a change must be at least
  // settle_tolerance_ (1e-9) of the distance. There this cut the values to 1.5 per vertex, changed no distance
  // by more than 8.1e-9 of itself and E not in its first 5 digits; on meshes without such clusters nothing
  // changes.
  FT lowering_tolerance(Index v) const
  {
    return lowerings_[std::size_t(v)] > settle_after_ ? settle_tolerance_ : improvement_;
  }

  bool lowers(Index v, const FT& value) const
  {
    const FT& old = vs_[std::size_t(v)].dist;
    return value < old - lowering_tolerance(v) * old;
  }

  bool final_value(const FT& d) const { return d < unreached_ && d <= bound_; }

  // ------------------------------------------------------------------------------------------------
  // The distance function of an edge

  // The pseudo-source at distances c1 from (0,0) and c2 from (L,0), with y >= 0 (Heron's formula for y,
  // accurate when the pseudo-source is close to the line of the edge). Invalid when no such point exists
  // (|c1 - c2| > L or c1 + c2 < L beyond rounding) or L == 0.
  Pseudo_source pseudo_source(const FT& c1, const FT& c2, const FT& L) const
  {
    using std::sqrt;
    Pseudo_source s{false, FT(0), FT(0), FT(0), -1};
    if(!(L > FT(0)))
      return s;
    const FT tol = FT(64) * epsilon_ * (c1 + c2 + L);
    FT f1 = L + c2 - c1, f2 = c1 + c2 - L, f3 = L + c1 - c2;
    if(f1 < -tol || f2 < -tol || f3 < -tol)
      return s;
    if(f1 < FT(0)) f1 = FT(0);
    if(f2 < FT(0)) f2 = FT(0);
    if(f3 < FT(0)) f3 = FT(0);
    const FT f4 = c1 + c2 + L;
    s.valid = true;
    const FT inverse = FT(1) / (FT(2) * L);
    s.x = (c1 - c2) * (c1 + c2) * inverse + L / FT(2);
    s.y = sqrt(f1 * f2 * f3 * f4) * inverse;
    return s;
  }

  // The window of the edge (a, b): the one both ends belong to, or the window of one end rooted at the other.
  // Else two windows meet on the edge, and the offset is the smaller of the two ends' offsets, with no root: of
  // the two real fronts the flatter one (a larger radius d - sigma), so the rebuilt front is never more curved
  // than both. The thesis's zero offset here made every vertex downstream of a meeting flat-fronted (a child
  // inherits the edge's offset), which overestimates ahead of the edge; the smaller offset lowered E on 28 of
  // 30 meshes (the geodesics manual, *Where two windows meet*). Without vertex windows every offset is 0, the
  // thesis's rule. The thesis's zero offset here stays available (set_window_meeting()).
  void edge_window(Index a, Index b, FT& sigma, Index& root) const
  {
    if(given_roots_ != nullptr)
      return given_edge_window(a, b, sigma, root);
    const std::size_t ia = std::size_t(a), ib = std::size_t(b);
    if(vs_[ia].root == vs_[ib].root && vs_[ia].offset == vs_[ib].offset) {
      sigma = vs_[ia].offset;
      root = vs_[ia].root;
    } else if(vs_[ib].root == a && vs_[ib].offset == vs_[ia].dist) {
      sigma = vs_[ia].dist;
      root = a;
    } else if(vs_[ia].root == b && vs_[ia].offset == vs_[ib].dist) {
      sigma = vs_[ib].dist;
      root = b;
    } else {
      sigma = window_meeting_ == Window_meeting::smaller_offset ? (std::min)(vs_[ia].offset, vs_[ib].offset) : FT(0);
      root = -1;
    }
  }

  // edge_window() with the caller's roots (set_window_roots()): the same cases, with the roots given and the
  // offsets read from the roots' current distances (a root not reached yet counts as a source), or given too
  // (set_window_root_offsets()).
  void given_edge_window(Index a, Index b, FT& sigma, Index& root) const
  {
    const Index ra = (*given_roots_)[std::size_t(a)], rb = (*given_roots_)[std::size_t(b)];
    auto offset = [this](Index r) {
      if(r >= 0 && given_offsets_ != nullptr)
        return (*given_offsets_)[std::size_t(r)];
      return r < 0 || !reached(r) ? FT(0) : vs_[std::size_t(r)].dist;
    };
    if(ra == rb) {
      sigma = offset(ra);
      root = ra;
    } else if(rb == a || ra == b) {
      root = rb == a ? a : b;
      sigma = offset(root);
    } else {
      sigma = window_meeting_ == Window_meeting::smaller_offset ? (std::min)(offset(ra), offset(rb)) : FT(0);
      root = -1;
    }
  }

  // The distance function of the edge of h in h's frame (pseudo-source with the magnitude of y).
  Pseudo_source pseudo_source_of(Index h) const
  {
    return pseudo_source_ab(he_source(h), he_target(h), he_[std::size_t(h)].length);
  }

  // The same for the edge from a to b of length L, in the frame where a is at (0,0) and b at (L,0).
  Pseudo_source pseudo_source_ab(Index a, Index b, const FT& L) const
  {
    // two sources meet on the edge: no single pseudo-source explains both ends (rebuilding one would put a
    // vertex beyond the edge too close to both), the edge propagates along its ends only
    if(vs_[std::size_t(a)].source != vs_[std::size_t(b)].source)
      return Pseudo_source{false, FT(0), FT(0), FT(0), -1};
    FT sigma;
    Index root;
    edge_window(a, b, sigma, root);
    Pseudo_source s = pseudo_source(vs_[std::size_t(a)].dist - sigma, vs_[std::size_t(b)].dist - sigma, L);
    s.sigma = sigma;
    s.root = root;
    return s;
  }

  // The nearest source of the vertex opposite h when it is reached from the edge of h in the way `kind`.
  Index source_through(Index h, Parent_kind kind) const
  {
    const Index a = he_source(h), b = he_target(h);
    if(kind == ALONG_SOURCE) return vs_[std::size_t(a)].source;
    if(kind == ALONG_TARGET) return vs_[std::size_t(b)].source;
    if(vs_[std::size_t(a)].source == vs_[std::size_t(b)].source)
      return vs_[std::size_t(a)].source;
    const FT via_a = vs_[std::size_t(a)].dist + he_[std::size_t(Mesh::prev(h))].length;
    const FT via_b = vs_[std::size_t(b)].dist + he_[std::size_t(Mesh::next(h))].length;
    return via_a <= via_b ? vs_[std::size_t(a)].source : vs_[std::size_t(b)].source;
  }

  // The edge a vertex was lowered from (-1: a source, or unreached).
  Index parent_edge(Index v) const
  {
    const Parent_kind k = Parent_kind(parent_kind_[std::size_t(v)]);
    if(k == NONE || k == ROOT_VERTEX || k == ROOT_FACE)
      return -1;
    return he_[std::size_t(parent_he_[std::size_t(v)])].edge;
  }

  // ------------------------------------------------------------------------------------------------
  // Points in faces

  static FT length_2(const FT& x, const FT& y)
  {
    using std::sqrt;
    return sqrt(x * x + y * y);
  }

  // The point with barycentric coordinates b of face f, in the frame of the face's halfedge 3f+k.
  Point_2_ft<FT> point_in_halfedge_frame(Index f, const std::array<FT, 3>& b, int k) const
  {
    const Index g = 3 * f + k;
    const auto& o = he_[std::size_t(g)].opposite;
    const FT len = he_[std::size_t(g)].length;
    const FT wt = b[std::size_t((k + 1) % 3)], wo = b[std::size_t((k + 2) % 3)];
    return Point_2_ft<FT>{wt * len + wo * o.x, wo * o.y};
  }

  bool usable(Index v) const { return reached(v) && (!stopped_early_ || vs_[std::size_t(v)].dist <= bound_); }

  bool has_face_source(Index f) const
  {
    auto it = std::lower_bound(face_source_index_.begin(), face_source_index_.end(), std::make_pair(f, Index(-1)));
    return it != face_source_index_.end() && it->first == f;
  }

  // The best way to reach the point (f, b): a face source in f, a corner, or the pseudo-source of an edge of f
  // seen through that edge. A point on an edge is also looked at from the face on the other side.
  // With `dag_only` (paths, side links built), an edge whose side links point to the query's face is skipped:
  // its distance does not come from across it (a tie in degenerate faces).
  Candidate best_candidate(Index f, const std::array<FT, 3>& b, bool dag_only = false) const
  {
    Candidate best;
    int zeros = 0, nonzero = 0;
    for(int k = 0; k < 3; ++k) {
      if(b[std::size_t(k)] == FT(0)) ++zeros;
      else nonzero = k;
    }
    if(zeros >= 2) {
      const Index v = he_source(3 * f + nonzero);
      if(usable(v) && final_value(vs_[std::size_t(v)].dist)) {
        best.kind = Candidate::CORNER;
        best.value = vs_[std::size_t(v)].dist;
        best.source = vs_[std::size_t(v)].source;
        best.index = v;
      }
      return best;
    }
    candidates_in_face(f, b, best, dag_only);
    if(zeros == 1) {
      int k = 0;
      while(b[std::size_t((k + 2) % 3)] != FT(0))
        ++k;
      const Index g = 3 * f + k;
      const Index tw = he_[std::size_t(g)].twin;
      if(tw >= 0) {
        std::array<FT, 3> b2 = {FT(0), FT(0), FT(0)};
        b2[std::size_t(tw % 3)] = b[std::size_t((k + 1) % 3)];
        b2[std::size_t((tw % 3 + 1) % 3)] = b[std::size_t(k)];
        candidates_in_face(Mesh::face_of(tw), b2, best, dag_only);
      }
    }
    if(best.kind != Candidate::NONE && !final_value(best.value))
      best.kind = Candidate::NONE;
    return best;
  }

  void consider(Candidate& best, const Candidate& c) const
  {
    if(best.kind == Candidate::NONE || c.value < best.value)
      best = c;
  }

  void candidates_in_face(Index f, const std::array<FT, 3>& b, Candidate& best, bool dag_only) const
  {
    using std::sqrt;
    // face sources
    auto it = std::lower_bound(face_source_index_.begin(), face_source_index_.end(), std::make_pair(f, Index(-1)));
    for(; it != face_source_index_.end() && it->first == f; ++it) {
      const Face_source& s = face_sources_[std::size_t(it->second)];
      const Point_2_ft<FT> p = point_in_halfedge_frame(f, b, 0), q = point_in_halfedge_frame(f, s.barycentric, 0);
      Candidate c;
      c.kind = Candidate::FACE_SOURCE;
      c.value = length_2(p.x - q.x, p.y - q.y);
      c.source = s.id;
      c.index = it->second;
      c.face = f;
      consider(best, c);
    }
    for(int k = 0; k < 3; ++k) {
      const Index h = 3 * f + k;
      const Index a = he_source(h), bv = he_target(h);
      const Point_2_ft<FT> p = point_in_halfedge_frame(f, b, k);
      if(usable(a)) {
        Candidate c;
        c.kind = Candidate::CORNER;
        c.value = vs_[std::size_t(a)].dist + length_2(p.x, p.y);
        c.source = vs_[std::size_t(a)].source;
        c.index = a;
        consider(best, c);
      }
      if(!usable(a) || !usable(bv))
        continue;
      if(dag_only && side_he_[std::size_t(he_[std::size_t(h)].edge)] == h)
        continue;
      const FT L = he_[std::size_t(h)].length;
      const Pseudo_source s = pseudo_source_of(h);
      if(!s.valid)
        continue;
      const FT py = p.y < FT(0) ? FT(0) : p.y;
      const FT denom = py + s.y;
      if(!(denom > FT(0)))
        continue;
      const FT t = s.x + (p.x - s.x) * s.y / denom;
      if(!(t >= FT(0) && t <= L))
        continue;
      Candidate c;
      c.kind = Candidate::EDGE;
      const FT dx = p.x - s.x;
      c.value = s.sigma + sqrt(dx * dx + denom * denom);
      c.source = source_through(h, EUCLID);
      c.index = h;
      c.t = t;
      c.on_edge = b[std::size_t((k + 2) % 3)] == FT(0);
      consider(best, c);
    }
  }

  // ------------------------------------------------------------------------------------------------
  // Data

  const Mesh& mesh_;
  FT unreached_;
  FT epsilon_;
  FT improvement_; // a lowering must beat the current distance by this relative amount (rounding)
  // ... and a vertex's (settle_after_ + 2)-th and later values, by this one (see lowering_tolerance())
  FT settle_tolerance_ = FT(1e-9);
  unsigned char settle_after_ = 2;
  Queue_key queue_key_ = Queue_key::candidate;
  bool vertex_windows_ = true; // windows rooted at saddle and reflex boundary vertices
  Window_meeting window_meeting_ = Window_meeting::smaller_offset;
  const std::vector<Index>* given_roots_ = nullptr; // set_window_roots()
  const std::vector<FT>* given_offsets_ = nullptr;  // set_window_root_offsets()

  // per vertex
  // the hot per-vertex data, together: the distance, the offset of the vertex's window (the distance of its
  // root), the nearest source, the root vertex of the window (-1: a source, or a meeting of two windows)
  struct Vertex_state
  {
    FT dist;
    FT offset;
    Index source;
    Index root;
  };
  Large_vector<Vertex_state> vs_;
  Large_vector<Index> parent_he_;            // see Parent_kind
  Large_vector<unsigned char> parent_kind_;
  Large_vector<unsigned char> lowerings_;    // how often the vertex was lowered (saturates at 255)
  Large_vector<char> vertex_is_pseudo_source_; // saddle or boundary vertex
  Large_vector<std::uint32_t> first_reached_, last_lowered_; // lowering times (clock_)
  std::uint32_t clock_ = 0;
  Large_vector<Index> child_next_, child_prev_; // the list of the vertices updated from the same edge
  Large_vector<Index> vedge_begin_;
  Large_vector<Index> vedge_;                // the edges around each vertex
  Large_vector<Index> vedge_other_;          // and their other ends (an edge waits for both ends: checked first)
  const Large_vector<Halfedge_data>& he_;   // the mesh's halfedges: he_[h].length, .opposite, .source, .twin, .edge
  // per edge
  Large_vector<Index> child_head_;           // first vertex updated from the edge
  // side links, built with the first path query (mutable: a cache)
  mutable Large_vector<Index> side_he_;      // the halfedge of the edge in the face of its side links, -1: none
  mutable Large_vector<unsigned char> side_mask_; // its side parents: bit 0 the edge of next(side_he_), bit 1 prev
  Large_vector<Index> heap_position_;        // the edge's position in heap_, -1: not queued
  // searches
  Large_vector<std::uint32_t> visit_vertex_;
  std::vector<Index> stack_, starts_, touched_;
  std::uint32_t search_stamp_ = 0;
  bool recording_touched_ = false;

  Large_vector<Heap_entry> heap_;
  std::size_t peak_heap_ = 0;
  std::vector<Vertex_source> vertex_sources_;
  std::vector<Face_source> face_sources_;
  std::vector<std::pair<Index, Index>> face_source_index_; // (face, face source), sorted

  std::vector<Index> stop_targets_;
  FT limit_ = FT(0);
  bool has_limit_ = false;
  FT front_ = FT(0);
  FT bound_ = FT(0);
  bool stopped_early_ = false;
  Geodesic_statistics stats_;
  mutable Counters counters_;
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_FLAT_EXACT_FIELD_H
