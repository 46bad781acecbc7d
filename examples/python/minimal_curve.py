#!/usr/bin/env python3
# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Globally minimal curves: the minimal surface of rotation between two rings (the catenoid problem), solved on a
random line arrangement with the built-in functional and again with the same integrand written as a vectorised NumPy
function, compared with the exact catenoid; then a curve of least "travel time" through a medium whose slowness is a
user function. Writes minimal_curve.svg.

    python3 minimal_curve.py [OUTPUT_FOLDER] [--lines N]

OUTPUT_FOLDER: default mdcs-output; --lines: the number of random lines of the arrangement (default 1600).
"""

import argparse
import os

import numpy as np

import mdcs


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folder", nargs="?", default="mdcs-output")
    parser.add_argument("--lines", type=int, default=1600)
    args = parser.parse_args()
    lines, folder = args.lines, args.folder
    os.makedirs(folder, exist_ok=True)
    problem = dict(interval=(-1, 1), value_range=(0, 2), left=2.0, right=2.0, lines=lines)
    builtin = mdcs.variational.minimal_curve("surface_of_rotation", **problem)
    user = mdcs.variational.minimal_curve(lambda f, fp, x: 2 * np.pi * np.abs(f) * np.sqrt(1 + fp ** 2), **problem)
    exact = mdcs.variational.surface_of_rotation_minimum(2.0)
    print(f"{lines} lines ({builtin.arrangement['faces']} cells): discrete minimum {builtin.energy:.6f} (built-in), "
          f"{user.energy:.6f} (NumPy integrand); exact {exact['energy']:.6f} ({exact['branch']}), "
          f"relative error {(builtin.energy - exact['energy']) / exact['energy']:.2e}")

    # Fermat's principle: light through a medium that is slow in a band around y = 0.5 + 0.3 sin(3x)
    slowness = lambda f, fp, x: (1 + 3 * np.exp(-((f - 0.5 - 0.3 * np.sin(3 * x)) / 0.1) ** 2)) * np.sqrt(1 + fp ** 2)  # noqa: E731
    ray = mdcs.variational.minimal_curve(slowness, interval=(0, 2), value_range=(0, 1), left=0.1, right=0.9,
                                         lines=lines)
    print(f"least-time ray: travel time {ray.energy:.5f}, {len(ray.polyline)} vertices")

    # the exact minimiser: the shallow catenary f = c cosh(x / c) with c cosh(1 / c) = 2 (the larger root)
    lo, hi = 0.6, 2.0
    for _ in range(60):
        c = 0.5 * (lo + hi)
        lo, hi = (c, hi) if c * np.cosh(1 / c) < 2 else (lo, c)
    xs = np.linspace(-1, 1, 100)

    def poly(points, x0, y0, sx, sy, colour, dash=""):
        pts = " ".join(f"{x0 + sx * x:.1f},{y0 - sy * y:.1f}" for x, y in points)
        return f"<polyline points='{pts}' fill='none' stroke='{colour}' stroke-width='2' {dash}/>\n"

    with open(os.path.join(folder, "minimal_curve.svg"), "w") as out:
        out.write("<svg xmlns='http://www.w3.org/2000/svg' width='820' height='330' font-family='sans-serif' "
                  "font-size='12'><rect width='100%' height='100%' fill='white'/>\n")
        out.write(poly([(-1, 0), (1, 0)], 210, 290, 180, 130, "#888888"))
        out.write(poly(np.c_[xs, c * np.cosh(xs / c)], 210, 290, 180, 130, "#333333", "stroke-dasharray='5,4'"))
        out.write(poly(builtin.polyline, 210, 290, 180, 130, "#c0392b"))
        out.write("<text x='20' y='320'>catenoid: discrete global minimum (red), exact (dashed)</text>\n")
        out.write(poly(np.c_[2 * (xs + 1) / 2, 0.5 + 0.3 * np.sin(3 * (xs + 1))], 450, 290, 180, 260, "#bbbbbb"))
        out.write(poly(ray.polyline, 450, 290, 180, 260, "#2b5d9b"))
        out.write("<text x='450' y='320'>least-time ray (blue) across a slow band (grey)</text></svg>\n")
    print(f"picture: {folder}/minimal_curve.svg")


if __name__ == "__main__":
    main()
