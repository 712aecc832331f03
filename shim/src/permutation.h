// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// permutation.h — a hashed permutation of [0, length) evaluated one element at a time, or a run of them at once.
//
// Kensler, "Correlated Multi-Jittered Sampling" (Pixar Technical Memo 13-01, 2013): a bijective hash on the
// next power of two, cycle-walked into [0, length). O(1) expected per element (< 2 rounds on average), no
// table, so random access (stipple_sampler_sample) and the batch call evaluate the same permutation cheaply.
#pragma once

#include <cstdint>

namespace stipple::detail {

// The smallest all-ones mask covering [0, length): the domain of the bijection the cycle walk runs in.
constexpr uint32_t permutationMask(uint32_t length) {
    uint32_t w = length - 1;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    return w;
}

// One step of the cycle walk: Kensler's bijection of [0, w] keyed by p.
[[gnu::always_inline]] constexpr uint32_t permutationStep(uint32_t i, uint32_t w, uint32_t p) {
    i ^= p;
    i *= 0xe170893du;
    i ^= p >> 16;
    i ^= (i & w) >> 4;
    i ^= p >> 8;
    i *= 0x0929eb3fu;
    i ^= p >> 23;
    i ^= (i & w) >> 1;
    i *= 1u | p >> 27;
    i *= 0x6935fa69u;
    i ^= (i & w) >> 11;
    i *= 0x74dcb303u;
    i ^= (i & w) >> 2;
    i *= 0x9e501cc3u;
    i ^= (i & w) >> 2;
    i *= 0xc860a3dfu;
    i &= w;
    i ^= i >> 5;
    return i;
}

constexpr uint32_t permuteIndex(uint32_t i, uint32_t length, uint32_t p) {
    const uint32_t w = permutationMask(length);
    do i = permutationStep(i, w, p);
    while (i >= length);
    return static_cast<uint32_t>((uint64_t(i) + p) % length);
}

// The cycle walk of a run of elements, in place: step(v) until every value lies in [0, length). One element's
// walk takes a random number of steps, a branch the processor mispredicts about every other element; here each
// pass steps every element still outside, until none is, so the loops have no branch per element and vectorise.
template <typename Step>
[[gnu::always_inline]] inline void walkIntoRange(uint32_t* values, uint32_t count, uint32_t length, const Step& step) {
    uint32_t outside = 0;
    for (uint32_t k = 0; k < count; ++k) {
        values[k] = step(values[k]);
        outside |= static_cast<uint32_t>(values[k] >= length);
    }
    while (outside) {
        outside = 0;
        for (uint32_t k = 0; k < count; ++k) {
            const uint32_t v = values[k];
            values[k] = v >= length ? step(v) : v;
            outside |= static_cast<uint32_t>(values[k] >= length);
        }
    }
}

// permuteIndex of every values[k] in place (length <= 2^31), for the batch paths (walkIntoRange). The final
// offset is a subtraction: (i + p) mod length = (i + p mod length) mod length, and i + p mod length is below
// 2 length.
[[gnu::always_inline]] inline void permuteIndices(uint32_t* values, uint32_t count, uint32_t length, uint32_t p) {
    const uint32_t w = permutationMask(length);
    walkIntoRange(values, count, length, [w, p](uint32_t i) { return permutationStep(i, w, p); });
    const uint32_t offset = p % length;
    for (uint32_t k = 0; k < count; ++k) {
        const uint32_t shifted = values[k] + offset;
        values[k] = shifted >= length ? shifted - length : shifted;
    }
}

} // namespace stipple::detail

namespace stipple::detail {

// A cheaper hashed permutation of [0, length) for the per-value paths: a bijection on the next power of two
// (xor-shift and odd-multiply rounds, each invertible mod 2^k), cycle-walked into [0, length); no division.
// For a power-of-two length it is a single pass.
struct FastPermutation {
    uint32_t w, half, seed;
    constexpr FastPermutation(uint32_t length, uint32_t s)
        : w(permutationMask(length)), half((32 - static_cast<uint32_t>(__builtin_clz(w | 1))) / 2 + 1), seed(s) {}
    [[gnu::always_inline]] constexpr uint32_t step(uint32_t i) const {
        i = (i ^ seed) & w;
        i = (i * (seed | 1u)) & w;
        i ^= i >> half;
        i = (i * 0x2c1b3c6du) & w;
        i ^= (i >> 3) ^ (seed >> 16 & w);
        i = (i * 0x297a2d39u) & w;
        i ^= i >> half;
        return i;
    }
};

constexpr uint32_t permuteIndexFast(uint32_t i, uint32_t length, uint32_t seed) {
    const FastPermutation permutation(length, seed);
    do i = permutation.step(i);
    while (i >= length);
    return i;
}

// permuteIndexFast of every values[k] in place, for the batch paths (walkIntoRange).
[[gnu::always_inline]] inline void permuteIndicesFast(uint32_t* values, uint32_t count, uint32_t length,
                                                      uint32_t seed) {
    const FastPermutation permutation(length, seed);
    walkIntoRange(values, count, length, [&permutation](uint32_t i) { return permutation.step(i); });
}

} // namespace stipple::detail
