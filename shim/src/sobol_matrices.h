// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// sobol_matrices.h — the generator matrices of the first three dimensions of Sobol's sequence.
//
// Dimension 0 is van der Corput's (the identity on reversed bits); dimensions 1 and 2 use the primitive
// polynomials x + 1 and x^2 + x + 1 with initial direction numbers m = (1) and (1, 3), as in Joe & Kuo's
// tables. Dimensions 0 and 1 form a (0,2)-sequence in base 2: every aligned block of 2^m consecutive points is a
// (0,m,2)-net (one point in every elementary interval of area 2^-m). All three form a (1,3)-sequence.
// Columns are 32-bit fixed-point direction numbers v_j = m_j / 2^j, column j for index bit j.
#pragma once

#include "owen_scrambling.h"

#include <array>
#include <bit>
#include <cstdint>

namespace stipple::detail {

namespace detail {

constexpr std::array<uint32_t, 32> sobolColumns(uint32_t degree, uint32_t coefficients,
                                                std::array<uint32_t, 2> initial) {
    std::array<uint64_t, 32> m{};
    for (uint32_t j = 0; j < 32; ++j) {
        if (j < degree) {
            m[j] = initial[j];
            continue;
        }
        // m_j = 2 a_1 m_{j-1} ^ 4 a_2 m_{j-2} ^ ... ^ 2^s m_{j-s} ^ m_{j-s}
        uint64_t v = (m[j - degree] << degree) ^ m[j - degree];
        for (uint32_t k = 1; k < degree; ++k)
            if ((coefficients >> (degree - 1 - k)) & 1u) v ^= m[j - k] << k;
        m[j] = v;
    }
    std::array<uint32_t, 32> columns{};
    for (uint32_t j = 0; j < 32; ++j) columns[j] = static_cast<uint32_t>(m[j] << (31 - j));
    return columns;
}

} // namespace detail

inline constexpr std::array<std::array<uint32_t, 32>, 3> kSobolMatrices = [] {
    std::array<std::array<uint32_t, 32>, 3> matrices{};
    for (uint32_t j = 0; j < 32; ++j) matrices[0][j] = 1u << (31 - j);
    matrices[1] = detail::sobolColumns(1, 0, {1, 0});
    matrices[2] = detail::sobolColumns(2, 1, {1, 3});
    return matrices;
}();

// The same columns bit-reversed: a coordinate's digits in the order the Laine-Karras hash takes them.
inline constexpr std::array<std::array<uint32_t, 32>, 3> kSobolMatricesReversed = [] {
    std::array<std::array<uint32_t, 32>, 3> matrices{};
    for (uint32_t d = 0; d < 3; ++d)
        for (uint32_t j = 0; j < 32; ++j) matrices[d][j] = reverseBits32(kSobolMatrices[d][j]);
    return matrices;
}();

// reverseBits32(sobolSample(index, d)) without the reversal: dimension 0 is the index itself.
constexpr uint32_t sobolSampleReversed(uint32_t index, uint32_t d) {
    if (d == 0) return index;
    uint32_t result = 0;
    for (; index != 0; index &= index - 1) result ^= kSobolMatricesReversed[d][std::countr_zero(index)];
    return result;
}

// The index-th point's coordinate in dimension d (0..2) as a 32-bit fraction.
// Dimension 0 is the bit reversal; the others XOR the columns of the index's set bits.
constexpr uint32_t sobolSample(uint32_t index, uint32_t d) {
    if (d == 0) return reverseBits32(index);
    uint32_t result = 0;
    for (; index != 0; index &= index - 1) result ^= kSobolMatrices[d][std::countr_zero(index)];
    return result;
}

} // namespace stipple::detail
