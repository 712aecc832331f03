#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The stipple authors

"""lattice_search.py — the lattice maps of the blue-noise flag (src/blue_noise.cpp), found by a seeded random search.

A pixel p = (x, y) of a 64 x 64 tile maps to c(p) = (A p + o) mod Q per axis (Q = 64; 1D: 4096). Mode k of a
periodic function of c becomes, across the tile, a plane wave of pixel frequency A^T k / Q. Tiles have independent
offsets, so each wave is cut by the 64-pixel tile window and leaks into nearby frequencies (most along the pixel
axes: a wave whose x frequency is low leaks into the low band through its y sidelobes). The criterion, for a
candidate A: the expected share of the error energy that lands in the measured low band (|f| < 1/8 cycle per
pixel of a 128 x 128 image of independent 64 x 64 tiles), one A per arity for each of three error models:
  - strata (stratified): inside a small stratum a smooth integrand is its second-order Taylor polynomial
    u + v + uv + u^2 + v^2 over the sub-cell coordinates u, v, each folded by the tent; the weights are its DFT
    powers (the ramp gives odd modes, the curvature even ones).
  - square (independent: the stratum is the unit square): Gaussian bumps of width 0.15 (the pattern table's) at 5
    positions per axis, folded by the tent; the score is the worst bump's (where a bump sits decides its modes).
  - shifts (poisson, pmj02, sobol): the error of a shift has the integrand's Fourier modes times the base set's;
    weights 1 / |k|^4.
Lower is better; white noise has 0.048. For 2D shifts the model ranks candidates only roughly (nets and Poisson sets
damp their own low modes); the script lists its 12 best, and blue_noise.cpp keeps the one whose least measured
ratio over poisson, sobol and pmj02 was highest (each substituted into blue_noise.cpp, shim_blue_noise_test at
N = 16). 2D maps: det A odd (a bijection of the tile onto the 64 x 64 values). 3D: a 3 x 2 map (no bijection).
1D: c = a x + b y mod 4096, a bijection of the tile onto its 4096 values.

    /usr/bin/python3 lattice_search.py     # deterministic (seeded); prints the chosen A per arity and its shares
    /usr/bin/python3 lattice_search.py --strata-aliasing   # the 2D A of strata and of the square: the models
    /usr/bin/python3 lattice_search.py --square-aliasing   # above and aliasing (battery_gain, below)
    /usr/bin/python3 lattice_search.py --family strata     # the 2D family of the strata (search_family, below)
"""
import itertools

import numpy as np

BAND = 16  # the low band on the 128-pixel grid: |b| < 16 bins = 1/8 cycle per pixel
_b = np.arange(128)
_bw = np.where(_b < 64, _b, _b - 128)
_band = (_bw[:, None] ** 2 + _bw[None, :] ** 2) < BAND * BAND
_band[0, 0] = False
WHITE = _band.sum() / 128 ** 2


def window(f0):
    """Periodogram share per 128-grid bin of a unit wave of frequency f0 (cycles per pixel, array) cut to 64 px."""
    x = np.arange(64)
    d = _b[None, :] / 128.0 - np.asarray(f0)[:, None]
    s = np.exp(2j * np.pi * d[:, :, None] * x[None, None, :]).sum(-1)
    return np.abs(s) ** 2 / (64 * 128)


_windows = {}


def leak(c, q):
    """Band share of waves at frequencies c / q (n x 2 integers, cycles per pixel)."""
    if q not in _windows:
        _windows[q] = window(np.arange(q) / q)
    if q == 64:  # every frequency is on the grid: one table
        if 'table' not in _windows:
            e = _windows[q]
            _windows['table'] = np.einsum('ax,yx,by->ab', e, _band, e)
        return _windows['table'][c[:, 0], c[:, 1]]
    e = _windows[q]
    return np.einsum('nx,yx,ny->n', e[c[:, 0]], _band, e[c[:, 1]])


def tent(c, q):
    return np.where(c < q // 2, 2 * c, 2 * (q - 1 - c) + 1)


def tent_modes(arity, q, K):
    """Modes (|k_i| <= K) and DFT powers of the second-order Taylor model sum u_i + sum_{i<j} u_i u_j + sum u_i^2
    over the tent-folded sub-cell coordinates u_i (centred)."""
    u = (tent(np.arange(q), q) + 0.5) / q - 0.5
    grids = np.meshgrid(*([u] * arity), indexing='ij')
    F = sum(g + g * g for g in grids) + sum(grids[i] * grids[j] for i in range(arity) for j in range(i + 1, arity))
    P = np.abs(np.fft.fftn(F) / F.size) ** 2
    ks = np.array([k for k in itertools.product(range(-K, K + 1), repeat=arity) if any(k)])
    w = P[tuple((ks % q).T)]
    keep = w > 1e-30
    return ks[keep], w[keep]


def square_modes(arity, q, K, sigma=0.15):
    """A stratum as large as the unit square (independent): Gaussian bumps of width sigma (the pattern table's)
    centred at each of 0.1, 0.3, ..., 0.9 per axis, folded by the tent; one row of DFT powers per bump (the score
    is the worst bump's: where the bump sits decides which modes carry its error)."""
    u = (tent(np.arange(q), q) + 0.5) / q
    ks = np.array([k for k in itertools.product(range(-K, K + 1), repeat=arity) if any(k)])
    rows = []
    for centre in itertools.product(np.arange(0.1, 1.0, 0.2), repeat=arity):
        F = np.ones((q,) * arity)
        for i, m in enumerate(centre):
            shape = [1] * arity
            shape[i] = q
            F = F * np.exp(-(u - m) ** 2 / (2 * sigma ** 2)).reshape(shape)
        rows.append((np.abs(np.fft.fftn(F) / F.size) ** 2)[tuple((ks % q).T)])
    return ks, np.array(rows)


def shift_modes(arity, K):
    """The error of a shift has the integrand's Fourier modes times the base set's: weights 1 / |k|^4, |k_i| <= K
    (an integrand with an edge, or the seam the shift makes; a smooth bump would weight only |k| <= 2)."""
    ks = np.array([k for k in itertools.product(range(-K, K + 1), repeat=arity) if any(k)])
    return ks, 1.0 / (ks ** 2).sum(1) ** 2


def share(At, q, ks, w):
    """w: weights, or one row of weights per integrand (then the worst integrand's share)."""
    w = np.atleast_2d(w)
    return ((w @ leak(np.mod(ks @ At, q), q)) / w.sum(1)).max()


def search(arity, q, model, trials, bijective, seed=3, keep=1):
    """The `keep` best candidates (share, A), best first."""
    rng = np.random.default_rng(seed)
    ks, w = model
    x, y = np.meshgrid(np.arange(64), np.arange(64))
    found = []
    for _ in range(trials):
        At = rng.integers(0, q, size=(arity, 2))
        if bijective and arity == 2 and round(np.linalg.det(At)) % 2 == 0:
            continue
        if bijective and arity == 1 and len(np.unique((At[0, 0] * x + At[0, 1] * y) % q)) != q:
            continue
        found.append((share(At, q, ks, w), At))
        found = sorted(found, key=lambda f: f[0])[:keep]
    return found


# Aliasing (2D strata). The Taylor model covers what is smooth inside a stratum; an integrand that oscillates
# inside one (the battery's zone plate 0.5 + 0.5 cos(60 (x^2 + y^2)) has 2-7 periods across a stratum at N = 16)
# has its error in modes |k| ~ 5-15 of the tent-folded sub-cells, and a lattice that keeps the lowest modes out of
# the band takes its 1/16 share of the band from exactly such modes: the former strata A (47, 39; 25, 46) had a
# predicted zone-plate gain of 0.92 at N = 16 (measured 0.93 [0.90, 0.96]). battery_gain predicts the measured
# gain from the sub-cell means of each stratum of an n x n grid (per-stratum DFT powers over the tent-folded
# sub-cells; the spread inside a sub-cell stays white), for the zone plate and the battery's 2D edges and smooth
# bumps.
BATTERY = {
    'zone plate': lambda x, y: 0.5 + 0.5 * np.cos(60 * (x * x + y * y)),
    'slanted step': lambda x, y: (x < 0.3 + 0.4 * y).astype(float),
    'pmj disk': lambda x, y: (x * x + y * y < 2 / np.pi).astype(float),
    'pmj triangle': lambda x, y: (y < x).astype(float),
    'pmj step': lambda x, y: (x < 1 / 3).astype(float),
    'gaussian': lambda x, y: np.exp(-x * x - y * y),
    'off-centre gaussian': lambda x, y: np.exp(-((x - 0.7) ** 2 + (y - 0.35) ** 2) / (2 * 0.15 ** 2)),
}
_all_modes = np.array([k for k in itertools.product(range(-31, 33), repeat=2) if any(k)])


def stratum_modes(f, n, q=64, sub=4):
    """DFT powers (summed over the n x n strata) of f's sub-cell means over the tent-folded sub-cells, and the
    summed variance inside sub-cells."""
    t = tent(np.arange(q), q)
    power, spread = np.zeros(len(_all_modes)), 0.0
    u = (np.arange(q * sub) + 0.5) / (q * sub)
    for sx in range(n):
        for sy in range(n):
            X, Y = np.meshgrid((sx + u) / n, (sy + u) / n, indexing='ij')
            v = f(X, Y).reshape(q, sub, q, sub)
            g = v.mean(axis=(1, 3))[t][:, t]
            power += (np.abs(np.fft.fft2(g) / g.size) ** 2)[tuple((_all_modes % q).T)]
            spread += v.var(axis=(1, 3)).mean()
    return power, spread


def battery_gain(At, modes, q=64):
    """Predicted low-band gain (white / flagged) for one integrand's stratum_modes, the worse of the two value-axis
    rotations blue_noise.cpp picks from."""
    power, spread = modes
    gains = []
    for A in (At, At[::-1]):
        band = power @ leak(np.mod(_all_modes @ A, q), q)
        gains.append(WHITE * (power.sum() + spread) / (band + WHITE * spread))
    return min(gains)


ALIASING = {  # use: (its model, strata per axis measured, former A, model gain floor, zone-plate floor, seed)
    'strata': (lambda: tent_modes(2, 64, 16), (4, 8, 16), [[47, 39], [25, 46]], 500, 1.05, 7),
    'square': (lambda: square_modes(2, 64, 16), (1,), [[40, 55], [9, 17]], 5, 1.02, 11),
}


def search_aliasing(use, trials=60000, keep=6):
    """2D candidates whose model gain (Taylor for strata, the worst bump for the square) is >= the floor and whose
    predicted zone-plate gain is >= its floor at every N (strata: N = 16, 64, 256; square: the unit square), ranked
    by the least ratio of their predicted battery gains to the former A's (edges and smooth bumps)."""
    model, grids, former, taylor_min, zone_min, seed = ALIASING[use]
    rng = np.random.default_rng(seed)
    ks, w = model()
    modes = {(name, n): stratum_modes(f, n) for name, f in BATTERY.items() for n in grids}
    former = np.array(former)
    reference = {key: battery_gain(former, m) for key, m in modes.items()}
    ranked = []
    for _ in range(trials):
        At = rng.integers(0, 64, size=(2, 2))
        if round(np.linalg.det(At)) % 2 == 0:
            continue
        taylor = WHITE / share(At, 64, ks, w)
        if taylor < taylor_min or any(battery_gain(At, modes[('zone plate', n)]) < zone_min for n in grids):
            continue
        gains = {key: battery_gain(At, m) for key, m in modes.items()}
        worst = min(gains[key] / reference[key] for key in gains if key[0] != 'zone plate')
        ranked.append((worst, taylor, At, gains))
    ranked.sort(key=lambda r: -r[0])
    return ranked[:keep]


# The 2D family of the strata (blue_noise.cpp, kMaps2): one map per tile, hashed. A single map sends the modes of some
# integrand that varies inside a stratum into the low band in every tile (the former A (23, 50; 15, 37): 12 x 12
# checkerboards at N = 16 and 24 x 24 at N = 64 lost 1.25-1.4x); a family averages it out. Training integrands:
# checkerboards 7 x 7 to 24 x 24 (also shifted), gratings with |k| <= 2 sqrt(N) at N = 16 and 64 (and a few more),
# periodic and thin stripes, axis, near-axis and slanted steps, opposite bumps across a stratum face and the
# battery's 2D edges and bumps, at 4 x 4, 8 x 8 and 16 x 16 strata. The pool: maps whose Taylor gain (white / share,
# the worst of their value-axis rotations and reflections) is >= 100; greedily, the map that most raises the sum
# of the three least predicted gains of the family's average (over its maps and the tile's value-axis symmetries).
def _family_integrands():
    checker = lambda s, o=0.0: (lambda x, y: ((np.floor(s * x + o) + np.floor(s * y + 0.7 * o)) % 2).astype(float))
    grating = lambda a, b: (lambda x, y: np.cos(2 * np.pi * (a * x + b * y)))
    stripes = lambda s, w: (lambda x, y: ((s * x) % 1 < w).astype(float))
    step = lambda a, t: (lambda x, y: (x * np.cos(t) + y * np.sin(t) < a).astype(float))
    g = lambda x, c: np.exp(-((x - c) ** 2) / (2 * 0.01 ** 2))
    bumps = lambda c: (lambda x, y: (g(x, c - 0.02) - g(x, c + 0.02)) * g(y, 0.5))
    out = [(f'checker{s}', checker(s), (4, 8, 16)) for s in range(7, 25)]
    out += [(f'stripes{s}', stripes(s, 0.2), (4, 8, 16)) for s in (3, 5, 7, 11, 16)]
    out += [(f'step{t:.2f}', step(0.37 + 0.1 * np.sin(t), t), (4, 8, 16)) for t in (0, 0.03, 0.1, 0.3, 0.7)]
    out += [(f'g{a}_{b}', grating(a, b), (4, 8, 16)) for a, b in
            [(1, 0), (3, 1), (5, 2), (8, 0), (7, 7), (12, 5), (16, 3), (20, 11), (29, 3)]]
    out += [(name, f, (4, 8, 16)) for name, f in BATTERY.items()]
    for n in (4, 8):
        out += [(f'g{a}_{b}', grating(a, b), (n,)) for a in range(2 * n + 1) for b in range(a + 1)
                if 0 < a * a + b * b <= 4 * n * n]
    out += [(f'chk{s}', checker(s, 0.31), (4, 8, 16)) for s in (7, 9, 11, 13, 15, 19, 21, 22)]
    out += [(f'str{s}_{w:g}', stripes(s, w), (4, 8, 16)) for s, w in ((4, 0.05), (9, 0.1), (13, 0.3), (20, 0.1))]
    out += [(f'stp{t:.2f}', step(0.41, t), (4, 8, 16)) for t in (0.01, 0.05, 0.2, 0.5, 1.2, np.pi / 4)]
    out += [(f'g{a}_{b}', grating(a, b), (4, 8, 16)) for a, b in
            [(2, 1), (4, 4), (6, 0), (9, 4), (11, 2), (14, 14), (18, 7), (25, 0), (31, 6)]]
    out += [(f'bump{c:g}', bumps(c), (4, 8, 16)) for c in (0.25, 0.5)]
    return out


def _in_range(name, n):
    """Gratings with |k| <= 2 sqrt(N) and periodic stripes of frequency <= 2 sqrt(N) (N = n * n) only."""
    import re
    m = re.match(r'g(\d+)_(\d+)$', name)
    if m:
        return int(m[1]) ** 2 + int(m[2]) ** 2 <= 4 * n * n
    m = re.match(r'str(?:ipes)?(\d+)', name)
    return not m or int(m[1]) <= 2 * n


def search_family(size=32, taylor_min=100, pool_size=300, seed=17):
    modes = {}
    for name, f, grids in _family_integrands():
        for n in grids:
            if _in_range(name, n):
                modes[(name, n)] = stratum_modes(f, n, sub=2 if name.startswith('g') and name[1].isdigit() else 4)
    keys = [k for k, (p, _) in modes.items() if p.sum() > 1e-14]
    power = np.array([modes[k][0] for k in keys])
    total = power.sum(1) + np.array([modes[k][1] for k in keys])
    spread = np.array([modes[k][1] for k in keys])

    def variants(At):
        out = []
        for A in (At, At[::-1]):
            for sign in (1, -1):
                B = A.copy()
                B[0] *= sign
                out.append(B)
        return out

    def gain(band):
        return WHITE * total / (band + WHITE * spread)

    ks, w = tent_modes(2, 64, 16)
    rng = np.random.default_rng(seed)
    pool = []
    while len(pool) < pool_size:
        At = rng.integers(0, 64, size=(2, 2))
        if round(np.linalg.det(At)) % 2 == 0:
            continue
        taylor = WHITE / max(share(V, 64, ks, w) for V in variants(At))
        if taylor >= taylor_min:
            pool.append((taylor, At, np.mean([power @ leak(np.mod(_all_modes @ V, 64), 64) for V in variants(At)], 0)))
    family, mean = [], np.zeros(len(keys))
    for j in range(size):
        scores = [np.sort(gain((mean * j + c[2]) / (j + 1)))[:3].sum() for c in pool]
        best = int(np.argmax(scores))
        family.append(pool[best])
        mean = (mean * j + pool[best][2]) / (j + 1)
    g = gain(mean)
    return family, sorted(zip(g, keys))[:6]


if __name__ == '__main__' and __import__('sys').argv[1:] == ['--family', 'strata']:
    family, worst = search_family()
    print('kMaps2 = {' + ', '.join('{{%d, %d}, {%d, %d}}' % tuple(A.ravel()) for _, A, _ in family) + '}')
    print('Taylor gains', [round(t) for t, _, _ in family])
    print('least predicted gains', [(key, round(float(v), 3)) for v, key in worst])
elif __name__ == '__main__' and len(__import__('sys').argv) > 1 and __import__('sys').argv[1].endswith('-aliasing'):
    # blue_noise.cpp's 2D A: strata, of these candidates the one with a Taylor-model gain >= 800; square, the first.
    use = __import__('sys').argv[1][2:].split('-')[0]
    for worst, taylor, At, gains in search_aliasing(use):
        print(f'A = {At.tolist()}  model white / share {taylor:.0f}, least battery gain / former {worst:.2f}, zone plate '
              + ', '.join(f'{n * n} strata: {gains[("zone plate", n)]:.2f}' for n in ALIASING[use][1]))
elif __name__ == '__main__':
    K = {1: 64, 2: 16, 3: 6}  # modes |k_i| <= K
    for arity, q, trials in ((2, 64, 30000), (3, 64, 10000), (1, 4096, 5000)):
        for name, model, bijective in (('strata', tent_modes(arity, q, K[arity]), arity < 3),
                                       ('square', square_modes(arity, q, K[arity]), arity < 3),
                                       ('shifts', shift_modes(arity, K[arity]), arity < 3)):
            for s, At in search(arity, q, model, trials, bijective, keep=12 if (arity, name) == (2, 'shifts') else 1):
                print(f'arity {arity} {name} (mod {q}): A = {At.tolist()}  low-band share {s:.2e} (white / share '
                      f'{WHITE / s:.0f})')
