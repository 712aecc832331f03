#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""A pattern's cost in one libstipple build against another's, through the C ABI, in one session.

    python3 shim/bench/abi_cost_compare.py BIN BEFORE_LIB_DIR AFTER_LIB_DIR [--runs K (5)] [--bound B] [-- ARGS]

BIN is shim_abi_cost (built from either tree: it uses the ABI 1.1 functions only); each LIB_DIR holds a
libstipple.so.1. The two libraries are run in alternation, K processes each (before, after, before, ...), so that the
machine's load falls on both alike; per pattern, arity, N and call the median of the K runs' ns per value, and the
ratio after / before. With --bound, exit status 1 when a ratio exceeds it. ARGS after "--" go to shim_abi_cost
(e.g. --patterns sobol).
"""
import argparse
import os
import statistics
import subprocess
import sys


def run(binary, lib_dir, args):
    env = dict(os.environ, LD_LIBRARY_PATH=lib_dir)
    out = subprocess.run([binary] + args, env=env, check=True, capture_output=True, text=True).stdout
    rows = {}
    for line in out.splitlines():
        pattern, arity, n, fill, stream = line.split()
        rows[(pattern, int(arity), int(n))] = (float(fill), float(stream))
    return rows


def main(argv):
    args, passthrough = (argv[: argv.index("--")], argv[argv.index("--") + 1:]) if "--" in argv else (argv, [])
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("binary")
    parser.add_argument("before_dir")
    parser.add_argument("after_dir")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--bound", type=float)
    options = parser.parse_args(args)
    binary, before_dir, after_dir, runs, bound = (options.binary, options.before_dir, options.after_dir, options.runs,
                                                  options.bound)
    for d in (before_dir, after_dir):
        if not os.path.exists(os.path.join(d, "libstipple.so.1")):
            sys.exit(f"abi_cost_compare: no libstipple.so.1 in {d}")
    samples = {"before": [], "after": []}
    for _ in range(runs):
        samples["before"].append(run(binary, before_dir, passthrough))
        samples["after"].append(run(binary, after_dir, passthrough))
    worst = 0.0
    print("| pattern | arity | N | call | before ns/value | after ns/value | after / before |")
    print("|---|---|---|---|---|---|---|")
    for key in sorted(samples["before"][0]):
        for c, call in enumerate(("fill_pixel", "stream_fill")):
            before = statistics.median(r[key][c] for r in samples["before"])
            after = statistics.median(r[key][c] for r in samples["after"])
            ratio = after / before
            worst = max(worst, ratio)
            print(f"| {key[0]} | {key[1]} | {key[2]} | {call} | {before:.3f} | {after:.3f} | {ratio:.2f} |")
    print(f"\nlargest ratio {worst:.2f} (medians of {runs} alternating runs per library)")
    if bound is not None and worst > bound:
        print(f"abi_cost_compare: a ratio exceeds the bound {bound}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
