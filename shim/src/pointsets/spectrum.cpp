// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// spectrum.cpp — see spectrum.h. O(N F) per set for F kept frequencies, from per-point phase tables per axis.
#include "spectrum.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace stipple::detail::pointsets {

PowerSpectrum::PowerSpectrum(int dim, int maxFrequency, int annulusWidth)
    : dim_(dim), K_(maxFrequency), width_(std::max(1, annulusWidth)) {
    const int K = K_, ky = dim >= 2 ? K : 0, kz = dim >= 3 ? K : 0;
    for (int z = -kz; z <= kz; ++z)
        for (int y = -ky; y <= ky; ++y)
            for (int x = -K; x <= K; ++x) {
                // The half space: the first nonzero coordinate from the last axis down is positive.
                const bool positive = z > 0 || (z == 0 && (y > 0 || (y == 0 && x > 0)));
                const long r2 = long(x) * x + long(y) * y + long(z) * z;
                if (!positive || r2 > long(K) * K) continue;
                const int k[3] = {x, y, z};
                frequencies_.insert(frequencies_.end(), k, k + dim);
                radius_.push_back(int(std::lround(std::sqrt(double(r2)) / width_)));
            }
    sum_.assign(radius_.size(), 0.0);
}

void PowerSpectrum::add(const float* points, uint32_t n) {
    std::vector<double> values(frequencies());
    periodogram(points, n, values.data());
    addPeriodogram(values.data(), 1.0);
}

void PowerSpectrum::periodogram(const float* points, uint32_t n, double* out) const {
    const int W = 2 * K_ + 1;
    std::vector<std::complex<double>> phase(size_t(dim_) * W); // exp(-2 pi i k x) per axis, k = -K..K
    std::vector<std::complex<double>> sum(radius_.size());
    const double twoPi = 2.0 * std::acos(-1.0);
    for (uint32_t i = 0; i < n; ++i) {
        for (int c = 0; c < dim_; ++c) {
            const std::complex<double> step = std::polar(1.0, -twoPi * double(points[size_t(i) * dim_ + c]));
            std::complex<double>* row = phase.data() + size_t(c) * W;
            row[K_] = 1.0;
            for (int k = 1; k <= K_; ++k) {
                // Renormalised every step so that the recurrence does not drift at large K.
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
    for (size_t f = 0; f < sum.size(); ++f) out[f] = std::norm(sum[f]) / n;
}

void PowerSpectrum::addPeriodogram(const double* values, double weight) {
    for (size_t f = 0; f < sum_.size(); ++f) sum_[f] += weight * values[f];
    weight_ += weight;
}

std::vector<PowerSpectrum::Annulus> PowerSpectrum::annuli() const {
    const int annuli = K_ / width_ + 1;
    std::vector<double> s(size_t(annuli) + 1, 0.0), s2(size_t(annuli) + 1, 0.0);
    std::vector<int> count(size_t(annuli) + 1, 0);
    for (size_t f = 0; f < sum_.size(); ++f) {
        const double p = sum_[f] / std::max(weight_, 1.0);
        s[size_t(radius_[f])] += p;
        s2[size_t(radius_[f])] += p * p;
        ++count[size_t(radius_[f])];
    }
    std::vector<Annulus> out;
    for (int r = 1; r <= annuli; ++r) {
        if (count[size_t(r)] == 0) continue;
        const double mean = s[size_t(r)] / count[size_t(r)];
        const double variance = std::max(0.0, s2[size_t(r)] / count[size_t(r)] - mean * mean);
        const double anisotropy = count[size_t(r)] > 1 && mean > 0 && variance > 0
                                      ? 10.0 * std::log10(variance / (mean * mean))
                                      : std::numeric_limits<double>::quiet_NaN();
        out.push_back({r * width_, mean, anisotropy, count[size_t(r)]});
    }
    return out;
}

double PowerSpectrum::medianAnisotropy() const {
    std::vector<double> values;
    if (dim_ == 1) return std::numeric_limits<double>::quiet_NaN(); // an annulus of a line holds no directions
    for (const Annulus& a : annuli())
        if (a.count >= 8 && !std::isnan(a.anisotropy)) values.push_back(a.anisotropy);
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::sort(values.begin(), values.end());
    const size_t h = values.size() / 2;
    return values.size() % 2 ? values[h] : 0.5 * (values[h - 1] + values[h]);
}

double PowerSpectrum::rapsPeak() const {
    double best = 0.0;
    for (const Annulus& a : annuli()) best = std::max(best, a.mean);
    return best;
}

double PowerSpectrum::largestPeak() const {
    double best = 0.0;
    for (double v : sum_) best = std::max(best, v / std::max(weight_, 1.0));
    return best;
}

double PowerSpectrum::largestPeakRadius() const {
    const size_t f = size_t(std::max_element(sum_.begin(), sum_.end()) - sum_.begin());
    const int* k = frequencies_.data() + f * size_t(dim_);
    double r2 = 0;
    for (int c = 0; c < dim_; ++c) r2 += double(k[c]) * k[c];
    return std::sqrt(r2);
}

} // namespace stipple::detail::pointsets
