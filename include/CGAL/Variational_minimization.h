// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Convenience header of the Variational_minimization package: globally minimal discrete curves (line
// arrangements, `_2`) and surfaces (plane arrangements, `_3`).

#ifndef CGAL_VARIATIONAL_MINIMIZATION_H
#define CGAL_VARIATIONAL_MINIMIZATION_H

#include <CGAL/Variational_minimization/Curve_problem_2.h>
#include <CGAL/Variational_minimization/Line_arrangement_2.h>
#include <CGAL/Variational_minimization/Minimal_curve_2.h>
#include <CGAL/Variational_minimization/analytic_solutions_2.h>
#include <CGAL/Variational_minimization/curve_edge_weights_2.h>
#include <CGAL/Variational_minimization/curve_functionals_2.h>
#include <CGAL/Variational_minimization/directed_shortest_path_2.h>
#include <CGAL/Variational_minimization/edge_weight_2.h>
#include <CGAL/Variational_minimization/line_grids_2.h>
#include <CGAL/Variational_minimization/local_descent_2.h>
#include <CGAL/Variational_minimization/minimize_curve_functional_2.h>
#include <CGAL/Variational_minimization/minimize_on_regular_grid_2.h>
#include <CGAL/Variational_minimization/IO/write_curve_svg.h>

#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/analytic_solutions_3.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/monte_carlo_functional_3.h>
#include <CGAL/Variational_minimization/refine_surface_3.h>
#include <CGAL/Variational_minimization/refine_surface_by_tangent_planes_3.h>
#include <CGAL/Variational_minimization/relax_surface_3.h>
#include <CGAL/Variational_minimization/select_planes_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#endif // CGAL_VARIATIONAL_MINIMIZATION_H
