// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reference implementations that the tests and benchmarks compare with: CGAL's own exact geodesics
// (Surface_mesh_shortest_path, Chen and Han / Xin and Wang), an independent algorithm of the same distances.

#include "geodesic_surface.h"

#include <CGAL/Surface_mesh_shortest_path.h>

#include <limits>

namespace mdcs_python {
namespace {

py::array_t<double> cgal_shortest_path_distances(py::handle vertices, py::handle faces, py::handle source)
{
  const auto arrays = checked_mesh_arrays(vertices, faces);
  const std::size_t n = std::size_t(arrays.first.shape(0)), m = std::size_t(arrays.second.shape(0));
  const std::int64_t s = checked_index(source, "source", std::int64_t(n), "vertices");
  Geo_mesh mesh;
  bool oriented = false;
  const auto copies = mesh_from_arrays(arrays.first.data(), n, arrays.second.data(), m, mesh, oriented);
  if(!copies.empty())
    throw Value_error("mdcs: the reference needs a manifold mesh (this one has non-manifold vertices)");
  std::vector<double> d(n, std::numeric_limits<double>::infinity());
  {
    py::gil_scoped_release release;
    typedef CGAL::Surface_mesh_shortest_path_traits<Geo_kernel, Geo_mesh> Traits;
    CGAL::Surface_mesh_shortest_path<Traits> smsp(mesh);
    smsp.add_source_point(Geo_mesh::Vertex_index(static_cast<Geo_mesh::size_type>(s)));
    smsp.build_sequence_tree();
    for(std::size_t v = 0; v < n; ++v) {
      const double x = smsp.shortest_distance_to_source_points(Geo_mesh::Vertex_index(static_cast<Geo_mesh::size_type>(v))).first;
      if(x >= 0) d[v] = x;
    }
  }
  return to_numpy(std::move(d));
}

} // namespace

void bind_reference(py::module_& m)
{
  py::module_ r = m.def_submodule("reference", "Reference implementations used by the tests and benchmarks");
  r.def("cgal_shortest_path_distances", &cgal_shortest_path_distances, py::arg("vertices"), py::arg("faces"),
        py::arg("source"),
        "Exact geodesic distances from one vertex by CGAL::Surface_mesh_shortest_path (an independent algorithm); "
        "+inf where unreachable.");
}

} // namespace mdcs_python
