// The full field of the vertex-oriented schedule (set_vertex_oriented_full_field(true): Parent records per vertex,
// internal/vertex_oriented_paths.h) against the window propagation's full field (the independent oracle, lower
// envelopes of every edge): vertex distances and nearest sources, distances and nearest sources at random face
// locations (1e-12 relative), shortest paths (same length as the oracle's, length == distance, start at the target,
// end at a source, consecutive nodes on one face, sequence == points), with vertex and face-location sources,
// several sources, a distance limit and stop targets, on curved, flat-with-hole and real meshes.
#include <catch2/catch.hpp>

#include <MDCS_test/cgal_meshes.h>
#include <MDCS_test/geodesic_oracles.h>
#include <MDCS_test/geodesic_test_meshes.h>
#include <MDCS_test/mesh_generators.h>
#include <MDCS_test/geodesic_test_geometry.h>

#include <CGAL/Polyhedral_geodesics_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace MDCS_test::Epick_surface_mesh;
namespace PG = CGAL::Polyhedral_geodesics_3;
typedef PG::Exact_geodesic_distances_3<Mesh> Geodesics;
typedef Geodesics::Face_location Face_location;
using MDCS_test::Vec3;

// A path node as a point, and the faces it lies on.
struct Node_recorder
{
  const Mesh& m;
  std::vector<Vec3> points;
  std::vector<std::set<face_descriptor>> faces_of;
  void operator()(vertex_descriptor v)
  {
    points.push_back(MDCS_test::vertex_vec3(m, v));
    std::set<face_descriptor> s;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(v, m), m))
      if(!is_border(h, m)) s.insert(face(h, m));
    faces_of.push_back(s);
  }
  void operator()(halfedge_descriptor h, double t)
  {
    points.push_back(MDCS_test::lerp(MDCS_test::vertex_vec3(m, source(h, m)), MDCS_test::vertex_vec3(m, target(h, m)), t));
    std::set<face_descriptor> s;
    if(!is_border(h, m)) s.insert(face(h, m));
    if(!is_border(opposite(h, m), m)) s.insert(face(opposite(h, m), m));
    faces_of.push_back(s);
  }
  void operator()(face_descriptor f, const std::array<double, 3>& b)
  {
    points.push_back(MDCS_test::location_point(m, f, b));
    faces_of.push_back(std::set<face_descriptor>{f});
  }
};

struct Report
{
  std::size_t vertices = 0, points = 0, paths = 0;
  std::size_t bad_vertex = 0, bad_point = 0, bad_source = 0, bad_path = 0;
  double worst_vertex = 0, worst_point = 0, worst_path = 0;
  std::string first;
  void note(const std::string& s)
  {
    if(first.empty()) first = s;
  }
};

using MDCS_test::tolerance;

bool same(double a, double b, double floor_value, double& worst)
{
  if(std::isinf(a) || std::isinf(b))
    return a == b;
  const double r = MDCS_test::relative_difference(a, b, floor_value);
  worst = std::max(worst, r);
  return r <= tolerance;
}

// Checks one path from `target` of the vertex-oriented run `g` against the oracle `w`.
void check_path(Geodesics& g, Geodesics& w, const Mesh& m, const Face_location& target,
                const std::vector<Vec3>& source_points, double diag, Report& r)
{
  const double d = g.distance(target);
  if(std::isinf(d) || std::isinf(w.distance(target)))
    return; // unreachable, or beyond the front where one of the runs stopped
  ++r.paths;
  std::ostringstream where;
  where << "path from face " << std::size_t(target.first) << " (" << target.second[0] << ", " << target.second[1]
        << ", " << target.second[2] << ")";
  std::vector<Point_3> pts, wpts;
  Node_recorder rec{m, {}, {}};
  try {
    g.shortest_path_points(target, std::back_inserter(pts));
    g.shortest_path_sequence(target, rec);
    w.shortest_path_points(target, std::back_inserter(wpts));
  }
  catch(const std::exception& e) {
    ++r.bad_path;
    r.note(where.str() + ": exception " + e.what());
    return;
  }
  if(pts.empty() || wpts.empty()) {
    ++r.bad_path;
    r.note(where.str() + ": empty");
    return;
  }
  const double len = MDCS_test::path_length(pts), wlen = MDCS_test::path_length(wpts);
  const double rel = std::max(MDCS_test::relative_difference(len, wlen, tolerance * diag),
                              MDCS_test::relative_difference(len, d, tolerance * diag));
  r.worst_path = std::max(r.worst_path, rel);
  bool ok = rel <= 1e-10;
  if(!ok) r.note(where.str() + ": length " + MDCS_test::format(len) + ", oracle's " + MDCS_test::format(wlen) +
                 ", distance " + MDCS_test::format(d));
  const Vec3 tp = MDCS_test::location_point(m, target.first, target.second);
  if(MDCS_test::dist(MDCS_test::to_vec3(pts.front()), tp) > 1e-9 * diag) {
    ok = false;
    r.note(where.str() + ": does not start at the target");
  }
  bool at_source = false;
  for(const Vec3& s : source_points)
    if(MDCS_test::dist(MDCS_test::to_vec3(pts.back()), s) <= 1e-9 * diag) at_source = true;
  if(!at_source) {
    ok = false;
    r.note(where.str() + ": does not end at a source");
  }
  if(rec.points.size() != pts.size()) {
    ok = false;
    r.note(where.str() + ": sequence and points differ in size");
  } else {
    for(std::size_t i = 0; i < pts.size(); ++i)
      if(MDCS_test::dist(rec.points[i], MDCS_test::to_vec3(pts[i])) > 1e-12 * diag) {
        ok = false;
        r.note(where.str() + ": sequence and points differ");
        break;
      }
    for(std::size_t i = 1; i < rec.faces_of.size(); ++i) {
      bool shared = false;
      for(face_descriptor f : rec.faces_of[i - 1])
        if(rec.faces_of[i].count(f)) shared = true;
      if(!shared) {
        ok = false;
        r.note(where.str() + ": nodes " + std::to_string(i - 1) + " and " + std::to_string(i) + " share no face");
        break;
      }
    }
  }
  if(!ok) ++r.bad_path;
}

// Runs both full fields with the same sources and options and compares them.
void compare_full_fields(const Mesh& m, const std::vector<Source>& sources, const std::string& what,
                         std::size_t n_points, std::size_t n_paths, double limit = -1,
                         const std::vector<vertex_descriptor>& stop_targets = {})
{
  INFO(what);
  Geodesics g(m), w(m);
  g.set_vertex_oriented_full_field(true);
  w.set_vertex_oriented_propagation(false);
  for(Geodesics* x : {&g, &w}) {
    if(limit >= 0) x->set_distance_limit(limit);
    if(!stop_targets.empty()) x->set_stop_targets(stop_targets);
    add_sources(*x, sources);
  }
  std::vector<Vec3> source_points;
  for(const Source& s : sources)
    source_points.push_back(s.at_vertex ? MDCS_test::vertex_vec3(m, s.v)
                                        : MDCS_test::location_point(m, s.loc.first, s.loc.second));
  const double diag = MDCS_test::bbox_diagonal(m), floor_value = tolerance * diag;
  Report r;
  const bool partial = limit >= 0 || !stop_targets.empty();
  for(vertex_descriptor v : vertices(m)) {
    ++r.vertices;
    const double a = g.distance(v), b = w.distance(v);
    if(partial && (std::isinf(a) != std::isinf(b))) {
      // the two runs stop at different fronts: a value one of them reports must be the other's, none is wrong
      continue;
    }
    if(!same(a, b, floor_value, r.worst_vertex)) {
      ++r.bad_vertex;
      r.note("vertex " + std::to_string(std::size_t(v)) + ": " + MDCS_test::format(a) + " vs " + MDCS_test::format(b));
    }
  }
  for(vertex_descriptor t : stop_targets) {
    CHECK_FALSE(std::isinf(g.distance(t)));
    check_path(g, w, m, g.vertex_location(t), source_points, diag, r);
  }
  const auto locations = MDCS_test::random_face_locations(m, n_points, 17u);
  std::size_t k = 0;
  for(const Face_location& loc : locations) {
    ++r.points;
    const auto a = g.nearest_source(loc), b = w.nearest_source(loc);
    if(partial && (std::isinf(a.first) != std::isinf(b.first)))
      continue;
    if(!same(a.first, b.first, floor_value, r.worst_point)) {
      ++r.bad_point;
      r.note("point " + std::to_string(k) + ": " + MDCS_test::format(a.first) + " vs " + MDCS_test::format(b.first));
    } else if(a.second != b.second && !std::isinf(a.first)) {
      // a tie: the named source must be at the same distance
      const Vec3 p = source_points[a.second];
      (void)p;
      Geodesics single(m);
      single.set_vertex_oriented_propagation(false);
      add_sources(single, {sources[a.second]});
      if(!(MDCS_test::relative_difference(single.distance(loc), a.first, floor_value) <= 1e-9)) {
        ++r.bad_source;
        r.note("point " + std::to_string(k) + ": nearest source " + std::to_string(a.second) + " vs " +
               std::to_string(b.second));
      }
    }
    if(k < n_paths)
      check_path(g, w, m, loc, source_points, diag, r);
    ++k;
  }
  // paths to a few vertices too
  std::size_t i = 0;
  const std::size_t step = std::max<std::size_t>(1, num_vertices(m) / std::max<std::size_t>(1, n_paths));
  for(vertex_descriptor v : vertices(m))
    if(i++ % step == 0 && !std::isinf(g.distance(v)))
      check_path(g, w, m, g.vertex_location(v), source_points, diag, r);
  INFO("vertices " << r.vertices << " (worst " << r.worst_vertex << "), points " << r.points << " (worst "
                   << r.worst_point << "), paths " << r.paths << " (worst length " << r.worst_path
                   << "); first problem: " << r.first);
  CHECK(g.used_vertex_oriented_propagation());
  CHECK_FALSE(w.used_vertex_oriented_propagation());
  CHECK(r.paths > 0);
  CHECK(r.bad_vertex == 0);
  CHECK(r.bad_point == 0);
  CHECK(r.bad_source == 0);
  CHECK(r.bad_path == 0);
}

using MDCS_test::vertex_at;
face_descriptor face_at(const Mesh& m, std::size_t i) { return *std::next(faces(m).begin(), std::ptrdiff_t(i)); }

} // namespace

TEST_CASE("vertex-oriented full field: equal to the window propagation on a curved mesh",
          "[geodesics][exact][vertex_oriented][full_field]")
{
  const Mesh m = make_mesh(MDCS_test::bumpy_sphere<Point_3>(3, 0.2, 5));
  compare_full_fields(m, {at(vertex_at(m, 0))}, "bumpy sphere, one vertex source", 60, 20);
  compare_full_fields(m, {at(Face_location(face_at(m, 11), {{0.2, 0.3, 0.5}})), at(vertex_at(m, 100))},
                      "bumpy sphere, a face source and a vertex source", 60, 20);
  compare_full_fields(m, {at(Face_location(face_at(m, 40), {{0.4, 0.6, 0.0}}))}, "bumpy sphere, a source on an edge",
                      40, 10);
}

TEST_CASE("vertex-oriented full field: flat mesh with a hole and a height field",
          "[geodesics][exact][vertex_oriented][full_field]")
{
  const Mesh hole = make_mesh(MDCS_test::square_with_hole<Point_3>(14, 4, 9, 5, 8));
  compare_full_fields(hole, {at(vertex_at(hole, 3))}, "square with a hole", 60, 20);
  const Mesh hf = make_mesh(MDCS_test::height_field_grid<Point_3>(16, 0.15, 3));
  compare_full_fields(hf, {at(vertex_at(hf, 7)), at(Face_location(face_at(hf, 300), {{0.1, 0.1, 0.8}}))},
                      "height field, two sources", 60, 20);
}

TEST_CASE("vertex-oriented full field: distance limit and stop targets", "[geodesics][exact][vertex_oriented][full_field]")
{
  const Mesh m = make_mesh(MDCS_test::bumpy_sphere<Point_3>(3, 0.2, 7));
  compare_full_fields(m, {at(vertex_at(m, 5))}, "bumpy sphere, limit 0.8", 60, 15, 0.8);
  compare_full_fields(m, {at(vertex_at(m, 5))}, "bumpy sphere, stop targets", 60, 15, -1,
                      {vertex_at(m, 200), vertex_at(m, 321)});
}

TEST_CASE("vertex-oriented full field: a CGAL demo mesh", "[geodesics][exact][vertex_oriented][full_field][real]")
{
  Mesh m;
  if(!MDCS_test::read_mesh(MDCS_test::cgal_demo_mesh("elephant.off"), m)) {
    WARN("CGAL's demo meshes not found: skipped");
    return;
  }
  compare_full_fields(m, {at(vertex_at(m, 0)), at(vertex_at(m, num_vertices(m) / 2))}, "elephant, two sources", 60, 20);
}

// Point queries on the records run a small propagation each; after many of them the engine builds the window
// field once and answers from it (Exact_geodesic_engine::distance_at). The answers must not change in kind: equal
// to the oracle before and after the switch, paths to points as long as their distances, and the vertex data
// (which stays the records') unchanged bit for bit.
TEST_CASE("vertex-oriented full field: many point queries switch to the window field with the same answers",
          "[geodesics][exact][vertex_oriented][full_field]")
{
  const Mesh m = make_mesh(MDCS_test::bumpy_sphere<Point_3>(3, 0.2, 9));
  const std::vector<Source> sources = {at(vertex_at(m, 0)), at(Face_location(face_at(m, 57), {{0.25, 0.25, 0.5}}))};
  Geodesics g(m), w(m);
  w.set_vertex_oriented_propagation(false);
  add_sources(g, sources);
  add_sources(w, sources);
  const std::vector<double> before = MDCS_test::vertex_distances(g, m);
  const double diag = MDCS_test::bbox_diagonal(m), floor_value = tolerance * diag;
  const auto locations = MDCS_test::random_face_locations(m, 5000, 23u);
  std::size_t asked = 0, bad = 0;
  double worst = 0;
  for(const Face_location& loc : locations) {
    if(g.point_queries_from_window_field())
      break;
    ++asked;
    if(!same(g.distance(loc), w.distance(loc), floor_value, worst)) ++bad;
  }
  INFO(asked << " point queries before the switch, worst relative difference " << worst);
  REQUIRE(g.point_queries_from_window_field());
  CHECK(asked > 20); // the records answered a fair number first
  CHECK(bad == 0);
  std::size_t after = 0, bad_after = 0, bad_path = 0;
  for(std::size_t i = asked; i < locations.size() && after < 300; ++i, ++after) {
    const Face_location& loc = locations[i];
    const auto a = g.nearest_source(loc), b = w.nearest_source(loc);
    if(!same(a.first, b.first, floor_value, worst)) ++bad_after;
    if(after < 20) {
      std::vector<Point_3> pts;
      g.shortest_path_points(loc, std::back_inserter(pts));
      if(pts.empty() || !(MDCS_test::relative_difference(MDCS_test::path_length(pts), a.first, floor_value) <= 1e-10))
        ++bad_path;
    }
  }
  CHECK(bad_after == 0);
  CHECK(bad_path == 0);
  CHECK(g.used_vertex_oriented_propagation());
  CHECK(MDCS_test::vertex_distances(g, m) == before);
  // a new run starts on the records again
  g.add_source(vertex_at(m, 200));
  w.add_source(vertex_at(m, 200));
  CHECK(same(g.distance(locations[0]), w.distance(locations[0]), floor_value, worst));
  CHECK_FALSE(g.point_queries_from_window_field());
}

// Through a needle (a face far lower than its edges) a path walked on the records loses digits, so full-field runs
// on such meshes use the window propagation; distances_only runs keep the vertex-oriented schedule.
TEST_CASE("vertex-oriented full field: not on meshes with needle faces", "[geodesics][exact][vertex_oriented][full_field]")
{
  for(const double gap : {1e-10, 1e-6}) {
    INFO("needle column of width " << gap);
    const Mesh m = make_mesh(MDCS_test::grid_with_needle_column<Point_3>(8, 0.43, gap));
    Geodesics full(m), light(m, PG::Geodesic_memory_mode::distances_only);
    full.add_source(vertex_at(m, 0));
    light.add_source(vertex_at(m, 0));
    full.compute();
    light.compute();
    CHECK(light.used_vertex_oriented_propagation());
    // 1e-10 across an edge of 0.125: a needle; 1e-6: 8e-6 of the edge, above the 1e-7 threshold
    CHECK(full.used_vertex_oriented_propagation() == (gap > 1e-7));
  }
}
