#!/usr/bin/env python3
# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The cost of the Python layer: mdcs.geodesics.Mesh.distances(source) against the same computation timed inside C++
(Surface._cpp_distances_seconds: the same pooled solver, propagation and copy of every vertex's distance, without
argument checks, GIL release, progress bridge and NumPy result). Single source, exact method, meshes of >= 10k
vertices. Interleaved: each round times one C++ run and one Python run from the same source, then the next source.

    PYTHONPATH=<build>/python python3 bench_python_overhead.py [--meshes ChineseDragon-10kv.off,man.off,armadillo.off]
        [--rounds 15] [--sources 5] [--method exact] [--csv FILE]

Prints per mesh the medians of both and the overhead (Python / C++ - 1; the goal: <= 5%), and the load.
"""

import argparse
import csv
import os
import statistics
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mdcs  # noqa: E402
from bench_meshes import demo_mesh  # noqa: E402


def measure(mesh, sources, rounds, method):
    cpp, py = [], []
    for r in range(rounds):
        s = int(sources[r % len(sources)])
        order = (0, 1) if r % 2 == 0 else (1, 0)  # alternate which goes first
        for which in order:
            if which == 0:
                cpp.append(mesh._surface._cpp_distances_seconds(s, method, 1)[0])
            else:
                t = time.perf_counter()
                mesh.distances(s, method=method, progress=False)
                py.append(time.perf_counter() - t)
    return statistics.median(cpp), statistics.median(py), cpp, py


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--meshes", default="ChineseDragon-10kv.off,man.off,armadillo.off")
    parser.add_argument("--mesh-dir", default=None)
    parser.add_argument("--rounds", type=int, default=15)
    parser.add_argument("--sources", type=int, default=5)
    parser.add_argument("--method", default="exact")
    parser.add_argument("--csv", default=None)
    args = parser.parse_args()
    rows = []
    print(f"load before: {os.getloadavg()}; mdcs {mdcs.__version__}, method {args.method}, {args.rounds} rounds")
    print(f"{'mesh':28s} {'vertices':>9s} {'C++ median s':>13s} {'Python median s':>16s} {'overhead':>9s}")
    for name in args.meshes.split(","):
        V, F = demo_mesh(name, args.mesh_dir)
        mesh = mdcs.Mesh(V, F)
        sources = np.linspace(0, len(V) - 1, args.sources).astype(int)
        mesh.distances(int(sources[0]), method=args.method, progress=False)  # warm the pool
        cpp, py, _, _ = measure(mesh, sources, args.rounds, args.method)
        overhead = py / cpp - 1
        print(f"{name:28s} {len(V):9d} {cpp:13.5f} {py:16.5f} {100 * overhead:8.2f}%")
        rows.append({"mesh": name, "vertices": len(V), "method": args.method, "rounds": args.rounds,
                     "cpp_median_s": cpp, "python_median_s": py, "overhead": overhead})
    load = os.getloadavg()
    print(f"load after: {load}")
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0]) + ["load1"])
            w.writeheader()
            for r in rows:
                w.writerow({**r, "load1": load[0]})


if __name__ == "__main__":
    main()
