// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The prepared surface of mdcs.geodesics.Mesh (see geodesic_surface.h).

#include "geodesic_surface.h"

#include <CGAL/MDCS/concurrency.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mdcs_python {

Geodesic_method parse_geodesic_method(const std::string& name)
{
  if(name == "exact") return Geodesic_method::exact;
  if(name == "merged") return Geodesic_method::merged;
  if(name == "flat_exact" || name == "flat-exact") return Geodesic_method::flat_exact;
  if(name == "fast_marching" || name == "fmm") return Geodesic_method::fast_marching;
  if(name == "dijkstra") return Geodesic_method::dijkstra;
  throw Value_error("mdcs: unknown geodesic method '" + name +
                    "'; use 'exact', 'merged', 'flat_exact', 'fast_marching' or 'dijkstra'");
}

const char* method_name(Geodesic_method method)
{
  switch(method) {
  case Geodesic_method::exact: return "exact";
  case Geodesic_method::merged: return "merged";
  case Geodesic_method::flat_exact: return "flat_exact";
  case Geodesic_method::fast_marching: return "fast_marching";
  case Geodesic_method::dijkstra: return "dijkstra";
  }
  return "exact";
}

namespace {

// Records which point each duplicated point copies (orient_polygon_soup appends copies at the end).
struct Duplicate_recorder : CGAL::Polygon_mesh_processing::Default_orientation_visitor
{
  std::vector<std::pair<std::size_t, std::size_t>>* copies = nullptr; // (original, copy)
  void duplicated_vertex(std::size_t original, std::size_t copy) { copies->push_back({original, copy}); }
};

} // namespace

std::vector<std::pair<std::size_t, std::size_t>> mesh_from_arrays(const double* V, std::size_t n,
                                                                  const std::int64_t* F, std::size_t m,
                                                                  Geo_mesh& mesh, bool& oriented)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<Geo_point> points;
  points.reserve(n);
  for(std::size_t i = 0; i < n; ++i) points.emplace_back(V[3 * i], V[3 * i + 1], V[3 * i + 2]);
  std::vector<std::array<std::size_t, 3>> polygons(m);
  for(std::size_t f = 0; f < m; ++f)
    for(int k = 0; k < 3; ++k) polygons[f][std::size_t(k)] = std::size_t(F[3 * f + std::size_t(k)]);
  std::vector<std::pair<std::size_t, std::size_t>> copies;
  oriented = !PMP::is_polygon_soup_a_polygon_mesh(polygons);
  if(oriented) {
    Duplicate_recorder recorder;
    recorder.copies = &copies;
    PMP::orient_polygon_soup(points, polygons, CGAL::parameters::visitor(recorder));
    if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
      throw Value_error("mdcs: the faces cannot be made into a surface mesh, even after orienting them and splitting "
                        "non-manifold vertices");
  }
  mesh.reserve(Geo_mesh::size_type(points.size()), Geo_mesh::size_type(3 * m / 2 + 3),
               Geo_mesh::size_type(m));
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if(mesh.number_of_vertices() != points.size() || mesh.number_of_faces() != m)
    throw std::logic_error("mdcs: internal error: the surface mesh does not have one vertex per point and one face "
                           "per triangle");
  return copies;
}

std::pair<Double_array, Index_array> checked_mesh_arrays(py::handle vertices, py::handle faces)
{
  Double_array V = checked_doubles(vertices, "vertices", 2, 3, true, "(n, 3)");
  const std::int64_t n = std::int64_t(V.shape(0));
  Index_array F = checked_indices(faces, "faces", 2, 3, n, "(m, 3)", "vertices");
  if(F.shape(0) == 0) throw Value_error("mdcs: faces is empty: a surface needs at least one triangle");
  const std::int64_t* f = F.data();
  for(py::ssize_t i = 0; i < F.shape(0); ++i)
    if(f[3 * i] == f[3 * i + 1] || f[3 * i + 1] == f[3 * i + 2] || f[3 * i] == f[3 * i + 2])
      throw Value_error("mdcs: faces[" + std::to_string(i) + "] = (" + std::to_string(f[3 * i]) + ", " +
                        std::to_string(f[3 * i + 1]) + ", " + std::to_string(f[3 * i + 2]) +
                        ") repeats a vertex: every face needs three distinct corners");
  return {V, F};
}

Geodesic_surface::Geodesic_surface(const double* vertices, std::size_t n, const std::int64_t* faces, std::size_t m)
  : n_(n), m_(m)
{
  if(n >= std::size_t(std::numeric_limits<std::int32_t>::max()) / 2 ||
     m >= std::size_t(std::numeric_limits<std::int32_t>::max()) / 8)
    throw Value_error("mdcs: the mesh is too large for the geodesic classes (32-bit halfedge indices)");
  const auto copies = mesh_from_arrays(vertices, n, faces, m, mesh_, oriented_);
  const std::size_t nv = mesh_.number_of_vertices();

  user_of_mesh_vertex_.resize(nv);
  for(std::size_t v = 0; v < n; ++v) user_of_mesh_vertex_[v] = std::uint32_t(v);
  // A copy of a copy refers to its first original.
  for(const auto& c : copies) user_of_mesh_vertex_[c.second] = user_of_mesh_vertex_[c.first];
  extra_copies_begin_.assign(n + 1, 0);
  for(std::size_t v = n; v < nv; ++v) ++extra_copies_begin_[user_of_mesh_vertex_[v] + 1];
  for(std::size_t u = 0; u < n; ++u) extra_copies_begin_[u + 1] += extra_copies_begin_[u];
  extra_copies_.resize(nv - n);
  {
    std::vector<std::uint32_t> fill(extra_copies_begin_.begin(), extra_copies_begin_.end() - 1);
    for(std::size_t v = n; v < nv; ++v) extra_copies_[fill[user_of_mesh_vertex_[v]]++] = std::uint32_t(v);
  }
  std::vector<char> split(n, 0);
  for(std::size_t v = n; v < nv; ++v) split[user_of_mesh_vertex_[v]] = 1;
  split_vertices_ = std::size_t(std::count(split.begin(), split.end(), 1));

  isolated_flag_.assign(n, 1);
  for(std::size_t i = 0; i < 3 * m; ++i) isolated_flag_[std::size_t(faces[i])] = 0;
  isolated_ = std::size_t(std::count(isolated_flag_.begin(), isolated_flag_.end(), 1));

  // Corner correspondence: the facade's barycentric order is source(h), target(h), target(next(h)), h = halfedge(f).
  corner_of_.resize(m);
  for(std::size_t f = 0; f < m; ++f) {
    const Geo_mesh::Face_index fi(static_cast<Geo_mesh::size_type>(f));
    const Geo_mesh::Halfedge_index h = mesh_.halfedge(fi);
    const std::size_t mesh_corner[3] = {user_of_mesh_vertex_[std::size_t(mesh_.source(h))],
                                        user_of_mesh_vertex_[std::size_t(mesh_.target(h))],
                                        user_of_mesh_vertex_[std::size_t(mesh_.target(mesh_.next(h)))]};
    for(int k = 0; k < 3; ++k) {
      const std::size_t u = std::size_t(faces[3 * f + std::size_t(k)]);
      int position = -1;
      for(int p = 0; p < 3; ++p)
        if(mesh_corner[p] == u) position = p;
      if(position < 0) throw std::logic_error("mdcs: internal error: a face lost a corner in the surface mesh");
      corner_of_[f][std::size_t(k)] = std::int8_t(position);
    }
  }

  double total = 0;
  for(auto e : mesh_.edges()) {
    const Geo_point& a = mesh_.point(mesh_.source(mesh_.halfedge(e)));
    const Geo_point& b = mesh_.point(mesh_.target(mesh_.halfedge(e)));
    total += std::sqrt(CGAL::squared_distance(a, b));
  }
  mean_edge_length_ = mesh_.number_of_edges() == 0 ? 0.0 : total / double(mesh_.number_of_edges());
}

std::vector<std::size_t> Geodesic_surface::mesh_vertices(std::size_t u) const
{
  std::vector<std::size_t> r{u};
  for(std::uint32_t i = extra_copies_begin_[u]; i < extra_copies_begin_[u + 1]; ++i) r.push_back(extra_copies_[i]);
  return r;
}

std::array<double, 3> Geodesic_surface::to_mesh_barycentric(std::size_t f, const std::array<double, 3>& b) const
{
  std::array<double, 3> r{{0, 0, 0}};
  for(int k = 0; k < 3; ++k) r[std::size_t(corner_of_[f][std::size_t(k)])] = b[std::size_t(k)];
  return r;
}

std::array<double, 3> Geodesic_surface::to_user_barycentric(std::size_t f, const std::array<double, 3>& b) const
{
  std::array<double, 3> r{{0, 0, 0}};
  for(int k = 0; k < 3; ++k) r[std::size_t(k)] = b[std::size_t(corner_of_[f][std::size_t(k)])];
  return r;
}

Mesh_source Geodesic_surface::vertex_source(std::size_t u) const
{
  Mesh_source s;
  s.at_vertex = true;
  s.vertices = mesh_vertices(u);
  return s;
}

Mesh_source Geodesic_surface::point_source(std::size_t f, const std::array<double, 3>& user_barycentric) const
{
  Mesh_source s;
  s.at_vertex = false;
  s.face = f;
  s.barycentric = to_mesh_barycentric(f, user_barycentric);
  return s;
}

void Geodesic_surface::add_source(Geodesic_solver& solver, const Mesh_source& s) const
{
  if(s.at_vertex) {
    for(std::size_t v : s.vertices) solver.add_vertex_source(v);
  } else {
    solver.add_point_source(s.face, s.barycentric);
  }
}

void Geodesic_surface::user_results(const std::vector<double>& mesh_distances,
                                    const std::vector<std::int64_t>* mesh_nearest,
                                    const std::vector<std::int64_t>& source_of, double* distances,
                                    std::int64_t* nearest) const
{
  auto caller_source = [&](std::int64_t s) { return s < 0 ? std::int64_t(-1) : source_of[std::size_t(s)]; };
  for(std::size_t u = 0; u < n_; ++u) {
    double d = mesh_distances[u];
    std::int64_t s = mesh_nearest ? caller_source((*mesh_nearest)[u]) : -1;
    for(std::uint32_t i = extra_copies_begin_[u]; i < extra_copies_begin_[u + 1]; ++i) {
      const std::size_t c = extra_copies_[i];
      if(mesh_distances[c] < d) {
        d = mesh_distances[c];
        if(mesh_nearest) s = caller_source((*mesh_nearest)[c]);
      }
    }
    distances[u] = d;
    if(nearest) nearest[u] = std::isinf(d) ? -1 : s;
  }
}

void Geodesic_surface::convert_path(const std::vector<Raw_path_node>& raw, Path& out) const
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  out = Path();
  for(const Raw_path_node& node : raw) {
    std::array<double, 3> p{{0, 0, 0}};
    std::int64_t vertex = -1, e0 = -1, e1 = -1, face = -1;
    double t = nan;
    std::array<double, 3> b{{nan, nan, nan}};
    switch(node.kind) {
    case Raw_path_node::VERTEX: {
      const Geo_mesh::Vertex_index v(static_cast<Geo_mesh::size_type>(node.index));
      const Geo_point& q = mesh_.point(v);
      p = {{q.x(), q.y(), q.z()}};
      vertex = std::int64_t(user_of_mesh_vertex_[node.index]);
      break;
    }
    case Raw_path_node::EDGE: {
      const Geo_mesh::Halfedge_index h(static_cast<Geo_mesh::size_type>(node.index));
      const Geo_point& a = mesh_.point(mesh_.source(h));
      const Geo_point& c = mesh_.point(mesh_.target(h));
      t = node.t;
      p = {{(1 - t) * a.x() + t * c.x(), (1 - t) * a.y() + t * c.y(), (1 - t) * a.z() + t * c.z()}};
      e0 = std::int64_t(user_of_mesh_vertex_[std::size_t(mesh_.source(h))]);
      e1 = std::int64_t(user_of_mesh_vertex_[std::size_t(mesh_.target(h))]);
      break;
    }
    default: {
      const Geo_mesh::Face_index f(static_cast<Geo_mesh::size_type>(node.index));
      const Geo_mesh::Halfedge_index h = mesh_.halfedge(f);
      const Geo_point* q[3] = {&mesh_.point(mesh_.source(h)), &mesh_.point(mesh_.target(h)),
                               &mesh_.point(mesh_.target(mesh_.next(h)))};
      for(int k = 0; k < 3; ++k) {
        p[0] += node.barycentric[std::size_t(k)] * q[k]->x();
        p[1] += node.barycentric[std::size_t(k)] * q[k]->y();
        p[2] += node.barycentric[std::size_t(k)] * q[k]->z();
      }
      face = std::int64_t(node.index);
      b = to_user_barycentric(node.index, node.barycentric);
      break;
    }
    }
    out.points.insert(out.points.end(), p.begin(), p.end());
    out.kinds.push_back(std::uint8_t(node.kind));
    out.vertex.push_back(vertex);
    out.edge.push_back(e0);
    out.edge.push_back(e1);
    out.t.push_back(t);
    out.face.push_back(face);
    out.barycentric.insert(out.barycentric.end(), b.begin(), b.end());
  }
}

std::unique_ptr<Geodesic_solver> Geodesic_surface::make_solver(const Solver_kind& kind) const
{
  switch(kind.method) {
  case Geodesic_method::exact: return make_window_solver(mesh_, false, 0.0, kind.full_field);
  case Geodesic_method::merged: return make_window_solver(mesh_, true, kind.tolerance, kind.full_field);
  default: return make_approximate_solver(mesh_, kind.method, kind.full_field);
  }
}

std::unique_ptr<Geodesic_solver> Geodesic_surface::acquire(const Solver_kind& kind) const
{
  {
    std::lock_guard<std::mutex> lock(pool_mutex_);
    for(auto it = pool_.begin(); it != pool_.end(); ++it)
      if(it->first == kind) {
        std::unique_ptr<Geodesic_solver> s = std::move(it->second);
        pool_.erase(it);
        return s;
      }
  }
  return make_solver(kind);
}

void Geodesic_surface::release(const Solver_kind& kind, std::unique_ptr<Geodesic_solver> solver) const
{
  // Solvers of the full field keep every window until their next run: they are not pooled.
  if(!solver || kind.full_field) return;
  solver->clear_sources();
  std::lock_guard<std::mutex> lock(pool_mutex_);
  if(pool_.size() < 2 * CGAL::MDCS::hardware_threads() + 2) pool_.emplace_back(kind, std::move(solver));
}

} // namespace mdcs_python
