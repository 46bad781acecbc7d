// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Geodesic_solver interface implemented by any class of the package's GeodesicDistances3 concept on the
// surface's Surface_mesh. Included by the two translation units that instantiate the five classes.

#ifndef MDCS_PYTHON_GEODESIC_SOLVER_IMPL_H
#define MDCS_PYTHON_GEODESIC_SOLVER_IMPL_H

#include "geodesic_surface.h"

#include <functional>
#include <limits>

namespace mdcs_python {

template <class Geodesics>
class Geodesic_solver_impl : public Geodesic_solver
{
  typedef typename Geodesics::Face_location Face_location;

public:
  template <class... Args>
  explicit Geodesic_solver_impl(const Geo_mesh& mesh, Args&&... args)
    : mesh_(mesh), g_(mesh, std::forward<Args>(args)...)
  {}

  Geodesics& geodesics() { return g_; }

  void clear_sources() override { g_.clear_sources(); }

  void add_vertex_source(std::size_t v) override { g_.add_source(vertex(v)); }

  void add_point_source(std::size_t f, const std::array<double, 3>& b) override { g_.add_source(location(f, b)); }

  void set_distance_limit(double limit) override
  {
    if(limit == std::numeric_limits<double>::infinity()) g_.clear_distance_limit();
    else g_.set_distance_limit(limit);
  }

  void set_stop_targets(const std::vector<std::size_t>& targets) override
  {
    if(targets.empty()) {
      g_.clear_stop_targets();
      return;
    }
    std::vector<Geo_mesh::Vertex_index> vs;
    vs.reserve(targets.size());
    for(std::size_t v : targets) vs.push_back(vertex(v));
    g_.set_stop_targets(vs);
  }

  void set_path_shortening(bool on) override { g_.set_path_shortening(on); }

  void set_threads(std::size_t threads) override
  {
    if(threads != threads_) set_threads_of(g_, threads, 0); // (a change invalidates the results)
    threads_ = threads;
  }

  void compute(Progress_bridge& progress) override { g_.compute(std::ref(progress)); }

  void compute_quietly() override { g_.compute(); }

  void vertex_results(std::vector<double>& distances, std::vector<std::int64_t>* nearest) override
  {
    const std::size_t n = mesh_.number_of_vertices();
    distances.resize(n);
    if(nearest) nearest->resize(n);
    for(std::size_t v = 0; v < n; ++v) {
      const auto r = g_.nearest_source(vertex(v));
      distances[v] = r.first;
      if(nearest) (*nearest)[v] = r.second == Geodesics::no_source ? std::int64_t(-1) : std::int64_t(r.second);
    }
  }

  std::pair<double, std::int64_t> point_result(std::size_t f, const std::array<double, 3>& b) override
  {
    const auto r = g_.nearest_source(location(f, b));
    return {r.first, r.second == Geodesics::no_source ? std::int64_t(-1) : std::int64_t(r.second)};
  }

  void path(std::size_t f, const std::array<double, 3>& b, std::vector<Raw_path_node>& out) override
  {
    Visitor visitor{&out};
    out.clear();
    g_.shortest_path_sequence(location(f, b), visitor);
  }

  void vertex_path(std::size_t v, std::vector<Raw_path_node>& out) override
  {
    Visitor visitor{&out};
    out.clear();
    g_.shortest_path_sequence(vertex(v), visitor);
  }

  CGAL::Polyhedral_geodesics_3::Geodesic_statistics statistics() const override { return g_.statistics(); }

private:
  // Classes with a parallel single-source schedule (set_concurrency(), the exact class) get the thread count.
  template <class G>
  static auto set_threads_of(G& g, std::size_t threads, int)
    -> decltype(g.set_concurrency(CGAL::Parallel_if_available_tag(), threads), void())
  {
    if(threads == 1) g.set_concurrency(CGAL::Sequential_tag());
    else g.set_concurrency(CGAL::Parallel_if_available_tag(), threads);
  }
  template <class G>
  static void set_threads_of(G&, std::size_t, long) {}

  // Collects the path as the library reports it.
  struct Visitor
  {
    std::vector<Raw_path_node>* out;
    void operator()(Geo_mesh::Vertex_index v) { out->push_back({Raw_path_node::VERTEX, std::size_t(v), 0.0, {{0, 0, 0}}}); }
    void operator()(Geo_mesh::Halfedge_index h, double t) { out->push_back({Raw_path_node::EDGE, std::size_t(h), t, {{0, 0, 0}}}); }
    void operator()(Geo_mesh::Face_index face, const std::array<double, 3>& bary)
    {
      out->push_back({Raw_path_node::FACE, std::size_t(face), 0.0, bary});
    }
  };

  static Geo_mesh::Vertex_index vertex(std::size_t v) { return Geo_mesh::Vertex_index(static_cast<Geo_mesh::size_type>(v)); }
  static Face_location location(std::size_t f, const std::array<double, 3>& b)
  {
    return Face_location(Geo_mesh::Face_index(static_cast<Geo_mesh::size_type>(f)), b);
  }

  const Geo_mesh& mesh_;
  Geodesics g_;
  std::size_t threads_ = 1;
};

} // namespace mdcs_python

#endif // MDCS_PYTHON_GEODESIC_SOLVER_IMPL_H
