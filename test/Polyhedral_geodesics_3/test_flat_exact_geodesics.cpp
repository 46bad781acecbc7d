// Tests of Flat_exact_geodesic_distances_3 (the flat-exact algorithm of the thesis, chapter 4.3):
//  - planar meshes (subdivided triangle and square, jittered grids) give the Euclidean distances at every vertex
//    and at random surface points, and straight paths as long as the distances, from sources at a corner, at an
//    inner vertex, inside a face, on an edge, and from several sources;
//  - every traced path ends at a source, with a length close to the reported distance on curved meshes (bumpy
//    sphere, subdivided cube, square with a hole, CGAL's elephant) and never below the exact distance (the
//    dependence DAG and the settling of repeated lowerings, on the engine itself: test_flat_exact_engine.cpp);
//  - the mean relative error against Exact_geodesic_distances_3 stays below measured bounds;
//  - distance limit and stop targets, Surface_mesh and Polyhedron_3 agree, degenerate input (zero-length edge,
//    collinear triangle, needles, two components), invalid input, progress and cancellation, statistics;
//  - the large-page arrays of the engine, and a reused object giving a fresh object's results bit for bit.
#include <catch2/catch.hpp>

#include <MDCS_test/cgal_meshes.h>
#include <MDCS_test/geodesic_oracles.h>
#include <MDCS_test/geodesic_test_meshes.h>
#include <MDCS_test/mesh_generators.h>
#include <MDCS_test/geodesic_test_geometry.h>

#include <CGAL/Polyhedral_geodesics_3/Exact_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Flat_exact_geodesic_distances_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace MDCS_test::Epick_surface_mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
namespace PG = CGAL::Polyhedral_geodesics_3;
typedef PG::Flat_exact_geodesic_distances_3<Mesh> Flat_geodesics;
typedef PG::Exact_geodesic_distances_3<Mesh> Exact_geodesics;
typedef Flat_geodesics::Face_location Face_location;
using MDCS_test::Vec3;

using MDCS_test::tolerance;

vertex_descriptor vertex_at(std::size_t i) { return vertex_descriptor(static_cast<Mesh::size_type>(i)); }

// The vertex of a planar_grid(n, n) at column i, row j.
vertex_descriptor grid_vertex(std::size_t n, std::size_t i, std::size_t j) { return vertex_at(j * (n + 1) + i); }

Vec3 point_of(const Mesh& m, const Face_location& l) { return MDCS_test::location_point(m, l.first, l.second); }

// One node of a path as reported to a GeodesicPathVisitor.
struct Flat_path_recorder
{
  const Mesh* m;
  std::vector<Vec3> points;
  std::size_t bad_parameters = 0;
  void operator()(vertex_descriptor v) { points.push_back(MDCS_test::vertex_vec3(*m, v)); }
  void operator()(halfedge_descriptor h, double t)
  {
    if(!(t > 0 && t < 1)) ++bad_parameters;
    points.push_back(MDCS_test::lerp(MDCS_test::vertex_vec3(*m, source(h, *m)), MDCS_test::vertex_vec3(*m, target(h, *m)), t));
  }
  void operator()(face_descriptor f, const std::array<double, 3>& b)
  {
    for(double x : b)
      if(!(x >= 0 && x <= 1)) ++bad_parameters;
    points.push_back(MDCS_test::location_point(*m, f, b));
  }
};

// Checks of the paths to a set of targets.
struct Flat_path_report
{
  std::size_t checked = 0, empty = 0, bad_start = 0, bad_end = 0, exceptions = 0, sequence_mismatch = 0,
              bad_parameters = 0, below_exact = 0;
  double worst_length = 0;    // max |length - distance| / distance
  double mean_length = 0;     // mean of the same
  std::string first_problem;
};

void flat_note(Flat_path_report& r, const std::string& what)
{
  if(r.first_problem.empty()) r.first_problem = what;
}

// The path from `target` must start there, end at one of `sources`, have the reported length (relative error
// recorded), match the visitor sequence, and not be shorter than `exact` (if given, > 0).
template <class G>
void check_path(G& g, const Mesh& m, const Face_location& target, const std::vector<Vec3>& sources, double diag,
                double exact, Flat_path_report& r)
{
  ++r.checked;
  const double d = g.distance(target);
  std::vector<Point_3> pts;
  Flat_path_recorder rec{&m, {}, 0};
  try {
    g.shortest_path_points(target, std::back_inserter(pts));
    g.shortest_path_sequence(target, rec);
  }
  catch(const std::exception& ex) {
    ++r.exceptions;
    flat_note(r, std::string("exception: ") + ex.what());
    return;
  }
  if(pts.empty()) {
    ++r.empty;
    flat_note(r, "empty path");
    return;
  }
  const Vec3 tp = point_of(m, target);
  if(MDCS_test::dist(MDCS_test::to_vec3(pts.front()), tp) > 1e-12 * diag) {
    ++r.bad_start;
    flat_note(r, "the path does not start at the target");
  }
  double to_source = MDCS_test::inf;
  for(const Vec3& s : sources)
    to_source = std::min(to_source, MDCS_test::dist(MDCS_test::to_vec3(pts.back()), s));
  if(!(to_source <= 1e-12 * diag)) {
    ++r.bad_end;
    flat_note(r, "the path does not end at a source");
  }
  const double len = MDCS_test::path_length(pts);
  if(d > 1e-9 * diag) {
    const double e = std::abs(len - d) / d;
    r.worst_length = std::max(r.worst_length, e);
    r.mean_length += e;
  }
  if(exact > 0 && len < exact * (1 - 1e-9)) {
    ++r.below_exact;
    flat_note(r, "a path shorter than the exact distance");
  }
  r.bad_parameters += rec.bad_parameters;
  bool same = rec.points.size() == pts.size();
  for(std::size_t i = 0; same && i < pts.size(); ++i)
    same = MDCS_test::dist(rec.points[i], MDCS_test::to_vec3(pts[i])) <= 1e-12 * diag;
  if(!same) {
    ++r.sequence_mismatch;
    flat_note(r, "the visitor sequence differs from the points");
  }
}

std::ostream& operator<<(std::ostream& os, const Flat_path_report& r)
{
  return os << r.checked << " paths: empty " << r.empty << ", bad start " << r.bad_start << ", bad end " << r.bad_end
            << ", exceptions " << r.exceptions << ", sequence mismatches " << r.sequence_mismatch
            << ", bad parameters " << r.bad_parameters << ", shorter than exact " << r.below_exact
            << ", |length - distance| / distance: worst " << r.worst_length << ", mean "
            << (r.checked ? r.mean_length / double(r.checked) : 0.0) << " (first problem: " << r.first_problem << ")";
}

bool paths_end_at_sources(const Flat_path_report& r)
{
  return r.empty == 0 && r.bad_start == 0 && r.bad_end == 0 && r.exceptions == 0 && r.sequence_mismatch == 0 &&
         r.bad_parameters == 0;
}

// A planar (convex) mesh: distances at every vertex and at random points are the Euclidean distances to the
// nearest source point, nearest sources are right where not tied, and the paths (to every `path_step`-th vertex
// and to random points) are straight: they end at a source and are exactly as long as the distance.
void check_planar(Flat_geodesics& g, const Mesh& m, const std::vector<Vec3>& sources, std::size_t path_step,
                  const std::string& what, double path_tolerance = 1e-12)
{
  INFO(what);
  const double diag = MDCS_test::bbox_diagonal(m);
  auto nearest = [&](const Vec3& p, std::size_t& which, double& gap) {
    double best = MDCS_test::inf, second = MDCS_test::inf;
    for(std::size_t i = 0; i < sources.size(); ++i) {
      const double d = MDCS_test::dist(p, sources[i]);
      if(d < best) {
        second = best;
        best = d;
        which = i;
      } else if(d < second) {
        second = d;
      }
    }
    gap = second - best;
    return best;
  };
  std::vector<double> e, got;
  std::size_t wrong_source = 0;
  for(vertex_descriptor v : vertices(m)) {
    std::size_t which = 0;
    double gap = 0;
    e.push_back(nearest(MDCS_test::vertex_vec3(m, v), which, gap));
    const auto ns = g.nearest_source(v);
    got.push_back(ns.first);
    if(gap > 1e-9 * diag && ns.second != which) ++wrong_source;
  }
  const auto cmp = MDCS_test::compare_distances(e, got, tolerance * diag);
  INFO("vertices: " << cmp);
  CHECK(cmp.ok(tolerance));
  CHECK(wrong_source == 0);
  std::vector<double> eq, gq;
  const auto locations = MDCS_test::random_face_locations(m, 200, 17);
  for(const auto& q : locations) {
    std::size_t which = 0;
    double gap = 0;
    eq.push_back(nearest(MDCS_test::location_point(m, q.first, q.second), which, gap));
    const auto ns = g.nearest_source(Face_location(q.first, q.second));
    gq.push_back(g.distance(Face_location(q.first, q.second)));
    CHECK(ns.first == gq.back());
    if(gap > 1e-9 * diag && ns.second != which) ++wrong_source;
  }
  const auto cmp_q = MDCS_test::compare_distances(eq, gq, tolerance * diag);
  INFO("face locations: " << cmp_q);
  CHECK(cmp_q.ok(tolerance));
  CHECK(wrong_source == 0);
  Flat_path_report r;
  std::size_t i = 0;
  for(vertex_descriptor v : vertices(m))
    if(i++ % path_step == 0)
      check_path(g, m, g.vertex_location(v), sources, diag, 0, r);
  for(std::size_t k = 0; k < locations.size(); k += 4)
    check_path(g, m, Face_location(locations[k].first, locations[k].second), sources, diag, 0, r);
  INFO(r);
  CHECK(paths_end_at_sources(r));
  CHECK(r.worst_length <= path_tolerance);
}

// The mean relative error of the flat-exact distances against the exact ones over the vertices at a positive
// exact distance; `worst` receives the largest.
double mean_relative_error(Flat_geodesics& flat, Exact_geodesics& exact, const Mesh& m, double& worst)
{
  double sum = 0;
  std::size_t n = 0;
  worst = 0;
  for(vertex_descriptor v : vertices(m)) {
    const double de = exact.distance(v);
    if(!(de > 0) || std::isinf(de))
      continue;
    const double r = std::abs(flat.distance(v) - de) / de;
    sum += r;
    worst = std::max(worst, r);
    ++n;
  }
  return n ? sum / double(n) : 0.0;
}

} // namespace

TEST_CASE("flat-exact geodesics: planar meshes give Euclidean distances and straight paths", "[geodesics][flat_exact]")
{
  struct Case
  {
    std::string name;
    MDCS_test::Triangle_soup<Point_3> soup;
  };
  const std::vector<Case> cases = {{"subdivided triangle 24", MDCS_test::subdivided_triangle<Point_3>(24)},
                                   {"square grid 20", MDCS_test::planar_grid<Point_3>(20, 20)},
                                   {"jittered grid 24", MDCS_test::jittered_planar_grid<Point_3>(24, 24, 1, 1, 0.2, 3)},
                                   {"jittered rectangle 40x12", MDCS_test::jittered_planar_grid<Point_3>(40, 12, 2, 0.5, 0.2, 11)}};
  for(const Case& c : cases) {
    const Mesh m = make_mesh(c.soup);
    const std::size_t nv = num_vertices(m);
    const face_descriptor f0 = *std::next(faces(m).begin(), long(num_faces(m) / 3));
    Flat_geodesics g(m);
    // a corner
    g.add_source(vertex_at(0));
    check_planar(g, m, {MDCS_test::vertex_vec3(m, vertex_at(0))}, 1, c.name + ", source at a corner");
    // an inner vertex
    g.clear_sources();
    const vertex_descriptor inner = MDCS_test::nearest_vertex(m, MDCS_test::vertex_vec3(m, vertex_at(nv / 2 + 3)));
    g.add_source(inner);
    check_planar(g, m, {MDCS_test::vertex_vec3(m, inner)}, 1, c.name + ", source at an inner vertex");
    // inside a face
    g.clear_sources();
    const Face_location in_face(f0, {0.2, 0.3, 0.5});
    g.add_source(in_face);
    check_planar(g, m, {point_of(m, in_face)}, 1, c.name + ", source inside a face");
    // on an edge and at a vertex, given as face locations
    g.clear_sources();
    const Face_location on_edge(f0, {0.35, 0.65, 0}), at_corner(f0, {0, 0, 1});
    g.add_source(on_edge);
    check_planar(g, m, {point_of(m, on_edge)}, 2, c.name + ", source on an edge");
    g.clear_sources();
    g.add_source(at_corner);
    check_planar(g, m, {point_of(m, at_corner)}, 2, c.name + ", source at a vertex given as a face location");
  }
}

TEST_CASE("flat-exact geodesics: several sources on a planar mesh", "[geodesics][flat_exact]")
{
  // Exact (Euclidean) away from the bisectors of the sources; next to them an edge whose ends belong to two
  // sources propagates along its ends only, which gives values a little too long, never too short.
  const std::size_t n = 30;
  const Mesh m = make_mesh(MDCS_test::jittered_planar_grid<Point_3>(n, n, 1, 1, 0.15, 5));
  const double diag = MDCS_test::bbox_diagonal(m);
  Flat_geodesics g(m);
  const vertex_descriptor a = grid_vertex(n, 3, 4), b = grid_vertex(n, 24, 22);
  const face_descriptor f = *std::next(faces(m).begin(), long(num_faces(m) * 3 / 4));
  const Face_location c(f, {0.6, 0.1, 0.3});
  CHECK(g.add_source(a) == 0);
  CHECK(g.add_source(b) == 1);
  CHECK(g.add_source(c) == 2);
  const std::vector<Vec3> sources = {MDCS_test::vertex_vec3(m, a), MDCS_test::vertex_vec3(m, b), point_of(m, c)};
  auto nearest = [&](const Vec3& p, double& gap) {
    std::vector<double> d;
    for(const Vec3& s : sources) d.push_back(MDCS_test::dist(p, s));
    const std::size_t i = std::size_t(std::min_element(d.begin(), d.end()) - d.begin());
    double second = MDCS_test::inf;
    for(std::size_t k = 0; k < d.size(); ++k)
      if(k != i) second = std::min(second, d[k]);
    gap = second - d[i];
    return i;
  };
  // the nearest source of every vertex, and whether its 2-ring has only that one
  std::vector<std::size_t> owner;
  for(vertex_descriptor v : vertices(m)) {
    double gap;
    owner.push_back(nearest(MDCS_test::vertex_vec3(m, v), gap));
  }
  std::size_t checked_exact = 0, inexact = 0, too_short = 0, too_long = 0, wrong_source = 0;
  double worst = 0;
  for(vertex_descriptor v : vertices(m)) {
    double gap;
    const std::size_t i = nearest(MDCS_test::vertex_vec3(m, v), gap);
    const double e = MDCS_test::dist(MDCS_test::vertex_vec3(m, v), sources[i]);
    const auto ns = g.nearest_source(v);
    const double r = e > 0 ? (ns.first - e) / e : ns.first;
    worst = std::max(worst, std::abs(r));
    if(r < -tolerance) ++too_short;
    if(r > 0.05) ++too_long; // measured: 2.2%
    if(gap > 0.05 * e && ns.second != i) ++wrong_source;
    bool pure = true;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(v, m), m))
      for(halfedge_descriptor k : CGAL::halfedges_around_target(halfedge(source(h, m), m), m))
        pure = pure && owner[std::size_t(source(h, m))] == i && owner[std::size_t(source(k, m))] == i;
    if(pure) {
      ++checked_exact;
      if(std::abs(r) > tolerance) ++inexact;
    }
  }
  INFO("largest relative error " << worst << ", vertices with a single source in their 2-ring " << checked_exact);
  CHECK(too_short == 0);
  CHECK(too_long == 0);
  CHECK(inexact == 0);
  CHECK(wrong_source == 0);
  CHECK(checked_exact > num_vertices(m) * 2 / 3);
  CHECK(g.nearest_source(a).second == 0);
  CHECK(g.nearest_source(b).second == 1);
  CHECK(g.nearest_source(c).second == 2);
  CHECK(g.distance(c) == 0);
  // every path ends at a source and is as long as the distance
  Flat_path_report r;
  for(vertex_descriptor v : vertices(m))
    check_path(g, m, g.vertex_location(v), sources, diag, 0, r);
  INFO(r);
  CHECK(paths_end_at_sources(r));
  CHECK(r.worst_length <= 0.01); // measured: 0.22% (paths next to a bisector bend at a vertex)
}

TEST_CASE("flat-exact geodesics: curved meshes, error against the exact distances, paths", "[geodesics][flat_exact]")
{
  struct Case
  {
    std::string name;
    MDCS_test::Triangle_soup<Point_3> soup;
    double max_mean_error;     // bound on the mean relative error against the exact distances (measured x ~1.5)
    double max_path_mean;      // bound on the mean |path length - distance| / distance
    double max_path_worst;     // bound on the largest
  };
  // measured (mean error, path mean, path worst), 2 sources each: bumpy sphere 0.97%, 0.011, 0.106; cube 0.003%,
  // 0.0004, 0.068; square with a hole 0.12%, 0.0010, 0.067; elephant 0.68%, 0.0055, 0.099
  std::vector<Case> cases = {{"bumpy sphere", MDCS_test::bumpy_sphere<Point_3>(3, 0.1, 2), 0.015, 0.015, 0.15},
                             {"subdivided cube", MDCS_test::subdivided_cube<Point_3>(10), 0.0001, 0.001, 0.1},
                             {"square with a hole", MDCS_test::square_with_hole<Point_3>(30, 10, 20, 12, 18), 0.002, 0.002, 0.08}};
  Mesh elephant;
  const bool have_elephant = MDCS_test::read_mesh(MDCS_test::cgal_demo_mesh("elephant.off"), elephant);
  if(have_elephant)
    cases.push_back({"elephant", MDCS_test::Triangle_soup<Point_3>(), 0.01, 0.01, 0.15});
  else
    WARN("CGAL's demo meshes not found (MDCS_CGAL_MESH_DIR): the elephant is skipped");
  for(const Case& c : cases) {
    INFO(c.name);
    const Mesh m = c.soup.points.empty() ? elephant : make_mesh(c.soup);
    const double diag = MDCS_test::bbox_diagonal(m);
    Flat_geodesics flat(m);
    Exact_geodesics exact(m);
    const auto sources = MDCS_test::spread_vertices(m, 2, 5);
    std::vector<Vec3> source_points;
    for(vertex_descriptor s : sources) {
      flat.add_source(s);
      exact.add_source(s);
      source_points.push_back(MDCS_test::vertex_vec3(m, s));
    }
    double worst = 0;
    const double E = mean_relative_error(flat, exact, m, worst);
    INFO("mean relative error " << E << ", largest " << worst);
    CHECK(E < c.max_mean_error);
    // never NaN, every vertex reached, the same nearest source as the exact distances where clearly apart
    std::size_t bad = 0;
    for(vertex_descriptor v : vertices(m))
      if(!(flat.distance(v) >= 0) || std::isinf(flat.distance(v))) ++bad;
    CHECK(bad == 0);
    Flat_path_report r;
    const std::size_t step = num_vertices(m) / 600 + 1;
    std::size_t i = 0;
    for(vertex_descriptor v : vertices(m))
      if(i++ % step == 0)
        check_path(flat, m, flat.vertex_location(v), source_points, diag, exact.distance(v), r);
    for(const auto& q : MDCS_test::random_face_locations(m, 100, 3))
      check_path(flat, m, Face_location(q.first, q.second), source_points, diag,
                 exact.distance(Face_location(q.first, q.second)), r);
    INFO(r);
    CHECK(paths_end_at_sources(r));
    CHECK(r.below_exact == 0);
    CHECK(r.mean_length / double(r.checked) < c.max_path_mean);
    CHECK(r.worst_length < c.max_path_worst);
    // a few paths lie on the surface (consecutive points share a face)
    std::size_t off_surface = 0;
    i = 0;
    for(vertex_descriptor v : vertices(m))
      if(i++ % (num_vertices(m) / 10 + 1) == 0) {
        std::vector<Point_3> pts;
        flat.shortest_path_points(v, std::back_inserter(pts));
        if(!MDCS_test::is_surface_path(m, pts, 1e-9 * diag)) ++off_surface;
      }
    CHECK(off_surface == 0);
  }
}

TEST_CASE("flat-exact geodesics: distance limit and stop targets", "[geodesics][flat_exact]")
{
  const Mesh m = make_mesh(MDCS_test::bumpy_sphere<Point_3>(3, 0.1, 9));
  const vertex_descriptor s = vertex_at(5);
  Flat_geodesics full(m);
  full.add_source(s);
  std::vector<double> d;
  for(vertex_descriptor v : vertices(m)) d.push_back(full.distance(v));
  std::vector<double> sorted = d;
  std::sort(sorted.begin(), sorted.end());
  const double limit = sorted[sorted.size() / 2];
  const auto locations = MDCS_test::random_face_locations(m, 100, 21);

  Flat_geodesics limited(m);
  limited.add_source(s);
  limited.set_distance_limit(limit);
  std::size_t finite = 0, wrong = 0, missing = 0;
  for(vertex_descriptor v : vertices(m)) {
    const double x = limited.distance(v), y = d[std::size_t(v)];
    if(std::isinf(x)) {
      if(y < limit) ++missing;
      CHECK(limited.nearest_source(v).second == Flat_geodesics::no_source);
      continue;
    }
    ++finite;
    if(!(x <= limit) || std::abs(x - y) > tolerance * y) ++wrong;
  }
  CHECK(wrong == 0);
  CHECK(missing == 0);
  CHECK(finite >= sorted.size() / 2);
  CHECK(limited.statistics().stopped_early);
  for(const auto& q : locations) {
    const Face_location l(q.first, q.second);
    const double x = limited.distance(l);
    if(!std::isinf(x)) CHECK(std::abs(x - full.distance(l)) <= tolerance * x);
    else CHECK(full.distance(l) > limit * (1 - 1e-12));
  }
  // paths within the limit still end at the source
  std::vector<Point_3> pts;
  limited.shortest_path_points(vertex_at(std::size_t(std::min_element(d.begin() + 1, d.end()) - d.begin())),
                               std::back_inserter(pts));
  CHECK(!pts.empty());

  // stop targets: their distances are final, every other finite value is the full one
  Flat_geodesics stopped(m);
  stopped.add_source(s);
  const std::vector<vertex_descriptor> targets = {vertex_at(40), vertex_at(100), vertex_at(7)};
  stopped.set_stop_targets(targets);
  for(vertex_descriptor t : targets) CHECK(std::abs(stopped.distance(t) - d[std::size_t(t)]) <= tolerance * d[std::size_t(t)]);
  std::size_t unreached = 0;
  wrong = 0;
  for(vertex_descriptor v : vertices(m)) {
    const double x = stopped.distance(v);
    if(std::isinf(x)) ++unreached;
    else if(std::abs(x - d[std::size_t(v)]) > tolerance * d[std::size_t(v)]) ++wrong;
  }
  CHECK(wrong == 0);
  CHECK(stopped.statistics().stopped_early);
  INFO("vertices left unreached by the stop targets: " << unreached);
  CHECK(unreached > 0);
  // the options are forgotten again
  stopped.clear_stop_targets();
  limited.clear_distance_limit();
  for(vertex_descriptor v : vertices(m)) {
    CHECK(stopped.distance(v) == d[std::size_t(v)]);
    CHECK(limited.distance(v) == d[std::size_t(v)]);
  }
}

TEST_CASE("flat-exact geodesics: Surface_mesh and Polyhedron_3 agree", "[geodesics][flat_exact]")
{
  for(const auto& soup : {MDCS_test::bumpy_sphere<Point_3>(3, 0.1, 6), MDCS_test::square_with_hole<Point_3>(16, 4, 10, 5, 9)}) {
    const Mesh sm = make_mesh(soup);
    const Polyhedron ph = MDCS_test::mesh_from_soup<Polyhedron>(soup);
    Flat_geodesics a(sm);
    PG::Flat_exact_geodesic_distances_3<Polyhedron> b(ph);
    a.add_source(vertex_at(3));
    b.add_source(*std::next(vertices(ph).begin(), 3));
    std::vector<double> da, db;
    for(vertex_descriptor v : vertices(sm)) da.push_back(a.distance(v));
    for(auto v : vertices(ph)) db.push_back(b.distance(v));
    const auto cmp = MDCS_test::compare_distances(da, db, 1e-12);
    INFO(cmp);
    CHECK(cmp.ok(1e-12));
    // a path on the Polyhedron_3 as well
    std::vector<Point_3> pts;
    b.shortest_path_points(*std::next(vertices(ph).begin(), 20), std::back_inserter(pts));
    CHECK(pts.size() >= 2);
    CHECK(std::abs(MDCS_test::path_length(pts) - db[20]) <= 0.2 * db[20]);
  }
}

TEST_CASE("flat-exact geodesics: degenerate meshes", "[geodesics][flat_exact]")
{
  // a zero-length edge, a collinear (zero-area) triangle, needle triangles: still the plane
  std::array<std::size_t, 2> coincident;
  struct Case
  {
    std::string name;
    MDCS_test::Triangle_soup<Point_3> soup;
  };
  // Distances stay exact; a path crossing the zero-area triangle cannot go straight through it (its side is
  // undefined) and bends at one of its corners: measured 2.7% longer at worst.
  const std::vector<Case> cases = {{"zero-length edge", MDCS_test::grid_with_zero_length_edge<Point_3>(8, coincident)},
                                   {"collinear triangle", MDCS_test::grid_with_cap_triangle<Point_3>(8)},
                                   {"needle strip", MDCS_test::needle_strip<Point_3>(40, 0.01)},
                                   {"needle column", MDCS_test::grid_with_needle_column<Point_3>(10, 0.43, 1e-7)}};
  for(const Case& c : cases) {
    const Mesh m = make_mesh(c.soup);
    const double path_tolerance = c.name == "collinear triangle" ? 0.05 : 1e-12;
    Flat_geodesics g(m);
    g.add_source(vertex_at(0));
    check_planar(g, m, {MDCS_test::vertex_vec3(m, vertex_at(0))}, 1, c.name, path_tolerance);
    g.clear_sources();
    const vertex_descriptor last = vertex_at(num_vertices(m) - 1);
    g.add_source(last);
    check_planar(g, m, {MDCS_test::vertex_vec3(m, last)}, 1, c.name + ", another source", path_tolerance);
  }
  // two components: the other one is unreachable
  const std::size_t n = 6;
  const Mesh two = make_mesh(MDCS_test::two_grids<Point_3>(n));
  Flat_geodesics g(two);
  g.add_source(vertex_at(0));
  const vertex_descriptor far_vertex = vertex_at((n + 1) * (n + 1) + 3);
  CHECK(std::isinf(g.distance(far_vertex)));
  CHECK(g.nearest_source(far_vertex).second == Flat_geodesics::no_source);
  std::vector<Point_3> pts;
  g.shortest_path_points(far_vertex, std::back_inserter(pts));
  CHECK(pts.empty());
  CHECK(g.distance(vertex_at(n)) == Approx(1.0).epsilon(1e-12));
}

TEST_CASE("flat-exact geodesics: invalid input is rejected", "[geodesics][flat_exact]")
{
  {
    const Mesh quad = unit_square_quad();
    CHECK_THROWS_AS(Flat_geodesics(quad), std::invalid_argument);
  }
  const Mesh m = make_mesh(MDCS_test::planar_grid<Point_3>(3, 3));
  const face_descriptor f = *faces(m).begin();
  {
    Flat_geodesics g(m);
    CHECK_THROWS_AS(g.compute(), std::logic_error);
    CHECK_THROWS_AS(g.distance(vertex_at(0)), std::logic_error);
    CHECK_THROWS_AS(g.distance(Face_location(f, {0.2, 0.3, 0.5})), std::logic_error);
    std::vector<Point_3> pts;
    CHECK_THROWS_AS(g.shortest_path_points(vertex_at(0), std::back_inserter(pts)), std::logic_error);
  }
  {
    Flat_geodesics g(m);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for(const std::array<double, 3>& b : {std::array<double, 3>{0.5, 0.6, 0.1}, std::array<double, 3>{-0.1, 0.6, 0.5},
                                          std::array<double, 3>{nan, 0.5, 0.5}})
      CHECK_THROWS_AS(g.add_source(Face_location(f, b)), std::invalid_argument);
    g.add_source(vertex_at(0));
    CHECK_THROWS_AS(g.distance(Face_location(f, {0.5, 0.6, 0.1})), std::invalid_argument);
    std::vector<Point_3> pts;
    CHECK_THROWS_AS(g.shortest_path_points(Face_location(f, {1.2, -0.1, -0.1}), std::back_inserter(pts)),
                    std::invalid_argument);
    CHECK_THROWS_AS(g.set_distance_limit(-1.0), std::invalid_argument);
  }
}

TEST_CASE("flat-exact geodesics: memory modes, progress, cancellation, statistics", "[geodesics][flat_exact]")
{
  const Mesh m = make_mesh(MDCS_test::jittered_planar_grid<Point_3>(50, 50, 1, 1, 0.2, 13));
  Flat_geodesics full(m);
  full.add_source(vertex_at(0));
  std::vector<std::pair<std::string, double>> calls;
  full.compute([&](const char* stage, double fraction) {
    calls.push_back({stage, fraction});
    return true;
  });
  REQUIRE(calls.size() >= 3);
  CHECK(calls.size() <= 200);
  bool ordered = true, named = true;
  for(std::size_t i = 0; i < calls.size(); ++i) {
    named = named && calls[i].first == "flat-exact propagation";
    ordered = ordered && calls[i].second >= 0 && calls[i].second <= 1 && (i == 0 || calls[i].second >= calls[i - 1].second);
  }
  CHECK(named);
  CHECK(ordered);
  CHECK(calls.front().second == 0);
  CHECK(calls.back().second == 1);

  const auto& st = full.statistics();
  CHECK(st.vertex_updates >= num_vertices(m) - 1);
  CHECK(st.vertex_updates <= 3 * num_vertices(m));
  CHECK(st.updates_rejected_by_dag == 0);
  CHECK(st.peak_memory_bytes > 0);
  CHECK(!st.stopped_early);

  // distances_only: the same distances, no paths
  Flat_geodesics small(m, PG::Geodesic_memory_mode::distances_only);
  small.add_source(vertex_at(0));
  for(vertex_descriptor v : vertices(m)) CHECK(small.distance(v) == full.distance(v));
  std::vector<Point_3> pts;
  CHECK_THROWS_AS(small.shortest_path_points(vertex_at(7), std::back_inserter(pts)), std::logic_error);

  // cancellation, then a normal run of the same object
  Flat_geodesics c(m);
  c.add_source(vertex_at(100));
  CHECK_THROWS_AS(c.compute([](const char*, double f) { return f < 0.3; }), CGAL::MDCS::Operation_cancelled);
  CHECK(!c.is_computed());
  c.compute();
  CHECK(c.distance(vertex_at(100)) == 0);
  CHECK(c.distance(vertex_at(0)) == Approx(MDCS_test::dist(MDCS_test::vertex_vec3(m, vertex_at(0)),
                                                           MDCS_test::vertex_vec3(m, vertex_at(100)))).epsilon(1e-12));
}

TEST_CASE("flat-exact geodesics: the arrays of the engine (large pages, reuse of one object)", "[geodesics][flat_exact]")
{
  // the allocator of the large arrays: values kept through growth, large blocks aligned for huge pages
  PG::internal::Large_vector<std::int32_t> big;
  for(std::int32_t i = 0; i < 600000; ++i)
    big.push_back(i);
  big.resize(700000, -1);
  long long sum = 0;
  for(std::int32_t x : big)
    sum += x;
  CHECK(sum == 599999LL * 600000LL / 2 - 100000LL);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  CHECK(reinterpret_cast<std::uintptr_t>(big.data()) % (std::uintptr_t(2) << 20) == 0);
#endif
  PG::internal::Large_vector<double> small(10, 2.5);
  small.push_back(1.0);
  CHECK(small.size() == 11);
  CHECK(small.front() == 2.5);
  CHECK(small.back() == 1.0);

  // one object, several runs: each equals a fresh object's run bit for bit (no state survives a recomputation)
  const Mesh m = make_mesh(MDCS_test::bumpy_sphere<Point_3>(2, 0.15, 5));
  std::vector<std::vector<double>> fresh;
  for(std::size_t s : {std::size_t(0), std::size_t(37), std::size_t(0)}) {
    Flat_geodesics g(m);
    g.add_source(vertex_at(s));
    std::vector<double> d;
    for(vertex_descriptor v : vertices(m))
      d.push_back(g.distance(v));
    fresh.push_back(d);
  }
  Flat_geodesics reused(m);
  std::size_t run = 0;
  for(std::size_t s : {std::size_t(0), std::size_t(37), std::size_t(0)}) {
    reused.clear_sources();
    reused.add_source(vertex_at(s));
    std::size_t i = 0, differ = 0;
    for(vertex_descriptor v : vertices(m))
      if(reused.distance(v) != fresh[run][i++])
        ++differ;
    CHECK(differ == 0);
    ++run;
  }
  CHECK(fresh[0] == fresh[2]);
  CHECK(fresh[0] != fresh[1]);
}
