// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A compact, index-based copy of a triangle mesh for the geodesic algorithms: faces are numbered
// 0..F-1 by the mesh's face index map, the three corners of face f are the compact halfedges 3f, 3f+1,
// 3f+2 (halfedge(f), next, next(next)), every halfedge knows its twin (or -1 on the boundary) and, in
// its own planar frame, the position of the opposite corner. Building it once makes the propagation
// independent of the FaceGraph model (Surface_mesh, Polyhedron_3 with or without ids, OpenMesh) and
// keeps the per-window work on contiguous arrays.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_GEODESIC_MESH_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_GEODESIC_MESH_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Large_page_allocator.h>

#include <boost/multiprecision/number.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
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

template <class FT>
struct Geodesic_mesh
{
  typedef std::int32_t Index;

  std::size_t number_of_vertices = 0;
  std::size_t number_of_faces = 0;
  std::size_t number_of_edges = 0;

  Large_vector<std::array<FT, 3>> points;     // per vertex
  Large_vector<Index> he_source;              // per compact halfedge (3 per face): its source vertex
  Large_vector<Index> he_twin;                // twin halfedge or -1 on the boundary
  Large_vector<Index> he_edge;                // undirected edge id
  Large_vector<FT> he_length;                 // length of the edge
  Large_vector<Point_2_ft<FT>> he_opposite;   // opposite corner in the halfedge's frame: source at (0,0),
                                              // target at (length,0), the face on the side y >= 0
  Large_vector<Index> edge_halfedge;          // canonical halfedge of each edge (the one the edge frame uses)
  Large_vector<Index> vertex_halfedge;        // one compact halfedge whose source is the vertex, -1 if isolated
  Large_vector<char> vertex_on_boundary;
  Large_vector<FT> vertex_angle_sum;          // sum of the corner angles (as double-precision estimate in FT)

  static Index face_of(Index h) { return h / 3; }
  static Index next(Index h) { return h % 3 == 2 ? h - 2 : h + 1; }
  static Index prev(Index h) { return h % 3 == 0 ? h + 2 : h - 1; }
  Index source(Index h) const { return he_source[h]; }
  Index target(Index h) const { return he_source[next(h)]; }
  Index opposite_vertex(Index h) const { return he_source[prev(h)]; }
};

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
    ++star_begin[std::size_t(mesh.he_source[h]) + 1];
  for(std::size_t v = 0; v < nv; ++v)
    star_begin[v + 1] += star_begin[v];
  star.assign(nh, 0);
  std::vector<Index> fill(star_begin.begin(), star_begin.end() - 1);
  for(std::size_t h = 0; h < nh; ++h)
    star[std::size_t(fill[std::size_t(mesh.he_source[h])]++)] = Index(h);
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
template <class FT>
bool is_saddle_or_boundary_vertex(const Geodesic_mesh<FT>& mesh, std::size_t v)
{
  return mesh.vertex_on_boundary[v] || to_double_value(mesh.vertex_angle_sum[v]) > 2 * 3.14159265358979323846 - 1e-9;
}

template <class FT>
FT squared_distance_3(const std::array<FT, 3>& a, const std::array<FT, 3>& b)
{
  const FT dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
  return dx * dx + dy * dy + dz * dz;
}

// Fills mesh.he_opposite for halfedge h from the 3D points, robustly: the foot of the opposite corner is
// a projection (dot product) and its height the norm of a cross product, so needle and zero-area faces
// give a tiny non-negative height instead of the square root of a negative number.
template <class FT>
void compute_halfedge_frame(Geodesic_mesh<FT>& mesh, typename Geodesic_mesh<FT>::Index h)
{
  using std::sqrt;
  const auto& a = mesh.points[mesh.source(h)];
  const auto& b = mesh.points[mesh.target(h)];
  const auto& c = mesh.points[mesh.opposite_vertex(h)];
  const FT ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const FT vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const FT length = mesh.he_length[h];
  if(length == FT(0)) {
    // Zero-length edge: the face is a segment from a to c; put c on the y axis of a degenerate frame.
    mesh.he_opposite[h] = Point_2_ft<FT>{FT(0), sqrt(vx * vx + vy * vy + vz * vz)};
    return;
  }
  const FT dot = ux * vx + uy * vy + uz * vz;
  const FT cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
  mesh.he_opposite[h] = Point_2_ft<FT>{dot / length, sqrt(cx * cx + cy * cy + cz * cz) / length};
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
  explicit Vertex_angle_accumulator(std::size_t n) : re_(n, 1.0), im_(n, 0.0), turns_(n, 0) {}

  void add(std::size_t v, double x, double y)
  {
    if(x == 0 && y == 0)
      return; // a zero-length edge: no corner
    const double r = re_[v], i = im_[v];
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
      ++turns_[v];
    re_[v] = nr;
    im_[v] = ni;
  }

  double sum(std::size_t v) const
  {
    const double two_pi = 2 * 3.14159265358979323846;
    double a = std::atan2(im_[v], re_[v]);
    if(a < 0)
      a += two_pi;
    return two_pi * turns_[v] + a;
  }

private:
  std::vector<double> re_, im_;
  std::vector<int> turns_;
};

template <class FT, class TriangleMesh, class VertexPointMap, class VertexIndexMap, class FaceIndexMap>
void build_geodesic_mesh(const TriangleMesh& tm, VertexPointMap vpm, VertexIndexMap vim, FaceIndexMap fim,
                         Geodesic_mesh<FT>& mesh,
                         std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>& halfedge_of)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename Geodesic_mesh<FT>::Index Index;
  using std::sqrt;

  const std::size_t nv = num_vertices(tm), nf = num_faces(tm);
  if(nv > std::size_t(INT32_MAX / 2) || 3 * nf > std::size_t(INT32_MAX / 2))
    throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: mesh too large for 32-bit indices");
  mesh.number_of_vertices = nv;
  mesh.number_of_faces = nf;
  mesh.points.assign(nv, std::array<FT, 3>{FT(0), FT(0), FT(0)});
  for(auto v : vertices(tm)) {
    const std::size_t i = get(vim, v);
    if(i >= nv)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: the vertex index map is not in [0, num_vertices)");
    const auto& p = get(vpm, v);
    mesh.points[i] = {FT(CGAL::to_double(p.x())), FT(CGAL::to_double(p.y())), FT(CGAL::to_double(p.z()))};
  }

  mesh.he_source.assign(3 * nf, -1);
  mesh.he_twin.assign(3 * nf, -1);
  halfedge_of.assign(3 * nf, halfedge_descriptor());
  std::vector<char> face_seen(nf, 0);
  for(auto f : faces(tm)) {
    const std::size_t fi = get(fim, f);
    if(fi >= nf || face_seen[fi])
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: the face index map is not a bijection onto [0, num_faces)");
    face_seen[fi] = 1;
    halfedge_descriptor h = halfedge(f, tm);
    if(next(next(next(h, tm), tm), tm) != h)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: the mesh has a face that is not a triangle "
                                  "(triangulate it first, e.g. with CGAL::Polygon_mesh_processing::triangulate_faces)");
    for(int k = 0; k < 3; ++k, h = next(h, tm)) {
      halfedge_of[3 * fi + k] = h;
      mesh.he_source[3 * fi + k] = Index(get(vim, source(h, tm)));
    }
  }

  // Twins: match halfedge (a,b) with (b,a) through the mesh's own opposite() when both sides are faces.
  // Going through the original connectivity (not vertex pairs) keeps pinched vertices and duplicated
  // edges of non-manifold inputs apart.
  {
    // Map the original halfedge to its compact index through the face index + position in the face.
    for(std::size_t fi = 0; fi < nf; ++fi)
      for(int k = 0; k < 3; ++k) {
        const Index h = Index(3 * fi + k);
        const halfedge_descriptor oh = opposite(halfedge_of[h], tm);
        if(is_border(oh, tm))
          continue;
        const std::size_t ofi = get(fim, face(oh, tm));
        halfedge_descriptor g = halfedge(face(oh, tm), tm);
        int ok = 0;
        while(g != oh) { g = next(g, tm); ++ok; }
        mesh.he_twin[h] = Index(3 * ofi + ok);
      }
  }

  mesh.he_edge.assign(3 * nf, -1);
  mesh.edge_halfedge.clear();
  mesh.edge_halfedge.reserve(3 * nf / 2 + 1);
  for(Index h = 0; h < Index(3 * nf); ++h) {
    if(mesh.he_edge[h] >= 0)
      continue;
    const Index e = Index(mesh.edge_halfedge.size());
    mesh.edge_halfedge.push_back(h);
    mesh.he_edge[h] = e;
    if(mesh.he_twin[h] >= 0)
      mesh.he_edge[mesh.he_twin[h]] = e;
  }
  mesh.number_of_edges = mesh.edge_halfedge.size();

  mesh.he_length.resize(3 * nf);
  for(Index h = 0; h < Index(3 * nf); ++h)
    mesh.he_length[h] = sqrt(squared_distance_3(mesh.points[mesh.source(h)], mesh.points[mesh.target(h)]));
  // Twins must agree bit for bit on the length (the window frames of the two sides are mirror images).
  for(Index h = 0; h < Index(3 * nf); ++h)
    if(mesh.he_twin[h] >= 0 && mesh.he_twin[h] < h)
      mesh.he_length[h] = mesh.he_length[mesh.he_twin[h]];
  mesh.he_opposite.resize(3 * nf);
  for(Index h = 0; h < Index(3 * nf); ++h)
    compute_halfedge_frame(mesh, h);

  mesh.vertex_halfedge.assign(nv, -1);
  mesh.vertex_on_boundary.assign(nv, 0);
  Vertex_angle_accumulator angles(nv);
  for(Index h = 0; h < Index(3 * nf); ++h) {
    const Index v = mesh.source(h);
    if(mesh.vertex_halfedge[v] < 0)
      mesh.vertex_halfedge[v] = h;
    if(mesh.he_twin[h] < 0) {
      mesh.vertex_on_boundary[v] = 1;
      mesh.vertex_on_boundary[mesh.target(h)] = 1;
    }
    // the corner at the source of h, between h and prev(h) reversed: the opposite corner in h's frame
    angles.add(std::size_t(v), to_double_value(mesh.he_opposite[h].x), to_double_value(mesh.he_opposite[h].y));
  }
  mesh.vertex_angle_sum.resize(nv);
  for(std::size_t v = 0; v < nv; ++v)
    mesh.vertex_angle_sum[v] = FT(angles.sum(v));
}

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_GEODESIC_MESH_H
