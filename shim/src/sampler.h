// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// sampler.h — the object behind a stipple_sampler handle: immutable after creation, shared by threads.
//
// Two ways in:
//  - the declared layout (dimension d of the desc, k values per sample): fillPixel / sample;
//  - streams (no layout needed): dimension index d asked with an arity 1..3 at the call, one value per sample.
//    Stream (d, arity) is its own set of N points per block, keyed apart from the declared layout's dimension d.
// Sample index i lies in block b = i / N at position i mod N; each block is a full, independently randomised set.
#pragma once

#include "array_sets.h"
#include "dimension.h"
#include "pattern_registry.h"

#include <stipple/stipple.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <vector>

namespace stipple::detail {

class Sampler {
public:
    // pattern: a valid public id (findPattern(pattern) != nullptr); flags: known STIPPLE_SAMPLER_FLAG_* bits.
    Sampler(uint32_t pattern, uint32_t samplesPerPixel, uint64_t seed, std::vector<Dimension> dimensions,
            uint32_t flags = 0);

    uint32_t pattern() const { return pattern_; }
    const PatternOps& patternOps() const { return ops_; }
    uint32_t samplesPerPixel() const { return samplesPerPixel_; }
    uint64_t seed() const { return seed_; }
    uint32_t flags() const { return flags_; }
    uint32_t dimensionCount() const { return static_cast<uint32_t>(dimensions_.size()); }
    const Dimension& dimension(uint32_t d) const { return dimensions_[d]; }

    // Arguments are checked by the ABI layer; these only compute.
    void fillPixel(uint32_t pixelX, uint32_t pixelY, uint32_t d, float* out) const; // block 0
    void sample(uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex, uint32_t d, float* out) const;
    void stream(uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex, uint32_t d, uint32_t arity, float* out) const;
    // Samples [firstSample, firstSample + count) of stream (d, arity); firstSample + count <= 2^32.
    void streamFill(uint32_t pixelX, uint32_t pixelY, uint32_t firstSample, uint32_t count, uint32_t d, uint32_t arity,
                    float* out) const;
    void sampleIndependent(uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex, uint32_t stream, float* out,
                           size_t count) const;

    // Array streams (sampler_arrays.cpp): k values per sample of array (index, arity), one set of k * N points per
    // block as a declared dimension of count k. Arguments (k within the pattern's limits) checked by the ABI layer.
    void array(uint32_t pixelX, uint32_t pixelY, uint32_t sampleIndex, uint32_t index, uint32_t arity, uint32_t k,
               float* out) const;
    void arrayFill(uint32_t pixelX, uint32_t pixelY, uint32_t firstSample, uint32_t count, uint32_t index,
                   uint32_t arity, uint32_t k, float* out) const;

private:
    // One set of the sampler: the declared dimension d (streamArity 0) or stream (d, streamArity), in one block.
    struct SetRef {
        uint32_t pixelX, pixelY, d, streamArity, block;
    };
    uint64_t pixelKey(const SetRef& set) const; // (seed, pattern, pixel, d, stream arity), before the block
    const Dimension& streamDimension(uint32_t arity) const;
    bool blueNoise() const { return (flags_ & STIPPLE_SAMPLER_FLAG_BLUE_NOISE) != 0; }
    // To the pattern: points [first, first + count) / point p of one block of one set.
    void fill(const SetRef& set, const Dimension& dim, uint32_t first, uint32_t count, float* out) const;
    void point(const SetRef& set, const Dimension& dim, uint32_t p, float* out) const;
    // The blue-noise flag's variants of fill (blue_noise.h); off the flagless path.
    // pixel: the set's plain key (block included), which keys each pixel's own part.
    void fillBlueNoise(const SetRef& set, const SetKey& pixel, const Dimension& dim, uint32_t first, uint32_t count,
                       float* out) const;

    uint32_t pattern_;
    const PatternOps& ops_;
    PatternFill fill_;             // ops_.fill for the batch ISA at creation
    PatternStrataFill fillStrata_; // ops_.fillStrata likewise
    uint32_t samplesPerPixel_;
    uint64_t seed_;
    uint64_t seedKey_; // seedKey(seed, the pattern's hash domain)
    std::vector<Dimension> dimensions_;
    uint32_t flags_;
    uint64_t tileSeedKey_; // seedKey(seed, the pattern's domain ^ BlueNoiseTile): keys of blue-noise tiles
    // Streams of arity 1, 2, 3: sets of N points, prepared at creation or on first use (PatternOps).
    std::array<Dimension, 3> streams_;
    mutable std::array<std::once_flag, 3> streamFamilyOnce_;
    // Array streams: the set state of each (arity, k) asked, made on first use (arraySet).
    const Dimension& arraySet(uint32_t arity, uint32_t k) const;
    mutable ArraySets arraySets_;
};

// A set of `points` points of one arity, k = count per sample, with the pattern's state prepared (PatternOps).
Dimension makePatternDimension(const PatternOps& ops, uint32_t arity, uint32_t count, uint32_t points);

// Validates desc completely (every message names the argument, its value and what was expected) and builds
// the sampler. Throws stipple::detail::Error.
Sampler* createSampler(const stipple_sampler_desc& desc);

// The C handle (stipple_sampler_t*) is a Sampler* in disguise. struct stipple_sampler_t is never defined, so
// the library's debug info (and the ABI baseline made from it) shows the handle as opaque, as hosts see it.
inline stipple_sampler toHandle(Sampler* sampler) { return reinterpret_cast<stipple_sampler>(sampler); }
inline Sampler* fromHandle(stipple_sampler handle) { return reinterpret_cast<Sampler*>(handle); }

} // namespace stipple::detail
