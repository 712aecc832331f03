// blue_noise.h — screen-space blue noise: neighbouring pixels get sets whose errors are negatively correlated.
//
// STIPPLE_SAMPLER_FLAG_BLUE_NOISE. Two mechanisms:
// - sobol: a Morton (Z-order) assignment of Sobol' blocks to pixels, as in Ahmed & Wonka (2020) and pbrt-v4's
//   ZSobolSampler. Within a tile of 2^T x 2^T pixels all pixels share one Owen scrambling per dimension, and the
//   pixel at (x, y) takes block number morton(x, y), with each base-4 Morton digit permuted by a hash of the
//   digits above it (and of the tile and dimension). Every aligned 2^l x 2^l square of pixels then holds 4^l
//   consecutive blocks: together a (0, m + 2l, 2)-net, so the sum of their errors is far below that of
//   independent sets — the error has little energy at low frequencies. Each pixel's own set is still a
//   scrambled net, so per-pixel quality is unchanged.
// - stratified and independent: stratification across pixels. In a tile of 2^T x 2^T pixels (T = 6), every
//   stratum (independent: the unit square, once per point index) is cut into 2^T x 2^T sub-cells (1D: 4^T), and
//   the pixels of the tile take its sub-cells through the same digit-permuted Morton map as above, with a
//   permutation hashed per stratum. A pixel's point is still uniform in its stratum and independent of its
//   other points (each stratum has its own permutation), so every pixel's set has the plain pattern's
//   distribution; the points of an aligned 2^l x 2^l square of pixels in one stratum are stratified 2^l x 2^l.
// - poisson, poisson-seed and pmj02: a per-pixel toroidal shift (Cranley-Patterson rotation) read from a 64 x 64
//   blue-noise mask (Georgiev & Fajardo 2016), over a base set shared by the pixels of a 64 x 64 tile.
//   The mask is made once, deterministically, by void-and-cluster (Ulichney 1993). A shift uniform over
//   [0,1)^d per pixel (mask value plus a hashed offset per tile and axis) keeps every sample uniform.
#pragma once

#include "patterns.h"

#include <cstdint>

namespace stipple {

constexpr uint32_t kBlueNoiseMaskLog2 = 6; // 64 x 64

// The void-and-cluster mask: kBlueNoiseMaskSize^2 values (i + 0.5) / size^2, each rank once, row-major.
const float* blueNoiseMask();

constexpr uint32_t kCrossPixelLevels = 6; // tiles of 64 x 64 pixels

// Where pixel (x, y) puts its point inside a stratum shared by the pixels of its tile.
struct CrossPixelStrata {
    uint64_t tileKey; // hashed from (seed, pattern, tile, dimension)
    uint32_t pixelX, pixelY;
    // The pixel's sub-cell of the stratum with this id: a Morton index in [0, 4^T), digits permuted per stratum.
    uint32_t subcell(uint64_t stratum) const;
    // The jitters (32-bit fractions of the stratum per axis) moved into the pixel's sub-cell.
    void place(uint64_t stratum, uint32_t arity, uint32_t* jitter) const;
};

// The sobol set of pixel (x, y) for a dimension: dimensionKey is hashed from (seed, dimension) (the tile is
// folded in here), pixelKey from (seed, pixel, dimension).
SobolSet zOrderSobolSet(uint64_t dimensionKey, uint64_t pixelKey, uint32_t pixelX, uint32_t pixelY,
                        uint32_t log2Length);

// The per-pixel toroidal shift of the mask-based variant, one value per axis in [0, 1).
void blueNoiseShift(uint64_t tileKey, uint32_t pixelX, uint32_t pixelY, uint32_t arity, float* shift);

// x + shift wrapped into [0, 1) for count points of `arity` floats.
void applyToroidalShift(const float* shift, uint32_t arity, size_t count, float* values);

} // namespace stipple
