// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// dimension.h — one validated entry of a sampler's dimension layout, with what its pattern precomputed.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

namespace stipple::detail {

struct Dimension {
    uint32_t arity = 1;   // floats per value
    uint32_t count = 1;   // k values per pixel sample
    uint32_t setSize = 1; // M = k * N points in the pixel's set
    std::string name;
    uint32_t log2Length = 0; // L = 2^log2Length, the least power of two >= M (the sequences' length)
    // What the pattern precomputed for the set (stratified: its strata grid; poisson: the family of stored sets;
    // pmj02: its family of sequences), owned by the pattern's file: its PatternOps::prepare sets it, its functions
    // read it back with stateAs. No pattern has a field here.
    std::shared_ptr<const void> patternState;

    template <typename State>
    const State& stateAs() const {
        return *static_cast<const State*>(patternState.get());
    }

    uint32_t floatsPerPixel() const { return setSize * arity; }
    uint32_t floatsPerSample() const { return count * arity; }
};

} // namespace stipple::detail
