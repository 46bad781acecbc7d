// Thread scaling of the geodesic distance matrices (issue 29 item 2; goals at 2 threads, this machine's 2 cores):
//   dense:  geodesic_distance_rows() from S sources (vertex ids i * n / S) to every vertex, exact distances_only:
//           wall time at each thread count, speed-up and efficiency against 1 thread (goal >= 1.85x at 2 threads,
//           100 sources, ~200k vertices);
//   sparse: symmetric_local_geodesic_distance_matrix() from every vertex with max_distance = R mean edge lengths:
//           wall time at each thread count and its ratio to one full single-source run (exact, distances_only, the
//           same mesh; goal: <= 8x at 2 threads, R = 5, ~200k vertices), entries, symmetry check, peak memory.
// Runs are interleaved (for each repetition, every thread count in turn) and medians reported; CPU times give the
// per-stage serial fractions, from which the wall time at 16 threads is projected by Amdahl's law (a projection,
// not a measurement). The rows are compared across thread counts (they must be identical).
//
//   bench_distance_matrix [--meshes NAMES] [--mesh-dir DIR] [--extra-dir DIR] [--runs N] [--threads 1,2]
//                         [--sources S] [--radius-edges R] [--parts dense,sparse] [--method NAME] [--csv FILE]
//                         [--write-matrix FILE] [--quick] [--list]
// Default mesh: refined_elephant after one Loop subdivision (177,842 vertices). --quick: the unsubdivided
// refined_elephant (44,460), 20 sources, 1 run, a check of the whole pipeline on a small input.
// --write-matrix FILE: the sparse symmetric matrix of the first run (Matrix Market, 17 digits: bit for bit), to
// compare two versions of the code; the console also prints a checksum of it (FNV-1a of its columns and the bits of
// its values).
#include <geodesic_bench_common.h>

#include <CGAL/Polyhedral_geodesics_3/Exact_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/IO/distance_matrix_files.h>
#include <CGAL/Polyhedral_geodesics_3/geodesic_distance_matrix.h>

#include <cstring>

#include <iostream>
#include <map>

using namespace geodesic_bench;
namespace PG = CGAL::Polyhedral_geodesics_3;

namespace {

struct Options
{
  Common_options common;
  std::vector<std::size_t> threads = {1, 2};
  std::size_t sources = 100;
  double radius_edges = 5;
  bool dense = true, sparse = true, quick = false;
  std::string write_matrix;
  PG::Geodesic_method method = PG::Geodesic_method::exact;
};

void usage()
{
  std::cerr << "usage: bench_distance_matrix [--meshes NAMES] [--mesh-dir DIR] [--extra-dir DIR] [--runs N] [--threads 1,2]\n"
               "                             [--sources S] [--radius-edges R] [--parts dense,sparse] [--method exact|merged|flat-exact|fmm|dijkstra]\n"
               "                             [--csv FILE] [--write-matrix FILE] [--quick] [--list]\n";
}

// FNV-1a over the row starts, columns and value bits of a sparse matrix.
std::uint64_t checksum(const PG::Geodesic_sparse_matrix& m)
{
  std::uint64_t h = 1469598103934665603ull;
  const auto mix = [&](std::uint64_t x) {
    for(int b = 0; b < 8; ++b) {
      h ^= (x >> (8 * b)) & 0xff;
      h *= 1099511628211ull;
    }
  };
  for(std::size_t r : m.row_begin) mix(r);
  for(std::uint32_t c : m.column) mix(c);
  for(double v : m.value) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    mix(bits);
  }
  return h;
}

double full_single_source_seconds(const Mesh& mesh, Vertex s, double& cpu)
{
  const double t0 = mdcs_bench::now_seconds(), c0 = mdcs_bench::cpu_seconds();
  PG::Exact_geodesic_distances_3<Mesh> g(mesh, PG::Geodesic_memory_mode::distances_only);
  g.add_source(s);
  g.compute();
  cpu = mdcs_bench::cpu_seconds() - c0;
  return mdcs_bench::now_seconds() - t0;
}

std::string load_line()
{
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

// Amdahl: the wall time at `p` threads of a run whose serial part took `serial` and parallel part `parallel` on one.
double amdahl(double serial, double parallel, double p) { return serial + parallel / p; }

// The speed-up at `t` threads on an otherwise idle machine, from CPU times (meaningful on a loaded machine, where
// wall times are not): the serial part `serial` (CPU s at one thread) runs alone, the rest of the CPU time `cpu_t`
// measured at `t` threads (its parallel overhead included) is spread over the `t` threads. A projection.
double cpu_speedup(double cpu_1, double cpu_t, double serial, double t)
{
  return cpu_1 / (serial + std::max(0.0, cpu_t - serial) / t);
}

} // namespace

int main(int argc, char** argv)
{
  Options o;
  o.common.csv = "distance_matrix.csv";
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool v = i + 1 < argc;
    if(o.common.parse(argc, argv, i)) continue;
    if(a == "--threads" && v) {
      o.threads.clear();
      for(const std::string& t : split(argv[++i], ',')) o.threads.push_back(std::size_t(std::stoul(t)));
    } else if(a == "--sources" && v) o.sources = std::size_t(std::stoul(argv[++i]));
    else if(a == "--radius-edges" && v) o.radius_edges = std::atof(argv[++i]);
    else if(a == "--write-matrix" && v) o.write_matrix = argv[++i];
    else if(a == "--parts" && v) {
      const std::string p = argv[++i];
      o.dense = p.find("dense") != std::string::npos;
      o.sparse = p.find("sparse") != std::string::npos;
    } else if(a == "--method" && v) {
      const std::string m = argv[++i];
      bool found = false;
      for(PG::Geodesic_method x : {PG::Geodesic_method::exact, PG::Geodesic_method::merged_windows,
                                   PG::Geodesic_method::flat_exact, PG::Geodesic_method::fast_marching,
                                   PG::Geodesic_method::dijkstra})
        if(m == PG::geodesic_method_name(x)) { o.method = x; found = true; }
      if(!found) { usage(); return 2; }
    } else if(a == "--quick") o.quick = true;
    else { usage(); return 2; }
  }
  if(o.quick) {
    o.sources = std::min<std::size_t>(o.sources, 20);
    o.common.runs = 1;
  }
  const std::vector<Mesh_spec> builtin = {
    {"refined_elephant-loop1", o.common.in_mesh_dir("refined_elephant.off"), 1},
    {"refined_elephant", o.common.in_mesh_dir("refined_elephant.off"), 0},
    {"bunny00-loop1", o.common.in_mesh_dir("bunny00.off"), 1},
    {"armadillo-loop1", o.common.in_mesh_dir("armadillo.off"), 1}};
  if(o.common.selected.empty()) o.common.selected = {o.quick ? "refined_elephant" : "refined_elephant-loop1"};
  std::vector<Mesh_spec> specs;
  const int early = select_or_list_meshes(builtin, o.common, specs, usage);
  if(early >= 0) return early;

  std::cout << "Geodesic distance matrices, thread scaling (method " << PG::geodesic_method_name(o.method) << ", "
            << o.common.runs << " interleaved runs, medians; TBB " << (CGAL::MDCS::has_parallel_support() ? "yes" : "NO")
            << ", " << CGAL::MDCS::hardware_threads() << " hardware threads). Load at start: " << load_line() << "\n\n";
  mdcs_bench::Table table({"mesh", "vertices", "part", "sources", "max_distance", "threads", "wall_s", "cpu_s",
                           "speedup", "efficiency", "cpu_ratio", "cpu_speedup", "cpu_efficiency", "full_run_s",
                           "ratio_to_full_run", "full_run_cpu_s", "cpu_ratio_to_full_run", "entries", "peak_MiB",
                           "serial_fraction", "projected_16_threads_s", "identical", "load"});
  for(const Mesh_spec& spec : specs) {
    Mesh mesh;
    std::string message;
    if(!load_mesh(spec, mesh, message)) {
      std::cerr << spec.name << ": " << message << "\n";
      continue;
    }
    const std::size_t n = num_vertices(mesh);
    const double edge = average_edge_length(mesh);
    std::cout << spec.name << ": " << n << " vertices, mean edge length " << edge << (message.empty() ? "" : " (" + message + ")")
              << "\n";
    std::vector<Vertex> sources;
    for(std::size_t i = 0; i < o.sources; ++i) sources.push_back(Vertex(std::uint32_t(i * n / o.sources)));
    std::vector<Vertex> all(vertices(mesh).begin(), vertices(mesh).end());

    // One full single-source run, the reference of the sparse goal (median over the runs, interleaved below).
    std::vector<double> full_wall, full_cpu;
    const auto run_full = [&] {
      double cpu = 0;
      full_wall.push_back(full_single_source_seconds(mesh, sources[0], cpu));
      full_cpu.push_back(cpu);
    };

    if(o.dense) {
      std::map<std::size_t, std::vector<double>> wall, cpu;
      std::map<std::size_t, std::vector<double>> checksum; // per thread count: the sum of every finite entry, per row
      std::map<std::size_t, double> setup_cpu;
      for(int r = 0; r < o.common.runs; ++r) {
        run_full();
        for(std::size_t t : o.threads) {
          PG::Geodesic_matrix_options mo;
          mo.method = o.method;
          mo.threads = t;
          std::vector<double> sums(sources.size(), 0);
          double first_row_cpu = -1;
          const double c0 = mdcs_bench::cpu_seconds(), t0 = mdcs_bench::now_seconds();
          PG::geodesic_distance_rows<CGAL::Parallel_tag>(mesh, sources, [&](std::size_t i, const std::vector<double>& row) {
            double s = 0;
            for(double d : row) if(d < inf) s += d;
            sums[i] = s;
          }, mo, [&](const char*, double f) {
            if(f == 0 && first_row_cpu < 0) first_row_cpu = mdcs_bench::cpu_seconds() - c0; // the mesh preparation
            return true;
          });
          wall[t].push_back(mdcs_bench::now_seconds() - t0);
          cpu[t].push_back(mdcs_bench::cpu_seconds() - c0);
          setup_cpu[t] = first_row_cpu;
          if(r == 0) checksum[t] = sums;
        }
      }
      const double w1 = mdcs_bench::median(wall[o.threads.front()]);
      const double c1 = mdcs_bench::median(cpu[o.threads.front()]);
      // Serial part: the compact mesh (built once, before the first row); everything else is per source.
      const double serial = std::max(0.0, setup_cpu[o.threads.front()]);
      for(std::size_t t : o.threads) {
        const double w = mdcs_bench::median(wall[t]);
        const bool identical = checksum[t] == checksum[o.threads.front()];
        table.add_row({spec.name, std::to_string(n), "dense", std::to_string(sources.size()), "inf", std::to_string(t),
                       fmt(w), fmt(mdcs_bench::median(cpu[t])), fmt(w1 / w), fmt(w1 / w / double(t)),
                       fmt(mdcs_bench::median(cpu[t]) / c1), fmt(cpu_speedup(c1, mdcs_bench::median(cpu[t]), serial, double(t))),
                       fmt(cpu_speedup(c1, mdcs_bench::median(cpu[t]), serial, double(t)) / double(t)), "-", "-", "-", "-",
                       std::to_string(sources.size() * n), "-", fmt(serial / c1), fmt(amdahl(serial, c1 - serial, 16)),
                       identical ? "yes" : "NO", load_line()});
        std::cout << "  dense, " << t << " thread(s): " << fmt(w) << " s, speed-up " << fmt(w1 / w) << ", CPU "
                  << fmt(mdcs_bench::median(cpu[t])) << " s (idle-machine speed-up from CPU times "
                  << fmt(cpu_speedup(c1, mdcs_bench::median(cpu[t]), serial, double(t))) << ")"
                  << (identical ? "" : "  ROWS DIFFER") << "\n";
      }
    }

    if(o.sparse) {
      const double r_max = o.radius_edges * edge;
      std::map<std::size_t, std::vector<double>> wall, cpu, rows_cpu;
      std::map<std::size_t, double> peak;
      std::map<std::size_t, std::size_t> entries;
      std::map<std::size_t, std::vector<double>> values;
      bool symmetric = true;
      std::uint64_t sum = 0;
      for(int r = 0; r < o.common.runs; ++r) {
        run_full();
        for(std::size_t t : o.threads) {
          PG::Geodesic_matrix_options mo;
          mo.method = o.method;
          mo.threads = t;
          mo.max_distance = r_max;
          malloc_trim(0);
          mdcs_bench::reset_peak_rss();
          const double rss0 = mdcs_bench::current_rss_mib();
          double rows_begin = -1, rows_end = 0;
          const double c0 = mdcs_bench::cpu_seconds(), t0 = mdcs_bench::now_seconds();
          const PG::Geodesic_sparse_matrix m = PG::symmetric_local_geodesic_distance_matrix<CGAL::Parallel_tag>(
            mesh, mo, [&](const char*, double f) {
              if(f == 0 && rows_begin < 0) rows_begin = mdcs_bench::cpu_seconds();
              if(f == 1.0) rows_end = mdcs_bench::cpu_seconds();
              return true;
            });
          wall[t].push_back(mdcs_bench::now_seconds() - t0);
          cpu[t].push_back(mdcs_bench::cpu_seconds() - c0);
          rows_cpu[t].push_back(rows_end - rows_begin);
          peak[t] = std::max(peak[t], mdcs_bench::peak_rss_mib() - rss0);
          entries[t] = m.number_of_entries();
          if(r == 0) {
            values[t] = m.value;
            if(t == o.threads.front()) {
              sum = checksum(m);
              if(!o.write_matrix.empty()) {
                std::ofstream out(o.write_matrix);
                PG::IO::write_matrix_market(out, m, "bench_distance_matrix: " + spec.name);
              }
            }
            for(std::size_t u = 0; u < m.rows && symmetric; ++u)
              for(std::size_t k = m.row_begin[u]; k < m.row_begin[u + 1]; ++k)
                if(m.at(m.column[k], u) != m.value[k] || m.value[k] > r_max) { symmetric = false; break; }
          }
        }
      }
      const double full = mdcs_bench::median(full_wall), full_c = mdcs_bench::median(full_cpu);
      const double w1 = mdcs_bench::median(wall[o.threads.front()]);
      const double c1 = mdcs_bench::median(cpu[o.threads.front()]);
      // Serial part at one thread: everything but the rows (the compact mesh, the symmetrization, counted as serial
      // although its lookups run in parallel).
      const double serial = std::max(0.0, c1 - mdcs_bench::median(rows_cpu[o.threads.front()]));
      for(std::size_t t : o.threads) {
        const double w = mdcs_bench::median(wall[t]);
        const bool identical = values[t] == values[o.threads.front()] && entries[t] == entries[o.threads.front()];
        table.add_row({spec.name, std::to_string(n), "sparse symmetric", std::to_string(n), fmt(r_max), std::to_string(t),
                       fmt(w), fmt(mdcs_bench::median(cpu[t])), fmt(w1 / w), fmt(w1 / w / double(t)),
                       fmt(mdcs_bench::median(cpu[t]) / c1), fmt(cpu_speedup(c1, mdcs_bench::median(cpu[t]), serial, double(t))),
                       fmt(cpu_speedup(c1, mdcs_bench::median(cpu[t]), serial, double(t)) / double(t)), fmt(full),
                       fmt(w / full), fmt(full_c),
                       fmt(c1 / cpu_speedup(c1, mdcs_bench::median(cpu[t]), serial, double(t)) / full_c),
                       std::to_string(entries[t]), fmt(peak[t]), fmt(serial / c1),
                       fmt(amdahl(serial, c1 - serial, 16)), identical && symmetric ? "yes" : "NO", load_line()});
        std::cout << "  sparse (max_distance " << o.radius_edges << " edges), " << t << " thread(s): " << fmt(w)
                  << " s = " << fmt(w / full) << " full single-source runs (" << fmt(full) << " s), "
                  << entries[t] << " entries (" << fmt(double(entries[t]) / double(n)) << " per row); from CPU times: "
                  << fmt(c1 / cpu_speedup(c1, mdcs_bench::median(cpu[t]), serial, double(t)) / full_c)
                  << " full runs on an idle machine"
                  << (symmetric ? "" : "  NOT SYMMETRIC") << (identical ? "" : "  DIFFERS") << "\n";
      }
      std::cout << "  sparse matrix checksum " << std::hex << sum << std::dec << "\n";
    }
  }
  std::cout << "\n";
  table.print();
  std::cout << "\nspeedup = wall(1 thread) / wall(t threads); efficiency = speedup / t; cpu_ratio = CPU time at t "
               "threads / CPU time at 1 (parallel overhead); cpu_speedup = CPU(1) / (serial CPU + (CPU(t) - serial CPU) "
               "/ t), the speed-up an idle machine would give (a projection from CPU times, meaningful when the "
               "machine is loaded and wall times are not); cpu_efficiency = cpu_speedup / t; cpu_ratio_to_full_run = "
               "the sparse matrix's wall time at t threads projected from CPU times / CPU time of one full run; "
               "serial_fraction = serial CPU "
               "time / total CPU time at one thread; projected_16_threads_s = Amdahl's law from it (a projection, "
               "not a measurement). Load: /proc/loadavg at the end of each row (the machine may be shared).\n";
  write_table_csv(table, o.common.csv);
  return 0;
}
