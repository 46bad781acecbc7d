// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The length of a bounding box's diagonal: the scale that the mesh builders of the packages check their input
// against (Polyhedral_geodesics_3's compact mesh, Silhouette_simplification_3's indexed mesh).

#ifndef CGAL_MDCS_INTERNAL_BOUNDING_BOX_H
#define CGAL_MDCS_INTERNAL_BOUNDING_BOX_H

#include <CGAL/Bbox_3.h>

#include <cmath>

namespace CGAL {
namespace MDCS {
namespace internal {

// 0 for a box of one point; +infinity when a side overflows; not meaningful for an empty box.
inline double bbox_diagonal(const CGAL::Bbox_3& b)
{
  const double dx = b.xmax() - b.xmin(), dy = b.ymax() - b.ymin(), dz = b.zmax() - b.zmin();
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

} // namespace internal
} // namespace MDCS
} // namespace CGAL

#endif // CGAL_MDCS_INTERNAL_BOUNDING_BOX_H
