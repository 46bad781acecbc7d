# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""mdcs.variational against the C++ suite's oracles: the catenoid's exact minimum, straight lines, planes for
linear boundary data, cut == shortest path (every engine agrees), and user functionals (vectorised callbacks)
against the built-in closed forms."""

import numpy as np
import pytest

import mdcs

V = mdcs.variational


def catenoid(lines, functional="surface_of_rotation", engine="planar", seed=1):
    return V.minimal_curve(functional, interval=(-1, 1), value_range=(0, 2), left=2, right=2, lines=lines, seed=seed,
                           engine=engine, progress=False)


def test_catenoid_approaches_the_exact_minimum():
    exact = V.surface_of_rotation_minimum(2.0)
    assert exact["branch"] == "catenoid"
    errors = [(catenoid(n).energy - exact["energy"]) / exact["energy"] for n in (100, 800)]
    assert all(e >= -1e-12 for e in errors)  # a discrete curve is a function: never below the minimum
    assert errors[1] < errors[0] and errors[1] < 5e-3


def test_engines_agree_and_cut_equals_energy():
    ref = catenoid(150)
    for engine in ("pseudoflow", "push_relabel", "boykov_kolmogorov"):
        c = catenoid(150, engine=engine)
        assert c.energy == pytest.approx(ref.energy, rel=1e-12)
    assert ref.solver_value == pytest.approx(ref.energy, rel=1e-12)
    assert np.all(np.diff(ref.polyline[:, 0]) >= 0)  # a function of x
    assert ref.polyline[0].tolist() == [-1, 2] and ref.polyline[-1].tolist() == [1, 2]


def test_a_vectorised_user_functional_matches_the_closed_form():
    ref = catenoid(200)
    user = catenoid(200, functional=lambda f, fp, x: 2 * np.pi * np.abs(f) * np.sqrt(1 + fp * fp))
    finite = np.isfinite(ref.weights)
    assert np.array_equal(finite, np.isfinite(user.weights))
    np.testing.assert_allclose(user.weights[finite], ref.weights[finite], rtol=1e-8, atol=1e-12)
    assert user.energy == pytest.approx(ref.energy, rel=1e-9)


def test_arc_length_through_a_grid_is_the_straight_line():
    c = V.minimal_curve("arc_length", interval=(0, 4), value_range=(0, 16), left=1, right=9, grid=4, progress=False)
    assert c.feasible and c.energy == pytest.approx(np.hypot(4, 8), rel=1e-12)
    relaxed = V.minimal_curve("arc_length", interval=(0, 1), value_range=(0, 1), left=(0.2, 0.6), right=0.4,
                              lines=100, progress=False)
    assert relaxed.feasible and relaxed.energy >= 1 - 1e-12


def test_infeasible_grid_is_reported():
    c = V.minimal_curve("arc_length", interval=(0, 1), value_range=(0, 1), left=0.5, right=0.5,
                        lines=np.array([[0, 0.1, 1, 0.9]]), progress=False)
    assert not c.feasible and c.energy == np.inf and len(c.polyline) == 0


def test_linear_boundary_data_gives_the_plane_area():
    plane = lambda x, y: 0.25 + 0.5 * x + 0.25 * y  # noqa: E731
    s = V.minimal_surface("area", value_range=(0, 1), boundary=plane, planes=60, segments=8, progress=False)
    area = np.sqrt(1 + 0.25 + 0.0625)
    assert s.feasible and area - 1e-9 <= s.energy < area * 1.02
    assert s.projected_area == pytest.approx(1.0, rel=1e-9)
    assert s.solver_value == pytest.approx(s.energy, rel=1e-9)


def test_user_surface_functional_and_engines():
    kwargs = dict(domain=(-1, -1, 1, 1), value_range=(-1.1, 1.1), boundary=lambda x, y: x * y, planes=60,
                  progress=False)
    ref = V.minimal_surface("area", **kwargs)
    user = V.minimal_surface(lambda f, fx, fy, x, y: np.sqrt(1 + fx * fx + fy * fy), **kwargs)
    assert user.energy == pytest.approx(ref.energy, rel=1e-9)  # constant on a facet: the quadrature is exact
    assert V.minimal_surface("area", engine="boykov_kolmogorov", **kwargs).energy == pytest.approx(ref.energy, rel=1e-9)
    membrane = dict(value_range=(0, 1), boundary=0.75, planes=80, segments=2, pencil_fraction=0.3, progress=False)
    heavy = V.minimal_surface("membrane", k_g=2.0, **membrane)
    # the flat membrane costs 1 + 2 * 0.75; sagging does better and never rises above the rim
    assert heavy.energy < 2.5 - 1e-3 and heavy.points[:, 2].max() <= 0.75 + 1e-9 and heavy.points[:, 2].min() < 0.7
    assert V.minimal_surface("membrane", k_g=0.0, **membrane).energy == pytest.approx(1.0, rel=1e-9)


def test_polygonal_domain_and_free_boundary():
    L = [[0, 0], [1, 0], [1, 0.5], [0.5, 0.5], [0.5, 1], [0, 1]]
    s = V.minimal_surface("area", polygon=L, value_range=(0, 1), boundary=0.3, planes=40, progress=False)
    assert s.feasible and s.projected_area == pytest.approx(0.75, rel=1e-9)
    assert s.energy == pytest.approx(0.75, rel=1e-9)  # the flat surface at height 0.3
    free = V.minimal_surface("area", value_range=(0, 1), boundary=0.1, upper_boundary=0.9, planes=30, progress=False)
    assert free.energy == pytest.approx(1.0, rel=1e-9)


def test_builtin_surface_functionals_give_the_same_surface_for_every_thread_count():
    kwargs = dict(domain=(-1, -1, 1, 1), value_range=(-1.1, 1.1), boundary=lambda x, y: x * y, planes=50,
                  progress=False)
    for functional in ("area", "membrane"):
        runs = [V.minimal_surface(functional, threads=t, **kwargs) for t in (1, 2, 8)]
        for s in runs[1:]:
            assert s.energy == runs[0].energy and np.array_equal(s.facets, runs[0].facets)
    with pytest.raises(ValueError, match="threads"):
        V.minimal_surface("area", threads=-2, **kwargs)


# The sagging membrane of the C++ benchmark bench_surface_plane_grids_3 (MDCS_test::sagging_membrane_problem()): the
# unit square, rim at 0.75, values in [0, 1], 2 boundary segments per side, area + 2 f; grid slope bound 1.
MEMBRANE = dict(value_range=(0, 1), boundary=0.75, segments=2, k_g=2.0, z_bottom=0.0, max_slope=1.0, progress=False)
WALLS = 6  # the arrangement's count includes the six walls of the box


def grid_plane_count(n, m):
    """The planes of the regular grid G_n on MEMBRANE, enumerated exactly from the manual's definition (world planes
    z = A x + B y + C as fractions; all its gradients and heights are dyadic for n a power of 2 and m = 1 or 2, so
    the lattice holds them exactly): the boundary cone (a flat rim: every cone plane is z = 3/4), the pencils of
    slopes t / n across every side, and the interior planes with gradients (i, j) / n at centre heights
    1/2 + k / m that cross the open box; equal planes once."""
    from fractions import Fraction as Q
    planes = {(Q(0), Q(0), Q(3, 4))}
    for t in range(-n, n + 1):
        s = Q(t, n)  # slope across the side, towards the inside
        planes |= {(s, Q(0), Q(3, 4)), (-s, Q(0), Q(3, 4) + s), (Q(0), s, Q(3, 4)), (Q(0), -s, Q(3, 4) + s)}
    for i in range(-n, n + 1):
        for j in range(-n, n + 1):
            A, B = Q(i, n), Q(j, n)
            for k in range(-4 * m, 4 * m + 1):
                C = Q(1, 2) + Q(k, m) - (A + B) / 2
                corners = [A * x + B * y + C for x in (0, 1) for y in (0, 1)]
                if max(corners) > 0 and min(corners) < 1:
                    planes.add((A, B, C))
    return len(planes)


def benchmark_rows():
    """The regular-grid rows of the C++ benchmark's CSV (energies and cell counts are deterministic)."""
    import csv
    import os
    path = os.path.join(os.path.dirname(__file__), "..", "..", "benchmark", "results", "surface_plane_grids.csv")
    if not os.path.exists(path):
        pytest.skip("benchmark/results/surface_plane_grids.csv is not beside the tests")
    with open(path, encoding="utf-8") as f:
        return {(r["problem"], int(r["n"]), int(r["m"])): r for r in csv.DictReader(f) if r["source"] == "grid"}


def test_regular_plane_grid_matches_the_cpp_benchmark_and_the_manual():
    rows = benchmark_rows()
    energies, surfaces = [], {}
    for n, m in ((1, 1), (2, 1), (2, 2), (4, 1)):
        s = V.minimal_surface("membrane", plane_grid=n, grid_offset_steps=m, **MEMBRANE)
        assert s.feasible and s.projected_area == pytest.approx(1.0, abs=1e-9)
        assert s.energy == pytest.approx(s.solver_value, rel=1e-9)
        assert s.arrangement["planes"] - WALLS == grid_plane_count(n, m)
        row = rows[("membrane", n, m)]
        assert s.arrangement["planes"] - WALLS == int(row["planes"])
        assert s.arrangement["cells"] == int(row["cells"])
        assert s.energy == pytest.approx(float(row["energy"]), rel=1e-8)
        surfaces[n, m] = s
        if m == 1:
            energies.append(s.energy)
    # Nested grids (n = 1, 2, 4: every plane of G_n is in G_2n) can only lower the discrete optimum; here they do.
    assert energies[0] > energies[1] > energies[2]
    # n = 1 is the flat membrane at the rim: area 1 plus 2 * 0.75.
    assert energies[0] == pytest.approx(2.5, rel=1e-12)
    # Deterministic: no seed, the same surface twice.
    again = V.minimal_surface("membrane", plane_grid=2, grid_offset_steps=1, **MEMBRANE)
    assert again.energy == energies[1] and np.array_equal(again.points, surfaces[2, 1].points)


def test_regular_plane_grid_refuses_mixed_or_bad_options():
    square = dict(value_range=(0, 1), boundary=0.5, progress=False)
    for random_option in (dict(planes=40), dict(seed=3), dict(distribution="isotropic"), dict(pencil_fraction=0.5)):
        with pytest.raises(ValueError, match="excludes the random-plane options"):
            V.minimal_surface("area", plane_grid=2, **random_option, **square)
    with pytest.raises(ValueError, match="rectangular domain"):
        V.minimal_surface("area", plane_grid=2, polygon=[[0, 0], [1, 0], [1, 1]], **square)
    with pytest.raises(ValueError, match="grid_offset_steps applies to plane_grid only"):
        V.minimal_surface("area", grid_offset_steps=2, **square)
    for bad in (0, -1, 64, 2.0, True, "4"):
        with pytest.raises(ValueError, match="plane_grid"):
            V.minimal_surface("area", plane_grid=bad, **square)
    with pytest.raises(ValueError, match="grid_offset_steps"):
        V.minimal_surface("area", plane_grid=2, grid_offset_steps=0, **square)
    # The library's own refusals: more than 16384 planes, a slope bound too steep for the lattice, or too gentle.
    with pytest.raises(ValueError, match="more than 16384 planes"):
        V.minimal_surface("area", plane_grid=63, **square)
    with pytest.raises(ValueError, match="max_slope"):
        V.minimal_surface("area", plane_grid=2, max_slope=1e9, **square)
    with pytest.raises(ValueError, match="too small"):
        V.minimal_surface("area", plane_grid=63, grid_offset_steps=1, max_slope=1e-3, **square)
