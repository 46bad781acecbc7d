// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Model of LinearProgramSolver on COIN-OR CLP (dual simplex). Needs MDCS_HAS_CLP and linking libClp.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_CLP_LINEAR_PROGRAM_SOLVER_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_CLP_LINEAR_PROGRAM_SOLVER_H

#include <CGAL/Minimum_weight_triangulation_2/Linear_program.h>

#include <coin/ClpEventHandler.hpp>
#include <coin/ClpSimplex.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {

/*!
  \brief LP solver on COIN-OR CLP's dual simplex (the fastest and most stable model measured here).
  \cgalModels `LinearProgramSolver`

  CLP's primal simplex with default settings was observed to stop at non-optimal fractional points on
  these LPs; the dual simplex is used by default. Callers still check the answer.

  Time limit and progress (`set_control()`): a CLP event handler looks at the clock after every iteration and
  asks the control's `keep_going` about once a second (a hundredth of the limit when that is shorter); it stops
  the simplex at the limit (`Lp_status::time_limit`) or when `keep_going` returns false (`Lp_status::cancelled`).
  CLP asserts (aborts the process) on objective coefficients of 1e25 or more: programs with a cost, a matrix
  entry or a finite bound of magnitude 1e20 or more are refused with `std::invalid_argument` (CLP reads larger
  bounds as infinite anyway).
*/
class CLP_linear_program_solver
{
public:
  enum Algorithm { dual_simplex, primal_simplex };

  explicit CLP_linear_program_solver(Algorithm a = dual_simplex, int log_level = 0)
    : algorithm_(a), log_level_(log_level) {}

  static const char* name() { return "clp"; }

  /// Time limit and progress of `solve()`.
  void set_control(const Lp_solve_control& c) { control_ = c; }
  const Lp_solve_control& control() const { return control_; }

  Linear_program_solution solve(const Sparse_linear_program& lp) const
  {
    lp.check();
    check_range(lp);
    Linear_program_solution s;
    const internal::Lp_solve_clock clock(control_);
    if(!clock.keep_going()) {
      s.status = Lp_status::cancelled;
      s.message = "cancelled before the simplex (CLP)";
      return s;
    }
    Stop_state stop{&clock, clock.has_limit() ? std::max(0.05, std::min(1.0, control_.time_limit / 100)) : 1.0, 0.0,
                    false, false};
    Event_handler handler(&stop);
    ClpSimplex model;
    model.setLogLevel(log_level_);
    const int nc = int(lp.number_of_columns()), nr = int(lp.number_of_rows);
    std::vector<CoinBigIndex> start(lp.column_start.begin(), lp.column_start.end());
    model.loadProblem(nc, nr, start.data(), lp.row_index.data(), lp.value.data(), lp.col_lower.data(),
                      lp.col_upper.data(), lp.cost.data(), lp.row_lower.data(), lp.row_upper.data());
    model.setPrimalTolerance(1e-9);
    model.setDualTolerance(1e-9);
    if(control_.keep_going || clock.has_limit()) model.passInEventHandler(&handler);   // CLP keeps a clone
    if(algorithm_ == dual_simplex) model.dual();
    else model.primal();
    s.iterations = model.numberIterations();
    if(stop.cancelled || stop.timed_out) {
      s.status = stop.cancelled ? Lp_status::cancelled : Lp_status::time_limit;
      s.message = std::string(stop.cancelled ? "cancelled" : "time limit reached") + " during the simplex (CLP, after " +
                  std::to_string(s.iterations) + " iterations)";
      return s;
    }
    switch(model.status()) {
      case 0: s.status = Lp_status::optimal; break;
      case 1: s.status = Lp_status::infeasible; break;
      case 2: s.status = Lp_status::unbounded; break;
      case 3: s.status = Lp_status::iteration_limit; break;
      default: s.status = Lp_status::failed; break;
    }
    s.message = std::string("CLP status ") + std::to_string(model.status()) + " (" + status_name(model.status()) +
                "), secondary status " + std::to_string(model.secondaryStatus());
    if(s.status != Lp_status::optimal) return s;
    s.objective = model.objectiveValue();
    if(!std::isfinite(s.objective)) {   // never an "optimal" NaN
      s.status = Lp_status::failed;
      s.message += "; the objective value is not finite";
      return s;
    }
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
  // Shared by the handler and the clone CLP makes of it.
  struct Stop_state
  {
    const internal::Lp_solve_clock* clock;
    double interval, next;
    bool timed_out, cancelled;
  };

  class Event_handler : public ClpEventHandler
  {
  public:
    explicit Event_handler(Stop_state* s) : state_(s) {}
    Event_handler(const Event_handler& o) : ClpEventHandler(o), state_(o.state_) {}
    ClpEventHandler* clone() const override { return new Event_handler(*this); }

    int event(Event e) override
    {
      if(e != endOfIteration) return -1;
      Stop_state& s = *state_;
      if(s.clock->expired()) { s.timed_out = true; return 5; }   // any value >= 0 stops the simplex
      const double now = s.clock->elapsed();
      if(now < s.next) return -1;
      s.next = now + s.interval;
      if(!s.clock->keep_going()) { s.cancelled = true; return 5; }
      return -1;
    }

  private:
    Stop_state* state_;
  };

  static void check_range(const Sparse_linear_program& lp)
  {
    const double big = 1e20;
    auto bad = [big](double v) { return std::isfinite(v) && std::abs(v) >= big; };
    for(double c : lp.cost)
      if(bad(c)) throw std::invalid_argument("CLP_linear_program_solver: a cost of magnitude >= 1e20 (CLP's limit)");
    for(double v : lp.value)
      if(bad(v)) throw std::invalid_argument("CLP_linear_program_solver: a matrix entry of magnitude >= 1e20 (CLP's limit)");
    for(const auto* b : {&lp.col_lower, &lp.col_upper, &lp.row_lower, &lp.row_upper})
      for(double v : *b)
        if(bad(v)) throw std::invalid_argument("CLP_linear_program_solver: a finite bound of magnitude >= 1e20 (CLP reads it as infinite)");
  }

  static const char* status_name(int st)
  {
    switch(st) {
      case 0: return "optimal";
      case 1: return "primal infeasible";
      case 2: return "dual infeasible";
      case 3: return "stopped on iterations or time";
      case 4: return "stopped due to errors";
      case 5: return "stopped by the event handler";
      default: return "unknown";
    }
  }

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
  Lp_solve_control control_;
};

} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_CLP_LINEAR_PROGRAM_SOLVER_H
