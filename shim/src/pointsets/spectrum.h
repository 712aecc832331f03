// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// spectrum.h — the periodogram of 2D toroidal point sets: the isotropy check of the Poisson sets.
//
// On the unit torus the Fourier series of a point set is exact at integer frequencies k:
//   P(k) = |sum_i exp(-2 pi i k.x_i)|^2 / N,  P = 1 for white noise, P(0) = N.
// Averaged over sets, its radial mean is the "radial power spectrum" and the variance over a ring
// divided by the squared mean is PSA's anisotropy (in dB; an isotropic spectrum averaged over M sets sits
// at the noise floor 10 log10(1/M)). Used by the tests and by shim/tools, not by the library's API.
#pragma once

#include <cstdint>
#include <vector>

namespace stipple::detail::pointsets {

class PowerSpectrum2D {
public:
    explicit PowerSpectrum2D(int maxFrequency);

    // Adds one set's periodogram (n points, interleaved x,y).
    void add(const float* points, uint32_t n);

    int maxFrequency() const { return K_; }
    int sets() const { return sets_; }
    // Mean periodogram over the sets added, at integer frequency (kx, ky), |kx|,|ky| <= K.
    double at(int kx, int ky) const;

    struct Ring {
        double radius;     // mean |k| of the ring (integer frequencies)
        double mean;       // radially averaged power
        double anisotropy; // 10 log10(variance / mean^2) over the ring, in dB
        int count;
    };
    // Rings of unit width centred on integer radii 1..K. skipAxes leaves out the frequencies on the axes
    // (kx = 0 or ky = 0), which sets with stratified 1D projections empty on purpose.
    std::vector<Ring> rings(bool skipAxes = false) const;

private:
    int K_, W_;
    int sets_ = 0;
    std::vector<double> sum_; // (2K+1)^2, row ky, column kx
};

} // namespace stipple::detail::pointsets
