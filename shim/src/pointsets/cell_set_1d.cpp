// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// cell_set_1d.cpp — "poisson" in 1D: one point in each cell [c/n, (c+1)/n), at an offset that steps by a fixed
// fraction from cell to cell.
//
// Set j of a family puts cell c's point at the centre of sub-cell sigma(c) of the cell's m sub-cells
// (m = cellSubdivision1D(n)): sigma(c) = floor(((c q) mod n) m / n), so the offset steps by q / n modulo 1 (a Weyl
// sequence, one lattice in the (cell, offset) square). The serving (pattern_poisson.cpp) shifts the set by whole
// cells, reflects it and rotates every offset inside its cell by one uniform tau: the domain's ends stay cell
// boundaries (a non-periodic integrand sees no seam) and every point is uniform on [0,1). Two neighbours are then
// q / n of a cell apart or more (a step q = 0, every offset equal, keeps them a whole cell apart): rho >= q / n.
//
// With one common rotation the cells' errors are coupled through the offsets' differences, lag L apart by
// L q / n modulo 1. On a smooth integrand neighbouring cells see slopes of one sign and gain from differences near
// 1/2; at a kink or a peak about a cell wide they see slopes of opposite signs, which gain from differences near 0
// and lose near 1/2 (measured, shim/POINTSETS.md: the step 0.809 lost 1.3-1.7x stratified's MSE on the Genz
// kink up to N = 56). Hence two regimes:
//  - from 64 points on, q / n = 1 - beta with beta = 1 / (5 + 1/phi) = 0.191 (rho ~ 0.81) in every set: its
//    harmonics j beta mod 1 stay away from 0 for small j (continued fraction [0; 5, 1, 1, 1, ...]), so a smooth
//    integrand's error is boundary terms only (0.004x stratified's MSE on exp(-x) at 4096);
//  - below, each n has its own steps (kSmallFamilies1D): up to four values of q with q = 0 or q / n in [1/2, 1)
//    (rho >= 1/2), mixed over the family's 32 sets by count, chosen by shim_poisson1d_steps (bench/): the least
//    worst ratio to jittered sampling's exact MSE over classes of random probe integrands (the six Genz families,
//    difficulties x0.5-2, ramps, exp(-x), Gaussians, steps) — a minimax over the mixtures, not over the battery's
//    own instances. What it reaches is measured in POINTSETS.md; below 24 points no mixture keeps the kink and the
//    peaks both under jittered's MSE, and the table is the best compromise found (every class within a few
//    percent of 1 on the probes).
// Offsets drawn independently per cell instead (jittered with a balanced sigma) gave 1.0-1.4x, and a random
// balanced sigma repaired by swaps to rho >= 0.8 gave 4-15x on the oscillation and the Gaussian (the repair leaves
// slow drifts in the offsets).
#include "pointsets.h"

#include <cmath>
#include <numeric>
#include <utility>

#include "random.h"

namespace stipple::detail::pointsets {
namespace {

constexpr double kWeylStep1D = 0.19098300562505258; // 1 / (5 + 1/phi)
constexpr uint32_t kFirstWeylStepSize = 64;
constexpr uint32_t kFamilySets = 32;

// shim_poisson1d_steps's output for n = 8 .. 63: per n, four (q, number of the family's 32 sets) pairs.
constexpr uint32_t kFirstSmallFamily = 8;
constexpr std::pair<uint32_t, uint32_t> kSmallFamilies1D[][4] = {
    {{4, 17}, {7, 11}, {5, 3}, {6, 1}},     {{5, 23}, {8, 6}, {0, 3}, {0, 0}},      // n = 8, 9
    {{5, 12}, {9, 9}, {6, 6}, {8, 5}},      {{6, 21}, {9, 6}, {10, 3}, {0, 2}},     // n = 10, 11
    {{7, 19}, {11, 7}, {8, 4}, {0, 2}},     {{7, 21}, {11, 6}, {12, 3}, {0, 2}},    // n = 12, 13
    {{10, 15}, {7, 9}, {13, 7}, {12, 1}},   {{8, 23}, {13, 6}, {0, 2}, {14, 1}},    // n = 14, 15
    {{9, 16}, {8, 8}, {15, 6}, {14, 2}},    {{9, 21}, {14, 9}, {0, 1}, {13, 1}},    // n = 16, 17
    {{10, 25}, {17, 5}, {0, 1}, {15, 1}},   {{10, 21}, {16, 9}, {0, 1}, {11, 1}},   // n = 18, 19
    {{11, 19}, {10, 5}, {16, 4}, {19, 4}},  {{11, 21}, {18, 10}, {0, 1}, {0, 0}},   // n = 20, 21
    {{12, 21}, {11, 5}, {21, 4}, {16, 2}},  {{12, 18}, {13, 10}, {21, 3}, {0, 1}},  // n = 22, 23
    {{13, 23}, {12, 5}, {23, 3}, {14, 1}},  {{13, 16}, {14, 12}, {23, 3}, {0, 1}},  // n = 24, 25
    {{14, 25}, {13, 4}, {15, 3}, {0, 0}},   {{14, 16}, {15, 10}, {24, 5}, {0, 1}},  // n = 26, 27
    {{16, 14}, {15, 12}, {14, 3}, {27, 3}}, {{16, 19}, {15, 12}, {27, 1}, {0, 0}},  // n = 28, 29
    {{17, 14}, {16, 11}, {15, 4}, {29, 3}}, {{17, 22}, {16, 8}, {0, 1}, {30, 1}},   // n = 30, 31
    {{18, 23}, {17, 5}, {16, 2}, {31, 2}},  {{18, 23}, {17, 4}, {22, 4}, {32, 1}},  // n = 32, 33
    {{23, 18}, {18, 12}, {17, 2}, {0, 0}},  {{21, 16}, {19, 13}, {34, 2}, {33, 1}}, // n = 34, 35
    {{21, 27}, {18, 2}, {35, 2}, {34, 1}},  {{24, 16}, {21, 14}, {25, 1}, {36, 1}}, // n = 36, 37
    {{21, 16}, {20, 10}, {25, 4}, {19, 2}}, {{23, 21}, {20, 6}, {26, 4}, {36, 1}},  // n = 38, 39
    {{25, 19}, {21, 8}, {24, 4}, {39, 1}},  {{25, 26}, {21, 4}, {23, 1}, {27, 1}},  // n = 40, 41
    {{26, 14}, {29, 13}, {28, 4}, {41, 1}}, {{25, 27}, {32, 3}, {41, 1}, {42, 1}},  // n = 42, 43
    {{26, 20}, {33, 9}, {43, 2}, {42, 1}},  {{29, 26}, {30, 3}, {23, 2}, {37, 1}},  // n = 44, 45
    {{28, 15}, {31, 14}, {24, 2}, {23, 1}}, {{30, 23}, {31, 8}, {42, 1}, {0, 0}},   // n = 46, 47
    {{31, 24}, {32, 5}, {47, 2}, {46, 1}},  {{28, 14}, {33, 9}, {36, 8}, {45, 1}},  // n = 48, 49
    {{32, 28}, {40, 2}, {25, 1}, {49, 1}},  {{38, 16}, {33, 11}, {30, 3}, {34, 2}}, // n = 50, 51
    {{31, 17}, {34, 8}, {43, 6}, {26, 1}},  {{37, 14}, {28, 13}, {27, 4}, {36, 1}}, // n = 52, 53
    {{32, 21}, {45, 9}, {28, 1}, {53, 1}},  {{35, 27}, {44, 3}, {53, 1}, {54, 1}},  // n = 54, 55
    {{35, 18}, {45, 8}, {37, 5}, {31, 1}},  {{39, 21}, {32, 7}, {29, 2}, {38, 2}},  // n = 56, 57
    {{33, 22}, {40, 5}, {39, 4}, {29, 1}},  {{34, 18}, {44, 13}, {56, 1}, {0, 0}},  // n = 58, 59
    {{37, 22}, {36, 6}, {31, 4}, {0, 0}},   {{33, 15}, {52, 8}, {40, 7}, {46, 2}},  // n = 60, 61
    {{37, 20}, {39, 11}, {31, 1}, {0, 0}},  {{38, 19}, {54, 8}, {36, 4}, {47, 1}},  // n = 62, 63
};
static_assert(std::size(kSmallFamilies1D) == kFirstWeylStepSize - kFirstSmallFamily);

// The step q of set j (of a family of kFamilySets sets; larger families repeat the composition).
uint32_t stepFor(uint32_t n, uint32_t setIndex) {
    if (n < kFirstSmallFamily) return 0; // one sub-cell per cell (cellSubdivision1D): the lattice, whatever the step
    if (n >= kFirstWeylStepSize) {
        uint32_t q = uint32_t(std::lround(double(n) * (1.0 - kWeylStep1D)));
        while (std::gcd(q, n) != 1) ++q;
        return q;
    }
    uint32_t slot = setIndex % kFamilySets;
    for (const auto& [q, sets] : kSmallFamilies1D[n - kFirstSmallFamily]) {
        if (slot < sets) return q;
        slot -= sets;
    }
    return kSmallFamilies1D[n - kFirstSmallFamily][0].first;
}

} // namespace

uint32_t cellSubdivision1D(uint32_t n) {
    // The largest divisor m of n with n * m <= 2^23 (sub-cell centres resolved in float). Below 8 sub-cells the
    // Weyl step cannot be resolved: then m = 1, the shifted lattice.
    for (uint32_t m = std::min<uint64_t>(n, (uint64_t(1) << 23) / std::max(n, 1u)); m >= 8; --m)
        if (n % m == 0) return m;
    return 1;
}

uint32_t cellStep1D(uint32_t n, uint32_t setIndex) { return stepFor(n, setIndex); }

std::vector<float> generateCellSet1D(uint32_t n, uint32_t setIndex, uint64_t seed) {
    if (n == 0 || n > kMaxPoints) return {};
    const uint64_t stream = deriveSeed(seed, 0x9015500u + 1u);
    const uint32_t m = cellSubdivision1D(n), q = stepFor(n, setIndex);
    std::vector<float> pts(n);
    const double fine = double(n) * m;
    for (uint32_t c = 0; c < n; ++c) {
        const uint64_t rotated = uint64_t(c) * q % n;
        const uint64_t sigma = rotated * m / n;
        pts[c] = float((double(c) * m + double(sigma) + 0.5) / fine); // fine <= 2^23: 1/2-sub-cell resolution
    }
    // Fisher-Yates: hosts get no spatial order to trip on.
    SplitMix64 rng(deriveSeed(stream, 0x5a0ffu));
    for (uint32_t i = n; i > 1; --i) std::swap(pts[i - 1], pts[rng.uniformBelow(i)]);
    return pts;
}

} // namespace stipple::detail::pointsets
