// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// correlation_test.cpp — no correlation between dimensions, nor between neighbouring pixels.
//
// For each pattern x N (16, 256) x pair of streams A, B: pairs (A_i, B_i) of one sample index i. Pairs: (dimension
// 0, dimension 1) of one pixel, and (dimension 0 of pixel x, dimension 0 of pixel x+1).
//  - Joint uniformity: one pair per pixel (at a sample index hashed from the pixel), 51200 pixels, binned on an 8x8
//    joint grid; Pearson chi-square against the uniform joint. Pixels are independent randomisations, so the counts
//    are exactly multinomial. (All pairs of one pixel are not: progressive orders stratify every aligned block of
//    2^j samples in each dimension, so inside a block of 8 samples the 8 coarse bins of A meet those of B as a
//    permutation -- a Latin-hypercube pairing, random across pixels, which pooled counts would mistake for
//    dependence.)
//  - Within a pixel: the Pearson correlation r_p of all N pairs of pixel p has mean 0 across pixels; a two-sided
//    t-test on the 200+ values r_p.
// Family-wise alpha = 0.01, Sidak-corrected over all checks.
#define BOOST_TEST_MODULE correlation
#include <stipple/testing/statistics.h>
#include "sampler_fixture.h"

#include <cmath>

using namespace stipple::test;
using namespace stipple::testing;

namespace {
float valueAt(stipple_sampler s, uint32_t x, uint32_t y, uint32_t i, uint32_t d) {
    float v = -1.0f;
    BOOST_REQUIRE_EQUAL(stipple_sampler_sample(s, x, y, i, d, &v, 1), STIPPLE_OK);
    return v;
}

double pearson(const std::vector<float>& a, const std::vector<float>& b) {
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    const double m = double(a.size());
    for (size_t i = 0; i < a.size(); ++i)
        sa += a[i], sb += b[i], saa += double(a[i]) * a[i], sbb += double(b[i]) * b[i], sab += double(a[i]) * b[i];
    return (sab / m - sa / m * sb / m) / std::sqrt((saa / m - sa / m * sa / m) * (sbb / m - sb / m * sb / m));
}
} // namespace

BOOST_AUTO_TEST_CASE(dimensions_and_pixels_are_uncorrelated) {
    const double alpha = sidak(0.01, patternCount() * 2 * 2 * 2);
    for (uint32_t pattern : allPatterns()) {
        for (uint32_t n : {16u, 256u}) {
            auto s = makeSampler(pattern, n, 0xc0ffee + n, {{1, 1}, {1, 1}});
            for (int pair = 0; pair < 2; ++pair) {
                const char* what = pair == 0 ? "dimension 0 vs 1" : "pixel x vs x+1";
                // One pair per pixel.
                const uint32_t pixels =
                    pattern == STIPPLE_PATTERN_POISSON_SEED ? 3200 : 51200; // >= 50 expected per cell
                std::vector<double> observed(64, 0.0), expected(64, double(pixels) / 64);
                for (uint32_t p = 0; p < pixels; ++p) {
                    const uint32_t i = uint32_t((uint64_t(p) * 0x9e3779b97f4a7c15ull) >> 40) % n;
                    const float a = valueAt(s.get(), 2 * p, 7, i, 0);
                    const float b = pair == 0 ? valueAt(s.get(), 2 * p, 7, i, 1) : valueAt(s.get(), 2 * p + 1, 7, i, 0);
                    observed[uint32_t(a * 8) * 8 + uint32_t(b * 8)] += 1;
                }
                const ChiSquareResult chi = chiSquareTest(observed, expected);
                BOOST_CHECK_MESSAGE(chi.pValue > alpha, patternName(pattern)
                                                            << " N=" << n << " " << what << ": chi2 = " << chi.statistic
                                                            << ", p = " << chi.pValue);
                // Within pixels: mean of per-pixel correlations is 0.
                const uint32_t count = std::max(200u, 51200 / n);
                double sum = 0, sum2 = 0;
                for (uint32_t p = 0; p < count; ++p) {
                    const std::vector<float> a = fillPixel(s.get(), 2 * p, 1, 0);
                    const std::vector<float> b =
                        pair == 0 ? fillPixel(s.get(), 2 * p, 1, 1) : fillPixel(s.get(), 2 * p + 1, 1, 0);
                    const double r = n > 1 ? pearson(a, b) : 0.0;
                    sum += r, sum2 += r * r;
                }
                const double mean = sum / count, sd = std::sqrt((sum2 - sum * mean) / (count - 1));
                const double t = mean / (sd / std::sqrt(double(count)));
                const double p = stipple::statistics::studentTTwoSidedP(t, count - 1);
                BOOST_CHECK_MESSAGE(p > alpha, patternName(pattern)
                                                   << " N=" << n << " " << what << ": mean per-pixel r = " << mean
                                                   << ", t = " << t);
            }
        }
    }
}

BOOST_AUTO_TEST_CASE(identical_order_would_be_detected) {
    // The test's power, shown on a stream that is correlated by construction: dimension 0 against itself.
    auto s = makeSampler(STIPPLE_PATTERN_STRATIFIED, 16, 1, {{1, 1}});
    std::vector<double> observed(64, 0.0), expected(64, 3200.0 / 64);
    for (uint32_t p = 0; p < 200; ++p) {
        const std::vector<float> a = fillPixel(s.get(), p, 0, 0);
        for (uint32_t i = 0; i < 16; ++i) observed[uint32_t(a[i] * 8) * 8 + uint32_t(a[i] * 8)] += 1;
    }
    BOOST_CHECK_LT(chiSquareTest(observed, expected).pValue, 1e-6);
}
