// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// dimension.h — one validated entry of a sampler's dimension layout, with what its pattern precomputed.
#pragma once

#include "pmj02_family.h"
#include "poisson_cache.h"
#include "strata_grid.h"

#include <cstdint>
#include <memory>
#include <string>

namespace stipple::detail {

struct Dimension {
    uint32_t arity = 1;   // floats per value
    uint32_t count = 1;   // k values per pixel sample
    uint32_t setSize = 1; // M = k * N points in the pixel's set
    std::string name;
    StrataGrid grid;                              // stratified only
    std::shared_ptr<const PoissonFamily> poisson; // poisson only
    uint32_t log2Length = 0;                      // sobol, pmj02: L = 2^log2Length is the least power of two >= M
    std::shared_ptr<const Pmj02Family> pmj02;     // pmj02 only
    // What any other pattern precomputes for the set (its PatternOps::prepare sets it, its functions read it back
    // with stateAs): a pattern's state needs no field here.
    std::shared_ptr<const void> patternState;

    template <typename State>
    const State& stateAs() const {
        return *static_cast<const State*>(patternState.get());
    }

    uint32_t floatsPerPixel() const { return setSize * arity; }
    uint32_t floatsPerSample() const { return count * arity; }
};

} // namespace stipple::detail
