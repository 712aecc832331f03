// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// blue_noise.h — screen-space blue noise: neighbouring pixels get sets whose errors cancel at low frequencies.
//
// STIPPLE_SAMPLER_FLAG_BLUE_NOISE, for stratified. One mechanism: a lattice map per tile of 64 x 64 pixels and
// dimension. Pixel p = (x, y) of the tile maps to c(p) = (A p + o) mod Q per axis (A an integer arity x 2 matrix,
// o an offset). Mode k of any periodic function of c is, across the tile, a plane wave of pixel frequency A^T k / Q;
// A (blue_noise.cpp; shim/bench/lattice_search.py) is chosen so that the modes which carry a smooth integrand's
// error land far above the low band. Within a tile the error of a fixed integrand is therefore a sum of
// high-frequency gratings, like an ordered dither. Per (tile, dimension, stream, block) a hashed signed
// permutation of the pixel axes and of the value axes, random offsets and (2D) a hashed A of a family make
// neighbouring tiles and different dimensions use different gratings; the family keeps integrands whose error sits
// in high modes inside a stratum (checkerboards, gratings near the sample spacing) from landing in the low band
// in every tile.
// Every stratum is cut into 64 x 64 sub-cells (3D: per axis; 1D: 4096); the pixel's point goes to sub-cell
// tent(c(p)) with an offset o hashed per stratum, and keeps its own jitter inside it. tent(c) = 2c below Q/2,
// 2(Q - 1 - c) + 1 above: a bijection of 0..Q-1 that makes a ramp inside the stratum (what a smooth integrand is
// there) a continuous periodic function of c, whose modes decay fast (a sawtooth's do not). 2D and 1D maps are
// bijections of the tile onto the sub-cells (det A odd; 1D checked), so a tile's pixels stratify every stratum
// among themselves. The offset makes the sub-cell uniform and independent across strata: every pixel's set has
// exactly the plain pattern's distribution.
// Other patterns refuse the flag (pattern_registry.h, BlueNoiseMode::Unsupported, with the reason).
#pragma once

#include "hash.h"
#include "batch_isa.h"
#include "dimension.h"

#include <cstddef>
#include <cstdint>

namespace stipple::detail {

constexpr uint32_t kBlueNoiseTileLog2 = 6; // tiles of 64 x 64 pixels

// The lattice map of one (tile, dimension, stream, block): c(p) = (k0 + kx x + ky y) mod Q per axis for the pixel
// (x, y) of the tile, with the tile's hashed signed permutations folded into the coefficients, so that a pixel's
// values cost no hash (the sampler keeps the tile's map with its key, sampler.cpp).
struct LatticeTile {
    uint32_t k0[3] = {0, 0, 0}, kx[3] = {0, 0, 0}, ky[3] = {0, 0, 0};
    uint32_t mask = 0; // Q - 1
    LatticeTile() = default;
    LatticeTile(uint64_t tileKey, uint32_t arity);
};

// The lattice map of one (tile, dimension, stream, block) at one pixel: c(p) without the offset, per axis.
struct LatticePixel {
    uint32_t c[3] = {0, 0, 0}; // in [0, Q): Q = 64, or 4096 for arity 1
    LatticePixel(const LatticeTile& tile, uint32_t pixelX, uint32_t pixelY) {
        constexpr uint32_t kMask = (1u << kBlueNoiseTileLog2) - 1;
        const uint32_t x = pixelX & kMask, y = pixelY & kMask;
        for (uint32_t i = 0; i < 3; ++i) c[i] = (tile.k0[i] + tile.kx[i] * x + tile.ky[i] * y) & tile.mask;
    }
};

// Axis `axis` of a jitter (a 32-bit fraction of the stratum) moved into sub-cell tent((c + o) mod Q) of the stratum,
// c the pixel's lattice value and o the axis' offset (bits 8 axis.. of `offsets`; 1D: its low 12 bits). tent: the
// sub-cell order 0, 2, 4, ..., Q-2, Q-1, ..., 3, 1, so neighbouring values of c are neighbouring sub-cells also
// across the wrap. Branch-free integer work, so the batch kernels vectorise it.
template <uint32_t Arity>
[[gnu::always_inline]] inline uint32_t jitterInSubCell(uint32_t latticeC, uint64_t offsets, uint32_t axis,
                                                       uint32_t jitter) {
    constexpr uint32_t kQLog2 = Arity == 1 ? 2 * kBlueNoiseTileLog2 : kBlueNoiseTileLog2, Q = 1u << kQLog2;
    const uint32_t c = (latticeC + static_cast<uint32_t>(Arity == 1 ? offsets : offsets >> (8 * axis))) & (Q - 1);
    const uint32_t t = c < Q / 2 ? 2 * c : 2 * (Q - 1 - c) + 1;
    return (t << (32 - kQLog2)) | (jitter >> kQLog2);
}

// Where pixel (x, y) puts its point inside a stratum shared by the pixels of its tile.
struct CrossPixelStrata {
    uint64_t tileKey; // hashed from (seed, pattern, tile, dimension[, stream arity][, block])
    LatticePixel lattice;
    CrossPixelStrata(uint64_t tileKey, const LatticeTile& tile, uint32_t pixelX, uint32_t pixelY)
        : tileKey(tileKey), lattice(tile, pixelX, pixelY) {}
    // The key of the tile's per-stratum offsets: a stratum's offsets are hashAt(offsetKey(), stratum id), one mix
    // per point (the ids are distinct per stratum).
    uint64_t offsetKey() const { return tileKey ^ 0x0ff5e75a17ed0001ull; }
    // The jitters (32-bit fractions of the stratum per axis) moved into the pixel's sub-cell of the stratum.
    void place(uint64_t stratum, uint32_t arity, uint32_t* jitter) const;
};

} // namespace stipple::detail
