// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The approximate classes (flat-exact, fast marching, Dijkstra) behind the Geodesic_solver interface.

#include "geodesic_solver_impl.h"

#include <CGAL/Polyhedral_geodesics_3/Dijkstra_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Fast_marching_geodesic_distances_3.h>
#include <CGAL/Polyhedral_geodesics_3/Flat_exact_geodesic_distances_3.h>

namespace mdcs_python {

std::unique_ptr<Geodesic_solver> make_approximate_solver(const Geo_mesh& mesh, Geodesic_method method, bool full_field)
{
  namespace PG = CGAL::Polyhedral_geodesics_3;
  const PG::Geodesic_memory_mode mode =
    full_field ? PG::Geodesic_memory_mode::full_field : PG::Geodesic_memory_mode::distances_only;
  switch(method) {
  case Geodesic_method::flat_exact:
    return std::unique_ptr<Geodesic_solver>(
      new Geodesic_solver_impl<PG::Flat_exact_geodesic_distances_3<Geo_mesh>>(mesh, mode));
  case Geodesic_method::fast_marching:
    return std::unique_ptr<Geodesic_solver>(
      new Geodesic_solver_impl<PG::Fast_marching_geodesic_distances_3<Geo_mesh>>(mesh, mode));
  case Geodesic_method::dijkstra:
    return std::unique_ptr<Geodesic_solver>(
      new Geodesic_solver_impl<PG::Dijkstra_geodesic_distances_3<Geo_mesh>>(mesh, mode));
  default:
    throw std::logic_error("mdcs: internal error: make_approximate_solver called for a window method");
  }
}

} // namespace mdcs_python
