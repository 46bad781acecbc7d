// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A sparse linear program in column-major form and the solution record returned by the models of the
// `LinearProgramSolver` concept (see doc/Minimum_weight_triangulation_2/Concepts/LinearProgramSolver.h).

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_LINEAR_PROGRAM_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_LINEAR_PROGRAM_H

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {

/*!
  \brief A minimisation LP `min c.x  s.t.  row_lower <= A x <= row_upper, col_lower <= x <= col_upper`.

  The matrix `A` is stored column by column: the entries of column `j` are
  `row_index[k], value[k]` for `k` in `[column_start[j], column_start[j+1])`.
  Infinite bounds are `infinity()`.
*/
struct Sparse_linear_program
{
  static double infinity() { return std::numeric_limits<double>::infinity(); }

  std::size_t number_of_rows = 0;
  std::vector<double> cost, col_lower, col_upper;      ///< one per column
  std::vector<double> row_lower, row_upper;            ///< one per row
  std::vector<int> column_start{0};                    ///< size: number of columns + 1
  std::vector<int> row_index;
  std::vector<double> value;

  std::size_t number_of_columns() const { return cost.size(); }
  std::size_t number_of_nonzeros() const { return value.size(); }

  /// Appends a column; `rows` and `coefficients` have the same length.
  int add_column(double c, double lower, double upper, const int* rows, const double* coefficients, int k)
  {
    cost.push_back(c);
    col_lower.push_back(lower);
    col_upper.push_back(upper);
    for(int i = 0; i < k; ++i) {
      row_index.push_back(rows[i]);
      value.push_back(coefficients[i]);
    }
    column_start.push_back(int(row_index.size()));
    return int(cost.size()) - 1;
  }

  /// Appends a row with bounds; its entries come with the columns.
  int add_row(double lower, double upper)
  {
    row_lower.push_back(lower);
    row_upper.push_back(upper);
    return int(number_of_rows++);
  }

  /// Throws std::invalid_argument when sizes or indices are inconsistent, or a number is unusable: a cost or a
  /// matrix entry that is not finite, a NaN bound, a lower bound above its upper bound, or an infinite bound on
  /// the wrong side (-inf upper, +inf lower). Solvers call it first: such a program would trip CLP's and GLPK's
  /// internal assertions (process abort) or come back with a NaN objective.
  void check() const
  {
    const std::size_t n = number_of_columns();
    if(col_lower.size() != n || col_upper.size() != n || column_start.size() != n + 1)
      throw std::invalid_argument("Sparse_linear_program: column arrays have different sizes");
    if(row_lower.size() != number_of_rows || row_upper.size() != number_of_rows)
      throw std::invalid_argument("Sparse_linear_program: row arrays have different sizes");
    if(row_index.size() != value.size() || column_start.front() != 0 ||
       std::size_t(column_start.back()) != row_index.size())
      throw std::invalid_argument("Sparse_linear_program: column_start does not match the entries");
    for(std::size_t j = 0; j < n; ++j)
      if(column_start[j + 1] < column_start[j])
        throw std::invalid_argument("Sparse_linear_program: column_start decreases at column " + std::to_string(j));
    if(number_of_rows > std::size_t((std::numeric_limits<int>::max)()) - 1 ||
       n > std::size_t((std::numeric_limits<int>::max)()) - 1)
      throw std::invalid_argument("Sparse_linear_program: too many rows or columns for a 32-bit solver index");
    for(int r : row_index)
      if(r < 0 || std::size_t(r) >= number_of_rows)
        throw std::invalid_argument("Sparse_linear_program: row index out of range");
    for(std::size_t j = 0; j < n; ++j) {
      if(!std::isfinite(cost[j]))
        throw std::invalid_argument("Sparse_linear_program: the cost of column " + std::to_string(j) + " is not finite");
      check_bounds(col_lower[j], col_upper[j], "column", j);
    }
    for(std::size_t i = 0; i < number_of_rows; ++i) check_bounds(row_lower[i], row_upper[i], "row", i);
    for(std::size_t k = 0; k < value.size(); ++k)
      if(!std::isfinite(value[k]))
        throw std::invalid_argument("Sparse_linear_program: a matrix entry of row " + std::to_string(row_index[k]) +
                                    " is not finite");
  }

private:
  static void check_bounds(double lo, double up, const char* what, std::size_t i)
  {
    if(std::isnan(lo) || std::isnan(up) || lo == infinity() || up == -infinity() || lo > up)
      throw std::invalid_argument(std::string("Sparse_linear_program: the bounds of ") + what + " " + std::to_string(i) +
                                  " are not a non-empty interval [lower, upper] (lower < +inf, upper > -inf, no NaN)");
  }
};

/*!
  Status of an LP (or MIP) solve. `time_limit`: the solver stopped at the time limit of its `Lp_solve_control`
  (a MIP may still return its best feasible point then); `cancelled`: the control's `keep_going` returned false.
*/
enum class Lp_status { optimal, infeasible, unbounded, iteration_limit, failed, time_limit, cancelled };

inline const char* to_string(Lp_status s)
{
  switch(s) {
    case Lp_status::optimal: return "optimal";
    case Lp_status::infeasible: return "infeasible";
    case Lp_status::unbounded: return "unbounded";
    case Lp_status::iteration_limit: return "iteration_limit";
    case Lp_status::time_limit: return "time_limit";
    case Lp_status::cancelled: return "cancelled";
    default: return "failed";
  }
}

/*!
  \brief Time limit and progress of one solve, given to the built-in solver models (`set_control()`).

  `keep_going(fraction)` (may be empty) is called about once a second while the solver runs (CLP: between
  iterations; GLPK: between slices of the simplex, see `GLPK_linear_program_solver`), with the elapsed part of the
  time limit as fraction (0 without a limit: the call is then a heartbeat only). When it returns false the solver
  stops and reports `Lp_status::cancelled`; when the time limit passes it stops and reports `Lp_status::time_limit`.
*/
struct Lp_solve_control
{
  double time_limit = 0;                   ///< seconds (wall clock); 0 or less: no limit
  std::function<bool(double)> keep_going;  ///< may be empty
};

namespace internal {

// The clock of a solve with an Lp_solve_control: elapsed time, the fraction of the limit, whether it has passed.
class Lp_solve_clock
{
public:
  explicit Lp_solve_clock(const Lp_solve_control& c) : control_(c), start_(std::chrono::steady_clock::now()) {}
  double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  bool has_limit() const { return control_.time_limit > 0; }
  /// Seconds left (a large number without a limit).
  double remaining() const { return has_limit() ? control_.time_limit - elapsed() : 1e30; }
  bool expired() const { return has_limit() && elapsed() >= control_.time_limit; }
  double fraction() const { return has_limit() ? (std::min)(1.0, elapsed() / control_.time_limit) : 0.0; }
  /// Asks `keep_going`; true when there is none.
  bool keep_going() const { return !control_.keep_going || control_.keep_going(fraction()); }

private:
  const Lp_solve_control& control_;
  std::chrono::steady_clock::time_point start_;
};

} // namespace internal

/// Basis status of a column or a row (the auxiliary variable `A_i x`).
enum class Basis_status { basic, at_lower, at_upper, free, fixed, unknown };

/*!
  \brief What a `LinearProgramSolver` returns.

  Sign convention of the duals: `reduced_cost[j] = cost[j] - sum_i A_ij dual[i]` (minimisation).
  Callers never trust these numbers blindly: the MWT code recomputes reduced costs and bounds itself.
*/
struct Linear_program_solution
{
  Lp_status status = Lp_status::failed;
  double objective = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> primal;                 ///< per column
  std::vector<double> dual;                   ///< per row (empty after a MIP solve)
  std::vector<Basis_status> column_status;    ///< per column (may be empty)
  std::vector<Basis_status> row_status;       ///< per row (may be empty)
  long iterations = 0;
  bool exact = false;                         ///< true when the optimum was verified in rational arithmetic
  std::string message;
};

/*!
  Whether `s` is usable as an optimum of `lp`: status `optimal`, a finite objective, one finite primal value per
  column, and (when given) one dual per row (non-finite duals only cost the certificate: the bounds skip them). Otherwise returns false and says why in `why`.
  The MWT code calls it on every solver's answer before anything of it becomes a result.
*/
inline bool is_usable_optimum(const Sparse_linear_program& lp, const Linear_program_solution& s, std::string* why = nullptr)
{
  auto fail = [why](const std::string& w) {
    if(why) *why = w;
    return false;
  };
  if(s.status != Lp_status::optimal) return fail(std::string("status ") + to_string(s.status));
  if(!std::isfinite(s.objective)) return fail("the objective value is not finite");
  if(s.primal.size() != lp.number_of_columns())
    return fail(std::to_string(s.primal.size()) + " primal values for " + std::to_string(lp.number_of_columns()) + " columns");
  for(std::size_t j = 0; j < s.primal.size(); ++j)
    if(!std::isfinite(s.primal[j])) return fail("the primal value of column " + std::to_string(j) + " is not finite");
  if(!s.dual.empty() && s.dual.size() != lp.number_of_rows)
    return fail(std::to_string(s.dual.size()) + " dual values for " + std::to_string(lp.number_of_rows) + " rows");
  return true;
}

} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_LINEAR_PROGRAM_H
