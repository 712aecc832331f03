// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// random.h — the small deterministic generator the point-set code draws from.
//
// SplitMix64 (Steele, Lea, Flood 2014): one 64-bit add and a mix per draw, passes BigCrush, and any
// 64-bit seed is a valid state, so (dim, n, seed) -> state needs no care. Private to pointsets/.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace stipple::detail::pointsets {

inline uint64_t mix64(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

class SplitMix64 {
public:
    explicit SplitMix64(uint64_t seed) : state_(mix64(seed)) {}

    uint64_t next() {
        state_ += 0x9e3779b97f4a7c15ull;
        return mix64(state_);
    }
    // Uniform in [0,1): 24 random bits, so the largest value is 1 - 2^-24, never 1.0.
    float uniformFloat() { return float(next() >> 40) * 0x1p-24f; }
    // Uniform in [0,1) with 53 bits.
    double uniformDouble() { return double(next() >> 11) * 0x1p-53; }
    // Uniform integer in [0, bound), bound > 0 (Lemire's multiply-shift; bias < 2^-32 for our bounds).
    uint32_t uniformBelow(uint32_t bound) { return uint32_t(((next() >> 32) * uint64_t(bound)) >> 32); }

private:
    uint64_t state_;
};

// Seeds of independent streams derived from one seed: the stream id is mixed in, not added.
inline uint64_t deriveSeed(uint64_t seed, uint64_t stream) {
    return mix64(seed ^ mix64(stream + 0x632be59bd9b4e019ull));
}

// Fisher-Yates over the first n points of D floats each, from its own stream: a served set carries no spatial order
// a host could trip on.
template <int D> void shufflePoints(std::vector<float>& pts, uint32_t n, uint64_t seed) {
    SplitMix64 rng(seed);
    for (uint32_t i = n; i > 1; --i) {
        const uint32_t j = rng.uniformBelow(i);
        for (int k = 0; k < D; ++k) std::swap(pts[size_t(i - 1) * D + k], pts[size_t(j) * D + k]);
    }
}

} // namespace stipple::detail::pointsets
