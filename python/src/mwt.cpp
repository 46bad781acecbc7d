// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Bindings of Minimum_weight_triangulation_2: the triangle-based LP with its certificate, for a point array.

#include "common.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Minimum_weight_triangulation_2.h>

#include <functional>
#include <vector>

namespace mdcs_python {
namespace {

namespace MWT = CGAL::Minimum_weight_triangulation_2;
typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 Point_2;

MWT::Edge_metric parse_metric(const std::string& s)
{
  if(s == "L2" || s == "l2" || s == "euclidean") return MWT::Edge_metric::L2;
  if(s == "L1" || s == "l1" || s == "manhattan") return MWT::Edge_metric::L1;
  if(s == "Linf" || s == "linf" || s == "Chebyshev" || s == "chebyshev") return MWT::Edge_metric::Linf;
  throw Value_error("mdcs: unknown metric '" + s + "'; use 'L2', 'L1' or 'Linf'");
}

MWT::Pruning parse_pruning(const std::string& s)
{
  if(s == "auto" || s == "automatic") return MWT::Pruning::automatic;
  if(s == "none") return MWT::Pruning::none;
  if(s == "diamond") return MWT::Pruning::diamond;
  throw Value_error("mdcs: unknown pruning '" + s + "'; use 'auto', 'none' or 'diamond'");
}

MWT::Lp_solver_choice parse_solver(const std::string& s)
{
  MWT::Lp_solver_choice c;
  if(s == "auto" || s == "automatic") c = MWT::Lp_solver_choice::automatic;
  else if(s == "clp") c = MWT::Lp_solver_choice::clp;
  else if(s == "glpk") c = MWT::Lp_solver_choice::glpk;
  else if(s == "exact") c = MWT::Lp_solver_choice::exact;
  else if(s == "qp") c = MWT::Lp_solver_choice::qp_solver;
  else throw Value_error("mdcs: unknown LP solver '" + s + "'; use 'auto', 'clp', 'glpk', 'exact' or 'qp'");
  if(!MWT::has_lp_solver(c))
    throw Value_error("mdcs: the LP solver '" + s + "' was not built into this module (needs COIN-OR CLP or GLPK)");
  return c;
}

// Mwt_options::qp_max_columns: an integer >= 0 (0: no limit).
std::size_t checked_column_limit(py::handle object)
{
  const char* what = "mdcs: qp_max_columns must be an integer >= 0 (0: no limit)";
  if(PyBool_Check(object.ptr()) || !PyIndex_Check(object.ptr())) throw Value_error(what);
  long long n = 0;
  try {
    n = py::reinterpret_borrow<py::object>(object).cast<long long>();
  } catch(const py::cast_error&) {
    throw Value_error(what);   // beyond long long
  }
  if(n < 0) throw Value_error(std::string(what) + ", got " + std::to_string(n));
  return std::size_t(n);
}

py::dict statistics_dict(const MWT::Mwt_statistics& s)
{
  py::dict d;
  d["points"] = s.points;
  d["hull_points"] = s.hull_points;
  d["candidate_edges"] = s.candidate_edges;
  d["empty_triangles"] = s.empty_triangles;
  d["lp_columns"] = s.lp_columns;
  d["lp_rows"] = s.lp_rows;
  d["lp_nonzeros"] = s.lp_nonzeros;
  d["fractional_variables"] = s.fractional_variables;
  d["lp_iterations"] = s.lp_iterations;
  d["lmt_certain_edges"] = s.lmt_certain_edges;
  d["lmt_possible_edges"] = s.lmt_possible_edges;
  d["lmt_faces"] = s.lmt_faces;
  d["lmt_solved_faces"] = s.lmt_solved_faces;
  d["dp_triangles"] = s.dp_triangles;
  d["time_setup"] = s.time_setup;
  d["time_candidates"] = s.time_candidates;
  d["time_triangles"] = s.time_triangles;
  d["time_lp_build"] = s.time_lp_build;
  d["time_lp_solve"] = s.time_lp_solve;
  d["time_certificate"] = s.time_certificate;
  d["time_branch_and_bound"] = s.time_branch_and_bound;
  d["time_total"] = s.time_total;
  return d;
}

py::dict minimum_weight_triangulation(py::handle points, const std::string& metric, const std::string& pruning,
                                      const std::string& solver, bool resolve_fractional,
                                      double branch_and_bound_time_limit, double certificate_tolerance,
                                      double integrality_tolerance, bool validate, bool use_lmt_skeleton,
                                      bool exact_support_certificate, py::handle threads, py::object progress,
                                      py::handle qp_max_columns)
{
  const std::size_t thread_count = checked_thread_count(threads);
  const Double_array P = checked_doubles(points, "points", 2, 2, true, "(n, 2)");
  const std::size_t n = std::size_t(P.shape(0));
  if(n < 3) throw Value_error("mdcs: a triangulation needs at least 3 points, got " + std::to_string(n));
  MWT::Mwt_options options;
  options.metric = parse_metric(metric);
  options.pruning = parse_pruning(pruning);
  options.solver = parse_solver(solver);
  if(options.pruning == MWT::Pruning::diamond && options.metric != MWT::Edge_metric::L2)
    throw Value_error("mdcs: the diamond test is valid for the Euclidean metric (L2) only");
  if(use_lmt_skeleton && options.metric != MWT::Edge_metric::L2)
    throw Value_error("mdcs: the LMT-skeleton is valid for the Euclidean metric (L2) only");
  options.resolve_fractional = resolve_fractional;
  options.branch_and_bound_time_limit = checked_number(py::float_(branch_and_bound_time_limit),
                                                       "branch_and_bound_time_limit", 0, false);
  options.certificate_tolerance = checked_number(py::float_(certificate_tolerance), "certificate_tolerance", 0, false);
  options.integrality_tolerance = checked_number(py::float_(integrality_tolerance), "integrality_tolerance", 0, true);
  options.validate = validate;
  options.use_lmt_skeleton = use_lmt_skeleton;
  options.exact_support_certificate = exact_support_certificate;
  options.threads = thread_count;
  options.qp_max_columns = checked_column_limit(qp_max_columns);
  std::vector<Point_2> pts;
  pts.reserve(n);
  for(std::size_t i = 0; i < n; ++i) pts.emplace_back(P.data()[2 * i], P.data()[2 * i + 1]);

  Progress_bridge bridge(progress);
  options.progress = [&bridge](const char* stage, double fraction) { return bridge(stage, fraction); };
  // The parallel pipeline gives the same triangulation, weight and certificate for every thread count.
  MWT::Mwt_result r = run_without_gil(bridge, [&] {
    try {
      return thread_count == 1 ? MWT::minimum_weight_triangulation_2(pts, options)
                               : MWT::minimum_weight_triangulation_2<CGAL::Parallel_if_available_tag>(pts, options);
    } catch(const MWT::Linear_program_too_large& e) {   // ValueError naming the keyword that raises the limit
      throw Value_error("mdcs: " + std::string(e.what()) + " (qp_max_columns=" + std::to_string(e.limit()) + ")");
    }
  });
  // A cancelled branch and bound ends with a status instead of an exception: report the interruption.
  if(bridge.has_stashed_error()) bridge.raise_stashed_error();
  if(bridge.stopped()) throw Cancelled_error("mdcs: the minimum weight triangulation was cancelled by the progress callback");

  std::vector<std::int64_t> triangles;
  triangles.reserve(3 * r.triangles.size());
  for(const auto& t : r.triangles)
    for(int v : t) triangles.push_back(v);
  py::dict d;
  d["triangles"] = to_numpy(std::move(triangles), py::ssize_t(r.triangles.size()), 3);
  d["weight"] = r.weight;
  d["status"] = MWT::to_string(r.status);
  d["lower_bound"] = r.lower_bound;
  d["lp_objective"] = r.lp_objective;
  d["lp_integral"] = r.lp_integral;
  d["lp_exact"] = r.lp_exact;
  d["certificate_exact"] = r.certificate_exact;
  d["certificate_support"] = r.certificate_support;
  d["solver"] = r.solver;
  d["message"] = r.message;
  d["statistics"] = statistics_dict(r.statistics);
  return d;
}

} // namespace

void bind_mwt(py::module_& m)
{
  py::module_ w = m.def_submodule("mwt", "C++ core of mdcs.mwt (use mdcs.mwt)");
  w.def("minimum_weight_triangulation", &minimum_weight_triangulation, py::arg("points"), py::arg("metric"),
        py::arg("pruning"), py::arg("solver"), py::arg("resolve_fractional"), py::arg("branch_and_bound_time_limit"),
        py::arg("certificate_tolerance"), py::arg("integrality_tolerance"), py::arg("validate"),
        py::arg("use_lmt_skeleton"), py::arg("exact_support_certificate"), py::arg("threads"), py::arg("progress"),
        py::arg("qp_max_columns"));
  py::list solvers;
  solvers.append("auto");
  const std::pair<const char*, MWT::Lp_solver_choice> choices[] = {{"clp", MWT::Lp_solver_choice::clp},
      {"glpk", MWT::Lp_solver_choice::glpk}, {"exact", MWT::Lp_solver_choice::exact},
      {"qp", MWT::Lp_solver_choice::qp_solver}};
  for(const auto& c : choices)
    if(MWT::has_lp_solver(c.second)) solvers.append(c.first);
  w.attr("solvers") = py::tuple(solvers);
  w.attr("qp_max_columns_default") = MWT::Mwt_options().qp_max_columns;
}

} // namespace mdcs_python
