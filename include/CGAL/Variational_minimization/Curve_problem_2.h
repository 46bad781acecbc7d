// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The univariate variational problem: its domain box and end conditions.

#ifndef CGAL_VARIATIONAL_MINIMIZATION_CURVE_PROBLEM_2_H
#define CGAL_VARIATIONAL_MINIMIZATION_CURVE_PROBLEM_2_H

#include <CGAL/Bbox_2.h>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/*!
  \brief The value allowed for the function at one end of the interval.

  A *fixed* condition f(a) = A has `low == high == A`; a *relaxed* condition A0 <= f(a) <= A1 has
  `low = A0 < high = A1`.
*/
struct End_condition
{
  double low = 0;
  double high = 0;

  static End_condition fixed(double value) { return End_condition{value, value}; }
  static End_condition range(double low, double high) { return End_condition{low, high}; }
  bool is_fixed() const { return low == high; }
};

/*!
  \brief A univariate problem: minimise F(f) = ∫_a^b G(f, f', x) dx over functions f : [a, b] -> [ymin, ymax]
  with the given end conditions.

  `box` is the rectangle [a, b] x [ymin, ymax] of the (x, f) plane in which the discrete curves live
  (`box.xmin() = a`, `box.xmax() = b`). The functional G is passed to the solvers separately.
*/
struct Curve_problem_2
{
  CGAL::Bbox_2 box;
  End_condition left;
  End_condition right;

  /// Throws `std::invalid_argument` with a message saying what is wrong.
  void validate() const
  {
    auto fail = [](const std::string& what) { throw std::invalid_argument("MDCS: invalid curve problem: " + what); };
    const double v[4] = {box.xmin(), box.xmax(), box.ymin(), box.ymax()};
    for(double c : v)
      if(!std::isfinite(c)) fail("the box coordinates must be finite");
    if(!(box.xmin() < box.xmax())) fail("the interval [a, b] is empty (need box.xmin() < box.xmax())");
    if(!(box.ymin() < box.ymax())) fail("the range of values is empty (need box.ymin() < box.ymax())");
    check_end("left (f(a))", left, fail);
    check_end("right (f(b))", right, fail);
  }

  /// The marks to split the left wall at: {low} for a fixed end, {low, high} for a relaxed one.
  std::vector<double> left_marks() const { return marks(left); }
  std::vector<double> right_marks() const { return marks(right); }

private:
  template <class Fail>
  void check_end(const char* name, const End_condition& e, Fail fail) const
  {
    std::ostringstream s;
    if(!std::isfinite(e.low) || !std::isfinite(e.high)) {
      s << "the " << name << " end condition is not finite";
      fail(s.str());
    }
    if(e.low > e.high) {
      s << "the " << name << " end range [" << e.low << ", " << e.high << "] has low > high";
      fail(s.str());
    }
    if(e.low < box.ymin() || e.high > box.ymax()) {
      s << "the " << name << " end value(s) [" << e.low << ", " << e.high << "] lie outside the range of values ["
        << box.ymin() << ", " << box.ymax() << "]";
      fail(s.str());
    }
  }

  static std::vector<double> marks(const End_condition& e)
  {
    if(e.is_fixed()) return {e.low};
    return {e.low, e.high};
  }
};

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_CURVE_PROBLEM_2_H
