// patterns.h — the sample patterns as pure functions of a set key.
//
// Each pattern serves the set of one (pixel, dimension): M = k*N points of `arity` floats. fill* writes the
// whole set (point p at out[p * arity]); point* writes point p alone and is bitwise equal to fill*'s point p.
// The key is setKey(seed, pattern domain, pixel, dimension).
#pragma once

#include "dimension.h"
#include "hash.h"

#include <cstdint>

namespace stipple {

struct CrossPixelStrata; // blue_noise.h: with the blue-noise flag, stratified and independent take one

void fillIndependent(uint64_t key, const Dimension& dim, float* out, const CrossPixelStrata* blue = nullptr);
void pointIndependent(uint64_t key, const Dimension& dim, uint32_t p, float* out,
                      const CrossPixelStrata* blue = nullptr);

void fillStratified(uint64_t key, const Dimension& dim, float* out, const CrossPixelStrata* blue = nullptr);
void pointStratified(uint64_t key, const Dimension& dim, uint32_t p, float* out,
                     const CrossPixelStrata* blue = nullptr);

void fillPoisson(uint64_t key, const Dimension& dim, float* out);
void pointPoisson(uint64_t key, const Dimension& dim, uint32_t p, float* out);

// poisson-seed generates its set afresh on every call (the study's cost, kept deliberately); random access to
// one sample therefore goes through a whole fill (Sampler::sample).
void fillPoissonSeed(uint64_t key, const Dimension& dim, float* out);

// sobol: the randomisation of one set (pattern_sobol.cpp). perPixel is the plain pattern; the blue-noise
// variant (blue_noise.h) shares the Owen scrambling across a tile of pixels and gives each pixel its own block.
struct SobolSet {
    uint32_t indexSeed = 0;
    uint32_t scramble[3] = {0, 0, 0};
    uint32_t blockBase = 0;   // Sobol' block of the set's first M points
    uint32_t blockStride = 1; // blocks between the set's block b and b + 1 (points past the set)
    static SobolSet perPixel(uint64_t key);
};
void fillSobol(const SobolSet& set, const Dimension& dim, float* out);
void pointSobol(const SobolSet& set, const Dimension& dim, uint32_t p, float* out);

void fillPmj02(uint64_t key, const Dimension& dim, float* out);
void pointPmj02(uint64_t key, const Dimension& dim, uint32_t p, float* out);

} // namespace stipple
