// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "metrics/error_spectrum.h"

#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>

namespace stipple::validation {

namespace {

using Complex = std::complex<double>;

// In-place DFT of n values at the given stride (direct O(n²): the images here are ≤ a few hundred pixels wide,
// and a row costs microseconds).
void dft(std::vector<Complex>& v, size_t offset, size_t n, size_t stride, std::vector<Complex>& scratch) {
    scratch.assign(n, 0);
    const double w = -2 * 3.14159265358979323846 / double(n);
    for (size_t k = 0; k < n; ++k) {
        Complex sum = 0;
        for (size_t j = 0; j < n; ++j) sum += v[offset + j * stride] * std::polar(1.0, w * double((k * j) % n));
        scratch[k] = sum;
    }
    for (size_t k = 0; k < n; ++k) v[offset + k * stride] = scratch[k];
}

} // namespace

ErrorSpectrum errorSpectrum(const Image& ref, const Image& test) {
    if (ref.width != test.width || ref.height != test.height)
        throw std::invalid_argument("error spectrum: images differ in size");
    ErrorSpectrum out;
    out.highOverLow = std::numeric_limits<double>::quiet_NaN();
    const size_t w = size_t(ref.width), h = size_t(ref.height);
    if (w < 8 || h < 8) return out;
    // Luminance error (Rec.709 weights), non-finite pixels as 0, mean removed (the DC term says nothing of
    // the error's scale).
    std::vector<Complex> e(w * h);
    double mean = 0;
    for (size_t i = 0; i < w * h; ++i) {
        double d = 0;
        for (int c = 0; c < 3; ++c) {
            const double weight = c == 0 ? 0.2126 : c == 1 ? 0.7152 : 0.0722;
            d += weight * (double(test.rgb[3 * i + c]) - double(ref.rgb[3 * i + c]));
        }
        e[i] = std::isfinite(d) ? d : 0.0;
        mean += e[i].real();
    }
    mean /= double(w * h);
    for (auto& v : e) v -= mean;
    std::vector<Complex> scratch;
    for (size_t y = 0; y < h; ++y) dft(e, y * w, w, 1, scratch);
    for (size_t x = 0; x < w; ++x) dft(e, x, h, w, scratch);

    constexpr int kBins = 46; // up to √2 / 2 cycles per pixel at 1/64 per bin
    std::vector<double> sum(kBins, 0);
    std::vector<size_t> count(kBins, 0);
    double high = 0, low = 0;
    size_t nHigh = 0, nLow = 0;
    for (size_t y = 0; y < h; ++y)
        for (size_t x = 0; x < w; ++x) {
            const double fx = (x <= w / 2 ? double(x) : double(x) - double(w)) / double(w);
            const double fy = (y <= h / 2 ? double(y) : double(y) - double(h)) / double(h);
            const double f = std::hypot(fx, fy), p = std::norm(e[y * w + x]);
            const int bin = std::min(kBins - 1, int(f * 64));
            sum[bin] += p;
            ++count[bin];
            if (f > 0 && f <= 0.125) low += p, ++nLow;
            if (f >= 0.25 && f <= 0.5) high += p, ++nHigh;
        }
    for (int b = 0; b < kBins; ++b) out.radialPower.push_back(count[b] ? sum[b] / double(count[b]) : 0);
    if (nLow && nHigh && low > 0) out.highOverLow = (high / double(nHigh)) / (low / double(nLow));
    return out;
}

} // namespace stipple::validation
