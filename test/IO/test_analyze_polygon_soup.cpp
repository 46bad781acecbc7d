// analyze_polygon_soup(): each defect on a soup made to have it (a Moebius strip against its orientable
// double cover, a fan of three sheets, a pinched vertex, flipped faces, duplicates, isolated and coincident
// points, zero-area faces, components), and on random soups the verdict against CGAL's
// is_polygon_soup_a_polygon_mesh() and orient_polygon_soup() (independent oracles).
#include <catch2/catch.hpp>

#include <MDCS_test/mesh_generators.h>

#include <CGAL/MDCS/analyze_polygon_soup.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <cmath>
#include <random>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 P;
typedef std::vector<std::size_t> Face;
using CGAL::MDCS::analyze_polygon_soup;
using CGAL::MDCS::Polygon_soup_analysis;

namespace {

// A band of n quads (as triangle pairs) around the unit circle, twisted by half a turn `twists` times: an
// annulus for an even number of twists, a Moebius strip for an odd number.
void band(std::size_t n, int twists, std::vector<P>& points, std::vector<Face>& faces)
{
  const double pi = 3.14159265358979323846;
  points.clear();
  faces.clear();
  for(std::size_t i = 0; i < n; ++i) {
    const double t = 2 * pi * double(i) / double(n), a = twists * t / 2;
    for(double s : {-0.3, 0.3})
      points.emplace_back((1 + s * std::cos(a)) * std::cos(t), (1 + s * std::cos(a)) * std::sin(t), s * std::sin(a));
  }
  for(std::size_t i = 0; i < n; ++i) {
    const std::size_t a = 2 * i, b = 2 * i + 1;
    std::size_t c = 2 * ((i + 1) % n), d = c + 1;
    if(i + 1 == n && twists % 2 == 1) std::swap(c, d); // the strip closes with its sides swapped
    faces.push_back({a, c, d});
    faces.push_back({a, d, b});
  }
}

} // namespace

TEST_CASE("analyze_polygon_soup: a closed mesh is valid", "[io][analysis]")
{
  const auto soup = MDCS_test::icosphere<P>(2);
  std::vector<Face> faces;
  for(const auto& t : soup.triangles) faces.push_back({t[0], t[1], t[2]});
  const Polygon_soup_analysis a = analyze_polygon_soup(soup.points, faces);
  CHECK(a.is_polygon_mesh());
  CHECK(a.is_triangle_mesh());
  CHECK(a.problem().empty());
  CHECK(a.number_of_points == 162);
  CHECK(a.number_of_polygons == 320);
  CHECK(a.boundary_edges == 0);
  CHECK(a.interior_edges == 480);
  CHECK(a.connected_components == 1);
  CHECK(a.isolated_points == 0);
  CHECK(a.summary() == "162 points, 320 faces of 3 corners, 1 component, 0 boundary edges");
  // With std::array points and faces too.
  std::vector<std::array<double, 3>> xyz;
  for(const P& p : soup.points) xyz.push_back({{p.x(), p.y(), p.z()}});
  CHECK(analyze_polygon_soup(xyz, soup.triangles).is_triangle_mesh());
}

TEST_CASE("analyze_polygon_soup: a Moebius strip against its orientable double cover", "[io][analysis]")
{
  std::vector<P> points;
  std::vector<Face> faces;
  band(12, 1, points, faces);
  const Polygon_soup_analysis moebius = analyze_polygon_soup(points, faces);
  CHECK_FALSE(moebius.is_polygon_mesh());
  CHECK(moebius.non_orientable_components == 1);
  CHECK_FALSE(moebius.is_orientable_polygon_mesh());
  CHECK(moebius.non_manifold_edges == 0);
  CHECK(moebius.non_manifold_vertices == 0);
  CHECK(moebius.boundary_edges == 24); // one boundary loop, twice as long as each side
  CHECK(moebius.problem().find("not orientable") != std::string::npos);
  // CGAL's orientation must cut it open (duplicate vertices), which says the same.
  std::vector<P> p2 = points;
  std::vector<Face> f2 = faces;
  CHECK_FALSE(CGAL::Polygon_mesh_processing::orient_polygon_soup(p2, f2));
  // Its double cover (two turns, a full twist) is an orientable annulus, consistently oriented as built.
  band(24, 2, points, faces);
  const Polygon_soup_analysis cover = analyze_polygon_soup(points, faces);
  CHECK(cover.is_triangle_mesh());
  CHECK(cover.non_orientable_components == 0);
  CHECK(cover.boundary_edges == 48);
  // Flipping one face of the annulus makes it inconsistent but still orientable (each triangle of the band
  // has one boundary edge and two interior ones).
  std::swap(faces[5][1], faces[5][2]);
  const Polygon_soup_analysis flipped = analyze_polygon_soup(points, faces);
  CHECK_FALSE(flipped.is_polygon_mesh());
  CHECK(flipped.is_orientable_polygon_mesh());
  CHECK(flipped.inconsistent_edges == 2);
  CHECK(flipped.problem().find("not consistently oriented") != std::string::npos);
}

TEST_CASE("analyze_polygon_soup: non-manifold edges and pinched vertices", "[io][analysis]")
{
  // A fan of three sheets on the edge (0, 1).
  std::vector<P> points = {P(0, 0, 0), P(1, 0, 0), P(0.5, 1, 0), P(0.5, -1, 0), P(0.5, 0, 1)};
  std::vector<Face> faces = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  Polygon_soup_analysis a = analyze_polygon_soup(points, faces);
  CHECK(a.non_manifold_edges == 1);
  CHECK(a.example_non_manifold_edge == std::array<std::size_t, 2>{{0, 1}});
  CHECK(a.example_non_manifold_edge_uses == 3);
  CHECK(a.example_non_manifold_edge_polygons == std::vector<std::size_t>{0, 1, 2});
  CHECK(a.problem().find("edge (0, 1) is shared by 3 face sides (faces 0, 1, 2)") != std::string::npos);
  CHECK(a.connected_components == 1);
  // Two tetrahedra sharing a vertex: closed, two components, one pinched vertex.
  points = {P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(0, 0, 1), P(-1, 0, 0), P(0, -1, 0), P(0, 0, -1)};
  faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 4, 5}, {0, 6, 4}, {0, 5, 6}, {4, 6, 5}};
  a = analyze_polygon_soup(points, faces);
  CHECK(a.non_manifold_vertices == 1);
  CHECK(a.example_non_manifold_vertex == 0);
  CHECK(a.example_non_manifold_vertex_fans == 2);
  CHECK(a.non_manifold_edges == 0);
  CHECK(a.inconsistent_edges == 0);
  CHECK(a.connected_components == 2);
  CHECK(a.problem() == "vertex 0 is pinched: the faces around it form 2 separate fans");
  // A bow tie: two triangles sharing one vertex, with boundary.
  points = {P(0, 0, 0), P(1, 1, 0), P(1, -1, 0), P(-1, 1, 0), P(-1, -1, 0)};
  faces = {{0, 2, 1}, {0, 3, 4}};
  a = analyze_polygon_soup(points, faces);
  CHECK(a.non_manifold_vertices == 1);
  CHECK_FALSE(CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(faces));
}

TEST_CASE("analyze_polygon_soup: combinatorial and geometric defects", "[io][analysis]")
{
  std::vector<P> points = {P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(2, 0, 0), P(1, 0, 0), P(5, 5, 5)};
  std::vector<Face> faces = {
    {0, 1, 2},    // fine
    {2, 1, 0},    // the same points reversed: a duplicate (a valid pillow with the first)
    {0, 1, 3},    // collinear: zero area (and its edge (0, 1) is a third use)
    {0, 2},       // too few corners
    {0, 2, 2, 1}, // a repeated point
  };
  const Polygon_soup_analysis a = analyze_polygon_soup(points, faces);
  CHECK(a.polygons_with_too_few_corners == 1);
  CHECK(a.example_small_polygon == 3);
  CHECK(a.polygons_with_repeated_points == 1);
  CHECK(a.example_repeated_polygon == 4);
  CHECK(a.example_repeated_point == 2);
  CHECK(a.duplicate_polygons == 1);
  CHECK(a.example_duplicate_polygons == std::array<std::size_t, 2>{{0, 1}});
  CHECK(a.degenerate_polygons >= 1);
  CHECK(a.example_degenerate_polygon == 2);
  CHECK(a.isolated_points == 2); // 4 (a copy of 1, unused) and 5
  CHECK(a.coincident_points == 1);
  CHECK(a.example_coincident_points == std::array<std::size_t, 2>{{1, 4}});
  CHECK(a.smallest_polygon == 2);
  CHECK(a.largest_polygon == 4);
  CHECK_FALSE(a.all_triangles());
  CHECK(a.problem() == "face 3 has fewer than 3 corners");
  // Non-finite points: counted, and no geometric test is attempted.
  points[5] = P(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  const Polygon_soup_analysis b = analyze_polygon_soup(points, faces);
  CHECK(b.non_finite_points == 1);
  CHECK(b.degenerate_polygons == 0);
  // Indices beyond the points are a caller's error.
  faces.push_back({0, 1, 9});
  CHECK_THROWS_AS(analyze_polygon_soup(points, faces), std::invalid_argument);
  std::vector<std::vector<int>> negative = {{0, 1, -1}};
  CHECK_THROWS_AS(analyze_polygon_soup(points, negative), std::invalid_argument);
  // The empty soup.
  const Polygon_soup_analysis e = analyze_polygon_soup(std::vector<P>(), std::vector<Face>());
  CHECK(e.is_polygon_mesh());
  CHECK_FALSE(e.is_triangle_mesh());
}

// Random damage to a closed mesh (faces removed, flipped, duplicated; vertices glued): the verdict must equal
// CGAL's is_polygon_soup_a_polygon_mesh(); where the soup is orientable and manifold, CGAL's
// orient_polygon_soup() must succeed without duplicating a vertex, and fail where it is not orientable.
TEST_CASE("analyze_polygon_soup: agrees with CGAL on randomly damaged soups", "[io][analysis][oracle]")
{
  const auto sphere = MDCS_test::icosphere<P>(1);
  std::mt19937 random(28);
  std::size_t valid = 0, invalid = 0, non_orientable = 0;
  for(int round = 0; round < 400; ++round) {
    std::vector<Face> faces;
    for(const auto& t : sphere.triangles) faces.push_back({t[0], t[1], t[2]});
    const int damages = int(random() % 4);
    for(int d = 0; d < damages; ++d) {
      const std::size_t f = random() % faces.size();
      switch(random() % 5) {
      case 0: faces.erase(faces.begin() + std::ptrdiff_t(f)); break;
      case 1: std::swap(faces[f][0], faces[f][1]); break;
      case 2: faces.push_back(faces[f]); break;
      case 3: { // glue two vertices
        const std::size_t from = random() % sphere.points.size(), to = random() % sphere.points.size();
        for(Face& g : faces)
          for(std::size_t& v : g)
            if(v == from) v = to;
        break;
      }
      default: { // flip a whole region: every face touching a vertex
        const std::size_t v = random() % sphere.points.size();
        for(Face& g : faces)
          if(std::find(g.begin(), g.end(), v) != g.end()) std::swap(g[1], g[2]);
        break;
      }
      }
    }
    INFO("round " << round);
    const Polygon_soup_analysis a = analyze_polygon_soup(sphere.points, faces);
    CHECK(a.is_polygon_mesh() == CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(faces));
    (a.is_polygon_mesh() ? valid : invalid) += 1;
    if(a.polygons_with_repeated_points == 0 && a.non_manifold_edges == 0 && a.non_manifold_vertices == 0) {
      std::vector<P> p = sphere.points;
      std::vector<Face> g = faces;
      const bool oriented_without_duplication = CGAL::Polygon_mesh_processing::orient_polygon_soup(p, g);
      CHECK(oriented_without_duplication == (a.non_orientable_components == 0));
      non_orientable += a.non_orientable_components > 0 ? 1 : 0;
    }
  }
  CHECK(valid > 50);
  CHECK(invalid > 50);
}
