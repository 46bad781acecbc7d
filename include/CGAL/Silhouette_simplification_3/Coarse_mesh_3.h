// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Preprocessing of silhouette simplification: the coarse mesh (half-edge collapses that keep an
// endpoint, then smoothing) and the fine-to-coarse face map. This is the only header of the package
// that includes CGAL's Surface_mesh_simplification (slow to compile): include it only where the
// coarse mesh is built.

#ifndef CGAL_SILHOUETTE_SIMPLIFICATION_3_COARSE_MESH_3_H
#define CGAL_SILHOUETTE_SIMPLIFICATION_3_COARSE_MESH_3_H

#include <CGAL/Silhouette_simplification_3/internal/Indexed_mesh.h>
#include <CGAL/MDCS/progress.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/Surface_mesh_simplification/Edge_collapse_visitor_base.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_cost.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Kernel_traits.h>

#include <boost/optional.hpp>

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Silhouette_simplification_3 {

/// \ingroup PkgSilhouetteSimplification3Ref
/// Options of `build_coarse_mesh()`.
struct Coarse_mesh_options
{
  /// The number of faces to simplify to (the result may have a few more when no edge can be collapsed).
  std::size_t target_faces = 1000;
  /// Iterations of Taubin smoothing (lambda = 0.5, mu = -0.53, uniform weights, border vertices fixed).
  unsigned smoothing_iterations = 3;
};

/*!
  \ingroup PkgSilhouetteSimplification3Ref
  \brief The coarse mesh of silhouette simplification and the map from fine faces to coarse faces.

  `coarse_face_of_fine_face[i]` is the index (in `faces(mesh)` order) of the coarse face that the
  `i`-th face of the fine mesh (in `faces(fine)` order) belongs to. Every fine face has one.
*/
template <class Point_3>
struct Coarse_mesh_3
{
  CGAL::Surface_mesh<Point_3> mesh;
  std::vector<std::uint32_t> coarse_face_of_fine_face;
  std::size_t number_of_collapses = 0;
};

namespace internal {

// The collapse record shared by all copies of the visitor (edge_collapse copies its visitor).
struct Collapse_record
{
  std::vector<std::uint32_t> parent; // per working face: the face it was merged into, NONE if alive
  std::size_t collapses = 0;
  std::size_t expected = 1;
};

template <class SM, class Progress>
struct Face_map_visitor : CGAL::Surface_mesh_simplification::Edge_collapse_visitor_base<SM>
{
  typedef typename boost::graph_traits<SM>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<SM>::face_descriptor face_descriptor;

  Face_map_visitor(std::shared_ptr<Collapse_record> r, const SM* m, Progress* p) : record(r), sm(m), progress(p) {}

  // The triangle on the left of h disappears; its two other edges merge into one, so the faces across
  // them become neighbours. The removed face is merged into the face across next(h) (or prev(h)).
  void merge_left(halfedge_descriptor h) const
  {
    if(is_border(h, *sm)) return;
    const face_descriptor f = face(h, *sm);
    halfedge_descriptor a = opposite(next(h, *sm), *sm);
    if(is_border(a, *sm)) a = opposite(prev(h, *sm), *sm);
    if(is_border(a, *sm)) return;
    record->parent[std::size_t(f)] = std::uint32_t(std::size_t(face(a, *sm)));
  }

  template <class Profile, class Placement>
  void OnCollapsing(const Profile& profile, const Placement&)
  {
    merge_left(profile.v0_v1());
    merge_left(profile.v1_v0());
  }

  template <class Profile, class V>
  void OnCollapsed(const Profile&, const V&)
  {
    ++record->collapses;
    if(record->collapses % 256 == 0 && !(*progress)("simplification", std::min(1.0, double(record->collapses) / double(record->expected))))
      throw CGAL::MDCS::Operation_cancelled("simplification");
  }

  std::shared_ptr<Collapse_record> record;
  const SM* sm;
  Progress* progress;
};

// Placement that keeps one endpoint of the collapsed edge (a half-edge collapse): the one of lower
// Lindstrom-Turk cost. Coarse vertices are thus fine vertices until smoothing.
template <class SM>
struct Endpoint_placement
{
  template <class Profile>
  boost::optional<typename Profile::Point> operator()(const Profile& profile) const
  {
    typedef boost::optional<typename Profile::Point> Opt;
    const CGAL::Surface_mesh_simplification::LindstromTurk_cost<SM> cost;
    const Opt p0(profile.p0()), p1(profile.p1());
    const auto c0 = cost(profile, p0), c1 = cost(profile, p1);
    if(!c0 && !c1) return Opt();
    if(!c1) return p0;
    if(!c0) return p1;
    return *c0 <= *c1 ? p0 : p1;
  }
};

} // namespace internal

/*!
  \ingroup PkgSilhouetteSimplification3Ref
  \brief Builds the coarse mesh of `fine` by half-edge collapses and smoothing, and the fine-to-coarse face map.

  The fine mesh is copied into a `Surface_mesh` and simplified with CGAL's `edge_collapse()` (cost:
  Lindstrom-Turk evaluated at the kept endpoint; placement: the endpoint of lower cost, so every
  collapse is a half-edge collapse) until about `options.target_faces` faces remain. A visitor records,
  for each of the two faces that a collapse removes, the face it merges into (the face across one of
  its remaining edges, which becomes adjacent to the surviving neighbour); the face map is resolved once
  at the end by following these records. The coarse mesh is then smoothed.

  \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
  \throws std::invalid_argument when a face is not a triangle, the mesh is empty or `target_faces < 4`
  \throws CGAL::MDCS::Operation_cancelled when `progress` (stage `"simplification"`) returns false
*/
template <class TriangleMesh, class VertexPointMap, class Progress = CGAL::MDCS::No_progress>
Coarse_mesh_3<typename boost::property_traits<VertexPointMap>::value_type>
build_coarse_mesh(const TriangleMesh& fine, VertexPointMap vpm, const Coarse_mesh_options& options = Coarse_mesh_options(),
                  Progress progress = Progress())
{
  typedef typename boost::property_traits<VertexPointMap>::value_type Point_3;
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel K;
  typedef CGAL::Surface_mesh<Point_3> SM;
  typedef typename boost::graph_traits<TriangleMesh> GT;
  typedef typename boost::graph_traits<SM>::face_descriptor sm_face;
  typedef typename boost::graph_traits<SM>::vertex_descriptor sm_vertex;
  namespace SMS = CGAL::Surface_mesh_simplification;
  using internal::NONE;

  if(options.target_faces < 4)
    throw std::invalid_argument("MDCS: build_coarse_mesh: target_faces must be at least 4");

  // Working copy whose face i is the i-th fine face.
  internal::Indexed_mesh<Point_3> im;
  std::vector<typename GT::halfedge_descriptor> hd;
  std::vector<typename GT::face_descriptor> fd;
  std::vector<typename GT::vertex_descriptor> vd;
  internal::build_indexed_mesh(fine, vpm, im, hd, fd, vd, "build_coarse_mesh");
  SM sm;
  for(const Point_3& p : im.points) sm.add_vertex(p);
  for(std::size_t f = 0; f < im.faces.size(); ++f) {
    const auto& t = im.faces[f];
    const sm_face nf = sm.add_face(sm_vertex(t[0]), sm_vertex(t[1]), sm_vertex(t[2]));
    if(nf == SM::null_face() || std::size_t(nf) != f)
      throw std::invalid_argument("MDCS: build_coarse_mesh: face " + std::to_string(f) +
                                  " cannot be added to a manifold copy of the mesh (non-manifold configuration)");
  }

  auto record = std::make_shared<internal::Collapse_record>();
  record->parent.assign(im.faces.size(), NONE);
  record->expected = im.faces.size() > options.target_faces ? (im.faces.size() - options.target_faces) / 2 : 1;
  Coarse_mesh_3<Point_3> result;
  if(im.faces.size() > options.target_faces) {
    internal::Face_map_visitor<SM, Progress> visitor(record, &sm, &progress);
    SMS::Count_stop_predicate<SM> stop((3 * options.target_faces + 1) / 2);
    SMS::edge_collapse(sm, stop,
                       CGAL::parameters::get_cost(SMS::LindstromTurk_cost<SM>())
                         .get_placement(internal::Endpoint_placement<SM>())
                         .visitor(visitor));
  }
  progress("simplification", 1.0);
  result.number_of_collapses = record->collapses;

  // Clean copy of the surviving faces.
  std::vector<std::pair<sm_face, sm_face>> f2f;
  CGAL::copy_face_graph(sm, result.mesh, CGAL::parameters::face_to_face_output_iterator(std::back_inserter(f2f)));
  std::vector<std::uint32_t> coarse_of_work(im.faces.size(), NONE);
  for(const auto& p : f2f) coarse_of_work[std::size_t(p.first)] = std::uint32_t(std::size_t(p.second));

  // Resolve the merge records once (with path compression).
  std::vector<std::uint32_t>& parent = record->parent;
  std::vector<std::uint32_t>& map = result.coarse_face_of_fine_face;
  map.assign(im.faces.size(), NONE);
  std::vector<std::uint32_t> chain;
  for(std::uint32_t f = 0; f < im.faces.size(); ++f) {
    std::uint32_t g = f;
    chain.clear();
    while(map[g] == NONE && parent[g] != NONE && coarse_of_work[g] == NONE) {
      chain.push_back(g);
      g = parent[g];
      if(chain.size() > im.faces.size()) throw std::logic_error("MDCS: build_coarse_mesh: cyclic merge record");
    }
    const std::uint32_t c = map[g] != NONE ? map[g] : coarse_of_work[g];
    map[g] = c;
    for(std::uint32_t x : chain) map[x] = c;
  }
  // Faces whose record ends nowhere (removed without a surviving neighbour): take a neighbour's face.
  for(bool changed = true; changed;) {
    changed = false;
    for(std::uint32_t f = 0; f < im.faces.size(); ++f) {
      if(map[f] != NONE) continue;
      for(std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t g = im.face(im.opposite[3 * f + k]);
        if(g != NONE && map[g] != NONE) { map[f] = map[g]; changed = true; break; }
      }
    }
  }
  for(std::uint32_t& c : map)
    if(c == NONE) c = 0; // a component that vanished entirely: any face (documented)

  // Taubin smoothing, border vertices fixed.
  SM& cm = result.mesh;
  std::vector<typename K::Vector_3> delta(num_vertices(cm));
  for(unsigned it = 0; it < 2 * options.smoothing_iterations; ++it) {
    const double factor = it % 2 == 0 ? 0.5 : -0.53;
    for(sm_vertex v : vertices(cm)) {
      delta[std::size_t(v)] = CGAL::NULL_VECTOR;
      if(CGAL::is_border(v, cm) || halfedge(v, cm) == boost::graph_traits<SM>::null_halfedge()) continue;
      typename K::Vector_3 sum = CGAL::NULL_VECTOR;
      int n = 0;
      for(sm_vertex w : CGAL::vertices_around_target(halfedge(v, cm), cm)) { sum = sum + (cm.point(w) - cm.point(v)); ++n; }
      if(n > 0) delta[std::size_t(v)] = sum * (factor / double(n));
    }
    for(sm_vertex v : vertices(cm)) cm.point(v) = cm.point(v) + delta[std::size_t(v)];
  }
  return result;
}

/// Same as above with the mesh's internal vertex point map.
template <class TriangleMesh>
Coarse_mesh_3<typename boost::property_traits<typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type>
build_coarse_mesh(const TriangleMesh& fine, const Coarse_mesh_options& options = Coarse_mesh_options())
{
  return build_coarse_mesh(fine, get(CGAL::vertex_point, fine), options);
}

} // namespace Silhouette_simplification_3
} // namespace CGAL

#endif // CGAL_SILHOUETTE_SIMPLIFICATION_3_COARSE_MESH_3_H
