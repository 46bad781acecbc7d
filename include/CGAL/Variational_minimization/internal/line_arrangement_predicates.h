// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Exact predicates and careful constructions on lines given by two points with double coordinates,
// used by Line_arrangement_2. Every predicate first runs a floating-point filter with a static error
// bound (a handful of flops) and falls back to exact arithmetic on the input doubles only when the
// filter cannot decide. The exact fallback is Mpzf (exact +,-,* on doubles) where available.

#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_LINE_ARRANGEMENT_PREDICATES_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_LINE_ARRANGEMENT_PREDICATES_H

#include <CGAL/Interval_nt.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Mpzf.h>
#include <CGAL/assertions.h>
#include <CGAL/enum.h>

#include <mpfr.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

#ifdef CGAL_HAS_MPZF
typedef CGAL::Mpzf Arr_exact_nt;
#else
typedef CGAL::Gmpq Arr_exact_nt;
#endif

// A supporting line of the arrangement: the line through p and q, stored with p before q in the
// (x, then y) lexicographic order, so that the parameter t of p + t (q - p) grows left to right, or
// bottom to top on a vertical line. The normalization only swaps the two input points, so the line
// is still exactly the one through two doubles. dx, dy are the rounded differences; they feed the
// filters only, never a decision by themselves.
struct Arr_line
{
  double px, py, qx, qy;
  double dx, dy;
};

inline Arr_line make_arr_line(double px, double py, double qx, double qy)
{
  if(qx < px || (qx == px && qy < py)) {
    std::swap(px, qx);
    std::swap(py, qy);
  }
  Arr_line l;
  l.px = px; l.py = py; l.qx = qx; l.qy = qy;
  l.dx = qx - px;
  l.dy = qy - py;
  return l;
}

inline bool is_vertical(const Arr_line& l) { return l.px == l.qx; }   // exact: the doubles themselves
inline bool is_horizontal(const Arr_line& l) { return l.py == l.qy; }

// Constants of the static filters. u is the unit roundoff 2^-53.
// A difference of two doubles followed by a product and a subtraction of two such products carries
// a relative error of at most gamma_4 = 4u/(1-4u) with respect to the sum of the magnitudes of the
// two products; we use 8u to also cover the rounding of the bound itself. The absolute term covers
// gradual underflow (each product loses at most 2^-1075), far above it so it can never matter unless
// the data are themselves around 1e-150.
constexpr double arr_u = 1.0 / 9007199254740992.0;   // 2^-53
constexpr double arr_product_bound = 8 * arr_u;
constexpr double arr_tiny = 1e-300;
constexpr double arr_inflate = 1 + 64 * arr_u;

// The parameter along `base` of its intersection with `other`: base.p + t (base.q - base.p) lies on
// `other` for t = N / D with
//   N = cross(d_o, p_o - p_b),  D = cross(d_o, d_b).
// On success, the exact t lies in [lo, hi]. Fails (returns false) when the sign of D is not certain
// (parallel or nearly parallel lines) or on overflow.
inline bool approx_param(const Arr_line& base, const Arr_line& other, double& lo, double& hi)
{
  const double c = other.px - base.px, e = other.py - base.py;
  const double p1 = other.dx * e, p2 = other.dy * c;
  const double p3 = other.dx * base.dy, p4 = other.dy * base.dx;
  const double n = p1 - p2, d = p3 - p4;
  const double en = arr_product_bound * (std::abs(p1) + std::abs(p2)) + arr_tiny;
  const double ed = arr_product_bound * (std::abs(p3) + std::abs(p4)) + arr_tiny;
  const double ad = std::abs(d);
  // The negated comparisons also reject NaN.
  if(!(ad > ed) || !(en <= DBL_MAX))
    return false;
  const double t = n / d;
  const double at = std::abs(t);
  // |N/D - n/d| <= (en + |n/d| ed) / (|d| - ed); plus the rounding of n/d and of t -+ err.
  const double err = ((en + at * ed) / (ad - ed)) * arr_inflate + 4 * arr_u * at + arr_tiny;
  if(!(err <= DBL_MAX))
    return false;
  lo = t - err;
  hi = t + err;
  return true;
}

template <class NT>
void exact_param(const Arr_line& base, const Arr_line& other, NT& n, NT& d)
{
  const NT odx = NT(other.qx) - NT(other.px), ody = NT(other.qy) - NT(other.py);
  const NT bdx = NT(base.qx) - NT(base.px), bdy = NT(base.qy) - NT(base.py);
  const NT c = NT(other.px) - NT(base.px), e = NT(other.py) - NT(base.py);
  n = odx * e - ody * c;
  d = odx * bdy - ody * bdx;
}

// Exact sign of D = cross(d_other, d_base) above: zero iff the lines are parallel (or equal).
inline CGAL::Sign exact_cross_sign(const Arr_line& base, const Arr_line& other)
{
  const double p3 = other.dx * base.dy, p4 = other.dy * base.dx;
  const double d = p3 - p4;
  const double ed = arr_product_bound * (std::abs(p3) + std::abs(p4)) + arr_tiny;
  if(ed <= DBL_MAX) {
    if(d > ed) return CGAL::POSITIVE;
    if(d < -ed) return CGAL::NEGATIVE;
  }
  typedef Arr_exact_nt NT;
  const NT odx = NT(other.qx) - NT(other.px), ody = NT(other.qy) - NT(other.py);
  const NT bdx = NT(base.qx) - NT(base.px), bdy = NT(base.qy) - NT(base.py);
  return CGAL::sign(odx * bdy - ody * bdx);
}

// Tight enclosing interval of the parameter, computed exactly when the filter fails.
// Precondition: the lines are not parallel.
inline void param_interval(const Arr_line& base, const Arr_line& other, double& lo, double& hi)
{
  if(approx_param(base, other, lo, hi))
    return;
  Arr_exact_nt n, d;
  exact_param(base, other, n, d);
  CGAL_assertion(CGAL::sign(d) != CGAL::ZERO);
  CGAL::Protect_FPU_rounding<true> protection;
  typedef CGAL::Interval_nt<false> I;
  const I t = I(CGAL::to_interval(n)) / I(CGAL::to_interval(d));
  lo = t.inf();
  hi = t.sup();
}

// Exact comparison of the parameters along `base` of its intersections with a and b.
// Precondition: neither a nor b is parallel to base.
inline CGAL::Comparison_result compare_params_exact(const Arr_line& base, const Arr_line& a, const Arr_line& b)
{
  Arr_exact_nt na, da, nb, db;
  exact_param(base, a, na, da);
  exact_param(base, b, nb, db);
  const CGAL::Sign s = CGAL::sign(na * db - nb * da);
  return CGAL::Comparison_result(int(s) * int(CGAL::sign(da)) * int(CGAL::sign(db)));
}

// The same, filtered.
inline CGAL::Comparison_result compare_params(const Arr_line& base, const Arr_line& a, const Arr_line& b)
{
  double alo, ahi, blo, bhi;
  if(approx_param(base, a, alo, ahi) && approx_param(base, b, blo, bhi)) {
    if(ahi < blo) return CGAL::SMALLER;
    if(bhi < alo) return CGAL::LARGER;
  }
  return compare_params_exact(base, a, b);
}

// Slope order of normalized lines: the direction angle lies in (-90, 90] degrees; vertical lines
// come last. slope(a) < slope(b) iff cross(d_a, d_b) > 0, and exact_cross_sign(a, b) is the sign of
// cross(d_b, d_a).
inline CGAL::Comparison_result compare_slopes(const Arr_line& a, const Arr_line& b)
{
  return CGAL::Comparison_result(int(exact_cross_sign(a, b)));
}

// Rounds the exact rational num/den to the nearest double.
inline double nearest_double(const Arr_exact_nt& num, const Arr_exact_nt& den)
{
  const CGAL::Gmpq q = CGAL::Gmpq(num) / CGAL::Gmpq(den);
  mpfr_t r;
  mpfr_init2(r, 53);
  mpfr_set_q(r, q.mpq(), MPFR_RNDN);
  const double result = mpfr_get_d(r, MPFR_RNDN);
  mpfr_clear(r);
  return result;
}

// One coordinate of the intersection of base and other:
//   x = base.px + t * (base.qx - base.px), t = N / D.
// The double formula is kept when its error bound is below accuracy * (|x| + scale); otherwise the
// coordinate is rounded from its exact value. Precondition: the lines are not parallel.
constexpr double arr_point_accuracy = 1.0 / 4398046511104.0;   // 2^-42

inline void intersection_point(const Arr_line& base, const Arr_line& other, double scale_x, double scale_y,
                               double& x, double& y)
{
  double lo, hi;
  bool x_ok = false, y_ok = false;
  if(approx_param(base, other, lo, hi)) {
    const double t = 0.5 * (lo + hi);
    const double et = 0.5 * (hi - lo) * arr_inflate + 2 * arr_u * std::abs(t) + arr_tiny;
    const double tx = t * base.dx, ty = t * base.dy;
    x = base.px + tx;
    y = base.py + ty;
    const double ex = (et * std::abs(base.dx) + 6 * arr_u * std::abs(tx)) * arr_inflate + 2 * arr_u * std::abs(x);
    const double ey = (et * std::abs(base.dy) + 6 * arr_u * std::abs(ty)) * arr_inflate + 2 * arr_u * std::abs(y);
    x_ok = ex <= arr_point_accuracy * (std::abs(x) + scale_x);
    y_ok = ey <= arr_point_accuracy * (std::abs(y) + scale_y);
  }
  if(x_ok && y_ok)
    return;
  typedef Arr_exact_nt NT;
  NT n, d;
  exact_param(base, other, n, d);
  CGAL_assertion(CGAL::sign(d) != CGAL::ZERO);
  if(!x_ok)
    x = nearest_double(NT(base.px) * d + n * (NT(base.qx) - NT(base.px)), d);
  if(!y_ok)
    y = nearest_double(NT(base.py) * d + n * (NT(base.qy) - NT(base.py)), d);
}

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_LINE_ARRANGEMENT_PREDICATES_H
