// permutation.h — a hashed permutation of [0, length) evaluated one element at a time.
//
// Kensler, "Correlated Multi-Jittered Sampling" (Pixar Technical Memo 13-01, 2013): a bijective hash on the
// next power of two, cycle-walked into [0, length). O(1) expected per element (< 2 rounds on average), no
// table, so random access (stipple_sampler_sample) and the batch call evaluate the same permutation cheaply.
#pragma once

#include <cstdint>

namespace stipple {

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

} // namespace stipple
