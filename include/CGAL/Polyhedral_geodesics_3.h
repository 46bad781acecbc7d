// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Convenience header of the package Polyhedral_geodesics_3: geodesic distances and shortest paths on
// triangle meshes, exact (window propagation) and approximate (interval merging, flat-exact, fast
// marching, Dijkstra), the error metric that compares them, locating points and rays on the surface, and
// iso-distance curves.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_H
#define CGAL_POLYHEDRAL_GEODESICS_3_H

#include <CGAL/Polyhedral_geodesics_3/Geodesic_types.h>
#include <CGAL/Polyhedral_geodesics_3/Exact_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Merged_window_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Flat_exact_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Fast_marching_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Dijkstra_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/geodesic_distance_error.h>
#include <CGAL/Polyhedral_geodesics_3/Surface_point_locator_3.h>
#include <CGAL/Polyhedral_geodesics_3/iso_distance_curves.h>

#endif // CGAL_POLYHEDRAL_GEODESICS_3_H
