// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The pieces of adaptive refinement (thesis ch. 2.7) shared by refine_surface_3() and refine_surface_multilevel_3():
// an envelope [min s_r - margin, max s_r + margin] of known surfaces, new planes through random points inside it,
// and the minimum cut of an arrangement whose cells outside the envelope are contracted into the terminals.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_ENVELOPE_CUT_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_ENVELOPE_CUT_3_H

#include <CGAL/Min_cut/internal/contract_terminal_nodes.h>
#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/internal/surface_domain_cells_3.h>
#include <CGAL/Variational_minimization/internal/surface_dual_network_3.h>
#include <CGAL/Variational_minimization/internal/surface_height_3.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

// The band between the lowest and the highest of some surfaces, widened by `margin` (world z units) on each side and
// clamped to [zmin, zmax]. One surface with a margin is the envelope of a multi-level refinement step. The surfaces
// are referred to, not copied: they must outlive the envelope.
class Surface_envelope_3
{
public:
  Surface_envelope_3(const Surface_problem_3& problem, const std::vector<Minimal_surface_3>& surfaces, double margin)
    : zmin_(problem.zmin), zmax_(problem.zmax), margin_(margin)
  {
    for(const Minimal_surface_3& s : surfaces) heights_.emplace_back(s);
  }
  double margin() const { return margin_; }
  // The unwidened band [min s_r, max s_r] at (x, y).
  void band(double x, double y, double& lo, double& hi) const
  {
    lo = 1e300;
    hi = -1e300;
    for(const Surface_height_3& h : heights_) {
      const double z = h(x, y);
      lo = (std::min)(lo, z);
      hi = (std::max)(hi, z);
    }
  }
  // The widened band, clamped to the box.
  void widened(double x, double y, double& lo, double& hi) const
  {
    band(x, y, lo, hi);
    lo = (std::max)(zmin_, lo - margin_);
    hi = (std::min)(zmax_, hi + margin_);
  }

private:
  double zmin_, zmax_, margin_;
  std::vector<Surface_height_3> heights_;
};

// Each plane once (duplicates are harmless in an arrangement, which drops them, but they would count against n).
inline std::vector<Lattice_plane_3> unique_planes_3(const std::vector<Lattice_plane_3>& planes)
{
  std::vector<Lattice_plane_3> unique;
  for(const Lattice_plane_3& p : planes) {
    const Lattice_plane_3 q = normalized_plane(p);
    bool seen = false;
    for(const Lattice_plane_3& u : unique) seen = seen || (u.a == q.a && u.b == q.b && u.c == q.c && u.d == q.d);
    if(!seen) unique.push_back(q);
  }
  return unique;
}

// Appends planes until `planes` holds n: each through a random point of the widened envelope over Ω (points of the
// bounding box outside a polygonal Ω are redrawn), with the orientations of `options.distribution`.
template <class Rng>
void add_planes_in_envelope_3(const Surface_problem_3& problem, const Surface_plane_options_3& options,
                              const Surface_envelope_3& envelope, std::size_t n, Rng& rng,
                              std::vector<Lattice_plane_3>& planes)
{
  const double L = double(Plane_arrangement_3::lattice_size);
  const double sx = (problem.domain.xmax() - problem.domain.xmin()) / L,
               sy = (problem.domain.ymax() - problem.domain.ymin()) / L, sz = (problem.zmax - problem.zmin) / L;
  std::uniform_real_distribution<double> U(0, 1), S(-options.max_slope, options.max_slope);
  std::normal_distribution<double> N;
  const std::vector<Lattice_point_2> polygon = problem.lattice_polygon();
  while(planes.size() < n) {
    const double u = U(rng), v = U(rng);
    if(problem.is_polygonal() && !lattice_polygon_contains(polygon, u * L, v * L)) continue;
    const double x = problem.domain.xmin() + u * (problem.domain.xmax() - problem.domain.xmin()),
                 y = problem.domain.ymin() + v * (problem.domain.ymax() - problem.domain.ymin());
    double lo, hi;
    envelope.widened(x, y, lo, hi);
    const double z = lo + U(rng) * (hi - lo);
    const std::array<double, 3> q = {{u * L, v * L, (z - problem.zmin) / sz}};
    std::array<double, 3> normal;
    if(options.distribution == Plane_distribution_3::isotropic) normal = {{N(rng), N(rng), N(rng)}};
    else normal = {{-S(rng) * sx / sz, -S(rng) * sy / sz, 1.0}};
    if(!(std::abs(normal[0]) + std::abs(normal[1]) + std::abs(normal[2]) > 1e-12)) continue;
    planes.push_back(plane_through(normal, q));
  }
}

// An interior point of each cell, in world coordinates: the mean of the vertices of its facets.
inline std::vector<std::array<double, 3>> cell_points_3(const Plane_arrangement_3& arrangement,
                                                        const Surface_problem_3& problem)
{
  typedef Plane_arrangement_3 Arr;
  std::vector<std::array<double, 3>> out(arrangement.number_of_cells());
  for(std::size_t c = 0; c < arrangement.number_of_cells(); ++c) {
    std::array<double, 3> m = {{0, 0, 0}};
    std::size_t k = 0;
    for(Arr::Facet_index f : arrangement.cell_facets(Arr::Cell_index(c)))
      for(std::size_t i = 0; i < arrangement.facet_degree(f); ++i, ++k)
        for(int j = 0; j < 3; ++j) m[j] += arrangement.point(arrangement.facet_vertex(f, i))[j];
    for(int j = 0; j < 3; ++j) m[j] /= double(k);
    out[c] = problem.to_world(m);
  }
  return out;
}

// What minimize_in_envelope_3() classified and solved.
struct Envelope_cut_counts_3
{
  std::size_t cells = 0, cells_below = 0, cells_above = 0, cells_outside = 0;
  std::size_t network_nodes = 0, network_facets = 0;
};

// The minimal surface of `arrangement` among those inside the widened envelope: cells lying lower than the margin
// below the band are tied to the source, those higher than the margin above it to the sink, by contracting them
// into the terminals (cells outside a polygonal Ω, which have no arcs, go to the source and are left out). A cell
// is placed by an interior point (the mean of its facets' vertices): no surface of the band crosses a cell whose
// arrangement holds that surface's planes, so each such surface stays feasible.
template <class Functional, class Engine>
Minimal_surface_3 minimize_in_envelope_3(const Plane_arrangement_3& arrangement, const Surface_problem_3& problem,
                                         const Functional& G, const Surface_envelope_3& envelope,
                                         int quadrature_level, Engine engine, Envelope_cut_counts_3& counts)
{
  typedef Plane_arrangement_3 Arr;
  counts = Envelope_cut_counts_3();
  counts.cells = arrangement.number_of_cells();
  std::vector<char> label(arrangement.number_of_cells(), 0);
  const double eps = envelope.margin() + 1e-9 * (problem.zmax - problem.zmin);
  const std::vector<char> inside = surface_domain_cells_3(arrangement, problem);
  const std::vector<std::array<double, 3>> points = cell_points_3(arrangement, problem);
  for(std::size_t c = 0; c < arrangement.number_of_cells(); ++c) {
    if(!inside[c]) {
      label[c] = 1;
      ++counts.cells_outside;
      continue;
    }
    const std::array<double, 3>& p = points[c];
    double lo, hi;
    envelope.band(p[0], p[1], lo, hi);
    if(p[2] < lo - eps) {
      label[c] = 1;
      ++counts.cells_below;
    } else if(p[2] > hi + eps) {
      label[c] = 2;
      ++counts.cells_above;
    }
  }
  // The contracted network is built straight from the arrangement: neither the full network nor a weight vector
  // exists, and G is integrated only over the facets that can still matter (those touching a cell inside the
  // envelope, and those between a cell below it and one above it, which every cut crosses).
  const auto weight_of = [&](Arr::Facet_index f) {
    return surface_facet_weight_3(arrangement, problem, G, f, quadrature_level);
  };
  CGAL::Min_cut::internal::Contracted_network<double> reduced;
  {
    CGAL::Min_cut::internal::Terminal_contraction<double> builder(label);
    build_surface_dual_network_3(arrangement, weight_of, problem, builder);
    reduced = builder.release();
  }
  counts.network_nodes = reduced.network.number_of_nodes();
  counts.network_facets = reduced.network.number_of_facets();
  return surface_from_contracted_cut_3(arrangement, problem, weight_of, reduced, engine);
}

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_SURFACE_ENVELOPE_CUT_3_H
