// Thread scaling of the parallel paths of the variational solvers (issue 29 item 4; goal: facet weights and
// independent rounds >= 1.8x at 2 threads on this machine's 2 cores):
//   weights-*   surface_facet_weights_3<Parallel_tag>: the blob functional by Gauss quadrature (levels 1 and 2), the
//               same by Monte Carlo (64 samples per facet), the area in closed form (memory-bound: the cheapest);
//   refine      refine_surface_3: R independent runs (one per thread), then the refined solve (sequential);
//   restarts    select_planes_multistart_3: R independent plane selections;
//   basin       select_planes_relaxed_3 with search threads: rounds (weights parallel), relaxations, speculative moves;
//   tangent     refine_surface_by_tangent_planes_3: per round the fits and the weights in parallel.
// Every path is run at each thread count in turn (interleaved), medians over the runs; the results are compared
// with the first thread count (they must be identical). Per-stage CPU times at one thread give the serial fraction
// (everything outside the parallel stages: arrangement builds, max-flows, the final solve) and Amdahl's projection
// of the wall time at 16 threads (a projection, not a measurement).
//
//   bench_parallel_variational [--threads 1,2] [--runs N] [--planes N] [--parts weights,refine,restarts,basin,tangent]
//                              [--quick] [--csv FILE]
#include <mdcs_bench.h>
#include <MDCS_test/surface_problems.h>

#include <CGAL/MDCS/concurrency.h>
#include <CGAL/Variational_minimization/monte_carlo_functional_3.h>
#include <CGAL/Variational_minimization/refine_surface_3.h>
#include <CGAL/Variational_minimization/refine_surface_by_tangent_planes_3.h>
#include <CGAL/Variational_minimization/search_surface_basins_3.h>
#include <CGAL/Variational_minimization/select_planes_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace VM = CGAL::Variational_minimization;
using MDCS_test::blob_planes;
using MDCS_test::blob_problem;
using mdcs_bench::fmt;

namespace {

std::string load_line()
{
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

// The CPU and wall times of the parallel stage of a run (between the first and the last progress call of the stage).
struct Stage_time
{
  double cpu = 0, wall = 0;
};

// One measured path: `run(threads, stage)` returns a fingerprint of its result (compared across thread counts) and
// the times of its parallel stage in `stage`.
struct Path
{
  std::string name, size;
  std::function<std::vector<double>(std::size_t threads, Stage_time& stage)> run;
};

struct Stage_clock
{
  std::string stage;
  double first = -1, last = -1, first_wall = -1, last_wall = -1;
  bool operator()(const char* s, double)
  {
    if(stage == s) {
      const double c = mdcs_bench::cpu_seconds(), w = mdcs_bench::now_seconds();
      if(first < 0) { first = c; first_wall = w; }
      last = c;
      last_wall = w;
    }
    return true;
  }
  Stage_time time() const { return first < 0 ? Stage_time() : Stage_time{last - first, last_wall - first_wall}; }
};

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::size_t> threads = {1, 2};
  int runs = 3;
  long planes = 160;
  bool quick = false;
  std::string parts = "weights,refine,restarts,basin,tangent", csv = "parallel_variational.csv";
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool v = i + 1 < argc;
    if(a == "--threads" && v) {
      threads.clear();
      std::string list = argv[++i];
      for(std::size_t p = 0; p < list.size();) {
        const std::size_t q = list.find(',', p);
        threads.push_back(std::size_t(std::stoul(list.substr(p, q - p))));
        p = q == std::string::npos ? list.size() : q + 1;
      }
    } else if(a == "--runs" && v) runs = std::max(1, std::atoi(argv[++i]));
    else if(a == "--planes" && v) planes = std::atol(argv[++i]);
    else if(a == "--parts" && v) parts = argv[++i];
    else if(a == "--csv" && v) csv = argv[++i];
    else if(a == "--quick") quick = true;
    else {
      std::fprintf(stderr, "usage: %s [--threads 1,2] [--runs N] [--planes N] [--parts weights,refine,restarts,basin,tangent] "
                           "[--quick] [--csv FILE]\n", argv[0]);
      return 2;
    }
  }
  if(quick) {
    runs = 1;
    planes = std::min(planes, 70L);
  }
  const auto want = [&](const char* p) { return parts.find(p) != std::string::npos; };
  std::printf("Variational solvers, thread scaling: %d interleaved run(s), medians; TBB %s, %zu hardware threads. Load "
              "at start: %s\n\n", runs, CGAL::MDCS::has_parallel_support() ? "yes" : "NO", CGAL::MDCS::hardware_threads(),
              load_line().c_str());
  const VM::Surface_problem_3 P = blob_problem();
  const VM::Density_weighted_area_functional_3 G = VM::random_blob_functional_3(P, 9, 4, 0.08, -1.5, 5);
  std::vector<Path> paths;
  std::unique_ptr<VM::Plane_arrangement_3> A; // shared by the weight paths

  if(want("weights")) {
    A.reset(new VM::Plane_arrangement_3(VM::surface_planes_3(P, std::size_t(planes), blob_planes(3))));
    const std::string size = std::to_string(A->number_of_facets()) + " facets";
    const auto weights_path = [&, size](const std::string& name, auto functional, int level) {
      paths.push_back({name, size, [&P, &A, functional, level](std::size_t t, Stage_time& stage) {
                         Stage_clock clock{"weights"};
                         const std::vector<double> w =
                           VM::surface_facet_weights_3<CGAL::Parallel_tag>(*A, P, functional, level, t, std::ref(clock));
                         stage = clock.time();
                         return w;
                       }});
    };
    weights_path("weights-quadrature-L1", G, 1);
    weights_path("weights-quadrature-L2", G, 2);
    weights_path("weights-monte-carlo-64", VM::make_monte_carlo_functional_3(G, 64, 1), 1);
    weights_path("weights-area-closed-form", VM::Area_functional_3(), 1);
  }
  const std::size_t n_round = std::size_t(quick ? 50 : planes / 2);
  const int independent = quick ? 2 : 4;
  if(want("refine"))
    paths.push_back({"refine-" + std::to_string(independent) + "-runs", std::to_string(n_round) + " planes",
                     [&](std::size_t t, Stage_time& stage) {
                       VM::Surface_plane_options_3 o = blob_planes(7);
                       o.threads = t;
                       // The runs end when the refinement reports fraction runs / (runs + 1).
                       double start = -1, end = -1, start_wall = -1, end_wall = -1;
                       const VM::Surface_refinement_result_3 r = VM::refine_surface_3(
                         P, G, n_round, independent, o, 0.05, 1, CGAL::Min_cut::Default_max_flow_engine(),
                         [&](const char*, double f) {
                           const double c = mdcs_bench::cpu_seconds(), w = mdcs_bench::now_seconds();
                           if(start < 0) { start = c; start_wall = w; }
                           if(std::abs(f - double(independent) / double(independent + 1)) < 1e-12 && end < 0) { end = c; end_wall = w; }
                           return true;
                         });
                       stage = Stage_time{end - start, end_wall - start_wall};
                       std::vector<double> out = r.run_energies;
                       out.push_back(r.surface.energy);
                       return out;
                     }});
  if(want("restarts"))
    paths.push_back({"restarts-" + std::to_string(independent), std::to_string(n_round) + " planes x 3 rounds",
                     [&](std::size_t t, Stage_time& stage) {
                       VM::Surface_plane_options_3 o = blob_planes(11);
                       o.threads = t;
                       Stage_clock clock{"plane selection restarts"};
                       const VM::Plane_selection_multistart_result_3 r =
                         VM::select_planes_multistart_3(P, G, n_round, 3, std::size_t(independent), o, 1,
                                                        CGAL::Min_cut::Default_max_flow_engine(), std::ref(clock));
                       stage = clock.time();
                       return r.restart_energies;
                     }});
  if(want("basin"))
    paths.push_back({"basin-search", std::to_string(n_round) + " planes x 2 rounds, tilings 3,4",
                     [&](std::size_t t, Stage_time& stage) {
                       VM::Surface_plane_options_3 o = blob_planes(2);
                       o.threads = t;
                       VM::Surface_basin_search_options_3 so;
                       so.threads = t;
                       so.wide_tilings.clear();
                       so.sweeps = 2;
                       Stage_clock clock{"basin search"};
                       const VM::Relaxed_plane_selection_result_3 r =
                         VM::select_planes_relaxed_3(P, G, n_round, 2, o, so, CGAL::Min_cut::Default_max_flow_engine(), std::ref(clock));
                       stage = clock.time();
                       return std::vector<double>{r.search.relaxed.energy, double(r.search.moves), double(r.search.improvements)};
                     }});
  if(want("tangent"))
    paths.push_back({"tangent-refinement", std::to_string(n_round) + " planes x 3 rounds", [&](std::size_t t, Stage_time& stage) {
                       const VM::Surface_problem_3 S = MDCS_test::tall_scherk_problem();
                       const VM::Surface_plane_options_3 o = MDCS_test::tall_scherk_planes();
                       VM::Tangent_refinement_options_3 to;
                       to.rounds = 3;
                       to.threads = t;
                       // The weights of each round are the parallel stage; the fits are too small to time apart.
                       stage = Stage_time();
                       const VM::Tangent_refinement_result_3 r =
                         VM::refine_surface_by_tangent_planes_3(S, VM::Area_functional_3(), std::size_t(n_round * 2), to, o);
                       return r.round_energies;
                     }});

  mdcs_bench::Table table({"path", "size", "threads", "wall_s", "cpu_s", "speedup", "efficiency", "cpu_ratio",
                           "cpu_speedup", "cpu_efficiency", "stage_wall_s",
                           "stage_speedup", "serial_fraction", "projected_16_threads_s", "identical", "load"});
  for(const Path& p : paths) {
    std::map<std::size_t, std::vector<double>> wall, cpu, par, par_wall;
    std::map<std::size_t, std::vector<double>> fingerprint;
    for(int r = 0; r < runs; ++r)
      for(std::size_t t : threads) {
        Stage_time stage;
        const double t0 = mdcs_bench::now_seconds(), c0 = mdcs_bench::cpu_seconds();
        std::vector<double> f = p.run(t, stage);
        wall[t].push_back(mdcs_bench::now_seconds() - t0);
        cpu[t].push_back(mdcs_bench::cpu_seconds() - c0);
        par[t].push_back(stage.cpu);
        par_wall[t].push_back(stage.wall);
        if(r == 0) fingerprint[t] = std::move(f);
      }
    const std::size_t t1 = threads.front();
    const double w1 = mdcs_bench::median(wall[t1]), c1 = mdcs_bench::median(cpu[t1]);
    const double serial = p.name == "tangent-refinement" ? std::numeric_limits<double>::quiet_NaN()
                                                         : std::max(0.0, c1 - mdcs_bench::median(par[t1]));
    const double sw1 = mdcs_bench::median(par_wall[t1]);
    for(std::size_t t : threads) {
      const double w = mdcs_bench::median(wall[t]), sw = mdcs_bench::median(par_wall[t]);
      const double ct = mdcs_bench::median(cpu[t]);
      // The speed-up an idle machine would give, from CPU times (see the legend); not for the tangent path, whose
      // serial part is not measured apart.
      const double cs = std::isnan(serial) ? serial : c1 / (serial + std::max(0.0, ct - serial) / double(t));
      const bool identical = fingerprint[t] == fingerprint[t1];
      table.add_row({p.name, p.size, std::to_string(t), fmt(w), fmt(ct), fmt(w1 / w),
                     fmt(w1 / w / double(t)), fmt(ct / c1), fmt(cs), fmt(cs / double(t)), sw > 0 ? fmt(sw) : "-", sw > 0 ? fmt(sw1 / sw) : "-", fmt(serial / c1),
                     fmt(serial + (c1 - serial) / 16), identical ? "yes" : "NO", load_line()});
      std::printf("  %-26s %zu thread(s): %8.3f s, speed-up %.3f, CPU %.3f s (idle-machine speed-up from CPU times "
                  "%.3f)%s\n", p.name.c_str(), t, w, w1 / w, ct, cs, identical ? "" : "  RESULTS DIFFER");
      std::fflush(stdout);
    }
  }
  std::printf("\n");
  table.print();
  std::printf("\nspeedup = wall(1 thread) / wall(t); efficiency = speedup / t; cpu_ratio = CPU time at t threads / "
              "CPU time at 1 (parallel overhead); cpu_speedup = CPU(1) / (serial CPU + (CPU(t) - serial CPU) / t), the "
              "speed-up an idle machine would give (a projection from CPU times, meaningful when the machine is "
              "loaded and wall times are not); cpu_efficiency = cpu_speedup / t; stage_wall_s, stage_speedup: the same "
              "for the parallel stage alone (weights: the weights; refine: the independent runs; restarts: all of it; "
              "basin: the search moves); serial_fraction = CPU time outside the "
              "parallel stages / total CPU time at one thread (weights: outside the \"weights\" stage; refine: the "
              "refined solve; restarts: the choice of the best; basin: everything but the search moves, i.e. the plane "
              "selection's builds and cuts; tangent: not split); projected_16_threads_s = Amdahl's law from it, a "
              "projection, not a measurement.\n");
  if(table.write_csv(csv)) std::printf("CSV: %s\n", csv.c_str());
  return 0;
}
