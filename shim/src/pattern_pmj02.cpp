// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// pattern_pmj02.cpp — progressive multi-jittered (0,2) sequences, served from cached families.
//
// Each (pixel, dimension) set takes one cached pmj02 sequence (pmj02_family.h: S = 2^storedLog2Length points,
// S >= 8 L for sets of L = 2^m >= M points, up to 2^16) by hash and serves M consecutive points of it per block:
// 2D points are (x, y) of that sequence; 1D points its x; 3D points its (x, y, z), z the sequence's depth
// coordinate (pmj02_generator.h: a digital (0,1)-sequence in the point index that stratifies the points of every
// (x, y) cell in z, so every 2^k prefix has one point in every 2^-r x 2^-r x 2^-(k-2r) box, a jittered 3D set at
// 8^r points; the index shuffle below keeps that, as it keeps prefixes). Randomisation, all
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
#include "pmj02_family.h"

#include <bit>

#if defined(STIPPLE_BATCH_ISA_CLONES)
#include "avx512_intrinsics.h"
#endif

namespace stipple::detail {

// pmj02: the key is the set's (before any block); block b continues the set's sequence (pattern_pmj02.cpp).
template <BatchIsa Isa>
void fillPmj02(uint64_t key, uint32_t block, const Dimension& dim, uint32_t first, uint32_t count, float* out);
void pointPmj02(uint64_t key, uint32_t block, const Dimension& dim, uint32_t p, float* out);

namespace {

struct Pmj02Set {
    const FixedPoint2* xy;
    const uint32_t* z;
    uint32_t indexSeed;
    uint32_t scramble[3];
    uint32_t offset; // sequence index of the block's first point
    uint32_t length; // points in the sequence

    Pmj02Set(uint64_t key, uint32_t block, const Dimension& dim) {
        const Pmj02Family& family = dim.stateAs<Pmj02Family>();
        length = 1u << family.storedLog2Length();
        // key = hashCombine(key, generation). Block 0 (every fill_pixel) is generation 0 at offset 0: no divisions,
        // and the generation's own mix is a constant, off the call's chain of hashes.
        constexpr uint64_t kFirstGeneration = mix64(0 + kGolden64);
        uint64_t generationWord = kFirstGeneration;
        offset = 0;
        if (block != 0) {
            const uint32_t blocksPerSequence = length / dim.setSize;
            const uint32_t generation = block / blocksPerSequence;
            offset = (block - generation * blocksPerSequence) * dim.setSize;
            generationWord = mix64(generation + kGolden64);
        }
        key = mix64(key ^ generationWord);
        const uint64_t h0 = hashAt(key, 0), h1 = hashAt(key, 1), h2 = hashAt(key, 2);
        // (h0 >> 32) mod setCount; a family's count is a power of two (setCountFor), a mask instead of a division.
        const uint32_t draw = static_cast<uint32_t>(h0 >> 32), sets = family.setCount();
        const uint32_t sequence = (sets & (sets - 1)) == 0 ? draw & (sets - 1) : draw % sets;
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
        for (uint32_t i = 0; i < n; ++i)
            o[size_t(i) * Arity] = fixedToUnitFloat(reversedScramble(a[i], set.scramble[0]));
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

// The batch with AVX-512 intrinsics, 16 points per step: the same values as pmj02Point (shim.batch_isa compares
// them bitwise). What the compiler's version of pmj02Chunks spends most on is bit reversal (three per 1D point),
// one GFNI affine and one byte shuffle here; the octave comes from a lane leading-zero count.
#define STIPPLE_PMJ02_KERNEL [[STIPPLE_TARGET_AVX512, gnu::always_inline]] inline

STIPPLE_PMJ02_KERNEL __m512i reverse32(__m512i v) {
    const __m512i bytes = _mm512_gf2p8affine_epi64_epi8(v, _mm512_set1_epi64(0x8040201008040201ll), 0);
    return _mm512_shuffle_epi8(
        bytes, _mm512_broadcast_i32x4(_mm_setr_epi8(3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12)));
}

STIPPLE_PMJ02_KERNEL __m512i xorMul(__m512i x, uint32_t c) {
    return _mm512_xor_si512(x, _mm512_mullo_epi32(x, _mm512_set1_epi32(int(c))));
}

// laineKarrasPermutation with a per-lane seed.
STIPPLE_PMJ02_KERNEL __m512i laineKarras(__m512i x, __m512i seed) {
    x = _mm512_add_epi32(x, seed);
    x = xorMul(x, 0x6c50b47cu);
    x = xorMul(x, 0xb82f1e52u);
    x = xorMul(x, 0xc7afe638u);
    return xorMul(x, 0x8d22f6e6u);
}

// fixedToUnitFloat(reversedScramble(reversed, seed)).
STIPPLE_PMJ02_KERNEL __m512 unitValue(__m512i reversed, __m512i seed) {
    const __m512i v = reverse32(laineKarras(reversed, seed));
    return _mm512_mul_ps(_mm512_cvtepi32_ps(_mm512_srli_epi32(v, 8)), _mm512_set1_ps(0x1p-24f));
}

// Block 0's lanes t = 0..15 in octaveShuffle's terms (constants: the first block is on every call's path).
struct FirstBlock {
    alignas(64) uint32_t head[16];     // t below 2, else its octave 2^floor(log2 t)
    alignas(64) uint32_t octave[16];   // 0 below 2
    alignas(64) uint32_t reversed[16]; // reverseBits32(t - octave)
    alignas(64) uint32_t low[16];      // octave - 1, 0 below 2
    constexpr FirstBlock() : head(), octave(), reversed(), low() {
        for (uint32_t t = 0; t < 16; ++t) {
            octave[t] = t < 2 ? 0u : std::bit_floor(t);
            head[t] = t < 2 ? t : octave[t];
            reversed[t] = reverseBits32(t - octave[t]);
            low[t] = t < 2 ? 0u : octave[t] - 1u;
        }
    }
};
inline constexpr FirstBlock kFirstBlock{};

STIPPLE_PMJ02_KERNEL __m512i loadLanes(const uint32_t (&lanes)[16]) { return _mm512_load_si512(lanes); }

// octaveShuffle(blockFirst + lane, seed) of a block of 16 points.
STIPPLE_PMJ02_KERNEL __m512i blockIndex(uint32_t blockFirst, uint32_t seed) {
    if (blockFirst == 0) {
        const __m512i octave = loadLanes(kFirstBlock.octave);
        const __m512i inOctave = reverse32(
            laineKarras(loadLanes(kFirstBlock.reversed), _mm512_xor_si512(_mm512_set1_epi32(int(seed)), octave)));
        return _mm512_ternarylogic_epi32(loadLanes(kFirstBlock.head), inOctave, loadLanes(kFirstBlock.low),
                                         0xf8); // a | (b & c)
    }
    if (blockFirst >= 16 && blockFirst % 16 == 0) {
        // An aligned block lies in one octave (>= 16), and the reversal of blockFirst - octave + lane is that of
        // blockFirst - octave (a multiple of 16) with the lane's bits on top.
        const __m512i reversedLanes =
            _mm512_setr_epi32(0, int(0x80000000u), 0x40000000, int(0xc0000000u), 0x20000000, int(0xa0000000u),
                              0x60000000, int(0xe0000000u), 0x10000000, int(0x90000000u), 0x50000000, int(0xd0000000u),
                              0x30000000, int(0xb0000000u), 0x70000000, int(0xf0000000u));
        const uint32_t octave = std::bit_floor(blockFirst);
        const __m512i reversed =
            _mm512_or_si512(_mm512_set1_epi32(int(reverseBits32(blockFirst - octave))), reversedLanes);
        const __m512i inOctave = reverse32(laineKarras(reversed, _mm512_set1_epi32(int(seed ^ octave))));
        return _mm512_ternarylogic_epi32(_mm512_set1_epi32(int(octave)), inOctave, _mm512_set1_epi32(int(octave - 1)),
                                         0xf8);
    }
    const __m512i t = _mm512_add_epi32(_mm512_set1_epi32(int(blockFirst)),
                                       _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15));
    // octaveShuffle: octave 0x80000000 >> clz(t) (0 for t < 2), the order inside it scrambled.
    const __mmask16 small = _mm512_cmplt_epu32_mask(t, _mm512_set1_epi32(2));
    const __m512i octave =
        _mm512_maskz_srlv_epi32(__mmask16(~small), _mm512_set1_epi32(int(0x80000000u)), _mm512_lzcnt_epi32(t));
    const __m512i low = _mm512_maskz_sub_epi32(__mmask16(~small), octave, _mm512_set1_epi32(1));
    const __m512i inOctave = reverse32(
        laineKarras(reverse32(_mm512_sub_epi32(t, octave)), _mm512_xor_si512(_mm512_set1_epi32(int(seed)), octave)));
    return _mm512_ternarylogic_epi32(_mm512_mask_mov_epi32(octave, small, t), inOctave, low, 0xf8);
}

// The values of the block of 16 points from blockFirst whose table indices are `index`, stored interleaved.
template <uint32_t Arity>
STIPPLE_PMJ02_KERNEL void storeBlock(const Pmj02Set& set, __m512i index, uint32_t blockFirst, uint32_t points,
                                     float* out) {
    const int* table = reinterpret_cast<const int*>(set.xy);
    __m512i scramble[Arity];
    for (uint32_t c = 0; c < Arity; ++c) scramble[c] = _mm512_set1_epi32(int(set.scramble[c]));
    __m512 axis[Arity];
    if (blockFirst % 16 == 0 && set.length >= 16) {
        // An aligned block's 16 indices are the 16 of one aligned run of the table (the octave shuffle is an Owen
        // scramble: bits 4 and up of i - octave fix those of its image; block 0's all lie below 16). So the run is
        // loaded and scrambled in its own order, and a lane permute per axis puts the values in the block's: no
        // gathers, and the value scramble does not wait for the index order (a short call's latency). The whole
        // run exists even past a tail: the length is a multiple of 16.
        const uint32_t run =
            blockFirst == 0 ? 0u : static_cast<uint32_t>(_mm_cvtsi128_si32(_mm512_castsi512_si128(index))) & ~15u;
        const __m512i lane = _mm512_and_si512(index, _mm512_set1_epi32(15));
        const __m512i lo = _mm512_loadu_si512(table + 2 * size_t(run));
        const __m512i hi = _mm512_loadu_si512(table + 2 * size_t(run) + 16);
        if constexpr (Arity == 1) {
            const __m512i even = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
            axis[0] = _mm512_permutexvar_ps(lane, unitValue(_mm512_permutex2var_epi32(lo, even, hi), scramble[0]));
        } else {
            // (x, y) pairs in run order, each scrambled with its axis' seed (x's in the even lanes), then picked
            // per lane.
            const __m512i pairScramble = _mm512_mask_mov_epi32(scramble[0], __mmask16(0xaaaa), scramble[1]);
            const __m512 valuesLo = unitValue(lo, pairScramble), valuesHi = unitValue(hi, pairScramble);
            const __m512i pair = _mm512_slli_epi32(lane, 1);
            axis[0] = _mm512_permutex2var_ps(valuesLo, pair, valuesHi);
            axis[1] = _mm512_permutex2var_ps(valuesLo, _mm512_add_epi32(pair, _mm512_set1_epi32(1)), valuesHi);
        }
        if constexpr (Arity == 3)
            axis[2] = _mm512_permutexvar_ps(lane, unitValue(_mm512_loadu_si512(set.z + run), scramble[2]));
    } else {
        const __mmask16 live = __mmask16((1u << points) - 1u);
        const __m512i pair = _mm512_slli_epi32(index, 1);
        axis[0] = unitValue(_mm512_mask_i32gather_epi32(_mm512_setzero_si512(), live, pair, table, 4), scramble[0]);
        if constexpr (Arity >= 2)
            axis[1] =
                unitValue(_mm512_mask_i32gather_epi32(_mm512_setzero_si512(), live, pair, table + 1, 4), scramble[1]);
        if constexpr (Arity == 3)
            axis[2] = unitValue(_mm512_mask_i32gather_epi32(_mm512_setzero_si512(), live, index,
                                                            reinterpret_cast<const int*>(set.z), 4),
                                scramble[2]);
    }
    storeInterleaved<Arity>(out, axis, points * Arity);
}

template <uint32_t Arity>
[[STIPPLE_TARGET_AVX512]] void pmj02BatchAvx512(const Pmj02Set& set, uint32_t first, uint32_t count, float* out) {
    const uint32_t start = set.offset + first;
    if (count <= 16) // one block: its index order straight into the table reads
        return storeBlock<Arity>(set, blockIndex(start, set.indexSeed), start, count, out);
    // Two passes per chunk: the index order first (hashes only, independent across blocks), then the table reads
    // and value scrambles, so that neither waits on the other's latency chain.
    constexpr uint32_t kChunkBlocks = 16;
    alignas(64) uint32_t chunkIndex[kChunkBlocks * 16];
    for (uint32_t chunk = 0; chunk < count; chunk += kChunkBlocks * 16) {
        const uint32_t chunkEnd = count - chunk < kChunkBlocks * 16 ? count : chunk + kChunkBlocks * 16;
        for (uint32_t base = chunk; base < chunkEnd; base += 16)
            _mm512_store_si512(chunkIndex + (base - chunk), blockIndex(start + base, set.indexSeed));
        for (uint32_t base = chunk; base < chunkEnd; base += 16)
            storeBlock<Arity>(set, _mm512_load_si512(chunkIndex + (base - chunk)), start + base,
                              count - base < 16 ? count - base : 16, out + size_t(base) * Arity);
    }
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
    .limits = {.maxArity = 3, .maxSetSize = 1u << Pmj02Family::kMaxLog2Length},
    .prepare = [](Dimension& dim) { dim.patternState = Pmj02Family::acquire(dim.log2Length); },
    .prepareStreamsOnFirstUse = false, // a family generates its sequences on first use
    .point = [](const SetKey& set, const Dimension& dim, uint32_t p,
                float* out) { pointPmj02(set.key, set.block, dim, p, out); },
    .fill = {fillSet<BatchIsa::Baseline>, fillSet<BatchIsa::Avx2>, fillSet<BatchIsa::Avx512>},
};

} // namespace stipple::detail
