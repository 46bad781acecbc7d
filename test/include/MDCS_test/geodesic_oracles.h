// Independent oracles for the tests of geodesic distances on triangle meshes:
//  - CGAL's Surface_mesh_shortest_path (Xin and Wang's exact algorithm, a different implementation) from
//    vertex sources or surface points;
//  - Dijkstra over the mesh edges (an upper bound of every geodesic distance from vertex sources);
//  - analytic distances: the unit cube from a corner, the regular tetrahedron from a vertex (unfoldings),
//    a convex planar domain (Euclidean), a square with a rectangular hole (visibility graph);
//  - mesh builders: jittered planar grids, the subdivided unit cube, needle strips, grids with degenerate
//    (zero-length edge, collinear) triangles, a square with a hole, two components, a quad mesh.
// Everything here is plain double arithmetic written independently of the package under test.
#ifndef MDCS_TEST_GEODESIC_ORACLES_H
#define MDCS_TEST_GEODESIC_ORACLES_H

#include <MDCS_test/geodesic_test_geometry.h>
#include <MDCS_test/mesh_generators.h>

#include <CGAL/Surface_mesh_shortest_path.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <iomanip>
#include <ostream>
#include <limits>
#include <map>
#include <queue>
#include <random>
#include <sstream>
#include <string>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

namespace MDCS_test {

// ---------------------------------------------------------------------------------------------------------
// Oracle 1: CGAL's Surface_mesh_shortest_path. Requires a mesh with internal indices (Surface_mesh, or
// Polyhedron_3 with ids). Distances are doubles; unreachable points give +infinity.

template <class K, class Mesh>
class Smsp_oracle
{
  typedef CGAL::Surface_mesh_shortest_path_traits<K, Mesh> Traits;
  typedef CGAL::Surface_mesh_shortest_path<Traits> SMSP;
  typedef boost::graph_traits<Mesh> GT;

public:
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename Traits::Barycentric_coordinates Barycentric_coordinates;

  explicit Smsp_oracle(const Mesh& m) : mesh_(m), smsp_(m) {}

  void add_source(vertex_descriptor v) { smsp_.add_source_point(v); }
  void add_source(face_descriptor f, const std::array<double, 3>& b)
  {
    smsp_.add_source_point(f, Barycentric_coordinates{{typename K::FT(b[0]), typename K::FT(b[1]), typename K::FT(b[2])}});
  }

  double distance(vertex_descriptor v)
  {
    const auto r = smsp_.shortest_distance_to_source_points(v);
    const double d = CGAL::to_double(r.first);
    return d < 0 ? inf : d;
  }

  double distance(face_descriptor f, const std::array<double, 3>& b)
  {
    const auto r = smsp_.shortest_distance_to_source_points(
        f, Barycentric_coordinates{{typename K::FT(b[0]), typename K::FT(b[1]), typename K::FT(b[2])}});
    const double d = CGAL::to_double(r.first);
    return d < 0 ? inf : d;
  }

  // Index (order of addition) of the nearest source of vertex v.
  std::size_t nearest_source(vertex_descriptor v)
  {
    const auto r = smsp_.shortest_distance_to_source_points(v);
    if(r.second == smsp_.source_points_end())
      return std::size_t(-1);
    return std::size_t(std::distance(smsp_.source_points_begin(), r.second));
  }

  void build() { smsp_.build_sequence_tree(); }

  // The points of Surface_mesh_shortest_path's shortest path from v to its nearest source.
  std::vector<typename K::Point_3> path_points(vertex_descriptor v)
  {
    std::vector<typename K::Point_3> pts;
    smsp_.shortest_path_points_to_source_points(v, std::back_inserter(pts));
    return pts;
  }

private:
  const Mesh& mesh_;
  SMSP smsp_;
};

// Distances from the vertex sources to every vertex, in the order of vertices(m).
template <class K, class Mesh, class VertexRange>
std::vector<double> smsp_vertex_distances(const Mesh& m, const VertexRange& sources)
{
  Smsp_oracle<K, Mesh> oracle(m);
  for(auto s : sources)
    oracle.add_source(s);
  oracle.build();
  std::vector<double> r;
  for(auto v : vertices(m))
    r.push_back(oracle.distance(v));
  return r;
}

// Is the polyline `points` a path on the surface of m, i.e. does every point lie on a face (within tol) and every
// two consecutive points on a common face? (Brute force over the faces: for diagnostics on a few paths.) A valid
// surface path of length L proves that the geodesic distance between its ends is <= L.
template <class Mesh, class Point>
bool is_surface_path(const Mesh& m, const std::vector<Point>& points, double tol, std::size_t* first_bad = nullptr)
{
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  std::vector<std::vector<face_descriptor>> on;
  for(const auto& P : points) {
    const Vec3 p = to_vec3(P);
    std::vector<face_descriptor> fs;
    for(auto f : faces(m)) {
      const auto vs = face_vertices(m, f);
      const Vec3 a = vertex_vec3(m, vs[0]), b = vertex_vec3(m, vs[1]), c = vertex_vec3(m, vs[2]);
      // distance from p to the triangle, by the closest point among the interior projection and the edges
      const Vec3 n = cross(sub(b, a), sub(c, a));
      const double n2 = dot(n, n);
      double d = std::min({distance_to_segment(p, a, b), distance_to_segment(p, b, c), distance_to_segment(p, c, a)});
      if(n2 > 0) {
        const double l0 = dot(cross(sub(b, p), sub(c, p)), n) / n2, l1 = dot(cross(sub(c, p), sub(a, p)), n) / n2;
        if(l0 >= 0 && l1 >= 0 && l0 + l1 <= 1)
          d = std::min(d, std::abs(dot(sub(p, a), n)) / std::sqrt(n2));
      }
      if(d <= tol)
        fs.push_back(f);
    }
    on.push_back(fs);
  }
  for(std::size_t i = 0; i < on.size(); ++i) {
    bool ok = !on[i].empty();
    if(ok && i > 0) {
      ok = false;
      for(auto f : on[i])
        if(std::find(on[i - 1].begin(), on[i - 1].end(), f) != on[i - 1].end())
          ok = true;
    }
    if(!ok) {
      if(first_bad) *first_bad = i;
      return false;
    }
  }
  return true;
}

// ---------------------------------------------------------------------------------------------------------
// Oracle 2: Dijkstra over the mesh edges, in the order of vertices(m). Every geodesic distance from the same
// vertex sources is <= this (edge paths lie on the surface).

template <class Mesh, class VertexRange>
std::vector<double> dijkstra_vertex_distances(const Mesh& m, const VertexRange& sources)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  auto vim = CGAL::get_initialized_vertex_index_map(m);
  const std::size_t n = num_vertices(m);
  std::vector<double> d(n, inf);
  std::vector<vertex_descriptor> vd(n);
  for(auto v : vertices(m))
    vd[get(vim, v)] = v;
  typedef std::pair<double, std::size_t> Item;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for(auto s : sources) {
    d[get(vim, s)] = 0;
    queue.push({0.0, std::size_t(get(vim, s))});
  }
  while(!queue.empty()) {
    const Item it = queue.top();
    queue.pop();
    if(it.first > d[it.second])
      continue;
    const vertex_descriptor v = vd[it.second];
    if(halfedge(v, m) == boost::graph_traits<Mesh>::null_halfedge())
      continue;
    for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m)) {
      const vertex_descriptor w = source(h, m);
      const std::size_t wi = get(vim, w);
      const double nd = it.first + dist(vertex_vec3(m, v), vertex_vec3(m, w));
      if(nd < d[wi]) {
        d[wi] = nd;
        queue.push({nd, wi});
      }
    }
  }
  std::vector<double> r;
  for(auto v : vertices(m))
    r.push_back(d[get(vim, v)]);
  return r;
}

// ---------------------------------------------------------------------------------------------------------
// Oracle 3: analytic distances.

// Distance on the surface of the unit cube [0,1]^3 from the corner (0,0,0) to a surface point p. On the three
// faces through the corner it is Euclidean; a point on a far face (say x = 1) is reached across one of the two
// near faces that share an edge with it (y = 0 or z = 0), unfolded: sqrt((1+y)^2 + z^2) or sqrt((1+z)^2 + y^2).
inline double cube_corner_distance(const Vec3& p, double tol = 1e-12)
{
  for(int k = 0; k < 3; ++k)
    if(std::abs(p[std::size_t(k)]) <= tol)
      return norm(p);
  double best = inf;
  for(int k = 0; k < 3; ++k) {
    if(std::abs(p[std::size_t(k)] - 1) > tol)
      continue;
    const double a = p[std::size_t((k + 1) % 3)], b = p[std::size_t((k + 2) % 3)];
    best = std::min(best, std::sqrt((1 + a) * (1 + a) + b * b));
    best = std::min(best, std::sqrt((1 + b) * (1 + b) + a * a));
  }
  if(best == inf)
    throw std::invalid_argument("cube_corner_distance: the point is not on the unit cube");
  return best;
}

// The length of the straight path from s to p through the edge [a, b], after unfolding the triangle (a, b, s)
// into the plane of the triangle (a, b, c) on the other side of ab (p lies in (a, b, c)). +infinity if the
// unfolded segment does not cross [a, b] (then this unfolding is not a path on the surface).
inline double unfolded_distance(const Vec3& s, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p)
{
  const Vec3 ab = sub(b, a);
  const double L = norm(ab);
  const Vec3 ex = {ab[0] / L, ab[1] / L, ab[2] / L};
  auto frame = [&](const Vec3& q, double& x, double& y) {
    const Vec3 aq = sub(q, a);
    x = dot(aq, ex);
    const Vec3 perp = {aq[0] - x * ex[0], aq[1] - x * ex[1], aq[2] - x * ex[2]};
    y = norm(perp);
  };
  double cx, cy, px, py, sx, sy;
  frame(c, cx, cy);
  frame(s, sx, sy);
  sy = -sy; // s on the other side of ab
  // p in the frame: the sign of its y is the side of c (p is in triangle abc)
  {
    const Vec3 ap = sub(p, a);
    px = dot(ap, ex);
    const Vec3 perp = {ap[0] - px * ex[0], ap[1] - px * ex[1], ap[2] - px * ex[2]};
    py = norm(perp);
    (void)cx;
    (void)cy;
  }
  // crossing with y = 0
  const double t = (0 - sy) / (py - sy);
  const double x = sx + t * (px - sx);
  if(x < -1e-12 * L || x > L * (1 + 1e-12))
    return inf;
  return std::hypot(px - sx, py - sy);
}

// The distance on a tetrahedron (any shape with all its face angles acute is fine, e.g. the regular one) from
// its vertex s to a point p of the face (a, b, c) opposite s: the shortest of the three unfoldings across the
// edges of that face (a shortest path from a vertex first crosses one face incident to it, then enters the
// opposite face through its edge; no shortest path passes through a vertex of total angle < 2 pi).
inline double tetrahedron_opposite_face_distance(const Vec3& s, const Vec3& a, const Vec3& b, const Vec3& c,
                                                 const Vec3& p)
{
  return std::min({unfolded_distance(s, a, b, c, p), unfolded_distance(s, b, c, a, p), unfolded_distance(s, c, a, b, p)});
}

// Shortest distance in the square [0,w]x[0,h] minus the open axis-aligned rectangle (x0,x1)x(y0,y1) (the
// hole), between two points of the domain: a shortest path is a polygonal line whose inner vertices are
// corners of the hole (visibility graph).
struct Rectangle_hole_domain
{
  double x0, y0, x1, y1;

  // does the segment [p, q] meet the open rectangle? (Liang-Barsky clipping against the shrunk open box)
  bool blocked(const Vec3& p, const Vec3& q) const
  {
    const double eps = 1e-12;
    double t0 = 0, t1 = 1;
    const double dx = q[0] - p[0], dy = q[1] - p[1];
    const double pp[4] = {-dx, dx, -dy, dy};
    const double qq[4] = {p[0] - (x0 + eps), (x1 - eps) - p[0], p[1] - (y0 + eps), (y1 - eps) - p[1]};
    for(int i = 0; i < 4; ++i) {
      if(pp[i] == 0) {
        if(qq[i] <= 0)
          return false;
      }
      else {
        const double r = qq[i] / pp[i];
        if(pp[i] < 0) {
          if(r > t1) return false;
          if(r > t0) t0 = r;
        }
        else {
          if(r < t0) return false;
          if(r < t1) t1 = r;
        }
      }
    }
    return t1 - t0 > 1e-12;
  }

  double distance(const Vec3& s, const Vec3& p) const
  {
    const std::array<Vec3, 4> corner = {Vec3{x0, y0, 0}, Vec3{x1, y0, 0}, Vec3{x1, y1, 0}, Vec3{x0, y1, 0}};
    // Dijkstra on the 4 corners (tiny: Bellman-Ford style relaxation)
    std::array<double, 4> d;
    for(int i = 0; i < 4; ++i)
      d[std::size_t(i)] = blocked(s, corner[std::size_t(i)]) ? inf : dist(s, corner[std::size_t(i)]);
    for(int round = 0; round < 4; ++round)
      for(int i = 0; i < 4; ++i)
        for(int j = 0; j < 4; ++j)
          if(i != j && !blocked(corner[std::size_t(i)], corner[std::size_t(j)]))
            d[std::size_t(j)] = std::min(d[std::size_t(j)], d[std::size_t(i)] + dist(corner[std::size_t(i)], corner[std::size_t(j)]));
    double best = blocked(s, p) ? inf : dist(s, p);
    for(int i = 0; i < 4; ++i)
      if(!blocked(corner[std::size_t(i)], p))
        best = std::min(best, d[std::size_t(i)] + dist(corner[std::size_t(i)], p));
    return best;
  }
};

// ---------------------------------------------------------------------------------------------------------
// Mesh builders (Triangle_soup, see mesh_generators.h).

// The planar grid [0,w]x[0,h] (z = 0) of planar_grid() with every vertex moved randomly by up to `jitter` times
// the cell size in x and y; boundary vertices move along the boundary only and corners stay, so the domain stays
// the (convex) rectangle. jitter <= 0.2 keeps every triangle positively oriented (checked).
template <class Point_3>
Triangle_soup<Point_3> jittered_planar_grid(std::size_t nx, std::size_t ny, double w, double h, double jitter,
                                           unsigned seed)
{
  Triangle_soup<Point_3> soup = planar_grid<Point_3>(nx, ny, w, h);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  const double cx = w / double(nx), cy = h / double(ny);
  for(std::size_t j = 0; j <= ny; ++j)
    for(std::size_t i = 0; i <= nx; ++i) {
      Point_3& p = soup.points[j * (nx + 1) + i];
      double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
      const double dx = u(rng) * cx, dy = u(rng) * cy;
      if(i != 0 && i != nx) x += dx;
      if(j != 0 && j != ny) y += dy;
      p = Point_3(x, y, 0);
    }
  for(const auto& t : soup.triangles) {
    const Vec3 a = to_vec3(soup.points[t[0]]), b = to_vec3(soup.points[t[1]]), c = to_vec3(soup.points[t[2]]);
    if(cross(sub(b, a), sub(c, a))[2] <= 0)
      throw std::logic_error("jittered_planar_grid: a triangle flipped (jitter too large)");
  }
  return soup;
}

// The grid [0,1]^2 (z = 0) of planar_grid() sheared to the parallelogram x' = x + 0.9 y: half of its triangles have
// an obtuse corner.
template <class Point_3>
Triangle_soup<Point_3> sheared_planar_grid(std::size_t n)
{
  Triangle_soup<Point_3> soup = planar_grid<Point_3>(n, n);
  for(Point_3& p : soup.points)
    p = Point_3(CGAL::to_double(p.x()) + 0.9 * CGAL::to_double(p.y()), CGAL::to_double(p.y()), 0);
  return soup;
}

// The surface of the unit cube [0,1]^3, every face an n x n grid of squares split along alternating diagonals,
// outward oriented, closed (6 n^2 + 2 vertices, 12 n^2 triangles).
template <class Point_3>
Triangle_soup<Point_3> subdivided_cube(std::size_t n)
{
  if(n == 0) throw std::invalid_argument("subdivided_cube: n must be positive");
  Triangle_soup<Point_3> soup;
  std::map<std::array<std::size_t, 3>, std::size_t> index;
  auto id = [&](std::array<std::size_t, 3> c) {
    auto it = index.find(c);
    if(it != index.end()) return it->second;
    soup.points.emplace_back(double(c[0]) / double(n), double(c[1]) / double(n), double(c[2]) / double(n));
    return index[c] = soup.points.size() - 1;
  };
  for(std::size_t a = 0; a < 3; ++a)
    for(std::size_t side = 0; side < 2; ++side) {
      const std::size_t u = (a + 1) % 3, v = (a + 2) % 3;
      for(std::size_t i = 0; i < n; ++i)
        for(std::size_t j = 0; j < n; ++j) {
          auto corner = [&](std::size_t di, std::size_t dj) {
            std::array<std::size_t, 3> c;
            c[a] = side * n;
            c[u] = i + di;
            c[v] = j + dj;
            return id(c);
          };
          const std::size_t p00 = corner(0, 0), p10 = corner(1, 0), p11 = corner(1, 1), p01 = corner(0, 1);
          std::array<std::size_t, 3> t1, t2;
          if((i + j) % 2 == 0) {
            t1 = {p00, p10, p11};
            t2 = {p00, p11, p01};
          }
          else {
            t1 = {p00, p10, p01};
            t2 = {p10, p11, p01};
          }
          if(side == 0) { // outward normal -a: reverse
            std::swap(t1[1], t1[2]);
            std::swap(t2[1], t2[2]);
          }
          soup.triangles.push_back(t1);
          soup.triangles.push_back(t2);
        }
    }
  return soup;
}

// A planar strip of needle triangles: bottom vertices (i/n, 0), i = 0..n, top vertices ((i+1/2)/n, width),
// i = 0..n-1, plus the two top corners (0, width) and (1, width). Aspect ratio ~ 1/(n width). Convex domain
// (the rectangle [0,1]x[0,width]).
template <class Point_3>
Triangle_soup<Point_3> needle_strip(std::size_t n, double width)
{
  Triangle_soup<Point_3> soup;
  for(std::size_t i = 0; i <= n; ++i)
    soup.points.emplace_back(double(i) / double(n), 0, 0); // 0..n
  soup.points.emplace_back(0, width, 0);                    // n+1
  for(std::size_t i = 0; i < n; ++i)
    soup.points.emplace_back((double(i) + 0.5) / double(n), width, 0); // n+2+i
  soup.points.emplace_back(1, width, 0);                                // 2n+2
  auto top = [&](std::size_t i) { return n + 2 + i; };                  // i in [0, n)
  soup.triangles.push_back({0, top(0), n + 1});
  for(std::size_t i = 0; i < n; ++i) {
    soup.triangles.push_back({i, i + 1, top(i)});
    if(i + 1 < n)
      soup.triangles.push_back({i + 1, top(i + 1), top(i)});
  }
  soup.triangles.push_back({n, 2 * n + 2, top(n - 1)});
  return soup;
}

// The planar grid [0,1]^2 (nx x nx cells) with columns of vertices at x and x + gap (gap tiny), so the cells
// of that column are needles of width `gap`. Convex domain.
template <class Point_3>
Triangle_soup<Point_3> grid_with_needle_column(std::size_t n, double x, double gap)
{
  std::vector<double> xs;
  for(std::size_t i = 0; i <= n; ++i)
    xs.push_back(double(i) / double(n));
  xs.push_back(x);
  xs.push_back(x + gap);
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  // the triangulation of planar_grid, with its columns moved to the abscissae xs
  const std::size_t nx = xs.size() - 1;
  Triangle_soup<Point_3> soup = planar_grid<Point_3>(nx, n);
  for(std::size_t j = 0; j <= n; ++j)
    for(std::size_t i = 0; i <= nx; ++i) {
      Point_3& p = soup.points[j * (nx + 1) + i];
      p = Point_3(xs[i], p.y(), p.z());
    }
  return soup;
}

// Splits the (unique) edge {a, b} of the soup by a new vertex at `position`, splitting both incident triangles.
// With position == point a the new edge {a, new} has length zero and the triangles (a, new, c) have zero area.
template <class Point_3>
std::size_t split_soup_edge(Triangle_soup<Point_3>& soup, std::size_t a, std::size_t b, const Point_3& position)
{
  const std::size_t m = soup.points.size();
  soup.points.push_back(position);
  std::vector<std::array<std::size_t, 3>> out;
  std::size_t split = 0;
  for(const auto& t : soup.triangles) {
    int ia = -1, ib = -1;
    for(int k = 0; k < 3; ++k) {
      if(t[std::size_t(k)] == a) ia = k;
      if(t[std::size_t(k)] == b) ib = k;
    }
    if(ia < 0 || ib < 0) {
      out.push_back(t);
      continue;
    }
    ++split;
    // rotate so that the edge is (t0, t1) in the triangle's order
    std::array<std::size_t, 3> r = t;
    while(!((r[0] == a && r[1] == b) || (r[0] == b && r[1] == a)))
      r = {r[1], r[2], r[0]};
    out.push_back({r[0], m, r[2]});
    out.push_back({m, r[1], r[2]});
  }
  if(split == 0)
    throw std::invalid_argument("split_soup_edge: not an edge");
  soup.triangles.swap(out);
  return m;
}

// Planar grid [0,1]^2 (n x n cells, n >= 2) with a zero-length edge: the interior edge between the grid vertices
// (n/2, n/2) and (n/2+1, n/2) is split at a point coincident with (n/2, n/2), so two coincident vertices are
// joined by an edge and two triangles have zero area. Returns the soup; `coincident` receives the two indices.
template <class Point_3>
Triangle_soup<Point_3> grid_with_zero_length_edge(std::size_t n, std::array<std::size_t, 2>& coincident)
{
  Triangle_soup<Point_3> soup = planar_grid<Point_3>(n, n);
  const std::size_t a = (n / 2) * (n + 1) + n / 2, b = a + 1;
  const std::size_t m = split_soup_edge(soup, a, b, soup.points[a]);
  coincident = {a, m};
  return soup;
}

// Planar grid [0,1]^2 (n x n cells) with a collinear (cap) triangle of zero area and no short edge: the
// midpoint m of the horizontal edge {a, b} between grid vertices (n/2, n/2) and (n/2+1, n/2) becomes a vertex;
// the triangle on one side of the edge, (b, a, d), is split into (b, m, d), (m, a, d), the triangle on the
// other side, (a, b, c), stays, and the zero-area triangle (b, a, m) (angle pi at m) fills the gap between
// them. The surface is still the flat square (distances are Euclidean).
template <class Point_3>
Triangle_soup<Point_3> grid_with_cap_triangle(std::size_t n)
{
  Triangle_soup<Point_3> soup = planar_grid<Point_3>(n, n);
  const std::size_t i = n / 2, j = n / 2;
  const std::size_t a = j * (n + 1) + i, b = a + 1;
  const Vec3 pa = to_vec3(soup.points[a]), pb = to_vec3(soup.points[b]);
  const std::size_t m = soup.points.size();
  soup.points.emplace_back(0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]), 0);
  std::vector<std::array<std::size_t, 3>> out;
  int found = 0;
  for(const auto& t : soup.triangles) {
    int ia = -1, ib = -1;
    for(int k = 0; k < 3; ++k) {
      if(t[std::size_t(k)] == a) ia = k;
      if(t[std::size_t(k)] == b) ib = k;
    }
    if(ia < 0 || ib < 0) {
      out.push_back(t);
      continue;
    }
    std::array<std::size_t, 3> r = t;
    while(!((r[0] == a && r[1] == b) || (r[0] == b && r[1] == a)))
      r = {r[1], r[2], r[0]};
    if(r[0] == b) { // (b, a, d): split through m
      out.push_back({b, m, r[2]});
      out.push_back({m, a, r[2]});
      found |= 1;
    }
    else { // (a, b, c): keep, and glue the cap (b, a, m) on its edge
      out.push_back(r);
      out.push_back({b, a, m});
      found |= 2;
    }
  }
  if(found != 3)
    throw std::logic_error("grid_with_cap_triangle: construction failed");
  soup.triangles.swap(out);
  return soup;
}

// The square [0,1]^2 made of n x n grid cells minus the cells [i0, i1) x [j0, j1) (a rectangular hole).
template <class Point_3>
Triangle_soup<Point_3> square_with_hole(std::size_t n, std::size_t i0, std::size_t i1, std::size_t j0, std::size_t j1)
{
  Triangle_soup<Point_3> grid = planar_grid<Point_3>(n, n), soup;
  soup.points = grid.points;
  for(std::size_t j = 0, t = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i, t += 2)
      if(!(i >= i0 && i < i1 && j >= j0 && j < j1)) {
        soup.triangles.push_back(grid.triangles[t]);
        soup.triangles.push_back(grid.triangles[t + 1]);
      }
  // drop the vertices strictly inside the hole (unused) and renumber
  std::vector<std::size_t> index(soup.points.size(), std::size_t(-1));
  for(const auto& t : soup.triangles)
    for(std::size_t v : t) index[v] = 0;
  Triangle_soup<Point_3> compact;
  for(std::size_t v = 0; v < soup.points.size(); ++v)
    if(index[v] == 0) {
      index[v] = compact.points.size();
      compact.points.push_back(soup.points[v]);
    }
  for(const auto& t : soup.triangles)
    compact.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
  return compact;
}

// Two disjoint copies of the planar n x n grid: [0,1]^2 and [2,3]x[0,1]. The first (n+1)^2 vertices belong to
// the first component.
template <class Point_3>
Triangle_soup<Point_3> two_grids(std::size_t n)
{
  Triangle_soup<Point_3> a = planar_grid<Point_3>(n, n), soup = a;
  const std::size_t off = a.points.size();
  for(const auto& p : a.points)
    soup.points.emplace_back(CGAL::to_double(p.x()) + 2, CGAL::to_double(p.y()), 0);
  for(const auto& t : a.triangles)
    soup.triangles.push_back({t[0] + off, t[1] + off, t[2] + off});
  return soup;
}

// A terrain: the planar grid [0,1]^2 (n x n cells) lifted to z = amplitude * (sum of a few random bumps), with
// hills, pits and saddles and a boundary.
template <class Point_3>
Triangle_soup<Point_3> height_field_grid(std::size_t n, double amplitude, unsigned seed)
{
  Triangle_soup<Point_3> soup = planar_grid<Point_3>(n, n);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1), sgn(-1, 1);
  std::vector<std::array<double, 4>> bumps; // cx, cy, radius, height
  for(int k = 0; k < 6; ++k)
    bumps.push_back({u(rng), u(rng), 0.1 + 0.2 * u(rng), sgn(rng)});
  for(auto& p : soup.points) {
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
    double z = 0;
    for(const auto& b : bumps)
      z += b[3] * std::exp(-((x - b[0]) * (x - b[0]) + (y - b[1]) * (y - b[1])) / (b[2] * b[2]));
    p = Point_3(x, y, amplitude * z);
  }
  return soup;
}

// The icosphere with every vertex moved radially by a random factor in [1 - amplitude, 1 + amplitude]: a closed
// non-convex surface with saddle vertices (angle sum > 2 pi).
template <class Point_3>
Triangle_soup<Point_3> bumpy_sphere(std::size_t levels, double amplitude, unsigned seed)
{
  Triangle_soup<Point_3> soup = icosphere<Point_3>(levels);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(1 - amplitude, 1 + amplitude);
  for(auto& p : soup.points) {
    const double f = u(rng);
    p = Point_3(CGAL::to_double(p.x()) * f, CGAL::to_double(p.y()) * f, CGAL::to_double(p.z()) * f);
  }
  return soup;
}

// ---------------------------------------------------------------------------------------------------------
// Comparison of two distance vectors (expected = oracle, got = under test).

struct Distance_comparison
{
  double max_relative = 0;           // max |got - expected| / max(expected, floor) over finite pairs
  std::size_t worst = std::size_t(-1);
  double worst_expected = 0, worst_got = 0;
  std::size_t nans = 0;              // got is NaN
  std::size_t infinity_mismatches = 0; // exactly one of the two is infinite
  std::size_t first_bad = std::size_t(-1);
  std::size_t count = 0;

  bool ok(double tolerance) const { return nans == 0 && infinity_mismatches == 0 && max_relative <= tolerance; }
};

inline Distance_comparison compare_distances(const std::vector<double>& expected, const std::vector<double>& got,
                                             double floor_value)
{
  Distance_comparison c;
  if(expected.size() != got.size())
    throw std::invalid_argument("compare_distances: sizes differ");
  c.count = got.size();
  for(std::size_t i = 0; i < got.size(); ++i) {
    if(std::isnan(got[i]) || std::isnan(expected[i])) {
      ++c.nans;
      if(c.first_bad == std::size_t(-1)) c.first_bad = i;
      continue;
    }
    if(std::isinf(got[i]) != std::isinf(expected[i])) {
      ++c.infinity_mismatches;
      if(c.first_bad == std::size_t(-1)) c.first_bad = i;
      continue;
    }
    const double r = relative_difference(got[i], expected[i], floor_value);
    if(r > c.max_relative) {
      c.max_relative = r;
      c.worst = i;
      c.worst_expected = expected[i];
      c.worst_got = got[i];
    }
  }
  return c;
}

inline std::ostream& operator<<(std::ostream& os, const Distance_comparison& c)
{
  const auto old_precision = os.precision(17);
  os << "compared " << c.count << " values: max relative difference " << c.max_relative;
  if(c.worst != std::size_t(-1))
    os << " at #" << c.worst << " (expected " << c.worst_expected << ", got " << c.worst_got << ")";
  os << ", NaN: " << c.nans << ", finite/infinite mismatches: " << c.infinity_mismatches;
  if(c.first_bad != std::size_t(-1))
    os << " (first at #" << c.first_bad << ")";
  os.precision(old_precision);
  return os;
}

// The mesh of a triangle soup, checked: every triangle became a face and every point a vertex (in order).
template <class Mesh, class Point>
Mesh mesh_from_soup(const Triangle_soup<Point>& soup)
{
  Mesh m;
  soup.to_mesh(m);
  if(num_faces(m) != soup.triangles.size() || num_vertices(m) != soup.points.size())
    throw std::runtime_error("mesh_from_soup: the soup is not a valid polygon mesh");
  return m;
}

} // namespace MDCS_test

#endif // MDCS_TEST_GEODESIC_ORACLES_H
