// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// fast_divider.h — exact division of numerators < 2^22 by a fixed divisor with one multiply and one shift.
//
// Granlund & Montgomery (1994), Theorem 4.2: with k = 22 + ceil(log2 d) and m = ceil(2^k / d),
// floor(n / d) = floor(m * n / 2^k) for every n < 2^22. m * n < 2^45, so 64-bit arithmetic suffices.
// Set sizes are bounded by STIPPLE_MAX_SET_SIZE = 2^22, which is what makes this exact for every set index.
#pragma once

#include <cstdint>

namespace stipple::detail {

class FastDivider {
public:
    static constexpr uint32_t kNumeratorBits = 22;

    constexpr FastDivider() = default;
    explicit constexpr FastDivider(uint32_t divisor) : divisor_(divisor) {
        uint32_t log2Ceil = 0;
        while ((uint64_t(1) << log2Ceil) < divisor) ++log2Ceil;
        shift_ = kNumeratorBits + log2Ceil;
        magic_ = ((uint64_t(1) << shift_) + divisor - 1) / divisor;
    }

    constexpr uint32_t divisor() const { return divisor_; }
    constexpr uint32_t divide(uint32_t n) const { return static_cast<uint32_t>((n * magic_) >> shift_); }

private:
    uint64_t magic_ = uint64_t(1) << kNumeratorBits;
    uint32_t shift_ = kNumeratorBits;
    uint32_t divisor_ = 1;
};

} // namespace stipple::detail
