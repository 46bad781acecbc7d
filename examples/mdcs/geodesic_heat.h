// CGAL's heat method (Heat_method_3) for `mdcs geodesics --method heat / heat-idt`, made safe:
//  - CGAL 5.5's heat method returns DBL_MAX for every vertex (the sources included) on a mesh of several connected
//    components, and garbage on degenerate faces. Here it runs on each connected component that holds a source
//    (a copy of that component); components without a source are unreachable; a mesh with a degenerate face
//    (collinear corners: zero area, cotangent weights undefined) is refused (exit code 3).
//  - CGAL 5.5's Eigen_sparse_matrix leaves its `m_is_symmetric` flag uninitialised in the default constructor,
//    and the heat method default-constructs its matrices and swaps them, which reads that flag (UBSan: "load of
//    value ..., which is not a valid value for type 'bool'"); its (size_t, size_t) constructor even reads the
//    flag before setting it. The linear-algebra traits below use a matrix type that initialises every member
//    (and only calls the constructors that do), so the sanitizer build runs the heat method without a report.
#ifndef MDCS_CLI_GEODESIC_HEAT_H
#define MDCS_CLI_GEODESIC_HEAT_H

#include "cli_common.h"
#include "mesh_input.h"

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Eigen_sparse_matrix.h>
#include <CGAL/boost/graph/Face_filtered_graph.h>
#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace mdcs_cli {

namespace heat_detail {

class Initialised_sparse_matrix : public CGAL::Eigen_sparse_matrix<double>
{
  typedef CGAL::Eigen_sparse_matrix<double> Base;

public:
  // An empty matrix, every flag set (the base's default constructor leaves one uninitialised).
  Initialised_sparse_matrix() : Base(Base::EigenType()) {}
  Initialised_sparse_matrix(const Base& m) : Base(m) {}
  Initialised_sparse_matrix(const Base::EigenType& m) : Base(m) {}
  template <class N, class = typename std::enable_if<std::is_integral<N>::value>::type>
  explicit Initialised_sparse_matrix(N dimension, bool symmetric = false)
    : Base(static_cast<int>(dimension), static_cast<int>(dimension), symmetric)
  {}
  template <class R, class C, class = typename std::enable_if<std::is_integral<R>::value && std::is_integral<C>::value>::type>
  Initialised_sparse_matrix(R rows, C columns, bool symmetric = false)
    : Base(static_cast<int>(rows), static_cast<int>(columns), symmetric) // the (int, int) constructor sets the flag first
  {}
};

// CGAL's default traits of the heat method (a sparse LDLT) with that matrix type.
struct Linear_algebra : CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::EigenType>>
{
  typedef Initialised_sparse_matrix Matrix;
};

} // namespace heat_detail

struct Heat_result
{
  std::vector<double> distance; // per vertex of the whole mesh; +infinity in components without a source
  std::size_t components = 0, components_with_sources = 0;
  double seconds_setup = 0, seconds_compute = 0;
};

// The first degenerate face (three collinear corners, exact predicate), or -1.
inline long long first_degenerate_face(const Geo_mesh& mesh)
{
  for(Geo_mesh::Face_index f : mesh.faces()) {
    const auto h = mesh.halfedge(f);
    if(CGAL::collinear(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)), mesh.point(mesh.target(mesh.next(h)))))
      return (long long)f.idx();
  }
  return -1;
}

// Heat distances from the vertex `sources` on every connected component that holds one.
template <class Mode>
Heat_result heat_distances_per_component(const Geo_mesh& mesh, const std::vector<std::size_t>& sources, const Progress_bar& progress)
{
  typedef CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<Geo_mesh, Mode, CGAL::Default, heat_detail::Linear_algebra> Heat;
  const double inf = std::numeric_limits<double>::infinity();
  const long long degenerate = first_degenerate_face(mesh);
  if(degenerate >= 0)
    throw Input_error("the heat method cannot handle degenerate faces (face " + std::to_string(degenerate) +
                      " has collinear corners: zero area, undefined cotangent weights); use --method exact, flat-exact, fmm "
                      "or dijkstra, which accept them");
  Heat_result result;
  result.distance.assign(mesh.number_of_vertices(), inf);
  std::vector<std::size_t> component(mesh.number_of_faces(), 0);
  const auto component_of_face = boost::make_iterator_property_map(component.begin(), get(boost::face_index, mesh));
  result.components = CGAL::Polygon_mesh_processing::connected_components(mesh, component_of_face);
  std::vector<std::vector<Geo_mesh::Vertex_index>> sources_of(result.components);
  for(std::size_t s : sources) {
    const Geo_mesh::Vertex_index v = Geo_mesh::Vertex_index(Geo_mesh::size_type(s));
    // every component around the vertex (a vertex can join components at a pinch)
    for(Geo_mesh::Face_index f : CGAL::faces_around_target(mesh.halfedge(v), mesh))
      if(f != Geo_mesh::null_face()) sources_of[get(component_of_face, f)].push_back(v);
  }
  for(std::size_t c = 0; c < result.components; ++c) {
    if(sources_of[c].empty()) continue;
    ++result.components_with_sources;
    const std::string stage = result.components == 1 ? std::string("heat method")
                                                     : "heat method, component " + std::to_string(c + 1) + " of " + std::to_string(result.components);
    progress.begin(stage.c_str());
    const auto t_setup = std::chrono::steady_clock::now();
    Geo_mesh part;
    std::vector<std::pair<Geo_mesh::Vertex_index, Geo_mesh::Vertex_index>> to_part; // (mesh vertex, part vertex)
    std::vector<std::size_t> part_vertex(mesh.number_of_vertices(), std::size_t(-1));
    if(result.components == 1) {
      part = mesh;
    } else {
      CGAL::Face_filtered_graph<Geo_mesh> filtered(mesh, c, component_of_face);
      CGAL::copy_face_graph(filtered, part, CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(to_part)));
    }
    if(part.has_garbage()) throw std::logic_error("mdcs: the copy of a mesh component has garbage");
    for(const auto& m : to_part) part_vertex[m.first.idx()] = m.second.idx();
    Heat heat(part);
    for(Geo_mesh::Vertex_index v : sources_of[c])
      heat.add_source(result.components == 1 ? v : Geo_mesh::Vertex_index(Geo_mesh::size_type(part_vertex[v.idx()])));
    result.seconds_setup += seconds_since(t_setup);
    const auto t_compute = std::chrono::steady_clock::now();
    std::vector<double> field(part.number_of_vertices(), inf);
    heat.estimate_geodesic_distances(boost::make_iterator_property_map(field.begin(), get(boost::vertex_index, part)));
    result.seconds_compute += seconds_since(t_compute);
    if(result.components == 1) {
      result.distance = field;
    } else {
      for(const auto& m : to_part)
        result.distance[m.first.idx()] = std::min(result.distance[m.first.idx()], field[m.second.idx()]);
    }
    progress.end();
  }
  return result;
}

} // namespace mdcs_cli

#endif // MDCS_CLI_GEODESIC_HEAT_H
