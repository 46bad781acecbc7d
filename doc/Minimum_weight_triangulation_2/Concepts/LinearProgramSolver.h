/*!
\ingroup PkgMinimumWeightTriangulation2Ref
\cgalConcept

A linear-program solver minimises `c.x` subject to `row_lower <= A x <= row_upper` and
`col_lower <= x <= col_upper` for a `CGAL::Minimum_weight_triangulation_2::Sparse_linear_program` (column-major
sparse matrix) and returns a `CGAL::Minimum_weight_triangulation_2::Linear_program_solution`: the status, the
objective, the primal values, the row duals (sign convention `reduced_cost = c - A^T dual`), the basis status
of columns and rows, the iteration count, and whether the optimum was verified in rational arithmetic.

The MWT code never trusts the answer: it rounds nothing silently, recomputes reduced costs and a dual bound
in interval arithmetic, checks integrality, and validates the triangulation with exact predicates. A solver
with inaccurate duals therefore yields `optimal_uncertified`, never a wrong "certified" answer.

\cgalHasModel `CGAL::Minimum_weight_triangulation_2::CLP_linear_program_solver` (dual simplex; the default)
\cgalHasModel `CGAL::Minimum_weight_triangulation_2::GLPK_linear_program_solver` (primal simplex with presolve;
with `exact = true`, re-solved by `glp_exact` from the floating-point basis)
\cgalHasModel `CGAL::Minimum_weight_triangulation_2::QP_solver_linear_program_solver` (CGAL's exact `QP_solver`:
the exact optimum, primal values and duals of the program's double data, rounded once; no external library;
small programs)
\cgalHasModel `CGAL::Minimum_weight_triangulation_2::Mixed_integer_program_linear_program_solver` (any model of
CGAL's `MixedIntegerProgramTraits`, e.g. `CGAL::GLPK_mixed_integer_program_traits` or
`CGAL::SCIP_mixed_integer_program_traits`; primal values only, so its optima are validated but not certified;
its `solve_binary()` can resolve fractional optima)
*/
class LinearProgramSolver
{
public:
  /// A short name ("clp", "glpk", "exact", "qp-solver"), copied into `Mwt_result::solver`.
  const char* name() const;

  /// Solves `lp`. Never throws on an infeasible or unbounded program: reports it in the status.
  CGAL::Minimum_weight_triangulation_2::Linear_program_solution
  solve(const CGAL::Minimum_weight_triangulation_2::Sparse_linear_program& lp) const;
};
