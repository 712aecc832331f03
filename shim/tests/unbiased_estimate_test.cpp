// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// unbiased_estimate_test.cpp — every pattern gives unbiased estimates of integrals with known values.
//
// For each pattern x arity (1, 2, 3) x N (16, 256): 512 pixels, each an independent estimate (the mean of the
// integrand over the pixel's N samples). A two-sided one-sample Student t-test compares the mean of the 512
// estimates with the exact value. Integrands with an edge, where a biased stratification or a biased shift
// would show first: 1D the step [x < 0.3] (0.3), 2D the quarter disk (pi/4), 3D the sphere octant (pi/6).
// Fixed seeds; family-wise alpha = 0.01, Sidak-corrected over the 24 tests.
#define BOOST_TEST_MODULE unbiased_estimate
#include <stipple/testing/statistics.h>
#include "sampler_fixture.h"

#include <cmath>
#include <numbers>

using namespace stipple::test;
using namespace stipple::testing;

namespace {

double integrand(uint32_t arity, const float* p) {
    switch (arity) {
    case 1: return p[0] < 0.3f ? 1.0 : 0.0;
    case 2: return double(p[0]) * p[0] + double(p[1]) * p[1] < 1.0 ? 1.0 : 0.0;
    default: return double(p[0]) * p[0] + double(p[1]) * p[1] + double(p[2]) * p[2] < 1.0 ? 1.0 : 0.0;
    }
}

double exactValue(uint32_t arity) {
    return arity == 1 ? 0.3 : arity == 2 ? std::numbers::pi / 4 : std::numbers::pi / 6;
}

} // namespace

BOOST_AUTO_TEST_CASE(estimates_are_unbiased) {
    const int kTests = patternCount() * 3 * 2;
    constexpr uint32_t kPixels = 512;
    const double alpha = sidak(0.01, kTests);
    for (uint32_t pattern : allPatterns()) {
        for (uint32_t arity = 1; arity <= 3; ++arity) {
            for (uint32_t n : {16u, 256u}) {
                auto s = makeSampler(pattern, n, 0xb1a5ed00 + 31 * arity + n, {{arity, 1}});
                double sum = 0, sumSq = 0;
                for (uint32_t p = 0; p < kPixels; ++p) {
                    const std::vector<float> values = fillPixel(s.get(), p % 32, p / 32, 0);
                    double estimate = 0;
                    for (uint32_t i = 0; i < n; ++i) estimate += integrand(arity, values.data() + size_t(i) * arity);
                    estimate /= n;
                    sum += estimate;
                    sumSq += estimate * estimate;
                }
                const double mean = sum / kPixels;
                const double variance = std::max(0.0, (sumSq - kPixels * mean * mean) / (kPixels - 1));
                const double error = mean - exactValue(arity);
                const double standardError = std::sqrt(variance / kPixels);
                // A zero spread would make any error infinitely significant; no pattern reaches it at these N.
                BOOST_REQUIRE_MESSAGE(standardError > 0, patternName(pattern) << " arity " << arity << " N=" << n
                                                                              << ": all 512 estimates identical");
                const double t = error / standardError;
                const double pValue = stipple::statistics::studentTTwoSidedP(t, kPixels - 1);
                BOOST_CHECK_MESSAGE(pValue > alpha, patternName(pattern)
                                                        << " arity " << arity << " N=" << n << ": mean " << mean
                                                        << " vs exact " << exactValue(arity) << ", t = " << t
                                                        << ", p = " << pValue << " <= " << alpha);
            }
        }
    }
}
