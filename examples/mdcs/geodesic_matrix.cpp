// `mdcs geodesics --matrix npy|mtx`: geodesic distance matrices (CGAL/Polyhedral_geodesics_3/geodesic_distance_matrix.h)
// written as files other tools read: dense rows from the given sources as NumPy .npy (float64, inf = unreachable),
// or the sparse local matrix (pairs within --max-distance) as Matrix Market. Sources run in parallel (--threads);
// the rows arrive in order, one at a time (possibly on a worker thread), and are written as they come.
// Its own translation unit: the matrix engines are templates of every method.
#include "geodesic_matrix.h"

#include "geodesic_locations.h"
#include "geodesic_soup.h"
#include "mesh_input.h"

#include <CGAL/Polyhedral_geodesics_3/IO/distance_matrix_files.h>
#include <CGAL/Polyhedral_geodesics_3/geodesic_distance_matrix.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace mdcs_cli {

namespace {

namespace PG = CGAL::Polyhedral_geodesics_3;

// Matrix files above this size are refused (a dense all-pairs matrix of n vertices takes 8 n^2 bytes).
constexpr double max_dense_bytes = 16.0 * 1024 * 1024 * 1024;

PG::Geodesic_method matrix_method(const Geo_method& m)
{
  switch(m.kind) {
  case Geo_method_kind::exact: return PG::Geodesic_method::exact;
  case Geo_method_kind::merged: return PG::Geodesic_method::merged_windows;
  case Geo_method_kind::flat_exact: return PG::Geodesic_method::flat_exact;
  case Geo_method_kind::fmm: return PG::Geodesic_method::fast_marching;
  case Geo_method_kind::dijkstra: return PG::Geodesic_method::dijkstra;
  default: break;
  }
  throw Usage_error("--matrix: the method '" + m.text + "' has no distance matrix (exact, merged:EPS, flat-exact, fmm, dijkstra)");
}

// What the matrix functions take: a mesh and its vertex descriptors, or a soup's surface and vertex indices.
const Geo_mesh& matrix_input(const Geo_mesh& mesh) { return mesh; }
const PG::Geodesic_surface_3<PG::Triangle_soup>& matrix_input(const Geo_soup& soup) { return *soup.surface; }
std::vector<Geo_mesh::Vertex_index> matrix_descriptors(const Geo_mesh&, const std::vector<std::size_t>& v)
{
  std::vector<Geo_mesh::Vertex_index> d;
  for(std::size_t i : v) d.push_back(Geo_mesh::Vertex_index(Geo_mesh::size_type(i)));
  return d;
}
const std::vector<std::size_t>& matrix_descriptors(const Geo_soup&, const std::vector<std::size_t>& v) { return v; }

// Vertex sources (or targets) of the matrix: "all" or vertex indices (no surface points: the rows and columns of
// a matrix are vertices).
template <class Surface>
std::vector<std::size_t> matrix_vertices(const Surface& mesh, const std::string& spec, const char* option)
{
  std::vector<std::size_t> result;
  if(spec == "all") {
    for(std::size_t v = 0; v < geo_vertex_count(mesh); ++v) result.push_back(v); // rows = vertex indices
    return result;
  }
  const std::vector<Geo_location> locations = parse_geo_locations(spec, option);
  validate_geo_locations(mesh, locations, option);
  for(const Geo_location& loc : locations) {
    if(!loc.at_vertex)
      throw Usage_error(std::string("--") + option + ": '" + loc.text + "' is a surface point; a matrix has vertex rows and columns");
    result.push_back(loc.index);
  }
  return result;
}

// Refuses the options of the single-source mode that mean nothing here, so that none is silently ignored.
void refuse_single_source_options(const Parsed_options& o)
{
  for(const char* name : {"limit", "stop-at-targets", "shorten-paths", "memory", "view", "up", "levels", "compare-exact",
                          "compare-cgal", "no-picture"})
    if(o.given(name)) throw Usage_error(std::string("--") + name + " does not apply with --matrix (no field, paths or picture)");
}

std::string number(double v)
{
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// The matrix on a mesh or on a surface used as given (geodesic_soup.h).
template <class Surface>
int geodesic_matrix_on(Invocation& run, const Geodesics_settings& s, const Surface& mesh, bool repaired,
                       const std::vector<std::string>& notes, double seconds_read)
{
  const Parsed_options& o = run.options; // checked by run_geodesic_matrix
  const std::string format = o.text("matrix");
  const bool sparse = format == "mtx";
  const double max_distance = o.given("max-distance") ? o.real("max-distance") : std::numeric_limits<double>::infinity();
  const bool symmetric = o.flag("symmetric");

  refuse_unsupported_on_soup(mesh, s);
  const Geo_surface_shape shape = geo_surface_shape(mesh, repaired);
  const std::vector<std::size_t> sources = matrix_vertices(mesh, s.sources, "source");
  const std::vector<std::size_t> targets = s.targets.empty() ? std::vector<std::size_t>() : matrix_vertices(mesh, s.targets, "targets");
  if(sources.empty()) throw Input_error("the mesh has no vertex");
  const std::size_t rows = sources.size(), columns = targets.empty() ? geo_vertex_count(mesh) : targets.size();
  const auto& input = matrix_input(mesh);
  const auto& source_descriptors = matrix_descriptors(mesh, sources);
  if(!sparse && 8.0 * double(rows) * double(columns) > max_dense_bytes)
    throw Usage_error("--matrix npy: " + std::to_string(rows) + " x " + std::to_string(columns) + " doubles would take " +
                      number(8.0 * double(rows) * double(columns) / (1024.0 * 1024 * 1024)) +
                      " GiB (at most 16): give fewer sources, or --matrix mtx with --max-distance");

  const double mean_edge = geo_edge_lengths(mesh).mean();

  PG::Geodesic_matrix_options mo;
  mo.method = matrix_method(s.method);
  mo.merge_tolerance = s.method.merge_eps * mean_edge;
  mo.max_distance = max_distance;
  mo.threads = run.threads.used();
  const Progress_bar& bar = run.progress;
  auto progress = [&bar](const char* stage, double f) { return bar(stage, f); };

  const auto folder = prepare_output_folder(s.output);
  const std::string path = (folder / (sparse ? "distances.mtx" : "distances.npy")).string();
  const std::string comment = "mdcs geodesics " + s.method.text + " on " + s.mesh + ": rows = sources, columns = " +
                              (targets.empty() ? std::string("vertex indices") : std::string("the --targets")) +
                              (std::isfinite(max_distance) ? ", pairs within " + number(max_distance) : std::string());

  // Every value is checked before it is written: >= 0 and finite, or +inf (unreachable / beyond the distance);
  // a source's own entry is 0.
  std::size_t finite_entries = 0, entries = 0;
  double largest = 0;
  auto check = [&](std::size_t row, std::uint32_t column, double d) {
    const bool ok = (d >= 0 && d <= max_distance * (1 + 1e-12)) || (!sparse && d == std::numeric_limits<double>::infinity());
    if(!ok) throw Result_error("the distance (" + std::to_string(row) + ", " + std::to_string(column) + ") is " + number(d));
    if(std::isfinite(d)) {
      ++finite_entries;
      largest = std::max(largest, d);
    }
  };
  auto check_source = [&](std::size_t row, double d) {
    if(geo_is_isolated(mesh, sources[row])) return; // no face: the library gives it no distance
    if(d != 0) throw Result_error("the distance of source vertex " + std::to_string(sources[row]) + " to itself is " + number(d));
  };

  const auto t1 = std::chrono::steady_clock::now();
  Output_file file(path);
  if(!sparse) {
    PG::IO::Npy_matrix_writer npy(file.stream(), rows, columns);
    auto output = [&](std::size_t i, const std::vector<double>& row) {
      for(std::size_t c = 0; c < row.size(); ++c) check(i, std::uint32_t(c), row[c]);
      if(targets.empty()) check_source(i, row[sources[i]]);
      npy.write_row(row);
    };
    if(targets.empty())
      PG::geodesic_distance_rows<CGAL::Parallel_if_available_tag>(input, source_descriptors, output, mo, progress);
    else
      PG::geodesic_distance_rows<CGAL::Parallel_if_available_tag>(input, source_descriptors, matrix_descriptors(mesh, targets), output, mo,
                                                                  progress);
    npy.close();
    entries = rows * columns;
  } else {
    PG::Geodesic_sparse_matrix m;
    if(s.sources == "all") {
      m = symmetric ? PG::symmetric_local_geodesic_distance_matrix<CGAL::Parallel_if_available_tag>(input, mo, progress)
                    : PG::local_geodesic_distance_matrix<CGAL::Parallel_if_available_tag>(input, mo, progress);
    } else {
      // Rows from the given sources, held as a sparse matrix (memory follows the entries within the distance).
      m.rows = rows;
      m.columns = geo_vertex_count(mesh);
      PG::local_geodesic_distance_rows<CGAL::Parallel_if_available_tag>(
        input, source_descriptors,
        [&](std::size_t, const std::vector<std::uint32_t>& cols, const std::vector<double>& vals) {
          m.column.insert(m.column.end(), cols.begin(), cols.end());
          m.value.insert(m.value.end(), vals.begin(), vals.end());
          m.row_begin.push_back(m.column.size());
        },
        mo, progress);
    }
    if(m.rows != rows || m.row_begin.size() != rows + 1)
      throw Result_error("the sparse matrix has " + std::to_string(m.rows) + " rows for " + std::to_string(rows) + " sources");
    for(std::size_t r = 0; r < m.rows; ++r) {
      bool own = false;
      const std::size_t own_column = sources[r];
      for(std::size_t k = m.row_begin[r]; k < m.row_begin[r + 1]; ++k) {
        check(r, m.column[k], m.value[k]);
        if(m.column[k] == own_column) {
          own = true;
          check_source(r, m.value[k]);
        }
      }
      if(!own && !geo_is_isolated(mesh, sources[r]))
        throw Result_error("row " + std::to_string(r) + " of the sparse matrix lacks its source's own entry (0)");
    }
    entries = m.number_of_entries();
    PG::IO::write_matrix_market(file.stream(), m, comment);
  }
  file.commit();
  const double seconds_matrix = seconds_since(t1);

  std::ostringstream sum;
  sum << "mdcs geodesics --matrix " << format << " on " << s.mesh << (repaired ? " (repaired by CGAL's soup repair)" : "") << "\n"
      << "  mesh: " << geo_vertex_count(mesh) << " vertices, " << geo_face_count(mesh) << " faces, mean edge length "
      << number(mean_edge) << "\n"
      << "  method: " << s.method.description() << "\n"
      << "  matrix: " << rows << " x " << columns << (sparse ? (symmetric ? ", sparse, symmetric (min of both directions)" : ", sparse") : ", dense")
      << (std::isfinite(max_distance) ? ", within " + number(max_distance) : std::string()) << "\n"
      << "  entries: " << (sparse ? entries : finite_entries) << (sparse ? " stored" : " finite of " + std::to_string(entries))
      << ", largest distance " << number(largest) << "\n"
      << "  time: read " << number(seconds_read) << " s, matrix " << number(seconds_matrix) << " s\n"
      << "  threads: " << threads_text(run.threads) << "\n"
      << "  file: " << path << "\n";
  sum << shape.text();
  for(const std::string& note : notes) sum << "note: " << note << "\n";
  std::cout << sum.str();
  Run_summary_json json;
  json.files.push_back(path);
  json.files.push_back((folder / "summary.txt").string());
  write_text_file(json.files.back(), sum.str());
  json.inputs.add("mesh", s.mesh).add("repaired", repaired).add("vertices", (unsigned long long)geo_vertex_count(mesh))
    .add("faces", (unsigned long long)geo_face_count(mesh)).add("mean_edge_length", mean_edge).add("surface", shape.json());
  json.timings.add("read", seconds_read).add("matrix", seconds_matrix);
  json.results.add("matrix_file", path).add("format", format).add("rows", (unsigned long long)rows)
    .add("columns", (unsigned long long)columns).add("symmetric", symmetric).add("entries", (unsigned long long)entries)
    .add("finite_entries", (unsigned long long)finite_entries).add("largest_distance", largest)
    .add("method", s.method.text).add("merge_tolerance", mo.merge_tolerance);
  if(std::isfinite(max_distance)) json.results.add("max_distance", max_distance);
  json.notes = notes;
  json.notes.push_back(sparse ? "Matrix Market: 1-based row (source) and column (vertex) indices; absent pairs are farther than max_distance"
                              : ".npy float64 C order: numpy.load() reads it; inf = unreachable (or beyond --max-distance)");
  json.write((folder / "summary.json").string(), run, EXIT_OK);
  return EXIT_OK;
}

} // namespace

int run_geodesic_matrix(Invocation& run, const Geodesics_settings& s)
{
  const Parsed_options& o = run.options;
  refuse_single_source_options(o);
  const bool sparse = o.text("matrix") == "mtx";
  if(sparse && !o.given("max-distance"))
    throw Usage_error("--matrix mtx needs --max-distance D (the sparse matrix holds the pairs within D)");
  const bool symmetric = o.flag("symmetric");
  if(symmetric && !sparse) throw Usage_error("--symmetric applies to --matrix mtx (a dense matrix holds both directions)");
  if(symmetric && s.sources != "all") throw Usage_error("--symmetric needs --source all (the matrix of every vertex pair)");
  if(sparse && !s.targets.empty()) throw Usage_error("--targets (the columns) applies to --matrix npy only");
  if(s.method.is_heat()) matrix_method(s.method); // throws: no matrix for the heat method
  const auto t0 = std::chrono::steady_clock::now();
  Geo_mesh mesh;
  Geo_soup soup;
  std::vector<std::string> notes;
  run.progress.begin("reading the mesh");
  const Geo_input_kind kind = load_geodesics_input(s.mesh, mesh, soup, notes, s.repair);
  run.progress.end();
  for(const std::string& note : notes) std::cerr << "mdcs geodesics: note: " << note << "\n";
  const double seconds_read = seconds_since(t0);
  if(kind == Geo_input_kind::soup) return geodesic_matrix_on(run, s, soup, false, notes, seconds_read);
  return geodesic_matrix_on(run, s, mesh, kind == Geo_input_kind::repaired_mesh, notes, seconds_read);
}

} // namespace mdcs_cli
