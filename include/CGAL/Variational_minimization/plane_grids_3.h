// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The regular plane grid for bivariate problems (thesis ch. 2.5.3): the plane analogue of the line grid C_n^pl,
// a deterministic plane source beside the random ones of surface_planes_3.h.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_PLANE_GRIDS_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_PLANE_GRIDS_3_H

#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/// How `regular_surface_planes_3()` lays out its grid.
struct Regular_surface_plane_options_3
{
  /// The largest gradient component |A|, |B| (world units) of the grid's planes: finite, > 0 and at most
  /// `surface_max_slope_3(problem)`.
  double max_slope = 2;
  /// m: the planes of one gradient are spaced (zmax - zmin) / m apart in height; 0 means m = n.
  std::size_t offset_steps = 0;
};

/// \ingroup PkgVariationalMinimizationSurfaces
/// The largest grid resolution n of `regular_surface_planes_3()`: 63 (the (2n + 1)^2 gradients of a larger n alone
/// exceed `surface_max_planes_3()`).
inline std::size_t regular_surface_max_steps_3() { return 63; }

namespace internal {

// The layout of the regular grid in the lattice of Plane_arrangement_3: plane (i, j, k) is
// -i step_a X - j step_b Y + c Z + d = 0 through (L/2, L/2, L/2 + k dz). Integer steps keep the gradients exactly
// regular and the grid exactly symmetric about the centre of the box.
struct Regular_plane_grid_layout_3
{
  std::int64_t n = 0, step_a = 0, step_b = 0, c = 0, dz = 0;

  Lattice_plane_3 plane(std::int64_t i, std::int64_t j, std::int64_t k) const
  {
    const std::int64_t h = Plane_arrangement_3::lattice_size / 2;
    Lattice_plane_3 p;
    p.a = -i * step_a;
    p.b = -j * step_b;
    p.c = c;
    p.d = -(p.a * h + p.b * h + c * (h + k * dz));
    return normalized_plane(p);
  }
};

// Whether the plane crosses the open lattice box: its value is negative at one corner and positive at another.
inline bool plane_meets_open_box_3(const Lattice_plane_3& p)
{
  const std::int64_t L = Plane_arrangement_3::lattice_size;
  bool negative = false, positive = false;
  for(int corner = 0; corner < 8; ++corner) {
    const std::int64_t v = p.a * ((corner & 1) ? L : 0) + p.b * ((corner & 2) ? L : 0) + p.c * ((corner & 4) ? L : 0) + p.d;
    negative = negative || v < 0;
    positive = positive || v > 0;
  }
  return negative && positive;
}

inline Regular_plane_grid_layout_3 regular_plane_grid_layout_3(const Surface_problem_3& problem, std::size_t n,
                                                               const Regular_surface_plane_options_3& options)
{
  const char* who = "MDCS: regular_surface_planes_3: ";
  problem.validate();
  if(problem.is_polygonal())
    throw std::invalid_argument(std::string(who) + "the regular grid is defined on a rectangular domain only (use "
                                "surface_planes_3() on a polygon)");
  if(n < 1) throw std::invalid_argument(std::string(who) + "n must be at least 1");
  if(n > regular_surface_max_steps_3())
    throw std::invalid_argument(std::string(who) + "n = " + std::to_string(n) + " is too large: at most " +
                                std::to_string(regular_surface_max_steps_3()) + " ((2n + 1)^2 gradients, at most " +
                                std::to_string(surface_max_planes_3()) + " planes)");
  const std::size_t m = options.offset_steps == 0 ? n : options.offset_steps;
  if(m > surface_max_planes_3())
    throw std::invalid_argument(std::string(who) + "offset_steps = " + std::to_string(m) + " is too large: at most " +
                                std::to_string(surface_max_planes_3()) + " planes");
  const double steepest = surface_max_slope_3(problem);
  if(!(options.max_slope > 0) || !std::isfinite(options.max_slope) || options.max_slope > steepest) {
    std::ostringstream o;
    o << who << "max_slope must be finite, > 0 and at most " << steepest << " (it is " << options.max_slope << ")";
    throw std::invalid_argument(o.str());
  }
  // The steepest lattice slopes dZ/dX and dZ/dY; the common Z coefficient c keeps the normals within 2^20.
  const double zr = problem.zmax - problem.zmin;
  const double tx = options.max_slope * (problem.domain.xmax() - problem.domain.xmin()) / zr,
               ty = options.max_slope * (problem.domain.ymax() - problem.domain.ymin()) / zr;
  const double unit = double(std::int64_t(1) << 20);
  Regular_plane_grid_layout_3 g;
  g.n = std::int64_t(n);
  g.c = std::llround(unit / (std::max)({1.0, tx, ty}));
  g.step_a = std::llround(tx * double(g.c) / double(n));
  g.step_b = std::llround(ty * double(g.c) / double(n));
  // A gradient step of fewer than 2^10 lattice units would round the gradients by more than 0.1%.
  if(g.step_a < 1024 || g.step_b < 1024) {
    std::ostringstream o;
    o << who << "max_slope = " << options.max_slope << " is too small for n = " << n << " in the lattice of the "
      << "arrangement (its gradient steps would round by more than 0.1%)";
    throw std::invalid_argument(o.str());
  }
  g.dz = std::llround(double(Plane_arrangement_3::lattice_size) / double(m));
  return g;
}

// Calls f(plane) for every plane of the grid that crosses the open box, gradient by gradient (i, then j, from -n to
// n), heights from the centre outwards; stops early and returns false once f returns false.
template <class F>
bool for_each_regular_grid_plane_3(const Regular_plane_grid_layout_3& g, F f)
{
  for(std::int64_t i = -g.n; i <= g.n; ++i)
    for(std::int64_t j = -g.n; j <= g.n; ++j)
      for(std::int64_t direction : {1, -1})
        // The heights at the centre that keep the plane in the box form one range about k = 0 (the plane through
        // the centre of the box always crosses it).
        for(std::int64_t k = (direction == 1 ? 0 : -1);; k += direction) {
          const Lattice_plane_3 p = g.plane(i, j, k);
          if(!plane_meets_open_box_3(p)) break;
          if(!f(p)) return false;
        }
  return true;
}

} // namespace internal

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief The regular plane grid G_n for `problem` (thesis ch. 2.5.3: the grid of hyperplanes in Ω x [zmin, zmax]),
  the plane analogue of the line grid C_n^pl (`regular_grid_lines_2()`), on a rectangular domain.

  C_n^pl is the set of lines with slopes on a regular set (k / n, |k| <= n^2) through the points of a regular
  grid. The thesis gives no definition in 3D; G_n takes the same two regular families, with the size decoupled
  from the slope range (the literal analogue, gradients k / n up to n in both axes through the points of an
  n x n x n^2 grid, has of the order of n^6 planes: thousands already at n = 2, beyond any arrangement):

  - the boundary planes, first: the boundary cone of `surface_planes_3()` (one plane per boundary segment through
    the apex, which makes the problem feasible), then through every boundary segment the pencil planes whose slope
    across the segment, towards the inside, is `max_slope * t / n`, t = -n..n (on both boundary curves of a relaxed
    problem);
  - the interior planes z = A x + B y + C with gradients (A, B) = `max_slope` (i, j) / n, |i|, |j| <= n, and,
    for each gradient, heights at the centre of Ω spaced (zmax - zmin) / m apart, k = 0, +-1, +-2, ..., every one
    whose plane crosses the open box (m = `options.offset_steps`, default n).

  In the lattice of `Plane_arrangement_3` the interior gradients are integer multiples of one step per axis and
  the heights integer multiples of one spacing, so the parallel families are exactly parallel, the spacing is
  exactly regular, and the set of interior planes is exactly symmetric about the centre of the box (x -> -x,
  y -> -y, z -> -z); the world gradients and spacing are those asked within 0.1% (rounding to the lattice). Equal
  planes are listed once. The count grows like (2n + 1)^2 m (1 + max_slope (width + height) / (2 (zmax - zmin)))
  for the interior, plus (2n + 2) planes per boundary segment. The pencil slopes are rounded like those of the
  slope-limited `surface_planes_3()`: to steps of (zmax - zmin) / (64 w), w the side length across the wall, and
  clamped to 8 (zmax - zmin) / w; pencils that round to the same plane are listed once.

  \throws std::invalid_argument if the problem is invalid or polygonal, n < 1 or n > `regular_surface_max_steps_3()`,
  `max_slope` is not finite, not > 0, above `surface_max_slope_3(problem)` or too small for the lattice, or the grid
  would have more than `surface_max_planes_3()` planes (checked while the list is built, which never grows past
  that bound).
*/
inline std::vector<Lattice_plane_3>
regular_surface_planes_3(const Surface_problem_3& problem, std::size_t n,
                         const Regular_surface_plane_options_3& options = Regular_surface_plane_options_3())
{
  const internal::Regular_plane_grid_layout_3 g = internal::regular_plane_grid_layout_3(problem, n, options);
  std::vector<std::array<std::array<std::int64_t, 3>, 2>> segments;
  std::vector<Lattice_plane_3> planes;
  internal::rectangle_boundary_cone_3(problem, segments, planes);
  for(const auto& s : segments)
    for(std::int64_t t = -std::int64_t(n); t <= std::int64_t(n); ++t)
      planes.push_back(internal::wall_pencil_plane_3(problem, s, options.max_slope * double(t) / double(n)));

  // Equal planes once (a pencil can coincide with another segment's or with a grid plane); the bound is checked
  // while the grid is enumerated, so an absurd size never grows the list.
  std::set<std::tuple<std::int64_t, std::int64_t, std::int64_t, std::int64_t>> seen;
  std::vector<Lattice_plane_3> unique;
  auto add = [&](const Lattice_plane_3& p) {
    if(!seen.insert(std::make_tuple(p.a, p.b, p.c, p.d)).second) return true;
    if(unique.size() == surface_max_planes_3()) return false;
    unique.push_back(p);
    return true;
  };
  bool within_bound = true;
  for(const Lattice_plane_3& p : planes) within_bound = within_bound && add(p);
  if(!within_bound || !internal::for_each_regular_grid_plane_3(g, add))
    throw std::invalid_argument("MDCS: regular_surface_planes_3: the grid n = " + std::to_string(n) + ", m = " +
                                std::to_string(options.offset_steps == 0 ? n : options.offset_steps) +
                                " has more than " + std::to_string(surface_max_planes_3()) + " planes");
  return unique;
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_PLANE_GRIDS_3_H
