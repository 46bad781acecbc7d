#!/usr/bin/env python3
# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Runs the published test suites of tvb-gdist and pygeodesic against mdcs.compat, outside this repository.

    python3 run_upstream_tests.py [--tvb-gdist DIR] [--pygeodesic DIR] [-- PYTEST_ARGS...]

DIR is a checkout of https://github.com/the-virtual-brain/tvb-gdist or https://github.com/mhogg/pygeodesic (their
tests are not part of MDCS). A temporary folder gets two shims, ``gdist`` and ``pygeodesic``, that make those names
import mdcs.compat.gdist and mdcs.compat.pygeodesic; pytest then runs each project's tests from its own checkout
(tvb-gdist's tests read data/ relative to the working directory). mdcs must be importable (installed, or on
PYTHONPATH, e.g. <build>/python). Exits with pytest's status (non-zero if any suite fails).

--smsp-check: also compares mdcs.compat.gdist.local_gdist_matrix on tvb-gdist's data/surface_data surfaces with
CGAL's Surface_mesh_shortest_path, row by row (what tests/test_equality_with_stable.py checks against stored
matrices, for checkouts that lack those files; about a minute).
"""

import argparse
import os
import subprocess
import sys
import tempfile

GDIST_SHIM = """import sys
import mdcs.compat.gdist as _module
sys.modules[__name__] = _module
"""

PYGEODESIC_SHIM = """import sys
import mdcs.compat.pygeodesic as _package
import mdcs.compat.pygeodesic.geodesic as _geodesic
sys.modules["pygeodesic"] = _package
sys.modules["pygeodesic.geodesic"] = _geodesic
"""


def run(label, checkout, tests, shim_dir, pytest_args):
    env = dict(os.environ)
    # absolute: the tests run in the checkout
    paths = [os.path.abspath(p) for p in env.get("PYTHONPATH", "").split(os.pathsep) if p]
    env["PYTHONPATH"] = os.pathsep.join([shim_dir] + paths)
    env["PYTHONDONTWRITEBYTECODE"] = "1"
    # pytest runs in the checkout (tvb-gdist's tests read data/ from there), but without the checkout on sys.path
    # (as "python -m pytest" would put it): the original package there (pygeodesic/) must not shadow the shim.
    runner = "import sys; sys.path.pop(0); import pytest; sys.exit(pytest.main(sys.argv[1:]))"
    command = [sys.executable, "-c", runner, "-p", "no:cacheprovider", "-v", tests] + pytest_args
    print(f"== {label}: {' '.join(command)} (in {checkout})", flush=True)
    return subprocess.call(command, cwd=checkout, env=env)


def smsp_check(checkout, tolerance=1e-9):
    """Every row of local_gdist_matrix on tvb-gdist's surface_data surfaces against CGAL's SMSP; returns 0 or 1."""
    import numpy as np

    import mdcs.compat.gdist as gdist
    from mdcs import _mdcs

    folder = os.path.join(checkout, "data", "surface_data")
    status = 0
    for name in sorted(os.listdir(folder)):
        V = np.loadtxt(os.path.join(folder, name, "vertices.txt"), dtype=np.float64)
        T = np.loadtxt(os.path.join(folder, name, "triangles.txt"), dtype=np.int32)
        M = gdist.local_gdist_matrix(V, T).toarray()
        T64 = T.astype(np.int64)
        worst = max(np.abs(M[s] - np.asarray(_mdcs.reference.cgal_shortest_path_distances(V, T64, s))).max()
                    for s in range(len(V)))
        ok = worst <= tolerance and np.array_equal(M, M.T)
        status |= 0 if ok else 1
        print(f"== smsp-check {name}: {len(V)} vertices, max |local_gdist_matrix - CGAL SMSP| = {worst:.3g}, "
              f"symmetric {np.array_equal(M, M.T)}: {'PASSED' if ok else 'FAILED'}", flush=True)
    return status


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--tvb-gdist", help="checkout of the-virtual-brain/tvb-gdist")
    parser.add_argument("--pygeodesic", help="checkout of mhogg/pygeodesic")
    parser.add_argument("--smsp-check", action="store_true",
                        help="compare local_gdist_matrix on tvb-gdist's surface_data with CGAL's SMSP")
    parser.add_argument("pytest_args", nargs="*")
    args = parser.parse_args()
    if not args.tvb_gdist and not args.pygeodesic:
        parser.error("give --tvb-gdist and/or --pygeodesic")
    status = 0
    with tempfile.TemporaryDirectory() as shim_dir:
        with open(os.path.join(shim_dir, "gdist.py"), "w") as f:
            f.write(GDIST_SHIM)
        os.makedirs(os.path.join(shim_dir, "pygeodesic"))
        with open(os.path.join(shim_dir, "pygeodesic", "__init__.py"), "w") as f:
            f.write(PYGEODESIC_SHIM)
        if args.tvb_gdist:
            status |= run("tvb-gdist", args.tvb_gdist, "tests", shim_dir, args.pytest_args)
        if args.tvb_gdist and args.smsp_check:
            status |= smsp_check(args.tvb_gdist)
        if args.pygeodesic:
            status |= run("pygeodesic", args.pygeodesic, "tests", shim_dir, args.pytest_args)
    return status


if __name__ == "__main__":
    sys.exit(main())
