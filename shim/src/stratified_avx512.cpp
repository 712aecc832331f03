// stratified_avx512.cpp — the progressive stratified batch (pattern_stratified.cpp, progressiveChunks) with AVX-512
// and GFNI intrinsics, 16 points per step: the same values, computed as progressivePoint does (simd_avx512.h).
#include "batch_isa.h"
#include "hash.h"
#include "progressive_strata.h"
#include "simd_avx512.h"

#if defined(STIPPLE_BATCH_ISA_CLONES)
#include <immintrin.h>

namespace stipple {

namespace {

#define STIPPLE_KERNEL [[STIPPLE_TARGET_AVX512, gnu::always_inline]] inline

// Bit reversal of every 32-bit lane: GFNI reverses the bits of each byte, a byte shuffle the bytes of each dword.
STIPPLE_KERNEL __m512i reverse32(__m512i v) {
    const __m512i bytes = _mm512_gf2p8affine_epi64_epi8(v, _mm512_set1_epi64(0x8040201008040201ll), 0);
    return _mm512_shuffle_epi8(bytes,
                               _mm512_broadcast_i32x4(_mm_setr_epi8(3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12)));
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

// (v | v >> s) & m in one ternary-logic op after the shift.
template <int S>
STIPPLE_KERNEL __m512i foldBits(__m512i v, uint32_t m) {
    return _mm512_ternarylogic_epi32(v, _mm512_srli_epi32(v, S), _mm512_set1_epi32(int(m)), 0xa8);
}

STIPPLE_KERNEL __m512i compactEvery2(__m512i v) { // progressive_strata.h's, per lane
    v = _mm512_and_si512(v, _mm512_set1_epi32(0x55555555));
    v = foldBits<1>(v, 0x33333333u);
    v = foldBits<2>(v, 0x0f0f0f0fu);
    v = foldBits<4>(v, 0x00ff00ffu);
    return foldBits<8>(v, 0x0000ffffu);
}

STIPPLE_KERNEL __m512i compactEvery3(__m512i v) {
    v = _mm512_and_si512(v, _mm512_set1_epi32(0x09249249));
    v = foldBits<2>(v, 0x030c30c3u);
    v = foldBits<4>(v, 0x0300f00fu);
    v = foldBits<8>(v, 0x030000ffu);
    return foldBits<16>(v, 0x000003ffu);
}

STIPPLE_KERNEL __m128i count(uint32_t s) { return _mm_cvtsi32_si128(int(s)); }

// The high (Odd) or low dwords of the 64-bit lanes of lo (points 0..7) and hi (points 8..15), as 16 lanes.
template <bool Odd>
STIPPLE_KERNEL __m512i dwordsOf(__m512i lo, __m512i hi) {
    const __m512i even = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
    return _mm512_permutex2var_epi32(lo, Odd ? _mm512_add_epi32(even, _mm512_set1_epi32(1)) : even, hi);
}

STIPPLE_KERNEL __m512i mul64(__m512i x, uint64_t c) { return _mm512_mullo_epi64(x, _mm512_set1_epi64(int64_t(c))); }

STIPPLE_KERNEL __m512i mix64(__m512i z) { // hash.h's, per 64-bit lane
    z = mul64(_mm512_xor_si512(z, _mm512_srli_epi64(z, 30)), 0xbf58476d1ce4e5b9ull);
    z = mul64(_mm512_xor_si512(z, _mm512_srli_epi64(z, 27)), 0x94d049bb133111ebull);
    return _mm512_xor_si512(z, _mm512_srli_epi64(z, 31));
}

// hashAt(key, q) for 8 lanes of q (64-bit).
STIPPLE_KERNEL __m512i hashAt(uint64_t key, __m512i q) {
    const __m512i counter = _mm512_add_epi64(q, _mm512_set1_epi64(1));
    return mix64(_mm512_xor_si512(_mm512_set1_epi64(int64_t(key)), mul64(counter, kGolden64)));
}

// The 1D jitter: one multiply of the keyed counter (its top 32 bits are used).
STIPPLE_KERNEL __m512i jitter1D(uint64_t key, __m512i q) {
    return mul64(_mm512_xor_si512(_mm512_set1_epi64(int64_t(key)), mul64(q, kGolden64)), 0xd1342543de82ef95ull);
}

// (cell << (24 - axisBits)) | (jitter >> (8 + axisBits)) as float: exact (< 2^24), as in progressivePoint.
STIPPLE_KERNEL __m512 value(__m512i cell, __m512i jitter, uint32_t axisBits) {
    const __m512i bits = _mm512_or_si512(_mm512_sll_epi32(cell, count(24 - axisBits)),
                                         _mm512_srl_epi32(jitter, count(8 + axisBits)));
    return _mm512_mul_ps(_mm512_cvtepi32_ps(bits), _mm512_set1_ps(0x1p-24f));
}

// Stores the first `floats` (<= 16) lanes.
STIPPLE_KERNEL void store(float* out, __m512 v, uint32_t floats) {
    if (floats >= 16)
        _mm512_storeu_ps(out, v);
    else
        _mm512_mask_storeu_ps(out, __mmask16((1u << floats) - 1u), v);
}

// Lane indices that interleave three 16-lane axes into 48 floats (float f is axis f % 3 of point f / 3): the
// first permute takes x or y, the second keeps that or takes z.
struct Interleave3 {
    alignas(64) int32_t xy[3][16];
    alignas(64) int32_t z[3][16];
    constexpr Interleave3() : xy(), z() {
        for (int w = 0; w < 3; ++w)
            for (int l = 0; l < 16; ++l) {
                const int f = 16 * w + l, point = f / 3, c = f % 3;
                xy[w][l] = (c == 1 ? 16 : 0) + point;
                z[w][l] = c == 2 ? 16 + point : l;
            }
    }
};
inline constexpr Interleave3 kInterleave3{};

// The GF(2) affine matrix that sets bit i of every byte to bit from[i] (gf2p8affine: result bit i is the parity of
// byte 7 - i of the matrix ANDed with the input byte); from[i] < 0 leaves bit i zero.
constexpr int64_t bitMatrix(const int (&from)[8]) {
    uint64_t m = 0;
    for (int i = 0; i < 8; ++i)
        if (from[i] >= 0) m |= uint64_t(1) << (8 * (7 - i) + from[i]);
    return int64_t(m);
}
// Bytes of every dword reversed (reverse32's shuffle).
STIPPLE_KERNEL __m512i reverseBytes(__m512i v) {
    return _mm512_shuffle_epi8(v, _mm512_broadcast_i32x4(_mm_setr_epi8(3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12)));
}

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

// (top & topMask) | (jitter >> (8 + axisBits)) as float: exact (< 2^24), as in progressivePoint.
STIPPLE_KERNEL __m512 valueOf(__m512i top, __m512i topMask, __m512i jitter, __m128i jitterShift) {
    const __m512i bits = _mm512_ternarylogic_epi32(top, topMask, _mm512_srl_epi32(jitter, jitterShift), 0xea);
    return _mm512_mul_ps(_mm512_cvtepi32_ps(bits), _mm512_set1_ps(0x1p-24f));
}

template <uint32_t Arity>
[[STIPPLE_TARGET_AVX512]] void progressive(const ProgressiveKernelArgs& a, uint32_t first, uint32_t count,
                                           float* out) {
    const uint32_t bits = a.pointBits;
    const __m512i mask = _mm512_set1_epi32(int((1u << bits) - 1u));
    const __m128i unused = stipple::count(32 - bits); // >= 32 shifts to 0, as reverseBits(v, 0) is 0
    const __m512i lanes = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    // reverseBits(p, bits) of an aligned block p = b + i (16 | b, i < 16 <= 2^bits) is reverseBits(b) | that of i.
    const __m512i reversedLanes = _mm512_srl_epi32(reverse32(lanes), unused);
    __m512i topMask[3];
    __m128i jitterShift[3];
    for (uint32_t c = 0; c < Arity; ++c) {
        topMask[c] = _mm512_set1_epi32(int(((1u << a.axisBits[c]) - 1u) << (24 - a.axisBits[c])));
        jitterShift[c] = stipple::count(8 + a.axisBits[c]);
    }
    for (uint32_t base = 0; base < count; base += 16) {
        const uint32_t blockFirst = first + base;
        // Index shuffle, then value scramble. Masking before a reversal is not needed: it keeps only low bits.
        const __m512i reversed =
            blockFirst % 16 == 0 && bits >= 4
                ? _mm512_or_si512(_mm512_set1_epi32(int(reverseBits(blockFirst, bits))), reversedLanes)
                : _mm512_srl_epi32(reverse32(_mm512_add_epi32(_mm512_set1_epi32(int(blockFirst)), lanes)), unused);
        const __m512i shuffled = _mm512_srl_epi32(reverse32(laineKarras(reversed, a.orderSeed)), unused);
        const __m512i q = _mm512_and_si512(laineKarras(shuffled, a.valueSeed), mask);
        // The jitter hash in 64-bit lanes, points 0..7 and 8..15.
        const __m512i qLo = _mm512_cvtepu32_epi64(_mm512_castsi512_si256(q));
        const __m512i qHi = _mm512_cvtepu32_epi64(_mm512_extracti64x4_epi64(q, 1));
        const uint32_t floats = (count - base < 16 ? count - base : 16) * Arity;
        float* o = out + size_t(base) * Arity;
        if constexpr (Arity == 1) {
            const __m512i jitter = dwordsOf<true>(jitter1D(a.jitterKey, qLo), jitter1D(a.jitterKey, qHi));
            // cell << (24 - bits) is reverse32(q) >> 8 (q < 2^bits): the bytes of q reversed and moved down by one.
            const __m512i bytes = _mm512_gf2p8affine_epi64_epi8(q, _mm512_set1_epi64(0x8040201008040201ll), 0);
            const __m512i top = _mm512_shuffle_epi8(
                bytes, _mm512_broadcast_i32x4(_mm_setr_epi8(2, 1, 0, -1, 6, 5, 4, -1, 10, 9, 8, -1, 14, 13, 12, -1)));
            store(o, valueOf(top, topMask[0], jitter, jitterShift[0]), floats);
        } else {
            const __m512i hLo = hashAt(a.jitterKey, qLo), hHi = hashAt(a.jitterKey, qHi);
            __m512 v[Arity];
            if constexpr (Arity == 2) {
                __m512i top0, top1;
                cells2D(q, top0, top1);
                const __m512 x = valueOf(top0, topMask[0], dwordsOf<true>(hLo, hHi), jitterShift[0]);
                const __m512 y = valueOf(top1, topMask[1], dwordsOf<false>(hLo, hHi), jitterShift[1]);
                const __m512i lo = _mm512_setr_epi32(0, 16, 1, 17, 2, 18, 3, 19, 4, 20, 5, 21, 6, 22, 7, 23);
                v[0] = _mm512_permutex2var_ps(x, lo, y);
                v[1] = _mm512_permutex2var_ps(x, _mm512_add_epi32(lo, _mm512_set1_epi32(8)), y);
            } else {
                const __m512i r = reverse32(q);
                __m512 axis[3];
                for (uint32_t c = 0; c < 3; ++c) {
                    const __m512i cell = _mm512_srl_epi32(compactEvery3(_mm512_srl_epi32(r, stipple::count(4 - c))),
                                                          stipple::count(10 - a.axisBits[c]));
                    const __m128i shift = stipple::count(43 - 21 * c);
                    const __m512i jitter = dwordsOf<false>(_mm512_slli_epi64(_mm512_srl_epi64(hLo, shift), 11),
                                                           _mm512_slli_epi64(_mm512_srl_epi64(hHi, shift), 11));
                    axis[c] = valueOf(_mm512_sll_epi32(cell, stipple::count(24 - a.axisBits[c])), topMask[c], jitter,
                                      jitterShift[c]);
                }
                // Interleave x, y, z.
                for (uint32_t w = 0; w < 3; ++w) {
                    const __m512 t = _mm512_permutex2var_ps(axis[0], _mm512_load_si512(kInterleave3.xy[w]), axis[1]);
                    v[w] = _mm512_permutex2var_ps(t, _mm512_load_si512(kInterleave3.z[w]), axis[2]);
                }
            }
            for (uint32_t w = 0; w < Arity; ++w)
                if (floats > 16 * w) store(o + 16 * w, v[w], floats - 16 * w);
        }
    }
}

} // namespace

void progressiveAvx512(const ProgressiveKernelArgs& args, uint32_t arity, uint32_t first, uint32_t count, float* out) {
    switch (arity) {
    case 1: return progressive<1>(args, first, count, out);
    case 2: return progressive<2>(args, first, count, out);
    default: return progressive<3>(args, first, count, out);
    }
}

} // namespace stipple
#endif
