#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""Per-value cost of stipple.hpp's PixelSampleCursor against a hand-written per-pixel batch cache, from one run of
shim_cursor_bench (see its header for the command).

    python3 shim/bench/cursor_ratios.py cursor.json

Prints ns per float served for the cursor, the hand-written cache and one C call per value, and the ratios
cursor / hand-written and per-value / hand-written per (pattern, N, arrays). Exit status 1 when a cursor ratio
exceeds 1.1 (the cursor is the documented fast path).
"""
import json
import re
import sys

BOUND = 1.1


def main(path):
    with open(path) as f:
        run = json.load(f)
    repeated = any(b.get("aggregate_name") == "median" for b in run["benchmarks"])
    ns, labels = {}, {}
    for b in run["benchmarks"]:
        m = re.match(r"BM_(Cursor|HandBatch|PerValue)/pattern:(\d+)/N:(\d+)/arrays:(\d+)", b["name"])
        if not m or b.get("error_occurred") or "items_per_second" not in b:
            continue
        if (b.get("aggregate_name") == "median") != repeated:
            continue
        key = (int(m.group(2)), int(m.group(3)), int(m.group(4)))
        ns[(m.group(1),) + key] = 1e9 / b["items_per_second"]
        labels[key[0]] = b.get("label", str(key[0]))
    print("ns per float" + (" (medians of the repetitions)" if repeated else ""))
    print(f"{'pattern':<12}{'N':>4}{'arrays':>7}{'cursor':>9}{'hand':>9}{'per-value':>11}"
          f"{'cursor/hand':>13}{'per-value/hand':>16}")
    failed = False
    ratios = []
    for key in sorted({k[1:] for k in ns}):
        c, h, v = (ns.get((call,) + key) for call in ("Cursor", "HandBatch", "PerValue"))
        if c is None or h is None:
            continue
        ratio = c / h
        ratios.append(ratio)
        failed |= ratio > BOUND
        print(f"{labels[key[0]]:<12}{key[1]:>4}{'yes' if key[2] else 'no':>7}{c:>9.2f}{h:>9.2f}"
              f"{(v if v else float('nan')):>11.2f}{ratio:>12.2f}x{(v / h if v else float('nan')):>15.2f}x"
              + ("  > 1.1" if ratio > BOUND else ""))
    if ratios:
        ratios.sort()
        middle = len(ratios) // 2
        median = ratios[middle] if len(ratios) % 2 else (ratios[middle - 1] + ratios[middle]) / 2
        print(f"cursor/hand over {len(ratios)} rows: median {median:.3f}x, largest {ratios[-1]:.3f}x, "
              f"{sum(r <= BOUND for r in ratios)} of {len(ratios)} <= {BOUND}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
