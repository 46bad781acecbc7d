// Simple silhouettes of a fine mesh guided by a coarse one (thesis chapter 5): builds a 1,000-face coarse
// mesh once, then for one view extracts the fine and coarse silhouettes, picks fine silhouette loops
// (method A) and maps the coarse loops onto the fine mesh by minimum cuts (method B); prints edge and
// loop counts and writes the mapped silhouette as polylines to a text file.
// Usage: simple_silhouette [mesh.off [output.polylines.txt]]  (default: CGAL's bunny00.off, or a
// generated noisy sphere when that file is not installed).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Silhouette_simplification_3.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/boost/graph/generators.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>

#ifndef MDCS_CGAL_MESH_DIR
#define MDCS_CGAL_MESH_DIR ""
#endif

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
namespace SS = CGAL::Silhouette_simplification_3;

int main(int argc, char** argv)
{
  Mesh fine;
  const std::string default_mesh = std::string(MDCS_CGAL_MESH_DIR) + "/bunny00.off";
  const std::string path = argc > 1 ? argv[1] : default_mesh;
  const std::string output = argc > 2 ? argv[2] : "simple_silhouette.polylines.txt";
  if(!CGAL::IO::read_polygon_mesh(path, fine) || faces(fine).empty()) {
    if(argc > 1) {
      std::cerr << "cannot read a mesh from " << path << "\n";
      return 1;
    }
    // Fallback: an icosahedron subdivided four times (5,120 faces) with a wavy radius.
    CGAL::make_icosahedron(fine, Point_3(0, 0, 0), 1.0);
    CGAL::Subdivision_method_3::Loop_subdivision(fine, CGAL::parameters::number_of_iterations(4));
    for(Mesh::Vertex_index v : vertices(fine)) {
      const Point_3 p = fine.point(v);
      const double r = std::sqrt(p.x() * p.x() + p.y() * p.y() + p.z() * p.z());
      const double s = (1 + 0.05 * std::sin(13 * p.x()) * std::sin(11 * p.y()) * std::sin(7 * p.z())) / r;
      fine.point(v) = Point_3(s * p.x(), s * p.y(), s * p.z());
    }
    std::cout << "(" << default_mesh << " not found: using a wavy sphere)\n";
  }

  try {
    // Preprocessing, once per mesh: coarse mesh by half-edge collapses and smoothing, fine-to-coarse face map.
    SS::Coarse_mesh_options options;
    options.target_faces = std::min<std::size_t>(1000, num_faces(fine) / 4);
    const auto coarse = SS::build_coarse_mesh(fine, options);
    SS::Silhouette_simplifier_3<Mesh> simplifier(fine, coarse.mesh, coarse.coarse_face_of_fine_face);
    std::cout << "fine mesh " << num_faces(fine) << " faces, coarse mesh " << num_faces(coarse.mesh) << " faces\n";

    // One perspective view: the eye 2.5 bounding-box diagonals away, slightly above the model.
    const CGAL::Bbox_3 b = CGAL::Polygon_mesh_processing::bbox(fine);
    const double d = simplifier.diagonal();
    const Point_3 eye((b.xmin() + b.xmax()) / 2 + 2.5 * d * std::cos(0.5), (b.ymin() + b.ymax()) / 2 + 0.75 * d,
                      (b.zmin() + b.zmax()) / 2 + 2.5 * d * std::sin(0.5));
    SS::Silhouette_frame frame;
    simplifier.extract(SS::View_3<K>::perspective(eye), frame); // silhouettes and loops, fine and coarse
    simplifier.pick_loops(frame);                               // method A -> frame.picked
    simplifier.map_loops(frame);                                // method B -> frame.mapped (alpha = 0.1)

    std::cout << "fine silhouette:   " << frame.fine_silhouette.size() << " edges, " << frame.fine_loops.size() << " loops\n"
              << "coarse silhouette: " << frame.coarse_silhouette.size() << " edges, " << frame.coarse_loops.size() << " loops\n"
              << "picked (A):        " << frame.picked_halfedges().size() << " edges, " << frame.picked.size() << " loops\n"
              << "mapped (B):        " << frame.mapped_halfedges().size() << " edges, " << frame.mapped.size() << " loops\n";

    // The mapped loops are real edges of the fine mesh: write their vertices, one loop per line.
    std::ofstream out(output);
    for(const auto& loop : frame.mapped) {
      out << loop.halfedges.size() + (loop.closed ? 1 : 0);
      for(std::uint32_t h : loop.halfedges) out << "  " << fine.point(source(simplifier.fine_halfedge(h), fine));
      if(loop.closed && !loop.halfedges.empty())
        out << "  " << fine.point(source(simplifier.fine_halfedge(loop.halfedges.front()), fine));
      out << "\n";
    }
    std::cout << "mapped loops written to " << output << " (one polyline per line: count, then x y z)\n";
  } catch(const std::invalid_argument& e) {
    std::cerr << "invalid input: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
