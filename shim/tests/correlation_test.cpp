// correlation_test.cpp — no correlation between dimensions, nor between neighbouring pixels.
//
// For each pattern x N (16, 256) x pair, the pairs (value of sample i in A, value of sample i in B) over all
// samples of many pixels are binned on an 8x8 joint grid; Pearson chi-square against the uniform joint,
// family-wise alpha = 0.01 Sidak-corrected over the 16 tests. Pairs: (dimension 0, dimension 1) of one pixel,
// and (dimension 0 of pixel x, dimension 0 of pixel x+1). Within a pixel, stratified and Poisson marginals are
// more even than multinomial, which only lowers the statistic: the test stays valid (conservative) for them.
// The Pearson correlation coefficient is also bounded: |r| < 4 / sqrt(pairs) (4 standard errors).
#define BOOST_TEST_MODULE correlation
#include <stipple/testing/statistics.h>
#include "sampler_fixture.h"

#include <cmath>

using namespace stipple::test;
using namespace stipple::testing;

BOOST_AUTO_TEST_CASE(dimensions_and_pixels_are_uncorrelated) {
    const double alpha = sidak(0.01, kPatternCount * 2 * 2);
    for (uint32_t pattern : kAllPatterns) {
        for (uint32_t n : {16u, 256u}) {
            const uint32_t pixels = 51200 / n; // 51200 pairs: 800 per cell
            auto s = makeSampler(pattern, n, 0xc0ffee + n, {{1, 1}, {1, 1}});
            for (int pair = 0; pair < 2; ++pair) {
                std::vector<double> observed(64, 0.0), expected(64, 51200.0 / 64);
                double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
                for (uint32_t p = 0; p < pixels; ++p) {
                    const std::vector<float> a = fillPixel(s.get(), 2 * p, 1, 0);
                    const std::vector<float> b =
                        pair == 0 ? fillPixel(s.get(), 2 * p, 1, 1) : fillPixel(s.get(), 2 * p + 1, 1, 0);
                    for (uint32_t i = 0; i < n; ++i) {
                        observed[uint32_t(a[i] * 8) * 8 + uint32_t(b[i] * 8)] += 1;
                        sa += a[i], sb += b[i], saa += double(a[i]) * a[i], sbb += double(b[i]) * b[i],
                            sab += double(a[i]) * b[i];
                    }
                }
                const double m = 51200.0;
                const double r =
                    (sab / m - sa / m * sb / m) / std::sqrt((saa / m - sa / m * sa / m) * (sbb / m - sb / m * sb / m));
                const ChiSquareResult chi = chiSquareTest(observed, expected);
                const char* what = pair == 0 ? "dimension 0 vs 1" : "pixel x vs x+1";
                BOOST_CHECK_MESSAGE(chi.pValue > alpha, patternName(pattern)
                                                            << " N=" << n << " " << what << ": chi2 = " << chi.statistic
                                                            << ", p = " << chi.pValue);
                BOOST_CHECK_MESSAGE(std::abs(r) < 4.0 / std::sqrt(m),
                                    patternName(pattern) << " N=" << n << " " << what << ": Pearson r = " << r);
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
