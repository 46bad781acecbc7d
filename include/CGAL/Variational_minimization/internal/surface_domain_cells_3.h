// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Which cells of a plane arrangement lie over a polygonal domain of Surface_problem_3.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_DOMAIN_CELLS_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_DOMAIN_CELLS_3_H

#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/internal/surface_polygon_predicates_3.h>

#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

// Per cell, 1 if its (x, y)-projection lies in Ω, else 0 (all 1 for a rectangle). The arrangement must contain the
// vertical planes through the polygon's edges (surface_planes_3() puts them first), so that no cell straddles
// the boundary of Ω: the mean of a cell's facet vertices (an interior point of the cell) decides.
inline std::vector<char> surface_domain_cells_3(const Plane_arrangement_3& arrangement, const Surface_problem_3& problem)
{
  std::vector<char> inside(arrangement.number_of_cells(), 1);
  if(!problem.is_polygonal()) return inside;
  const std::vector<Lattice_point_2> poly = problem.lattice_polygon();
  for(std::size_t c = 0; c < inside.size(); ++c) {
    double x = 0, y = 0;
    std::size_t n = 0;
    for(std::uint32_t f : arrangement.cell_facets(Plane_arrangement_3::Cell_index(c)))
      for(std::size_t k = 0; k < arrangement.facet_degree(f); ++k) {
        const std::array<double, 3>& p = arrangement.point(arrangement.facet_vertex(f, k));
        x += p[0];
        y += p[1];
        ++n;
      }
    inside[c] = n > 0 && lattice_polygon_contains(poly, x / double(n), y / double(n)) ? 1 : 0;
  }
  return inside;
}

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_DOMAIN_CELLS_3_H
