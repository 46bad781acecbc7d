// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A tree over the edges of an indexed triangle mesh that skips, for a given view, whole groups of edges
// proved to hold no silhouette edge (the idea of Sander, Gu, Gortler, Hoppe and Snyder, "Silhouette
// clipping", SIGGRAPH 2000, with a simpler node test: a normal cone and a range of plane offsets).

#ifndef CGAL_SILHOUETTE_SIMPLIFICATION_3_INTERNAL_EDGE_CONE_HIERARCHY_H
#define CGAL_SILHOUETTE_SIMPLIFICATION_3_INTERNAL_EDGE_CONE_HIERARCHY_H

#include <CGAL/Silhouette_simplification_3/internal/Indexed_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Silhouette_simplification_3 {

/*!
  \ingroup PkgSilhouetteSimplification3Ref
  \brief How `Silhouette_edge_hierarchy_3` groups the edges.
*/
struct Silhouette_hierarchy_options
{
  /// Largest number of edges in a leaf (1 to 127).
  std::size_t leaf_edges = 16;
  /// Weight of the edge midpoints (divided by the bounding box diagonal) against the unit edge normals when
  /// a node is split along the widest of these six coordinates (non-negative, finite).
  double position_weight = 1.0;
};

/*!
  \ingroup PkgSilhouetteSimplification3Ref
  \brief What one hierarchical extraction did: the work that replaced the scan of every face.
*/
struct Silhouette_hierarchy_statistics
{
  std::size_t nodes_visited = 0; ///< nodes whose test was evaluated
  std::size_t edges_tested = 0;  ///< edges whose two faces were classified with the exact predicate
};

namespace internal {

// Nodes hold the faces next to their edges in a normal cone (unit axis, half-angle) and, for a centre c,
// the range of the offsets n_f . (p - c) over the vertices p of each face f with unit normal n_f. For an eye e,
// with w = e - c, every face has n_f . (e - p) = n_f . w - n_f . (p - c), and n_f . w lies between
// |w| cos(theta + alpha) and |w| cos(theta - alpha) (theta the angle between w and the axis). So when the
// first bound exceeds the largest offset every face is front-facing; when the second is below the smallest
// offset every face is back-facing: either way no edge of the node is a silhouette edge (border edges only in
// the second case). Orthographic views need only the cone. The leaves apply the exact predicate of the view,
// the one the scan applies, so the result is the scan's edge set.
//
// Floating point: the normals are computed in double. A face whose normal direction could be off by more than
// 1e-8 radians (slivers, zero-area faces, tiny faces far from the origin) is not put in the tree: its edges are
// tested at every query. For the others the cone is widened by 1e-7 radians and the offsets by 1e-7 times the
// node radius plus 1e-12 times the magnitudes involved, far more than the rounding errors of these few
// operations, so a node is only skipped when the exact predicate agrees on all its faces.
class Edge_cone_hierarchy
{
public:
  template <class Point_3>
  void build(const Indexed_mesh<Point_3>& im, const Silhouette_hierarchy_options& options = Silhouette_hierarchy_options())
  {
    if(options.leaf_edges == 0 || options.leaf_edges > 127)
      throw std::invalid_argument("MDCS: Silhouette_edge_hierarchy_3: leaf_edges must be in [1, 127]");
    if(!(options.position_weight >= 0 && std::isfinite(options.position_weight)))
      throw std::invalid_argument("MDCS: Silhouette_edge_hierarchy_3: position_weight must be finite and non-negative");
    nodes_.clear();
    edges_.clear();
    untreed_.clear();
    leaf_faces_.clear();
    local_faces_.clear();
    faces_ = im.faces.size();
    compute_face_data(im);
    const std::uint32_t nh = std::uint32_t(im.number_of_interior_halfedges());
    std::vector<std::array<float, 6>> key;
    for(std::uint32_t h = 0; h < nh; ++h) {
      const std::uint32_t o = im.opposite[h];
      if(o < nh && o < h) continue; // one halfedge per edge: the interior one of smaller index
      const std::uint32_t f = h / 3, g = o < nh ? o / 3 : NONE;
      if(!reliable_[f] || (g != NONE && !reliable_[g])) {
        untreed_.push_back(h);
        continue;
      }
      edges_.push_back(h);
      const double* a = &coords_[3 * im.source[h]];
      const double* b = &coords_[3 * im.source[o]];
      double n[3] = {normal_[3 * f], normal_[3 * f + 1], normal_[3 * f + 2]};
      if(g != NONE)
        for(int i = 0; i < 3; ++i) n[i] += normal_[3 * g + i];
      const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      std::array<float, 6> k;
      for(int i = 0; i < 3; ++i) {
        k[i] = float(options.position_weight * (a[i] + b[i]) / (2 * im.diagonal));
        k[3 + i] = float(len > 0 ? n[i] / len : 0);
      }
      key.push_back(k);
    }
    if(!edges_.empty()) {
      std::vector<std::uint32_t> order(edges_.size());
      for(std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
      nodes_.reserve(4 * edges_.size() / options.leaf_edges + 2);
      build_node(im, key, order, 0, std::uint32_t(order.size()), options.leaf_edges);
      std::vector<std::uint32_t> permuted(edges_.size());
      for(std::size_t i = 0; i < order.size(); ++i) permuted[i] = edges_[order[i]];
      edges_.swap(permuted);
      list_leaf_faces(im);
    }
    // The per-face data is only needed while building.
    std::vector<double>().swap(normal_);
    std::vector<double>().swap(coords_);
    std::vector<char>().swap(reliable_);
  }

  // The silhouette halfedges for `view` (front face on the left), in increasing index order: the same vector
  // as classify_faces() followed by silhouette_from_faces().
  template <class Point_3, class View>
  void query(const Indexed_mesh<Point_3>& im, const View& view, std::vector<std::uint32_t>& out,
             Silhouette_hierarchy_statistics* stats = nullptr) const
  {
    if(im.faces.size() != faces_)
      throw std::logic_error("MDCS: Silhouette_edge_hierarchy_3: the hierarchy was built for another mesh");
    out.clear();
    Silhouette_hierarchy_statistics s;
    double eye[3] = {0, 0, 0}, toward_viewer[3] = {0, 0, 0};
    const bool perspective = view.is_perspective();
    if(perspective) {
      eye[0] = CGAL::to_double(view.eye().x());
      eye[1] = CGAL::to_double(view.eye().y());
      eye[2] = CGAL::to_double(view.eye().z());
    } else {
      const double d[3] = {CGAL::to_double(view.direction().x()), CGAL::to_double(view.direction().y()),
                           CGAL::to_double(view.direction().z())};
      const double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      for(int i = 0; i < 3; ++i) toward_viewer[i] = -d[i] / l;
    }
    const double eye_norm = std::sqrt(eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]);
    const std::uint32_t n = std::uint32_t(nodes_.size());
    for(std::uint32_t i = 0; i < n;) {
      const Node& node = nodes_[i];
      ++s.nodes_visited;
      const Facing facing = perspective ? node_facing_eye(node, eye, eye_norm) : node_facing_direction(node, toward_viewer);
      if(facing == ALL_BACK || (facing == ALL_FRONT && !node.has_border)) {
        i = node.skip;
        continue;
      }
      if(node.skip == i + 1) { // a leaf: classify its faces once each, then compare across its edges
        bool front[2 * 127];
        for(std::uint32_t j = node.face_begin; j < node.face_end; ++j)
          front[j - node.face_begin] = is_front(im, view, leaf_faces_[j]);
        for(std::uint32_t k = node.begin; k < node.end; ++k) {
          const bool left = front[local_faces_[k][0]];
          if(local_faces_[k][1] == BORDER) {
            if(left) out.push_back(edges_[k]);
          } else if(left != front[local_faces_[k][1]]) {
            out.push_back(left ? edges_[k] : im.opposite[edges_[k]]);
          }
        }
        s.edges_tested += node.end - node.begin;
      }
      ++i;
    }
    for(std::uint32_t h : untreed_) test_edge(im, view, h, out);
    s.edges_tested += untreed_.size();
    std::sort(out.begin(), out.end());
    if(stats) *stats = s;
  }

  std::size_t number_of_nodes() const { return nodes_.size(); }
  std::size_t number_of_edges_outside_the_tree() const { return untreed_.size(); }
  std::size_t memory_bytes() const
  {
    return nodes_.capacity() * sizeof(Node) +
           (edges_.capacity() + untreed_.capacity() + leaf_faces_.capacity()) * sizeof(std::uint32_t) +
           local_faces_.capacity() * sizeof(local_faces_[0]);
  }

private:
  enum Facing { MIXED, ALL_FRONT, ALL_BACK };

  struct Node
  {
    double center[3], axis[3];
    double cos_angle, sin_angle;    // cone half-angle, widened
    double offset_min, offset_max;  // widened
    double center_norm;
    std::uint32_t begin, end;       // range of edges_
    std::uint32_t skip;             // the node after this subtree (i + 1 for a leaf)
    std::uint32_t face_begin, face_end; // a leaf's distinct faces in leaf_faces_
    bool has_border;
  };

  static constexpr std::uint8_t BORDER = 255;

  static constexpr double ANGLE_MARGIN = 1e-7;
  static constexpr double RELATIVE_ROUNDING_MARGIN = 1e-12;

  template <class Point_3, class View>
  static bool is_front(const Indexed_mesh<Point_3>& im, const View& view, std::uint32_t f)
  {
    const auto& t = im.faces[f];
    return view.is_front_facing(im.points[t[0]], im.points[t[1]], im.points[t[2]]);
  }

  template <class Point_3, class View>
  static void test_edge(const Indexed_mesh<Point_3>& im, const View& view, std::uint32_t h, std::vector<std::uint32_t>& out)
  {
    const std::uint32_t o = im.opposite[h];
    const bool front = is_front(im, view, h / 3);
    if(im.is_border(o)) {
      if(front) out.push_back(h);
      return;
    }
    if(front != is_front(im, view, o / 3)) out.push_back(front ? h : o);
  }

  // Bounds of n . w over the unit vectors n within the cone, from a . w and |a x w|.
  static void cone_range(const Node& node, const double w[3], double length, double& lo, double& hi)
  {
    const double* a = node.axis;
    const double aw = a[0] * w[0] + a[1] * w[1] + a[2] * w[2];
    const double c[3] = {a[1] * w[2] - a[2] * w[1], a[2] * w[0] - a[0] * w[2], a[0] * w[1] - a[1] * w[0]};
    const double cw = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    // theta + alpha < pi iff cos(theta) > -cos(alpha); theta - alpha > 0 iff cos(theta) < cos(alpha).
    lo = aw > -node.cos_angle * length ? node.cos_angle * aw - node.sin_angle * cw : -length;
    hi = aw < node.cos_angle * length ? node.cos_angle * aw + node.sin_angle * cw : length;
  }

  static Facing node_facing_eye(const Node& node, const double eye[3], double eye_norm)
  {
    const double w[3] = {eye[0] - node.center[0], eye[1] - node.center[1], eye[2] - node.center[2]};
    const double length = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    double lo, hi;
    cone_range(node, w, length, lo, hi);
    const double margin = RELATIVE_ROUNDING_MARGIN * (length + eye_norm + node.center_norm);
    if(lo - margin > node.offset_max) return ALL_FRONT;
    if(hi + margin < node.offset_min) return ALL_BACK;
    return MIXED;
  }

  static Facing node_facing_direction(const Node& node, const double toward_viewer[3])
  {
    double lo, hi;
    cone_range(node, toward_viewer, 1.0, lo, hi);
    if(lo > RELATIVE_ROUNDING_MARGIN) return ALL_FRONT;
    if(hi < -RELATIVE_ROUNDING_MARGIN) return ALL_BACK;
    return MIXED;
  }

  // Unit normals in double, and whether their direction is trustworthy to 1e-8 radians: the error of the
  // computed cross product is below about 6u |u||v| from the products and 4u |p| (|u| + |v|) from rounding the
  // coordinates to double (u = 2^-53), relative to its length.
  template <class Point_3>
  void compute_face_data(const Indexed_mesh<Point_3>& im)
  {
    coords_.resize(3 * im.points.size());
    for(std::size_t v = 0; v < im.points.size(); ++v) {
      coords_[3 * v] = CGAL::to_double(im.points[v].x());
      coords_[3 * v + 1] = CGAL::to_double(im.points[v].y());
      coords_[3 * v + 2] = CGAL::to_double(im.points[v].z());
    }
    normal_.assign(3 * im.faces.size(), 0);
    reliable_.assign(im.faces.size(), 0);
    const double unit_roundoff = 1.1102230246251565e-16;
    for(std::size_t f = 0; f < im.faces.size(); ++f) {
      const double* p = &coords_[3 * im.faces[f][0]];
      const double* q = &coords_[3 * im.faces[f][1]];
      const double* r = &coords_[3 * im.faces[f][2]];
      const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, v[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
      const double nn[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
      const double len = std::sqrt(nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2]);
      const double lu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]), lv = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      double big = 0;
      for(const double* x : {p, q, r}) big = std::max(big, std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]));
      const double error = unit_roundoff * (6 * lu * lv + 4 * big * (lu + lv));
      if(!(len > 0) || !(error <= 1e-8 * len)) continue;
      for(int i = 0; i < 3; ++i) normal_[3 * f + i] = nn[i] / len;
      reliable_[f] = 1;
    }
  }

  // Builds the subtree of the edges order[b, e) in depth-first order: the left child follows its parent, the
  // right child follows the left subtree. Splits at the median of the widest key coordinate.
  template <class Point_3>
  std::uint32_t build_node(const Indexed_mesh<Point_3>& im, const std::vector<std::array<float, 6>>& key,
                           std::vector<std::uint32_t>& order, std::uint32_t b, std::uint32_t e, std::size_t leaf_edges)
  {
    const std::uint32_t index = std::uint32_t(nodes_.size());
    nodes_.push_back(bound(im, order, b, e));
    if(e - b > leaf_edges) {
      float lo[6], hi[6];
      for(int k = 0; k < 6; ++k) { lo[k] = HUGE_VALF; hi[k] = -HUGE_VALF; }
      for(std::uint32_t i = b; i < e; ++i)
        for(int k = 0; k < 6; ++k) {
          lo[k] = std::min(lo[k], key[order[i]][k]);
          hi[k] = std::max(hi[k], key[order[i]][k]);
        }
      int axis = 0;
      for(int k = 1; k < 6; ++k)
        if(hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
      const std::uint32_t m = b + (e - b) / 2;
      std::nth_element(order.begin() + b, order.begin() + m, order.begin() + e,
                       [&](std::uint32_t x, std::uint32_t y) { return key[x][axis] < key[y][axis]; });
      build_node(im, key, order, b, m, leaf_edges);
      build_node(im, key, order, m, e, leaf_edges);
    }
    nodes_[index].skip = std::uint32_t(nodes_.size());
    return index;
  }

  // For each leaf, its distinct faces (leaf_faces_) and, per edge, the positions of its two faces among them
  // (local_faces_; BORDER for a missing face), so that a query classifies each face of a leaf once.
  template <class Point_3>
  void list_leaf_faces(const Indexed_mesh<Point_3>& im)
  {
    local_faces_.resize(edges_.size());
    for(Node& node : nodes_) {
      node.face_begin = node.face_end = std::uint32_t(leaf_faces_.size());
      if(node.skip != std::uint32_t(&node - nodes_.data()) + 1) continue;
      auto local = [&](std::uint32_t f) {
        for(std::uint32_t j = node.face_begin; j < leaf_faces_.size(); ++j)
          if(leaf_faces_[j] == f) return std::uint8_t(j - node.face_begin);
        leaf_faces_.push_back(f);
        return std::uint8_t(leaf_faces_.size() - 1 - node.face_begin);
      };
      for(std::uint32_t k = node.begin; k < node.end; ++k) {
        const std::uint32_t h = edges_[k], o = im.opposite[h];
        local_faces_[k][0] = local(h / 3);
        local_faces_[k][1] = im.is_border(o) ? BORDER : local(o / 3);
      }
      node.face_end = std::uint32_t(leaf_faces_.size());
    }
  }

  // The cone and offset range of the faces next to the edges order[b, e).
  template <class Point_3>
  Node bound(const Indexed_mesh<Point_3>& im, const std::vector<std::uint32_t>& order, std::uint32_t b, std::uint32_t e) const
  {
    Node node;
    node.begin = b;
    node.end = e;
    node.has_border = false;
    double sum[3] = {0, 0, 0}, lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    auto for_each_face = [&](auto&& f) {
      for(std::uint32_t i = b; i < e; ++i) {
        const std::uint32_t h = edges_[order[i]], o = im.opposite[h];
        f(h / 3);
        if(im.is_border(o)) node.has_border = true;
        else f(o / 3);
      }
    };
    for_each_face([&](std::uint32_t f) {
      for(int i = 0; i < 3; ++i) sum[i] += normal_[3 * f + i];
      for(std::uint32_t v : im.faces[f])
        for(int i = 0; i < 3; ++i) {
          lo[i] = std::min(lo[i], coords_[3 * v + i]);
          hi[i] = std::max(hi[i], coords_[3 * v + i]);
        }
    });
    double len = std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
    if(!(len > 1e-3)) { sum[0] = 0; sum[1] = 0; sum[2] = 1; len = 1; } // normals cancel: any axis (a wide cone)
    for(int i = 0; i < 3; ++i) {
      node.axis[i] = sum[i] / len;
      node.center[i] = (lo[i] + hi[i]) / 2;
    }
    double min_cos = 1, radius = 0, off_lo = HUGE_VAL, off_hi = -HUGE_VAL;
    for_each_face([&](std::uint32_t f) {
      const double* n = &normal_[3 * f];
      min_cos = std::min(min_cos, n[0] * node.axis[0] + n[1] * node.axis[1] + n[2] * node.axis[2]);
      for(std::uint32_t v : im.faces[f]) {
        const double d[3] = {coords_[3 * v] - node.center[0], coords_[3 * v + 1] - node.center[1],
                             coords_[3 * v + 2] - node.center[2]};
        const double off = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
        off_lo = std::min(off_lo, off);
        off_hi = std::max(off_hi, off);
        radius = std::max(radius, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
      }
    });
    // Lower the cosine a little before acos so that the angle is an upper bound despite rounding.
    const double angle = std::acos(std::max(-1.0, min_cos - 1e-15)) + ANGLE_MARGIN;
    const double pi = 3.14159265358979323846;
    node.cos_angle = angle >= pi ? -1.0 : std::cos(angle);
    node.sin_angle = angle >= pi ? 0.0 : std::sin(angle);
    node.center_norm = std::sqrt(node.center[0] * node.center[0] + node.center[1] * node.center[1] +
                                 node.center[2] * node.center[2]);
    const double widen = ANGLE_MARGIN * radius + RELATIVE_ROUNDING_MARGIN * (node.center_norm + radius);
    node.offset_min = off_lo - widen;
    node.offset_max = off_hi + widen;
    return node;
  }

  std::vector<Node> nodes_;
  std::vector<std::uint32_t> edges_;   // one interior halfedge per edge, in leaf order
  std::vector<std::uint32_t> untreed_; // edges next to a face without a trustworthy normal: always tested
  std::vector<std::uint32_t> leaf_faces_;
  std::vector<std::array<std::uint8_t, 2>> local_faces_; // per entry of edges_
  std::size_t faces_ = 0;
  // Build-time data.
  std::vector<double> coords_, normal_;
  std::vector<char> reliable_;
};

} // namespace internal
} // namespace Silhouette_simplification_3
} // namespace CGAL

#endif // CGAL_SILHOUETTE_SIMPLIFICATION_3_INTERNAL_EDGE_CONE_HIERARCHY_H
