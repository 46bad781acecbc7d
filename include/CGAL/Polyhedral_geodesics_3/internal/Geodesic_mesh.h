// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A compact, index-based copy of a triangle mesh for the geodesic algorithms: faces are numbered
// 0..F-1 by the mesh's face index map, the three corners of face f are the compact halfedges 3f, 3f+1,
// 3f+2 (halfedge(f), next, next(next)), every halfedge knows its twin (or -1 on the boundary) and, in
// its own planar frame, the position of the opposite corner. Building it once makes the propagation
// independent of the FaceGraph model (Surface_mesh, Polyhedron_3 with or without ids, OpenMesh) and
// keeps the per-window work on contiguous arrays. The data of a halfedge is one packed record, which every
// engine reads in place; each record is written once, in order, after passes over small temporary arrays.

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
  FT length;               // of the edge (the same, bit for bit, on both halfedges)
  std::int32_t source;     // the source vertex
  std::int32_t twin;       // the twin halfedge, -1 on the boundary
  std::int32_t edge;       // the undirected edge
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
  Large_vector<char> vertex_on_boundary;
  Large_vector<FT> vertex_angle_sum;          // sum of the corner angles (as double-precision estimate in FT)

  static Index face_of(Index h) { return h / 3; }
  static Index next(Index h) { return h % 3 == 2 ? h - 2 : h + 1; }
  static Index prev(Index h) { return h % 3 == 0 ? h + 2 : h - 1; }
  Index source(Index h) const { return he[std::size_t(h)].source; }
  Index target(Index h) const { return he[std::size_t(next(h))].source; }
  Index opposite_vertex(Index h) const { return he[std::size_t(prev(h))].source; }
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
  std::vector<Product> acc_;
};

// The compact twin of every compact halfedge h (halfedge_of[h] the original one), -1 on the boundary, through the
// mesh's own opposite() (going through the original connectivity, not vertex pairs, keeps pinched vertices and
// duplicated edges of non-manifold inputs apart). Models without an internal halfedge index: from the opposite
// halfedge's face, halfedge(face) and then next() until the opposite halfedge itself.
template <class TriangleMesh, class FaceIndexMap, class IndexVector,
          bool has_halfedge_index = CGAL::graph_has_property<TriangleMesh, boost::halfedge_index_t>::value>
struct Compact_twins
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  static void compute(const TriangleMesh& tm, FaceIndexMap fim, const std::vector<halfedge_descriptor>& halfedge_of,
                      IndexVector& twin_of)
  {
    for(std::size_t h = 0; h < halfedge_of.size(); ++h) {
      std::int32_t twin = -1;
      const halfedge_descriptor oh = opposite(halfedge_of[h], tm);
      if(!is_border(oh, tm)) {
        const auto of = face(oh, tm);
        halfedge_descriptor g = halfedge(of, tm);
        int ok = 0;
        while(g != oh) { g = next(g, tm); ++ok; }
        twin = std::int32_t(3 * get(fim, of) + std::size_t(ok));
      }
      twin_of[h] = twin;
    }
  }
};

// Models with an internal halfedge index (Surface_mesh, OpenMesh, Polyhedron_3 with ids): an array from that index
// to the compact halfedge, so the twin is two lookups. The walk above, three dependent random reads of the input
// mesh per halfedge, was 0.55 of 3.2 ms of the construction at 10k vertices (Surface_mesh, warm caches). A
// boundary halfedge is in no face, so its entry stays -1, which is the twin of its opposite.
template <class TriangleMesh, class FaceIndexMap, class IndexVector>
struct Compact_twins<TriangleMesh, FaceIndexMap, IndexVector, true>
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  static void compute(const TriangleMesh& tm, FaceIndexMap, const std::vector<halfedge_descriptor>& halfedge_of,
                      IndexVector& twin_of)
  {
    const auto him = CGAL::get_initialized_halfedge_index_map(tm);
    const std::size_t nhm = num_halfedges(tm); // Surface_mesh: removed halfedges included, as in its indices
    std::vector<std::int32_t> compact_of(nhm, -1);
    for(std::size_t h = 0; h < halfedge_of.size(); ++h) {
      const std::size_t i = std::size_t(get(him, halfedge_of[h]));
      if(i >= nhm)
        throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: the halfedge index map is not in [0, num_halfedges)");
      compact_of[i] = std::int32_t(h);
    }
    for(std::size_t h = 0; h < halfedge_of.size(); ++h) {
      const std::size_t i = std::size_t(get(him, opposite(halfedge_of[h], tm)));
      twin_of[h] = i < nhm ? compact_of[i] : std::int32_t(-1);
    }
  }
};

// The halfedge records of the compact mesh (and halfedge_of), from the mesh's connectivity and mesh.points.
// Returns the largest edge length (+infinity when a length overflows).
template <class FT, class TriangleMesh, class VertexIndexMap, class FaceIndexMap>
double build_halfedge_records(const TriangleMesh& tm, VertexIndexMap vim, FaceIndexMap fim, Geodesic_mesh<FT>& mesh,
                            std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>& halfedge_of)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef Geodesic_mesh<FT> Mesh;
  typedef typename Mesh::Index Index;
  using std::sqrt;

  // The records are written once, in order, by the last pass below; the passes before it fill small arrays.
  // At 150k vertices the 36 MB of records no longer fit the processor's cache, while arrays of 4 bytes per
  // halfedge do: filling the records field by field, or reading a twin's record, cost 1.3 times the time.
  const std::size_t nf = mesh.number_of_faces, nh = 3 * nf;
  halfedge_of.resize(nh);
  Large_vector<Index> source_of(nh), twin_of(nh), edge_of(nh);

  // Connectivity: the source of each compact halfedge, and the original halfedge it stands for.
  {
    std::vector<char> face_seen(nf, 0);
    std::size_t seen = 0;
    for(auto f : faces(tm)) {
      const std::size_t fi = get(fim, f);
      if(fi >= nf || face_seen[fi])
        throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: the face index map is not a bijection onto [0, num_faces)");
      face_seen[fi] = 1;
      ++seen;
      halfedge_descriptor h = halfedge(f, tm);
      if(next(next(next(h, tm), tm), tm) != h)
        throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: the mesh has a face that is not a triangle "
                                    "(triangulate it first, e.g. with CGAL::Polygon_mesh_processing::triangulate_faces)");
      for(int k = 0; k < 3; ++k, h = next(h, tm)) {
        halfedge_of[3 * fi + k] = h;
        source_of[3 * fi + k] = Index(get(vim, source(h, tm)));
      }
    }
    // Fewer faces than num_faces(): a Surface_mesh with removed faces counts them in num_faces() and its
    // indices, so the compact faces of those would be left without data.
    if(seen != nf)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: the face index map is not a bijection onto "
                                  "[0, num_faces) (a Surface_mesh with removed elements: call collect_garbage() first)");
  }

  // The twins: a pass of its own, whose accesses to the mesh are random; without other work in the loop the
  // processor overlaps many of them.
  Compact_twins<TriangleMesh, FaceIndexMap, Large_vector<Index>>::compute(tm, fim, halfedge_of, twin_of);

  // The edges, numbered in the order of their first halfedge (the canonical one); the second gets the number
  // ahead, when the first is numbered.
  mesh.edge_halfedge.clear();
  mesh.edge_halfedge.reserve(nh); // an upper bound (closed meshes use half): no reallocation
  for(std::size_t h = 0; h < nh; ++h) {
    const Index twin = twin_of[h];
    if(twin < 0 || std::size_t(twin) > h) {
      edge_of[h] = Index(mesh.edge_halfedge.size());
      if(twin >= 0)
        edge_of[std::size_t(twin)] = edge_of[h];
      mesh.edge_halfedge.push_back(Index(h));
    }
  }

  // The records, in order: the length of the edge, computed from the canonical halfedge's end points in that
  // order on both sides, so that the two halfedges agree bit for bit (the window frames of the two sides are
  // mirror images), and the opposite corner in the halfedge's frame.
  mesh.he.clear();
  mesh.he.reserve(nh);
  double largest_length = 0;
  for(std::size_t h = 0; h < nh; ++h) {
    const Index twin = twin_of[h];
    const Index a = source_of[h], b = source_of[std::size_t(Mesh::next(Index(h)))];
    const Index c = source_of[std::size_t(Mesh::prev(Index(h)))];
    const bool canonical = twin < 0 || std::size_t(twin) > h;
    const FT length = sqrt(canonical ? squared_distance_3(mesh.points[std::size_t(a)], mesh.points[std::size_t(b)])
                                     : squared_distance_3(mesh.points[std::size_t(b)], mesh.points[std::size_t(a)]));
    const Point_2_ft<FT> opposite = halfedge_frame_opposite(mesh.points[std::size_t(a)], mesh.points[std::size_t(b)],
                                                            mesh.points[std::size_t(c)], length);
    const double length_double = to_double_value(length); // NaN when the squared length overflowed
    largest_length = std::isnan(length_double) ? std::numeric_limits<double>::infinity()
                                               : (std::max)(largest_length, length_double);
    mesh.he.push_back(Geodesic_halfedge<FT>{opposite, length, a, twin, edge_of[h]});
  }
  mesh.number_of_edges = mesh.edge_halfedge.size();
  return largest_length;
}

template <class FT, class TriangleMesh, class VertexPointMap, class VertexIndexMap, class FaceIndexMap>
void build_geodesic_mesh(const TriangleMesh& tm, VertexPointMap vpm, VertexIndexMap vim, FaceIndexMap fim,
                         Geodesic_mesh<FT>& mesh,
                         std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>& halfedge_of)
{
  typedef typename Geodesic_mesh<FT>::Index Index;

  const std::size_t nv = num_vertices(tm), nf = num_faces(tm);
  if(nv > std::size_t(INT32_MAX / 2) || 3 * nf > std::size_t(INT32_MAX / 2))
    throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: mesh too large for 32-bit indices");
  mesh.number_of_vertices = nv;
  mesh.number_of_faces = nf;
  mesh.points.assign(nv, std::array<FT, 3>{FT(0), FT(0), FT(0)});
  CGAL::Bbox_3 box;
  for(auto v : vertices(tm)) {
    const std::size_t i = get(vim, v);
    if(i >= nv)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: the vertex index map is not in [0, num_vertices)");
    const auto& p = get(vpm, v);
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
    // A NaN or infinite coordinate would leave its vertex unreachable by every engine, and the safety net of
    // the window engines would expand its neighbours forever.
    if(!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z)))
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: vertex " + std::to_string(i) +
                                  " has a coordinate that is not finite (NaN or infinity)");
    mesh.points[i] = {FT(x), FT(y), FT(z)};
    box += CGAL::Bbox_3(x, y, z, x, y, z);
  }

  // The halfedge records; their temporary arrays are released before the vertex pass.
  const double largest_length = build_halfedge_records(tm, vim, fim, mesh, halfedge_of);

  // The engines work in double with products of several lengths (squared distances of pseudo-sources, the
  // frames' cross products), so far from unit scale these under- or overflow. Exact (both schedules), merged,
  // flat-exact and fast marching give the same distances, bit for bit up to the scale, for CGAL's elephant
  // (diameter about 1, edges about 0.015) scaled by 2^-150 to 2^150; at 2^-170 and 2^190 the window engines are
  // off by 1e-6 to 5e-2, at 1e-90 the exact one did not end, and at 1e100 the frames overflow. Hence a
  // precondition with a margin: the largest edge at least 1e-40 and the bounding box's diagonal at most 1e40.
  const double diagonal = MDCS::internal::bbox_diagonal(box);
  if(nf > 0 && !(largest_length >= 1e-40 && diagonal <= 1e40)) {
    char text[96];
    std::snprintf(text, sizeof text, "largest edge length %g, bounding box diagonal %g", largest_length, diagonal);
    throw std::invalid_argument(std::string("CGAL::Polyhedral_geodesics_3: the mesh's scale is out of range (") +
                                text + "): the largest edge must be at least 1e-40 and the bounding box diagonal "
                                "at most 1e40 (scale the mesh, e.g. with CGAL::Polygon_mesh_processing::transform)");
  }

  // Per vertex (a pass of its own, for the same reason as the twins): one outgoing halfedge, the boundary flag,
  // and the sum of the corner angles.
  const std::size_t nh = 3 * nf;
  mesh.vertex_halfedge.assign(nv, -1);
  mesh.vertex_on_boundary.assign(nv, 0);
  Vertex_angle_accumulator angles(nv);
  for(std::size_t h = 0; h < nh; ++h) {
    const Geodesic_halfedge<FT>& r = mesh.he[h];
    const Index a = r.source;
    if(mesh.vertex_halfedge[std::size_t(a)] < 0)
      mesh.vertex_halfedge[std::size_t(a)] = Index(h);
    if(r.twin < 0) {
      mesh.vertex_on_boundary[std::size_t(a)] = 1;
      mesh.vertex_on_boundary[std::size_t(mesh.target(Index(h)))] = 1;
    }
    // the corner at the source of h, between h and prev(h) reversed: the opposite corner in h's frame
    angles.add(std::size_t(a), to_double_value(r.opposite.x), to_double_value(r.opposite.y));
  }
  mesh.vertex_angle_sum.resize(nv);
  for(std::size_t v = 0; v < nv; ++v)
    mesh.vertex_angle_sum[v] = FT(angles.sum(v));
}

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_GEODESIC_MESH_H
