# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Long cases (run with --run-long, CTest: python.pytest_long): the examples end to end, the catenoid at 1,600
lines, CGAL agreement on a 10k-vertex demo mesh."""

import os
import subprocess
import sys

import numpy as np
import pytest

import mdcs
from mdcs import _mdcs

EXAMPLES = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "python")


@pytest.mark.long
@pytest.mark.parametrize("script, outputs", [("distance_matrix.py", ["distance_field.svg", "distance_matrix.svg"]),
                                             ("mwt.py", ["mwt.svg"]), ("minimal_curve.py", ["minimal_curve.svg"])])
def test_examples_run(tmp_path, script, outputs):
    args = [sys.executable, os.path.join(EXAMPLES, script)]
    args += [str(tmp_path)] + (["--lines", "800"] if script == "minimal_curve.py" else [])
    result = subprocess.run(args, capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stderr
    for name in outputs:
        assert (tmp_path / name).stat().st_size > 1000


@pytest.mark.long
def test_catenoid_with_1600_lines_within_3e_3():
    exact = mdcs.variational.surface_of_rotation_minimum(2.0)["energy"]
    errors = [(mdcs.variational.minimal_curve("surface_of_rotation", interval=(-1, 1), value_range=(0, 2), left=2,
                                              right=2, lines=1600, seed=seed, progress=False).energy - exact) / exact
              for seed in (1, 2, 3)]
    assert np.median(errors) <= 3e-3


@pytest.mark.long
def test_exact_agrees_with_cgal_on_the_chinese_dragon(cgal_mesh_dir):
    if cgal_mesh_dir is None:
        pytest.skip("CGAL's demo meshes are not available")
    V, F = mdcs.io.read_mesh(os.path.join(cgal_mesh_dir, "ChineseDragon-10kv.off"))
    mesh = mdcs.Mesh(V, F)
    for source in (0, 4321, 9999):
        np.testing.assert_allclose(mesh.distances(source, progress=False),
                                   _mdcs.reference.cgal_shortest_path_distances(V, F, source), rtol=1e-8, atol=1e-12)
