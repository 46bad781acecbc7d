// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The window-propagation classes (exact and merged) behind the Geodesic_solver interface; their own translation
// unit keeps the compile time and memory of each file of the module moderate.

#include "geodesic_solver_impl.h"

#include <CGAL/Polyhedral_geodesics_3/Exact_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Merged_window_geodesic_distances_3.h>

namespace mdcs_python {

std::unique_ptr<Geodesic_solver> make_window_solver(const Geo_mesh& mesh, bool merged, double tolerance, bool full_field)
{
  namespace PG = CGAL::Polyhedral_geodesics_3;
  const PG::Geodesic_memory_mode mode =
    full_field ? PG::Geodesic_memory_mode::full_field : PG::Geodesic_memory_mode::distances_only;
  if(merged)
    return std::unique_ptr<Geodesic_solver>(
      new Geodesic_solver_impl<PG::Merged_window_geodesic_distances_3<Geo_mesh>>(mesh, tolerance, mode));
  return std::unique_ptr<Geodesic_solver>(new Geodesic_solver_impl<PG::Exact_geodesic_distances_3<Geo_mesh>>(mesh, mode));
}

} // namespace mdcs_python
