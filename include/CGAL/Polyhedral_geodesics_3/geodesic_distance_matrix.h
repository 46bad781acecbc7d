// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Geodesic distance matrices (issue 29 item 2): dense rows from given sources (to every vertex or to given targets),
// streamed so that the memory stays bounded for any number of sources, and the sparse local matrix of every pair
// within a distance, for any method of the package, with the sources on several threads. One compact mesh is built
// and shared read-only by every thread; each thread has its own engine.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_GEODESIC_DISTANCE_MATRIX_H
#define CGAL_POLYHEDRAL_GEODESICS_3_GEODESIC_DISTANCE_MATRIX_H

#include <CGAL/MDCS/concurrency.h>
#include <CGAL/MDCS/progress.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_surface_3.h>
#include <CGAL/Polyhedral_geodesics_3/internal/Geodesic_mesh.h>
#include <CGAL/Polyhedral_geodesics_3/internal/geodesic_matrix_engines.h>
#include <CGAL/Polyhedral_geodesics_3/internal/local_geodesic_submesh.h>
#include <CGAL/Polyhedral_geodesics_3/internal/vertex_oriented_propagation.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polyhedral_geodesics_3 {

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief The options of the distance-matrix functions.
*/
struct Geodesic_matrix_options
{
  /// The propagation (the method of one of the package's distance classes).
  Geodesic_method method = Geodesic_method::exact;
  /// `Geodesic_method::merged_windows` only: the absolute merge tolerance (>= 0).
  double merge_tolerance = 0;
  /// Distances beyond it are not computed: +infinity in dense rows, no entry in sparse ones. Each source then
  /// costs what its neighbourhood costs (see `local_geodesic_distance_rows()`). Required (finite) by the sparse
  /// functions; +infinity (the default) for full dense rows.
  double max_distance = std::numeric_limits<double>::infinity();
  /// Threads (0: all hardware threads); with `CGAL::Sequential_tag` or without TBB, 1. Results do not depend on it.
  std::size_t threads = 0;
  /// Rows computed ahead of the one delivered (memory: one row each); 0: four per thread.
  std::size_t rows_in_flight = 0;
};

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief A sparse matrix in compressed rows: the entries of row `r` are `column[k]`, `value[k]` for `k` in
  `[row_begin[r], row_begin[r + 1])`, by increasing column. Columns are vertex indices (see
  `geodesic_distance_rows()`).
*/
struct Geodesic_sparse_matrix
{
  std::size_t rows = 0, columns = 0;
  std::vector<std::size_t> row_begin = std::vector<std::size_t>(1, 0);
  std::vector<std::uint32_t> column;
  std::vector<double> value;
  /// Whether the matrix was made symmetric (`symmetric_local_geodesic_distance_matrix()`).
  bool symmetric = false;

  std::size_t number_of_entries() const { return column.size(); }
  /// The entry at (r, c), +infinity if there is none.
  double at(std::size_t r, std::size_t c) const
  {
    const auto first = column.begin() + std::ptrdiff_t(row_begin[r]), last = column.begin() + std::ptrdiff_t(row_begin[r + 1]);
    const auto it = std::lower_bound(first, last, std::uint32_t(c));
    return it != last && *it == c ? value[std::size_t(it - column.begin())] : std::numeric_limits<double>::infinity();
  }
};

namespace internal {

// The compact mesh of the matrix functions (that of a Geodesic_surface_3), read by every thread.
struct Matrix_surface
{
  const Matrix_mesh& mesh;
};

inline void check_matrix_options(const Geodesic_matrix_options& o, bool sparse)
{
  if(!(o.merge_tolerance >= 0) || !std::isfinite(o.merge_tolerance))
    throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: distance matrix: the merge tolerance must be finite and >= 0");
  if(!(o.max_distance >= 0))
    throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: distance matrix: max_distance must be >= 0 (not NaN)");
  if(sparse && !std::isfinite(o.max_distance))
    throw std::invalid_argument("CGAL::Polyhedral_geodesics_3: a sparse distance matrix needs a finite max_distance");
}

// The merge tolerance of the window engines: the option for merged windows, 0 (exact) for the exact method.
inline double merge_tolerance(const Geodesic_matrix_options& o)
{
  return o.method == Geodesic_method::merged_windows ? o.merge_tolerance : 0.0;
}

// One row of the local matrix: the vertices within max_distance of `source`, by increasing index, and their
// distances. One per thread, reused from row to row.
//
// The exact method runs its vertex-oriented schedule on the whole shared mesh, limited to max_distance (one engine
// per thread, kept from row to row: each row resets only the vertices and window lists the previous one touched, so
// a row costs what its neighbourhood costs and nothing is allocated per row). Profiled on refined_elephant (44k
// vertices, 5 mean edge lengths), a neighbourhood mesh built per row spent 28% of the time building it and the
// propagation went on to the whole Euclidean ball, beyond the limit.
//
// The other methods (and the exact method on a mesh where the vertex-oriented schedule does not run: zero-area faces,
// non-manifold or reversed edges) run on the neighbourhood of the source, copied into a small compact mesh of its
// own (Local_geodesic_submesh) with a new engine per row: merged windows take their vertex-oriented schedule there
// without a limit (merging and a limit need the window propagation on the whole mesh); Dijkstra, fast marching
// and flat-exact run with the limit.
template <class Engine>
class Local_row_solver
{
public:
  Local_row_solver(const Matrix_surface& s, const Geodesic_matrix_options& o)
    : s_(s), o_(o), radius_(neighbourhood_radius(o.method, o.max_distance))
  {
    if(o.method == Geodesic_method::exact && !s.mesh.has_special_edges() &&
       !Exact_geodesic_engine<double>::has_zero_area_face(s.mesh)) {
      whole_.reset(new Vertex_oriented_window_propagation<double>(s.mesh));
      whole_->set_record_parents(false);
      whole_->set_reuse_between_runs(true);
      whole_->set_shadow_pruning(true); // saddles emit only where a shortest path can bend (same distances)
      whole_->set_distance_limit(radius_); // a little beyond max_distance (rounding); filtered below
      whole_->clear();
    } else {
      sub_.reset(new Local_geodesic_submesh(s.mesh));
    }
  }

  void solve(Matrix_index source, std::vector<std::uint32_t>& columns, std::vector<double>& values)
  {
    columns.clear();
    values.clear();
    if(s_.mesh.star_begin[std::size_t(source)] == s_.mesh.star_begin[std::size_t(source) + 1]) { // an isolated vertex
      columns.push_back(std::uint32_t(source));
      values.push_back(0);
      return;
    }
    if(whole_) solve_on_whole_mesh(source, columns, values);
    else solve_on_neighbourhood(source, columns, values);
  }

private:
  void solve_on_whole_mesh(Matrix_index source, std::vector<std::uint32_t>& columns, std::vector<double>& values)
  {
    whole_->clear();
    whole_->add_vertex_source(source, 0);
    MDCS::No_progress none;
    whole_->run(none);
    reached_.clear();
    for(Matrix_index v : whole_->touched_vertices()) {
      const double d = whole_->vertex_distance(v);
      if(d <= o_.max_distance) reached_.push_back(std::make_pair(v, d));
    }
    std::sort(reached_.begin(), reached_.end());
    for(const auto& r : reached_) {
      columns.push_back(std::uint32_t(r.first));
      values.push_back(r.second);
    }
  }

  void solve_on_neighbourhood(Matrix_index source, std::vector<std::uint32_t>& columns, std::vector<double>& values)
  {
    sub_->build(source, radius_);
    std::unique_ptr<Engine> engine = make_matrix_engine<Engine>(sub_->mesh(), merge_tolerance(o_));
    // The window methods run without the limit: on the neighbourhood, distances_only takes their vertex-oriented
    // schedule, several times faster than the window propagation a limit needs, and the vertices within
    // max_distance get their distances on the whole mesh all the same (their shortest paths lie inside); the
    // others stop at the limit.
    const bool exact_kind = o_.method == Geodesic_method::exact || o_.method == Geodesic_method::merged_windows;
    run_single_source(*engine, sub_->local_source(), !exact_kind, o_.max_distance);
    for(std::size_t v = 0; v < sub_->mesh().number_of_vertices; ++v) {
      const double d = engine->vertex_distance(Matrix_index(v));
      if(d <= o_.max_distance) {
        columns.push_back(std::uint32_t(sub_->global_vertex(Matrix_index(v))));
        values.push_back(d);
      }
    }
  }

  const Matrix_surface& s_;
  const Geodesic_matrix_options& o_;
  double radius_;
  std::unique_ptr<Vertex_oriented_window_propagation<double>> whole_;
  std::vector<std::pair<Matrix_index, double>> reached_;
  std::unique_ptr<Local_geodesic_submesh> sub_;
};

// Dense rows: `out(row, const std::vector<double>&)` with the distances to `targets` (all vertices if null).
template <class Engine, class Output, class Progress>
void dense_rows(const Matrix_surface& s, const std::vector<Matrix_index>& sources,
                const std::vector<Matrix_index>* targets, Output& out, const Geodesic_matrix_options& o,
                std::size_t threads, Progress& progress)
{
  const std::size_t nv = s.mesh.number_of_vertices;
  const std::size_t width = targets ? targets->size() : nv;
  const bool local = std::isfinite(o.max_distance);
  // With a limit: the local rows, scattered into the targets' columns.
  std::vector<std::int64_t> column_of;
  if(local && targets) {
    column_of.assign(nv, -1);
    // a vertex listed twice among the targets: every column gets it (the first through column_of, the others below)
    for(std::size_t k = 0; k < targets->size(); ++k)
      if(column_of[std::size_t((*targets)[k])] < 0) column_of[std::size_t((*targets)[k])] = std::int64_t(k);
  }
  struct Solver
  {
    std::unique_ptr<Engine> full;
    std::unique_ptr<Local_row_solver<Engine>> local;
    std::vector<std::uint32_t> columns;
    std::vector<double> values;
  };
  CGAL::MDCS::Per_thread<std::shared_ptr<Solver>> solvers([&] {
    std::shared_ptr<Solver> solver(new Solver);
    if(local) solver->local.reset(new Local_row_solver<Engine>(s, o));
    else solver->full = make_matrix_engine<Engine>(s.mesh, merge_tolerance(o));
    return solver;
  });
  CGAL::MDCS::Parallel_progress<Progress> reporter(progress, "geodesic distance matrix", sources.size());
  std::vector<std::vector<double>> slots(o.rows_in_flight > 0 ? o.rows_in_flight : 4 * threads);
  const double inf = std::numeric_limits<double>::infinity();
  CGAL::MDCS::parallel_ordered_pipeline(
    sources.size(), threads, slots,
    [&](std::size_t i, std::vector<double>& row) {
      Solver& solver = *solvers.local();
      row.assign(width, inf);
      if(local) {
        solver.local->solve(sources[i], solver.columns, solver.values);
        for(std::size_t k = 0; k < solver.columns.size(); ++k) {
          if(!targets) row[solver.columns[k]] = solver.values[k];
          else if(column_of[solver.columns[k]] >= 0) row[std::size_t(column_of[solver.columns[k]])] = solver.values[k];
        }
        if(targets) // repeated targets
          for(std::size_t k = 0; k < width; ++k)
            if(column_of[std::size_t((*targets)[k])] != std::int64_t(k)) row[k] = row[std::size_t(column_of[std::size_t((*targets)[k])])];
      } else {
        run_single_source(*solver.full, sources[i], false, 0);
        for(std::size_t k = 0; k < width; ++k)
          row[k] = solver.full->vertex_distance(targets ? (*targets)[k] : Matrix_index(k));
      }
      return reporter.advance();
    },
    [&](std::size_t i, std::vector<double>& row) { out(i, static_cast<const std::vector<double>&>(row)); });
  reporter.finish();
}

// Sparse rows: `out(row, const std::vector<std::uint32_t>& columns, const std::vector<double>& values)`.
template <class Engine, class Output, class Progress>
void sparse_rows(const Matrix_surface& s, const std::vector<Matrix_index>& sources, Output& out,
                 const Geodesic_matrix_options& o, std::size_t threads, Progress& progress)
{
  struct Row
  {
    std::vector<std::uint32_t> columns;
    std::vector<double> values;
  };
  CGAL::MDCS::Per_thread<std::shared_ptr<Local_row_solver<Engine>>> solvers(
    [&] { return std::make_shared<Local_row_solver<Engine>>(s, o); });
  CGAL::MDCS::Parallel_progress<Progress> reporter(progress, "local geodesic distance matrix", sources.size());
  std::vector<Row> slots(o.rows_in_flight > 0 ? o.rows_in_flight : 4 * threads);
  CGAL::MDCS::parallel_ordered_pipeline(
    sources.size(), threads, slots,
    [&](std::size_t i, Row& row) {
      solvers.local()->solve(sources[i], row.columns, row.values);
      return reporter.advance();
    },
    [&](std::size_t i, Row& row) {
      out(i, static_cast<const std::vector<std::uint32_t>&>(row.columns), static_cast<const std::vector<double>&>(row.values));
    });
  reporter.finish();
}

// The compact indices of vertex descriptors of a surface; the descriptors must be vertices of it.
template <class Surface, class VertexRange>
std::vector<Matrix_index> vertex_indices(const Surface& surface, const VertexRange& vertices_range, const char* what)
{
  const std::size_t nv = surface.number_of_vertices();
  std::vector<Matrix_index> out;
  for(auto v : vertices_range) {
    const std::size_t i = std::size_t(surface.vertex_index(v));
    if(i >= nv)
      throw std::invalid_argument(std::string("CGAL::Polyhedral_geodesics_3: distance matrix: a ") + what +
                                  " is not a vertex of the mesh");
    out.push_back(Matrix_index(i));
  }
  return out;
}

// Flat-exact and fast marching follow `twin` alone (as their classes, they refuse non-manifold and reversed edges).
inline void check_matrix_surface(const Matrix_mesh& mesh, Geodesic_method method)
{
  if(!mesh.has_special_edges() || (method != Geodesic_method::flat_exact && method != Geodesic_method::fast_marching))
    return;
  throw std::invalid_argument(std::string("CGAL::Polyhedral_geodesics_3: distance matrix with the method ") +
                              geodesic_method_name(method) + ": the surface has " +
                              std::to_string(mesh.number_of_nonmanifold_edges) + " edges of three or more faces and " +
                              std::to_string(mesh.number_of_reversed_edges) +
                              " edges whose two faces are oriented against each other, which this method does not "
                              "support (the exact, merged-window and Dijkstra methods do)");
}

template <class TriangleMesh, class NamedParameters>
Geodesic_surface_3<TriangleMesh> make_matrix_surface(const TriangleMesh& tm, const NamedParameters& np)
{
  return Geodesic_surface_3<TriangleMesh>(tm, np);
}

// The symmetric matrix of a square directed one (see symmetric_local_geodesic_distance_matrix()).
inline Geodesic_sparse_matrix symmetrize_by_minimum(const Geodesic_sparse_matrix& d, std::size_t threads)
{
  const std::size_t n = d.rows;
  struct Orphan
  {
    std::uint32_t row, column;
    double value;
  };
  // Every entry (u, v): the smaller of the two directions if both exist; an entry whose transpose is missing is
  // added to the other row (an orphan). Blocks of rows write their own entries; orphans per block, in block order.
  const std::size_t block = 4096;
  const std::size_t blocks = (n + block - 1) / block;
  std::vector<double> value(d.value.size());
  std::vector<std::vector<Orphan>> orphans(blocks);
  CGAL::MDCS::parallel_for_blocks(n, block, threads, [&](std::size_t begin, std::size_t end, std::size_t b) {
    for(std::size_t u = begin; u < end; ++u)
      for(std::size_t k = d.row_begin[u]; k < d.row_begin[u + 1]; ++k) {
        const std::uint32_t v = d.column[k];
        const double back = v == u ? d.value[k] : d.at(v, u);
        if(back < std::numeric_limits<double>::infinity()) value[k] = (std::min)(d.value[k], back);
        else {
          value[k] = d.value[k];
          orphans[b].push_back(Orphan{v, std::uint32_t(u), d.value[k]});
        }
      }
  });
  std::vector<Orphan> all;
  for(const auto& o : orphans) all.insert(all.end(), o.begin(), o.end());
  std::sort(all.begin(), all.end(), [](const Orphan& a, const Orphan& b) {
    return a.row < b.row || (a.row == b.row && a.column < b.column);
  });
  Geodesic_sparse_matrix s;
  s.rows = d.rows;
  s.columns = d.columns;
  s.symmetric = true;
  s.row_begin.assign(n + 1, 0);
  s.column.reserve(d.column.size() + all.size());
  s.value.reserve(d.column.size() + all.size());
  std::size_t a = 0;
  for(std::size_t u = 0; u < n; ++u) {
    std::size_t k = d.row_begin[u];
    const std::size_t end = d.row_begin[u + 1];
    while(k < end || (a < all.size() && all[a].row == u)) {
      const bool take_orphan = a < all.size() && all[a].row == u && (k == end || all[a].column < d.column[k]);
      if(take_orphan) {
        s.column.push_back(all[a].column);
        s.value.push_back(all[a].value);
        ++a;
      } else {
        s.column.push_back(d.column[k]);
        s.value.push_back(value[k]);
        ++k;
      }
    }
    s.row_begin[u + 1] = s.column.size();
  }
  return s;
}

// The dense rows from indices (see geodesic_distance_rows()); `targets` null: every vertex.
template <class ConcurrencyTag, class RowOutput, class Progress>
void dense_rows_on(const Matrix_mesh& mesh, const std::vector<Matrix_index>& sources,
                   const std::vector<Matrix_index>* targets, RowOutput& output, const Geodesic_matrix_options& options,
                   Progress& progress)
{
  check_matrix_options(options, false);
  check_matrix_surface(mesh, options.method);
  const Matrix_surface surface{mesh};
  const std::size_t threads = CGAL::MDCS::effective_threads<ConcurrencyTag>(options.threads);
  with_matrix_engine(options.method, [&](auto tag) {
    dense_rows<typename decltype(tag)::type>(surface, sources, targets, output, options, threads, progress);
  });
}

template <class ConcurrencyTag, class RowOutput, class Progress>
void sparse_rows_on(const Matrix_mesh& mesh, const std::vector<Matrix_index>& sources, RowOutput& output,
                    const Geodesic_matrix_options& options, Progress& progress)
{
  check_matrix_options(options, true);
  check_matrix_surface(mesh, options.method);
  const Matrix_surface surface{mesh};
  const std::size_t threads = CGAL::MDCS::effective_threads<ConcurrencyTag>(options.threads);
  with_matrix_engine(options.method, [&](auto tag) {
    sparse_rows<typename decltype(tag)::type>(surface, sources, output, options, threads, progress);
  });
}

template <class ConcurrencyTag, class Progress>
Geodesic_sparse_matrix local_matrix_on(const Matrix_mesh& mesh, const Geodesic_matrix_options& options, Progress& progress)
{
  Geodesic_sparse_matrix m;
  m.rows = m.columns = mesh.number_of_vertices;
  std::vector<Matrix_index> all(m.rows);
  for(std::size_t v = 0; v < m.rows; ++v) all[v] = Matrix_index(v);
  auto append = [&](std::size_t, const std::vector<std::uint32_t>& columns, const std::vector<double>& values) {
    m.column.insert(m.column.end(), columns.begin(), columns.end());
    m.value.insert(m.value.end(), values.begin(), values.end());
    m.row_begin.push_back(m.column.size());
  };
  sparse_rows_on<ConcurrencyTag>(mesh, all, append, options, progress);
  return m;
}

} // namespace internal

/// \name Distance matrices on a prepared surface
/// The functions below also take a `Geodesic_surface_3` (any triangle mesh or triangle soup, built once and shared:
/// see that class) instead of a mesh; sources and targets are then its vertex descriptors (soups: vertex indices).
/// @{

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief Dense rows of geodesic distances: for each vertex `sources[i]`, the distance to every vertex of the
  surface (or to every vertex of `targets`, in that order) by `options.method`, delivered to `output(i, row)`
  (`row`: a `const std::vector<double>&`, +infinity where unreachable or beyond `options.max_distance`) in the order
  of the sources, one row at a time.

  Columns without targets are the vertex indices of the surface (`Geodesic_surface_3::vertex_index()`: for a mesh,
  `CGAL::get_initialized_vertex_index_map(tm)`, i.e. the vertex index of a `Surface_mesh`; for a soup, the point
  index). Each row equals the distances of a single-source run of the method's class in `distances_only` mode
  (exactly so without a limit: the same engine on the same compact mesh; with a finite `max_distance` the run is on
  the source's neighbourhood, see `local_geodesic_distance_rows()`).

  \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`: with TBB
          and a parallel tag, sources run on `options.threads` threads, one engine per thread on the surface's
          compact mesh, shared read-only. Rows are computed in source order by whichever thread is free and at most
          `options.rows_in_flight` are held, so the memory is that of a few rows whatever the number of sources;
          `output` is never called twice at a time, possibly from a worker thread. The rows do not depend on the
          thread count.
  \param progress `bool(const char* stage, double fraction)` (stage `"geodesic distance matrix"`), called on the
         calling thread; `false` stops after the rows already computed (they are delivered) and throws
         `CGAL::MDCS::Operation_cancelled`.
  \throws std::invalid_argument for invalid options, sources or targets, or a surface the method does not support
          (flat-exact and fast marching refuse non-manifold and reversed edges, as their classes do).
*/
template <class ConcurrencyTag, class TriangleMesh, class VertexPointMap, class SourceRange, class TargetRange,
          class RowOutput, class Progress = CGAL::MDCS::No_progress>
void geodesic_distance_rows(const Geodesic_surface_3<TriangleMesh, double, VertexPointMap>& surface,
                            const SourceRange& sources, const TargetRange& targets, RowOutput output,
                            const Geodesic_matrix_options& options = Geodesic_matrix_options(),
                            Progress progress = Progress())
{
  const std::vector<internal::Matrix_index> s = internal::vertex_indices(surface, sources, "source");
  const std::vector<internal::Matrix_index> t = internal::vertex_indices(surface, targets, "target");
  internal::dense_rows_on<ConcurrencyTag>(surface.compact_mesh(), s, &t, output, options, progress);
}

/// The same, to every vertex of the surface (rows of `number_of_vertices()` entries, indexed by vertex index).
template <class ConcurrencyTag, class TriangleMesh, class VertexPointMap, class SourceRange, class RowOutput,
          class Progress = CGAL::MDCS::No_progress>
void geodesic_distance_rows(const Geodesic_surface_3<TriangleMesh, double, VertexPointMap>& surface,
                            const SourceRange& sources, RowOutput output,
                            const Geodesic_matrix_options& options = Geodesic_matrix_options(),
                            Progress progress = Progress())
{
  const std::vector<internal::Matrix_index> s = internal::vertex_indices(surface, sources, "source");
  internal::dense_rows_on<ConcurrencyTag>(surface.compact_mesh(), s, nullptr, output, options, progress);
}

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief Sparse rows of the local distance matrix: for each vertex `sources[i]`, every vertex within
  `options.max_distance` (required, finite) and its distance by `options.method`, to `output(i, columns, values)`
  (`const std::vector<std::uint32_t>&` of vertex indices, increasing, the source itself included with distance 0;
  `const std::vector<double>&`), in the order of the sources, one row at a time.

  **Cost.** Each source costs what its neighbourhood costs, never the size of the mesh. The exact method runs its
  vertex-oriented schedule on the whole mesh stopped at `max_distance`, one engine per thread reused from source to
  source (each run resets only what the previous one touched; nothing is allocated per source). The other methods
  (and the exact one on a mesh with zero-area faces or non-manifold or reversed edges) run on the faces within
  Euclidean distance `max_distance` of the source (twice that for `fast_marching` and `flat_exact`, whose values are
  estimates that may undercut a path's length), copied into a small compact mesh with the original records; nothing
  of the whole mesh's size is cleared per source. Paths of length at most `max_distance` stay inside that ball, so
  the exact methods and Dijkstra give the distances of a run on the whole mesh stopped at `max_distance` (up to
  rounding: the exact methods run their faster vertex-oriented schedule, which agrees with the window propagation
  of a limited run of `Exact_geodesic_distances_3` to about 1e-15 relative; the tests compare).

  Threads, memory, progress and errors as in `geodesic_distance_rows()` (stage `"local geodesic distance matrix"`).
  Each row is directed (from its source): for a symmetric matrix see `symmetric_local_geodesic_distance_matrix()`.
*/
template <class ConcurrencyTag, class TriangleMesh, class VertexPointMap, class SourceRange, class RowOutput,
          class Progress = CGAL::MDCS::No_progress>
void local_geodesic_distance_rows(const Geodesic_surface_3<TriangleMesh, double, VertexPointMap>& surface,
                                  const SourceRange& sources, RowOutput output, const Geodesic_matrix_options& options,
                                  Progress progress = Progress())
{
  const std::vector<internal::Matrix_index> s = internal::vertex_indices(surface, sources, "source");
  internal::sparse_rows_on<ConcurrencyTag>(surface.compact_mesh(), s, output, options, progress);
}

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief The local distance matrix from every vertex (rows and columns: vertex indices), as
  `local_geodesic_distance_rows()` computes its rows: entry (u, v) is the distance from u to v when it is at most
  `options.max_distance`, and there is no entry otherwise. Not symmetric in general: the two directions of a pair
  are two runs (for the exact methods they differ by rounding, for the approximate ones by the method's error).
*/
template <class ConcurrencyTag, class TriangleMesh, class VertexPointMap, class Progress = CGAL::MDCS::No_progress>
Geodesic_sparse_matrix local_geodesic_distance_matrix(const Geodesic_surface_3<TriangleMesh, double, VertexPointMap>& surface,
                                                      const Geodesic_matrix_options& options,
                                                      Progress progress = Progress())
{
  return internal::local_matrix_on<ConcurrencyTag>(surface.compact_mesh(), options, progress);
}

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief The local distance matrix made symmetric by construction: for every unordered pair {u, v}, both (u, v)
  and (v, u) hold `min(d(u -> v), d(v -> u))` when that minimum is at most `options.max_distance`, and neither
  exists otherwise (the diagonal holds 0).

  How the two directions are reconciled: the matrix holds the row of every vertex (`local_geodesic_distance_matrix()`),
  then each entry takes the smaller of its two directions; a pair found in one direction only (the other is beyond
  `max_distance`, by rounding for the exact methods) is added to the other row with that value. The smaller value is
  kept because every method's distance is the length of a path it found or an over-estimate (merged windows,
  Dijkstra, and in practice fast marching), so the smaller one is the better estimate; for the exact methods the two
  directions agree up to rounding (the tests measure 1e-13 relative or less) and the choice changes nothing beyond
  it. The memory is that of the matrix plus the entries found in one direction only.
*/
template <class ConcurrencyTag, class TriangleMesh, class VertexPointMap, class Progress = CGAL::MDCS::No_progress>
Geodesic_sparse_matrix symmetric_local_geodesic_distance_matrix(
  const Geodesic_surface_3<TriangleMesh, double, VertexPointMap>& surface, const Geodesic_matrix_options& options,
  Progress progress = Progress())
{
  const Geodesic_sparse_matrix directed = internal::local_matrix_on<ConcurrencyTag>(surface.compact_mesh(), options, progress);
  return internal::symmetrize_by_minimum(directed, CGAL::MDCS::effective_threads<ConcurrencyTag>(options.threads));
}

/// @}
/// \name Distance matrices on a triangle mesh
/// The same functions on a `FaceGraph` with triangle faces: they build its `Geodesic_surface_3` first (named
/// parameter `vertex_point_map`; sources and targets are vertex descriptors).
/// @{

template <class ConcurrencyTag, class TriangleMesh, class SourceRange, class TargetRange, class RowOutput,
          class Progress = CGAL::MDCS::No_progress,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
void geodesic_distance_rows(const TriangleMesh& tm, const SourceRange& sources, const TargetRange& targets,
                            RowOutput output, const Geodesic_matrix_options& options = Geodesic_matrix_options(),
                            Progress progress = Progress(),
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::check_matrix_options(options, false);
  const auto surface = internal::make_matrix_surface(tm, np);
  geodesic_distance_rows<ConcurrencyTag>(surface, sources, targets, output, options, progress);
}

template <class ConcurrencyTag, class TriangleMesh, class SourceRange, class RowOutput,
          class Progress = CGAL::MDCS::No_progress,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
void geodesic_distance_rows(const TriangleMesh& tm, const SourceRange& sources, RowOutput output,
                            const Geodesic_matrix_options& options = Geodesic_matrix_options(),
                            Progress progress = Progress(),
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::check_matrix_options(options, false);
  const auto surface = internal::make_matrix_surface(tm, np);
  geodesic_distance_rows<ConcurrencyTag>(surface, sources, output, options, progress);
}

/*!
  \ingroup PkgPolyhedralGeodesics3Ref
  \brief The dense matrix of `geodesic_distance_rows()` to every vertex, row-major in one vector
  (`sources.size() * num_vertices(tm)` entries: for many sources prefer the rows function, whose memory is bounded).
*/
template <class ConcurrencyTag, class TriangleMesh, class SourceRange>
std::vector<double> geodesic_distance_matrix(const TriangleMesh& tm, const SourceRange& sources,
                                             const Geodesic_matrix_options& options = Geodesic_matrix_options())
{
  const std::size_t nv = num_vertices(tm);
  std::vector<double> m;
  m.reserve(nv * std::size_t(std::distance(std::begin(sources), std::end(sources))));
  geodesic_distance_rows<ConcurrencyTag>(tm, sources, [&](std::size_t, const std::vector<double>& row) {
    m.insert(m.end(), row.begin(), row.end()); // rows arrive in order
  }, options);
  return m;
}

template <class ConcurrencyTag, class TriangleMesh, class SourceRange, class RowOutput,
          class Progress = CGAL::MDCS::No_progress,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
void local_geodesic_distance_rows(const TriangleMesh& tm, const SourceRange& sources, RowOutput output,
                                  const Geodesic_matrix_options& options, Progress progress = Progress(),
                                  const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::check_matrix_options(options, true);
  const auto surface = internal::make_matrix_surface(tm, np);
  local_geodesic_distance_rows<ConcurrencyTag>(surface, sources, output, options, progress);
}

template <class ConcurrencyTag, class TriangleMesh, class Progress = CGAL::MDCS::No_progress,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Geodesic_sparse_matrix local_geodesic_distance_matrix(const TriangleMesh& tm, const Geodesic_matrix_options& options,
                                                      Progress progress = Progress(),
                                                      const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::check_matrix_options(options, true);
  const auto surface = internal::make_matrix_surface(tm, np);
  return local_geodesic_distance_matrix<ConcurrencyTag>(surface, options, progress);
}

template <class ConcurrencyTag, class TriangleMesh, class Progress = CGAL::MDCS::No_progress,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Geodesic_sparse_matrix symmetric_local_geodesic_distance_matrix(
  const TriangleMesh& tm, const Geodesic_matrix_options& options, Progress progress = Progress(),
  const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::check_matrix_options(options, true);
  const auto surface = internal::make_matrix_surface(tm, np);
  return symmetric_local_geodesic_distance_matrix<ConcurrencyTag>(surface, options, progress);
}

/// @}

} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_GEODESIC_DISTANCE_MATRIX_H
