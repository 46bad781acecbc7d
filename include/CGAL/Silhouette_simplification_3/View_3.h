// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A viewpoint for silhouette extraction (perspective eye point or orthographic direction) and the
// exact front-facing predicate that decides, per triangle, on which side of the silhouette it lies.

#ifndef CGAL_SILHOUETTE_SIMPLIFICATION_3_VIEW_3_H
#define CGAL_SILHOUETTE_SIMPLIFICATION_3_VIEW_3_H

#include <CGAL/Interval_nt.h>
#include <CGAL/Gmpq.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <stdexcept>

namespace CGAL {
namespace Silhouette_simplification_3 {
namespace internal {

// The sign of det[q - p; r - p; d] computed exactly from the double coordinates (differences included).
inline int exact_sign_of_det3_differences(const double p[3], const double q[3], const double r[3], const double d[3])
{
  {
    typedef CGAL::Interval_nt<false> I;
    CGAL::Protect_FPU_rounding<true> protect;
    I u[3], v[3], w[3];
    for(int i = 0; i < 3; ++i) { u[i] = I(q[i]) - I(p[i]); v[i] = I(r[i]) - I(p[i]); w[i] = I(d[i]); }
    const I x = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
    if(x.inf() > 0) return 1;
    if(x.sup() < 0) return -1;
  }
  typedef CGAL::Gmpq Q;
  Q u[3], v[3], w[3];
  for(int i = 0; i < 3; ++i) { u[i] = Q(q[i]) - Q(p[i]); v[i] = Q(r[i]) - Q(p[i]); w[i] = Q(d[i]); }
  const Q x = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
  return CGAL::sign(x);
}

} // namespace internal

/*!
  \ingroup PkgSilhouetteSimplification3Ref
  \brief A viewpoint: a perspective eye point, or an orthographic viewing direction.

  A triangle `(p, q, r)` (counter-clockwise seen from outside, as in every CGAL face graph) is
  *front-facing* when the eye lies strictly on the positive side of its supporting plane
  (perspective: `orientation(p, q, r, eye) == POSITIVE`; orthographic: `det[q-p, r-p, -direction] > 0`,
  i.e. the outward normal points against the viewing direction). Every other triangle is back-facing:
  triangles seen edge-on, triangles whose plane contains the eye (e.g. an eye on the surface) and
  degenerate (zero-area) triangles. The predicate is exact (the kernel's `Orientation_3` for
  perspective views; an interval filter with an exact rational fallback on the double coordinates for
  orthographic views), so the classification depends only on the triangle and the view, never on the
  mesh data structure or on the vertex the face starts at.

  \tparam K a CGAL kernel
*/
template <class K>
class View_3
{
public:
  typedef typename K::Point_3 Point_3;
  typedef typename K::Vector_3 Vector_3;

  /// A perspective view from the eye point `eye`.
  static View_3 perspective(const Point_3& eye)
  {
    View_3 v;
    v.perspective_ = true;
    v.eye_ = eye;
    return v;
  }

  /// An orthographic view looking along `direction` (from the viewer towards the scene).
  /// \throws std::invalid_argument when `direction` is the null vector or not finite
  static View_3 orthographic(const Vector_3& direction)
  {
    const double x = CGAL::to_double(direction.x()), y = CGAL::to_double(direction.y()), z = CGAL::to_double(direction.z());
    if(!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z)) || (x == 0 && y == 0 && z == 0))
      throw std::invalid_argument("MDCS: Silhouette_simplification_3::View_3::orthographic: the viewing direction "
                                  "must be a finite non-null vector");
    View_3 v;
    v.perspective_ = false;
    v.direction_ = direction;
    return v;
  }

  View_3() : perspective_(true), eye_(0, 0, 10), direction_(0, 0, -1) {}

  bool is_perspective() const { return perspective_; }
  const Point_3& eye() const { return eye_; }
  const Vector_3& direction() const { return direction_; }

  /// Whether the triangle `(p, q, r)` faces the viewer (exact; see the class description).
  bool is_front_facing(const Point_3& p, const Point_3& q, const Point_3& r) const
  {
    if(perspective_)
      return typename K::Orientation_3()(p, q, r, eye_) == CGAL::POSITIVE;
    const double a[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    const double b[3] = {CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())};
    const double c[3] = {CGAL::to_double(r.x()), CGAL::to_double(r.y()), CGAL::to_double(r.z())};
    const double d[3] = {-CGAL::to_double(direction_.x()), -CGAL::to_double(direction_.y()),
                         -CGAL::to_double(direction_.z())};
    return internal::exact_sign_of_det3_differences(a, b, c, d) > 0;
  }

private:
  bool perspective_;
  Point_3 eye_;
  Vector_3 direction_;
};

} // namespace Silhouette_simplification_3
} // namespace CGAL

#endif // CGAL_SILHOUETTE_SIMPLIFICATION_3_VIEW_3_H
