// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// overlap_relaxation.h — spreading points on the torus until no two are closer than a radius.
//
// Each point is a soft disk (ball) of diameter R. A Gauss-Seidel pass pushes every pair closer than R
// apart along its axis by omega * half its overlap (position-based dynamics), until a pass meets no pair
// closer than the target (<= R: pushing to R while stopping at the target leaves a margin that converges
// in few passes).
#pragma once

#include <cstdint>
#include <vector>

namespace stipple::detail::pointsets {

struct RelaxParams {
    float diameter; // R, absolute
    float target;   // stop once a pass meets no pair closer than this (target <= R) ...
    float accept;   // ... and an exact measurement confirms no pair is closer than this (<= target)
    float omega;    // over-relaxation of each push, in [1, 2)
    int maxPasses;
    bool measureUnverified = true; // measure the exact minimum after maxPasses unverified passes
};

struct RelaxStats {
    int passes = 0;
    float minDistance = 0; // the last measurement (exact when verified)
    bool verified = false; // accept reached within maxPasses
};

// pts: n points, D interleaved floats each, in [0,1); returned in [0,1) (order is changed).
template <int D>
RelaxStats relaxOverlaps(std::vector<float>& pts, uint32_t n, const RelaxParams& params);

} // namespace stipple::detail::pointsets
