// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// spectrum.h — the averaged periodogram of toroidal point sets in 1 to 3 dimensions, the field's measures of a
// Poisson-disk set (Lagae & Dutre 2008; Heck et al. 2013).
//
// On the unit torus the Fourier series of a point set is exact at integer frequencies k:
//   P(k) = |sum_i exp(-2 pi i k.x_i)|^2 / N,  E P = 1 for white noise, P(0) = N.
// Averaged over M sets (or weighted, sum_s w_s P_s(k) / sum_s w_s): the radially averaged power spectrum (mean over
// the annulus of unit width round each integer radius), the anisotropy (10 log10(variance / mean^2) over an annulus,
// in dB; white noise averaged over M sets sits near 10 log10(1/M)), and the largest value of the averaged periodogram
// (a peak: white noise's largest value is about 1 + 4.5 / sqrt(M) over the thousands of frequencies). Used by the
// tests and shim_spectrum, not by the API.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace stipple::detail::pointsets {

class PowerSpectrum {
public:
    // Frequencies 0 < |k| <= maxFrequency (half of them: P(-k) = P(k)), in annuli of width annulusWidth round the
    // multiples of it (1D has one frequency per |k|: wider annuli smooth its radial spectrum).
    PowerSpectrum(int dim, int maxFrequency, int annulusWidth = 1);

    // Adds one set's periodogram (n points, dim floats each, interleaved): periodogram() then addPeriodogram(.., 1).
    void add(const float* points, uint32_t n);
    // One set's periodogram at the kept frequencies, into out[0, frequencies()). A caller that keeps it can average
    // the sets again under other weights (a bootstrap resamples sets) without a new transform.
    void periodogram(const float* points, uint32_t n, double* out) const;
    // Adds a periodogram (as periodogram() writes it) with weight w: an integer w counts as w sets.
    void addPeriodogram(const double* values, double weight);

    int dim() const { return dim_; }
    int maxFrequency() const { return K_; }
    size_t frequencies() const { return radius_.size(); }
    // The sets' total weight (their count when each was added once).
    double weight() const { return weight_; }

    struct Annulus {
        int radius;        // the radius the annulus is centred on (a multiple of the width)
        double mean;       // radially averaged power
        double anisotropy; // 10 log10(variance / mean^2) over the annulus, dB (0 values: not set)
        int count;         // frequencies in the annulus (of the half kept)
    };
    std::vector<Annulus> annuli() const;
    // Median of the annuli's anisotropy over those with at least 8 frequencies (none, or 1D: NaN).
    double medianAnisotropy() const;
    // Largest radially averaged power over the annuli (the RAPS' peak).
    double rapsPeak() const;
    // Largest value of the averaged periodogram over 0 < |k| <= maxFrequency, and its |k|.
    double largestPeak() const;
    double largestPeakRadius() const;

private:
    int dim_, K_, width_;
    double weight_ = 0;
    std::vector<int> frequencies_; // dim ints per kept frequency
    std::vector<int> radius_;      // its annulus
    std::vector<double> sum_;      // weighted sum of the periodograms per kept frequency
};

} // namespace stipple::detail::pointsets
