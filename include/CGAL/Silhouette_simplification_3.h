// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Convenience header of the package Silhouette_simplification_3 (thesis chapter 5). It includes the
// coarse-mesh preprocessing (CGAL Surface_mesh_simplification, slow to compile); code that only runs
// the per-view stages may include Silhouette_simplification_3/Silhouette_simplifier_3.h alone.

#ifndef CGAL_SILHOUETTE_SIMPLIFICATION_3_H
#define CGAL_SILHOUETTE_SIMPLIFICATION_3_H

/*!
  \defgroup PkgSilhouetteSimplification3Ref Silhouette_simplification_3 reference
  Views, silhouette extraction and loop decomposition, the coarse mesh and face map, loop picking and
  loop mapping, the temporal-coherence metric; see the manual page
  doc/Silhouette_simplification_3/Silhouette_simplification_3.md.
*/

#include <CGAL/Silhouette_simplification_3/View_3.h>
#include <CGAL/Silhouette_simplification_3/silhouette_edges.h>
#include <CGAL/Silhouette_simplification_3/Silhouette_edge_hierarchy_3.h>
#include <CGAL/Silhouette_simplification_3/Silhouette_simplifier_3.h>
#include <CGAL/Silhouette_simplification_3/silhouette_frames.h>
#include <CGAL/Silhouette_simplification_3/temporal_coherence.h>
#include <CGAL/Silhouette_simplification_3/Coarse_mesh_3.h>

#endif // CGAL_SILHOUETTE_SIMPLIFICATION_3_H
