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

} // namespace stipple::detail
