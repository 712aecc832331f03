// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// independent_avx512.cpp — the independent pattern's blue-noise batch (pattern_independent.cpp, blueHashedFloats)
// with AVX-512 intrinsics, 16 points per step: the same values as pointIndependent with the flag.
//
// Per point the values' hashes hashAt(key, p * arity + c) and the sub-cell offsets' hashAt(offsetKey, p) run on
// 64-bit lanes whose scaled counters (counter + 1) * kGolden64 advance by one add per step (no multiply); one
// permute per hash pair keeps the 32 bits each use reads (the offsets' low half, the values' high half).
#include "batch_isa.h"
#include "blue_noise_avx512.h"
#include "hash.h"
#include "hash_avx512.h"
#include "simd_avx512.h"

#if defined(STIPPLE_BATCH_ISA_CLONES)
#include "avx512_intrinsics.h"

namespace stipple::detail {

namespace {

#define STIPPLE_KERNEL [[STIPPLE_TARGET_AVX512, gnu::always_inline]] inline

// The 16 low (even) or high (odd) dwords of two vectors of 8 64-bit lanes, in lane order.
STIPPLE_KERNEL __m512i dwordsOf(__m512i lo, __m512i hi, int odd) {
    const __m512i even = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
    return _mm512_permutex2var_epi32(lo, odd ? _mm512_add_epi32(even, _mm512_set1_epi32(1)) : even, hi);
}

// pointIndependent's value of a jitter word moved into its sub-cell, given word >> 8 (exact as a float, < 2^24):
// times 2^-24.
STIPPLE_KERNEL __m512 unitOfShifted8(__m512i shifted) {
    return _mm512_mul_ps(_mm512_cvtepi32_ps(shifted), _mm512_set1_ps(0x1p-24f));
}

template <uint32_t Arity>
[[STIPPLE_TARGET_AVX512]] void blueIndependent(uint64_t key, const CrossPixelStrata& blue, uint32_t first,
                                               uint32_t count, float* out) {
    const __m512i golden = _mm512_set1_epi64(int64_t(kGolden64));
    const __m512i lanes = _mm512_setr_epi64(0, 1, 2, 3, 4, 5, 6, 7);
    // Scaled counters of half h (points first + 8 h + lane): values' (p * Arity + c + 1) * G, offsets' (p + 1) * G.
    __m512i valueCounter[2][Arity], offsetCounter[2];
    for (uint32_t h = 0; h < 2; ++h) {
        const uint64_t p0 = uint64_t(first) + 8 * h;
        for (uint32_t c = 0; c < Arity; ++c)
            valueCounter[h][c] =
                _mm512_mullo_epi64(_mm512_add_epi64(_mm512_set1_epi64(int64_t(p0 * Arity + c + 1)),
                                                    _mm512_mullo_epi64(lanes, _mm512_set1_epi64(Arity))),
                                   golden);
        offsetCounter[h] = _mm512_mullo_epi64(_mm512_add_epi64(_mm512_set1_epi64(int64_t(p0 + 1)), lanes), golden);
    }
    const __m512i valueStep = _mm512_set1_epi64(int64_t(16 * Arity * kGolden64));
    const __m512i offsetStep = _mm512_set1_epi64(int64_t(16 * kGolden64));
    const __m512i valueKey = _mm512_set1_epi64(int64_t(key)), offsetKey = _mm512_set1_epi64(int64_t(blue.offsetKey()));
    // The pixel's lattice values: 1D's on every lane, 2D's and 3D's packed in bytes (tentBytes).
    const __m512i lattice =
        Arity == 1 ? _mm512_set1_epi32(int(blue.lattice.c[0])) : latticeBytes(blue.lattice.c, Arity);
    const __m512i tentMask = _mm512_set1_epi32(int(0xfff00000u));
    for (uint32_t base = 0; base < count; base += 16) {
        // 1D: the value's counter is the offsets' (p + 1), so the offsets reuse it.
        const __m512i offsets =
            dwordsOf(hashAtScaled(offsetKey, Arity == 1 ? valueCounter[0][0] : offsetCounter[0]),
                     hashAtScaled(offsetKey, Arity == 1 ? valueCounter[1][0] : offsetCounter[1]), 0);
        __m512 axis[Arity];
        const __m512i tents = Arity == 1 ? tent12(offsets, lattice, tentMask) : tentBytes(offsets, lattice);
        for (uint32_t c = 0; c < Arity; ++c) {
            const __m512i jitter =
                dwordsOf(hashAtScaled(valueKey, valueCounter[0][c]), hashAtScaled(valueKey, valueCounter[1][c]), 1);
            // The word >> 8: 1D (t << 20 | jitter >> 12) >> 8.
            axis[c] =
                unitOfShifted8(Arity == 1 ? _mm512_or_si512(_mm512_srli_epi32(tents, 8), _mm512_srli_epi32(jitter, 20))
                                          : subCellWordShifted8(tents, c, jitter));
            for (uint32_t h = 0; h < 2; ++h) valueCounter[h][c] = _mm512_add_epi64(valueCounter[h][c], valueStep);
        }
        if constexpr (Arity > 1)
            for (uint32_t h = 0; h < 2; ++h) offsetCounter[h] = _mm512_add_epi64(offsetCounter[h], offsetStep);
        const uint32_t floats = (count - base < 16 ? count - base : 16) * Arity;
        storeInterleaved<Arity>(out + size_t(base) * Arity, axis, floats);
    }
}

} // namespace

void independentBlueAvx512(uint64_t key, const CrossPixelStrata& blue, uint32_t arity, uint32_t first, uint32_t count,
                           float* out) {
    switch (arity) {
    case 1: return blueIndependent<1>(key, blue, first, count, out);
    case 2: return blueIndependent<2>(key, blue, first, count, out);
    default: return blueIndependent<3>(key, blue, first, count, out);
    }
}

} // namespace stipple::detail
#endif
