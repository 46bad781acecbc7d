// Number types and kernels of the exact geodesics: the computation in a high-precision number type agrees with
// the double one (and reaches analytic values far below double precision), and meshes whose points come from the
// exact-constructions kernel (Epeck) work with the default double computation.
//
// High-precision types: CGAL::Gmpfr with 170 bits (about 50 decimal digits) and
// boost::multiprecision::mpfr_float_50 (converted with its own convert_to<double>(), since CGAL 5.5 has no
// Real_embeddable_traits for Boost's floating-point numbers).
#define MDCS_TEST_BOOST_MPFR_FLOAT 1
#include <catch2/catch.hpp>

#include <MDCS_test/geodesic_oracles.h>
#include <MDCS_test/geodesic_test_meshes.h>
#include <MDCS_test/mesh_generators.h>

#include <CGAL/Polyhedral_geodesics_3.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpfr.h>
#include <CGAL/Surface_mesh.h>

#ifdef MDCS_TEST_BOOST_MPFR_FLOAT
#include <boost/multiprecision/mpfr.hpp>
#endif

#include <algorithm>
#include <string>
#include <vector>

namespace {

using namespace MDCS_test::Epick_surface_mesh;
typedef CGAL::Exact_predicates_exact_constructions_kernel EK;
typedef CGAL::Surface_mesh<EK::Point_3> Exact_mesh;
namespace PG = CGAL::Polyhedral_geodesics_3;
typedef PG::Exact_geodesic_distances_3<Mesh> Geodesics;
using MDCS_test::Vec3;

typedef MDCS_test::Named_soup<Point_3> Named_soup;

template <class M, class P>
M make(const MDCS_test::Triangle_soup<P>& soup)
{
  M m;
  soup.to_mesh(m);
  REQUIRE(num_faces(m) == soup.triangles.size());
  return m;
}

// The number type helpers of the test (conversions, square root, absolute value).
double as_double(const CGAL::Gmpfr& x) { return CGAL::to_double(x); }
CGAL::Gmpfr hp_sqrt(const CGAL::Gmpfr& x) { return CGAL::sqrt(x); }
CGAL::Gmpfr hp_abs(const CGAL::Gmpfr& x) { return CGAL::abs(x); }
#ifdef MDCS_TEST_BOOST_MPFR_FLOAT
typedef boost::multiprecision::mpfr_float_50 Mpfr;
double as_double(const Mpfr& x) { return x.convert_to<double>(); }
Mpfr hp_sqrt(const Mpfr& x) { return boost::multiprecision::sqrt(x); }
Mpfr hp_abs(const Mpfr& x) { return boost::multiprecision::abs(x); }
#endif

// Sets CGAL::Gmpfr's default precision for the lifetime of the object.
struct Gmpfr_precision
{
  CGAL::Gmpfr::Precision_type old;
  explicit Gmpfr_precision(CGAL::Gmpfr::Precision_type p) : old(CGAL::Gmpfr::set_default_precision(p)) {}
  ~Gmpfr_precision() { CGAL::Gmpfr::set_default_precision(old); }
};

template <class FT>
void check_agrees_with_double()
{
  typedef PG::Exact_geodesic_distances_3<Mesh, FT> Geodesics_hp;
  const std::vector<Named_soup> meshes = {{"regular tetrahedron", MDCS_test::regular_tetrahedron<Point_3>()},
                                          {"jittered grid 5x5", MDCS_test::jittered_planar_grid<Point_3>(5, 5, 1.0, 1.0, 0.2, 2)},
                                          {"cube 3x3", MDCS_test::subdivided_cube<Point_3>(3)},
                                          {"icosphere 1", MDCS_test::icosphere<Point_3>(1)},
                                          {"bumpy sphere 1", MDCS_test::bumpy_sphere<Point_3>(1, 0.2, 6)}};
  for(const Named_soup& ns : meshes) {
    const Mesh m = make<Mesh>(ns.soup);
    const double floor_value = 1e-12 * MDCS_test::bbox_diagonal(m);
    const auto sources = MDCS_test::spread_vertices(m, 2, 1);
    const auto loc = MDCS_test::random_face_locations(m, 1, 2)[0];
    const auto queries = MDCS_test::random_face_locations(m, 40, 3);
    INFO(ns.name);
    Geodesics gd(m);
    Geodesics_hp gm(m);
    for(auto s : sources) {
      gd.add_source(s);
      gm.add_source(s);
    }
    gd.add_source(Geodesics::Face_location(loc.first, loc.second));
    gm.add_source(typename Geodesics_hp::Face_location(loc.first, {FT(loc.second[0]), FT(loc.second[1]), FT(1) - FT(loc.second[0]) - FT(loc.second[1])}));
    // the distance from each source alone (double), to skip ties when comparing nearest sources
    std::vector<std::vector<double>> single;
    for(std::size_t i = 0; i <= sources.size(); ++i) {
      Geodesics gi(m);
      if(i < sources.size())
        gi.add_source(sources[i]);
      else
        gi.add_source(Geodesics::Face_location(loc.first, loc.second));
      std::vector<double> di;
      for(vertex_descriptor v : vertices(m)) di.push_back(gi.distance(v));
      single.push_back(di);
    }
    std::vector<double> a, b;
    std::size_t other_source = 0, k = 0;
    for(vertex_descriptor v : vertices(m)) {
      a.push_back(gd.distance(v));
      b.push_back(as_double(gm.distance(v)));
      std::vector<double> ds;
      for(const auto& di : single) ds.push_back(di[k]);
      std::sort(ds.begin(), ds.end());
      const bool tie = ds[1] - ds[0] <= 1e-9 * std::max(1.0, ds[0]);
      if(!tie && gm.nearest_source(v).second != gd.nearest_source(v).second) ++other_source;
      ++k;
    }
    const auto cmp = MDCS_test::compare_distances(b, a, floor_value);
    INFO("vertices, double vs high precision: " << cmp);
    CHECK(cmp.ok(1e-12));
    CHECK(other_source == 0);
    std::vector<double> qa, qb;
    for(const auto& q : queries) {
      qa.push_back(gd.distance(Geodesics::Face_location(q.first, q.second)));
      qb.push_back(as_double(gm.distance(typename Geodesics_hp::Face_location(q.first, {FT(q.second[0]), FT(q.second[1]), FT(q.second[2])}))));
    }
    const auto cmp_q = MDCS_test::compare_distances(qb, qa, floor_value);
    INFO("face locations, double vs high precision: " << cmp_q);
    CHECK(cmp_q.ok(1e-12));
    // a path in high precision
    std::vector<Point_3> path;
    const vertex_descriptor target = sources[0] == *vertices(m).begin() ? *(++vertices(m).begin()) : *vertices(m).begin();
    gm.shortest_path_points(target, std::back_inserter(path));
    CHECK(path.size() >= 2);
    CHECK(MDCS_test::relative_difference(MDCS_test::path_length(path), as_double(gm.distance(target)), floor_value) <= 1e-9);
    // made locally shortest in high precision (set_path_shortening): already a geodesic, its length stays
    gm.set_path_shortening(true);
    std::vector<Point_3> shortened;
    gm.shortest_path_points(target, std::back_inserter(shortened));
    CHECK(shortened.size() >= 2);
    CHECK(MDCS_test::relative_difference(MDCS_test::path_length(shortened), as_double(gm.distance(target)), floor_value) <= 1e-9);
    CHECK(gm.statistics().windows_created > 0);
  }
}

template <class FT>
void check_analytic_high_precision(double digits_tolerance)
{
  typedef PG::Exact_geodesic_distances_3<Mesh, FT> Geodesics_hp;
  const FT tol(digits_tolerance);
  {
    // tetrahedron: centroid of the opposite face at 2/sqrt(3). The points of the generator are rounded to double,
    // so the tetrahedron is regular only up to ~1e-16: compare to 1e-14.
    const Mesh m = make<Mesh>(MDCS_test::regular_tetrahedron<Point_3>());
    Geodesics_hp g(m);
    const vertex_descriptor s = *vertices(m).begin();
    g.add_source(s);
    for(auto f : faces(m)) {
      const auto vs = MDCS_test::face_vertices(m, f);
      if(vs[0] == s || vs[1] == s || vs[2] == s) continue;
      const FT third = FT(1) / FT(3);
      const FT d = g.distance(typename Geodesics_hp::Face_location(f, {third, third, FT(1) - FT(2) * third}));
      CHECK(as_double(hp_abs(d - FT(2) / hp_sqrt(FT(3)))) <= 1e-14);
    }
  }
  {
    // cube with vertices at multiples of 1/4 (exact in binary): corner to corner is sqrt(5) exactly, to the
    // centre of a far face sqrt(5/2), in exact arithmetic; the high-precision type must get them to ~1e-40
    const Mesh m = make<Mesh>(MDCS_test::subdivided_cube<Point_3>(4));
    Geodesics_hp g(m);
    g.add_source(MDCS_test::nearest_vertex(m, Vec3{0, 0, 0}));
    const FT e1 = hp_abs(g.distance(MDCS_test::nearest_vertex(m, Vec3{1, 1, 1})) - hp_sqrt(FT(5)));
    const FT e2 = hp_abs(g.distance(MDCS_test::nearest_vertex(m, Vec3{0.5, 0.5, 1})) - hp_sqrt(FT(5) / FT(2)));
    const FT e3 = hp_abs(g.distance(MDCS_test::nearest_vertex(m, Vec3{1, 0.75, 0.25})) - hp_sqrt(FT(1.25 * 1.25 + 0.75 * 0.75)));
    INFO("errors: " << as_double(e1) << " " << as_double(e2) << " " << as_double(e3));
    CHECK(e1 < tol);
    CHECK(e2 < tol);
    CHECK(e3 < tol);
    // every vertex against the analytic formula evaluated in the same number type
    std::size_t wrong = 0;
    double worst = 0;
    for(vertex_descriptor v : vertices(m)) {
      const Vec3 p = MDCS_test::vertex_vec3(m, v);
      FT best(-1);
      bool near_face = false;
      for(int k = 0; k < 3; ++k)
        if(p[std::size_t(k)] == 0) near_face = true;
      if(near_face)
        best = hp_sqrt(FT(p[0]) * FT(p[0]) + FT(p[1]) * FT(p[1]) + FT(p[2]) * FT(p[2]));
      else
        for(int k = 0; k < 3; ++k) {
          if(p[std::size_t(k)] != 1) continue;
          const FT a(p[std::size_t((k + 1) % 3)]), b(p[std::size_t((k + 2) % 3)]);
          const FT c1 = hp_sqrt((FT(1) + a) * (FT(1) + a) + b * b), c2 = hp_sqrt((FT(1) + b) * (FT(1) + b) + a * a);
          const FT c = c1 < c2 ? c1 : c2;
          if(best < FT(0) || c < best) best = c;
        }
      const FT err = hp_abs(g.distance(v) - best);
      worst = std::max(worst, as_double(err));
      if(!(err < tol)) ++wrong;
    }
    INFO("largest error at a vertex " << worst);
    CHECK(wrong == 0);
  }
}

} // namespace

TEST_CASE("exact geodesics: CGAL::Gmpfr (170 bits) agrees with double", "[geodesics][exact][number_types]")
{
  Gmpfr_precision precision(170);
  check_agrees_with_double<CGAL::Gmpfr>();
}

TEST_CASE("exact geodesics: CGAL::Gmpfr (170 bits) reaches analytic values beyond double precision",
          "[geodesics][exact][number_types][analytic]")
{
  Gmpfr_precision precision(170);
  check_analytic_high_precision<CGAL::Gmpfr>(1e-40);
}

#ifdef MDCS_TEST_BOOST_MPFR_FLOAT
TEST_CASE("exact geodesics: mpfr_float_50 agrees with double", "[geodesics][exact][number_types]")
{
  check_agrees_with_double<Mpfr>();
}

TEST_CASE("exact geodesics: mpfr_float_50 reaches analytic values beyond double precision",
          "[geodesics][exact][number_types][analytic]")
{
  check_analytic_high_precision<Mpfr>(1e-40);
}
#endif

TEST_CASE("exact geodesics: a mesh with Epeck points", "[geodesics][exact][number_types]")
{
  for(const Named_soup& ns : {Named_soup{"bumpy sphere 2", MDCS_test::bumpy_sphere<Point_3>(2, 0.2, 4)},
                              Named_soup{"terrain 8x8", MDCS_test::height_field_grid<Point_3>(8, 0.3, 2)}}) {
    INFO(ns.name);
    MDCS_test::Triangle_soup<EK::Point_3> esoup;
    for(const auto& p : ns.soup.points) esoup.points.emplace_back(p.x(), p.y(), p.z());
    esoup.triangles = ns.soup.triangles;
    const Mesh m = make<Mesh>(ns.soup);
    const Exact_mesh em = make<Exact_mesh>(esoup);
    const auto sources = MDCS_test::spread_vertices(m, 2, 7);
    Geodesics g(m);
    PG::Exact_geodesic_distances_3<Exact_mesh> ge(em);
    for(auto s : sources) {
      g.add_source(s);
      ge.add_source(boost::graph_traits<Exact_mesh>::vertex_descriptor(static_cast<Exact_mesh::size_type>(std::size_t(s))));
    }
    std::size_t differ = 0;
    for(vertex_descriptor v : vertices(m)) {
      const auto ev = boost::graph_traits<Exact_mesh>::vertex_descriptor(static_cast<Exact_mesh::size_type>(std::size_t(v)));
      if(!(MDCS_test::relative_difference(ge.distance(ev), g.distance(v), 1e-14) <= 1e-14)) ++differ;
    }
    CHECK(differ == 0);
    const auto f = *faces(em).begin();
    const auto fm = *faces(m).begin();
    CHECK(MDCS_test::relative_difference(ge.distance(PG::Exact_geodesic_distances_3<Exact_mesh>::Face_location(f, {0.2, 0.3, 0.5})),
                                         g.distance(Geodesics::Face_location(fm, {0.2, 0.3, 0.5})), 1e-14) <= 1e-14);
    std::vector<EK::Point_3> path;
    ge.shortest_path_points(*(--vertices(em).end()), std::back_inserter(path));
    CHECK(path.size() >= 2);
    CHECK(MDCS_test::relative_difference(MDCS_test::path_length(path), ge.distance(*(--vertices(em).end())), 1e-12) <= 1e-9);
  }
}
