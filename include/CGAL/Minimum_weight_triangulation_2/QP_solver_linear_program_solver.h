// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Model of LinearProgramSolver on CGAL's QP_solver (CGAL/QP_functions.h): the simplex method in exact arithmetic,
// so the optimum, the primal values and the duals are those of the program's double data, exactly (rounded once
// to double on the way out). No external library; meant for small programs (the exact arithmetic costs far more
// than CLP's or GLPK's floating point).

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_QP_SOLVER_LINEAR_PROGRAM_SOLVER_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_QP_SOLVER_LINEAR_PROGRAM_SOLVER_H

#include <CGAL/Minimum_weight_triangulation_2/Linear_program.h>

#include <CGAL/Gmpzf.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {

/*!
  \brief Thrown by `QP_solver_linear_program_solver::solve()` (and so by `minimum_weight_triangulation_2()` with
  `Lp_solver_choice::qp_solver`) when the program has more columns than the solver's limit
  (`QP_solver_linear_program_solver::set_max_columns()`, `Mwt_options::qp_max_columns`): the solve is refused
  before it starts because it could not be stopped once started. A `std::length_error`, like the library's other
  size limits.
*/
class Linear_program_too_large : public std::length_error
{
public:
  Linear_program_too_large(const std::string& what, std::size_t columns, std::size_t rows, std::size_t limit)
    : std::length_error(what), columns_(columns), rows_(rows), limit_(limit)
  {}
  std::size_t columns() const { return columns_; }   ///< of the refused program
  std::size_t rows() const { return rows_; }
  std::size_t limit() const { return limit_; }       ///< the column limit it exceeded

private:
  std::size_t columns_, rows_, limit_;
};

/*!
  \brief LP solver on CGAL's exact `QP_solver` (`CGAL::solve_linear_program()`).
  \cgalModels `LinearProgramSolver`

  The program is handed to `QP_solver` as a `CGAL::Quadratic_program<double>` and solved with the exact number
  type `ET` (default `CGAL::Gmpzf`, which represents every double exactly; `CGAL::Gmpq` or `CGAL::MP_Float` work
  too). The optimum is therefore the exact optimum of the program's (double) data: `Linear_program_solution::exact`
  is set, and the objective, the primal values and the duals are the exact rationals rounded to double once.
  `solve(lp, objective, primal)` also gives the exact rationals themselves.

  A row with two different finite bounds becomes two constraints of `QP_solver` (its dual is their sum); a row
  without finite bound is left out (dual 0). The duals follow the concept's convention
  (`reduced_cost = cost - A^T dual`); they are the negated optimality certificate of `QP_solver`. The basic
  columns are reported as `Basis_status::basic`, the others at the bound they sit on; row statuses are left
  empty.

  `QP_solver` has no progress callback and no iteration or time limit: `CGAL::solve_linear_program()` constructs
  a `CGAL::QP_solver`, whose constructor (CGAL/QP_solver/Initialization.h) calls `init()` and `solve()`, and
  `solve()` is the loop `while (phase() < 3) { pivot_step(); }` with no other exit (CGAL 5.5;
  `CGAL::Quadratic_program_options` only sets the verbosity, the pricing strategy, the validation and logging).
  The control's `keep_going` (`set_control()`) is therefore asked once before the solve, and its time limit is
  not enforced. What can be
  bounded is the size of the program: `set_max_columns()` refuses larger programs up front with
  `Linear_program_too_large`. Meant for small programs: the MWT program of 20 uniform points (164 columns) took
  0.84 s of CPU time on a loaded machine, a random wheel of 20 points on the circle (658 columns) 16-22 s (exact
  GLPK: 2 and 9 ms);
  the manual has the measured scaling.

  \tparam ET an exact number type accepted by `CGAL::solve_linear_program()`.
*/
template <class ET = CGAL::Gmpzf>
class QP_solver_linear_program_solver
{
public:
  typedef CGAL::Quotient<ET> Exact_value;

  const char* name() const { return "qp-solver"; }

  /// Progress and cancellation (asked once, before the solve; the time limit is not enforced).
  void set_control(const Lp_solve_control& c) { control_ = c; }
  const Lp_solve_control& control() const { return control_; }

  /// The largest number of columns `solve()` accepts (0, the default: no limit); a larger program is refused
  /// with `Linear_program_too_large` before anything else is done.
  void set_max_columns(std::size_t n) { max_columns_ = n; }
  std::size_t max_columns() const { return max_columns_; }

  Linear_program_solution solve(const Sparse_linear_program& lp) const
  {
    Exact_value objective;
    std::vector<Exact_value> primal;
    return solve(lp, objective, primal);
  }

  /// The same, and the exact optimum and primal values (one per column) when the status is `optimal`.
  Linear_program_solution solve(const Sparse_linear_program& lp, Exact_value& exact_objective,
                                std::vector<Exact_value>& exact_primal) const
  {
    lp.check();
    if(max_columns_ > 0 && lp.number_of_columns() > max_columns_)
      throw Linear_program_too_large(
          "QP_solver_linear_program_solver: the linear program has " + std::to_string(lp.number_of_columns()) +
              " columns (" + std::to_string(lp.number_of_rows) + " rows), more than the limit of " +
              std::to_string(max_columns_) + " columns; CGAL's exact QP_solver cannot be interrupted once started "
              "and its time grows about like the cube of the columns: raise the limit (0: none) or use another LP solver",
          lp.number_of_columns(), lp.number_of_rows, max_columns_);
    Linear_program_solution s;
    exact_objective = Exact_value();
    exact_primal.clear();
    internal::Lp_solve_clock clock(control_);
    if(!clock.keep_going()) {
      s.status = Lp_status::cancelled;
      s.message = "cancelled before QP_solver";
      return s;
    }
    const std::size_t n = lp.number_of_columns();
    // QP_solver's constraints: the original row of each (several per ranged row).
    CGAL::Quadratic_program<double> qp(CGAL::EQUAL, true, 0, false, 0);
    std::vector<std::size_t> row_of;
    std::vector<std::vector<int>> constraints_of_row(lp.number_of_rows);
    const double inf = Sparse_linear_program::infinity();
    for(std::size_t i = 0; i < lp.number_of_rows; ++i) {
      const double lo = lp.row_lower[i], up = lp.row_upper[i];
      auto add = [&](CGAL::Comparison_result r, double b) {
        const int k = int(row_of.size());
        qp.set_r(k, r);
        qp.set_b(k, b);
        row_of.push_back(i);
        constraints_of_row[i].push_back(k);
      };
      if(lo == up)
        add(CGAL::EQUAL, lo);
      else {
        if(lo != -inf) add(CGAL::LARGER, lo);
        if(up != inf) add(CGAL::SMALLER, up);
      }
    }
    for(std::size_t j = 0; j < n; ++j) {
      const int jj = int(j);
      qp.set_c(jj, lp.cost[j]);
      qp.set_l(jj, lp.col_lower[j] != -inf, lp.col_lower[j] != -inf ? lp.col_lower[j] : 0.0);
      qp.set_u(jj, lp.col_upper[j] != inf, lp.col_upper[j] != inf ? lp.col_upper[j] : 0.0);
      for(int k = lp.column_start[j]; k < lp.column_start[j + 1]; ++k)
        for(int c : constraints_of_row[std::size_t(lp.row_index[std::size_t(k)])])
          qp.set_a(jj, c, lp.value[std::size_t(k)]);
    }
    if(row_of.empty()) { // QP_solver needs a constraint: 0 <= 0 changes nothing
      qp.set_r(0, CGAL::SMALLER);
      qp.set_b(0, 0);
      if(n == 0)
        qp.set_c(0, 0);
    }
    try {
      const CGAL::Quadratic_program_solution<ET> sol = CGAL::solve_linear_program(qp, ET());
      s.iterations = long(sol.number_of_iterations());
      s.message = std::string("QP_solver: ") + status_name(sol.status());
      if(sol.is_infeasible()) {
        s.status = Lp_status::infeasible;
        return s;
      }
      if(sol.is_unbounded()) {
        s.status = Lp_status::unbounded;
        return s;
      }
      if(!sol.is_optimal()) {
        s.status = Lp_status::failed;
        return s;
      }
      s.status = Lp_status::optimal;
      s.exact = true;
      exact_objective = sol.objective_value();
      s.objective = CGAL::to_double(exact_objective);
      std::vector<char> basic(n, 0);
      for(auto it = sol.basic_variable_indices_begin(); it != sol.basic_variable_indices_end(); ++it)
        if(*it >= 0 && std::size_t(*it) < n)
          basic[std::size_t(*it)] = 1;
      s.primal.reserve(n);
      s.column_status.reserve(n);
      std::size_t j = 0;
      for(auto it = sol.variable_values_begin(); it != sol.variable_values_end() && j < n; ++it, ++j) {
        exact_primal.push_back(*it);
        const double x = CGAL::to_double(*it);
        s.primal.push_back(x);
        if(basic[j])
          s.column_status.push_back(Basis_status::basic);
        else if(lp.col_lower[j] == lp.col_upper[j])
          s.column_status.push_back(Basis_status::fixed);
        else if(*it == Exact_value(ET(lp.col_lower[j])) && lp.col_lower[j] != -inf)
          s.column_status.push_back(Basis_status::at_lower);
        else if(lp.col_upper[j] != inf && *it == Exact_value(ET(lp.col_upper[j])))
          s.column_status.push_back(Basis_status::at_upper);
        else
          s.column_status.push_back(Basis_status::free);
      }
      std::vector<Exact_value> dual(lp.number_of_rows, Exact_value(ET(0)));
      std::size_t k = 0;
      for(auto it = sol.optimality_certificate_begin(); it != sol.optimality_certificate_end() && k < row_of.size();
          ++it, ++k)
        dual[row_of[k]] -= *it; // QP_solver: cost + A^T lambda >= 0 on the reduced costs; ours: cost - A^T dual
      s.dual.reserve(lp.number_of_rows);
      for(const Exact_value& y : dual)
        s.dual.push_back(CGAL::to_double(y));
      if(!std::isfinite(s.objective)) {
        s.status = Lp_status::failed;
        s.message += "; the objective value is not finite in double";
      }
    } catch(const std::exception& e) {
      s = Linear_program_solution();
      exact_primal.clear();
      s.status = Lp_status::failed;
      s.message = std::string("QP_solver failed: ") + e.what();
    }
    return s;
  }

private:
  static const char* status_name(CGAL::Quadratic_program_status st)
  {
    switch(st) {
      case CGAL::QP_OPTIMAL: return "optimal";
      case CGAL::QP_INFEASIBLE: return "infeasible";
      case CGAL::QP_UNBOUNDED: return "unbounded";
      default: return "not solved";
    }
  }

  Lp_solve_control control_;
  std::size_t max_columns_ = 0;
};

} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_QP_SOLVER_LINEAR_PROGRAM_SOLVER_H
