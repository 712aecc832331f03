// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pmj02_generator.h — progressive multi-jittered (0,2) sequences (Christensen, Kensler & Kilpatrick 2018).
//
// generatePmj02(log2Length, seed) returns 2^log2Length points as 32-bit fixed-point (x, y) pairs such that every
// prefix of 2^k points (k <= log2Length) has exactly one point in every 2D elementary interval of area 2^-k
// (every 2^a x 2^(k-a) grid), hence is also stratified in 1D. A pure function of (log2Length, seed).
#pragma once

#include <cstdint>
#include <vector>

namespace stipple::detail {

struct FixedPoint2 {
    uint32_t x, y;
};

std::vector<FixedPoint2> generatePmj02(uint32_t log2Length, uint64_t seed);

// True if points[0, 2^k) has one point in every elementary interval of area 2^-k (used by the generator's own
// verification and by the tests).
bool isElementaryNet(const FixedPoint2* points, uint32_t k);

} // namespace stipple::detail
