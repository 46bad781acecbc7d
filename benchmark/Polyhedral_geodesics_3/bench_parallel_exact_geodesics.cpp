// Parallel single-source exact distances (issue 31 item 3): Exact_geodesic_distances_3 in distances_only mode with
// the sequential vertex-oriented schedule (Sequential_tag) against the parallel schedule (Parallel_tag) at each
// thread count of --threads, from one source vertex to every vertex, on meshes of 200k vertices and more.
//
//   bench_parallel_exact_geodesics [--meshes a,b] [--threads 1,2] [--runs N] [--source I] [--lists-per-round N]
//                                  [--mesh-dir DIR] [--extra-dir DIR] [--csv FILE] [--list]
//
// Built-in meshes (CGAL's demo meshes, Loop-subdivided in memory): armadillo-loop2 (~415k vertices, the default),
// bunny00-loop2 (~600k), refined_elephant-loop1 (~178k), elephant (quick check). The prepared surface is built
// once per mesh; each row times the propagation only (compute()), medians of --runs runs, interleaved (sequential,
// then each thread count, --runs times) so that a change of the machine's load hits every column alike.
//
// Columns (the profile columns come from one more, profiled run; their times are CPU times of the threads that ran
// the step, see Vertex_oriented_parallel_profile): wall and process CPU time (user + system of every thread) per configuration; speed-up = sequential
// wall / parallel wall; cpu_ratio = parallel CPU / sequential CPU (the parallel schedule's overhead: 1 thread
// measures the cost of the rounds themselves); rounds; the parallel step's share of the 1-thread run (the part that
// scales); per-thread busy time (work balance); the projected time at 2..16 threads from the measured rounds (a
// round's parallel step takes at least max(work / P, its longest block)) plus the measured sequential steps; the
// largest relative difference to the sequential schedule, and whether every thread count gave the same bits.
// On a loaded machine the wall-clock columns are unreliable: look at the CPU and projection columns, and rerun on
// an idle machine (benchmark/README.md).
#include <geodesic_bench_common.h>
#include <mdcs_bench.h>

#include <CGAL/Polyhedral_geodesics_3/Exact_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_surface_3.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace PG = CGAL::Polyhedral_geodesics_3;
using mdcs_bench::fmt;

namespace {

using namespace geodesic_bench;
typedef PG::Exact_geodesic_distances_3<Mesh> Geodesics;
typedef PG::Geodesic_surface_3<Mesh> Surface;

struct Options
{
  Common_options common;
  std::vector<std::size_t> threads = {1, 2};
  std::size_t source = 0, lists_per_round = 0;
};

void usage()
{
  std::cerr << "usage: bench_parallel_exact_geodesics [--meshes a,b] [--threads 1,2] [--runs N] [--source I]\n"
               "                                      [--lists-per-round N] [--mesh-dir DIR] [--extra-dir DIR]\n"
               "                                      [--csv FILE] [--list]\n"
               "  built-in meshes: armadillo-loop2 (default) bunny00-loop2 refined_elephant-loop1 elephant\n";
}

struct Measure
{
  std::vector<double> wall, cpu;
  std::vector<double> distances;
  PG::internal::Vertex_oriented_parallel_profile profile;
  std::size_t windows_propagated = 0, windows_created = 0;
};

// One propagation; threads 0: Sequential_tag. A timed run (its wall and CPU time are kept), or the profiled run
// (not timed: the profile's clocks cost a little): its distances and profile are kept.
void run_once(const std::shared_ptr<const Surface>& surface, const Mesh& mesh, const Options& o, std::size_t threads,
              Measure& m, bool profiled)
{
  Geodesics g(surface, PG::Geodesic_memory_mode::distances_only);
  if(threads == 0)
    g.set_concurrency(CGAL::Sequential_tag());
  else
    g.set_concurrency(CGAL::Parallel_tag(), threads);
  if(o.lists_per_round > 0)
    g.set_parallel_lists_per_round(o.lists_per_round);
  g.set_parallel_profile(profiled && threads > 0);
  g.add_source(*std::next(vertices(mesh).begin(), std::ptrdiff_t(o.source)));
  const double c0 = mdcs_bench::cpu_seconds(), t0 = mdcs_bench::now_seconds();
  g.compute();
  const double t1 = mdcs_bench::now_seconds(), c1 = mdcs_bench::cpu_seconds();
  if(!profiled) {
    m.wall.push_back(t1 - t0);
    m.cpu.push_back(c1 - c0);
  }
  if(threads > 0 && g.used_parallel_propagation() == false)
    std::cerr << "warning: the parallel schedule did not run\n";
  if(profiled) {
    m.distances.clear();
    for(auto v : vertices(mesh))
      m.distances.push_back(g.distance(v));
    m.profile = g.parallel_profile();
    m.windows_propagated = g.statistics().windows_propagated;
    m.windows_created = g.statistics().windows_created;
  }
}

double max_relative_difference(const std::vector<double>& a, const std::vector<double>& b)
{
  double worst = 0;
  for(std::size_t i = 0; i < a.size(); ++i) {
    if(std::isinf(a[i]) || std::isinf(b[i])) {
      if(a[i] != b[i]) return std::numeric_limits<double>::infinity();
      continue;
    }
    const double scale = std::max(std::abs(a[i]), 1e-300);
    worst = std::max(worst, std::abs(a[i] - b[i]) / scale);
  }
  return worst;
}

std::string load_text()
{
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

} // namespace

int main(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if(o.common.parse(argc, argv, i)) continue;
    if(a == "--threads" && has_value) {
      o.threads.clear();
      for(const std::string& t : split(argv[++i], ',')) o.threads.push_back(std::size_t(std::max(1, std::atoi(t.c_str()))));
    } else if(a == "--source" && has_value) o.source = std::size_t(std::atol(argv[++i]));
    else if(a == "--lists-per-round" && has_value) o.lists_per_round = std::size_t(std::atol(argv[++i]));
    else {
      usage();
      return a == "--help" ? 0 : 2;
    }
  }
  const std::vector<Mesh_spec> builtin = {{"armadillo-loop2", o.common.in_mesh_dir("armadillo.off"), 2},
                                          {"bunny00-loop2", o.common.in_mesh_dir("bunny00.off"), 2},
                                          {"refined_elephant-loop1", o.common.in_mesh_dir("refined_elephant.off"), 1},
                                          {"elephant", o.common.in_mesh_dir("elephant.off"), 0}};
  if(o.common.selected.empty()) o.common.selected = {"armadillo-loop2"};
  std::vector<Mesh_spec> specs;
  const int listed = select_or_list_meshes(builtin, o.common, specs, usage);
  if(listed >= 0) return listed;

  std::vector<std::string> columns = {"mesh", "vertices", "threads", "wall_s", "cpu_s", "speedup", "cpu_ratio",
                                      "windows_propagated", "windows_created", "rounds", "tasks", "settle_s", "merge_s", "merge_span_s", "parallel_s", "work_s",
                                      "thread_busy_s", "max_rel_diff_vs_sequential", "identical_across_threads"};
  for(int p : PG::internal::Vertex_oriented_parallel_profile::projected_threads())
    if(p > 1) columns.push_back("projected_" + std::to_string(p) + "t_s");
  columns.push_back("load");
  mdcs_bench::Table table(columns);
  for(const Mesh_spec& spec : specs) {
    Mesh mesh;
    std::string message;
    if(!load_mesh(spec, mesh, message)) {
      std::cerr << spec.name << ": " << message << "\n";
      continue;
    }
    std::cout << spec.name << ": " << num_vertices(mesh) << " vertices" << (message.empty() ? "" : " (" + message + ")")
              << ", load " << load_text() << std::endl;
    const auto surface = std::make_shared<const Surface>(mesh);
    Measure sequential;
    std::vector<Measure> parallel(o.threads.size());
    for(int r = 0; r <= o.common.runs; ++r) { // the last round: the profiled runs
      const bool profiled = r == o.common.runs;
      run_once(surface, mesh, o, 0, sequential, profiled);
      for(std::size_t k = 0; k < o.threads.size(); ++k)
        run_once(surface, mesh, o, o.threads[k], parallel[k], profiled);
    }
    const std::string load = load_text();
    const double seq_wall = mdcs_bench::median(sequential.wall), seq_cpu = mdcs_bench::median(sequential.cpu);
    table.add_row({spec.name, std::to_string(num_vertices(mesh)), "sequential", fmt(seq_wall), fmt(seq_cpu), "1", "1",
                   std::to_string(sequential.windows_propagated), std::to_string(sequential.windows_created), "", "", "", "", "", "", "", "", "0", ""});
    bool identical = true;
    for(const Measure& m : parallel)
      identical = identical && m.distances.size() == parallel[0].distances.size() &&
                  std::memcmp(m.distances.data(), parallel[0].distances.data(), m.distances.size() * sizeof(double)) == 0;
    for(std::size_t k = 0; k < o.threads.size(); ++k) {
      const Measure& m = parallel[k];
      const auto& p = m.profile;
      const double wall = mdcs_bench::median(m.wall), cpu = mdcs_bench::median(m.cpu);
      std::string busy;
      for(double b : p.thread_busy_seconds) busy += (busy.empty() ? "" : ";") + fmt(b);
      std::vector<std::string> row = {spec.name, std::to_string(num_vertices(mesh)), std::to_string(o.threads[k]),
                                      fmt(wall), fmt(cpu), fmt(seq_wall / wall), fmt(cpu / seq_cpu),
                                      std::to_string(m.windows_propagated), std::to_string(m.windows_created),
                                      std::to_string(p.rounds), std::to_string(p.tasks), fmt(p.settle_seconds),
                                      fmt(p.merge_seconds), fmt(p.merge_span_seconds), fmt(p.parallel_seconds), fmt(p.work_seconds), busy,
                                      fmt(max_relative_difference(sequential.distances, m.distances), "%.3g"),
                                      identical ? "yes" : "no"};
      // the projection from the 1-thread-like measure of this run: sequential steps + bound of the parallel step
      const auto ps = PG::internal::Vertex_oriented_parallel_profile::projected_threads();
      for(std::size_t j = 0; j < ps.size(); ++j)
        if(ps[j] > 1) row.push_back(fmt(p.settle_seconds + p.merge_span_seconds + p.projected_lower[j]));
      row.push_back(load);
      table.add_row(row);
    }
  }
  std::cout << "\n";
  table.print();
  write_table_csv(table, o.common.csv);
  return 0;
}
