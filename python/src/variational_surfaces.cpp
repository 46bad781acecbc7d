// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bindings of the bivariate problems of Variational_minimization: a plane arrangement built for a surface problem,
// its facets (for weights computed in Python from a vectorised user functional), the built-in functionals, and the
// globally minimal surface for given weights. The planes are random (surface_planes_3) or the regular grid
// (regular_surface_planes_3).

#include "common.h"

#include <CGAL/Variational_minimization/Minimal_surface_3.h>
#include <CGAL/Variational_minimization/Plane_arrangement_3.h>
#include <CGAL/Variational_minimization/Surface_problem_3.h>
#include <CGAL/Variational_minimization/minimize_surface_functional_3.h>
#include <CGAL/Variational_minimization/plane_grids_3.h>
#include <CGAL/Variational_minimization/surface_facet_weights_3.h>
#include <CGAL/Variational_minimization/surface_functionals_3.h>
#include <CGAL/Variational_minimization/surface_planes_3.h>

#include <cmath>
#include <limits>
#include <map>
#include <memory>

namespace mdcs_python {
namespace {

namespace VM = CGAL::Variational_minimization;
namespace MC = CGAL::Min_cut;

// The problem without boundary data: domain, range, segments. Boundary functions are tabulated at the boundary
// samples, the only points where the library evaluates them (validate(), boundary_loop()).
VM::Surface_problem_3 problem_geometry(py::handle domain, py::handle polygon, py::handle value_range, int segments)
{
  VM::Surface_problem_3 P;
  if(!polygon.is_none()) {
    if(!domain.is_none()) throw Value_error("mdcs: give either a domain rectangle or a domain polygon, not both");
    const Double_array a = checked_doubles(polygon, "polygon", 2, 2, true, "(k, 2)");
    std::vector<std::array<double, 2>> v;
    for(py::ssize_t i = 0; i < a.shape(0); ++i) v.push_back({{a.data()[2 * i], a.data()[2 * i + 1]}});
    P.set_domain_polygon(v);
  } else {
    const Double_array d = checked_doubles(domain, "domain", 1, -1, true, "(4,): xmin, ymin, xmax, ymax");
    if(d.size() != 4) throw Value_error("mdcs: domain must be (xmin, ymin, xmax, ymax)");
    P.domain = CGAL::Bbox_2(d.data()[0], d.data()[1], d.data()[2], d.data()[3]);
  }
  const Double_array r = checked_doubles(value_range, "value_range", 1, -1, true, "(2,): zmin, zmax");
  if(r.size() != 2) throw Value_error("mdcs: value_range must be (zmin, zmax)");
  P.zmin = r.data()[0];
  P.zmax = r.data()[1];
  if(segments < 1 || segments > 256) throw Value_error("mdcs: segments must be in [1, 256]");
  P.boundary_segments_per_side = segments;
  return P;
}

py::array_t<double> boundary_samples(py::handle domain, py::handle polygon, py::handle value_range, int segments)
{
  VM::Surface_problem_3 P = problem_geometry(domain, polygon, value_range, segments);
  // boundary_samples() needs a valid polygon and box: check what can be checked without boundary data.
  P.lower_boundary = [&P](double, double) { return P.zmin; };
  P.validate();
  std::vector<double> out;
  for(const auto& s : P.boundary_samples()) {
    out.push_back(s[0]);
    out.push_back(s[1]);
  }
  const py::ssize_t k = py::ssize_t(out.size() / 2);
  return to_numpy(std::move(out), k, 2);
}

typedef std::map<std::pair<double, double>, double> Boundary_table;

std::function<double(double, double)> tabulated(std::shared_ptr<const Boundary_table> table)
{
  return [table](double x, double y) {
    const auto it = table->find({x, y});
    if(it == table->end())
      throw std::logic_error("mdcs: internal error: a boundary function was evaluated off the boundary samples");
    return it->second;
  };
}

py::dict surface_dict(const VM::Minimal_surface_3& s)
{
  std::vector<double> points;
  for(const auto& p : s.points) points.insert(points.end(), p.begin(), p.end());
  std::vector<std::int64_t> triangles;
  for(const auto& t : s.triangles)
    for(std::uint32_t v : t) triangles.push_back(v);
  py::dict d;
  d["feasible"] = s.is_feasible;
  d["energy"] = s.energy;
  d["solver_value"] = s.solver_value;
  d["projected_area"] = s.projected_area;
  d["facets"] = to_numpy(std::vector<std::int64_t>(s.facets.begin(), s.facets.end()));
  d["planes"] = to_numpy(std::vector<std::int64_t>(s.planes.begin(), s.planes.end()));
  d["points"] = to_numpy(std::move(points), py::ssize_t(s.points.size()), 3);
  d["triangles"] = to_numpy(std::move(triangles), py::ssize_t(s.triangles.size()), 3);
  return d;
}

class Py_surface_arrangement
{
public:
  Py_surface_arrangement(py::handle domain, py::handle polygon, py::handle value_range, int segments,
                         py::handle lower_values, py::handle upper_values, std::size_t planes, std::uint64_t seed,
                         const std::string& distribution, double max_slope, double pencil_fraction,
                         std::size_t plane_grid, std::size_t grid_offset_steps, py::object progress)
    : problem_(problem_geometry(domain, polygon, value_range, segments))
  {
    // The boundary data at the samples (in the order of boundary_samples()).
    VM::Surface_problem_3 probe = problem_;
    probe.lower_boundary = [this](double, double) { return problem_.zmin; };
    probe.validate();
    const std::vector<std::array<double, 2>> samples = probe.boundary_samples();
    auto table = [&](py::handle values, const char* name) {
      const Double_array v = checked_doubles(values, name, 1, -1, true, "(number of boundary samples,)");
      if(std::size_t(v.size()) != samples.size())
        throw Value_error(std::string("mdcs: ") + name + " has " + std::to_string(v.size()) + " values for " +
                          std::to_string(samples.size()) + " boundary samples");
      auto t = std::make_shared<Boundary_table>();
      for(std::size_t i = 0; i < samples.size(); ++i) (*t)[{samples[i][0], samples[i][1]}] = v.data()[i];
      return tabulated(t);
    };
    problem_.lower_boundary = table(lower_values, "boundary values");
    if(!upper_values.is_none()) problem_.upper_boundary = table(upper_values, "upper boundary values");
    problem_.validate();
    Progress_bridge bridge(progress);
    if(plane_grid > 0) {
      // The grid's own checks (rectangle, n, offset steps, max_slope, plane count) raise ValueError; they run before
      // the arrangement is built, so a too large grid never allocates it.
      VM::Regular_surface_plane_options_3 options;
      options.max_slope = checked_number(py::float_(max_slope), "max_slope", 0, true);
      options.offset_steps = grid_offset_steps;
      arrangement_ = run_without_gil(bridge, [&] {
        const std::vector<VM::Lattice_plane_3> P = VM::regular_surface_planes_3(problem_, plane_grid, options);
        return std::make_shared<VM::Plane_arrangement_3>(VM::build_surface_arrangement_3(problem_, P, std::ref(bridge)));
      });
      return;
    }
    if(planes < 1) throw Value_error("mdcs: planes must be at least 1");
    VM::Surface_plane_options_3 options;
    if(distribution == "slope_limited") options.distribution = VM::Plane_distribution_3::slope_limited;
    else if(distribution == "isotropic") options.distribution = VM::Plane_distribution_3::isotropic;
    else throw Value_error("mdcs: distribution must be 'slope_limited' or 'isotropic'");
    options.max_slope = checked_number(py::float_(max_slope), "max_slope", 0, true);
    if(!(pencil_fraction >= 0 && pencil_fraction <= 1)) throw Value_error("mdcs: pencil_fraction must be in [0, 1]");
    options.pencil_fraction = pencil_fraction;
    options.seed = seed;
    arrangement_ = run_without_gil(bridge, [&] {
      const std::vector<VM::Lattice_plane_3> P = VM::surface_planes_3(problem_, planes, options);
      return std::make_shared<VM::Plane_arrangement_3>(VM::build_surface_arrangement_3(problem_, P, std::ref(bridge)));
    });
  }

  std::size_t cells() const { return arrangement_->number_of_cells(); }
  std::size_t facets() const { return arrangement_->number_of_facets(); }
  std::size_t vertices() const { return arrangement_->number_of_vertices(); }
  std::size_t planes() const { return arrangement_->number_of_planes(); }
  double domain_area() const { return problem_.domain_area(); }

  // The weights known without the functional (0: side walls and facets outside a polygonal domain, +inf: vertical
  // facets), and for the others the world plane z = A x + B y + C and the (x, y) polygon, counter-clockwise.
  py::tuple weight_facets() const
  {
    const VM::Plane_arrangement_3& A = *arrangement_;
    const std::size_t n = A.number_of_facets();
    std::vector<double> base(n, 0.0), abc, xy;
    std::vector<std::int64_t> which, offsets{0};
    const bool polygonal = problem_.is_polygonal();
    const std::vector<char> inside =
      polygonal ? VM::internal::surface_domain_cells_3(A, problem_) : std::vector<char>();
    for(std::size_t i = 0; i < n; ++i) {
      const auto f = VM::Plane_arrangement_3::Facet_index(i);
      const auto& F = A.facet(f);
      if(polygonal) {
        const bool in = (F.negative_cell != VM::Plane_arrangement_3::null_index && inside[F.negative_cell]) ||
                        (F.positive_cell != VM::Plane_arrangement_3::null_index && inside[F.positive_cell]);
        if(!in) continue;
      }
      if(F.plane < 4) continue; // side walls
      const VM::Lattice_plane_3& plane = A.plane(F.plane);
      if(plane.c == 0) {
        base[i] = std::numeric_limits<double>::infinity();
        continue;
      }
      const std::array<double, 3> w = problem_.world_plane(plane);
      const std::vector<std::array<double, 2>> poly = VM::surface_facet_projection_3(A, problem_, f);
      if(poly.size() < 3) continue;
      which.push_back(std::int64_t(i));
      abc.insert(abc.end(), w.begin(), w.end());
      for(const auto& p : poly) xy.insert(xy.end(), p.begin(), p.end());
      offsets.push_back(offsets.back() + std::int64_t(poly.size()));
    }
    const py::ssize_t q = py::ssize_t(which.size());
    const py::ssize_t pts = py::ssize_t(xy.size() / 2);
    return py::make_tuple(to_numpy(std::move(base)), to_numpy(std::move(which)), to_numpy(std::move(abc), q, 3),
                          to_numpy(std::move(offsets)), to_numpy(std::move(xy), pts, 2));
  }

  template <class Run>
  py::dict solve_with(const std::string& engine, Progress_bridge& bridge, Run run) const
  {
    const VM::Minimal_surface_3 s = run_without_gil(bridge, [&] {
      if(engine == "pseudoflow") return run(MC::Pseudoflow_max_flow());
      if(engine == "push_relabel") return run(MC::Push_relabel_max_flow());
      if(engine == "boykov_kolmogorov") return run(MC::Boykov_kolmogorov_max_flow());
      throw Value_error("mdcs: unknown engine '" + engine + "'; use 'pseudoflow', 'push_relabel' or 'boykov_kolmogorov'");
    });
    return surface_dict(s);
  }

  py::dict solve(py::handle weights, const std::string& engine, py::object progress) const
  {
    const Double_array W = checked_doubles(weights, "weights", 1, -1, false, "(number of facets,)");
    if(std::size_t(W.size()) != arrangement_->number_of_facets())
      throw Value_error("mdcs: weights has " + std::to_string(W.size()) + " entries for " +
                        std::to_string(arrangement_->number_of_facets()) + " arrangement facets");
    const std::vector<double> w(W.data(), W.data() + W.size());
    for(std::size_t i = 0; i < w.size(); ++i)
      if(!(w[i] >= 0))
        throw Value_error("mdcs: weights[" + std::to_string(i) + "] = " + std::to_string(w[i]) +
                          "; facet weights must be >= 0 (+inf allowed), not NaN");
    Progress_bridge bridge(progress);
    return solve_with(engine, bridge, [&](auto e) {
      return VM::minimize_surface_functional_3(*arrangement_, w, problem_, e, std::ref(bridge));
    });
  }

  // The facet weights on `threads` threads (identical for every count; the max-flow is sequential).
  py::dict solve_builtin(const std::string& name, double k_g, double z_bottom, int quadrature_level,
                         const std::string& engine, py::handle threads_object, py::object progress) const
  {
    if(quadrature_level < 0 || quadrature_level > 8) throw Value_error("mdcs: quadrature_level must be in [0, 8]");
    const std::size_t threads = checked_thread_count(threads_object);
    Progress_bridge bridge(progress);
    if(name == "area")
      return solve_with(engine, bridge, [&](auto e) {
        return VM::minimize_surface_functional_3<CGAL::Parallel_if_available_tag>(
          *arrangement_, problem_, VM::Area_functional_3(), quadrature_level, threads, e, std::ref(bridge));
      });
    if(name == "membrane") {
      VM::Membrane_functional_3 G;
      G.k_g = checked_number(py::float_(k_g), "k_g", 0, false);
      G.z_bottom = std::isnan(z_bottom) ? problem_.zmin : z_bottom;
      return solve_with(engine, bridge, [&](auto e) {
        return VM::minimize_surface_functional_3<CGAL::Parallel_if_available_tag>(*arrangement_, problem_, G,
                                                                                 quadrature_level, threads, e,
                                                                                 std::ref(bridge));
      });
    }
    throw Value_error("mdcs: unknown surface functional '" + name + "'; use 'area' or 'membrane'");
  }

private:
  VM::Surface_problem_3 problem_;
  std::shared_ptr<const VM::Plane_arrangement_3> arrangement_;
};

} // namespace

void bind_variational_surfaces(py::module_& m)
{
  py::module_ v = m.attr("variational").cast<py::module_>();
  v.def("surface_boundary_samples", &boundary_samples, py::arg("domain"), py::arg("polygon"), py::arg("value_range"),
        py::arg("segments"));
  v.attr("regular_surface_max_steps") = VM::regular_surface_max_steps_3();
  py::class_<Py_surface_arrangement>(v, "SurfaceArrangement")
    .def(py::init<py::handle, py::handle, py::handle, int, py::handle, py::handle, std::size_t, std::uint64_t,
                  const std::string&, double, double, std::size_t, std::size_t, py::object>(),
         py::arg("domain"), py::arg("polygon"), py::arg("value_range"), py::arg("segments"), py::arg("lower_values"),
         py::arg("upper_values"), py::arg("planes"), py::arg("seed"), py::arg("distribution"), py::arg("max_slope"),
         py::arg("pencil_fraction"), py::arg("plane_grid"), py::arg("grid_offset_steps"), py::arg("progress"))
    .def_property_readonly("number_of_cells", &Py_surface_arrangement::cells)
    .def_property_readonly("number_of_facets", &Py_surface_arrangement::facets)
    .def_property_readonly("number_of_vertices", &Py_surface_arrangement::vertices)
    .def_property_readonly("number_of_planes", &Py_surface_arrangement::planes)
    .def_property_readonly("domain_area", &Py_surface_arrangement::domain_area)
    .def("weight_facets", &Py_surface_arrangement::weight_facets)
    .def("solve", &Py_surface_arrangement::solve, py::arg("weights"), py::arg("engine"), py::arg("progress"))
    .def("solve_builtin", &Py_surface_arrangement::solve_builtin, py::arg("name"), py::arg("k_g"), py::arg("z_bottom"),
         py::arg("quadrature_level"), py::arg("engine"), py::arg("threads"), py::arg("progress"));
}

} // namespace mdcs_python
