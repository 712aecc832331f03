#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""Per-value cost ratios against independent from one run of shim_shim_bench.

    bin/shim_shim_bench [--isa=baseline|avx2|avx512] --benchmark_filter='BM_(FillPixel|Sample|Stream|StreamFill)/' \\
        [--benchmark_repetitions=3] --benchmark_format=json > bench.json
    python3 shim/bench/ratios.py bench.json

For every call (FillPixel = batch, Sample = random access, Stream = streaming, StreamFill = streaming batch),
arity and N, prints ns per value of each pattern and its ratio to independent's in the same run, and checks the
bounds: stratified and poisson (sobol and pmj02 are shown, not bounded) at most 2x independent in the batch calls, at most 3x in the per-value calls.
Exit status 1 when a bound is exceeded.
"""
import json
import re
import sys

BOUND = {"FillPixel": 2.0, "StreamFill": 2.0, "Sample": 3.0, "Stream": 3.0}
# Patterns by name, as each benchmark's label gives it (shim_bench asks the library for the list and the names).
BOUNDED = ("stratified", "poisson")  # the bounds are their promise; sobol and pmj02 are reported alongside
SHOWN = ("stratified", "poisson", "sobol", "pmj02", "lattice", "halton")


def main(path):
    with open(path) as f:
        run = json.load(f)
    ns = {}
    # With --benchmark_repetitions the median aggregate of each benchmark is used, else its single run.
    repeated = any(b.get("aggregate_name") == "median" for b in run["benchmarks"])
    for b in run["benchmarks"]:
        m = re.match(r"BM_(\w+)/pattern:(\d+)/arity:(\d+)/N:(\d+)", b["name"])
        if not m or b.get("error_occurred") or "items_per_second" not in b:
            continue
        if (b.get("aggregate_name") == "median") != repeated:
            continue
        call, pattern, arity, n = m.group(1), b.get("label", m.group(2)), int(m.group(3)), int(m.group(4))
        ns[(call, pattern, arity, n)] = 1e9 / b["items_per_second"]
    failed = False
    print(f"batch kernels: {run.get('context', {}).get('batch_isa', '?')}" +
          (" (medians of the repetitions)" if repeated else ""))
    print(f"{'call':<11}{'arity':>6}{'N':>6}  {'independent ns':>15}" +
          "".join(f"  {p + ' ns (x)':>20}" for p in SHOWN))
    sizes = sorted({key[3] for key in ns})
    for call in ("FillPixel", "Sample", "Stream", "StreamFill"):
        for arity in (1, 2, 3):
            for n in sizes:
                base = ns.get((call, "independent", arity, n))
                if base is None:
                    continue
                cells = []
                for pattern in SHOWN:
                    v = ns.get((call, pattern, arity, n))
                    if v is None:
                        cells.append("-")
                        continue
                    ratio = v / base
                    mark = "" if pattern not in BOUNDED or ratio <= BOUND[call] else " OVER"
                    failed = failed or bool(mark)
                    cells.append(f"{v:.2f} ({ratio:.2f}x){mark}")
                print(f"{call:<11}{arity:>6}{n:>6}  {base:>15.2f}" + "".join(f"  {c:>20}" for c in cells))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
