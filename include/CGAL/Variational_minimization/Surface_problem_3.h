// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The bivariate variational problem: its domain, range of values and boundary condition, and the map between its
// world coordinates and the integer lattice of Plane_arrangement_3.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_SURFACE_PROBLEM_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_SURFACE_PROBLEM_3_H

#include <CGAL/Bbox_2.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/internal/surface_polygon_predicates_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief A bivariate problem: minimise F(f) = ∬_Ω G(f, f_x, f_y, x, y) dx dy over functions
  f : Ω -> [zmin, zmax] with a boundary condition on ∂Ω.

  Ω is the rectangle `domain`, or the simple polygon `domain_polygon` when that is not empty (set it with
  `set_domain_polygon()`, which makes `domain` its bounding box). The polygon's vertices are rounded to the grid
  of 1/256 of its bounding box (the lattice points whose X and Y are multiples of 2^8, which keeps the planes
  through them within the coefficient bounds); the discrete problem, `domain_area()` and every check use the
  rounded polygon. The boundary condition is either *fixed*, f = g on ∂Ω (`lower_boundary = g`,
  `upper_boundary` empty), or *relaxed*, g0 <= f <= g1 on ∂Ω (both set). The boundary curves are sampled at
  `boundary_segments_per_side + 1` points per side (at most 257, at multiples of 1/256 of the side; on a polygon,
  per edge, at the grid points of the edge, so an edge from (0, 0) to (3, 1) in grid units has only its two
  endpoints) and rounded to the lattice of the arrangement: the discrete problem uses these piecewise linear curves (their vertices are
  within `(zmax - zmin) / 2^17` of g).

  The box Ω x [zmin, zmax] is mapped affinely onto the lattice box [0, L]^3 of `Plane_arrangement_3`.
*/
struct Surface_problem_3
{
  CGAL::Bbox_2 domain = CGAL::Bbox_2(0, 0, 1, 1);
  /// A simple polygon (either orientation) instead of the rectangle; empty: the rectangle `domain`.
  std::vector<std::array<double, 2>> domain_polygon;
  double zmin = 0;
  double zmax = 1;
  std::function<double(double, double)> lower_boundary;
  std::function<double(double, double)> upper_boundary;
  int boundary_segments_per_side = 8;

  bool is_relaxed() const { return bool(upper_boundary); }
  bool is_polygonal() const { return !domain_polygon.empty(); }

  /// Makes Ω the polygon `vertices` and `domain` its bounding box (checked by `validate()`).
  void set_domain_polygon(const std::vector<std::array<double, 2>>& vertices)
  {
    domain_polygon = vertices;
    if(vertices.empty()) return;
    double x0 = vertices[0][0], x1 = x0, y0 = vertices[0][1], y1 = y0;
    for(const auto& v : vertices) {
      x0 = (std::min)(x0, v[0]); x1 = (std::max)(x1, v[0]);
      y0 = (std::min)(y0, v[1]); y1 = (std::max)(y1, v[1]);
    }
    domain = CGAL::Bbox_2(x0, y0, x1, y1);
  }

  /// The polygon's vertices in lattice coordinates (multiples of 2^8), counter-clockwise, as `validate()` checks
  /// them; for a rectangle, its four corners.
  std::vector<std::array<std::int64_t, 2>> lattice_polygon() const
  {
    const std::int64_t L = Plane_arrangement_3::lattice_size;
    if(!is_polygonal()) return {{{0, 0}}, {{L, 0}}, {{L, L}}, {{0, L}}};
    std::vector<std::array<std::int64_t, 2>> out = raw_lattice_polygon();
    if(internal::lattice_polygon_area2(out) < 0) std::reverse(out.begin(), out.end());
    return out;
  }

  /// Throws `std::invalid_argument` with a message saying what is wrong.
  void validate() const
  {
    auto fail = [](const std::string& what) { throw std::invalid_argument("MDCS: invalid surface problem: " + what); };
    if(is_polygonal()) validate_polygon(fail);
    const double v[6] = {domain.xmin(), domain.xmax(), domain.ymin(), domain.ymax(), zmin, zmax};
    for(double c : v)
      if(!std::isfinite(c)) fail("the domain and the range of values must be finite");
    if(!(domain.xmin() < domain.xmax()) || !(domain.ymin() < domain.ymax()))
      fail("the domain rectangle is empty (need xmin < xmax and ymin < ymax)");
    if(!(zmin < zmax)) fail("the range of values is empty (need zmin < zmax)");
    if(!std::isfinite(domain.xmax() - domain.xmin()) || !std::isfinite(domain.ymax() - domain.ymin()) ||
       !std::isfinite(zmax - zmin))
      fail("the domain's width and height and the range zmax - zmin must be finite (they overflow)");
    if(!lower_boundary) fail("no boundary function is given (lower_boundary is empty)");
    if(boundary_segments_per_side < 1 || boundary_segments_per_side > 256)
      fail("boundary_segments_per_side must be in [1, 256]");
    for(const std::array<double, 2>& p : boundary_samples()) {
      const double lo = lower_boundary(p[0], p[1]);
      const double hi = upper_boundary ? upper_boundary(p[0], p[1]) : lo;
      std::ostringstream s;
      s << "at the boundary point (" << p[0] << ", " << p[1] << ") ";
      if(!std::isfinite(lo) || !std::isfinite(hi)) fail(s.str() + "the boundary data is not finite");
      if(lo < zmin || hi > zmax) {
        s << "the boundary data [" << lo << ", " << hi << "] lies outside the range of values [" << zmin << ", "
          << zmax << "]";
        fail(s.str());
      }
      if(lo > hi) fail(s.str() + "the lower boundary lies above the upper boundary");
    }
  }

  /// The boundary sample points of Ω, counter-clockwise from (xmin, ymin), `4 * boundary_segments_per_side` of them
  /// (on a polygon: from its first counter-clockwise vertex, at most `boundary_segments_per_side` per edge).
  std::vector<std::array<double, 2>> boundary_samples() const
  {
    std::vector<std::array<double, 2>> out;
    if(is_polygonal()) {
      for(const auto& q : polygon_samples()) {
        const std::array<double, 3> w = to_world({{double(q[0]), double(q[1]), 0.0}});
        out.push_back({{w[0], w[1]}});
      }
      return out;
    }
    const int k = boundary_segments_per_side;
    const std::array<double, 2> corner[5] = {{{domain.xmin(), domain.ymin()}}, {{domain.xmax(), domain.ymin()}},
                                             {{domain.xmax(), domain.ymax()}}, {{domain.xmin(), domain.ymax()}},
                                             {{domain.xmin(), domain.ymin()}}};
    for(int s = 0; s < 4; ++s)
      for(int i = 0; i < k; ++i) {
        // The lattice position first, so that the sample is exactly a lattice point of the side.
        const std::int64_t t = lattice_step(i, k);
        const double u = double(t) / double(Plane_arrangement_3::lattice_size);
        out.push_back({{corner[s][0] + u * (corner[s + 1][0] - corner[s][0]),
                        corner[s][1] + u * (corner[s + 1][1] - corner[s][1])}});
      }
    return out;
  }

  /// The lattice loop of the lower (`upper == false`) or upper boundary curve: lattice points (X, Y, Z),
  /// counter-clockwise, one per boundary sample.
  std::vector<std::array<std::int64_t, 3>> boundary_loop(bool upper) const
  {
    const std::int64_t L = Plane_arrangement_3::lattice_size;
    const int k = boundary_segments_per_side;
    std::vector<std::array<std::int64_t, 3>> out;
    const std::vector<std::array<double, 2>> samples = boundary_samples();
    const std::vector<std::array<std::int64_t, 3>> polygonal = is_polygonal() ? polygon_samples()
                                                                              : std::vector<std::array<std::int64_t, 3>>();
    for(std::size_t i = 0; i < samples.size(); ++i) {
      int s = int(i) / k;
      const std::int64_t t = lattice_step(int(i) % k, k);
      std::int64_t X = 0, Y = 0;
      if(is_polygonal()) { X = polygonal[i][0]; Y = polygonal[i][1]; s = -1; }
      switch(s) {
      case -1: break;
      case 0: X = t; Y = 0; break;
      case 1: X = L; Y = t; break;
      case 2: X = L - t; Y = L; break;
      default: X = 0; Y = L - t; break;
      }
      const auto& g = (upper && upper_boundary) ? upper_boundary : lower_boundary;
      const double z = g(samples[i][0], samples[i][1]);
      std::int64_t Z = std::llround((z - zmin) / (zmax - zmin) * double(L));
      Z = (std::max)(std::int64_t(0), (std::min)(L, Z));
      out.push_back({{X, Y, Z}});
    }
    return out;
  }

  /// World coordinates of a lattice point.
  std::array<double, 3> to_world(const std::array<double, 3>& p) const
  {
    const double L = double(Plane_arrangement_3::lattice_size);
    return {{domain.xmin() + p[0] / L * (domain.xmax() - domain.xmin()),
             domain.ymin() + p[1] / L * (domain.ymax() - domain.ymin()), zmin + p[2] / L * (zmax - zmin)}};
  }

  /*!
    The world plane z = A x + B y + C of a non-vertical lattice plane (c != 0), as {A, B, C}.
  */
  std::array<double, 3> world_plane(const Lattice_plane_3& p) const
  {
    const double L = double(Plane_arrangement_3::lattice_size);
    const double sx = (domain.xmax() - domain.xmin()) / L, sy = (domain.ymax() - domain.ymin()) / L,
                 sz = (zmax - zmin) / L;
    const double a = double(p.a), b = double(p.b), c = double(p.c), d = double(p.d);
    const double A = -sz * a / (c * sx), B = -sz * b / (c * sy);
    const double C = zmin - sz / c * (d - a * domain.xmin() / sx - b * domain.ymin() / sy);
    return {{A, B, C}};
  }

  /// The area of Ω (of the rounded polygon).
  double domain_area() const
  {
    const double box = (domain.xmax() - domain.xmin()) * (domain.ymax() - domain.ymin());
    if(!is_polygonal()) return box;
    const double L = double(Plane_arrangement_3::lattice_size);
    return double(internal::lattice_polygon_area2(lattice_polygon())) / (2 * L * L) * box;
  }

  /*!
    The boundary samples of a polygon in lattice coordinates: (X, Y, edge), counter-clockwise from the first vertex
    of `lattice_polygon()`; edge i runs from vertex i to vertex i + 1, its samples are the grid points of the edge
    (X, Y multiples of 2^8) nearest to `boundary_segments_per_side` equal steps, without repetitions.
  */
  std::vector<std::array<std::int64_t, 3>> polygon_samples() const
  {
    const std::vector<std::array<std::int64_t, 2>> poly = lattice_polygon();
    std::vector<std::array<std::int64_t, 3>> out;
    const std::int64_t k = boundary_segments_per_side;
    for(std::size_t e = 0; e < poly.size(); ++e) {
      const auto& a = poly[e];
      const auto& b = poly[(e + 1) % poly.size()];
      const std::int64_t dx = (b[0] - a[0]) / 256, dy = (b[1] - a[1]) / 256;
      const std::int64_t g = internal::gcd64(dx, dy); // the edge has g + 1 grid points
      std::int64_t last = -1;
      for(std::int64_t i = 0; i < k; ++i) {
        const std::int64_t j = (2 * i * g + k) / (2 * k); // round(i * g / k)
        if(j == last || j >= g) continue;                 // j = g is the next edge's first sample
        last = j;
        out.push_back({{a[0] + j * (dx / g) * 256, a[1] + j * (dy / g) * 256, std::int64_t(e)}});
      }
    }
    return out;
  }

private:
  template <class Fail>
  void validate_polygon(const Fail& fail) const
  {
    std::ostringstream s;
    if(domain_polygon.size() < 3) {
      s << "the domain polygon has " << domain_polygon.size() << " vertices; at least 3 are needed";
      fail(s.str());
    }
    if(domain_polygon.size() > 1024) fail("the domain polygon has more than 1024 vertices");
    for(std::size_t i = 0; i < domain_polygon.size(); ++i)
      if(!std::isfinite(domain_polygon[i][0]) || !std::isfinite(domain_polygon[i][1])) {
        s << "vertex " << i << " of the domain polygon is not finite";
        fail(s.str());
      }
    Surface_problem_3 box;
    box.set_domain_polygon(domain_polygon);
    if(!(box.domain == domain))
      fail("the domain rectangle must be the bounding box of the domain polygon (use set_domain_polygon())");
    if(!(domain.xmin() < domain.xmax()) || !(domain.ymin() < domain.ymax()))
      fail("the domain polygon has zero area (all its vertices lie on one line)");
    if(!std::isfinite(domain.xmax() - domain.xmin()) || !std::isfinite(domain.ymax() - domain.ymin()))
      fail("the domain polygon's bounding box is too large (its width or height overflows)");
    // The checks are exact, on the rounded lattice polygon (in input order).
    const std::vector<std::array<std::int64_t, 2>> p = raw_lattice_polygon();
    const std::size_t n = p.size();
    auto where = [&](std::size_t i) {
      std::ostringstream t;
      t << "vertex " << i << " (" << domain_polygon[i][0] << ", " << domain_polygon[i][1] << ")";
      return t.str();
    };
    const char* grid = " (after rounding the vertices to the grid of 1/256 of the bounding box)";
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t j = i + 1; j < n; ++j)
        if(p[i] == p[j]) fail(where(i) + " and " + where(j) + " of the domain polygon coincide" + grid);
    for(std::size_t i = 0; i < n; ++i) {
      const auto& a = p[(i + n - 1) % n];
      const auto& b = p[i];
      const auto& c = p[(i + 1) % n];
      if(internal::orient_2_lattice(a, b, c) == 0)
        fail(where(i) + " of the domain polygon is collinear with its two neighbours" + grid);
    }
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t j = i + 1; j < n; ++j) {
        if(j == i + 1 || (i == 0 && j == n - 1)) continue; // adjacent edges meet at their common vertex only
        if(internal::lattice_segments_meet(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n])) {
          std::ostringstream t;
          t << "the domain polygon is self-intersecting: edge " << i << " (from " << where(i) << ") meets edge " << j
            << " (from " << where(j) << ")" << grid;
          fail(t.str());
        }
      }
    if(internal::lattice_polygon_area2(p) == 0) fail("the domain polygon has zero area" + std::string(grid));
    // The triangulation of the boundary loop (surface_planes_3) is quadratic in the number of samples.
    if(polygon_samples().size() > 4096)
      fail("the domain polygon has more than 4096 boundary samples (vertices x boundary_segments_per_side)");
  }

  std::vector<std::array<std::int64_t, 2>> raw_lattice_polygon() const
  {
    std::vector<std::array<std::int64_t, 2>> out;
    const double w = domain.xmax() - domain.xmin(), h = domain.ymax() - domain.ymin();
    for(const auto& v : domain_polygon)
      out.push_back({{256 * std::llround((v[0] - domain.xmin()) / w * 256.0),
                      256 * std::llround((v[1] - domain.ymin()) / h * 256.0)}});
    return out;
  }

  // Boundary samples lie at multiples of 2^8 in X and Y, so that planes through two boundary samples and the apex of
  // the boundary cone keep their integer coefficients within the bounds of Lattice_plane_3.
  static std::int64_t lattice_step(int i, int k)
  {
    return 256 * std::llround(double(i) * double(Plane_arrangement_3::lattice_size / 256) / double(k));
  }
};

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_SURFACE_PROBLEM_3_H
