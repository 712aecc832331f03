// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// blue_noise_avx512.h — jitterInSubCell (blue_noise.h) on 16 lanes, for the hand-written AVX-512 kernels' own files.
//
// jitterInSubCell's word is (t << (32 - L)) | (jitter >> L), L = log2 Q, with t = tent((c + o) mod Q) =
// (2c' mod Q) xor (Q - 1 if c' >= Q / 2) for c' = (c + o) mod Q (2 (Q - 1 - c') + 1 = (Q - 1) xor (2c' mod Q) there).
// The kernels want the word shifted right (by 8 and more), so these give the tent and leave the jitter to them.
#pragma once

#include "batch_isa.h"

#include <cstdint>

#if defined(STIPPLE_BATCH_ISA_CLONES)
#include "avx512_intrinsics.h"

namespace stipple::detail {

// Arity 1 (Q = 4096), the pixel's lattice value c on every lane: t << 20 and zeros below, from the offsets' low 32
// bits. u = o + c holds c' in its low 12 bits; u << 21 is 2c' mod Q in the top 12 bits, flipped (xor tentMask,
// 0xfff00000 on every lane) where c''s top bit, u's bit 11, is set.
[[STIPPLE_TARGET_AVX512, gnu::always_inline]] inline __m512i tent12(__m512i offsets, __m512i lattice,
                                                                    __m512i tentMask) {
    const __m512i u = _mm512_add_epi32(offsets, lattice);
    const __m512i twice = _mm512_slli_epi32(u, 21);
    return _mm512_mask_xor_epi32(twice, _mm512_test_epi32_mask(u, _mm512_set1_epi32(0x800)), twice, tentMask);
}

// Arity 2 and 3 (Q = 64; axis a's offset is byte a of `offsets`, its lattice value byte a of latticeBytes): every
// axis' tent at once. A byte add gives c' in each byte's low 6 bits; the tent is linear over GF(2) in c''s bits
// (t_0 = c'_5, t_i = c'_(i-1) xor c'_5), so one affine map per byte makes it, as t << 2 (bits 2..7 of byte a; the
// bytes' bits 6 and 7 are ignored).
constexpr int64_t kTentMatrix = [] {
    // Output bit i is the parity of byte 7 - i of the matrix ANDed with the input byte.
    constexpr uint8_t rows[8] = {0, 0, 1u << 5, 0x21, 0x22, 0x24, 0x28, 0x30};
    uint64_t m = 0;
    for (int i = 0; i < 8; ++i) m |= uint64_t(rows[i]) << (8 * (7 - i));
    return int64_t(m);
}();

// The lattice values of a pixel's axes (arity 2 or 3), byte a = c[a], on every lane.
[[STIPPLE_TARGET_AVX512, gnu::always_inline]] inline __m512i latticeBytes(const uint32_t* c, uint32_t arity) {
    return _mm512_set1_epi32(int(c[0] | c[1] << 8 | (arity == 3 ? c[2] << 16 : 0u)));
}

[[STIPPLE_TARGET_AVX512, gnu::always_inline]] inline __m512i tentBytes(__m512i offsets, __m512i latticeBytes) {
    return _mm512_gf2p8affine_epi64_epi8(_mm512_add_epi8(offsets, latticeBytes), _mm512_set1_epi64(kTentMatrix), 0);
}

// jitterInSubCell's word >> 8 for axis `axis` of arity 2 or 3, given tentBytes: the tent in bits 18..23
// ((t << 26) >> 8), the jitter's top 18 bits below.
[[STIPPLE_TARGET_AVX512, gnu::always_inline]] inline __m512i subCellWordShifted8(__m512i tents, uint32_t axis,
                                                                                 __m512i jitter) {
    const __m512i tent = axis == 2 ? tents : _mm512_slli_epi32(tents, 16 - 8 * int(axis));
    return _mm512_ternarylogic_epi32(tent, _mm512_set1_epi32(0x00fc0000), _mm512_srli_epi32(jitter, 14),
                                     0xea); // (a & b) | c
}

} // namespace stipple::detail
#endif
