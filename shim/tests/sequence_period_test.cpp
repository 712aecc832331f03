// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// sequence_period_test.cpp — sobol, lattice and halton past their period (stipple.h, "Any sample index").
//
// A set of M = k*N points of these patterns is served from a sequence with a 32-bit index, P sample indices long
// (sobol, lattice: P = N * 2^(32 - ceil(log2 M)); halton: P = N * floor(2^32 / M)). Past P the library serves a
// freshly randomised sequence: sample i + P is never sample i (an index that wrapped gave it exactly: i and
// i + 3 * 2^30 at N = 3, i and i + 2^22 for arrays of k = 1024 at N = 4096). Through the C ABI only, so the test
// runs against any build of the library.
#define BOOST_TEST_MODULE sequence_period
#include "sampler_fixture.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <set>

using namespace stipple::test;

namespace {

constexpr uint32_t kSequencePatterns[] = {STIPPLE_PATTERN_SOBOL, STIPPLE_PATTERN_LATTICE, STIPPLE_PATTERN_HALTON};

// The period in sample indices of sets of M = k * N points (stipple.h); 2^32 or more: never reached.
uint64_t period(uint32_t pattern, uint32_t n, uint32_t k) {
    const uint64_t m = uint64_t(k) * n;
    if (pattern == STIPPLE_PATTERN_HALTON) return n * ((uint64_t(1) << 32) / m);
    return n * (uint64_t(1) << (32 - std::bit_width(m - 1)));
}

std::vector<float> arrayValues(stipple_sampler s, uint32_t x, uint32_t y, uint32_t first, uint32_t count,
                               uint32_t index, uint32_t arity, uint32_t k) {
    std::vector<float> out(size_t(count) * k * arity);
    BOOST_REQUIRE_MESSAGE(stipple_sampler_array_fill(s, x, y, first, count, index, arity, k, out.data(), out.size()) ==
                              STIPPLE_OK,
                          stipple_last_error_message());
    return out;
}

std::vector<float> streamValues(stipple_sampler s, uint32_t x, uint32_t y, uint32_t first, uint32_t count, uint32_t d,
                                uint32_t arity) {
    std::vector<float> out(size_t(count) * arity);
    BOOST_REQUIRE_MESSAGE(stipple_sampler_stream_fill(s, x, y, first, count, d, arity, out.data(), out.size()) ==
                              STIPPLE_OK,
                          stipple_last_error_message());
    return out;
}

bool samePoint(const float* a, const float* b, uint32_t floats) {
    return std::memcmp(a, b, floats * sizeof(float)) == 0;
}

} // namespace

BOOST_AUTO_TEST_CASE(the_documented_periods) {
    BOOST_CHECK_EQUAL(period(STIPPLE_PATTERN_SOBOL, 3, 1), 3ull << 30);
    BOOST_CHECK_EQUAL(period(STIPPLE_PATTERN_LATTICE, 4096, 1024), 1ull << 22);
    BOOST_CHECK_EQUAL(period(STIPPLE_PATTERN_HALTON, 4096, 1024), 1ull << 22);
    BOOST_CHECK_EQUAL(period(STIPPLE_PATTERN_HALTON, 3, 1), (1ull << 32) - 1);
    BOOST_CHECK_EQUAL(period(STIPPLE_PATTERN_SOBOL, 4, 1), 1ull << 32); // never reached by a uint32 index
}

// Sample i + P is not a repeat of any sample of i's block (for sets of up to 2^16 points; of sample i for larger
// ones), for streams and arrays, N and k with and without padding, in the first block and the last one with a partner.
BOOST_AUTO_TEST_CASE(samples_past_the_period_are_not_repeats) {
    struct Case {
        uint32_t n, k;
    };
    const Case cases[] = {{3, 1}, {5, 7}, {3, 5}, {96, 3}, {1000, 1}, {4096, 1024}, {1000, 1000}};
    for (uint32_t pattern : kSequencePatterns)
        for (const Case& c : cases) {
            const uint64_t p = period(pattern, c.n, c.k);
            BOOST_REQUIRE_LT(p, 1ull << 32);
            const bool wholeBlock = uint64_t(c.n) * c.k <= (1u << 16);
            auto s = makeSampler(pattern, c.n, 0x5e9u + c.n, {});
            const auto values = [&](uint32_t x, uint32_t first, uint32_t count, uint32_t arity) {
                return c.k == 1 ? streamValues(s.get(), x, 1, first, count, 2, arity)
                                : arrayValues(s.get(), x, 1, first, count, 2, arity, c.k);
            };
            for (uint32_t arity = 1; arity <= 3; ++arity) {
                const uint32_t floats = c.k * arity;
                const uint32_t lastBlock = static_cast<uint32_t>(((1ull << 32) - 1 - p) / c.n);
                uint32_t repeats = 0, checked = 0;
                for (uint32_t block : {0u, lastBlock})
                    for (uint32_t x = 0; x < (wholeBlock ? 4u : 1u); ++x) {
                        const uint32_t first = block * c.n;
                        const std::vector<float> before =
                            wholeBlock ? values(x, first, c.n, arity) : std::vector<float>{};
                        for (uint32_t i = 0; i < c.n && first + i + p < (1ull << 32); i += 1 + c.n / 8) {
                            const std::vector<float> after = values(x, static_cast<uint32_t>(first + i + p), 1, arity);
                            if (wholeBlock) {
                                for (uint32_t j = 0; j < c.n; ++j)
                                    repeats += samePoint(after.data(), &before[size_t(j) * floats], floats);
                            } else {
                                repeats += samePoint(after.data(), values(x, first + i, 1, arity).data(), floats);
                            }
                            ++checked;
                        }
                    }
                BOOST_CHECK_GT(checked, 0u);
                BOOST_CHECK_MESSAGE(repeats == 0, patternName(pattern)
                                                      << " N=" << c.n << " k=" << c.k << " arity " << arity << ": "
                                                      << repeats << " of " << checked
                                                      << " samples past the period repeat one before it");
            }
        }
}

// The same for a declared dimension (sample and fill_pixel's path): sample i + P at N = 3 is not sample i.
BOOST_AUTO_TEST_CASE(declared_dimensions_past_the_period_are_not_repeats) {
    for (uint32_t pattern : kSequencePatterns) {
        auto s = makeSampler(pattern, 3, 11, {{2, 1}, {1, 4}});
        for (uint32_t d = 0; d < 2; ++d) {
            const uint32_t k = d == 0 ? 1 : 4, floats = d == 0 ? 2 : 4;
            const uint64_t p = period(pattern, 3, k);
            uint32_t repeats = 0;
            for (uint32_t i = 0; i < 3 && i + p < (1ull << 32); ++i) {
                float a[4], b[4];
                BOOST_REQUIRE(stipple_sampler_sample(s.get(), 7, 7, i, d, a, floats) == STIPPLE_OK);
                BOOST_REQUIRE(stipple_sampler_sample(s.get(), 7, 7, uint32_t(i + p), d, b, floats) == STIPPLE_OK);
                repeats += samePoint(a, b, floats);
            }
            BOOST_CHECK_MESSAGE(repeats == 0, patternName(pattern) << " dimension " << d << ": " << repeats
                                                                   << " samples repeat at i + P");
        }
    }
}

// Past the period the sequence is a fresh randomisation: over 4000 pixels, the values of sample i and sample i + P
// are uncorrelated. |r| < 0.08 is 5 standard deviations (1/sqrt(4000) = 0.016) of the correlation of independent
// pairs: with these fixed seeds a false failure has probability below 1e-6.
BOOST_AUTO_TEST_CASE(the_next_period_is_uncorrelated_with_the_first) {
    constexpr uint32_t kPixels = 4000;
    for (uint32_t pattern : kSequencePatterns)
        for (uint32_t n : {3u, 1000u}) {
            const uint64_t p = period(pattern, n, 1);
            auto s = makeSampler(pattern, n, 77, {});
            const uint32_t i = static_cast<uint32_t>(((1ull << 32) - 1 - p) / 2); // mid-range: any index with a partner
            double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
            for (uint32_t x = 0; x < kPixels; ++x) {
                float a = 0, b = 0;
                BOOST_REQUIRE(stipple_sampler_stream(s.get(), x, 3, i, 0, 1, &a, 1) == STIPPLE_OK);
                BOOST_REQUIRE(stipple_sampler_stream(s.get(), x, 3, uint32_t(i + p), 0, 1, &b, 1) == STIPPLE_OK);
                sa += a, sb += b, saa += double(a) * a, sbb += double(b) * b, sab += double(a) * b;
            }
            const double cov = sab / kPixels - (sa / kPixels) * (sb / kPixels);
            const double va = saa / kPixels - (sa / kPixels) * (sa / kPixels);
            const double vb = sbb / kPixels - (sb / kPixels) * (sb / kPixels);
            const double r = cov / std::sqrt(va * vb);
            BOOST_CHECK_MESSAGE(std::abs(r) < 0.08, patternName(pattern) << " N=" << n << ": correlation " << r
                                                                         << " between samples i and i + P");
        }
}

// The first block past the period is a full set of the pattern: arrays of k = 1024 at N = 4096 (M = 2^22 points,
// P = 2^22) put one value in each interval of 2^-22 in block 0 of both generations, and the two sets differ.
BOOST_AUTO_TEST_CASE(the_block_past_the_period_is_a_full_set) {
    constexpr uint32_t n = 4096, k = 1024, m = n * k;
    for (uint32_t pattern : kSequencePatterns) {
        const uint64_t p = period(pattern, n, k);
        BOOST_REQUIRE_EQUAL(p, uint64_t(m));
        auto s = makeSampler(pattern, n, 2026, {});
        const std::vector<float> first = arrayValues(s.get(), 5, 6, 0, n, 9, 1, k);
        const std::vector<float> next = arrayValues(s.get(), 5, 6, uint32_t(p), n, 9, 1, k);
        std::vector<bool> seen(m);
        uint32_t cells = 0, same = 0;
        for (uint32_t i = 0; i < m; ++i) {
            const uint32_t cell = static_cast<uint32_t>(double(next[i]) * m);
            cells += !seen[cell];
            seen[cell] = true;
            same += first[i] == next[i];
        }
        BOOST_CHECK_MESSAGE(cells == m, patternName(pattern)
                                            << ": " << cells << " of " << m << " intervals hold a value");
        // Two independent sets share a value at one position with probability about 2^-24 each.
        BOOST_CHECK_MESSAGE(same < 16, patternName(pattern) << ": " << same << " of " << m << " values repeat");
    }
}

// Batch calls across the period boundary equal the per-sample calls (streams and arrays).
BOOST_AUTO_TEST_CASE(batch_calls_across_the_period_equal_per_sample_calls) {
    for (uint32_t pattern : kSequencePatterns)
        for (uint32_t n : {3u, 1000u}) {
            const uint64_t p = period(pattern, n, 1);
            auto s = makeSampler(pattern, n, 31, {});
            const uint32_t first = static_cast<uint32_t>(p - n - 1);
            const uint32_t count = static_cast<uint32_t>(std::min<uint64_t>(2 * n + 2, (1ull << 32) - first));
            for (uint32_t arity = 1; arity <= 3; ++arity) {
                const std::vector<float> run = streamValues(s.get(), 1, 1, first, count, 4, arity);
                uint32_t mismatches = 0;
                for (uint32_t j = 0; j < count; ++j) {
                    float one[3];
                    BOOST_REQUIRE(stipple_sampler_stream(s.get(), 1, 1, first + j, 4, arity, one, 3) == STIPPLE_OK);
                    mismatches += !samePoint(one, &run[size_t(j) * arity], arity);
                }
                BOOST_CHECK_MESSAGE(mismatches == 0, patternName(pattern) << " N=" << n << " arity " << arity << ": "
                                                                          << mismatches << " values differ");
            }
            const uint32_t k = 3;
            const uint64_t pa = period(pattern, n, k);
            const uint32_t firstArray = static_cast<uint32_t>(pa - 2);
            const std::vector<float> run = arrayValues(s.get(), 2, 2, firstArray, 4, 1, 2, k);
            for (uint32_t j = 0; j < 4; ++j) {
                float one[2 * k];
                BOOST_REQUIRE(stipple_sampler_array(s.get(), 2, 2, firstArray + j, 1, 2, k, one, 2 * k) == STIPPLE_OK);
                BOOST_CHECK(samePoint(one, &run[size_t(j) * 2 * k], 2 * k));
            }
        }
}
