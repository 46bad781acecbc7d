// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bindings of Polyhedral_geodesics_3: the prepared surface (mdcs._mdcs.geodesics.Surface), distances from vertex and
// surface-point sources with every method, fields kept for point queries and shortest paths, and distance matrices
// computed in parallel (one solver per thread, rows in a fixed order). The pure-Python layer (mdcs/geodesics.py)
// gives these their documented signatures.

#include "geodesic_surface.h"

#include <CGAL/MDCS/concurrency.h>

#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <limits>
#include <memory>
#include <mutex>
#include <sstream>

namespace mdcs_python {
namespace {

const double infinity = std::numeric_limits<double>::infinity();

// The sources of a call, in the caller's order: vertex sources first, then surface points.
struct Source_set
{
  std::vector<Mesh_source> sources;
  std::vector<std::int64_t> caller_vertex; // -1 for surface points
};

std::array<double, 3> checked_barycentric(const double* b, std::size_t i, const char* name)
{
  const double sum = b[0] + b[1] + b[2];
  if(!(b[0] >= -1e-9 && b[1] >= -1e-9 && b[2] >= -1e-9) || !(std::abs(sum - 1.0) <= 1e-6)) {
    std::ostringstream s;
    s.precision(17);
    s << "mdcs: " << name << '[' << i << "] = (" << b[0] << ", " << b[1] << ", " << b[2]
      << ") are not barycentric coordinates of a point of the face: they must be >= 0 and sum to 1";
    throw Value_error(s.str());
  }
  std::array<double, 3> r{{std::max(0.0, b[0]), std::max(0.0, b[1]), std::max(0.0, b[2])}};
  const double total = r[0] + r[1] + r[2];
  for(double& x : r) x /= total;
  return r;
}

// Surface points given as face indices and barycentric coordinates (in the order of the face's corners).
void read_points(const Geodesic_surface& s, py::handle faces, py::handle barycentric, const char* faces_name,
                 const char* barycentric_name, std::vector<std::size_t>& f_out,
                 std::vector<std::array<double, 3>>& b_out)
{
  if(faces.is_none() && barycentric.is_none()) return;
  if(faces.is_none() || barycentric.is_none())
    throw Value_error(std::string("mdcs: ") + faces_name + " and " + barycentric_name + " go together (one is None)");
  const Index_array f = checked_indices(faces, faces_name, 1, -1, std::int64_t(s.number_of_faces()), "(k,)", "faces");
  const Double_array b = checked_doubles(barycentric, barycentric_name, 2, 3, true, "(k, 3)");
  if(b.shape(0) != f.shape(0))
    throw Value_error(std::string("mdcs: ") + faces_name + " has " + std::to_string(f.shape(0)) + " entries but " +
                      barycentric_name + " has " + std::to_string(b.shape(0)) + " rows");
  for(py::ssize_t i = 0; i < f.shape(0); ++i) {
    f_out.push_back(std::size_t(f.data()[i]));
    b_out.push_back(checked_barycentric(b.data() + 3 * i, std::size_t(i), barycentric_name));
  }
}

Source_set read_sources(const Geodesic_surface& s, py::handle vertex_sources, py::handle point_faces,
                        py::handle point_barycentric)
{
  Source_set set;
  if(!vertex_sources.is_none())
    for(std::int64_t u : checked_index_list(vertex_sources, "sources", std::int64_t(s.number_of_vertices()), "vertices")) {
      set.sources.push_back(s.vertex_source(std::size_t(u)));
      set.caller_vertex.push_back(u);
    }
  std::vector<std::size_t> faces;
  std::vector<std::array<double, 3>> bary;
  read_points(s, point_faces, point_barycentric, "source_faces", "source_barycentric", faces, bary);
  for(std::size_t i = 0; i < faces.size(); ++i) {
    set.sources.push_back(s.point_source(faces[i], bary[i]));
    set.caller_vertex.push_back(-1);
  }
  if(set.sources.empty()) throw Value_error("mdcs: no source was given");
  return set;
}

// Sources added to a solver: the caller's index of each solver source, and the sources at isolated vertices (which
// the solver cannot take: their distance is 0 at themselves and +infinity elsewhere).
struct Applied_sources
{
  std::vector<std::int64_t> source_of;
  std::vector<std::size_t> isolated; // indices into Source_set
  bool any_in_mesh() const { return !source_of.empty(); }
};

Applied_sources apply_sources(const Geodesic_surface& s, Geodesic_solver* solver, const Source_set& set,
                              std::size_t first, std::size_t last)
{
  Applied_sources a;
  if(solver) solver->clear_sources();
  for(std::size_t i = first; i < last; ++i) {
    const Mesh_source& src = set.sources[i];
    if(src.at_vertex && s.is_isolated(std::size_t(set.caller_vertex[i]))) {
      a.isolated.push_back(i);
      continue;
    }
    if(!solver) continue;
    s.add_source(*solver, src);
    const std::size_t added = src.at_vertex ? src.vertices.size() : 1;
    for(std::size_t k = 0; k < added; ++k) a.source_of.push_back(std::int64_t(i));
  }
  return a;
}

// Caller-level distances (and nearest sources) of every vertex after the solver ran (solver == nullptr: no source in
// the mesh).
void caller_results(const Geodesic_surface& s, Geodesic_solver* solver, const Applied_sources& a, const Source_set& set,
                    std::vector<double>& mesh_d, std::vector<std::int64_t>* mesh_s, double* d, std::int64_t* nearest)
{
  const std::size_t n = s.number_of_vertices();
  if(solver && a.any_in_mesh()) {
    solver->vertex_results(mesh_d, mesh_s);
    s.user_results(mesh_d, mesh_s, a.source_of, d, nearest);
  } else {
    std::fill(d, d + n, infinity);
    if(nearest) std::fill(nearest, nearest + n, std::int64_t(-1));
  }
  for(std::size_t i : a.isolated) {
    const std::size_t u = std::size_t(set.caller_vertex[i]);
    if(d[u] > 0) {
      d[u] = 0;
      if(nearest) nearest[u] = std::int64_t(i);
    }
  }
}

Solver_kind solver_kind(const std::string& method, double tolerance, bool full_field)
{
  Solver_kind k;
  k.method = parse_geodesic_method(method);
  if(k.method == Geodesic_method::merged) {
    if(!(tolerance >= 0) || !std::isfinite(tolerance))
      throw Value_error("mdcs: the merge tolerance must be a finite number >= 0");
    k.tolerance = tolerance;
  } else if(tolerance != 0) {
    throw Value_error(std::string("mdcs: a merge tolerance was given for method '") + method +
                      "'; it applies to method='merged' only");
  }
  k.full_field = full_field;
  return k;
}

// A solver owned by one thread of a parallel loop (a plain pointer: the per-thread storage copies its elements).
struct Thread_solver
{
  Geodesic_solver* solver = nullptr;
};

// Returns a solver to the pool when the scope ends (also on exceptions), sequential again: a row of a distance
// matrix must not start a parallel propagation inside the matrix's own parallel loop.
struct Pooled_solver
{
  const Geodesic_surface& surface;
  Solver_kind kind;
  std::unique_ptr<Geodesic_solver> solver;
  Pooled_solver(const Geodesic_surface& s, const Solver_kind& k) : surface(s), kind(k), solver(s.acquire(k)) {}
  ~Pooled_solver()
  {
    solver->set_threads(1);
    surface.release(kind, std::move(solver));
  }
};

py::dict statistics_dict(const CGAL::Polyhedral_geodesics_3::Geodesic_statistics& st)
{
  py::dict d;
  d["windows_created"] = st.windows_created;
  d["windows_propagated"] = st.windows_propagated;
  d["windows_pruned"] = st.windows_pruned;
  d["windows_merged"] = st.windows_merged;
  d["peak_live_windows"] = st.peak_live_windows;
  d["stored_windows"] = st.stored_windows;
  d["peak_memory_bytes"] = st.peak_memory_bytes;
  d["vertex_updates"] = st.vertex_updates;
  d["updates_rejected_by_dag"] = st.updates_rejected_by_dag;
  d["stopped_early"] = st.stopped_early;
  return d;
}

py::dict path_dict(Geodesic_surface::Path&& p)
{
  const py::ssize_t k = py::ssize_t(p.kinds.size());
  py::dict d;
  d["points"] = to_numpy(std::move(p.points), k, 3);
  d["kind"] = to_numpy(std::move(p.kinds));
  d["vertex"] = to_numpy(std::move(p.vertex));
  d["edge"] = to_numpy(std::move(p.edge), k, 2);
  d["t"] = to_numpy(std::move(p.t));
  d["face"] = to_numpy(std::move(p.face));
  d["barycentric"] = to_numpy(std::move(p.barycentric), k, 3);
  return d;
}

// ----------------------------------------------------------------------------------------------------------------

class Py_surface
{
public:
  Py_surface(py::handle vertices, py::handle faces)
  {
    const auto arrays = checked_mesh_arrays(vertices, faces);
    const Double_array& V = arrays.first;
    const Index_array& F = arrays.second;
    const std::size_t n = std::size_t(V.shape(0));
    const std::int64_t* f = F.data();
    const double* v = V.data();
    const std::size_t m = std::size_t(F.shape(0));
    py::gil_scoped_release release;
    surface_ = std::make_shared<const Geodesic_surface>(v, n, f, m);
    // Twice the sum of the triangles' perimeters: no geodesic distance from a vertex or a surface point to a
    // reachable vertex is longer (an edge path is at most the sum of the edges, plus one edge from a point inside
    // a triangle). A max_distance at least this large cannot prune anything; it is dropped, because a distance
    // limit makes the exact class use its window engine, 3-4x slower than its vertex engine on a whole mesh
    // (gdist.local_gdist_matrix's default max_distance is 1e100).
    double perimeters = 0;
    for(std::size_t t = 0; t < m; ++t)
      for(int k = 0; k < 3; ++k) {
        const double* a = v + 3 * f[3 * t + k];
        const double* b = v + 3 * f[3 * t + (k + 1) % 3];
        perimeters += std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                                (a[2] - b[2]) * (a[2] - b[2]));
      }
    pruning_bound_ = 2 * perimeters;
  }

  const Geodesic_surface& surface() const { return *surface_; }
  std::shared_ptr<const Geodesic_surface> shared() const { return surface_; }

  // Distances of every vertex (or of `targets`) to the nearest source.
  py::tuple distances(py::handle sources, py::handle source_faces, py::handle source_barycentric, const std::string& method,
                      double tolerance, py::handle max_distance, py::handle targets, bool stop_at_targets,
                      bool want_nearest, py::handle threads_object, py::object progress)
  {
    const Geodesic_surface& s = *surface_;
    const std::size_t threads = checked_thread_count(threads_object);
    const Source_set set = read_sources(s, sources, source_faces, source_barycentric);
    const double limit = pruning_limit(number_or(max_distance, "max_distance", infinity, 0, false));
    std::vector<std::int64_t> target_list;
    const bool has_targets = !targets.is_none();
    if(has_targets) target_list = checked_index_list(targets, "targets", std::int64_t(s.number_of_vertices()), "vertices");
    if(stop_at_targets && !has_targets) throw Value_error("mdcs: stop_at_targets needs targets");
    const Solver_kind kind = solver_kind(method, tolerance, false);
    Progress_bridge bridge(progress);
    const std::size_t n = s.number_of_vertices();
    std::vector<double> d(n);
    std::vector<std::int64_t> nearest(want_nearest ? n : 0);
    run_without_gil(bridge, [&] {
      Pooled_solver pooled(s, kind);
      Geodesic_solver& solver = *pooled.solver;
      const Applied_sources applied = apply_sources(s, &solver, set, 0, set.sources.size());
      if(applied.any_in_mesh()) {
        solver.set_distance_limit(limit);
        std::vector<std::size_t> stop;
        if(stop_at_targets)
          for(std::int64_t u : target_list)
            for(std::size_t c : s.mesh_vertices(std::size_t(u))) stop.push_back(c);
        solver.set_stop_targets(stop);
        solver.set_threads(threads);
        solver.compute(bridge);
      }
      std::vector<double> mesh_d;
      std::vector<std::int64_t> mesh_s;
      caller_results(s, &solver, applied, set, mesh_d, want_nearest ? &mesh_s : nullptr, d.data(),
                     want_nearest ? nearest.data() : nullptr);
      solver.set_stop_targets({});
      return 0;
    });
    if(has_targets) {
      std::vector<double> dt(target_list.size());
      std::vector<std::int64_t> st(want_nearest ? target_list.size() : 0);
      for(std::size_t i = 0; i < target_list.size(); ++i) {
        dt[i] = d[std::size_t(target_list[i])];
        if(want_nearest) st[i] = nearest[std::size_t(target_list[i])];
      }
      d.swap(dt);
      nearest.swap(st);
    }
    py::object nearest_out = want_nearest ? py::object(to_numpy(std::move(nearest))) : py::object(py::none());
    return py::make_tuple(to_numpy(std::move(d)), nearest_out);
  }

  // Distances from each source to every vertex (or to `targets`): dense rows, or the entries <= max_distance.
  py::object distance_matrix(py::handle sources, py::handle source_faces, py::handle source_barycentric,
                             py::handle targets, const std::string& method, double tolerance, py::handle max_distance,
                             bool sparse, py::handle threads_object, py::object progress)
  {
    const std::size_t threads = checked_thread_count(threads_object);
    const Geodesic_surface& s = *surface_;
    const Source_set set = read_sources(s, sources, source_faces, source_barycentric);
    const double limit = pruning_limit(number_or(max_distance, "max_distance", infinity, 0, false));
    std::vector<std::int64_t> target_list;
    const bool has_targets = !targets.is_none();
    if(has_targets) target_list = checked_index_list(targets, "targets", std::int64_t(s.number_of_vertices()), "vertices");
    const Solver_kind kind = solver_kind(method, tolerance, false);
    const std::size_t rows = set.sources.size(), n = s.number_of_vertices();
    const std::size_t columns = has_targets ? target_list.size() : n;
    if(!sparse && columns > 0 && rows > std::size_t(PTRDIFF_MAX / 8) / columns)
      throw Value_error("mdcs: the dense distance matrix would be too large");
    Progress_bridge bridge(progress);

    std::vector<double> dense(sparse ? 0 : rows * columns);
    std::vector<std::vector<std::pair<std::uint32_t, double>>> entries(sparse ? rows : 0);
    const std::size_t used_threads = CGAL::MDCS::effective_threads(threads, true);
    run_without_gil(bridge, [&] {
      // One solver per thread, taken from the surface's pool and given back when the loop ends (also on errors).
      CGAL::MDCS::Per_thread<Thread_solver> solvers([&] { return Thread_solver{s.acquire(kind).release()}; });
      struct Give_back
      {
        const Geodesic_surface& s;
        const Solver_kind& kind;
        CGAL::MDCS::Per_thread<Thread_solver>& solvers;
        ~Give_back()
        {
          solvers.for_each([&](Thread_solver& t) {
            s.release(kind, std::unique_ptr<Geodesic_solver>(t.solver));
            t.solver = nullptr;
          });
        }
      } give_back{s, kind, solvers};
      CGAL::MDCS::Parallel_progress<Progress_bridge> report(bridge, "distance matrix", rows);
      CGAL::MDCS::parallel_for_each_index(rows, used_threads, [&](std::size_t i) {
        if(report.cancelled()) return;
        Geodesic_solver& solver = *solvers.local().solver;
        const Applied_sources applied = apply_sources(s, &solver, set, i, i + 1);
        if(applied.any_in_mesh()) {
          solver.set_distance_limit(limit);
          solver.compute_quietly();
        }
        std::vector<double> row(n), mesh_d;
        caller_results(s, &solver, applied, set, mesh_d, nullptr, row.data(), nullptr);
        if(sparse) {
          auto& e = entries[i];
          for(std::size_t c = 0; c < columns; ++c) {
            const double x = row[has_targets ? std::size_t(target_list[c]) : c];
            if(x <= limit) e.emplace_back(std::uint32_t(c), x);
          }
        } else {
          double* out = dense.data() + i * columns;
          for(std::size_t c = 0; c < columns; ++c) out[c] = row[has_targets ? std::size_t(target_list[c]) : c];
        }
        report.advance();
      });
      report.finish();
      return 0;
    });
    if(!sparse) return to_numpy(std::move(dense), py::ssize_t(rows), py::ssize_t(columns));
    std::vector<std::int64_t> indptr(rows + 1, 0), indices;
    std::vector<double> data;
    for(std::size_t i = 0; i < rows; ++i) indptr[i + 1] = indptr[i] + std::int64_t(entries[i].size());
    indices.reserve(std::size_t(indptr[rows]));
    data.reserve(std::size_t(indptr[rows]));
    for(auto& e : entries)
      for(const auto& x : e) {
        indices.push_back(std::int64_t(x.first));
        data.push_back(x.second);
      }
    return py::make_tuple(to_numpy(std::move(indptr)), to_numpy(std::move(indices)), to_numpy(std::move(data)),
                          py::make_tuple(rows, columns));
  }

  // The benchmark's anchor: the same computation as distances(source) for a vertex source, timed inside C++ (one
  // pooled solver, sources set, propagation, the distance of every vertex copied out), `repeats` times. Returns
  // (wall-clock seconds, CPU seconds of the calling thread) per repeat; with `with_progress` the propagation reports
  // to a progress bridge without a callback, as distances() does.
  std::vector<std::pair<double, double>> cpp_distances_seconds(std::int64_t source, const std::string& method,
                                                               std::size_t repeats, bool with_progress)
  {
    const Geodesic_surface& s = *surface_;
    const std::int64_t v = checked_index(py::int_(source), "source", std::int64_t(s.number_of_vertices()), "vertices");
    const Solver_kind kind = solver_kind(method, 0.0, false);
    std::vector<std::pair<double, double>> seconds;
    Progress_bridge bridge{py::none()};
    py::gil_scoped_release release;
    Pooled_solver pooled(s, kind);
    std::vector<double> d(s.number_of_vertices()), mesh_d;
    auto cpu = [] {
      timespec t;
      clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
      return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
    };
    for(std::size_t r = 0; r < repeats; ++r) {
      const auto start = std::chrono::steady_clock::now();
      const double cpu_start = cpu();
      pooled.solver->clear_sources();
      s.add_source(*pooled.solver, s.vertex_source(std::size_t(v)));
      pooled.solver->set_distance_limit(infinity);
      if(with_progress) pooled.solver->compute(bridge);
      else pooled.solver->compute_quietly();
      pooled.solver->vertex_results(mesh_d, nullptr);
      s.user_results(mesh_d, nullptr, {0}, d.data(), nullptr);
      seconds.emplace_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                           cpu() - cpu_start);
    }
    return seconds;
  }

  // The distance limit to give a solver: infinity when `limit` cannot prune anything (see the constructor).
  double pruning_limit(double limit) const { return limit >= pruning_bound_ ? infinity : limit; }

  // The surface points closest to 3D points (k x 3): (faces, barycentric) in the caller's indices and corner order.
  py::tuple locate(py::handle points_object)
  {
    const Double_array points = checked_doubles(points_object, "points", 2, 3, true, "(k, 3)");
    const std::size_t k = std::size_t(points.shape(0));
    std::vector<std::int64_t> faces(k);
    std::vector<double> barycentric(3 * k);
    const double* p = points.data();
    {
      py::gil_scoped_release release;
      mdcs_python::locate_points(*surface_, locator(), p, k, faces.data(), barycentric.data());
    }
    return py::make_tuple(to_numpy(std::move(faces)), to_numpy(std::move(barycentric), py::ssize_t(k), 3));
  }

  // The first surface point of each ray: face -1 and NaN where a ray misses.
  py::tuple locate_rays(py::handle origins_object, py::handle directions_object)
  {
    const Double_array origins = checked_doubles(origins_object, "origins", 2, 3, true, "(k, 3)");
    const Double_array directions = checked_doubles(directions_object, "directions", 2, 3, true, "(k, 3)");
    if(origins.shape(0) != directions.shape(0))
      throw Value_error("mdcs: origins and directions must have the same number of rows, got " +
                        shape_text(origins) + " and " + shape_text(directions));
    const std::size_t k = std::size_t(origins.shape(0));
    const double* d = directions.data();
    for(std::size_t i = 0; i < k; ++i)
      if(d[3 * i] == 0 && d[3 * i + 1] == 0 && d[3 * i + 2] == 0)
        throw Value_error("mdcs: directions[" + std::to_string(i) + "] is the zero vector");
    std::vector<std::int64_t> faces(k);
    std::vector<double> barycentric(3 * k);
    const double* o = origins.data();
    {
      py::gil_scoped_release release;
      mdcs_python::locate_rays(*surface_, locator(), o, d, k, faces.data(), barycentric.data());
    }
    return py::make_tuple(to_numpy(std::move(faces)), to_numpy(std::move(barycentric), py::ssize_t(k), 3));
  }

  // The AABB tree of locate(), built at the first call (then shared by every thread).
  const Point_locator& locator()
  {
    std::call_once(locator_once_, [this] { locator_ = make_point_locator(*surface_); });
    return *locator_;
  }

  std::shared_ptr<const Geodesic_surface> surface_;
  double pruning_bound_ = infinity;
  std::once_flag locator_once_;
  std::shared_ptr<const Point_locator> locator_;
};

// Iso-distance curves of vertex distances on the caller's arrays: a list of (level, closed, points (k, 3)).
py::list iso_distance_curves(py::handle vertices, py::handle faces, py::handle distances_object, py::handle levels_object)
{
  const auto arrays = checked_mesh_arrays(vertices, faces);
  const std::size_t n = std::size_t(arrays.first.shape(0)), m = std::size_t(arrays.second.shape(0));
  const Double_array distances = checked_doubles(distances_object, "distances", 1, -1, false, "(n,)");
  if(std::size_t(distances.shape(0)) != n)
    throw Value_error("mdcs: distances must have one value per vertex (" + std::to_string(n) + "), got " +
                      shape_text(distances));
  const double* d = distances.data();
  for(std::size_t i = 0; i < n; ++i)
    if(std::isnan(d[i]) || d[i] == -infinity)
      throw Value_error("mdcs: distances[" + std::to_string(i) + "] is not a number or +inf (unreachable)");
  const Double_array levels_array = checked_doubles(levels_object, "levels", 1, -1, true, "(k,)");
  const std::vector<double> levels(levels_array.data(), levels_array.data() + levels_array.shape(0));
  std::vector<Iso_curve> curves;
  {
    py::gil_scoped_release release;
    curves = iso_curves(arrays.first.data(), n, arrays.second.data(), m, d, levels);
  }
  py::list out;
  for(Iso_curve& c : curves) {
    const py::ssize_t k = py::ssize_t(c.points.size() / 3);
    out.append(py::make_tuple(c.level, c.closed, to_numpy(std::move(c.points), k, 3)));
  }
  return out;
}

// A computed distance field (full field): vertex distances, distances at surface points, shortest paths.
class Py_field
{
public:
  Py_field(const Py_surface& owner, py::handle sources, py::handle source_faces, py::handle source_barycentric,
           const std::string& method, double tolerance, py::handle max_distance, bool shorten_paths,
           py::object progress)
    : surface_(owner.shared())
  {
    const Geodesic_surface& s = *surface_;
    set_ = read_sources(s, sources, source_faces, source_barycentric);
    const double limit = owner.pruning_limit(number_or(max_distance, "max_distance", infinity, 0, false));
    kind_ = solver_kind(method, tolerance, true);
    Progress_bridge bridge(progress);
    const std::size_t n = s.number_of_vertices();
    std::vector<double> d(n);
    std::vector<std::int64_t> nearest(n);
    run_without_gil(bridge, [&] {
      solver_ = s.make_solver(kind_);
      applied_ = apply_sources(s, solver_.get(), set_, 0, set_.sources.size());
      solver_->set_path_shortening(shorten_paths);
      if(applied_.any_in_mesh()) {
        solver_->set_distance_limit(limit);
        solver_->compute(bridge);
      }
      caller_results(s, solver_.get(), applied_, set_, mesh_distances_, &mesh_nearest_, d.data(), nearest.data());
      return 0;
    });
    distances_ = to_numpy(std::move(d));
    nearest_ = to_numpy(std::move(nearest));
    distances_.attr("setflags")(py::arg("write") = false);
    nearest_.attr("setflags")(py::arg("write") = false);
  }

  py::array_t<double> distances() const { return distances_; }
  py::array_t<std::int64_t> nearest_sources() const { return nearest_; }
  std::size_t number_of_sources() const { return set_.sources.size(); }
  py::dict statistics() const { return statistics_dict(solver_->statistics()); }

  py::tuple point_distances(py::handle faces, py::handle barycentric)
  {
    const Geodesic_surface& s = *surface_;
    std::vector<std::size_t> f;
    std::vector<std::array<double, 3>> b;
    read_points(s, faces, barycentric, "faces", "barycentric", f, b);
    std::vector<double> d(f.size(), infinity);
    std::vector<std::int64_t> nearest(f.size(), -1);
    Progress_bridge bridge{py::none()};
    run_without_gil(bridge, [&] {
      std::lock_guard<std::mutex> lock(mutex_);
      if(!applied_.any_in_mesh()) return 0;
      for(std::size_t i = 0; i < f.size(); ++i) {
        const auto r = solver_->point_result(f[i], s.to_mesh_barycentric(f[i], b[i]));
        d[i] = r.first;
        nearest[i] = r.second < 0 ? -1 : applied_.source_of[std::size_t(r.second)];
      }
      return 0;
    });
    // A point at an isolated source vertex cannot be given as a face point (the vertex has no face).
    return py::make_tuple(to_numpy(std::move(d)), to_numpy(std::move(nearest)));
  }

  py::list paths(py::handle targets)
  {
    const Geodesic_surface& s = *surface_;
    const std::vector<std::int64_t> list = checked_index_list(targets, "target", std::int64_t(s.number_of_vertices()), "vertices");
    std::vector<Geodesic_surface::Path> out(list.size());
    Progress_bridge bridge{py::none()};
    run_without_gil(bridge, [&] {
      std::lock_guard<std::mutex> lock(mutex_);
      std::vector<Raw_path_node> raw;
      for(std::size_t i = 0; i < list.size(); ++i) {
        raw.clear();
        const std::size_t u = std::size_t(list[i]);
        if(s.is_isolated(u)) {
          // Only an isolated source reaches itself: a path of one point.
          for(std::size_t k : applied_.isolated)
            if(set_.caller_vertex[k] == std::int64_t(u)) {
              raw.push_back({Raw_path_node::VERTEX, u, 0.0, {{0, 0, 0}}});
              break;
            }
        } else if(applied_.any_in_mesh()) {
          std::size_t best = u;
          for(std::size_t c : s.mesh_vertices(u))
            if(mesh_distances_[c] < mesh_distances_[best]) best = c;
          if(mesh_distances_[best] < infinity) solver_->vertex_path(best, raw);
        }
        s.convert_path(raw, out[i]);
      }
      return 0;
    });
    py::list result;
    for(auto& p : out) result.append(path_dict(std::move(p)));
    return result;
  }

  py::list point_paths(py::handle faces, py::handle barycentric)
  {
    const Geodesic_surface& s = *surface_;
    std::vector<std::size_t> f;
    std::vector<std::array<double, 3>> b;
    read_points(s, faces, barycentric, "faces", "barycentric", f, b);
    std::vector<Geodesic_surface::Path> out(f.size());
    Progress_bridge bridge{py::none()};
    run_without_gil(bridge, [&] {
      std::lock_guard<std::mutex> lock(mutex_);
      std::vector<Raw_path_node> raw;
      for(std::size_t i = 0; i < f.size(); ++i) {
        raw.clear();
        if(applied_.any_in_mesh()) solver_->path(f[i], s.to_mesh_barycentric(f[i], b[i]), raw);
        s.convert_path(raw, out[i]);
      }
      return 0;
    });
    py::list result;
    for(auto& p : out) result.append(path_dict(std::move(p)));
    return result;
  }

private:
  std::shared_ptr<const Geodesic_surface> surface_;
  Source_set set_;
  Solver_kind kind_;
  std::unique_ptr<Geodesic_solver> solver_;
  Applied_sources applied_;
  std::vector<double> mesh_distances_;
  std::vector<std::int64_t> mesh_nearest_;
  py::array_t<double> distances_;
  py::array_t<std::int64_t> nearest_;
  std::mutex mutex_;
};

} // namespace

void bind_geodesics(py::module_& m)
{
  py::module_ g = m.def_submodule("geodesics", "C++ core of mdcs.geodesics (use mdcs.geodesics)");

  py::class_<Py_surface>(g, "Surface", "A triangle mesh prepared once for geodesic computations (see mdcs.geodesics.Mesh).")
    .def(py::init<py::handle, py::handle>(), py::arg("vertices"), py::arg("faces"))
    .def_property_readonly("number_of_vertices", [](const Py_surface& p) { return p.surface().number_of_vertices(); })
    .def_property_readonly("number_of_faces", [](const Py_surface& p) { return p.surface().number_of_faces(); })
    .def_property_readonly("was_oriented", [](const Py_surface& p) { return p.surface().was_oriented(); })
    .def_property_readonly("number_of_split_vertices", [](const Py_surface& p) { return p.surface().number_of_split_vertices(); })
    .def_property_readonly("number_of_isolated_vertices", [](const Py_surface& p) { return p.surface().number_of_isolated_vertices(); })
    .def_property_readonly("mean_edge_length", [](const Py_surface& p) { return p.surface().mean_edge_length(); })
    .def("distances", &Py_surface::distances, py::arg("sources"), py::arg("source_faces"),
         py::arg("source_barycentric"), py::arg("method"), py::arg("tolerance"), py::arg("max_distance"),
         py::arg("targets"), py::arg("stop_at_targets"), py::arg("nearest"), py::arg("threads"), py::arg("progress"))
    .def("distance_matrix", &Py_surface::distance_matrix, py::arg("sources"), py::arg("source_faces"),
         py::arg("source_barycentric"), py::arg("targets"), py::arg("method"), py::arg("tolerance"),
         py::arg("max_distance"), py::arg("sparse"), py::arg("threads"), py::arg("progress"))
    .def("locate", &Py_surface::locate, py::arg("points"))
    .def("locate_rays", &Py_surface::locate_rays, py::arg("origins"), py::arg("directions"))
    .def("_cpp_distances_seconds", &Py_surface::cpp_distances_seconds, py::arg("source"), py::arg("method"),
         py::arg("repeats"), py::arg("with_progress") = false,
         "Benchmark anchor: (wall, thread CPU) seconds of the same computation as distances(source), timed in C++.");

  g.def("iso_distance_curves", &iso_distance_curves, py::arg("vertices"), py::arg("faces"), py::arg("distances"),
        py::arg("levels"));

  py::class_<Py_field>(g, "Field", "A computed geodesic distance field (see mdcs.geodesics.GeodesicField).")
    .def(py::init<const Py_surface&, py::handle, py::handle, py::handle, const std::string&, double, py::handle, bool,
                  py::object>(),
         py::arg("surface"), py::arg("sources"), py::arg("source_faces"), py::arg("source_barycentric"),
         py::arg("method"), py::arg("tolerance"), py::arg("max_distance"), py::arg("shorten_paths"),
         py::arg("progress"), py::keep_alive<1, 2>())
    .def_property_readonly("distances", &Py_field::distances)
    .def_property_readonly("nearest_sources", &Py_field::nearest_sources)
    .def_property_readonly("number_of_sources", &Py_field::number_of_sources)
    .def("statistics", &Py_field::statistics)
    .def("point_distances", &Py_field::point_distances, py::arg("faces"), py::arg("barycentric"))
    .def("paths", &Py_field::paths, py::arg("targets"))
    .def("point_paths", &Py_field::point_paths, py::arg("faces"), py::arg("barycentric"));
}

} // namespace mdcs_python
