// triangulate_polygon_soup(): convex, concave, non-planar, self-intersecting and degenerate polygons. Oracles:
// the polygon's area (shoelace / Newell) against the sum of the triangles' signed areas, every triangle turned
// like its polygon, the combinatorial cover (each side once, each diagonal once each way), a closed polygon
// mesh that stays closed with its volume, and CGAL's triangulate_faces() on the same mesh.
#include <catch2/catch.hpp>

#include <CGAL/MDCS/analyze_polygon_soup.h>
#include <CGAL/MDCS/triangulate_polygon_soup.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 P;
typedef K::Vector_3 V;
typedef std::vector<std::size_t> Face;
typedef std::array<std::size_t, 3> Tri;
using CGAL::MDCS::Polygon_soup_triangulation_report;
using CGAL::MDCS::triangulate_polygon_soup;

namespace {

const double pi = 3.14159265358979323846;

// Twice the vector area of a polygon (Newell).
V newell(const std::vector<P>& p, const Face& f)
{
  V n(0, 0, 0);
  for(std::size_t i = 0; i < f.size(); ++i) n = n + CGAL::cross_product(p[f[i]] - CGAL::ORIGIN, p[f[(i + 1) % f.size()]] - CGAL::ORIGIN);
  return n;
}

// Places planar 2D outlines in a tilted plane, so that no coordinate plane is special.
std::vector<P> in_tilted_plane(const std::vector<std::array<double, 2>>& xy)
{
  const V u = V(1, 0.3, 0.2) / std::sqrt(1.13), w0 = CGAL::cross_product(V(1, 0.3, 0.2), V(0.1, 1, -0.4));
  const V w = CGAL::cross_product(w0, u) / std::sqrt(w0.squared_length());
  std::vector<P> p;
  for(const auto& q : xy) p.push_back(P(0.5, -2, 3) + q[0] * u + q[1] * w);
  return p;
}

// Triangulates one polygon and checks the oracles that hold for every method.
std::vector<Tri> triangulate_one(const std::vector<P>& p, Polygon_soup_triangulation_report& report)
{
  Face f(p.size());
  for(std::size_t i = 0; i < p.size(); ++i) f[i] = i;
  std::vector<Tri> t;
  std::vector<std::size_t> origin;
  report = triangulate_polygon_soup(p, std::vector<Face>{f}, t, &origin);
  CHECK(t.size() == p.size() - 2);
  CHECK(origin == std::vector<std::size_t>(t.size(), 0));
  std::vector<std::array<std::size_t, 3>> local(t.begin(), t.end());
  CHECK(CGAL::MDCS::internal::covers_polygon(p.size(), local));
  return t;
}

// For a planar simple polygon: the triangles' signed areas (along the polygon's normal) are all positive and
// sum to the polygon's area, so they cover it without overlap.
void check_planar_cover(const std::vector<P>& p, const std::vector<Tri>& t)
{
  const V n = newell(p, Face([&] { Face f(p.size()); for(std::size_t i = 0; i < f.size(); ++i) f[i] = i; return f; }()));
  const V unit = n / std::sqrt(n.squared_length());
  double sum = 0;
  for(const Tri& tr : t) {
    const double signed_area = CGAL::cross_product(p[tr[1]] - p[tr[0]], p[tr[2]] - p[tr[0]]) * unit / 2;
    CHECK(signed_area > 0);
    sum += signed_area;
  }
  CHECK(sum == Approx(std::sqrt(n.squared_length()) / 2).epsilon(1e-12));
}

} // namespace

TEST_CASE("triangulate_polygon_soup: convex and concave planar polygons", "[io][triangulation]")
{
  Polygon_soup_triangulation_report r;
  // A regular hexagon, an L, a star of 10 corners, a comb of 20 corners, a regular 1000-gon.
  std::vector<std::array<double, 2>> hexagon, star, comb, big;
  for(int i = 0; i < 6; ++i) hexagon.push_back({{std::cos(i * pi / 3), std::sin(i * pi / 3)}});
  for(int i = 0; i < 10; ++i) {
    const double radius = i % 2 ? 0.35 : 1.0;
    star.push_back({{radius * std::cos(i * pi / 5), radius * std::sin(i * pi / 5)}});
  }
  // A comb: a base [0, 9] x [-1, 0] with five teeth of height 3 (20 corners, area 24).
  comb = {{{0, -1}}, {{9, -1}}};
  for(int k = 4; k >= 0; --k) {
    comb.push_back({{2.0 * k + 1, 3}});
    comb.push_back({{2.0 * k, 3}});
    if(k > 0) {
      comb.push_back({{2.0 * k, 0}});
      comb.push_back({{2.0 * k - 1, 0}});
    }
  }
  for(int i = 0; i < 1000; ++i) big.push_back({{std::cos(i * pi / 500), std::sin(i * pi / 500)}});
  const std::vector<std::array<double, 2>> el = {{{0, 0}}, {{2, 0}}, {{2, 1}}, {{1, 1}}, {{1, 3}}, {{0, 3}}};
  typedef std::vector<std::array<double, 2>> Outline;
  for(const Outline* outline : std::vector<const Outline*>{&hexagon, &el, &star, &comb, &big}) {
    INFO(outline->size() << " corners");
    const std::vector<P> p = in_tilted_plane(*outline);
    const auto t = triangulate_one(p, r);
    CHECK(r.by_constrained_delaunay == 1);
    check_planar_cover(p, t);
    // The same polygon turned the other way: triangles turned the other way.
    std::vector<P> reversed(p.rbegin(), p.rend());
    check_planar_cover(reversed, triangulate_one(reversed, r));
  }
}

TEST_CASE("triangulate_polygon_soup: quadrilaterals, non-planar and self-intersecting polygons", "[io][triangulation]")
{
  Polygon_soup_triangulation_report r;
  // A planar square and a non-planar quad: the diagonal of CGAL's rule.
  triangulate_one({P(0, 0, 0), P(1, 0, 0), P(1, 1, 0), P(0, 1, 0)}, r);
  CHECK(r.quadrilaterals == 1);
  for(const std::vector<P>& q : {std::vector<P>{P(0, 0, 0), P(1, 0, 0), P(1.5, 1, 0.8), P(0, 1, 0)},
                                 std::vector<P>{P(0, 0, 0), P(2, 0, 0.3), P(1, 1, 0), P(0, 1, -0.5)}}) {
    const auto t = triangulate_one(q, r);
    CHECK(r.quadrilaterals == 1);
    // The diagonal chosen gives the pair of triangles whose normals have the larger dot product.
    auto normal = [&](std::size_t a, std::size_t b, std::size_t c) { return CGAL::cross_product(q[b] - q[a], q[c] - q[a]); };
    const double along_02 = normal(0, 1, 2) * normal(0, 2, 3), along_13 = normal(1, 2, 3) * normal(1, 3, 0);
    const bool chose_02 = (t[0] == Tri{{0, 1, 2}} || t[1] == Tri{{0, 1, 2}});
    CHECK(chose_02 == (along_02 > along_13));
  }
  // A crown: a hexagon whose corners go up and down; its projection along the Newell normal is simple.
  std::vector<P> crown;
  for(int i = 0; i < 8; ++i) crown.push_back(P(std::cos(i * pi / 4), std::sin(i * pi / 4), i % 2 ? 0.4 : -0.4));
  triangulate_one(crown, r);
  CHECK(r.by_constrained_delaunay == 1);
  // A pentagram: the boundary crosses itself in its plane (lifted a little so that it is not degenerate).
  std::vector<P> pentagram;
  for(int i = 0; i < 5; ++i) {
    const int j = (2 * i) % 5;
    pentagram.push_back(P(std::cos(j * 2 * pi / 5), std::sin(j * 2 * pi / 5), 0.1 * i));
  }
  triangulate_one(pentagram, r);
  CHECK(r.by_constrained_delaunay == 0);
  CHECK(r.by_hole_filling + r.by_fan == 1);
  // A large self-intersecting polygon: beyond the hole-filling limit it becomes a fan (and says so).
  std::vector<P> spiral;
  for(int i = 0; i < 400; ++i) {
    const int j = (7 * i) % 400;
    spiral.push_back(P(std::cos(j * pi / 200), std::sin(j * pi / 200), 0));
  }
  triangulate_one(spiral, r);
  CHECK(r.by_fan == 1);
}

TEST_CASE("triangulate_polygon_soup: degenerate polygons become fans", "[io][triangulation]")
{
  Polygon_soup_triangulation_report r;
  triangulate_one({P(0, 0, 0), P(1, 0, 0), P(2, 0, 0), P(3, 0, 0), P(4, 0, 0)}, r); // collinear
  CHECK(r.by_fan == 1);
  triangulate_one({P(0, 0, 0), P(0, 0, 0), P(0, 0, 0), P(0, 0, 0), P(0, 0, 0)}, r); // one point
  CHECK(r.by_fan == 1);
  triangulate_one({P(0, 0, 0), P(1, 0, 0), P(1, 1, 0), P(std::nan(""), 1, 0)}, r); // a NaN
  CHECK(r.by_fan == 1);
  triangulate_one({P(0, 0, 0), P(1e300, 0, 0), P(1e300, 1e300, 0), P(0, 1e300, 0), P(-1e300, 0, 0)}, r); // overflow
  CHECK(r.by_fan == 1);
  // A point repeated in a polygon (not a simple polygon): a fan over the corners as given.
  std::vector<P> p = {P(0, 0, 0), P(1, 0, 0), P(1, 1, 0), P(0, 1, 0)};
  std::vector<Tri> t;
  r = triangulate_polygon_soup(p, std::vector<Face>{{0, 1, 2, 1, 3}}, t);
  CHECK(r.by_fan == 1);
  CHECK(t.size() == 3);
  // Fewer than 3 corners, or an index beyond the points: the caller's error.
  CHECK_THROWS_AS(triangulate_polygon_soup(p, std::vector<Face>{{0, 1}}, t), std::invalid_argument);
  CHECK_THROWS_AS(triangulate_polygon_soup(p, std::vector<Face>{{0, 1, 4}}, t), std::invalid_argument);
}

TEST_CASE("triangulate_polygon_soup: a closed polygon mesh stays closed, with CGAL's area and volume", "[io][triangulation][oracle]")
{
  // A prism over an L (concave hexagons at both ends, quads on the sides).
  const std::vector<std::array<double, 2>> el = {{{0, 0}}, {{2, 0}}, {{2, 1}}, {{1, 1}}, {{1, 3}}, {{0, 3}}};
  std::vector<P> points;
  for(double z : {0.0, 1.5})
    for(const auto& q : el) points.push_back(P(q[0], q[1], z));
  std::vector<Face> faces = {{5, 4, 3, 2, 1, 0}, {6, 7, 8, 9, 10, 11}};
  for(std::size_t i = 0; i < 6; ++i) faces.push_back({i, (i + 1) % 6, 6 + (i + 1) % 6, 6 + i});
  std::vector<Tri> triangles;
  std::vector<std::size_t> origin;
  const Polygon_soup_triangulation_report r = triangulate_polygon_soup(points, faces, triangles, &origin);
  CHECK(r.quadrilaterals == 6);
  CHECK(r.by_constrained_delaunay == 2);
  CHECK(r.triangles == 20);
  CHECK(origin.front() == 0);
  CHECK(origin.back() == 7);
  const auto a = CGAL::MDCS::analyze_polygon_soup(points, triangles);
  CHECK(a.is_triangle_mesh());
  CHECK(a.boundary_edges == 0);
  CGAL::Surface_mesh<P> ours, theirs;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, ours);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, theirs);
  CGAL::Polygon_mesh_processing::triangulate_faces(theirs);
  CHECK(CGAL::Polygon_mesh_processing::volume(ours) == Approx(6.0).epsilon(1e-12)); // area of the L (4) x 1.5
  CHECK(CGAL::Polygon_mesh_processing::volume(ours) == Approx(CGAL::Polygon_mesh_processing::volume(theirs)).epsilon(1e-12));
  CHECK(CGAL::Polygon_mesh_processing::area(ours) == Approx(CGAL::Polygon_mesh_processing::area(theirs)).epsilon(1e-12));
}
