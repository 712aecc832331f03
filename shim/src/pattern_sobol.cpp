// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pattern_sobol.cpp — Owen-scrambled Sobol' points (Burley 2020), padded per (pixel, dimension).
//
// The set of one (pixel, dimension) is M points of the first `arity` Sobol' dimensions (M = k*N for a declared
// dimension, N for a stream). Let L = 2^m be the smallest power of two >= M. Sample index i lies in block
// b = i / N (the sampler passes SobolSet::atBlock(b)); point r of that block has the Sobol' index
//     (block(b) << m) | (nestedUniformScramble(r, indexSeed) mod L),   block(b) = blockBase + b,
// where the index shuffle (an Owen scramble of r's binary digits) maps every prefix [0, 2^j) of r onto an
// aligned run of 2^j Sobol' indices, i.e. a (0,j,2)-net in 2D. Each coordinate is then Owen-scrambled with its
// own seed. indexSeed and the scramble seeds are hashed from the set key, so the dimensions of one pixel are
// decorrelated (the pairing of points across dimensions is shuffled), as in Burley's padding.
// - M a power of two: each block is a full (0,m,2)-net (3D: a (1,m,3)-net), and block b follows block b - 1 in
//   the sequence, so the first 2^j blocks together are again a net: progressive by construction.
// - Other M: each block is the first M points of a shuffled net of L points (every prefix of a power-of-two
//   length is a net; the rest is a nested-scrambled part of the next doubling). Never a fall-back to random.
// The index is 32-bit: a set's sequence has 2^(32-m) blocks, its period N * 2^(32-m) sample indices; block b past
// them is block b mod 2^(32-m) of a freshly scrambled sequence, generation b / 2^(32-m) (sequence_generation.h).
#include "batch_isa.h"
#include "owen_scrambling.h"
#include "pattern_registry.h"
#include "sequence_generation.h"
#include "sobol_matrices.h"

namespace stipple::detail {

// The randomisation of one set. perPixel is the plain pattern; the blue-noise
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

namespace {

// The seed of a coordinate's deep digits (deepOwenScrambleReversed), derived from its scramble seed.
constexpr uint32_t deepSeed(uint32_t scramble) { return mixBits32(scramble ^ 0x5b0b01deu); }

// A coordinate's Owen scramble, on and to reversed digits (z = reverseBits32 of the Sobol' fraction): Laine-Karras
// (Vegdahl's hash) for every digit, completed below the set's level (log2 of its power-of-two length L, where each point
// of a block has an elementary interval of its own) by deepOwenScrambleReversed. One bit reversal, at the end.
inline float sobolScrambleToFloat(uint32_t z, uint32_t seed, uint32_t deep, uint32_t level) {
    return fixedToUnitFloat(reverseBits32(deepOwenScrambleReversed(vegdahlPermutation(z, seed), level, deep)));
}

inline void sobolPoint(const SobolSet& set, const Dimension& dim, uint32_t r, float* out) {
    const uint32_t lowMask = dim.log2Length == 32 ? ~0u : (1u << dim.log2Length) - 1u;
    const uint32_t index = (dim.log2Length >= 32 ? 0u : set.blockBase << dim.log2Length) |
                           (nestedUniformScramble(r, set.indexSeed) & lowMask);
    for (uint32_t c = 0; c < dim.arity; ++c)
        out[c] = sobolScrambleToFloat(sobolSampleReversed(index, c), set.scramble[c], deepSeed(set.scramble[c]),
                                      dim.log2Length);
}

} // namespace

SobolSet SobolSet::perPixel(uint64_t key) {
    SobolSet set;
    const uint64_t h0 = hashAt(key, 0), h1 = hashAt(key, 1);
    set.indexSeed = static_cast<uint32_t>(h0);
    set.scramble[0] = static_cast<uint32_t>(h0 >> 32);
    set.scramble[1] = static_cast<uint32_t>(h1);
    set.scramble[2] = static_cast<uint32_t>(h1 >> 32);
    return set;
}

namespace {

// The batch with wide vectors (AVX2, AVX-512; batch_isa.h): the same values as sobolPoint, a chunk of points at a
// time in loops the compiler vectorises. The
// Sobol' matrix product is linear over GF(2), so the block's high index bits (the same for the whole set) are
// multiplied once, and the low bits by a branchless loop over the set's log2Length bits (sobolSample loops over
// the set bits of the index, a data-dependent branch per point).
template <uint32_t Arity>
[[gnu::always_inline]] inline void sobolChunks(const SobolSet& set, const Dimension& dim, uint32_t first,
                                               uint32_t count, float* out) {
    constexpr uint32_t kChunk = 64;
    const uint32_t bits = dim.log2Length >= 32 ? 32 : dim.log2Length;
    const uint32_t lowMask = bits == 32 ? ~0u : (1u << bits) - 1u;
    const uint32_t high = bits >= 32 ? 0u : set.blockBase << bits;
    const uint32_t indexSeed = set.indexSeed;
    uint32_t highPart[3], scramble[3], deep[3];
    for (uint32_t c = 0; c < Arity; ++c)
        highPart[c] = sobolSampleReversed(high, c), scramble[c] = set.scramble[c], deep[c] = deepSeed(set.scramble[c]);
    alignas(64) uint32_t index[kChunk], v[kChunk];
    for (uint32_t base = 0; base < count; base += kChunk) {
        const uint32_t n = count - base < kChunk ? count - base : kChunk;
        for (uint32_t i = 0; i < n; ++i) index[i] = nestedUniformScramble(first + base + i, indexSeed) & lowMask;
        float* o = out + size_t(base) * Arity;
        for (uint32_t c = 0; c < Arity; ++c) {
            if (c == 0) {
                for (uint32_t i = 0; i < n; ++i) v[i] = index[i];
            } else {
                for (uint32_t i = 0; i < n; ++i) v[i] = 0;
                for (uint32_t j = 0; j < bits; ++j) {
                    const uint32_t column = kSobolMatricesReversed[c][j];
                    for (uint32_t i = 0; i < n; ++i) v[i] ^= (0u - ((index[i] >> j) & 1u)) & column;
                }
            }
            for (uint32_t i = 0; i < n; ++i)
                o[size_t(i) * Arity + c] = sobolScrambleToFloat(v[i] ^ highPart[c], scramble[c], deep[c], bits);
        }
    }
}

#if defined(STIPPLE_BATCH_ISA_CLONES)
template <uint32_t Arity>
[[STIPPLE_TARGET_AVX2]] void sobolBatchAvx2(const SobolSet& set, const Dimension& dim, uint32_t first, uint32_t count,
                                            float* out) {
    sobolChunks<Arity>(set, dim, first, count, out);
}
template <uint32_t Arity>
[[STIPPLE_TARGET_AVX512]] void sobolBatchAvx512(const SobolSet& set, const Dimension& dim, uint32_t first,
                                                uint32_t count, float* out) {
    sobolChunks<Arity>(set, dim, first, count, out);
}
#endif

template <BatchIsa Isa, uint32_t Arity>
void sobolBatch(const SobolSet& set, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
#if defined(STIPPLE_BATCH_ISA_CLONES)
    if constexpr (Isa == BatchIsa::Avx512) return sobolBatchAvx512<Arity>(set, dim, first, count, out);
    if constexpr (Isa == BatchIsa::Avx2) return sobolBatchAvx2<Arity>(set, dim, first, count, out);
#endif
    // Without wide vectors the per-point code is the faster one (SSE2 has no 32-bit lane multiply).
    for (uint32_t i = 0; i < count; ++i) sobolPoint(set, dim, first + i, out + size_t(i) * Arity);
}

} // namespace

template <BatchIsa Isa>
void fillSobol(const SobolSet& set, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
    switch (dim.arity) {
    case 1: return sobolBatch<Isa, 1>(set, dim, first, count, out);
    case 2: return sobolBatch<Isa, 2>(set, dim, first, count, out);
    default: return sobolBatch<Isa, 3>(set, dim, first, count, out);
    }
}

void pointSobol(const SobolSet& set, const Dimension& dim, uint32_t p, float* out) { sobolPoint(set, dim, p, out); }

namespace {
// The Sobol' set of block set.block, in its generation.
SobolSet sobolSet(const SetKey& set, const Dimension& dim) {
    const SetKey inGeneration = sequenceGeneration(set, blocksPerGenerationPadded(dim.log2Length));
    return SobolSet::perPixel(inGeneration.key).atBlock(inGeneration.block);
}

template <BatchIsa Isa>
void fillSet(const SetKey& set, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
    fillSobol<Isa>(sobolSet(set, dim), dim, first, count, out);
}
void pointSet(const SetKey& set, const Dimension& dim, uint32_t p, float* out) {
    pointSobol(sobolSet(set, dim), dim, p, out);
}
} // namespace

// Blocks continue the sequence (SobolSet::atBlock) for a period, then a fresh one starts (sequence_generation.h).
extern const PatternOps kSobolPattern;
constinit const PatternOps kSobolPattern{
    .name = "sobol",
    .domain = HashDomain::Sobol,
    .blockKeying = BlockKeying::Sequence,
    .point = pointSet,
    .fill = {fillSet<BatchIsa::Baseline>, fillSet<BatchIsa::Avx2>, fillSet<BatchIsa::Avx512>},
};

} // namespace stipple::detail
