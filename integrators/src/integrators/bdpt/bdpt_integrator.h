// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Bidirectional path tracing (Veach's thesis ch. 10, in the spirit of pbrt-v3's BDPTIntegrator). The factory,
// makeBdptIntegrator, is declared in integrator_registry.h; this header holds what tests also need: the debug
// variants that render one strategy, or one path depth, alone.
//
//   bdpt                   every strategy, MIS-weighted (power heuristic)
//   bdpt:s=S,t=T           strategy (S, T) alone, unweighted: estimates all paths of depth S+T-2 it can sample
//   bdpt:s=S,t=T,mis       strategy (S, T) alone with its MIS weight (these sum to "bdpt" over S, T)
//   bdpt:depth=D           every strategy of path depth D (= S+T-2 bounces), MIS-weighted
#pragma once

#include <string>

namespace stipple::render::bdpt {

struct StrategyFilter {
    int s = -1, t = -1; // one strategy, or -1 for all
    int depth = -1;     // one depth, or -1 for all
    bool weighted = true;

    bool accepts(int s_, int t_) const {
        if (s >= 0 && (s_ != s || t_ != t)) return false;
        return depth < 0 || s_ + t_ - 2 == depth;
    }
};

// Parses an integrator name of the forms above; throws std::invalid_argument with the expected forms otherwise.
StrategyFilter parseVariant(const std::string& name);

} // namespace stipple::render::bdpt
