// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// uniformity_test.cpp — every sample of every pattern is uniformly distributed over [0,1)^arity.
//
// For each pattern x arity (1, 2, 3) x N (1, 7, 16, 97) one sample index (N/2) is read in 3200 pixels and
// binned on a 64-cell grid (64, 8x8, 4x4x4 cells; 50 expected per cell). Pearson chi-square, fixed seeds,
// family-wise alpha = 0.01 Sidak-corrected over the 49 tests (the 49th: the past-the-layout stream).
#define BOOST_TEST_MODULE uniformity
#include <stipple/testing/statistics.h>
#include "sampler_fixture.h"

using namespace stipple::test;
using namespace stipple::testing;

const int kTests = patternCount() * 3 * 4 + 1;

BOOST_AUTO_TEST_CASE(each_sample_is_uniform) {
    const uint32_t counts[] = {1, 7, 16, 97};
    const uint32_t binsPerAxis[] = {0, 64, 8, 4};
    constexpr uint32_t kPixels = 3200;
    const double alpha = sidak(0.01, kTests);
    for (uint32_t pattern : allPatterns()) {
        for (uint32_t arity = 1; arity <= 3; ++arity) {
            for (uint32_t n : counts) {
                auto s = makeSampler(pattern, n, 0x5eed0000 + 97 * arity + n, {{arity, 1}});
                const uint32_t bins = binsPerAxis[arity];
                const uint32_t cells = arity == 1 ? bins : arity == 2 ? bins * bins : bins * bins * bins;
                std::vector<double> observed(cells, 0.0), expected(cells, double(kPixels) / cells);
                const uint32_t index = n / 2;
                std::vector<float> sample(arity);
                for (uint32_t p = 0; p < kPixels; ++p) {
                    BOOST_REQUIRE_EQUAL(stipple_sampler_sample(s.get(), p % 80, p / 80, index, 0, sample.data(), arity),
                                        STIPPLE_OK);
                    uint32_t cell = 0;
                    for (uint32_t c = arity; c-- > 0;) cell = cell * bins + uint32_t(sample[c] * bins);
                    observed[cell] += 1;
                }
                const ChiSquareResult r = chiSquareTest(observed, expected);
                BOOST_CHECK_MESSAGE(r.pValue > alpha, patternName(pattern) << " arity " << arity << " N=" << n
                                                                           << ": chi2 = " << r.statistic << " (dof "
                                                                           << r.degreesOfFreedom
                                                                           << "), p = " << r.pValue << " <= " << alpha);
            }
        }
    }
}

BOOST_AUTO_TEST_CASE(past_the_layout_stream_is_uniform) {
    // Value 5 of stream 3, sample 2, over 6400 pixels, pairs of consecutive values binned 8x8.
    auto s = makeSampler(STIPPLE_PATTERN_STRATIFIED, 4, 0xabcdef, {{1, 1}});
    std::vector<double> observed(64, 0.0), expected(64, 6400.0 / 64);
    float values[7];
    for (uint32_t p = 0; p < 6400; ++p) {
        BOOST_REQUIRE_EQUAL(stipple_sampler_sample_independent(s.get(), p % 80, p / 80, 2, 3, values, 7), STIPPLE_OK);
        observed[uint32_t(values[5] * 8) * 8 + uint32_t(values[6] * 8)] += 1;
    }
    const ChiSquareResult r = chiSquareTest(observed, expected);
    BOOST_CHECK_MESSAGE(r.pValue > sidak(0.01, kTests), "chi2 = " << r.statistic << ", p = " << r.pValue);
}
