// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact predicates of the plane arrangement (BSP complex) of Plane_arrangement_3: planes with bounded integer
// coefficients, vertices as the intersection of three such planes, the side of a vertex with respect to a plane
// decided by a double filter with an exact 128-bit integer fallback.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_PLANE_ARRANGEMENT_PREDICATES_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_PLANE_ARRANGEMENT_PREDICATES_3_H

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Variational_minimization {

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  A plane `a X + b Y + c Z + d = 0` with integer coefficients in the lattice coordinates of a
  `Plane_arrangement_3` (the box `[0, L]^3`, `L = Plane_arrangement_3::lattice_size`).
  Bounds (checked): `|a|, |b|, |c| <= 2^25`, `|d| <= 3 * 2^41`, and `(a, b, c) != 0`. With these bounds every
  predicate of the arrangement is evaluated exactly in 128-bit integers.
*/
struct Lattice_plane_3
{
  std::int64_t a = 0, b = 0, c = 0, d = 0;
};

namespace internal {

__extension__ typedef __int128 Int128;

constexpr std::int64_t plane_normal_bound = std::int64_t(1) << 25;
constexpr std::int64_t plane_offset_bound = std::int64_t(3) << 41;

inline void check_lattice_plane(const Lattice_plane_3& p, std::size_t index)
{
  auto bad = [&](const char* what) {
    throw std::invalid_argument("MDCS: Plane_arrangement_3: plane " + std::to_string(index) + " (" +
                                std::to_string(p.a) + ", " + std::to_string(p.b) + ", " + std::to_string(p.c) +
                                ", " + std::to_string(p.d) + ") " + what);
  };
  if(p.a == 0 && p.b == 0 && p.c == 0) bad("has a zero normal");
  if(std::llabs(p.a) > plane_normal_bound || std::llabs(p.b) > plane_normal_bound ||
     std::llabs(p.c) > plane_normal_bound)
    bad("has a normal coefficient above 2^25 in absolute value");
  if(std::llabs(p.d) > plane_offset_bound) bad("has an offset above 3 * 2^41 in absolute value");
}

inline std::int64_t gcd64(std::int64_t a, std::int64_t b)
{
  a = std::llabs(a);
  b = std::llabs(b);
  while(b != 0) {
    const std::int64_t t = a % b;
    a = b;
    b = t;
  }
  return a;
}

// Divides by the gcd of the four coefficients and makes the first non-zero of (a, b, c) positive: two planes
// are the same set exactly when their normalised coefficients are equal.
inline Lattice_plane_3 normalized_plane(Lattice_plane_3 p)
{
  std::int64_t g = gcd64(gcd64(p.a, p.b), gcd64(p.c, p.d));
  if(g == 0) return p;
  const bool flip = p.a < 0 || (p.a == 0 && (p.b < 0 || (p.b == 0 && p.c < 0)));
  if(flip) g = -g;
  p.a /= g;
  p.b /= g;
  p.c /= g;
  p.d /= g;
  return p;
}

// The intersection point of three planes in homogeneous integer coordinates (X, Y, Z) = (nx, ny, nz) / den.
struct Exact_vertex_3
{
  Int128 nx, ny, nz, den;
};

inline Int128 det3(Int128 a1, Int128 b1, Int128 c1, Int128 a2, Int128 b2, Int128 c2, Int128 a3, Int128 b3,
                   Int128 c3)
{
  return a1 * (b2 * c3 - b3 * c2) - b1 * (a2 * c3 - a3 * c2) + c1 * (a2 * b3 - a3 * b2);
}

// Cramer's rule for a_i X + b_i Y + c_i Z = -d_i. den == 0 when the normals are dependent.
inline Exact_vertex_3 intersect_planes(const Lattice_plane_3& p, const Lattice_plane_3& q, const Lattice_plane_3& r)
{
  Exact_vertex_3 v;
  v.den = det3(p.a, p.b, p.c, q.a, q.b, q.c, r.a, r.b, r.c);
  v.nx = det3(-p.d, p.b, p.c, -q.d, q.b, q.c, -r.d, r.b, r.c);
  v.ny = det3(p.a, -p.d, p.c, q.a, -q.d, q.c, r.a, -r.d, r.c);
  v.nz = det3(p.a, p.b, -p.d, q.a, q.b, -q.d, r.a, r.b, -r.d);
  return v;
}

// Sign of the plane's left-hand side at the exact vertex: -1, 0, 1. Exact under the coefficient bounds
// (|value| < 2^124 before the sign of den is applied).
inline int exact_side(const Exact_vertex_3& v, const Lattice_plane_3& p)
{
  const Int128 value = Int128(p.a) * v.nx + Int128(p.b) * v.ny + Int128(p.c) * v.nz + Int128(p.d) * v.den;
  const int s = value > 0 ? 1 : (value < 0 ? -1 : 0);
  return v.den > 0 ? s : -s;
}

inline std::array<double, 3> approximate_point(const Exact_vertex_3& v)
{
  const double den = double(v.den);
  return {{double(v.nx) / den, double(v.ny) / den, double(v.nz) / den}};
}

// The double filter: the side from the approximate point when the value is clearly away from zero, 0 ("unsure")
// otherwise. The approximate point has relative error below 2^-50 in each coordinate (|coordinate| <= L).
inline int filtered_side(const std::array<double, 3>& x, const Lattice_plane_3& p, double lattice_size, bool& sure)
{
  const double a = double(p.a), b = double(p.b), c = double(p.c), d = double(p.d);
  const double value = a * x[0] + b * x[1] + c * x[2] + d;
  const double magnitude = std::abs(a * x[0]) + std::abs(b * x[1]) + std::abs(c * x[2]) + std::abs(d);
  const double bound = (std::abs(a) + std::abs(b) + std::abs(c)) * lattice_size * 0x1p-46 + magnitude * 0x1p-48;
  sure = std::abs(value) > bound;
  return value > 0 ? 1 : -1;
}

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_PLANE_ARRANGEMENT_PREDICATES_3_H
