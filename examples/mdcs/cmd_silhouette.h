// `mdcs silhouette`: Silhouette simplification of a triangle mesh (issue 7, thesis chapter 5): the fine
// silhouette for a view, the coarse mesh's silhouette, loop picking (method A) and loop mapping by
// min cut (method B), drawn from the front and from the side; optionally a rotation sequence with the
// temporal-coherence metric.
#ifndef MDCS_CLI_CMD_SILHOUETTE_H
#define MDCS_CLI_CMD_SILHOUETTE_H

#include "cli_common.h"
#include "cmd_mincut.h" // Input_error
#include "mesh_input.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Silhouette_simplification_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#ifndef MDCS_CGAL_MESH_DIR
#define MDCS_CGAL_MESH_DIR ""
#endif

namespace mdcs_cli {

namespace sil_detail {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
namespace SS = CGAL::Silhouette_simplification_3;
typedef SS::View_3<K> View;
typedef SS::Silhouette_simplifier_3<Mesh> Simplifier;

// A camera: eye, forward, right and up unit vectors; perspective or orthographic.
struct Camera
{
  Point_3 eye;
  Vector_3 f, r, u;
  bool perspective = true;

  std::array<double, 2> project(const Point_3& p) const
  {
    const Vector_3 q = p - eye;
    if(!perspective) return {q * r, q * u};
    const double z = std::max(q * f, 1e-12);
    return {(q * r) / z, (q * u) / z};
  }
};

inline Vector_3 unit(const Vector_3& v) { return v / std::sqrt(v.squared_length()); }

// The camera at azimuth/elevation (degrees) around the box centre, distance 2.5 diagonals, up axis `up`.
inline Camera orbit_camera(const CGAL::Bbox_3& b, double azimuth_deg, double elevation_deg, int up)
{
  const double pi = 3.14159265358979323846;
  const Point_3 c((b.xmin() + b.xmax()) / 2, (b.ymin() + b.ymax()) / 2, (b.zmin() + b.zmax()) / 2);
  const double d = std::sqrt((b.xmax() - b.xmin()) * (b.xmax() - b.xmin()) + (b.ymax() - b.ymin()) * (b.ymax() - b.ymin()) +
                             (b.zmax() - b.zmin()) * (b.zmax() - b.zmin()));
  const double a = azimuth_deg * pi / 180, e = elevation_deg * pi / 180;
  // Local frame: up axis `up`, two horizontal axes.
  Vector_3 U(0, 0, 0), X(0, 0, 0), Y(0, 0, 0);
  if(up == 0) { U = Vector_3(1, 0, 0); X = Vector_3(0, 1, 0); Y = Vector_3(0, 0, 1); }
  else if(up == 1) { U = Vector_3(0, 1, 0); X = Vector_3(0, 0, 1); Y = Vector_3(1, 0, 0); }
  else { U = Vector_3(0, 0, 1); X = Vector_3(1, 0, 0); Y = Vector_3(0, 1, 0); }
  const Vector_3 dir = std::cos(e) * (std::cos(a) * X + std::sin(a) * Y) + std::sin(e) * U;
  Camera cam;
  cam.eye = c + 2.5 * d * dir;
  cam.f = unit(-dir);
  cam.r = unit(CGAL::cross_product(cam.f, U));
  cam.u = CGAL::cross_product(cam.r, cam.f);
  return cam;
}

// The side camera of `cam`: orthographic, looking along cam.r (from the viewer's left).
inline Camera side_camera(const Camera& cam)
{
  Camera s;
  s.perspective = false;
  s.eye = cam.eye;
  s.f = cam.r;
  s.r = -cam.f;
  s.u = cam.u;
  return s;
}

struct Edge_set
{
  std::string label, color;
  std::vector<std::uint32_t> halfedges;
  double width = 1.0;
};

// One panel per edge set per camera, in a grid (cameras are rows).
inline void write_svg(const std::string& path, const Simplifier& s, const std::vector<Camera>& cams,
                      const std::vector<std::string>& cam_names, const std::vector<Edge_set>& sets,
                      const std::string& title)
{
  const double W = 360, H = 360, margin = 14, top = 40, label = 22;
  Output_file file(path);
  std::ostream& out = file.stream();
  out.precision(6);
  const double width = sets.size() * W, height = top + cams.size() * (H + label);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height << "\" viewBox=\"0 0 "
      << width << " " << height << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"10\" y=\"24\" font-family=\"sans-serif\" font-size=\"16\">" << title << "</text>\n";
  const auto& fine = s.fine();
  for(std::size_t ci = 0; ci < cams.size(); ++ci) {
    // Fit the projected fine vertices.
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for(const Point_3& p : fine.points) {
      const auto q = cams[ci].project(p);
      for(int k = 0; k < 2; ++k) { lo[k] = std::min(lo[k], q[k]); hi[k] = std::max(hi[k], q[k]); }
    }
    const double scale = std::min((W - 2 * margin) / std::max(hi[0] - lo[0], 1e-300), (H - 2 * margin) / std::max(hi[1] - lo[1], 1e-300));
    for(std::size_t si = 0; si < sets.size(); ++si) {
      const double x0 = si * W, y0 = top + ci * (H + label);
      out << "<rect x=\"" << x0 + 2 << "\" y=\"" << y0 << "\" width=\"" << W - 4 << "\" height=\"" << H
          << "\" fill=\"none\" stroke=\"#ddd\"/>\n";
      out << "<text x=\"" << x0 + 8 << "\" y=\"" << y0 + H + 16 << "\" font-family=\"sans-serif\" font-size=\"13\">"
          << cam_names[ci] << ": " << sets[si].label << "</text>\n";
      const bool coarse = sets[si].label.rfind("coarse", 0) == 0;
      const auto& m = coarse ? s.coarse() : fine;
      out << "<path fill=\"none\" stroke=\"" << sets[si].color << "\" stroke-width=\"" << sets[si].width
          << "\" stroke-linecap=\"round\" d=\"";
      out << std::fixed << std::setprecision(1);
      for(std::uint32_t h : sets[si].halfedges) {
        const auto a = cams[ci].project(m.points[m.source[h]]), b = cams[ci].project(m.points[m.target(h)]);
        out << "M" << x0 + margin + (a[0] - lo[0]) * scale << " " << y0 + H - margin - (a[1] - lo[1]) * scale << "L"
            << x0 + margin + (b[0] - lo[0]) * scale << " " << y0 + H - margin - (b[1] - lo[1]) * scale;
      }
      out << std::defaultfloat << std::setprecision(6);
      out << "\"/>\n";
    }
  }
  out << "</svg>\n";
  file.commit();
}

struct Run_summary
{
  std::size_t fine_faces = 0, coarse_faces = 0, fine_edges = 0, coarse_edges = 0, picked_edges = 0, mapped_edges = 0;
  std::size_t fine_loops = 0, coarse_loops = 0, picked_loops = 0, mapped_loops = 0;
  double preprocess_s = 0, extract_ms = 0, picking_ms = 0, mapping_ms = 0, rotation_s = 0, coherence_s = 0, output_s = 0;
  double incoherence[4] = {-1, -1, -1, -1}; // picking, picking+remedy, mapping, mapping+remedy
  bool consistent = true;
  std::string problems;
  std::vector<std::string> files;
  std::string report; // the text printed and written to summary.txt
};

struct Run_parameters
{
  std::size_t coarse_faces = 1000;
  double alpha = 0.1, azimuth = 30, elevation = 20, remedy_bias = 0.5;
  int up = 1;
  bool picking = true, mapping = true, orthographic = false, picture = true;
  bool hierarchy = false; // fine silhouettes through Silhouette_simplifier_3::build_silhouette_hierarchy()
  long frames = 0;
  std::size_t threads = 0; // frames and temporal coherence in parallel (0: every hardware thread)
  std::string name = "mesh";
};

inline double ms_since(std::chrono::steady_clock::time_point t0) { return 1e3 * seconds_since(t0); }

// Checks that loops are closed chains of real fine edges; picked edges lie on the fine silhouette.
inline void check_frame(const Simplifier& s, const SS::Silhouette_frame& frame, Run_summary& sum)
{
  auto fail = [&](const std::string& what) { sum.consistent = false; if(sum.problems.empty()) sum.problems = what; };
  for(const auto* loops : {&frame.fine_loops, &frame.coarse_loops, &frame.mapped}) {
    const auto& m = loops == &frame.coarse_loops ? s.coarse() : s.fine();
    for(const auto& l : *loops) {
      if(!l.closed) fail("an open loop");
      for(std::size_t i = 0; i < l.halfedges.size(); ++i)
        if(l.halfedges[i] >= m.number_of_halfedges() || m.target(l.halfedges[i]) != m.source[l.halfedges[(i + 1) % l.halfedges.size()]])
          fail("a loop that is not a chain of mesh edges");
    }
  }
  std::vector<char> on(s.fine().number_of_halfedges(), 0);
  for(std::uint32_t h : frame.fine_silhouette) on[h] = 1;
  for(std::uint32_t h : frame.picked_halfedges())
    if(!on[h]) fail("a picked edge off the fine silhouette");
}

// The loops of one view as data (loops.csv): one row per loop vertex, in loop order, with the loop's set (fine:
// every fine silhouette loop; coarse; picked: method A; mapped: method B), its number in the set, whether it is
// closed, the vertex (an index into the mesh as read for fine / picked / mapped, into coarse.off for coarse) and
// its coordinates (17 significant digits).
inline void write_loops_csv(const std::string& path, const Simplifier& s, const SS::Silhouette_frame& frame, const Run_parameters& p)
{
  Output_file out(path);
  out << "set,loop,closed,position,vertex,x,y,z\n";
  auto loops = [&](const char* set, const std::vector<SS::Silhouette_frame::Loop>& list, const std::vector<std::uint32_t>* pick, bool coarse) {
    const auto& m = coarse ? s.coarse() : s.fine();
    const std::size_t count = pick ? pick->size() : list.size();
    for(std::size_t k = 0; k < count; ++k) {
      const auto& l = list[pick ? (*pick)[k] : k];
      for(std::size_t i = 0; i < l.halfedges.size(); ++i) {
        const std::uint32_t v = m.source[l.halfedges[i]];
        const Point_3& q = m.points[v];
        out << set << "," << k << "," << (l.closed ? 1 : 0) << "," << i << "," << v << "," << q.x() << "," << q.y() << "," << q.z() << "\n";
      }
    }
  };
  loops("fine", frame.fine_loops, nullptr, false);
  loops("coarse", frame.coarse_loops, nullptr, true);
  if(p.picking) loops("picked", frame.fine_loops, &frame.picked, false);
  if(p.mapping) loops("mapped", frame.mapped, nullptr, false);
  out.commit();
}

inline void write_off_checked(const std::string& path, const Mesh& m)
{
  Output_file out(path);
  out << "OFF\n" << m.number_of_vertices() << " " << m.number_of_faces() << " 0\n";
  for(Mesh::Vertex_index v : m.vertices()) out << m.point(v).x() << " " << m.point(v).y() << " " << m.point(v).z() << "\n";
  for(Mesh::Face_index f : m.faces()) {
    out << "3";
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(m.halfedge(f), m)) out << " " << std::size_t(v);
    out << "\n";
  }
  out.commit();
}

// Runs one view (and optionally a rotation) and writes the files into `folder`: loops.csv, coarse.off,
// silhouette.svg (front and side) unless p.picture is false, and with p.frames > 1 frames.csv and frame_NNN.svg.
// Defined in cmd_silhouette.cpp, so that it is compiled once: `mdcs demo` calls it too, and each translation unit that
// compiled the run instantiated every algorithm it uses again (under the sanitizers of CI, minutes of CPU).
Run_summary run_silhouette(const Mesh& fine, const Run_parameters& p, const std::filesystem::path& folder, const Progress_bar& progress);

// The mesh reader of the mesh commands (mesh_input.h): OFF / PLY / OBJ / STL, repaired and triangulated when
// needed (with a note on stderr), or the generated @torus / @icosphere.
inline Mesh read_triangle_mesh(const std::string& path, bool repair = false, bool* repaired = nullptr)
{
  Mesh m;
  std::vector<std::string> notes;
  const bool was_repaired = load_geodesics_mesh(path, m, notes, repair);
  if(repaired) *repaired = was_repaired;
  for(const std::string& note : notes) std::cerr << "mdcs silhouette: note: " << note << "\n";
  return m;
}

// A bumpy closed surface for machines without CGAL's demo meshes: a subdivided icosahedron with radial noise.
inline Mesh generated_mesh(int levels)
{
  Mesh m;
  const double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<Point_3> p = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                            {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<std::size_t, 3>> f = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                               {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                                               {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for(int l = 0; l < levels; ++l) {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> mid;
    auto m_ = [&](std::size_t a, std::size_t b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(key);
      if(it != mid.end()) return it->second;
      p.push_back(CGAL::midpoint(p[a], p[b]));
      return mid[key] = p.size() - 1;
    };
    std::vector<std::array<std::size_t, 3>> g;
    for(const auto& x : f) {
      const std::size_t ab = m_(x[0], x[1]), bc = m_(x[1], x[2]), ca = m_(x[2], x[0]);
      g.push_back({x[0], ab, ca}); g.push_back({x[1], bc, ab}); g.push_back({x[2], ca, bc}); g.push_back({ab, bc, ca});
    }
    f.swap(g);
  }
  std::vector<Mesh::Vertex_index> v;
  for(std::size_t i = 0; i < p.size(); ++i) {
    const double x = CGAL::to_double(p[i].x()), y = CGAL::to_double(p[i].y()), z = CGAL::to_double(p[i].z());
    const double n = std::sqrt(x * x + y * y + z * z);
    const double r = 1 + 0.15 * std::sin(5 * x) * std::sin(4 * y) * std::sin(3 * z + 1) + 0.03 * std::sin(23 * x + 17 * y);
    v.push_back(m.add_vertex(Point_3(r * x / n, r * y / n, r * z / n)));
  }
  for(const auto& x : f) m.add_face(v[x[0]], v[x[1]], v[x[2]]);
  return m;
}

} // namespace sil_detail

} // namespace mdcs_cli

#endif // MDCS_CLI_CMD_SILHOUETTE_H
