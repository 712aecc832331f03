// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// A seeded, platform-independent random stream (PCG32, O'Neill 2014). std::*_distribution is not used on
// purpose: its output differs between standard libraries, and the generator must be byte-reproducible.
#pragma once

#include <cstdint>

namespace stipple::citygen {

class Rng {
public:
    explicit Rng(uint64_t seed, uint64_t stream = 0x9e3779b97f4a7c15ull) : inc_((stream << 1u) | 1u) {
        next();
        state_ += seed;
        next();
    }
    uint32_t next() {
        uint64_t old = state_;
        state_ = old * 6364136223846793005ull + inc_;
        uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
        uint32_t rot = uint32_t(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }
    // Uniform in [0, 1) with 24 bits, exactly representable.
    double uniform() { return double(next() >> 8) * (1.0 / 16777216.0); }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    // Uniform integer in [lo, hi] (inclusive); the modulo bias is irrelevant here.
    int range(int lo, int hi) { return lo + int(next() % uint32_t(hi - lo + 1)); }
    bool chance(double p) { return uniform() < p; }

private:
    uint64_t state_ = 0;
    uint64_t inc_;
};

} // namespace stipple::citygen
