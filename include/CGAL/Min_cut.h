// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Convenience header: the whole public interface of the Min_cut package.

#ifndef CGAL_MIN_CUT_H
#define CGAL_MIN_CUT_H

/*!
  \defgroup PkgMinCutRef Min_cut reference
  Flow networks of cell complexes, max-flow engines and `solve_min_cut()`; see the manual page
  doc/Min_cut/Min_cut.md.

  \defgroup PkgMinCutConcepts Min_cut concepts
  \ingroup PkgMinCutRef
*/

#include <CGAL/Min_cut/Flow_network.h>
#include <CGAL/Min_cut/Boykov_kolmogorov_max_flow.h>
#include <CGAL/Min_cut/Pseudoflow_max_flow.h>
#include <CGAL/Min_cut/Push_relabel_max_flow.h>
#include <CGAL/Min_cut/solve_min_cut.h>
#include <CGAL/Min_cut/Planar_dual.h>
#include <CGAL/Min_cut/solve_planar_min_cut.h>

#endif // CGAL_MIN_CUT_H
