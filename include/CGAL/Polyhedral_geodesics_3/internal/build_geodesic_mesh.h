// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The builders of the compact mesh (Geodesic_mesh.h): from a FaceGraph (the edges are the graph's own, through
// opposite()) and from a triangle soup (the edges come from the face indices: the halfedges that join the same two
// vertices form one edge, however many they are and whichever way they run). Both end in the same passes over
// arrays, so a soup and a FaceGraph with the same vertices and corners give the same compact mesh, bit for bit.
//
// Cost. Fresh memory is the largest cost here: on the project's virtual machines a new 2 MiB page costs about
// 1 ms to fault in and a 4 KiB page about 4 microseconds, so every temporary array is a Large_vector (huge pages)
// and the passes keep few of them. No pass allocates per element. The connectivity comes from a counting sort of
// the halfedges by their source vertex (the vertex stars, which the engines also use): the star of v holds every
// halfedge that leaves v and, as prev() of those, every halfedge that enters it, so the halfedges of each edge
// {v, x} with v < x, and the fans around v, are found in the star of v alone, with a scratch array indexed by
// vertex.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_BUILD_GEODESIC_MESH_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_BUILD_GEODESIC_MESH_H

#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/MDCS/internal/bounding_box.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

// The most faces an edge may have: the stored field of the window propagation tags each window with the position
// of its face among those of its edge in 5 bits (window_field.h).
constexpr std::size_t max_faces_per_edge = 31;

// ------------------------------------------------------------------------------------------------------------
// Connectivity

// The link of a compact halfedge h, as the passes below write it (one array instead of twin and radial):
// >= 0: its twin (an edge of an oriented manifold: the two halfedges run in opposite directions); -1: the only
// halfedge of a border edge; <= -2: a halfedge of a non-manifold or reversed edge, whose next halfedge around the
// edge is -2 - link.
inline std::int32_t radial_of_link(std::int32_t h, std::int32_t link)
{
  return link >= 0 ? link : (link == -1 ? h : -2 - link);
}

// The vertex stars as compressed rows, by a counting sort of the halfedges on their source vertex.
template <class FT>
void build_star_rows(const Large_vector<std::int32_t>& source_of, Geodesic_mesh<FT>& mesh)
{
  typedef std::int32_t Index;
  const std::size_t nv = mesh.number_of_vertices, nh = source_of.size();
  mesh.star_begin.assign(nv + 1, 0);
  for(std::size_t h = 0; h < nh; ++h)
    ++mesh.star_begin[std::size_t(source_of[h]) + 1];
  for(std::size_t v = 0; v < nv; ++v)
    mesh.star_begin[v + 1] += mesh.star_begin[v];
  mesh.star.resize(nh);
  // fill from the back, with star_begin[v + 1] as the cursor, so that no copy of the offsets is needed: the
  // halfedges of v come out in increasing order
  for(std::size_t h = nh; h-- > 0;)
    mesh.star[std::size_t(--mesh.star_begin[std::size_t(source_of[h]) + 1])] = Index(h);
  // the cursors now hold the row starts shifted by one vertex: star_begin[v + 1] == start of v
  for(std::size_t v = 0; v < nv; ++v)
    mesh.star_begin[v] = mesh.star_begin[v + 1];
  mesh.star_begin[nv] = Index(nh);
}

// The links of the halfedges of one edge (sorted by halfedge): see radial_of_link. Throws if there are too many.
template <class Member, class Mesh>
void link_edge_halfedges(const Member* members, std::size_t n, const Large_vector<std::int32_t>& source_of,
                         Large_vector<std::int32_t>& link)
{
  typedef std::int32_t Index;
  if(n == 1) {
    link[std::size_t(members[0].halfedge)] = -1;
  } else if(n == 2 && source_of[std::size_t(members[0].halfedge)] != source_of[std::size_t(members[1].halfedge)]) {
    link[std::size_t(members[0].halfedge)] = members[1].halfedge;
    link[std::size_t(members[1].halfedge)] = members[0].halfedge;
  } else {
    if(n > max_faces_per_edge) {
      const Index h = members[0].halfedge;
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: the edge between vertices " +
                                  std::to_string(source_of[std::size_t(h)]) + " and " +
                                  std::to_string(source_of[std::size_t(Mesh::next(h))]) + " is shared by " +
                                  std::to_string(n) + " triangles; at most " + std::to_string(max_faces_per_edge) +
                                  " are supported");
    }
    for(std::size_t m = 0; m < n; ++m)
      link[std::size_t(members[m].halfedge)] = -2 - members[m + 1 < n ? m + 1 : 0].halfedge;
  }
}

// One pass over the vertex stars: the fans of every vertex (pinched vertices, counted and marked in `pinched`),
// and, when `group_edges` (triangle soups), the edges: the halfedges joining v to a vertex x > v form the edge
// {v, x}; their links are written to `link` (see radial_of_link). Throws if an edge has too many faces.
//
// The corners of v whose faces share an edge at v (they have a neighbour x in common) belong to one fan. Stars of
// up to 16 corners (nearly all) are handled in local arrays by comparing every pair; larger ones with a scratch
// array indexed by the neighbour and a sort. This pass took a third of the construction's instructions with the
// scratch-array form for every star (270 per halfedge at 44k vertices).
template <class FT>
void scan_vertex_stars(const Large_vector<std::int32_t>& source_of, bool group_edges, Geodesic_mesh<FT>& mesh,
                       Large_vector<std::int32_t>& link, Large_vector<char>& pinched)
{
  typedef std::int32_t Index;
  typedef Geodesic_mesh<FT> Mesh;
  const std::size_t nv = mesh.number_of_vertices;
  struct Member
  {
    Index key;      // the neighbour x (one per edge {v, x})
    Index halfedge; // a halfedge of that edge
  };
  auto member_less = [](const Member& a, const Member& b) {
    return a.key < b.key || (a.key == b.key && a.halfedge < b.halfedge);
  };
  // links of the members, sorted, edge by edge
  auto link_members = [&](Member* m, std::size_t count) {
    for(std::size_t i = 0; i < count;) {
      std::size_t j = i + 1;
      while(j < count && m[j].key == m[i].key)
        ++j;
      link_edge_halfedges<Member, Mesh>(m + i, j - i, source_of, link);
      i = j;
    }
  };
  Large_vector<Index> slot; // large stars: per neighbour of the current vertex, the first corner that has it
  std::vector<Index> parent, touched;
  std::vector<Member> members;
  pinched.assign(nv, 0);
  mesh.number_of_pinched_vertices = 0;
  constexpr Index small = 16;
  for(std::size_t v = 0; v < nv; ++v) {
    const Index begin = mesh.star_begin[v], end = mesh.star_begin[v + 1];
    const Index k = end - begin;
    if(k == 0)
      continue; // an isolated vertex
    Index fans = 0;
    if(k <= small) {
      Index nb[small][2], root[small];
      Member local[2 * small];
      std::size_t count = 0;
      for(Index i = 0; i < k; ++i) {
        const Index g = mesh.star[std::size_t(begin + i)];
        // the corner of v in the face of g: its two neighbours along the face's edges
        nb[i][0] = source_of[std::size_t(Mesh::next(g))];
        nb[i][1] = source_of[std::size_t(Mesh::prev(g))];
        root[i] = i;
        if(group_edges) {
          if(std::size_t(nb[i][0]) > v)
            local[count++] = Member{nb[i][0], g};              // v -> x
          if(std::size_t(nb[i][1]) > v)
            local[count++] = Member{nb[i][1], Mesh::prev(g)};  // x -> v
        }
      }
      // The usual case, an oriented manifold vertex: around the fan, the corner after corner i is the one whose
      // incoming neighbour is the outgoing neighbour of i. Walk both ways from corner 0; if that reaches every
      // corner, there is one fan.
      std::uint32_t seen = 1;
      Index reached = 1;
      for(int way = 0; way < 2 && reached < k; ++way)
        for(Index cur = 0;;) {
          const Index x = nb[cur][way];
          Index next = -1;
          for(Index j = 0; j < k; ++j)
            if(nb[j][1 - way] == x) {
              next = j;
              break;
            }
          if(next < 0 || ((seen >> next) & 1u))
            break;
          seen |= 1u << next;
          ++reached;
          cur = next;
        }
      if(reached == k) {
        fans = 1;
      } else {
        // several fans, or an edge of the star with three or more faces or a reversed one: every pair of corners
        // that share a neighbour
        auto find = [&](Index i) {
          while(root[i] != i)
            i = root[i] = root[root[i]];
          return i;
        };
        for(Index i = 1; i < k; ++i)
          for(Index j = 0; j < i; ++j)
            if(nb[i][0] == nb[j][0] || nb[i][0] == nb[j][1] || nb[i][1] == nb[j][0] || nb[i][1] == nb[j][1]) {
              const Index a = find(i), b = find(j);
              if(a != b)
                root[a] = b;
            }
        for(Index i = 0; i < k; ++i)
          if(find(i) == i)
            ++fans;
      }
      if(group_edges) {
        for(std::size_t i = 1; i < count; ++i) // insertion sort: at most 32 members
          for(std::size_t j = i; j > 0 && member_less(local[j], local[j - 1]); --j)
            std::swap(local[j], local[j - 1]);
        link_members(local, count);
      }
    } else {
      if(slot.empty())
        slot.assign(nv, -1);
      parent.resize(std::size_t(k));
      for(Index i = 0; i < k; ++i)
        parent[std::size_t(i)] = i;
      auto find = [&](Index i) {
        while(parent[std::size_t(i)] != i) {
          parent[std::size_t(i)] = parent[std::size_t(parent[std::size_t(i)])];
          i = parent[std::size_t(i)];
        }
        return i;
      };
      members.clear();
      for(Index i = 0; i < k; ++i) {
        const Index g = mesh.star[std::size_t(begin + i)];
        const Index nb[2] = {source_of[std::size_t(Mesh::next(g))], source_of[std::size_t(Mesh::prev(g))]};
        for(int side = 0; side < 2; ++side) {
          const Index x = nb[side];
          Index& s = slot[std::size_t(x)];
          if(s < 0) {
            s = i;
            touched.push_back(x);
          } else {
            const Index a = find(i), b = find(s);
            if(a != b)
              parent[std::size_t(a)] = b;
          }
          if(group_edges && std::size_t(x) > v)
            members.push_back(Member{x, side == 0 ? g : Mesh::prev(g)}); // v -> x, or x -> v
        }
      }
      for(Index i = 0; i < k; ++i)
        if(find(i) == i)
          ++fans;
      for(Index x : touched)
        slot[std::size_t(x)] = -1;
      touched.clear();
      if(group_edges) {
        std::sort(members.begin(), members.end(), member_less);
        link_members(members.data(), members.size());
      }
    }
    if(fans > 1) {
      pinched[v] = 1;
      ++mesh.number_of_pinched_vertices;
    }
  }
}

// Everything after the points and the source of every compact halfedge: the edges (numbered in the order of
// their canonical halfedge, the first of the edge), the packed records, the vertex data. `link` holds the links
// (see radial_of_link) unless `group_edges`, in which case they come from the vertex pairs. Both temporary arrays
// are released. Returns the largest edge length (+infinity when a length overflows).
template <class FT>
double finish_geodesic_mesh(Large_vector<std::int32_t>& source_of, Large_vector<std::int32_t>& link,
                            bool group_edges, Geodesic_mesh<FT>& mesh)
{
  typedef Geodesic_mesh<FT> Mesh;
  typedef typename Mesh::Index Index;
  using std::sqrt;
  const std::size_t nv = mesh.number_of_vertices, nh = source_of.size();

  build_star_rows(source_of, mesh);
  if(group_edges)
    link.resize(nh);
  Large_vector<char> singular;
  scan_vertex_stars(source_of, group_edges, mesh, link, singular);

  // The edges, numbered in the order of their first halfedge (the canonical one); the others get its number when
  // it is numbered, along the cycle of the edge.
  Large_vector<Index> edge_of(nh, -1);
  mesh.edge_halfedge.clear();
  mesh.edge_halfedge.reserve(nh); // an upper bound (closed meshes use half); untouched pages cost nothing
  mesh.number_of_border_edges = mesh.number_of_nonmanifold_edges = mesh.number_of_reversed_edges = 0;
  for(std::size_t h = 0; h < nh; ++h) {
    if(edge_of[h] >= 0)
      continue;
    const Index e = Index(mesh.edge_halfedge.size());
    mesh.edge_halfedge.push_back(Index(h));
    const Index l = link[h];
    if(l >= 0) {
      edge_of[std::size_t(l)] = e;
    } else if(l == -1) {
      ++mesh.number_of_border_edges;
    } else {
      std::size_t n = 0;
      for(Index g = Index(h); n == 0 || g != Index(h); g = radial_of_link(g, link[std::size_t(g)]), ++n)
        edge_of[std::size_t(g)] = e;
      if(n >= 3) {
        ++mesh.number_of_nonmanifold_edges;
        singular[std::size_t(source_of[h])] = 1; // paths may go from any face of the edge into any other
        singular[std::size_t(source_of[std::size_t(Mesh::next(Index(h)))])] = 1;
      } else {
        ++mesh.number_of_reversed_edges;
      }
    }
    edge_of[h] = e;
  }
  mesh.number_of_edges = mesh.edge_halfedge.size();

  // The records, in order: the length of the edge, computed from the canonical halfedge's end points in that
  // order on every side, so that the halfedges agree bit for bit (the window frames of two sides are mirror
  // images), and the opposite corner in the halfedge's frame.
  mesh.he.clear();
  mesh.he.reserve(nh);
  double largest_length = 0;
  for(std::size_t h = 0; h < nh; ++h) {
    const Index l = link[h];
    const Index a = source_of[h], b = source_of[std::size_t(Mesh::next(Index(h)))];
    const Index c = source_of[std::size_t(Mesh::prev(Index(h)))];
    const Index twin = l >= 0 ? l : Index(-1);
    const bool like_canonical =
        l >= -1 ? (l < 0 || std::size_t(l) > h)
                : source_of[std::size_t(mesh.edge_halfedge[std::size_t(edge_of[h])])] == a;
    const FT length = sqrt(like_canonical ? squared_distance_3(mesh.points[std::size_t(a)], mesh.points[std::size_t(b)])
                                          : squared_distance_3(mesh.points[std::size_t(b)], mesh.points[std::size_t(a)]));
    const Point_2_ft<FT> opposite = halfedge_frame_opposite(mesh.points[std::size_t(a)], mesh.points[std::size_t(b)],
                                                            mesh.points[std::size_t(c)], length);
    const double length_double = to_double_value(length); // NaN when the squared length overflowed
    largest_length = std::isnan(length_double) ? std::numeric_limits<double>::infinity()
                                               : (std::max)(largest_length, length_double);
    mesh.he.push_back(Geodesic_halfedge<FT>{opposite, length, a, twin, edge_of[h], radial_of_link(Index(h), l)});
  }
  Large_vector<Index>().swap(edge_of);
  Large_vector<Index>().swap(link);
  Large_vector<Index>().swap(source_of);

  // Per vertex: one outgoing halfedge, the border flag, and the sum of the corner angles.
  mesh.vertex_halfedge.assign(nv, -1);
  mesh.vertex_on_boundary.assign(nv, 0);
  Vertex_angle_accumulator angles(nv);
  for(std::size_t h = 0; h < nh; ++h) {
    const Geodesic_halfedge<FT>& r = mesh.he[h];
    const Index a = r.source;
    if(r.radial == Index(h)) {
      mesh.vertex_on_boundary[std::size_t(a)] = 1;
      mesh.vertex_on_boundary[std::size_t(mesh.target(Index(h)))] = 1;
    }
    // the corner at the source of h, between h and prev(h) reversed: the opposite corner in h's frame
    angles.add(std::size_t(a), to_double_value(r.opposite.x), to_double_value(r.opposite.y));
  }
  mesh.number_of_isolated_vertices = 0;
  for(std::size_t v = 0; v < nv; ++v) {
    const Index b = mesh.star_begin[v];
    if(b < mesh.star_begin[v + 1])
      mesh.vertex_halfedge[v] = mesh.star[std::size_t(b)]; // the first outgoing halfedge, as before
    else
      ++mesh.number_of_isolated_vertices;
  }
  mesh.vertex_angle_sum.resize(nv);
  for(std::size_t v = 0; v < nv; ++v)
    mesh.vertex_angle_sum[v] = FT(angles.sum(v));
  singular.swap(mesh.vertex_is_singular);
  return largest_length;
}

// The scale precondition of the engines (see build_geodesic_mesh).
inline void check_geodesic_mesh_scale(std::size_t number_of_faces, double largest_length, const CGAL::Bbox_3& box)
{
  // The engines work in double with products of several lengths (squared distances of pseudo-sources, the
  // frames' cross products), so far from unit scale these under- or overflow. Exact (both schedules), merged,
  // flat-exact and fast marching give the same distances, bit for bit up to the scale, for CGAL's elephant
  // (diameter about 1, edges about 0.015) scaled by 2^-150 to 2^150; at 2^-170 and 2^190 the window engines are
  // off by 1e-6 to 5e-2, at 1e-90 the exact one did not end, and at 1e100 the frames overflow. Hence a
  // precondition with a margin: the largest edge at least 1e-40 and the bounding box's diagonal at most 1e40.
  const double diagonal = MDCS::internal::bbox_diagonal(box);
  if(number_of_faces > 0 && !(largest_length >= 1e-40 && diagonal <= 1e40)) {
    char text[96];
    std::snprintf(text, sizeof text, "largest edge length %g, bounding box diagonal %g", largest_length, diagonal);
    throw std::invalid_argument(std::string("CGAL::Polyhedral_geodesics_3: the mesh's scale is out of range (") +
                                text + "): the largest edge must be at least 1e-40 and the bounding box diagonal "
                                "at most 1e40 (scale the mesh, e.g. with CGAL::Polygon_mesh_processing::transform)");
  }
}

inline void check_geodesic_mesh_size(std::size_t nv, std::size_t nf)
{
  if(nv > std::size_t(INT32_MAX / 2) || nf > std::size_t(INT32_MAX / 2) / 3)
    throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: mesh too large for 32-bit indices");
}

// A point, checked: a NaN or infinite coordinate would leave its vertex unreachable by every engine, and the
// safety net of the window engines would expand its neighbours forever.
template <class FT>
void set_geodesic_mesh_point(Geodesic_mesh<FT>& mesh, std::size_t i, double x, double y, double z, CGAL::Bbox_3& box,
                             const char* what)
{
  if(!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z)))
    throw std::invalid_argument(std::string("CGAL::Polyhedral_geodesics_3: ") + what + " " + std::to_string(i) +
                                " has a coordinate that is not finite (NaN or infinity)");
  mesh.points[i] = {FT(x), FT(y), FT(z)};
  box += CGAL::Bbox_3(x, y, z, x, y, z);
}

// ------------------------------------------------------------------------------------------------------------
// From a FaceGraph

// The compact twin of every compact halfedge h (halfedge_of[h] the original one), -1 on the boundary, through the
// mesh's own opposite(). (The builder uses Compact_links below, which needs no halfedge_of; this form is kept for
// the tests, which compare its two variants.) Models without an internal halfedge index: from the opposite
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

// Models with an internal halfedge index: an array from that index to the compact halfedge.
template <class TriangleMesh, class FaceIndexMap, class IndexVector>
struct Compact_twins<TriangleMesh, FaceIndexMap, IndexVector, true>
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  static void compute(const TriangleMesh& tm, FaceIndexMap, const std::vector<halfedge_descriptor>& halfedge_of,
                      IndexVector& twin_of)
  {
    const auto him = CGAL::get_initialized_halfedge_index_map(tm);
    const std::size_t nhm = num_halfedges(tm);
    Large_vector<std::int32_t> compact_of(nhm, -1);
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

// The link (twin or -1) of every compact halfedge, face by face, as Compact_twins (going through the original
// connectivity, not vertex pairs, keeps duplicated edges apart).
template <class TriangleMesh, class FaceIndexMap,
          bool has_halfedge_index = CGAL::graph_has_property<TriangleMesh, boost::halfedge_index_t>::value>
struct Compact_links
{
  static void compute(const TriangleMesh& tm, FaceIndexMap fim, Large_vector<std::int32_t>& link)
  {
    typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
    for(auto f : faces(tm)) {
      const std::size_t fi = get(fim, f);
      halfedge_descriptor h = halfedge(f, tm);
      for(int k = 0; k < 3; ++k, h = next(h, tm)) {
        std::int32_t twin = -1;
        const halfedge_descriptor oh = opposite(h, tm);
        if(!is_border(oh, tm)) {
          const auto of = face(oh, tm);
          halfedge_descriptor g = halfedge(of, tm);
          int ok = 0;
          while(g != oh) { g = next(g, tm); ++ok; }
          twin = std::int32_t(3 * get(fim, of) + std::size_t(ok));
        }
        link[3 * fi + std::size_t(k)] = twin;
      }
    }
  }
};

// Models with an internal halfedge index (Surface_mesh, OpenMesh, Polyhedron_3 with ids): an array from that index
// to the compact halfedge, so the twin is two lookups. The walk above, three dependent random reads of the input
// mesh per halfedge, was 0.55 of 3.2 ms of the construction at 10k vertices (Surface_mesh, warm caches). A
// boundary halfedge is in no face, so its entry stays -1, which is the twin of its opposite.
template <class TriangleMesh, class FaceIndexMap>
struct Compact_links<TriangleMesh, FaceIndexMap, true>
{
  static void compute(const TriangleMesh& tm, FaceIndexMap fim, Large_vector<std::int32_t>& link)
  {
    typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
    const auto him = CGAL::get_initialized_halfedge_index_map(tm);
    const std::size_t nhm = num_halfedges(tm); // Surface_mesh: removed halfedges included, as in its indices
    Large_vector<std::int32_t> compact_of(nhm, -1);
    for(auto f : faces(tm)) {
      const std::size_t fi = get(fim, f);
      halfedge_descriptor h = halfedge(f, tm);
      for(int k = 0; k < 3; ++k, h = next(h, tm)) {
        const std::size_t i = std::size_t(get(him, h));
        if(i >= nhm)
          throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: the halfedge index map is not in [0, num_halfedges)");
        compact_of[i] = std::int32_t(3 * fi + std::size_t(k));
      }
    }
    for(auto f : faces(tm)) {
      const std::size_t fi = get(fim, f);
      halfedge_descriptor h = halfedge(f, tm);
      for(int k = 0; k < 3; ++k, h = next(h, tm)) {
        const std::size_t i = std::size_t(get(him, opposite(h, tm)));
        link[3 * fi + std::size_t(k)] = i < nhm ? compact_of[i] : std::int32_t(-1);
      }
    }
  }
};

// Builds the compact mesh of a FaceGraph. `record_face(fi, f)` is called for every face (fi its index).
template <class FT, class TriangleMesh, class VertexPointMap, class VertexIndexMap, class FaceIndexMap, class RecordFace>
void build_geodesic_mesh_from_face_graph(const TriangleMesh& tm, VertexPointMap vpm, VertexIndexMap vim,
                                         FaceIndexMap fim, Geodesic_mesh<FT>& mesh, RecordFace record_face)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename Geodesic_mesh<FT>::Index Index;

  const std::size_t nv = num_vertices(tm), nf = num_faces(tm), nh = 3 * nf;
  check_geodesic_mesh_size(nv, nf);
  mesh = Geodesic_mesh<FT>();
  mesh.number_of_vertices = nv;
  mesh.number_of_faces = nf;
  mesh.points.assign(nv, std::array<FT, 3>{FT(0), FT(0), FT(0)});
  CGAL::Bbox_3 box;
  for(auto v : vertices(tm)) {
    const std::size_t i = get(vim, v);
    if(i >= nv)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: the vertex index map is not in [0, num_vertices)");
    const auto& p = get(vpm, v);
    set_geodesic_mesh_point(mesh, i, CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()), box,
                            "vertex");
  }

  // Connectivity: the source of each compact halfedge.
  Large_vector<Index> source_of(nh);
  {
    Large_vector<char> face_seen(nf, 0);
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
      for(int k = 0; k < 3; ++k, h = next(h, tm))
        source_of[3 * fi + std::size_t(k)] = Index(get(vim, source(h, tm)));
      if(source_of[3 * fi] == source_of[3 * fi + 1] || source_of[3 * fi + 1] == source_of[3 * fi + 2] ||
         source_of[3 * fi + 2] == source_of[3 * fi])
        throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: face " + std::to_string(fi) +
                                    " has the same vertex at two corners");
      record_face(fi, f);
    }
    // Fewer faces than num_faces(): a Surface_mesh with removed faces counts them in num_faces() and its
    // indices, so the compact faces of those would be left without data.
    if(seen != nf)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: the face index map is not a bijection onto "
                                  "[0, num_faces) (a Surface_mesh with removed elements: call collect_garbage() first)");
  }

  // The twins: a pass of its own, whose accesses to the mesh are random; without other work in the loop the
  // processor overlaps many of them.
  Large_vector<Index> link(nh);
  Compact_links<TriangleMesh, FaceIndexMap>::compute(tm, fim, link);

  const double largest_length = finish_geodesic_mesh(source_of, link, false, mesh);
  check_geodesic_mesh_scale(nf, largest_length, box);
}

// The same, returning the original halfedge of every compact halfedge in `halfedge_of` (the interface the tests
// and benchmarks use).
template <class FT, class TriangleMesh, class VertexPointMap, class VertexIndexMap, class FaceIndexMap>
void build_geodesic_mesh(const TriangleMesh& tm, VertexPointMap vpm, VertexIndexMap vim, FaceIndexMap fim,
                         Geodesic_mesh<FT>& mesh,
                         std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>& halfedge_of)
{
  halfedge_of.resize(3 * num_faces(tm));
  build_geodesic_mesh_from_face_graph(tm, vpm, vim, fim, mesh, [&](std::size_t fi, typename boost::graph_traits<TriangleMesh>::face_descriptor f) {
    auto h = halfedge(f, tm);
    for(int k = 0; k < 3; ++k, h = next(h, tm))
      halfedge_of[3 * fi + std::size_t(k)] = h;
  });
}

// ------------------------------------------------------------------------------------------------------------
// From a triangle soup

// The coordinates of a point of a soup: p.x(), p.y(), p.z() (CGAL points) or p[0], p[1], p[2] (arrays).
template <class P, class = void>
struct Soup_point_coordinates
{
  static double get(const P& p, int i) { return CGAL::to_double(p[std::size_t(i)]); }
};

template <class P>
struct Soup_point_coordinates<P, decltype(void(std::declval<const P&>().x()))>
{
  static double get(const P& p, int i) { return CGAL::to_double(i == 0 ? p.x() : (i == 1 ? p.y() : p.z())); }
};

// The number of corners of a soup polygon, when its type can tell (3 for fixed-size arrays).
template <class T, class = void>
struct Soup_polygon_size
{
  static std::size_t get(const T&) { return 3; }
};

template <class T>
struct Soup_polygon_size<T, decltype(void(std::declval<const T&>().size()))>
{
  static std::size_t get(const T& t) { return std::size_t(t.size()); }
};

// A corner index of a soup triangle, checked: in [0, n).
template <class I>
std::size_t checked_soup_index(const I& value, std::size_t n, std::size_t triangle, int corner)
{
  static_assert(std::is_integral<I>::value, "triangle corners must be integer vertex indices");
  bool negative = false;
  if(std::is_signed<I>::value)
    negative = value < I(0);
  if(negative || static_cast<unsigned long long>(value) >= static_cast<unsigned long long>(n)) {
    const std::string text = std::is_signed<I>::value ? std::to_string(static_cast<long long>(value))
                                                      : std::to_string(static_cast<unsigned long long>(value));
    throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: triangle " + std::to_string(triangle) + " has corner " +
                                std::to_string(corner) + " = " + text + ", not a vertex index (the soup has " +
                                std::to_string(n) + " points)");
  }
  return std::size_t(value);
}

// Builds the compact mesh of a soup given as accessors: point(i, xyz) fills the coordinates of point i (of
// nv), corner(f, k) returns corner k of triangle f (of nf) as a checked index.
template <class FT, class PointAt, class CornerAt>
void build_geodesic_mesh_from_soup_access(std::size_t nv, std::size_t nf, PointAt point, CornerAt corner,
                                          Geodesic_mesh<FT>& mesh)
{
  typedef typename Geodesic_mesh<FT>::Index Index;
  const std::size_t nh = 3 * nf;
  check_geodesic_mesh_size(nv, nf);
  mesh = Geodesic_mesh<FT>();
  mesh.number_of_vertices = nv;
  mesh.number_of_faces = nf;
  mesh.points.resize(nv);
  CGAL::Bbox_3 box;
  for(std::size_t i = 0; i < nv; ++i) {
    double xyz[3];
    point(i, xyz);
    set_geodesic_mesh_point(mesh, i, xyz[0], xyz[1], xyz[2], box, "point");
  }
  Large_vector<Index> source_of(nh);
  for(std::size_t f = 0; f < nf; ++f) {
    for(int k = 0; k < 3; ++k)
      source_of[3 * f + std::size_t(k)] = Index(corner(f, k));
    for(int k = 0; k < 3; ++k)
      if(source_of[3 * f + std::size_t(k)] == source_of[3 * f + std::size_t((k + 1) % 3)])
        throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: triangle " + std::to_string(f) +
                                    " has a repeated corner (vertex " + std::to_string(source_of[3 * f + std::size_t(k)]) +
                                    " twice)");
  }
  Large_vector<Index> link;
  const double largest_length = finish_geodesic_mesh(source_of, link, true, mesh);
  check_geodesic_mesh_scale(nf, largest_length, box);
}

// From a range of points (CGAL points or arrays of three coordinates) and a range of triangles (arrays, vectors or
// other random-access containers of three integer vertex indices).
template <class FT, class PointRange, class TriangleRange>
void build_geodesic_mesh_from_soup(const PointRange& points, const TriangleRange& triangles, Geodesic_mesh<FT>& mesh)
{
  typedef typename std::iterator_traits<decltype(std::begin(points))>::value_type Point;
  typedef typename std::iterator_traits<decltype(std::begin(triangles))>::value_type Triangle;
  const std::size_t nv = std::size_t(std::distance(std::begin(points), std::end(points)));
  const std::size_t nf = std::size_t(std::distance(std::begin(triangles), std::end(triangles)));
  // ranges without random access are walked once, in order
  auto point_it = std::begin(points);
  std::size_t point_next = 0;
  auto triangle_it = std::begin(triangles);
  std::size_t triangle_next = 0;
  build_geodesic_mesh_from_soup_access<FT>(
      nv, nf,
      [&](std::size_t i, double* xyz) {
        for(; point_next < i; ++point_next) ++point_it;
        const Point& p = *point_it;
        for(int c = 0; c < 3; ++c)
          xyz[c] = Soup_point_coordinates<Point>::get(p, c);
      },
      [&](std::size_t f, int k) -> std::size_t {
        for(; triangle_next < f; ++triangle_next) ++triangle_it;
        const Triangle& t = *triangle_it;
        if(k == 0) {
          const std::size_t size = Soup_polygon_size<Triangle>::get(t);
          if(size != 3)
            throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: polygon " + std::to_string(f) + " has " +
                                        std::to_string(size) + " corners, not 3 (triangulate the soup first)");
        }
        return checked_soup_index(t[std::size_t(k)], nv, f, k);
      },
      mesh);
}

// From raw arrays (e.g. NumPy's): `coordinates` holds x, y, z of each of the `number_of_points` points, `corners`
// the three vertex indices of each of the `number_of_triangles` triangles.
template <class FT, class IndexType>
void build_geodesic_mesh_from_soup_arrays(const double* coordinates, std::size_t number_of_points,
                                          const IndexType* corners, std::size_t number_of_triangles,
                                          Geodesic_mesh<FT>& mesh)
{
  if((number_of_points > 0 && coordinates == nullptr) || (number_of_triangles > 0 && corners == nullptr))
    throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: null array of points or triangles");
  build_geodesic_mesh_from_soup_access<FT>(
      number_of_points, number_of_triangles,
      [&](std::size_t i, double* xyz) {
        for(int c = 0; c < 3; ++c)
          xyz[c] = coordinates[3 * i + std::size_t(c)];
      },
      [&](std::size_t f, int k) { return checked_soup_index(corners[3 * f + std::size_t(k)], number_of_points, f, k); },
      mesh);
}

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_BUILD_GEODESIC_MESH_H
