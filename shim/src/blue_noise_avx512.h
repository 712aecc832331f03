// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// blue_noise_avx512.h — jitterInSubCell (blue_noise.h) on 16 lanes, for the hand-written AVX-512 kernels' own files.
#pragma once

#include "batch_isa.h"

#include <cstdint>

#if defined(STIPPLE_BATCH_ISA_CLONES)
#include "avx512_intrinsics.h"

namespace stipple::detail {

// A pixel's lattice value c of one axis on every lane, as jitterInSubCellLanes adds it: c << (32 - log2 Q). Made
// once per call (the kernels' loops would otherwise reload and broadcast it per block).
template <uint32_t Arity>
[[STIPPLE_TARGET_AVX512, gnu::always_inline]] inline __m512i latticeLanes(uint32_t lattice) {
    constexpr uint32_t L = Arity == 1 ? 12 : 6;
    return _mm512_set1_epi32(int(lattice << (32 - L)));
}

// jitterInSubCell<Arity>(lattice, offsets, axis, jitter) per lane, offsets' low 32 bits and latticeLanes given.
// With L = log2 Q, s = ((o >> 8 axis) + c) << (32 - L) holds (c + o) mod Q in its top L bits without a mask (the
// left shift drops the rest; the right one clears the bit below, which 2 s moves up); the tent is then 2 s xor (all
// ones if s's top bit is set) in those L bits, because 2 (Q - 1 - c) + 1 = (Q - 1) xor (2 c mod Q) for c >= Q / 2.
// The tent's L bits (tentMask<Arity>() on every lane): a kernel that keeps it in a register passes it.
template <uint32_t Arity>
[[STIPPLE_TARGET_AVX512, gnu::always_inline]] inline __m512i tentMaskLanes() {
    constexpr uint32_t L = Arity == 1 ? 12 : 6;
    return _mm512_set1_epi32(int(~0u << (32 - L)));
}

template <uint32_t Arity>
[[STIPPLE_TARGET_AVX512, gnu::always_inline]] inline __m512i
jitterInSubCellLanes(__m512i lattice, __m512i offsets, uint32_t axis, __m512i jitter,
                     __m512i tentMask = tentMaskLanes<Arity>()) {
    constexpr uint32_t L = Arity == 1 ? 12 : 6;
    const __m512i o = axis ? _mm512_srli_epi32(offsets, 8 * axis) : offsets;
    const __m512i s = _mm512_add_epi32(_mm512_slli_epi32(o, 32 - L), lattice);
    const __m512i tent =
        _mm512_ternarylogic_epi32(_mm512_slli_epi32(s, 1), _mm512_srai_epi32(s, 31), tentMask, 0x28); // (a ^ b) & c
    return _mm512_or_si512(tent, _mm512_srli_epi32(jitter, L));
}

// Arity 2 and 3 (Q = 64; axis a's offset is byte a of `offsets`, its lattice value byte a of latticeBytes): every
// axis' tent at once. A byte add gives (c + o) mod 64 in each byte's low 6 bits; the tent t = (2c mod 64) xor (63 if
// c >= 32) is linear over GF(2) in c's bits (t_0 = c_5, t_i = c_(i-1) xor c_5), so one affine map per byte makes
// it, as t << 2 (bits 2..7 of byte a; the bytes' bits 6 and 7 are ignored).
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

// jitterInSubCell<Arity>(...) >> 8 for axis `axis` of arity 2 or 3, given tentBytes: the tent in bits 18..23
// ((t << 26) >> 8), the jitter's top 18 bits below.
[[STIPPLE_TARGET_AVX512, gnu::always_inline]] inline __m512i subCellWordShifted8(__m512i tents, uint32_t axis,
                                                                                __m512i jitter) {
    const __m512i tent = axis == 2 ? tents : _mm512_slli_epi32(tents, 16 - 8 * int(axis));
    return _mm512_ternarylogic_epi32(tent, _mm512_set1_epi32(0x00fc0000), _mm512_srli_epi32(jitter, 14),
                                     0xea); // (a & b) | c
}

} // namespace stipple::detail
#endif
