#!/usr/bin/env python3
# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Minimum weight triangulations: 200 random points (certified optimal, compared with the Delaunay triangulation's
weight) and the thesis's 13-wheel, whose LP optimum is fractional (18.7636) and whose MWT (18.7989) needs branch and
bound. Writes mwt.svg.

    python3 mwt.py [OUTPUT_FOLDER]
"""

import os
import sys

import numpy as np
import scipy.spatial

import mdcs


def edges_of(triangles):
    e = np.sort(np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]]), axis=1)
    return np.unique(e, axis=0)


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else "mdcs-output"
    os.makedirs(folder, exist_ok=True)
    points = np.random.default_rng(42).random((200, 2))
    r = mdcs.mwt.minimum_weight_triangulation(points)
    delaunay = edges_of(scipy.spatial.Delaunay(points).simplices)
    delaunay_weight = np.linalg.norm(points[delaunay[:, 0]] - points[delaunay[:, 1]], axis=1).sum()
    print(f"200 random points: {r.status}, weight {r.weight:.6f} (lower bound {r.lower_bound:.6f}); "
          f"Delaunay {delaunay_weight:.6f}; {len(r.triangles)} triangles, solver {r.solver}, "
          f"{r.statistics['time_total']:.2f} s")

    angles = 2 * np.pi * np.arange(13) / 13
    wheel = np.vstack([[0, 0], np.c_[np.cos(angles), np.sin(angles)]])
    lp = mdcs.mwt.minimum_weight_triangulation(wheel, resolve_fractional=False)
    w = mdcs.mwt.minimum_weight_triangulation(wheel)
    print(f"13-wheel: LP optimum {lp.lp_objective:.4f} ({lp.status}), MWT {w.weight:.4f} ({w.status})")

    with open(os.path.join(folder, "mwt.svg"), "w") as out:
        out.write("<svg xmlns='http://www.w3.org/2000/svg' width='620' height='660' font-family='sans-serif'>"
                  "<rect width='100%' height='100%' fill='white'/>\n")
        for a, b in r.edges:
            (x0, y0), (x1, y1) = 10 + 600 * points[a], 10 + 600 * points[b]
            out.write(f"<line x1='{x0:.1f}' y1='{610 - y0 + 10:.1f}' x2='{x1:.1f}' y2='{610 - y1 + 10:.1f}' "
                      "stroke='#2b5d9b' stroke-width='0.8'/>\n")
        out.write(f"<text x='10' y='630' font-size='13'>minimum weight triangulation of 200 random points: "
                  f"{r.status}</text><text x='10' y='650' font-size='13'>weight {r.weight:.4f} "
                  f"(Delaunay triangulation {delaunay_weight:.4f})</text></svg>\n")
    print(f"picture: {folder}/mwt.svg")


if __name__ == "__main__":
    main()
