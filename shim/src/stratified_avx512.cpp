// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// stratified_avx512.cpp — the progressive stratified batch (pattern_stratified.cpp, progressiveChunks) with AVX-512
// and GFNI intrinsics, 16 points per step: the same values, computed as progressivePoint does (simd_avx512.h).
#include "batch_isa.h"
#include "blue_noise_avx512.h"
#include "hash.h"
#include "hash_avx512.h"
#include "progressive_strata.h"
#include "simd_avx512.h"

#if defined(STIPPLE_BATCH_ISA_CLONES)
#include "avx512_intrinsics.h"

namespace stipple::detail {

namespace {

#define STIPPLE_KERNEL [[STIPPLE_TARGET_AVX512, gnu::always_inline]] inline

// The byte shuffle that reverses the bytes of every dword.
STIPPLE_KERNEL __m512i dwordByteReversal() {
    return _mm512_broadcast_i32x4(_mm_setr_epi8(3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12));
}

// Bit reversal of every 32-bit lane: GFNI reverses the bits of each byte, a byte shuffle the bytes of each dword.
STIPPLE_KERNEL __m512i reverse32(__m512i v) {
    const __m512i bytes = _mm512_gf2p8affine_epi64_epi8(v, _mm512_set1_epi64(0x8040201008040201ll), 0);
    return _mm512_shuffle_epi8(bytes, dwordByteReversal());
}

STIPPLE_KERNEL __m512i mul32(__m512i x, uint32_t c) { return _mm512_mullo_epi32(x, _mm512_set1_epi32(int(c))); }

// laineKarras of pattern_stratified.cpp, per lane.
STIPPLE_KERNEL __m512i laineKarras(__m512i x, uint32_t seed) {
    x = _mm512_xor_si512(x, mul32(x, 0x3d20adeau));
    x = _mm512_add_epi32(x, _mm512_set1_epi32(int(seed)));
    x = mul32(x, (seed >> 16) | 1u);
    x = _mm512_xor_si512(x, mul32(x, 0x05526c56u));
    return _mm512_xor_si512(x, mul32(x, 0x53a22864u));
}

STIPPLE_KERNEL __m128i count(uint32_t s) { return _mm_cvtsi32_si128(int(s)); }

// axisJitter of pattern_stratified.cpp (lowbias32 of ((s << 2) | c) ^ seed) without its last step x ^= x >> 16,
// given u = jitterBase(s, seed): lowbias32's first step is the same for every axis. valueOfHead applies the last
// step.
STIPPLE_KERNEL __m512i axisJitterHead(__m512i u, uint32_t c) {
    __m512i x = mul32(c ? _mm512_xor_si512(u, _mm512_set1_epi32(int(c))) : u, 0x7feb352du);
    return mul32(_mm512_xor_si512(x, _mm512_srli_epi32(x, 15)), 0x846ca68bu);
}

// The whole axisJitter per axis (the head and its last step), for the blue-noise kernels' sub-cell moves.
template <uint32_t Arity>
STIPPLE_KERNEL void axisJitters(__m512i u, __m512i (&jitter)[Arity]) {
    for (uint32_t c = 0; c < Arity; ++c) {
        const __m512i x = axisJitterHead(u, c);
        jitter[c] = _mm512_xor_si512(x, _mm512_srli_epi32(x, 16));
    }
}

// The GF(2) affine matrix that sets bit i of every byte to bit from[i] (gf2p8affine: result bit i is the parity of
// byte 7 - i of the matrix ANDed with the input byte); from[i] < 0 leaves bit i zero.
constexpr int64_t bitMatrix(const int (&from)[8]) {
    uint64_t m = 0;
    for (int i = 0; i < 8; ++i)
        if (from[i] >= 0) m |= uint64_t(1) << (8 * (7 - i) + from[i]);
    return int64_t(m);
}
// Bytes of every dword reversed (reverse32's shuffle).
STIPPLE_KERNEL __m512i reverseBytes(__m512i v) { return _mm512_shuffle_epi8(v, dwordByteReversal()); }

// 2D cells of q, as cell[c] << (24 - axisBits[c]) before masking: axis 0 has q's even bits, axis 1 its odd bits,
// each read from bit 0 as the cell's most significant bit (progressiveCell). With q's bytes reversed in every dword,
// one affine per axis puts the axis' four bits of each byte, in cell order, in both nibbles; a byte of the cell is
// then the 8 bits straddling two such bytes, which a multishift picks (into bits 8..23 of each dword).
STIPPLE_KERNEL void cells2D(__m512i q, __m512i& x, __m512i& y) {
    const __m512i bytes = reverseBytes(q);
    constexpr int64_t even = bitMatrix({6, 4, 2, 0, 6, 4, 2, 0}), odd = bitMatrix({7, 5, 3, 1, 7, 5, 3, 1});
    // Window offsets: dword byte 1 <- its bits 4..11, byte 2 <- bits 20..27; bytes 0 and 3 are masked to zero.
    const __m512i windows = _mm512_set1_epi64(int64_t(0x0034240000140400ull));
    constexpr __mmask64 middle = 0x6666666666666666ull;
    x = _mm512_maskz_multishift_epi64_epi8(middle, windows,
                                           _mm512_gf2p8affine_epi64_epi8(bytes, _mm512_set1_epi64(even), 0));
    y = _mm512_maskz_multishift_epi64_epi8(middle, windows,
                                           _mm512_gf2p8affine_epi64_epi8(bytes, _mm512_set1_epi64(odd), 0));
}

// 3D cells of q, as cell[c] << (24 - axisBits[c]) before masking: axis c's bit t from the top is q's bit 3t + c.
// A 6-bit chunk k of q (bits 6k..6k+5) holds bits t = 2k, 2k + 1 of every axis. A multishift puts chunk k in byte
// 3 - k of its dword, a 64-entry byte table (one VBMI permute per axis) maps it to the axis' two bits (t = 2k in
// bit 1), and one multiply by 2^6 + 2^12 + 2^18 + 2^24 moves byte 3 - k's field to bits 31 - 2k and 30 - 2k: the
// other partial products land on disjoint bits below or past bit 31, so nothing carries into the top byte.
struct ChunkAxes {
    alignas(64) uint8_t table[3][64];
    constexpr ChunkAxes() : table() {
        for (uint32_t c = 0; c < 3; ++c)
            for (uint32_t x = 0; x < 64; ++x) table[c][x] = uint8_t((((x >> c) & 1u) << 1) | ((x >> (c + 3)) & 1u));
    }
};
inline constexpr ChunkAxes kChunkAxes{};

STIPPLE_KERNEL void cells3D(__m512i q, __m512i top[3]) {
    // Byte 3 - k of each dword <- bits 6k.. of the dword (the permute reads the low 6 bits of a byte).
    const __m512i chunks = _mm512_multishift_epi64_epi8(_mm512_set1_epi64(int64_t(0x20262c3200060c12ull)), q);
    // One multiply, not the shifts and adds a compiler would make of it.
    __m512i spread = _mm512_set1_epi32((1 << 6) | (1 << 12) | (1 << 18) | (1 << 24));
    asm("" : "+v"(spread));
    for (uint32_t c = 0; c < 3; ++c) {
        const __m512i fields = _mm512_permutexvar_epi8(chunks, _mm512_load_si512(kChunkAxes.table[c]));
        top[c] = _mm512_srli_epi32(_mm512_mullo_epi32(fields, spread), 8);
    }
}

// bits / 2^24 as float (bits < 2^24): the conversion is exact, and scaling an exact nonzero float by 2^-24 lowers
// its exponent field by 24 (no result is subnormal), an integer subtract instead of a multiply's latency.
// (A kernel that keeps the exponent step 24 << 23 in a register passes it.)
STIPPLE_KERNEL __m512 unitOf(__m512i bits, __m512i exponent24 = _mm512_set1_epi32(24 << 23)) {
    const __m512i f = _mm512_castps_si512(_mm512_cvtepi32_ps(bits));
    return _mm512_castsi512_ps(_mm512_mask_sub_epi32(f, _mm512_test_epi32_mask(bits, bits), f, exponent24));
}

// (top & topMask) | (jitter >> (8 + axisBits)) as float: exact (< 2^24), as in progressivePoint.
STIPPLE_KERNEL __m512 valueOf(__m512i top, __m512i topMask, __m512i jitter, __m128i jitterShift) {
    return unitOf(_mm512_ternarylogic_epi32(top, topMask, _mm512_srl_epi32(jitter, jitterShift), 0xea));
}

// The same with jitter = x ^ (x >> 16) (lowbias32's last step, axisJitterHead): its shift is (x >> s) ^ (x >> (s +
// 16)), two parallel shifts and then one three-way operation with the masked cell bits.
STIPPLE_KERNEL __m512 valueOfHead(__m512i top, __m512i topMask, __m512i x, __m128i jitterShift, __m128i jitterShift16) {
    const __m512i cell = _mm512_and_si512(top, topMask);
    return unitOf(_mm512_ternarylogic_epi32(cell, _mm512_srl_epi32(x, jitterShift), _mm512_srl_epi32(x, jitterShift16),
                                            0xf6)); // a | (b ^ c)
}

// The cell bits of 16 points' cell indices q per axis, as cell[c] << (24 - axisBits[c]) before masking.
template <uint32_t Arity>
STIPPLE_KERNEL void cellTops(__m512i q, __m512i (&top)[Arity]) {
    if constexpr (Arity == 1) {
        // cell << (24 - bits) is reverse32(q) >> 8 (q < 2^bits): the bytes of q reversed and moved down by one.
        const __m512i bytes = _mm512_gf2p8affine_epi64_epi8(q, _mm512_set1_epi64(0x8040201008040201ll), 0);
        top[0] = _mm512_shuffle_epi8(
            bytes, _mm512_broadcast_i32x4(_mm_setr_epi8(2, 1, 0, -1, 6, 5, 4, -1, 10, 9, 8, -1, 14, 13, 12, -1)));
    } else if constexpr (Arity == 2) {
        cells2D(q, top[0], top[1]);
    } else {
        cells3D(q, top);
    }
}

// The pixel's blue-noise constants on every lane, made once per call (the loops would otherwise reload them from
// the CrossPixelStrata and broadcast them in every block), with the shift counts and two constants of the second
// pass that the compiler would otherwise rebuild from immediates in every block.
template <uint32_t Arity>
struct BlueLanes {
    __m512i offsetKey;
    __m512i lattice;         // 1D: c on every lane (tent12); 2D, 3D: packed in bytes (tentBytes)
    __m128i axisBits[Arity]; // 2D, 3D: shift counts
    __m128i jitterShift20;   // 1D: 20 + bits
    __m512i tentMask, exponent24;
};

// The low 32 bits of hashAt(offsetKey, stratum) per point, the stratum id of 16 points' cells
// ((cell[2] << 42) ^ (cell[1] << 21) ^ cell[0]) taken as the even and the odd dword lanes in 8 64-bit lanes each
// (a mask and a shift, not widening shuffles), merged back by one in-lane shuffle. 1D: `cell` holds the ids plus 1
// (the counter's + 1 on 16 lanes at once; a cell index plus 1 fits 32 bits).
template <uint32_t Arity>
STIPPLE_KERNEL __m512i stratumOffsets(const __m512i* cell, __m512i offsetKey) {
    __m512i half[2];
    for (int h = 0; h < 2; ++h) {
        __m512i wide[Arity];
        for (uint32_t c = 0; c < Arity; ++c)
            wide[c] = h ? _mm512_srli_epi64(cell[c], 32) : _mm512_and_si512(cell[c], _mm512_set1_epi64(0xffffffffll));
        __m512i id = wide[0];
        if constexpr (Arity >= 2) id = _mm512_xor_si512(id, _mm512_slli_epi64(wide[1], 21));
        if constexpr (Arity == 3) id = _mm512_xor_si512(id, _mm512_slli_epi64(wide[2], 42));
        if constexpr (Arity >= 2) id = _mm512_add_epi64(id, _mm512_set1_epi64(1));
        half[h] = hashAtScaled(offsetKey, _mm512_mullo_epi64(id, _mm512_set1_epi64(int64_t(kGolden64))));
    }
    // Even lanes' low dwords stay; the odd lanes' move up into the odd dwords.
    return _mm512_mask_shuffle_epi32(half[0], __mmask16(0xaaaa), half[1], _MM_PERM_CCAA);
}

// With the flag, the first pass of a chunk of blocks leaves each block's cell bits (as top) and full jitter words
// per axis here; the second moves the jitters into the pixel's sub-cells of the points' strata. Two passes, so
// that the strata's 64-bit offset hashes do not lengthen one block's chain of latencies beyond what the core
// overlaps across blocks.
constexpr uint32_t kBlueChunkBlocks = 16;
template <uint32_t Arity>
struct BlueStage {
    __m512i top[kBlueChunkBlocks][Arity];
    __m512i jitter[kBlueChunkBlocks][Arity];
};

// The offsets' low 32 bits of the strata of 16 points, given their cell bits (as top).
template <uint32_t Arity>
STIPPLE_KERNEL __m512i blockOffsets(const __m512i* top, const __m512i* topMask, const __m128i* cellShift,
                                    const BlueLanes<Arity>& blue) {
    __m512i cell[Arity];
    if constexpr (Arity == 1) {
        // 1D's top is exactly cell << (24 - bits) (cellTops): no mask.
        cell[0] = _mm512_add_epi32(_mm512_srl_epi32(top[0], cellShift[0]), _mm512_set1_epi32(1));
    } else {
        for (uint32_t c = 0; c < Arity; ++c)
            cell[c] = _mm512_srl_epi32(_mm512_and_si512(top[c], topMask[c]), cellShift[c]);
    }
    return stratumOffsets<Arity>(cell, blue.offsetKey);
}

// One block of the second pass: `floats` values from out, the strata's offsets given.
// (Staged blocks are bound by throughput, not latency: there the float is made with a multiply, one instruction less
// than unitOf's exponent step; the same value.)
template <uint32_t Arity, bool Staged>
STIPPLE_KERNEL void blueBlock(const __m512i* top, const __m512i* jitter, __m512i offsets, const BlueLanes<Arity>& blue,
                              const __m512i* topMask, const __m128i* jitterShift, float* out, uint32_t floats) {
    __m512 axis[Arity];
    const __m512i tents = Arity == 1 ? tent12(offsets, blue.lattice, blue.tentMask) : tentBytes(offsets, blue.lattice);
    for (uint32_t c = 0; c < Arity; ++c) {
        // (top & topMask) | (word >> (8 + axisBits)), word the jitter moved into the sub-cell. 1D: top is exactly the
        // cell's bits (cellTops) and the word's parts are shifted apart, (t << 20) >> (8 + bits) and
        // jitter >> (20 + bits): one three-way OR.
        const __m512i bits =
            Arity == 1 ? _mm512_ternarylogic_epi32(top[0], _mm512_srl_epi32(tents, jitterShift[0]),
                                                   _mm512_srl_epi32(jitter[0], blue.jitterShift20), 0xfe)
                       : _mm512_ternarylogic_epi32(
                             top[c], topMask[c],
                             _mm512_srl_epi32(subCellWordShifted8(tents, c, jitter[c]), blue.axisBits[c]), 0xea);
        axis[c] =
            Staged ? _mm512_mul_ps(_mm512_cvtepi32_ps(bits), _mm512_set1_ps(0x1p-24f)) : unitOf(bits, blue.exponent24);
    }
    storeInterleaved<Arity>(out, axis, floats);
}

// With the flag, a block's cell bits and jitter words: staged for the second pass, or, in a one-block call (nothing
// to overlap), finished at once. A set of at most 16 points has its offsets per cell index q at hand (smallOffsets,
// hashed off the block's path of latencies): one permute by q.
template <uint32_t Arity>
STIPPLE_KERNEL void blueBlockOrStage(BlueStage<Arity>& stage, uint32_t block, bool oneBlock, const __m512i* top,
                                     const __m512i* jitter, bool small, __m512i smallOffsets, __m512i q,
                                     const BlueLanes<Arity>& blue, const __m512i* topMask, const __m128i* cellShift,
                                     const __m128i* jitterShift, float* out, uint32_t floats) {
    if (oneBlock) {
        const __m512i offsets =
            small ? _mm512_permutexvar_epi32(q, smallOffsets) : blockOffsets<Arity>(top, topMask, cellShift, blue);
        return blueBlock<Arity, false>(top, jitter, offsets, blue, topMask, jitterShift, out, floats);
    }
    for (uint32_t c = 0; c < Arity; ++c) {
        stage.top[block][c] = top[c];
        stage.jitter[block][c] = jitter[c];
    }
}

template <uint32_t Arity, bool Blue>
[[STIPPLE_TARGET_AVX512]] void progressive(const ProgressiveKernelArgs& a, const CrossPixelStrata* blue, uint32_t first,
                                           uint32_t count, float* out) {
    const uint32_t bits = a.pointBits;
    const __m512i mask = _mm512_set1_epi32(int((1u << bits) - 1u));
    const __m128i unused = stipple::detail::count(32 - bits); // >= 32 shifts to 0, as reverseBits(v, 0) is 0
    const __m512i lanes = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    // reverseBits(p, bits) of an aligned block p = b + i (16 | b, i < 16 <= 2^bits) is reverseBits(b) | that of i.
    // (A constant: computing it would sit on the path of a one-block call.)
    const __m512i reversedLanes = _mm512_srl_epi32(
        _mm512_setr_epi32(0, int(0x80000000u), 0x40000000, int(0xc0000000u), 0x20000000, int(0xa0000000u), 0x60000000,
                          int(0xe0000000u), 0x10000000, int(0x90000000u), 0x50000000, int(0xd0000000u), 0x30000000,
                          int(0xb0000000u), 0x70000000, int(0xf0000000u)),
        unused);
    __m512i topMask[3];
    __m128i jitterShift[3], jitterShift16[3], cellShift[3];
    for (uint32_t c = 0; c < Arity; ++c) {
        cellShift[c] = stipple::detail::count(24 - a.axisBits[c]);
        topMask[c] = _mm512_set1_epi32(int(((1u << a.axisBits[c]) - 1u) << (24 - a.axisBits[c])));
        jitterShift[c] = stipple::detail::count(8 + a.axisBits[c]);
        jitterShift16[c] =
            stipple::detail::count(24 + a.axisBits[c]); // a count >= 32 shifts to 0, as x >> (24 + axisBits) is
    }
    [[maybe_unused]] BlueLanes<Arity> blueLanes;
    // A set of at most 16 points (pointBits <= 4) is one block whose cell indices q are < 16: the offsets of every
    // q, hashed here in parallel with the block's scramble rather than after it.
    [[maybe_unused]] const bool small = bits <= 4;
    [[maybe_unused]] __m512i smallOffsets = _mm512_setzero_si512();
    if constexpr (Blue) {
        blueLanes.offsetKey = _mm512_set1_epi64(int64_t(blue->offsetKey()));
        blueLanes.lattice =
            Arity == 1 ? _mm512_set1_epi32(int(blue->lattice.c[0])) : latticeBytes(blue->lattice.c, Arity);
        for (uint32_t c = 0; c < Arity; ++c) blueLanes.axisBits[c] = stipple::detail::count(a.axisBits[c]);
        blueLanes.jitterShift20 = stipple::detail::count(20 + a.axisBits[0]); // >= 32 shifts to 0, as in the word
        blueLanes.tentMask = _mm512_set1_epi32(int(0xfff00000u));
        blueLanes.exponent24 = _mm512_set1_epi32(24 << 23);
        asm("" : "+v"(blueLanes.tentMask), "+v"(blueLanes.exponent24)); // kept in registers, not rematerialised
        if (small) {
            __m512i top[Arity];
            cellTops<Arity>(_mm512_and_si512(lanes, mask), top); // q < 2^bits, as cellTops needs
            smallOffsets = blockOffsets<Arity>(top, topMask, cellShift, blueLanes);
        }
    }
    const uint32_t orderSeed = a.orderSeed, valueSeed = a.valueSeed; // in registers across the stores
    alignas(64) BlueStage<Arity> stage;
    for (uint32_t chunk = 0; chunk < count; chunk += kBlueChunkBlocks * 16) {
        const uint32_t chunkEnd = count - chunk < kBlueChunkBlocks * 16 ? count : chunk + kBlueChunkBlocks * 16;
        for (uint32_t base = chunk; base < chunkEnd; base += 16) {
            const uint32_t blockFirst = first + base;
            const uint32_t block = (base - chunk) / 16;
            // Index shuffle, then value scramble. Masking before a reversal is not needed: it keeps only low bits.
            // (Block 0 apart: a scalar reversal of 0 would lie on the path of a one-block call.)
            const __m512i reversed =
                blockFirst == 0 && bits >= 4 ? reversedLanes
                : blockFirst % 16 == 0 && bits >= 4
                    ? _mm512_or_si512(_mm512_set1_epi32(int(reverseBits(blockFirst, bits))), reversedLanes)
                    : _mm512_srl_epi32(reverse32(_mm512_add_epi32(_mm512_set1_epi32(int(blockFirst)), lanes)), unused);
            const __m512i shuffled = _mm512_srl_epi32(reverse32(laineKarras(reversed, orderSeed)), unused);
            const __m512i scrambled = laineKarras(shuffled, valueSeed);
            const __m512i q = _mm512_and_si512(scrambled, mask);
            const uint32_t floats = (count - base < 16 ? count - base : 16) * Arity;
            float* o = out + size_t(base) * Arity;
            if constexpr (Arity == 1) {
                // The jitter word is the unmasked scramble (progressivePoint).
                __m512i top[1];
                cellTops<1>(q, top);
                if constexpr (Blue) {
                    blueBlockOrStage<1>(stage, block, count <= 16, top, &scrambled, small, smallOffsets, q, blueLanes,
                                        topMask, cellShift, jitterShift, o, floats);
                } else {
                    storeFirst(o, valueOf(top[0], topMask[0], scrambled, jitterShift[0]), floats);
                }
            } else {
                // jitterBase of pattern_stratified.cpp: u = t ^ (t >> 16) with t = (s << 2) ^ seed, s the shuffled
                // index (< 2^22), is (s << 2) ^ (s >> 14) ^ (seed ^ seed >> 16): one three-way XOR after two
                // parallel shifts.
                const __m512i t =
                    _mm512_ternarylogic_epi32(_mm512_slli_epi32(shuffled, 2), _mm512_srli_epi32(shuffled, 14),
                                              _mm512_set1_epi32(int(a.jitterSeed ^ (a.jitterSeed >> 16))), 0x96);
                __m512 v[Arity];
                if constexpr (Arity == 2) {
                    __m512i top0, top1;
                    cells2D(q, top0, top1);
                    if constexpr (Blue) {
                        const __m512i top[2] = {top0, top1};
                        __m512i jitter[2];
                        axisJitters<2>(t, jitter);
                        blueBlockOrStage<Arity>(stage, block, count <= 16, top, jitter, small, smallOffsets, q,
                                                blueLanes, topMask, cellShift, jitterShift, o, floats);
                        continue;
                    }
                    const __m512 x =
                        valueOfHead(top0, topMask[0], axisJitterHead(t, 0), jitterShift[0], jitterShift16[0]);
                    const __m512 y =
                        valueOfHead(top1, topMask[1], axisJitterHead(t, 1), jitterShift[1], jitterShift16[1]);
                    const __m512i lo = _mm512_setr_epi32(0, 16, 1, 17, 2, 18, 3, 19, 4, 20, 5, 21, 6, 22, 7, 23);
                    v[0] = _mm512_permutex2var_ps(x, lo, y);
                    v[1] = _mm512_permutex2var_ps(x, _mm512_add_epi32(lo, _mm512_set1_epi32(8)), y);
                } else {
                    __m512i top[3];
                    cells3D(q, top);
                    if constexpr (Blue) {
                        __m512i jitter[3];
                        axisJitters<3>(t, jitter);
                        blueBlockOrStage<Arity>(stage, block, count <= 16, top, jitter, small, smallOffsets, q,
                                                blueLanes, topMask, cellShift, jitterShift, o, floats);
                        continue;
                    }
                    __m512 axis[3];
                    for (uint32_t c = 0; c < 3; ++c)
                        axis[c] =
                            valueOfHead(top[c], topMask[c], axisJitterHead(t, c), jitterShift[c], jitterShift16[c]);
                    // Interleave x, y, z.
                    for (uint32_t w = 0; w < 3; ++w) {
                        const __m512 xy =
                            _mm512_permutex2var_ps(axis[0], _mm512_load_si512(kInterleave3.xy[w]), axis[1]);
                        v[w] = _mm512_permutex2var_ps(xy, _mm512_load_si512(kInterleave3.z[w]), axis[2]);
                    }
                }
                for (uint32_t w = 0; w < Arity; ++w)
                    if (floats > 16 * w) storeFirst(o + 16 * w, v[w], floats - 16 * w);
            }
        }
        if constexpr (Blue)
            if (count > 16)
                for (uint32_t base = chunk; base < chunkEnd; base += 16) {
                    const __m512i* top = stage.top[(base - chunk) / 16];
                    blueBlock<Arity, true>(top, stage.jitter[(base - chunk) / 16],
                                           blockOffsets<Arity>(top, topMask, cellShift, blueLanes), blueLanes, topMask,
                                           jitterShift, out + size_t(base) * Arity,
                                           (count - base < 16 ? count - base : 16) * Arity);
                }
    }
}

} // namespace

void progressiveAvx512(const ProgressiveKernelArgs& args, uint32_t arity, uint32_t first, uint32_t count, float* out) {
    switch (arity) {
    case 1: return progressive<1, false>(args, nullptr, first, count, out);
    case 2: return progressive<2, false>(args, nullptr, first, count, out);
    default: return progressive<3, false>(args, nullptr, first, count, out);
    }
}

void progressiveBlueAvx512(const ProgressiveKernelArgs& args, const CrossPixelStrata& blue, uint32_t arity,
                           uint32_t first, uint32_t count, float* out) {
    switch (arity) {
    case 1: return progressive<1, true>(args, &blue, first, count, out);
    case 2: return progressive<2, true>(args, &blue, first, count, out);
    default: return progressive<3, true>(args, &blue, first, count, out);
    }
}

} // namespace stipple::detail
#endif
