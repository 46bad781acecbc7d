// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of Line_arrangement_2: structural invariants through the public API only, and comparison with
// CGAL::Arrangement_2 on an exact kernel (segments clipped exactly to the box) as the oracle.

#include <CGAL/Variational_minimization/Line_arrangement_2.h>
#include <CGAL/Variational_minimization/line_grids_2.h>

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace VM = CGAL::Variational_minimization;

namespace {

typedef VM::Line_arrangement_2 Arr;
typedef VM::Arrangement_line_2 Line;
typedef VM::Point_2 P;
typedef CGAL::Exact_predicates_exact_constructions_kernel EK;
typedef CGAL::Arrangement_2<CGAL::Arr_segment_traits_2<EK>> Oracle;

Line line(double px, double py, double qx, double qy) { return Line{ P(px, py), P(qx, qy) }; }

// ---------------------------------------------------------------------------------------------------
// The oracle: the lines clipped exactly to the box, the four walls, and the marks as points.
struct Oracle_arrangement
{
  Oracle arr;
  std::size_t bounded_faces = 0;
};

void build_oracle(const CGAL::Bbox_2& b, const std::vector<Line>& lines, const std::vector<double>& left_marks,
                  const std::vector<double>& right_marks, Oracle_arrangement& out)
{
  const EK::Iso_rectangle_2 rect(EK::Point_2(b.xmin(), b.ymin()), EK::Point_2(b.xmax(), b.ymax()));
  std::vector<EK::Segment_2> segments;
  for(const Line& l : lines) {
    const EK::Line_2 support(EK::Point_2(l.p.x(), l.p.y()), EK::Point_2(l.q.x(), l.q.y()));
    const auto clipped = CGAL::intersection(support, rect);
    if(!clipped) continue;
    if(const EK::Segment_2* s = boost::get<EK::Segment_2>(&*clipped)) segments.push_back(*s);
    // A single point is a corner, which is a vertex anyway.
  }
  const EK::Point_2 c[4] = { EK::Point_2(b.xmin(), b.ymin()), EK::Point_2(b.xmax(), b.ymin()),
                             EK::Point_2(b.xmax(), b.ymax()), EK::Point_2(b.xmin(), b.ymax()) };
  for(int i = 0; i < 4; ++i) segments.push_back(EK::Segment_2(c[i], c[(i + 1) % 4]));
  CGAL::insert(out.arr, segments.begin(), segments.end());
  for(double y : left_marks) CGAL::insert_point(out.arr, EK::Point_2(b.xmin(), y));
  for(double y : right_marks) CGAL::insert_point(out.arr, EK::Point_2(b.xmax(), y));
  out.bounded_faces = out.arr.number_of_faces() - 1;
}

// ---------------------------------------------------------------------------------------------------
// Invariants checked through the public API.
void check_invariants(const Arr& a)
{
  const std::size_t nv = a.number_of_vertices(), ne = a.number_of_edges(), nf = a.number_of_faces();
  const CGAL::Bbox_2& b = a.box();
  INFO("V = " << nv << ", E = " << ne << ", F = " << nf);
  // Euler's formula with the exterior face.
  REQUIRE(nv + nf + 1 == ne + 2);
  const double scale = (std::max)({ std::abs(b.xmin()), std::abs(b.xmax()), std::abs(b.ymin()), std::abs(b.ymax()) });
  const double tol = 1e-12 * scale;

  for(std::size_t v = 0; v < nv; ++v) {
    const P& p = a.point(Arr::Vertex_index(v));
    REQUIRE(p.x() >= b.xmin());
    REQUIRE(p.x() <= b.xmax());
    REQUIRE(p.y() >= b.ymin());
    REQUIRE(p.y() <= b.ymax());
  }

  // Edges: kinds, faces, orientation.
  std::vector<std::vector<std::pair<Arr::Edge_index, bool>>> sides(nf);   // (edge, face on its left?)
  for(std::size_t i = 0; i < ne; ++i) {
    const Arr::Edge_index e = Arr::Edge_index(i);
    const Arr::Edge& ed = a.edge(e);
    INFO("edge " << e << " kind " << int(ed.kind));
    REQUIRE(ed.source < nv);
    REQUIRE(ed.target < nv);
    REQUIRE(ed.source != ed.target);
    const P& s = a.point(ed.source);
    const P& t = a.point(ed.target);
    if(ed.kind == Arr::LINE_EDGE) {
      REQUIRE(ed.line < a.number_of_input_lines());
      REQUIRE(a.is_line_used(ed.line));
      REQUIRE(ed.left_face < nf);
      REQUIRE(ed.right_face < nf);
      REQUIRE(ed.left_face != ed.right_face);
      const Line& l = a.line(ed.line);
      REQUIRE(a.is_vertical(e) == (l.p.x() == l.q.x()));
    } else {
      REQUIRE(ed.line == Arr::null_index);
      const bool outside_left = (ed.kind == Arr::TOP_WALL || ed.kind == Arr::LEFT_WALL);
      REQUIRE((outside_left ? ed.left_face : ed.right_face) == Arr::null_index);
      REQUIRE((outside_left ? ed.right_face : ed.left_face) < nf);
      REQUIRE(a.is_vertical(e) == (ed.kind == Arr::LEFT_WALL || ed.kind == Arr::RIGHT_WALL));
    }
    // The order is exact (checked against the oracle); approximations of vertices closer than a few
    // ulps may swap, hence the tolerance.
    if(a.is_vertical(e)) {
      // Vertices on a vertical line or wall have that x exactly.
      REQUIRE(s.x() == t.x());
      REQUIRE(s.y() <= t.y() + tol);
    } else {
      REQUIRE(s.x() <= t.x() + tol);
    }
    if(ed.left_face != Arr::null_index) sides[ed.left_face].emplace_back(e, true);
    if(ed.right_face != Arr::null_index) sides[ed.right_face].emplace_back(e, false);
  }

  // Faces: each is one closed cycle, traversed counterclockwise (positive area); the areas sum to the box.
  double total = 0;
  for(std::size_t f = 0; f < nf; ++f) {
    INFO("face " << f);
    const auto& list = sides[f];
    REQUIRE(list.size() >= 3);
    std::map<Arr::Vertex_index, Arr::Vertex_index> next;   // boundary traversed with f on the left
    double area = 0;
    const P origin = a.point(a.edge(list.front().first).source);   // against cancellation far from 0
    for(const auto& side : list) {
      const Arr::Edge& ed = a.edge(side.first);
      const Arr::Vertex_index u = side.second ? ed.source : ed.target;
      const Arr::Vertex_index w = side.second ? ed.target : ed.source;
      REQUIRE(next.count(u) == 0);   // every boundary vertex is left exactly once
      next[u] = w;
      const P& pu = a.point(u);
      const P& pw = a.point(w);
      area += (pu.x() - origin.x()) * (pw.y() - origin.y()) - (pw.x() - origin.x()) * (pu.y() - origin.y());
    }
    // A single cycle through all boundary vertices.
    Arr::Vertex_index start = next.begin()->first, v = start;
    std::size_t steps = 0;
    do {
      REQUIRE(next.count(v) == 1);
      v = next[v];
      ++steps;
    } while(v != start && steps <= list.size());
    REQUIRE(v == start);
    REQUIRE(steps == list.size());
    // Counterclockwise: positive area, up to rounding for faces of a few ulps.
    REQUIRE(area >= -tol * scale);
    total += area / 2;
  }
  const double box_area = (b.xmax() - b.xmin()) * (b.ymax() - b.ymin());
  REQUIRE(total == Approx(box_area).epsilon(1e-9));

  // Walls: chains from corner to corner in the documented order.
  struct Wall_spec { Arr::Edge_kind kind; P from, to; };
  const Wall_spec walls[4] = { { Arr::LEFT_WALL, P(b.xmin(), b.ymin()), P(b.xmin(), b.ymax()) },
                               { Arr::RIGHT_WALL, P(b.xmax(), b.ymin()), P(b.xmax(), b.ymax()) },
                               { Arr::BOTTOM_WALL, P(b.xmin(), b.ymin()), P(b.xmax(), b.ymin()) },
                               { Arr::TOP_WALL, P(b.xmin(), b.ymax()), P(b.xmax(), b.ymax()) } };
  std::size_t wall_edge_count = 0;
  for(const Wall_spec& w : walls) {
    const auto& list = a.wall_edges(w.kind);
    REQUIRE(!list.empty());
    wall_edge_count += list.size();
    REQUIRE(a.point(a.edge(list.front()).source) == w.from);
    REQUIRE(a.point(a.edge(list.back()).target) == w.to);
    for(std::size_t k = 0; k < list.size(); ++k) {
      REQUIRE(a.edge(list[k]).kind == w.kind);
      if(k + 1 < list.size()) REQUIRE(a.edge(list[k]).target == a.edge(list[k + 1]).source);
      const P& p = a.point(a.edge(list[k]).target);
      if(w.kind == Arr::LEFT_WALL) REQUIRE(p.x() == b.xmin());
      if(w.kind == Arr::RIGHT_WALL) REQUIRE(p.x() == b.xmax());
      if(w.kind == Arr::BOTTOM_WALL) REQUIRE(p.y() == b.ymin());
      if(w.kind == Arr::TOP_WALL) REQUIRE(p.y() == b.ymax());
    }
  }
  std::size_t walls_in_edges = 0;
  for(std::size_t i = 0; i < ne; ++i) walls_in_edges += a.edge(Arr::Edge_index(i)).kind != Arr::LINE_EDGE;
  REQUIRE(walls_in_edges == wall_edge_count);
}

// ---------------------------------------------------------------------------------------------------
// Comparison with the oracle: counts, face sizes, vertex positions, and the orientation of every edge
// decided on the oracle's exact vertices.
void compare_with_oracle(const Arr& a, const std::vector<Line>& lines, const std::vector<double>& left_marks,
                         const std::vector<double>& right_marks)
{
  Oracle_arrangement o;
  build_oracle(a.box(), lines, left_marks, right_marks, o);
  REQUIRE(a.number_of_vertices() == o.arr.number_of_vertices());
  REQUIRE(a.number_of_edges() == o.arr.number_of_edges());
  REQUIRE(a.number_of_faces() == o.bounded_faces);

  // Multiset of face sizes.
  std::vector<std::size_t> ours(a.number_of_faces(), 0), theirs;
  for(std::size_t i = 0; i < a.number_of_edges(); ++i) {
    const Arr::Edge& ed = a.edge(Arr::Edge_index(i));
    if(ed.left_face != Arr::null_index) ++ours[ed.left_face];
    if(ed.right_face != Arr::null_index) ++ours[ed.right_face];
  }
  for(auto f = o.arr.faces_begin(); f != o.arr.faces_end(); ++f) {
    if(f->is_unbounded()) continue;
    REQUIRE(f->number_of_holes() == 0);
    std::size_t k = 0;
    auto h = f->outer_ccb(), start = h;
    do { ++k; } while(++h != start);
    theirs.push_back(k);
  }
  std::sort(ours.begin(), ours.end());
  std::sort(theirs.begin(), theirs.end());
  REQUIRE(ours == theirs);

  // Vertex positions: match every vertex with an oracle vertex within 1e-12 (relative to the box).
  const CGAL::Bbox_2& b = a.box();
  const double scale = (std::max)({ std::abs(b.xmin()), std::abs(b.xmax()), std::abs(b.ymin()), std::abs(b.ymax()),
                                    b.xmax() - b.xmin(), b.ymax() - b.ymin() });
  const double tol = 1e-12 * scale;
  // The sort keys are converted from the exact values: CGAL::to_double of a lazy EPECK number only
  // guarantees a relative precision of 1e-5 (Lazy_exact_nt::get_relative_precision_of_to_double), far
  // coarser than tol on small boxes, and how tight the cached interval is depends on which predicates
  // forced an exact evaluation before (CGAL's own assertions do in debug builds, not with NDEBUG).
  std::vector<std::pair<std::pair<double, double>, EK::Point_2>> exact;
  for(auto v = o.arr.vertices_begin(); v != o.arr.vertices_end(); ++v)
    exact.emplace_back(std::make_pair(CGAL::to_double(CGAL::exact(v->point().x())),
                                      CGAL::to_double(CGAL::exact(v->point().y()))),
                       v->point());
  std::sort(exact.begin(), exact.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<int> used(exact.size(), 0);
  std::vector<const EK::Point_2*> match(a.number_of_vertices(), nullptr);
  std::size_t ambiguous = 0;
  for(std::size_t v = 0; v < a.number_of_vertices(); ++v) {
    const P& p = a.point(Arr::Vertex_index(v));
    auto it = std::lower_bound(exact.begin(), exact.end(), p.x() - 2 * tol,   // keys: 1 ulp off at most
                               [](const auto& x, double key) { return x.first.first < key; });
    std::size_t found = 0;
    const EK::Point_2* hit = nullptr;
    for(; it != exact.end() && it->first.first <= p.x() + 2 * tol; ++it) {
      const EK::Point_2& q = it->second;
      // Compared exactly, for the same reason.
      const EK::FT etol(tol);
      if(CGAL::abs(q.x() - EK::FT(p.x())) <= etol && CGAL::abs(q.y() - EK::FT(p.y())) <= etol) {
        ++found;
        hit = &q;
        ++used[std::size_t(it - exact.begin())];
      }
    }
    INFO("vertex " << v << " at (" << p.x() << ", " << p.y() << ")");
    REQUIRE(found >= 1);
    if(found == 1) match[v] = hit; else ++ambiguous;
  }
  // Without ambiguity, the matching is a bijection.
  if(ambiguous == 0)
    for(int u : used) REQUIRE(u == 1);

  // Orientation and verticality, decided exactly on the oracle's points.
  for(std::size_t i = 0; i < a.number_of_edges(); ++i) {
    const Arr::Edge& ed = a.edge(Arr::Edge_index(i));
    const EK::Point_2* s = match[ed.source];
    const EK::Point_2* t = match[ed.target];
    if(!s || !t) continue;
    INFO("edge " << i);
    REQUIRE(CGAL::compare_xy(*s, *t) == CGAL::SMALLER);
    REQUIRE(a.is_vertical(Arr::Edge_index(i)) == (s->x() == t->x()));
  }
}

void check_all(const CGAL::Bbox_2& box, const std::vector<Line>& lines, const std::vector<double>& left_marks = {},
               const std::vector<double>& right_marks = {})
{
  const Arr a(box, lines, left_marks, right_marks);
  check_invariants(a);
  compare_with_oracle(a, lines, left_marks, right_marks);
  for(std::size_t k = 0; k < left_marks.size(); ++k)
    REQUIRE(a.point(a.left_wall_mark_vertex(k)) == P(box.xmin(), left_marks[k]));
  for(std::size_t k = 0; k < right_marks.size(); ++k)
    REQUIRE(a.point(a.right_wall_mark_vertex(k)) == P(box.xmax(), right_marks[k]));
}

double next_up(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }
double next_down(double x) { return std::nextafter(x, -std::numeric_limits<double>::infinity()); }

} // namespace

// ---------------------------------------------------------------------------------------------------

TEST_CASE("Line_arrangement_2: filtered predicates against exact rationals", "[Variational_minimization][arrangement]")
{
  namespace I = VM::internal;
  typedef CGAL::Gmpq Q;
  std::mt19937_64 rng(12345);
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * VM::internal::unit_random(rng); };
  auto exact_t = [](const I::Arr_line& b, const I::Arr_line& o) {
    const Q odx = Q(o.qx) - Q(o.px), ody = Q(o.qy) - Q(o.py), bdx = Q(b.qx) - Q(b.px), bdy = Q(b.qy) - Q(b.py);
    const Q n = odx * (Q(o.py) - Q(b.py)) - ody * (Q(o.px) - Q(b.px));
    const Q d = odx * bdy - ody * bdx;
    return n / d;
  };
  std::size_t exact_ties = 0;
  for(int trial = 0; trial < 20000; ++trial) {
    // Scales from 1e-6 to 1e6, lines through a common point half of the time (exact ties), directions
    // sometimes one ulp apart (nearly parallel).
    const double scale = std::pow(10.0, uniform(-6, 6));
    const double cx = uniform(-1, 1) * scale, cy = uniform(-1, 1) * scale;
    auto random_line = [&](bool through_c) {
      const double px = through_c ? cx : uniform(-1, 1) * scale, py = through_c ? cy : uniform(-1, 1) * scale;
      double qx = px + uniform(-1, 1) * scale, qy = py + uniform(-1, 1) * scale;
      if(trial % 7 == 0) qy = std::nextafter(qy, 0.0);
      return I::make_arr_line(px, py, qx, qy);
    };
    const bool tie = trial % 2 == 0;
    const I::Arr_line b = random_line(tie), o1 = random_line(tie), o2 = random_line(tie);
    if(I::exact_cross_sign(b, o1) == CGAL::ZERO || I::exact_cross_sign(b, o2) == CGAL::ZERO) continue;
    const Q t1 = exact_t(b, o1), t2 = exact_t(b, o2);
    double lo, hi;
    if(I::approx_param(b, o1, lo, hi)) {
      REQUIRE(Q(lo) <= t1);
      REQUIRE(t1 <= Q(hi));
    }
    I::param_interval(b, o1, lo, hi);
    REQUIRE(Q(lo) <= t1);
    REQUIRE(t1 <= Q(hi));
    const CGAL::Comparison_result expected = CGAL::compare(t1, t2);
    REQUIRE(I::compare_params(b, o1, o2) == expected);
    REQUIRE(I::compare_params_exact(b, o1, o2) == expected);
    exact_ties += expected == CGAL::EQUAL;
    // The vertex approximation: within 2^-42 (|x| + scale) of the exact coordinates.
    double x, y;
    I::intersection_point(b, o1, scale, scale, x, y);
    const Q ex = Q(b.px) + t1 * (Q(b.qx) - Q(b.px)), ey = Q(b.py) + t1 * (Q(b.qy) - Q(b.py));
    REQUIRE(std::abs(CGAL::to_double(Q(x) - ex)) <= std::ldexp(std::abs(x) + scale, -42));
    REQUIRE(std::abs(CGAL::to_double(Q(y) - ey)) <= std::ldexp(std::abs(y) + scale, -42));
  }
  CHECK(exact_ties > 5000);
}

TEST_CASE("Line_arrangement_2: the box alone", "[Variational_minimization][arrangement]")
{
  const CGAL::Bbox_2 box(0, 0, 2, 1);
  const Arr a(box, {});
  CHECK(a.number_of_vertices() == 4);
  CHECK(a.number_of_edges() == 4);
  CHECK(a.number_of_faces() == 1);
  check_invariants(a);
  // Lines that do not meet the open box are dropped.
  const std::vector<Line> lines = { line(3, 0, 3, 1),                 // misses the box
                                    line(0, 0, 1, 0),                 // along the floor
                                    line(2, -1, 2, 5),                // along the right wall
                                    line(-1, 1, 1, -1),               // touches the corner (0, 0) only
                                    line(1, 2, 3, 0) };               // touches the corner (2, 1) only
  const Arr b(box, lines, { 0.5 });
  for(std::size_t i = 0; i < lines.size(); ++i) CHECK_FALSE(b.is_line_used(Arr::Line_index(i)));
  CHECK(b.number_of_vertices() == 5);
  CHECK(b.number_of_faces() == 1);
  check_all(box, lines, { 0.5 });
}

TEST_CASE("Line_arrangement_2: one line, exact structure", "[Variational_minimization][arrangement]")
{
  const CGAL::Bbox_2 box(0, 0, 1, 1);
  const Arr a(box, { line(0.2, 0.1, 0.8, 0.7) });   // y = x - 0.1: enters the floor at 0.1, leaves at x = 1
  REQUIRE(a.number_of_vertices() == 6);
  REQUIRE(a.number_of_edges() == 7);
  REQUIRE(a.number_of_faces() == 2);
  const Arr::Edge& e = a.edge(0);
  REQUIRE(e.kind == Arr::LINE_EDGE);
  CHECK(a.point(e.source).x() == Approx(0.1).epsilon(1e-15));
  CHECK(a.point(e.source).y() == 0);
  CHECK(a.point(e.target).x() == 1);
  CHECK(a.point(e.target).y() == Approx(0.9).epsilon(1e-15));
  // Left = above the line (the big face), right = below (the triangle).
  check_invariants(a);
  const auto& floor = a.wall_edges(Arr::BOTTOM_WALL);
  REQUIRE(floor.size() == 2);
  CHECK(a.edge(floor[0]).left_face == e.left_face);
  CHECK(a.edge(floor[1]).left_face == e.right_face);
  const auto& right = a.wall_edges(Arr::RIGHT_WALL);
  REQUIRE(right.size() == 2);
  CHECK(a.edge(right[0]).left_face == e.right_face);
  CHECK(a.edge(right[1]).left_face == e.left_face);
  // Reversing the defining points changes nothing.
  const Arr r(box, { line(0.8, 0.7, 0.2, 0.1) });
  CHECK(r.point(r.edge(0).source) == a.point(e.source));
  CHECK(r.point(r.edge(0).target) == a.point(e.target));
}

TEST_CASE("Line_arrangement_2: random lines against CGAL::Arrangement_2", "[Variational_minimization][arrangement]")
{
  const CGAL::Bbox_2 unit(0, 0, 1, 1);
  for(std::uint64_t seed = 1; seed <= 4; ++seed)
    for(std::size_t n : { 5, 20, 60 }) {
      INFO("seed " << seed << ", n " << n);
      check_all(unit, VM::random_lines_2(unit, n, seed), { 0.25, 0.5 }, { 0.75 });
    }
  const CGAL::Bbox_2 wide(-1, 0, 1, 2);
  check_all(wide, VM::random_lines_2(wide, 200, 11), { 1.0 }, { 2.0 });
}

TEST_CASE("Line_arrangement_2: pencils through boundary points", "[Variational_minimization][arrangement]")
{
  const CGAL::Bbox_2 box(-1, 0, 1, 2);
  VM::Random_lines_options options;
  options.pencil_points = { P(-1, 0.5), P(1, 1.5) };
  options.pencil_fraction = 0.5;
  for(std::uint64_t seed = 1; seed <= 3; ++seed) {
    const auto lines = VM::random_lines_2(box, 80, seed, options);
    INFO("seed " << seed);
    check_all(box, lines, { 0.5 }, { 1.5 });
    const Arr a(box, lines, { 0.5 }, { 1.5 });
    // The pencil point is one vertex where all its lines end, and it is the mark vertex.
    const Arr::Vertex_index v = a.left_wall_mark_vertex(0);
    std::size_t degree = 0;
    for(std::size_t i = 0; i < a.number_of_edges(); ++i)
      degree += (a.edge(Arr::Edge_index(i)).source == v) + (a.edge(Arr::Edge_index(i)).target == v);
    CHECK(degree == 2 + 20);
  }
  // Pencils through the corners, with the corners as marks.
  const CGAL::Bbox_2 unit(0, 0, 1, 1);
  options.pencil_points = { P(0, 0), P(1, 1), P(0, 1) };
  options.pencil_fraction = 0.6;
  check_all(unit, VM::random_lines_2(unit, 60, 5, options), { 0.0, 1.0 }, { 1.0 });
}

TEST_CASE("Line_arrangement_2: a pencil through an interior point", "[Variational_minimization][arrangement]")
{
  // Pencil lines have the point as a defining point; four more lines pass through it exactly without it.
  const CGAL::Bbox_2 box(0, 0, 1, 1);
  VM::Random_lines_options options;
  options.pencil_points = { P(0.375, 0.625) };
  options.pencil_fraction = 0.5;
  std::vector<Line> lines = VM::random_lines_2(box, 80, 17, options);
  lines.push_back(line(0.125, 0.375, 0.625, 0.875));
  lines.push_back(line(0.125, 0.875, 0.625, 0.375));
  lines.push_back(line(0.375, 0, 0.375, 1));
  lines.push_back(line(0, 0.625, 1, 0.625));
  check_all(box, lines);
  const Arr a(box, lines);
  std::size_t degree = 0;
  for(std::size_t i = 0; i < a.number_of_edges(); ++i) {
    const Arr::Edge& ed = a.edge(Arr::Edge_index(i));
    degree += (a.point(ed.source) == P(0.375, 0.625)) + (a.point(ed.target) == P(0.375, 0.625));
  }
  CHECK(degree == 2 * (40 + 4));
}

TEST_CASE("Line_arrangement_2: the planar regular grid C_n^pl", "[Variational_minimization][arrangement]")
{
  // Exact grids: every grid point is one vertex where many lines meet.
  const CGAL::Bbox_2 unit(0, 0, 1, 1);
  check_all(unit, VM::regular_grid_lines_2(unit, 2), { 0.5 }, { 0.25 });
  const CGAL::Bbox_2 integral(0, 0, 3, 9);
  const auto lines3 = VM::regular_grid_lines_2(integral, 3);
  check_all(integral, lines3, { 4 }, { 5 });
  const Arr a(integral, lines3);
  // Every grid point is a vertex; count the lines through the centre-ish grid point (1, 4).
  std::size_t at = Arr::null_index;
  for(std::size_t v = 0; v < a.number_of_vertices(); ++v)
    if(a.point(Arr::Vertex_index(v)) == P(1, 4)) at = v;
  REQUIRE(at != Arr::null_index);
  std::size_t degree = 0;
  for(std::size_t i = 0; i < a.number_of_edges(); ++i)
    degree += (a.edge(Arr::Edge_index(i)).source == at) + (a.edge(Arr::Edge_index(i)).target == at);
  // The lines row = c + d col through (1, 4) of C_3 exist for d = -5..5 (an edge to column 0 or 2).
  CHECK(degree == 2 * 11);
}

TEST_CASE("Line_arrangement_2: C_n^pl on an inexact grid", "[Variational_minimization][arrangement][.long]")
{
  // 1/3 and 1/9 are not doubles: the lines miss most grid points by rounding, and the arrangement (exact
  // for the given lines) has clusters of nearby vertices; the oracle is slow on them.
  const CGAL::Bbox_2 unit(0, 0, 1, 1);
  check_all(unit, VM::regular_grid_lines_2(unit, 3));
}

TEST_CASE("Line_arrangement_2: lines through corners, along walls, parallel and duplicate",
          "[Variational_minimization][arrangement]")
{
  const CGAL::Bbox_2 box(0, 0, 1, 1);
  const std::vector<Line> lines = {
    line(0, 0, 1, 1),            // diagonal through two corners
    line(0.25, 0.25, 0.5, 0.5),  // the same line, other points
    line(1, 0, 0, 1),            // the other diagonal
    line(0, 0, 1, 0.5),          // through a corner
    line(0, 0, 0.5, 1),          // through a corner
    line(0, 0.5, 1, 1),          // parallel to line 3, through the top right corner
    line(0, 0.25, 1, 0.75),      // parallel again
    line(0.5, 0, 0.5, 1),        // vertical
    line(0.5, 0.3, 0.5, 0.9),    // the same vertical
    line(0, 0.5, 1, 0.5),        // horizontal, through the centre (0.5, 0.5) where four lines meet
    line(-3, 0.5, 7, 0.5),       // the same horizontal
    line(0, 0, 2, 0),            // along the floor
    line(1, -1, 1, 2),           // along the right wall
    line(0.2, 1, 0.9, 1),        // along the ceiling
    line(-1, 0, 0, -1),          // misses
    line(0.5, 0.5, 0.75, 0.5),   // the horizontal again
    line(0, 1, 0.25, 0.75),      // the anti-diagonal again
  };
  const Arr a(box, lines, { 0.5, 0.5, 0 }, { 0.75 });
  const bool expected_used[] = { true, false, true, true, true, true, true, true, false, true, false,
                                 false, false, false, false, false, false };
  for(std::size_t i = 0; i < lines.size(); ++i) {
    INFO("line " << i);
    CHECK(a.is_line_used(Arr::Line_index(i)) == expected_used[i]);
  }
  CHECK(a.left_wall_mark_vertex(0) == a.left_wall_mark_vertex(1));
  CHECK(a.point(a.left_wall_mark_vertex(2)) == P(0, 0));
  check_all(box, lines, { 0.5, 0.5, 0 }, { 0.75 });
}

TEST_CASE("Line_arrangement_2: nearly parallel lines", "[Variational_minimization][arrangement]")
{
  const CGAL::Bbox_2 box(0, 0, 1, 1);
  std::vector<Line> lines = {
    // Directions differing in the last bit, through a common defining point.
    line(0.5, 0.5, 1.5, 0.7), line(0.5, 0.5, 1.5, next_up(0.7)), line(0.5, 0.5, 1.5, next_down(0.7)),
    // Crossing far away (outside) and just inside.
    line(0, 0.3, 1, 0.7), line(0, next_up(0.3), 1, next_down(0.7)), line(0, next_down(0.3), 1, 0.7),
    line(0, 0.3, 1, next_up(0.7)),
    // Two lines crossing very close to the wall x = 1.
    line(0, 0.2, 1, 0.6), line(0, next_up(0.2), 1, next_down(0.6)),
  };
  // Lines through the crossings, to make them vertices of high degree.
  lines.push_back(line(0.5, 0, 0.5, 1));
  lines.push_back(line(0.25, 0, 0.75, 1));
  for(const Line& l : VM::random_lines_2(box, 20, 3)) lines.push_back(l);
  check_all(box, lines, { 0.3 }, { 0.7 });
}

TEST_CASE("Line_arrangement_2: lines meeting exactly on a wall and marks on hits",
          "[Variational_minimization][arrangement]")
{
  const CGAL::Bbox_2 box(-1, 0, 1, 2);
  std::vector<Line> lines;
  // A fan through (-1, 1) and one through (0.25, 0) on the floor, one through (1, 2) (a corner).
  for(int k = 1; k <= 7; ++k) lines.push_back(line(-1, 1, 1, 0.25 * k));
  for(int k = 1; k <= 7; ++k) lines.push_back(line(0.25, 0, -1 + 0.25 * k, 2));
  for(int k = 1; k <= 5; ++k) lines.push_back(line(1, 2, -1, 0.3 * k));
  // Pairs of lines meeting on the right wall at y = 0.5 (a mark there too).
  lines.push_back(line(0, 0, 1, 0.5));
  lines.push_back(line(0, 1, 1, 0.5));
  check_all(box, lines, { 1, 1, 0.5, 2 }, { 0.5, 0, 2, 1.25 });
}

TEST_CASE("Line_arrangement_2: lines through lattice points", "[Variational_minimization][arrangement]")
{
  // Lines through two random points of a small integer lattice around the box: many lines through each
  // lattice point, through corners, along walls, parallel and duplicate lines, marks on line hits. With
  // the scale 0.1 the lattice is not exact in doubles (near-degenerate instead of degenerate).
  std::mt19937_64 rng(77);
  for(int instance = 0; instance < 150; ++instance) {
    const long r = 2 + long(rng() % 7);
    const double sx = instance % 2 ? 1.0 : 0.1, sy = sx * double(1 + rng() % 2);
    const CGAL::Bbox_2 box(0, 0, double(r) * sx, double(r) * sy);
    std::vector<Line> lines;
    const int n = 1 + int(rng() % 30);
    for(int i = 0; i < n; ++i) {
      const long a = long(rng() % (3 * r + 1)) - r, b = long(rng() % (3 * r + 1)) - r;
      const long c = long(rng() % (3 * r + 1)) - r, d = long(rng() % (3 * r + 1)) - r;
      if(a != c || b != d) lines.push_back(line(double(a) * sx, double(b) * sy, double(c) * sx, double(d) * sy));
    }
    std::vector<double> left, right;
    for(int k = int(rng() % 4); k > 0; --k) left.push_back(double(rng() % (2 * r + 1)) / 2 * sy);
    for(int k = int(rng() % 4); k > 0; --k) right.push_back(double(rng() % (2 * r + 1)) / 2 * sy);
    INFO("instance " << instance);
    check_all(box, lines, left, right);
  }
}

TEST_CASE("Line_arrangement_2: other boxes and scales", "[Variational_minimization][arrangement]")
{
  const CGAL::Bbox_2 far(1e6, -3e5, 1e6 + 1, -3e5 + 2);
  check_all(far, VM::random_lines_2(far, 40, 7), { -3e5 + 1 }, {});
  const CGAL::Bbox_2 tiny(1e-9, 2e-9, 3e-9, 2.5e-9);
  check_all(tiny, VM::random_lines_2(tiny, 40, 8));
  const CGAL::Bbox_2 flat(-10, 0, 10, 1e-3);
  VM::Random_lines_options slope;
  slope.max_abs_slope = 1e-4;
  check_all(flat, VM::random_lines_2(flat, 60, 9, slope));
}

TEST_CASE("Line_arrangement_2: bad input throws", "[Variational_minimization][arrangement]")
{
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const CGAL::Bbox_2 box(0, 0, 1, 1);
  CHECK_THROWS_AS(Arr(CGAL::Bbox_2(0, 0, 0, 1), {}), std::invalid_argument);
  CHECK_THROWS_AS(Arr(CGAL::Bbox_2(1, 0, 0, 1), {}), std::invalid_argument);
  CHECK_THROWS_AS(Arr(CGAL::Bbox_2(0, 1, 1, 1), {}), std::invalid_argument);
  CHECK_THROWS_AS(Arr(CGAL::Bbox_2(0, 0, inf, 1), {}), std::invalid_argument);
  CHECK_THROWS_AS(Arr(CGAL::Bbox_2(nan, 0, 1, 1), {}), std::invalid_argument);
  CHECK_THROWS_AS(Arr(box, { line(0.5, 0.5, 0.5, 0.5) }), std::invalid_argument);
  CHECK_THROWS_AS(Arr(box, { line(0.5, nan, 0.2, 0.5) }), std::invalid_argument);
  CHECK_THROWS_AS(Arr(box, { line(0.5, 0.1, inf, 0.5) }), std::invalid_argument);
  CHECK_THROWS_AS(Arr(box, {}, { 1.5 }), std::invalid_argument);
  CHECK_THROWS_AS(Arr(box, {}, {}, { -0.1 }), std::invalid_argument);
  CHECK_THROWS_AS(Arr(box, {}, { nan }), std::invalid_argument);
  CHECK_THROWS_WITH(Arr(box, {}, { 2 }), Catch::Matchers::StartsWith("MDCS: "));
  CHECK_THROWS_WITH(Arr(box, { line(1, 1, 1, 1) }), Catch::Matchers::StartsWith("MDCS: "));
  const Arr a(box, {});
  CHECK_THROWS_AS(a.wall_edges(Arr::LINE_EDGE), std::invalid_argument);
  CHECK_THROWS(a.left_wall_mark_vertex(0));
}

TEST_CASE("Line_arrangement_2: progress and cancellation", "[Variational_minimization][arrangement]")
{
  const CGAL::Bbox_2 box(0, 0, 1, 1);
  const auto lines = VM::random_lines_2(box, 300, 2);
  std::vector<double> fractions;
  bool stage_ok = true;
  auto record = [&](const char* stage, double fraction) {
    stage_ok = stage_ok && std::string(stage) == "arrangement";
    fractions.push_back(fraction);
    return true;
  };
  const Arr a(box, lines, {}, {}, record);
  CHECK(stage_ok);
  REQUIRE(fractions.size() >= 3);
  CHECK(fractions.size() <= 300);
  CHECK(fractions.front() == 0.0);
  CHECK(fractions.back() == 1.0);
  CHECK(std::is_sorted(fractions.begin(), fractions.end()));
  std::size_t calls = 0;
  auto cancel = [&](const char*, double) { return ++calls < 5; };
  CHECK_THROWS_AS(Arr(box, lines, {}, {}, cancel), CGAL::MDCS::Operation_cancelled);
}

TEST_CASE("Line_arrangement_2: larger random instances", "[Variational_minimization][arrangement][.long]")
{
  const CGAL::Bbox_2 box(-1, 0, 1, 2);
  VM::Random_lines_options options;
  options.pencil_points = { P(-1, 2), P(1, 2) };
  check_all(box, VM::random_lines_2(box, 600, 21, options), { 2 }, { 2 });
  const Arr a(box, VM::random_lines_2(box, 3000, 22, options));
  check_invariants(a);
}
