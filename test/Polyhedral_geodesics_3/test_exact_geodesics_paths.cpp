// Shortest paths of the exact geodesics: straight on flat meshes, length == distance, from the target to the
// nearest source, every segment on one face (consecutive nodes of shortest_path_sequence share a face), the
// points of shortest_path_sequence equal those of shortest_path_points, paths around the corners of a hole
// pass through them, the cube's corner-to-corner path has length sqrt(5) and crosses the right edge.
#include <catch2/catch.hpp>

#include <MDCS_test/cgal_meshes.h>
#include <MDCS_test/geodesic_oracles.h>
#include <MDCS_test/geodesic_test_meshes.h>
#include <MDCS_test/mesh_generators.h>

#include <CGAL/Polyhedral_geodesics_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <set>
#include <string>
#include <vector>

namespace {

using namespace MDCS_test::Epick_surface_mesh;
namespace PG = CGAL::Polyhedral_geodesics_3;
typedef PG::Exact_geodesic_distances_3<Mesh> Geodesics;
typedef Geodesics::Face_location Face_location;
using MDCS_test::Vec3;

// One node of a path as reported to a GeodesicPathVisitor.
struct Node
{
  int kind; // 0 vertex, 1 edge, 2 face
  vertex_descriptor v;
  halfedge_descriptor h;
  double t = 0;
  face_descriptor f;
  std::array<double, 3> b = {{0, 0, 0}};
};

struct Recorder
{
  std::vector<Node> nodes;
  void operator()(vertex_descriptor v) { Node n; n.kind = 0; n.v = v; nodes.push_back(n); }
  void operator()(halfedge_descriptor h, double t) { Node n; n.kind = 1; n.h = h; n.t = t; nodes.push_back(n); }
  void operator()(face_descriptor f, const std::array<double, 3>& b) { Node n; n.kind = 2; n.f = f; n.b = b; nodes.push_back(n); }
};

Vec3 node_point(const Mesh& m, const Node& n)
{
  switch(n.kind) {
  case 0: return MDCS_test::vertex_vec3(m, n.v);
  case 1: return MDCS_test::lerp(MDCS_test::vertex_vec3(m, source(n.h, m)), MDCS_test::vertex_vec3(m, target(n.h, m)), n.t);
  default: return MDCS_test::location_point(m, n.f, n.b);
  }
}

std::set<face_descriptor> node_faces(const Mesh& m, const Node& n)
{
  std::set<face_descriptor> r;
  switch(n.kind) {
  case 0:
    for(auto h : CGAL::halfedges_around_target(halfedge(n.v, m), m))
      if(!is_border(h, m)) r.insert(face(h, m));
    break;
  case 1:
    if(!is_border(n.h, m)) r.insert(face(n.h, m));
    if(!is_border(opposite(n.h, m), m)) r.insert(face(opposite(n.h, m), m));
    break;
  default:
    r.insert(n.f);
  }
  return r;
}

struct Path_report
{
  std::size_t checked = 0;
  std::size_t empty = 0;           // a reachable target got no path
  std::size_t bad_start = 0;       // the first point is not the target
  std::size_t bad_end = 0;         // the last point is not a source
  std::size_t other_source_end = 0; // ends at a source other than nearest_source() (a tie), informative
  std::size_t bad_length = 0;      // length != distance
  std::size_t off_surface = 0;     // two consecutive nodes share no face
  std::size_t sequence_mismatch = 0; // visitor points != shortest_path_points
  std::size_t bad_edge_parameter = 0; // t outside (0, 1) or barycentric outside the face
  std::size_t exceptions = 0;      // a query threw
  double worst_length = 0;
  std::string first_problem;
};

void note(Path_report& r, const std::string& what)
{
  if(r.first_problem.empty()) r.first_problem = what;
}

// Checks the path from `target` (a face location) to its nearest source; `sources` are the source points.
void check_path(Geodesics& g, const Mesh& m, const Face_location& target, const std::vector<Vec3>& sources,
                double diag, Path_report& r)
{
  ++r.checked;
  const double d = g.distance(target);
  const auto nearest = g.nearest_source(target);
  std::vector<Point_3> points;
  Recorder rec;
  const Vec3 tp = MDCS_test::location_point(m, target.first, target.second);
  const std::string where = "target (" + MDCS_test::format(tp[0]) + ", " + MDCS_test::format(tp[1]) + ", " + MDCS_test::format(tp[2]) + ")";
  try {
    g.shortest_path_points(target, std::back_inserter(points));
    g.shortest_path_sequence(target, rec);
  }
  catch(const std::exception& ex) {
    ++r.exceptions;
    note(r, std::string("exception \"") + ex.what() + "\" at " + where);
    return;
  }
  if(points.empty()) {
    ++r.empty;
    note(r, "empty path at " + where);
    return;
  }
  if(MDCS_test::dist(MDCS_test::to_vec3(points.front()), tp) > 1e-9 * diag) {
    ++r.bad_start;
    note(r, "path does not start at the " + where);
  }
  REQUIRE(nearest.second < sources.size());
  if(MDCS_test::dist(MDCS_test::to_vec3(points.back()), sources[nearest.second]) > 1e-9 * diag) {
    // with ties, the path may end at another source at the same distance (its length is checked below)
    bool at_a_source = false;
    for(const Vec3& s : sources)
      if(MDCS_test::dist(MDCS_test::to_vec3(points.back()), s) <= 1e-9 * diag) at_a_source = true;
    if(at_a_source)
      ++r.other_source_end;
    else {
      ++r.bad_end;
      note(r, "path does not end at a source, " + where);
    }
  }
  const double len = MDCS_test::path_length(points);
  const double rel = MDCS_test::relative_difference(len, d, 1e-12 * diag);
  r.worst_length = std::max(r.worst_length, rel);
  if(!(rel <= 1e-9)) {
    ++r.bad_length;
    note(r, "length " + MDCS_test::format(len) + " != distance " + MDCS_test::format(d) + " at " + where);
  }
  if(rec.nodes.size() != points.size()) {
    ++r.sequence_mismatch;
    note(r, "shortest_path_sequence has " + std::to_string(rec.nodes.size()) + " nodes, shortest_path_points " +
                std::to_string(points.size()) + " at " + where);
  }
  else
    for(std::size_t i = 0; i < points.size(); ++i)
      if(MDCS_test::dist(node_point(m, rec.nodes[i]), MDCS_test::to_vec3(points[i])) > 1e-12 * diag) {
        ++r.sequence_mismatch;
        note(r, "node " + std::to_string(i) + " of shortest_path_sequence differs from shortest_path_points at " + where);
        break;
      }
  for(const Node& n : rec.nodes) {
    const bool ok = n.kind == 1 ? (n.t > 0 && n.t < 1)
                  : n.kind == 2 ? (n.b[0] >= 0 && n.b[1] >= 0 && n.b[2] >= 0 && std::abs(n.b[0] + n.b[1] + n.b[2] - 1) <= 1e-9)
                                : true;
    if(!ok) {
      ++r.bad_edge_parameter;
      note(r, "edge parameter or barycentric coordinates out of range at " + where);
      break;
    }
  }
  for(std::size_t i = 1; i < rec.nodes.size(); ++i) {
    const auto a = node_faces(m, rec.nodes[i - 1]), b = node_faces(m, rec.nodes[i]);
    bool shared = false;
    for(auto f : a)
      if(b.count(f)) shared = true;
    if(!shared) {
      ++r.off_surface;
      note(r, "nodes " + std::to_string(i - 1) + " and " + std::to_string(i) + " share no face at " + where);
      break;
    }
  }
}

void check_report(const Path_report& r)
{
  INFO("paths checked: " << r.checked << " (" << r.other_source_end << " end at a source other than nearest_source(), ties), worst relative length error " << r.worst_length << "; first problem: " << r.first_problem);
  CHECK(r.checked > 0);
  CHECK(r.empty == 0);
  CHECK(r.bad_start == 0);
  CHECK(r.bad_end == 0);
  CHECK(r.bad_length == 0);
  CHECK(r.off_surface == 0);
  CHECK(r.sequence_mismatch == 0);
  CHECK(r.bad_edge_parameter == 0);
  CHECK(r.exceptions == 0);
}

} // namespace

TEST_CASE("exact geodesic paths: straight segments on flat meshes", "[geodesics][exact][paths][flat]")
{
  const std::vector<std::pair<std::string, MDCS_test::Triangle_soup<Point_3>>> meshes = {
      {"planar grid 8x8", MDCS_test::planar_grid<Point_3>(8, 8)},
      {"jittered grid 10x10", MDCS_test::jittered_planar_grid<Point_3>(10, 10, 1.0, 1.0, 0.2, 3)},
      {"subdivided triangle 6", MDCS_test::subdivided_triangle<Point_3>(6)}};
  for(const auto& nm : meshes) {
    const Mesh m = make_mesh(nm.second);
    const double diag = MDCS_test::bbox_diagonal(m);
    const auto src_loc = MDCS_test::random_face_locations(m, 1, 8)[0];
    for(int kind = 0; kind < 2; ++kind) {
      INFO(nm.first << (kind == 0 ? ", source: interior vertex" : ", source: face location"));
      Geodesics g(m);
      Vec3 s;
      if(kind == 0) {
        const vertex_descriptor sv = MDCS_test::nearest_vertex(m, Vec3{0.37, 0.42, 0});
        g.add_source(sv);
        s = MDCS_test::vertex_vec3(m, sv);
      }
      else {
        g.add_source(Face_location(src_loc.first, {src_loc.second[0], src_loc.second[1], src_loc.second[2]}));
        s = MDCS_test::location_point(m, src_loc.first, src_loc.second);
      }
      Path_report r;
      std::size_t bent = 0;
      double worst_bend = 0;
      auto straight = [&](const Vec3& target) {
        std::vector<Point_3> pts;
        const auto loc = MDCS_test::locate_point(m, target);
        try {
          g.shortest_path_points(Face_location(loc.first, loc.second), std::back_inserter(pts));
        }
        catch(const std::exception&) {
          return; // counted by check_path
        }
        for(const auto& p : pts) {
          const double off = MDCS_test::distance_to_segment(MDCS_test::to_vec3(p), s, target);
          worst_bend = std::max(worst_bend, off);
          // Where two candidate paths tie within rounding (delta ~ 1e-17), choosing the wrong one moves a path
          // point by up to sqrt(delta * length) ~ 3e-9 while the length stays exact: the tolerance is 1e-7.
          if(off > 1e-7) { ++bent; break; }
        }
      };
      for(vertex_descriptor v : vertices(m)) {
        check_path(g, m, g.vertex_location(v), {s}, diag, r);
        straight(MDCS_test::vertex_vec3(m, v));
      }
      for(const auto& q : MDCS_test::random_face_locations(m, 40, 21)) {
        check_path(g, m, Face_location(q.first, q.second), {s}, diag, r);
        straight(MDCS_test::location_point(m, q.first, q.second));
      }
      check_report(r);
      INFO("largest distance of a path point to the straight segment: " << worst_bend);
      CHECK(bent == 0);
    }
  }
}

TEST_CASE("exact geodesic paths: curved meshes, several sources", "[geodesics][exact][paths]")
{
  const std::vector<std::pair<std::string, MDCS_test::Triangle_soup<Point_3>>> meshes = {
      {"bumpy sphere 2", MDCS_test::bumpy_sphere<Point_3>(2, 0.2, 5)},
      {"terrain 10x10", MDCS_test::height_field_grid<Point_3>(10, 0.35, 4)},
      {"cube 3x3", MDCS_test::subdivided_cube<Point_3>(3)},
      {"tetrahedron", MDCS_test::regular_tetrahedron<Point_3>()},
      {"square with a hole", MDCS_test::square_with_hole<Point_3>(10, 3, 7, 4, 6)}};
  for(const auto& nm : meshes) {
    const Mesh m = make_mesh(nm.second);
    const double diag = MDCS_test::bbox_diagonal(m);
    for(std::size_t count : {1, 3}) {
      INFO(nm.first << ", " << count << " sources (vertex sources and a face-location source)");
      Geodesics g(m);
      std::vector<Vec3> sources;
      for(auto s : MDCS_test::spread_vertices(m, count, 6)) {
        g.add_source(s);
        sources.push_back(MDCS_test::vertex_vec3(m, s));
      }
      const auto fl = MDCS_test::random_face_locations(m, 1, unsigned(count))[0];
      g.add_source(Face_location(fl.first, fl.second));
      sources.push_back(MDCS_test::location_point(m, fl.first, fl.second));
      Path_report r;
      for(vertex_descriptor v : vertices(m))
        check_path(g, m, g.vertex_location(v), sources, diag, r);
      for(const auto& q : MDCS_test::random_face_locations(m, 60, 31))
        check_path(g, m, Face_location(q.first, q.second), sources, diag, r);
      check_report(r);
    }
  }
}

TEST_CASE("exact geodesic paths: cube corner to corner and around a hole", "[geodesics][exact][paths][analytic]")
{
  {
    const Mesh m = make_mesh(MDCS_test::subdivided_cube<Point_3>(2));
    Geodesics g(m);
    const vertex_descriptor a = MDCS_test::nearest_vertex(m, Vec3{0, 0, 0}), b = MDCS_test::nearest_vertex(m, Vec3{1, 1, 1});
    g.add_source(a);
    std::vector<Point_3> pts;
    g.shortest_path_points(b, std::back_inserter(pts));
    REQUIRE(pts.size() >= 3);
    CHECK(MDCS_test::path_length(pts) == Approx(std::sqrt(5.0)).epsilon(1e-12));
    // the path crosses one of the six edges at distance 1 from both corners in the middle: e.g. the edge
    // x = 1, z = 0 at y = 1/2 (unfolding of the faces z = 0 and x = 1): some path point is the midpoint of an
    // edge of the cube that touches neither corner
    bool crosses_midpoint = false;
    for(const auto& p : pts) {
      const Vec3 q = MDCS_test::to_vec3(p);
      int halves = 0, ones = 0, zeros = 0;
      for(double c : q) {
        if(std::abs(c - 0.5) < 1e-12) ++halves;
        if(std::abs(c - 1) < 1e-12) ++ones;
        if(std::abs(c) < 1e-12) ++zeros;
      }
      if(halves == 1 && ones == 1 && zeros == 1) crosses_midpoint = true;
    }
    CHECK(crosses_midpoint);
    // the path's points lie on the cube and on at most two faces' planes (a straight unfolded segment)
    for(const auto& p : pts)
      CHECK(MDCS_test::cube_corner_distance(MDCS_test::to_vec3(p), 1e-12) <= std::sqrt(5.0) + 1e-12);
  }
  {
    // square [0,1]^2 minus the hole (0.3, 0.7) x (0.4, 0.6); the source below the hole; a target right above the
    // hole's middle must go around a hole corner: the path passes through the vertex (0.3, 0.6) or (0.7, 0.6)
    const Mesh m = make_mesh(MDCS_test::square_with_hole<Point_3>(10, 3, 7, 4, 6));
    const MDCS_test::Rectangle_hole_domain hole{0.3, 0.4, 0.7, 0.6};
    const vertex_descriptor s = MDCS_test::nearest_vertex(m, Vec3{0.5, 0.1, 0});
    const vertex_descriptor t = MDCS_test::nearest_vertex(m, Vec3{0.5, 0.9, 0});
    const vertex_descriptor t2 = MDCS_test::nearest_vertex(m, Vec3{0.4, 0.8, 0});
    Geodesics g(m);
    g.add_source(s);
    for(vertex_descriptor target : {t, t2}) {
      Recorder rec;
      g.shortest_path_sequence(target, rec);
      std::vector<Point_3> pts;
      g.shortest_path_points(target, std::back_inserter(pts));
      const double expected = hole.distance(MDCS_test::vertex_vec3(m, s), MDCS_test::vertex_vec3(m, target));
      CHECK(MDCS_test::path_length(pts) == Approx(expected).epsilon(1e-12));
      CHECK(g.distance(target) == Approx(expected).epsilon(1e-12));
      std::size_t corners = 0;
      for(const Node& n : rec.nodes)
        if(n.kind == 0) {
          const Vec3 p = MDCS_test::vertex_vec3(m, n.v);
          if(std::abs(p[1] - 0.6) < 1e-12 && (std::abs(p[0] - 0.3) < 1e-12 || std::abs(p[0] - 0.7) < 1e-12)) ++corners;
          if(std::abs(p[1] - 0.4) < 1e-12 && (std::abs(p[0] - 0.3) < 1e-12 || std::abs(p[0] - 0.7) < 1e-12)) ++corners;
        }
      CHECK(corners == 2); // around the lower and then the upper corner of one side
      // every path point is in the domain (not inside the hole)
      for(const auto& p : pts) {
        const Vec3 q = MDCS_test::to_vec3(p);
        CHECK_FALSE((q[0] > 0.3 + 1e-12 && q[0] < 0.7 - 1e-12 && q[1] > 0.4 + 1e-12 && q[1] < 0.6 - 1e-12));
      }
    }
  }
}

TEST_CASE("exact geodesic paths: target at the source, unreachable target", "[geodesics][exact][paths]")
{
  const Mesh m = make_mesh(MDCS_test::two_grids<Point_3>(4));
  const vertex_descriptor s = MDCS_test::nearest_vertex(m, Vec3{0.5, 0.5, 0});
  const vertex_descriptor other = MDCS_test::nearest_vertex(m, Vec3{2.5, 0.5, 0});
  Geodesics g(m);
  g.add_source(s);
  std::vector<Point_3> pts;
  g.shortest_path_points(s, std::back_inserter(pts));
  REQUIRE(!pts.empty());
  for(const auto& p : pts)
    CHECK(MDCS_test::dist(MDCS_test::to_vec3(p), MDCS_test::vertex_vec3(m, s)) == 0);
  CHECK(MDCS_test::path_length(pts) == 0);
  pts.clear();
  g.shortest_path_points(other, std::back_inserter(pts));
  CHECK(pts.empty());
  Recorder rec;
  g.shortest_path_sequence(other, rec);
  CHECK(rec.nodes.empty());
}

TEST_CASE("exact geodesic paths on the elephant", "[geodesics][exact][paths][real]")
{
  Mesh m;
  if(!MDCS_test::read_mesh(MDCS_test::cgal_demo_mesh("elephant.off"), m)) {
    WARN("CGAL demo mesh elephant.off not found; test skipped");
    return;
  }
  const double diag = MDCS_test::bbox_diagonal(m);
  Geodesics g(m);
  std::vector<Vec3> sources;
  for(auto s : MDCS_test::spread_vertices(m, 2, 40)) {
    g.add_source(s);
    sources.push_back(MDCS_test::vertex_vec3(m, s));
  }
  Path_report r;
  for(auto v : MDCS_test::spread_vertices(m, 150, 1))
    check_path(g, m, g.vertex_location(v), sources, diag, r);
  for(const auto& q : MDCS_test::random_face_locations(m, 100, 77))
    check_path(g, m, Face_location(q.first, q.second), sources, diag, r);
  check_report(r);
}
