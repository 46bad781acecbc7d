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
    env["PYTHONPATH"] = os.pathsep.join([shim_dir] + [os.path.abspath(p) for p in env.get("PYTHONPATH", "").split(os.pathsep) if p])
    env["PYTHONDONTWRITEBYTECODE"] = "1"
    # pytest runs in the checkout (tvb-gdist's tests read data/ from there), but without the checkout on sys.path
    # (as "python -m pytest" would put it): the original package there (pygeodesic/) must not shadow the shim.
    runner = "import sys; sys.path.pop(0); import pytest; sys.exit(pytest.main(sys.argv[1:]))"
    command = [sys.executable, "-c", runner, "-p", "no:cacheprovider", "-v", tests] + pytest_args
    print(f"== {label}: {' '.join(command)} (in {checkout})", flush=True)
    return subprocess.call(command, cwd=checkout, env=env)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--tvb-gdist", help="checkout of the-virtual-brain/tvb-gdist")
    parser.add_argument("--pygeodesic", help="checkout of mhogg/pygeodesic")
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
        if args.pygeodesic:
            status |= run("pygeodesic", args.pygeodesic, "tests", shim_dir, args.pytest_args)
    return status


if __name__ == "__main__":
    sys.exit(main())
