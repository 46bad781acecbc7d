#!/usr/bin/env python3
# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Dask scaling of mdcs.dask.distance_matrix: a LocalCluster of 1 worker process against one of 2 (one thread each,
each block computed on one thread), the same exact distance matrix from --sources sources on a mesh of at least
--min-vertices vertices (a demo mesh subdivided by Loop until it is that large). The goal: 2 workers >= 1.7x faster
than 1, with identical values.

    PYTHONPATH=<build>/python python3 bench_dask_scaling.py [--mesh man.off] [--min-vertices 200000]
        [--sources 200] [--rounds 1] [--block-size 10] [--csv FILE]
    python3 bench_dask_scaling.py --quick      # a check on small inputs (30k vertices, 12 sources)

Each timing covers what a user waits for: sending the mesh to the workers (prepared once per worker), the blocks,
and gathering the matrix; the clusters are started before the clock. Rounds alternate the two clusters. Prints the
medians, the speedup, whether the two matrices are identical (bit for bit), the worker processes' peak memory, and
the load.
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
import mdcs.dask  # noqa: E402
from bench_meshes import demo_mesh, subdivided  # noqa: E402


def peak_rss_mib(client):
    def rss():
        import resource

        return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0

    return max(client.run(rss).values())


def worker_cpu_seconds(client):
    """Processor time (user + system) of each worker process so far, keyed by worker address."""
    def cpu():
        import resource

        r = resource.getrusage(resource.RUSAGE_SELF)
        return r.ru_utime + r.ru_stime

    return client.run(cpu)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--mesh", default="man.off")
    parser.add_argument("--mesh-dir", default=None)
    parser.add_argument("--min-vertices", type=int, default=200000)
    parser.add_argument("--sources", type=int, default=200)
    parser.add_argument("--method", default="exact")
    parser.add_argument("--rounds", type=int, default=1)
    parser.add_argument("--block-size", type=int, default=10)
    parser.add_argument("--quick", action="store_true", help="small inputs: 30k vertices, 12 sources")
    parser.add_argument("--csv", default=None)
    args = parser.parse_args()
    if args.quick:
        args.min_vertices, args.sources, args.block_size = 30000, 12, 2

    from distributed import Client, LocalCluster

    V, F = demo_mesh(args.mesh, args.mesh_dir)
    V, F, steps = subdivided(V, F, args.min_vertices)
    mesh = mdcs.Mesh(V, F)
    sources = np.linspace(0, len(V) - 1, args.sources).astype(np.int64)
    print(f"mesh {args.mesh} after {steps} Loop step(s): {len(V)} vertices, {len(F)} faces; {len(sources)} sources, "
          f"method {args.method}, blocks of {args.block_size}; load {os.getloadavg()}", flush=True)

    clusters = {}
    for workers in (1, 2):
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                               dashboard_address="127.0.0.1:0", silence_logs=40)
        clusters[workers] = (cluster, Client(cluster))
    times = {1: [], 2: []}
    cpu_total = {1: [], 2: []}   # processor time of all workers together
    cpu_busiest = {1: [], 2: []}  # of the busiest worker: the wall time with free cores, serial parts aside
    results = {}
    try:
        for r in range(args.rounds):
            for workers in ((1, 2) if r % 2 == 0 else (2, 1)):
                client = clusters[workers][1]
                before = worker_cpu_seconds(client)
                start = time.perf_counter()
                D = mdcs.dask.distance_matrix(client, mesh, sources, method=args.method, block_size=args.block_size,
                                              progress=False)
                times[workers].append(time.perf_counter() - start)
                after = worker_cpu_seconds(client)
                spent = [after[w] - before[w] for w in after]
                cpu_total[workers].append(sum(spent))
                cpu_busiest[workers].append(max(spent))
                results[workers] = D
                print(f"round {r + 1}: {workers} worker(s) {times[workers][-1]:.2f} s, worker CPU "
                      f"{' + '.join(f'{x:.2f}' for x in spent)} s (load {os.getloadavg()[0]:.2f})", flush=True)
        memory = {w: peak_rss_mib(clusters[w][1]) for w in (1, 2)}
    finally:
        for cluster, client in clusters.values():
            client.close()
            cluster.close()

    t1, t2 = statistics.median(times[1]), statistics.median(times[2])
    c1, c2 = statistics.median(cpu_total[1]), statistics.median(cpu_total[2])
    b2 = statistics.median(cpu_busiest[2])
    identical = np.array_equal(results[1], results[2])
    print(f"1 worker: {t1:.2f} s, 2 workers: {t2:.2f} s, speedup {t1 / t2:.2f}x (goal >= 1.7x), identical values: "
          f"{identical}; worker peak RSS {memory[1]:.0f} / {memory[2]:.0f} MiB; load {os.getloadavg()}")
    # Under load the wall-clock ratio measures the machine's other users; the processor times do not: the work
    # must not grow with the second worker (c2 ~ c1), and it must be balanced (c1 / b2 near 2).
    print(f"worker processor time: 1 worker {c1:.2f} s, 2 workers {c2:.2f} s together ({c2 / c1 - 1:+.1%}), "
          f"busiest {b2:.2f} s; processor-time bound on the speedup {c1 / b2:.2f}x")
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["mesh", "vertices", "sources", "method", "block_size", "rounds", "one_worker_s",
                        "two_workers_s", "speedup", "identical", "worker_peak_rss_mib_1", "worker_peak_rss_mib_2",
                        "worker_cpu_1_s", "worker_cpu_2_s", "busiest_worker_cpu_2_s", "cpu_bound_speedup", "load1"])
            w.writerow([args.mesh, len(V), len(sources), args.method, args.block_size, args.rounds, t1, t2, t1 / t2,
                        identical, memory[1], memory[2], c1, c2, b2, c1 / b2, os.getloadavg()[0]])
    return 0 if identical else 1


if __name__ == "__main__":
    sys.exit(main())
