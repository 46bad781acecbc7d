// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Convenience header: the whole public interface of the Minimum_weight_triangulation_2 package.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_H

/*!
  \defgroup PkgMinimumWeightTriangulation2Ref Minimum_weight_triangulation_2 reference
  The triangle-based LP for minimum weight triangulations, LP solver models, the convex-polygon and
  simple-polygon dynamic programs, the MWT of polygonal domains with holes and interior points (the exact QP_solver model has its own header,
  QP_solver_linear_program_solver.h); see the manual page doc/Minimum_weight_triangulation_2/Minimum_weight_triangulation_2.md.
*/

#include <CGAL/Minimum_weight_triangulation_2/Linear_program.h>
#include <CGAL/Minimum_weight_triangulation_2/Mwt_result.h>
#include <CGAL/Minimum_weight_triangulation_2/Minimum_weight_triangulation_lp_2.h>
#include <CGAL/Minimum_weight_triangulation_2/minimum_weight_triangulation_2.h>
#include <CGAL/Minimum_weight_triangulation_2/convex_polygon_mwt_2.h>
#include <CGAL/Minimum_weight_triangulation_2/simple_polygon_mwt_2.h>
#include <CGAL/Minimum_weight_triangulation_2/polygon_with_holes_mwt_2.h>
#include <CGAL/Minimum_weight_triangulation_2/edge_based_lp_2.h>
#include <CGAL/Minimum_weight_triangulation_2/Mixed_integer_program_linear_program_solver.h>

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_H
