// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// hash_avx512.h — hash.h's mix64 and hashAt on 8 64-bit lanes, for the hand-written AVX-512 kernels' own files.
#pragma once

#include "batch_isa.h"
#include "hash.h"

#if defined(STIPPLE_BATCH_ISA_CLONES)
#include "avx512_intrinsics.h"

namespace stipple::detail {

// mix64 (hash.h) of every lane.
[[STIPPLE_TARGET_AVX512, gnu::always_inline]] inline __m512i mix64Lanes(__m512i z) {
    z = _mm512_mullo_epi64(_mm512_xor_si512(z, _mm512_srli_epi64(z, 30)),
                           _mm512_set1_epi64(int64_t(0xbf58476d1ce4e5b9ull)));
    z = _mm512_mullo_epi64(_mm512_xor_si512(z, _mm512_srli_epi64(z, 27)),
                           _mm512_set1_epi64(int64_t(0x94d049bb133111ebull)));
    return _mm512_xor_si512(z, _mm512_srli_epi64(z, 31));
}

// hashAt(key, counter) of every lane, given the scaled counters (counter + 1) * kGolden64.
[[STIPPLE_TARGET_AVX512, gnu::always_inline]] inline __m512i hashAtScaled(__m512i key, __m512i scaledCounter) {
    return mix64Lanes(_mm512_xor_si512(scaledCounter, key));
}

} // namespace stipple::detail
#endif
