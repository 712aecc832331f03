// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// set_spectra.h — the periodogram of toroidal point sets kept set by set, so that the field's measures (largest peak,
// RAPS peak, median anisotropy) can be taken over any weighting of the sets: a bootstrap over pixels resamples the
// sets, not the points, and costs no new transform.
//
// Transform, frequencies and measures are the library's PowerSpectrum (pointsets/spectrum.h): each weighting adds the
// kept periodograms to an empty one, so unit weights give its values bit for bit (tests/poisson_serving_test.cpp
// checks it). The averaged periodogram with weights w is sum_s w_s P_s(k) / sum_s w_s.
#pragma once

#include "pointsets/spectrum.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace stipple::bench {

class SetSpectra {
public:
    SetSpectra(int dim, int maxFrequency, int annulusWidth) : empty_(dim, maxFrequency, annulusWidth) {}

    size_t sets() const { return values_.size() / std::max<size_t>(1, empty_.frequencies()); }

    // Appends one set's periodogram (n points, dim floats each, interleaved).
    void add(const float* points, uint32_t n) {
        const size_t F = empty_.frequencies();
        values_.resize(values_.size() + F);
        empty_.periodogram(points, n, values_.data() + values_.size() - F);
    }

    struct Measures {
        double peak, peakRadius, raps, anisotropy;
    };

    // The measures of the averaged periodogram with weight weights[s] on set s (empty: every set once).
    Measures measures(const std::vector<uint32_t>& weights = {}) const {
        detail::pointsets::PowerSpectrum average = empty_;
        for (size_t s = 0, S = sets(), F = empty_.frequencies(); s < S; ++s) {
            const double w = weights.empty() ? 1.0 : double(weights[s]);
            if (w != 0) average.addPeriodogram(values_.data() + s * F, w);
        }
        return {average.largestPeak(), average.largestPeakRadius(), average.rapsPeak(), average.medianAnisotropy()};
    }

private:
    detail::pointsets::PowerSpectrum empty_; // no set added: the frequencies each weighting starts from
    std::vector<double> values_;             // per set, one periodogram value per kept frequency
};

} // namespace stipple::bench
