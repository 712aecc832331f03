// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// patterns.h — the sample patterns as pure functions of a set key.
//
// Each pattern serves the set of one (pixel, dimension, block): M points of `arity` floats (M = k*N for a
// declared dimension, N for a streamed one). fill* writes points [first, first + count) of the set (point p at
// out[(p - first) * arity]); point* writes point p alone and is bitwise equal to fill*'s point p. The key is
// the sampler's set key (seed, pattern domain, pixel, dimension, arity for streams) after the pattern's block
// keying (pattern_registry.h). A fill with batch kernels is a template on the BatchIsa it runs with; each pattern's
// source file instantiates it for its PatternOps, which is how the sampler reaches these functions.
#pragma once

#include "batch_isa.h"
#include "dimension.h"
#include "hash.h"

#include <cstdint>

namespace stipple::detail {

struct CrossPixelStrata; // blue_noise.h: with the blue-noise flag, stratified takes one

template <BatchIsa Isa>
void fillIndependent(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out);
void pointIndependent(uint64_t key, const Dimension& dim, uint32_t p, float* out);

template <BatchIsa Isa>
void fillStratified(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out,
                    const CrossPixelStrata* blue = nullptr);
void pointStratified(uint64_t key, const Dimension& dim, uint32_t p, float* out,
                     const CrossPixelStrata* blue = nullptr);

// The stored set a "poisson" set key serves: its top 32 bits scaled to [0, setCount) (no division per value).
constexpr uint32_t poissonSetIndex(uint64_t key, uint32_t setCount) {
    return static_cast<uint32_t>(((key >> 32) * setCount) >> 32);
}
template <BatchIsa Isa>
void fillPoisson(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out);
void pointPoisson(uint64_t key, const Dimension& dim, uint32_t p, float* out);

// poisson-seed generates its set afresh on every call (the study's cost, kept deliberately); random access to
// one point therefore goes through a whole generation.
void fillPoissonSeed(uint64_t key, const Dimension& dim, uint32_t first, uint32_t count, float* out);
void pointPoissonSeed(uint64_t key, const Dimension& dim, uint32_t p, float* out);

// sobol: the randomisation of one set (pattern_sobol.cpp). perPixel is the plain pattern; the blue-noise
// variant (blue_noise.h) takes one set per tile of pixels and shifts it per pixel.
struct SobolSet {
    uint32_t indexSeed = 0;
    uint32_t scramble[3] = {0, 0, 0};
    uint32_t blockBase = 0; // Sobol' block of the set's first M points
    static SobolSet perPixel(uint64_t key);
    // Block b of the set (sample indices [b*N, (b+1)*N)): the set's Sobol' block blockBase + b.
    SobolSet atBlock(uint32_t block) const {
        SobolSet s = *this;
        s.blockBase += block;
        return s;
    }
};
template <BatchIsa Isa>
void fillSobol(const SobolSet& set, const Dimension& dim, uint32_t first, uint32_t count, float* out);
void pointSobol(const SobolSet& set, const Dimension& dim, uint32_t p, float* out);

// pmj02: the key is the set's (before any block); block b continues the set's sequence (pattern_pmj02.cpp).
template <BatchIsa Isa>
void fillPmj02(uint64_t key, uint32_t block, const Dimension& dim, uint32_t first, uint32_t count, float* out);
void pointPmj02(uint64_t key, uint32_t block, const Dimension& dim, uint32_t p, float* out);

} // namespace stipple::detail
