// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Convenience header of the package Polyhedral_geodesics_3: geodesic distances and shortest paths on
// triangle meshes.

#ifndef CGAL_POLYHEDRAL_GEODESICS_3_H
#define CGAL_POLYHEDRAL_GEODESICS_3_H

#include <CGAL/Polyhedral_geodesics_3/Geodesic_types.h>
#include <CGAL/Polyhedral_geodesics_3/Exact_geodesic_distances_3.h>

#endif // CGAL_POLYHEDRAL_GEODESICS_3_H
