// `mdcs geodesics`: exact geodesic distances and shortest paths on a triangle mesh (Polyhedral_geodesics_3),
// drawn as a shaded picture with iso-distance lines and written as a PLY file with the distance of every vertex.
#ifndef MDCS_CLI_CMD_GEODESICS_H
#define MDCS_CLI_CMD_GEODESICS_H

#include "cli_common.h"
#include "cmd_mincut.h" // Input_error

#include <CGAL/Polyhedral_geodesics_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#ifndef MDCS_CGAL_MESH_DIR
#define MDCS_CGAL_MESH_DIR ""
#endif

namespace mdcs_cli {

namespace PG = CGAL::Polyhedral_geodesics_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Geo_kernel;
typedef Geo_kernel::Point_3 Geo_point;
typedef CGAL::Surface_mesh<Geo_point> Geo_mesh;
typedef std::array<double, 3> Geo_vec;

inline const char* geodesics_usage()
{
  return
    "usage: mdcs geodesics MESH --source SPEC [options]\n"
    "Exact geodesic distances on a triangle mesh from one or more sources (interval propagation,\n"
    "CGAL::Polyhedral_geodesics_3), shortest paths to targets, a picture and a PLY file with every distance.\n"
    "  MESH               OFF, PLY, OBJ or STL file, or @torus / @icosphere (generated meshes). Files that are not\n"
    "                     a valid polygon mesh are repaired (CGAL's soup repair), faces with more than three\n"
    "                     corners are triangulated; both with a note on stderr. Indices refer to the mesh as used,\n"
    "                     which distances.ply lists (the file's own order for a valid triangle mesh).\n"
    "  --source SPEC      comma-separated sources: vertex indices (0,17) and/or surface points f:FACE:B0:B1:B2\n"
    "                     (weights of the face's corners in the order distances.ply lists them; >= 0, normalised)\n"
    "  --targets SPEC     shortest paths to these points, same syntax (default: the farthest reachable vertex)\n"
    "  --limit D          stop the propagation at geodesic distance D (farther vertices: unreachable)\n"
    "  --stop-at-targets  stop as soon as the target distances are final (other vertices may stay unreachable)\n"
    "  --memory MODE      full (default): the whole distance field, needed for paths | distances: vertex\n"
    "                     distances only, less memory, no paths\n"
    "  --view X,Y,Z       direction from the mesh towards the viewer (default 1,1,1; orthographic projection)\n"
    "  --up X,Y,Z         direction drawn upwards (default 0,1,0)\n"
    "  --levels N         about N iso-distance lines at round values (default 20; 0: none)\n"
    "  --compare-cgal     also run CGAL::Surface_mesh_shortest_path; report the largest difference and both times\n"
    "  --output DIR       output folder (default mdcs-output): distances.ply, geodesics.svg (.png with\n"
    "                     rsvg-convert), summary.txt\n"
    "  --quiet            no progress bar\n"
    "distances.ply is ASCII: per vertex x y z, 'float distance' (-1 for unreachable vertices, which no viewer\n"
    "mistakes for a distance) and the colour of the picture's map (grey: unreachable).\n"
    "A malformed or out-of-range --source/--targets is a command-line error (exit 2); a mesh that cannot be\n"
    "read, has no face or cannot be triangulated is bad input (exit 3).\n";
}

// A source or target: a vertex, or a point of a face given by the weights of its corners in listing order.
struct Geo_location
{
  bool at_vertex = true;
  std::size_t index = 0;                       // vertex or face index
  std::array<double, 3> weights = {{1, 0, 0}}; // faces: corners in listing order, normalised
  std::string text;                            // as given on the command line
};

struct Geodesics_settings
{
  std::string mesh;
  std::string sources, targets;
  double limit = -1; // < 0: none
  bool stop_at_targets = false;
  bool full_field = true;
  Geo_vec view = {{1, 1, 1}}, up = {{0, 1, 0}};
  long levels = 20;
  bool compare_cgal = false;
  std::string output = "mdcs-output";
  bool quiet = false;
};

struct Geodesic_target_report
{
  Geo_location where;
  double distance = std::numeric_limits<double>::infinity();
  double path_length = NAN;
  std::size_t path_points = 0;
  std::vector<Geo_point> path; // from the target to its nearest source
  bool automatic = false;      // the farthest vertex, chosen because no target was given
  std::string path_error;      // why the path tracing failed (empty when it did not)
  double cgal_distance = NAN;  // Surface_mesh_shortest_path's distance (with --compare-cgal)
};

struct Geodesics_run
{
  std::string mesh_name;
  std::size_t V = 0, F = 0, isolated = 0;
  std::vector<std::string> notes; // repairs, triangulation
  std::vector<Geo_location> sources;
  std::vector<double> distance; // per vertex, +inf when unreachable
  double max_distance = 0;      // largest finite distance (0 when none)
  std::size_t farthest = 0, reachable = 0;
  PG::Geodesic_statistics stats;
  double seconds_read = 0, seconds_setup = 0, seconds_compute = 0, seconds_output = 0;
  std::vector<Geodesic_target_report> targets;
  double iso_spacing = 0;
  // CGAL::Surface_mesh_shortest_path on the same input (with --compare-cgal)
  bool compared = false;
  double cgal_seconds = 0, max_relative_difference = 0, max_absolute_difference = 0;
  std::size_t compared_vertices = 0, reachability_mismatches = 0;
  std::string ply, svg, png, summary_file, summary;
};

// ------------------------------------------------------------------------------------------------------------
// Small vector helpers (doubles).
namespace geo_detail {

inline Geo_vec sub(const Geo_vec& a, const Geo_vec& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
inline double dot(const Geo_vec& a, const Geo_vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Geo_vec cross(const Geo_vec& a, const Geo_vec& b)
{
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
inline Geo_vec normalized(const Geo_vec& a)
{
  const double l = std::sqrt(dot(a, a));
  return l > 0 ? Geo_vec{{a[0] / l, a[1] / l, a[2] / l}} : a;
}
inline Geo_vec vec(const Geo_point& p) { return {{p.x(), p.y(), p.z()}}; }

// The colour map of distances in [0, 1]: "turbo" (Mikhailov, 2019, polynomial fit), lightened by 18% towards
// white so that the dark iso-lines stay readable at both ends.
inline std::array<double, 3> colour_map(double t)
{
  t = std::min(1.0, std::max(0.0, t));
  const double r = 0.13572138 + t * (4.61539260 + t * (-42.66032258 + t * (132.13108234 + t * (-152.94239396 + t * 59.28637943))));
  const double g = 0.09140261 + t * (2.19418839 + t * (4.84296658 + t * (-14.18503333 + t * (4.27729857 + t * 2.82956604))));
  const double b = 0.10667330 + t * (12.64194608 + t * (-60.58204836 + t * (110.36276771 + t * (-89.90310912 + t * 27.34824973))));
  std::array<double, 3> c = {{r, g, b}};
  for(double& x : c) x = 0.82 * std::min(1.0, std::max(0.0, x)) + 0.18;
  return c;
}

inline const std::array<double, 3>& unreachable_colour()
{
  static const std::array<double, 3> grey = {{0.74, 0.74, 0.74}};
  return grey;
}

inline std::string hex_colour(const std::array<double, 3>& c, double shade = 1.0)
{
  char buf[8];
  auto byte = [&](double x) { return int(std::lround(255.0 * std::min(1.0, std::max(0.0, x * shade)))); };
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(c[0]), byte(c[1]), byte(c[2]));
  return buf;
}

// A round spacing (1, 2, 2.5 or 5 times a power of ten) for about `levels` lines below `range`.
inline double nice_spacing(double range, long levels)
{
  if(!(range > 0) || levels <= 0) return 0;
  const double raw = range / double(levels);
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  double best = p;
  for(double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if(std::abs(std::log(m * p / raw)) < std::abs(std::log(best / raw))) best = m * p;
  return best;
}

inline std::string number_text(double x, int digits = 4)
{
  std::ostringstream s;
  s << std::setprecision(digits) << x;
  return s.str();
}

inline std::string xml_escape(const std::string& s)
{
  std::string r;
  for(char c : s) r += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return r;
}

} // namespace geo_detail

// ------------------------------------------------------------------------------------------------------------
// Generated meshes (for a machine without CGAL's data, and for `@torus` / `@icosphere`).

inline void add_outward_triangles(Geo_mesh& m, const std::vector<Geo_point>& points,
                                  std::vector<std::array<std::size_t, 3>> triangles)
{
  double volume = 0; // six times the signed volume: flip everything if the faces point inwards
  for(const auto& t : triangles)
    volume += geo_detail::dot(geo_detail::vec(points[t[0]]), geo_detail::cross(geo_detail::vec(points[t[1]]), geo_detail::vec(points[t[2]])));
  if(volume < 0)
    for(auto& t : triangles) std::swap(t[1], t[2]);
  std::vector<Geo_mesh::Vertex_index> v;
  for(const Geo_point& p : points) v.push_back(m.add_vertex(p));
  for(const auto& t : triangles) m.add_face(v[t[0]], v[t[1]], v[t[2]]);
}

// A torus around the y axis: radii R and r, nu x nv quads split into two triangles each.
inline void make_torus_mesh(Geo_mesh& m, double R, double r, std::size_t nu, std::size_t nv)
{
  std::vector<Geo_point> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  const double pi = 3.14159265358979323846;
  for(std::size_t i = 0; i < nu; ++i)
    for(std::size_t j = 0; j < nv; ++j) {
      const double u = 2 * pi * double(i) / double(nu), w = 2 * pi * double(j) / double(nv);
      points.emplace_back((R + r * std::cos(w)) * std::cos(u), r * std::sin(w), (R + r * std::cos(w)) * std::sin(u));
    }
  auto id = [&](std::size_t i, std::size_t j) { return (i % nu) * nv + (j % nv); };
  for(std::size_t i = 0; i < nu; ++i)
    for(std::size_t j = 0; j < nv; ++j) {
      triangles.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}});
      triangles.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}});
    }
  add_outward_triangles(m, points, triangles);
}

// The unit icosphere: an icosahedron with every triangle split into four, `levels` times.
inline void make_icosphere_mesh(Geo_mesh& m, int levels)
{
  const double t = (1.0 + std::sqrt(5.0)) / 2;
  std::vector<Geo_vec> p = {{{-1, t, 0}}, {{1, t, 0}}, {{-1, -t, 0}}, {{1, -t, 0}}, {{0, -1, t}}, {{0, 1, t}},
                            {{0, -1, -t}}, {{0, 1, -t}}, {{t, 0, -1}}, {{t, 0, 1}}, {{-t, 0, -1}}, {{-t, 0, 1}}};
  for(auto& x : p) x = geo_detail::normalized(x);
  std::vector<std::array<std::size_t, 3>> f = {{{0, 11, 5}}, {{0, 5, 1}}, {{0, 1, 7}}, {{0, 7, 10}}, {{0, 10, 11}},
    {{1, 5, 9}}, {{5, 11, 4}}, {{11, 10, 2}}, {{10, 7, 6}}, {{7, 1, 8}}, {{3, 9, 4}}, {{3, 4, 2}}, {{3, 2, 6}},
    {{3, 6, 8}}, {{3, 8, 9}}, {{4, 9, 5}}, {{2, 4, 11}}, {{6, 2, 10}}, {{8, 6, 7}}, {{9, 8, 1}}};
  for(int level = 0; level < levels; ++level) {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> middle;
    auto mid = [&](std::size_t a, std::size_t b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto it = middle.find(key);
      if(it != middle.end()) return it->second;
      p.push_back(geo_detail::normalized({{p[a][0] + p[b][0], p[a][1] + p[b][1], p[a][2] + p[b][2]}}));
      return middle[key] = p.size() - 1;
    };
    std::vector<std::array<std::size_t, 3>> g;
    for(const auto& tri : f) {
      const std::size_t a = mid(tri[0], tri[1]), b = mid(tri[1], tri[2]), c = mid(tri[2], tri[0]);
      g.push_back({{tri[0], a, c}});
      g.push_back({{tri[1], b, a}});
      g.push_back({{tri[2], c, b}});
      g.push_back({{a, b, c}});
    }
    f.swap(g);
  }
  std::vector<Geo_point> points;
  for(const auto& x : p) points.emplace_back(x[0], x[1], x[2]);
  add_outward_triangles(m, points, f);
}

// Reads MESH (or generates @torus / @icosphere); repairs and triangulates when needed, noting it in `notes`.
inline void load_geodesics_mesh(const std::string& path, Geo_mesh& mesh, std::vector<std::string>& notes)
{
  mesh.clear();
  if(path == "@torus") {
    make_torus_mesh(mesh, 1.0, 0.4, 96, 40);
    return;
  }
  if(path == "@icosphere") {
    make_icosphere_mesh(mesh, 4);
    return;
  }
  std::error_code ec;
  if(!std::filesystem::is_regular_file(path, ec)) throw Input_error("cannot open '" + path + "'");
  bool ok = false;
  try {
    ok = CGAL::IO::read_polygon_mesh(path, mesh);
  } catch(const std::exception&) {
    ok = false;
  }
  if(!ok || faces(mesh).empty()) {
    // Not a valid polygon mesh as is (e.g. non-manifold, or a polygon soup): CGAL's repair and orientation.
    mesh.clear();
    bool repaired = false;
    try {
      repaired = CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(path, mesh);
    } catch(const std::exception&) {
      repaired = false;
    }
    if(!repaired)
      throw Input_error("cannot read a polygon mesh from '" + path + "' (OFF, PLY, OBJ or STL; not a polygon mesh even after repair)");
    if(!faces(mesh).empty())
      notes.push_back("the file is not a valid polygon mesh as is: it was repaired and oriented (CGAL::Polygon_mesh_processing::IO::"
                      "read_polygon_mesh); vertex and face indices refer to the repaired mesh written to distances.ply");
  }
  if(faces(mesh).empty()) throw Input_error("'" + path + "' has no face");
  if(mesh.has_garbage()) mesh.collect_garbage();
  if(!CGAL::is_triangle_mesh(mesh)) {
    const std::size_t before = mesh.number_of_faces();
    if(!CGAL::Polygon_mesh_processing::triangulate_faces(mesh))
      throw Input_error("'" + path + "' has faces that cannot be triangulated");
    if(mesh.has_garbage()) mesh.collect_garbage();
    notes.push_back("faces with more than three corners were triangulated (" + std::to_string(before) + " -> " +
                    std::to_string(mesh.number_of_faces()) + " faces); face indices refer to the triangulated mesh");
  }
}

// ------------------------------------------------------------------------------------------------------------
// Sources and targets.

inline std::vector<Geo_location> parse_geo_locations(const std::string& spec, const char* option)
{
  std::vector<Geo_location> result;
  const std::string what = std::string("--") + option;
  auto bad = [&](const std::string& item, const std::string& why) {
    return Usage_error(what + ": '" + item + "' " + why + " (expected vertex indices such as 0,17 or face points f:FACE:B0:B1:B2)");
  };
  auto index = [&](const std::string& item, const std::string& s) {
    if(s.empty() || s.find_first_not_of("0123456789") != std::string::npos) throw bad(item, "is not a non-negative integer");
    try {
      return std::size_t(std::stoull(s));
    } catch(const std::exception&) {
      throw bad(item, "is too large");
    }
  };
  std::stringstream items(spec);
  std::string item;
  while(std::getline(items, item, ',')) {
    if(item.empty()) throw bad(spec, "has an empty item");
    Geo_location loc;
    loc.text = item;
    if(item[0] == 'f' || item[0] == 'F') {
      std::vector<std::string> parts;
      std::stringstream fields(item);
      std::string field;
      while(std::getline(fields, field, ':')) parts.push_back(field);
      if(parts.size() != 5 || (parts[0] != "f" && parts[0] != "F")) throw bad(item, "is not f:FACE:B0:B1:B2");
      loc.at_vertex = false;
      loc.index = index(item, parts[1]);
      double sum = 0;
      for(int k = 0; k < 3; ++k) {
        char* end = nullptr;
        const double w = std::strtod(parts[std::size_t(k) + 2].c_str(), &end);
        if(parts[std::size_t(k) + 2].empty() || *end != '\0' || !std::isfinite(w) || w < 0)
          throw bad(item, "has a weight that is not a finite number >= 0");
        loc.weights[std::size_t(k)] = w;
        sum += w;
      }
      if(!(sum > 0)) throw bad(item, "has weights that sum to 0");
      for(double& w : loc.weights) w /= sum;
    } else {
      loc.index = index(item, item);
    }
    result.push_back(loc);
  }
  if(!spec.empty() && spec.back() == ',') throw bad(spec, "ends with a comma");
  return result;
}

inline void validate_geo_locations(const Geo_mesh& m, const std::vector<Geo_location>& locations, const char* option)
{
  for(const Geo_location& loc : locations) {
    if(loc.at_vertex) {
      if(loc.index >= m.number_of_vertices())
        throw Usage_error(std::string("--") + option + ": vertex " + std::to_string(loc.index) + " does not exist (the mesh has " +
                          std::to_string(m.number_of_vertices()) + " vertices, 0 to " + std::to_string(m.number_of_vertices() - 1) + ")");
      if(m.is_isolated(Geo_mesh::Vertex_index(Geo_mesh::size_type(loc.index))))
        throw Usage_error(std::string("--") + option + ": vertex " + std::to_string(loc.index) + " has no incident face");
    } else if(loc.index >= m.number_of_faces()) {
      throw Usage_error(std::string("--") + option + ": face " + std::to_string(loc.index) + " does not exist (the mesh has " +
                        std::to_string(m.number_of_faces()) + " faces, 0 to " + std::to_string(m.number_of_faces() - 1) + ")");
    }
  }
}

// The corners of a triangle in listing order (the order of distances.ply, and of the file for valid meshes).
inline std::array<Geo_mesh::Vertex_index, 3> face_corners(const Geo_mesh& m, Geo_mesh::Face_index f)
{
  const auto h = m.halfedge(f);
  return {{m.target(h), m.target(m.next(h)), m.target(m.next(m.next(h)))}};
}

// Face_location coordinates refer to source(h), target(h), target(next(h)), that is corners 2, 0, 1.
inline std::array<double, 3> face_location_weights(const Geo_location& loc)
{
  return {{loc.weights[2], loc.weights[0], loc.weights[1]}};
}

inline Geo_point location_point(const Geo_mesh& m, const Geo_location& loc)
{
  if(loc.at_vertex) return m.point(Geo_mesh::Vertex_index(Geo_mesh::size_type(loc.index)));
  const auto c = face_corners(m, Geo_mesh::Face_index(Geo_mesh::size_type(loc.index)));
  double x = 0, y = 0, z = 0;
  for(int k = 0; k < 3; ++k) {
    const Geo_point& p = m.point(c[std::size_t(k)]);
    x += loc.weights[std::size_t(k)] * p.x();
    y += loc.weights[std::size_t(k)] * p.y();
    z += loc.weights[std::size_t(k)] * p.z();
  }
  return Geo_point(x, y, z);
}

inline std::string describe_location(const Geo_location& loc)
{
  if(loc.at_vertex) return "vertex " + std::to_string(loc.index);
  std::ostringstream s;
  s << "face " << loc.index << " (" << std::setprecision(3) << loc.weights[0] << ", " << loc.weights[1] << ", " << loc.weights[2] << ")";
  return s.str();
}

// ------------------------------------------------------------------------------------------------------------
// The picture: orthographic view, faces coloured by distance and shaded by their normal, painted back to front
// (hidden faces found with a software depth buffer are left out), iso-distance lines per face, the sources, and
// the shortest paths (dashed where hidden).

struct Geodesic_picture
{
  std::vector<Geo_vec> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<double> distance; // per point; +inf when unreachable
  double max_distance = 0;      // the top of the colour map
  std::vector<Geo_vec> sources;
  std::vector<std::vector<Geo_vec>> paths; // one polyline per target
  std::vector<Geo_vec> targets;
  Geo_vec view = {{1, 1, 1}}, up = {{0, 1, 0}};
  long levels = 20;
  std::string title;
  std::vector<std::string> caption_lines;
  // results of the writer
  double iso_spacing = 0;
  std::size_t drawn_faces = 0;
};

inline void write_geodesic_svg(const std::string& file, Geodesic_picture& pic)
{
  using namespace geo_detail;
  const double inf = std::numeric_limits<double>::infinity();
  // Camera frame.
  const Geo_vec d = normalized(pic.view);
  Geo_vec up = normalized(pic.up);
  if(!(std::abs(dot(up, d)) < 0.99)) up = std::abs(d[1]) < 0.9 ? Geo_vec{{0, 1, 0}} : Geo_vec{{0, 0, 1}};
  const Geo_vec right = normalized(cross(up, d));
  const Geo_vec screen_up = cross(d, right);
  const Geo_vec light = normalized({{0.8 * d[0] + 0.45 * screen_up[0] - 0.3 * right[0], 0.8 * d[1] + 0.45 * screen_up[1] - 0.3 * right[1],
                                     0.8 * d[2] + 0.45 * screen_up[2] - 0.3 * right[2]}});

  // Projection of the vertices used by faces.
  const std::size_t n = pic.points.size();
  std::vector<double> X(n), Y(n), Z(n);
  double xmin = inf, xmax = -inf, ymin = inf, ymax = -inf, zmin = inf, zmax = -inf;
  for(std::size_t i = 0; i < n; ++i) {
    X[i] = dot(pic.points[i], right);
    Y[i] = dot(pic.points[i], screen_up);
    Z[i] = dot(pic.points[i], d);
  }
  for(const auto& t : pic.triangles)
    for(std::size_t i : t) {
      xmin = std::min(xmin, X[i]), xmax = std::max(xmax, X[i]);
      ymin = std::min(ymin, Y[i]), ymax = std::max(ymax, Y[i]);
      zmin = std::min(zmin, Z[i]), zmax = std::max(zmax, Z[i]);
    }
  if(pic.triangles.empty()) xmin = ymin = zmin = 0, xmax = ymax = zmax = 1;
  const double diag = std::max(1e-300, std::sqrt((xmax - xmin) * (xmax - xmin) + (ymax - ymin) * (ymax - ymin) + (zmax - zmin) * (zmax - zmin)));
  const double pad = 0.03 * std::max(xmax - xmin, ymax - ymin) + 1e-12 * diag;
  xmin -= pad, xmax += pad, ymin -= pad, ymax += pad;

  // Layout (pixels).
  const double W = 1000, margin = 20, top = 48, max_plot_w = W - 2 * margin, max_plot_h = 760;
  const double scale = std::min(max_plot_w / (xmax - xmin), max_plot_h / (ymax - ymin));
  const double plot_w = (xmax - xmin) * scale, plot_h = (ymax - ymin) * scale;
  const double left = (W - plot_w) / 2;
  auto sx = [&](double x) { return left + (x - xmin) * scale; };
  auto sy = [&](double y) { return top + (ymax - y) * scale; };

  // Depth buffer, one sample per pixel, and the face owning each pixel.
  const int bw = std::max(1, int(std::ceil(plot_w))), bh = std::max(1, int(std::ceil(plot_h)));
  std::vector<double> zbuf(std::size_t(bw) * std::size_t(bh), -inf);
  std::vector<std::int64_t> owner(zbuf.size(), -1);
  for(std::size_t f = 0; f < pic.triangles.size(); ++f) {
    const auto& t = pic.triangles[f];
    const double x0 = sx(X[t[0]]) - left, y0 = sy(Y[t[0]]) - top, x1 = sx(X[t[1]]) - left, y1 = sy(Y[t[1]]) - top,
                 x2 = sx(X[t[2]]) - left, y2 = sy(Y[t[2]]) - top;
    const double area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    if(!(std::abs(area) > 1e-12)) continue;
    const int i0 = std::max(0, int(std::floor(std::min({x0, x1, x2})))), i1 = std::min(bw - 1, int(std::ceil(std::max({x0, x1, x2}))));
    const int j0 = std::max(0, int(std::floor(std::min({y0, y1, y2})))), j1 = std::min(bh - 1, int(std::ceil(std::max({y0, y1, y2}))));
    for(int j = j0; j <= j1; ++j)
      for(int i = i0; i <= i1; ++i) {
        const double px = i + 0.5, py = j + 0.5;
        const double a = ((x1 - px) * (y2 - py) - (x2 - px) * (y1 - py)) / area;
        const double b = ((x2 - px) * (y0 - py) - (x0 - px) * (y2 - py)) / area;
        const double c = 1 - a - b;
        if(a < 0 || b < 0 || c < 0) continue;
        const double z = a * Z[t[0]] + b * Z[t[1]] + c * Z[t[2]];
        const std::size_t k = std::size_t(j) * std::size_t(bw) + std::size_t(i);
        if(z > zbuf[k]) zbuf[k] = z, owner[k] = std::int64_t(f);
      }
  }
  const double depth_tolerance = 3.0 / scale + 1e-6 * diag;
  // Whether a point (projected x, y, depth z) is in front of the surface around its pixel.
  auto visible = [&](double x, double y, double z) {
    const int i = int(std::floor(sx(x) - left)), j = int(std::floor(sy(y) - top));
    double back = inf;
    for(int dj = -1; dj <= 1; ++dj)
      for(int di = -1; di <= 1; ++di) {
        const int a = i + di, b = j + dj;
        if(a < 0 || b < 0 || a >= bw || b >= bh) return true;
        const double zb = zbuf[std::size_t(b) * std::size_t(bw) + std::size_t(a)];
        if(zb == -inf) return true; // next to the silhouette
        back = std::min(back, zb);
      }
    return z >= back - depth_tolerance;
  };

  // The faces to draw: those owning a pixel, and tiny ones whose centre is not hidden; back to front.
  std::vector<char> keep(pic.triangles.size(), 0);
  for(std::int64_t f : owner)
    if(f >= 0) keep[std::size_t(f)] = 1;
  std::vector<std::pair<double, std::size_t>> order;
  for(std::size_t f = 0; f < pic.triangles.size(); ++f) {
    const auto& t = pic.triangles[f];
    const double cz = (Z[t[0]] + Z[t[1]] + Z[t[2]]) / 3;
    if(!keep[f] && !visible((X[t[0]] + X[t[1]] + X[t[2]]) / 3, (Y[t[0]] + Y[t[1]] + Y[t[2]]) / 3, cz)) continue;
    order.emplace_back(cz, f);
  }
  std::sort(order.begin(), order.end());
  pic.drawn_faces = order.size();
  const bool seams = order.size() <= 60000; // a stroke in the face colour hides the anti-aliasing seams

  const double maxd = pic.max_distance;
  const double spacing = maxd > 0 ? nice_spacing(maxd, pic.levels) : 0;
  pic.iso_spacing = spacing;

  std::ofstream out(file);
  if(!out) throw std::runtime_error("cannot write '" + file + "'");
  const double legend_top = top + plot_h + 16;
  const double H = legend_top + 58 + 19 * double(pic.caption_lines.size()) + 8;
  char buf[256];
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  std::snprintf(buf, sizeof buf, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\">\n", W, H, W, H);
  out << buf;
  out << "<style>.i{fill:none;stroke:#111;stroke-width:0.7;stroke-opacity:0.65}"
         ".j{fill:none;stroke:#000;stroke-width:1.3;stroke-opacity:0.8}"
         ".h{fill:none;stroke:#fff;stroke-width:6;stroke-linejoin:round;stroke-linecap:round;stroke-opacity:0.9}"
         ".p{fill:none;stroke:#c2007a;stroke-width:3;stroke-linejoin:round;stroke-linecap:round}"
         ".q{fill:none;stroke:#c2007a;stroke-width:2;stroke-dasharray:6,4;stroke-opacity:0.9}"
         "text{font-family:Helvetica,Arial,sans-serif;fill:#222}</style>\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out << "<text x=\"" << W / 2 << "\" y=\"30\" font-size=\"18\" text-anchor=\"middle\">" << xml_escape(pic.title) << "</text>\n";

  // Faces and iso-lines, interleaved back to front so that nearer faces hide farther lines.
  out << "<g stroke-width=\"0.7\" stroke-linejoin=\"round\">\n";
  for(const auto& entry : order) {
    const auto& t = pic.triangles[entry.second];
    const Geo_vec& p0 = pic.points[t[0]];
    Geo_vec normal = normalized(cross(sub(pic.points[t[1]], p0), sub(pic.points[t[2]], p0)));
    if(dot(normal, d) < 0) normal = {{-normal[0], -normal[1], -normal[2]}}; // two-sided lighting
    const double shade = 0.62 + 0.38 * std::max(0.0, dot(normal, light));
    const double d0 = pic.distance[t[0]], d1 = pic.distance[t[1]], d2 = pic.distance[t[2]];
    const bool reached = std::isfinite(d0) && std::isfinite(d1) && std::isfinite(d2) && maxd > 0;
    const std::string colour = hex_colour(reached ? colour_map((d0 + d1 + d2) / (3 * maxd)) : unreachable_colour(), shade);
    std::snprintf(buf, sizeof buf, "<path d=\"M%.1f %.1fL%.1f %.1fL%.1f %.1fZ\" fill=\"%s\"", sx(X[t[0]]), sy(Y[t[0]]), sx(X[t[1]]),
                  sy(Y[t[1]]), sx(X[t[2]]), sy(Y[t[2]]), colour.c_str());
    out << buf;
    if(seams) out << " stroke=\"" << colour << "\"";
    out << "/>\n";
    if(!reached || !(spacing > 0)) continue;
    // Iso-lines: a segment per level crossing the face, by linear interpolation of the vertex distances.
    const double lo = std::min({d0, d1, d2}), hi = std::max({d0, d1, d2});
    std::string minor, major;
    for(long k = std::max(1L, long(std::ceil(lo / spacing))); double(k) * spacing <= hi; ++k) {
      const double level = double(k) * spacing;
      double ex[2], ey[2];
      int found = 0;
      for(int e = 0; e < 3 && found < 2; ++e) {
        const std::size_t a = t[std::size_t(e)], b = t[std::size_t((e + 1) % 3)];
        const double da = pic.distance[a], db = pic.distance[b];
        if((da >= level) == (db >= level)) continue;
        const double s = (level - da) / (db - da);
        ex[found] = sx(X[a] + s * (X[b] - X[a]));
        ey[found] = sy(Y[a] + s * (Y[b] - Y[a]));
        ++found;
      }
      if(found != 2) continue;
      std::snprintf(buf, sizeof buf, "M%.1f %.1fL%.1f %.1f", ex[0], ey[0], ex[1], ey[1]);
      (k % 5 == 0 ? major : minor) += buf;
    }
    if(!minor.empty()) out << "<path class=\"i\" d=\"" << minor << "\"/>\n";
    if(!major.empty()) out << "<path class=\"j\" d=\"" << major << "\"/>\n";
  }
  out << "</g>\n";

  // Shortest paths: solid where visible, dashed where hidden behind the surface.
  auto polyline = [&](const std::vector<std::pair<double, double>>& pts, const char* cls) {
    if(pts.size() < 2) return;
    out << "<polyline class=\"" << cls << "\" points=\"";
    for(const auto& q : pts) {
      std::snprintf(buf, sizeof buf, "%.1f,%.1f ", q.first, q.second);
      out << buf;
    }
    out << "\"/>\n";
  };
  std::vector<std::vector<std::pair<double, double>>> shown, hidden;
  for(const auto& path : pic.paths) {
    std::vector<std::pair<double, double>> run;
    bool run_visible = true;
    auto flush = [&] {
      if(run.size() >= 2) (run_visible ? shown : hidden).push_back(run);
      run.clear();
    };
    for(std::size_t i = 0; i + 1 < path.size(); ++i) {
      const Geo_vec& a = path[i];
      const Geo_vec& b = path[i + 1];
      const double ax = dot(a, right), ay = dot(a, screen_up), az = dot(a, d);
      const double bx = dot(b, right), by = dot(b, screen_up), bz = dot(b, d);
      const int pieces = std::max(1, int(std::ceil(std::hypot(bx - ax, by - ay) * scale / 2.0)));
      for(int k = 0; k < pieces; ++k) {
        const double s0 = double(k) / pieces, s1 = double(k + 1) / pieces, sm = (s0 + s1) / 2;
        const bool v = visible(ax + sm * (bx - ax), ay + sm * (by - ay), az + sm * (bz - az));
        const std::pair<double, double> q0(sx(ax + s0 * (bx - ax)), sy(ay + s0 * (by - ay)));
        const std::pair<double, double> q1(sx(ax + s1 * (bx - ax)), sy(ay + s1 * (by - ay)));
        if(run.empty() || v != run_visible) {
          flush();
          run_visible = v;
          run.push_back(q0);
        }
        run.push_back(q1);
      }
    }
    flush();
  }
  out << "<g id=\"paths\">\n";
  for(const auto& r : hidden) polyline(r, "q");
  for(const auto& r : shown) polyline(r, "h");
  for(const auto& r : shown) polyline(r, "p");
  out << "</g>\n";

  // Targets and sources (hollow where hidden).
  out << "<g id=\"markers\" font-size=\"13\">\n";
  for(std::size_t i = 0; i < pic.targets.size(); ++i) {
    const Geo_vec& p = pic.targets[i];
    const double x = sx(dot(p, right)), y = sy(dot(p, screen_up));
    const bool v = visible(dot(p, right), dot(p, screen_up), dot(p, d));
    std::snprintf(buf, sizeof buf, "<rect x=\"%.1f\" y=\"%.1f\" width=\"9\" height=\"9\" transform=\"rotate(45 %.1f %.1f)\" fill=\"%s\" stroke=\"#000\" stroke-width=\"1.2\"/>\n",
                  x - 4.5, y - 4.5, x, y, v ? "#c2007a" : "none");
    out << buf;
    std::snprintf(buf, sizeof buf, "<text x=\"%.1f\" y=\"%.1f\" stroke=\"#fff\" stroke-width=\"3\" paint-order=\"stroke\">T%zu</text>\n", x + 8, y - 6, i + 1);
    out << buf;
  }
  for(std::size_t i = 0; i < pic.sources.size(); ++i) {
    const Geo_vec& p = pic.sources[i];
    const double x = sx(dot(p, right)), y = sy(dot(p, screen_up));
    const bool v = visible(dot(p, right), dot(p, screen_up), dot(p, d));
    std::snprintf(buf, sizeof buf, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"6.5\" fill=\"%s\" stroke=\"#000\" stroke-width=\"2\"%s/>\n", x, y,
                  v ? "#fff" : "none", v ? "" : " stroke-dasharray=\"3,2\"");
    out << buf;
    std::snprintf(buf, sizeof buf, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"2.5\" fill=\"#000\"/>\n", x, y);
    out << buf;
    if(pic.sources.size() > 1) {
      std::snprintf(buf, sizeof buf, "<text x=\"%.1f\" y=\"%.1f\" stroke=\"#fff\" stroke-width=\"3\" paint-order=\"stroke\">S%zu</text>\n", x + 9, y + 15, i);
      out << buf;
    }
  }
  out << "</g>\n";

  // Legend: the colour bar with the major iso values, the unreachable grey, the path and source symbols.
  const double bar_x = margin + 10, bar_w = 360, bar_y = legend_top + 16;
  out << "<defs><linearGradient id=\"cmap\">";
  for(int k = 0; k <= 16; ++k) out << "<stop offset=\"" << k / 16.0 << "\" stop-color=\"" << hex_colour(colour_map(k / 16.0)) << "\"/>";
  out << "</linearGradient></defs>\n";
  out << "<g font-size=\"12\">\n";
  std::snprintf(buf, sizeof buf, "<text x=\"%.1f\" y=\"%.1f\">geodesic distance%s</text>\n", bar_x, legend_top + 10,
                spacing > 0 ? (", iso-lines every " + number_text(spacing) + " (bold every " + number_text(5 * spacing) + ")").c_str() : "");
  out << buf;
  std::snprintf(buf, sizeof buf, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"12\" fill=\"url(#cmap)\" stroke=\"#555\" stroke-width=\"0.6\"/>\n", bar_x, bar_y, bar_w);
  out << buf;
  if(maxd > 0) {
    std::vector<double> ticks = {0};
    if(spacing > 0)
      for(long k = 5; double(k) * spacing <= maxd * (1 + 1e-9); k += 5) ticks.push_back(double(k) * spacing);
    if(ticks.size() < 3) ticks.push_back(maxd);
    for(double v : ticks) {
      const double x = bar_x + bar_w * v / maxd;
      std::snprintf(buf, sizeof buf, "<path d=\"M%.1f %.1fv5\" stroke=\"#333\"/><text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" font-size=\"11\">%s</text>\n",
                    x, bar_y + 12, x, bar_y + 28, number_text(v).c_str());
      out << buf;
    }
  }
  const double lx = bar_x + bar_w + 30;
  std::snprintf(buf, sizeof buf, "<rect x=\"%.1f\" y=\"%.1f\" width=\"18\" height=\"12\" fill=\"%s\" stroke=\"#555\" stroke-width=\"0.6\"/>"
                "<text x=\"%.1f\" y=\"%.1f\">unreachable</text>\n", lx, bar_y, hex_colour(unreachable_colour()).c_str(), lx + 24, bar_y + 10);
  out << buf;
  std::snprintf(buf, sizeof buf, "<path class=\"p\" d=\"M%.1f %.1fh24\"/><path class=\"q\" d=\"M%.1f %.1fh24\"/>"
                "<text x=\"%.1f\" y=\"%.1f\">shortest path (dashed: hidden)</text>\n", lx + 115, bar_y + 3, lx + 115, bar_y + 11, lx + 145, bar_y + 10);
  out << buf;
  std::snprintf(buf, sizeof buf, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"6\" fill=\"#fff\" stroke=\"#000\" stroke-width=\"2\"/><circle cx=\"%.1f\" cy=\"%.1f\" r=\"2.3\"/>"
                "<text x=\"%.1f\" y=\"%.1f\">source</text>\n", lx + 345, bar_y + 6, lx + 345, bar_y + 6, lx + 357, bar_y + 10);
  out << buf;
  out << "</g>\n";
  for(std::size_t i = 0; i < pic.caption_lines.size(); ++i)
    out << "<text x=\"" << bar_x << "\" y=\"" << legend_top + 62 + 19 * double(i) << "\" font-size=\"13\">" << xml_escape(pic.caption_lines[i]) << "</text>\n";
  out << "</svg>\n";
  if(!out) throw std::runtime_error("cannot write '" + file + "'");
}

// ASCII PLY with the distance of every vertex (-1: unreachable) and its colour in the picture's map.
inline void write_distance_ply(const std::string& file, const Geo_mesh& m, const std::vector<double>& distance, double max_distance)
{
  std::ofstream out(file);
  if(!out) throw std::runtime_error("cannot write '" + file + "'");
  out << "ply\nformat ascii 1.0\n"
      << "comment mdcs geodesics: exact geodesic distance to the nearest source; distance -1 = unreachable\n"
      << "element vertex " << m.number_of_vertices() << "\n"
      << "property float x\nproperty float y\nproperty float z\nproperty float distance\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      << "element face " << m.number_of_faces() << "\n"
      << "property list uchar int vertex_indices\nend_header\n";
  char buf[160];
  for(Geo_mesh::Vertex_index v : m.vertices()) {
    const Geo_point& p = m.point(v);
    const double dv = distance[v.idx()];
    const bool reached = std::isfinite(dv);
    const auto c = reached && max_distance > 0 ? geo_detail::colour_map(dv / max_distance) : geo_detail::unreachable_colour();
    std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g %.9g %d %d %d\n", p.x(), p.y(), p.z(), reached ? dv : -1.0,
                  int(std::lround(255 * c[0])), int(std::lround(255 * c[1])), int(std::lround(255 * c[2])));
    out << buf;
  }
  for(Geo_mesh::Face_index f : m.faces()) {
    const auto c = face_corners(m, f);
    out << "3 " << c[0].idx() << " " << c[1].idx() << " " << c[2].idx() << "\n";
  }
  if(!out) throw std::runtime_error("cannot write '" + file + "'");
}

// ------------------------------------------------------------------------------------------------------------

inline Geodesics_settings parse_geodesics_settings(const Options& o)
{
  Geodesics_settings s;
  s.sources = o.text("source", "");
  s.targets = o.text("targets", "");
  if(o.has("limit")) {
    s.limit = o.number("limit", -1);
    if(!(s.limit >= 0) || !std::isfinite(s.limit)) throw Usage_error("--limit must be a finite number >= 0");
  }
  s.stop_at_targets = o.has("stop-at-targets");
  o.text("stop-at-targets", "");
  const std::string memory = o.text("memory", "full");
  if(memory != "full" && memory != "distances") throw Usage_error("--memory must be full or distances (got '" + memory + "')");
  s.full_field = memory == "full";
  auto vector3 = [&](const char* name, Geo_vec fallback) {
    const std::string t = o.text(name, "");
    if(t.empty()) return fallback;
    Geo_vec v;
    char c1 = 0, c2 = 0;
    std::istringstream in(t);
    if(!(in >> v[0] >> c1 >> v[1] >> c2 >> v[2]) || c1 != ',' || c2 != ',' || !(in >> std::ws).eof())
      throw Usage_error(std::string("--") + name + " must be X,Y,Z (got '" + t + "')");
    if(!(geo_detail::dot(v, v) > 0) || !std::isfinite(geo_detail::dot(v, v)))
      throw Usage_error(std::string("--") + name + " must be a non-zero finite vector");
    return v;
  };
  s.view = vector3("view", s.view);
  s.up = vector3("up", s.up);
  s.levels = o.integer("levels", s.levels, 0);
  s.compare_cgal = o.has("compare-cgal");
  o.text("compare-cgal", "");
  s.output = o.text("output", s.output);
  s.quiet = o.has("quiet");
  o.text("quiet", "");
  return s;
}

// Runs everything on a mesh that is already loaded (the demo loads it to choose its sources).
inline Geodesics_run run_geodesics_on(const Geo_mesh& mesh, const std::string& mesh_name, const std::vector<std::string>& notes,
                                      double seconds_read, const Geodesics_settings& s, Progress_bar& progress)
{
  typedef PG::Exact_geodesic_distances_3<Geo_mesh> Geodesics;
  const double inf = std::numeric_limits<double>::infinity();
  Geodesics_run run;
  run.mesh_name = mesh_name;
  run.notes = notes;
  run.seconds_read = seconds_read;
  run.V = mesh.number_of_vertices();
  run.F = mesh.number_of_faces();
  for(Geo_mesh::Vertex_index v : mesh.vertices()) run.isolated += mesh.is_isolated(v) ? 1 : 0;

  if(s.sources.empty()) throw Usage_error("--source is required (vertex indices such as 0,17 or face points f:FACE:B0:B1:B2)");
  run.sources = parse_geo_locations(s.sources, "source");
  validate_geo_locations(mesh, run.sources, "source");
  const std::vector<Geo_location> targets = parse_geo_locations(s.targets, "targets");
  validate_geo_locations(mesh, targets, "targets");
  if(s.stop_at_targets && targets.empty()) throw Usage_error("--stop-at-targets needs --targets");

  auto vertex = [](std::size_t i) { return Geo_mesh::Vertex_index(Geo_mesh::size_type(i)); };
  auto face_location = [](const Geo_location& loc) {
    const auto w = face_location_weights(loc);
    return Geodesics::Face_location(Geo_mesh::Face_index(Geo_mesh::size_type(loc.index)), {{w[0], w[1], w[2]}});
  };

  // The propagation.
  const auto t_setup = std::chrono::steady_clock::now();
  Geodesics geodesics(mesh, s.full_field ? PG::Geodesic_memory_mode::full_field : PG::Geodesic_memory_mode::distances_only);
  for(const Geo_location& loc : run.sources) {
    if(loc.at_vertex) geodesics.add_source(vertex(loc.index));
    else geodesics.add_source(face_location(loc));
  }
  if(s.limit >= 0) geodesics.set_distance_limit(s.limit);
  if(s.stop_at_targets) {
    std::vector<Geo_mesh::Vertex_index> stop;
    for(const Geo_location& loc : targets) {
      if(loc.at_vertex) stop.push_back(vertex(loc.index));
      else for(auto c : face_corners(mesh, Geo_mesh::Face_index(Geo_mesh::size_type(loc.index)))) stop.push_back(c);
    }
    geodesics.set_stop_targets(stop);
  }
  run.seconds_setup = seconds_since(t_setup);
  const auto t_compute = std::chrono::steady_clock::now();
  geodesics.compute([&](const char* stage, double fraction) { return progress(stage, fraction); });
  run.seconds_compute = seconds_since(t_compute);
  run.stats = geodesics.statistics();

  std::vector<double> field(run.V, inf);
  geodesics.distances(boost::make_iterator_property_map(field.begin(), get(boost::vertex_index, mesh)));
  run.distance = field;
  for(std::size_t i = 0; i < run.V; ++i)
    if(std::isfinite(field[i])) {
      ++run.reachable;
      if(field[i] > run.max_distance || run.reachable == 1) run.max_distance = std::max(run.max_distance, field[i]), run.farthest = i;
    }

  // Targets: distances and shortest paths.
  std::vector<Geo_location> wanted = targets;
  bool automatic = false;
  if(wanted.empty() && run.reachable > 0 && run.max_distance > 0) {
    Geo_location far;
    far.index = run.farthest;
    far.text = std::to_string(run.farthest);
    wanted.push_back(far);
    automatic = true;
  }
  for(const Geo_location& loc : wanted) {
    Geodesic_target_report r;
    r.where = loc;
    r.automatic = automatic;
    if(loc.at_vertex) r.distance = run.distance[loc.index];
    else r.distance = s.full_field ? double(geodesics.distance(face_location(loc))) : NAN;
    if(s.full_field) {
      // A failure of the path tracing is reported for this target; the distances and the other paths stay useful.
      try {
        if(loc.at_vertex) geodesics.shortest_path_points(vertex(loc.index), std::back_inserter(r.path));
        else geodesics.shortest_path_points(face_location(loc), std::back_inserter(r.path));
      } catch(const std::exception& e) {
        r.path.clear();
        r.path_error = e.what();
        std::cerr << "mdcs geodesics: warning: no path to " << describe_location(loc) << ": " << e.what() << "\n";
      }
      r.path_points = r.path.size();
      if(!r.path.empty()) {
        r.path_length = 0;
        for(std::size_t i = 0; i + 1 < r.path.size(); ++i) r.path_length += std::sqrt(CGAL::squared_distance(r.path[i], r.path[i + 1]));
      }
    }
    run.targets.push_back(r);
  }

  // CGAL's Surface_mesh_shortest_path on the same sources, for comparison.
  if(s.compare_cgal) {
    typedef CGAL::Surface_mesh_shortest_path_traits<Geo_kernel, Geo_mesh> Smsp_traits;
    typedef CGAL::Surface_mesh_shortest_path<Smsp_traits> Smsp;
    const auto t_cgal = std::chrono::steady_clock::now();
    Smsp cgal(mesh);
    for(const Geo_location& loc : run.sources) {
      if(loc.at_vertex) cgal.add_source_point(vertex(loc.index));
      else {
        const auto w = face_location_weights(loc);
        cgal.add_source_point(Geo_mesh::Face_index(Geo_mesh::size_type(loc.index)), Smsp::Barycentric_coordinates{{w[0], w[1], w[2]}});
      }
    }
    cgal.build_sequence_tree();
    std::vector<double> reference(run.V, inf);
    for(Geo_mesh::Vertex_index v : mesh.vertices()) {
      if(mesh.is_isolated(v)) continue;
      const double r = CGAL::to_double(cgal.shortest_distance_to_source_points(v).first);
      if(r >= 0) reference[v.idx()] = r;
    }
    run.cgal_seconds = seconds_since(t_cgal);
    run.compared = true;
    for(auto& t : run.targets) {
      const double r = t.where.at_vertex ? reference[t.where.index]
        : CGAL::to_double(cgal.shortest_distance_to_source_points(Geo_mesh::Face_index(Geo_mesh::size_type(t.where.index)),
                                                                  face_location_weights(t.where)).first);
      t.cgal_distance = r >= 0 ? r : inf;
    }
    CGAL::Bbox_3 box;
    for(Geo_mesh::Vertex_index v : mesh.vertices()) box += mesh.point(v).bbox();
    const double diag = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) + CGAL::square(box.zmax() - box.zmin()));
    const bool partial = s.limit >= 0 || s.stop_at_targets; // unreachable by choice
    for(std::size_t i = 0; i < run.V; ++i) {
      const double a = run.distance[i], b = reference[i];
      if(std::isfinite(a) && std::isfinite(b)) {
        ++run.compared_vertices;
        run.max_absolute_difference = std::max(run.max_absolute_difference, std::abs(a - b));
        run.max_relative_difference = std::max(run.max_relative_difference, std::abs(a - b) / std::max(b, 1e-9 * diag));
      } else if(std::isfinite(a) != std::isfinite(b) && !(partial && !std::isfinite(a))) {
        ++run.reachability_mismatches;
      }
    }
  }

  // Outputs.
  const auto t_output = std::chrono::steady_clock::now();
  const std::filesystem::path folder = prepare_output_folder(s.output);
  run.ply = (folder / "distances.ply").string();
  write_distance_ply(run.ply, mesh, run.distance, run.max_distance);

  Geodesic_picture pic;
  pic.points.resize(run.V);
  for(Geo_mesh::Vertex_index v : mesh.vertices()) pic.points[v.idx()] = geo_detail::vec(mesh.point(v));
  for(Geo_mesh::Face_index f : mesh.faces()) {
    const auto c = face_corners(mesh, f);
    pic.triangles.push_back({{c[0].idx(), c[1].idx(), c[2].idx()}});
  }
  pic.distance = run.distance;
  pic.max_distance = run.max_distance;
  for(const Geo_location& loc : run.sources) pic.sources.push_back(geo_detail::vec(location_point(mesh, loc)));
  for(const auto& t : run.targets) {
    pic.targets.push_back(geo_detail::vec(location_point(mesh, t.where)));
    std::vector<Geo_vec> path;
    for(const Geo_point& p : t.path) path.push_back(geo_detail::vec(p));
    pic.paths.push_back(path);
  }
  pic.view = s.view;
  pic.up = s.up;
  pic.levels = s.levels;
  std::ostringstream title, c1, c2;
  title << "exact geodesic distances on " << mesh_name;
  c1 << run.V << " vertices, " << run.F << " faces; " << run.sources.size() << (run.sources.size() == 1 ? " source" : " sources")
     << "; propagation " << std::setprecision(3) << run.seconds_compute << " s, " << run.stats.windows_created << " windows created";
  if(run.reachable == 0) c2 << "no vertex reachable";
  else c2 << "max distance " << std::setprecision(6) << run.max_distance << " (" << run.reachable << " of " << run.V << " vertices reachable)";
  for(std::size_t i = 0; i < run.targets.size() && i < 4; ++i)
    c2 << (i == 0 ? "; " : ", ") << "T" << i + 1 << " " << std::setprecision(5) << run.targets[i].distance;
  pic.title = title.str();
  pic.caption_lines = {c1.str(), c2.str()};
  run.svg = (folder / "geodesics.svg").string();
  write_geodesic_svg(run.svg, pic);
  run.iso_spacing = pic.iso_spacing;
  if(svg_to_png(run.svg)) run.png = (folder / "geodesics.png").string();
  run.seconds_output = seconds_since(t_output);

  // Summary.
  std::ostringstream sum;
  sum.precision(10);
  sum << "mesh: " << mesh_name << " (" << run.V << " vertices, " << run.F << " faces";
  if(run.isolated) sum << ", " << run.isolated << " isolated vertices";
  sum << ")\n";
  for(const std::string& note : run.notes) sum << "note: " << note << "\n";
  sum << "sources: " << run.sources.size() << " (";
  for(std::size_t i = 0; i < run.sources.size() && i < 8; ++i) sum << (i ? ", " : "") << describe_location(run.sources[i]);
  if(run.sources.size() > 8) sum << ", ...";
  sum << ")\n";
  if(s.limit >= 0) sum << "distance limit: " << s.limit << "\n";
  sum << "memory mode: " << (s.full_field ? "full field" : "distances only") << (s.stop_at_targets ? ", stop at targets" : "") << "\n";
  sum << std::setprecision(4) << "time: read " << run.seconds_read << " s, setup " << run.seconds_setup << " s, propagation "
      << run.seconds_compute << " s, output " << run.seconds_output << " s\n";
  sum << "windows: created " << run.stats.windows_created << ", propagated " << run.stats.windows_propagated << ", pruned "
      << run.stats.windows_pruned << ", peak live " << run.stats.peak_live_windows << ", stored " << run.stats.stored_windows
      << ", peak memory " << std::setprecision(3) << double(run.stats.peak_memory_bytes) / (1024.0 * 1024.0) << " MiB"
      << (run.stats.stopped_early ? ", stopped early" : "") << "\n";
  sum << std::setprecision(10);
  if(run.reachable == 0) sum << "distances: no vertex is reachable (every distance is +infinity)\n";
  else sum << "distances: " << run.reachable << " of " << run.V << " vertices reachable, max distance " << run.max_distance
           << " at vertex " << run.farthest << "\n";
  for(std::size_t i = 0; i < run.targets.size(); ++i) {
    const auto& t = run.targets[i];
    sum << "target T" << i + 1 << " " << describe_location(t.where) << (t.automatic ? " (farthest vertex)" : "") << ": ";
    if(std::isnan(t.distance)) sum << "distance n/a (face point: needs --memory full)";
    else if(!std::isfinite(t.distance)) sum << "unreachable";
    else sum << "distance " << t.distance;
    if(!std::isnan(t.cgal_distance)) sum << " (CGAL: " << t.cgal_distance << ")";
    if(!s.full_field) sum << ", no path (--memory distances)";
    else if(!t.path_error.empty()) sum << ", path tracing FAILED: " << t.path_error;
    else if(t.path.empty()) sum << ", no path";
    else sum << ", path length " << t.path_length << " (" << t.path_points << " points, relative difference to the distance "
             << std::setprecision(3) << std::abs(t.path_length - t.distance) / std::max(t.distance, 1e-300) << std::setprecision(10) << ")";
    sum << "\n";
  }
  if(run.targets.empty()) sum << "targets: none (no vertex is reachable at a positive distance)\n";
  if(run.compared) {
    sum << std::setprecision(4) << "CGAL Surface_mesh_shortest_path: " << run.cgal_seconds << " s (ours: " << run.seconds_setup + run.seconds_compute
        << " s); over " << run.compared_vertices << " vertices max relative difference " << std::setprecision(3) << run.max_relative_difference
        << ", max absolute difference " << run.max_absolute_difference;
    if(run.reachability_mismatches) sum << "; " << run.reachability_mismatches << " vertices reachable in one and not in the other";
    sum << "\n";
  }
  if(run.iso_spacing > 0) sum << "picture: iso-lines every " << geo_detail::number_text(run.iso_spacing) << "\n";
  run.summary_file = (folder / "summary.txt").string();
  sum << "files: " << run.ply << ", " << run.svg << (run.png.empty() ? "" : ", " + run.png) << ", " << run.summary_file << "\n";
  run.summary = sum.str();
  std::ofstream(run.summary_file) << run.summary;
  return run;
}

inline Geodesics_run run_geodesics(const Geodesics_settings& s, Progress_bar& progress)
{
  // Parse the sources and targets before reading the mesh, so that a malformed command line fails at once.
  parse_geo_locations(s.sources, "source");
  parse_geo_locations(s.targets, "targets");
  const auto t0 = std::chrono::steady_clock::now();
  Geo_mesh mesh;
  std::vector<std::string> notes;
  load_geodesics_mesh(s.mesh, mesh, notes);
  for(const std::string& note : notes) std::cerr << "mdcs geodesics: note: " << note << "\n";
  const double seconds_read = seconds_since(t0);
  const std::string name = s.mesh[0] == '@' ? s.mesh.substr(1) + " (generated)" : std::filesystem::path(s.mesh).filename().string();
  return run_geodesics_on(mesh, name, notes, seconds_read, s, progress);
}

inline int command_geodesics(const Options& o)
{
  if(o.has("help")) {
    std::cout << geodesics_usage();
    return EXIT_OK;
  }
  Geodesics_settings s = parse_geodesics_settings(o);
  o.reject_unknown();
  if(o.positional().size() != 1) throw Usage_error("mdcs geodesics needs exactly one mesh (a file, @torus or @icosphere)");
  s.mesh = o.positional().front();
  if(s.sources.empty()) throw Usage_error("--source is required");
  Progress_bar progress(s.quiet);
  const Geodesics_run run = run_geodesics(s, progress);
  std::cout << run.summary;
  return EXIT_OK;
}

// ------------------------------------------------------------------------------------------------------------
// The geodesics section of `mdcs demo`: one vertex source and three targets on CGAL's elephant (a generated
// torus when CGAL's data is missing; with the dragon too unless --quick), compared with
// Surface_mesh_shortest_path. Appends to summary.md; returns whether the checks passed.

inline bool demo_geodesics(const std::filesystem::path& folder, bool quick, bool quiet, Progress_bar& progress, std::ostream& md)
{
  const std::string dir = MDCS_CGAL_MESH_DIR;
  std::vector<std::string> meshes;
  for(const char* name : {"elephant.off", "ChineseDragon-10kv.off"}) {
    const std::string path = dir.empty() ? std::string() : (std::filesystem::path(dir) / name).string();
    if(!path.empty() && std::filesystem::is_regular_file(path)) meshes.push_back(path);
    if(quick) break;
  }
  const bool fallback = meshes.empty();
  if(fallback) meshes.push_back("@torus");

  md << "\n## Exact geodesic distances\n\n"
        "Exact geodesic distances from one vertex by interval (window) propagation with side lobes "
        "(`CGAL::Polyhedral_geodesics_3::Exact_geodesic_distances_3`), shortest paths to three far vertices, and the same "
        "distances from CGAL's `Surface_mesh_shortest_path` (the Chen-Han / Xin-Wang algorithm) as an independent check "
        "on every vertex. The pictures colour the surface by distance with iso-distance lines; the paths are solid where "
        "visible and dashed behind the surface. `distances.ply` holds every vertex distance (-1: unreachable).";
  if(fallback) md << " CGAL's meshes are not installed (libcgal-demo), so a generated torus is used.";
  md << "\n\n| mesh | vertices | faces | propagation (s) | windows created | max distance | CGAL SMSP (s) | max relative difference | picture |\n"
        "|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
  std::ostringstream targets_md;
  targets_md << "\n| mesh | target | distance | CGAL SMSP distance | path length | path points |\n|---|---|---:|---:|---:|---:|\n";
  bool ok = true;
  std::string pictures; // the first PNG, shown in summary.md
  for(const std::string& path : meshes) {
    Geo_mesh mesh;
    std::vector<std::string> notes;
    const auto t0 = std::chrono::steady_clock::now();
    load_geodesics_mesh(path, mesh, notes);
    const double seconds_read = seconds_since(t0);
    // The source and targets: extreme vertices of the default view, so that they are on the silhouette and visible.
    Geodesics_settings s;
    s.mesh = path;
    s.compare_cgal = true;
    s.quiet = quiet;
    const std::string stem = path[0] == '@' ? path.substr(1) : std::filesystem::path(path).stem().string();
    // Three-quarter views that show the animals' sides (both are y-up), and the torus from above.
    s.view = stem == "elephant" ? Geo_vec{{0.45, 0.3, 1}} : stem == "ChineseDragon-10kv" ? Geo_vec{{1, 0.35, 0.75}} : Geo_vec{{0.3, 1, 0.8}};
    s.output = (folder / ("geodesics-" + stem)).string();
    const Geo_vec d = geo_detail::normalized(s.view);
    const Geo_vec right = geo_detail::normalized(geo_detail::cross(s.up, d)), up = geo_detail::cross(d, right);
    std::size_t imin = 0, imax = 0, itop = 0, ibottom = 0;
    double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
    for(Geo_mesh::Vertex_index v : mesh.vertices()) {
      if(mesh.is_isolated(v)) continue;
      const Geo_vec p = geo_detail::vec(mesh.point(v));
      const double x = geo_detail::dot(p, right), y = geo_detail::dot(p, up);
      if(x < xmin) xmin = x, imin = v.idx();
      if(x > xmax) xmax = x, imax = v.idx();
      if(y < ymin) ymin = y, ibottom = v.idx();
      if(y > ymax) ymax = y, itop = v.idx();
    }
    s.sources = std::to_string(imin);
    s.targets = std::to_string(imax) + "," + std::to_string(itop) + "," + std::to_string(ibottom);
    const std::string name = path[0] == '@' ? "torus (generated)" : std::filesystem::path(path).filename().string();
    const Geodesics_run run = run_geodesics_on(mesh, name, notes, seconds_read, s, progress);
    std::cout << "== geodesics on " << name << "\n" << run.summary << "\n";

    const bool close = run.compared_vertices > 0 && run.max_relative_difference <= 1e-6 && run.reachability_mismatches == 0;
    bool paths_ok = true;
    for(const auto& t : run.targets)
      if(!std::isfinite(t.distance) || t.path.empty() || !(std::abs(t.path_length - t.distance) <= 1e-6 * t.distance)) paths_ok = false;
    if(!close || !paths_ok || run.targets.size() != 3) ok = false;
    const std::string link = "geodesics-" + stem + "/geodesics." + (run.png.empty() ? "svg" : "png");
    md << "| " << name << " | " << run.V << " | " << run.F << " | " << std::setprecision(3) << run.seconds_compute << " | "
       << run.stats.windows_created << " | " << (run.reachable ? geo_detail::number_text(run.max_distance, 6) : std::string("- (none reachable)"))
       << " | " << std::setprecision(3) << run.cgal_seconds << " | "
       << (run.compared_vertices ? geo_detail::number_text(run.max_relative_difference, 2) : std::string("-"))
       << (run.reachability_mismatches ? " (" + std::to_string(run.reachability_mismatches) + " vertices reachable in one only)" : std::string())
       << " | [" << link << "](" << link << ") |\n";
    for(std::size_t i = 0; i < run.targets.size(); ++i) {
      const auto& t = run.targets[i];
      targets_md << "| " << name << " | T" << i + 1 << " = vertex " << t.where.index << " | " << geo_detail::number_text(t.distance, 10)
                 << " | " << geo_detail::number_text(t.cgal_distance, 10) << " | "
                 << (!t.path_error.empty() ? "tracing failed: " + t.path_error
                     : t.path.empty() ? std::string("no path") : geo_detail::number_text(t.path_length, 10))
                 << " | " << t.path_points << " |\n";
    }
    if(pictures.empty() && !run.png.empty()) pictures = link;
  }
  md << targets_md.str();
  md << "\nSource: the leftmost vertex of the view; targets T1-T3: the rightmost, topmost and lowest vertices. "
        "Checks: every vertex distance within 1e-6 (relative) of CGAL's, and every path as long as its distance: "
     << (ok ? "passed" : "FAILED") << ".\n";
  if(!pictures.empty()) md << "\n![exact geodesic distances](" << pictures << ")\n";
  return ok;
}

} // namespace mdcs_cli

#endif // MDCS_CLI_CMD_GEODESICS_H
