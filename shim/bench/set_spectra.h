// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// set_spectra.h — the periodogram of toroidal point sets kept set by set, so that the field's measures (largest peak,
// RAPS peak, median anisotropy) can be taken over any weighting of the sets: a bootstrap over pixels resamples the
// sets, not the points, and costs no new transform.
//
// Frequencies, annuli and measures are those of the library's PowerSpectrum (pointsets/spectrum.h), computed the same
// way and in the same order, so that unit weights give its values bit for bit (tests/poisson_serving_test.cpp checks
// it). The averaged periodogram with weights w is sum_s w_s P_s(k) / sum_s w_s.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <limits>
#include <vector>

namespace stipple::bench {

class SetSpectra {
public:
    SetSpectra(int dim, int maxFrequency, int annulusWidth)
        : dim_(dim), K_(maxFrequency), width_(std::max(1, annulusWidth)) {
        const int K = K_, ky = dim >= 2 ? K : 0, kz = dim >= 3 ? K : 0;
        for (int z = -kz; z <= kz; ++z)
            for (int y = -ky; y <= ky; ++y)
                for (int x = -K; x <= K; ++x) {
                    const bool positive = z > 0 || (z == 0 && (y > 0 || (y == 0 && x > 0)));
                    const long r2 = long(x) * x + long(y) * y + long(z) * z;
                    if (!positive || r2 > long(K) * K) continue;
                    const int k[3] = {x, y, z};
                    frequencies_.insert(frequencies_.end(), k, k + dim);
                    radius_.push_back(int(std::lround(std::sqrt(double(r2)) / width_)));
                }
    }

    size_t frequencyCount() const { return radius_.size(); }
    size_t sets() const { return values_.size() / std::max<size_t>(1, radius_.size()); }

    // Appends one set's periodogram (n points, dim floats each, interleaved).
    void add(const float* points, uint32_t n) {
        const int W = 2 * K_ + 1;
        std::vector<std::complex<double>> phase(size_t(dim_) * W);
        std::vector<std::complex<double>> sum(radius_.size());
        const double twoPi = 2.0 * std::acos(-1.0);
        for (uint32_t i = 0; i < n; ++i) {
            for (int c = 0; c < dim_; ++c) {
                const std::complex<double> step = std::polar(1.0, -twoPi * double(points[size_t(i) * dim_ + c]));
                std::complex<double>* row = phase.data() + size_t(c) * W;
                row[K_] = 1.0;
                for (int k = 1; k <= K_; ++k) {
                    row[K_ + k] = row[K_ + k - 1] * step;
                    row[K_ + k] /= std::abs(row[K_ + k]);
                    row[K_ - k] = std::conj(row[K_ + k]);
                }
            }
            const int* k = frequencies_.data();
            for (size_t f = 0; f < sum.size(); ++f, k += dim_) {
                std::complex<double> e = phase[size_t(K_ + k[0])];
                for (int c = 1; c < dim_; ++c) e *= phase[size_t(c) * W + size_t(K_ + k[c])];
                sum[f] += e;
            }
        }
        for (size_t f = 0; f < sum.size(); ++f) values_.push_back(std::norm(sum[f]) / n);
    }

    struct Measures {
        double peak, peakRadius, raps, anisotropy;
    };

    // The measures of the averaged periodogram with weight weights[s] on set s (empty: every set once).
    Measures measures(const std::vector<uint32_t>& weights = {}) const {
        const size_t F = radius_.size(), S = sets();
        std::vector<double> sum(F, 0.0);
        double total = 0;
        for (size_t s = 0; s < S; ++s) {
            const double w = weights.empty() ? 1.0 : double(weights[s]);
            if (w == 0) continue;
            total += w;
            const double* v = values_.data() + s * F;
            for (size_t f = 0; f < F; ++f) sum[f] += w * v[f];
        }
        const double sets = std::max(total, 1.0);
        Measures m{};
        const size_t best = size_t(std::max_element(sum.begin(), sum.end()) - sum.begin());
        m.peak = 0.0;
        for (double v : sum) m.peak = std::max(m.peak, v / sets);
        double r2 = 0;
        for (int c = 0; c < dim_; ++c) r2 += double(frequencies_[best * size_t(dim_) + size_t(c)]) *
                                             frequencies_[best * size_t(dim_) + size_t(c)];
        m.peakRadius = std::sqrt(r2);
        // Annuli exactly as PowerSpectrum::annuli, then its RAPS peak and median anisotropy.
        const int annuli = K_ / width_ + 1;
        std::vector<double> s1(size_t(annuli) + 1, 0.0), s2(size_t(annuli) + 1, 0.0);
        std::vector<int> count(size_t(annuli) + 1, 0);
        for (size_t f = 0; f < F; ++f) {
            const double p = sum[f] / sets;
            s1[size_t(radius_[f])] += p;
            s2[size_t(radius_[f])] += p * p;
            ++count[size_t(radius_[f])];
        }
        m.raps = 0.0;
        std::vector<double> anisotropies;
        for (int r = 1; r <= annuli; ++r) {
            if (count[size_t(r)] == 0) continue;
            const double mean = s1[size_t(r)] / count[size_t(r)];
            const double variance = std::max(0.0, s2[size_t(r)] / count[size_t(r)] - mean * mean);
            m.raps = std::max(m.raps, mean);
            if (count[size_t(r)] >= 8 && mean > 0 && variance > 0)
                anisotropies.push_back(10.0 * std::log10(variance / (mean * mean)));
        }
        m.anisotropy = std::numeric_limits<double>::quiet_NaN();
        if (dim_ > 1 && !anisotropies.empty()) {
            std::sort(anisotropies.begin(), anisotropies.end());
            const size_t h = anisotropies.size() / 2;
            m.anisotropy = anisotropies.size() % 2 ? anisotropies[h] : 0.5 * (anisotropies[h - 1] + anisotropies[h]);
        }
        return m;
    }

private:
    int dim_, K_, width_;
    std::vector<int> frequencies_; // dim ints per kept frequency
    std::vector<int> radius_;      // its annulus
    std::vector<double> values_;   // per set, one periodogram value per kept frequency
};

} // namespace stipple::bench
