#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""quarter_disk.py — a Python host of libstipple: estimates the quarter disk's area pi/4 with every pattern the
library offers (with and without blue noise), through the stipple package.

Usage: quarter_disk.py [path to libstipple.so.1]   (without it, the package's search: $STIPPLE_LIBRARY, the
installed prefix, the checkout's build tree, the system loader). Run from a checkout without installing:
PYTHONPATH=shim/python/src python3 shim/examples/quarter_disk.py

For N = 16..4096 it estimates pi/4 = P(x^2 + y^2 < 1) in each of 256 pixels (one call for all pixels per N) and
prints the RMS error per pattern and N. Exit status 0 only if stratified beats independent at every N >= 64 by a
one-sided F-test on the mean squared errors (F = MSE_independent / MSE_stratified, (256, 256) degrees of freedom),
alpha = 0.01 Sidak-corrected over the 4 tested N, with ln F ~ Normal(0, 2/256 + 2/256) giving the critical value
(about 1.42); 2 if the library cannot be loaded or a call fails.
"""
import math
import sys

import numpy as np

import stipple

SEED = 20261121
PIXELS = np.array([[x, y] for y in range(16) for x in range(16)])
COUNTS = [16, 64, 256, 1024, 4096]


def mean_squared_error(lib, pattern, blue_noise, n):
    with lib.sampler(pattern, n, SEED, blue_noise=blue_noise) as sampler:
        points = sampler.pixels(PIXELS, dimension=0, arity=2).astype(np.float64)  # (256, n, 2)
    estimates = np.mean(np.sum(points**2, axis=2) < 1.0, axis=1)
    return float(np.mean((estimates - math.pi / 4) ** 2))


def main(argv):
    try:
        lib = stipple.Library(argv[1] if len(argv) > 1 else None)
    except stipple.StippleError as e:
        print(f"quarter_disk.py: {e}", file=sys.stderr)
        return 2
    critical_f = math.exp(2.807 * math.sqrt(2.0 / len(PIXELS) + 2.0 / len(PIXELS)))  # Sidak: 1 - 0.99^(1/4)

    print(f"RMS error of the pi/4 estimate over {len(PIXELS)} pixels (seed {SEED}), libstipple "
          f"{'.'.join(map(str, lib.version))} from {lib.path}")
    print(f"{'pattern':<26}" + "".join(f" {'N=%d' % n:>10}" for n in COUNTS))
    mse = {}
    try:
        for pattern in lib.patterns:
            for blue_noise in (False, True):
                label = pattern + (" + blue noise" if blue_noise else "")
                try:
                    mse[label] = [mean_squared_error(lib, pattern, blue_noise, n) for n in COUNTS]
                except stipple.StippleError as e:
                    if not blue_noise or e.status != stipple.errors.INVALID_ARGUMENT:
                        raise
                    print(f"{label:<26} refused by the library (the flag serves strata patterns only)", flush=True)
                    continue
                print(f"{label:<26}" + "".join(f" {math.sqrt(m):10.3e}" for m in mse[label]), flush=True)
    except stipple.StippleError as e:
        print(f"quarter_disk.py: {e}", file=sys.stderr)
        return 2

    print(f"F-test stratified < independent (critical F = {critical_f:.3f}, alpha 0.01 Sidak over 4 N):")
    passed = True
    for c, n in enumerate(COUNTS):
        if n < 64:
            continue
        f = mse["independent"][c] / mse["stratified"][c]
        passed = passed and f > critical_f
        print(f"  N={n:<5d} F = MSE_independent / MSE_stratified = {f:8.2f}  {'pass' if f > critical_f else 'FAIL'}")
    return 0 if passed else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
