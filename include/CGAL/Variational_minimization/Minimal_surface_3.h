// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The result of a bivariate solve, and writers for it (PLY, OFF).
#ifndef CGAL_VARIATIONAL_MINIMIZATION_MINIMAL_SURFACE_3_H
#define CGAL_VARIATIONAL_MINIMIZATION_MINIMAL_SURFACE_3_H

#include <array>
#include <cstdint>
#include <fstream>
#include <iomanip>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Variational_minimization {

/*!
  \ingroup PkgVariationalMinimizationSurfaces
  \brief The globally minimal discrete surface found on a plane arrangement.

  When no discrete function meets the boundary condition on the arrangement, `is_feasible` is false, `energy` is
  +infinity and the mesh is empty.
*/
struct Minimal_surface_3
{
  bool is_feasible = false;
  /// Sum of the weights of the surface's facets (the discrete energy); +infinity when infeasible.
  double energy = std::numeric_limits<double>::infinity();
  /// The min-cut value; equal to `energy` up to rounding (the duality theorem, checked by the tests).
  double solver_value = std::numeric_limits<double>::infinity();
  /// Sum of the signed (x, y)-projected areas of the facets, oriented upwards; equals the domain's area exactly
  /// when the surface is single-valued over Ω (up to rounding).
  double projected_area = 0;
  /// The arrangement facets of the surface.
  std::vector<std::uint32_t> facets;
  /// The planes those facets lie on (sorted, unique).
  std::vector<std::uint32_t> planes;
  /// The triangulated surface in world coordinates: vertices, and triangles oriented upwards.
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

/// Writes the surface as an ASCII PLY file with a per-vertex `height` property. \throws std::runtime_error on I/O failure.
inline void write_surface_ply(const std::string& path, const Minimal_surface_3& s)
{
  std::ofstream out(path);
  if(!out) throw std::runtime_error("MDCS: cannot write " + path);
  out << "ply\nformat ascii 1.0\ncomment MDCS minimal discrete surface, energy " << std::setprecision(17) << s.energy
      << "\nelement vertex " << s.points.size() << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "element face " << s.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for(const auto& p : s.points) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for(const auto& t : s.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  if(!out) throw std::runtime_error("MDCS: error while writing " + path);
}

/// Writes the surface as an OFF file. \throws std::runtime_error on I/O failure.
inline void write_surface_off(const std::string& path, const Minimal_surface_3& s)
{
  std::ofstream out(path);
  if(!out) throw std::runtime_error("MDCS: cannot write " + path);
  out << "OFF\n" << s.points.size() << ' ' << s.triangles.size() << " 0\n" << std::setprecision(17);
  for(const auto& p : s.points) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for(const auto& t : s.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  if(!out) throw std::runtime_error("MDCS: error while writing " + path);
}

} // namespace Variational_minimization
} // namespace CGAL

#endif // CGAL_VARIATIONAL_MINIMIZATION_MINIMAL_SURFACE_3_H
