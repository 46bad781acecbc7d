// Small double geometry and mesh helpers shared by the geodesic test oracles (geodesic_oracles.h) and the
// tests: vectors, distances to segments, relative differences, face corners and points of face locations,
// locating a surface point, nearest vertices. Plain double arithmetic, independent of the package under test.
#ifndef MDCS_TEST_GEODESIC_TEST_GEOMETRY_H
#define MDCS_TEST_GEODESIC_TEST_GEOMETRY_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <MDCS_test/test_numbers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <iomanip>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <stdexcept>
#include <utility>
#include <vector>

namespace MDCS_test {

// ---------------------------------------------------------------------------------------------------------
// Small geometry in doubles.

typedef std::array<double, 3> Vec3;


// x with 17 significant digits (for messages).
inline std::string format(double x)
{
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}

template <class P>
Vec3 to_vec3(const P& p)
{
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline double dist(const Vec3& a, const Vec3& b) { return norm(sub(a, b)); }
inline Vec3 lerp(const Vec3& a, const Vec3& b, double t)
{
  return {(1 - t) * a[0] + t * b[0], (1 - t) * a[1] + t * b[1], (1 - t) * a[2] + t * b[2]};
}

// Distance from p to the segment [a, b].
inline double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = sub(b, a);
  const double l2 = dot(ab, ab);
  if(l2 == 0)
    return dist(p, a);
  const double t = std::max(0.0, std::min(1.0, dot(sub(p, a), ab) / l2));
  return dist(p, lerp(a, b, t));
}

// |a - b| / max(|b|, floor): the relative difference with an absolute floor.
inline double relative_difference(double a, double b, double floor_value)
{
  if(a == b)
    return 0; // also +inf == +inf
  return std::abs(a - b) / std::max(std::abs(b), floor_value);
}

template <class Range>
double path_length(const Range& points)
{
  double l = 0;
  bool first = true;
  Vec3 prev{};
  for(const auto& p : points) {
    const Vec3 q = to_vec3(p);
    if(!first)
      l += dist(prev, q);
    prev = q;
    first = false;
  }
  return l;
}

// ---------------------------------------------------------------------------------------------------------
// Mesh helpers.

template <class Mesh>
double bbox_diagonal(const Mesh& m)
{
  Vec3 lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  for(auto v : vertices(m)) {
    const Vec3 p = to_vec3(get(CGAL::vertex_point, m, v));
    for(int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  return dist(lo, hi);
}

template <class Mesh>
Vec3 vertex_vec3(const Mesh& m, typename boost::graph_traits<Mesh>::vertex_descriptor v)
{
  return to_vec3(get(CGAL::vertex_point, m, v));
}

// The three vertices of face f in the order of Polygon_mesh_processing::Face_location:
// source(halfedge(f)), target(halfedge(f)), target(next(halfedge(f))).
template <class Mesh>
std::array<typename boost::graph_traits<Mesh>::vertex_descriptor, 3>
face_vertices(const Mesh& m, typename boost::graph_traits<Mesh>::face_descriptor f)
{
  const auto h = halfedge(f, m);
  return {source(h, m), target(h, m), target(next(h, m), m)};
}

// The 3D point of a face location (barycentric coordinates in any number type).
template <class Mesh, class B>
Vec3 location_point(const Mesh& m, typename boost::graph_traits<Mesh>::face_descriptor f, const std::array<B, 3>& b)
{
  const auto vs = face_vertices(m, f);
  Vec3 r{0, 0, 0};
  for(int i = 0; i < 3; ++i) {
    const Vec3 p = vertex_vec3(m, vs[std::size_t(i)]);
    const double w = CGAL::to_double(b[std::size_t(i)]);
    for(int k = 0; k < 3; ++k)
      r[std::size_t(k)] += w * p[std::size_t(k)];
  }
  return r;
}

// A face location of the surface point p (brute force over the faces): the first face whose triangle contains p
// within `tol` (distance to the plane and barycentric coordinates >= -tol). Throws if none.
template <class Mesh>
std::pair<typename boost::graph_traits<Mesh>::face_descriptor, std::array<double, 3>>
locate_point(const Mesh& m, const Vec3& p, double tol = 1e-12)
{
  for(auto f : faces(m)) {
    const auto vs = face_vertices(m, f);
    const Vec3 a = vertex_vec3(m, vs[0]), b = vertex_vec3(m, vs[1]), c = vertex_vec3(m, vs[2]);
    const Vec3 n = cross(sub(b, a), sub(c, a));
    const double n2 = dot(n, n);
    if(n2 == 0)
      continue;
    if(std::abs(dot(sub(p, a), n)) / std::sqrt(n2) > tol)
      continue;
    const double l0 = dot(cross(sub(b, p), sub(c, p)), n) / n2;
    const double l1 = dot(cross(sub(c, p), sub(a, p)), n) / n2;
    const double l2 = 1 - l0 - l1;
    if(l0 >= -tol && l1 >= -tol && l2 >= -tol) {
      std::array<double, 3> bc = {std::max(0.0, l0), std::max(0.0, l1), std::max(0.0, l2)};
      const double s = bc[0] + bc[1] + bc[2];
      return {f, {bc[0] / s, bc[1] / s, bc[2] / s}};
    }
  }
  throw std::invalid_argument("locate_point: the point is not on the mesh");
}

// `count` random face locations (uniform over the faces, uniform barycentric coordinates inside each).
template <class Mesh>
std::vector<std::pair<typename boost::graph_traits<Mesh>::face_descriptor, std::array<double, 3>>>
random_face_locations(const Mesh& m, std::size_t count, unsigned seed)
{
  std::vector<typename boost::graph_traits<Mesh>::face_descriptor> fs(faces(m).begin(), faces(m).end());
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, fs.size() - 1);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::pair<typename boost::graph_traits<Mesh>::face_descriptor, std::array<double, 3>>> r;
  for(std::size_t i = 0; i < count; ++i) {
    double a = u(rng), b = u(rng);
    if(a + b > 1) {
      a = 1 - a;
      b = 1 - b;
    }
    r.push_back({fs[pick(rng)], {1 - a - b, a, b}});
  }
  return r;
}

// The vertex of m nearest to p (linear scan).
template <class Mesh>
typename boost::graph_traits<Mesh>::vertex_descriptor nearest_vertex(const Mesh& m, const Vec3& p)
{
  typename boost::graph_traits<Mesh>::vertex_descriptor best = *vertices(m).begin();
  double bd = inf;
  for(auto v : vertices(m)) {
    const double d = dist(vertex_vec3(m, v), p);
    if(d < bd) {
      bd = d;
      best = v;
    }
  }
  return best;
}

// `count` vertices spread over the mesh (deterministic: every (n/count)-th vertex of the iteration order).
template <class Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> spread_vertices(const Mesh& m, std::size_t count,
                                                                                   std::size_t offset = 0)
{
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> all(vertices(m).begin(), vertices(m).end()), r;
  const std::size_t n = all.size();
  for(std::size_t i = 0; i < count && i < n; ++i)
    r.push_back(all[(offset + (i * n) / count + i * 7919) % n]);
  std::sort(r.begin(), r.end());
  r.erase(std::unique(r.begin(), r.end()), r.end());
  return r;
}

// The relative agreement required of the exact methods (with each other and with analytic values).
const double tolerance = 1e-12;

inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

// Position of `v` in vertices(m) (num_vertices(m) if absent), and the vertex at a position.
template <class Mesh>
std::size_t index_of(const Mesh& m, typename boost::graph_traits<Mesh>::vertex_descriptor v)
{
  return std::size_t(std::distance(vertices(m).begin(), std::find(vertices(m).begin(), vertices(m).end(), v)));
}
template <class Mesh>
typename boost::graph_traits<Mesh>::vertex_descriptor vertex_at(const Mesh& m, std::size_t i)
{
  return *std::next(vertices(m).begin(), std::ptrdiff_t(i));
}

} // namespace MDCS_test

#endif // MDCS_TEST_GEODESIC_TEST_GEOMETRY_H
