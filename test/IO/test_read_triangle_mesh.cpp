// read_triangle_mesh(): a valid file becomes the mesh with the file's vertex and face order (Surface_mesh and
// Polyhedron_3); polygons are triangulated with a face map; a surface that is not a valid oriented manifold
// mesh is refused with the reason, or repaired on request (and the report says so).
#include "io_test_helpers.h"

#include <CGAL/MDCS/IO/read_triangle_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

namespace MIO = CGAL::MDCS::IO;
using namespace io_test;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

TEST_CASE("read_triangle_mesh: the file's order in a Surface_mesh and a Polyhedron_3", "[io][mesh]")
{
  Scratch dir;
  auto v = octahedron_points();
  v.push_back({{7, 7, 7}}); // an isolated vertex: kept, with a note
  const auto f = octahedron_faces();
  for(const std::string& name : {std::string("o.off"), std::string("o.ply"), std::string("o.obj")}) {
    INFO(name);
    const std::string text = name == "o.off" ? off_text(v, f) : name == "o.ply" ? ply_ascii_text(v, f) : obj_text(v, f);
    Mesh m;
    const MIO::Triangle_mesh_reading_report r = MIO::read_triangle_mesh(dir.write(name, text), m);
    REQUIRE(m.number_of_vertices() == 7);
    REQUIRE(m.number_of_faces() == 8);
    CHECK(m.is_valid(false));
    CHECK_FALSE(r.repaired);
    for(std::size_t i = 0; i < v.size(); ++i) CHECK(m.point(Mesh::Vertex_index(Mesh::size_type(i))) == K::Point_3(v[i][0], v[i][1], v[i][2]));
    std::size_t fi = 0;
    for(auto face : m.faces()) {
      std::vector<std::size_t> corners;
      for(auto vd : CGAL::vertices_around_face(m.halfedge(face), m)) corners.push_back(std::size_t(vd));
      std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
      Face expected = f[fi++];
      std::rotate(expected.begin(), std::min_element(expected.begin(), expected.end()), expected.end());
      CHECK(corners == expected);
    }
    CHECK(r.face_to_file_face == std::vector<std::size_t>{0, 1, 2, 3, 4, 5, 6, 7});
    REQUIRE(r.notes.size() == 1);
    CHECK(r.notes[0].find("1 vertex belongs to no face (vertex 6 is one)") != std::string::npos);
    CHECK(CGAL::Polygon_mesh_processing::volume(m) == Approx(4.0 / 3));
  }
  CGAL::Polyhedron_3<K> poly;
  MIO::read_triangle_mesh(dir.write("p.off", off_text(octahedron_points(), f)), poly);
  CHECK(poly.size_of_vertices() == 6);
  CHECK(poly.size_of_facets() == 8);
  CHECK(poly.is_valid());
}

TEST_CASE("read_triangle_mesh: polygons are triangulated, with the face map", "[io][mesh]")
{
  Scratch dir;
  const std::vector<Xyz> cube = {{{0, 0, 0}}, {{1, 0, 0}}, {{1, 1, 0}}, {{0, 1, 0}}, {{0, 0, 1}}, {{1, 0, 1}}, {{1, 1, 1}}, {{0, 1, 1}}};
  const std::vector<Face> quads = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  Mesh m;
  const auto r = MIO::read_triangle_mesh(dir.write("cube.off", off_text(cube, quads)), m);
  CHECK(m.number_of_faces() == 12);
  CHECK(r.triangulation.quadrilaterals == 6);
  CHECK(r.face_to_file_face == std::vector<std::size_t>{0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5});
  CHECK(CGAL::is_closed(m));
  CHECK(CGAL::Polygon_mesh_processing::volume(m) == Approx(1.0).epsilon(1e-14));
  REQUIRE_FALSE(r.notes.empty());
  CHECK(r.notes[0].find("6 faces with more than three corners were triangulated (6 -> 12 faces)") != std::string::npos);
}

TEST_CASE("read_triangle_mesh: refusals say why, the repair is opt-in and reported", "[io][mesh][repair]")
{
  Scratch dir;
  struct Case
  {
    const char* name;
    std::string text;
    const char* reason;
  };
  // A fan of three sheets, a pinched vertex between two tetrahedra, a flipped face.
  const std::vector<Case> cases = {
    {"sheets.off", "OFF\n5 3 0\n0 0 0\n1 0 0\n0.5 1 0\n0.5 -1 0\n0.5 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n",
     "edge (0, 1) is shared by 3 face sides (faces 0, 1, 2)"},
    {"pinched.off", "OFF\n7 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n-1 0 0\n0 -1 0\n0 0 -1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
                    "3 0 4 5\n3 0 6 4\n3 0 5 6\n3 4 6 5\n", "vertex 0 is pinched: the faces around it form 2 separate fans"},
    {"flipped.off", off_text(octahedron_points(), {{0, 4, 2}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}),
     "the faces are not consistently oriented"},
  };
  for(const Case& c : cases) {
    INFO(c.name);
    const std::string path = dir.write(c.name, c.text);
    Mesh m;
    MIO::Triangle_mesh_reading_options refuse;
    refuse.refusal_hint = "ask for the repair";
    const std::string message = expect_read_error([&] { MIO::read_triangle_mesh(path, m, refuse); }, c.reason, 0);
    CHECK(message.find("not a valid oriented manifold mesh") != std::string::npos);
    CHECK(message.find("; ask for the repair") != std::string::npos);
    MIO::Triangle_mesh_reading_options repair;
    repair.repair = true;
    const auto r = MIO::read_triangle_mesh(path, m, repair);
    CHECK(m.is_valid(false));
    CHECK(r.face_to_file_face.empty());
    CHECK(r.repaired);
    REQUIRE_FALSE(r.notes.empty());
    CHECK(r.notes[0].find("CGAL's soup repair made a mesh of it") != std::string::npos);
    CHECK(r.notes[0].find("results are for the repaired surface") != std::string::npos);
    CHECK(r.points_after_repair == m.number_of_vertices());
  }
  // A real Moebius strip (twelve triangles around a twisted band): refused as not orientable.
  std::string moebius = "OFF\n12 12 0\n";
  const double pi = 3.14159265358979323846;
  for(int i = 0; i < 6; ++i)
    for(double s : {-0.3, 0.3}) {
      const double t = 2 * pi * i / 6, w = s * std::cos(t / 2);
      moebius += number((1 + w) * std::cos(t)) + " " + number((1 + w) * std::sin(t)) + " " + number(s * std::sin(t / 2)) + "\n";
    }
  for(int i = 0; i < 6; ++i) {
    const int a = 2 * i, b = 2 * i + 1, c = i < 5 ? 2 * i + 2 : 1, d = i < 5 ? 2 * i + 3 : 0;
    moebius += "3 " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(d) + "\n3 " + std::to_string(a) +
               " " + std::to_string(d) + " " + std::to_string(b) + "\n";
  }
  Mesh m;
  expect_read_error([&] { MIO::read_triangle_mesh(dir.write("strip.off", moebius), m); }, "the surface is not orientable");
  // No face, or nothing left after the repair.
  expect_read_error([&] { MIO::read_triangle_mesh(dir.write("points.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"), m); },
                    "the file has no face (3 points)");
  MIO::Triangle_mesh_reading_options repair;
  repair.repair = true;
  expect_read_error([&] { MIO::read_triangle_mesh(dir.write("flat.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n3 2 2 2\n"), m, repair); },
                    "no face is left after CGAL's soup repair");
  // The mesh is cleared first; a read error leaves it empty.
  MIO::read_triangle_mesh(dir.write("good.off", off_text(octahedron_points(), octahedron_faces())), m);
  CHECK(m.number_of_faces() == 8);
  CHECK_THROWS_AS(MIO::read_triangle_mesh(dir.path("missing.off"), m), MIO::Read_error);
  CHECK(m.number_of_vertices() == 0);
}
