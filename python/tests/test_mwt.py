# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""mdcs.mwt against the C++ suite's oracles: the thesis's 13-wheel (LP 18.7636 fractional, MWT 18.7989), the
Euler count of a triangulation, and the Delaunay triangulation as an upper bound (scipy.spatial)."""

import numpy as np
import pytest
import scipy.spatial

import mdcs


def wheel(k):
    a = 2 * np.pi * np.arange(k) / k
    return np.vstack([[0, 0], np.c_[np.cos(a), np.sin(a)]])


def weight(points, triangles, metric="L2"):
    e = np.sort(np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]]), axis=1)
    e = np.unique(e, axis=0)
    d = points[e[:, 0]] - points[e[:, 1]]
    if metric == "L1":
        return np.abs(d).sum()
    if metric == "Linf":
        return np.abs(d).max(axis=1).sum()
    return np.linalg.norm(d, axis=1).sum()


def test_the_13_wheel():
    p = wheel(13)
    lp_only = mdcs.mwt.minimum_weight_triangulation(p, resolve_fractional=False, progress=False)
    assert lp_only.status == "fractional_bound_only" and not lp_only.lp_integral
    assert lp_only.lp_objective == pytest.approx(18.7636, abs=5e-5)
    assert not lp_only.has_triangulation
    r = mdcs.mwt.minimum_weight_triangulation(p, progress=False)
    assert r.status == "optimal_after_branch_and_bound"
    assert r.weight == pytest.approx(18.7989, abs=5e-5)
    assert r.lower_bound <= r.weight
    assert r.weight == pytest.approx(weight(p, r.triangles), rel=1e-12)
    assert r.triangles.shape == (13, 3) and r.triangles.dtype == np.int64


# 60 points: "qp" (CGAL's exact QP_solver, minutes at this size) has its own small tests below
@pytest.mark.parametrize("solver", [s for s in mdcs.mwt.SOLVERS if s not in ("exact", "qp")])
def test_random_points_every_solver(solver):
    rng = np.random.default_rng(7)
    p = rng.random((60, 2))
    r = mdcs.mwt.minimum_weight_triangulation(p, solver=solver, progress=False)
    assert r.status in ("certified_optimal", "optimal_after_branch_and_bound")
    hull = scipy.spatial.ConvexHull(p)
    assert len(r.triangles) == 2 * len(p) - len(hull.vertices) - 2  # Euler's count
    # counter-clockwise triangles covering the hull exactly
    a, b, c = p[r.triangles[:, 0]], p[r.triangles[:, 1]], p[r.triangles[:, 2]]
    area = 0.5 * ((b - a)[:, 0] * (c - a)[:, 1] - (b - a)[:, 1] * (c - a)[:, 0])
    assert np.all(area > 0) and area.sum() == pytest.approx(hull.volume, rel=1e-12)
    assert r.weight == pytest.approx(weight(p, r.triangles), rel=1e-12)
    delaunay = scipy.spatial.Delaunay(p)
    assert r.weight <= weight(p, delaunay.simplices) + 1e-12  # the MWT is never heavier than Delaunay
    assert r.lower_bound <= r.weight + 1e-9


def test_metrics_and_the_lmt_skeleton():
    rng = np.random.default_rng(3)
    p = rng.random((40, 2))
    l2 = mdcs.mwt.minimum_weight_triangulation(p, progress=False)
    lmt = mdcs.mwt.minimum_weight_triangulation(p, use_lmt_skeleton=True, progress=False)
    assert lmt.weight == pytest.approx(l2.weight, rel=1e-12)
    for metric in ("L1", "Linf"):
        r = mdcs.mwt.minimum_weight_triangulation(p, metric=metric, progress=False)
        assert r.has_triangulation
        assert r.weight == pytest.approx(weight(p, r.triangles, metric), rel=1e-12)
        # the L2 optimum is a triangulation too: never lighter in this metric than the metric's own optimum
        assert r.weight <= weight(p, l2.triangles, metric) + 1e-12
    assert len(l2.edges) == 3 * len(p) - len(scipy.spatial.ConvexHull(p).vertices) - 3


def test_the_same_triangulation_for_every_thread_count():
    p = np.random.default_rng(11).random((3000, 2))
    # the LMT-skeleton pipeline on 3000 points, the LP alone on 300 (its LP is the slow part, and sequential)
    for points, lmt in ((p, True), (p[:300], False)):
        results = [mdcs.mwt.minimum_weight_triangulation(points, use_lmt_skeleton=lmt, threads=t, progress=False)
                   for t in (1, 2, 3, 8, 0)]
        for r in results:
            assert r.status == "certified_optimal"
            assert np.array_equal(r.triangles, results[0].triangles) and r.weight == results[0].weight
    for bad in (-1, 2000, 2.0):
        with pytest.raises(ValueError, match="threads"):
            mdcs.mwt.minimum_weight_triangulation(p[:10], threads=bad, progress=False)


def canonical_triangles(triangles):
    """Each triangle rotated to start at its smallest index, the rows sorted."""
    t = np.array([np.roll(row, -int(np.argmin(row))) for row in triangles])
    return t[np.lexsort(t.T[::-1])]


def test_the_qp_solver_equals_exact_glpk():
    assert "qp" in mdcs.mwt.SOLVERS
    rng = np.random.default_rng(11)
    for p in (rng.random((12, 2)), wheel(13)):  # an integral and a fractional LP optimum
        exact = mdcs.mwt.minimum_weight_triangulation(p, solver="exact", progress=False)
        qp = mdcs.mwt.minimum_weight_triangulation(p, solver="qp", progress=False)
        assert qp.solver == "qp-solver" and qp.lp_exact
        assert qp.status == exact.status
        assert qp.lp_objective == pytest.approx(exact.lp_objective, rel=1e-14)
        assert qp.weight == pytest.approx(exact.weight, rel=1e-14)
        assert np.array_equal(canonical_triangles(qp.triangles), canonical_triangles(exact.triangles))
        assert qp.weight == pytest.approx(weight(p, qp.triangles), rel=1e-12)
    assert qp.status == "optimal_after_branch_and_bound" and not qp.lp_integral  # the 13-wheel


def test_the_qp_solver_column_limit():
    p = np.random.default_rng(12).random((12, 2))
    r = mdcs.mwt.minimum_weight_triangulation(p, solver="qp", qp_max_columns=0, progress=False)  # 0: no limit
    columns = r.statistics["lp_columns"]
    at_limit = mdcs.mwt.minimum_weight_triangulation(p, solver="qp", qp_max_columns=columns, progress=False)
    assert at_limit.weight == r.weight
    with pytest.raises(ValueError, match=f"has {columns} columns.*more than the limit of {columns - 1} .*qp_max_columns"):
        mdcs.mwt.minimum_weight_triangulation(p, solver="qp", qp_max_columns=columns - 1, progress=False)
    for bad in (-1, 2.5, True, "10"):
        with pytest.raises(ValueError, match="qp_max_columns must be an integer"):
            mdcs.mwt.minimum_weight_triangulation(p, solver="qp", qp_max_columns=bad, progress=False)
