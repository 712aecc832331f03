// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pattern_pmj02.cpp — progressive multi-jittered (0,2) sequences, served from cached families.
//
// Each (pixel, dimension) set takes one cached pmj02 sequence (pmj02_family.h: S = 2^storedLog2Length points,
// S >= 8 L for sets of L = 2^m >= M points, up to 2^16) by hash and serves M consecutive points of it per block:
// 2D points are (x, y) of that sequence; 1D points its x; 3D points its (x, y, z), z the sequence's depth
// coordinate (pmj02_generator.h: tied to (x, y) like the third column of an orthogonal array, so every prefix of
// 4^q points is stratified on the 2^q x 2^q grids of (x, z) and (y, z) and every prefix of 2^k points, k != 1, in
// z at 2^-k; the 3D strata themselves are not: the points of one (x, y) cell share z's top digits, so the part
// of an integrand that is neither additive nor pairwise converges at the independent rate). Randomisation, all
// hashed from the set key:
// - an index shuffle that keeps every octave [2^j, 2^(j+1)) in place and Owen-scrambles the order inside it, so
//   every prefix of 2^j points is exactly the sequence's own prefix (a (0,j,2)-net) while two dimensions that
//   drew the same sequence still pair their points differently;
// - Owen scrambling of every coordinate, which maps elementary intervals onto elementary intervals (the nets
//   stay nets) and makes every point uniformly distributed.
// Past N: block b (sample indices [bN, (b+1)N)) serves sequence points [(b mod Q) M, (b mod Q + 1) M) with
// Q = S / M blocks per sequence, so the first Q blocks together are the sequence's first Q M points: 4N samples
// of an N-sample set are a pmj02 set of 4N points. Block b >= Q starts over with a set randomised from
// hashCombine(set key, b / Q) (block 0 is hashCombine(set key, 0), as before).
#include "batch_isa.h"
#include "owen_scrambling.h"
#include "pattern_registry.h"
#include "patterns.h"

#include <bit>

namespace stipple::detail {

namespace {

struct Pmj02Set {
    const FixedPoint2* xy;
    const uint32_t* z;
    uint32_t indexSeed;
    uint32_t scramble[3];
    uint32_t offset; // sequence index of the block's first point

    Pmj02Set(uint64_t key, uint32_t block, const Dimension& dim) {
        const Pmj02Family& family = *dim.pmj02;
        const uint32_t blocksPerSequence = (1u << family.storedLog2Length()) / dim.setSize;
        const uint32_t generation = block / blocksPerSequence;
        offset = (block - generation * blocksPerSequence) * dim.setSize;
        key = hashCombine(key, generation);
        const uint64_t h0 = hashAt(key, 0), h1 = hashAt(key, 1), h2 = hashAt(key, 2);
        const uint32_t sequence = static_cast<uint32_t>((h0 >> 32) % family.setCount());
        xy = family.sequence(sequence);
        z = dim.arity == 3 ? family.depth(sequence) : nullptr;
        indexSeed = static_cast<uint32_t>(h1);
        scramble[0] = static_cast<uint32_t>(h2);
        scramble[1] = static_cast<uint32_t>(h2 >> 32);
        scramble[2] = static_cast<uint32_t>(hashAt(key, 3));
    }
};

// Owen scrambling of a coordinate the family stores bit-reversed: nestedUniformScramble of the coordinate.
inline uint32_t reversedScramble(uint32_t reversed, uint32_t seed) {
    return reverseBits32(laineKarrasPermutation(reversed, seed));
}

// Keeps octaves in place, Owen-scrambles the order inside each (branch-free: octave 0 holds indices 0 and 1).
inline uint32_t octaveShuffle(uint32_t i, uint32_t seed) {
    const uint32_t octave = i < 2 ? 0u : 0x80000000u >> std::countl_zero(i);
    const uint32_t low = octave == 0 ? 0u : octave - 1u;
    return (i < 2 ? i : octave) | (nestedUniformScramble(i - octave, seed ^ octave) & low);
}

inline void pmj02Point(const Pmj02Set& set, uint32_t arity, uint32_t r, float* out) {
    const uint32_t index = octaveShuffle(set.offset + r, set.indexSeed);
    const FixedPoint2& xy = set.xy[index];
    out[0] = fixedToUnitFloat(reversedScramble(xy.x, set.scramble[0]));
    if (arity == 1) return;
    out[1] = fixedToUnitFloat(reversedScramble(xy.y, set.scramble[1]));
    if (arity == 2) return;
    out[2] = fixedToUnitFloat(reversedScramble(set.z[index], set.scramble[2]));
}

// The batch with wide vectors: the same values as pmj02Point, a chunk of points at a time in loops the compiler
// vectorises (the table reads become gathers).
template <uint32_t Arity>
[[gnu::always_inline]] inline void pmj02Chunks(const Pmj02Set& set, uint32_t first, uint32_t count, float* out) {
    constexpr uint32_t kChunk = 64;
    alignas(64) uint32_t index[kChunk], a[kChunk], b[kChunk];
    const uint32_t* table = reinterpret_cast<const uint32_t*>(set.xy);
    for (uint32_t base = 0; base < count; base += kChunk) {
        const uint32_t n = count - base < kChunk ? count - base : kChunk;
        const uint32_t t0 = set.offset + first + base;
        for (uint32_t i = 0; i < n; ++i) index[i] = octaveShuffle(t0 + i, set.indexSeed);
        for (uint32_t i = 0; i < n; ++i) a[i] = table[2 * size_t(index[i])];
        if constexpr (Arity >= 2)
            for (uint32_t i = 0; i < n; ++i) b[i] = table[2 * size_t(index[i]) + 1];
        float* o = out + size_t(base) * Arity;
        for (uint32_t i = 0; i < n; ++i) o[size_t(i) * Arity] = fixedToUnitFloat(reversedScramble(a[i], set.scramble[0]));
        if constexpr (Arity >= 2)
            for (uint32_t i = 0; i < n; ++i)
                o[size_t(i) * Arity + 1] = fixedToUnitFloat(reversedScramble(b[i], set.scramble[1]));
        if constexpr (Arity == 3) {
            for (uint32_t i = 0; i < n; ++i) a[i] = set.z[index[i]];
            for (uint32_t i = 0; i < n; ++i)
                o[size_t(i) * Arity + 2] = fixedToUnitFloat(reversedScramble(a[i], set.scramble[2]));
        }
    }
}

#if defined(STIPPLE_BATCH_ISA_CLONES)
template <uint32_t Arity>
[[STIPPLE_TARGET_AVX2]] void pmj02BatchAvx2(const Pmj02Set& set, uint32_t first, uint32_t count, float* out) {
    pmj02Chunks<Arity>(set, first, count, out);
}
template <uint32_t Arity>
[[STIPPLE_TARGET_AVX512]] void pmj02BatchAvx512(const Pmj02Set& set, uint32_t first, uint32_t count, float* out) {
    pmj02Chunks<Arity>(set, first, count, out);
}
#endif

template <BatchIsa Isa, uint32_t Arity>
void pmj02Batch(const Pmj02Set& set, uint32_t first, uint32_t count, float* out) {
#if defined(STIPPLE_BATCH_ISA_CLONES)
    if constexpr (Isa == BatchIsa::Avx512) return pmj02BatchAvx512<Arity>(set, first, count, out);
    if constexpr (Isa == BatchIsa::Avx2) return pmj02BatchAvx2<Arity>(set, first, count, out);
#endif
    for (uint32_t i = 0; i < count; ++i) pmj02Point(set, Arity, first + i, out + size_t(i) * Arity);
}

} // namespace

template <BatchIsa Isa>
void fillPmj02(uint64_t key, uint32_t block, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
    const Pmj02Set set(key, block, dim);
    switch (dim.arity) {
    case 1: return pmj02Batch<Isa, 1>(set, first, count, out);
    case 2: return pmj02Batch<Isa, 2>(set, first, count, out);
    default: return pmj02Batch<Isa, 3>(set, first, count, out);
    }
}

void pointPmj02(uint64_t key, uint32_t block, const Dimension& dim, uint32_t p, float* out) {
    pmj02Point(Pmj02Set(key, block, dim), dim.arity, p, out);
}

namespace {
template <BatchIsa Isa>
void fillSet(const SetKey& set, const Dimension& dim, uint32_t first, uint32_t count, float* out) {
    fillPmj02<Isa>(set.key, set.block, dim, first, count, out);
}
} // namespace

// The set key for every block (Sequence keying): the pattern continues its sequence past N and rekeys itself
// once the stored sequence runs out (Pmj02Set).
extern const PatternOps kPmj02Pattern;
constinit const PatternOps kPmj02Pattern{
    .name = "pmj02",
    .domain = HashDomain::Pmj02,
    .blockKeying = BlockKeying::Sequence,
    .blueNoise = BlueNoiseMode::Unsupported,
    .latticeUse = LatticeUse::Strata, // unused
    .limits = {.maxArity = 3, .maxSetSize = 1u << Pmj02Family::kMaxLog2Length},
    .prepare = [](Dimension& dim) { dim.pmj02 = Pmj02Family::acquire(dim.log2Length); },
    .prepareStreamsOnFirstUse = false, // a family generates its sequences on first use
    .strata = nullptr,
    .point = [](const SetKey& set, const Dimension& dim, uint32_t p,
                float* out) { pointPmj02(set.key, set.block, dim, p, out); },
    .fill = {fillSet<BatchIsa::Baseline>, fillSet<BatchIsa::Avx2>, fillSet<BatchIsa::Avx512>},
    .fillStrata = nullptr,
};

} // namespace stipple::detail
