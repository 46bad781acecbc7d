// Shared fixtures for the bivariate (surface) variational tests and benchmarks: the "blob" problem of the thesis
// (Table 2.3; used with VM::random_blob_functional_3) and the plane options its tests draw planes with.
#ifndef MDCS_TEST_SURFACE_PROBLEMS_H
#define MDCS_TEST_SURFACE_PROBLEMS_H

#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <cstdint>

namespace MDCS_test {

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

} // namespace MDCS_test

#endif // MDCS_TEST_SURFACE_PROBLEMS_H
