// iso_distance_curves() and triangle_soup_iso_distance_curves(): level sets of the linearly interpolated distance
// field as polylines. Oracles: on a flat grid with one vertex source (exact distances = Euclidean), every curve
// point lies on an edge where the interpolated distance is the level, and near the analytic circle within the
// linear interpolation's error; closed circles inside, open arcs where the circle leaves the grid, none above the
// largest distance; on a sphere every level below the antipode is one closed curve; a component without a source
// has no curve; the soup and the FaceGraph versions agree.
#include <catch2/catch.hpp>

#include <MDCS_test/geodesic_test_meshes.h>
#include <MDCS_test/mesh_generators.h>

#include <CGAL/Polyhedral_geodesics_3/Exact_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/iso_distance_curves.h>

#include <cmath>
#include <iterator>
#include <limits>
#include <vector>

namespace {

using namespace MDCS_test::Epick_surface_mesh;
namespace PG = CGAL::Polyhedral_geodesics_3;
typedef PG::Iso_distance_curve<Point_3> Iso_curve;
typedef Mesh::Property_map<vertex_descriptor, double> Iso_distance_map;

Iso_distance_map iso_exact_distances(Mesh& m, vertex_descriptor source)
{
  Iso_distance_map d = m.add_property_map<vertex_descriptor, double>("v:iso_test_distance", 0).first;
  PG::Exact_geodesic_distances_3<Mesh> g(m, PG::Geodesic_memory_mode::distances_only);
  g.add_source(source);
  g.distances(d);
  return d;
}

// The linear interpolation of d at p, found on the edge of m that contains p (brute force); NaN if none does.
double iso_interpolated_value(const Mesh& m, const Iso_distance_map& d, const Point_3& p)
{
  for(auto e : edges(m)) {
    const vertex_descriptor a = source(e, m), b = target(e, m);
    const K::Segment_3 s(m.point(a), m.point(b));
    if(CGAL::squared_distance(p, s) > 1e-28) continue;
    const double t = std::sqrt(CGAL::squared_distance(p, m.point(a)) / s.squared_length());
    return (1 - t) * d[a] + t * d[b];
  }
  return std::numeric_limits<double>::quiet_NaN();
}

std::vector<Iso_curve> iso_curves_at(const Mesh& m, const Iso_distance_map& d, const std::vector<double>& levels,
                                     double level)
{
  std::vector<Iso_curve> all, r;
  PG::iso_distance_curves(m, d, levels, std::back_inserter(all));
  for(const Iso_curve& c : all)
    if(c.level == level) r.push_back(c);
  return r;
}

} // namespace

TEST_CASE("iso_distance_curves: circles around a vertex of a flat grid", "[geodesics][iso_curves]")
{
  const std::size_t n = 20; // h = 1/20, diagonals 0.0707
  Mesh m = make_mesh(MDCS_test::planar_grid<Point_3>(n, n));
  vertex_descriptor centre;
  for(vertex_descriptor v : vertices(m))
    if(m.point(v) == Point_3(0.5, 0.5, 0)) centre = v;
  const Iso_distance_map d = iso_exact_distances(m, centre);
  const std::vector<double> levels = {0.6, 0.15, 0.3, 0.45, 0.8, 0.15}; // unsorted, with a duplicate
  std::vector<Iso_curve> curves;
  PG::iso_distance_curves(m, d, levels, std::back_inserter(curves));
  const double h = std::sqrt(2.0) / double(n); // longest edge
  std::size_t closed = 0, open = 0;
  double previous = 0;
  for(const Iso_curve& c : curves) {
    CHECK(c.level >= previous); // by increasing level
    previous = c.level;
    (c.closed ? closed : open) += 1;
    CHECK(c.closed == (c.level < 0.5));
    for(const Point_3& p : c.points) {
      // on an edge, where the interpolated field is the level
      CHECK(iso_interpolated_value(m, d, p) == Approx(c.level).margin(1e-12));
      // the interpolation of the convex |x - c| is above it: the point is inside the circle, by at most the
      // interpolation error h^2 / (8 r) (second derivative 1/r across an edge of length h; 2x margin)
      const double r = std::hypot(p.x() - 0.5, p.y() - 0.5);
      CHECK(r <= c.level + 1e-12);
      CHECK(r >= c.level - h * h / (4 * (c.level - h)));
    }
    if(c.closed) { // the enclosed area is that of the circle up to the same error
      double area = 0;
      for(std::size_t i = 0; i < c.points.size(); ++i) {
        const Point_3& a = c.points[i];
        const Point_3& b = c.points[(i + 1) % c.points.size()];
        area += (a.x() - 0.5) * (b.y() - 0.5) - (b.x() - 0.5) * (a.y() - 0.5);
      }
      CHECK(std::abs(area) / 2 == Approx(3.14159265358979323846 * c.level * c.level).epsilon(0.03));
    }
  }
  // 0.15, 0.3, 0.45: one closed circle each; 0.6: four arcs in the corners, open at the border; 0.8 > sqrt(1/2):
  // no curve
  CHECK(closed == 3);
  CHECK(open == 4);
  CHECK(iso_curves_at(m, d, levels, 0.6).size() == 4);
  CHECK(iso_curves_at(m, d, levels, 0.8).empty());
  for(const Iso_curve& c : iso_curves_at(m, d, levels, 0.6)) { // each arc starts and ends on the border
    for(const Point_3* p : {&c.points.front(), &c.points.back()}) {
      const double border = std::min({p->x(), p->y(), 1 - p->x(), 1 - p->y()});
      CHECK(border <= 1e-15);
    }
  }
}

TEST_CASE("iso_distance_curves: quarter circles from a corner, and the soup version agrees", "[geodesics][iso_curves]")
{
  const MDCS_test::Triangle_soup<Point_3> soup = MDCS_test::planar_grid<Point_3>(12, 12);
  Mesh m = make_mesh(soup);
  const Iso_distance_map d = iso_exact_distances(m, *vertices(m).begin()); // (0, 0)
  REQUIRE(m.point(*vertices(m).begin()) == Point_3(0, 0, 0));
  const std::vector<double> levels = {0.25, 0.5, 0.75, 1.0, 1.2, 1.5};
  std::vector<Iso_curve> curves;
  PG::iso_distance_curves(m, d, levels, std::back_inserter(curves));
  REQUIRE(curves.size() == 5); // one open arc per level up to 1.2 (the far corner is at sqrt(2)); none at 1.5
  for(const Iso_curve& c : curves) {
    CHECK_FALSE(c.closed);
    CHECK(c.points.size() >= 2);
    for(std::size_t i = 1; i < c.points.size(); ++i) CHECK_FALSE(c.points[i] == c.points[i - 1]);
  }
  // the level 0.75 passes through the border vertices (0.75, 0) and (0, 0.75) (whose distances are 0.75 up to
  // rounding): its ends are those points
  CHECK(curves[2].level == 0.75);
  for(const Point_3* p : {&curves[2].points.front(), &curves[2].points.back()})
    CHECK(std::min(CGAL::squared_distance(*p, Point_3(0.75, 0, 0)), CGAL::squared_distance(*p, Point_3(0, 0.75, 0))) <= 1e-28);
  // the soup version with the vertex values in the soup's order (the mesh keeps it)
  std::vector<double> values;
  for(vertex_descriptor v : vertices(m)) values.push_back(d[v]);
  std::vector<Iso_curve> from_soup;
  PG::triangle_soup_iso_distance_curves(soup.points, soup.triangles, values, levels, std::back_inserter(from_soup));
  REQUIRE(from_soup.size() == curves.size());
  for(std::size_t i = 0; i < curves.size(); ++i) {
    CHECK(from_soup[i].level == curves[i].level);
    CHECK(from_soup[i].closed == curves[i].closed);
    // the same polyline, possibly run the other way (the mesh may orient or order the faces differently)
    std::vector<Point_3> reversed(curves[i].points.rbegin(), curves[i].points.rend());
    CHECK((from_soup[i].points == curves[i].points || from_soup[i].points == reversed));
  }
  // wrong input
  CHECK_THROWS_AS(PG::triangle_soup_iso_distance_curves(soup.points, soup.triangles, std::vector<double>(3, 0.0),
                                                        levels, std::back_inserter(from_soup)),
                  std::invalid_argument);
}

TEST_CASE("iso_distance_curves: closed curves on a sphere, none on a component without a source",
          "[geodesics][iso_curves]")
{
  // the sphere and a second sphere beside it, as one mesh of two components
  MDCS_test::Triangle_soup<Point_3> soup = MDCS_test::icosphere<Point_3>(3);
  const std::size_t np = soup.points.size(), nt = soup.triangles.size();
  for(std::size_t i = 0; i < np; ++i) soup.points.push_back(soup.points[i] + K::Vector_3(5, 0, 0));
  for(std::size_t t = 0; t < nt; ++t)
    soup.triangles.push_back({{soup.triangles[t][0] + np, soup.triangles[t][1] + np, soup.triangles[t][2] + np}});
  Mesh m = make_mesh(soup);
  const Iso_distance_map d = iso_exact_distances(m, *vertices(m).begin());
  std::vector<double> levels;
  for(int k = 1; k <= 9; ++k) levels.push_back(0.3 * k); // up to 2.7 < pi (the antipode is at about pi)
  std::vector<Iso_curve> curves;
  PG::iso_distance_curves(m, d, levels, std::back_inserter(curves));
  REQUIRE(curves.size() == levels.size()); // one closed curve per level, all on the first sphere
  for(std::size_t i = 0; i < curves.size(); ++i) {
    CHECK(curves[i].level == levels[i]);
    CHECK(curves[i].closed);
    for(const Point_3& p : curves[i].points) CHECK(p.x() < 2);
  }
}
