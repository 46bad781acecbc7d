#!/usr/bin/env python3
# Copyright (c) 2026 MDCS contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Exact geodesics side by side: MDCS's Exact_geodesic_distances_3 against VTP (Qin et al. 2016, the authors' code)
and Kirsanov's 2005 MMP library, on the same meshes, from the same source vertex, with the same timing.

The third-party code is not part of MDCS and never enters its repository. Place it in a folder of your own:

    THIRD_PARTY/VTP_source_code/       a copy of github.com/YipengQin/VTP_source_code
    THIRD_PARTY/<any name>/            Kirsanov's "geodesic" library: the folder holding geodesic_algorithm_exact.h
                                       and geodesic_algorithm_subdivision.h (for example pygeodesic's
                                       pygeodesic/geodesic_kirsanov/ or gdist's geodesic_library/)

and run, from a build folder configured with -DMDCS_BUILD_BENCHMARKS=ON (target bench_geodesics_side_by_side):

    run_side_by_side.py --third-party THIRD_PARTY --mdcs-bench build/benchmark/bench_geodesics_side_by_side \\
        --meshes armadillo,bunny00-loop1 --runs 5 --csv side_by_side.csv

The script compiles small drivers (vtp_driver.cpp, kirsanov_driver.cpp next to this script, MDCS code) against
those folders with g++ into --work (default THIRD_PARTY/side_by_side_work, outside the repository), converts each
mesh once to a binary file with the MDCS benchmark (Loop subdivision: NAME-loopK), and then runs every method in
its own process, interleaved: round 1 runs every method once, round 2 again (starting with the next method), and
so on. Each driver times the same section (its library's mesh structure built from the arrays, the propagation,
every vertex distance read, and in full_field mode the paths) and reports the peak resident set of that section.
The CSV has one row per mesh and method: medians over the rounds, the ratio of each MDCS mode to VTP and to
Kirsanov computed within each round (median of the per-round ratios, which cancels most of the noise of a shared
machine), the largest relative difference of the distances to MDCS's, and the load average during the rounds.
"""

import argparse
import csv
import math
import os
import resource
import shutil
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def find_library(root, is_wanted):
    for dirpath, dirnames, filenames in os.walk(root):
        if dirpath[len(root):].count(os.sep) > 4:
            dirnames[:] = []
            continue
        dirnames[:] = [d for d in dirnames if not d.startswith('.') and d != 'side_by_side_work']
        if 'geodesic_algorithm_exact.h' in filenames and is_wanted(dirpath, filenames):
            return dirpath
    return None


def is_vtp(dirpath, filenames):
    with open(os.path.join(dirpath, 'geodesic_algorithm_exact.h'), errors='replace') as f:
        return 'm_list_queue' in f.read()


def is_kirsanov(dirpath, filenames):
    return 'geodesic_algorithm_subdivision.h' in filenames and not is_vtp(dirpath, filenames)


def build_driver(name, library_dir, work, compiler):
    source = os.path.join(HERE, name + '.cpp')
    binary = os.path.join(work, 'bin', name)
    inputs = [source, os.path.join(HERE, 'side_by_side_driver.h')]
    inputs += [os.path.join(library_dir, f) for f in os.listdir(library_dir) if f.endswith('.h')]
    if os.path.exists(binary) and os.path.getmtime(binary) >= max(os.path.getmtime(p) for p in inputs):
        return binary
    os.makedirs(os.path.dirname(binary), exist_ok=True)
    # Both libraries are C++ of their time (std::auto_ptr in VTP): C++14 is the newest standard they compile with.
    command = [compiler, '-std=gnu++14', '-O3', '-DNDEBUG', '-w', '-I' + HERE, '-I' + library_dir, source, '-o', binary]
    print('building', name, ':', ' '.join(command), flush=True)
    subprocess.run(command, check=True)
    return binary


def parse_result(stdout):
    for line in stdout.splitlines():
        if line.startswith('RESULT'):
            values = {}
            for item in line.split()[1:]:
                key, _, value = item.partition('=')
                values[key] = value
            return values
    return None


def run_process(command, timeout_s, mem_limit_mib):
    def limit():
        if mem_limit_mib > 0:
            size = int(mem_limit_mib * 1024 * 1024)
            resource.setrlimit(resource.RLIMIT_AS, (size, size))
    started = time.time()
    try:
        p = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=timeout_s,
                           preexec_fn=limit)
    except subprocess.TimeoutExpired:
        return None, 'timeout after %.0f s' % timeout_s
    if p.returncode != 0:
        tail = (p.stderr.strip().splitlines() or ['(no message)'])[-1]
        kind = 'out of memory (address space above %.0f MiB)' % mem_limit_mib if 'bad_alloc' in p.stderr else \
            'exit code %d' % p.returncode
        return None, '%s after %.0f s: %s' % (kind, time.time() - started, tail[:200])
    result = parse_result(p.stdout)
    if result is None:
        return None, 'no RESULT line'
    return result, ''


def read_doubles(path):
    import array
    a = array.array('d')
    with open(path, 'rb') as f:
        a.frombytes(f.read())
    return a


def max_relative_difference(a, b):
    if len(a) != len(b):
        return math.inf, 'sizes differ'
    finite = [x for x in b if math.isfinite(x)]
    scale = max(finite) if finite else 1.0
    tiny = 1e-12 * scale
    worst, mismatch = 0.0, 0
    for x, y in zip(a, b):
        fx, fy = math.isfinite(x) and x < 1e300, math.isfinite(y) and y < 1e300
        if fx != fy:
            mismatch += 1
            continue
        if fx:
            worst = max(worst, abs(x - y) / max(abs(y), tiny))
    return (math.inf if mismatch else worst), ('%d vertices finite in one only' % mismatch if mismatch else '')


def loglog_slope(points):
    pts = [(math.log(x), math.log(y)) for x, y in points if x > 0 and y > 0 and math.isfinite(y)]
    if len(set(p[0] for p in pts)) < 2:
        return float('nan')
    n = len(pts)
    sx = sum(p[0] for p in pts)
    sy = sum(p[1] for p in pts)
    sxx = sum(p[0] ** 2 for p in pts)
    sxy = sum(p[0] * p[1] for p in pts)
    return (n * sxy - sx * sy) / (n * sxx - sx * sx)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--third-party', required=True, help='folder holding VTP_source_code and Kirsanov\'s library')
    ap.add_argument('--mdcs-bench', required=True, help='the bench_geodesics_side_by_side executable of an MDCS build')
    ap.add_argument('--work', help='build and data folder (default THIRD_PARTY/side_by_side_work)')
    ap.add_argument('--meshes', default='armadillo,bunny00,refined_elephant,armadillo-loop1,bunny00-loop1',
                    help='comma-separated NAME or NAME-loopK (CGAL demo meshes or --extra-dir files)')
    ap.add_argument('--mesh-dir', help='folder of the CGAL demo meshes (default: the MDCS build\'s)')
    ap.add_argument('--extra-dir', help='another folder of meshes, e.g. ../shared/data')
    ap.add_argument('--runs', type=int, default=5, help='rounds (every method once per round)')
    ap.add_argument('--methods', default='MDCS:distances_only,MDCS:full_field,MDCS:full_field_windows,VTP:distances_only,Kirsanov:full_field',
                    help='LIBRARY:MODE[:THREADS] list; libraries MDCS, VTP, Kirsanov')
    ap.add_argument('--paths', type=int, default=10, help='shortest paths traced in full_field mode')
    ap.add_argument('--source', type=int, default=0, help='source vertex')
    ap.add_argument('--kirsanov-max-vertices', type=int, default=300000,
                    help='skip Kirsanov above this size (it needs about 7 GB at 600k vertices)')
    ap.add_argument('--vtp-max-vertices', type=int, default=3000000)
    ap.add_argument('--timeout', type=float, default=3600, help='seconds per run')
    ap.add_argument('--mem-limit-mib', type=float, default=7000, help='address-space limit of each run')
    ap.add_argument('--compiler', default=os.environ.get('CXX', 'g++'))
    ap.add_argument('--csv', default='side_by_side.csv')
    ap.add_argument('--raw-csv', help='also write every single run')
    args = ap.parse_args()

    third_party = os.path.abspath(args.third_party)
    work = os.path.abspath(args.work or os.path.join(third_party, 'side_by_side_work'))
    os.makedirs(work, exist_ok=True)
    methods = []
    for item in args.methods.split(','):
        parts = item.split(':')
        library, mode = parts[0], parts[1] if len(parts) > 1 else 'distances_only'
        threads = int(parts[2]) if len(parts) > 2 else 1
        methods.append((library, mode, threads))
    libraries = set(m[0] for m in methods)

    drivers = {'MDCS': os.path.abspath(args.mdcs_bench)}
    if not os.path.exists(drivers['MDCS']):
        sys.exit('no MDCS benchmark at %s (build the target bench_geodesics_side_by_side)' % drivers['MDCS'])
    if 'VTP' in libraries:
        vtp = find_library(third_party, is_vtp)
        if vtp is None:
            sys.exit('no VTP source (a folder with VTP\'s geodesic_algorithm_exact.h) under ' + third_party)
        drivers['VTP'] = build_driver('vtp_driver', vtp, work, args.compiler)
    if 'Kirsanov' in libraries:
        kirsanov = find_library(third_party, is_kirsanov)
        if kirsanov is None:
            sys.exit('no Kirsanov library (geodesic_algorithm_exact.h with geodesic_algorithm_subdivision.h) under ' +
                     third_party)
        drivers['Kirsanov'] = build_driver('kirsanov_driver', kirsanov, work, args.compiler)

    rows, raw = [], []
    for name in args.meshes.split(','):
        mesh_file = os.path.join(work, 'meshes', name + '.bin')
        os.makedirs(os.path.dirname(mesh_file), exist_ok=True)
        command = [drivers['MDCS'], 'prepare', '--name', name, '--out', mesh_file]
        if args.mesh_dir:
            command += ['--mesh-dir', args.mesh_dir]
        if args.extra_dir:
            command += ['--extra-dir', args.extra_dir]
        if not os.path.exists(mesh_file):
            p = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            if p.returncode != 0:
                print('skipping', name, ':', p.stderr.strip(), flush=True)
                continue
        with open(mesh_file, 'rb') as f:
            header = f.read(24)
        vertices = int.from_bytes(header[8:16], 'little')
        print('%s: %d vertices' % (name, vertices), flush=True)

        runnable = []
        notes = {}
        for m in methods:
            if m[0] == 'Kirsanov' and vertices > args.kirsanov_max_vertices:
                notes[m] = 'skipped: %d vertices > --kirsanov-max-vertices' % vertices
            elif m[0] == 'VTP' and vertices > args.vtp_max_vertices:
                notes[m] = 'skipped: %d vertices > --vtp-max-vertices' % vertices
            else:
                runnable.append(m)
        results = {m: [] for m in methods}
        failed = set()
        distances = {}
        for r in range(args.runs):
            order = runnable[r % len(runnable):] + runnable[:r % len(runnable)] if runnable else []
            for m in order:
                if m in failed:
                    continue
                library, mode, threads = m
                dist_file = os.path.join(work, 'distances', '%s_%s_%s_%d.bin' % (name, library, mode, threads))
                os.makedirs(os.path.dirname(dist_file), exist_ok=True)
                command = [drivers[library]]
                if library == 'MDCS':
                    command.append('run')
                command += ['--mesh', mesh_file, '--source', str(args.source), '--mode', mode]
                if mode.startswith('full_field'):
                    command += ['--paths', str(args.paths)]
                if threads != 1:
                    command += ['--threads', str(threads)]
                if r == 0:
                    command += ['--distances-out', dist_file]
                load = os.getloadavg()[0]
                result, failure = run_process(command, args.timeout, args.mem_limit_mib)
                label = '%s %s%s' % (library, mode, '' if threads == 1 else ' %d threads' % threads)
                if result is None:
                    print('  round %d, %s: FAILED: %s' % (r + 1, label, failure), flush=True)
                    failed.add(m)
                    notes[m] = 'FAILED: ' + failure
                    continue
                result['load'] = load
                result['round'] = r
                results[m].append(result)
                raw.append(dict(mesh=name, vertices=vertices, library=library, mode=mode, threads=threads, round=r + 1,
                                time_s=result['time_s'], cpu_s=result.get('cpu_s', ''), peak_mib=result['peak_mib'],
                                load=load))
                if r == 0:
                    distances[m] = dist_file
                print('  round %d, %s: %.4g s (cpu %.4g s), %.1f MiB, load %.1f' % (
                    r + 1, label, float(result['time_s']), float(result.get('cpu_s', 'nan')),
                    float(result['peak_mib']), load), flush=True)

        reference = next((distances[m] for m in methods if m in distances and m[0] == 'MDCS'), None)
        ref_values = read_doubles(reference) if reference else None

        def per_round(m):
            return {res['round']: float(res['time_s']) for res in results[m]}

        anchors = {lib: next((m for m in runnable if m[0] == lib and m in results and results[m]), None)
                   for lib in ('VTP', 'Kirsanov')}
        for m in methods:
            library, mode, threads = m
            res = results[m]
            row = dict(mesh=name, vertices=vertices, library=library, mode=mode, threads=threads, runs=len(res))
            if res:
                times = [float(x['time_s']) for x in res]
                row['time_s'] = statistics.median(times)
                row['time_min_s'] = min(times)
                row['time_max_s'] = max(times)
                cpus = [float(x['cpu_s']) for x in res if 'cpu_s' in x]
                row['cpu_s'] = statistics.median(cpus) if cpus else ''
                row['peak_mib'] = statistics.median(float(x['peak_mib']) for x in res)
                row['load_median'] = statistics.median(x['load'] for x in res)
                for key in ('windows_created', 'windows_propagated', 'stored_windows', 'path_length_sum'):
                    if key in res[0]:
                        row[key] = res[0][key]
                for lib, anchor in anchors.items():
                    if anchor is None or anchor == m:
                        continue
                    mine, theirs = per_round(m), per_round(anchor)
                    ratios = [mine[k] / theirs[k] for k in mine if k in theirs and theirs[k] > 0]
                    if ratios:
                        row['ratio_to_' + lib] = statistics.median(ratios)
                        row['ratio_to_%s_range' % lib] = '%.3f-%.3f' % (min(ratios), max(ratios))
                    anchor_rows = results[anchor]
                    row['peak_ratio_to_' + lib] = row['peak_mib'] / statistics.median(
                        float(x['peak_mib']) for x in anchor_rows)
                if ref_values is not None and m in distances:
                    diff, note = max_relative_difference(read_doubles(distances[m]), ref_values)
                    row['max_rel_diff_to_MDCS'] = diff
                    if note:
                        notes[m] = (notes.get(m, '') + '; ' + note).strip('; ')
            row['note'] = notes.get(m, '')
            rows.append(row)

    columns = ['mesh', 'vertices', 'library', 'mode', 'threads', 'runs', 'time_s', 'time_min_s', 'time_max_s', 'cpu_s',
               'peak_mib', 'ratio_to_VTP', 'ratio_to_VTP_range', 'ratio_to_Kirsanov', 'ratio_to_Kirsanov_range',
               'peak_ratio_to_VTP', 'peak_ratio_to_Kirsanov', 'max_rel_diff_to_MDCS', 'windows_created',
               'windows_propagated', 'stored_windows', 'path_length_sum', 'load_median', 'note']

    def cell(v):
        if isinstance(v, float):
            return '%.4g' % v
        return str(v)

    if args.csv:
        os.makedirs(os.path.dirname(os.path.abspath(args.csv)), exist_ok=True)
        with open(args.csv, 'w', newline='') as f:
            w = csv.writer(f)
            w.writerow(columns)
            for row in rows:
                w.writerow([cell(row.get(c, '')) for c in columns])
        print('\nCSV:', args.csv)
    if args.raw_csv:
        with open(args.raw_csv, 'w', newline='') as f:
            keys = ['mesh', 'vertices', 'library', 'mode', 'threads', 'round', 'time_s', 'cpu_s', 'peak_mib', 'load']
            w = csv.DictWriter(f, fieldnames=keys)
            w.writeheader()
            for row in raw:
                w.writerow(row)

    shown = ['mesh', 'vertices', 'library', 'mode', 'threads', 'time_s', 'cpu_s', 'peak_mib', 'ratio_to_VTP',
             'ratio_to_Kirsanov', 'max_rel_diff_to_MDCS', 'load_median', 'note']
    print()
    print(' | '.join(shown))
    for row in rows:
        print(' | '.join(cell(row.get(c, '')) for c in shown))
    print('\nGrowth exponents (least-squares slope of log(time) against log(vertices)):')
    for m in methods:
        pts = [(r['vertices'], r['time_s']) for r in rows
               if (r['library'], r['mode'], r['threads']) == m and 'time_s' in r]
        cpu = [(r['vertices'], float(r['cpu_s'])) for r in rows
               if (r['library'], r['mode'], r['threads']) == m and r.get('cpu_s', '') != '']
        print('  %s %s %d thread(s): time n^%.2f, CPU n^%.2f over %d meshes' % (
            m[0], m[1], m[2], loglog_slope(pts), loglog_slope(cpu), len(pts)))


if __name__ == '__main__':
    main()
