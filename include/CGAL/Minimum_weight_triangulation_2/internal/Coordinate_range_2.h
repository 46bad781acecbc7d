// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The precondition on the coordinates (Mwt_coordinate_range): squared coordinate differences must stay finite
// and out of the subnormal range, because every length of the package is sqrt(dx^2 + dy^2) in double precision.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_COORDINATE_RANGE_2_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_COORDINATE_RANGE_2_H

#include <CGAL/Minimum_weight_triangulation_2/Mwt_result.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {
namespace internal {

/// Throws std::invalid_argument when a coordinate is not finite or above Mwt_coordinate_range::max_abs_coordinate(),
/// or when the larger side of the bounding box is below Mwt_coordinate_range::min_extent(). `P` offers size(),
/// x(int), y(int) (Indexed_points_2); `who` starts the message.
template <class P>
void check_coordinate_range(const P& pts, const char* who = "minimum_weight_triangulation_2")
{
  const double big = Mwt_coordinate_range::max_abs_coordinate();
  const int n = int(pts.size());
  double xmin = HUGE_VAL, xmax = -HUGE_VAL, ymin = HUGE_VAL, ymax = -HUGE_VAL;
  for(int i = 0; i < n; ++i) {
    const double x = pts.x(i), y = pts.y(i);
    if(!std::isfinite(x) || !std::isfinite(y))
      throw std::invalid_argument(std::string(who) + ": point " + std::to_string(i) + " has a non-finite coordinate");
    if(!(std::abs(x) <= big) || !(std::abs(y) <= big)) {
      std::ostringstream s;
      s.precision(17);
      s << who << ": point " << i << " (" << x << ", " << y << ") has a coordinate beyond 2^500 (about 3.3e150) in "
        << "absolute value, where squared edge lengths overflow; scale the points down (a power of two keeps them "
        << "exact)";
      throw std::invalid_argument(s.str());
    }
    xmin = (std::min)(xmin, x); xmax = (std::max)(xmax, x);
    ymin = (std::min)(ymin, y); ymax = (std::max)(ymax, y);
  }
  if(n >= 2 && !((std::max)(xmax - xmin, ymax - ymin) >= Mwt_coordinate_range::min_extent())) {
    std::ostringstream s;
    s.precision(17);
    s << who << ": the points' bounding box is " << (xmax - xmin) << " x " << (ymax - ymin) << ", smaller than 2^-400 "
      << "(about 3.9e-121) on its larger side, where squared edge lengths lose their precision; scale the points up "
      << "(a power of two keeps them exact)";
    throw std::invalid_argument(s.str());
  }
}

} // namespace internal
} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_INTERNAL_COORDINATE_RANGE_2_H
