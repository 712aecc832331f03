// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// spectrum.cpp — see spectrum.h. O(N K^2) per set with per-point phase tables; P(-k) = P(k) halves it.
#include "spectrum.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace stipple::detail::pointsets {

PowerSpectrum2D::PowerSpectrum2D(int maxFrequency)
    : K_(std::max(1, maxFrequency)), W_(2 * K_ + 1), sum_(size_t(W_) * W_, 0.0) {}

void PowerSpectrum2D::add(const float* points, uint32_t n) {
    if (n == 0 || points == nullptr) return;
    using C = std::complex<double>;
    const double twoPi = 6.283185307179586;
    // Phase tables e^{-2 pi i k x} for k = -K..K, per point.
    std::vector<C> ex(size_t(n) * W_), ey(size_t(n) * W_);
    for (uint32_t i = 0; i < n; ++i)
        for (int k = -K_; k <= K_; ++k) {
            ex[size_t(i) * W_ + (k + K_)] = std::polar(1.0, -twoPi * k * double(points[2 * size_t(i)]));
            ey[size_t(i) * W_ + (k + K_)] = std::polar(1.0, -twoPi * k * double(points[2 * size_t(i) + 1]));
        }
    // Half plane ky >= 0 (and kx >= 0 on ky = 0), mirrored.
    for (int ky = 0; ky <= K_; ++ky)
        for (int kx = ky == 0 ? 0 : -K_; kx <= K_; ++kx) {
            C s = 0.0;
            for (uint32_t i = 0; i < n; ++i) s += ex[size_t(i) * W_ + (kx + K_)] * ey[size_t(i) * W_ + (ky + K_)];
            double p = std::norm(s) / double(n);
            sum_[size_t(ky + K_) * W_ + (kx + K_)] += p;
            if (kx != 0 || ky != 0) sum_[size_t(-ky + K_) * W_ + (-kx + K_)] += p;
        }
    ++sets_;
}

double PowerSpectrum2D::at(int kx, int ky) const {
    if (sets_ == 0 || std::abs(kx) > K_ || std::abs(ky) > K_) return 0.0;
    return sum_[size_t(ky + K_) * W_ + (kx + K_)] / sets_;
}

std::vector<PowerSpectrum2D::Ring> PowerSpectrum2D::rings(bool skipAxes) const {
    std::vector<double> s(K_ + 1, 0.0), s2(K_ + 1, 0.0), r(K_ + 1, 0.0);
    std::vector<int> c(K_ + 1, 0);
    for (int ky = -K_; ky <= K_; ++ky)
        for (int kx = -K_; kx <= K_; ++kx) {
            double radius = std::hypot(double(kx), double(ky));
            int ring = int(std::lround(radius));
            if (ring < 1 || ring > K_ || (skipAxes && (kx == 0 || ky == 0))) continue;
            double p = at(kx, ky);
            s[ring] += p;
            s2[ring] += p * p;
            r[ring] += radius;
            ++c[ring];
        }
    std::vector<Ring> out;
    for (int ring = 1; ring <= K_; ++ring) {
        if (c[ring] == 0) continue;
        double mean = s[ring] / c[ring], var = std::max(0.0, s2[ring] / c[ring] - mean * mean);
        double aniso = mean > 0.0 && var > 0.0 ? 10.0 * std::log10(var / (mean * mean)) : -99.0;
        out.push_back({r[ring] / c[ring], mean, aniso, c[ring]});
    }
    return out;
}

} // namespace stipple::detail::pointsets
