// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A sparse linear program in column-major form and the solution record returned by the models of the
// `LinearProgramSolver` concept (see doc/Minimum_weight_triangulation_2/Concepts/LinearProgramSolver.h).

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_LINEAR_PROGRAM_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_LINEAR_PROGRAM_H

#include <cstddef>
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

  /// Throws std::invalid_argument when sizes or indices are inconsistent.
  void check() const
  {
    const std::size_t n = number_of_columns();
    if(col_lower.size() != n || col_upper.size() != n || column_start.size() != n + 1)
      throw std::invalid_argument("Sparse_linear_program: column arrays have different sizes");
    if(row_lower.size() != number_of_rows || row_upper.size() != number_of_rows)
      throw std::invalid_argument("Sparse_linear_program: row arrays have different sizes");
    for(int r : row_index)
      if(r < 0 || std::size_t(r) >= number_of_rows)
        throw std::invalid_argument("Sparse_linear_program: row index out of range");
  }
};

/// Status of an LP (or MIP) solve.
enum class Lp_status { optimal, infeasible, unbounded, iteration_limit, failed };

inline const char* to_string(Lp_status s)
{
  switch(s) {
    case Lp_status::optimal: return "optimal";
    case Lp_status::infeasible: return "infeasible";
    case Lp_status::unbounded: return "unbounded";
    case Lp_status::iteration_limit: return "iteration_limit";
    default: return "failed";
  }
}

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

} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_LINEAR_PROGRAM_H
