// Shared checks of the polygonal-domain tests: distance to a polygon's boundary and a closed point-in-polygon
// test with a tolerance (an oracle independent of the library's lattice predicates).
#ifndef MDCS_TEST_POLYGON_GEOMETRY_H
#define MDCS_TEST_POLYGON_GEOMETRY_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace MDCS_test {

typedef std::vector<std::array<double, 2>> Polygon;

// Distance from (x, y) to the boundary of p, and the index of the nearest edge.
inline double boundary_distance(const Polygon& p, double x, double y, std::size_t* edge = nullptr)
{
  double best = 1e300;
  for(std::size_t i = 0; i < p.size(); ++i) {
    const auto& a = p[i];
    const auto& b = p[(i + 1) % p.size()];
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double t = (std::max)(0.0, (std::min)(1.0, ((x - a[0]) * dx + (y - a[1]) * dy) / (dx * dx + dy * dy)));
    const double d = std::hypot(a[0] + t * dx - x, a[1] + t * dy - y);
    if(d < best) {
      best = d;
      if(edge) *edge = i;
    }
  }
  return best;
}

// Closed point-in-polygon: points within eps of the boundary count as inside.
inline bool in_polygon(const Polygon& p, double x, double y, double eps = 1e-9)
{
  if(boundary_distance(p, x, y) <= eps) return true;
  bool in = false;
  for(std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
    if((p[i][1] > y) != (p[j][1] > y) && x < (p[j][0] - p[i][0]) * (y - p[i][1]) / (p[j][1] - p[i][1]) + p[i][0])
      in = !in;
  return in;
}

} // namespace MDCS_test

#endif // MDCS_TEST_POLYGON_GEOMETRY_H
