// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// poisson.cpp — "poisson": toroidal Poisson-disk sets of exactly N points that integrate at least as well as
// jittered sampling, fast.
//
// Method (see shim/POINTSETS.md for the measurements behind each choice):
//  1. Start: jittered, one uniform point in each cell of a grid of at least N cells (vacancies, if any, at
//     random cells). One point per cell makes the density exact at every scale above a cell: the periodogram
//     vanishes towards k = 0 (hyperuniform), which is what smooth integrands read. (A start of ~4 points per
//     coarse cell did not survive the relaxation as well: poisson then lost to stratified on the Gaussian
//     from N = 256, 3.4x at 4096.)
//  2. Overlap removal (overlap_relaxation.h): soft disks of diameter R = 0.89 d_max (3D: 0.88) pushed
//     apart pairwise in Gauss-Seidel passes over a uniform grid, over-relaxed (omega = 1.6), until no pair is
//     closer than 0.86 d_max (3D 0.84).
//  3. Stratified projections: every 1D projection is made a Latin hypercube (one point in each [r/N, (r+1)/N))
//     while keeping the disks apart: passes that move each coordinate half way into the stratum of its rank,
//     each followed by one relaxation pass with disks of 0.95 d_max, then an exact projection. An edge along an
//     axis (the seam of a non-periodic integrand, seen through the serving's toroidal shift, is one) then
//     costs O(1/N^2) instead of O(N^-1.5). The result is accepted once its exact minimum distance is
//     rho >= 0.855 (3D 0.835).
//  4. A set that misses is redrawn from a derived seed (at most maxAttempts(n)); if no attempt reaches the
//     target with stratified projections, the best set of step 2 is served (rho first; measured: never in 2D
//     for N >= 16, 2% of seeds in 3D at N = 17 and 20, see POINTSETS.md).
//  5. Shuffle the order (the relaxation leaves points in cell order).
//
// 1D is different (cell_set_1d.cpp): one point per cell of width 1/N at a sub-cell position that steps by a fixed
// fraction from cell to cell, served with whole-cell shifts so that the domain's ends are cell boundaries (no seam
// for non-periodic integrands).
#include "pointsets.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <utility>

#include "low_frequency.h"
#include "overlap_relaxation.h"
#include "random.h"
#include "torus.h"

namespace stipple::detail::pointsets {
namespace {

// Relaxation diameter and stopping target, as fractions of d_max (measured in POINTSETS.md).
struct Tuning {
    double diameter, target, accept;
    float omega;
    int maxPasses;
    double stratifyDiameter; // disks of the passes that stratify the projections
    int stratifyPasses;      // at most this many of them
    int cancelFrequency;     // modes 0 < |k| <= this are cancelled (low_frequency.h) during those passes
};
Tuning tuningFor(int dim) {
    if (dim == 2) return {0.89, 0.86, 0.855, 1.6f, 100, 0.95, 300, 4};
    return {0.88, 0.84, 0.835, 1.5f, 100, 0.95, 300, 3};
}
// The stratifying passes try an exact projection every this many passes, and cancel the lowest modes every
// kCancelEvery (each cancellation costs about a relaxation pass in 2D; the passes in between heal the distances).
constexpr int kStratifyCheckEvery = 20;
constexpr int kCancelEvery = 5;

// Retries of a set that misses `accept`; tiny sets cost nothing, so they get more tries at their optimum.
inline int maxAttempts(uint32_t n) { return n < 16 ? 32 : n < 128 ? 16 : 4; }

// The start: one uniform point per cell of a grid of at least n cells, as near cubic as N allows (a power of
// two splits its bits evenly: 2:1 cells for N = 2 * 4^k in 2D). Cells beyond n stay empty, chosen at random:
// vacancies at evenly spaced cell indices would line up along a diagonal, a density wave the smooth
// integrands read (measured: 45x stratified's MSE on the Gaussian).
template <int D>
void jitteredStart(std::vector<float>& pts, uint32_t n, SplitMix64& rng) {
    uint32_t g[D];
    if (std::has_single_bit(n)) {
        const int bits = std::countr_zero(n);
        for (int k = 0; k < D; ++k) g[k] = 1u << ((bits + D - 1 - k) / D);
    } else {
        uint32_t rest = n;
        for (int k = 0; k < D; ++k) {
            g[k] = std::max(1u, uint32_t(std::lround(std::pow(double(rest), 1.0 / (D - k)))));
            rest = (rest + g[k] - 1) / g[k]; // the last axis takes what is left: the product is >= n
        }
    }
    uint32_t cells = 1;
    for (int k = 0; k < D; ++k) cells *= g[k];
    // The first n cells of a random permutation of the cells hold the points.
    std::vector<uint32_t> cell(cells);
    for (uint32_t c = 0; c < cells; ++c) cell[c] = c;
    for (uint32_t i = 0; i < n && cells > n; ++i) std::swap(cell[i], cell[i + rng.uniformBelow(cells - i)]);
    for (uint32_t i = 0; i < n; ++i) {
        uint32_t rest = cell[i];
        for (int k = 0; k < D; ++k, rest /= g[k - 1])
            pts[size_t(i) * D + k] = clampBelowOne((rest % g[k] + rng.uniformDouble()) / g[k]);
    }
}

// Moves every coordinate beta of the way into the stratum [r/n, (r+1)/n) of its rank r along its axis (beta = 1:
// the nearest point of the stratum, the least motion that makes each projection a Latin hypercube). Ranks by
// a counting sort on the stratum index, then by (x, index) inside each stratum: O(n) for the well-spread sets
// this sees, where a comparison sort of every pass cost more than the relaxation pass itself.
template <int D>
void stratifyProjections(std::vector<float>& pts, uint32_t n, float beta, std::vector<uint32_t>& order,
                         std::vector<uint32_t>& start) {
    order.resize(n);
    start.resize(size_t(n) + 1);
    for (int k = 0; k < D; ++k) {
        auto x = [&](uint32_t i) { return pts[size_t(i) * D + k]; };
        auto stratum = [&](uint32_t i) { return std::min(n - 1, uint32_t(double(x(i)) * n)); };
        std::fill(start.begin(), start.end(), 0u);
        for (uint32_t i = 0; i < n; ++i) ++start[stratum(i) + 1];
        for (uint32_t b = 0; b < n; ++b) start[b + 1] += start[b];
        for (uint32_t i = 0; i < n; ++i) order[start[stratum(i)]++] = i; // start[b] is now stratum b's end
        for (uint32_t b = 0, begin = 0; b < n; begin = start[b++])
            for (uint32_t j = begin + 1; j < start[b]; ++j) // insertion sort of one stratum's few points
                for (uint32_t m = j; m > begin; --m) {
                    const uint32_t a = order[m - 1], c = order[m];
                    if (x(a) < x(c) || (x(a) == x(c) && a < c)) break;
                    std::swap(order[m - 1], order[m]);
                }
        for (uint32_t r = 0; r < n; ++r) {
            float& v = pts[size_t(order[r]) * D + k];
            // The stratum's float bounds: floor(v * n) = r exactly (the product is exact in double).
            float lo = float(double(r) / n), hi = float(double(r + 1) / n);
            if (double(lo) * n < r) lo = std::nextafter(lo, 1.0f);
            while (double(hi) * n >= r + 1) hi = std::nextafter(hi, 0.0f);
            hi = std::min(hi, kOneMinusEpsilon);
            const float inside = std::clamp(v, lo, hi);
            v = beta == 1.0f ? inside : wrapUnit(v + beta * (inside - v));
        }
    }
}

// Step 3: stratified projections with disks kept apart. True (and pts stratified, rho >= accept) on success.
template <int D>
bool stratifiedRelaxation(std::vector<float>& pts, uint32_t n, double scale, const Tuning& tuning) {
    const float accept = float(tuning.accept * scale), diameter = float(tuning.stratifyDiameter * scale);
    const RelaxParams pass{diameter, 2.0f * diameter, 0.0f, 1.0f, 1, false}; // one pass, nothing measured
    const RelaxParams measure{accept, 0.0f, 0.0f, 1.0f, 0};                  // no pass, the exact minimum
    std::vector<uint32_t> order, start;
    std::vector<float> trial;
    for (int p = 1; p <= tuning.stratifyPasses; ++p) {
        if (p % kCancelEvery == 0) cancelLowFrequencies<D>(pts, n, tuning.cancelFrequency, 1);
        stratifyProjections<D>(pts, n, 0.5f, order, start);
        relaxOverlaps<D>(pts, n, pass);
        if (p % kStratifyCheckEvery != 0) continue;
        trial = pts;
        stratifyProjections<D>(trial, n, 1.0f, order, start);
        if (relaxOverlaps<D>(trial, n, measure).minDistance >= accept) {
            pts.swap(trial);
            return true;
        }
    }
    return false;
}

template <int D>
std::vector<float> relaxedSet(uint32_t n, uint64_t seed, const Tuning& tuning) {
    const double dmax = packingDistance(D, n);
    std::vector<float> best;
    float bestDistance = -1.0f;
    // Deterministic retries: a set that misses is redrawn from a derived seed. The relaxation's own target drops
    // 1.5% per retry, for tiny N where the torus cannot hold it (N = 3: the optimum is rho = 0.834, below R =
    // 0.89); the stratified set must still reach the full target. Without one, the best relaxed set is served.
    for (int attempt = 0; attempt < maxAttempts(n); ++attempt) {
        const double scale = dmax * std::pow(0.985, attempt);
        const RelaxParams params{float(tuning.diameter * scale), float(tuning.target * scale),
                                 float(tuning.accept * scale), tuning.omega, tuning.maxPasses};
        SplitMix64 rng(deriveSeed(seed, uint64_t(attempt)));
        std::vector<float> pts(size_t(n) * D);
        jitteredStart<D>(pts, n, rng);
        RelaxStats stats = relaxOverlaps<D>(pts, n, params);
        if (stats.minDistance > bestDistance) {
            bestDistance = stats.minDistance;
            best = pts;
        }
        if (stats.verified && n >= 2 && stratifiedRelaxation<D>(pts, n, dmax, tuning)) {
            best.swap(pts);
            break;
        }
    }
    shufflePoints<D>(best, n, deriveSeed(seed, 0x5a0ffu)); // the relaxation leaves points in cell order
    return best;
}

} // namespace

std::vector<float> generatePoisson(int dim, uint32_t n, uint64_t seed) {
    if (n == 0 || n > kMaxPoints || dim < 1 || dim > 3) return {};
    if (dim == 1) return generateCellSet1D(n, 0, seed);
    uint64_t stream = deriveSeed(seed, 0x9015500u + uint64_t(dim));
    Tuning tuning = tuningFor(dim);
    return dim == 2 ? relaxedSet<2>(n, stream, tuning) : relaxedSet<3>(n, stream, tuning);
}

} // namespace stipple::detail::pointsets
