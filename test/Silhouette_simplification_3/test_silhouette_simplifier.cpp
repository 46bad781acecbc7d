// Coarse mesh and face map, loop picking (method A), loop mapping by min cut (method B), Surface_mesh
// versus Polyhedron_3, temporal coherence.
#include <catch2/catch.hpp>

#include "silhouette_test_meshes.h"

#include <CGAL/Silhouette_simplification_3.h>
#include <CGAL/Min_cut/Boykov_kolmogorov_max_flow.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/transform.h>

#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>

using namespace silhouette_test;
namespace SS = CGAL::Silhouette_simplification_3;
typedef SS::View_3<K> View;
typedef SS::Silhouette_simplifier_3<Mesh> Simplifier;

namespace {

View orbit_view(double angle, double elevation = 0.3, double radius = 4)
{
  return View::perspective(Point_3(radius * std::cos(angle) * std::cos(elevation), radius * std::sin(angle) * std::cos(elevation),
                                   radius * std::sin(elevation)));
}

struct Fixture
{
  Mesh fine;
  SS::Coarse_mesh_3<Point_3> coarse;
  std::unique_ptr<Simplifier> simplifier;
  explicit Fixture(const MDCS_test::Triangle_soup<Point_3>& soup, std::size_t target = 300)
  {
    fine = make<Mesh>(soup);
    SS::Coarse_mesh_options o;
    o.target_faces = target;
    coarse = SS::build_coarse_mesh(fine, o);
    simplifier.reset(new Simplifier(fine, coarse.mesh, coarse.coarse_face_of_fine_face));
  }
};

// Total weight of halfedges under the factors used by map_loops.
double weight(const Simplifier& s, const SS::Silhouette_frame& frame, const std::vector<std::uint32_t>& hs, double alpha)
{
  std::set<std::uint32_t> sil;
  for(std::uint32_t h : frame.fine_silhouette) sil.insert(s.fine().edge(h));
  double w = 0;
  for(std::uint32_t h : hs) w += s.edge_length(s.fine().edge(h)) * (sil.count(s.fine().edge(h)) ? alpha : 1.0);
  return w;
}

} // namespace

TEST_CASE("build_coarse_mesh: face count, closedness, and a face map that covers every fine face", "[silhouette][coarse]")
{
  const Mesh fine = make<Mesh>(noisy_sphere(4, 0.05));
  for(unsigned smoothing : {0u, 3u}) {
    SS::Coarse_mesh_options o;
    o.target_faces = 400;
    o.smoothing_iterations = smoothing;
    const auto coarse = SS::build_coarse_mesh(fine, o);
    const std::size_t nc = num_faces(coarse.mesh);
    CHECK(nc >= 380);
    CHECK(nc <= 420);
    CHECK(CGAL::is_closed(coarse.mesh));
    CHECK(CGAL::is_triangle_mesh(coarse.mesh));
    REQUIRE(coarse.coarse_face_of_fine_face.size() == num_faces(fine));
    std::vector<int> hits(nc, 0);
    for(std::uint32_t c : coarse.coarse_face_of_fine_face) {
      REQUIRE(c < nc);
      ++hits[c];
    }
    for(int h : hits) CHECK(h >= 1); // every coarse face is the image of its own fine face at least
    if(smoothing == 0) {
      // Half-edge collapses keep endpoints: every coarse vertex is a fine vertex.
      std::set<Point_3> fine_points;
      for(auto v : vertices(fine)) fine_points.insert(fine.point(v));
      for(auto v : vertices(coarse.mesh)) CHECK(fine_points.count(coarse.mesh.point(v)) == 1);
    }
  }
  SS::Coarse_mesh_options bad;
  bad.target_faces = 2;
  CHECK_THROWS_AS(SS::build_coarse_mesh(fine, bad), std::invalid_argument);
}

TEST_CASE("build_coarse_mesh: the fine region of most coarse faces is connected", "[silhouette][coarse]")
{
  Fixture fx(noisy_sphere(4, 0.05), 300);
  const auto& s = *fx.simplifier;
  std::size_t connected = 0, n = s.coarse().faces.size();
  std::vector<int> mark(s.fine().faces.size(), -1);
  for(std::uint32_t c = 0; c < n; ++c) {
    const auto b = s.fine_faces_of_coarse_begin()[c], e = s.fine_faces_of_coarse_begin()[c + 1];
    std::vector<std::uint32_t> stack = {s.fine_faces_of_coarse()[b]};
    mark[stack[0]] = int(c);
    std::size_t reached = 1;
    while(!stack.empty()) {
      const std::uint32_t f = stack.back();
      stack.pop_back();
      for(std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t g = s.fine().face(s.fine().opposite[3 * f + k]);
        if(g != SS::internal::NONE && s.face_map()[g] == c && mark[g] != int(c)) { mark[g] = int(c); ++reached; stack.push_back(g); }
      }
    }
    if(reached == e - b) ++connected;
  }
  CHECK(double(connected) >= 0.9 * double(n));
}

TEST_CASE("loop mapping: closed loops of real fine edges; cut value = loop weight; the loops separate the band boundaries",
          "[silhouette][mapping]")
{
  Fixture fx(noisy_sphere(4, 0.06), 300);
  Simplifier& s = *fx.simplifier;
  const double alpha = 0.1;
  std::size_t mapped_loops = 0;
  for(int i = 0; i < 6; ++i) {
    SS::Silhouette_frame frame;
    s.extract(orbit_view(1.1 * i, 0.2 * i - 0.5), frame);
    REQUIRE(!frame.coarse_loops.empty());
    const std::vector<SS::Silhouette_frame::Loop> coarse_loops = frame.coarse_loops;
    for(const auto& cl : coarse_loops) {
      // Map one coarse loop at a time, so that the mapper's last network is this loop's.
      frame.coarse_loops = {cl};
      s.map_loops(frame);
      REQUIRE(frame.mapping_reports.size() == 1);
      const auto& rep = frame.mapping_reports[0];
      if(rep.source_arcs == 0 || rep.sink_arcs == 0) continue;
      ++mapped_loops;
      const auto hs = frame.mapped_halfedges();
      REQUIRE(!hs.empty());
      for(const auto& loop : frame.mapped) {
        REQUIRE(loop.closed);
        for(std::size_t k = 0; k < loop.halfedges.size(); ++k) {
          const std::uint32_t h = loop.halfedges[k], g = loop.halfedges[(k + 1) % loop.halfedges.size()];
          REQUIRE(h < s.fine().number_of_halfedges());   // a real fine edge
          REQUIRE(s.fine().target(h) == s.fine().source[g]);
        }
      }
      CHECK(weight(s, frame, hs, alpha) == Approx(rep.cut_value).epsilon(1e-9));
      // Separation: from the uncut source arcs, crossing only uncut dual edges, no uncut sink arc is reached.
      const auto& net = s.mapper().network();
      const auto& band = s.mapper().fine_band();
      std::set<std::uint32_t> cut_edges;
      for(std::uint32_t h : s.mapper().chain()) cut_edges.insert(s.fine().edge(h));
      std::vector<std::vector<std::uint32_t>> adj(net.number_of_nodes());
      for(const auto& f : net.facets())
        if(!cut_edges.count(s.fine().edge(f.id))) { adj[f.u].push_back(f.v); adj[f.v].push_back(f.u); }
      std::vector<char> reached(net.number_of_nodes(), 0);
      std::vector<std::uint32_t> stack;
      for(const auto& t : net.source_facets())
        if(!cut_edges.count(s.fine().edge(t.id)) && !reached[t.node]) { reached[t.node] = 1; stack.push_back(t.node); }
      while(!stack.empty()) {
        const std::uint32_t u = stack.back();
        stack.pop_back();
        for(std::uint32_t v : adj[u]) if(!reached[v]) { reached[v] = 1; stack.push_back(v); }
      }
      for(const auto& t : net.sink_facets())
        if(!cut_edges.count(s.fine().edge(t.id))) REQUIRE(!reached[t.node]);
      CHECK(band.size() == rep.band_fine_faces);
      // An independent max-flow engine finds the same value.
      const auto bk = CGAL::Min_cut::solve_min_cut(net, CGAL::Min_cut::Boykov_kolmogorov_max_flow());
      CHECK(bk.value == Approx(rep.cut_value).epsilon(1e-9));
    }
  }
  CHECK(mapped_loops >= 6);
}

TEST_CASE("loop picking: picked loops are fine silhouette loops and the error decreases", "[silhouette][picking]")
{
  Fixture fx(noisy_sphere(4, 0.06), 300);
  Simplifier& s = *fx.simplifier;
  for(int i = 0; i < 4; ++i) {
    SS::Silhouette_frame frame;
    s.extract(orbit_view(0.7 * i), frame);
    SS::Loop_picking_options o;
    o.min_loop_edges = 3;
    s.pick_loops(frame, o);
    REQUIRE(!frame.picked.empty());
    std::set<std::uint32_t> sil(frame.fine_silhouette.begin(), frame.fine_silhouette.end());
    for(std::uint32_t h : frame.picked_halfedges()) REQUIRE(sil.count(h) == 1);
    std::set<std::uint32_t> distinct(frame.picked.begin(), frame.picked.end());
    CHECK(distinct.size() == frame.picked.size());
    // Oracle for the error: recompute the sum of squared distances by brute force.
    double error = 0;
    std::size_t ncoarse = 0;
    for(const auto& cl : frame.coarse_loops)
      for(std::uint32_t h : cl.halfedges) {
        const Point_3& c = s.coarse().points[s.coarse().source[h]];
        double best = s.diagonal() * s.diagonal();
        for(std::uint32_t l : frame.picked)
          for(std::uint32_t g : frame.fine_loops[l].halfedges)
            best = std::min(best, CGAL::squared_distance(c, s.fine().points[s.fine().source[g]]));
        error += best;
        ++ncoarse;
      }
    CHECK(frame.picking_error == Approx(error).epsilon(1e-5));
    // Picking more (no stopping rule) never increases the error.
    SS::Silhouette_frame all = frame;
    o.threshold = 0;
    o.min_relative_gain = 0;
    s.pick_loops(all, o);
    CHECK(all.picked.size() >= frame.picked.size());
    CHECK(all.picking_error <= frame.picking_error * (1 + 1e-6));
  }
}

TEST_CASE("Silhouette_simplifier_3: identical results on Surface_mesh and Polyhedron_3", "[silhouette][generic]")
{
  const auto soup = torus(48, 20, 1, 0.4, 0.08);
  const Mesh sm = make<Mesh>(soup);
  const Polyhedron poly = make<Polyhedron>(soup);
  SS::Coarse_mesh_options o;
  o.target_faces = 250;
  const auto c1 = SS::build_coarse_mesh(sm, o);
  const auto c2 = SS::build_coarse_mesh(poly, o);
  REQUIRE(c1.coarse_face_of_fine_face == c2.coarse_face_of_fine_face);
  REQUIRE(num_faces(c1.mesh) == num_faces(c2.mesh));
  Simplifier s1(sm, c1.mesh, c1.coarse_face_of_fine_face);
  SS::Silhouette_simplifier_3<Polyhedron> s2(poly, c2.mesh, c2.coarse_face_of_fine_face);
  for(int i = 0; i < 3; ++i) {
    SS::Silhouette_frame f1, f2;
    s1.extract(orbit_view(0.9 * i, 0.6), f1);
    s2.extract(orbit_view(0.9 * i, 0.6), f2);
    s1.pick_loops(f1);
    s2.pick_loops(f2);
    s1.map_loops(f1);
    s2.map_loops(f2);
    CHECK(f1.fine_silhouette == f2.fine_silhouette);
    CHECK(f1.coarse_silhouette == f2.coarse_silhouette);
    CHECK(f1.picked == f2.picked);
    CHECK(f1.mapped_halfedges() == f2.mapped_halfedges());
    // The descriptors map back to the same geometric edges.
    for(std::uint32_t h : f1.mapped_halfedges()) {
      CHECK(sm.point(source(s1.fine_halfedge(h), sm)) == s2.fine_halfedge(h)->opposite()->vertex()->point());
    }
  }
}

TEST_CASE("Silhouette_simplifier_3: bad input", "[silhouette][robustness]")
{
  const Mesh fine = make<Mesh>(noisy_sphere(2, 0.05));
  const Mesh coarse = make<Mesh>(noisy_sphere(1, 0.05));
  std::vector<std::uint32_t> map(num_faces(fine), 0);
  CHECK_NOTHROW(Simplifier(fine, coarse, map));
  map.pop_back();
  CHECK_THROWS_AS(Simplifier(fine, coarse, map), std::invalid_argument);
  map.assign(num_faces(fine), std::uint32_t(num_faces(coarse)));
  CHECK_THROWS_AS(Simplifier(fine, coarse, map), std::invalid_argument);
  map.assign(num_faces(fine), 0);
  Simplifier s(fine, coarse, map);
  SS::Silhouette_frame frame;
  s.extract(orbit_view(0.3), frame);
  SS::Loop_mapping_options mo;
  mo.alpha = 0;
  CHECK_THROWS_AS(s.map_loops(frame, mo), std::invalid_argument);
  SS::Loop_picking_options po;
  po.threshold = -1;
  CHECK_THROWS_AS(s.pick_loops(frame, po), std::invalid_argument);
  // Open fine mesh: the coarse mesh and the mapping still work and give closed loops.
  Fixture open(bumpy_grid(40), 200);
  SS::Silhouette_frame f;
  open.simplifier->extract(View::perspective(Point_3(0.5, -2, 1.0)), f);
  open.simplifier->map_loops(f);
  for(const auto& l : f.mapped) CHECK(l.closed);
}

TEST_CASE("temporal coherence: metric and the previous-frame bias", "[silhouette][coherence]")
{
  CHECK(SS::relative_edge_set_change({1, 2, 3}, {1, 2, 3}) == 0);
  CHECK(SS::relative_edge_set_change({1, 2}, {3, 4}) == 1);
  CHECK(SS::relative_edge_set_change({1, 2, 3}, {2, 3, 4}) == Approx(2.0 / 6.0));
  Fixture fx(noisy_sphere(4, 0.06), 300);
  Simplifier& s = *fx.simplifier;
  double incoherence[2];
  for(int remedy = 0; remedy < 2; ++remedy) {
    std::vector<std::vector<std::uint32_t>> fine_sets, mapped_sets;
    SS::Silhouette_frame prev, cur;
    SS::Loop_mapping_options o;
    o.previous_bias = remedy ? 0.5 : 1.0;
    for(int t = 0; t < 12; ++t) {
      s.extract(orbit_view(0.02 * t), cur);
      s.map_loops(cur, o, t > 0 ? &prev : nullptr);
      std::vector<std::uint32_t> f, m;
      for(std::uint32_t h : cur.fine_silhouette) f.push_back(s.fine().edge(h));
      for(std::uint32_t h : cur.mapped_halfedges()) m.push_back(s.fine().edge(h));
      fine_sets.push_back(f);
      mapped_sets.push_back(m);
      std::swap(prev, cur);
    }
    incoherence[remedy] = SS::temporal_incoherence(mapped_sets, fine_sets);
  }
  CHECK(incoherence[1] < incoherence[0]);
}

#include <MDCS_test/cgal_meshes.h>

TEST_CASE("Silhouette_simplifier_3: CGAL's elephant, both methods over a rotation", "[silhouette][real]")
{
  Mesh fine;
  if(!MDCS_test::read_mesh(MDCS_test::cgal_demo_mesh("elephant.off"), fine)) {
    WARN("CGAL's demo meshes are not available (libcgal-demo): case skipped");
    return;
  }
  SS::Coarse_mesh_options o;
  o.target_faces = 600;
  const auto coarse = SS::build_coarse_mesh(fine, o);
  Simplifier s(fine, coarse.mesh, coarse.coarse_face_of_fine_face);
  const auto box = CGAL::Polygon_mesh_processing::bbox(fine);
  const Point_3 c((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2, (box.zmin() + box.zmax()) / 2);
  std::size_t fine_total = 0, mapped_total = 0, picked_total = 0;
  for(int i = 0; i < 8; ++i) {
    const double a = 0.785 * i;
    SS::Silhouette_frame frame;
    s.extract(View::perspective(c + 3 * s.diagonal() * Vector_3(std::cos(a), 0.4, std::sin(a))), frame);
    s.pick_loops(frame);
    s.map_loops(frame);
    for(const auto* loops : {&frame.fine_loops, &frame.mapped})
      for(const auto& l : *loops) REQUIRE(l.closed);
    std::set<std::uint32_t> sil(frame.fine_silhouette.begin(), frame.fine_silhouette.end());
    for(std::uint32_t h : frame.picked_halfedges()) REQUIRE(sil.count(h) == 1);
    fine_total += frame.fine_silhouette.size();
    mapped_total += frame.mapped_halfedges().size();
    picked_total += frame.picked_halfedges().size();
  }
  CHECK(mapped_total < fine_total);
  CHECK(picked_total < fine_total);
}

TEST_CASE("temporal coherence: hysteresis of loop picking", "[silhouette][coherence][picking]")
{
  Fixture fx(noisy_sphere(4, 0.06), 300);
  Simplifier& s = *fx.simplifier;
  double incoherence[2];
  for(int remedy = 0; remedy < 2; ++remedy) {
    std::vector<std::vector<std::uint32_t>> fine_sets, picked_sets;
    SS::Silhouette_frame prev, cur;
    SS::Loop_picking_options o;
    o.min_loop_edges = 3;
    o.previous_bias = remedy ? 0.5 : 1.0;
    for(int t = 0; t < 24; ++t) {
      s.extract(orbit_view(0.01 * t), cur);
      s.pick_loops(cur, o, t > 0 ? &prev : nullptr);
      // The remedy keeps the invariants: distinct fine silhouette loops, and the reported error is the
      // true (unbiased) sum of squared distances, recomputed here by brute force.
      std::set<std::uint32_t> distinct(cur.picked.begin(), cur.picked.end());
      REQUIRE(distinct.size() == cur.picked.size());
      double error = 0;
      for(const auto& cl : cur.coarse_loops)
        for(std::uint32_t h : cl.halfedges) {
          const Point_3& c = s.coarse().points[s.coarse().source[h]];
          double best = s.diagonal() * s.diagonal();
          for(std::uint32_t l : cur.picked)
            for(std::uint32_t g : cur.fine_loops[l].halfedges)
              best = std::min(best, CGAL::squared_distance(c, s.fine().points[s.fine().source[g]]));
          error += best;
        }
      CHECK(cur.picking_error == Approx(error).epsilon(1e-5));
      std::vector<std::uint32_t> f, p;
      for(std::uint32_t h : cur.fine_silhouette) f.push_back(s.fine().edge(h));
      for(std::uint32_t h : cur.picked_halfedges()) p.push_back(s.fine().edge(h));
      fine_sets.push_back(f);
      picked_sets.push_back(p);
      std::swap(prev, cur);
    }
    incoherence[remedy] = SS::temporal_incoherence(picked_sets, fine_sets);
  }
  INFO("picking incoherence without / with hysteresis: " << incoherence[0] << " / " << incoherence[1]);
  CHECK(incoherence[1] < 0.95 * incoherence[0]); // measured: 1.95 -> 1.73
  SS::Silhouette_frame f;
  s.extract(orbit_view(0), f);
  SS::Loop_picking_options bad;
  bad.previous_bias = 1.5;
  CHECK_THROWS_AS(s.pick_loops(f, bad, &f), std::invalid_argument);
}

// Coordinates: NaN or infinity and a mesh far from unit scale are refused by every entry point (before: the
// coarse mesh was built from a NaN vertex, CGAL's exact predicates asserted on an overflowing mesh, and at 1e-100
// or 1e100 no edge was collapsed); inside the range the results do not depend on the scale (powers of two, so
// the scaled coordinates are exact): the same coarse mesh and the same mapped loops at 2^-90 and 2^90.
TEST_CASE("silhouette: non-finite coordinates and the scale range", "[silhouette][robustness]")
{
  const Mesh base = make<Mesh>(noisy_sphere(3, 0.05));
  auto scaled = [&](double s) {
    Mesh m = base;
    CGAL::Polygon_mesh_processing::transform(K::Aff_transformation_3(CGAL::SCALING, s), m);
    return m;
  };
  auto message_of = [](const std::function<void()>& f) {
    try {
      f();
    } catch(const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  SS::Coarse_mesh_options o;
  o.target_faces = 200;
  for(double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    Mesh m = base;
    const auto v = *std::next(vertices(m).begin(), 4);
    m.point(v) = Point_3(bad, 0, 0);
    std::vector<Mesh::Halfedge_index> out;
    CHECK(message_of([&] { SS::build_coarse_mesh(m, o); }).find("vertex 4 has a coordinate that is not finite") !=
          std::string::npos);
    CHECK(message_of([&] { SS::silhouette_halfedges(m, orbit_view(0.3), std::back_inserter(out)); }).find("not finite") !=
          std::string::npos);
    const auto coarse = SS::build_coarse_mesh(base, o);
    CHECK(message_of([&] { Simplifier(m, coarse.mesh, coarse.coarse_face_of_fine_face); }).find("not finite") !=
          std::string::npos);
  }
  for(double s : {1e-40, 1e40}) {
    const Mesh m = scaled(s);
    CHECK(message_of([&] { SS::build_coarse_mesh(m, o); }).find("must be in [1e-30, 1e30]") != std::string::npos);
  }
  // Scale invariance inside the range: coarse faces and mapped loops as at unit scale.
  auto run = [&](double s) {
    const Mesh m = scaled(s);
    const auto coarse = SS::build_coarse_mesh(m, o);
    Simplifier simplifier(m, coarse.mesh, coarse.coarse_face_of_fine_face);
    SS::Silhouette_frame frame;
    const double a = 0.3, e = 0.3, r = 4 * s;
    simplifier.extract(View::perspective(Point_3(r * std::cos(a) * std::cos(e), r * std::sin(a) * std::cos(e), r * std::sin(e))),
                       frame);
    simplifier.map_loops(frame);
    return std::make_pair(num_faces(coarse.mesh), frame.mapped_halfedges());
  };
  const auto unit = run(1.0);
  CHECK(!unit.second.empty());
  for(int exponent : {-90, 90}) {
    INFO("scale 2^" << exponent);
    const auto other = run(std::ldexp(1.0, exponent));
    CHECK(other.first == unit.first);
    CHECK(other.second == unit.second);
  }
}
