// Tests of the prepared surface (Geodesic_surface_3): one compact mesh, built once, shared by every geodesic class
// and every thread, from a FaceGraph or from a triangle soup.
//  - A soup made of a FaceGraph's own points and corners gives the same compact mesh (every array, bit for bit) and
//    therefore the same results in every class and mode (distances, nearest sources, point queries, path
//    sequences in indices), bit for bit: on Surface_mesh and Polyhedron_3, closed and with borders, with vertex
//    and surface-point sources, limits and stop targets.
//  - Objects built on one surface share it (nothing is rebuilt); one object per thread on one surface is in
//    test_parallel_geodesic_surface.cpp.
//  - Bad soups are refused with a message that names the problem: an index out of range or negative, a repeated
//    corner, a polygon that is not a triangle, a NaN or infinite coordinate, null arrays, an edge of too many faces,
//    an index out of range given to a class.
#include <catch2/catch.hpp>

#include <MDCS_test/cgal_meshes.h>
#include <MDCS_test/geodesic_oracles.h>
#include <MDCS_test/geodesic_test_meshes.h>
#include <MDCS_test/mesh_generators.h>
#include <MDCS_test/geodesic_test_geometry.h>

#include <CGAL/Polyhedral_geodesics_3.h>
#include <CGAL/Polyhedral_geodesics_3/Geodesic_surface_3.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace MDCS_test::Epick_surface_mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
namespace PG = CGAL::Polyhedral_geodesics_3;
typedef PG::Triangle_soup Soup;
typedef PG::Geodesic_surface_3<Soup> Soup_surface;

using MDCS_test::same_bits;

// The points and triangles of a FaceGraph in its own numbering (vertex and face index maps), the corners of
// triangle f in the order of Face_location: source(halfedge(f)), target(halfedge(f)), target(next(halfedge(f))).
template <class TM>
void soup_of(const TM& tm, std::vector<std::array<double, 3>>& points, std::vector<std::array<std::uint32_t, 3>>& triangles)
{
  const auto vim = CGAL::get_initialized_vertex_index_map(tm);
  const auto fim = CGAL::get_initialized_face_index_map(tm);
  points.assign(num_vertices(tm), {0, 0, 0});
  for(auto v : vertices(tm)) {
    const auto& p = get(CGAL::vertex_point, tm, v);
    points[get(vim, v)] = {p.x(), p.y(), p.z()};
  }
  triangles.assign(num_faces(tm), {0, 0, 0});
  for(auto f : faces(tm)) {
    auto h = halfedge(f, tm);
    triangles[get(fim, f)] = {std::uint32_t(get(vim, source(h, tm))), std::uint32_t(get(vim, target(h, tm))),
                              std::uint32_t(get(vim, target(next(h, tm), tm)))};
  }
}

template <class V>
bool same_array_bytes(const V& a, const V& b, std::size_t used_bytes = sizeof(typename V::value_type))
{
  if(a.size() != b.size())
    return false;
  const unsigned char* pa = reinterpret_cast<const unsigned char*>(a.data());
  const unsigned char* pb = reinterpret_cast<const unsigned char*>(b.data());
  for(std::size_t i = 0; i < a.size(); ++i)
    if(std::memcmp(pa + i * sizeof(a[0]), pb + i * sizeof(a[0]), used_bytes) != 0)
      return false;
  return true;
}

// Every array of the two compact meshes, bit for bit (the records without their padding).
template <class CM>
void check_same_compact_mesh(const CM& a, const CM& b)
{
  CHECK(a.number_of_vertices == b.number_of_vertices);
  CHECK(a.number_of_faces == b.number_of_faces);
  CHECK(a.number_of_edges == b.number_of_edges);
  REQUIRE(a.he.size() == b.he.size());
  std::size_t differing = 0;
  for(std::size_t h = 0; h < a.he.size(); ++h) {
    const auto &x = a.he[h], &y = b.he[h];
    if(!(same_bits(x.opposite.x, y.opposite.x) && same_bits(x.opposite.y, y.opposite.y) &&
         same_bits(x.length, y.length) && x.source == y.source && x.twin == y.twin && x.edge == y.edge &&
         x.radial == y.radial))
      ++differing;
  }
  CHECK(differing == 0);
  CHECK(same_array_bytes(a.points, b.points));
  CHECK(same_array_bytes(a.edge_halfedge, b.edge_halfedge));
  CHECK(same_array_bytes(a.vertex_halfedge, b.vertex_halfedge));
  CHECK(same_array_bytes(a.vertex_on_boundary, b.vertex_on_boundary));
  CHECK(same_array_bytes(a.vertex_is_singular, b.vertex_is_singular));
  CHECK(same_array_bytes(a.vertex_angle_sum, b.vertex_angle_sum));
  CHECK(same_array_bytes(a.star_begin, b.star_begin));
  CHECK(same_array_bytes(a.star, b.star));
  CHECK(a.number_of_border_edges == b.number_of_border_edges);
  CHECK(a.number_of_pinched_vertices == b.number_of_pinched_vertices);
}

// A path node in indices: kind (0 vertex, 1 edge, 2 face), index (vertex, 3 face + corner, face), ratio or
// barycentric coordinates.
struct Index_node
{
  int kind;
  std::size_t index;
  std::array<double, 3> numbers;
  bool operator==(const Index_node& o) const
  {
    return kind == o.kind && index == o.index && same_bits(numbers[0], o.numbers[0]) &&
           same_bits(numbers[1], o.numbers[1]) && same_bits(numbers[2], o.numbers[2]);
  }
};

template <class TM>
struct Mesh_path_recorder
{
  const TM* tm;
  std::vector<Index_node>* nodes;
  typedef boost::graph_traits<TM> GT;
  void operator()(typename GT::vertex_descriptor v)
  {
    nodes->push_back({0, std::size_t(get(CGAL::get_initialized_vertex_index_map(*tm), v)), {0, 0, 0}});
  }
  void operator()(typename GT::halfedge_descriptor h, double t)
  {
    const auto f = face(h, *tm);
    auto g = halfedge(f, *tm);
    std::size_t k = 0;
    while(g != h) { g = next(g, *tm); ++k; }
    nodes->push_back({1, 3 * std::size_t(get(CGAL::get_initialized_face_index_map(*tm), f)) + k, {t, 0, 0}});
  }
  void operator()(typename GT::face_descriptor f, const std::array<double, 3>& b)
  {
    nodes->push_back({2, std::size_t(get(CGAL::get_initialized_face_index_map(*tm), f)), b});
  }
};

struct Soup_path_recorder
{
  std::vector<Index_node>* nodes;
  void operator()(std::size_t v) { nodes->push_back({0, v, {0, 0, 0}}); }
  void operator()(const PG::Triangle_soup_halfedge& h, double t)
  {
    nodes->push_back({1, 3 * h.face + std::size_t(h.corner), {t, 0, 0}});
  }
  void operator()(std::size_t f, const std::array<double, 3>& b) { nodes->push_back({2, f, b}); }
};

// Runs the same queries on a FaceGraph object and a soup object of one class: every vertex distance and nearest
// source, 5 point queries and 5 path sequences (full field), all bit for bit.
template <class A, class B, class TM>
void check_same_results(A& a, B& b, const TM& tm, bool full_field, const std::string& what)
{
  INFO(what);
  const auto vim = CGAL::get_initialized_vertex_index_map(tm);
  const auto fim = CGAL::get_initialized_face_index_map(tm);
  std::vector<double> da(num_vertices(tm), -1), db(num_vertices(tm), -2);
  a.distances(boost::make_iterator_property_map(da.begin(), vim));
  b.distances(CGAL::make_property_map(db));
  std::size_t differing = 0, finite = 0;
  for(auto v : vertices(tm)) {
    const std::size_t i = get(vim, v);
    if(!same_bits(da[i], db[i]) || a.nearest_source(v).second != b.nearest_source(i).second)
      ++differing;
    if(std::isfinite(da[i]))
      ++finite;
  }
  CHECK(differing == 0);
  CHECK(finite > 0);
  if(!full_field)
    return;
  std::size_t k = 0;
  for(auto f : faces(tm)) {
    if(++k % (num_faces(tm) / 5 + 1) != 0)
      continue;
    const std::array<double, 3> bary = {0.2, 0.5, 0.3};
    const double pa = a.distance(typename A::Face_location(f, bary));
    const double pb = b.distance(typename B::Face_location(std::size_t(get(fim, f)), bary));
    CHECK(same_bits(pa, pb));
    std::vector<Index_node> na, nb;
    Mesh_path_recorder<TM> ra{&tm, &na};
    Soup_path_recorder rb{&nb};
    a.shortest_path_sequence(typename A::Face_location(f, bary), ra);
    b.shortest_path_sequence(typename B::Face_location(std::size_t(get(fim, f)), bary), rb);
    CHECK(na == nb);
    std::vector<Point_3> pa_points;
    std::vector<std::array<double, 3>> pb_points;
    a.shortest_path_points(typename A::Face_location(f, bary), std::back_inserter(pa_points));
    b.shortest_path_points(typename B::Face_location(std::size_t(get(fim, f)), bary), std::back_inserter(pb_points));
    REQUIRE(pa_points.size() == pb_points.size());
    for(std::size_t i = 0; i < pa_points.size(); ++i)
      CHECK((same_bits(pa_points[i].x(), pb_points[i][0]) && same_bits(pa_points[i].y(), pb_points[i][1]) &&
             same_bits(pa_points[i].z(), pb_points[i][2])));
  }
}

// Every class and mode on the FaceGraph and on its soup.
template <class TM>
void check_soup_equals_face_graph(const TM& tm, const std::string& name)
{
  INFO(name);
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  soup_of(tm, points, triangles);
  const auto mesh_surface = std::make_shared<const PG::Geodesic_surface_3<TM>>(tm);
  const auto soup_surface = std::make_shared<const Soup_surface>(points, triangles);
  check_same_compact_mesh(mesh_surface->compact_mesh(), soup_surface->compact_mesh());
  CHECK(soup_surface->has_oriented_manifold_edges());
  CHECK(soup_surface->number_of_border_edges() == mesh_surface->number_of_border_edges());

  const auto vim = CGAL::get_initialized_vertex_index_map(tm);
  const auto fim = CGAL::get_initialized_face_index_map(tm);
  const auto v0 = *std::next(vertices(tm).begin(), std::ptrdiff_t(num_vertices(tm) / 3));
  const auto v1 = *std::next(vertices(tm).begin(), std::ptrdiff_t(2 * num_vertices(tm) / 3));
  const auto f0 = *std::next(faces(tm).begin(), std::ptrdiff_t(num_faces(tm) / 2));
  const std::array<double, 3> inside = {0.25, 0.35, 0.4}, on_edge = {0.0, 0.6, 0.4};
  auto add_sources = [&](auto& a, auto& b) {
    typedef std::decay_t<decltype(a)> A;
    typedef std::decay_t<decltype(b)> B;
    a.add_source(v0);
    b.add_source(std::size_t(get(vim, v0)));
    a.add_source(typename A::Face_location(f0, inside));
    b.add_source(typename B::Face_location(std::size_t(get(fim, f0)), inside));
    a.add_source(typename A::Face_location(*faces(tm).begin(), on_edge));
    b.add_source(typename B::Face_location(std::size_t(get(fim, *faces(tm).begin())), on_edge));
  };
  const auto full = PG::Geodesic_memory_mode::full_field, only = PG::Geodesic_memory_mode::distances_only;
  for(auto mode : {full, only}) {
    const bool ff = mode == full;
    {
      PG::Exact_geodesic_distances_3<TM> a(mesh_surface, mode);
      PG::Exact_geodesic_distances_3<Soup> b(soup_surface, mode);
      add_sources(a, b);
      check_same_results(a, b, tm, ff, "exact");
      CHECK(a.used_vertex_oriented_propagation() == b.used_vertex_oriented_propagation());
      // a limit, then stop targets
      a.set_distance_limit(0.4);
      b.set_distance_limit(0.4);
      check_same_results(a, b, tm, ff, "exact with a limit");
      a.clear_distance_limit();
      b.clear_distance_limit();
      a.set_stop_targets(std::vector<typename boost::graph_traits<TM>::vertex_descriptor>{v1});
      b.set_stop_targets(std::vector<std::size_t>{std::size_t(get(vim, v1))});
      check_same_results(a, b, tm, ff, "exact with a stop target");
    }
    {
      PG::Merged_window_geodesic_distances_3<TM> a(mesh_surface, 0.01, mode);
      PG::Merged_window_geodesic_distances_3<Soup> b(soup_surface, 0.01, mode);
      add_sources(a, b);
      check_same_results(a, b, tm, ff, "merged");
    }
    {
      PG::Flat_exact_geodesic_distances_3<TM> a(mesh_surface, mode);
      PG::Flat_exact_geodesic_distances_3<Soup> b(soup_surface, mode);
      add_sources(a, b);
      check_same_results(a, b, tm, ff, "flat-exact");
    }
    {
      PG::Fast_marching_geodesic_distances_3<TM> a(mesh_surface, mode);
      PG::Fast_marching_geodesic_distances_3<Soup> b(soup_surface, mode);
      add_sources(a, b);
      check_same_results(a, b, tm, ff, "fast marching");
    }
    {
      PG::Dijkstra_geodesic_distances_3<TM> a(mesh_surface, mode);
      PG::Dijkstra_geodesic_distances_3<Soup> b(soup_surface, mode);
      add_sources(a, b);
      check_same_results(a, b, tm, ff, "Dijkstra");
    }
  }
  // The classes' own constructors (a surface of their own) give the results of the shared surface.
  PG::Exact_geodesic_distances_3<TM> own(tm), shared(mesh_surface);
  own.add_source(v0);
  shared.add_source(v0);
  for(auto v : vertices(tm))
    CHECK(same_bits(own.distance(v), shared.distance(v)));
}

} // namespace

TEST_CASE("geodesic surface: a soup of a FaceGraph's own corners gives the same results bit for bit",
          "[geodesics][surface]")
{
  check_soup_equals_face_graph(MDCS_test::mesh_from_soup<Mesh>(MDCS_test::icosphere<Point_3>(2)), "icosphere");
  check_soup_equals_face_graph(MDCS_test::mesh_from_soup<Mesh>(MDCS_test::planar_grid<Point_3>(9, 7)), "planar grid");
  check_soup_equals_face_graph(MDCS_test::mesh_from_soup<Polyhedron>(MDCS_test::icosphere<Point_3>(1)),
                               "icosphere, Polyhedron_3");
  Mesh elephant;
  if(MDCS_test::read_mesh(MDCS_test::cgal_demo_mesh("elephant.off"), elephant))
    check_soup_equals_face_graph(elephant, "elephant");
  Mesh holes;
  if(MDCS_test::read_mesh(MDCS_test::cgal_demo_mesh("elephant-with-holes.off"), holes))
    check_soup_equals_face_graph(holes, "elephant with holes");
}

TEST_CASE("geodesic surface: objects of every class share one surface", "[geodesics][surface]")
{
  const MDCS_test::Triangle_soup<Point_3> soup = MDCS_test::icosphere<Point_3>(2);
  const auto surface = PG::make_geodesic_surface(soup.points, soup.triangles);
  REQUIRE(surface.use_count() == 1);
  {
    PG::Exact_geodesic_distances_3<Soup> exact(surface);
    PG::Merged_window_geodesic_distances_3<Soup> merged(surface, 0.01);
    PG::Flat_exact_geodesic_distances_3<Soup> flat(surface);
    PG::Fast_marching_geodesic_distances_3<Soup> fmm(surface);
    PG::Dijkstra_geodesic_distances_3<Soup> dijkstra(*surface); // by reference: not owned
    CHECK(surface.use_count() == 5);
    CHECK(&exact.surface() == surface.get());
    CHECK(&dijkstra.surface() == surface.get());
    CHECK(&exact.surface().compact_mesh() == &flat.surface().compact_mesh());
    // several sources in a row on one object
    double previous = -1;
    for(std::size_t s = 0; s < 5; ++s) {
      exact.clear_sources();
      exact.add_source(s);
      CHECK(exact.distance(s) == 0);
      CHECK(exact.distance(std::size_t(40)) != previous);
      previous = exact.distance(std::size_t(40));
    }
    for(auto* object : {static_cast<void*>(&merged), static_cast<void*>(&fmm)})
      CHECK(object != nullptr);
  }
  CHECK(surface.use_count() == 1);
  CHECK(surface->memory_bytes() > 0);
  CHECK(surface->number_of_vertices() == soup.points.size());
  CHECK(surface->number_of_faces() == soup.triangles.size());
  CHECK(surface->number_of_edges() == 3 * soup.triangles.size() / 2);
}

namespace {

template <class F>
void check_refused(F make, const std::string& expected)
{
  try {
    make();
    FAIL("accepted, expected: " << expected);
  } catch(const std::invalid_argument& e) {
    INFO(e.what());
    CHECK(std::string(e.what()).find(expected) != std::string::npos);
  }
}

} // namespace

TEST_CASE("geodesic surface: bad soups are refused with a message that names the problem", "[geodesics][surface]")
{
  const std::vector<std::array<double, 3>> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  typedef std::vector<std::array<long, 3>> Triangles;
  check_refused([&] { Soup_surface s(points, Triangles{{0, 1, 2}, {1, 3, 4}}); }, "triangle 1 has corner 2 = 4");
  check_refused([&] { Soup_surface s(points, Triangles{{0, -1, 2}}); }, "triangle 0 has corner 1 = -1");
  check_refused([&] { Soup_surface s(points, Triangles{{0, 1, 2}, {2, 2, 3}}); }, "triangle 1 has a repeated corner");
  check_refused([&] { Soup_surface s(points, std::vector<std::vector<int>>{{0, 1, 2, 3}}); }, "polygon 0 has 4 corners");
  check_refused([&] { Soup_surface s(points, std::vector<std::vector<int>>{{0, 1}}); }, "polygon 0 has 2 corners");
  std::vector<std::array<double, 3>> bad_points = points;
  bad_points[2][1] = std::numeric_limits<double>::quiet_NaN();
  check_refused([&] { Soup_surface s(bad_points, Triangles{{0, 1, 2}}); }, "point 2 has a coordinate that is not finite");
  bad_points[2][1] = std::numeric_limits<double>::infinity();
  check_refused([&] { Soup_surface s(bad_points, Triangles{{0, 1, 2}}); }, "point 2 has a coordinate that is not finite");
  const std::int64_t corners[3] = {0, 1, 2};
  check_refused([&] { Soup_surface s(nullptr, 4, corners, 1); }, "null array");
  // the scale precondition, as for meshes
  const std::vector<std::array<double, 3>> tiny = {{0, 0, 0}, {1e-50, 0, 0}, {0, 1e-50, 0}};
  check_refused([&] { Soup_surface s(tiny, Triangles{{0, 1, 2}}); }, "scale is out of range");
  // 32 triangles on one edge: more than the stored field can tell apart
  std::vector<std::array<double, 3>> fan = {{0, 0, 0}, {0, 0, 1}};
  Triangles sheets;
  for(int i = 0; i < 32; ++i) {
    fan.push_back({std::cos(0.19 * i), std::sin(0.19 * i), 0.5});
    sheets.push_back({0, 1, long(2 + i)});
  }
  check_refused([&] { Soup_surface s(fan, sheets); }, "shared by 32 triangles; at most 31");
  sheets.pop_back();
  Soup_surface thirty_one(fan, sheets);
  CHECK(thirty_one.number_of_nonmanifold_edges() == 1);

  // the arrays constructor, and indices given to a class
  const double xyz[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  const std::uint32_t two[6] = {0, 1, 2, 1, 3, 2};
  const auto square = std::make_shared<const Soup_surface>(xyz, 4, two, 2);
  CHECK(square->number_of_edges() == 5);
  CHECK(square->number_of_border_edges() == 4);
  CHECK(square->triangle_corner(1, 1) == 3);
  PG::Exact_geodesic_distances_3<Soup> exact(square);
  check_refused([&] { exact.add_source(std::size_t(4)); }, "vertex index 4 out of range");
  check_refused([&] { exact.add_source(PG::Exact_geodesic_distances_3<Soup>::Face_location(2, {1, 0, 0})); },
                "triangle index 2 out of range");
  exact.add_source(std::size_t(0));
  CHECK(exact.distance(std::size_t(3)) == Approx(std::sqrt(2.0)).epsilon(1e-15));
  check_refused([&] { exact.distance(std::size_t(9)); }, "vertex index 9 out of range");
  check_refused([&] { exact.set_stop_targets(std::vector<std::size_t>{7}); }, "vertex index 7 out of range");
  // an isolated vertex is unreachable; an empty soup has no faces
  const std::vector<std::array<double, 3>> with_isolated = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}};
  const auto isolated = std::make_shared<const Soup_surface>(with_isolated, Triangles{{0, 1, 2}});
  CHECK(isolated->number_of_isolated_vertices() == 1);
  PG::Dijkstra_geodesic_distances_3<Soup> d(isolated);
  d.add_source(std::size_t(0));
  CHECK(d.distance(std::size_t(3)) == std::numeric_limits<double>::infinity());
  CHECK(d.nearest_source(std::size_t(3)).second == d.no_source);
}
