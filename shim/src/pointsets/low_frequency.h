// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// low_frequency.h — cancelling the lowest Fourier modes of a toroidal point set by a smooth displacement.
//
// A set's density modes S(k) = sum_i exp(-2 pi i k.x_i) at small k are what smooth integrands read: the error
// of a toroidally shifted set on f is sum over k != 0 of f^(k) S(k) / N. Moving every point by the smooth field
// u(x) = sum_k 2 Re(a_k exp(2 pi i k.x)) k with a_k = S(k) / (2 pi i |k|^2 N) cancels S(k) to first order (the
// term q = k of sum_q a_q (k.q) S(k - q), the others being small for a well-spread set). A few iterations drive
// the chosen modes to ~0; the displacement is a small fraction of the spacing (~1-2% at the sizes measured in
// POINTSETS.md), so neighbour distances barely change.
#pragma once

#include <cstdint>
#include <vector>

namespace stipple::detail::pointsets {

// Cancels the modes 0 < |k| <= maxFrequency (integer k, one of each +-k pair) in `iterations` steps.
// pts: n points, D interleaved floats each, in [0,1); returned in [0,1), same order.
template <int D>
void cancelLowFrequencies(std::vector<float>& pts, uint32_t n, int maxFrequency, int iterations);

// sum over the same modes of |S(k)|^2 / N (the periodogram; white noise has 1 per mode).
template <int D>
double lowFrequencyEnergy(const std::vector<float>& pts, uint32_t n, int maxFrequency);

} // namespace stipple::detail::pointsets
