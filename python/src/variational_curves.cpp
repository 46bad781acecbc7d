// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bindings of the univariate problems of Variational_minimization: a line arrangement built for a curve problem,
// its edges (for weights computed in Python from a vectorised user functional), the weights of the built-in
// functionals, and the globally minimal curve for given weights.

#include "common.h"

#include <CGAL/Variational_minimization/Curve_problem_2.h>
#include <CGAL/Variational_minimization/Line_arrangement_2.h>
#include <CGAL/Variational_minimization/analytic_solutions_2.h>
#include <CGAL/Variational_minimization/curve_edge_weights_2.h>
#include <CGAL/Variational_minimization/curve_functionals_2.h>
#include <CGAL/Variational_minimization/line_grids_2.h>
#include <CGAL/Variational_minimization/minimize_curve_functional_2.h>

#include <cmath>
#include <limits>

namespace mdcs_python {
namespace {

namespace VM = CGAL::Variational_minimization;
namespace MC = CGAL::Min_cut;

VM::End_condition end_condition(py::handle value, const char* name)
{
  if(py::isinstance<py::tuple>(value) || py::isinstance<py::list>(value)) {
    const py::sequence s = py::reinterpret_borrow<py::sequence>(value);
    if(py::len(s) != 2) throw Value_error(std::string("mdcs: ") + name + " must be a number or a pair (low, high)");
    const double lo = checked_number(s[0], name, -std::numeric_limits<double>::max(), false);
    const double hi = checked_number(s[1], name, -std::numeric_limits<double>::max(), false);
    return VM::End_condition::range(lo, hi);
  }
  return VM::End_condition::fixed(checked_number(value, name, -std::numeric_limits<double>::max(), false));
}

std::pair<double, double> pair_of(py::handle value, const char* name)
{
  const Double_array a = checked_doubles(value, name, 1, -1, true, "(2,)");
  if(a.size() != 2) throw Value_error(std::string("mdcs: ") + name + " must hold two numbers");
  return {a.data()[0], a.data()[1]};
}

class Py_curve_arrangement
{
public:
  Py_curve_arrangement(py::handle interval, py::handle value_range, py::handle left, py::handle right,
                       py::handle lines, std::size_t grid, std::uint64_t seed, double pencil_fraction,
                       double max_abs_slope, bool include_floor, py::object progress)
  {
    const auto x = pair_of(interval, "interval");
    const auto y = pair_of(value_range, "value_range");
    problem_.box = CGAL::Bbox_2(x.first, y.first, x.second, y.second);
    problem_.left = end_condition(left, "left");
    problem_.right = end_condition(right, "right");
    problem_.validate();
    std::vector<VM::Arrangement_line_2> L;
    if(grid > 0) {
      if(!lines.is_none()) throw Value_error("mdcs: give either lines or grid, not both");
      L = VM::regular_grid_lines_2(problem_.box, grid);
    } else if(!lines.is_none() && (PyLong_Check(lines.ptr()) || py::isinstance<py::int_>(lines))) {
      const long count = lines.cast<long>();
      if(count < 1) throw Value_error("mdcs: lines must be at least 1");
      VM::Random_lines_options options;
      if(!(pencil_fraction >= 0 && pencil_fraction <= 1)) throw Value_error("mdcs: pencil_fraction must be in [0, 1]");
      options.pencil_fraction = pencil_fraction;
      options.max_abs_slope = checked_number(py::float_(max_abs_slope), "max_abs_slope", 0, false);
      options.include_floor = include_floor;
      // Pencils through the fixed end points, so that the arrangement has lines leaving them in many directions.
      if(problem_.left.is_fixed()) options.pencil_points.emplace_back(x.first, problem_.left.low);
      if(problem_.right.is_fixed()) options.pencil_points.emplace_back(x.second, problem_.right.low);
      L = VM::random_lines_2(problem_.box, std::size_t(count), seed, options);
    } else if(!lines.is_none()) {
      const Double_array a = checked_doubles(lines, "lines", 2, 4, true, "(k, 4): x0, y0, x1, y1 of two points per line");
      for(py::ssize_t i = 0; i < a.shape(0); ++i) {
        const double* r = a.data() + 4 * i;
        if(r[0] == r[2] && r[1] == r[3])
          throw Value_error("mdcs: lines[" + std::to_string(i) + "] has two equal points");
        L.push_back(VM::Arrangement_line_2{VM::Point_2(r[0], r[1]), VM::Point_2(r[2], r[3])});
      }
    } else {
      throw Value_error("mdcs: give lines (a count of random lines, or a (k, 4) array) or grid");
    }
    Progress_bridge bridge(progress);
    arrangement_.reset(new VM::Line_arrangement_2(
      run_without_gil(bridge, [&] { return VM::build_curve_arrangement_2(problem_, L, std::ref(bridge)); })));
  }

  std::size_t vertices() const { return arrangement_->number_of_vertices(); }
  std::size_t edges() const { return arrangement_->number_of_edges(); }
  std::size_t faces() const { return arrangement_->number_of_faces(); }

  // Per edge: x0, y0, x1, y1, slope, and whether a function may use it (not a wall, not vertical, x0 < x1).
  py::tuple edge_geometry() const
  {
    const VM::Line_arrangement_2& A = *arrangement_;
    const std::size_t n = A.number_of_edges();
    std::vector<double> g(5 * n);
    std::vector<std::uint8_t> usable(n);
    for(std::size_t i = 0; i < n; ++i) {
      const auto e = VM::Line_arrangement_2::Edge_index(i);
      const auto& E = A.edge(e);
      const auto& a = A.point(E.source);
      const auto& b = A.point(E.target);
      double slope = 0;
      if(E.kind == VM::Line_arrangement_2::LINE_EDGE && !A.is_vertical(e)) {
        const VM::Arrangement_line_2& l = A.line(E.line);
        slope = (l.q.y() - l.p.y()) / (l.q.x() - l.p.x());
      }
      g[5 * i] = a.x();
      g[5 * i + 1] = a.y();
      g[5 * i + 2] = b.x();
      g[5 * i + 3] = b.y();
      g[5 * i + 4] = slope;
      const bool wall = E.kind == VM::Line_arrangement_2::LEFT_WALL || E.kind == VM::Line_arrangement_2::RIGHT_WALL;
      usable[i] = !wall && !A.is_vertical(e);
    }
    return py::make_tuple(to_numpy(std::move(g), py::ssize_t(n), 5), to_numpy(std::move(usable)));
  }

  // The weights of a built-in functional (closed forms).
  py::array_t<double> builtin_weights(const std::string& name, py::object progress) const
  {
    Progress_bridge bridge(progress);
    std::vector<double> w = run_without_gil(bridge, [&] {
      if(name == "surface_of_rotation")
        return VM::curve_edge_weights_2(*arrangement_, VM::Surface_of_rotation_functional(), std::ref(bridge));
      if(name == "arc_length") return VM::curve_edge_weights_2(*arrangement_, VM::Arc_length_functional(), std::ref(bridge));
      throw Value_error("mdcs: unknown curve functional '" + name + "'; use 'surface_of_rotation' or 'arc_length'");
    });
    return to_numpy(std::move(w));
  }

  py::dict solve(py::handle weights, const std::string& engine, py::object progress) const
  {
    const Double_array W = checked_doubles(weights, "weights", 1, -1, false, "(number of edges,)");
    if(std::size_t(W.size()) != arrangement_->number_of_edges())
      throw Value_error("mdcs: weights has " + std::to_string(W.size()) + " entries for " +
                        std::to_string(arrangement_->number_of_edges()) + " arrangement edges");
    std::vector<double> w(W.data(), W.data() + W.size());
    for(std::size_t i = 0; i < w.size(); ++i)
      if(!(w[i] >= 0))
        throw Value_error("mdcs: weights[" + std::to_string(i) + "] = " + std::to_string(w[i]) +
                          "; edge weights must be >= 0 (+inf allowed), not NaN");
    Progress_bridge bridge(progress);
    const VM::Minimal_curve_2 c = run_without_gil(bridge, [&] {
      if(engine == "planar") return VM::minimize_curve_functional_2(*arrangement_, w, problem_, MC::Planar_min_cut(), std::ref(bridge));
      if(engine == "pseudoflow")
        return VM::minimize_curve_functional_2(*arrangement_, w, problem_, MC::Pseudoflow_max_flow(), std::ref(bridge));
      if(engine == "push_relabel")
        return VM::minimize_curve_functional_2(*arrangement_, w, problem_, MC::Push_relabel_max_flow(), std::ref(bridge));
      if(engine == "boykov_kolmogorov")
        return VM::minimize_curve_functional_2(*arrangement_, w, problem_, MC::Boykov_kolmogorov_max_flow(), std::ref(bridge));
      throw Value_error("mdcs: unknown engine '" + engine +
                        "'; use 'planar', 'pseudoflow', 'push_relabel' or 'boykov_kolmogorov'");
    });
    std::vector<double> polyline;
    for(const auto& p : c.polyline) {
      polyline.push_back(p.x());
      polyline.push_back(p.y());
    }
    std::vector<std::int64_t> edges(c.edges.begin(), c.edges.end());
    py::dict d;
    d["feasible"] = c.is_feasible;
    d["energy"] = c.energy;
    d["solver_value"] = c.solver_value;
    d["polyline"] = to_numpy(std::move(polyline), py::ssize_t(c.polyline.size()), 2);
    d["edges"] = to_numpy(std::move(edges));
    return d;
  }

private:
  VM::Curve_problem_2 problem_;
  std::unique_ptr<VM::Line_arrangement_2> arrangement_;
};

py::dict surface_of_rotation_minimum(double R, double h)
{
  checked_number(py::float_(R), "R", 0, true);
  checked_number(py::float_(h), "h", 0, true);
  const VM::Surface_of_rotation_minimum m = VM::global_minimum_surface_of_rotation(R, h);
  py::dict d;
  d["energy"] = m.energy;
  d["branch"] = m.branch == VM::Surface_of_rotation_minimum::Branch::Catenoid ? "catenoid" : "goldschmidt";
  d["catenoid_exists"] = m.catenoids.exists;
  d["catenoid_energy"] = m.catenoids.exists ? m.catenoid_energy : std::numeric_limits<double>::infinity();
  d["goldschmidt_energy"] = m.goldschmidt_energy;
  return d;
}

} // namespace

void bind_variational_curves(py::module_& m)
{
  py::module_ v = m.def_submodule("variational", "C++ core of mdcs.variational (use mdcs.variational)");
  py::class_<Py_curve_arrangement>(v, "CurveArrangement")
    .def(py::init<py::handle, py::handle, py::handle, py::handle, py::handle, std::size_t, std::uint64_t, double, double,
                  bool, py::object>(),
         py::arg("interval"), py::arg("value_range"), py::arg("left"), py::arg("right"), py::arg("lines"),
         py::arg("grid"), py::arg("seed"), py::arg("pencil_fraction"), py::arg("max_abs_slope"),
         py::arg("include_floor"), py::arg("progress"))
    .def_property_readonly("number_of_vertices", &Py_curve_arrangement::vertices)
    .def_property_readonly("number_of_edges", &Py_curve_arrangement::edges)
    .def_property_readonly("number_of_faces", &Py_curve_arrangement::faces)
    .def("edge_geometry", &Py_curve_arrangement::edge_geometry)
    .def("builtin_weights", &Py_curve_arrangement::builtin_weights, py::arg("name"), py::arg("progress"))
    .def("solve", &Py_curve_arrangement::solve, py::arg("weights"), py::arg("engine"), py::arg("progress"));
  v.def("surface_of_rotation_minimum", &surface_of_rotation_minimum, py::arg("R"), py::arg("h") = 1.0);
}

} // namespace mdcs_python
