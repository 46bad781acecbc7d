// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Benchmark of Line_arrangement_2 on random lines, with CGAL::Arrangement_2 (exact kernel, aggregated
// insertion of the clipped segments) as the anchor for the smaller sizes.
//
//   bench_line_arrangement_2 [--large] [--no-cgal] [--csv FILE] [--sizes 100,300,...]
//
// Two families: random lines in the unit square, and random lines in [-1, 1] x [0, 2] with 10% of them
// in pencils through (-1, 2) and (1, 2) (the boundary points of a curve problem). Build time is the
// median of 3 runs (1 run from 10^4 lines on); "peak MiB" is the growth of the peak resident set during
// one build (the peak counter is reset before it), "final MiB" the memory held by the result.

#include <CGAL/Variational_minimization/Line_arrangement_2.h>
#include <CGAL/Variational_minimization/line_grids_2.h>

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include "mdcs_bench.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace VM = CGAL::Variational_minimization;

namespace {

typedef CGAL::Exact_predicates_exact_constructions_kernel EK;
typedef CGAL::Arrangement_2<CGAL::Arr_segment_traits_2<EK>> Cgal_arrangement;

struct Family
{
  const char* name;
  CGAL::Bbox_2 box;
  VM::Random_lines_options options;
};

// Our structure, timed; the result is destroyed before returning so that the next run starts clean.
struct Our_run
{
  double seconds = 0, peak_mib = 0, final_mib = 0;
  std::size_t v = 0, e = 0, f = 0;
};

// Give freed heap memory back to the system, so that the resident set before a build is a fair base
// (otherwise a build reuses memory kept from a larger earlier one and its growth reads as zero).
void release_free_memory()
{
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

Our_run run_ours(const Family& family, const std::vector<VM::Arrangement_line_2>& lines)
{
  Our_run r;
  release_free_memory();
  const double base = mdcs_bench::current_rss_mib();
  mdcs_bench::reset_peak_rss();
  const double t0 = mdcs_bench::now_seconds();
  std::unique_ptr<VM::Line_arrangement_2> a(new VM::Line_arrangement_2(family.box, lines));
  r.seconds = mdcs_bench::now_seconds() - t0;
  r.peak_mib = mdcs_bench::peak_rss_mib() - base;
  r.v = a->number_of_vertices();
  r.e = a->number_of_edges();
  r.f = a->number_of_faces();
  r.final_mib = (double(r.v) * sizeof(VM::Point_2) + double(r.e) * sizeof(VM::Line_arrangement_2::Edge)) / 1048576.0;
  return r;
}

double run_cgal(const Family& family, const std::vector<VM::Arrangement_line_2>& lines, std::size_t& v)
{
  const CGAL::Bbox_2& b = family.box;
  const double t0 = mdcs_bench::now_seconds();
  const EK::Iso_rectangle_2 rect(EK::Point_2(b.xmin(), b.ymin()), EK::Point_2(b.xmax(), b.ymax()));
  std::vector<EK::Segment_2> segments;
  for(const auto& l : lines) {
    const auto clipped = CGAL::intersection(EK::Line_2(EK::Point_2(l.p.x(), l.p.y()), EK::Point_2(l.q.x(), l.q.y())), rect);
    if(clipped)
      if(const EK::Segment_2* s = boost::get<EK::Segment_2>(&*clipped)) segments.push_back(*s);
  }
  const EK::Point_2 c[4] = { EK::Point_2(b.xmin(), b.ymin()), EK::Point_2(b.xmax(), b.ymin()),
                             EK::Point_2(b.xmax(), b.ymax()), EK::Point_2(b.xmin(), b.ymax()) };
  for(int i = 0; i < 4; ++i) segments.push_back(EK::Segment_2(c[i], c[(i + 1) % 4]));
  Cgal_arrangement arr;
  CGAL::insert(arr, segments.begin(), segments.end());
  const double seconds = mdcs_bench::now_seconds() - t0;
  v = arr.number_of_vertices();
  return seconds;
}

std::vector<std::size_t> parse_sizes(const std::string& text)
{
  std::vector<std::size_t> sizes;
  std::stringstream in(text);
  std::string item;
  while(std::getline(in, item, ','))
    sizes.push_back(std::size_t(std::stoull(item)));
  return sizes;
}

} // namespace

int main(int argc, char** argv)
{
  bool large = false, cgal = true;
  std::string csv;
  std::vector<std::size_t> sizes = { 100, 300, 1000, 3000, 10000 };
  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if(arg == "--large") large = true;
    else if(arg == "--no-cgal") cgal = false;
    else if(arg == "--csv" && i + 1 < argc) csv = argv[++i];
    else if(arg == "--sizes" && i + 1 < argc) sizes = parse_sizes(argv[++i]);
    else {
      std::fprintf(stderr, "usage: %s [--large] [--no-cgal] [--csv FILE] [--sizes 100,300,...]\n", argv[0]);
      return 2;
    }
  }
  const std::size_t cgal_limit = 1000;

  std::vector<Family> families(2);
  families[0].name = "unit-square";
  families[0].box = CGAL::Bbox_2(0, 0, 1, 1);
  families[1].name = "pencils";   // [-1, 1] x [0, 2], 10% in pencils
  families[1].box = CGAL::Bbox_2(-1, 0, 1, 2);
  families[1].options.pencil_points = { VM::Point_2(-1, 2), VM::Point_2(1, 2) };
  families[1].options.pencil_fraction = 0.1;

  mdcs_bench::Table table({ "family", "lines", "V", "E", "F", "build s", "peak MiB", "final MiB", "CGAL s", "CGAL/ours" });
  for(const Family& family : families) {
    double last_seconds = 0;
    std::size_t last_n = 0;
    for(std::size_t n : sizes) {
      // The largest size only on request, or when the extrapolation from the previous one is modest
      // (the cost grows like n^2).
      if(n >= 10000 && !large && last_n != 0) {
        const double predicted = last_seconds * (double(n) / double(last_n)) * (double(n) / double(last_n));
        if(predicted > 60) {
          std::printf("skipping %zu lines (predicted %.0f s; use --large)\n", n, predicted);
          continue;
        }
      }
      const auto lines = VM::random_lines_2(family.box, n, /*seed*/ 1000 + n, family.options);
      const int runs = n >= 10000 ? 1 : 3;
      std::vector<double> times;
      Our_run r;
      double peak = 0;
      for(int k = 0; k < runs; ++k) {
        r = run_ours(family, lines);
        times.push_back(r.seconds);
        peak = std::max(peak, r.peak_mib);
      }
      const double ours = mdcs_bench::median(times);
      last_seconds = ours;
      last_n = n;

      std::string cgal_s = "-", ratio = "-";
      if(cgal && n <= cgal_limit) {
        std::vector<double> cgal_times;
        const int cgal_runs = n <= 300 ? 3 : 1;
        for(int k = 0; k < cgal_runs; ++k) {
          std::size_t v = 0;
          cgal_times.push_back(run_cgal(family, lines, v));
          if(v != r.v) {
            std::fprintf(stderr, "vertex count mismatch with CGAL: %zu vs %zu\n", r.v, v);
            return 1;
          }
        }
        const double c = mdcs_bench::median(cgal_times);
        cgal_s = mdcs_bench::fmt(c);
        ratio = mdcs_bench::fmt(c / ours, "%.0f");
      }
      table.add_row({ family.name, std::to_string(n), std::to_string(r.v), std::to_string(r.e), std::to_string(r.f),
                      mdcs_bench::fmt(ours), mdcs_bench::fmt(peak, "%.1f"), mdcs_bench::fmt(r.final_mib, "%.1f"),
                      cgal_s, ratio });
      std::printf("%s, %zu lines: %.3f s\n", family.name, n, ours);
      std::fflush(stdout);
    }
  }
  table.print();
  if(!csv.empty() && !table.write_csv(csv)) {
    std::fprintf(stderr, "cannot write %s\n", csv.c_str());
    return 1;
  }
  return 0;
}
