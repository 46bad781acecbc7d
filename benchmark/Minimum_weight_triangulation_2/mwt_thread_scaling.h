// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Thread scaling of the MWT pipeline (issue 29, item 8), the `--threads` mode of bench_mwt: every input is run
// with each thread count in turn (interleaved, the order reversed every other repeat), each stage timed in
// wall-clock and processor time between the progress callback's stage changes, and the results compared (the
// triangulation, the weight and the bounds must not depend on the thread count). From the one-thread runs, the
// statistics' time inside parallel loops gives each stage's serial part, and Amdahl's law the projected wall
// time at 16 threads (a projection: it ignores memory bandwidth and the machine's other load).

#ifndef MDCS_BENCH_MWT_THREAD_SCALING_H
#define MDCS_BENCH_MWT_THREAD_SCALING_H

#include <CGAL/Minimum_weight_triangulation_2.h>

#include "mdcs_bench.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace mwt_scaling {

namespace MWT = CGAL::Minimum_weight_triangulation_2;

// The stages as the progress callback names them ("setup": before the first report: Hilbert sort, checks,
// hull, grid), and their short names in the tables.
inline const std::vector<std::pair<std::string, std::string>>& stages()
{
  static const std::vector<std::pair<std::string, std::string>> s{
    {"setup", "setup"},           {"candidate edges", "candidates"},       {"empty triangles", "triangles"},
    {"LMT-skeleton", "skeleton"}, {"face dynamic program", "face_dp"},      {"LP solve", "lp"},
    {"branch and bound", "bb"},   {"certificate", "certificate"}};
  return s;
}

struct Run
{
  std::size_t threads = 1;
  std::map<std::string, double> wall, cpu;   // per stage (progress callback names)
  double wall_total = 0, cpu_total = 0, peak_mib = 0;
  MWT::Mwt_result result;
  std::uint64_t digest = 0;   // triangles, weight and bound bits, status
};

inline std::uint64_t digest(const MWT::Mwt_result& r)
{
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&](std::uint64_t v) { h ^= v; h *= 1099511628211ull; };
  for(const auto& t : r.triangles)
    for(int v : t) mix(std::uint64_t(std::uint32_t(v)));
  std::uint64_t w, b;
  std::memcpy(&w, &r.weight, 8);
  std::memcpy(&b, &r.lower_bound, 8);
  mix(w);
  mix(b);
  mix(std::uint64_t(r.status));
  mix(std::uint64_t(r.certificate_exact));
  return h;
}

template <class Point>
Run run_once(const std::vector<Point>& p, MWT::Mwt_options o, std::size_t threads)
{
  Run run;
  run.threads = threads;
  o.threads = threads;
  std::string stage = "setup";
  double w0 = mdcs_bench::now_seconds(), c0 = mdcs_bench::cpu_seconds();
  const double wall_start = w0, cpu_start = c0;
  auto close = [&](const std::string& next) {
    const double w = mdcs_bench::now_seconds(), c = mdcs_bench::cpu_seconds();
    run.wall[stage] += w - w0;
    run.cpu[stage] += c - c0;
    stage = next;
    w0 = w;
    c0 = c;
  };
  o.progress = [&](const char* s, double) {   // called from this thread only
    if(stage != s) close(s);
    return true;
  };
  run.result = MWT::minimum_weight_triangulation_2<CGAL::Parallel_if_available_tag>(p, o);
  close("");
  run.wall_total = mdcs_bench::now_seconds() - wall_start;
  run.cpu_total = mdcs_bench::cpu_seconds() - cpu_start;
  run.peak_mib = mdcs_bench::peak_rss_mib();
  run.digest = digest(run.result);
  return run;
}

// Serial and parallel processor seconds of a one-thread run, from the statistics (the stage clock is the
// process's processor time in this benchmark); what the statistics do not cover (copies of the input, mapping
// the triangles back, freeing) is counted as serial.
struct Amdahl
{
  double total = 0, serial = 0, parallel = 0;
  std::vector<std::pair<std::string, std::array<double, 2>>> per_stage;   // (stage, {time, time in parallel loops})
  double fraction() const { return total > 0 ? serial / total : 0; }
  double projected(double threads) const { return serial + parallel / threads; }
};

inline Amdahl amdahl(const Run& one_thread)
{
  const MWT::Mwt_statistics& s = one_thread.result.statistics;
  Amdahl a;
  a.per_stage = {{"setup", {{s.time_setup, s.time_parallel_setup}}},
                 {"candidates", {{s.time_candidates, s.time_parallel_candidates}}},
                 {"triangles", {{s.time_triangles, s.time_parallel_triangles}}},
                 {"skeleton", {{s.time_lmt, s.time_parallel_lmt}}},
                 {"face_dp", {{s.time_face_dp, s.time_parallel_face_dp}}},
                 {"lp", {{s.time_lp_build + s.time_lp_solve + s.time_branch_and_bound, 0.0}}},
                 {"certificate", {{s.time_certificate, s.time_parallel_certificate}}}};
  for(const auto& st : a.per_stage) {
    a.parallel += st.second[1];
    a.serial += st.second[0] - st.second[1];
  }
  // the rest of the call (outside the statistics' stages) is serial
  const double outside = one_thread.cpu_total - s.time_total;
  if(outside > 0) a.serial += outside;
  a.per_stage.push_back({"outside_stages", {{outside > 0 ? outside : 0.0, 0.0}}});
  a.total = a.serial + a.parallel;
  return a;
}

/*!
  Runs `inputs` (name, points) with every thread count of `threads`, `repeats` times (interleaved), and writes
  `<base>_threads.csv` (medians per input, thread count and stage: wall, processor time, speed-up and efficiency
  against one thread), `<base>_threads_runs.csv` (every run) and `<base>_threads_amdahl.csv` (serial fractions
  of the one-thread runs and the projections). `project_total` > 0: also the projection at 16 threads of a
  one-thread total of that many seconds (e.g. the measured 10^7 run) with the serial fraction measured here.
  Returns false when a result differs between thread counts.
*/
template <class Point>
bool thread_scaling(const std::vector<std::pair<std::string, std::vector<Point>>>& inputs, const MWT::Mwt_options& o,
                    const std::vector<std::size_t>& threads, int repeats, const std::string& base, double project_total)
{
  bool all_identical = true;
  mdcs_bench::Table runs({"input", "n", "threads", "repeat", "status", "weight", "digest", "stage", "wall_s", "cpu_s",
                          "process_peak_MiB"});
  mdcs_bench::Table summary({"input", "n", "threads", "stage", "wall_s", "cpu_s", "speedup", "efficiency", "identical"});
  mdcs_bench::Table am({"input", "n", "stage", "cpu_1thread_s", "in_parallel_loops_s", "serial_s", "serial_fraction"});
  mdcs_bench::Table proj({"input", "n", "threads", "measured_wall_s", "measured_cpu_s", "amdahl_wall_s", "serial_fraction",
                          "note"});
  for(const auto& input : inputs) {
    const std::vector<Point>& p = input.second;
    std::map<std::size_t, std::vector<Run>> by_threads;
    for(int r = 0; r < repeats; ++r)
      for(std::size_t k = 0; k < threads.size(); ++k) {
        const std::size_t t = threads[r % 2 == 0 ? k : threads.size() - 1 - k];
        Run run = run_once(p, o, t);
        std::fprintf(stderr, "%s n=%zu threads=%zu repeat %d: %s, %.3f s wall, %.3f s cpu, process peak %.0f MiB\n",
                     input.first.c_str(), p.size(), t, r, MWT::to_string(run.result.status), run.wall_total, run.cpu_total,
                     run.peak_mib);
        char dg[32];
        std::snprintf(dg, sizeof dg, "%016llx", (unsigned long long)run.digest);
        for(const auto& st : stages())
          if(run.wall.count(st.first))
            runs.add_row({input.first, std::to_string(p.size()), std::to_string(t), std::to_string(r),
                          MWT::to_string(run.result.status), mdcs_bench::fmt(run.result.weight, "%.10f"), dg, st.second,
                          mdcs_bench::fmt(run.wall[st.first], "%.4f"), mdcs_bench::fmt(run.cpu[st.first], "%.4f"),
                          mdcs_bench::fmt(run.peak_mib, "%.0f")});
        runs.add_row({input.first, std::to_string(p.size()), std::to_string(t), std::to_string(r),
                      MWT::to_string(run.result.status), mdcs_bench::fmt(run.result.weight, "%.10f"), dg, "total",
                      mdcs_bench::fmt(run.wall_total, "%.4f"), mdcs_bench::fmt(run.cpu_total, "%.4f"),
                      mdcs_bench::fmt(run.peak_mib, "%.0f")});
        by_threads[t].push_back(std::move(run));
      }
    // identical results for every thread count and repeat
    const std::uint64_t d0 = by_threads.begin()->second.front().digest;
    bool identical = true;
    for(const auto& bt : by_threads)
      for(const Run& run : bt.second) identical = identical && run.digest == d0;
    all_identical = all_identical && identical;
    auto median_of = [&](std::size_t t, const std::string& stage, bool wall) {
      std::vector<double> v;
      for(const Run& run : by_threads[t]) {
        if(stage == "total") v.push_back(wall ? run.wall_total : run.cpu_total);
        else {
          const auto& m = wall ? run.wall : run.cpu;
          const auto it = m.find(stage);
          v.push_back(it == m.end() ? 0.0 : it->second);
        }
      }
      return mdcs_bench::median(v);
    };
    const std::size_t t1 = threads.front();
    std::vector<std::pair<std::string, std::string>> names = stages();
    names.push_back({"total", "total"});
    for(std::size_t t : threads)
      for(const auto& st : names) {
        const double w = median_of(t, st.first, true), c = median_of(t, st.first, false), w1 = median_of(t1, st.first, true);
        if(w == 0 && w1 == 0) continue;
        const double speedup = w > 0 ? w1 / w : 0;
        summary.add_row({input.first, std::to_string(p.size()), std::to_string(t), st.second, mdcs_bench::fmt(w, "%.4f"),
                         mdcs_bench::fmt(c, "%.4f"), mdcs_bench::fmt(speedup, "%.3f"),
                         mdcs_bench::fmt(speedup * double(t1) / double(t), "%.3f"), identical ? "yes" : "NO"});
      }
    // serial fractions from the one-thread runs (medians of the stage times: the run with the median total)
    if(by_threads.count(1)) {
      std::vector<Run>& ones = by_threads[1];
      std::vector<double> totals;
      for(const Run& run : ones) totals.push_back(run.cpu_total);
      const double med = mdcs_bench::median(totals);
      const Run* pick = &ones.front();
      for(const Run& run : ones)
        if(std::abs(run.cpu_total - med) < std::abs(pick->cpu_total - med)) pick = &run;
      const Amdahl a = amdahl(*pick);
      for(const auto& st : a.per_stage)
        am.add_row({input.first, std::to_string(p.size()), st.first, mdcs_bench::fmt(st.second[0], "%.4f"),
                    mdcs_bench::fmt(st.second[1], "%.4f"), mdcs_bench::fmt(st.second[0] - st.second[1], "%.4f"),
                    mdcs_bench::fmt(st.second[0] > 0 ? (st.second[0] - st.second[1]) / st.second[0] : 0.0, "%.4f")});
      am.add_row({input.first, std::to_string(p.size()), "total", mdcs_bench::fmt(a.total, "%.4f"),
                  mdcs_bench::fmt(a.parallel, "%.4f"), mdcs_bench::fmt(a.serial, "%.4f"), mdcs_bench::fmt(a.fraction(), "%.4f")});
      for(std::size_t t : threads)
        proj.add_row({input.first, std::to_string(p.size()), std::to_string(t), mdcs_bench::fmt(median_of(t, "total", true), "%.4f"),
                      mdcs_bench::fmt(median_of(t, "total", false), "%.4f"), mdcs_bench::fmt(a.projected(double(t)), "%.4f"),
                      mdcs_bench::fmt(a.fraction(), "%.4f"), "measured; amdahl_wall from the one-thread processor times"});
      for(double t : {4.0, 8.0, 16.0})
        proj.add_row({input.first, std::to_string(p.size()), mdcs_bench::fmt(t, "%.0f"), "-", "-",
                      mdcs_bench::fmt(a.projected(t), "%.4f"), mdcs_bench::fmt(a.fraction(), "%.4f"), "PROJECTION (Amdahl)"});
      if(project_total > 0)
        proj.add_row({input.first, "given total", "16", "-", mdcs_bench::fmt(project_total, "%.1f"),
                      mdcs_bench::fmt(project_total * (a.fraction() + (1 - a.fraction()) / 16), "%.2f"),
                      mdcs_bench::fmt(a.fraction(), "%.4f"),
                      "PROJECTION (Amdahl) of the given one-thread total with this serial fraction"});
    }
  }
  std::printf("\nThread scaling (medians of %d; wall-clock and processor seconds per stage; speed-up and efficiency "
              "against %zu thread(s)):\n", repeats, threads.front());
  summary.print();
  std::printf("\nSerial parts of the one-thread run (processor seconds; the stage clock of the statistics):\n");
  am.print();
  std::printf("\nMeasured and projected wall-clock time (Amdahl's law from the serial fraction above; a projection "
              "ignores memory bandwidth):\n");
  proj.print();
  std::printf("\nresults identical for every thread count and repeat: %s\n", all_identical ? "yes" : "NO");
  summary.write_csv(base + "_threads.csv");
  runs.write_csv(base + "_threads_runs.csv");
  am.write_csv(base + "_threads_amdahl.csv");
  proj.write_csv(base + "_threads_projection.csv");
  return all_identical;
}

} // namespace mwt_scaling

#endif // MDCS_BENCH_MWT_THREAD_SCALING_H
