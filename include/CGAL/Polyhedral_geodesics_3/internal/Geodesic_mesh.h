// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A compact, index-based copy of a triangle mesh for the geodesic algorithms: faces are numbered
// 0..F-1 (by the mesh's face index map, or in the order of a triangle soup), the three corners of face f are
// the compact halfedges 3f, 3f+1, 3f+2 (halfedge(f), next, next(next); or the soup triangle's corners 0, 1, 2),
// every halfedge knows the other halfedges of its edge and, in its own planar frame, the position of the
// opposite corner. Building it once makes the propagation independent of the input (Surface_mesh, Polyhedron_3
// with or without ids, OpenMesh, a triangle soup) and keeps the per-window work on contiguous arrays. The data of
// a halfedge is one packed record, which every engine reads in place. The builders are in
// build_geodesic_mesh.h (included at the end of this file).
//
// Edges. The halfedges of an edge form a cycle (`radial`). On an edge of an oriented manifold surface the
// cycle is the halfedge and its twin, which runs the other way; on a border edge it is the halfedge alone. A
// triangle soup may also have *non-manifold* edges (three or more faces) and *reversed* edges (two faces that run
// through the edge in the same direction, as where a Moebius strip closes); their halfedges have twin -1 and
// are linked by `radial` only, so engines that read `twin` alone see them as borders and must refuse such
// meshes (Geodesic_mesh::has_special_edges()).

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_GEODESIC_MESH_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_GEODESIC_MESH_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/MDCS/internal/bounding_box.h>
#include <CGAL/number_utils.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Large_page_allocator.h>

#include <boost/multiprecision/number.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

// double value of a number of the computation: CGAL::to_double for CGAL number types, the explicit
// conversion for Boost.Multiprecision (CGAL 5.5 has no Real_embeddable_traits for its floating types).
template <class FT>
double to_double_value(const FT& x)
{
  return CGAL::to_double(x);
}

inline double to_double_value(double x) { return x; }

template <class Backend, boost::multiprecision::expression_template_option ET>
double to_double_value(const boost::multiprecision::number<Backend, ET>& x)
{
  return x.template convert_to<double>();
}

template <class FT>
struct Point_2_ft
{
  FT x, y;
};

// The arrays of the compact mesh and of the engines: std::vector with huge pages for large blocks.
template <class T>
using Large_vector = std::vector<T, Large_page_allocator<T>>;

// The data of one compact halfedge, packed: the propagation reads a face's three halfedges together (120
// contiguous bytes with double), and one array instead of five costs fewer page faults when it is filled.
template <class FT>
struct Geodesic_halfedge
{
  Point_2_ft<FT> opposite; // the opposite corner in the halfedge's frame: source at (0,0), target at (length,0),
                           // the face on the side y >= 0
  FT length;               // of the edge (the same, bit for bit, on every halfedge of the edge)
  std::int32_t source;     // the source vertex
  std::int32_t twin;       // the twin halfedge on an edge of an oriented manifold, -1 on a border, non-manifold
                           // or reversed edge
  std::int32_t edge;       // the undirected edge
  std::int32_t radial;     // the next halfedge of the same edge (a cycle in increasing order; the twin on an
                           // oriented manifold edge, the halfedge itself on a border edge)
};

template <class FT>
struct Geodesic_mesh
{
  typedef std::int32_t Index;

  std::size_t number_of_vertices = 0;
  std::size_t number_of_faces = 0;
  std::size_t number_of_edges = 0;

  Large_vector<std::array<FT, 3>> points;     // per vertex
  Large_vector<Geodesic_halfedge<FT>> he;     // per compact halfedge (3 per face)
  Large_vector<Index> edge_halfedge;          // canonical halfedge of each edge (the one the edge frame uses)
  Large_vector<Index> vertex_halfedge;        // one compact halfedge whose source is the vertex, -1 if isolated
  Large_vector<char> vertex_on_boundary;      // an end of an edge with one face
  Large_vector<char> vertex_is_singular;      // a pinched vertex (its faces form several fans) or an end of a
                                              // non-manifold edge: shortest paths may bend there whatever the angles
  Large_vector<FT> vertex_angle_sum;          // sum of the corner angles (as double-precision estimate in FT)
  Large_vector<Index> star_begin, star;       // the outgoing halfedges of vertex v (every fan) are
                                              // star[star_begin[v] .. star_begin[v + 1])

  // The shape of the surface (see above).
  std::size_t number_of_border_edges = 0;
  std::size_t number_of_nonmanifold_edges = 0; // edges of three or more faces
  std::size_t number_of_reversed_edges = 0;    // edges of two faces that run through them in the same direction
  std::size_t number_of_pinched_vertices = 0;  // vertices whose faces form several fans
  std::size_t number_of_isolated_vertices = 0; // vertices of no face

  // Whether some edge is non-manifold or reversed: engines that follow `twin` alone must refuse the mesh.
  bool has_special_edges() const { return number_of_nonmanifold_edges + number_of_reversed_edges > 0; }

  static Index face_of(Index h) { return h / 3; }
  static Index next(Index h) { return h % 3 == 2 ? h - 2 : h + 1; }
  static Index prev(Index h) { return h % 3 == 0 ? h + 2 : h - 1; }
  Index source(Index h) const { return he[std::size_t(h)].source; }
  Index target(Index h) const { return he[std::size_t(next(h))].source; }
  Index opposite_vertex(Index h) const { return he[std::size_t(prev(h))].source; }
  Index radial(Index h) const { return he[std::size_t(h)].radial; }
  // Whether h and g (two halfedges of one edge) run in the same direction.
  bool same_direction(Index h, Index g) const { return source(h) == source(g); }
  // Whether h runs in the direction of its edge's canonical halfedge (whose frame the edge's windows use).
  bool runs_like_canonical(Index h) const
  {
    return source(h) == source(edge_halfedge[std::size_t(he[std::size_t(h)].edge)]);
  }
  // Calls f(g) for every other halfedge g of h's edge (the twin on an oriented manifold edge, none on a border).
  template <class F>
  void for_each_other_halfedge(Index h, F f) const
  {
    for(Index g = he[std::size_t(h)].radial; g != h; g = he[std::size_t(g)].radial)
      f(g);
  }
};

// The bytes a compact mesh holds.
template <class FT>
std::size_t compact_mesh_bytes(const Geodesic_mesh<FT>& m)
{
  return m.points.capacity() * sizeof(m.points[0]) + m.he.capacity() * sizeof(Geodesic_halfedge<FT>) +
         (m.edge_halfedge.capacity() + m.vertex_halfedge.capacity() + m.star_begin.capacity() + m.star.capacity()) *
             sizeof(typename Geodesic_mesh<FT>::Index) +
         m.vertex_on_boundary.capacity() + m.vertex_is_singular.capacity() + m.vertex_angle_sum.capacity() * sizeof(FT);
}

// The outgoing compact halfedges of every vertex, as compressed rows: those of v are
// star[star_begin[v] .. star_begin[v + 1]).
template <class FT>
void build_vertex_star(const Geodesic_mesh<FT>& mesh, std::vector<typename Geodesic_mesh<FT>::Index>& star_begin,
                       std::vector<typename Geodesic_mesh<FT>::Index>& star)
{
  typedef typename Geodesic_mesh<FT>::Index Index;
  const std::size_t nv = mesh.number_of_vertices, nh = 3 * mesh.number_of_faces;
  star_begin.assign(nv + 1, 0);
  for(std::size_t h = 0; h < nh; ++h)
    ++star_begin[std::size_t(mesh.he[h].source) + 1];
  for(std::size_t v = 0; v < nv; ++v)
    star_begin[v + 1] += star_begin[v];
  star.assign(nh, 0);
  std::vector<Index> fill(star_begin.begin(), star_begin.end() - 1);
  for(std::size_t h = 0; h < nh; ++h)
    star[std::size_t(fill[std::size_t(mesh.he[h].source)]++)] = Index(h);
}

// The safety net of the window engines after a run with interval merging: calls expand(w) for every reached
// vertex w (dist[w] < unreached) next to an unreached one. Returns whether it called it at all.
template <class FT, class IndexVector, class DistVector, class Expand>
bool expand_reached_neighbours_of_unreached(const Geodesic_mesh<FT>& mesh, const IndexVector& star_begin,
                                            const IndexVector& star, const DistVector& dist, const FT& unreached,
                                            Expand expand)
{
  typedef typename Geodesic_mesh<FT>::Index Index;
  bool any = false;
  for(std::size_t u = 0; u < dist.size(); ++u) {
    if(dist[u] < unreached)
      continue;
    for(Index k = star_begin[u]; k < star_begin[u + 1]; ++k) {
      const Index h = star[std::size_t(k)]; // source(h) == u
      for(Index w : {mesh.target(h), mesh.source(Geodesic_mesh<FT>::prev(h))})
        if(dist[std::size_t(w)] < unreached) {
          expand(w);
          any = true;
        }
    }
  }
  return any;
}

// Shortest paths can bend only at saddle vertices (angle sum above 2 pi) and boundary vertices. Flat vertices
// are included: rounding decides their side.
// Singular vertices (pinched, or on a non-manifold edge) are included whatever their angles.
template <class FT>
bool is_saddle_or_boundary_vertex(const Geodesic_mesh<FT>& mesh, std::size_t v)
{
  return mesh.vertex_on_boundary[v] || (!mesh.vertex_is_singular.empty() && mesh.vertex_is_singular[v]) ||
         to_double_value(mesh.vertex_angle_sum[v]) > 2 * 3.14159265358979323846 - 1e-9;
}

template <class FT>
FT squared_distance_3(const std::array<FT, 3>& a, const std::array<FT, 3>& b)
{
  const FT dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
  return dx * dx + dy * dy + dz * dz;
}

// The opposite corner c of the halfedge from a to b (length `length`) in the halfedge's frame, robustly: the
// foot of c is a projection (dot product) and its height the norm of a cross product, so needle and zero-area
// faces give a tiny non-negative height instead of the square root of a negative number.
template <class FT>
Point_2_ft<FT> halfedge_frame_opposite(const std::array<FT, 3>& a, const std::array<FT, 3>& b,
                                       const std::array<FT, 3>& c, const FT& length)
{
  using std::sqrt;
  const FT ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const FT vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  if(length == FT(0)) {
    // Zero-length edge: the face is a segment from a to c; put c on the y axis of a degenerate frame.
    return Point_2_ft<FT>{FT(0), sqrt(vx * vx + vy * vy + vz * vz)};
  }
  const FT dot = ux * vx + uy * vy + uz * vz;
  const FT cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
  return Point_2_ft<FT>{dot / length, sqrt(cx * cx + cy * cy + cz * cz) / length};
}

// The sum of the corner angles around each vertex without an atan2 per corner (which took a tenth of the
// construction): the corners of a vertex, as vectors (x, y) with y >= 0 (angles in [0, pi]), are multiplied
// as complex numbers, which adds their angles modulo 2 pi; one atan2 per vertex gives that remainder and the
// whole turns are counted on the way. With steps of at most pi, the argument of the product passes 2 pi
// exactly when it goes from the lower half-plane (im < 0) to the closed upper one, or, for a step of exactly
// pi, from the left of the upper half-plane to the right of it (no smaller step crosses the imaginary axis
// backwards). The same sign convention as the final atan2 (im >= 0 is the argument in [0, pi]) keeps the two
// consistent; rounding only moves the product by ulps. The result agrees with the sum of the atan2 to a few
// ulps per corner (measured: at most 3.6e-15 on CGAL's demo meshes and ../shared/data).
class Vertex_angle_accumulator
{
public:
  explicit Vertex_angle_accumulator(std::size_t n) : acc_(n, Product{1.0, 0.0, 0}) {}
  Vertex_angle_accumulator() = default;

  void add(std::size_t v, double x, double y)
  {
    if(x == 0 && y == 0)
      return; // a zero-length edge: no corner
    Product& p = acc_[v];
    const double r = p.re, i = p.im;
    double nr = r * x - i * y, ni = r * y + i * x;
    // The product is a direction: its length (the product of edge lengths) only needs to stay far from under-
    // and overflow. Rescaling by a power of two is exact and only needed now and then.
    const double m = (std::max)(std::abs(nr), std::abs(ni));
    if(!(m > 0x1p-400 && m < 0x1p400)) {
      if(!(m > 0) || !(m < std::numeric_limits<double>::infinity()))
        return; // coordinates near the limits of double: the corner is not counted
      int e;
      std::frexp(m, &e);
      nr = std::ldexp(nr, -e);
      ni = std::ldexp(ni, -e);
    }
    if(ni >= 0 && (i < 0 || (r < 0 && nr > 0)))
      ++p.turns;
    p.re = nr;
    p.im = ni;
  }

  double sum(std::size_t v) const
  {
    const double two_pi = 2 * 3.14159265358979323846;
    const Product& p = acc_[v];
    double a = std::atan2(p.im, p.re);
    if(a < 0)
      a += two_pi;
    return two_pi * p.turns + a;
  }

private:
  struct Product // the running product of a vertex's corner directions, and the whole turns so far
  {
    double re, im;
    int turns;
  };
  Large_vector<Product> acc_; // 4 KiB pages cost 4 microseconds each here: 14 MB (600k vertices) took 60 ms
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

// The builders (from a FaceGraph, from a triangle soup) need the declarations above.
#include <CGAL/Polyhedral_geodesics_3/internal/build_geodesic_mesh.h>

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_GEODESIC_MESH_H
