#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""Samples per second of one stipple-render build against another's, per scene and integrator, in one session.

    python3 integrators/bench/render_compare.py --baseline DIR --candidate DIR [--rounds K (7)]
        [--scenes-dir DIR] [--cases SCENE:INTEGRATOR:SPP,...] [--threads T (2)] [--shim LIB] [--bound B]

Each DIR is a build tree (or a copy of one, or its bin/stipple-render) holding bin/stipple-render and
lib/libstipple.so.1. Per case the two
builds run in alternation, K rounds of one process each (the order flips every round: ABBA...), so that the load of
a shared machine falls on both alike. A run's rate is the image's samples (width x height x spp) over the render
time the program reports (wall clock, scene loading and the BVH build excluded); beside it, the rate per CPU second
of rendering, which time-slicing with other processes does not inflate: the process's CPU time (getrusage of the
child, user + system) minus that of the same build rendering 1 spp (the median of 3 such runs per case and build:
program start, scene loading, BVH build and one sample per pixel). Per case: each build's median rate, the
median of the per-round ratios candidate / baseline, and a distribution-free 95 % interval of that median (order
statistics of the K ratios, binomial coverage >= 95 %; K >= 6 is needed for one). The load average (1 min) before
and after every case is printed with it. With --bound, exit status 1 when some case's interval does not lie
entirely above the bound (e.g. --bound 1.2).

By default both builds load their own libstipple (what a user of each build gets); --shim gives both the same one,
so that only the renderers differ. The images are written to a temporary folder and deleted.
"""
import argparse
import math
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile

# The four scenes with the integrator each is made for, and the path tracer on each; the spp keep a run near one
# CPU second of rendering on the machine the project is developed on.
DEFAULT_CASES = [
    ("cornell-box", "path", 16),
    ("cornell-box", "bdpt", 4),
    ("veach-mis", "direct", 32),
    ("veach-mis", "path", 16),
    ("veach-bidir", "bdpt", 4),
    ("veach-bidir", "path", 16),
    ("italian-city", "bdpt", 4),
    ("italian-city", "path", 8),
]

RENDER_LINE = re.compile(r"^render ([0-9.eE+-]+) s \((\d+)x(\d+), (\d+) spp")


def load_average():
    with open("/proc/loadavg") as f:
        return float(f.read().split()[0])


def render(build, scene_path, integrator, spp, threads, shim, out_dir, fixed_cpu=0.0):
    exe = os.path.join(build, "bin", "stipple-render")
    cmd = [exe, scene_path, "--integrator", integrator, "--spp", str(spp), "--threads", str(threads),
           "--pattern", "stratified", "--seed", "1", "-o", os.path.join(out_dir, "bench.exr")]
    if shim:
        cmd += ["--shim", shim]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    proc = subprocess.run(cmd, capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode != 0:
        sys.exit(f"render_compare: {' '.join(cmd)} exited with {proc.returncode}: {proc.stderr.strip()}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    for line in proc.stdout.splitlines():
        m = RENDER_LINE.match(line)
        if m:
            seconds, w, h, n = float(m.group(1)), int(m.group(2)), int(m.group(3)), int(m.group(4))
            return w * h * n / seconds, w * h * (n - 1) / max(1e-9, cpu - fixed_cpu), cpu
    sys.exit(f"render_compare: no 'render ... s' line in the output of {' '.join(cmd)}")


def median_interval(values, confidence=0.95):
    """The order-statistic interval (x_(j), x_(n+1-j)) of the median with binomial coverage >= confidence."""
    xs = sorted(values)
    n = len(xs)
    best = None
    for j in range(1, n // 2 + 1):
        # P(x_(j) <= median <= x_(n+1-j)) = 1 - 2 P(Binomial(n, 1/2) <= j - 1)
        tail = sum(math.comb(n, i) for i in range(j)) / 2 ** n
        if 1 - 2 * tail >= confidence:
            best = (xs[j - 1], xs[n - j])
    return best


def parse_cases(text):
    cases = []
    for item in text.split(","):
        parts = item.split(":")
        if len(parts) != 3 or not parts[2].isdigit() or int(parts[2]) < 2:
            sys.exit(f"render_compare: --cases: expected SCENE:INTEGRATOR:SPP with SPP >= 2, got '{item}'")
        cases.append((parts[0], parts[1], int(parts[2])))
    return cases


def build_tree(path):
    """A build tree, given as the tree or as its bin/stipple-render (what CMake's $<TARGET_FILE> names)."""
    if os.path.basename(path) == "stipple-render" and os.path.isfile(path):
        return os.path.dirname(os.path.dirname(os.path.abspath(path)))
    return path


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--baseline", required=True, help="build tree with bin/stipple-render (the reference)")
    parser.add_argument("--candidate", required=True, help="build tree with bin/stipple-render (the one measured)")
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--scenes-dir", default=os.path.join(here, "..", "..", "scenes"))
    parser.add_argument("--cases", help="SCENE:INTEGRATOR:SPP,... (default: the four scenes, eight cases)")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--shim", help="libstipple.so.1 both builds load (default: each its own)")
    parser.add_argument("--bound", type=float, help="exit 1 unless every interval lies above this ratio")
    o = parser.parse_args(argv)
    if o.rounds < 1:
        sys.exit("render_compare: --rounds must be at least 1")
    o.baseline, o.candidate = build_tree(o.baseline), build_tree(o.candidate)
    for d in (o.baseline, o.candidate):
        if not os.access(os.path.join(d, "bin", "stipple-render"), os.X_OK):
            sys.exit(f"render_compare: no bin/stipple-render in {d}")
    cases = parse_cases(o.cases) if o.cases else DEFAULT_CASES
    for scene, _, _ in cases:
        if not os.path.exists(os.path.join(o.scenes_dir, scene + ".yaml")):
            sys.exit(f"render_compare: no {scene}.yaml in {o.scenes_dir}")

    print(f"{o.rounds} alternating rounds per case, {o.threads} threads, stratified, seed 1; "
          f"{os.cpu_count()} hardware threads")
    print("| scene | integrator | spp | baseline Msamples/s | candidate Msamples/s | ratio (median) | 95 % interval "
          "| per CPU s: ratio (median) | 95 % interval | load before-after |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    failed = False
    with tempfile.TemporaryDirectory(prefix="render_compare.") as out_dir:
        for scene, integrator, spp in cases:
            path = os.path.join(o.scenes_dir, scene + ".yaml")
            load_before = load_average()
            fixed = {}
            for which, build in (("baseline", o.baseline), ("candidate", o.candidate)):
                fixed[which] = statistics.median(
                    render(build, path, integrator, 1, o.threads, o.shim, out_dir)[2] for _ in range(3))
            base, cand, ratios, cpu_ratios = [], [], [], []
            for r in range(o.rounds):
                order = ("baseline", "candidate") if r % 2 == 0 else ("candidate", "baseline")
                rate = {}
                for which in order:
                    build = o.baseline if which == "baseline" else o.candidate
                    rate[which] = render(build, path, integrator, spp, o.threads, o.shim, out_dir, fixed[which])
                base.append(rate["baseline"][0])
                cand.append(rate["candidate"][0])
                ratios.append(rate["candidate"][0] / rate["baseline"][0])
                cpu_ratios.append(rate["candidate"][1] / rate["baseline"][1])
            load_after = load_average()
            interval = median_interval(ratios)
            cpu_interval = median_interval(cpu_ratios)
            show = lambda i: f"{i[0]:.3f}-{i[1]:.3f}" if i else "(needs 6 rounds)"
            print(f"| {scene} | {integrator} | {spp} | {statistics.median(base) / 1e6:.3f} | "
                  f"{statistics.median(cand) / 1e6:.3f} | {statistics.median(ratios):.3f} | {show(interval)} | "
                  f"{statistics.median(cpu_ratios):.3f} | {show(cpu_interval)} | "
                  f"{load_before:.2f}-{load_after:.2f} |", flush=True)
            if o.bound is not None and (interval is None or interval[0] <= o.bound):
                failed = True
    if o.bound is not None and failed:
        print(f"render_compare: some interval does not lie above {o.bound}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
