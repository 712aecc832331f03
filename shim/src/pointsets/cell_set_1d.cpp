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
// kink up to N = 48). Hence two regimes:
//  - from 64 points on, q / n = 1 - beta with beta = 1 / (5 + 1/phi) = 0.191 (rho ~ 0.81) in every set: its
//    harmonics j beta mod 1 stay away from 0 for small j (continued fraction [0; 5, 1, 1, 1, ...]), so a smooth
//    integrand's error is boundary terms only (0.004x stratified's MSE on exp(-x) at 4096);
//  - below, each n has its own steps (kSmallFamilies1D): up to four values of q with q = 0 or q / n in [1/2, 1)
//    (rho >= 1/2), mixed over the family's 32 sets by count, chosen by shim_poisson1d_steps (bench/): the least
//    worst ratio to jittered sampling's exact MSE over classes of random probe integrands (the six Genz families
//    in three bands of difficulty, ramps, exp(-x), Gaussians, steps; not the battery's own instances), smooth
//    gains bought with at most 5% on the worst class. With one common rotation no mixture keeps every class under
//    jittered's MSE at small n: the worst probe class is at 1.1-1.2x for n <= 16, at most 1.05x from 29
//    (POINTSETS.md, "1D").
// Offsets drawn independently per cell instead (jittered with a balanced sigma) gave 1.0-1.4x, and a random
// balanced sigma repaired by swaps to rho >= 0.8 gave 4-15x on the oscillation and the Gaussian (the repair leaves
// slow drifts in the offsets). Generation is O(n): the table is looked up, not searched.
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
    {{4, 16}, {7, 11}, {6, 5}, {0, 0}},     {{5, 23}, {8, 6}, {0, 3}, {0, 0}},      // n = 8, 9
    {{6, 12}, {5, 11}, {9, 9}, {0, 0}},     {{6, 28}, {0, 2}, {10, 2}, {0, 0}},     // n = 10, 11
    {{7, 13}, {6, 9}, {11, 6}, {10, 4}},    {{7, 21}, {11, 6}, {9, 3}, {0, 2}},     // n = 12, 13
    {{8, 16}, {7, 7}, {13, 6}, {11, 3}},    {{8, 21}, {12, 9}, {0, 1}, {14, 1}},    // n = 14, 15
    {{9, 22}, {15, 5}, {13, 3}, {0, 2}},    {{11, 28}, {15, 2}, {0, 1}, {16, 1}},   // n = 16, 17
    {{10, 16}, {14, 7}, {9, 5}, {17, 4}},   {{10, 19}, {15, 12}, {0, 1}, {0, 0}},   // n = 18, 19
    {{11, 20}, {10, 5}, {16, 4}, {19, 3}},  {{11, 18}, {12, 7}, {18, 6}, {0, 1}},   // n = 20, 21
    {{12, 20}, {18, 7}, {11, 4}, {21, 1}},  {{13, 18}, {12, 12}, {0, 1}, {21, 1}},  // n = 22, 23
    {{13, 26}, {12, 5}, {14, 1}, {0, 0}},   {{14, 17}, {13, 13}, {0, 1}, {23, 1}},  // n = 24, 25
    {{15, 14}, {14, 13}, {13, 3}, {25, 2}}, {{15, 22}, {14, 10}, {0, 0}, {0, 0}},   // n = 26, 27
    {{15, 17}, {16, 13}, {14, 2}, {0, 0}},  {{16, 24}, {15, 7}, {19, 1}, {0, 0}},   // n = 28, 29
    {{17, 19}, {16, 11}, {15, 2}, {0, 0}},  {{17, 18}, {16, 7}, {18, 7}, {0, 0}},   // n = 30, 31
    {{19, 20}, {17, 8}, {16, 2}, {18, 2}},  {{18, 15}, {20, 12}, {17, 4}, {19, 1}}, // n = 32, 33
    {{19, 23}, {20, 6}, {23, 2}, {17, 1}},  {{19, 14}, {21, 11}, {23, 5}, {18, 2}}, // n = 34, 35
    {{21, 29}, {18, 1}, {33, 1}, {35, 1}},  {{21, 22}, {25, 8}, {28, 1}, {35, 1}},  // n = 36, 37
    {{21, 20}, {25, 9}, {23, 2}, {19, 1}},  {{23, 26}, {26, 3}, {29, 2}, {38, 1}},  // n = 38, 39
    {{23, 14}, {24, 9}, {21, 7}, {25, 2}},  {{25, 26}, {21, 4}, {23, 1}, {27, 1}},  // n = 40, 41
    {{26, 14}, {29, 14}, {28, 3}, {41, 1}}, {{26, 30}, {40, 2}, {0, 0}, {0, 0}},    // n = 42, 43
    {{26, 25}, {33, 5}, {35, 1}, {43, 1}},  {{29, 26}, {30, 3}, {23, 2}, {37, 1}},  // n = 44, 45
    {{28, 20}, {31, 10}, {23, 1}, {37, 1}}, {{30, 23}, {31, 8}, {42, 1}, {0, 0}},   // n = 46, 47
    {{30, 21}, {31, 8}, {38, 2}, {47, 1}},  {{28, 14}, {33, 9}, {36, 8}, {45, 1}},  // n = 48, 49
    {{32, 22}, {30, 7}, {42, 2}, {49, 1}},  {{38, 16}, {33, 11}, {30, 3}, {34, 2}}, // n = 50, 51
    {{31, 17}, {34, 8}, {43, 6}, {26, 1}},  {{37, 21}, {28, 6}, {27, 3}, {36, 2}},  // n = 52, 53
    {{35, 18}, {33, 11}, {36, 2}, {45, 1}}, {{35, 20}, {37, 8}, {44, 2}, {50, 2}},  // n = 54, 55
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
    shufflePoints<1>(pts, n, deriveSeed(stream, 0x5a0ffu));
    return pts;
}

} // namespace stipple::detail::pointsets
