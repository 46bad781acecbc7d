// Silhouette extraction and loop decomposition (thesis 5.2.1): exact front-facing predicate, closed
// loops on closed and open meshes, loops without repeated vertices, defined behaviour on bad input.
#include <catch2/catch.hpp>

#include "silhouette_test_meshes.h"

#include <CGAL/Silhouette_simplification_3/silhouette_edges.h>
#include <CGAL/Silhouette_simplification_3/Silhouette_simplifier_3.h>

#include <map>
#include <set>

using namespace silhouette_test;
namespace SS = CGAL::Silhouette_simplification_3;
typedef SS::View_3<K> View;

namespace {

// Views on a sphere of radius 4 around the origin, perspective and orthographic.
std::vector<View> test_views(std::size_t n)
{
  std::vector<View> views;
  for(std::size_t i = 0; i < n; ++i) {
    const double a = 6.283185307179586 * hash01(3 * i + 1), z = 2 * hash01(3 * i + 2) - 1;
    const double s = std::sqrt(1 - z * z);
    const Vector_3 d(s * std::cos(a), s * std::sin(a), z);
    views.push_back(View::perspective(CGAL::ORIGIN + 4 * d));
    views.push_back(View::orthographic(-d));
  }
  return views;
}

// Checks the loop invariants on a mesh: each loop chains, is closed, has no repeated vertex, and the
// loops partition the input silhouette.
template <class Mesh_>
void check_loops(const Mesh_& m, const std::vector<typename boost::graph_traits<Mesh_>::halfedge_descriptor>& sil,
                 const std::vector<SS::Silhouette_loop<typename boost::graph_traits<Mesh_>::halfedge_descriptor>>& loops)
{
  std::size_t total = 0;
  std::set<typename boost::graph_traits<Mesh_>::halfedge_descriptor> seen;
  for(const auto& loop : loops) {
    REQUIRE(loop.closed);
    REQUIRE(loop.halfedges.size() >= 3);
    std::set<typename boost::graph_traits<Mesh_>::vertex_descriptor> vs;
    for(std::size_t i = 0; i < loop.halfedges.size(); ++i) {
      const auto h = loop.halfedges[i], g = loop.halfedges[(i + 1) % loop.halfedges.size()];
      REQUIRE(target(h, m) == source(g, m));
      REQUIRE(vs.insert(source(h, m)).second); // no repeated vertex
      REQUIRE(seen.insert(h).second);
    }
    total += loop.halfedges.size();
  }
  REQUIRE(total == sil.size());
  for(auto h : sil) REQUIRE(seen.count(h) == 1);
}

} // namespace

TEST_CASE("View_3: front-facing predicate on a tetrahedron, independent of the starting vertex", "[silhouette][view]")
{
  const Point_3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  // Face (a, b, c) is counter-clockwise seen from +z: its outward normal is +z.
  CHECK(View::perspective(Point_3(0.2, 0.2, 1)).is_front_facing(a, b, c));
  CHECK(View::perspective(Point_3(0.2, 0.2, 1)).is_front_facing(b, c, a));
  CHECK(!View::perspective(Point_3(0.2, 0.2, -1)).is_front_facing(a, b, c));
  CHECK(!View::perspective(Point_3(5, 5, 0)).is_front_facing(a, b, c));      // eye in the plane: back
  CHECK(View::orthographic(Vector_3(0, 0, -1)).is_front_facing(a, b, c));    // looking down -z
  CHECK(View::orthographic(Vector_3(0, 0, -1)).is_front_facing(c, a, b));
  CHECK(!View::orthographic(Vector_3(0, 0, 1)).is_front_facing(a, b, c));
  CHECK(!View::orthographic(Vector_3(1, 0, 0)).is_front_facing(a, b, c));    // edge-on: back
  // Nearly edge-on: the exact predicate decides by the true sign of a tiny determinant.
  CHECK(View::orthographic(Vector_3(1, 0, -1e-300)).is_front_facing(a, b, c));
  CHECK(!View::orthographic(Vector_3(1, 0, 1e-300)).is_front_facing(a, b, c));
  // Degenerate triangle: back.
  CHECK(!View::perspective(Point_3(0, 0, 1)).is_front_facing(a, b, Point_3(2, 0, 0)));
  CHECK_THROWS_AS(View::orthographic(Vector_3(0, 0, 0)), std::invalid_argument);
}

TEST_CASE("silhouette: on closed meshes the silhouette forms closed loops without repeated vertices", "[silhouette][loops]")
{
  for(int shape = 0; shape < 3; ++shape) {
    const Mesh m = make<Mesh>(shape == 0 ? noisy_sphere(3, 0.08) : shape == 1 ? torus(40, 16, 1, 0.4, 0.05)
                                                                               : noisy_sphere(2, 0.3, 7));
    for(const View& view : test_views(10)) {
      std::vector<Mesh::Halfedge_index> sil;
      SS::silhouette_halfedges(m, view, std::back_inserter(sil));
      REQUIRE(!sil.empty());
      // Oracle: the definition, face by face.
      std::size_t expected = 0;
      for(auto h : halfedges(m)) {
        if(is_border(h, m)) continue;
        auto front = [&](Mesh::Face_index f) {
          auto hh = halfedge(f, m);
          return view.is_front_facing(m.point(source(hh, m)), m.point(target(hh, m)), m.point(target(next(hh, m), m)));
        };
        if(front(face(h, m)) && !front(face(opposite(h, m), m))) ++expected;
      }
      REQUIRE(sil.size() == expected);
      const auto loops = SS::decompose_into_loops(m, sil);
      check_loops(m, sil, loops);
    }
  }
}

TEST_CASE("silhouette: open meshes: border edges of front faces close the loops", "[silhouette][loops][border]")
{
  const Mesh m = make<Mesh>(bumpy_grid(20));
  for(const View& view : test_views(6)) {
    std::vector<Mesh::Halfedge_index> sil;
    SS::silhouette_halfedges(m, view, std::back_inserter(sil));
    const auto loops = SS::decompose_into_loops(m, sil);
    check_loops(m, sil, loops);
    for(auto h : sil) REQUIRE(!is_border(h, m));
  }
  // Seen from above, every face is front-facing: the silhouette is the border loop.
  std::vector<Mesh::Halfedge_index> sil;
  SS::silhouette_halfedges(m, View::orthographic(Vector_3(0, 0, -1)), std::back_inserter(sil));
  CHECK(sil.size() == 80);
  CHECK(SS::decompose_into_loops(m, sil).size() == 1);
}

TEST_CASE("decompose_into_loops: sub-loops are snapped off; non-cycles give open chains", "[silhouette][loops]")
{
  // Figure eight through the centre vertex of a 2x2 grid: (0,0)->(1,0)->(1,1)->(0,1)->... use grid vertices.
  const Mesh m = make<Mesh>(MDCS_test::planar_grid<Point_3>(2, 2));
  auto v = [&](int i, int j) { return Mesh::Vertex_index(std::uint32_t(j * 3 + i)); };
  auto he = [&](Mesh::Vertex_index a, Mesh::Vertex_index b) {
    auto r = halfedge(a, b, m);
    REQUIRE(r.second);
    return r.first;
  };
  // Loop 1: (0,0)->(1,0)->(1,1)->(0,1)->(0,0); loop 2: (1,1)->(2,1)->(2,2)->(1,2)->(1,1). Given interleaved.
  std::vector<Mesh::Halfedge_index> hs = {he(v(0, 0), v(1, 0)), he(v(1, 0), v(1, 1)), he(v(1, 1), v(2, 1)),
                                          he(v(2, 1), v(2, 2)), he(v(2, 2), v(1, 2)), he(v(1, 2), v(1, 1)),
                                          he(v(1, 1), v(0, 1)), he(v(0, 1), v(0, 0))};
  // The planar grid's diagonals decide which of these edges exist; skip the case if one does not.
  const auto loops = SS::decompose_into_loops(m, hs);
  check_loops(m, hs, loops);
  CHECK(loops.size() == 2);
  // An open chain.
  std::vector<Mesh::Halfedge_index> chain = {he(v(0, 0), v(1, 0)), he(v(1, 0), v(2, 0))};
  const auto open = SS::decompose_into_loops(m, chain);
  REQUIRE(open.size() == 1);
  CHECK(!open[0].closed);
  CHECK(open[0].halfedges.size() == 2);
}

TEST_CASE("silhouette: bad input gets a clear error or a defined result", "[silhouette][robustness]")
{
  // Non-triangle face.
  Mesh quad;
  auto a = quad.add_vertex(Point_3(0, 0, 0)), b = quad.add_vertex(Point_3(1, 0, 0)), c = quad.add_vertex(Point_3(1, 1, 0)),
       d = quad.add_vertex(Point_3(0, 1, 0));
  quad.add_face(a, b, c, d);
  std::vector<Mesh::Halfedge_index> out;
  CHECK_THROWS_AS(SS::silhouette_halfedges(quad, View::perspective(Point_3(0, 0, 1)), std::back_inserter(out)),
                  std::invalid_argument);
  // Empty mesh.
  Mesh empty;
  CHECK_THROWS_AS(SS::silhouette_halfedges(empty, View::perspective(Point_3(0, 0, 1)), std::back_inserter(out)),
                  std::invalid_argument);
  // Eye on the surface (at a vertex) and degenerate faces: the loops stay closed.
  Mesh m = make<Mesh>(noisy_sphere(2, 0.1));
  std::vector<Mesh::Halfedge_index> sil;
  SS::silhouette_halfedges(m, View::perspective(m.point(Mesh::Vertex_index(5))), std::back_inserter(sil));
  check_loops(m, sil, SS::decompose_into_loops(m, sil));
  // Flatten a face: all three vertices collapse to one point (zero-area faces around it).
  auto f0 = *faces(m).begin();
  auto h0 = halfedge(f0, m);
  m.point(target(h0, m)) = m.point(source(h0, m));
  m.point(target(next(h0, m), m)) = m.point(source(h0, m));
  for(const View& view : test_views(4)) {
    sil.clear();
    SS::silhouette_halfedges(m, view, std::back_inserter(sil));
    check_loops(m, sil, SS::decompose_into_loops(m, sil));
  }
}

TEST_CASE("silhouette: pinched (non-manifold) vertex: loops stay closed", "[silhouette][robustness]")
{
  // Two open fans (half-disks, bent out of the plane) sharing their apex: a bow-tie vertex.
  Mesh m;
  std::vector<Mesh::Vertex_index> v;
  const double P[7][3] = {{0, 0, 0}, {1, -1, 0.3}, {1.2, 0, -0.2}, {1, 1, 0.4}, {-1, 1, -0.3}, {-1.2, 0, 0.2}, {-1, -1, 0.5}};
  for(auto& p : P) v.push_back(m.add_vertex(Point_3(p[0], p[1], p[2])));
  m.add_face(v[0], v[1], v[2]);
  m.add_face(v[0], v[2], v[3]);
  m.add_face(v[0], v[4], v[5]);
  m.add_face(v[0], v[5], v[6]);
  REQUIRE(num_faces(m) == 4);
  for(const View& view : test_views(8)) {
    std::vector<Mesh::Halfedge_index> sil;
    SS::silhouette_halfedges(m, view, std::back_inserter(sil));
    check_loops(m, sil, SS::decompose_into_loops(m, sil));
  }
}

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

TEST_CASE("Silhouette_simplifier_3: exact kernel (Epeck), user-given coarse mesh and face map", "[silhouette][kernel]")
{
  typedef CGAL::Exact_predicates_exact_constructions_kernel EK;
  typedef CGAL::Surface_mesh<EK::Point_3> EMesh;
  const auto soup = noisy_sphere(2, 0.1);
  MDCS_test::Triangle_soup<EK::Point_3> esoup;
  for(const auto& p : soup.points) esoup.points.emplace_back(p.x(), p.y(), p.z());
  esoup.triangles = soup.triangles;
  EMesh fine;
  esoup.to_mesh(fine);
  // The mesh is its own coarse mesh (identity face map): every mapped loop must follow the coarse
  // loop exactly when silhouette edges are cheap, so the mapped silhouette equals the fine one.
  std::vector<std::uint32_t> identity(num_faces(fine));
  for(std::uint32_t i = 0; i < identity.size(); ++i) identity[i] = i;
  SS::Silhouette_simplifier_3<EMesh> s(fine, fine, identity);
  const SS::View_3<EK> view = SS::View_3<EK>::perspective(EK::Point_3(3, 1, 2));
  SS::Silhouette_frame frame;
  s.extract(view, frame);
  REQUIRE(frame.fine_silhouette == frame.coarse_silhouette);
  SS::Loop_mapping_options o;
  o.alpha = 1e-3;
  s.map_loops(frame, o);
  std::vector<std::uint32_t> mapped = frame.mapped_halfedges(), fine_sil = frame.fine_silhouette;
  std::sort(mapped.begin(), mapped.end());
  std::sort(fine_sil.begin(), fine_sil.end());
  CHECK(mapped == fine_sil);
}
