// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Piecewise linear functions on a triangle mesh of a polygonal domain (the relaxation of relax_surface_3() on
// polygons): the mesh (CGAL's constrained Delaunay triangulation of the polygon, refined by Delaunay_mesher_2 with a
// size bound), the energy of a function for a functional G (centroid rule, as on the rectangle's grids: exact for G
// depending only on the gradient and for G linear in f) and its gradient.
#ifndef CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_MESH_SURFACE_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_MESH_SURFACE_3_H

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/internal/functional_evaluation_3.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Variational_minimization {
namespace internal {

// A triangle mesh of Ω: nodes (x, y), counter-clockwise triangles, which nodes lie on ∂Ω, and per triangle its
// area, centroid and the gradients of its three barycentric (hat) functions.
struct Triangle_mesh_frame_3
{
  std::vector<std::array<double, 2>> nodes;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<char> on_boundary;
  std::vector<double> area;
  std::vector<std::array<double, 2>> centroid;
  std::vector<std::array<double, 3>> dphi_x, dphi_y;

  std::size_t size() const { return nodes.size(); }

  // Fills the per-triangle data from nodes and triangles (orients the triangles counter-clockwise).
  void finish()
  {
    const std::size_t m = triangles.size();
    area.resize(m);
    centroid.resize(m);
    dphi_x.resize(m);
    dphi_y.resize(m);
    for(std::size_t t = 0; t < m; ++t) {
      std::array<std::uint32_t, 3>& v = triangles[t];
      double det = (nodes[v[1]][0] - nodes[v[0]][0]) * (nodes[v[2]][1] - nodes[v[0]][1]) -
                   (nodes[v[1]][1] - nodes[v[0]][1]) * (nodes[v[2]][0] - nodes[v[0]][0]);
      if(det < 0) {
        std::swap(v[1], v[2]);
        det = -det;
      }
      if(!(det > 0)) throw std::logic_error("MDCS: internal error: a degenerate triangle in the relaxation mesh");
      area[t] = 0.5 * det;
      centroid[t] = {{(nodes[v[0]][0] + nodes[v[1]][0] + nodes[v[2]][0]) / 3,
                      (nodes[v[0]][1] + nodes[v[1]][1] + nodes[v[2]][1]) / 3}};
      for(int k = 0; k < 3; ++k) {
        // grad phi_k = perp(p_{k+2} - p_{k+1}) / det, perp(x, y) = (-y, x) rotated to point towards p_k.
        const auto& a = nodes[v[(k + 1) % 3]];
        const auto& b = nodes[v[(k + 2) % 3]];
        dphi_x[t][k] = (a[1] - b[1]) / det;
        dphi_y[t][k] = (b[0] - a[0]) / det;
      }
    }
  }
};

// The mesh of the (rounded) polygon of `problem` for relaxation level n: the constrained Delaunay triangulation of
// the polygon refined by CGAL's Delaunay mesher with angles >= about 20.7 degrees and edges no longer than the
// diagonal of a square of the n x n grid over the bounding box (the longest edge of the rectangle's grid triangles).
inline Triangle_mesh_frame_3 polygon_relaxation_mesh_3(const Surface_problem_3& problem, int n)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, K> Vb0;
  typedef CGAL::Delaunay_mesh_vertex_base_2<K, Vb0> Vb;
  typedef CGAL::Delaunay_mesh_face_base_2<K> Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag> CDT;
  typedef CGAL::Delaunay_mesh_size_criteria_2<CDT> Criteria;

  std::vector<K::Point_2> polygon;
  for(const auto& q : problem.lattice_polygon()) {
    const std::array<double, 3> w = problem.to_world({{double(q[0]), double(q[1]), 0.0}});
    polygon.push_back(K::Point_2(w[0], w[1]));
  }
  CDT cdt;
  cdt.insert_constraint(polygon.begin(), polygon.end(), true);
  const double hx = (problem.domain.xmax() - problem.domain.xmin()) / n,
               hy = (problem.domain.ymax() - problem.domain.ymin()) / n;
  CGAL::refine_Delaunay_mesh_2(cdt, Criteria(0.125, std::sqrt(hx * hx + hy * hy)));

  Triangle_mesh_frame_3 mesh;
  const std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) v->info() = none;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if(!f->is_in_domain()) continue;
    std::array<std::uint32_t, 3> t;
    for(int k = 0; k < 3; ++k) {
      auto v = f->vertex(k);
      if(v->info() == none) {
        v->info() = std::uint32_t(mesh.nodes.size());
        mesh.nodes.push_back({{v->point().x(), v->point().y()}});
      }
      t[k] = v->info();
    }
    mesh.triangles.push_back(t);
  }
  mesh.on_boundary.assign(mesh.nodes.size(), 0);
  for(auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
    if(cdt.is_constrained(*e))
      for(int k = 1; k <= 2; ++k) {
        auto v = e->first->vertex((e->second + k) % 3);
        if(v->info() != none) mesh.on_boundary[v->info()] = 1;
      }
  mesh.finish();
  return mesh;
}

// Energy and (optionally) gradient of the piecewise linear function with node values f.
template <class Functional>
double mesh_energy_3(const Triangle_mesh_frame_3& m, const Functional& G, const std::vector<double>& f,
                     std::vector<double>* grad)
{
  if(grad) grad->assign(f.size(), 0.0);
  double energy = 0;
  for(std::size_t t = 0; t < m.triangles.size(); ++t) {
    const std::array<std::uint32_t, 3>& v = m.triangles[t];
    double fx = 0, fy = 0;
    for(int k = 0; k < 3; ++k) {
      fx += f[v[k]] * m.dphi_x[t][k];
      fy += f[v[k]] * m.dphi_y[t][k];
    }
    const double fc = (f[v[0]] + f[v[1]] + f[v[2]]) / 3, cx = m.centroid[t][0], cy = m.centroid[t][1];
    energy += m.area[t] * checked_value(G, fc, fx, fy, cx, cy);
    if(grad) {
      // Central differences of G in (f, fx, fy), as on the rectangle's grids.
      double d[3];
      functional_partials(G, fc, fx, fy, cx, cy, d);
      for(int k = 0; k < 3; ++k)
        (*grad)[v[k]] += m.area[t] * (d[0] / 3 + d[1] * m.dphi_x[t][k] + d[2] * m.dphi_y[t][k]);
    }
  }
  return energy;
}

} // namespace internal
} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_INTERNAL_MESH_SURFACE_3_H
