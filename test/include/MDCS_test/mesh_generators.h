// Triangle meshes made in code, shared by the test suites of every package (no data files needed): planar
// grids and subdivided triangles (geodesics are Euclidean distances there), the regular tetrahedron and an
// icosphere (analytic distances), and a mesh with a boundary. Each generator fills any FaceGraph that
// CGAL::Euler can build (Surface_mesh, Polyhedron_3, ...).
#ifndef MDCS_TEST_MESH_GENERATORS_H
#define MDCS_TEST_MESH_GENERATORS_H

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>
#include <string>
#include <vector>

namespace MDCS_test {

template <class Point_3>
struct Triangle_soup
{
  std::vector<Point_3> points;
  std::vector<std::array<std::size_t, 3>> triangles;

  template <class FaceGraph>
  void to_mesh(FaceGraph& mesh) const
  {
    std::vector<std::vector<std::size_t>> polygons;
    for(const auto& t : triangles) polygons.push_back({t[0], t[1], t[2]});
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  }
};

// A generated mesh with the name the tests report it by.
template <class Point_3>
struct Named_soup
{
  std::string name;
  Triangle_soup<Point_3> soup;
};

// The planar grid [0, w] x [0, h] in the plane z = 0 with nx x ny squares, each split into two triangles along
// alternating diagonals (so that no direction is preferred). A boundary mesh, genus 0, one boundary loop.
template <class Point_3>
Triangle_soup<Point_3> planar_grid(std::size_t nx, std::size_t ny, double w = 1, double h = 1)
{
  if(nx == 0 || ny == 0) throw std::invalid_argument("planar_grid: nx and ny must be positive");
  Triangle_soup<Point_3> soup;
  for(std::size_t j = 0; j <= ny; ++j)
    for(std::size_t i = 0; i <= nx; ++i)
      soup.points.emplace_back(w * double(i) / double(nx), h * double(j) / double(ny), 0);
  auto id = [&](std::size_t i, std::size_t j) { return j * (nx + 1) + i; };
  for(std::size_t j = 0; j < ny; ++j)
    for(std::size_t i = 0; i < nx; ++i) {
      const std::size_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if((i + j) % 2 == 0) {
        soup.triangles.push_back({a, b, c});
        soup.triangles.push_back({a, c, d});
      } else {
        soup.triangles.push_back({a, b, d});
        soup.triangles.push_back({b, c, d});
      }
    }
  return soup;
}

// The triangle (0,0,0), (1,0,0), (0.5, sqrt(3)/2, 0) subdivided regularly into k^2 triangles (thesis fig. 4.4).
template <class Point_3>
Triangle_soup<Point_3> subdivided_triangle(std::size_t k)
{
  if(k == 0) throw std::invalid_argument("subdivided_triangle: k must be positive");
  Triangle_soup<Point_3> soup;
  const double s3 = std::sqrt(3.0) / 2;
  std::vector<std::vector<std::size_t>> index(k + 1);
  for(std::size_t j = 0; j <= k; ++j)
    for(std::size_t i = 0; i + j <= k; ++i) {
      index[j].push_back(soup.points.size());
      soup.points.emplace_back((double(i) + 0.5 * double(j)) / double(k), s3 * double(j) / double(k), 0);
    }
  for(std::size_t j = 0; j < k; ++j)
    for(std::size_t i = 0; i + j < k; ++i) {
      soup.triangles.push_back({index[j][i], index[j][i + 1], index[j + 1][i]});
      if(i + j + 1 < k) soup.triangles.push_back({index[j][i + 1], index[j + 1][i + 1], index[j + 1][i]});
    }
  return soup;
}

// The regular tetrahedron with unit edges.
template <class Point_3>
Triangle_soup<Point_3> regular_tetrahedron()
{
  Triangle_soup<Point_3> soup;
  const double s = 1.0 / std::sqrt(8.0);
  soup.points = {Point_3(s, s, s), Point_3(s, -s, -s), Point_3(-s, s, -s), Point_3(-s, -s, s)};
  soup.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  return soup;
}

// The unit icosphere: an icosahedron subdivided `levels` times, vertices projected on the sphere.
template <class Point_3>
Triangle_soup<Point_3> icosphere(std::size_t levels)
{
  const double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<std::array<double, 3>> p = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                          {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<std::size_t, 3>> f = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11},
                                               {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                               {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9},
                                               {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  auto normalise = [](std::array<double, 3> v) {
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return std::array<double, 3>{v[0] / n, v[1] / n, v[2] / n};
  };
  for(auto& v : p) v = normalise(v);
  for(std::size_t l = 0; l < levels; ++l) {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> middle;
    auto mid = [&](std::size_t a, std::size_t b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = middle.find(key);
      if(it != middle.end()) return it->second;
      p.push_back(normalise({p[a][0] + p[b][0], p[a][1] + p[b][1], p[a][2] + p[b][2]}));
      return middle[key] = p.size() - 1;
    };
    std::vector<std::array<std::size_t, 3>> g;
    for(const auto& tri : f) {
      const std::size_t ab = mid(tri[0], tri[1]), bc = mid(tri[1], tri[2]), ca = mid(tri[2], tri[0]);
      g.push_back({tri[0], ab, ca});
      g.push_back({tri[1], bc, ab});
      g.push_back({tri[2], ca, bc});
      g.push_back({ab, bc, ca});
    }
    f.swap(g);
  }
  Triangle_soup<Point_3> soup;
  for(const auto& v : p) soup.points.emplace_back(v[0], v[1], v[2]);
  soup.triangles = f;
  return soup;
}

} // namespace MDCS_test

#endif // MDCS_TEST_MESH_GENERATORS_H
