// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// cell_set_1d.cpp — "poisson" in 1D: one point in each cell [c/n, (c+1)/n) of the torus, its offset a reflecting
// random walk from cell to cell.
//
// Cell c's point is (c + o(c)) / n with o(c + 1) = reflect(o(c) + u), u uniform on [-a, a] and reflect folding the
// sum back into [0, 1] at its ends; a = 1 - poissonRadius(1) = 0.8. The fold is symmetric, so the walk is doubly
// stochastic and every offset is uniform; two neighbours are 1 + o(c + 1) - o(c) >= 1 - a cells apart (the minimum
// distance, rho = 0.2); the step from cell n - 1 back to cell 0 is redrawn until it obeys the same bound (the set is
// toroidal, served with a toroidal shift). One point per cell keeps the low frequencies empty (what a smooth
// integrand reads). Why so small a minimum distance: a 1D set's gaps have mean 1 and are at least rho, so the higher
// rho the more regular the gaps and the higher the spectrum's peak near k = n (measured, POINTSETS.md: rho = 0.5 put
// the radially averaged peak at 2.3-2.5, dart throwing's is 1.4-1.6; rho = 0.2 at or below it). a = 1 would be
// jittered sampling (independent uniform offsets). The former construction (a fixed offset step kept under a common
// rotation of the offsets) had a peak of 0.1 n near k = 1.14 n.
// Offsets are kept a margin of n 2^-23 cells inside their cells, so that a served value stays in its cell of the
// served grid: the stored float and the shifted one are each rounded by at most 2^-25, n 2^-24 cells in all. The
// margin is as small as that allows: offsets uniform on [d, 1 - d] instead of [0, 1] put a Bragg peak of about
// 4 n d^2 at k = n (d = 1/64 measured 1.0 at n = 1024, 2.3 at 4096; this margin: below 0.06 up to n = 4096).
#include "pointsets.h"

#include <algorithm>
#include <cmath>

#include "random.h"

namespace stipple::detail::pointsets {

namespace {
constexpr int kClosingDraws = 256;

double reflect(double v) { return v < 0.0 ? -v : v > 1.0 ? 2.0 - v : v; }
} // namespace

std::vector<float> generateCellSet1D(uint32_t n, uint64_t seed) {
    if (n == 0 || n > kMaxPoints) return {};
    const double a = 1.0 - poissonRadius(1);
    SplitMix64 rng(deriveSeed(seed, 0x9015501u));
    std::vector<double> offset(n);
    offset[0] = rng.uniformDouble();
    const auto step = [&](double from) { return reflect(from + a * (2.0 * rng.uniformDouble() - 1.0)); };
    for (uint32_t c = 1; c < n; ++c) offset[c] = step(offset[c - 1]);
    // Closing the walk: the last offset is redrawn until it is within a of the first (about three draws in four
    // are). n = 1 has no neighbour; n = 2 and a walk that does not close (never seen) take o(n-1) = o(0).
    if (n >= 2) {
        bool closed = std::abs(offset[n - 1] - offset[0]) <= a;
        for (int draw = 0; draw < kClosingDraws && !closed && n >= 3; ++draw) {
            offset[n - 1] = step(offset[n - 2]);
            closed = std::abs(offset[n - 1] - offset[0]) <= a;
        }
        if (!closed) offset[n - 1] = offset[0];
    }
    std::vector<float> pts(n);
    const double margin = double(n) * 0x1p-23;
    for (uint32_t c = 0; c < n; ++c) {
        const double inside = margin + (1.0 - 2.0 * margin) * offset[c];
        pts[c] = float((c + inside) / n);
    }
    shufflePoints<1>(pts, n, deriveSeed(seed, 0x5a0ffu));
    return pts;
}

} // namespace stipple::detail::pointsets
