# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Globally minimal discrete curves and surfaces of variational problems (the C++ package Variational_minimization).

Curves (univariate problems): minimise ``F(f) = integral_a^b G(f, f', x) dx`` over functions f on [a, b] with
values in [ymin, ymax] and fixed (``left=A``) or free (``left=(A0, A1)``) end values. The rectangle is cut by a
line arrangement; every arrangement edge weighs the integral of G along it; the minimum cut of the directed dual
graph is the minimal curve among all functions made of arrangement edges, a global optimum.

>>> import mdcs
>>> c = mdcs.variational.minimal_curve("surface_of_rotation", interval=(-1, 1), value_range=(0, 2), left=2, right=2,
...                                     lines=400, seed=1)
>>> exact = mdcs.variational.surface_of_rotation_minimum(2.0)["energy"]
>>> bool(abs(c.energy - exact) / exact < 0.01)
True

Surfaces (bivariate problems): minimise ``F(f) = double integral over Omega of G(f, f_x, f_y, x, y)`` over functions
on a rectangle or a simple polygon with a boundary condition ``f = g`` (or ``g0 <= f <= g1``) on its boundary, by
a minimum cut of the dual graph of a plane arrangement: of random planes, or of the regular plane grid
(``plane_grid=n``, rectangles only).

Built-in functionals are named (curves: ``"surface_of_rotation"``, ``"arc_length"``; surfaces: ``"area"``,
``"membrane"``) and use their closed-form integrals. A user functional is a vectorised NumPy function:
``G(f, fp, x)`` for curves, ``G(f, fx, fy, x, y)`` for surfaces, called with arrays of equal shape and returning an
array of values >= 0 (``inf`` allowed to forbid positions or slopes). Its integrals are computed by quadrature in
batches: adaptive Gauss-Legendre along the curve edges, the degree-5 seven-point rule on the surface facets
(subdivided ``quadrature_level`` times, as the C++ code does for functionals without a closed form).
"""

import dataclasses

import numpy as np

from . import _mdcs
from ._progress import progress_callback

__all__ = ["minimal_curve", "minimal_surface", "MinimalCurve", "MinimalSurface", "surface_of_rotation_minimum",
           "CURVE_FUNCTIONALS", "SURFACE_FUNCTIONALS"]

_core = _mdcs.variational

CURVE_FUNCTIONALS = ("surface_of_rotation", "arc_length")
SURFACE_FUNCTIONALS = ("area", "membrane")
_PLANE_GRID_MAX = _core.regular_surface_max_steps  # the largest order n of the regular plane grid (63)


def surface_of_rotation_minimum(R, h=1.0):
    """The exact global minimum of the surface-of-rotation problem between rings of radius ``R`` at ``x = -h`` and
    ``x = h``: a dict with ``energy``, ``branch`` (``"catenoid"`` or ``"goldschmidt"``), ``catenoid_energy`` and
    ``goldschmidt_energy`` (two discs and the axis)."""
    return _core.surface_of_rotation_minimum(float(R), float(h))


@dataclasses.dataclass
class MinimalCurve:
    """The globally minimal discrete curve of :func:`minimal_curve`.

    Attributes:
        feasible: whether a function made of arrangement edges meets the end conditions (otherwise the polyline
            is empty and the energy ``inf``).
        energy: the sum of the curve's edge weights (the discrete energy).
        solver_value: the min-cut value (equal to ``energy`` up to rounding).
        polyline: ``(k, 2)`` the curve's vertices from left to right.
        edges: the arrangement edges of the curve.
        weights: the weight of every arrangement edge.
        arrangement: counts of the line arrangement (vertices, edges, faces).
    """

    feasible: bool
    energy: float
    solver_value: float
    polyline: np.ndarray
    edges: np.ndarray
    weights: np.ndarray
    arrangement: dict


@dataclasses.dataclass
class MinimalSurface:
    """The globally minimal discrete surface of :func:`minimal_surface`.

    Attributes:
        feasible: whether a function made of arrangement facets meets the boundary condition.
        energy: the sum of the surface's facet weights (the discrete energy).
        solver_value: the min-cut value (equal to ``energy`` up to rounding).
        projected_area: the signed area of the surface's projection (the domain's area when single-valued).
        points, triangles: the triangulated surface, ``(n, 3)`` and ``(m, 3)``, triangles oriented upwards.
        facets, planes: the arrangement facets of the surface and the planes they lie on.
        arrangement: counts of the plane arrangement (cells, facets, vertices, planes: the 6 walls of the box
            included).
    """

    feasible: bool
    energy: float
    solver_value: float
    projected_area: float
    points: np.ndarray
    triangles: np.ndarray
    facets: np.ndarray
    planes: np.ndarray
    arrangement: dict


def _checked_values(values, shape, what):
    values = np.asarray(values, dtype=np.float64)
    if values.shape != shape:
        try:
            values = np.broadcast_to(values, shape)
        except ValueError:
            raise ValueError(f"mdcs: the functional returned an array of shape {values.shape} for inputs of shape "
                             f"{shape}; it must be vectorised (return one value per input)") from None
    bad = ~(values >= 0)
    if bad.any():
        i = int(np.flatnonzero(bad.ravel())[0])
        raise ValueError(f"mdcs: the functional must be >= 0 and not NaN; {what(i)} = {values.ravel()[i]}")
    return values


_GAUSS_X, _GAUSS_W = np.polynomial.legendre.leggauss(8)


def _curve_weights(G, geometry, usable, tolerance, max_depth=14):
    """The integral of G(y(x), k, x) along each usable edge by adaptive Gauss-Legendre (8 points), vectorised over
    all the panels of a round; a panel is accepted when one rule and the rule on its two halves agree within
    ``tolerance`` (relative to the edge's integral)."""
    weights = np.where(usable, 0.0, np.inf)
    x0, y0, x1, y1, slope = geometry.T
    keep = usable & (x1 > x0)
    edge = np.flatnonzero(keep)
    # Panels: (edge, a, b) with the value of the one-rule estimate on [a, b].
    a, b = x0[edge], x1[edge]

    def rule(e, lo, hi):
        half = 0.5 * (hi - lo)
        x = (0.5 * (lo + hi))[:, None] + half[:, None] * _GAUSS_X[None, :]
        t = (x - x0[e][:, None]) / (x1[e] - x0[e])[:, None]
        f = y0[e][:, None] + t * (y1[e] - y0[e])[:, None]
        k = np.broadcast_to(slope[e][:, None], x.shape)
        values = _checked_values(G(f, k, x), x.shape,
                                 lambda i: f"G(f={f.ravel()[i]}, f'={k.ravel()[i]}, x={x.ravel()[i]})")
        return half * (values @ _GAUSS_W)

    whole = rule(edge, a, b)
    scale = np.abs(whole)
    owner = np.arange(len(edge))
    for depth in range(max_depth + 1):
        if len(edge) == 0:
            break
        mid = 0.5 * (a + b)
        left, right = rule(edge, a, mid), rule(edge, mid, b)
        refined = left + right
        error = np.abs(refined - whole)
        done = (error <= tolerance * np.maximum(scale[owner], 1e-300)) | (depth == max_depth) | ~np.isfinite(refined)
        np.add.at(weights, edge[done], refined[done])
        go = ~done
        edge = np.concatenate([edge[go], edge[go]])
        owner = np.concatenate([owner[go], owner[go]])
        a, b = np.concatenate([a[go], mid[go]]), np.concatenate([mid[go], b[go]])
        whole = np.concatenate([left[go], right[go]])
    return weights


def _end(value, name):
    if np.ndim(value) == 0:
        return float(value)
    value = tuple(float(v) for v in np.asarray(value, dtype=float).ravel())
    if len(value) != 2:
        raise ValueError(f"mdcs: {name} must be a number (fixed end) or a pair (low, high) (free end)")
    return value


def minimal_curve(functional, *, interval, value_range, left, right, lines=1600, grid=None, seed=1,
                  pencil_fraction=0.1, max_abs_slope=0.0, include_floor=False, engine="planar", tolerance=1e-10,
                  progress="auto"):
    """The globally minimal discrete curve of a univariate problem (see the module documentation).

    Parameters:
        functional: ``"surface_of_rotation"`` (G = 2 pi |f| sqrt(1 + f'^2)), ``"arc_length"``
            (G = sqrt(1 + f'^2)), or a vectorised callable ``G(f, fp, x) -> array >= 0``.
        interval: ``(a, b)``, the domain of f.
        value_range: ``(ymin, ymax)``, the range of values.
        left, right: the end conditions: a number (fixed) or a pair ``(low, high)`` (free in that range).
        lines: the number of random lines of the arrangement (10% through the fixed end points), or a ``(k, 4)``
            array of lines given by two points ``x0, y0, x1, y1``.
        grid: instead of lines: the regular grid C_n^pl of order n (every line through two grid points of adjacent
            columns; about n^5 lines).
        seed, pencil_fraction, max_abs_slope, include_floor: options of the random lines (slopes limited to
            ``max_abs_slope`` unless 0; the line f = 0 added with ``include_floor``).
        engine: ``"planar"`` (default: the cut as a shortest path in the planar dual), ``"pseudoflow"``,
            ``"push_relabel"``, ``"boykov_kolmogorov"``.
        tolerance: relative accuracy of the quadrature of a user functional.
        progress: as everywhere in mdcs.

    Returns:
        :class:`MinimalCurve`.
    """
    if isinstance(lines, np.integer):
        lines = int(lines)
    elif isinstance(lines, (bool, float, np.floating)):
        raise ValueError(f"mdcs: lines must be a number of random lines (an integer) or a (k, 4) array, got {lines!r}")
    with progress_callback(progress, "curve") as callback:
        arrangement = _core.CurveArrangement(interval, value_range, _end(left, "left"), _end(right, "right"),
                                             lines if grid is None else None, 0 if grid is None else int(grid),
                                             int(seed), float(pencil_fraction), float(max_abs_slope),
                                             bool(include_floor), callback)
        if isinstance(functional, str):
            weights = arrangement.builtin_weights(functional, callback)
        elif callable(functional):
            geometry, usable = arrangement.edge_geometry()
            weights = _curve_weights(functional, geometry, usable.astype(bool), float(tolerance))
        else:
            raise ValueError("mdcs: functional must be a name (" + ", ".join(CURVE_FUNCTIONALS) + ") or a callable")
        result = arrangement.solve(weights, engine, callback)
    counts = {"vertices": arrangement.number_of_vertices, "edges": arrangement.number_of_edges,
              "faces": arrangement.number_of_faces}
    return MinimalCurve(result["feasible"], result["energy"], result["solver_value"], result["polyline"],
                        result["edges"], weights, counts)


# The degree-5 seven-point rule on a triangle (barycentric coordinates and weights).
_R, _S, _T, _U = 0.0597158717897698, 0.4701420641051151, 0.7974269853530873, 0.1012865073234563
_TRIANGLE_RULE = np.array([[1 / 3, 1 / 3, 1 / 3, 0.225],
                           [_R, _S, _S, 0.1323941527885062], [_S, _R, _S, 0.1323941527885062],
                           [_S, _S, _R, 0.1323941527885062],
                           [_T, _U, _U, 0.1259391805448271], [_U, _T, _U, 0.1259391805448271],
                           [_U, _U, _T, 0.1259391805448271]])


def _subdivide(tri, level):
    """Splits triangles ``(t, 3, 2)`` into 4^level triangles each (midpoint subdivision); returns (owner, tris)."""
    owner = np.arange(len(tri))
    for _ in range(level):
        a, b, c = tri[:, 0], tri[:, 1], tri[:, 2]
        ab, bc, ca = 0.5 * (a + b), 0.5 * (b + c), 0.5 * (c + a)
        tri = np.concatenate([np.stack(t, axis=1) for t in ((a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca))])
        owner = np.tile(owner, 4)
    return owner, tri


def _surface_weights(G, facets, quadrature_level):
    base, which, abc, offsets, xy = facets
    weights = base.copy()
    if len(which) == 0:
        return weights
    # Fan triangles of every polygon: (polygon, first corner, corner k, corner k + 1).
    sizes = np.diff(offsets)
    poly = np.repeat(np.arange(len(which)), sizes - 2)
    first = offsets[:-1][poly]
    k = np.arange(len(poly)) - np.repeat(np.cumsum(sizes - 2) - (sizes - 2), sizes - 2) + 1
    tri = np.stack([xy[first], xy[first + k], xy[first + k + 1]], axis=1)
    owner, tri = _subdivide(tri, quadrature_level)
    poly = poly[owner]
    area = 0.5 * np.abs((tri[:, 1, 0] - tri[:, 0, 0]) * (tri[:, 2, 1] - tri[:, 0, 1]) -
                        (tri[:, 1, 1] - tri[:, 0, 1]) * (tri[:, 2, 0] - tri[:, 0, 0]))
    bary, w = _TRIANGLE_RULE[:, :3], _TRIANGLE_RULE[:, 3]
    x = tri[:, :, 0] @ bary.T  # (triangles, 7)
    y = tri[:, :, 1] @ bary.T
    A, B, C = (abc[poly, i][:, None] for i in range(3))
    f = A * x + B * y + C
    fx, fy = np.broadcast_to(A, x.shape), np.broadcast_to(B, x.shape)
    values = _checked_values(G(f, fx, fy, x, y), x.shape,
                             lambda i: (f"G(f={f.ravel()[i]}, fx={fx.ravel()[i]}, fy={fy.ravel()[i]}, "
                                        f"x={x.ravel()[i]}, y={y.ravel()[i]})"))
    integral = area * (values @ w)
    np.add.at(weights, which, np.bincount(poly, weights=integral, minlength=len(which)))
    return weights


def _boundary_values(g, samples, name):
    if g is None:
        return None
    if np.ndim(g) == 0 and not callable(g):
        return np.full(len(samples), float(g))
    x, y = samples[:, 0].copy(), samples[:, 1].copy()
    try:
        values = np.asarray(g(x, y), dtype=np.float64)
        if values.shape != x.shape:
            values = np.broadcast_to(values, x.shape).astype(np.float64)
    except (TypeError, ValueError):
        # Not vectorised: one call per boundary sample.
        values = np.array([float(g(float(a), float(b))) for a, b in zip(x, y)])
    return values


def _plane_source(plane_grid, grid_offset_steps, polygon, random_options):
    """The plane source of :func:`minimal_surface` as ``(planes, seed, distribution, pencil_fraction, n, m)``, with
    the random options' defaults filled in, or ValueError when the options of the two sources are mixed."""
    def whole(value, name, low):
        if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
            raise ValueError(f"mdcs: {name} must be an integer, got {value!r}")
        if value < low:
            raise ValueError(f"mdcs: {name} must be at least {low}, got {value}")
        return int(value)

    if plane_grid is None:
        if grid_offset_steps is not None:
            raise ValueError("mdcs: grid_offset_steps applies to plane_grid only")
        defaults = {"planes": 150, "seed": 1, "distribution": "slope_limited", "pencil_fraction": 0.2}
        chosen = {k: defaults[k] if v is None else v for k, v in random_options.items()}
        return chosen["planes"], chosen["seed"], chosen["distribution"], chosen["pencil_fraction"], 0, 0
    given = [k for k, v in random_options.items() if v is not None]
    if given:
        raise ValueError("mdcs: plane_grid (the regular plane grid) excludes the random-plane options; drop "
                         + ", ".join(given))
    if polygon is not None:
        raise ValueError("mdcs: plane_grid needs a rectangular domain (domain=...), not a polygon; use random planes "
                         "on a polygon")
    n = whole(plane_grid, "plane_grid", 1)
    if n > _PLANE_GRID_MAX:
        raise ValueError(f"mdcs: plane_grid = {n} is too large: at most {_PLANE_GRID_MAX}")
    m = 0 if grid_offset_steps is None else whole(grid_offset_steps, "grid_offset_steps", 1)
    return 150, 1, "slope_limited", 0.0, n, m


def minimal_surface(functional, *, value_range, boundary, domain=None, polygon=None, upper_boundary=None, planes=None,
                    segments=4, seed=None, distribution=None, max_slope=3.0, pencil_fraction=None, plane_grid=None,
                    grid_offset_steps=None, engine="pseudoflow", quadrature_level=1, k_g=1.0, z_bottom=None,
                    threads=0, progress="auto"):
    """The globally minimal discrete surface of a bivariate problem (see the module documentation).

    Parameters:
        functional: ``"area"`` (G = sqrt(1 + |grad f|^2)), ``"membrane"`` (area plus ``k_g (f - z_bottom)``, a heavy
            membrane), or a vectorised callable ``G(f, fx, fy, x, y) -> array >= 0``.
        value_range: ``(zmin, zmax)``.
        boundary: the boundary condition ``f = g(x, y)`` on the boundary of the domain: a number or a callable
            (vectorised or not); evaluated at the boundary samples.
        domain: the rectangle ``(xmin, ymin, xmax, ymax)`` (default ``(0, 0, 1, 1)``), or
        polygon: a simple polygon ``(k, 2)`` instead (vertices rounded to 1/256 of its bounding box).
        upper_boundary: with it, the boundary condition is free: ``boundary <= f <= upper_boundary``.
        planes: the number of random planes of the arrangement (default 150; pencils through the boundary segments
            among them).
        segments: boundary segments per side of the rectangle (per polygon edge), 1..256.
        seed, distribution, pencil_fraction: the random planes: the seed (default 1), ``"slope_limited"`` (default)
            or ``"isotropic"``, the share of planes through the boundary segments (default 0.2).
        max_slope: the largest slope of the planes (default 3): of slope-limited random planes, or the largest
            gradient component of the grid's planes.
        plane_grid: instead of random planes, the regular plane grid G_n of order ``n`` (1..63; the C++
            ``regular_surface_planes_3``): the boundary cone, through every boundary segment the pencil of slopes
            ``max_slope * t / n`` (t = -n..n), and the planes with gradients ``max_slope * (i, j) / n``
            (|i|, |j| <= n) at heights spaced ``(zmax - zmin) / m`` apart. About
            ``(2n + 1)^2 m (1 + max_slope (width + height) / (2 (zmax - zmin)))`` planes plus ``2n + 2`` per
            boundary segment, at most 16384. Deterministic; rectangular domains only; excludes ``planes``,
            ``seed``, ``distribution`` and ``pencil_fraction`` (ValueError when combined, or on a polygon).
        grid_offset_steps: m, the grid's planes of one gradient are spaced ``(zmax - zmin) / m`` apart in height
            (default n; m = 1 gives far fewer cells and, in the measurements of the manual, the same energy).
        engine: ``"pseudoflow"`` (default), ``"push_relabel"``, ``"boykov_kolmogorov"``.
        quadrature_level: subdivisions of the facet quadrature (0..8) for functionals without a closed form.
        k_g, z_bottom: the membrane's weight per unit height and its reference height (default zmin).
        threads: for ``"area"`` and ``"membrane"``: threads of the facet weights (0, the default: every core; 1:
            sequential); the weights, hence the surface, are identical for every count. A callable functional is
            evaluated in Python, on one thread.
        progress: as everywhere in mdcs.

    Returns:
        :class:`MinimalSurface`.
    """
    planes, seed, distribution, pencil_fraction, grid_n, grid_m = _plane_source(
        plane_grid, grid_offset_steps, polygon,
        {"planes": planes, "seed": seed, "distribution": distribution, "pencil_fraction": pencil_fraction})
    if domain is None and polygon is None:
        domain = (0.0, 0.0, 1.0, 1.0)
    samples = _core.surface_boundary_samples(domain, polygon, value_range, int(segments))
    lower = _boundary_values(boundary, samples, "boundary")
    upper = _boundary_values(upper_boundary, samples, "upper_boundary")
    with progress_callback(progress, "surface") as callback:
        arrangement = _core.SurfaceArrangement(domain, polygon, value_range, int(segments), lower, upper,
                                               int(planes), int(seed), distribution, float(max_slope),
                                               float(pencil_fraction), grid_n, grid_m, callback)
        if isinstance(functional, str):
            z = float("nan") if z_bottom is None else float(z_bottom)
            result = arrangement.solve_builtin(functional, float(k_g), z, int(quadrature_level), engine, threads,
                                               callback)
        elif callable(functional):
            if not 0 <= int(quadrature_level) <= 8:
                raise ValueError("mdcs: quadrature_level must be in [0, 8]")
            weights = _surface_weights(functional, arrangement.weight_facets(), int(quadrature_level))
            result = arrangement.solve(weights, engine, callback)
        else:
            raise ValueError("mdcs: functional must be a name (" + ", ".join(SURFACE_FUNCTIONALS) + ") or a callable")
    counts = {"cells": arrangement.number_of_cells, "facets": arrangement.number_of_facets,
              "vertices": arrangement.number_of_vertices, "planes": arrangement.number_of_planes}
    return MinimalSurface(result["feasible"], result["energy"], result["solver_value"], result["projected_area"],
                          result["points"], result["triangles"], result["facets"], result["planes"], counts)
