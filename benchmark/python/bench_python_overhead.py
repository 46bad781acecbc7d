#!/usr/bin/env python3
# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The cost of the Python layer: mdcs.geodesics.Mesh.distances(source) against the same computation timed inside C++
(Surface._cpp_distances_seconds: the same pooled solver, propagation and copy of every vertex's distance, without
argument checks, GIL release, progress bridge and NumPy result). Single source, exact method, meshes of >= 10k
vertices. Interleaved: each round times one C++ run and one Python run from the same source, then the next source.

    PYTHONPATH=<build>/python python3 bench_python_overhead.py [--meshes ChineseDragon-10kv.off,man.off,armadillo.off]
        [--rounds 15] [--sources 5] [--method exact] [--csv FILE]

Prints per mesh the medians of both, wall-clock and CPU time of the calling thread (which runs the whole
computation; CPU time is less sensitive to other load), the overhead (Python / C++ - 1; the goal: <= 5%), and the
load.
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
    """Per round: (wall, thread CPU) seconds of the C++ anchor and of the Python call, in alternating order."""
    cpp, py = [], []
    for r in range(rounds):
        s = int(sources[r % len(sources)])
        for which in ((0, 1) if r % 2 == 0 else (1, 0)):
            if which == 0:
                cpp.append(mesh._surface._cpp_distances_seconds(s, method, 1)[0])
            else:
                wall, cpu = time.perf_counter(), time.thread_time()
                mesh.distances(s, method=method, progress=False)
                py.append((time.perf_counter() - wall, time.thread_time() - cpu))
    median = lambda xs, i: statistics.median(x[i] for x in xs)  # noqa: E731
    return median(cpp, 0), median(py, 0), median(cpp, 1), median(py, 1)


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
    print(f"{'mesh':24s} {'vertices':>9s} {'C++ wall s':>11s} {'Python wall s':>14s} {'overhead':>9s} "
          f"{'C++ CPU s':>10s} {'Python CPU s':>13s} {'CPU overhead':>13s}")
    for name in args.meshes.split(","):
        V, F = demo_mesh(name, args.mesh_dir)
        mesh = mdcs.Mesh(V, F)
        sources = np.linspace(0, len(V) - 1, args.sources).astype(int)
        mesh.distances(int(sources[0]), method=args.method, progress=False)  # warm the pool
        cpp, py, cpp_cpu, py_cpu = measure(mesh, sources, args.rounds, args.method)
        overhead, cpu_overhead = py / cpp - 1, py_cpu / cpp_cpu - 1
        print(f"{name:24s} {len(V):9d} {cpp:11.5f} {py:14.5f} {100 * overhead:8.2f}% {cpp_cpu:10.5f} {py_cpu:13.5f} "
              f"{100 * cpu_overhead:12.2f}%", flush=True)
        rows.append({"mesh": name, "vertices": len(V), "method": args.method, "rounds": args.rounds,
                     "cpp_wall_median_s": cpp, "python_wall_median_s": py, "overhead_wall": overhead,
                     "cpp_cpu_median_s": cpp_cpu, "python_cpu_median_s": py_cpu, "overhead_cpu": cpu_overhead})
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
