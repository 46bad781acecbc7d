// Exact geodesic distances from two sources (a vertex and a surface point), the nearest source of every
// vertex, and one shortest path. Usage: geodesic_distances [mesh.off]  (default: CGAL's elephant.off, or
// a small generated icosahedron when that file is not installed).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedral_geodesics_3.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/generators.h>

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PG = CGAL::Polyhedral_geodesics_3;

int main(int argc, char** argv)
{
  Mesh mesh;
  const std::string default_mesh = std::string(MDCS_CGAL_MESH_DIR) + "/elephant.off";
  const std::string path = argc > 1 ? argv[1] : default_mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || faces(mesh).empty()) {
    if(argc > 1) {
      std::cerr << "cannot read a mesh from " << path << "\n";
      return 1;
    }
    CGAL::make_icosahedron(mesh, K::Point_3(0, 0, 0), 1.0);
    std::cout << "(" << default_mesh << " not found: using an icosahedron)\n";
  }

  PG::Exact_geodesic_distances_3<Mesh> geodesics(mesh);      // full field: point queries and paths
  const Mesh::Vertex_index v0 = *vertices(mesh).begin();
  geodesics.add_source(v0);                                   // source 0: a vertex
  const Mesh::Face_index f = *std::prev(faces(mesh).end());
  geodesics.add_source({f, {1.0 / 3, 1.0 / 3, 1.0 / 3}});     // source 1: the centroid of a face

  auto distance = mesh.add_property_map<Mesh::Vertex_index, double>("v:geodesic_distance", 0).first;
  geodesics.distances(distance);

  Mesh::Vertex_index farthest = v0;
  std::size_t nearer_to_0 = 0;
  for(Mesh::Vertex_index v : vertices(mesh)) {
    if(distance[v] > distance[farthest])
      farthest = v;
    if(geodesics.nearest_source(v).second == 0)
      ++nearer_to_0;
  }
  std::vector<K::Point_3> path_points;
  geodesics.shortest_path_points(farthest, std::back_inserter(path_points));
  double length = 0;
  for(std::size_t i = 1; i < path_points.size(); ++i)
    length += std::sqrt(CGAL::squared_distance(path_points[i - 1], path_points[i]));

  std::cout << num_vertices(mesh) << " vertices; " << nearer_to_0 << " are nearer to source 0\n"
            << "farthest vertex " << std::size_t(farthest) << " at distance " << distance[farthest]
            << "; its shortest path has " << path_points.size() << " points and length " << length << "\n"
            << "windows created: " << geodesics.statistics().windows_created << "\n";
  return 0;
}
