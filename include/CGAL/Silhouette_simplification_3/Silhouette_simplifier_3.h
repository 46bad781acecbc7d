// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The per-view runtime of silhouette simplification (thesis chapter 5): silhouettes of the fine and
// coarse meshes, loop decomposition, loop picking (method A) and loop mapping (method B).

#ifndef CGAL_SILHOUETTE_SIMPLIFICATION_3_SILHOUETTE_SIMPLIFIER_3_H
#define CGAL_SILHOUETTE_SIMPLIFICATION_3_SILHOUETTE_SIMPLIFIER_3_H

#include <CGAL/Silhouette_simplification_3/View_3.h>
#include <CGAL/Silhouette_simplification_3/internal/Indexed_mesh.h>
#include <CGAL/Silhouette_simplification_3/internal/silhouette_extraction.h>
#include <CGAL/Silhouette_simplification_3/internal/Loop_picker.h>
#include <CGAL/Silhouette_simplification_3/internal/Loop_mapper.h>
#include <CGAL/Min_cut/solve_min_cut.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/properties.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Silhouette_simplification_3 {

/*!
  \ingroup PkgSilhouetteSimplification3Ref
  \brief Everything one view produces. Edges are halfedge indices of the simplifier's fine or coarse
  mesh (see `Silhouette_simplifier_3::fine_halfedge()`); every directed edge has the front-facing side on its left.
*/
struct Silhouette_frame
{
  typedef Silhouette_loop<std::uint32_t> Loop;
  std::vector<char> fine_front, coarse_front;             ///< per face: faces the viewer
  std::vector<std::uint32_t> fine_silhouette, coarse_silhouette; ///< silhouette halfedges
  std::vector<Loop> fine_loops, coarse_loops;             ///< their loop decompositions
  std::vector<std::uint32_t> picked;                      ///< method A: indices into `fine_loops`
  double picking_error = 0;                               ///< method A: final sum of squared distances
  std::vector<Loop> mapped;                               ///< method B: fine loops
  std::vector<Mapped_loop_report> mapping_reports;        ///< method B: one per coarse loop

  /// The fine halfedges of the picked loops.
  std::vector<std::uint32_t> picked_halfedges() const
  {
    std::vector<std::uint32_t> r;
    for(std::uint32_t l : picked) r.insert(r.end(), fine_loops[l].halfedges.begin(), fine_loops[l].halfedges.end());
    return r;
  }
  /// The fine halfedges of the mapped loops.
  std::vector<std::uint32_t> mapped_halfedges() const
  {
    std::vector<std::uint32_t> r;
    for(const Loop& l : mapped) r.insert(r.end(), l.halfedges.begin(), l.halfedges.end());
    return r;
  }
};

/*!
  \ingroup PkgSilhouetteSimplification3Ref
  \brief Simplified silhouettes of a fine triangle mesh, guided by a coarse mesh and a fine-to-coarse face map.

  Preprocessing (the constructor) copies both meshes into flat arrays and inverts the face map; the
  per-view calls `extract()`, `pick_loops()` and `map_loops()` then run on arrays only, whatever the
  input data structure. The coarse mesh and the map usually come from `build_coarse_mesh()`
  (header `Coarse_mesh_3.h`), but any coarse mesh and map may be given.

  \tparam TriangleMesh a model of `FaceListGraph` with triangle faces (e.g. `Surface_mesh`, `Polyhedron_3`)
  \tparam VertexPointMap its vertex point map; the kernel is deduced from its value type
*/
template <class TriangleMesh,
          class VertexPointMap = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>
class Silhouette_simplifier_3
{
public:
  typedef typename boost::property_traits<VertexPointMap>::value_type Point_3;
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel Kernel;
  typedef View_3<Kernel> View;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef internal::Indexed_mesh<Point_3> Indexed_mesh;

  /*!
    \param fine the fine mesh (must outlive this object only if `fine_halfedge()` descriptors are used)
    \param coarse the coarse mesh, any `FaceListGraph` with triangle faces and the same point type
    \param coarse_face_of_fine_face for the `i`-th face of `fine`, the index of its coarse face (in `faces(coarse)` order)
    \throws std::invalid_argument when a mesh is empty or not triangulated, or the map has the wrong size or an index out of range
  */
  template <class CoarseMesh>
  Silhouette_simplifier_3(const TriangleMesh& fine, const CoarseMesh& coarse,
                          const std::vector<std::uint32_t>& coarse_face_of_fine_face)
  {
    init(fine, get(CGAL::vertex_point, fine), coarse, get(CGAL::vertex_point, coarse), coarse_face_of_fine_face);
  }

  /// Same with explicit vertex point maps.

  template <class CoarseMesh, class CoarseVertexPointMap>
  Silhouette_simplifier_3(const TriangleMesh& fine, VertexPointMap vpm, const CoarseMesh& coarse,
                          CoarseVertexPointMap coarse_vpm, const std::vector<std::uint32_t>& coarse_face_of_fine_face)
  {
    init(fine, vpm, coarse, coarse_vpm, coarse_face_of_fine_face);
  }

  Silhouette_simplifier_3(const Silhouette_simplifier_3&) = delete;
  Silhouette_simplifier_3& operator=(const Silhouette_simplifier_3&) = delete;

  const Indexed_mesh& fine() const { return fine_; }
  const Indexed_mesh& coarse() const { return coarse_; }
  const std::vector<std::uint32_t>& face_map() const { return face_map_; }
  /// Fine faces of coarse face `c` are `fine_faces_of_coarse_begin()[c] .. [c+1]` in `fine_faces_of_coarse()`.
  const std::vector<std::uint32_t>& fine_faces_of_coarse_begin() const { return cf_begin_; }
  const std::vector<std::uint32_t>& fine_faces_of_coarse() const { return cf_; }
  /// The diagonal of the fine mesh's bounding box.
  double diagonal() const { return fine_.diagonal; }
  /// The fine mesh's halfedge descriptor of fine halfedge index `h`.
  halfedge_descriptor fine_halfedge(std::uint32_t h) const { return fine_halfedge_[h]; }
  /// The fine mesh's face descriptor of fine face index `f`.
  face_descriptor fine_face(std::uint32_t f) const { return fine_face_[f]; }

  /// Silhouette extraction (fine and coarse) without decomposition.
  void extract_silhouettes(const View& view, Silhouette_frame& frame) const
  {
    internal::classify_faces(fine_, view, frame.fine_front);
    internal::silhouette_from_faces(fine_, frame.fine_front, frame.fine_silhouette);
    internal::classify_faces(coarse_, view, frame.coarse_front);
    internal::silhouette_from_faces(coarse_, frame.coarse_front, frame.coarse_silhouette);
  }

  /// Loop decomposition of both silhouettes of `frame`.
  void decompose(Silhouette_frame& frame)
  {
    decomposer_(fine_, frame.fine_silhouette, frame.fine_loops);
    decomposer_(coarse_, frame.coarse_silhouette, frame.coarse_loops);
  }

  /// Silhouettes of both meshes and their loop decompositions for `view`.
  void extract(const View& view, Silhouette_frame& frame)
  {
    extract_silhouettes(view, frame);
    decompose(frame);
  }

  /*!
    Method A: greedy loop picking (thesis 5.2.2). Needs `extract()` first. `previous`, if given, is the
    previous frame (used when `options.previous_bias != 1`).
  */
  void pick_loops(Silhouette_frame& frame, const Loop_picking_options& options = Loop_picking_options(),
                  const Silhouette_frame* previous = nullptr)
  {
    if(!(options.threshold >= 0) || !(options.min_relative_gain >= 0) ||
       !(options.previous_bias > 0 && options.previous_bias <= 1))
      throw std::invalid_argument("MDCS: Silhouette_simplifier_3::pick_loops: threshold and min_relative_gain must "
                                  "be >= 0 and previous_bias in (0, 1]");
    coarse_points_.clear();
    for(const auto& loop : frame.coarse_loops)
      for(std::uint32_t h : loop.halfedges) coarse_points_.push_back(coarse_.points[coarse_.source[h]]);
    const std::vector<char>* flags = nullptr;
    if(previous && options.previous_bias != 1.0) {
      mark_edges(previous->picked_halfedges());
      flags = &edge_flag_;
    }
    frame.picking_error = internal::pick_loops(fine_, coarse_points_, frame.fine_loops, fine_.diagonal, options, flags,
                                               frame.picked, table_);
    if(flags) unmark_edges(previous->picked_halfedges());
  }

  /*!
    Method B: loop mapping by minimum cut (thesis 5.2.3). Needs `extract()` first. `previous`, if
    given, is the previous frame (used when `options.previous_bias != 1`).
    \tparam Engine a model of `MaxFlowEngine` (package Min_cut)
  */
  template <class Engine = CGAL::Min_cut::Default_max_flow_engine>
  void map_loops(Silhouette_frame& frame, const Loop_mapping_options& options = Loop_mapping_options(),
                 const Silhouette_frame* previous = nullptr, Engine engine = Engine())
  {
    if(!(options.alpha > 0 && options.alpha <= 1) || !(options.previous_bias > 0 && options.previous_bias <= 1))
      throw std::invalid_argument("MDCS: Silhouette_simplifier_3::map_loops: alpha and previous_bias must be in (0, 1]");
    // Weight factors per canonical edge, reset on every exit (exceptions included).
    std::vector<std::uint32_t> prev;
    if(previous && options.previous_bias != 1.0) prev = previous->mapped_halfedges();
    struct Reset
    {
      Silhouette_simplifier_3* s;
      const std::vector<std::uint32_t>* a;
      const std::vector<std::uint32_t>* b;
      ~Reset()
      {
        for(std::uint32_t h : *a) s->factor_[s->fine_.edge(h)] = 1.0;
        for(std::uint32_t h : *b) s->factor_[s->fine_.edge(h)] = 1.0;
      }
    } reset{this, &frame.fine_silhouette, &prev};
    for(std::uint32_t h : frame.fine_silhouette) factor_[fine_.edge(h)] = options.alpha;
    for(std::uint32_t h : prev) factor_[fine_.edge(h)] *= options.previous_bias;
    frame.mapped.clear();
    frame.mapping_reports.clear();
    for(std::size_t i = 0; i < frame.coarse_loops.size(); ++i) {
      Mapped_loop_report r = mapper_->map(frame.coarse_loops[i], factor_, engine, frame.mapped);
      r.coarse_loop = i;
      frame.mapping_reports.push_back(r);
    }
  }

  /// The weight of fine halfedge `h` without factors (its length).
  double edge_length(std::uint32_t h) const { return length_[h]; }

  /// The last dual network built by `map_loops()` (for tests and pictures).
  const internal::Loop_mapper<Point_3>& mapper() const { return *mapper_; }

private:
  template <class CoarseMesh, class CoarseVertexPointMap>
  void init(const TriangleMesh& fine, VertexPointMap vpm, const CoarseMesh& coarse, CoarseVertexPointMap cvpm,
            const std::vector<std::uint32_t>& map)
  {
    internal::build_indexed_mesh(fine, vpm, fine_, fine_halfedge_, fine_face_, fine_vertex_, "Silhouette_simplifier_3 (fine mesh)");
    std::vector<typename boost::graph_traits<CoarseMesh>::halfedge_descriptor> ch;
    std::vector<typename boost::graph_traits<CoarseMesh>::face_descriptor> cfd;
    std::vector<typename boost::graph_traits<CoarseMesh>::vertex_descriptor> cvd;
    internal::build_indexed_mesh(coarse, cvpm, coarse_, ch, cfd, cvd, "Silhouette_simplifier_3 (coarse mesh)");
    if(map.size() != fine_.faces.size())
      throw std::invalid_argument("MDCS: Silhouette_simplifier_3: the face map has " + std::to_string(map.size()) +
                                  " entries for " + std::to_string(fine_.faces.size()) + " fine faces");
    face_map_ = map;
    cf_begin_.assign(coarse_.faces.size() + 1, 0);
    for(std::size_t f = 0; f < map.size(); ++f) {
      if(map[f] >= coarse_.faces.size())
        throw std::invalid_argument("MDCS: Silhouette_simplifier_3: fine face " + std::to_string(f) +
                                    " maps to coarse face " + std::to_string(map[f]) + ", but the coarse mesh has " +
                                    std::to_string(coarse_.faces.size()) + " faces");
      ++cf_begin_[map[f] + 1];
    }
    for(std::size_t c = 0; c < coarse_.faces.size(); ++c) cf_begin_[c + 1] += cf_begin_[c];
    cf_.assign(map.size(), 0);
    std::vector<std::uint32_t> fill(cf_begin_.begin(), cf_begin_.end() - 1);
    for(std::uint32_t f = 0; f < map.size(); ++f) cf_[fill[map[f]]++] = f;

    length_.resize(fine_.number_of_halfedges());
    for(std::uint32_t h = 0; h < length_.size(); ++h)
      length_[h] = std::sqrt(CGAL::to_double(CGAL::squared_distance(fine_.points[fine_.source[h]],
                                                                    fine_.points[fine_.target(h)])));
    factor_.assign(fine_.number_of_halfedges(), 1.0);
    edge_flag_.assign(fine_.number_of_halfedges(), 0);
    mapper_.reset(new internal::Loop_mapper<Point_3>(&fine_, &coarse_, &cf_begin_, &cf_, &length_));
    // Representative fine face of each coarse face: the one whose centroid is closest to the coarse centroid.
    representative_.assign(coarse_.faces.size(), 0);
    for(std::uint32_t c = 0; c < coarse_.faces.size(); ++c) {
      const auto& t = coarse_.faces[c];
      const Point_3 cc = CGAL::centroid(coarse_.points[t[0]], coarse_.points[t[1]], coarse_.points[t[2]]);
      double best = HUGE_VAL;
      for(std::uint32_t k = cf_begin_[c]; k < cf_begin_[c + 1]; ++k) {
        const auto& u = fine_.faces[cf_[k]];
        const double d = CGAL::to_double(CGAL::squared_distance(
          cc, CGAL::centroid(fine_.points[u[0]], fine_.points[u[1]], fine_.points[u[2]])));
        if(d < best) { best = d; representative_[c] = cf_[k]; }
      }
    }
    mapper_->set_face_map(&face_map_, &representative_);
  }

  void mark_edges(const std::vector<std::uint32_t>& hs) { for(std::uint32_t h : hs) edge_flag_[fine_.edge(h)] = 1; }
  void unmark_edges(const std::vector<std::uint32_t>& hs) { for(std::uint32_t h : hs) edge_flag_[fine_.edge(h)] = 0; }

  Indexed_mesh fine_, coarse_;
  std::vector<halfedge_descriptor> fine_halfedge_;
  std::vector<face_descriptor> fine_face_;
  std::vector<vertex_descriptor> fine_vertex_;
  std::vector<std::uint32_t> face_map_, cf_begin_, cf_, representative_;
  std::vector<double> length_, factor_;
  std::vector<char> edge_flag_;
  std::vector<Point_3> coarse_points_;
  std::vector<float> table_;
  internal::Loop_decomposer decomposer_;
  std::unique_ptr<internal::Loop_mapper<Point_3>> mapper_;
};

} // namespace Silhouette_simplification_3
} // namespace CGAL

#endif // CGAL_SILHOUETTE_SIMPLIFICATION_3_SILHOUETTE_SIMPLIFIER_3_H
