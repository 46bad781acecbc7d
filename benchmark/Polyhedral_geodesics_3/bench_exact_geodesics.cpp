// Exact geodesic distances on triangle meshes: CGAL::Polyhedral_geodesics_3::Exact_geodesic_distances_3 (window
// propagation, in its distances_only and full_field memory modes) against CGAL::Surface_mesh_shortest_path
// (SMSP, Epick), from 1 and from 10 source vertices to every vertex, on meshes of 10k to ~600k vertices.
//
//   bench_exact_geodesics [--meshes a,b,c] [--runs N] [--sources 1|10|both] [--no-smsp]
//                         [--smsp-max-vertices N] [--smsp-cache DIR] [--mesh-dir DIR] [--extra-dir DIR]
//                         [--timeout S] [--mem-limit-mib M] [--csv FILE] [--list]
//
// Built-in meshes (CGAL's demo meshes, folder MDCS_CGAL_MESH_DIR or --mesh-dir): ChineseDragon-10kv,
// armadillo, bunny00, refined_elephant, and Loop subdivisions armadillo-loop1 (~104k vertices),
// bunny00-loop1 (~150k), bunny00-loop2 (~600k). --extra-dir adds every .off/.obj/.ply file of a folder
// (for example ../shared/data); --meshes may also name those files (by their stem).
//
// Every run of every method is a forked child process: its time is measured inside the child, and its peak
// memory is the child's peak resident set size minus its resident set size when the method starts (the
// input mesh, shared with the parent, is not counted; what the method allocates, including its own copy of
// the mesh, is). See benchmark/README.md.
#include <geodesic_bench_common.h>
#include <mdcs_bench.h>

#include <CGAL/Polyhedral_geodesics_3/Exact_geodesic_distances_3.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace PG = CGAL::Polyhedral_geodesics_3;
using mdcs_bench::fmt;

namespace {

using namespace geodesic_bench; // Mesh, Vertex, inf, nan_, run_forked, Mesh_spec, load_mesh, ...
typedef CGAL::Surface_mesh_shortest_path_traits<K, Mesh> SMSP_traits;
typedef CGAL::Surface_mesh_shortest_path<SMSP_traits> SMSP;
typedef PG::Exact_geodesic_distances_3<Mesh> Geodesics;

// ---- running one method in a forked child ------------------------------------------------------------------

struct Run_header
{
  std::int32_t ok = 0;
  double time_s = nan_;
  double setup_s = nan_;
  double peak_mib = nan_;       // peak RSS of the child minus its RSS when the method started
  double engine_peak_mib = nan_; // Geodesic_statistics::peak_memory_bytes (MDCS only)
  std::uint64_t windows_created = 0, windows_propagated = 0, windows_pruned = 0, peak_live_windows = 0,
                stored_windows = 0;
  std::uint64_t number_of_distances = 0;
  char error[512] = {0};
};

typedef Forked_result<Run_header> Run_result;

// ---- the methods -------------------------------------------------------------------------------------------

enum Method_kind { MDCS_DISTANCES, MDCS_FULL, CGAL_SMSP };
const char* method_name(Method_kind m)
{
  return m == MDCS_DISTANCES ? "MDCS distances_only" : m == MDCS_FULL ? "MDCS full_field" : "CGAL SMSP";
}

void run_mdcs(const Mesh& mesh, const std::vector<Vertex>& sources, PG::Geodesic_memory_mode mode, Run_header& h,
              std::vector<double>& distances)
{
  const double t0 = mdcs_bench::now_seconds();
  Geodesics geodesics(mesh, mode);
  const double t1 = mdcs_bench::now_seconds();
  for(Vertex s : sources)
    geodesics.add_source(s);
  geodesics.compute();
  distances.assign(mesh.number_of_vertices(), nan_);
  geodesics.distances(Distance_vector_map{&distances});
  const double t2 = mdcs_bench::now_seconds();
  h.time_s = t2 - t0;
  h.setup_s = t1 - t0;
  const PG::Geodesic_statistics& st = geodesics.statistics();
  h.windows_created = st.windows_created;
  h.windows_propagated = st.windows_propagated;
  h.windows_pruned = st.windows_pruned;
  h.peak_live_windows = st.peak_live_windows;
  h.stored_windows = st.stored_windows;
  h.engine_peak_mib = double(st.peak_memory_bytes) / (1024.0 * 1024.0);
}

void run_smsp(const Mesh& mesh, const std::vector<Vertex>& sources, Run_header& h, std::vector<double>& distances)
{
  const double t0 = mdcs_bench::now_seconds();
  SMSP smsp(mesh);
  for(Vertex s : sources)
    smsp.add_source_point(s);
  const double t1 = mdcs_bench::now_seconds();
  smsp.build_sequence_tree();
  distances.assign(mesh.number_of_vertices(), nan_);
  for(Vertex v : vertices(mesh)) {
    const double d = CGAL::to_double(smsp.shortest_distance_to_source_points(v).first);
    distances[std::size_t(v)] = d < 0 ? inf : d; // SMSP reports unreachable vertices with a negative distance
  }
  const double t2 = mdcs_bench::now_seconds();
  h.time_s = t2 - t0;
  h.setup_s = t1 - t0;
}

// ---- checks ------------------------------------------------------------------------------------------------

// Necessary conditions for geodesic distances, usable without a reference: every distance is at least the
// Euclidean distance to the nearest source, and |d(u) - d(v)| <= |uv| along every edge.
std::string sanity_check(const Mesh& mesh, const std::vector<Vertex>& sources, const std::vector<double>& d,
                         double tiny)
{
  std::size_t non_finite = 0, below_euclid = 0, lipschitz = 0, missing = 0;
  if(d.size() != mesh.number_of_vertices()) return "size mismatch";
  for(Vertex v : vertices(mesh)) {
    const double dv = d[std::size_t(v)];
    if(std::isnan(dv)) { ++missing; continue; }
    if(!std::isfinite(dv)) { ++non_finite; continue; }
    double e = inf;
    for(Vertex s : sources)
      e = std::min(e, std::sqrt(CGAL::squared_distance(mesh.point(v), mesh.point(s))));
    if(dv < e * (1 - 1e-12) - tiny) ++below_euclid;
  }
  for(auto e : edges(mesh)) {
    const Vertex a = source(halfedge(e, mesh), mesh), b = target(halfedge(e, mesh), mesh);
    const double da = d[std::size_t(a)], db = d[std::size_t(b)];
    if(!std::isfinite(da) || !std::isfinite(db)) continue;
    const double len = std::sqrt(CGAL::squared_distance(mesh.point(a), mesh.point(b)));
    if(std::abs(da - db) > len * (1 + 1e-12) + tiny) ++lipschitz;
  }
  if(!non_finite && !below_euclid && !lipschitz && !missing) return "ok";
  std::string s;
  if(missing) s += "nan:" + std::to_string(missing) + " ";
  if(non_finite) s += "inf:" + std::to_string(non_finite) + " ";
  if(below_euclid) s += "below_euclid:" + std::to_string(below_euclid) + " ";
  if(lipschitz) s += "lipschitz:" + std::to_string(lipschitz) + " ";
  s.pop_back();
  return s;
}

struct Comparison
{
  double max_rel = nan_;       // over the vertices where both are finite; +inf when finiteness differs somewhere
  std::size_t finiteness_mismatch = 0;
  std::size_t above_1e12 = 0;  // vertices with relative difference > 1e-12
  std::size_t worst = 0;
  double worst_value = nan_, worst_reference = nan_;
};

Comparison compare(const std::vector<double>& d, const std::vector<double>& ref, double tiny)
{
  Comparison c;
  if(d.size() != ref.size()) {
    c.max_rel = inf;
    c.finiteness_mismatch = std::max(d.size(), ref.size());
    return c;
  }
  double m = 0;
  for(std::size_t i = 0; i < d.size(); ++i) {
    const bool fa = std::isfinite(d[i]), fb = std::isfinite(ref[i]);
    if(fa != fb || std::isnan(d[i]) || std::isnan(ref[i])) {
      if(!c.finiteness_mismatch) { c.worst = i; c.worst_value = d[i]; c.worst_reference = ref[i]; }
      ++c.finiteness_mismatch;
      continue;
    }
    if(!fa) continue; // both unreachable
    const double r = std::abs(d[i] - ref[i]) / std::max(ref[i], tiny);
    if(r > 1e-12) ++c.above_1e12;
    if(r > m) {
      m = r;
      if(!c.finiteness_mismatch) { c.worst = i; c.worst_value = d[i]; c.worst_reference = ref[i]; }
    }
  }
  c.max_rel = c.finiteness_mismatch ? inf : m;
  return c;
}

// ---- SMSP result cache (--smsp-cache DIR) -------------------------------------------------------------------
// SMSP's results do not depend on MDCS, and SMSP takes minutes at 100k+ vertices: a cache lets one re-measure
// MDCS against stored SMSP times, memory and distances. Off by default (then every ratio comes from one run).

std::string cache_file(const std::string& dir, const std::string& mesh, std::size_t n, std::size_t k)
{
  return (std::filesystem::path(dir) / ("smsp_" + mesh + "_" + std::to_string(n) + "v_" + std::to_string(k) + "s.bin")).string();
}

const char cache_magic[8] = {'S', 'M', 'S', 'P', 'C', 'A', '1', 0};

bool save_smsp_cache(const std::string& file, std::size_t n, std::size_t k, const std::vector<Run_result>& results)
{
  std::ofstream out(file, std::ios::binary);
  if(!out) return false;
  const std::uint64_t header[3] = {n, k, results.size()};
  out.write(cache_magic, sizeof cache_magic);
  out.write(reinterpret_cast<const char*>(header), sizeof header);
  for(const Run_result& r : results) {
    const std::int32_t ok = r.ok ? 1 : 0;
    const std::uint64_t failure_size = r.failure.size();
    out.write(reinterpret_cast<const char*>(&ok), sizeof ok);
    out.write(reinterpret_cast<const char*>(&failure_size), sizeof failure_size);
    out.write(r.failure.data(), std::streamsize(failure_size));
    Run_header h = r.header;
    h.number_of_distances = r.distances.size();
    out.write(reinterpret_cast<const char*>(&h), sizeof h);
    out.write(reinterpret_cast<const char*>(r.distances.data()), std::streamsize(r.distances.size() * sizeof(double)));
  }
  return bool(out);
}

bool load_smsp_cache(const std::string& file, std::size_t n, std::size_t k, std::vector<Run_result>& results)
{
  std::ifstream in(file, std::ios::binary);
  if(!in) return false;
  char magic[8];
  std::uint64_t header[3];
  in.read(magic, sizeof magic);
  in.read(reinterpret_cast<char*>(header), sizeof header);
  if(!in || std::memcmp(magic, cache_magic, sizeof magic) != 0 || header[0] != n || header[1] != k || header[2] > 1000)
    return false;
  std::vector<Run_result> loaded(static_cast<std::size_t>(header[2]));
  for(Run_result& r : loaded) {
    std::int32_t ok = 0;
    std::uint64_t failure_size = 0;
    in.read(reinterpret_cast<char*>(&ok), sizeof ok);
    in.read(reinterpret_cast<char*>(&failure_size), sizeof failure_size);
    if(!in || failure_size > 4096) return false;
    r.ok = ok != 0;
    r.failure.resize(std::size_t(failure_size));
    in.read(&r.failure[0], std::streamsize(failure_size));
    in.read(reinterpret_cast<char*>(&r.header), sizeof r.header);
    if(!in || r.header.number_of_distances > n) return false;
    r.distances.resize(std::size_t(r.header.number_of_distances));
    in.read(reinterpret_cast<char*>(r.distances.data()), std::streamsize(r.distances.size() * sizeof(double)));
    if(!in) return false;
  }
  results = std::move(loaded);
  return true;
}

struct Row_data // one (mesh, sources, method) cell of the table
{
  std::string mesh;
  std::size_t vertices = 0;
  std::size_t sources = 0;
  Method_kind method = MDCS_DISTANCES;
  bool ran = false;
  std::string note;
  double time_s = nan_, setup_s = nan_, peak_mib = nan_, engine_peak_mib = nan_;
  std::uint64_t windows_created = 0, windows_propagated = 0, peak_live_windows = 0;
  double ratio = nan_;
  double max_rel_diff = nan_;
  bool has_reference = false;
  std::string sanity = "-";
};

std::string fmt_time(double t) { return std::isfinite(t) ? fmt(t, "%.4g") : "-"; }
std::string fmt_mib(double m) { return std::isfinite(m) ? fmt(m, "%.1f") : "-"; }

void usage()
{
  std::cerr << "usage: bench_exact_geodesics [--meshes a,b,c] [--runs N] [--sources 1|10|both] [--no-smsp]\n"
               "         [--smsp-max-vertices N] [--smsp-cache DIR] [--mesh-dir DIR] [--extra-dir DIR] [--timeout S]\n"
               "         [--mem-limit-mib M] [--csv FILE] [--list]\n"
               "  built-in meshes: ChineseDragon-10kv armadillo bunny00 refined_elephant armadillo-loop1 bunny00-loop1"
               " bunny00-loop2\n";
}

} // namespace

int main(int argc, char** argv)
{
  Common_options o;
  o.csv = "exact_geodesics.csv";
  std::string sources_option = "both";
  std::string smsp_cache;
  bool smsp = true;
  std::size_t smsp_max_vertices = 200000;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if(o.parse(argc, argv, i)) continue;
    if(a == "--sources" && has_value) sources_option = argv[++i];
    else if(a == "--no-smsp") smsp = false;
    else if(a == "--smsp-max-vertices" && has_value) smsp_max_vertices = std::strtoul(argv[++i], nullptr, 10);
    else if(a == "--smsp-cache" && has_value) smsp_cache = argv[++i];
    else {
      usage();
      return 2;
    }
  }
  const std::string& mesh_dir = o.mesh_dir;
  const std::string& csv = o.csv;
  const int runs = o.runs;
  const double timeout_s = o.timeout_s;
  std::vector<std::size_t> source_counts;
  if(sources_option == "1") source_counts = {1};
  else if(sources_option == "10") source_counts = {10};
  else if(sources_option == "both") source_counts = {1, 10};
  else {
    usage();
    return 2;
  }

  // ---- the list of meshes
  const std::vector<Mesh_spec> builtin = {
    {"ChineseDragon-10kv", o.in_mesh_dir("ChineseDragon-10kv.off"), 0}, {"armadillo", o.in_mesh_dir("armadillo.off"), 0},
    {"bunny00", o.in_mesh_dir("bunny00.off"), 0},                      {"refined_elephant", o.in_mesh_dir("refined_elephant.off"), 0},
    {"armadillo-loop1", o.in_mesh_dir("armadillo.off"), 1},            {"bunny00-loop1", o.in_mesh_dir("bunny00.off"), 1},
    {"bunny00-loop2", o.in_mesh_dir("bunny00.off"), 2}};
  std::vector<Mesh_spec> specs;
  if(const int exit_code = select_or_list_meshes(builtin, o, specs, usage); exit_code >= 0)
    return exit_code;

  const double mem_total_budget = o.memory_allowance_mib();
  std::cout << "Exact geodesic distances from 1 and 10 source vertices to all vertices.\n"
            << "MDCS = CGAL::Polyhedral_geodesics_3::Exact_geodesic_distances_3<Surface_mesh, double>;"
               " SMSP = CGAL::Surface_mesh_shortest_path (Epick).\n"
            << "time_s: median of " << runs << " runs (construction + sources + propagation + all vertex distances);"
               " peak_MiB: max over the runs of the peak RSS of a forked child minus its RSS at the start.\n"
            << "Each run is a separate child process with a " << fmt(timeout_s, "%.0f") << " s limit and a "
            << fmt(mem_total_budget, "%.0f") << " MiB address-space allowance.\n"
            << "SMSP runs " << (smsp ? "on meshes up to " + std::to_string(smsp_max_vertices) + " vertices" : "nowhere (--no-smsp)")
            << ". Mesh folder: " << (mesh_dir.empty() ? "(none)" : mesh_dir) << "\n\n";

  std::vector<Row_data> rows;
  double smsp_mib_per_vertex = 0; // largest observed SMSP peak per vertex, to predict whether SMSP fits

  for(const Mesh_spec& spec : specs) {
    Mesh mesh;
    std::string message;
    const double tl = mdcs_bench::now_seconds();
    if(!load_mesh(spec, mesh, message)) {
      std::cout << "skipping " << spec.name << ": " << message << "\n" << std::flush;
      continue;
    }
    const std::size_t n = mesh.number_of_vertices();
    const double tiny = 1e-6 * average_edge_length(mesh);
    std::cout << spec.name << ": " << n << " vertices, " << mesh.number_of_faces() << " faces"
              << (message.empty() ? "" : " (" + message + ")") << ", loaded in " << fmt(mdcs_bench::now_seconds() - tl, "%.2f")
              << " s\n" << std::flush;

    for(std::size_t k : source_counts) {
      std::vector<Vertex> sources;
      for(std::size_t i = 0; i < k; ++i)
        sources.push_back(Vertex(Mesh::size_type(i * n / k)));

      const std::vector<Method_kind> methods = {MDCS_DISTANCES, MDCS_FULL, CGAL_SMSP};
      std::map<Method_kind, std::vector<Run_result>> results;

      // Which methods run.
      std::string smsp_skip;
      std::string smsp_cache_note;
      bool smsp_from_cache = false;
      if(!smsp) smsp_skip = "SMSP not run (--no-smsp)";
      else if(n > smsp_max_vertices)
        smsp_skip = "SMSP skipped: " + std::to_string(n) + " vertices > --smsp-max-vertices " +
                    std::to_string(smsp_max_vertices) + " (too much time/memory)";
      else if(!smsp_cache.empty() && load_smsp_cache(cache_file(smsp_cache, spec.name, n, k), n, k, results[CGAL_SMSP])) {
        smsp_from_cache = true;
        smsp_cache_note = "SMSP results from the cache " + cache_file(smsp_cache, spec.name, n, k) + " (not measured in this run)";
        std::cout << "  " << spec.name << ", " << k << " source" << (k > 1 ? "s" : "") << ": " << smsp_cache_note << "\n";
      } else if(smsp_mib_per_vertex > 0 && 1.25 * smsp_mib_per_vertex * double(n) > mem_total_budget)
        smsp_skip = "SMSP skipped: predicted " + fmt(1.25 * smsp_mib_per_vertex * double(n), "%.0f") +
                    " MiB > the memory allowance " + fmt(mem_total_budget, "%.0f") + " MiB";

      for(int r = 0; r < runs; ++r)
        for(Method_kind m : methods) {
          if(m == CGAL_SMSP && (!smsp_skip.empty() || smsp_from_cache)) continue;
          // After a failure (crash, timeout) of a method, do not repeat it.
          if(!results[m].empty() && !results[m].back().ok) continue;
          const double started = mdcs_bench::now_seconds();
          Run_result res = run_forked<Run_header>(
            [&](Run_header& h, std::vector<double>& d) {
              if(m == CGAL_SMSP) run_smsp(mesh, sources, h, d);
              else run_mdcs(mesh, sources, m == MDCS_FULL ? PG::Geodesic_memory_mode::full_field
                                                           : PG::Geodesic_memory_mode::distances_only, h, d);
            },
            timeout_s, mem_total_budget);
          if(!res.ok) {
            if(res.failure.find("out of memory") != std::string::npos)
              res.failure += " within the allowance of " + fmt(mem_total_budget, "%.0f") + " MiB (--mem-limit-mib)";
            res.failure += " after " + fmt(mdcs_bench::now_seconds() - started, "%.0f") + " s";
          }
          std::cout << "  " << spec.name << ", " << k << " source" << (k > 1 ? "s" : "") << ", run " << r + 1 << ", "
                    << method_name(m) << ": "
                    << (res.ok ? fmt(res.header.time_s, "%.4g") + " s, " + fmt(res.header.peak_mib, "%.1f") + " MiB"
                               : "FAILED: " + res.failure)
                    << "\n" << std::flush;
          results[m].push_back(std::move(res));
        }
      if(smsp_skip.empty() && !smsp_cache.empty() && !smsp_from_cache) {
        std::error_code ec;
        std::filesystem::create_directories(smsp_cache, ec);
        const std::string file = cache_file(smsp_cache, spec.name, n, k);
        if(!save_smsp_cache(file, n, k, results[CGAL_SMSP])) std::cout << "  cannot write the SMSP cache " << file << "\n";
      }

      // Reference distances: the first successful SMSP run.
      const std::vector<double>* reference = nullptr;
      double smsp_time = nan_;
      {
        std::vector<double> t;
        for(const auto& res : results[CGAL_SMSP])
          if(res.ok) {
            if(!reference) reference = &res.distances;
            t.push_back(res.header.time_s);
          }
        if(!t.empty()) smsp_time = mdcs_bench::median(t);
      }
      const std::vector<double>* mdcs_distances_only = nullptr;
      for(const auto& res : results[MDCS_DISTANCES])
        if(res.ok) { mdcs_distances_only = &res.distances; break; }

      for(Method_kind m : methods) {
        Row_data row;
        row.mesh = spec.name;
        row.vertices = n;
        row.sources = k;
        row.method = m;
        if(m == CGAL_SMSP && !smsp_skip.empty()) {
          row.note = smsp_skip;
          rows.push_back(row);
          continue;
        }
        std::vector<double> times;
        const std::vector<double>* first = nullptr;
        std::size_t nondeterministic = 0;
        std::string failure;
        std::size_t failures = 0;
        for(const auto& res : results[m]) {
          if(!res.ok) {
            failure = res.failure;
            ++failures;
            continue;
          }
          times.push_back(res.header.time_s);
          row.peak_mib = std::isfinite(row.peak_mib) ? std::max(row.peak_mib, res.header.peak_mib) : res.header.peak_mib;
          row.setup_s = res.header.setup_s; // informative only: last run's
          row.engine_peak_mib = res.header.engine_peak_mib;
          row.windows_created = res.header.windows_created;
          row.windows_propagated = res.header.windows_propagated;
          row.peak_live_windows = res.header.peak_live_windows;
          if(!first) first = &res.distances;
          else if(res.distances.size() != first->size() ||
                  !std::equal(res.distances.begin(), res.distances.end(), first->begin(),
                              [](double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }))
            ++nondeterministic;
        }
        std::ostringstream note;
        if(m == CGAL_SMSP && smsp_from_cache) note << smsp_cache_note << "; ";
        if(!failure.empty())
          note << "FAILED in " << failures << " of " << results[m].size() << " runs (a failed method is not repeated): "
               << failure << "; ";
        row.ran = first != nullptr;
        if(row.ran) {
          row.time_s = mdcs_bench::median(times);
          row.sanity = sanity_check(mesh, sources, *first, tiny);
          if(nondeterministic) note << nondeterministic << " runs gave different distances than run 1; ";
          if(m == CGAL_SMSP) {
            row.has_reference = true;
            row.ratio = 1.0;
            row.max_rel_diff = 0.0;
            smsp_mib_per_vertex = std::max(smsp_mib_per_vertex, row.peak_mib / double(n));
          } else {
            if(reference) {
              row.has_reference = true;
              row.ratio = smsp_time / row.time_s;
              const Comparison c = compare(*first, *reference, tiny);
              row.max_rel_diff = c.max_rel;
              if(c.finiteness_mismatch)
                note << c.finiteness_mismatch << " vertices finite in one and not the other (e.g. v" << c.worst << ": "
                     << fmt(c.worst_value, "%.17g") << " vs SMSP " << fmt(c.worst_reference, "%.17g") << "); ";
              if(c.above_1e12)
                note << c.above_1e12 << " vertices differ by > 1e-12 (worst v" << c.worst << ": "
                     << fmt(c.worst_value, "%.17g") << " vs SMSP " << fmt(c.worst_reference, "%.17g") << "); ";
            }
            if(m == MDCS_FULL && mdcs_distances_only) {
              const Comparison c = compare(*first, *mdcs_distances_only, tiny);
              if(!(c.max_rel == 0)) note << "differs from distances_only by " << fmt(c.max_rel, "%.3g") << "; ";
            }
          }
        }
        row.note = note.str();
        if(row.note.size() >= 2) row.note.resize(row.note.size() - 2);
        rows.push_back(row);
      }
    }
  }

  // ---- the table
  mdcs_bench::Table table({"mesh", "vertices", "sources", "method", "time_s", "peak_MiB", "windows_created",
                           "peak_live_windows", "ratio_to_SMSP", "max_rel_diff_to_SMSP", "setup_s", "windows_propagated",
                           "engine_peak_MiB", "sanity", "note"});
  for(const Row_data& r : rows) {
    const bool mdcs = r.method != CGAL_SMSP;
    const bool failed = r.note.find("FAILED") != std::string::npos;
    std::string note = r.note;
    std::replace(note.begin(), note.end(), ',', ';');
    table.add_row({r.mesh, std::to_string(r.vertices), std::to_string(r.sources), method_name(r.method),
                   r.ran ? fmt_time(r.time_s) : failed ? "FAILED" : "skipped", r.ran ? fmt_mib(r.peak_mib) : "-",
                   mdcs && r.ran ? std::to_string(r.windows_created) : "-",
                   mdcs && r.ran ? std::to_string(r.peak_live_windows) : "-",
                   mdcs && r.ran && r.has_reference ? fmt(r.ratio, "%.3g") : "-",
                   mdcs && r.ran && r.has_reference ? fmt(r.max_rel_diff, "%.2e") : "-",
                   r.ran ? fmt_time(r.setup_s) : "-", mdcs && r.ran ? std::to_string(r.windows_propagated) : "-",
                   mdcs && r.ran ? fmt_mib(r.engine_peak_mib) : "-", r.sanity, note.empty() ? "-" : note});
  }
  std::cout << "\n";
  table.print();
  write_table_csv(table, csv);

  // ---- growth exponents
  std::cout << "\nGrowth exponents (least-squares slope of log(y) vs log(vertices), over the meshes where the method ran):\n";
  mdcs_bench::Table growth({"method", "sources", "meshes", "time_exponent", "peak_memory_exponent"});
  for(Method_kind m : {MDCS_DISTANCES, MDCS_FULL, CGAL_SMSP})
    for(std::size_t k : source_counts) {
      std::vector<std::pair<double, double>> t, p;
      for(const Row_data& r : rows)
        if(r.method == m && r.sources == k && r.ran) {
          t.emplace_back(double(r.vertices), r.time_s);
          p.emplace_back(double(r.vertices), r.peak_mib);
        }
      std::size_t ut = 0, up = 0;
      const double st = loglog_slope(t, ut), sp = loglog_slope(p, up);
      growth.add_row({method_name(m), std::to_string(k), std::to_string(ut),
                      std::isfinite(st) ? fmt(st, "%.2f") : "n/a", std::isfinite(sp) ? fmt(sp, "%.2f") : "n/a"});
    }
  growth.print();

  // ---- goal check
  auto find = [&](const std::string& mesh, std::size_t k, Method_kind m) -> const Row_data* {
    for(const Row_data& r : rows)
      if(r.mesh == mesh && r.sources == k && r.method == m) return &r;
    return nullptr;
  };
  const double MB = 1e6 / (1024.0 * 1024.0); // MiB per MB
  auto verdict = [](bool known, bool pass) { return !known ? std::string("n/a ") : pass ? std::string("PASS") : std::string("MISS"); };
  // A goal on time or memory counts only for correct distances: sane and, where SMSP ran, within 1e-12 of it.
  auto correct = [](const Row_data* r) { return r->sanity == "ok" && (!r->has_reference || r->max_rel_diff <= 1e-12); };
  auto caveat = [&](const Row_data* r) {
    return correct(r) ? std::string() : std::string(" (counted as MISS: the distances are wrong: sanity ") + r->sanity +
                                          ", max_rel_diff " + fmt(r->max_rel_diff, "%.2e") + ")";
  };
  std::cout << "\nGoal check (1 source, vertex 0; memory in MB = 10^6 bytes):\n";
  {
    const Row_data* d = find("refined_elephant", 1, MDCS_DISTANCES);
    const Row_data* f = find("refined_elephant", 1, MDCS_FULL);
    const bool dk = d && d->ran, fk = f && f->ran;
    std::cout << "  [" << verdict(dk, dk && correct(d) && d->time_s <= 0.3)
              << "] refined_elephant (44k): MDCS distances_only time <= 0.3 s: "
              << (dk ? fmt(d->time_s, "%.4g") + " s" + caveat(d) : "not measured") << "\n";
    if(fk) std::cout << "         (full_field time: " << fmt(f->time_s, "%.4g") << " s)\n";
    const bool rk = dk && d->has_reference;
    std::cout << "  [" << verdict(rk, rk && correct(d) && d->ratio >= 30) << "] refined_elephant (44k): SMSP time / MDCS time >= 30: "
              << (rk ? fmt(d->ratio, "%.3g") + caveat(d) : "not measured") << "\n";
    std::cout << "  [" << verdict(dk, dk && correct(d) && d->peak_mib / MB <= 70)
              << "] refined_elephant (44k): peak memory distances_only <= 70 MB: "
              << (dk ? fmt(d->peak_mib / MB, "%.1f") + " MB" + caveat(d) : "not measured") << "\n";
    std::cout << "  [" << verdict(fk, fk && correct(f) && f->peak_mib / MB <= 200)
              << "] refined_elephant (44k): peak memory full_field <= 200 MB: "
              << (fk ? fmt(f->peak_mib / MB, "%.1f") + " MB" + caveat(f) : "not measured") << "\n";
  }
  {
    // "~100k": the mesh closest to 100k vertices among those measured against SMSP (armadillo-loop1 by default).
    const Row_data* best = nullptr;
    for(const Row_data& r : rows)
      if(r.sources == 1 && r.method == MDCS_DISTANCES && r.ran && r.has_reference && r.vertices >= 70000 && r.vertices <= 140000)
        if(!best || std::abs(double(r.vertices) - 1e5) < std::abs(double(best->vertices) - 1e5)) best = &r;
    std::cout << "  [" << verdict(best != nullptr, best && correct(best) && best->ratio >= 30)
              << "] ~100k vertices: SMSP time / MDCS time >= 30: "
              << (best ? best->mesh + " (" + std::to_string(best->vertices) + "): " + fmt(best->ratio, "%.3g") + caveat(best)
                       : "no mesh of 70k-140k vertices measured with SMSP")
              << "\n";
  }
  {
    double worst = 0;
    std::size_t compared = 0;
    std::string where;
    for(const Row_data& r : rows)
      if(r.method != CGAL_SMSP && r.ran && r.has_reference) {
        ++compared;
        if(!(r.max_rel_diff <= worst)) {
          worst = r.max_rel_diff;
          where = r.mesh + ", " + std::to_string(r.sources) + " sources, " + method_name(r.method);
        }
      }
    std::cout << "  [" << verdict(compared > 0, compared > 0 && worst <= 1e-12)
              << "] max relative difference to SMSP <= 1e-12 everywhere: " << fmt(worst, "%.2e") << " over " << compared
              << " comparisons" << (where.empty() ? "" : " (worst: " + where + ")") << "\n";
  }
  {
    std::size_t failed = 0, insane = 0;
    for(const Row_data& r : rows) {
      if(r.note.find("FAILED") != std::string::npos) ++failed;
      if(r.ran && r.sanity != "ok") ++insane;
    }
    std::cout << "  [" << (failed ? "MISS" : "PASS") << "] no crash, timeout or exception: " << failed << " failing rows\n";
    std::cout << "  [" << (insane ? "MISS" : "PASS") << "] sanity (finite, >= Euclidean distance, 1-Lipschitz on edges): "
              << insane << " rows with violations\n";
  }
  return 0;
}
