// Merged windows on flat meshes (issue 28, item 6): the distances equal the straight-line distance (1e-12 relative) in
// every mode and at every tolerance, on convex planar meshes of several shapes, from vertex and surface-point
// sources. Before the rule on filler windows (window_edge_envelope.h, mergeable_over), the window propagation (the
// full field, distances with a limit or stop targets, or with the vertex-oriented schedule switched off) put 1 to
// 550 vertices of these meshes up to 0.66 tolerances above the straight-line distance, from 0.01 edge lengths up;
// the vertex-oriented schedule was exact already. Also: on a curved mesh the rule leaves the trade-off of merging
// intact (the error stays above 0 and below the previous code's by a small margin; tested loosely here, measured in
// the manual).
#include <catch2/catch.hpp>

#include <MDCS_test/geodesic_oracles.h>
#include <MDCS_test/geodesic_test_meshes.h>
#include <MDCS_test/mesh_generators.h>
#include <MDCS_test/geodesic_test_geometry.h>

#include <CGAL/Polyhedral_geodesics_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace {

using namespace MDCS_test::Epick_surface_mesh;
namespace PG = CGAL::Polyhedral_geodesics_3;
typedef PG::Merged_window_geodesic_distances_3<Mesh> Merged;

using MDCS_test::mean_edge_length;

// A regular hexagon fanned from its centre and refined: a convex planar mesh with border vertices of angle 2 pi / 3.
MDCS_test::Triangle_soup<Point_3> refined_hexagon(std::size_t rings)
{
  MDCS_test::Triangle_soup<Point_3> s;
  using MDCS_test::pi;
  // vertices by ring r (0: the centre) and position k in the ring (6 r of them)
  std::vector<std::vector<std::size_t>> ring(rings + 1);
  s.points.push_back(Point_3(0, 0, 0));
  ring[0].push_back(0);
  for(std::size_t r = 1; r <= rings; ++r)
    for(std::size_t side = 0; side < 6; ++side) {
      const double a0 = pi / 3 * double(side), a1 = pi / 3 * double(side + 1);
      for(std::size_t k = 0; k < r; ++k) {
        const double t = double(k) / double(r);
        const double x = double(r) * ((1 - t) * std::cos(a0) + t * std::cos(a1));
        const double y = double(r) * ((1 - t) * std::sin(a0) + t * std::sin(a1));
        s.points.push_back(Point_3(x, y, 0));
        ring[r].push_back(s.points.size() - 1);
      }
    }
  auto at = [&](std::size_t r, std::size_t i) { return r == 0 ? std::size_t(0) : ring[r][i % (6 * r)]; };
  for(std::size_t r = 1; r <= rings; ++r)
    for(std::size_t side = 0; side < 6; ++side)
      for(std::size_t k = 0; k < r; ++k) {
        const std::size_t outer = side * r + k, inner = side * (r - 1) + k;
        s.triangles.push_back({at(r - 1, inner), at(r, outer), at(r, outer + 1)});
        if(k + 1 < r)
          s.triangles.push_back({at(r - 1, inner), at(r, outer + 1), at(r - 1, inner + 1)});
      }
  return s;
}

struct Flat_case
{
  std::string name;
  Mesh mesh;
};

std::vector<Flat_case> flat_cases()
{
  std::vector<Flat_case> r;
  r.push_back({"subdivided triangle", MDCS_test::mesh_from_soup<Mesh>(MDCS_test::subdivided_triangle<Point_3>(20))});
  r.push_back({"planar grid", MDCS_test::mesh_from_soup<Mesh>(MDCS_test::planar_grid<Point_3>(18, 12, 2.0, 1.4))});
  r.push_back({"jittered grid 7", MDCS_test::mesh_from_soup<Mesh>(MDCS_test::jittered_planar_grid<Point_3>(20, 14, 2.0, 1.4, 0.3, 7))});
  r.push_back({"jittered grid 3", MDCS_test::mesh_from_soup<Mesh>(MDCS_test::jittered_planar_grid<Point_3>(22, 22, 1.0, 1.0, 0.3, 3))});
  r.push_back({"sheared grid", MDCS_test::mesh_from_soup<Mesh>(MDCS_test::sheared_planar_grid<Point_3>(18))});
  r.push_back({"refined hexagon", MDCS_test::mesh_from_soup<Mesh>(refined_hexagon(9))});
  return r;
}

enum class Mode { full_field, distances_only, distances_only_windows, limit, stop_targets };

const char* mode_name(Mode m)
{
  switch(m) {
  case Mode::full_field: return "full field";
  case Mode::distances_only: return "distances only (vertex-oriented)";
  case Mode::distances_only_windows: return "distances only (window propagation)";
  case Mode::limit: return "distance limit";
  case Mode::stop_targets: return "stop targets";
  }
  return "";
}

} // namespace

TEST_CASE("merged windows on flat meshes: the straight-line distance in every mode and at every tolerance",
          "[geodesics][merged][flat]")
{
  for(const Flat_case& c : flat_cases()) {
    const Mesh& m = c.mesh;
    const double edge = mean_edge_length(m);
    const std::size_t nv = num_vertices(m);
    std::size_t checked = 0;
    for(double relative : {0.001, 0.01, 0.1, 0.3, 1.0, 3.0})
      for(Mode mode : {Mode::full_field, Mode::distances_only, Mode::distances_only_windows, Mode::limit, Mode::stop_targets})
        for(std::size_t which : {std::size_t(0), nv / 3, nv / 2, std::size_t(-1)}) {
          INFO(c.name << ", tolerance " << relative << " edge lengths, " << mode_name(mode));
          Merged g(m, relative * edge,
                   mode == Mode::full_field ? PG::Geodesic_memory_mode::full_field : PG::Geodesic_memory_mode::distances_only);
          if(mode == Mode::distances_only_windows)
            g.set_vertex_oriented_propagation(false);
          // a vertex source, or a point inside a face in the middle of the mesh
          Point_3 ps;
          if(which != std::size_t(-1)) {
            const vertex_descriptor s(static_cast<Mesh::size_type>(which));
            g.add_source(s);
            ps = m.point(s);
            INFO("source vertex " << which);
          } else {
            const auto f = *std::next(faces(m).begin(), std::ptrdiff_t(num_faces(m) / 2));
            const std::array<double, 3> b = {0.2, 0.5, 0.3};
            g.add_source(Merged::Face_location(f, b));
            auto h = halfedge(f, m);
            const Point_3 &p0 = m.point(source(h, m)), &p1 = m.point(target(h, m)), &p2 = m.point(target(next(h, m), m));
            ps = Point_3(b[0] * p0.x() + b[1] * p1.x() + b[2] * p2.x(), b[0] * p0.y() + b[1] * p1.y() + b[2] * p2.y(), 0);
          }
          if(mode == Mode::limit)
            g.set_distance_limit(1e6);
          if(mode == Mode::stop_targets)
            g.set_stop_targets(std::vector<vertex_descriptor>{vertex_descriptor(static_cast<Mesh::size_type>(nv - 1))});
          std::size_t wrong = 0, unreached = 0;
          double worst = 0;
          for(vertex_descriptor v : vertices(m)) {
            const double e = std::sqrt(CGAL::to_double(CGAL::squared_distance(ps, m.point(v))));
            const double d = g.distance(v);
            if(mode == Mode::stop_targets && !std::isfinite(d)) {
              ++unreached; // allowed: stopped early
              continue;
            }
            const double error = std::abs(d - e) / std::max(e, 1e-300);
            if(!(error <= 1e-12) && !(std::abs(d - e) <= 1e-14))
              ++wrong;
            worst = std::max(worst, std::abs(d - e));
            ++checked;
          }
          INFO("worst difference " << worst << " (" << worst / edge << " edge lengths)");
          CHECK(wrong == 0);
          if(mode == Mode::full_field) {
            // point queries inside faces
            std::size_t k = 0;
            for(auto f : faces(m)) {
              if(++k % 17 != 0)
                continue;
              const std::array<double, 3> b = {0.3, 0.3, 0.4};
              auto h = halfedge(f, m);
              const Point_3 &p0 = m.point(source(h, m)), &p1 = m.point(target(h, m)), &p2 = m.point(target(next(h, m), m));
              const Point_3 q(b[0] * p0.x() + b[1] * p1.x() + b[2] * p2.x(), b[0] * p0.y() + b[1] * p1.y() + b[2] * p2.y(), 0);
              const double e = std::sqrt(CGAL::to_double(CGAL::squared_distance(ps, q)));
              CHECK(g.distance(Merged::Face_location(f, b)) == Approx(e).epsilon(1e-12).margin(1e-14));
            }
          }
        }
    CHECK(checked > 0);
  }
}

TEST_CASE("merged windows on flat meshes: curved meshes keep the trade-off", "[geodesics][merged]")
{
  // The rule only concerns filler windows: on a curved mesh the merged distances stay above the exact ones and
  // clearly away from them at a coarse tolerance (merging still happens), in the window propagation.
  const Mesh m = MDCS_test::mesh_from_soup<Mesh>(MDCS_test::bumpy_sphere<Point_3>(3, 0.2, 5));
  const double edge = mean_edge_length(m);
  const vertex_descriptor s(static_cast<Mesh::size_type>(num_vertices(m) / 3));
  PG::Exact_geodesic_distances_3<Mesh> exact(m, PG::Geodesic_memory_mode::full_field);
  exact.add_source(s);
  Merged merged(m, 0.3 * edge, PG::Geodesic_memory_mode::full_field);
  merged.add_source(s);
  double sum = 0;
  std::size_t below = 0;
  for(vertex_descriptor v : vertices(m)) {
    const double d = exact.distance(v), a = merged.distance(v);
    below += a < d * (1 - 1e-12) ? 1 : 0;
    if(d > 0)
      sum += (a - d) / d;
  }
  CHECK(below == 0);
  CHECK(sum / double(num_vertices(m)) > 1e-5);
  CHECK(merged.statistics().windows_merged > 0);
  CHECK(merged.statistics().windows_propagated < exact.statistics().windows_propagated);
}
