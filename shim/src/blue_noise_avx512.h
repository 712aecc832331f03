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

} // namespace stipple::detail
#endif
