#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""The render time of a validation matrix with one build against another's, in one session.

    python3 integrators/bench/matrix_time.py --baseline DIR --candidate DIR --matrix FILE [--rounds K (3)]
        [--threads T (2)]

Each DIR is a build tree (or a copy of one) holding bin/stipple-validate and lib/libstipple.so.1, or that
bin/stipple-validate itself. Each build first makes the references the matrix needs in a cache folder of its own
(--references-only, not timed: the reference cache keys on the renderer's sources, so two builds never share
references). Then the two builds run the whole matrix in alternation, K rounds (the order flips every round: ABBA...),
so that the load of a shared machine falls on both alike. A run's times are the sums over its results.json rows of
render_seconds (wall clock of each cell's render) and cpu_seconds (the CPU time of the render's threads), and the
wall clock of the whole stipple-validate process. Per build: the median of each; per time: the median of the
per-round ratios candidate / baseline and, with K >= 6, a distribution-free 95 % interval of it (as
render_compare.py). The load average (1 min) before and after is printed with them.

A run whose checks fail (exit status 1, e.g. a timing claim on a loaded machine) still counts: its results.json is
complete. Any other status stops the benchmark.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

sys.dont_write_bytecode = True  # no __pycache__ beside the scripts in a source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from render_compare import load_average, median_interval  # noqa: E402


def validate_exe(path):
    """bin/stipple-validate of a build tree, given as the tree or as the program itself."""
    if os.path.basename(path) == "stipple-validate" and os.path.isfile(path):
        return os.path.abspath(path)
    return os.path.join(path, "bin", "stipple-validate")


def run(cmd):
    start = time.monotonic()
    proc = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.monotonic() - start
    if proc.returncode not in (0, 1):
        sys.exit(f"matrix_time: {' '.join(cmd)} exited with {proc.returncode}: {proc.stderr.strip()[-2000:]}")
    return wall


def matrix_times(exe, matrix, threads, cache, out_dir):
    """(sum of render_seconds, sum of cpu_seconds, wall seconds) of one whole run of the matrix."""
    wall = run([exe, matrix, "-o", out_dir, "--cache", cache, "--threads", str(threads), "-q"])
    with open(os.path.join(out_dir, "results.json")) as f:
        rows = json.load(f)["rows"]
    if not rows:
        sys.exit(f"matrix_time: {out_dir}/results.json has no rows")
    return sum(r["render_seconds"] for r in rows), sum(r["cpu_seconds"] for r in rows), wall


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--baseline", required=True, help="build tree with bin/stipple-validate (the reference)")
    parser.add_argument("--candidate", required=True, help="build tree with bin/stipple-validate (the one measured)")
    parser.add_argument("--matrix", required=True, help="the matrix file (e.g. validation/quick.yaml)")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--threads", type=int, default=2)
    o = parser.parse_args(argv)
    if o.rounds < 1:
        sys.exit("matrix_time: --rounds must be at least 1")
    if o.threads < 1:
        sys.exit("matrix_time: --threads must be at least 1")
    exes = {"baseline": validate_exe(o.baseline), "candidate": validate_exe(o.candidate)}
    for exe in exes.values():
        if not os.access(exe, os.X_OK):
            sys.exit(f"matrix_time: no executable {exe}")
    if not os.path.isfile(o.matrix):
        sys.exit(f"matrix_time: no matrix file {o.matrix}")
    matrix = os.path.abspath(o.matrix)

    with tempfile.TemporaryDirectory(prefix="matrix_time.") as work:
        caches = {which: os.path.join(work, "cache-" + which) for which in exes}
        for which, exe in exes.items():
            run([exe, matrix, "-o", os.path.join(work, "references-" + which), "--cache", caches[which],
                 "--threads", str(o.threads), "--references-only", "-q"])
        load_before = load_average()
        times = {which: [] for which in exes}
        for r in range(o.rounds):
            order = ("baseline", "candidate") if r % 2 == 0 else ("candidate", "baseline")
            for which in order:
                out_dir = os.path.join(work, f"run-{which}-{r}")
                times[which].append(matrix_times(exes[which], matrix, o.threads, caches[which], out_dir))
        load_after = load_average()

    print(f"{os.path.basename(o.matrix)}: {o.rounds} alternating rounds, {o.threads} threads; "
          f"{os.cpu_count()} hardware threads; load (1 min) {load_before:.2f} before, {load_after:.2f} after")
    print("| time | baseline s (median) | candidate s (median) | ratio (median) | 95 % interval |")
    print("|---|---|---|---|---|")
    for k, label in enumerate(("cells' render (wall)", "cells' render (CPU)", "whole run (wall)")):
        base = [t[k] for t in times["baseline"]]
        cand = [t[k] for t in times["candidate"]]
        ratios = [c / b for b, c in zip(base, cand)]
        interval = median_interval(ratios)
        shown = f"{interval[0]:.3f}-{interval[1]:.3f}" if interval else "(needs 6 rounds)"
        print(f"| {label} | {statistics.median(base):.3f} | {statistics.median(cand):.3f} | "
              f"{statistics.median(ratios):.3f} | {shown} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
