#!/usr/bin/env python3
"""Runs the command-line cases of the mdcs tool: each case is a command line, the exit code it must give, and a
time limit. A case fails when the exit code differs, the time limit passes (a hang), a sanitizer reports anything
(AddressSanitizer, UndefinedBehaviorSanitizer, LeakSanitizer: their exit codes are moved away from the tool's
own 0-4 and their reports looked for on stderr), or the process dies of a signal (a crash).

Case files (test/cli/cases_*.txt), one case per line, fields separated by '|' (which arguments cannot contain):
    name | exit code | seconds | arguments after `mdcs` | optional checks
Blank lines and lines starting with '#' are ignored. In the arguments, {in} is test/cli/inputs, {tmp} a fresh
scratch folder of the case, {cgal} CGAL's mesh folder (cases that use it are skipped when it is missing).
Arguments are split like a shell would (shlex), without a shell. Checks, separated by ';':
    stderr~TEXT      stderr contains TEXT              stdout~TEXT   stdout contains TEXT
    file:PATH        PATH (with placeholders) exists   nofile:PATH   PATH does not exist
    nostderr~TEXT    stderr does not contain TEXT      contains:PATH~TEXT   the file PATH contains TEXT
    fsize:BYTES      run with a file size limit (RLIMIT_FSIZE): writes beyond BYTES fail like a full disk
    json:PATH:KEY=V  the JSON file PATH has V (compared as text) at the dotted KEY, e.g. results.reachable_vertices
    also:ARGUMENTS   before the other checks, run mdcs again with these arguments in the same scratch folder (it
                     must exit 0 without a sanitizer report): a second run whose outputs serve as an oracle
    plydist:PATH:V=D~TOL     vertex V of the PLY file PATH (the `distance` property, as in distances.ply) has
                             the distance D within TOL (absolute); D = -1 means unreachable
    plydist:PATH=PATH2~TOL   every vertex of PATH has, within TOL, the distance of the same vertex of PATH2 (which
                             may have more vertices: e.g. a double cover that numbers its first sheet like PATH)
    npyrow:NPY:ROW=PLY~TOL   row ROW of the float64 .npy matrix NPY equals, within TOL, the distances of the PLY
                             file PLY (inf in the matrix = -1 in the PLY: unreachable)
    same:PATH=PATH2          the files PATH and PATH2 are byte for byte the same (e.g. the outputs of an `also:` run
                             that reaches the same result another way)

usage: run_cli_cases.py MDCS_EXECUTABLE CASE_FILE... [--cgal DIR] [--memory-mib N] [--filter TEXT] [--list]
The memory limit (address space, default 4096 MiB) is not applied to sanitizer builds, whose shadow memory
needs far more address space; there the time limit still catches unbounded growth.
"""
import argparse
import json
import os
import resource
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SANITIZER_EXIT = {"asan": 86, "ubsan": 87, "lsan": 88}
SANITIZER_MARKS = ("ERROR: AddressSanitizer", "runtime error:", "ERROR: LeakSanitizer", "SUMMARY: UndefinedBehaviorSanitizer",
                   "WARNING: ThreadSanitizer")


def parse_cases(path):
    cases = []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if not line.strip() or line.lstrip().startswith("#"):
                continue
            fields = [x.strip() for x in line.split("|")]
            if len(fields) not in (4, 5):
                raise SystemExit(f"{path}:{number}: expected 'name | exit | seconds | arguments [| checks]'")
            name, code, seconds, args = fields[:4]
            checks = [c.strip() for c in fields[4].split(";") if c.strip()] if len(fields) == 5 else []
            cases.append(dict(name=name, code=int(code), seconds=float(seconds), args=args, checks=checks,
                              where=f"{os.path.basename(path)}:{number}"))
    return cases


def read_ply_distances(path):
    """The `distance` property of every vertex of an ASCII PLY file (distances.ply)."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    vertices, properties, column, body = 0, [], None, 0
    element = None
    for i, line in enumerate(lines):
        words = line.split()
        if words[:1] == ["element"]:
            element = words[1]
            if element == "vertex":
                vertices = int(words[2])
        elif words[:1] == ["property"] and element == "vertex":
            properties.append(words[-1])
        elif words[:1] == ["end_header"]:
            body = i + 1
            break
    column = properties.index("distance")
    return [float(lines[body + k].split()[column]) for k in range(vertices)]


def read_npy_row(path, row):
    """Row `row` of a 2-D little-endian float64 .npy file in C order (numpy.save's format), without NumPy."""
    import ast
    import struct
    with open(path, "rb") as f:
        data = f.read()
    if data[:6] != b"\x93NUMPY":
        raise ValueError("not a .npy file")
    major = data[6]
    length, start = (struct.unpack("<H", data[8:10])[0], 10) if major == 1 else (struct.unpack("<I", data[8:12])[0], 12)
    header = ast.literal_eval(data[start:start + length].decode("latin1"))
    if header["descr"] != "<f8" or header["fortran_order"] or len(header["shape"]) != 2:
        raise ValueError(f"unsupported .npy header {header}")
    rows, columns = header["shape"]
    if not 0 <= row < rows:
        raise IndexError(f"row {row} of {rows}")
    offset = start + length + 8 * columns * row
    return list(struct.unpack(f"<{columns}d", data[offset:offset + 8 * columns]))


def check_npy_row(kind, value, tmp):
    """The npyrow check (see the module's doc); returns a problem or None."""
    spec = kind[len("npyrow:"):]
    try:
        npy_path, _, rest = spec.partition(":")
        row, _, ply_path = rest.partition("=")
        got = read_npy_row(os.path.join(tmp, npy_path), int(row))
        want = [d if d >= 0 else float("inf") for d in read_ply_distances(os.path.join(tmp, ply_path))]
        if len(got) != len(want):
            return f"row {row} of {npy_path} has {len(got)} columns, {ply_path} {len(want)} vertices"
        tol = float(value)
        for k, (a, b) in enumerate(zip(got, want)):
            if not (a == b or abs(a - b) <= tol):
                return f"{npy_path} ({row}, {k}) is {a!r}, {ply_path} has {b!r} (tolerance {tol:g})"
        return None
    except (OSError, ValueError, IndexError, KeyError, SyntaxError) as e:
        return f"cannot check {spec} ({e})"


def check_ply_distances(kind, value, tmp):
    """The plydist checks (see the module's doc); returns a problem or None."""
    spec = kind[len("plydist:"):]
    tol = float(value)
    try:
        def is_number(text):
            try:
                float(text)
                return True
            except ValueError:
                return False
        if not is_number(spec.rpartition("=")[2]):
            a_path, _, b_path = spec.partition("=")
            a = read_ply_distances(os.path.join(tmp, a_path))
            b = read_ply_distances(os.path.join(tmp, b_path))
            if len(b) < len(a):
                return f"{b_path} has {len(b)} vertices, fewer than the {len(a)} of {a_path}"
            worst = max(range(len(a)), key=lambda k: abs(a[k] - b[k]), default=None)
            if worst is not None and abs(a[worst] - b[worst]) > tol:
                return f"vertex {worst}: {a[worst]!r} in {a_path}, {b[worst]!r} in {b_path} (tolerance {tol:g})"
            return None
        path, _, assignment = spec.rpartition(":")
        vertex, _, wanted = assignment.partition("=")
        d = read_ply_distances(os.path.join(tmp, path))
        got, want = d[int(vertex)], float(wanted)
        if abs(got - want) > tol:
            return f"{path}: vertex {vertex} has distance {got!r}, expected {want!r} (tolerance {tol:g})"
        return None
    except (OSError, ValueError, IndexError) as e:
        return f"cannot check {spec} ({e})"


def substitute(text, tmp, cgal):
    return text.replace("{in}", os.path.join(HERE, "inputs")).replace("{tmp}", tmp).replace("{cgal}", cgal or "")


# How much longer a case may take when mdcs is a sanitizer build (ASan+UBSan at -O1).
SANITIZER_TIME_FACTOR = 6

def run_case(exe, case, cgal, memory_mib, sanitized):
    if "{cgal}" in case["args"] and not cgal:
        return "skip", "no CGAL mesh folder"
    tmp = tempfile.mkdtemp(prefix="mdcs-cli-")
    try:
        args = [exe] + shlex.split(substitute(case["args"], tmp, cgal))
        env = dict(os.environ)
        env["ASAN_OPTIONS"] = f"exitcode={SANITIZER_EXIT['asan']}:detect_leaks=1:abort_on_error=0"
        env["UBSAN_OPTIONS"] = f"exitcode={SANITIZER_EXIT['ubsan']}:print_stacktrace=1:halt_on_error=1"
        env["LSAN_OPTIONS"] = f"exitcode={SANITIZER_EXIT['lsan']}"

        fsize = [int(c.partition(":")[2]) for c in case["checks"] if c.startswith("fsize:")]

        def limits():
            os.setsid()
            if not sanitized and memory_mib > 0:
                limit = memory_mib * 1024 * 1024
                resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
            if fsize:
                resource.setrlimit(resource.RLIMIT_FSIZE, (fsize[0], fsize[0]))

        start = time.monotonic()
        proc = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=tmp, env=env,
                                preexec_fn=limits)
        # A sanitizer build (-O1, instrumented) runs several times slower than Release: its limits are scaled, so
        # that a limit still separates a slow run from a hang or unbounded work without failing on a busy machine.
        limit = case["seconds"] * (SANITIZER_TIME_FACTOR if sanitized else 1)
        try:
            out, err = proc.communicate(timeout=limit)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.communicate()
            return "fail", f"no exit within {limit:g} s (hang or unbounded work)"
        elapsed = time.monotonic() - start
        out = out.decode("utf-8", "replace")
        err = err.decode("utf-8", "replace")
        problems = []
        if proc.returncode < 0:
            problems.append(f"killed by signal {-proc.returncode} (crash)")
        for mark in SANITIZER_MARKS:
            if mark in err:
                problems.append(f"sanitizer report ({mark})")
                break
        if proc.returncode != case["code"] and proc.returncode >= 0:
            problems.append(f"exit code {proc.returncode}, expected {case['code']}")
        for check in case["checks"]:
            if not check.startswith("also:"):
                continue
            also = [exe] + shlex.split(substitute(check[len("also:"):], tmp, cgal))
            try:
                second = subprocess.run(also, stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=tmp, env=env,
                                        preexec_fn=limits, timeout=limit)
            except subprocess.TimeoutExpired:
                problems.append(f"'{check}': no exit within {limit:g} s")
                continue
            second_err = second.stderr.decode("utf-8", "replace")
            if second.returncode != 0 or any(mark in second_err for mark in SANITIZER_MARKS):
                problems.append(f"'{check}' exited with {second.returncode}: {second_err.strip()[-300:]}")
        for check in case["checks"]:
            if check.startswith("also:"):
                continue
            kind, _, value = check.partition("~") if "~" in check else check.partition(":")
            value = substitute(value, tmp, cgal)
            if kind == "stderr" and value not in err:
                problems.append(f"stderr lacks '{value}'")
            elif kind == "stdout" and value not in out:
                problems.append(f"stdout lacks '{value}'")
            elif kind == "file" and not os.path.exists(os.path.join(tmp, value)):
                problems.append(f"file '{value}' missing")
            elif kind == "nofile" and os.path.exists(os.path.join(tmp, value)):
                problems.append(f"file '{value}' should not exist")
            elif kind == "nostderr" and value in err:
                problems.append(f"stderr has '{value}'")
            elif kind.startswith("npyrow:"):
                problem = check_npy_row(kind, value, tmp)
                if problem:
                    problems.append(problem)
            elif kind.startswith("plydist:"):
                problem = check_ply_distances(kind, value, tmp)
                if problem:
                    problems.append(problem)
            elif kind.startswith("contains:"):
                path = substitute(kind[len("contains:"):], tmp, cgal)
                try:
                    with open(os.path.join(tmp, path), encoding="utf-8", errors="replace") as f:
                        if value not in f.read():
                            problems.append(f"file '{path}' lacks '{value}'")
                except OSError as e:
                    problems.append(f"cannot read '{path}' ({e})")
            elif kind == "same":
                first, _, second = value.partition("=")
                try:
                    with open(os.path.join(tmp, first), "rb") as f, open(os.path.join(tmp, second), "rb") as g:
                        if f.read() != g.read():
                            problems.append(f"files '{first}' and '{second}' differ")
                except OSError as e:
                    problems.append(f"cannot compare '{first}' and '{second}' ({e})")
            elif kind == "json":
                path, _, expected = value.rpartition(":")
                key, _, wanted = expected.partition("=")
                try:
                    with open(os.path.join(tmp, path), encoding="utf-8") as f:
                        node = json.load(f)
                    for part in key.split("."):
                        node = node[int(part)] if isinstance(node, list) else node[part]
                    got = json.dumps(node) if not isinstance(node, str) else node
                    if got != wanted:
                        problems.append(f"{path}: {key} is {got}, expected {wanted}")
                except (OSError, ValueError, KeyError, IndexError, TypeError) as e:
                    problems.append(f"{path}: cannot read {key} ({e})")
            elif kind not in ("stderr", "stdout", "file", "nofile", "fsize", "nostderr", "same") and not kind.startswith(("contains:", "plydist:", "npyrow:")):
                problems.append(f"unknown check '{check}'")
        if problems:
            tail = "\n      ".join(err.strip().splitlines()[-6:])
            return "fail", "; ".join(problems) + f" [{elapsed:.2f} s]\n      stderr: {tail}"
        return "pass", f"{elapsed:.2f} s"
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("exe")
    parser.add_argument("case_files", nargs="+")
    parser.add_argument("--cgal", default="")
    parser.add_argument("--memory-mib", type=int, default=4096)
    parser.add_argument("--filter", default="")
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--sanitized", action="store_true", help="the executable is a sanitizer build")
    a = parser.parse_args()
    a.exe = os.path.abspath(a.exe)
    cgal = a.cgal if a.cgal and os.path.isdir(a.cgal) else ""
    cases = [c for f in a.case_files for c in parse_cases(f) if a.filter in c["name"]]
    if a.list:
        for c in cases:
            print(f"{c['where']}: {c['name']}")
        return 0
    failed = skipped = 0
    for c in cases:
        status, detail = run_case(a.exe, c, cgal, a.memory_mib, a.sanitized)
        print(f"{status:4} {c['name']} ({c['where']}): {detail}", flush=True)
        failed += status == "fail"
        skipped += status == "skip"
    print(f"{len(cases) - failed - skipped} passed, {failed} failed, {skipped} skipped of {len(cases)} cases")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
