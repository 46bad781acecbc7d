// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Random plane distributions for the bivariate problem: isotropic, slope-limited, and pencils of planes through the
// segments of the boundary curve (thesis ch. 2.7), all with integer coefficients in the lattice of Plane_arrangement_3.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_SURFACE_PLANES_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_SURFACE_PLANES_3_H

#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/// The law of the random (non-pencil) planes.
enum class Plane_distribution_3
{
  isotropic,    ///< normal uniform on the sphere (in lattice coordinates), through a uniform point of the box
  slope_limited ///< z = A x + B y + C with |A|, |B| <= max_slope (world), through a uniform point of the box
};

inline const char* plane_distribution_name(Plane_distribution_3 d)
{
  return d == Plane_distribution_3::isotropic ? "isotropic" : "slope-limited";
}

/// How `surface_planes_3()` draws planes; recorded with every result.
struct Surface_plane_options_3
{
  Plane_distribution_3 distribution = Plane_distribution_3::isotropic;
  /// slope_limited only: bound on |A| and |B| in world units; finite, > 0, and at most
  /// `surface_max_slope_3(problem)` (checked whatever the distribution)
  double max_slope = 2;
  double pencil_fraction = 0.1;  ///< share of the planes forced through the boundary segments (at least one each)
  std::uint64_t seed = 1;
  /// `select_planes_3()` only: the share of the redrawn planes that pass through random points near the current
  /// optimum (the others are drawn from `distribution` through the whole box); 0 (the default, the thesis's
  /// scheme) redraws them all uniformly.
  double selection_near_fraction = 0;
  /// `select_planes_3()` only: the spread of those points' heights about the optimum (standard deviation, as a
  /// share of zmax - zmin).
  double selection_near_spread = 0.1;
  /// `select_planes_3()`, `select_planes_multistart_3()` and `refine_surface_3()` only: threads for the facet
  /// weights and the independent runs (0: all hardware threads; TBB needed, else 1). Results do not depend on it.
  std::size_t threads = 1;
};

namespace internal {

inline Lattice_plane_3 reduced_plane(std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d)
{
  Lattice_plane_3 p;
  p.a = a; p.b = b; p.c = c; p.d = d;
  return normalized_plane(p);
}

// A plane with normal n (any scale), through the lattice point q; the normal is scaled to integers of at most 2^20.
inline Lattice_plane_3 plane_through(const std::array<double, 3>& n, const std::array<double, 3>& q)
{
  const double m = (std::max)({std::abs(n[0]), std::abs(n[1]), std::abs(n[2])});
  const double s = double(1 << 20) / m;
  const std::int64_t a = std::llround(n[0] * s), b = std::llround(n[1] * s), c = std::llround(n[2] * s);
  const std::int64_t d = -std::llround(double(a) * q[0] + double(b) * q[1] + double(c) * q[2]);
  return reduced_plane(a, b, c, d);
}

// A random non-vertical plane through the lattice segment p-q: normal (q - p) x r for a random integer r.
template <class Rng>
Lattice_plane_3 pencil_plane(const std::array<std::int64_t, 3>& p, const std::array<std::int64_t, 3>& q, Rng& rng)
{
  std::uniform_int_distribution<std::int64_t> U(-255, 255);
  const std::int64_t u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
  for(int attempt = 0; attempt < 1000; ++attempt) {
    const std::int64_t r[3] = {U(rng), U(rng), U(rng)};
    const std::int64_t a = u[1] * r[2] - u[2] * r[1], b = u[2] * r[0] - u[0] * r[2], c = u[0] * r[1] - u[1] * r[0];
    if(c == 0) continue; // vertical planes are useless for a function graph
    return reduced_plane(a, b, c, -(a * p[0] + b * p[1] + c * p[2]));
  }
  throw std::logic_error("MDCS: surface_planes_3: no non-vertical plane through a boundary segment");
}

// A plane through the boundary segment p-q (on a side wall) whose slope across the segment, towards the inside of the
// domain, is `lattice_slope` (dZ per lattice step): normal (q - p) x (64 n_in + k e_z), |k| <= 511.
inline Lattice_plane_3 sloped_pencil_plane(const std::array<std::int64_t, 3>& p, const std::array<std::int64_t, 3>& q,
                                           double lattice_slope)
{
  const std::int64_t L = Plane_arrangement_3::lattice_size;
  std::int64_t n_in[2] = {0, 0};
  if(p[0] == 0 && q[0] == 0) n_in[0] = 1;
  else if(p[0] == L && q[0] == L) n_in[0] = -1;
  else if(p[1] == 0 && q[1] == 0) n_in[1] = 1;
  else n_in[1] = -1;
  const std::int64_t k = (std::max)(std::int64_t(-511), (std::min)(std::int64_t(511), std::int64_t(std::llround(64 * lattice_slope))));
  const std::int64_t u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
  const std::int64_t v[3] = {64 * n_in[0], 64 * n_in[1], k};
  const std::int64_t a = u[1] * v[2] - u[2] * v[1], b = u[2] * v[0] - u[0] * v[2], c = u[0] * v[1] - u[1] * v[0];
  return reduced_plane(a, b, c, -(a * p[0] + b * p[1] + c * p[2]));
}

// A plane through the boundary segment p-q of a polygonal domain (counter-clockwise, X and Y multiples of 2^8) whose
// slope across the segment, towards the inside, is about `world_slope`: normal (q - p) x (n_in + k e_z), n_in the
// inward normal scaled to a largest component of 64, |k| <= 447 (so that |a|, |b| <= 2^25).
inline Lattice_plane_3 polygon_pencil_plane(const std::array<std::int64_t, 3>& p, const std::array<std::int64_t, 3>& q,
                                            double world_slope, const Surface_problem_3& problem)
{
  const double L = double(Plane_arrangement_3::lattice_size);
  const std::int64_t u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
  const double m = double((std::max)(std::llabs(u[0]), std::llabs(u[1])));
  const std::int64_t nx = std::llround(-64.0 * double(u[1]) / m), ny = std::llround(64.0 * double(u[0]) / m);
  const double sx = (problem.domain.xmax() - problem.domain.xmin()) / L,
               sy = (problem.domain.ymax() - problem.domain.ymin()) / L, sz = (problem.zmax - problem.zmin) / L;
  const double run = std::sqrt(double(nx * nx) * sx * sx + double(ny * ny) * sy * sy); // world length of n_in
  const std::int64_t k = (std::max)(std::int64_t(-447), (std::min)(std::int64_t(447), std::int64_t(std::llround(world_slope * run / sz))));
  const std::int64_t v[3] = {nx, ny, k};
  const std::int64_t a = u[1] * v[2] - u[2] * v[1], b = u[2] * v[0] - u[0] * v[2], c = u[0] * v[1] - u[1] * v[0];
  return reduced_plane(a, b, c, -(a * p[0] + b * p[1] + c * p[2]));
}

// The vertical plane through the lattice points a and b.
inline Lattice_plane_3 vertical_plane_through(const std::array<std::int64_t, 2>& a, const std::array<std::int64_t, 2>& b)
{
  const std::int64_t pa = b[1] - a[1], pb = a[0] - b[0];
  return reduced_plane(pa, pb, 0, -(pa * a[0] + pb * a[1]));
}

// The plane through the boundary segment p-q and the apex c (X, Y multiples of 2^8: see Surface_problem_3).
inline Lattice_plane_3 cone_plane(const std::array<std::int64_t, 3>& p, const std::array<std::int64_t, 3>& q,
                                  const std::array<std::int64_t, 3>& c)
{
  const std::int64_t u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
  const std::int64_t v[3] = {c[0] - p[0], c[1] - p[1], c[2] - p[2]};
  std::int64_t a = u[1] * v[2] - u[2] * v[1], b = u[2] * v[0] - u[0] * v[2], cc = u[0] * v[1] - u[1] * v[0];
  const std::int64_t g = gcd64(gcd64(a, b), cc);
  if(g == 0) throw std::logic_error("MDCS: surface_planes_3: degenerate boundary cone");
  a /= g; b /= g; cc /= g;
  return reduced_plane(a, b, cc, -(a * p[0] + b * p[1] + cc * p[2]));
}

} // namespace internal

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  The most planes `surface_planes_3()` draws: 2^14. An arrangement of n planes in general position has up to
  C(n, 3) + C(n, 2) + n + 1 cells (measured: about n^3 / 19 for the isotropic planes of the manual's tables, 3.9M
  cells and 0.9 GiB at 420 planes), and `Plane_arrangement_3` holds at most 2^32 - 2 cells: far fewer planes
  already exhaust any memory, and a count beyond this one can only be a mistake (it would size the plane list
  itself: 32 bytes per plane).
*/
inline std::size_t surface_max_planes_3() { return std::size_t(1) << 14; }

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  The largest `Surface_plane_options_3::max_slope` for `problem`: 2^20 (zmax - zmin) / max(width, height) of the
  domain's bounding box. The planes live in the integer lattice of `Plane_arrangement_3`, whose normals are scaled
  to integers of at most 2^20: a plane that climbs more than 2^20 lattice steps per lattice step is vertical
  there (and useless for a function graph); larger slopes also overflowed the integer conversions.
*/
inline double surface_max_slope_3(const Surface_problem_3& problem)
{
  const double w = (std::max)(problem.domain.xmax() - problem.domain.xmin(), problem.domain.ymax() - problem.domain.ymin());
  return std::ldexp(problem.zmax - problem.zmin, 20) / w;
}

/// Throws `std::invalid_argument` when `options` cannot draw planes for `problem` (checked by `surface_planes_3()`
/// and every entry point that draws planes): `pencil_fraction` outside [0, 1], `max_slope` not finite, not > 0 or
/// above `surface_max_slope_3(problem)`, `selection_near_fraction` outside [0, 1], `selection_near_spread` not
/// finite or negative. `problem` must be valid.
inline void check_surface_plane_options_3(const Surface_problem_3& problem, const Surface_plane_options_3& options,
                                          const char* who = "surface_planes_3")
{
  auto fail = [who](const std::string& what) { throw std::invalid_argument(std::string("MDCS: ") + who + ": " + what); };
  if(!(options.pencil_fraction >= 0 && options.pencil_fraction <= 1)) fail("pencil_fraction must be in [0, 1]");
  if(!(options.max_slope > 0) || !std::isfinite(options.max_slope)) {
    std::ostringstream o;
    o << "max_slope must be finite and > 0 (it is " << options.max_slope << ")";
    fail(o.str());
  }
  const double steepest = surface_max_slope_3(problem);
  if(options.max_slope > steepest) {
    std::ostringstream o;
    o << "max_slope = " << options.max_slope << " is steeper than " << steepest
      << " = 2^20 (zmax - zmin) / domain size: such planes are vertical in the lattice of the arrangement";
    fail(o.str());
  }
  if(!(options.selection_near_fraction >= 0 && options.selection_near_fraction <= 1))
    fail("selection_near_fraction must be in [0, 1]");
  if(!(options.selection_near_spread >= 0) || !std::isfinite(options.selection_near_spread))
    fail("selection_near_spread must be finite and >= 0");
}

/// The number of pencil planes that `surface_planes_3(problem, n, options)` puts first in its list.
inline std::size_t surface_pencil_count_3(const Surface_problem_3& problem, std::size_t n,
                                          const Surface_plane_options_3& options)
{
  if(problem.is_polygonal()) {
    // The vertical planes of the edges, then (per boundary curve) one plane per boundary segment.
    const std::size_t edges = problem.lattice_polygon().size();
    const std::size_t segments = problem.polygon_samples().size() * (problem.is_relaxed() ? 2 : 1);
    return (std::max)(edges + segments, std::size_t(std::ceil(options.pencil_fraction * double(n))));
  }
  const std::size_t segments = std::size_t(4 * problem.boundary_segments_per_side) * (problem.is_relaxed() ? 2 : 1);
  return (std::max)(segments, std::size_t(std::ceil(options.pencil_fraction * double(n))));
}

namespace internal {

// The random (non-pencil) planes of surface_planes_3(), appended until `planes` has n.
template <class Rng>
void add_random_surface_planes_3(const Surface_problem_3& problem, std::size_t n, const Surface_plane_options_3& options,
                                 Rng& rng, std::vector<Lattice_plane_3>& planes)
{
  const std::int64_t L = Plane_arrangement_3::lattice_size;
  std::uniform_real_distribution<double> U(0, double(L));
  std::normal_distribution<double> N;
  std::uniform_real_distribution<double> S(-options.max_slope, options.max_slope);
  const double sx = (problem.domain.xmax() - problem.domain.xmin()) / double(L),
               sy = (problem.domain.ymax() - problem.domain.ymin()) / double(L),
               sz = (problem.zmax - problem.zmin) / double(L);
  while(planes.size() < n) {
    const std::array<double, 3> q = {{U(rng), U(rng), U(rng)}};
    std::array<double, 3> normal;
    if(options.distribution == Plane_distribution_3::isotropic)
      normal = {{N(rng), N(rng), N(rng)}};
    else
      normal = {{-S(rng) * sx / sz, -S(rng) * sy / sz, 1.0}};
    if(!(std::abs(normal[0]) + std::abs(normal[1]) + std::abs(normal[2]) > 1e-12)) continue;
    planes.push_back(plane_through(normal, q));
  }
}

// surface_planes_3() on a polygonal domain: the vertical planes of the edges; the planes of a triangulation of the
// (lower) boundary loop, which hold a piecewise linear function meeting the boundary condition (the boundary cone
// of a rectangle needs a domain star-shaped from its apex), plus pencils up to one plane per boundary segment;
// then more pencils and the random planes.
template <class Rng>
std::vector<Lattice_plane_3> polygon_surface_planes_3(const Surface_problem_3& problem, std::size_t n,
                                                      const Surface_plane_options_3& options, Rng& rng)
{
  const std::vector<std::array<std::int64_t, 2>> poly = problem.lattice_polygon();
  std::vector<Lattice_plane_3> planes;
  for(std::size_t e = 0; e < poly.size(); ++e) planes.push_back(vertical_plane_through(poly[e], poly[(e + 1) % poly.size()]));
  const std::size_t edges = planes.size();
  std::vector<std::array<std::array<std::int64_t, 3>, 2>> segments;
  for(int upper = 0; upper < (problem.is_relaxed() ? 2 : 1); ++upper) {
    const auto loop = problem.boundary_loop(upper != 0);
    for(std::size_t i = 0; i < loop.size(); ++i) segments.push_back({{loop[i], loop[(i + 1) % loop.size()]}});
    if(upper == 0)
      for(const auto& t : lattice_polygon_triangulation(loop)) planes.push_back(cone_plane(loop[t[0]], loop[t[1]], loop[t[2]]));
  }
  const std::size_t pencils = surface_pencil_count_3(problem, n, options);
  std::uniform_real_distribution<double> slope(-options.max_slope, options.max_slope);
  for(std::size_t i = planes.size(); i < pencils; ++i) {
    const auto& s = segments[(i - edges) % segments.size()];
    if(options.distribution == Plane_distribution_3::slope_limited)
      planes.push_back(polygon_pencil_plane(s[0], s[1], slope(rng), problem));
    else
      planes.push_back(pencil_plane(s[0], s[1], rng));
  }
  add_random_surface_planes_3(problem, n, options, rng, planes);
  return planes;
}

} // namespace internal

namespace internal {
inline std::vector<Lattice_plane_3> draw_surface_planes_3(const Surface_problem_3& problem, std::size_t n,
                                                          const Surface_plane_options_3& options);
} // namespace internal

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief `n` random planes for `problem`: pencils of planes through the segments of the boundary curve(s)
  (`max(number of segments, pencil_fraction * n)` of them), the others drawn from `options.distribution`.

  The first plane through each segment passes through the apex (centre of Ω, mean boundary height): together
  these planes hold the *boundary cone*, a piecewise linear function that meets the boundary condition, so that
  the discrete problem is always feasible. The other pencil planes turn about the segments at random
  (round-robin over the segments). The pencils make the boundary curve a union of arrangement edges, which the
  cut needs. On a polygonal domain the list starts with the vertical planes through the polygon's edges, and the
  boundary cone is replaced by the planes of a triangulation of the boundary loop (ear clipping; any simple
  polygon), completed by pencils to one plane per segment (`surface_pencil_count_3()` counts all of these).
  \throws std::invalid_argument if the problem is invalid, `n > surface_max_planes_3()`, or the options are
  (`check_surface_plane_options_3()`).
*/
inline std::vector<Lattice_plane_3> surface_planes_3(const Surface_problem_3& problem, std::size_t n,
                                                     const Surface_plane_options_3& options = Surface_plane_options_3())
{
  problem.validate();
  check_surface_plane_options_3(problem, options);
  if(n > surface_max_planes_3())
    throw std::invalid_argument("MDCS: surface_planes_3: " + std::to_string(n) + " planes requested; at most " +
                                std::to_string(surface_max_planes_3()) + " (an arrangement of n planes has up to about "
                                "n^3 / 6 cells and holds at most 2^32 - 2)");
  return internal::draw_surface_planes_3(problem, n, options);
}

namespace internal {

// The boundary segments of a rectangular problem (the lower loop, then the upper one when relaxed) and the planes
// of its boundary cone: one per lower segment, through the apex (centre of Ω, mean boundary height).
inline void rectangle_boundary_cone_3(const Surface_problem_3& problem,
                                      std::vector<std::array<std::array<std::int64_t, 3>, 2>>& segments,
                                      std::vector<Lattice_plane_3>& planes)
{
  const std::int64_t L = Plane_arrangement_3::lattice_size;
  for(int upper = 0; upper < (problem.is_relaxed() ? 2 : 1); ++upper) {
    const auto loop = problem.boundary_loop(upper != 0);
    std::int64_t mean = 0;
    for(const auto& p : loop) mean += p[2];
    const std::array<std::int64_t, 3> apex = {{L / 2, L / 2, mean / std::int64_t(loop.size())}};
    for(std::size_t i = 0; i < loop.size(); ++i) {
      const auto& p = loop[i];
      const auto& q = loop[(i + 1) % loop.size()];
      segments.push_back({{p, q}});
      if(upper == 0) planes.push_back(internal::cone_plane(p, q, apex));
    }
  }
}

// The plane through the segment s on a side wall of a rectangular problem whose slope across the segment, towards
// the inside, is about `world_slope` (sloped_pencil_plane() in lattice units of the wall's inward axis).
inline Lattice_plane_3 wall_pencil_plane_3(const Surface_problem_3& problem,
                                           const std::array<std::array<std::int64_t, 3>, 2>& s, double world_slope)
{
  const std::int64_t L = Plane_arrangement_3::lattice_size;
  const bool x_wall = s[0][0] == s[1][0] && (s[0][0] == 0 || s[0][0] == L);
  const double h = x_wall ? problem.domain.xmax() - problem.domain.xmin() : problem.domain.ymax() - problem.domain.ymin();
  return sloped_pencil_plane(s[0], s[1], world_slope * h / (problem.zmax - problem.zmin));
}

// surface_planes_3() after its checks (problem, options and n <= surface_max_planes_3()); plane selection draws
// up to n + pencils planes here to replace some of its n.
inline std::vector<Lattice_plane_3> draw_surface_planes_3(const Surface_problem_3& problem, std::size_t n,
                                                          const Surface_plane_options_3& options)
{
  std::mt19937_64 rng(options.seed);
  if(problem.is_polygonal()) return internal::polygon_surface_planes_3(problem, n, options, rng);
  std::vector<std::array<std::array<std::int64_t, 3>, 2>> segments;
  std::vector<Lattice_plane_3> planes;
  rectangle_boundary_cone_3(problem, segments, planes);
  const std::size_t pencils = surface_pencil_count_3(problem, n, options);
  std::uniform_real_distribution<double> slope(-options.max_slope, options.max_slope);
  for(std::size_t i = planes.size(); i < pencils; ++i) {
    const auto& s = segments[i % segments.size()];
    if(options.distribution == Plane_distribution_3::slope_limited)
      planes.push_back(internal::wall_pencil_plane_3(problem, s, slope(rng)));
    else
      planes.push_back(internal::pencil_plane(s[0], s[1], rng));
  }
  internal::add_random_surface_planes_3(problem, n, options, rng, planes);
  return planes;
}

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_SURFACE_PLANES_3_H
