#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""The blue-noise flag's batch cost per value against the plain pattern's, from one run of shim_shim_bench.

    bin/shim_shim_bench --benchmark_filter='BM_BlueNoiseFill/' --benchmark_enable_random_interleaving=true \\
        --benchmark_repetitions=5 --benchmark_format=json > blue.json
    python3 shim/bench/blue_noise_ratios.py blue.json

Prints ns per value of fill_pixel without and with STIPPLE_SAMPLER_FLAG_BLUE_NOISE per pattern, arity and N (the
medians of the repetitions when there are any) and their ratio; exit status 1 when a ratio exceeds BOUND.
"""
import json
import re
import sys

BOUND = 2.0
PATTERNS = {1: "stratified"}  # the patterns that take the flag (independent refuses it)


def main(path):
    with open(path) as f:
        run = json.load(f)
    repeated = any(b.get("aggregate_name") == "median" for b in run["benchmarks"])
    ns = {}
    for b in run["benchmarks"]:
        m = re.match(r"BM_BlueNoiseFill/pattern:(\d+)/arity:(\d+)/N:(\d+)/blue:(\d)", b["name"])
        if not m or b.get("error_occurred") or "items_per_second" not in b:
            continue
        if (b.get("aggregate_name") == "median") != repeated:
            continue
        ns[tuple(int(g) for g in m.groups())] = 1e9 / b["items_per_second"]
    failed = False
    print(f"batch kernels: {run.get('context', {}).get('batch_isa', '?')}" +
          (" (medians of the repetitions)" if repeated else ""))
    print(f"{'pattern':<12}{'arity':>6}{'N':>6}{'plain ns':>10}{'blue ns':>10}{'blue/plain':>12}")
    for (pattern, arity, n, blue), plain in sorted(ns.items()):
        if blue != 0 or (pattern, arity, n, 1) not in ns:
            continue
        flagged = ns[(pattern, arity, n, 1)]
        ratio = flagged / plain
        mark = " OVER" if ratio > BOUND else ""
        failed = failed or bool(mark)
        print(f"{PATTERNS.get(pattern, str(pattern)):<12}{arity:>6}{n:>6}{plain:>10.3f}{flagged:>10.3f}"
              f"{ratio:>11.2f}x{mark}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
