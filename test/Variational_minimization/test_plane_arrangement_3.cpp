// Tests of the BSP plane arrangement (Plane_arrangement_3): invariants of the cell complex (volume, Euler
// characteristic, adjacency, convexity checked with the exact predicate), the cell count of simple arrangements,
// degenerate configurations (pencils, planes through corners and edges, duplicates), the exact predicate against
// GMP integers, and bad input.
#include <catch2/catch.hpp>

#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Gmpz.h>

#include <cmath>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

namespace VM = CGAL::Variational_minimization;
typedef VM::Plane_arrangement_3 Arr3;

namespace {

const std::int64_t L = Arr3::lattice_size;

VM::Lattice_plane_3 plane(std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d)
{
  VM::Lattice_plane_3 p;
  p.a = a; p.b = b; p.c = c; p.d = d;
  return p;
}

// Random planes through random points of the box, normals up to 2^20.
std::vector<VM::Lattice_plane_3> random_planes(std::size_t n, std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> N;
  std::uniform_real_distribution<double> U(0, double(L));
  std::vector<VM::Lattice_plane_3> out;
  for(std::size_t i = 0; i < n; ++i) {
    const double a = N(rng), b = N(rng), c = N(rng);
    const double s = double(1 << 20) / std::max({std::abs(a), std::abs(b), std::abs(c)});
    VM::Lattice_plane_3 p = plane(std::llround(a * s), std::llround(b * s), std::llround(c * s), 0);
    p.d = -std::llround(double(p.a) * U(rng) + double(p.b) * U(rng) + double(p.c) * U(rng));
    out.push_back(p);
  }
  return out;
}

// Signed volume of a cell by the divergence theorem (fan triangles of each facet, outward orientation from the
// facet plane and the side of the cell).
double cell_volume(const Arr3& A, Arr3::Cell_index c)
{
  double vol = 0;
  for(Arr3::Facet_index f : A.cell_facets(c)) {
    const Arr3::Facet& x = A.facet(f);
    const VM::Lattice_plane_3& P = A.plane(x.plane);
    const double out = (x.negative_cell == c) ? 1.0 : -1.0; // outward normal = +/- (a, b, c)
    const std::vector<Arr3::Vertex_index> v = A.facet_vertices(f);
    const auto& p0 = A.point(v[0]);
    for(std::size_t k = 1; k + 1 < v.size(); ++k) {
      const auto& p1 = A.point(v[k]);
      const auto& p2 = A.point(v[k + 1]);
      const double u[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
      const double w[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
      double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
      const double dot = n[0] * double(P.a) + n[1] * double(P.b) + n[2] * double(P.c);
      const double sgn = (dot >= 0 ? 1.0 : -1.0) * out; // orient the triangle outwards
      vol += sgn * (n[0] * p0[0] + n[1] * p0[1] + n[2] * p0[2]) / 6.0;
    }
  }
  return vol;
}

// Checks every invariant of the complex; returns the number of cells.
std::size_t check_complex(const Arr3& A, bool check_convexity)
{
  double volume = 0;
  std::size_t boundary = 0;
  std::vector<int> wall_area_count(6, 0);
  for(Arr3::Cell_index c = 0; c < A.number_of_cells(); ++c) {
    const double v = cell_volume(A, c);
    CHECK(v > 0);
    volume += v;
    std::set<Arr3::Vertex_index> vertices;
    std::size_t half_edges = 0;
    for(Arr3::Facet_index f : A.cell_facets(c)) {
      const Arr3::Facet& x = A.facet(f);
      CHECK((x.negative_cell == c || x.positive_cell == c)); // adjacency symmetric
      CHECK(x.negative_cell != x.positive_cell);
      for(Arr3::Vertex_index w : A.facet_vertices(f)) vertices.insert(w);
      half_edges += A.facet_degree(f);
      CHECK(A.facet_degree(f) >= 3);
    }
    // Euler characteristic of the boundary sphere of a convex polyhedron: V - E + F = 2.
    CHECK(long(vertices.size()) - long(half_edges / 2) + long(A.cell_facets(c).size()) == 2);
    CHECK(half_edges % 2 == 0);
    if(check_convexity)
      for(Arr3::Facet_index f : A.cell_facets(c)) {
        const Arr3::Facet& x = A.facet(f);
        const int inside = (x.negative_cell == c) ? -1 : 1;
        for(Arr3::Vertex_index w : vertices) {
          const int s = A.side(w, x.plane);
          CHECK((s == 0 || s == inside));
        }
        for(Arr3::Vertex_index w : A.facet_vertices(f)) CHECK(A.side(w, x.plane) == 0);
      }
  }
  for(Arr3::Facet_index f = 0; f < A.number_of_facets(); ++f) {
    const Arr3::Facet& x = A.facet(f);
    const bool on_wall = A.is_boundary_facet(f);
    CHECK(on_wall == (x.negative_cell == Arr3::null_index || x.positive_cell == Arr3::null_index));
    if(on_wall) ++boundary;
    for(Arr3::Cell_index c : {x.negative_cell, x.positive_cell})
      if(c != Arr3::null_index) {
        const auto& list = A.cell_facets(c);
        CHECK(std::count(list.begin(), list.end(), f) == 1);
      }
  }
  CHECK(boundary > 0);
  CHECK(std::abs(volume / std::pow(double(L), 3) - 1) <= 1e-9);
  return A.number_of_cells();
}

} // namespace

TEST_CASE("Plane_arrangement_3: the box alone", "[variational][surface][arrangement]")
{
  const Arr3 A;
  CHECK(A.number_of_cells() == 1);
  CHECK(A.number_of_facets() == 6);
  CHECK(A.number_of_vertices() == 8);
  CHECK(A.number_of_planes() == 6);
  check_complex(A, true);
}

TEST_CASE("Plane_arrangement_3: random planes keep every invariant", "[variational][surface][arrangement]")
{
  for(std::uint64_t seed : {1u, 2u, 3u}) {
    const Arr3 A(random_planes(25, seed));
    check_complex(A, true);
    CHECK(A.number_of_cells() > 200);
  }
  const Arr3 B(random_planes(60, 7));
  check_complex(B, false);
}

TEST_CASE("Plane_arrangement_3: insertions after a construction rebuild the released tree",
          "[variational][surface][arrangement]")
{
  for(std::uint64_t seed : {4u, 5u}) {
    const std::vector<VM::Lattice_plane_3> planes = random_planes(40, seed);
    const Arr3 all(planes);
    CHECK(all.number_of_tree_nodes() == 0); // released by the constructor
    Arr3 A(std::vector<VM::Lattice_plane_3>(planes.begin(), planes.begin() + 20));
    Arr3 C; // incremental from the box: the tree is kept
    for(std::size_t i = 0; i < planes.size(); ++i) {
      if(i >= 20) CHECK(A.insert_plane(planes[i]));
      CHECK(C.insert_plane(planes[i]));
    }
    CHECK(A.number_of_tree_nodes() == 2 * A.number_of_cells() - 1);
    CHECK(A.number_of_cells() == all.number_of_cells());
    CHECK(A.number_of_facets() == all.number_of_facets());
    CHECK(A.number_of_vertices() == all.number_of_vertices());
    CHECK(C.number_of_cells() == all.number_of_cells());
    CHECK(C.number_of_facets() == all.number_of_facets());
    check_complex(A, true);
    check_complex(C, false);
  }
}

TEST_CASE("Plane_arrangement_3: cell count of a simple arrangement", "[variational][surface][arrangement]")
{
  // Planes through points near the centre with well-spread normals: all triple intersections inside the box, so
  // the cells inside the box are all the cells of the arrangement in space: 1 + n + C(n,2) + C(n,3).
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<std::int64_t> N(-1000, 1000), P(L / 2 - 300, L / 2 + 300);
  int tested = 0;
  for(int trial = 0; trial < 20; ++trial) {
    std::vector<VM::Lattice_plane_3> planes;
    for(int i = 0; i < 7; ++i) {
      VM::Lattice_plane_3 p = plane(N(rng), N(rng), N(rng), 0);
      p.d = -(p.a * P(rng) + p.b * P(rng) + p.c * P(rng));
      planes.push_back(p);
    }
    // Only keep the trial if every triple meets at a single point strictly inside the box (checked in doubles).
    bool simple = true;
    for(int i = 0; i < 7 && simple; ++i)
      for(int j = i + 1; j < 7 && simple; ++j)
        for(int k = j + 1; k < 7 && simple; ++k) {
          const VM::internal::Exact_vertex_3 x =
            VM::internal::intersect_planes(planes[i], planes[j], planes[k]);
          if(x.den == 0) { simple = false; break; }
          const auto q = VM::internal::approximate_point(x);
          for(double c : q) simple = simple && c > 1 && c < double(L) - 1;
        }
    if(!simple) continue;
    ++tested;
    const Arr3 A(planes);
    const std::size_t n = 7;
    CHECK(A.number_of_cells() == 1 + n + n * (n - 1) / 2 + n * (n - 1) * (n - 2) / 6);
    check_complex(A, true);
  }
  CHECK(tested >= 3);
}

TEST_CASE("Plane_arrangement_3: degenerate configurations", "[variational][surface][arrangement]")
{
  // A pencil of k planes through the vertical line X = Y = L/2: 2k wedges; a horizontal plane doubles them.
  std::vector<VM::Lattice_plane_3> planes;
  const int k = 9;
  for(int i = 0; i < k; ++i) {
    const std::int64_t a = 1000 - 200 * i, b = 37 + 100 * i;
    planes.push_back(plane(a, b, 0, -(a + b) * (L / 2)));
  }
  {
    const Arr3 A(planes);
    CHECK(A.number_of_cells() == std::size_t(2 * k));
    check_complex(A, true);
  }
  planes.push_back(plane(0, 0, 1, -L / 3));
  {
    const Arr3 A(planes);
    CHECK(A.number_of_cells() == std::size_t(4 * k));
    check_complex(A, true);
  }
  // Planes through box corners, a box edge and the centre; duplicates (scaled) and a wall; a plane touching only a
  // corner; a pencil through a line inside the box lying in another plane.
  std::vector<VM::Lattice_plane_3> d = {
    plane(1, 1, 1, -L),           plane(1, 1, 1, -2 * L),     plane(1, -1, 0, 0),  plane(2, -2, 0, 0),
    plane(0, 1, -1, 0),           plane(1, 0, -1, 0),         plane(3, 0, 0, -3 * L), plane(1, 1, 1, -3 * L),
    plane(1, 1, -1, -L / 2),      plane(1, 1, -2, 0),         plane(1, 1, -3, L / 2), plane(0, 0, 1, -L / 2),
    plane(5, 3, -8, 0),           plane(1, 2, 3, -3 * L)};
  const Arr3 A(d);
  CHECK(!A.is_plane_used(6 + 3)); // duplicate of plane 6 + 2
  CHECK(!A.is_plane_used(6 + 6)); // the wall X = L
  CHECK(!A.is_plane_used(6 + 7)); // touches the box only at the corner (L, L, L)
  CHECK(A.is_plane_used(6 + 0));
  check_complex(A, true);
  // The same planes inserted in another order give the same complex size.
  std::vector<VM::Lattice_plane_3> r(d.rbegin(), d.rend());
  const Arr3 B(r);
  CHECK(B.number_of_cells() == A.number_of_cells());
  CHECK(B.number_of_facets() == A.number_of_facets());
  CHECK(B.number_of_vertices() == A.number_of_vertices());
}

TEST_CASE("Plane_arrangement_3: the filtered predicate agrees with GMP", "[variational][surface][arrangement]")
{
  const Arr3 A(random_planes(20, 5));
  std::mt19937_64 rng(3);
  std::size_t zeros = 0;
  for(int trial = 0; trial < 3000; ++trial) {
    const Arr3::Vertex_index v = Arr3::Vertex_index(rng() % A.number_of_vertices());
    const Arr3::Plane_index p = Arr3::Plane_index(rng() % A.number_of_planes());
    const auto& t = A.vertex_planes(v);
    // Cramer's rule and the 4x4 sign with GMP integers.
    CGAL::Gmpz m[3][4];
    for(int i = 0; i < 3; ++i) {
      const VM::Lattice_plane_3& q = A.plane(t[i]);
      m[i][0] = CGAL::Gmpz(double(q.a)); m[i][1] = CGAL::Gmpz(double(q.b));
      m[i][2] = CGAL::Gmpz(double(q.c)); m[i][3] = CGAL::Gmpz(double(-q.d));
    }
    auto det = [&](int c0, int c1, int c2) {
      return m[0][c0] * (m[1][c1] * m[2][c2] - m[2][c1] * m[1][c2]) -
             m[0][c1] * (m[1][c0] * m[2][c2] - m[2][c0] * m[1][c2]) +
             m[0][c2] * (m[1][c0] * m[2][c1] - m[2][c0] * m[1][c1]);
    };
    const CGAL::Gmpz D = det(0, 1, 2), X = det(3, 1, 2), Y = det(0, 3, 2), Z = det(0, 1, 3);
    const VM::Lattice_plane_3& q = A.plane(p);
    const CGAL::Gmpz value = CGAL::Gmpz(double(q.a)) * X + CGAL::Gmpz(double(q.b)) * Y +
                             CGAL::Gmpz(double(q.c)) * Z + CGAL::Gmpz(double(q.d)) * D;
    const int expected = CGAL::sign(value) * CGAL::sign(D);
    CHECK(A.side(v, p) == expected);
    if(expected == 0) ++zeros;
  }
  // The vertex planes themselves give exact zeros.
  for(Arr3::Vertex_index v = 0; v < A.number_of_vertices(); v += 7)
    for(Arr3::Plane_index p : A.vertex_planes(v)) CHECK(A.side(v, p) == 0);
  CHECK(zeros > 0);
}

TEST_CASE("Plane_arrangement_3: bad planes are rejected", "[variational][surface][arrangement]")
{
  CHECK_THROWS_AS(Arr3({plane(0, 0, 0, 5)}), std::invalid_argument);
  CHECK_THROWS_AS(Arr3({plane(std::int64_t(1) << 30, 1, 1, 0)}), std::invalid_argument);
  CHECK_THROWS_AS(Arr3({plane(1, 1, 1, std::int64_t(1) << 50)}), std::invalid_argument);
  Arr3 A;
  CHECK(A.insert_plane(plane(1, 0, 0, -L / 2)));
  CHECK(!A.insert_plane(plane(-2, 0, 0, L)));
  CHECK(A.number_of_cells() == 2);
}

TEST_CASE("Plane_arrangement_3: progress and cancellation", "[variational][surface][arrangement]")
{
  int calls = 0;
  const Arr3 A(random_planes(10, 1), [&](const char*, double) { ++calls; return true; });
  CHECK(calls >= 2);
  CHECK_THROWS_AS(Arr3(random_planes(10, 1), [](const char*, double f) { return f < 0.5; }),
                  CGAL::MDCS::Operation_cancelled);
}
