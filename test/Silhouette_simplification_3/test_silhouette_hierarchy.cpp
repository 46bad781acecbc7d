// Hierarchical silhouette extraction (Silhouette_edge_hierarchy_3): the same halfedges as the scan of every
// face, in the same order, for hundreds of views per mesh (near, far, inside the bounding box, on face planes,
// at vertices, orthographic along edges), on closed, open, flat, degenerate and real meshes; fewer edges tested
// than the mesh has; bad input.
#include <catch2/catch.hpp>

#include "silhouette_test_meshes.h"

#include <MDCS_test/cgal_meshes.h>

#include <CGAL/Silhouette_simplification_3/Silhouette_edge_hierarchy_3.h>
#include <CGAL/Silhouette_simplification_3/silhouette_edges.h>
#include <CGAL/Silhouette_simplification_3/Silhouette_simplifier_3.h>

using namespace silhouette_test;
namespace SSH = CGAL::Silhouette_simplification_3;
typedef SSH::View_3<K> Hierarchy_view;

namespace {

// Views that stress the node test: kind i % 8 of view i.
std::vector<Hierarchy_view> hierarchy_test_views(const Mesh& m, std::size_t n, std::uint64_t seed)
{
  CGAL::Bbox_3 box;
  for(auto v : vertices(m)) box += m.point(v).bbox();
  const Point_3 c((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2, (box.zmin() + box.zmax()) / 2);
  const Vector_3 half((box.xmax() - box.xmin()) / 2, (box.ymax() - box.ymin()) / 2, (box.zmax() - box.zmin()) / 2);
  const double radius = std::sqrt(half.squared_length());
  auto rnd = [&](std::uint64_t i) { return hash01(seed * 7919 + i); };
  auto direction = [&](std::uint64_t i) {
    const double a = 6.283185307179586 * rnd(2 * i), z = 2 * rnd(2 * i + 1) - 1, s = std::sqrt(1 - z * z);
    return Vector_3(s * std::cos(a), s * std::sin(a), z);
  };
  std::vector<Mesh::Face_index> fs(faces(m).begin(), faces(m).end());
  std::vector<Mesh::Vertex_index> vs(vertices(m).begin(), vertices(m).end());
  auto corners = [&](std::uint64_t i, Point_3& p, Point_3& q, Point_3& r) {
    const auto h = halfedge(fs[std::size_t(rnd(i) * double(fs.size()))], m);
    p = m.point(source(h, m));
    q = m.point(target(h, m));
    r = m.point(target(next(h, m), m));
  };
  std::vector<Hierarchy_view> views;
  for(std::uint64_t i = 0; i < n; ++i) {
    const std::uint64_t r = 1000 * i;
    Point_3 p, q, s;
    switch(i % 8) {
    case 0: views.push_back(Hierarchy_view::perspective(c + (1.05 + 2 * rnd(r)) * radius * direction(r + 1))); break;
    case 1: views.push_back(Hierarchy_view::perspective(c + (rnd(r) < 0.5 ? 1e3 : 1e6) * radius * direction(r + 1))); break;
    case 2:
      views.push_back(Hierarchy_view::perspective(c + Vector_3((2 * rnd(r) - 1) * half.x(), (2 * rnd(r + 1) - 1) * half.y(),
                                                               (2 * rnd(r + 2) - 1) * half.z())));
      break;
    case 3: // on (or within rounding of) the plane of a face, often outside the face
      corners(r, p, q, s);
      views.push_back(Hierarchy_view::perspective(p + (6 * rnd(r + 1) - 3) * (q - p) + (6 * rnd(r + 2) - 3) * (s - p)));
      break;
    case 4: views.push_back(Hierarchy_view::perspective(m.point(vs[std::size_t(rnd(r) * double(vs.size()))]))); break;
    case 5: views.push_back(Hierarchy_view::orthographic(direction(r))); break;
    case 6: // along an edge: exactly in the planes of both faces of that edge
      corners(r, p, q, s);
      views.push_back(Hierarchy_view::orthographic(q - p));
      break;
    default: // in the plane of a face
      corners(r, p, q, s);
      views.push_back(Hierarchy_view::orthographic((2 * rnd(r + 1) - 1) * (q - p) + (2 * rnd(r + 2) - 1) * (s - p)));
    }
  }
  return views;
}

// Checks the hierarchy against the scan for every view; returns the mean fraction of edges tested.
double check_hierarchy_against_scan(const Mesh& m, std::size_t n_views, std::uint64_t seed,
                                    const SSH::Silhouette_hierarchy_options& options = SSH::Silhouette_hierarchy_options())
{
  const SSH::Silhouette_edge_hierarchy_3<Mesh> hierarchy(m, options);
  const auto& im = hierarchy.index_mesh();
  std::vector<char> front;
  std::vector<std::uint32_t> scan, fast;
  double tested = 0;
  std::size_t i = 0;
  for(const Hierarchy_view& view : hierarchy_test_views(m, n_views, seed)) {
    // The scan: every face classified, then the boundary of the front region.
    SSH::internal::classify_faces(im, view, front);
    SSH::internal::silhouette_from_faces(im, front, scan);
    SSH::Silhouette_hierarchy_statistics stats;
    hierarchy.silhouette_indices(view, fast, &stats);
    INFO("view " << i << (view.is_perspective() ? " perspective" : " orthographic"));
    REQUIRE(fast == scan);
    tested += double(stats.edges_tested) / double(num_edges(m));
    if(i % 16 == 0) { // the descriptors, against the free function (which copies the mesh again)
      std::vector<Mesh::Halfedge_index> expected, got;
      SSH::silhouette_halfedges(m, view, std::back_inserter(expected));
      hierarchy.silhouette_halfedges(view, std::back_inserter(got));
      REQUIRE(got == expected);
    }
    ++i;
  }
  return tested / double(n_views);
}

} // namespace

TEST_CASE("Silhouette_edge_hierarchy_3: same halfedges as the scan on closed meshes, fewer edges tested",
          "[silhouette][hierarchy]")
{
  const Mesh sphere = make<Mesh>(noisy_sphere(4, 0.0));
  const double sphere_tested = check_hierarchy_against_scan(sphere, 400, 1);
  const Mesh bumpy = make<Mesh>(noisy_sphere(4, 0.08, 3));
  const double bumpy_tested = check_hierarchy_against_scan(bumpy, 400, 2);
  const Mesh ring = make<Mesh>(torus(60, 24, 1, 0.4, 0.05));
  const double ring_tested = check_hierarchy_against_scan(ring, 400, 3);
  // The tree must skip most edges of these smooth meshes (the views include eyes inside the box and on the
  // surface, where little can be skipped).
  CHECK(sphere_tested < 0.15);
  CHECK(bumpy_tested < 0.85); // radial noise of 8% at 5,120 faces: normals vary a lot between neighbours
  CHECK(ring_tested < 0.5);
  // Other splits and leaf sizes: still the scan's result.
  SSH::Silhouette_hierarchy_options options;
  options.leaf_edges = 1;
  options.position_weight = 0;
  check_hierarchy_against_scan(bumpy, 80, 4, options);
  options.leaf_edges = 64;
  options.position_weight = 10;
  check_hierarchy_against_scan(bumpy, 80, 5, options);
}

TEST_CASE("Silhouette_edge_hierarchy_3: open, flat and degenerate meshes", "[silhouette][hierarchy][degenerate]")
{
  // A bumpy grid (one border loop) and a flat grid (every face in one plane: views in that plane).
  check_hierarchy_against_scan(make<Mesh>(bumpy_grid(30)), 400, 6);
  check_hierarchy_against_scan(make<Mesh>(MDCS_test::planar_grid<Point_3>(20, 20)), 200, 7);
  // Zero-area faces (three vertices collapsed to one point), a sliver (a vertex moved onto its opposite edge's
  // line up to rounding) and a needle: these faces stay out of the tree.
  Mesh m = make<Mesh>(noisy_sphere(4, 0.05, 9));
  auto it = faces(m).begin();
  const auto h0 = halfedge(*it, m);
  m.point(target(h0, m)) = m.point(source(h0, m));
  m.point(target(next(h0, m), m)) = m.point(source(h0, m));
  std::advance(it, 2000);
  const auto h1 = halfedge(*it, m);
  const Point_3 a = m.point(source(h1, m)), b = m.point(target(h1, m));
  m.point(target(next(h1, m), m)) = a + 0.37 * (b - a);
  const SSH::Silhouette_edge_hierarchy_3<Mesh> hierarchy(m);
  CHECK(hierarchy.number_of_edges_outside_the_tree() >= 6);
  check_hierarchy_against_scan(m, 400, 8);
}

TEST_CASE("Silhouette_edge_hierarchy_3: a real mesh and Polyhedron_3", "[silhouette][hierarchy]")
{
  Mesh elephant;
  if(MDCS_test::read_mesh(MDCS_test::cgal_demo_mesh("elephant.off"), elephant))
    CHECK(check_hierarchy_against_scan(elephant, 400, 10) < 0.6);
  else
    WARN("CGAL demo mesh elephant.off not found (MDCS_CGAL_MESH_DIR): the elephant is skipped");
  // Another face graph: the same halfedges as the free function on it.
  const Polyhedron poly = make<Polyhedron>(noisy_sphere(3, 0.1, 11));
  const SSH::Silhouette_edge_hierarchy_3<Polyhedron> hierarchy(poly);
  for(const Hierarchy_view& view : hierarchy_test_views(make<Mesh>(noisy_sphere(3, 0.1, 11)), 24, 12)) {
    std::vector<boost::graph_traits<Polyhedron>::halfedge_descriptor> expected, got;
    SSH::silhouette_halfedges(poly, view, std::back_inserter(expected));
    hierarchy.silhouette_halfedges(view, std::back_inserter(got));
    REQUIRE(got == expected);
  }
}

TEST_CASE("Silhouette_simplifier_3 with a silhouette hierarchy: the same frames", "[silhouette][hierarchy]")
{
  // The mesh as its own coarse mesh (identity face map): extraction, loops, picking and mapping must not change.
  const Mesh m = make<Mesh>(noisy_sphere(3, 0.1, 13));
  std::vector<std::uint32_t> identity(num_faces(m));
  for(std::uint32_t i = 0; i < identity.size(); ++i) identity[i] = i;
  SSH::Silhouette_simplifier_3<Mesh> plain(m, m, identity), fast(m, m, identity);
  fast.build_silhouette_hierarchy();
  REQUIRE(fast.uses_silhouette_hierarchy());
  REQUIRE(!plain.uses_silhouette_hierarchy());
  for(const Hierarchy_view& view : hierarchy_test_views(m, 16, 14)) {
    SSH::Silhouette_frame a, b;
    plain.extract(view, a);
    fast.extract(view, b);
    REQUIRE(b.fine_front.empty());
    REQUIRE(a.fine_silhouette == b.fine_silhouette);
    REQUIRE(a.fine_loops.size() == b.fine_loops.size());
    plain.pick_loops(a);
    fast.pick_loops(b);
    REQUIRE(a.picked_halfedges() == b.picked_halfedges());
    plain.map_loops(a);
    fast.map_loops(b);
    REQUIRE(a.mapped_halfedges() == b.mapped_halfedges());
  }
}

TEST_CASE("Silhouette_edge_hierarchy_3: bad input", "[silhouette][hierarchy][robustness]")
{
  Mesh empty;
  CHECK_THROWS_AS(SSH::Silhouette_edge_hierarchy_3<Mesh>(empty), std::invalid_argument);
  Mesh quad;
  auto a = quad.add_vertex(Point_3(0, 0, 0)), b = quad.add_vertex(Point_3(1, 0, 0)), c = quad.add_vertex(Point_3(1, 1, 0)),
       d = quad.add_vertex(Point_3(0, 1, 0));
  quad.add_face(a, b, c, d);
  CHECK_THROWS_AS(SSH::Silhouette_edge_hierarchy_3<Mesh>(quad), std::invalid_argument);
  const Mesh m = make<Mesh>(noisy_sphere(1, 0.1));
  SSH::Silhouette_hierarchy_options options;
  options.leaf_edges = 0;
  CHECK_THROWS_AS(SSH::Silhouette_edge_hierarchy_3<Mesh>(m, options), std::invalid_argument);
  options.leaf_edges = 128; // local face indices of a leaf are bytes
  CHECK_THROWS_AS(SSH::Silhouette_edge_hierarchy_3<Mesh>(m, options), std::invalid_argument);
  options.leaf_edges = 8;
  options.position_weight = -1;
  CHECK_THROWS_AS(SSH::Silhouette_edge_hierarchy_3<Mesh>(m, options), std::invalid_argument);
  options.position_weight = std::nan("");
  CHECK_THROWS_AS(SSH::Silhouette_edge_hierarchy_3<Mesh>(m, options), std::invalid_argument);
}
