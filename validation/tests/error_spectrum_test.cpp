// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The error spectrum's summary tells white from blue from low-frequency error on synthetic errors with known
// spectra (fixed seeds).
#define BOOST_TEST_MODULE validation_error_spectrum
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <random>

#include "metrics/error_spectrum.h"

using namespace stipple::validation;

namespace {
Image grey(int n) {
    Image im;
    im.width = im.height = n;
    im.rgb.assign(size_t(3) * n * n, 0.5f);
    return im;
}
// White noise of the given amplitude added to grey.
Image noisy(int n, uint32_t seed) {
    Image im = grey(n);
    std::mt19937 rng(seed);
    std::normal_distribution<float> g(0, 0.1f);
    for (size_t i = 0; i < im.rgb.size() / 3; ++i) {
        const float d = g(rng);
        for (int c = 0; c < 3; ++c) im.rgb[3 * i + c] += d;
    }
    return im;
}
} // namespace

BOOST_AUTO_TEST_CASE(white_blue_and_low_frequency_errors) {
    const int n = 64;
    const Image ref = grey(n);
    // White: ratio near 1 (over 64² frequencies the estimate is within ±30%).
    const ErrorSpectrum white = errorSpectrum(ref, noisy(n, 1));
    BOOST_TEST_MESSAGE("white " << white.highOverLow);
    BOOST_CHECK(white.highOverLow > 0.7 && white.highOverLow < 1.3);
    // Blue: the difference of neighbouring white-noise pixels (a high-pass filter, |H|² = 4 sin²(π f)).
    Image blue = grey(n);
    const Image w = noisy(n, 2);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            for (int c = 0; c < 3; ++c)
                blue.rgb[3 * (y * n + x) + c] =
                    0.5f + w.rgb[3 * (y * n + x) + c] - w.rgb[3 * (y * n + (x + 1) % n) + c];
    const ErrorSpectrum b = errorSpectrum(ref, blue);
    BOOST_TEST_MESSAGE("blue " << b.highOverLow);
    BOOST_CHECK_GT(b.highOverLow, 3.0);
    // Low frequency: white noise box-blurred over 4 × 4 pixels.
    Image low = grey(n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            float s = 0;
            for (int dy = 0; dy < 4; ++dy)
                for (int dx = 0; dx < 4; ++dx) s += w.rgb[3 * (((y + dy) % n) * n + (x + dx) % n)] - 0.5f;
            for (int c = 0; c < 3; ++c) low.rgb[3 * (y * n + x) + c] = 0.5f + s / 16;
        }
    const ErrorSpectrum l = errorSpectrum(ref, low);
    BOOST_TEST_MESSAGE("low " << l.highOverLow);
    BOOST_CHECK_LT(l.highOverLow, 0.2);
    // Zero error: no ratio.
    BOOST_CHECK(std::isnan(errorSpectrum(ref, ref).highOverLow));
}
