// The mesh type most geodesics tests run on (Surface_mesh over EPICK) with the names they use for it, and the small
// builders and measures the test files of Polyhedral_geodesics_3 share: a mesh from a soup, a mesh with a
// quadrilateral face (input every triangle-mesh class must refuse), the mean edge length, the distances at every
// vertex. A test file opens the types with `using namespace MDCS_test::Epick_surface_mesh;` in its own unnamed
// namespace.
#ifndef MDCS_TEST_GEODESIC_TEST_MESHES_H
#define MDCS_TEST_GEODESIC_TEST_MESHES_H

#include <MDCS_test/geodesic_oracles.h>
#include <MDCS_test/mesh_generators.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedral_geodesics_3/Exact_geodesic_distances_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_3.h>

#include <boost/graph/graph_traits.hpp>

#include <cmath>
#include <vector>

namespace MDCS_test {

// The vertex distances of a computed geodesics object, in the order of vertices(m).
template <class Geodesics, class TriangleMesh>
std::vector<double> vertex_distances(Geodesics& g, const TriangleMesh& m)
{
  std::vector<double> r;
  for(auto v : vertices(m))
    r.push_back(CGAL::to_double(g.distance(v)));
  return r;
}

// The mean length of the edges of m: the scale of the mesh, for tolerances and distance limits.
template <class TriangleMesh>
double mean_edge_length(const TriangleMesh& m)
{
  double s = 0;
  for(auto e : edges(m))
    s += std::sqrt(CGAL::to_double(CGAL::squared_distance(get(CGAL::vertex_point, m, source(e, m)),
                                                          get(CGAL::vertex_point, m, target(e, m)))));
  return s / double(num_edges(m));
}

namespace Epick_surface_mesh {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
typedef boost::graph_traits<Mesh>::face_descriptor face_descriptor;

inline Mesh make_mesh(const Triangle_soup<Point_3>& soup) { return mesh_from_soup<Mesh>(soup); }

// The unit square as one quadrilateral face (vertices 0 to 3 counter-clockwise from the origin): not a triangle
// mesh, so every geodesics class must refuse it.
inline Mesh unit_square_quad()
{
  Mesh quad;
  const auto a = quad.add_vertex(Point_3(0, 0, 0)), b = quad.add_vertex(Point_3(1, 0, 0)),
             c = quad.add_vertex(Point_3(1, 1, 0)), d = quad.add_vertex(Point_3(0, 1, 0));
  quad.add_face(a, b, c, d);
  return quad;
}

// A source at a vertex or at a surface point, and adding a list of them to any geodesics class.
struct Source
{
  bool at_vertex;
  vertex_descriptor v;
  CGAL::Polyhedral_geodesics_3::Exact_geodesic_distances_3<Mesh>::Face_location loc;
};
inline Source at(vertex_descriptor v) { return Source{true, v, {}}; }
inline Source at(const CGAL::Polyhedral_geodesics_3::Exact_geodesic_distances_3<Mesh>::Face_location& loc)
{
  return Source{false, vertex_descriptor(), loc};
}
template <class G>
void add_sources(G& g, const std::vector<Source>& sources)
{
  for(const Source& s : sources) {
    if(s.at_vertex) g.add_source(s.v);
    else g.add_source(s.loc);
  }
}

} // namespace Epick_surface_mesh

} // namespace MDCS_test

#endif // MDCS_TEST_GEODESIC_TEST_MESHES_H
