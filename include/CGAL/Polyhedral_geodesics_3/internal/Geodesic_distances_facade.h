// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The public interface shared by every geodesic distance class of the package (the concept
// GeodesicDistances3): sources, options, queries and paths on any FaceGraph or triangle soup, translated to the
// compact mesh of a prepared surface (Geodesic_surface_3, shared and read-only) and forwarded to a propagation
// engine. Each public class (Exact_geodesic_distances_3, Flat_exact_geodesic_distances_3, ...) derives from this
// facade with its own engine.
//
// An engine is a class constructible from `const Geodesic_mesh<FT>&` with
//   void clear();                                   // forget sources and results
//   void set_keep_windows(bool full_field);         // may be ignored by engines without windows
//   void set_distance_limit(FT); void clear_distance_limit();
//   void set_stop_targets(const std::vector<Index>&);
//   void add_vertex_source(Index v, Index id);      // after clear(), before run()
//   void add_face_source(Index f, const std::array<FT, 3>& b, Index id);
//   template <class Progress> void run(Progress&);  // bool(const char*, double); false cancels
//   FT vertex_distance(Index v) const;              // +infinity when unreached
//   Index vertex_source(Index v) const;             // -1 when unreached
//   Geodesic_point_distance<FT> distance_at(Index f, const std::array<FT, 3>& b) const;
//   template <class Emit> void trace_path(Index f, const std::array<FT, 3>& b, Emit emit) const;
//                                                   // emit(const Geodesic_path_node<FT>&), query point first
//   const Geodesic_statistics& statistics() const;

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_GEODESIC_DISTANCES_FACADE_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_GEODESIC_DISTANCES_FACADE_H

#include <CGAL/MDCS/progress.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_surface_3.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_types.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>
#include <CGAL/Polyhedral_geodesics_3/internal/geodesic_engine_types.h>
#include <CGAL/Polyhedral_geodesics_3/internal/path_shortening.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

// What a class whose engine follows `twin` alone (fast marching, flat-exact) gives the facade's constructors on a
// prepared surface: such an engine cannot run on non-manifold or reversed edges (only a surface made from a
// triangle soup has them; a FaceGraph never does), so the surface is refused with std::invalid_argument naming
// the class and why its engine needs every edge to be an oriented manifold edge.
struct Special_edges_refusal
{
  const char* class_name;
  const char* why;
};

template <class TriangleMesh, class FT_, class VertexPointMap, class Engine_>
class Geodesic_distances_facade
{
public:
  typedef FT_ FT;
  /// The prepared surface the object runs on.
  typedef Geodesic_surface_3<TriangleMesh, FT_, VertexPointMap> Surface;
  typedef typename Surface::vertex_descriptor vertex_descriptor;
  typedef typename Surface::halfedge_descriptor halfedge_descriptor;
  typedef typename Surface::face_descriptor face_descriptor;
  typedef typename Surface::Point_3 Point_3;
  /// A point on the surface: a face and barycentric coordinates with respect to `source(halfedge(f))`,
  /// `target(halfedge(f))`, `target(next(halfedge(f)))`, as `CGAL::Polygon_mesh_processing::Face_location`
  /// (for a triangle soup: a triangle index and the weights of its three corners, in order).
  typedef std::pair<face_descriptor, std::array<FT, 3>> Face_location;
  /// returned by `nearest_source()` for unreachable points
  static constexpr std::size_t no_source = std::size_t(-1);

private:
  typedef Geodesic_mesh<FT> Mesh;
  typedef Engine_ Engine;
  typedef typename Mesh::Index Index;

public:
  // Builds a surface of its own. Throws std::invalid_argument on non-triangle faces.
  Geodesic_distances_facade(const TriangleMesh& tm, VertexPointMap vpm, Geodesic_memory_mode mode)
    : Geodesic_distances_facade(std::make_shared<const Surface>(tm, vpm), mode)
  {}

  // On a shared surface; with a refusal, a surface with special edges is refused (see Special_edges_refusal).
  Geodesic_distances_facade(std::shared_ptr<const Surface> surface, Geodesic_memory_mode mode,
                            const Special_edges_refusal* refusal = nullptr)
    : surface_(std::move(surface)), mesh_(checked_surface(surface_).compact_mesh()), mode_(mode)
  {
    if(refusal != nullptr)
      require_oriented_manifold_edges(*refusal);
    engine_.reset(new Engine(mesh_));
  }

  // On a surface that outlives the object.
  Geodesic_distances_facade(const Surface& surface, Geodesic_memory_mode mode,
                            const Special_edges_refusal* refusal = nullptr)
    : Geodesic_distances_facade(std::shared_ptr<const Surface>(std::shared_ptr<const Surface>(), &surface), mode,
                                refusal)
  {}

  Geodesic_distances_facade(const Geodesic_distances_facade&) = delete;
  Geodesic_distances_facade& operator=(const Geodesic_distances_facade&) = delete;

  /// \name Sources
  /// @{

  /// Adds a source at vertex `v`; returns its index (0, 1, ... in the order of addition).
  std::size_t add_source(vertex_descriptor v)
  {
    sources_.push_back(Source{true, surface_->vertex_index(v), -1, {FT(0), FT(0), FT(0)}});
    invalidate();
    return sources_.size() - 1;
  }

  /// Adds a source at a surface point. The barycentric coordinates must be non-negative and sum to 1
  /// (within 1e-9); a point on an edge or at a corner is handled as such.
  std::size_t add_source(const Face_location& location)
  {
    const Index f = face_index(location.first);
    check_barycentric(location.second, "add_source");
    sources_.push_back(Source{false, -1, f, location.second});
    invalidate();
    return sources_.size() - 1;
  }

  /// Removes the source of index `i` (as returned by `add_source()`) and keeps the others; the sources added
  /// after it move down one index (as in `std::vector::erase`). The next query runs again from the remaining
  /// sources, with the same results as a new object given them in the same order. Throws `std::out_of_range`
  /// if there is no source `i`.
  void remove_source(std::size_t i)
  {
    if(i >= sources_.size())
      throw std::out_of_range("CGAL::Polyhedral_geodesics_3::remove_source: no source " + std::to_string(i) + " (" +
                              std::to_string(sources_.size()) + " sources)");
    sources_.erase(sources_.begin() + std::ptrdiff_t(i));
    invalidate();
  }

  /// Removes every source.
  void clear_sources()
  {
    sources_.clear();
    invalidate();
  }

  std::size_t number_of_sources() const { return sources_.size(); }

  /// @}
  /// \name Options
  /// @{

  /// Stops the propagation at geodesic distance `limit`: points farther away report `+infinity`.
  void set_distance_limit(FT limit)
  {
    if(!(limit >= FT(0)))
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: the distance limit must be >= 0");
    limit_ = limit;
    has_limit_ = true;
    invalidate();
  }

  void clear_distance_limit()
  {
    has_limit_ = false;
    invalidate();
  }

  /// Stops the propagation as soon as the distances of all vertices in `targets` are final. Other
  /// vertices then report either their exact distance or `+infinity` (never a wrong finite value).
  template <class VertexRange>
  void set_stop_targets(const VertexRange& targets)
  {
    stop_targets_.clear();
    for(vertex_descriptor v : targets)
      stop_targets_.push_back(surface_->vertex_index(v));
    invalidate();
  }

  void clear_stop_targets()
  {
    stop_targets_.clear();
    invalidate();
  }

  Geodesic_memory_mode memory_mode() const { return mode_; }

  /// When `on`, every path that `shortest_path_points()` and `shortest_path_sequence()` report is first made
  /// locally shortest: straight in every unfolding of the faces it crosses, and through a vertex only where the
  /// angle on both sides is at least pi (a geodesic of the polyhedral surface). Its ends stay, it is never
  /// longer than the traced path, and it keeps the traced path's way around the surface's features (it is not
  /// necessarily the shortest path overall). Off by default; meant for the approximate classes, whose traced
  /// paths bend where a geodesic does not (the exact class's paths are already locally shortest). The distances
  /// do not change.
  void set_path_shortening(bool on) { shorten_paths_ = on; }
  bool path_shortening() const { return shorten_paths_; }

  void set_memory_mode(Geodesic_memory_mode mode)
  {
    mode_ = mode;
    invalidate();
  }

  /// @}
  /// \name Computation
  /// @{

  /// Runs the propagation (queries call it when needed). `progress` is a callable
  /// `bool(const char* stage, double fraction)`, see `CGAL::MDCS::No_progress`; returning false cancels
  /// with `CGAL::MDCS::Operation_cancelled`. The stage is `"geodesic propagation"`, the fraction the share of
  /// mesh vertices whose distance is final.
  template <class Progress = MDCS::No_progress>
  void compute(Progress progress = Progress())
  {
    if(computed_)
      return;
    if(sources_.empty())
      throw std::logic_error("CGAL::Polyhedral_geodesics_3: no source was added before the query");
    engine_->clear();
    engine_->set_keep_windows(mode_ == Geodesic_memory_mode::full_field);
    if(has_limit_)
      engine_->set_distance_limit(limit_);
    else
      engine_->clear_distance_limit();
    engine_->set_stop_targets(stop_targets_);
    for(std::size_t i = 0; i < sources_.size(); ++i) {
      const Source& s = sources_[i];
      if(s.at_vertex)
        engine_->add_vertex_source(s.vertex, Index(i));
      else
        engine_->add_face_source(s.face, s.barycentric, Index(i));
    }
    engine_->run(progress);
    computed_ = true;
  }

  bool is_computed() const { return computed_; }

  /// @}
  /// \name Queries
  /// @{

  /// The geodesic distance from vertex `v` to the nearest source, `+infinity` if unreachable.
  FT distance(vertex_descriptor v)
  {
    const Index i = surface_->vertex_index(v);
    compute();
    return engine_->vertex_distance(i);
  }

  /// The geodesic distance from a surface point to the nearest source. Needs the full field.
  FT distance(const Face_location& location)
  {
    require_full_field("distance(Face_location)");
    check_barycentric(location.second, "distance");
    compute();
    return engine_->distance_at(face_index(location.first), location.second).distance;
  }

  /// The nearest source of vertex `v` and its distance; `(+infinity, no_source)` if unreachable.
  std::pair<FT, std::size_t> nearest_source(vertex_descriptor v)
  {
    const Index i = surface_->vertex_index(v);
    compute();
    const Index s = engine_->vertex_source(i);
    return {engine_->vertex_distance(i), s < 0 ? no_source : std::size_t(s)};
  }

  /// The nearest source of a surface point and its distance. Needs the full field.
  std::pair<FT, std::size_t> nearest_source(const Face_location& location)
  {
    require_full_field("nearest_source(Face_location)");
    check_barycentric(location.second, "nearest_source");
    compute();
    const auto r = engine_->distance_at(face_index(location.first), location.second);
    return {r.distance, r.source < 0 ? no_source : std::size_t(r.source)};
  }

  /// Writes the distance of every vertex into `distance_map` (a writable vertex property map whose
  /// value type is constructible from `FT`; unreachable vertices get `+infinity`).
  template <class VertexDistanceMap>
  void distances(VertexDistanceMap distance_map)
  {
    compute();
    surface_->for_each_vertex([&](vertex_descriptor v, Index i) { put(distance_map, v, engine_->vertex_distance(i)); });
  }

  /// Writes the points of the shortest path from vertex `target` to its nearest source (both included)
  /// to `out` (value type `Point_3`). Writes nothing if `target` is unreachable. Needs the full field.
  template <class OutputIterator>
  OutputIterator shortest_path_points(vertex_descriptor target, OutputIterator out)
  {
    return shortest_path_points(vertex_location(target), out);
  }

  template <class OutputIterator>
  OutputIterator shortest_path_points(const Face_location& target, OutputIterator out)
  {
    require_full_field("shortest_path_points");
    check_barycentric(target.second, "shortest_path_points");
    compute();
    for_each_path_node(target, [&](const Geodesic_path_node<FT>& node) {
      *out++ = Surface::make_point(to_double_value(node.point[0]), to_double_value(node.point[1]),
                                   to_double_value(node.point[2]));
    });
    return out;
  }

  /// Reports the shortest path from vertex `target` to its nearest source to `visitor`, a model of
  /// `GeodesicPathVisitor` (vertices, edge crossings, face points). Needs the full field.
  template <class Visitor>
  void shortest_path_sequence(vertex_descriptor target, Visitor& visitor)
  {
    shortest_path_sequence(vertex_location(target), visitor);
  }

  template <class Visitor>
  void shortest_path_sequence(const Face_location& target, Visitor& visitor)
  {
    require_full_field("shortest_path_sequence");
    check_barycentric(target.second, "shortest_path_sequence");
    compute();
    for_each_path_node(target, [&](const Geodesic_path_node<FT>& node) {
      switch(node.kind) {
      case Geodesic_path_node<FT>::VERTEX:
        visitor(surface_->vertex(node.index));
        break;
      case Geodesic_path_node<FT>::EDGE:
        visitor(surface_->halfedge(node.index), node.t);
        break;
      case Geodesic_path_node<FT>::FACE:
        visitor(surface_->face(node.index), node.barycentric);
        break;
      }
    });
  }

  /// Counters of the last propagation.
  const Geodesic_statistics& statistics() const { return engine_->statistics(); }

  /// The surface point at vertex `v`, in a face incident to `v`. Throws for isolated vertices.
  Face_location vertex_location(vertex_descriptor v) const
  {
    const Index h = mesh_.vertex_halfedge[std::size_t(surface_->vertex_index(v))];
    if(h < 0)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: the vertex has no incident face");
    std::array<FT, 3> b = {FT(0), FT(0), FT(0)};
    b[std::size_t(h % 3)] = FT(1);
    return {surface_->face(Mesh::face_of(h)), b};
  }

  /// The prepared surface the object runs on (shared with every object built on it).
  const Surface& surface() const { return *surface_; }
  std::shared_ptr<const Surface> shared_surface() const { return surface_; }

  /// @}

protected:
  Engine& engine() { return *engine_; }
  const Engine& engine_const() const { return *engine_; }
  const Mesh& compact_mesh() const { return mesh_; }
  // Options of a derived class changed: the next query recomputes.
  void invalidate() { computed_ = false; }

private:
  void require_oriented_manifold_edges(const Special_edges_refusal& refusal) const
  {
    if(!mesh_.has_special_edges())
      return;
    throw std::invalid_argument(std::string("CGAL::Polyhedral_geodesics_3::") + refusal.class_name +
                                ": the surface has " + std::to_string(mesh_.number_of_nonmanifold_edges) +
                                " edges of three or more faces and " + std::to_string(mesh_.number_of_reversed_edges) +
                                " edges whose two faces are oriented against each other (non-orientable gluing); " +
                                refusal.why + " (the exact, merged-window and Dijkstra classes support such surfaces)");
  }

  struct Source
  {
    bool at_vertex;
    Index vertex;
    Index face;
    std::array<FT, 3> barycentric;
  };

  void require_full_field(const char* what) const
  {
    if(mode_ != Geodesic_memory_mode::full_field)
      throw std::logic_error(std::string("CGAL::Polyhedral_geodesics_3: ") + what +
                             " needs Geodesic_memory_mode::full_field (the object was built with distances_only)");
  }

  // The engine's path from `target`, shortened first if asked for.
  template <class Emit>
  void for_each_path_node(const Face_location& target, Emit emit)
  {
    if(!shorten_paths_) {
      engine_->trace_path(face_index(target.first), target.second, emit);
      return;
    }
    path_nodes_.clear();
    engine_->trace_path(face_index(target.first), target.second,
                        [&](const Geodesic_path_node<FT>& node) { path_nodes_.push_back(node); });
    if(!shortener_)
      shortener_.reset(new Geodesic_path_shortener<FT>(mesh_));
    shortener_->shorten(path_nodes_);
    for(const Geodesic_path_node<FT>& node : path_nodes_)
      emit(node);
  }

  static void check_barycentric(const std::array<FT, 3>& b, const char* what)
  {
    const double b0 = to_double_value(b[0]), b1 = to_double_value(b[1]),
                 b2 = to_double_value(b[2]);
    if(!(b0 >= -1e-12 && b1 >= -1e-12 && b2 >= -1e-12) || !(std::abs(b0 + b1 + b2 - 1.0) <= 1e-9))
      throw std::invalid_argument(std::string("CGAL::Polyhedral_geodesics_3::") + what +
                                  ": the barycentric coordinates must be >= 0 and sum to 1 (the point must lie in the face)");
  }

  Index face_index(face_descriptor f) const { return surface_->face_index(f); }

  static const Surface& checked_surface(const std::shared_ptr<const Surface>& surface)
  {
    if(!surface)
      throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: null surface");
    return *surface;
  }

  std::shared_ptr<const Surface> surface_;
  const Mesh& mesh_;
  Geodesic_memory_mode mode_;
  std::unique_ptr<Engine> engine_;
  std::vector<Source> sources_;
  std::vector<Index> stop_targets_;
  FT limit_ = FT(0);
  bool has_limit_ = false;
  bool computed_ = false;
  bool shorten_paths_ = false;
  std::vector<Geodesic_path_node<FT>> path_nodes_;
  std::unique_ptr<Geodesic_path_shortener<FT>> shortener_;
};

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_GEODESIC_DISTANCES_FACADE_H
