// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The relative rounding error of one arithmetic operation in a number type, which the exact engines scale into
// the tolerance of their comparisons.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_UNIT_ROUNDOFF_H
#define CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_UNIT_ROUNDOFF_H

#include <limits>

namespace CGAL {
namespace Polyhedral_geodesics_3 {
namespace internal {

// numeric_limits' epsilon where the type gives one; else found by halving, since CGAL::Gmpfr has no numeric_limits
// but rounds all the same (a tolerance of 0 there let the vertex-oriented schedule prune a window whose value
// equals a vertex distance up to rounding, and a point query on a 3x3 cube at 170 bits missed its best path by
// 1e-4); 0 for a type that does not round within 4096 halvings.
template <class FT>
FT unit_roundoff()
{
  if(std::numeric_limits<FT>::is_specialized && std::numeric_limits<FT>::epsilon() > FT(0))
    return FT(std::numeric_limits<FT>::epsilon());
  FT e(1);
  for(int i = 0; i < 4096; ++i) {
    const FT half = e / FT(2);
    if(!(FT(1) + half > FT(1)))
      return e;
    e = half;
  }
  return FT(0);
}

} // namespace internal
} // namespace Polyhedral_geodesics_3
} // namespace CGAL

#endif // CGAL_POLYHEDRAL_GEODESICS_3_INTERNAL_UNIT_ROUNDOFF_H
