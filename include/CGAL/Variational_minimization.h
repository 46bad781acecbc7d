// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Convenience header of the Variational_minimization package (globally minimal discrete curves).

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

#endif // CGAL_VARIATIONAL_MINIMIZATION_H
