// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pmj02_generator.h — progressive multi-jittered (0,2) sequences (Christensen, Kensler & Kilpatrick 2018).
//
// generatePmj02(log2Length, seed) returns 2^log2Length points as 32-bit fixed-point (x, y) pairs such that every
// prefix of 2^k points (k <= log2Length) has exactly one point in every 2D elementary interval of area 2^-k
// (every 2^a x 2^(k-a) grid), hence is also stratified in 1D. A pure function of (log2Length, seed).
//
// generatePmj02Depth(points, seed) adds a third coordinate z to such a sequence (at most 2^16 points): every
// prefix of 2^k points is stratified in z at 2^-k, and for every r with 2r <= k each (x, y) cell of side 2^-r
// holds 2^(k-2r) points stratified in z at 2^-(k-2r): one point in every 2^-r x 2^-r x 2^-(k-2r) box, so the
// cubes of side 2^-r hold equal counts (one per cube at 8^r points: a jittered 3D set) and (x, z) and (y, z) are
// stratified on the 2^r x 2^r grids with equal counts. They are not one point per cell of the finer 2^q x 2^q grids
// of a 4^q prefix (that, kept at every q, would put z on a surface).
#pragma once

#include <cstdint>
#include <vector>

namespace stipple::detail {

struct FixedPoint2 {
    uint32_t x, y;
};

std::vector<FixedPoint2> generatePmj02(uint32_t log2Length, uint64_t seed);

// z for every point of a generatePmj02 sequence (points.size() a power of two). A pure function of its arguments.
std::vector<uint32_t> generatePmj02Depth(const std::vector<FixedPoint2>& points, uint64_t seed);

// True if points[0, 2^k) has one point in every elementary interval of area 2^-k (used by the generator's own
// verification and by the tests).
bool isElementaryNet(const FixedPoint2* points, uint32_t k);

} // namespace stipple::detail
