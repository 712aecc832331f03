// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// torus.h — the unit torus [0,1)^d: wrapping, minimum-image differences, packing distances.
#pragma once

#include <cmath>
#include <cstdint>

namespace stipple::detail::pointsets {

// Largest float below 1: every coordinate we hand out is <= this.
inline constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

// Wraps x into [0,1). floor() alone is not enough: x - floor(x) rounds to 1.0f for tiny negative x, which
// is 0 on the torus (and NaN, which never occurs in our sets, becomes 0 too).
inline float wrapUnit(float x) {
    float w = x - std::floor(x);
    return w < 1.0f ? w : 0.0f;
}
inline float clampBelowOne(double x) {
    float f = float(x);
    return f < kOneMinusEpsilon ? (f < 0.0f ? 0.0f : f) : kOneMinusEpsilon;
}

// Minimum-image difference a - b on the unit circle, in [-0.5, 0.5].
inline float torusDelta(float a, float b) {
    float d = a - b;
    return d - std::nearbyint(d);
}

// d_max: the nearest-neighbour distance of the densest packing of n points on the unit d-torus
// (lattice bound: 1D equidistant, 2D hexagonal, 3D face-centred cubic).
inline double packingDistance(int dim, uint32_t n) {
    double N = double(n);
    switch (dim) {
    case 1: return 1.0 / N;
    case 2: return std::sqrt(2.0 / (std::sqrt(3.0) * N));
    default: return std::cbrt(std::sqrt(2.0) / N);
    }
}

} // namespace stipple::detail::pointsets
