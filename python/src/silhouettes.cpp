// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bindings of Silhouette_simplification_3: silhouette edges of a mesh for a view (by a scan of the faces, or by a
// bounding-cone hierarchy built once for many views), and simplified silhouettes (loops picked among the fine
// silhouette's loops, or coarse loops mapped onto the fine mesh by minimum cuts) through a coarse mesh built once.

#include "geodesic_surface.h" // mesh_from_arrays(), checked_mesh_arrays()

#include <CGAL/Silhouette_simplification_3.h>

#include <memory>

namespace mdcs_python {
namespace {

namespace SS = CGAL::Silhouette_simplification_3;
typedef SS::View_3<Geo_kernel> View;

View make_view(py::handle eye, py::handle direction)
{
  if(eye.is_none() == direction.is_none())
    throw Value_error("mdcs: give exactly one of eye (a perspective view) and direction (an orthographic view)");
  const bool perspective = !eye.is_none();
  const Double_array a = checked_doubles(perspective ? eye : direction, perspective ? "eye" : "direction", 1, -1, true,
                                         "(3,)");
  if(a.size() != 3) throw Value_error(std::string("mdcs: ") + (perspective ? "eye" : "direction") + " must have 3 coordinates");
  if(perspective) return View::perspective(Geo_point(a.data()[0], a.data()[1], a.data()[2]));
  return View::orthographic(Geo_kernel::Vector_3(a.data()[0], a.data()[1], a.data()[2]));
}

// The mesh of the arrays, and the caller's vertex of every mesh vertex (copies of split vertices appended).
struct Indexed_input
{
  Geo_mesh mesh;
  std::vector<std::int64_t> caller_vertex;
  bool oriented = false;
};

void read_mesh(py::handle vertices, py::handle faces, Indexed_input& in)
{
  const auto arrays = checked_mesh_arrays(vertices, faces);
  const std::size_t n = std::size_t(arrays.first.shape(0)), m = std::size_t(arrays.second.shape(0));
  const double* v = arrays.first.data();
  const std::int64_t* f = arrays.second.data();
  py::gil_scoped_release release;
  const auto copies = mesh_from_arrays(v, n, f, m, in.mesh, in.oriented);
  in.caller_vertex.resize(in.mesh.number_of_vertices());
  for(std::size_t i = 0; i < n; ++i) in.caller_vertex[i] = std::int64_t(i);
  for(const auto& c : copies) in.caller_vertex[c.second] = std::int64_t(c.first);
}

// The directed halfedges as an (k, 2) array of the caller's vertex pairs.
py::array_t<std::int64_t> caller_edges(const Indexed_input& in, const std::vector<Geo_mesh::Halfedge_index>& hs)
{
  std::vector<std::int64_t> out;
  out.reserve(2 * hs.size());
  for(auto h : hs) {
    out.push_back(in.caller_vertex[std::size_t(in.mesh.source(h))]);
    out.push_back(in.caller_vertex[std::size_t(in.mesh.target(h))]);
  }
  return to_numpy(std::move(out), py::ssize_t(hs.size()), 2);
}

py::array_t<std::int64_t> silhouette_edges(py::handle vertices, py::handle faces, py::handle eye, py::handle direction)
{
  Indexed_input in;
  read_mesh(vertices, faces, in);
  const View view = make_view(eye, direction);
  std::vector<Geo_mesh::Halfedge_index> hs;
  {
    py::gil_scoped_release release;
    SS::silhouette_halfedges(in.mesh, view, std::back_inserter(hs));
  }
  return caller_edges(in, hs);
}

// Silhouette edges of one mesh for many views: the bounding-cone hierarchy over its edges is built once; every
// query returns what silhouette_edges() returns for the view (same edges, same order). Queries are const in the
// library and run without the GIL, so Python threads may query one object concurrently.
class Py_silhouette_edges
{
public:
  Py_silhouette_edges(py::handle vertices, py::handle faces)
  {
    read_mesh(vertices, faces, input_);
    py::gil_scoped_release release;
    hierarchy_ = std::make_unique<Hierarchy>(input_.mesh);
  }

  py::array_t<std::int64_t> edges(py::handle eye, py::handle direction) const
  {
    const View view = make_view(eye, direction);
    std::vector<Geo_mesh::Halfedge_index> hs;
    {
      py::gil_scoped_release release;
      hierarchy_->silhouette_halfedges(view, std::back_inserter(hs));
    }
    return caller_edges(input_, hs);
  }

  std::size_t faces() const { return input_.mesh.number_of_faces(); }
  std::size_t nodes() const { return hierarchy_->number_of_nodes(); }
  std::size_t edges_outside_the_tree() const { return hierarchy_->number_of_edges_outside_the_tree(); }

private:
  typedef SS::Silhouette_edge_hierarchy_3<Geo_mesh> Hierarchy;
  Indexed_input input_; // the hierarchy's halfedges are descriptors of this mesh
  std::unique_ptr<Hierarchy> hierarchy_;
};

class Py_simplifier
{
public:
  Py_simplifier(py::handle vertices, py::handle faces, std::size_t target_faces, unsigned smoothing_iterations,
                bool hierarchy, py::object progress)
  {
    read_mesh(vertices, faces, input_);
    if(target_faces < 4) throw Value_error("mdcs: target_faces must be at least 4");
    SS::Coarse_mesh_options options;
    options.target_faces = target_faces;
    options.smoothing_iterations = smoothing_iterations;
    Progress_bridge bridge(progress);
    run_without_gil(bridge, [&] {
      coarse_ = std::make_unique<SS::Coarse_mesh_3<Geo_point>>(
        SS::build_coarse_mesh(input_.mesh, get(CGAL::vertex_point, input_.mesh), options, std::ref(bridge)));
      simplifier_ = std::make_unique<SS::Silhouette_simplifier_3<Geo_mesh>>(input_.mesh, coarse_->mesh,
                                                                              coarse_->coarse_face_of_fine_face);
      // The same fine silhouettes, found without classifying every fine face of each view.
      if(hierarchy) simplifier_->build_silhouette_hierarchy();
      return 0;
    });
  }

  py::tuple coarse_mesh() const
  {
    const Geo_mesh& c = coarse_->mesh;
    std::vector<double> V;
    std::vector<std::int64_t> index(c.number_of_vertices() + c.number_of_removed_vertices(), -1), F;
    std::int64_t k = 0;
    for(auto v : c.vertices()) {
      index[std::size_t(v)] = k++;
      const Geo_point& p = c.point(v);
      V.insert(V.end(), {p.x(), p.y(), p.z()});
    }
    for(auto f : c.faces())
      for(auto v : CGAL::vertices_around_face(c.halfedge(f), c)) F.push_back(index[std::size_t(v)]);
    return py::make_tuple(to_numpy(std::move(V), k, 3), to_numpy(std::move(F), py::ssize_t(F.size() / 3), 3),
                          to_numpy(std::vector<std::int64_t>(coarse_->coarse_face_of_fine_face.begin(),
                                                             coarse_->coarse_face_of_fine_face.end())));
  }

  // Loops of one view: "fine" (the whole fine silhouette), "picked" (method A), "mapped" (method B), "coarse".
  py::dict frame(py::handle eye, py::handle direction, double alpha, std::size_t min_loop_edges, double threshold,
                 double min_relative_gain)
  {
    const View view = make_view(eye, direction);
    SS::Loop_picking_options pick;
    pick.min_loop_edges = min_loop_edges;
    pick.threshold = threshold;
    pick.min_relative_gain = min_relative_gain;
    SS::Loop_mapping_options map;
    map.alpha = alpha;
    SS::Silhouette_frame f;
    {
      py::gil_scoped_release release;
      simplifier_->extract(view, f);
      simplifier_->pick_loops(f, pick);
      simplifier_->map_loops(f, map);
    }
    auto fine_loops = [&](const std::vector<SS::Silhouette_frame::Loop>& loops) {
      py::list out;
      for(const auto& l : loops) {
        std::vector<std::int64_t> vs;
        for(std::uint32_t h : l.halfedges)
          vs.push_back(input_.caller_vertex[std::size_t(input_.mesh.source(simplifier_->fine_halfedge(h)))]);
        out.append(py::make_tuple(to_numpy(std::move(vs)), l.closed));
      }
      return out;
    };
    std::vector<SS::Silhouette_frame::Loop> picked;
    for(std::uint32_t l : f.picked) picked.push_back(f.fine_loops[l]);
    py::list coarse;
    for(const auto& l : f.coarse_loops) {
      std::vector<double> pts;
      for(std::uint32_t h : l.halfedges) {
        const auto& p = simplifier_->coarse().points[simplifier_->coarse().source[h]];
        pts.insert(pts.end(), {p.x(), p.y(), p.z()});
      }
      const py::ssize_t k = py::ssize_t(pts.size() / 3);
      coarse.append(py::make_tuple(to_numpy(std::move(pts), k, 3), l.closed));
    }
    py::dict d;
    d["fine"] = fine_loops(f.fine_loops);
    d["picked"] = fine_loops(picked);
    d["mapped"] = fine_loops(f.mapped);
    d["coarse"] = coarse;
    d["picking_error"] = f.picking_error;
    d["fine_silhouette_edges"] = f.fine_silhouette.size();
    d["coarse_silhouette_edges"] = f.coarse_silhouette.size();
    return d;
  }

  std::size_t fine_faces() const { return simplifier_->fine().number_of_faces(); }
  std::size_t coarse_faces() const { return simplifier_->coarse().number_of_faces(); }
  bool uses_hierarchy() const { return simplifier_->uses_silhouette_hierarchy(); }

private:
  Indexed_input input_;
  std::unique_ptr<SS::Coarse_mesh_3<Geo_point>> coarse_;
  std::unique_ptr<SS::Silhouette_simplifier_3<Geo_mesh>> simplifier_;
};

} // namespace

void bind_silhouettes(py::module_& m)
{
  py::module_ s = m.def_submodule("silhouettes", "C++ core of mdcs.silhouettes (use mdcs.silhouettes)");
  s.def("silhouette_edges", &silhouette_edges, py::arg("vertices"), py::arg("faces"), py::arg("eye"),
        py::arg("direction"));
  py::class_<Py_silhouette_edges>(s, "SilhouetteEdges")
    .def(py::init<py::handle, py::handle>(), py::arg("vertices"), py::arg("faces"))
    .def("edges", &Py_silhouette_edges::edges, py::arg("eye"), py::arg("direction"))
    .def_property_readonly("number_of_faces", &Py_silhouette_edges::faces)
    .def_property_readonly("number_of_nodes", &Py_silhouette_edges::nodes)
    .def_property_readonly("number_of_edges_outside_the_tree", &Py_silhouette_edges::edges_outside_the_tree);
  py::class_<Py_simplifier>(s, "Simplifier")
    .def(py::init<py::handle, py::handle, std::size_t, unsigned, bool, py::object>(), py::arg("vertices"),
         py::arg("faces"), py::arg("target_faces"), py::arg("smoothing_iterations"), py::arg("hierarchy"),
         py::arg("progress"))
    .def_property_readonly("uses_hierarchy", &Py_simplifier::uses_hierarchy)
    .def("coarse_mesh", &Py_simplifier::coarse_mesh)
    .def_property_readonly("number_of_fine_faces", &Py_simplifier::fine_faces)
    .def_property_readonly("number_of_coarse_faces", &Py_simplifier::coarse_faces)
    .def("frame", &Py_simplifier::frame, py::arg("eye"), py::arg("direction"), py::arg("alpha"),
         py::arg("min_loop_edges"), py::arg("threshold"), py::arg("min_relative_gain"));
}

} // namespace mdcs_python
