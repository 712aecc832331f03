// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// simd_avx512.h — hand-written AVX-512 batch kernels (the BatchIsa::Avx512 variant, batch_isa.h).
//
// The compiler's vectorisation of the generic batch loops leaves per-value work that wide integer lanes do in one
// instruction: bit reversal of 32-bit lanes (GFNI reverses the bits of every byte, a byte shuffle the bytes of
// every dword), 64-bit lane multiplies, lane permutes for the XOR-shuffled copies. These kernels compute exactly
// the values of the generic code (integer arithmetic, the same float operations); shim.batch_isa compares them
// bitwise with the per-point path. Compiled with STIPPLE_TARGET_AVX512 in their own files, called only when
// batchIsa() is Avx512.
#pragma once

#include "blue_noise.h"

#include <cstdint>

namespace stipple::detail {

// The progressive stratified order (pattern_stratified.cpp): seeds of the set and the grid's shape.
struct ProgressiveKernelArgs {
    uint32_t orderSeed, valueSeed, jitterSeed;
    uint32_t pointBits;
    uint32_t axisBits[3];
};
void progressiveAvx512(const ProgressiveKernelArgs& args, uint32_t arity, uint32_t first, uint32_t count, float* out);
// The same with the blue-noise flag (blue_noise.h): the tile's offsets key and the pixel's lattice values per axis,
// read from the CrossPixelStrata itself (a copy's 64-bit read of two of its 32-bit lattice values, just stored,
// missed store forwarding).
void progressiveBlueAvx512(const ProgressiveKernelArgs& args, const CrossPixelStrata& blue, uint32_t arity,
                           uint32_t first, uint32_t count, float* out);

// A poisson set served in its layered order (pattern_poisson.cpp): position p reads stored point
// p ^ (orderSeed & (bit_floor(p) - 1)), output axis c its axis source[c], then shift + sign * x wrapped into [0,1).
// Handles sets of 2^j points from a first position on the 16-float grid (on the 16-point grid in 3D); returns false
// (nothing done) for the others.
struct PoissonKernelArgs {
    uint32_t orderSeed;
    uint32_t source[3];
    float sign[3], shift[3];
};
bool poissonLayeredAvx512(const PoissonKernelArgs& args, uint32_t arity, const float* stored, uint32_t points,
                          uint32_t first, uint32_t count, float* out);

} // namespace stipple::detail
