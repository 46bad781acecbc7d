// The parallel entry points of the variational solvers (issue 29 item 4) return what the sequential code returns,
// bit for bit, for 1, 2, 3 and 8 threads (8 oversubscribes the machine on purpose): facet and edge weights
// (quadrature, Monte Carlo, closed form, polygonal domain), the min-cut solve, plane selection and its restarts,
// adaptive refinement, the basin search and tangent-plane refinement. Errors are the sequential ones too.
// Tagged [parallel]: the ThreadSanitizer build runs these cases alone.
#include <catch2/catch.hpp>

#include <MDCS_test/curve_problems.h>
#include <MDCS_test/surface_problems.h>
#include <MDCS_test/thread_counts.h>

#include <CGAL/MDCS/concurrency.h>
#include <CGAL/Variational_minimization/curve_edge_weights_2.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/monte_carlo_functional_3.h>
#include <CGAL/Variational_minimization/refine_surface_3.h>
#include <CGAL/Variational_minimization/refine_surface_by_tangent_planes_3.h>
#include <CGAL/Variational_minimization/search_surface_basins_3.h>
#include <CGAL/Variational_minimization/select_planes_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace VM = CGAL::Variational_minimization;
using MDCS_test::blob_planes;
using MDCS_test::blob_problem;

namespace {

using MDCS_test::thread_counts;

VM::Surface_problem_3 saddle_problem() { return MDCS_test::saddle_problem(2); }

// A functional without closed form (Gauss quadrature): the area weighted by a smooth density.
struct Weighted_area
{
  double operator()(double f, double fx, double fy, double x, double y) const
  {
    return (1 + 0.5 * std::sin(3 * x + f) * std::cos(2 * y)) * std::sqrt(1 + fx * fx + fy * fy);
  }
};

// G is NaN where x + y > 1.2 (an invalid functional): the error must name the same facet for every thread count.
struct Nan_somewhere
{
  double operator()(double, double fx, double fy, double x, double y) const
  {
    return x + y > 1.2 ? std::numeric_limits<double>::quiet_NaN() : std::sqrt(1 + fx * fx + fy * fy);
  }
};

bool same_surface(const VM::Minimal_surface_3& a, const VM::Minimal_surface_3& b)
{
  return a.is_feasible == b.is_feasible && a.facets == b.facets && a.energy == b.energy &&
         a.solver_value == b.solver_value && a.points == b.points && a.triangles == b.triangles;
}

std::string error_of(const std::function<void()>& f)
{
  try {
    f();
  } catch(const std::exception& e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST_CASE("parallel facet weights: identical for 1, 2, 3 and 8 threads", "[variational][surface][parallel]")
{
  const VM::Surface_problem_3 P = saddle_problem();
  const VM::Plane_arrangement_3 A(VM::surface_planes_3(P, 32));
  REQUIRE(A.number_of_facets() > 3 * VM::internal::facet_weight_block_3); // several blocks
  const auto blob = VM::random_blob_functional_3(P, 4, 3, 0.1, -1.5, 3);
  const auto mc = VM::make_monte_carlo_functional_3(Weighted_area(), 16, 7);
  const std::vector<double> quadrature = VM::surface_facet_weights_3(A, P, Weighted_area(), 1);
  const std::vector<double> closed = VM::surface_facet_weights_3(A, P, VM::Area_functional_3());
  const std::vector<double> monte_carlo = VM::surface_facet_weights_3(A, P, mc);
  const std::vector<double> blobs = VM::surface_facet_weights_3(A, P, blob, 0);
  for(std::size_t t : thread_counts) {
    INFO(t << " threads");
    CHECK(VM::surface_facet_weights_3<CGAL::Parallel_tag>(A, P, Weighted_area(), 1, t) == quadrature);
    CHECK(VM::surface_facet_weights_3<CGAL::Parallel_if_available_tag>(A, P, VM::Area_functional_3(), 1, t) == closed);
    CHECK(VM::surface_facet_weights_3<CGAL::Parallel_tag>(A, P, mc, 1, t) == monte_carlo);
    CHECK(VM::surface_facet_weights_3<CGAL::Parallel_tag>(A, P, blob, 0, t) == blobs);
    CHECK(VM::surface_facet_weights_3<CGAL::Sequential_tag>(A, P, blob, 0, t) == blobs);
  }
  // The weights are not trivially equal: quadrature differs from the closed form somewhere, Monte Carlo too.
  CHECK(quadrature != closed);
  CHECK(monte_carlo != quadrature);
}

TEST_CASE("parallel arrangement build: the same arrangement for every thread count", "[variational][surface][parallel]")
{
  const VM::Surface_problem_3 P = saddle_problem();
  const std::vector<VM::Lattice_plane_3> planes = VM::surface_planes_3(P, 72);
  const VM::Plane_arrangement_3 seq(planes);
  REQUIRE(seq.number_of_cells() > 20000); // the last insertions create more than 1024 cells: boxes in parallel
  for(std::size_t t : thread_counts) {
    INFO(t << " threads");
    VM::Plane_arrangement_3 par(planes, CGAL::MDCS::No_progress(), t);
    REQUIRE(par.number_of_cells() == seq.number_of_cells());
    REQUIRE(par.number_of_facets() == seq.number_of_facets());
    REQUIRE(par.number_of_vertices() == seq.number_of_vertices());
    bool same = true;
    for(std::uint32_t f = 0; f < seq.number_of_facets() && same; ++f)
      same = seq.facet(f).plane == par.facet(f).plane && seq.facet(f).negative_cell == par.facet(f).negative_cell &&
             seq.facet(f).positive_cell == par.facet(f).positive_cell && seq.facet_vertices(f) == par.facet_vertices(f);
    for(std::uint32_t c = 0; c < seq.number_of_cells() && same; ++c)
      same = std::vector<std::uint32_t>(seq.cell_facets(c).begin(), seq.cell_facets(c).end()) ==
             std::vector<std::uint32_t>(par.cell_facets(c).begin(), par.cell_facets(c).end());
    for(std::uint32_t v = 0; v < seq.number_of_vertices() && same; ++v) same = seq.point(v) == par.point(v);
    CHECK(same);
    // Later insertions (a tree rebuilt from the cells' boxes) agree too.
    VM::Plane_arrangement_3 more_seq(planes);
    const std::vector<VM::Lattice_plane_3> extra = VM::surface_planes_3(P, 68, [] {
      VM::Surface_plane_options_3 o;
      o.seed = 99;
      return o;
    }());
    for(std::size_t i = 64; i < extra.size(); ++i) {
      par.insert_plane(extra[i]);
      more_seq.insert_plane(extra[i]);
    }
    CHECK(par.number_of_cells() == more_seq.number_of_cells());
    CHECK(par.number_of_cells() > seq.number_of_cells());
  }
}

TEST_CASE("parallel facet weights: polygonal domain, errors and progress as in the sequential code",
          "[variational][surface][parallel]")
{
  VM::Surface_problem_3 P;
  P.boundary_segments_per_side = 2;
  P.lower_boundary = [](double x, double y) { return 0.3 + 0.2 * x * y; };
  P.set_domain_polygon({{0, 0}, {1, 0}, {1, 0.5}, {0.5, 0.5}, {0.5, 1}, {0, 1}}); // an L
  const VM::Plane_arrangement_3 A(VM::surface_planes_3(P, 30));
  const std::vector<double> seq = VM::surface_facet_weights_3(A, P, Weighted_area());
  for(std::size_t t : thread_counts)
    CHECK(VM::surface_facet_weights_3<CGAL::Parallel_tag>(A, P, Weighted_area(), 1, t) == seq);

  const VM::Surface_problem_3 Q = saddle_problem();
  const VM::Plane_arrangement_3 B(VM::surface_planes_3(Q, 28));
  const std::string expected = error_of([&] { VM::surface_facet_weights_3(B, Q, Nan_somewhere()); });
  REQUIRE(!expected.empty());
  for(std::size_t t : thread_counts)
    CHECK(error_of([&] { VM::surface_facet_weights_3<CGAL::Parallel_tag>(B, Q, Nan_somewhere(), 1, t); }) == expected);

  // Progress from the calling thread only, ending at 1; cancellation throws Operation_cancelled.
  for(std::size_t t : thread_counts) {
    double last = -1;
    bool monotone = true;
    const std::thread::id caller = std::this_thread::get_id();
    bool same_thread = true;
    VM::surface_facet_weights_3<CGAL::Parallel_tag>(B, Q, Weighted_area(), 1, t, [&](const char* stage, double f) {
      same_thread = same_thread && std::this_thread::get_id() == caller && std::string(stage) == "weights";
      monotone = monotone && f >= last;
      last = f;
      return true;
    });
    CHECK(same_thread);
    CHECK(monotone);
    CHECK(last == 1.0);
    int calls = 0;
    CHECK_THROWS_AS(VM::surface_facet_weights_3<CGAL::Parallel_tag>(B, Q, Weighted_area(), 1, t,
                                                                      [&](const char*, double) { return ++calls < 2; }),
                    CGAL::MDCS::Operation_cancelled);
  }
}

TEST_CASE("parallel min-cut solve: the same surface for every thread count and engine",
          "[variational][surface][parallel]")
{
  const VM::Surface_problem_3 P = blob_problem();
  const auto G = VM::random_blob_functional_3(P, 4, 3, 0.1, -1.5, 3);
  const VM::Plane_arrangement_3 A(VM::surface_planes_3(P, 36, blob_planes(3)));
  const VM::Minimal_surface_3 lean = VM::minimize_surface_functional_3(A, P, G);
  REQUIRE(lean.is_feasible);
  const VM::Minimal_surface_3 bk =
    VM::minimize_surface_functional_3(A, P, G, 1, CGAL::Min_cut::Boykov_kolmogorov_max_flow());
  for(std::size_t t : thread_counts) {
    INFO(t << " threads");
    CHECK(same_surface(VM::minimize_surface_functional_3<CGAL::Parallel_tag>(A, P, G, 1, t), lean));
    CHECK(same_surface(VM::minimize_surface_functional_3<CGAL::Parallel_tag>(
                         A, P, G, 1, t, CGAL::Min_cut::Boykov_kolmogorov_max_flow()),
                       bk));
  }
}

TEST_CASE("parallel plane selection, restarts and adaptive refinement: identical results",
          "[variational][surface][parallel]")
{
  const VM::Surface_problem_3 P = blob_problem();
  const auto G = VM::random_blob_functional_3(P, 4, 3, 0.1, -1.5, 3);
  const VM::Plane_selection_result_3 seq = VM::select_planes_3(P, G, 30, 2, blob_planes(5));
  const VM::Plane_selection_multistart_result_3 multi_seq = VM::select_planes_multistart_3(P, G, 30, 2, 3, blob_planes(5));
  const VM::Surface_refinement_result_3 refined_seq = VM::refine_surface_3(P, G, 30, 3, blob_planes(5), 0.05);
  // Restart 0 is select_planes_3 itself; the best restart has the lowest energy.
  REQUIRE(multi_seq.restart_energies.size() == 3);
  const VM::Plane_selection_result_3& first = seq;
  CHECK(multi_seq.restart_energies[0] == first.surface.energy);
  for(double e : multi_seq.restart_energies) CHECK(multi_seq.best.surface.energy <= e);
  CHECK(multi_seq.best.surface.energy == multi_seq.restart_energies[multi_seq.best_restart]);
  for(std::size_t t : thread_counts) {
    INFO(t << " threads");
    VM::Surface_plane_options_3 o = blob_planes(5);
    o.threads = t;
    const VM::Plane_selection_result_3 par = VM::select_planes_3(P, G, 30, 2, o);
    CHECK(par.energies == seq.energies);
    CHECK(par.cells == seq.cells);
    CHECK(same_surface(par.surface, seq.surface));
    const VM::Plane_selection_multistart_result_3 multi = VM::select_planes_multistart_3(P, G, 30, 2, 3, o);
    CHECK(multi.restart_energies == multi_seq.restart_energies);
    CHECK(multi.best_restart == multi_seq.best_restart);
    CHECK(same_surface(multi.best.surface, multi_seq.best.surface));
    const VM::Surface_refinement_result_3 refined = VM::refine_surface_3(P, G, 30, 3, o, 0.05);
    CHECK(refined.run_energies == refined_seq.run_energies);
    CHECK(same_surface(refined.surface, refined_seq.surface));
    CHECK(refined.cells == refined_seq.cells);
    CHECK(refined.network_nodes == refined_seq.network_nodes);
  }
  CHECK_THROWS_AS(VM::select_planes_multistart_3(P, G, 30, 2, 0), std::invalid_argument);
}

TEST_CASE("parallel basin search: the moves of the sequential search, the same answer",
          "[variational][surface][basin_search][parallel]")
{
  const VM::Surface_problem_3 P = blob_problem();
  const auto G = VM::random_blob_functional_3(P, 4, 3, 0.1, -1.5, 5);
  VM::Surface_basin_search_options_3 so;
  so.tilings = {2, 3};
  so.wide_tilings = {2};
  so.relaxation.grids = {8};
  so.sweeps = 2;
  const VM::Relaxed_plane_selection_result_3 seq = VM::select_planes_relaxed_3(P, G, 30, 2, blob_planes(1), so);
  REQUIRE(seq.search.moves > 0);
  // The direct entry point, from several starts.
  const VM::Plane_arrangement_3 A(seq.selection.planes);
  const std::vector<double> w = VM::surface_facet_weights_3(A, P, G);
  const VM::Surface_basin_search_result_3 direct_seq = VM::search_surface_basins_3(A, w, P, G, seq.selection.surfaces, so);
  // Improvements happen: a batch of speculative moves is then cut short and evaluated again.
  CHECK(seq.search.improvements + direct_seq.improvements > 0);
  for(std::size_t t : thread_counts) {
    INFO(t << " threads");
    VM::Surface_basin_search_options_3 st = so;
    st.threads = t;
    VM::Surface_plane_options_3 o = blob_planes(1);
    o.threads = t;
    const VM::Relaxed_plane_selection_result_3 par = VM::select_planes_relaxed_3(P, G, 30, 2, o, st);
    CHECK(par.selection.energies == seq.selection.energies);
    CHECK(par.round_relaxed_energies == seq.round_relaxed_energies);
    CHECK(par.search.moves == seq.search.moves);
    CHECK(par.search.improvements == seq.search.improvements);
    CHECK(par.search.sweeps == seq.search.sweeps);
    CHECK(par.search.relaxed.energy == seq.search.relaxed.energy);
    CHECK(par.search.relaxed.heights == seq.search.relaxed.heights);
    CHECK(same_surface(par.search.discrete, seq.search.discrete));
    const VM::Surface_basin_search_result_3 direct = VM::search_surface_basins_3(A, w, P, G, seq.selection.surfaces, st);
    CHECK(direct.moves == direct_seq.moves);
    CHECK(direct.improvements == direct_seq.improvements);
    CHECK(direct.relaxed.heights == direct_seq.relaxed.heights);
  }
}

TEST_CASE("parallel tangent-plane refinement: the same planes and optimum", "[variational][surface][parallel]")
{
  const VM::Surface_problem_3 P = MDCS_test::tall_scherk_problem();
  const VM::Surface_plane_options_3 o = MDCS_test::tall_scherk_planes();
  VM::Tangent_refinement_options_3 to;
  to.rounds = 2;
  const VM::Tangent_refinement_result_3 seq = VM::refine_surface_by_tangent_planes_3(P, VM::Area_functional_3(), 44, to, o);
  for(std::size_t t : thread_counts) {
    INFO(t << " threads");
    VM::Tangent_refinement_options_3 tt = to;
    tt.threads = t;
    const VM::Tangent_refinement_result_3 par = VM::refine_surface_by_tangent_planes_3(P, VM::Area_functional_3(), 44, tt, o);
    CHECK(par.round_energies == seq.round_energies);
    CHECK(par.round_cells == seq.round_cells);
    CHECK(par.best_round == seq.best_round);
    CHECK(same_surface(par.surface, seq.surface));
    REQUIRE(par.planes.size() == seq.planes.size());
    bool planes_equal = true;
    for(std::size_t i = 0; i < par.planes.size(); ++i)
      planes_equal = planes_equal && par.planes[i].a == seq.planes[i].a && par.planes[i].b == seq.planes[i].b &&
                     par.planes[i].c == seq.planes[i].c && par.planes[i].d == seq.planes[i].d;
    CHECK(planes_equal);
  }
}

TEST_CASE("parallel curve edge weights: identical for every thread count", "[variational][curve][parallel]")
{
  const VM::Curve_problem_2 problem = MDCS_test::catenoid_problem(0.9);
  const VM::Line_arrangement_2 arrangement =
    VM::build_curve_arrangement_2(problem, MDCS_test::lines_for(problem, 120, 4));
  REQUIRE(arrangement.number_of_edges() > 3000);
  const VM::Surface_of_rotation_functional G;
  const auto density = VM::make_density_weighted_length_functional([](double x, double y) { return 1 + x * x * y; });
  const std::vector<double> closed = VM::curve_edge_weights_2(arrangement, G);
  const std::vector<double> quadrature = VM::curve_edge_weights_2(arrangement, density);
  for(std::size_t t : thread_counts) {
    CHECK(VM::curve_edge_weights_2<CGAL::Parallel_tag>(arrangement, G, t) == closed);
    CHECK(VM::curve_edge_weights_2<CGAL::Parallel_tag>(arrangement, density, t) == quadrature);
  }
}
