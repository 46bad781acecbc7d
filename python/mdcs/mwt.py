# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Minimum weight triangulations of point sets (the C++ package Minimum_weight_triangulation_2).

>>> import numpy as np, mdcs
>>> angles = 2 * np.pi * np.arange(13) / 13
>>> wheel = np.vstack([[0, 0], np.c_[np.cos(angles), np.sin(angles)]])
>>> r = mdcs.mwt.minimum_weight_triangulation(wheel)
>>> r.status, round(r.weight, 4)
('optimal_after_branch_and_bound', 18.7989)

The triangle-based linear program (a variable per empty triangle) is solved by an LP solver; an integral optimum
is certified by a dual bound (``status == "certified_optimal"``), a fractional one is resolved by branch and bound
(``"optimal_after_branch_and_bound"``) or reported with its lower bound (``"fractional_bound_only"``).
"""

import dataclasses

import numpy as np

from . import _mdcs
from ._progress import progress_callback

__all__ = ["minimum_weight_triangulation", "MwtResult", "SOLVERS", "METRICS", "QP_MAX_COLUMNS"]

#: LP solvers built into this module ("auto" picks CLP, else GLPK; "exact" is GLPK's simplex verified in rational
#: arithmetic; "qp" is CGAL's exact QP_solver, for small inputs: see ``qp_max_columns``).
SOLVERS = _mdcs.mwt.solvers
#: The default ``qp_max_columns`` (the C++ ``Mwt_options::qp_max_columns``).
QP_MAX_COLUMNS = _mdcs.mwt.qp_max_columns_default
#: Edge lengths: Euclidean, Manhattan, maximum norm.
METRICS = ("L2", "L1", "Linf")


@dataclasses.dataclass
class MwtResult:
    """The result of :func:`minimum_weight_triangulation`.

    Attributes:
        triangles: ``(k, 3)`` int64 indices into the points, counter-clockwise (empty when there is no
            triangulation, e.g. ``status == "fractional_bound_only"``).
        weight: the sum of the edge lengths (NaN without triangulation).
        status: ``"certified_optimal"`` (integral LP optimum, validated, proven optimal by a dual bound within
            ``certificate_tolerance``), ``"optimal_after_branch_and_bound"`` (fractional LP optimum resolved by
            GLPK's branch and cut), ``"optimal_uncertified"``, ``"fractional_bound_only"`` or ``"solver_failed"``.
        lower_bound: a rigorous lower bound of the MWT weight.
        lp_objective, lp_integral, lp_exact: the LP optimum, whether it is integral, whether it is exact (verified
            in rational arithmetic, or solved in it: ``solver == "qp-solver"``).
        certificate_exact, certificate_support: the certificate holds without tolerance (see the C++ manual).
        solver, message: the LP solver used and its message.
        statistics: sizes and timings of the stages (a dict).
    """

    triangles: np.ndarray
    weight: float
    status: str
    lower_bound: float
    lp_objective: float
    lp_integral: bool
    lp_exact: bool
    certificate_exact: bool
    certificate_support: int
    solver: str
    message: str
    statistics: dict

    @property
    def has_triangulation(self):
        return len(self.triangles) > 0

    @property
    def edges(self):
        """The ``(e, 2)`` undirected edges of the triangulation, sorted."""
        t = self.triangles
        e = np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), axis=1)
        return np.unique(e, axis=0)


def minimum_weight_triangulation(points, *, metric="L2", solver="auto", pruning="auto", resolve_fractional=True,
                                 branch_and_bound_time_limit=300.0, certificate_tolerance=1e-9,
                                 integrality_tolerance=1e-6, validate=True, use_lmt_skeleton=False,
                                 exact_support_certificate=True, threads=0, progress="auto", qp_max_columns=QP_MAX_COLUMNS):
    """The minimum weight triangulation of a point set.

    Parameters:
        points: ``(n, 2)`` finite coordinates (n >= 3, no duplicates, not all collinear).
        metric: ``"L2"`` (default), ``"L1"`` or ``"Linf"``: the length of an edge.
        solver: one of :data:`SOLVERS`: ``"auto"``, ``"clp"``, ``"glpk"``, ``"exact"`` (GLPK, optimum verified in
            rational arithmetic), ``"qp"`` (CGAL's exact ``QP_solver``: the exact LP optimum, ``lp_exact`` true;
            slow, small inputs only). A fractional optimum goes to GLPK's branch and bound with every solver.
        pruning: ``"auto"`` (the diamond test for L2, none otherwise), ``"none"``, ``"diamond"`` (L2 only).
        resolve_fractional: resolve a fractional LP optimum by branch and bound (GLPK).
        branch_and_bound_time_limit: seconds for it (0: none); when it runs out the status is
            ``"fractional_bound_only"``.
        certificate_tolerance: relative gap accepted by the certificate.
        integrality_tolerance: how far from 0/1 an LP value may be and count as integral.
        validate: check the triangulation with exact predicates.
        use_lmt_skeleton: L2 only: the LMT-skeleton and exact dynamic programs on its faces, the LP on the rest.
        exact_support_certificate: try the exact certificate on the near-zero reduced-cost support.
        threads: threads of the candidate edges, empty triangles, diamond test, LMT-skeleton and face dynamic
            programs (0, the default: every core; 1: sequential; the LP stays sequential). The triangulation,
            weight and certificate are identical for every thread count.
        progress: ``"auto"``, ``True``, ``False``/``None`` or a callable (see :mod:`mdcs._progress`).
        qp_max_columns: with ``solver="qp"``: the largest LP (columns, i.e. empty triangles) it is given; a larger
            one raises ``ValueError`` before the solve (0: no limit). CGAL's ``QP_solver`` cannot be interrupted
            once started (neither ``progress`` nor Ctrl-C stops it; they are asked just before), and its time grows
            about like the cube of the columns: 550 columns took up to 31 s, the default :data:`QP_MAX_COLUMNS`
            up to about 45 s (extrapolated; the C++ manual has the measurements).

    Returns:
        :class:`MwtResult`. Bad input raises ``ValueError`` naming the problem (duplicate points, collinear sets,
        NaN, wrong shape), and so does an LP over ``qp_max_columns`` with ``solver="qp"`` (the message gives its
        size).
    """
    with progress_callback(progress, "mwt") as callback:
        d = _mdcs.mwt.minimum_weight_triangulation(points, metric, pruning, solver, bool(resolve_fractional),
                                                   float(branch_and_bound_time_limit), float(certificate_tolerance),
                                                   float(integrality_tolerance), bool(validate),
                                                   bool(use_lmt_skeleton), bool(exact_support_certificate), threads,
                                                   callback, qp_max_columns)
    return MwtResult(**d)
