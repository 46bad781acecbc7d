// Approximate geodesic distances against exact ones, in the layout of the thesis's Table 4.4: for every mesh, one
// random source vertex (fixed seed), and for every method the median time of --runs runs and the mean relative
// error E (thesis eq. 4.4.1) of the distances at all vertices against Exact_geodesic_distances_3:
//   Dijkstra on the edges, fast marching (Kimmel-Sethian), CGAL's heat method (Direct and Intrinsic Delaunay),
//   flat-exact, merged windows at several tolerances, and exact.
//
//   bench_approximate_geodesics [--meshes a,b,c] [--runs N] [--methods LIST] [--tolerances T1,T2,...] [--seed S]
//                               [--skip-exact-above N] [--mesh-dir DIR] [--extra-dir DIR] [--timeout S]
//                               [--mem-limit-mib M] [--path-error K] [--csv FILE] [--list]
//
// --path-error K also measures E the way the thesis's Table 4.4 defines it: from the length of the shortest path
// each approximate method traces (Dijkstra, fast marching, flat-exact, merged) to K random vertices, against the
// exact distance; once as traced, once made locally shortest (set_path_shortening(true)). In this process, in
// full_field mode (paths need the field), outside the timed runs; the mean time per path of both is reported.
//
// Every run of every method is a forked child process (see geodesic_bench_common.h and benchmark/README.md):
// time measured inside the child, peak memory = the child's peak RSS minus its RSS when the method starts.
#include <geodesic_bench_common.h>
#include <mdcs_bench.h>

#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Dijkstra_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Exact_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Fast_marching_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Flat_exact_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Merged_window_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/geodesic_distance_error.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace PG = CGAL::Polyhedral_geodesics_3;
using mdcs_bench::fmt;

namespace {

using namespace geodesic_bench; // Mesh, Vertex, inf, nan_, run_forked, Mesh_spec, load_mesh, ...

struct Run_header
{
  std::int32_t ok = 0;
  double time_s = nan_;  // construction + source + propagation + all vertex distances (heat: the first solve,
                         // precomputation included)
  double setup_s = nan_; // construction (heat: the precomputation: matrices, factorisations, intrinsic Delaunay)
  double solve_s = nan_; // time_s - setup_s (heat: the solve alone, what a second source would cost)
  double peak_mib = nan_;
  double engine_peak_mib = nan_; // Geodesic_statistics::peak_memory_bytes (window methods)
  std::uint64_t windows_created = 0, windows_merged = 0, vertex_updates = 0, dag_rejections = 0;
  std::uint64_t number_of_distances = 0;
  char error[512] = {0};
};
typedef Forked_result<Run_header> Run_result;

enum Method_kind { DIJKSTRA, FMM, HEAT, HEAT_IDT, FLAT, MERGED, EXACT };

struct Method
{
  Method_kind kind;
  double eps = 0; // MERGED: tolerance in mean edge lengths
  std::string name() const
  {
    switch(kind) {
    case DIJKSTRA: return "Dijkstra";
    case FMM: return "FMM";
    case HEAT: return "heat";
    case HEAT_IDT: return "heat-IDT";
    case FLAT: return "flat-exact";
    case MERGED: return "merged:" + fmt(eps, "%g");
    case EXACT: return "exact";
    }
    return "?";
  }
  bool is_heat() const { return kind == HEAT || kind == HEAT_IDT; }
};

template <class Geodesics>
void fill_statistics(const Geodesics& g, Run_header& h)
{
  const PG::Geodesic_statistics& st = g.statistics();
  h.windows_created = st.windows_created;
  h.windows_merged = st.windows_merged;
  h.vertex_updates = st.vertex_updates;
  h.dag_rejections = st.updates_rejected_by_dag;
  h.engine_peak_mib = double(st.peak_memory_bytes) / (1024.0 * 1024.0);
}

// One class of the package, distances_only: construction, source, propagation, every vertex distance.
template <class Geodesics, class Make>
void run_class(Make make, const Mesh& mesh, Vertex source, Run_header& h, std::vector<double>& distances)
{
  const double t0 = mdcs_bench::now_seconds();
  Geodesics geodesics = make();
  const double t1 = mdcs_bench::now_seconds();
  geodesics.add_source(source);
  geodesics.compute();
  distances.assign(mesh.number_of_vertices(), nan_);
  geodesics.distances(Distance_vector_map{&distances});
  const double t2 = mdcs_bench::now_seconds();
  h.time_s = t2 - t0;
  h.setup_s = t1 - t0;
  h.solve_s = t2 - t1;
  fill_statistics(geodesics, h);
}

// CGAL's heat method: the precomputation (constructor) and the first solve.
template <class Mode>
void run_heat(const Mesh& mesh, Vertex source, Run_header& h, std::vector<double>& distances)
{
  typedef CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<Mesh, Mode> Heat;
  const double t0 = mdcs_bench::now_seconds();
  Heat heat(mesh);
  heat.add_source(source);
  const double t1 = mdcs_bench::now_seconds();
  distances.assign(mesh.number_of_vertices(), nan_);
  heat.estimate_geodesic_distances(Distance_vector_map{&distances});
  const double t2 = mdcs_bench::now_seconds();
  h.time_s = t2 - t0;
  h.setup_s = t1 - t0;
  h.solve_s = t2 - t1;
}

void run_method(const Method& m, const Mesh& mesh, Vertex source, double mean_edge, Run_header& h, std::vector<double>& d)
{
  const PG::Geodesic_memory_mode mode = PG::Geodesic_memory_mode::distances_only;
  switch(m.kind) {
  case DIJKSTRA:
    run_class<PG::Dijkstra_geodesic_distances_3<Mesh>>([&] { return PG::Dijkstra_geodesic_distances_3<Mesh>(mesh, mode); },
                                                       mesh, source, h, d);
    break;
  case FMM:
    run_class<PG::Fast_marching_geodesic_distances_3<Mesh>>(
      [&] { return PG::Fast_marching_geodesic_distances_3<Mesh>(mesh, mode); }, mesh, source, h, d);
    break;
  case HEAT:
    run_heat<CGAL::Heat_method_3::Direct>(mesh, source, h, d);
    break;
  case HEAT_IDT:
    run_heat<CGAL::Heat_method_3::Intrinsic_Delaunay>(mesh, source, h, d);
    break;
  case FLAT:
    run_class<PG::Flat_exact_geodesic_distances_3<Mesh>>([&] { return PG::Flat_exact_geodesic_distances_3<Mesh>(mesh, mode); },
                                                         mesh, source, h, d);
    break;
  case MERGED:
    run_class<PG::Merged_window_geodesic_distances_3<Mesh>>(
      [&] { return PG::Merged_window_geodesic_distances_3<Mesh>(mesh, m.eps * mean_edge, mode); }, mesh, source, h, d);
    break;
  case EXACT:
    run_class<PG::Exact_geodesic_distances_3<Mesh>>([&] { return PG::Exact_geodesic_distances_3<Mesh>(mesh, mode); },
                                                    mesh, source, h, d);
    break;
  }
}

struct Cell // one (mesh, method) result
{
  std::string mesh;
  std::size_t vertices = 0, faces = 0, boundary_edges = 0, components = 0, source = 0;
  double mean_edge = nan_;
  Method method{EXACT, 0};
  bool ran = false;
  bool is_reference = false;
  std::string reference; // "exact", "merged:1e-4 (exact skipped)", "" when none
  std::string note;
  std::size_t runs_ok = 0;
  double time_s = nan_, setup_s = nan_, solve_s = nan_, peak_mib = nan_;
  Run_header last;
  PG::Geodesic_distance_error error;
  bool has_error = false;
  double path_error = nan_;      // --path-error: mean relative error of the traced path lengths
  double shortened_path_error = nan_; // the same paths made locally shortest
  double path_us = nan_, shortened_path_us = nan_; // mean time per path, traced / traced and shortened
  std::size_t paths_measured = 0;
};

std::string pct(double e) { return std::isfinite(e) ? fmt(100 * e, "%.3g") : "-"; }

struct Path_error
{
  double traced = nan_, shortened = nan_; // mean relative error of the path lengths
  double traced_us = nan_, shortened_us = nan_; // mean microseconds per path
  std::size_t measured = 0;
};

// The thesis's eq. 4.4.1 taken literally: the mean over `count` random vertices (not the source, reachable in
// `reference`) of |length of the traced path - reference| / reference. One run in full_field mode; the same
// paths traced as the method gives them, then made locally shortest.
template <class Geodesics, class Make>
Path_error traced_path_error(Make make, Vertex source, const std::vector<double>& reference,
                             std::size_t count, std::uint64_t seed)
{
  Geodesics geodesics = make();
  geodesics.add_source(source);
  geodesics.compute();
  std::vector<std::size_t> candidates;
  for(std::size_t i = 0; i < reference.size(); ++i)
    if(std::isfinite(reference[i]) && reference[i] > 0) candidates.push_back(i);
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + 7);
  const std::size_t k = std::min(count, candidates.size());
  for(std::size_t i = 0; i < k; ++i) // partial Fisher-Yates: the first k are a uniform sample
    std::swap(candidates[i], candidates[i + std::size_t(rng() % (candidates.size() - i))]);
  Path_error result;
  std::vector<Mesh::Point> points;
  for(int shortened = 0; shortened < 2; ++shortened) {
    geodesics.set_path_shortening(shortened == 1);
    double sum = 0;
    std::size_t measured = 0;
    const auto start = std::chrono::steady_clock::now();
    for(std::size_t i = 0; i < k; ++i) {
      const Vertex v(Mesh::size_type(candidates[i]));
      points.clear();
      geodesics.shortest_path_points(v, std::back_inserter(points));
      double length = 0;
      for(std::size_t j = 1; j < points.size(); ++j) length += std::sqrt(CGAL::squared_distance(points[j - 1], points[j]));
      if(points.empty() || !std::isfinite(length)) continue;
      sum += std::abs(length - reference[candidates[i]]) / reference[candidates[i]];
      ++measured;
    }
    const double us = 1e6 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if(measured == 0) continue;
    (shortened ? result.shortened : result.traced) = sum / double(measured);
    (shortened ? result.shortened_us : result.traced_us) = us / double(k);
    result.measured = measured;
  }
  return result;
}

Path_error traced_path_error(const Method& m, const Mesh& mesh, Vertex source, double mean_edge,
                             const std::vector<double>& reference, std::size_t count, std::uint64_t seed)
{
  const PG::Geodesic_memory_mode mode = PG::Geodesic_memory_mode::full_field;
  switch(m.kind) {
  case DIJKSTRA:
    return traced_path_error<PG::Dijkstra_geodesic_distances_3<Mesh>>(
      [&] { return PG::Dijkstra_geodesic_distances_3<Mesh>(mesh, mode); }, source, reference, count, seed);
  case FMM:
    return traced_path_error<PG::Fast_marching_geodesic_distances_3<Mesh>>(
      [&] { return PG::Fast_marching_geodesic_distances_3<Mesh>(mesh, mode); }, source, reference, count, seed);
  case FLAT:
    return traced_path_error<PG::Flat_exact_geodesic_distances_3<Mesh>>(
      [&] { return PG::Flat_exact_geodesic_distances_3<Mesh>(mesh, mode); }, source, reference, count, seed);
  case MERGED:
    return traced_path_error<PG::Merged_window_geodesic_distances_3<Mesh>>(
      [&] { return PG::Merged_window_geodesic_distances_3<Mesh>(mesh, m.eps * mean_edge, mode); }, source, reference, count,
      seed);
  default:
    return Path_error(); // heat: no paths; exact: the reference itself
  }
}
std::string fmt_time(double t) { return std::isfinite(t) ? fmt(t, "%.3g") : "-"; }

void usage()
{
  std::cerr << "usage: bench_approximate_geodesics [--meshes a,b,c] [--runs N] [--methods LIST] [--tolerances T1,T2,...]\n"
               "         [--seed S] [--skip-exact-above N] [--mesh-dir DIR] [--extra-dir DIR] [--timeout S]\n"
               "         [--mem-limit-mib M] [--path-error K] [--csv FILE] [--list]\n"
               "  methods: dijkstra fmm heat heat-idt flat-exact merged exact (default: all)\n"
               "  tolerances of merged, in mean edge lengths (default 0.1,0.01,0.001,0.0001)\n"
               "  --path-error K: also E of the traced path lengths to K random vertices (thesis Table 4.4), as traced and\n"
               "                  made locally shortest, with the mean time per path (outside the timed runs)\n"
               "  built-in meshes: ChineseDragon-10kv mannequin-devil armadillo bunny00 refined_elephant\n"
               "                   mannequin-devil-loop1 armadillo-loop1 bunny00-loop1 bunny00-loop2\n";
}

} // namespace

int main(int argc, char** argv)
{
  Common_options o;
  o.csv = "approximate_geodesics.csv";
  std::set<std::string> method_names = {"dijkstra", "fmm", "heat", "heat-idt", "flat-exact", "merged", "exact"};
  std::vector<double> tolerances = {1e-1, 1e-2, 1e-3, 1e-4};
  std::uint64_t seed = 1;
  // every built-in mesh: the exact class (distances_only) took 21 s and 254 MiB at 603k vertices
  std::size_t skip_exact_above = 1000000;
  std::size_t path_error_count = 0;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if(o.parse(argc, argv, i)) continue;
    if(a == "--methods" && has_value) {
      const std::vector<std::string> wanted = split(argv[++i], ',');
      for(const std::string& w : wanted)
        if(!method_names.count(w)) {
          std::cerr << "unknown method '" << w << "'\n";
          usage();
          return 2;
        }
      method_names = std::set<std::string>(wanted.begin(), wanted.end());
    } else if(a == "--tolerances" && has_value) {
      tolerances.clear();
      for(const std::string& t : split(argv[++i], ',')) {
        char* end = nullptr;
        const double v = std::strtod(t.c_str(), &end);
        if(*end != '\0' || !(v >= 0) || !std::isfinite(v)) {
          std::cerr << "bad tolerance '" << t << "'\n";
          usage();
          return 2;
        }
        tolerances.push_back(v);
      }
      std::sort(tolerances.rbegin(), tolerances.rend()); // from the coarsest to the finest
    } else if(a == "--seed" && has_value) seed = std::strtoull(argv[++i], nullptr, 10);
    else if(a == "--skip-exact-above" && has_value) skip_exact_above = std::strtoul(argv[++i], nullptr, 10);
    else if(a == "--path-error" && has_value) path_error_count = std::strtoul(argv[++i], nullptr, 10);
    else {
      usage();
      return 2;
    }
  }

  // ---- the meshes: CGAL's demo meshes (mannequin-devil has boundary: 64 boundary edges in 3 holes), their
  // Loop subdivisions, and --extra-dir.
  const std::vector<Mesh_spec> builtin = {
    {"ChineseDragon-10kv", o.in_mesh_dir("ChineseDragon-10kv.off"), 0},
    {"mannequin-devil", o.in_mesh_dir("mannequin-devil.off"), 0},
    {"armadillo", o.in_mesh_dir("armadillo.off"), 0},
    {"bunny00", o.in_mesh_dir("bunny00.off"), 0},
    {"refined_elephant", o.in_mesh_dir("refined_elephant.off"), 0},
    {"mannequin-devil-loop1", o.in_mesh_dir("mannequin-devil.off"), 1},
    {"armadillo-loop1", o.in_mesh_dir("armadillo.off"), 1},
    {"bunny00-loop1", o.in_mesh_dir("bunny00.off"), 1},
    {"bunny00-loop2", o.in_mesh_dir("bunny00.off"), 2}};
  std::vector<Mesh_spec> specs;
  if(const int exit_code = select_or_list_meshes(builtin, o, specs, usage); exit_code >= 0)
    return exit_code;

  // ---- the methods, in the columns' order
  std::vector<Method> methods;
  if(method_names.count("dijkstra")) methods.push_back({DIJKSTRA, 0});
  if(method_names.count("fmm")) methods.push_back({FMM, 0});
  if(method_names.count("heat")) methods.push_back({HEAT, 0});
  if(method_names.count("heat-idt")) methods.push_back({HEAT_IDT, 0});
  if(method_names.count("flat-exact")) methods.push_back({FLAT, 0});
  if(method_names.count("merged"))
    for(double t : tolerances) methods.push_back({MERGED, t});
  if(method_names.count("exact")) methods.push_back({EXACT, 0});

  const double mem_total_budget = o.memory_allowance_mib();
  std::cout << "Approximate geodesic distances from one random source vertex (seed " << seed << ") to all vertices.\n"
            << "time: median of " << o.runs << " runs, seconds: construction + source + propagation + all vertex distances"
               " (classes of CGAL::Polyhedral_geodesics_3 in distances_only mode); for CGAL::Heat_method_3 the first solve"
               " including the precomputation (solve-only time in the CSV).\n"
            << "E: mean relative error (thesis eq. 4.4.1) over the vertices at positive distance, in percent, against "
               "Exact_geodesic_distances_3 (on meshes above " << skip_exact_above
            << " vertices (--skip-exact-above) against the finest merged tolerance, marked 'ref').\n"
            << "merged:T = Merged_window_geodesic_distances_3 with tolerance T x mean edge length.\n"
            << "Each run is a separate child process with a " << fmt(o.timeout_s, "%.0f") << " s limit and a "
            << fmt(mem_total_budget, "%.0f") << " MiB address-space allowance. Mesh folder: "
            << (o.mesh_dir.empty() ? "(none)" : o.mesh_dir) << "\n\n";

  std::vector<std::vector<Cell>> table_rows; // per mesh, per method
  for(const Mesh_spec& spec : specs) {
    Mesh mesh;
    std::string message;
    const double tl = mdcs_bench::now_seconds();
    if(!load_mesh(spec, mesh, message)) {
      std::cout << "skipping " << spec.name << ": " << message << "\n" << std::flush;
      continue;
    }
    const std::size_t n = mesh.number_of_vertices();
    const double mean_edge = average_edge_length(mesh);
    const std::size_t boundary = count_boundary_edges(mesh);
    const std::size_t components = count_components(mesh);
    std::mt19937_64 rng(seed); // the same draw on every machine: first number modulo n
    const Vertex source(Mesh::size_type(rng() % n));
    std::cout << spec.name << ": " << n << " vertices, " << mesh.number_of_faces() << " faces"
              << (message.empty() ? "" : " (" + message + ")") << ", mean edge " << fmt(mean_edge, "%.4g") << ", source vertex "
              << std::size_t(source) << ", loaded in " << fmt(mdcs_bench::now_seconds() - tl, "%.2f") << " s\n" << std::flush;

    const bool skip_exact = n > skip_exact_above;
    std::vector<std::vector<Run_result>> results(methods.size());
    for(int r = 0; r < o.runs; ++r)
      for(std::size_t k = 0; k < methods.size(); ++k) {
        const Method& m = methods[k];
        if(m.kind == EXACT && skip_exact) continue;
        if(!results[k].empty() && !results[k].back().ok) continue; // a failed method is not repeated
        const double started = mdcs_bench::now_seconds();
        Run_result res = run_forked<Run_header>(
          [&](Run_header& h, std::vector<double>& d) { run_method(m, mesh, source, mean_edge, h, d); }, o.timeout_s,
          mem_total_budget);
        if(!res.ok) {
          if(res.failure.find("out of memory") != std::string::npos)
            res.failure += " within the allowance of " + fmt(mem_total_budget, "%.0f") + " MiB (--mem-limit-mib)";
          res.failure += " after " + fmt(mdcs_bench::now_seconds() - started, "%.0f") + " s";
        }
        std::cout << "  " << spec.name << ", run " << r + 1 << ", " << m.name() << ": "
                  << (res.ok ? fmt(res.header.time_s, "%.4g") + " s, " + fmt(res.header.peak_mib, "%.1f") + " MiB"
                             : "FAILED: " + res.failure)
                  << "\n" << std::flush;
        results[k].push_back(std::move(res));
      }

    // The reference distances: exact, else the finest merged tolerance that ran.
    const std::vector<double>* reference = nullptr;
    std::string reference_name;
    std::size_t reference_index = methods.size();
    auto first_ok = [&](std::size_t k) -> const std::vector<double>* {
      for(const Run_result& res : results[k])
        if(res.ok) return &res.distances;
      return nullptr;
    };
    for(std::size_t k = 0; k < methods.size(); ++k)
      if(methods[k].kind == EXACT && first_ok(k)) reference = first_ok(k), reference_name = "exact", reference_index = k;
    if(!reference)
      for(std::size_t k = methods.size(); k-- > 0;)
        if(methods[k].kind == MERGED && first_ok(k)) {
          reference = first_ok(k);
          reference_name = methods[k].name() + " (exact " + (skip_exact ? "skipped" : "failed") + ")";
          reference_index = k;
          break;
        }

    std::vector<Cell> row;
    for(std::size_t k = 0; k < methods.size(); ++k) {
      Cell c;
      c.mesh = spec.name;
      c.vertices = n;
      c.faces = mesh.number_of_faces();
      c.boundary_edges = boundary;
      c.components = components;
      c.source = std::size_t(source);
      c.mean_edge = mean_edge;
      c.method = methods[k];
      c.reference = reference_name;
      c.is_reference = k == reference_index;
      std::ostringstream note;
      if(methods[k].kind == EXACT && skip_exact) note << "skipped: " << n << " vertices > --skip-exact-above " << skip_exact_above << "; ";
      std::vector<double> times, setups, solves;
      const std::vector<double>* first = nullptr;
      std::size_t nondeterministic = 0, failures = 0;
      std::string failure;
      for(const Run_result& res : results[k]) {
        if(!res.ok) {
          ++failures;
          failure = res.failure;
          continue;
        }
        ++c.runs_ok;
        times.push_back(res.header.time_s);
        setups.push_back(res.header.setup_s);
        solves.push_back(res.header.solve_s);
        c.peak_mib = std::isfinite(c.peak_mib) ? std::max(c.peak_mib, res.header.peak_mib) : res.header.peak_mib;
        c.last = res.header;
        if(!first) first = &res.distances;
        else if(res.distances.size() != first->size() ||
                !std::equal(res.distances.begin(), res.distances.end(), first->begin(),
                            [](double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }))
          ++nondeterministic;
      }
      if(failures) note << "FAILED in " << failures << " of " << results[k].size() << " runs: " << failure << "; ";
      if(nondeterministic) note << nondeterministic << " runs gave other distances than the first; ";
      c.ran = first != nullptr;
      if(c.ran) {
        c.time_s = mdcs_bench::median(times);
        c.setup_s = mdcs_bench::median(setups);
        c.solve_s = mdcs_bench::median(solves);
        if(reference) {
          const auto index = get(boost::vertex_index, mesh);
          c.error = PG::geodesic_distance_error(mesh, boost::make_iterator_property_map(first->cbegin(), index),
                                                boost::make_iterator_property_map(reference->cbegin(), index));
          c.has_error = true;
          if(c.error.unreachable_mismatches) note << c.error.unreachable_mismatches << " vertices reachable in one only; ";
          if(path_error_count > 0 && !c.is_reference) {
            const Path_error pe = traced_path_error(methods[k], mesh, source, mean_edge, *reference, path_error_count, seed);
            c.path_error = pe.traced;
            c.shortened_path_error = pe.shortened;
            c.path_us = pe.traced_us;
            c.shortened_path_us = pe.shortened_us;
            c.paths_measured = pe.measured;
            if(std::isfinite(c.path_error))
              std::cout << "  " << spec.name << ", " << methods[k].name() << ": E of traced path lengths "
                        << pct(c.path_error) << "% (" << fmt(c.path_us, "%.3g") << " us/path), locally shortest "
                        << pct(c.shortened_path_error) << "% (" << fmt(c.shortened_path_us, "%.3g") << " us/path; "
                        << c.paths_measured << " paths)\n" << std::flush;
          }
        }
      }
      c.note = note.str();
      if(c.note.size() >= 2) c.note.resize(c.note.size() - 2);
      row.push_back(c);
    }
    table_rows.push_back(row);
  }

  // ---- Table 4.4: time (s) / E (%)
  std::cout << "\nTime (s) / E (%), thesis Table 4.4 layout. 'ref': the reference of E on that mesh; '*': E against the finest "
               "merged tolerance (exact not run).\n";
  std::vector<std::string> header = {"model (vertices)", "boundary"};
  for(const Method& m : methods) header.push_back(m.name());
  mdcs_bench::Table main_table(header);
  for(const auto& row : table_rows) {
    std::vector<std::string> line = {row.front().mesh + " (" + std::to_string(row.front().vertices) + ")",
                                     std::to_string(row.front().boundary_edges)};
    for(const Cell& c : row) {
      if(!c.ran) line.push_back(c.note.find("FAILED") != std::string::npos ? "FAILED" : "-");
      else if(c.is_reference) line.push_back(fmt_time(c.time_s) + "/ref");
      else line.push_back(fmt_time(c.time_s) + "/" + (c.has_error ? pct(c.error.mean_relative) : "-") +
                          (c.has_error && c.reference != "exact" ? "*" : ""));
    }
    main_table.add_row(line);
  }
  main_table.print();

  std::cout << "\nPeak memory (MiB, max over the runs; the child's peak RSS minus its RSS at the start):\n";
  std::vector<std::string> mem_header = {"model"};
  for(const Method& m : methods) mem_header.push_back(m.name());
  mdcs_bench::Table mem_table(mem_header);
  for(const auto& row : table_rows) {
    std::vector<std::string> line = {row.front().mesh};
    for(const Cell& c : row) line.push_back(c.ran ? fmt(c.peak_mib, "%.1f") : "-");
    mem_table.add_row(line);
  }
  mem_table.print();

  if(path_error_count > 0) {
    std::cout << "\nE of traced path lengths (%), thesis Table 4.4's measure (eq. 4.4.1 with the length of each method's "
                 "path), on up to " << path_error_count << " random vertices:\n";
    mdcs_bench::Table path_table(mem_header);
    for(const auto& row : table_rows) {
      std::vector<std::string> line = {row.front().mesh};
      for(const Cell& c : row)
        line.push_back(std::isfinite(c.path_error) ? pct(c.path_error) + " / " + pct(c.shortened_path_error) : "-");
      path_table.add_row(line);
    }
    std::cout << "(traced / made locally shortest)\n";
    path_table.print();
  }

  std::cout << "\nMaximum relative error (%) against the reference:\n";
  mdcs_bench::Table max_table(mem_header);
  for(const auto& row : table_rows) {
    std::vector<std::string> line = {row.front().mesh};
    for(const Cell& c : row) line.push_back(c.ran && c.has_error && !c.is_reference ? pct(c.error.max_relative) : "-");
    max_table.add_row(line);
  }
  max_table.print();

  // ---- the CSV: one row per mesh and method
  mdcs_bench::Table csv_table({"mesh", "vertices", "faces", "boundary_edges", "components", "source_vertex", "mean_edge",
                               "method", "tolerance_edges", "tolerance_abs", "time_s", "setup_s", "solve_s", "peak_MiB",
                               "E_mean_rel_pct", "E_max_rel_pct", "max_abs_err", "compared", "unreachable_mismatches",
                               "reference", "runs_ok", "windows_created", "windows_merged", "vertex_updates",
                               "dag_rejections", "note", "E_path_pct", "paths_measured",
                               "E_path_shortened_pct", "path_us", "shortened_path_us"});
  for(const auto& row : table_rows)
    for(const Cell& c : row) {
      std::string note = c.note;
      std::replace(note.begin(), note.end(), ',', ';');
      std::string reference = c.reference;
      std::replace(reference.begin(), reference.end(), ',', ';');
      const bool merged = c.method.kind == MERGED;
      const bool e = c.ran && c.has_error;
      csv_table.add_row({c.mesh, std::to_string(c.vertices), std::to_string(c.faces), std::to_string(c.boundary_edges),
                         std::to_string(c.components), std::to_string(c.source), fmt(c.mean_edge, "%.6g"), c.method.name(),
                         merged ? fmt(c.method.eps, "%g") : "", merged ? fmt(c.method.eps * c.mean_edge, "%.6g") : "",
                         c.ran ? fmt(c.time_s, "%.6g") : "", c.ran ? fmt(c.setup_s, "%.6g") : "",
                         c.ran ? fmt(c.solve_s, "%.6g") : "", c.ran ? fmt(c.peak_mib, "%.1f") : "",
                         e ? fmt(100 * c.error.mean_relative, "%.6g") : "", e ? fmt(100 * c.error.max_relative, "%.6g") : "",
                         e ? fmt(c.error.max_absolute, "%.6g") : "", e ? std::to_string(c.error.compared) : "",
                         e ? std::to_string(c.error.unreachable_mismatches) : "", c.is_reference ? "self" : reference,
                         std::to_string(c.runs_ok), c.ran ? std::to_string(c.last.windows_created) : "",
                         c.ran ? std::to_string(c.last.windows_merged) : "", c.ran ? std::to_string(c.last.vertex_updates) : "",
                         c.ran ? std::to_string(c.last.dag_rejections) : "", note,
                         std::isfinite(c.path_error) ? fmt(100 * c.path_error, "%.6g") : "",
                         c.paths_measured ? std::to_string(c.paths_measured) : "",
                         std::isfinite(c.shortened_path_error) ? fmt(100 * c.shortened_path_error, "%.6g") : "",
                         std::isfinite(c.path_us) ? fmt(c.path_us, "%.4g") : "",
                         std::isfinite(c.shortened_path_us) ? fmt(c.shortened_path_us, "%.4g") : ""});
    }
  write_table_csv(csv_table, o.csv);

  // ---- the goals: flat-exact E <= 0.2% at <= 2x fast marching and <= 0.15x the heat method's first solve;
  // merged: a monotone trade-off between flat-exact and exact.
  auto find = [&](const std::vector<Cell>& row, Method_kind kind) -> const Cell* {
    for(const Cell& c : row)
      if(c.method.kind == kind && c.ran) return &c;
    return nullptr;
  };
  auto verdict = [](bool known, bool pass) { return !known ? std::string("n/a") : pass ? std::string("PASS") : std::string("MISS"); };
  std::cout << "\nGoals per mesh (flat-exact: E <= 0.2%, time <= 2 x FMM, time <= 0.15 x heat first solve (Direct); merged: E "
               "non-increasing as the tolerance shrinks):\n";
  mdcs_bench::Table goals({"model", "flat_E%", "E<=0.2%", "flat/FMM", "<=2", "flat/heat", "<=0.15", "flat/heat-IDT",
                           "merged_E%_coarse..fine", "merged_time_s_coarse..fine", "monotone"});
  std::size_t misses = 0, passes = 0;
  for(const auto& row : table_rows) {
    const Cell* flat = find(row, FLAT);
    const Cell* fmm = find(row, FMM);
    const Cell* heat = find(row, HEAT);
    const Cell* heat_idt = find(row, HEAT_IDT);
    const bool ek = flat && flat->has_error && !flat->is_reference;
    const bool e_ok = ek && flat->error.mean_relative <= 0.002 && flat->error.unreachable_mismatches == 0;
    const double r_fmm = flat && fmm ? flat->time_s / fmm->time_s : nan_;
    const double r_heat = flat && heat ? flat->time_s / heat->time_s : nan_;
    const double r_idt = flat && heat_idt ? flat->time_s / heat_idt->time_s : nan_;
    std::string merged_e, merged_t;
    bool monotone = true, any_merged = false;
    double previous = inf;
    for(const Cell& c : row)
      if(c.method.kind == MERGED && c.ran) {
        any_merged = true;
        const double e = c.has_error ? c.error.mean_relative : nan_;
        merged_e += (merged_e.empty() ? "" : " ") + (c.is_reference ? std::string("ref") : pct(e));
        merged_t += (merged_t.empty() ? "" : " ") + fmt_time(c.time_s);
        if(c.has_error && !c.is_reference) {
          if(e > previous * (1 + 1e-9) + 1e-15) monotone = false;
          previous = e;
        }
      }
    for(bool pass : {e_ok, std::isfinite(r_fmm) && r_fmm <= 2, std::isfinite(r_heat) && r_heat <= 0.15}) {
      if(pass) ++passes;
      else ++misses;
    }
    goals.add_row({row.front().mesh, ek ? pct(flat->error.mean_relative) : "-", verdict(ek, e_ok),
                   std::isfinite(r_fmm) ? fmt(r_fmm, "%.3g") : "-", verdict(std::isfinite(r_fmm), r_fmm <= 2),
                   std::isfinite(r_heat) ? fmt(r_heat, "%.3g") : "-", verdict(std::isfinite(r_heat), r_heat <= 0.15),
                   std::isfinite(r_idt) ? fmt(r_idt, "%.3g") : "-", any_merged ? merged_e : "-", any_merged ? merged_t : "-",
                   verdict(any_merged, monotone)});
  }
  goals.print();
  std::cout << "flat-exact goal checks: " << passes << " PASS, " << misses << " MISS or not measured\n";
  return 0;
}
