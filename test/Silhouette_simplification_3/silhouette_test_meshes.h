// Meshes for the silhouette tests: a noisy icosphere and a torus (closed), a bumpy grid (open).
#ifndef MDCS_TEST_SILHOUETTE_TEST_MESHES_H
#define MDCS_TEST_SILHOUETTE_TEST_MESHES_H

#include <MDCS_test/mesh_generators.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstdint>

namespace silhouette_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef K::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;

// A deterministic pseudo-random number in [0, 1).
inline double hash01(std::uint64_t i)
{
  i = (i ^ (i >> 30)) * 0xbf58476d1ce4e5b9ULL;
  i = (i ^ (i >> 27)) * 0x94d049bb133111ebULL;
  i ^= i >> 31;
  return double(i >> 11) / double(1ULL << 53);
}

// The unit icosphere with radial noise of relative amplitude `noise` (a bumpy closed genus-0 surface).
inline MDCS_test::Triangle_soup<Point_3> noisy_sphere(std::size_t levels, double noise, std::uint64_t seed = 1)
{
  auto soup = MDCS_test::icosphere<Point_3>(levels);
  for(std::size_t i = 0; i < soup.points.size(); ++i) {
    const double r = 1 + noise * (2 * hash01(seed * 1000003 + i) - 1);
    const Point_3& p = soup.points[i];
    soup.points[i] = Point_3(p.x() * r, p.y() * r, p.z() * r);
  }
  return soup;
}

// A torus (radii R, r) with n x m quads split into triangles, optional radial noise.
inline MDCS_test::Triangle_soup<Point_3> torus(std::size_t n, std::size_t m, double R = 1, double r = 0.4, double noise = 0)
{
  MDCS_test::Triangle_soup<Point_3> soup;
  const double pi = 3.14159265358979323846;
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < m; ++j) {
      const double u = 2 * pi * double(i) / double(n), v = 2 * pi * double(j) / double(m);
      const double rr = r * (1 + noise * (2 * hash01(i * m + j + 77) - 1));
      soup.points.emplace_back((R + rr * std::cos(v)) * std::cos(u), (R + rr * std::cos(v)) * std::sin(u), rr * std::sin(v));
    }
  auto id = [&](std::size_t i, std::size_t j) { return (i % n) * m + (j % m); };
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < m; ++j) {
      soup.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      soup.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return soup;
}

// A grid on [0,1]^2 lifted by bumps (an open surface with one boundary loop).
inline MDCS_test::Triangle_soup<Point_3> bumpy_grid(std::size_t n)
{
  auto soup = MDCS_test::planar_grid<Point_3>(n, n);
  for(auto& p : soup.points)
    p = Point_3(p.x(), p.y(), 0.15 * std::sin(9 * p.x()) * std::cos(7 * p.y()));
  return soup;
}

template <class FaceGraph>
FaceGraph make(const MDCS_test::Triangle_soup<Point_3>& soup)
{
  FaceGraph g;
  soup.to_mesh(g);
  return g;
}

} // namespace silhouette_test

#endif
