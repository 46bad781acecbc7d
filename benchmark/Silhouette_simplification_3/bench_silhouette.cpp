// Silhouette simplification (thesis chapter 5, Table 5.1): per-view timings of silhouette extraction,
// loop decomposition, loop picking (method A) and loop mapping (method B), the preprocessing (coarse
// mesh and face map) separately, edge counts, and the temporal-coherence metric with and without the
// previous-frame remedy.
//
// usage: bench_silhouette [--csv FILE] [--views N] [--frames N] [--large] [--mesh FILE --fine-faces N]...
//   Default meshes (CGAL's demo data, MDCS_CGAL_MESH_DIR): bunny00.off simplified to 20,000 faces
//   (coarse 1,000), bunny00.off as is (75k faces, coarse 1,000), and armadillo.off (52k faces, coarse
//   1,000). --large adds bunny00.off after two Loop subdivisions (~1.2M faces, coarse 1,000). --mesh FILE adds a mesh of your own.
#include <mdcs_bench.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Silhouette_simplification_3.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <cmath>
#include <cstdio>
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

struct Case
{
  std::string name, path;
  std::size_t fine_faces = 0; // 0: as read
  unsigned subdivisions = 0;
  std::size_t coarse_faces = 1000;
};

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
  std::size_t views = 36, frames = 60;
  bool large = false;
  std::vector<Case> cases;
  const std::string dir = MDCS_CGAL_MESH_DIR;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--csv" && i + 1 < argc) csv = argv[++i];
    else if(a == "--views" && i + 1 < argc) views = std::stoul(argv[++i]);
    else if(a == "--frames" && i + 1 < argc) frames = std::stoul(argv[++i]);
    else if(a == "--large") large = true;
    else if(a == "--mesh" && i + 1 < argc) { Case c; c.path = argv[++i]; c.name = c.path.substr(c.path.find_last_of('/') + 1); cases.push_back(c); }
    else if(a == "--fine-faces" && i + 1 < argc && !cases.empty()) cases.back().fine_faces = std::stoul(argv[++i]);
    else { std::fprintf(stderr, "usage: %s [--csv FILE] [--views N] [--frames N] [--large] [--mesh FILE [--fine-faces N]]...\n", argv[0]); return 2; }
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
  for(const Case& c : cases) {
    Mesh fine;
    if(!CGAL::IO::read_polygon_mesh(c.path, fine) || num_faces(fine) == 0) {
      std::fprintf(stderr, "cannot read %s, skipped\n", c.path.c_str());
      continue;
    }
    if(c.fine_faces > 0 && num_faces(fine) > c.fine_faces) {
      SS::Coarse_mesh_options o;
      o.target_faces = c.fine_faces;
      o.smoothing_iterations = 0;
      fine = SS::build_coarse_mesh(fine, o).mesh;
    }
    for(unsigned s = 0; s < c.subdivisions; ++s) CGAL::Subdivision_method_3::Loop_subdivision(fine);
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
  return 0;
}
