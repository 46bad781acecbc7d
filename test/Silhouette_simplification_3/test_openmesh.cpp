// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Silhouette simplification on OpenMesh's TriMesh (through CGAL's graph traits for OpenMesh): a valid coarse
// mesh, and with the same coarse mesh the same silhouettes, picked and mapped loops as on Surface_mesh built
// from the same triangles. Built only when
// CMake finds OpenMesh (MDCS_HAS_OPENMESH); otherwise one case reports the skip.

#include <catch2/catch.hpp>

#ifdef MDCS_HAS_OPENMESH

// OpenMesh's property storage appends default-constructed (uninitialised) vectors, which GCC reports when it
// inlines them here; the warning is about OpenMesh's code, not this test's.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "silhouette_test_meshes.h"

#include <CGAL/Silhouette_simplification_3.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>

#include <cmath>

using namespace silhouette_test;
namespace SS = CGAL::Silhouette_simplification_3;

namespace {

// OpenMesh's default TriMesh, float points: CGAL's point map writes floats, so the test soup is rounded to
// floats first and both meshes then hold exactly the same coordinates.
typedef OpenMesh::TriMesh_ArrayKernelT<> Open_mesh;

SS::View_3<K> openmesh_orbit_view(double angle, double elevation = 0.6, double radius = 4)
{
  return SS::View_3<K>::perspective(Point_3(radius * std::cos(angle) * std::cos(elevation),
                                            radius * std::sin(angle) * std::cos(elevation), radius * std::sin(elevation)));
}

} // namespace

TEST_CASE("Silhouette_simplifier_3: identical results on Surface_mesh and OpenMesh", "[silhouette][generic][openmesh]")
{
  auto soup = torus(48, 20, 1, 0.4, 0.08);
  for(Point_3& p : soup.points) {
    // Through volatile floats: with GCC 12 -O2 a plain static_cast<float> here was not applied to the stored
    // point (the check below caught it).
    volatile float x = float(p.x()), y = float(p.y()), z = float(p.z());
    p = Point_3(double(x), double(y), double(z));
  }
  const Mesh sm = make<Mesh>(soup);
  const Open_mesh om = make<Open_mesh>(soup);
  REQUIRE(num_faces(om) == num_faces(sm));
  for(auto v : vertices(sm)) REQUIRE(double(float(sm.point(v).x())) == sm.point(v).x()); // same points in both
  SS::Coarse_mesh_options o;
  o.target_faces = 250;
  // The coarse mesh built from OpenMesh is valid (its collapse order may differ from Surface_mesh's among
  // equal costs, since the copies enumerate halfedges differently), so both simplifiers share one coarse mesh.
  const auto c2 = SS::build_coarse_mesh(om, o);
  CHECK(num_faces(c2.mesh) <= 260);
  REQUIRE(c2.coarse_face_of_fine_face.size() == num_faces(om));
  for(std::uint32_t c : c2.coarse_face_of_fine_face) CHECK(c < num_faces(c2.mesh));
  const auto c1 = SS::build_coarse_mesh(sm, o);
  SS::Silhouette_simplifier_3<Mesh> s1(sm, c1.mesh, c1.coarse_face_of_fine_face);
  SS::Silhouette_simplifier_3<Open_mesh> s2(om, c1.mesh, c1.coarse_face_of_fine_face);
  for(int i = 0; i < 3; ++i) {
    SS::Silhouette_frame f1, f2;
    s1.extract(openmesh_orbit_view(0.9 * i), f1);
    s2.extract(openmesh_orbit_view(0.9 * i), f2);
    s1.pick_loops(f1);
    s2.pick_loops(f2);
    s1.map_loops(f1);
    s2.map_loops(f2);
    CHECK(!f1.fine_silhouette.empty());
    CHECK(f1.fine_silhouette == f2.fine_silhouette);
    CHECK(f1.coarse_silhouette == f2.coarse_silhouette);
    CHECK(f1.picked == f2.picked);
    CHECK(f1.mapped_halfedges() == f2.mapped_halfedges());
    // The descriptors map back to the same geometric edges.
    for(std::uint32_t h : f1.mapped_halfedges()) {
      const Point_3 a = sm.point(source(s1.fine_halfedge(h), sm));
      const auto b = om.point(source(s2.fine_halfedge(h), om));
      CHECK(a == Point_3(b[0], b[1], b[2]));
    }
  }
}

#else

TEST_CASE("Silhouette_simplifier_3 on OpenMesh: skipped (OpenMesh not found by CMake)", "[silhouette][openmesh]")
{
  WARN("OpenMesh (Debian's libopenmesh-dev) was not found: the OpenMesh case was not built");
  SUCCEED();
}

#endif
