// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// avx512_intrinsics.h — <immintrin.h> for the hand-written AVX-512 kernels' own files (simd_avx512.h).
//
// GCC 12's AVX-512 headers start some intrinsics from _mm512_undefined_*(), which -W(maybe-)uninitialized reports
// once inlined (GCC bug 105593, fixed in GCC 13). The warnings are silenced for the rest of the including file, so
// only the kernel files include this.
#pragma once

#include "batch_isa.h"

#include <cstdint>

#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ < 13
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#endif
#include <immintrin.h>

namespace stipple::detail {

// Stores the first `floats` (<= 16) lanes of v: whole, or masked for a block's tail.
[[STIPPLE_TARGET_AVX512, gnu::always_inline]] inline void storeFirst(float* out, __m512 v, uint32_t floats) {
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

// Stores the first `floats` (<= 16 * Arity) floats of 16 points given per axis, interleaved (x, y, z, x, ...).
template <uint32_t Arity>
[[STIPPLE_TARGET_AVX512, gnu::always_inline]] inline void storeInterleaved(float* out, const __m512* axis,
                                                                           uint32_t floats) {
    __m512 v[Arity];
    if constexpr (Arity == 1) {
        v[0] = axis[0];
    } else if constexpr (Arity == 2) {
        const __m512i lo = _mm512_setr_epi32(0, 16, 1, 17, 2, 18, 3, 19, 4, 20, 5, 21, 6, 22, 7, 23);
        v[0] = _mm512_permutex2var_ps(axis[0], lo, axis[1]);
        v[1] = _mm512_permutex2var_ps(axis[0], _mm512_add_epi32(lo, _mm512_set1_epi32(8)), axis[1]);
    } else {
        for (uint32_t w = 0; w < 3; ++w) {
            const __m512 xy = _mm512_permutex2var_ps(axis[0], _mm512_load_si512(kInterleave3.xy[w]), axis[1]);
            v[w] = _mm512_permutex2var_ps(xy, _mm512_load_si512(kInterleave3.z[w]), axis[2]);
        }
    }
    for (uint32_t w = 0; w < Arity; ++w)
        if (floats > 16 * w) storeFirst(out + 16 * w, v[w], floats - 16 * w);
}

} // namespace stipple::detail
