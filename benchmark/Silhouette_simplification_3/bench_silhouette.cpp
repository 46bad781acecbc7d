// Silhouette simplification (thesis chapter 5, Table 5.1): per-view timings of silhouette extraction,
// loop decomposition, loop picking (method A) and loop mapping (method B), the preprocessing (coarse
// mesh and face map) separately, edge counts, and the temporal-coherence metric with and without the
// previous-frame remedy.
//
// Thread scaling (issue 29 item 5): a rotation of --rotation-frames views (default 72) through
// simplify_silhouette_frames() at each of --threads (default 1,2), picking and mapping, without and with the
// previous-frame remedy (then the biased methods run in view order); interleaved runs (--runs, default 3), medians,
// speed-up, efficiency, the frames compared across thread counts, the serial fraction from the per-view stage
// times of the first table and Amdahl's projection at 16 threads (a projection). CSV: FILE with "_threads" added.
//
// usage: bench_silhouette [--csv FILE] [--views N] [--frames N] [--large] [--mesh FILE --fine-faces N]...
//                         [--threads 1,2] [--rotation-frames N] [--runs N]
//   Default meshes (CGAL's demo data, MDCS_CGAL_MESH_DIR): bunny00.off simplified to 20,000 faces
//   (coarse 1,000), bunny00.off as is (75k faces, coarse 1,000), and armadillo.off (52k faces, coarse
//   1,000). --large adds bunny00.off after two Loop subdivisions (~1.2M faces, coarse 1,000). --mesh FILE adds a mesh of your own.
#include <mdcs_bench.h>
#include <silhouette_bench_meshes.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Silhouette_simplification_3.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <cstring>
#include <string>
#include <vector>

#ifndef MDCS_CGAL_MESH_DIR
#define MDCS_CGAL_MESH_DIR ""
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
namespace SS = CGAL::Silhouette_simplification_3;
typedef SS::View_3<K> View;

typedef mdcs_bench::Silhouette_bench_case Case;

// Perspective views on a circle around the vertical axis (y for these models), slightly above.
static View orbit(const CGAL::Bbox_3& b, double angle)
{
  const double cx = (b.xmin() + b.xmax()) / 2, cy = (b.ymin() + b.ymax()) / 2, cz = (b.zmin() + b.zmax()) / 2;
  const double d = std::sqrt((b.xmax() - b.xmin()) * (b.xmax() - b.xmin()) + (b.ymax() - b.ymin()) * (b.ymax() - b.ymin()) +
                             (b.zmax() - b.zmin()) * (b.zmax() - b.zmin()));
  const double r = 2.5 * d;
  return View::perspective(Point_3(cx + r * std::cos(angle), cy + 0.3 * r, cz + r * std::sin(angle)));
}

int main(int argc, char** argv)
{
  std::string csv = "silhouette.csv";
  std::size_t views = 36, frames = 60, rotation_frames = 72;
  std::vector<std::size_t> threads = {1, 2};
  int runs = 3;
  bool large = false;
  std::vector<Case> cases;
  const std::string dir = MDCS_CGAL_MESH_DIR;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--csv" && i + 1 < argc) csv = argv[++i];
    else if(a == "--views" && i + 1 < argc) views = std::stoul(argv[++i]);
    else if(a == "--frames" && i + 1 < argc) frames = std::stoul(argv[++i]);
    else if(a == "--large") large = true;
    else if(a == "--rotation-frames" && i + 1 < argc) rotation_frames = std::stoul(argv[++i]);
    else if(a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
    else if(a == "--threads" && i + 1 < argc) {
      threads.clear();
      const std::string list = argv[++i];
      for(std::size_t p = 0; p < list.size();) {
        const std::size_t q = list.find(',', p);
        threads.push_back(std::size_t(std::stoul(list.substr(p, q - p))));
        p = q == std::string::npos ? list.size() : q + 1;
      }
    }
    else if(a == "--mesh" && i + 1 < argc) { Case c; c.path = argv[++i]; c.name = c.path.substr(c.path.find_last_of('/') + 1); cases.push_back(c); }
    else if(a == "--fine-faces" && i + 1 < argc && !cases.empty()) cases.back().fine_faces = std::stoul(argv[++i]);
    else { std::fprintf(stderr, "usage: %s [--csv FILE] [--views N] [--frames N] [--large] [--mesh FILE [--fine-faces N]]... "
                                "[--threads 1,2] [--rotation-frames N] [--runs N]\n", argv[0]); return 2; }
  }
  if(cases.empty()) {
    if(dir.empty()) { std::fprintf(stderr, "no CGAL demo meshes (MDCS_CGAL_MESH_DIR is empty): give --mesh FILE\n"); return 2; }
    Case bunny; bunny.name = "bunny 20k"; bunny.path = dir + "/bunny00.off"; bunny.fine_faces = 20000;
    Case full; full.name = "bunny 75k"; full.path = dir + "/bunny00.off";
    Case arma; arma.name = "armadillo"; arma.path = dir + "/armadillo.off";
    cases = {bunny, full, arma};
    if(large) { Case big; big.name = "bunny Loop x2"; big.path = dir + "/bunny00.off"; big.subdivisions = 2; cases.push_back(big); }
  }

  std::printf("Silhouette simplification, per-view medians over %zu views (ms); coherence over %zu frames of 0.5 deg.\n"
              "Machine shared with other jobs: timings are noisy.\n\n", views, frames);
  mdcs_bench::Table table({"mesh", "fine_faces", "coarse_faces", "preprocess_s", "coarse_extract_ms", "coarse_decomp_ms",
                           "fine_extract_ms", "fine_decomp_ms", "picking_ms", "mapping_ms", "fine_edges", "coarse_edges",
                           "picked_edges", "mapped_edges", "mapped_edges_alpha1", "fine_loops", "coarse_loops", "incoh_picking", "incoh_picking_remedy",
                           "incoh_mapping", "incoh_mapping_remedy", "peak_MiB"});
  mdcs_bench::Table scaling({"mesh", "fine_faces", "frames", "remedy", "threads", "wall_s", "cpu_s", "speedup", "efficiency",
                             "cpu_ratio", "cpu_speedup", "cpu_efficiency",
                             "serial_fraction", "projected_16_threads_s", "identical", "load"});
  const auto load_line = mdcs_bench::load_average;
  for(const Case& c : cases) {
    Mesh fine;
    if(!mdcs_bench::read_silhouette_bench_mesh(c.path, c.fine_faces, c.subdivisions, fine)) continue;
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(fine);

    double t0 = mdcs_bench::now_seconds();
    SS::Coarse_mesh_options o;
    o.target_faces = c.coarse_faces;
    const auto coarse = SS::build_coarse_mesh(fine, o);
    SS::Silhouette_simplifier_3<Mesh> simplifier(fine, coarse.mesh, coarse.coarse_face_of_fine_face);
    const double pre = mdcs_bench::now_seconds() - t0;

    std::vector<double> ce, cd, fe, fd, pk, mp, nf, nc, np, nm, nm1, lf, lc;
    SS::Silhouette_frame frame;
    for(std::size_t v = 0; v < views; ++v) {
      const View view = orbit(box, 6.283185307179586 * double(v) / double(views));
      // Silhouette extraction and decomposition, timed separately for the fine and coarse meshes.
      double a = mdcs_bench::now_seconds();
      SS::internal::classify_faces(simplifier.coarse(), view, frame.coarse_front);
      SS::internal::silhouette_from_faces(simplifier.coarse(), frame.coarse_front, frame.coarse_silhouette);
      double b = mdcs_bench::now_seconds();
      SS::internal::Loop_decomposer dec;
      dec(simplifier.coarse(), frame.coarse_silhouette, frame.coarse_loops);
      double d = mdcs_bench::now_seconds();
      ce.push_back(1e3 * (b - a)); cd.push_back(1e3 * (d - b));
      a = mdcs_bench::now_seconds();
      SS::internal::classify_faces(simplifier.fine(), view, frame.fine_front);
      SS::internal::silhouette_from_faces(simplifier.fine(), frame.fine_front, frame.fine_silhouette);
      b = mdcs_bench::now_seconds();
      dec(simplifier.fine(), frame.fine_silhouette, frame.fine_loops);
      d = mdcs_bench::now_seconds();
      fe.push_back(1e3 * (b - a)); fd.push_back(1e3 * (d - b));
      a = mdcs_bench::now_seconds();
      simplifier.pick_loops(frame);
      b = mdcs_bench::now_seconds();
      simplifier.map_loops(frame);
      d = mdcs_bench::now_seconds();
      pk.push_back(1e3 * (b - a)); mp.push_back(1e3 * (d - b));
      nf.push_back(double(frame.fine_silhouette.size())); nc.push_back(double(frame.coarse_silhouette.size()));
      np.push_back(double(frame.picked_halfedges().size())); nm.push_back(double(frame.mapped_halfedges().size()));
      {
        // Edge count of loop mapping without the silhouette discount (alpha = 1), not timed.
        SS::Silhouette_frame f1 = frame;
        SS::Loop_mapping_options o1;
        o1.alpha = 1.0;
        simplifier.map_loops(f1, o1);
        nm1.push_back(double(f1.mapped_halfedges().size()));
      }
      lf.push_back(double(frame.fine_loops.size())); lc.push_back(double(frame.coarse_loops.size()));
    }

    // Temporal coherence over a slow rotation, with and without the previous-frame bias.
    double incoh[4];
    for(int variant = 0; variant < 4; ++variant) {
      const bool mapping = variant >= 2, remedy = variant % 2 == 1;
      std::vector<std::vector<std::uint32_t>> fs, ss;
      SS::Silhouette_frame prev, cur;
      SS::Loop_picking_options po;
      SS::Loop_mapping_options mo;
      if(remedy) { po.previous_bias = 0.5; mo.previous_bias = 0.5; }
      for(std::size_t t = 0; t < frames; ++t) {
        simplifier.extract(orbit(box, 0.5 * 3.14159265358979 / 180 * double(t)), cur);
        std::vector<std::uint32_t> f, s;
        for(std::uint32_t h : cur.fine_silhouette) f.push_back(simplifier.fine().edge(h));
        if(mapping) {
          simplifier.map_loops(cur, mo, t > 0 ? &prev : nullptr);
          for(std::uint32_t h : cur.mapped_halfedges()) s.push_back(simplifier.fine().edge(h));
        } else {
          simplifier.pick_loops(cur, po, t > 0 ? &prev : nullptr);
          for(std::uint32_t h : cur.picked_halfedges()) s.push_back(simplifier.fine().edge(h));
        }
        fs.push_back(f);
        ss.push_back(s);
        std::swap(prev, cur);
      }
      incoh[variant] = SS::temporal_incoherence(ss, fs);
    }

    using mdcs_bench::fmt;
    using mdcs_bench::median;
    // Thread scaling of a whole rotation through simplify_silhouette_frames(), interleaved runs.
    {
      std::vector<View> rotation;
      for(std::size_t t = 0; t < rotation_frames; ++t) rotation.push_back(orbit(box, 6.283185307179586 * double(t) / double(rotation_frames)));
      const double per_view = median(ce) + median(cd) + median(fe) + median(fd) + median(pk) + median(mp);
      for(int remedy = 0; remedy < 2; ++remedy) {
        SS::Silhouette_frames_options fo;
        if(remedy) { fo.picking.previous_bias = 0.5; fo.mapping.previous_bias = 0.5; }
        std::map<std::size_t, std::vector<double>> wall, cpu;
        std::map<std::size_t, std::vector<double>> fingerprint;
        for(int r = 0; r < runs; ++r)
          for(std::size_t th : threads) {
            fo.threads = th;
            std::vector<double> f;
            const double t0 = mdcs_bench::now_seconds(), c0 = mdcs_bench::cpu_seconds();
            SS::simplify_silhouette_frames<CGAL::Parallel_tag>(simplifier, rotation, fo, [&](std::size_t, SS::Silhouette_frame& fr) {
              f.push_back(double(fr.fine_silhouette.size()));
              f.push_back(fr.picking_error);
              f.push_back(double(fr.mapped_halfedges().size()));
            });
            wall[th].push_back(mdcs_bench::now_seconds() - t0);
            cpu[th].push_back(mdcs_bench::cpu_seconds() - c0);
            if(r == 0) fingerprint[th] = f;
          }
        const std::size_t t1 = threads.front();
        const double w1 = median(wall[t1]), c1 = median(cpu[t1]);
        // Serial: with the remedy, picking and mapping run in view order (per-view medians of the table above).
        const double s = remedy ? (median(pk) + median(mp)) / per_view : 0.0;
        for(std::size_t th : threads) {
          const double w = median(wall[th]), ct = median(cpu[th]);
          // The speed-up an idle machine would give, from CPU times: the serial share of the CPU time at one thread
          // alone, the rest of the CPU time at th threads spread over them (a projection; see the legend).
          const double cs = c1 / (s * c1 + std::max(0.0, ct - s * c1) / double(th));
          const bool identical = fingerprint[th] == fingerprint[t1];
          scaling.add_row({"\"" + c.name + "\"", std::to_string(num_faces(fine)), std::to_string(rotation_frames),
                           remedy ? "yes" : "no", std::to_string(th), fmt(w), fmt(ct), fmt(w1 / w),
                           fmt(w1 / w / double(th)), fmt(ct / c1), fmt(cs), fmt(cs / double(th)), fmt(s, "%.3f"), fmt(c1 * (s + (1 - s) / 16)), identical ? "yes" : "NO",
                           load_line()});
          std::printf("  %s, rotation of %zu frames%s, %zu thread(s): %.3f s, speed-up %.3f, CPU %.3f s (idle-machine "
                      "speed-up from CPU times %.3f)%s\n", c.name.c_str(), rotation_frames, remedy ? " with the remedy" : "",
                      th, w, w1 / w, ct, cs, identical ? "" : "  FRAMES DIFFER");
          std::fflush(stdout);
        }
      }
    }
    table.add_row({"\"" + c.name + "\"", std::to_string(num_faces(fine)), std::to_string(num_faces(coarse.mesh)), fmt(pre, "%.3f"),
                   fmt(median(ce), "%.4f"), fmt(median(cd), "%.4f"), fmt(median(fe), "%.4f"), fmt(median(fd), "%.4f"),
                   fmt(median(pk), "%.4f"), fmt(median(mp), "%.3f"), fmt(median(nf), "%.0f"), fmt(median(nc), "%.0f"),
                   fmt(median(np), "%.0f"), fmt(median(nm), "%.0f"), fmt(median(nm1), "%.0f"), fmt(median(lf), "%.0f"), fmt(median(lc), "%.0f"),
                   fmt(incoh[0], "%.3f"), fmt(incoh[1], "%.3f"), fmt(incoh[2], "%.3f"), fmt(incoh[3], "%.3f"),
                   fmt(mdcs_bench::peak_rss_mib(), "%.0f")});
    std::fflush(stdout);
  }
  table.print();
  if(!table.write_csv(csv)) { std::fprintf(stderr, "cannot write %s\n", csv.c_str()); return 1; }
  std::printf("\nCSV written to %s\n", csv.c_str());
  std::printf("\nThread scaling of simplify_silhouette_frames (speedup = wall(1 thread) / wall(t); cpu_ratio = CPU time at "
              "t threads / CPU time at 1; cpu_speedup = CPU(1) / (serial CPU + (CPU(t) - serial CPU) / t), the speed-up "
              "an idle machine would give, a projection from CPU times for a loaded machine; serial_fraction: "
              "share of picking + mapping in a view when the remedy makes them run in order, else 0; "
              "projected_16_threads_s: Amdahl's law from it and the CPU time at one thread, a projection):\n");
  scaling.print();
  const std::string scaling_csv = csv.size() > 4 && csv.compare(csv.size() - 4, 4, ".csv") == 0
                                    ? csv.substr(0, csv.size() - 4) + "_threads.csv" : csv + "_threads.csv";
  if(!scaling.write_csv(scaling_csv)) { std::fprintf(stderr, "cannot write %s\n", scaling_csv.c_str()); return 1; }
  std::printf("CSV written to %s\n", scaling_csv.c_str());
  return 0;
}
