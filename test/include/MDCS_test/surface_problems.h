// Shared fixtures for the bivariate (surface) variational tests and benchmarks: the saddle problem, the "blob"
// problem of the thesis (Table 2.3; used with VM::random_blob_functional_3) and the plane options its tests draw
// planes with, Scherk's surface in a tall box with the planes of the tangent-plane refinement.
#ifndef MDCS_TEST_SURFACE_PROBLEMS_H
#define MDCS_TEST_SURFACE_PROBLEMS_H

#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <CGAL/Bbox_2.h>

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

} // namespace MDCS_test

#endif // MDCS_TEST_SURFACE_PROBLEMS_H
