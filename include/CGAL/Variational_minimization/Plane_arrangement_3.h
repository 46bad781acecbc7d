// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The exact arrangement of planes clipped to a box, held as a BSP cell tree: the spatial complex on which MDCS
// minimizes a surface functional (thesis ch. 2.7). Our own compact structure with exact integer predicates.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_PLANE_ARRANGEMENT_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_PLANE_ARRANGEMENT_3_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Variational_minimization/internal/Growable_array_3.h>
#include <CGAL/Variational_minimization/internal/plane_arrangement_predicates_3.h>
#include <CGAL/Variational_minimization/internal/pooled_index_lists_3.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <set>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/*!
  \defgroup PkgVariationalMinimizationSurfaces Bivariate problems (minimal surfaces)
  Globally minimal discrete surfaces: the plane arrangement (BSP complex), plane distributions, functionals, facet
  weights, the min-cut solve, relaxation and plane selection. Manual page: minimal_surfaces_3.md.
*/

namespace internal {
template <class Arrangement> class Plane_arrangement_builder_3;
}

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief The exact arrangement of planes inside the lattice box `[0, L]^3`, `L = lattice_size`, held as a BSP
  cell tree.

  The box is the root cell; planes are inserted one by one, and each splits exactly the cells whose interior it
  crosses (found by descending the tree, whose nodes keep a bounding box of their region). The leaves are the
  cells of the arrangement: convex polyhedra bounded by *facets*, convex polygons on one plane each, shared by
  the two cells on either side (one of them is `null_index` for a facet on the box boundary).

  **Exactness.** Planes have bounded integer coefficients (`Lattice_plane_3`), every vertex is the intersection
  of three of them, and the side of a vertex with respect to a plane is a determinant sign computed with a
  double filter and an exact 128-bit integer fallback. Every combinatorial decision is exact, whatever the
  degeneracy (many planes through one line or point, planes through box edges and corners, duplicate planes).
  Only `point()` is an approximation.

  **Storage.** A facet keeps its plane, its two cells and its polygon as a list of vertices (the plane of an edge,
  needed when a plane splits it, is recovered from the planes of its two vertices); a cell keeps its facet list; a vertex keeps its three planes and its approximate point. The
  polygons and the facet lists are pooled: during construction they live in large chunks with free lists (no
  allocation per list), afterwards they are packed in compressed-row form (one 32-bit offset per list into one
  array). The scratch data of the construction is released at its end (and rebuilt by a later `insert_plane()`).

  **Planes.** Planes 0-5 are the box walls `X = 0`, `X = L`, `Y = 0`, `Y = L`, `Z = 0`, `Z = L`; input plane
  `i` is plane `6 + i`. An input plane that duplicates an earlier plane or a wall, or misses the open box, is
  not used (`is_plane_used()`).
*/
class Plane_arrangement_3
{
public:
  typedef std::uint32_t Vertex_index;
  typedef std::uint32_t Facet_index;
  typedef std::uint32_t Cell_index;
  typedef std::uint32_t Plane_index;
  /// An invalid index; as a cell, the outside of the box.
  static constexpr std::uint32_t null_index = (std::numeric_limits<std::uint32_t>::max)();
  /// The side length `L` of the lattice box.
  static constexpr std::int64_t lattice_size = std::int64_t(1) << 16;
  /// The number of wall planes, which come first.
  static constexpr std::size_t number_of_walls = 6;

  /// A read-only range of indices (a cell's facets), valid until the arrangement changes.
  struct Index_range
  {
    const std::uint32_t* first;
    const std::uint32_t* last;
    const std::uint32_t* begin() const { return first; }
    const std::uint32_t* end() const { return last; }
    std::size_t size() const { return std::size_t(last - first); }
    bool empty() const { return first == last; }
    std::uint32_t operator[](std::size_t k) const { return first[k]; }
  };

  /// A facet: a convex polygon on `plane`; `negative_cell` lies where the plane's left-hand side is negative.
  struct Facet
  {
    Plane_index plane;
    Cell_index negative_cell, positive_cell;
  };

  /// An empty arrangement: the box alone (one cell, six facets, eight vertices).
  Plane_arrangement_3();

  /*!
    Builds the arrangement of `planes` in the box. `progress` is a callback `bool(const char* stage, double
    fraction)` called with stage `"arrangement"`; returning `false` throws `CGAL::MDCS::Operation_cancelled`.
    `threads` (0: all hardware threads; TBB needed) computes the bounding boxes of the cells each insertion creates
    in parallel, the part of an insertion that is independent (about a fifth of the instructions; the splits
    themselves share facets between neighbouring cells and stay sequential). The arrangement is the same for every
    thread count.
    \throws std::invalid_argument if a plane breaks the coefficient bounds of `Lattice_plane_3`, or if the
            arrangement would exceed 2^32 - 2 cells, facets or vertices.
  */
  template <class Progress = CGAL::MDCS::No_progress>
  explicit Plane_arrangement_3(const std::vector<Lattice_plane_3>& planes, Progress progress = Progress(),
                               std::size_t threads = 1);

  /// Inserts one more plane (incremental construction); returns whether it was used.
  bool insert_plane(const Lattice_plane_3& plane);

  std::size_t number_of_cells() const { return cell_facets_.size(); }
  std::size_t number_of_facets() const { return facets_.size(); }
  std::size_t number_of_vertices() const { return vertex_planes_.size(); }
  /// The number of planes, walls included.
  std::size_t number_of_planes() const { return planes_.size(); }

  const Lattice_plane_3& plane(Plane_index p) const { return planes_[p]; }
  bool is_wall(Plane_index p) const { return p < number_of_walls; }
  /// Whether plane `p` splits at least one cell (walls: always).
  bool is_plane_used(Plane_index p) const { return used_.at(p) != 0; }

  const Facet& facet(Facet_index f) const { return facets_[f]; }
  /// Whether the facet lies on the box boundary (on a wall; one of its cells is `null_index`).
  bool is_boundary_facet(Facet_index f) const { return facets_[f].plane < number_of_walls; }
  /// The polygon of facet `f`: its vertices in cyclic order.
  std::vector<Vertex_index> facet_vertices(Facet_index f) const
  {
    return std::vector<Vertex_index>(polygons_.begin(f), polygons_.end(f));
  }
  std::size_t facet_degree(Facet_index f) const { return polygons_.size(f); }
  Vertex_index facet_vertex(Facet_index f, std::size_t k) const { return polygons_.at(f, k); }
  /// A plane other than the facet's own that contains the edge from `facet_vertex(f, k)` to the next vertex
  /// (the polygons store no edge planes: it is found from the two vertices' planes, exactly).
  Plane_index facet_edge_plane(Facet_index f, std::size_t k) const
  {
    const std::size_t n = facet_degree(f);
    return common_plane(facet_vertex(f, k), facet_vertex(f, (k + 1) % n), facets_[f].plane);
  }

  /// The facets of cell `c`.
  Index_range cell_facets(Cell_index c) const { return Index_range{cell_facets_.begin(c), cell_facets_.end(c)}; }

  /// A double approximation of the vertex in lattice coordinates (relative error about 2^-52).
  const std::array<double, 3>& point(Vertex_index v) const { return points_[v]; }
  /// Three planes whose intersection is the vertex.
  const std::array<Plane_index, 3>& vertex_planes(Vertex_index v) const { return vertex_planes_[v]; }

  /// The exact side (-1, 0, 1) of vertex `v` with respect to plane `p` (sign of the plane's left-hand side).
  int side(Vertex_index v, Plane_index p) const { return side(v, planes_[p]); }
  int side(Vertex_index v, const Lattice_plane_3& p) const
  {
    bool sure = false;
    const int s = internal::filtered_side(points_[v], p, double(lattice_size), sure);
    if(sure) return s;
    const std::array<Plane_index, 3>& t = vertex_planes_[v];
    return internal::exact_side(internal::intersect_planes(planes_[t[0]], planes_[t[1]], planes_[t[2]]), p);
  }

  /// The number of nodes of the BSP tree (leaves are the cells). The constructor from a list of planes releases
  /// the tree at its end (0 nodes); `insert_plane()` then rebuilds one (a bounding-volume tree of the cells).
  std::size_t number_of_tree_nodes() const { return nodes_.size(); }

  /// An estimate of the memory held by the arrangement, in bytes (containers' capacities).
  std::size_t memory_bytes() const;

private:
  template <class Arrangement> friend class internal::Plane_arrangement_builder_3;

  // A plane other than `exclude` through the two distinct vertices u and v: usually one of the planes that
  // define both; otherwise (degenerate vertices on more than three planes) found by exact side tests.
  Plane_index common_plane(Vertex_index u, Vertex_index v, Plane_index exclude) const;

  // A node's box in whole lattice units, rounded outwards (20 bytes per node instead of 32 with floats); a
  // stored upper bound of 65535 stands for L = 65536.
  struct Tree_node
  {
    std::uint16_t lo[3], hi[3];
    std::uint32_t child[2];   // child[0] == null_index: a leaf, child[1] is its cell
  };

  std::vector<Lattice_plane_3> planes_;
  std::vector<unsigned char> used_;
  // The large arrays grow by realloc() (internal::Growable_array_3): no copy, hence no extra peak, when they grow.
  internal::Growable_array_3<Facet> facets_;
  internal::Pooled_index_lists_3 polygons_{1};    // per facet: its vertices in cyclic order
  internal::Pooled_index_lists_3 cell_facets_{4}; // per cell: its facets
  internal::Growable_array_3<std::array<Plane_index, 3>> vertex_planes_;
  internal::Growable_array_3<std::array<double, 3>> points_;
  internal::Growable_array_3<Tree_node> nodes_;
  internal::Growable_array_3<std::uint32_t> node_of_cell_;
  // Construction scratch: the side of each vertex with respect to the plane being inserted (valid when its
  // epoch is the current one); released after the construction, regrown by insert_plane().
  internal::Growable_array_3<std::uint32_t> side_epoch_;
  internal::Growable_array_3<signed char> side_cache_;
  std::uint32_t epoch_ = 0;
  std::set<std::array<std::int64_t, 4>> plane_keys_;
};

} // namespace Variational_minimization
} // namespace CGAL

#include <CGAL/Variational_minimization/internal/plane_arrangement_construction_3.h>

#endif // CGAL_VARIATIONAL_MINIMIZATION_PLANE_ARRANGEMENT_3_H
