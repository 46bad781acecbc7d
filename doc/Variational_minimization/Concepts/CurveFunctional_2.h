/*!
\ingroup PkgVariationalMinimizationConcepts
\cgalConcept

The integrand G(f, f', x) of a univariate functional F(f) = ∫ G(f, f', x) dx minimised by
`CGAL::Variational_minimization::minimize_curve_functional_2()`. It must be non-negative and finite wherever
it is evaluated (in the box of the problem, for the slopes of the lines of the grid); a negative or NaN
value is reported as `std::domain_error` by `CGAL::Variational_minimization::edge_weight_2()`.

\cgalHasModel `CGAL::Variational_minimization::Surface_of_rotation_functional`
\cgalHasModel `CGAL::Variational_minimization::Arc_length_functional`
\cgalHasModel `CGAL::Variational_minimization::Density_weighted_length_functional`
\cgalHasModel `CGAL::Variational_minimization::Callable_functional`
*/
class CurveFunctional_2
{
public:
  /// Copy constructible.
  CurveFunctional_2(const CurveFunctional_2&);

  /// The value G(f, f', x) >= 0.
  double operator()(double f, double fp, double x) const;

  /*!
    Optional: the exact integral of G along the segment from (x0, y0) to (x1, y1), which lies on a line of
    slope `slope` (the end points may be rounded approximations of exact vertices: use `slope` for f').
    When present (detected by `has_closed_form_edge_weight`), it replaces adaptive quadrature.
  */
  double edge_weight(double x0, double y0, double x1, double y1, double slope) const;
};
