// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// poisson_avx512.cpp — serving a 1D or 2D poisson set of 2^j points in its layered order (pattern_poisson.cpp,
// serveLayered) with AVX-512, a 16-float block at a time (simd_avx512.h).
//
// In an aligned block of P = 16 / arity positions b..b+P-1 with b >= P, every position lies in b's layer [B, 2B), so
// position b + i reads stored point (b ^ (seed & (B - 1) & ~(P - 1))) + (i ^ (seed & (P - 1))): one contiguous
// stored block, permuted within. The block at 0 holds the small layers: i ^ (seed & (bit_floor(i) - 1)).
#include "batch_isa.h"
#include "simd_avx512.h"

#if defined(STIPPLE_BATCH_ISA_CLONES)
#include "avx512_intrinsics.h"

#include <bit>

namespace stipple::detail {

namespace {

// wrapUnit(shift + sign * v) of pattern_poisson.cpp per lane (sign * v is exact, so a fused multiply-add rounds the
// same).
[[STIPPLE_TARGET_AVX512, gnu::always_inline]] inline __m512 wrapped(__m512 sign, __m512 v, __m512 shift) {
    // x - floor(x): for x >= 0 it is x - trunc(x), exact; for x in (-1, 0) it is x + 1 rounded to nearest, what
    // wrapUnit adds. (VREDUCEPS would round that sum down.)
    const __m512 x = _mm512_fmadd_ps(sign, v, shift);
    const __m512 r = _mm512_sub_ps(x, _mm512_roundscale_ps(x, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC));
    return _mm512_maskz_mov_ps(_mm512_cmp_ps_mask(r, _mm512_set1_ps(1.0f), _CMP_LT_OQ), r);
}

template <uint32_t Arity>
[[STIPPLE_TARGET_AVX512]] void layered(const PoissonKernelArgs& a, const float* stored, uint32_t points,
                                       uint32_t first, uint32_t count, float* out) {
    constexpr uint32_t P = 16 / Arity;
    const __m512i lane = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    const __m512i point = _mm512_srli_epi32(lane, Arity - 1); // lane's point in the block
    // Lane's axis c reads stored axis source[c]; shift and sign per lane.
    __m512i axis = _mm512_setzero_si512();
    __m512 shift = _mm512_set1_ps(a.shift[0]), sign = _mm512_set1_ps(a.sign[0]);
    if constexpr (Arity == 2) {
        axis = _mm512_mask_set1_epi32(_mm512_set1_epi32(int(a.source[0])), 0xaaaa, int(a.source[1]));
        shift = _mm512_mask_mov_ps(shift, 0xaaaa, _mm512_set1_ps(a.shift[1]));
        sign = _mm512_mask_mov_ps(sign, 0xaaaa, _mm512_set1_ps(a.sign[1]));
    }
    const __m512i seed = _mm512_set1_epi32(int(a.orderSeed));
    // Block 0: bit_floor(i) - 1 per point (0 for i < 2), a constant of the lane.
    const __m512i smallLayers = _mm512_srli_epi32(
        _mm512_setr_epi32(0, 0, 2, 2, 6, 6, 6, 6, 14, 14, 14, 14, 14, 14, 14, 14), Arity);
    const __m512i firstPermute =
        _mm512_add_epi32(_mm512_mullo_epi32(_mm512_xor_si512(point, _mm512_and_si512(seed, smallLayers)),
                                            _mm512_set1_epi32(Arity)),
                         axis);
    const __m512i permute = _mm512_add_epi32(
        _mm512_mullo_epi32(_mm512_xor_si512(point, _mm512_set1_epi32(int(a.orderSeed & (P - 1)))),
                           _mm512_set1_epi32(Arity)),
        axis);
    const __mmask16 storedLanes = points >= P ? 0xffff : __mmask16((1u << (points * Arity)) - 1u);
    for (uint32_t base = 0; base < count; base += P) {
        const uint32_t b = first + base;
        __m512 v;
        if (b == 0) {
            v = _mm512_permutexvar_ps(firstPermute, _mm512_maskz_loadu_ps(storedLanes, stored));
        } else {
            const uint32_t block = b ^ (a.orderSeed & (std::bit_floor(b) - 1) & ~(P - 1));
            v = _mm512_permutexvar_ps(permute, _mm512_loadu_ps(stored + size_t(block) * Arity));
        }
        const __m512 r = wrapped(sign, v, shift);
        const uint32_t floats = (count - base < P ? count - base : P) * Arity;
        float* o = out + size_t(base) * Arity;
        storeFirst(o, r, floats);
    }
}


// 3D: blocks of 16 points (48 floats, three registers). Output float f = 16w + l of a block is axis c = f % 3 of
// point i = f / 3, read from stored float 3 (i ^ s) + source[c] of the block: two permutes (floats 0..31 and
// 32..47) and a blend per output register, with indices fixed per call.
[[STIPPLE_TARGET_AVX512]] void layered3(const PoissonKernelArgs& a, const float* stored, uint32_t points,
                                        uint32_t first, uint32_t count, float* out) {
    // Per output register w: lane l's point i and axis c, and bit_floor(i) - 1 (0 for i < 2), constants.
    const __m512i pointOf[3] = {_mm512_setr_epi32(0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 4, 4, 4, 5),
                                _mm512_setr_epi32(5, 5, 6, 6, 6, 7, 7, 7, 8, 8, 8, 9, 9, 9, 10, 10),
                                _mm512_setr_epi32(10, 11, 11, 11, 12, 12, 12, 13, 13, 13, 14, 14, 14, 15, 15, 15)};
    const __m512i axisOf[3] = {_mm512_setr_epi32(0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0),
                               _mm512_setr_epi32(1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1),
                               _mm512_setr_epi32(2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2)};
    const __m512i layersOf[3] = {_mm512_setr_epi32(0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 3, 3, 3, 3),
                                 _mm512_setr_epi32(3, 3, 3, 3, 3, 3, 3, 3, 7, 7, 7, 7, 7, 7, 7, 7),
                                 _mm512_setr_epi32(7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7, 7)};
    // From scalars: a vector load of the just-written arguments would wait for store forwarding to fail.
    const __m512i source =
        _mm512_zextsi128_si512(_mm_setr_epi32(int(a.source[0]), int(a.source[1]), int(a.source[2]), 0));
    const __m512 shift = _mm512_zextps128_ps512(_mm_setr_ps(a.shift[0], a.shift[1], a.shift[2], 0.0f));
    const __m512 sign = _mm512_zextps128_ps512(_mm_setr_ps(a.sign[0], a.sign[1], a.sign[2], 0.0f));
    // Stored float 3 (i ^ m) + source[c] of the block for output float (i, c): m = seed & (bit_floor(i) - 1) in
    // block 0, seed & 15 past it (computed only when such a block is served).
    __m512i firstIndex[3], index[3];
    __m512 shifts[3], signs[3];
    for (uint32_t w = 0; w < 3; ++w) {
        const __m512i axis = _mm512_permutexvar_epi32(axisOf[w], source);
        if (first == 0) {
            const __m512i i = _mm512_xor_si512(pointOf[w], _mm512_and_si512(_mm512_set1_epi32(int(a.orderSeed)),
                                                                             layersOf[w]));
            firstIndex[w] = _mm512_add_epi32(_mm512_add_epi32(_mm512_slli_epi32(i, 1), i), axis);
        }
        if (first + count > 16) {
            const __m512i i = _mm512_xor_si512(pointOf[w], _mm512_set1_epi32(int(a.orderSeed & 15u)));
            index[w] = _mm512_add_epi32(_mm512_add_epi32(_mm512_slli_epi32(i, 1), i), axis);
        }
        shifts[w] = _mm512_permutexvar_ps(axisOf[w], shift);
        signs[w] = _mm512_permutexvar_ps(axisOf[w], sign);
    }
    const uint32_t storedFloats = points >= 16 ? 48 : points * 3;
    for (uint32_t base = 0; base < count; base += 16) {
        const uint32_t b = first + base;
        const __m512i* lanes = b == 0 ? firstIndex : index;
        const float* from = stored + size_t(b == 0 ? 0 : b ^ (a.orderSeed & (std::bit_floor(b) - 1) & ~15u)) * 3;
        __m512 r[3];
        for (uint32_t w = 0; w < 3; ++w) {
            const uint32_t left = storedFloats > 16 * w ? storedFloats - 16 * w : 0;
            r[w] = left >= 16 ? _mm512_loadu_ps(from + 16 * w)
                              : _mm512_maskz_loadu_ps(__mmask16((1u << left) - 1u), from + 16 * w);
        }
        const uint32_t floats = (count - base < 16 ? count - base : 16) * 3;
        float* o = out + size_t(base) * 3;
        for (uint32_t w = 0; w < 3 && 16 * w < floats; ++w) {
            const __m512i j = lanes[w];
            const __m512 low = _mm512_permutex2var_ps(r[0], j, r[1]);
            const __m512 v =
                _mm512_mask_permutexvar_ps(low, _mm512_cmpge_epi32_mask(j, _mm512_set1_epi32(32)), j, r[2]);
            const __m512 x = wrapped(signs[w], v, shifts[w]);
            storeFirst(o + 16 * w, x, floats - 16 * w);
        }
    }
}

} // namespace

bool poissonLayeredAvx512(const PoissonKernelArgs& args, uint32_t arity, const float* stored, uint32_t points,
                          uint32_t first, uint32_t count, float* out) {
    if ((points & (points - 1)) != 0 || first % (arity == 3 ? 16 : 16 / arity) != 0) return false;
    if (arity == 3)
        layered3(args, stored, points, first, count, out);
    else if (arity == 1)
        layered<1>(args, stored, points, first, count, out);
    else
        layered<2>(args, stored, points, first, count, out);
    return true;
}

} // namespace stipple::detail
#endif
