// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Model of LinearProgramSolver on GLPK: primal simplex (optionally with presolve), an optional exact
// verification (glp_exact, rational arithmetic, warm-started from the floating-point basis), and a MIP solve
// (glp_intopt) used to resolve fractional LP optima; all three with a time limit and a progress/cancel callback.
// Needs MDCS_HAS_GLPK and linking libglpk.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_GLPK_LINEAR_PROGRAM_SOLVER_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_GLPK_LINEAR_PROGRAM_SOLVER_H

#include <CGAL/Minimum_weight_triangulation_2/Linear_program.h>

#include <glpk.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <functional>
#include <string>
#include <memory>
#include <vector>

namespace CGAL {
namespace Minimum_weight_triangulation_2 {

/*!
  \brief LP solver on GLPK.
  \cgalModels `LinearProgramSolver`

  With `exact = true` the floating-point optimum is re-solved by `glp_exact` from its basis, so that the
  returned basis is optimal in rational arithmetic for the (double) data of the LP; `solution.exact` is set.
  `solve_binary()` solves the same program with every column restricted to {0, 1} by GLPK's branch and cut.

  Time limit and progress (`set_control()`): GLPK's simplex has no callback, so `solve()` runs it in slices of
  about a second (`tm_lim`), each resuming from the basis the previous one left, and asks the control's
  `keep_going` between slices; `glp_exact` is sliced the same way. A slice boundary costs one factorisation
  of the basis. Presolve (off by default: it removes nothing from the MWT programs, whose rows are equalities
  between triangles, and measured the same iteration counts with and without) cannot be resumed: with
  `presolve = true` the simplex runs in one call bounded by the time limit, without progress calls.
*/
class GLPK_linear_program_solver
{
public:
  explicit GLPK_linear_program_solver(bool exact = false, bool presolve = false, bool verbose = false)
    : exact_(exact), presolve_(presolve), verbose_(verbose) {}

  const char* name() const { return exact_ ? "exact" : "glpk"; }

  /// Time limit and progress of `solve()` (and of `solve_binary()` when it is given no limit of its own).
  void set_control(const Lp_solve_control& c) { control_ = c; }
  const Lp_solve_control& control() const { return control_; }

  Linear_program_solution solve(const Sparse_linear_program& lp) const
  {
    Holder h(load(lp));
    glp_prob* P = h.get();
    Linear_program_solution s;
    internal::Lp_solve_clock clock(control_);
    if(!clock.keep_going()) return stopped(s, Lp_status::cancelled, "cancelled before the simplex");
    glp_smcp parm;
    glp_init_smcp(&parm);
    parm.msg_lev = verbose_ ? GLP_MSG_ON : GLP_MSG_OFF;
    parm.presolve = presolve_ ? GLP_ON : GLP_OFF;
    // slices only when someone listens: each slice boundary costs a factorisation
    const bool sliced = !presolve_ && bool(control_.keep_going);
    int ret = run_sliced(clock, sliced, [&](int ms) {
      parm.tm_lim = ms;
      return glp_simplex(P, &parm);
    });
    s.iterations = glp_get_it_cnt(P);
    if(ret == slice_cancelled) return stopped(s, Lp_status::cancelled, "cancelled during the simplex");
    if(ret == GLP_ETMLIM) return stopped(s, Lp_status::time_limit, "time limit reached during the simplex");
    if(ret == 0 && exact_ && glp_get_status(P) == GLP_OPT) {
      glp_smcp eparm;
      glp_init_smcp(&eparm);
      eparm.msg_lev = verbose_ ? GLP_MSG_ON : GLP_MSG_OFF;
      ret = run_sliced(clock, sliced, [&](int ms) {
        eparm.tm_lim = ms;
        return glp_exact(P, &eparm);
      });
      s.iterations = glp_get_it_cnt(P);
      if(ret == slice_cancelled) return stopped(s, Lp_status::cancelled, "cancelled during the exact verification");
      if(ret == GLP_ETMLIM) return stopped(s, Lp_status::time_limit, "time limit reached during the exact verification");
      s.exact = (ret == 0 && glp_get_status(P) == GLP_OPT);
    }
    s.iterations = glp_get_it_cnt(P);
    const int st = glp_get_status(P);
    s.message = std::string("GLPK ") + (exact_ ? "simplex + exact" : "simplex") + " returned " + return_code_name(ret) +
                ", status " + status_name(st);
    if(ret != 0) { s.status = ret == GLP_EITLIM ? Lp_status::iteration_limit : Lp_status::failed; return s; }
    if(st == GLP_NOFEAS) { s.status = Lp_status::infeasible; return s; }
    if(st == GLP_UNBND) { s.status = Lp_status::unbounded; return s; }
    if(st != GLP_OPT) { s.status = Lp_status::failed; return s; }
    s.status = Lp_status::optimal;
    s.objective = glp_get_obj_val(P);
    const int nc = int(lp.number_of_columns()), nr = int(lp.number_of_rows);
    s.primal.resize(nc);
    s.column_status.resize(nc);
    for(int j = 0; j < nc; ++j) {
      s.primal[j] = glp_get_col_prim(P, j + 1);
      s.column_status[j] = convert(glp_get_col_stat(P, j + 1));
    }
    s.dual.resize(nr);
    s.row_status.resize(nr);
    for(int i = 0; i < nr; ++i) {
      s.dual[i] = glp_get_row_dual(P, i + 1);
      s.row_status[i] = convert(glp_get_row_stat(P, i + 1));
    }
    if(!std::isfinite(s.objective)) {   // never an "optimal" NaN
      s.status = Lp_status::failed;
      s.message += "; the objective value is not finite";
    }
    return s;
  }

  /*!
    Solves the program with all columns binary (branch and cut). `time_limit_s <= 0`: the control's limit
    (`set_control()`; none by default). `keep_going` (may be empty: the control's) is asked from GLPK's
    branch-and-cut callback, at most about once a second, with the elapsed fraction of the time limit (0 without
    a limit); when it returns false the search stops with status `Lp_status::cancelled` and a message starting
    with "cancelled". At the time limit the status is `Lp_status::time_limit`, with the best binary point found
    (if any) in `primal`.
  */
  Linear_program_solution solve_binary(const Sparse_linear_program& lp, double time_limit_s = 0,
                                       std::function<bool(double)> keep_going = nullptr) const
  {
    Lp_solve_control control = control_;
    if(time_limit_s > 0) control.time_limit = time_limit_s;
    if(keep_going) control.keep_going = keep_going;
    Holder h(load(lp));
    glp_prob* P = h.get();
    const int nc = int(lp.number_of_columns());
    for(int j = 1; j <= nc; ++j) glp_set_col_kind(P, j, GLP_BV);
    Linear_program_solution s;
    glp_iocp parm;
    glp_init_iocp(&parm);
    parm.msg_lev = verbose_ ? GLP_MSG_ON : GLP_MSG_OFF;
    parm.presolve = GLP_ON;
    parm.mip_gap = 0.0;
    if(control.time_limit > 0) parm.tm_lim = int(std::min(control.time_limit * 1000.0, 2.0e9));
    const internal::Lp_solve_clock clock(control);
    Callback_data data{&clock, report_interval(clock), 0.0, false};
    if(control.keep_going) {
      if(!clock.keep_going()) return stopped(s, Lp_status::cancelled, "cancelled before branch and cut");
      parm.cb_func = &callback;
      parm.cb_info = &data;
    }
    const int ret = glp_intopt(P, &parm);
    const int st = glp_mip_status(P);
    s.message = std::string(data.cancelled ? "cancelled; " : "") + "GLPK intopt returned " + return_code_name(ret) +
                ", status " + status_name(st);
    if(data.cancelled) { s.status = Lp_status::cancelled; return s; }
    if(st == GLP_NOFEAS) { s.status = Lp_status::infeasible; return s; }
    if(st != GLP_OPT && st != GLP_FEAS) {
      s.status = ret == GLP_ETMLIM ? Lp_status::time_limit : Lp_status::failed;
      return s;
    }
    s.status = st == GLP_OPT ? Lp_status::optimal : (ret == GLP_ETMLIM ? Lp_status::time_limit : Lp_status::failed);
    s.objective = glp_mip_obj_val(P);
    s.primal.resize(nc);
    for(int j = 0; j < nc; ++j) s.primal[j] = glp_mip_col_val(P, j + 1);
    if(!std::isfinite(s.objective)) {
      s.status = Lp_status::failed;
      s.message += "; the objective value is not finite";
    }
    return s;
  }

  /// Whether a solution's message says that `keep_going` stopped the search.
  static bool was_cancelled(const Linear_program_solution& s)
  {
    return s.status == Lp_status::cancelled || s.message.compare(0, 9, "cancelled") == 0;
  }

  /// GLPK's name of a return code of glp_simplex / glp_exact / glp_intopt ("0" for success).
  static std::string return_code_name(int ret)
  {
    switch(ret) {
      case 0: return "0";
      case GLP_EBADB: return "GLP_EBADB (invalid basis)";
      case GLP_ESING: return "GLP_ESING (singular basis matrix)";
      case GLP_ECOND: return "GLP_ECOND (ill-conditioned basis matrix)";
      case GLP_EBOUND: return "GLP_EBOUND (invalid bounds)";
      case GLP_EFAIL: return "GLP_EFAIL (solver failure)";
      case GLP_EITLIM: return "GLP_EITLIM (iteration limit)";
      case GLP_ETMLIM: return "GLP_ETMLIM (time limit)";
      case GLP_ENOPFS: return "GLP_ENOPFS (no primal feasible solution)";
      case GLP_ENODFS: return "GLP_ENODFS (no dual feasible solution)";
      case GLP_EROOT: return "GLP_EROOT (no optimal basis of the relaxation)";
      case GLP_ESTOP: return "GLP_ESTOP (stopped by the callback)";
      default: return std::to_string(ret);
    }
  }

  /// GLPK's name of a solution status.
  static std::string status_name(int st)
  {
    switch(st) {
      case GLP_UNDEF: return "GLP_UNDEF (undefined)";
      case GLP_FEAS: return "GLP_FEAS (feasible)";
      case GLP_INFEAS: return "GLP_INFEAS (infeasible)";
      case GLP_NOFEAS: return "GLP_NOFEAS (no feasible solution)";
      case GLP_OPT: return "GLP_OPT (optimal)";
      case GLP_UNBND: return "GLP_UNBND (unbounded)";
      default: return std::to_string(st);
    }
  }

private:
  static constexpr int slice_cancelled = -1;

  // Seconds between two calls of keep_going: a hundredth of the limit (at least 0.05 s), at most a second.
  static double report_interval(const internal::Lp_solve_clock& clock)
  {
    return clock.has_limit() ? std::max(0.05, std::min(1.0, clock.remaining() / 100)) : 1.0;
  }

  // Runs `step(tm_lim in ms)` until it returns something else than GLP_ETMLIM, in slices of report_interval()
  // when `sliced` (asking keep_going between slices), in one call bounded by the time limit otherwise. Returns
  // the last return code, GLP_ETMLIM when the time limit passed, slice_cancelled when keep_going said stop.
  template <class Step>
  static int run_sliced(const internal::Lp_solve_clock& clock, bool sliced, Step step)
  {
    const double interval = report_interval(clock);
    for(;;) {
      const double left = clock.remaining();
      if(left <= 0) return GLP_ETMLIM;
      const double slice = sliced ? std::min(left, interval) : left;
      const int ms = slice >= 2.0e6 ? INT_MAX : int(std::max(1.0, slice * 1000.0));   // INT_MAX: GLPK's "no limit"
      const int ret = step(ms);
      if(ret != GLP_ETMLIM) return ret;
      if(clock.expired() || !sliced) return GLP_ETMLIM;
      if(!clock.keep_going()) return slice_cancelled;
    }
  }

  static Linear_program_solution& stopped(Linear_program_solution& s, Lp_status st, const char* what)
  {
    s.status = st;
    s.message = std::string(what) + " (GLPK)";
    return s;
  }

  struct Callback_data
  {
    const internal::Lp_solve_clock* clock;
    double interval, next;
    bool cancelled;
  };

  static void callback(glp_tree* tree, void* info)
  {
    Callback_data& d = *static_cast<Callback_data*>(info);
    if(d.cancelled) return;
    const double now = d.clock->elapsed();
    if(now < d.next) return;   // GLPK calls back many times per node: ask the user about once per interval
    d.next = now + d.interval;
    if(!d.clock->keep_going()) {
      d.cancelled = true;
      glp_ios_terminate(tree);
    }
  }

  struct Deleter { void operator()(glp_prob* p) const { glp_delete_prob(p); } };
  typedef std::unique_ptr<glp_prob, Deleter> Holder;

  static glp_prob* load(const Sparse_linear_program& lp)
  {
    lp.check();   // GLPK aborts the process on a non-finite coefficient (glp_set_mat_col asserts |val| <= DBL_MAX)
    glp_prob* P = glp_create_prob();
    glp_set_obj_dir(P, GLP_MIN);
    const int nc = int(lp.number_of_columns()), nr = int(lp.number_of_rows);
    if(nr > 0) glp_add_rows(P, nr);
    if(nc > 0) glp_add_cols(P, nc);
    for(int i = 0; i < nr; ++i) glp_set_row_bnds(P, i + 1, bound_type(lp.row_lower[i], lp.row_upper[i]),
                                                 finite(lp.row_lower[i]), finite(lp.row_upper[i]));
    std::vector<int> ind;
    std::vector<double> val;
    for(int j = 0; j < nc; ++j) {
      glp_set_col_bnds(P, j + 1, bound_type(lp.col_lower[j], lp.col_upper[j]), finite(lp.col_lower[j]),
                       finite(lp.col_upper[j]));
      glp_set_obj_coef(P, j + 1, lp.cost[j]);
      ind.assign(1, 0);
      val.assign(1, 0.0);
      for(int k = lp.column_start[j]; k < lp.column_start[j + 1]; ++k) {
        ind.push_back(lp.row_index[k] + 1);
        val.push_back(lp.value[k]);
      }
      glp_set_mat_col(P, j + 1, int(ind.size()) - 1, ind.data(), val.data());
    }
    return P;
  }

  static double finite(double v) { return std::isfinite(v) ? v : 0.0; }

  static int bound_type(double lo, double up)
  {
    const bool fl = std::isfinite(lo), fu = std::isfinite(up);
    if(fl && fu) return lo == up ? GLP_FX : GLP_DB;
    if(fl) return GLP_LO;
    if(fu) return GLP_UP;
    return GLP_FR;
  }

  static Basis_status convert(int st)
  {
    switch(st) {
      case GLP_BS: return Basis_status::basic;
      case GLP_NL: return Basis_status::at_lower;
      case GLP_NU: return Basis_status::at_upper;
      case GLP_NF: return Basis_status::free;
      case GLP_NS: return Basis_status::fixed;
      default: return Basis_status::unknown;
    }
  }

  bool exact_, presolve_, verbose_;
  Lp_solve_control control_;
};

} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_GLPK_LINEAR_PROGRAM_SOLVER_H
