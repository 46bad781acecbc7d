// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Model of LinearProgramSolver on GLPK: primal simplex with presolve, an optional exact verification
// (glp_exact, rational arithmetic, warm-started from the floating-point basis), and a MIP solve (glp_intopt)
// used to resolve fractional LP optima. Needs MDCS_HAS_GLPK and linking libglpk.

#ifndef CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_GLPK_LINEAR_PROGRAM_SOLVER_H
#define CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_GLPK_LINEAR_PROGRAM_SOLVER_H

#include <CGAL/Minimum_weight_triangulation_2/Linear_program.h>

#include <glpk.h>

#include <algorithm>
#include <chrono>
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
*/
class GLPK_linear_program_solver
{
public:
  explicit GLPK_linear_program_solver(bool exact = false, bool presolve = true, bool verbose = false)
    : exact_(exact), presolve_(presolve), verbose_(verbose) {}

  const char* name() const { return exact_ ? "exact" : "glpk"; }

  Linear_program_solution solve(const Sparse_linear_program& lp) const
  {
    Holder h(load(lp));
    glp_prob* P = h.get();
    Linear_program_solution s;
    glp_smcp parm;
    glp_init_smcp(&parm);
    parm.msg_lev = verbose_ ? GLP_MSG_ON : GLP_MSG_OFF;
    parm.presolve = presolve_ ? GLP_ON : GLP_OFF;
    int ret = glp_simplex(P, &parm);
    if(ret == 0 && exact_ && glp_get_status(P) == GLP_OPT) {
      glp_smcp eparm;
      glp_init_smcp(&eparm);
      eparm.msg_lev = verbose_ ? GLP_MSG_ON : GLP_MSG_OFF;
      ret = glp_exact(P, &eparm);
      s.exact = (ret == 0 && glp_get_status(P) == GLP_OPT);
    }
    s.iterations = glp_get_it_cnt(P);
    const int st = glp_get_status(P);
    s.message = "GLPK simplex returned " + std::to_string(ret) + ", status " + std::to_string(st);
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
    return s;
  }

  /*!
    Solves the program with all columns binary (branch and cut). `time_limit_s <= 0`: no limit.
    `keep_going` (may be empty) is asked at every branch-and-cut callback of GLPK with the elapsed fraction of
    the time limit (0 without a limit); when it returns false the search stops and the solution's message
    starts with "cancelled".
  */
  Linear_program_solution solve_binary(const Sparse_linear_program& lp, double time_limit_s = 0,
                                       std::function<bool(double)> keep_going = nullptr) const
  {
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
    if(time_limit_s > 0) parm.tm_lim = int(std::min(time_limit_s * 1000.0, 2.0e9));
    Callback_data data{keep_going, time_limit_s, std::chrono::steady_clock::now(), false};
    if(keep_going) {
      parm.cb_func = &callback;
      parm.cb_info = &data;
    }
    const int ret = glp_intopt(P, &parm);
    const int st = glp_mip_status(P);
    s.message = std::string(data.cancelled ? "cancelled; " : "") + "GLPK intopt returned " + std::to_string(ret) +
                ", status " + std::to_string(st);
    if(data.cancelled) { s.status = Lp_status::failed; return s; }
    if(st == GLP_NOFEAS) { s.status = Lp_status::infeasible; return s; }
    if(st != GLP_OPT && st != GLP_FEAS) {
      s.status = ret == GLP_ETMLIM ? Lp_status::iteration_limit : Lp_status::failed;
      return s;
    }
    s.status = st == GLP_OPT ? Lp_status::optimal : Lp_status::iteration_limit;
    s.objective = glp_mip_obj_val(P);
    s.primal.resize(nc);
    for(int j = 0; j < nc; ++j) s.primal[j] = glp_mip_col_val(P, j + 1);
    return s;
  }

  /// Whether a solution's message says that `keep_going` stopped the search.
  static bool was_cancelled(const Linear_program_solution& s) { return s.message.compare(0, 9, "cancelled") == 0; }

private:
  struct Callback_data
  {
    std::function<bool(double)> keep_going;
    double limit;
    std::chrono::steady_clock::time_point start;
    bool cancelled;
  };

  static void callback(glp_tree* tree, void* info)
  {
    Callback_data& d = *static_cast<Callback_data*>(info);
    if(d.cancelled) return;
    double fraction = 0;
    if(d.limit > 0)
      fraction = std::min(1.0, std::chrono::duration<double>(std::chrono::steady_clock::now() - d.start).count() / d.limit);
    if(!d.keep_going(fraction)) {
      d.cancelled = true;
      glp_ios_terminate(tree);
    }
  }

  struct Deleter { void operator()(glp_prob* p) const { glp_delete_prob(p); } };
  typedef std::unique_ptr<glp_prob, Deleter> Holder;

  static glp_prob* load(const Sparse_linear_program& lp)
  {
    lp.check();
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
};

} // namespace Minimum_weight_triangulation_2
} // namespace CGAL

#endif // CGAL_MINIMUM_WEIGHT_TRIANGULATION_2_GLPK_LINEAR_PROGRAM_SOLVER_H
