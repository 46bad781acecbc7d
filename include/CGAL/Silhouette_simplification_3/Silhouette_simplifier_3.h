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
#include <CGAL/Silhouette_simplification_3/internal/Edge_cone_hierarchy.h>
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
  std::vector<char> fine_front, coarse_front;             ///< per face: faces the viewer (fine_front: empty with a hierarchy)
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
  input data structure. The preprocessed data never changes afterwards: with one `Workspace` per thread, the
  `const` overloads of the per-view calls process several views at once (`simplify_silhouette_frames()` does so
  for a sequence of views). The coarse mesh and the map usually come from `build_coarse_mesh()`
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

  /*!
    \brief The scratch memory of the per-view calls (loop decomposition, picking, mapping): about 60 bytes per fine
    face. The calls that take a workspace are `const`: views may be processed concurrently on one simplifier,
    with one workspace per thread (see `simplify_silhouette_frames()`). The calls without one use the simplifier's
    own workspace (one view at a time).
  */
  class Workspace
  {
  public:
    explicit Workspace(const Silhouette_simplifier_3& s)
      : factor_(s.fine_.number_of_halfedges(), 1.0), edge_flag_(s.fine_.number_of_halfedges(), 0),
        mapper_(new internal::Loop_mapper<Point_3>(&s.fine_, &s.coarse_, &s.cf_begin_, &s.cf_, &s.length_))
    {
      mapper_->set_face_map(&s.face_map_, &s.representative_);
    }

    /// The last dual network built by `map_loops()` with this workspace (for tests and pictures).
    const internal::Loop_mapper<Point_3>& mapper() const { return *mapper_; }

  private:
    friend class Silhouette_simplifier_3;
    std::vector<double> factor_;
    std::vector<char> edge_flag_;
    std::vector<Point_3> coarse_points_;
    std::vector<float> table_;
    internal::Loop_decomposer decomposer_;
    std::unique_ptr<internal::Loop_mapper<Point_3>> mapper_;
  };

  /// A workspace for this simplifier (see `Workspace`).
  Workspace make_workspace() const { return Workspace(*this); }

  /*!
    \brief Builds a bounding-cone hierarchy over the fine mesh's edges (see `Silhouette_edge_hierarchy_3`): the
    later calls of `extract_silhouettes()` find the same fine silhouette without classifying every fine face, and
    leave `Silhouette_frame::fine_front` empty. Not thread-safe with concurrent per-view calls.
  */
  void build_silhouette_hierarchy(const Silhouette_hierarchy_options& options = Silhouette_hierarchy_options())
  {
    fine_hierarchy_.build(fine_, options);
    use_hierarchy_ = true;
  }
  bool uses_silhouette_hierarchy() const { return use_hierarchy_; }

  /// Silhouette extraction (fine and coarse) without decomposition.
  void extract_silhouettes(const View& view, Silhouette_frame& frame) const
  {
    if(use_hierarchy_) {
      frame.fine_front.clear();
      fine_hierarchy_.query(fine_, view, frame.fine_silhouette);
    } else {
      internal::classify_faces(fine_, view, frame.fine_front);
      internal::silhouette_from_faces(fine_, frame.fine_front, frame.fine_silhouette);
    }
    internal::classify_faces(coarse_, view, frame.coarse_front);
    internal::silhouette_from_faces(coarse_, frame.coarse_front, frame.coarse_silhouette);
  }

  /// Loop decomposition of both silhouettes of `frame`.
  void decompose(Silhouette_frame& frame) { decompose(frame, *own_); }
  void decompose(Silhouette_frame& frame, Workspace& ws) const
  {
    ws.decomposer_(fine_, frame.fine_silhouette, frame.fine_loops);
    ws.decomposer_(coarse_, frame.coarse_silhouette, frame.coarse_loops);
  }

  /// Silhouettes of both meshes and their loop decompositions for `view`.
  void extract(const View& view, Silhouette_frame& frame) { extract(view, frame, *own_); }
  void extract(const View& view, Silhouette_frame& frame, Workspace& ws) const
  {
    extract_silhouettes(view, frame);
    decompose(frame, ws);
  }

  /*!
    Method A: greedy loop picking (thesis 5.2.2). Needs `extract()` first. `previous`, if given, is the
    previous frame (used when `options.previous_bias != 1`).
  */
  void pick_loops(Silhouette_frame& frame, const Loop_picking_options& options = Loop_picking_options(),
                  const Silhouette_frame* previous = nullptr)
  {
    pick_loops(frame, options, previous, *own_);
  }

  /// The same with the scratch memory of `ws` (`const`: see `Workspace`).
  void pick_loops(Silhouette_frame& frame, const Loop_picking_options& options, const Silhouette_frame* previous,
                  Workspace& ws) const
  {
    check_picking_options(options);
    ws.coarse_points_.clear();
    for(const auto& loop : frame.coarse_loops)
      for(std::uint32_t h : loop.halfedges) ws.coarse_points_.push_back(coarse_.points[coarse_.source[h]]);
    const std::vector<char>* flags = nullptr;
    std::vector<std::uint32_t> marked;
    if(previous && options.previous_bias != 1.0) {
      marked = previous->picked_halfedges();
      for(std::uint32_t h : marked) ws.edge_flag_[fine_.edge(h)] = 1;
      flags = &ws.edge_flag_;
    }
    // The flags are cleared on every exit, exceptions included.
    struct Unmark
    {
      const Silhouette_simplifier_3* s;
      Workspace* ws;
      const std::vector<std::uint32_t>* hs;
      ~Unmark() { for(std::uint32_t h : *hs) ws->edge_flag_[s->fine_.edge(h)] = 0; }
    } unmark{this, &ws, &marked};
    frame.picking_error = internal::pick_loops(fine_, ws.coarse_points_, frame.fine_loops, fine_.diagonal, options,
                                               flags, frame.picked, ws.table_);
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
    map_loops(frame, options, previous, engine, *own_);
  }

  /// The same with the scratch memory of `ws` (`const`: see `Workspace`).
  template <class Engine>
  void map_loops(Silhouette_frame& frame, const Loop_mapping_options& options, const Silhouette_frame* previous,
                 Engine engine, Workspace& ws) const
  {
    check_mapping_options(options);
    // Weight factors per canonical edge, reset on every exit (exceptions included).
    std::vector<std::uint32_t> prev;
    if(previous && options.previous_bias != 1.0) prev = previous->mapped_halfedges();
    struct Reset
    {
      const Silhouette_simplifier_3* s;
      Workspace* ws;
      const std::vector<std::uint32_t>* a;
      const std::vector<std::uint32_t>* b;
      ~Reset()
      {
        for(std::uint32_t h : *a) ws->factor_[s->fine_.edge(h)] = 1.0;
        for(std::uint32_t h : *b) ws->factor_[s->fine_.edge(h)] = 1.0;
      }
    } reset{this, &ws, &frame.fine_silhouette, &prev};
    for(std::uint32_t h : frame.fine_silhouette) ws.factor_[fine_.edge(h)] = options.alpha;
    for(std::uint32_t h : prev) ws.factor_[fine_.edge(h)] *= options.previous_bias;
    frame.mapped.clear();
    frame.mapping_reports.clear();
    for(std::size_t i = 0; i < frame.coarse_loops.size(); ++i) {
      Mapped_loop_report r = ws.mapper_->map(frame.coarse_loops[i], ws.factor_, engine, frame.mapped);
      r.coarse_loop = i;
      frame.mapping_reports.push_back(r);
    }
  }

  /// Throws `std::invalid_argument` unless `threshold` and `min_relative_gain` are >= 0 and `previous_bias` in (0, 1].
  static void check_picking_options(const Loop_picking_options& options)
  {
    if(!(options.threshold >= 0) || !(options.min_relative_gain >= 0) ||
       !(options.previous_bias > 0 && options.previous_bias <= 1))
      throw std::invalid_argument("MDCS: Silhouette_simplifier_3::pick_loops: threshold and min_relative_gain must "
                                  "be >= 0 and previous_bias in (0, 1]");
  }

  /// Throws `std::invalid_argument` unless `alpha` and `previous_bias` are in (0, 1].
  static void check_mapping_options(const Loop_mapping_options& options)
  {
    if(!(options.alpha > 0 && options.alpha <= 1) || !(options.previous_bias > 0 && options.previous_bias <= 1))
      throw std::invalid_argument("MDCS: Silhouette_simplifier_3::map_loops: alpha and previous_bias must be in (0, 1]");
  }

  /// The weight of fine halfedge `h` without factors (its length).
  double edge_length(std::uint32_t h) const { return length_[h]; }

  /// The last dual network built by `map_loops()` without a workspace (for tests and pictures).
  const internal::Loop_mapper<Point_3>& mapper() const { return own_->mapper(); }

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
    own_.reset(new Workspace(*this));
  }

  Indexed_mesh fine_, coarse_;
  internal::Edge_cone_hierarchy fine_hierarchy_;
  bool use_hierarchy_ = false;
  std::vector<halfedge_descriptor> fine_halfedge_;
  std::vector<face_descriptor> fine_face_;
  std::vector<vertex_descriptor> fine_vertex_;
  std::vector<std::uint32_t> face_map_, cf_begin_, cf_, representative_;
  std::vector<double> length_;
  std::unique_ptr<Workspace> own_; // the workspace of the calls without one
};

} // namespace Silhouette_simplification_3
} // namespace CGAL

#endif // CGAL_SILHOUETTE_SIMPLIFICATION_3_SILHOUETTE_SIMPLIFIER_3_H
