// Shared fixtures for the bivariate (surface) variational tests and benchmarks: the saddle problem, the "blob"
// problem of the thesis (Table 2.3; used with VM::random_blob_functional_3) and the plane options its tests draw
// planes with, Scherk's surface in a tall box with the planes of the tangent-plane refinement, Scherk's problem with
// its piecewise linear boundary, a heavy membrane.
#ifndef MDCS_TEST_SURFACE_PROBLEMS_H
#define MDCS_TEST_SURFACE_PROBLEMS_H

#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/analytic_solutions_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <CGAL/Bbox_2.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace MDCS_test {

// The unit square with the saddle 0.5 + (x - 0.5)(y - 0.5) as boundary (the area's minimiser is not flat).
inline CGAL::Variational_minimization::Surface_problem_3 saddle_problem(int segments_per_side)
{
  CGAL::Variational_minimization::Surface_problem_3 P;
  P.boundary_segments_per_side = segments_per_side;
  P.lower_boundary = [](double x, double y) { return 0.5 + (x - 0.5) * (y - 0.5); };
  return P;
}

// The unit square with one boundary segment per side and the boundary free between 0 and 1: the density of a
// random blob functional alone decides where the minimal surface goes.
inline CGAL::Variational_minimization::Surface_problem_3 blob_problem()
{
  CGAL::Variational_minimization::Surface_problem_3 P;
  P.boundary_segments_per_side = 1;
  P.lower_boundary = [](double, double) { return 0.0; };
  P.upper_boundary = [](double, double) { return 1.0; };
  return P;
}

// Planes of slope at most 2 (slope-limited distribution) drawn with the given seed.
inline CGAL::Variational_minimization::Surface_plane_options_3 blob_planes(std::uint64_t seed)
{
  CGAL::Variational_minimization::Surface_plane_options_3 o;
  o.distribution = CGAL::Variational_minimization::Plane_distribution_3::slope_limited;
  o.max_slope = 2;
  o.seed = seed;
  return o;
}

// Scherk's surface log(cos y / cos x) over [-1.2, 1.2]^2 with four boundary segments per side, in the box
// z in [-3, 3] (taller than VM::scherk_surface_problem_3's, so that tangent planes of any slope fit).
inline CGAL::Variational_minimization::Surface_problem_3 tall_scherk_problem()
{
  const double a = 1.2;
  CGAL::Variational_minimization::Surface_problem_3 P;
  P.domain = CGAL::Bbox_2(-a, -a, a, a);
  P.zmin = -3;
  P.zmax = 3;
  P.boundary_segments_per_side = 4;
  P.lower_boundary = [](double x, double y) { return std::log(std::cos(y) / std::cos(x)); };
  return P;
}

// The starting planes of the tangent-plane refinement of tall_scherk_problem(): slope at most 3, 20% pencils.
inline CGAL::Variational_minimization::Surface_plane_options_3 tall_scherk_planes()
{
  CGAL::Variational_minimization::Surface_plane_options_3 o;
  o.distribution = CGAL::Variational_minimization::Plane_distribution_3::slope_limited;
  o.max_slope = 3;
  o.pencil_fraction = 0.2;
  return o;
}


// Scherk's problem (VM::scherk_surface_problem_3) whose boundary is the piecewise linear curve through its samples,
// with Scherk's surface inside: the discrete problems span that curve, so their energies converge to the minimal
// area it spans (computed by relaxation), not to Scherk's.
inline CGAL::Variational_minimization::Surface_problem_3 scherk_piecewise_linear_boundary_problem(int segments)
{
  namespace VM = CGAL::Variational_minimization;
  VM::Surface_problem_3 Q = VM::scherk_surface_problem_3(segments);
  const double a = Q.domain.xmax(), h = 2 * a / segments;
  auto interpolate = [=](double t, double fixed, bool x_side) {
    const int k = std::min(segments - 1, int(std::floor((t + a) / h)));
    const double t0 = -a + k * h, u = (t - t0) / h;
    const double g0 = x_side ? VM::scherk_surface_height(fixed, t0) : VM::scherk_surface_height(t0, fixed);
    const double g1 = x_side ? VM::scherk_surface_height(fixed, t0 + h) : VM::scherk_surface_height(t0 + h, fixed);
    return (1 - u) * g0 + u * g1;
  };
  Q.lower_boundary = [=](double x, double y) {
    if(std::abs(std::abs(x) - a) < 1e-12) return interpolate(y, x, true);
    if(std::abs(std::abs(y) - a) < 1e-12) return interpolate(x, y, false);
    return VM::scherk_surface_height(x, y);
  };
  return Q;
}

// A heavy membrane: the unit square, boundary fixed at height 0.75 (2 segments per side, a flat boundary that the
// planes hold exactly), and the functional area + k_g f with k_g = 2. The area is convex in f and the potential
// linear, so the minimiser is unique; it has no closed form, and relaxation on fine grids gives its energy.
inline CGAL::Variational_minimization::Surface_problem_3 sagging_membrane_problem()
{
  CGAL::Variational_minimization::Surface_problem_3 P;
  P.lower_boundary = [](double, double) { return 0.75; };
  P.boundary_segments_per_side = 2;
  return P;
}

inline CGAL::Variational_minimization::Membrane_functional_3 sagging_membrane_functional()
{
  CGAL::Variational_minimization::Membrane_functional_3 G;
  G.k_g = 2;
  G.z_bottom = 0; // zmin of sagging_membrane_problem()
  return G;
}

} // namespace MDCS_test

#endif // MDCS_TEST_SURFACE_PROBLEMS_H
