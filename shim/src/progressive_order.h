// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// progressive_order.h — reordering a stored toroidal point set so that every prefix is well spread.
//
// Served Poisson sets are read in stored order, so the order chosen here is what a host rendering a prefix of a
// set (progressive passes, adaptive sampling) gets:
//  - M <= kFarthestPointLimit: greedy farthest-point order on the torus (the next point is the one farthest from
//    all earlier ones; the first is stored point 0). Prefixes keep a high minimum distance (measured in
//    POINTSETS.md). O(M^2) time, done once per stored set when the set is generated.
//  - larger M: the points sorted along a Morton curve (10 bits per axis), then read in the order of the radical
//    inverse of their curve position, so a prefix takes every 2^j-th point of the curve. O(M log M).
#pragma once

#include <cstdint>
#include <vector>

namespace stipple::detail {

inline constexpr uint32_t kFarthestPointLimit = 1024;

// Reorders points (M * arity floats in [0,1)) in place.
void orderProgressively(std::vector<float>& points, uint32_t arity);

} // namespace stipple::detail
