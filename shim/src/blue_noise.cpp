// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// blue_noise.cpp — the lattice map from pixels to sub-cells.
#include "blue_noise.h"

#include "hash.h"

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

// The map of pixel (x, y) is, per axis i, v = row[0] x' + row[1] y' negated or not, with (x', y') the pixel's
// position swapped and reflected (x' = 63 - x or x): a linear function of (x, y), whose coefficients are found here
// once per tile. Arithmetic mod 2^32, which Q divides.
LatticeTile::LatticeTile(uint64_t tileKey, uint32_t arity, LatticeUse use) {
    const LatticeMaps& maps = kMaps[static_cast<uint32_t>(use)];
    // A hashed signed permutation of the pixel axes (swap, then reflect each) and of the value axes (a rotation
    // of the axes, a reflection of each), so tiles and dimensions do not share one grating.
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
        set(0, maps.a1, (h & 8) != 0);
        mask = 4095u;
        return;
    }
    mask = 63u;
    // Divisions by the constants 2 and 3, not by `arity`.
    if (arity == 2) {
        const uint32_t rotation = uint32_t((h >> 8) & 1);
        for (uint32_t i = 0; i < 2; ++i) set(i, maps.a2[i ^ rotation], ((h >> (16 + i)) & 1) != 0);
        return;
    }
    const uint32_t rotation = uint32_t((h >> 8) % 3);
    for (uint32_t i = 0; i < 3; ++i)
        set(i, maps.a3[i + rotation < 3 ? i + rotation : i + rotation - 3], ((h >> (16 + i)) & 1) != 0);
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
