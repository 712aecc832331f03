// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// blue_noise.cpp — the lattice map from pixels to sub-cells.
#include "blue_noise.h"

#include "hash.h"

#include <utility>

namespace stipple::detail {

namespace {

// Rows: the coefficients of the pixel's x and y per axis, mod Q, from shim/bench/lattice_search.py (a seeded random
// search): per arity and use, the A whose plane waves, cut by the 64-pixel tiles, leak the least error energy into
// |f| < 1/8 cycle per pixel (predicted white / low-band ratios in parentheses). Strata: a second-order Taylor
// polynomial inside a stratum, folded by the tent (3D 460, 1D 1643); 2D (811) also counts aliasing: an integrand
// that oscillates inside a stratum (the zone plate) has its error in modes of moderate order, which the lattice
// minimising the Taylor share alone (1006) sent into the low band (zone-plate gain 0.93 at N = 16); the kept A
// comes from lattice_search.py --strata-aliasing (predicted zone-plate gain >= 1.59 at N = 16, 64, 256). Square
// (independent: the stratum is the unit square): the worst of Gaussian bumps of width 0.15 at 5 positions per axis,
// folded by the tent (3D 2, 1D 404); 2D (11) picked among the search's candidates for a zone-plate gain above 1
// (the least-share A, 20, added 4% low-frequency error there). Every 2D and 1D map is a bijection of the tile onto
// the 64 x 64
// (4096) values (2D: det A odd; 1D: checked below), so a tile's
// pixels take every sub-cell of a stratum once.
struct LatticeMaps {
    int32_t a1[2];
    int32_t a2[2][2];
    int32_t a3[3][2];
};
constexpr LatticeMaps kMaps[2] = {
    {{3136, 2339}, {{23, 50}, {15, 37}}, {{44, 52}, {55, 22}, {36, 24}}}, // LatticeUse::Strata
    {{1627, 576}, {{44, 33}, {47, 50}}, {{61, 21}, {18, 61}, {51, 35}}},  // LatticeUse::Square
};
constexpr bool oddDeterminant(const int32_t (&a)[2][2]) { return (a[0][0] * a[1][1] - a[0][1] * a[1][0]) % 2 != 0; }
static_assert(oddDeterminant(kMaps[0].a2) && oddDeterminant(kMaps[1].a2));
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
static_assert(bijective1(kMaps[0].a1) && bijective1(kMaps[1].a1));

constexpr uint64_t kSymmetryIndex = 0x5e77u;

} // namespace

LatticePixel::LatticePixel(uint64_t tileKey, uint32_t pixelX, uint32_t pixelY, uint32_t arity, LatticeUse use) {
    const LatticeMaps& maps = kMaps[static_cast<uint32_t>(use)];
    // A hashed signed permutation of the pixel axes (swap, then reflect each) and of the value axes (a rotation
    // of the axes, a reflection of each), so tiles and dimensions do not share one grating.
    const uint64_t h = hashAt(tileKey, kSymmetryIndex);
    constexpr uint32_t kMask = (1u << kBlueNoiseTileLog2) - 1;
    int32_t x = int32_t(pixelX & kMask), y = int32_t(pixelY & kMask);
    if (h & 1) std::swap(x, y);
    if (h & 2) x = int32_t(kMask) - x;
    if (h & 4) y = int32_t(kMask) - y;
    if (arity == 1) {
        const int32_t v = maps.a1[0] * x + maps.a1[1] * y;
        c[0] = uint32_t((h & 8) ? -v : v) & 4095u;
        return;
    }
    // Divisions by the constants 2 and 3, not by `arity` (a 64-bit division on the path of every blue-noise call).
    if (arity == 2) {
        const uint32_t rotation = uint32_t((h >> 8) & 1);
        for (uint32_t i = 0; i < 2; ++i) {
            const int32_t* row = maps.a2[i ^ rotation];
            const int32_t v = row[0] * x + row[1] * y;
            c[i] = uint32_t((h >> (16 + i)) & 1 ? -v : v) & 63u;
        }
        return;
    }
    const uint32_t rotation = uint32_t((h >> 8) % 3);
    for (uint32_t i = 0; i < 3; ++i) {
        const int32_t* row = maps.a3[i + rotation < 3 ? i + rotation : i + rotation - 3];
        const int32_t v = row[0] * x + row[1] * y;
        c[i] = uint32_t((h >> (16 + i)) & 1 ? -v : v) & 63u;
    }
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
