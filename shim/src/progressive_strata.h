// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// progressive_strata.h — the cell of point q in the progressive order of a power-of-two strata grid.
//
// q's bits, read from bit 0 up and dealt axis by axis (x, y, z, x, ...), are the cell coordinates' bits from the
// most significant down: q mod 2^j picks one cell of the coarse grid made of the first j dealt bits. Axis sizes
// of an exact power-of-two grid differ by at most one bit, so plain bit compaction deals them.
#pragma once

#include <cstdint>

namespace stipple::detail {

constexpr uint32_t reverseBits(uint32_t v, uint32_t bits) {
    v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
    v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
    v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
    v = __builtin_bswap32(v);
    return bits == 0 ? 0 : v >> (32 - bits);
}

// Bit-reversal of a byte, tabulated: reversing a value of <= 16 bits is then two lookups (the per-value path).
struct ReversedBytes {
    uint8_t table[256];
    constexpr ReversedBytes() : table() {
        for (uint32_t b = 0; b < 256; ++b) table[b] = static_cast<uint8_t>(reverseBits(b, 8));
    }
};
inline constexpr ReversedBytes kReversedBytes{};

// reverseBits(v, bits) for bits <= 16.
inline uint32_t reverseBits16(uint32_t v, uint32_t bits) {
    const uint32_t r = (uint32_t(kReversedBytes.table[v & 0xffu]) << 8) | kReversedBytes.table[(v >> 8) & 0xffu];
    return r >> (16 - bits);
}

constexpr uint32_t compactEvery2(uint32_t v) { // bits 0, 2, 4, ... of v
    v &= 0x55555555u;
    v = (v | (v >> 1)) & 0x33333333u;
    v = (v | (v >> 2)) & 0x0f0f0f0fu;
    v = (v | (v >> 4)) & 0x00ff00ffu;
    return (v | (v >> 8)) & 0x0000ffffu;
}

constexpr uint32_t compactEvery3(uint32_t v) { // bits 0, 3, 6, ... of v
    v &= 0x09249249u;
    v = (v | (v >> 2)) & 0x030c30c3u;
    v = (v | (v >> 4)) & 0x0300f00fu;
    v = (v | (v >> 8)) & 0x030000ffu;
    return (v | (v >> 16)) & 0x000003ffu;
}

// Cell coordinates of q for a grid of `arity` axes with axisBits[c] = log2(strata on axis c).
constexpr void progressiveCell(uint32_t q, uint32_t arity, const uint32_t axisBits[3], uint32_t cell[3]) {
    if (arity == 1) {
        cell[0] = reverseBits(q, axisBits[0]);
    } else if (arity == 2) {
        cell[0] = reverseBits(compactEvery2(q), axisBits[0]);
        cell[1] = reverseBits(compactEvery2(q >> 1), axisBits[1]);
    } else {
        cell[0] = reverseBits(compactEvery3(q), axisBits[0]);
        cell[1] = reverseBits(compactEvery3(q >> 1), axisBits[1]);
        cell[2] = reverseBits(compactEvery3(q >> 2), axisBits[2]);
    }
}

} // namespace stipple::detail
