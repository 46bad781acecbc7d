#!/usr/bin/env python3
# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Exact geodesic distances on a real mesh: the distance field from one vertex drawn on the mesh, and the distance
matrix between 12 vertices spread over the surface (computed in parallel), drawn as a heat map; both as SVG.

    python3 distance_matrix.py [OUTPUT_FOLDER] [--mesh FILE]

--mesh: an OFF/PLY/OBJ/STL file; default CGAL's elephant.off from Debian's libcgal-demo (or a generated wavy sphere
when that is not installed). Writes distance_field.svg and distance_matrix.svg (default folder: mdcs-output).
"""

import argparse
import os
import tarfile
import tempfile

import numpy as np

import mdcs

ARCHIVE = "/usr/share/doc/libcgal-dev/data.tar.gz"  # Debian's libcgal-demo


def load(path):
    if path:
        return mdcs.io.read_mesh(path), os.path.basename(path)
    if os.path.exists(ARCHIVE):
        with tarfile.open(ARCHIVE) as archive, tempfile.TemporaryDirectory() as tmp:
            target = os.path.join(tmp, "elephant.off")
            with open(target, "wb") as f:
                f.write(archive.extractfile("data/meshes/elephant.off").read())
            return mdcs.io.read_mesh(target), "CGAL's elephant.off"
    t = np.linspace(0, np.pi, 40)[1:-1]  # fallback: a wavy sphere of latitude rings
    p = np.linspace(0, 2 * np.pi, 60, endpoint=False)
    T, P = np.meshgrid(t, p, indexing="ij")
    r = 1 + 0.1 * np.sin(4 * T) * np.cos(5 * P)
    V = np.c_[(r * np.sin(T) * np.cos(P)).ravel(), (r * np.sin(T) * np.sin(P)).ravel(), (r * np.cos(T)).ravel()]
    V = np.vstack([V, [0, 0, 1.0], [0, 0, -1.0]])
    ring = lambda i, j: i * 60 + j % 60  # noqa: E731
    F = [[ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)] for i in range(37) for j in range(60)]
    F += [[ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)] for i in range(37) for j in range(60)]
    F += [[len(V) - 2, ring(0, j), ring(0, j + 1)] for j in range(60)]
    F += [[len(V) - 1, ring(37, j + 1), ring(37, j)] for j in range(60)]
    return (V, np.array(F)), "a wavy sphere"


def colour(x):
    """A blue-yellow-red colour for x in [0, 1]."""
    stops = np.array([[49, 54, 149], [116, 173, 209], [255, 255, 191], [244, 109, 67], [165, 0, 38]])
    x = np.clip(x, 0, 1) * (len(stops) - 1)
    i = np.minimum(x.astype(int), len(stops) - 2)
    c = stops[i] + (x - i)[:, None] * (stops[i + 1] - stops[i])
    return [f"rgb({r:.0f},{g:.0f},{b:.0f})" for r, g, b in c]


def legend(x, y, maximum, width=200):
    """A colour bar from 0 to `maximum` (SVG text)."""
    steps = 40
    fill = colour(np.linspace(0, 1, steps))
    bar = "".join(f"<rect x='{x + width * i / steps:.1f}' y='{y}' width='{width / steps + 0.5:.1f}' height='10' "
                  f"fill='{fill[i]}'/>" for i in range(steps))
    return (bar + f"<text x='{x}' y='{y + 24}' font-family='sans-serif' font-size='11'>0</text>"
            f"<text x='{x + width}' y='{y + 24}' font-family='sans-serif' font-size='11' text-anchor='end'>"
            f"{maximum:.3g}</text>\n")


def draw_field(V, F, d, sources, title, path, size=600):
    # orthographic view along -z after a turn about y; painter's order; faces coloured by their mean distance
    c, s = np.cos(0.6), np.sin(0.6)
    W = V @ np.array([[c, 0, -s], [0, 1, 0], [s, 0, c]]).T
    lo, hi = W[:, :2].min(axis=0), W[:, :2].max(axis=0)
    scale = 0.9 * size / (hi - lo).max()
    xy = (W[:, :2] - lo) * scale + 0.05 * size
    xy[:, 1] = size - xy[:, 1]
    order = np.argsort(W[F, 2].mean(axis=1))
    fill = colour(d[F].mean(axis=1) / d[np.isfinite(d)].max())
    with open(path, "w") as out:
        out.write(f"<svg xmlns='http://www.w3.org/2000/svg' width='{size}' height='{size + 60}'>"
                  f"<rect width='100%' height='100%' fill='white'/>"
                  f"<text x='10' y='{size + 20}' font-family='sans-serif' font-size='14'>{title}</text>\n")
        out.write(legend(10, size + 30, d[np.isfinite(d)].max()))
        for f in order:
            pts = " ".join(f"{x:.1f},{y:.1f}" for x, y in xy[F[f]])
            out.write(f"<polygon points='{pts}' fill='{fill[f]}' stroke='{fill[f]}' stroke-width='0.3'/>\n")
        for v in sources:
            out.write(f"<circle cx='{xy[v, 0]:.1f}' cy='{xy[v, 1]:.1f}' r='4' fill='black'/>\n")
        out.write("</svg>\n")


def draw_matrix(D, labels, path, cell=36):
    k = len(D)
    fill = colour((D / D.max()).ravel())
    with open(path, "w") as out:
        out.write(f"<svg xmlns='http://www.w3.org/2000/svg' width='{cell * k + 80}' height='{cell * k + 110}' "
                  "font-family='sans-serif' font-size='10'><rect width='100%' height='100%' fill='white'/>\n")
        out.write(legend(60, cell * k + 75, D.max()))
        for i in range(k):
            out.write(f"<text x='4' y='{60 + cell * i + cell / 2:.0f}'>{labels[i]}</text>"
                      f"<text x='{60 + cell * i + 2}' y='50'>{labels[i]}</text>\n")
            for j in range(k):
                out.write(f"<rect x='{60 + cell * j}' y='{60 + cell * i}' width='{cell}' height='{cell}' "
                          f"fill='{fill[i * k + j]}'><title>{D[i, j]:.4f}</title></rect>\n")
        out.write("</svg>\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folder", nargs="?", default="mdcs-output")
    parser.add_argument("--mesh", default=None)
    args = parser.parse_args()
    (V, F), name = load(args.mesh)
    folder = args.folder
    os.makedirs(folder, exist_ok=True)
    mesh = mdcs.Mesh(V, F)                                      # prepared once, reused by every call below
    sources = np.linspace(0, len(V) - 1, 12).astype(int)
    field = mesh.distances(sources[0])                          # exact distances to every vertex
    D = mesh.distance_matrix(sources, sources, symmetric=True)  # 12 propagations on every core
    draw_field(V, F, field, sources[:1], f"exact geodesic distance from vertex {sources[0]} on {name}",
               os.path.join(folder, "distance_field.svg"))
    draw_matrix(D, [str(s) for s in sources], os.path.join(folder, "distance_matrix.svg"))
    print(f"{name}: {len(V)} vertices; farthest vertex from {sources[0]} at {np.max(field[np.isfinite(field)]):.4f}")
    print("distance matrix of vertices", sources.tolist())
    print(np.array2string(D, precision=3, max_line_width=150))
    print(f"pictures: {folder}/distance_field.svg, {folder}/distance_matrix.svg")


if __name__ == "__main__":
    main()
