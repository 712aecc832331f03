// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// owen_scrambling.h — hash-based nested uniform (Owen) scrambling of 32-bit binary fractions.
//
// Burley, "Practical Hash-based Owen Scrambling" (JCGT 9(4), 2020), after Laine & Karras (2011): a hash whose
// every output bit depends only on the input bits below it (multiplication and addition carry upwards) is an
// Owen scramble of the bit-reversed value, because a binary fraction's digit t is then permuted by a function of
// the digits before it. Applied to a coordinate it keeps every elementary-interval stratification; applied to a
// sample index it shuffles the order so that every aligned block of 2^j indices maps onto an aligned block of
// 2^j indices (prefixes of a (0,m,2)-net stay nets).
#pragma once

#include <cstdint>

namespace stipple::detail {

constexpr uint32_t reverseBits32(uint32_t v) {
    v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
    v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
    v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
    v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
    return (v >> 16) | (v << 16);
}

// Burley's improved Laine-Karras permutation (the constants of the paper's listing 3).
constexpr uint32_t laineKarrasPermutation(uint32_t x, uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// Vegdahl's Laine-Karras hash ("Building a better LK hash", 2021): the seed also multiplies, which mixes the
// input's low bits (the fraction's leading digits) better than the listing above; the same cost.
constexpr uint32_t vegdahlPermutation(uint32_t x, uint32_t seed) {
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

// Owen scrambling of the binary fraction x / 2^32: output bit t depends on input bits t..31 only.
constexpr uint32_t nestedUniformScramble(uint32_t x, uint32_t seed) {
    return reverseBits32(laineKarrasPermutation(reverseBits32(x), seed));
}

// A 32-bit integer hash with full avalanche (Wellons' "lowbias32").
constexpr uint32_t mixBits32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

// The Laine-Karras hash is nested but not uniform: its low digits are poor functions of the digits above them
// (Vegdahl 2021), so inside the 2^-level intervals that a set of 2^level points fills once, the points are not
// uniform and independent (12 N Var(mean of frac(N x)) measured 0.25..2.2 instead of Owen's 1). deepOwenScramble
// completes a nested scramble below digit `level` the way Owen's definition asks, at the cost of two hashes:
//  - digits level, level+1, level+2: each flipped by its own bit of one hash of the digits above `level`, the bit
//    chosen by the (already scrambled) digits between: a binary tree of 7 flips, exactly Owen's per-digit flips;
//  - every digit from level + 3 on: XORed with a hash of the first level + 3 digits.
// The result is again a nested scramble (a digit's flip depends only on the digits above it, so it permutes the
// subintervals of every elementary interval): nets stay nets. For points whose first level + 3 digits differ
// (one block of 2^level points of a (0,level,1) projection, and up to 8 such blocks of the sequence) it is
// exactly nested uniform below `level`, up to the hash: each point uniform in its interval, independently.
// z holds the fraction's digits reversed (digit t at bit t), as the Laine-Karras hash sees them; level <= 22
// (the largest set), so level + 3 < 32.
constexpr uint32_t deepOwenScrambleReversed(uint32_t z, uint32_t level, uint32_t seed) {
    const uint32_t tree = mixBits32((z & ((1u << level) - 1u)) ^ seed);
    uint32_t node = 0; // 0; then 1, 2; then 3..6
    for (uint32_t t = level; t < level + 3; ++t) {
        z ^= ((tree >> node) & 1u) << t;
        node = 2 * node + 1 + ((z >> t) & 1u);
    }
    const uint32_t deep = level + 3;
    return z ^ (mixBits32((z & ((1u << deep) - 1u)) ^ (seed * 0x9e3779b9u)) << deep);
}

// A 32-bit fixed-point fraction as a float in [0, 1): the top 24 bits, so 1.0 cannot occur.
constexpr float fixedToUnitFloat(uint32_t x) { return static_cast<float>(x >> 8) * 0x1p-24f; }

} // namespace stipple::detail
