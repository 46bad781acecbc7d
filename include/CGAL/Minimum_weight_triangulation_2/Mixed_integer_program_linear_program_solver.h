// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Adapter: any model of CGAL's MixedIntegerProgramTraits (GLPK_mixed_integer_program_traits,
// SCIP_mixed_integer_program_traits, ...) as a LinearProgramSolver, and as the binary solver that resolves
// fractional optima.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_MIXED_INTEGER_PROGRAM_LINEAR_PROGRAM_SOLVER_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_MIXED_INTEGER_PROGRAM_LINEAR_PROGRAM_SOLVER_H

#include <CGAL/Minimum_weight_triangulation_2/Linear_program.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {

/*!
  \brief A `LinearProgramSolver` on top of a model of CGAL's `MixedIntegerProgramTraits` concept (for example
  `CGAL::GLPK_mixed_integer_program_traits<double>` or `CGAL::SCIP_mixed_integer_program_traits<double>`).
  \cgalModels `LinearProgramSolver`

  `solve()` passes the program with continuous variables, `solve_binary()` with binary ones (usable as the
  binary solver of `minimum_weight_triangulation_2()`, which resolves fractional LP optima).

  CGAL's traits return primal values only: no duals, no basis. The MWT code therefore cannot certify an
  optimum found through this adapter by its dual bound: an integral optimum is validated exactly and reported
  as `optimal_uncertified`. Use `CLP_linear_program_solver` or `GLPK_linear_program_solver` for certified
  results; this adapter lets a CGAL user plug in the MIP back end they already have (e.g. SCIP) and resolve
  fractional optima with it. The traits also cannot tell an infeasible program from a failed solve; both are
  reported as `Lp_status::failed` with the traits' error message; a returned point is checked against
  every row and column bound (1e-7 relative) and never reported as optimal when it violates one (CGAL's GLPK
  traits return the last simplex point even for an infeasible program).

  Infinite bounds are passed as the traits' `Variable::infinity()` (1e20 in CGAL).

  \tparam MixedIntegerProgramTraits a model of CGAL's `MixedIntegerProgramTraits` with `FT = double`
*/
template <class MixedIntegerProgramTraits>
class Mixed_integer_program_linear_program_solver
{
public:
  explicit Mixed_integer_program_linear_program_solver(const char* name = "mip-traits") : name_(name) {}

  const char* name() const { return name_; }

  Linear_program_solution solve(const Sparse_linear_program& lp) const { return run(lp, false); }

  /// The same program with every column restricted to {0, 1}.
  Linear_program_solution solve_binary(const Sparse_linear_program& lp) const { return run(lp, true); }

private:
  typedef MixedIntegerProgramTraits Traits;
  typedef typename Traits::Variable Variable;
  typedef typename Traits::Linear_constraint Linear_constraint;
  typedef typename Traits::Linear_objective Linear_objective;

  static double bound(double b)
  {
    if(b == Sparse_linear_program::infinity()) return Variable::infinity();
    if(b == -Sparse_linear_program::infinity()) return -Variable::infinity();
    return b;
  }

  Linear_program_solution run(const Sparse_linear_program& lp, bool binary) const
  {
    lp.check();
    Traits mip;
    const std::size_t nc = lp.number_of_columns();
    std::vector<Variable*> x(nc);
    for(std::size_t j = 0; j < nc; ++j)
      x[j] = binary ? mip.create_variable(Variable::BINARY, 0, 1)
                    : mip.create_variable(Variable::CONTINUOUS, bound(lp.col_lower[j]), bound(lp.col_upper[j]));
    std::vector<Linear_constraint*> rows(lp.number_of_rows);
    for(std::size_t i = 0; i < lp.number_of_rows; ++i)
      rows[i] = mip.create_constraint(bound(lp.row_lower[i]), bound(lp.row_upper[i]));
    Linear_objective* objective = mip.create_objective(Linear_objective::MINIMIZE);
    for(std::size_t j = 0; j < nc; ++j) {
      objective->add_coefficient(x[j], lp.cost[j]);
      for(int k = lp.column_start[j]; k < lp.column_start[j + 1]; ++k)
        rows[std::size_t(lp.row_index[std::size_t(k)])]->add_coefficient(x[j], lp.value[std::size_t(k)]);
    }

    Linear_program_solution s;
    if(!mip.solve()) {
      s.status = Lp_status::failed;
      s.message = std::string("MixedIntegerProgramTraits::solve() failed: ") + mip.error_message();
      return s;
    }
    const std::vector<double>& values = mip.solution();
    if(values.size() != nc) {
      s.status = Lp_status::failed;
      s.message = "MixedIntegerProgramTraits returned " + std::to_string(values.size()) + " values for " +
                  std::to_string(nc) + " variables";
      return s;
    }
    // The traits report success without a status (CGAL's GLPK traits return the last point even for an
    // infeasible program): never call a point optimal that violates the program.
    const std::string violation = first_violation(lp, values, binary);
    if(!violation.empty()) {
      s.status = Lp_status::failed;
      s.message = "MixedIntegerProgramTraits returned a point that violates the program (infeasible?): " + violation;
      return s;
    }
    s.status = Lp_status::optimal;
    s.primal = values;
    s.objective = 0;
    for(std::size_t j = 0; j < nc; ++j) s.objective += lp.cost[j] * values[j];
    s.message = binary ? "binary program solved through MixedIntegerProgramTraits"
                       : "linear program solved through MixedIntegerProgramTraits (no duals)";
    return s;
  }

  static std::string first_violation(const Sparse_linear_program& lp, const std::vector<double>& x, bool binary)
  {
    auto off = [](double v, double lo, double hi) {
      const double tol = 1e-7 * (1 + std::max(std::abs(lo == -Sparse_linear_program::infinity() ? 0 : lo),
                                              std::abs(hi == Sparse_linear_program::infinity() ? 0 : hi)));
      return !(v >= lo - tol && v <= hi + tol);
    };
    std::vector<double> activity(lp.number_of_rows, 0.0);
    for(std::size_t j = 0; j < x.size(); ++j) {
      if(off(x[j], binary ? 0.0 : lp.col_lower[j], binary ? 1.0 : lp.col_upper[j]) ||
         (binary && std::abs(x[j] - std::round(x[j])) > 1e-7))
        return "column " + std::to_string(j) + " = " + std::to_string(x[j]);
      for(int k = lp.column_start[j]; k < lp.column_start[j + 1]; ++k)
        activity[std::size_t(lp.row_index[std::size_t(k)])] += lp.value[std::size_t(k)] * x[j];
    }
    for(std::size_t i = 0; i < lp.number_of_rows; ++i)
      if(off(activity[i], lp.row_lower[i], lp.row_upper[i]))
        return "row " + std::to_string(i) + " = " + std::to_string(activity[i]);
    return std::string();
  }

  const char* name_;
};

} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_MIXED_INTEGER_PROGRAM_LINEAR_PROGRAM_SOLVER_H
