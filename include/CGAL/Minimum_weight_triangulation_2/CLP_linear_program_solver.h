// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Model of LinearProgramSolver on COIN-OR CLP (dual simplex). Needs MDCS_HAS_CLP and linking libClp.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_CLP_LINEAR_PROGRAM_SOLVER_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_CLP_LINEAR_PROGRAM_SOLVER_H

#include <CGAL/Minimum_weight_triangulation_2/Linear_program.h>

#include <coin/ClpSimplex.hpp>

#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {

/*!
  \brief LP solver on COIN-OR CLP's dual simplex (the fastest and most stable model measured here).
  \cgalModels `LinearProgramSolver`

  CLP's primal simplex with default settings was observed to stop at non-optimal fractional points on
  these LPs; the dual simplex is used by default. Callers still check the answer.
*/
class CLP_linear_program_solver
{
public:
  enum Algorithm { dual_simplex, primal_simplex };

  explicit CLP_linear_program_solver(Algorithm a = dual_simplex, int log_level = 0)
    : algorithm_(a), log_level_(log_level) {}

  static const char* name() { return "clp"; }

  Linear_program_solution solve(const Sparse_linear_program& lp) const
  {
    lp.check();
    Linear_program_solution s;
    ClpSimplex model;
    model.setLogLevel(log_level_);
    const int nc = int(lp.number_of_columns()), nr = int(lp.number_of_rows);
    std::vector<CoinBigIndex> start(lp.column_start.begin(), lp.column_start.end());
    model.loadProblem(nc, nr, start.data(), lp.row_index.data(), lp.value.data(), lp.col_lower.data(),
                      lp.col_upper.data(), lp.cost.data(), lp.row_lower.data(), lp.row_upper.data());
    model.setPrimalTolerance(1e-9);
    model.setDualTolerance(1e-9);
    if(algorithm_ == dual_simplex) model.dual();
    else model.primal();
    s.iterations = model.numberIterations();
    switch(model.status()) {
      case 0: s.status = Lp_status::optimal; break;
      case 1: s.status = Lp_status::infeasible; break;
      case 2: s.status = Lp_status::unbounded; break;
      case 3: s.status = Lp_status::iteration_limit; break;
      default: s.status = Lp_status::failed; break;
    }
    s.message = std::string("CLP status ") + std::to_string(model.status());
    if(s.status != Lp_status::optimal) return s;
    s.objective = model.objectiveValue();
    const double* x = model.primalColumnSolution();
    const double* y = model.dualRowSolution();
    s.primal.assign(x, x + nc);
    s.dual.assign(y, y + nr);
    s.column_status.resize(nc);
    s.row_status.resize(nr);
    for(int j = 0; j < nc; ++j) s.column_status[j] = convert(model.getColumnStatus(j));
    for(int i = 0; i < nr; ++i) s.row_status[i] = convert(model.getRowStatus(i));
    return s;
  }

private:
  static Basis_status convert(ClpSimplex::Status st)
  {
    switch(st) {
      case ClpSimplex::basic: return Basis_status::basic;
      case ClpSimplex::atLowerBound: return Basis_status::at_lower;
      case ClpSimplex::atUpperBound: return Basis_status::at_upper;
      case ClpSimplex::isFree: return Basis_status::free;
      case ClpSimplex::isFixed: return Basis_status::fixed;
      default: return Basis_status::unknown;
    }
  }

  Algorithm algorithm_;
  int log_level_;
};

} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_CLP_LINEAR_PROGRAM_SOLVER_H
