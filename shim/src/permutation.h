// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// permutation.h — a hashed permutation of [0, length) evaluated one element at a time.
//
// Kensler, "Correlated Multi-Jittered Sampling" (Pixar Technical Memo 13-01, 2013): a bijective hash on the
// next power of two, cycle-walked into [0, length). O(1) expected per element (< 2 rounds on average), no
// table, so random access (stipple_sampler_sample) and the batch call evaluate the same permutation cheaply.
#pragma once

#include <cstdint>

namespace stipple::detail {

constexpr uint32_t permuteIndex(uint32_t i, uint32_t length, uint32_t p) {
    uint32_t w = length - 1;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    do {
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
    } while (i >= length);
    return static_cast<uint32_t>((uint64_t(i) + p) % length);
}

} // namespace stipple::detail

namespace stipple::detail {

// A cheaper hashed permutation of [0, length) for the per-value paths: a bijection on the next power of two
// (xor-shift and odd-multiply rounds, each invertible mod 2^k), cycle-walked into [0, length); no division.
// For a power-of-two length it is a single pass.
constexpr uint32_t permuteIndexFast(uint32_t i, uint32_t length, uint32_t seed) {
    uint32_t w = length - 1;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    const uint32_t half = (32 - static_cast<uint32_t>(__builtin_clz(w | 1))) / 2 + 1;
    do {
        i = (i ^ seed) & w;
        i = (i * (seed | 1u)) & w;
        i ^= i >> half;
        i = (i * 0x2c1b3c6du) & w;
        i ^= (i >> 3) ^ (seed >> 16 & w);
        i = (i * 0x297a2d39u) & w;
        i ^= i >> half;
    } while (i >= length);
    return i;
}

} // namespace stipple::detail
