#!/usr/bin/env python3
# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The manual's picture of bench_surface_plane_grids_3: log-log plots of the relative energy error against the
number of planes and against the number of cells, per problem, for the regular grid (m = 1 and m = n) and the
random planes (median over the seeds, with the range as a bar). Standard library only.

    python3 plot_surface_plane_grids.py [--csv benchmark/results/surface_plane_grids.csv]
        [--svg doc/Variational_minimization/surface_plane_grids.svg]
"""
import argparse
import csv
import math
import statistics

TITLES = {"membrane": "heavy membrane (area + 2 f), max_slope 1", "scherk": "Scherk, 4 segments per side, max_slope 3"}
COLOURS = {"grid, m = 1": "#1f77b4", "grid, m = n": "#2ca02c", "random (median, range)": "#d62728"}


def series(rows, axis):
    """{label: [(x, y, lo, hi)]} for one problem; axis is 'planes' or 'cells' (random: median cells)."""
    out = {label: [] for label in COLOURS}
    random_rows = {}
    for r in rows:
        e = float(r["energy_rel_error"])
        if r["source"] == "grid":
            label = "grid, m = 1" if r["m"] == "1" else "grid, m = n"
            out[label].append((float(r[axis]), e, e, e))
        else:
            random_rows.setdefault(int(r["planes"]), []).append(r)
    for planes, rs in sorted(random_rows.items()):
        errors = [float(r["energy_rel_error"]) for r in rs]
        x = planes if axis == "planes" else statistics.median(float(r["cells"]) for r in rs)
        out["random (median, range)"].append((x, statistics.median(errors), min(errors), max(errors)))
    return out


def tick_label(v):
    if v >= 1e6:
        return "%gM" % (v / 1e6)
    if v >= 1e4:
        return "%gk" % (v / 1e3)
    return "%g" % v


def panel(out, ox, oy, pw, ph, title, x_label, data, y_label):
    points = [p for pts in data.values() for p in pts]
    lx0 = math.floor(math.log10(min(p[0] for p in points)) * 5) / 5
    lx1 = math.ceil(math.log10(max(p[0] for p in points)) * 5) / 5
    ly0 = math.floor(math.log10(max(1e-6, min(p[2] for p in points))) * 4) / 4
    ly1 = math.ceil(math.log10(max(p[3] for p in points)) * 4) / 4
    X = lambda v: ox + (math.log10(v) - lx0) / (lx1 - lx0) * pw
    Y = lambda v: oy + ph - (math.log10(max(v, 1e-6)) - ly0) / (ly1 - ly0) * ph
    out.append('<rect x="%.1f" y="%.1f" width="%g" height="%g" fill="none" stroke="black"/>' % (ox, oy, pw, ph))
    out.append('<text x="%.1f" y="%.1f" text-anchor="middle">%s</text>' % (ox + pw / 2, oy - 10, title))
    for e in range(int(math.floor(min(lx0, ly0))) - 1, int(math.ceil(max(lx1, ly1))) + 1):
        for f in (1, 2, 5):
            v = f * 10.0 ** e
            if lx0 - 1e-9 <= math.log10(v) <= lx1 + 1e-9:
                out.append('<line x1="%.1f" x2="%.1f" y1="%.1f" y2="%.1f" stroke="#ddd"/>' % (X(v), X(v), oy, oy + ph))
                out.append('<text x="%.1f" y="%.1f" text-anchor="middle">%s</text>' % (X(v), oy + ph + 14, tick_label(v)))
        for f in (1, 2, 3, 4, 5, 6, 8):
            v = f * 10.0 ** e
            if ly0 - 1e-9 <= math.log10(v) <= ly1 + 1e-9:
                out.append('<line x1="%.1f" x2="%.1f" y1="%.1f" y2="%.1f" stroke="#ddd"/>' % (ox, ox + pw, Y(v), Y(v)))
                out.append('<text x="%.1f" y="%.1f" text-anchor="end">%g%%</text>' % (ox - 4, Y(v) + 4, 100 * v))
    out.append('<text x="%.1f" y="%.1f" text-anchor="middle">%s</text>' % (ox + pw / 2, oy + ph + 30, x_label))
    if y_label:
        out.append('<text transform="translate(%.1f,%.1f) rotate(-90)" text-anchor="middle">relative energy error '
                   '(log)</text>' % (ox - 48, oy + ph / 2))
    for k, (label, pts) in enumerate(data.items()):
        colour = COLOURS[label]
        if pts:
            out.append('<polyline fill="none" stroke="%s" stroke-width="1.5" points="%s"/>' %
                       (colour, " ".join("%.1f,%.1f" % (X(p[0]), Y(p[1])) for p in pts)))
        for x, y, lo, hi in pts:
            if hi > lo:
                out.append('<line x1="%.1f" x2="%.1f" y1="%.1f" y2="%.1f" stroke="%s"/>' % (X(x), X(x), Y(lo), Y(hi), colour))
            out.append('<circle cx="%.1f" cy="%.1f" r="3" fill="%s"/>' % (X(x), Y(y), colour))
        out.append('<text x="%.1f" y="%.1f" fill="%s">%s</text>' % (ox + k * 125, oy + ph + 48, colour, label))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--csv", default="benchmark/results/surface_plane_grids.csv")
    parser.add_argument("--svg", default="doc/Variational_minimization/surface_plane_grids.svg")
    args = parser.parse_args()
    with open(args.csv) as f:
        rows = list(csv.DictReader(f))
    problems = [p for p in ("membrane", "scherk") if any(r["problem"] == p for r in rows)]
    pw, ph, left, top, gap_x, gap_y = 360, 260, 70, 30, 70, 90
    width, height = left + 2 * (pw + gap_x), len(problems) * (top + ph + gap_y)
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="11">'
           % (width, height), '<rect width="100%" height="100%" fill="white"/>']
    for i, p in enumerate(problems):
        mine = [r for r in rows if r["problem"] == p]
        oy = top + i * (top + ph + gap_y)
        panel(out, left, oy, pw, ph, TITLES.get(p, p), "planes", series(mine, "planes"), True)
        panel(out, left + pw + gap_x, oy, pw, ph, TITLES.get(p, p), "cells", series(mine, "cells"), True)
    out.append("</svg>")
    with open(args.svg, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
