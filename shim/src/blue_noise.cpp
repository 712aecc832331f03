// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// blue_noise.cpp — the lattice maps from pixels to sub-cells.
#include "blue_noise.h"

#include "hash.h"

namespace stipple::detail {

namespace {

// Rows: the coefficients of the pixel's x and y per axis, mod Q, from shim/bench/lattice_search.py (seeded random
// searches). 3D (predicted white / low-band share 460) and 1D (1643): the A whose plane waves, cut by the 64-pixel
// tiles, leak the least of a second-order Taylor polynomial inside a stratum (folded by the tent) into |f| < 1/8
// cycle per pixel. 2D: a family of kFamily2 maps, one hashed per tile (lattice_search.py --family strata). One map,
// however chosen, sends the modes of some integrand that varies inside a stratum into the low band: the former
// single A (23, 50; 15, 37) raised the low-band error of 12 x 12 checkerboards at N = 16 and 24 x 24 at N = 64
// 1.25-1.4 times. The family was picked greedily among maps with a Taylor gain >= 100 (their least 150, the former single map 811) so that the average
// over its maps (and the tile symmetries) keeps every integrand of the grown battery's classes - checkerboards
// 7 x 7 to 24 x 24, gratings cos(2 pi k.x) with |k| <= 2 sqrt(N), stripes, axis and near-axis steps - at a
// predicted gain > 1 at N = 16, 64, 256. Every 2D and 1D map is a bijection of the tile onto the 64 x 64 (4096)
// values (2D: det A odd; 1D: checked below), so a tile's pixels take every sub-cell of a stratum once.
constexpr uint32_t kFamily2Log2 = 5, kFamily2 = 1u << kFamily2Log2;
constexpr int32_t kMap1[2] = {3136, 2339};
constexpr int32_t kMaps2[kFamily2][2][2] = {
    {{45, 13}, {46, 31}}, {{45, 13}, {46, 31}}, {{37, 22}, {48, 39}}, {{23, 26}, {46, 9}},
    {{29, 40}, {38, 49}}, {{15, 40}, {26, 55}}, {{47, 28}, {13, 11}}, {{29, 40}, {38, 49}},
    {{16, 25}, {33, 14}}, {{37, 22}, {48, 39}}, {{23, 26}, {46, 9}}, {{43, 55}, {55, 32}},
    {{43, 56}, {13, 45}}, {{16, 25}, {33, 14}}, {{43, 56}, {13, 45}}, {{23, 26}, {46, 9}},
    {{16, 25}, {33, 14}}, {{47, 28}, {13, 11}}, {{25, 29}, {10, 41}}, {{37, 22}, {48, 39}},
    {{34, 23}, {9, 38}}, {{22, 27}, {55, 31}}, {{29, 40}, {38, 49}}, {{37, 22}, {48, 39}},
    {{34, 23}, {9, 38}}, {{16, 13}, {27, 16}}, {{25, 29}, {10, 41}}, {{30, 51}, {37, 24}},
    {{43, 56}, {13, 45}}, {{37, 22}, {48, 39}}, {{45, 13}, {46, 31}}, {{43, 55}, {55, 32}},
};
constexpr int32_t kMap3[3][2] = {{44, 52}, {55, 22}, {36, 24}};
constexpr bool oddDeterminant(const int32_t (&a)[2][2]) { return (a[0][0] * a[1][1] - a[0][1] * a[1][0]) % 2 != 0; }
constexpr bool oddDeterminants() {
    for (const auto& a : kMaps2)
        if (!oddDeterminant(a)) return false;
    return true;
}
static_assert(oddDeterminants());
// 1D: a x + b y mod 4096 takes every value once over the tile, for every swap and reflection of the pixel axes.
constexpr bool bijective1(const int32_t (&a)[2]) {
    for (uint32_t variant = 0; variant < 8; ++variant) {
        bool seen[4096] = {};
        for (int32_t y = 0; y < 64; ++y)
            for (int32_t x = 0; x < 64; ++x) {
                const int32_t u = variant & 2 ? 63 - x : x, v = variant & 4 ? 63 - y : y;
                const uint32_t c = uint32_t(variant & 1 ? a[0] * v + a[1] * u : a[0] * u + a[1] * v) & 4095u;
                if (seen[c]) return false;
                seen[c] = true;
            }
    }
    return true;
}
static_assert(bijective1(kMap1));

constexpr uint64_t kSymmetryIndex = 0x5e77u;

} // namespace

// The map of pixel (x, y) is, per axis i, v = row[0] x' + row[1] y' negated or not, with (x', y') the pixel's
// position swapped and reflected (x' = 63 - x or x): a linear function of (x, y), whose coefficients are found here
// once per tile. Arithmetic mod 2^32, which Q divides.
LatticeTile::LatticeTile(uint64_t tileKey, uint32_t arity) {
    // A hashed signed permutation of the pixel axes (swap, then reflect each) and of the value axes (a rotation
    // of the axes, a reflection of each), and in 2D a hashed map of the family, so tiles and dimensions do not
    // share one grating.
    const uint64_t h = hashAt(tileKey, kSymmetryIndex);
    constexpr uint32_t kEdge = (1u << kBlueNoiseTileLog2) - 1;
    // x' = base + step * (swapped ? y : x), likewise y'.
    const uint32_t xBase = h & 2 ? kEdge : 0, yBase = h & 4 ? kEdge : 0;
    const uint32_t xStep = h & 2 ? ~0u : 1u, yStep = h & 4 ? ~0u : 1u;
    const bool swapped = h & 1;
    const auto set = [&](uint32_t i, const int32_t* row, bool negated) {
        const uint32_t a = uint32_t(row[0]), b = uint32_t(row[1]), sign = negated ? ~0u : 1u;
        const uint32_t onX = a * xStep, onY = b * yStep; // coefficients of x' and y' in terms of the swapped axes
        k0[i] = sign * (a * xBase + b * yBase);
        kx[i] = sign * (swapped ? onY : onX);
        ky[i] = sign * (swapped ? onX : onY);
    };
    if (arity == 1) {
        set(0, kMap1, (h & 8) != 0);
        mask = 4095u;
        return;
    }
    mask = 63u;
    // Divisions by the constants 2 and 3, not by `arity`.
    if (arity == 2) {
        const uint32_t rotation = uint32_t((h >> 8) & 1);
        const int32_t(&a2)[2][2] = kMaps2[(h >> 24) & (kFamily2 - 1)];
        for (uint32_t i = 0; i < 2; ++i) set(i, a2[i ^ rotation], ((h >> (16 + i)) & 1) != 0);
        return;
    }
    const uint32_t rotation = uint32_t((h >> 8) % 3);
    for (uint32_t i = 0; i < 3; ++i)
        set(i, kMap3[i + rotation < 3 ? i + rotation : i + rotation - 3], ((h >> (16 + i)) & 1) != 0);
}

void CrossPixelStrata::place(uint64_t stratum, uint32_t arity, uint32_t* jitter) const {
    const uint64_t offsets = hashAt(offsetKey(), stratum);
    switch (arity) {
    case 1: jitter[0] = jitterInSubCell<1>(lattice.c[0], offsets, 0, jitter[0]); return;
    case 2:
        for (uint32_t i = 0; i < 2; ++i) jitter[i] = jitterInSubCell<2>(lattice.c[i], offsets, i, jitter[i]);
        return;
    default:
        for (uint32_t i = 0; i < 3; ++i) jitter[i] = jitterInSubCell<3>(lattice.c[i], offsets, i, jitter[i]);
    }
}

} // namespace stipple::detail
