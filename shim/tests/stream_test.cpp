// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// stream_test.cpp — streams (no declared layout) and sample indices past N.
//
// Statistical checks use fixed seeds and alpha = 0.01, Sidak-corrected over the checks of each test case.
#define BOOST_TEST_MODULE stream
#include <stipple/testing/statistics.h>
#include "sampler_fixture.h"

#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <thread>
#include <vector>

using namespace stipple::test;
using namespace stipple::testing;

namespace {

// poisson-seed generates a whole set per value (its deliberate cost): it is in the equality test below only.
constexpr uint32_t kStreamPatterns[] = {STIPPLE_PATTERN_INDEPENDENT, STIPPLE_PATTERN_STRATIFIED,
                                        STIPPLE_PATTERN_POISSON, STIPPLE_PATTERN_SOBOL, STIPPLE_PATTERN_PMJ02,
                                        STIPPLE_PATTERN_LATTICE, STIPPLE_PATTERN_HALTON};
constexpr int kStreamPatternCount = int(sizeof kStreamPatterns / sizeof kStreamPatterns[0]);

SamplerPtr makeFlaggedStreams(uint32_t pattern, uint32_t n, uint64_t seed, uint32_t flags,
                              const std::vector<DimensionSpec>& dims) {
    return makeSampler(pattern, n, seed, dims, flags);
}

std::array<float, 3> stream(stipple_sampler s, uint32_t x, uint32_t y, uint32_t i, uint32_t d, uint32_t arity) {
    std::array<float, 3> v{-1, -1, -1};
    BOOST_REQUIRE_EQUAL(stipple_sampler_stream(s, x, y, i, d, arity, v.data(), 3), STIPPLE_OK);
    return v;
}

// One stream of one pixel: sample indices [first, first + count), count * arity floats.
std::vector<float> streamFill(stipple_sampler s, uint32_t x, uint32_t y, uint32_t first, uint32_t count, uint32_t d,
                              uint32_t arity) {
    std::vector<float> v(size_t(count) * arity, -1.0f);
    BOOST_REQUIRE_EQUAL(stipple_sampler_stream_fill(s, x, y, first, count, d, arity, v.data(), v.size()), STIPPLE_OK);
    return v;
}

// The 2^j-cell grid a stratified prefix covers: first j bits dealt x, y, z, x, ... (see pattern_stratified.cpp).
uint32_t coarseCell(const float* v, uint32_t arity, uint32_t j) {
    uint32_t bits[3] = {0, 0, 0};
    for (uint32_t b = 0; b < j; ++b) ++bits[b % arity];
    uint32_t cell = 0;
    for (uint32_t c = 0; c < arity; ++c) cell = (cell << bits[c]) | uint32_t(v[c] * float(1u << bits[c]));
    return cell;
}

double twoSidedTP(double t, double dof) {
    return 2 * boost::math::cdf(boost::math::complement(boost::math::students_t(dof), std::abs(t)));
}

} // namespace

BOOST_AUTO_TEST_CASE(streams_are_deterministic_across_threads_and_call_orders) {
    for (uint32_t pattern : kStreamPatterns) {
        auto s = makeSampler(pattern, 16, 99, {});
        // Reference: one thread, natural order. Keys: pixel (4 x 4), sample (0..47: three blocks), dimension 0..9.
        auto index = [](uint32_t p, uint32_t i, uint32_t d) { return (size_t(p) * 48 + i) * 10 + d; };
        const size_t values = 16 * 48 * 10;
        std::vector<std::array<float, 3>> reference(values), threaded(values);
        for (uint32_t p = 0; p < 16; ++p)
            for (uint32_t i = 0; i < 48; ++i)
                for (uint32_t d = 0; d < 10; ++d)
                    reference[index(p, i, d)] = stream(s.get(), p % 4, p / 4, i, d, 1 + d % 3);
        // Four threads, each walking its share backwards, dimensions in reverse.
        std::vector<std::thread> workers;
        for (uint32_t t = 0; t < 4; ++t)
            workers.emplace_back([&, t] {
                for (uint32_t p = 16; p-- > 0;)
                    if (p % 4 == t)
                        for (uint32_t i = 48; i-- > 0;)
                            for (uint32_t d = 10; d-- > 0;) {
                                std::array<float, 3> v{-1, -1, -1};
                                if (stipple_sampler_stream(s.get(), p % 4, p / 4, i, d, 1 + d % 3, v.data(), 3) ==
                                    STIPPLE_OK)
                                    threaded[index(p, i, d)] = v;
                            }
            });
        for (auto& w : workers) w.join();
        BOOST_CHECK_MESSAGE(std::memcmp(reference.data(), threaded.data(), values * sizeof(reference[0])) == 0,
                            patternName(pattern) << ": threaded, reversed calls differ");
        // The batch call equals the single calls, across block boundaries (indices 5..40 span blocks 0, 1, 2).
        for (uint32_t arity = 1; arity <= 3; ++arity) {
            const std::vector<float> batch = streamFill(s.get(), 3, 2, 5, 36, 4, arity);
            for (uint32_t i = 0; i < 36; ++i) {
                const auto one = stream(s.get(), 3, 2, 5 + i, 4, arity);
                BOOST_REQUIRE(std::memcmp(one.data(), &batch[size_t(i) * arity], arity * sizeof(float)) == 0);
            }
        }
    }
}

BOOST_AUTO_TEST_CASE(values_lie_in_unit_interval_far_past_n_and_near_2_32) {
    for (uint32_t pattern : kStreamPatterns)
        for (uint32_t n : {1u, 7u, 16u, 100u}) {
            auto s = makeSampler(pattern, n, 5, {});
            for (uint32_t i : {0u, n - 1, n, 10 * n + 3, 0x7fffffffu, 0xfffffff0u, 0xfffffffeu, 0xffffffffu})
                for (uint32_t d : {0u, 1u, 1000u, 0xffffffffu})
                    for (uint32_t arity = 1; arity <= 3; ++arity) {
                        const auto v = stream(s.get(), 1, 2, i, d, arity);
                        for (uint32_t c = 0; c < arity; ++c) BOOST_REQUIRE(v[c] >= 0.0f && v[c] < 1.0f);
                    }
        }
}

BOOST_AUTO_TEST_CASE(every_block_is_a_full_stratified_set_even_near_2_32) {
    auto s = makeSampler(STIPPLE_PATTERN_STRATIFIED, 64, 17, {});
    // The last full block below 2^32 starts at 2^32 - 64; block 0; a block far past N.
    for (uint32_t first : {0u, 64u * 1000u, 0xffffffc0u})
        for (uint32_t arity = 1; arity <= 3; ++arity) {
            const std::vector<float> block = streamFill(s.get(), 9, 9, first, 64, 3, arity);
            std::set<uint32_t> cells;
            for (uint32_t i = 0; i < 64; ++i) cells.insert(coarseCell(&block[size_t(i) * arity], arity, 6));
            BOOST_CHECK_MESSAGE(cells.size() == 64,
                                "arity " << arity << " block at " << first << ": " << cells.size() << " of 64 strata");
            // Progressive: each prefix of 2^j samples covers the 2^j coarse cells once.
            for (uint32_t j = 1; j < 6; ++j) {
                std::set<uint32_t> coarse;
                for (uint32_t i = 0; i < (1u << j); ++i) coarse.insert(coarseCell(&block[size_t(i) * arity], arity, j));
                BOOST_CHECK_EQUAL(coarse.size(), size_t(1) << j);
            }
        }
}

BOOST_AUTO_TEST_CASE(one_index_with_two_arities_gives_two_independent_full_sets) {
    auto s = makeSampler(STIPPLE_PATTERN_STRATIFIED, 16, 23, {});
    const std::vector<float> one = streamFill(s.get(), 4, 4, 0, 16, 7, 1);
    const std::vector<float> two = streamFill(s.get(), 4, 4, 0, 16, 7, 2);
    std::set<uint32_t> cells1, cells2;
    size_t sameFirstAxis = 0;
    for (uint32_t i = 0; i < 16; ++i) {
        cells1.insert(uint32_t(one[i] * 16));
        cells2.insert(coarseCell(&two[2 * i], 2, 4));
        sameFirstAxis += one[i] == two[2 * i];
    }
    BOOST_CHECK_EQUAL(cells1.size(), 16u);
    BOOST_CHECK_EQUAL(cells2.size(), 16u);
    BOOST_CHECK_EQUAL(sameFirstAxis, 0u); // not the first axis of the 2D set
}

BOOST_AUTO_TEST_CASE(stream_values_are_uniform) {
    // One value per pixel (sample index hashed from the pixel, up to 8 N): chi-square on 64 cells.
    const double alpha = sidak(0.01, kStreamPatternCount * 3 * 2);
    for (uint32_t pattern : kStreamPatterns)
        for (uint32_t n : {16u, 256u})
            for (uint32_t arity = 1; arity <= 3; ++arity) {
                auto s = makeSampler(pattern, n, 31 + n, {});
                const uint32_t pixels = 12800;
                std::vector<double> observed(64, 0.0), expected(64, pixels / 64.0);
                for (uint32_t p = 0; p < pixels; ++p) {
                    const uint32_t i = uint32_t((uint64_t(p) * 0x9e3779b97f4a7c15ull) >> 40) % (8 * n);
                    const auto v = stream(s.get(), p % 128, p / 128, i, 2, arity);
                    const uint32_t cell = arity == 1 ? uint32_t(v[0] * 64)
                                          : arity == 2
                                              ? uint32_t(v[0] * 8) * 8 + uint32_t(v[1] * 8)
                                              : (uint32_t(v[0] * 4) * 4 + uint32_t(v[1] * 4)) * 4 + uint32_t(v[2] * 4);
                    observed[cell] += 1;
                }
                const ChiSquareResult chi = chiSquareTest(observed, expected);
                BOOST_CHECK_MESSAGE(chi.pValue > alpha, patternName(pattern)
                                                            << " N=" << n << " arity " << arity
                                                            << ": chi2 = " << chi.statistic << ", p = " << chi.pValue);
            }
}

BOOST_AUTO_TEST_CASE(consecutive_dimension_indices_are_uncorrelated) {
    // (index d, index d + 1) of one sample, one pair per pixel (independent randomisations), 8 x 8 chi-square.
    const double alpha = sidak(0.01, kStreamPatternCount * 2);
    for (uint32_t pattern : kStreamPatterns)
        for (uint32_t n : {16u, 256u}) {
            auto s = makeSampler(pattern, n, 41 + n, {});
            const uint32_t pixels = 25600;
            std::vector<double> observed(64, 0.0), expected(64, pixels / 64.0);
            for (uint32_t p = 0; p < pixels; ++p) {
                const uint32_t i = uint32_t((uint64_t(p) * 0x9e3779b97f4a7c15ull) >> 40) % (2 * n);
                const uint32_t d = p % 5;
                const float a = stream(s.get(), p % 160, p / 160, i, d, 1)[0];
                const float b = stream(s.get(), p % 160, p / 160, i, d + 1, 1)[0];
                observed[uint32_t(a * 8) * 8 + uint32_t(b * 8)] += 1;
            }
            const ChiSquareResult chi = chiSquareTest(observed, expected);
            BOOST_CHECK_MESSAGE(chi.pValue > alpha, patternName(pattern) << " N=" << n << ": chi2 = " << chi.statistic
                                                                         << ", p = " << chi.pValue);
        }
}

BOOST_AUTO_TEST_CASE(streamed_estimates_of_edged_integrals_are_unbiased) {
    // Per pixel, the N-sample estimate from block 3 (indices 3N..4N-1); t-test of the mean over 400 pixels against
    // the exact value. Integrands: 1D step at 0.3 (0.7), 2D quarter disk (pi/4), 3D sphere octant (pi/6).
    const double alpha = sidak(0.01, kStreamPatternCount * 2 * 3);
    const double pi = 3.14159265358979323846;
    for (uint32_t pattern : kStreamPatterns)
        for (uint32_t n : {16u, 64u})
            for (uint32_t arity = 1; arity <= 3; ++arity) {
                auto s = makeSampler(pattern, n, 53 + n, {});
                const double exact = arity == 1 ? 0.7 : arity == 2 ? pi / 4 : pi / 6;
                double sum = 0, sum2 = 0;
                const uint32_t pixels = 400;
                for (uint32_t p = 0; p < pixels; ++p) {
                    const std::vector<float> v = streamFill(s.get(), p, 3, 3 * n, n, 11, arity);
                    double hits = 0;
                    for (uint32_t i = 0; i < n; ++i) {
                        const float* x = &v[size_t(i) * arity];
                        double r2 = 0;
                        for (uint32_t c = 0; c < arity; ++c) r2 += double(x[c]) * x[c];
                        hits += arity == 1 ? (x[0] >= 0.3f) : (r2 < 1.0);
                    }
                    const double estimate = hits / n;
                    sum += estimate, sum2 += estimate * estimate;
                }
                const double mean = sum / pixels, sd = std::sqrt((sum2 - sum * mean) / (pixels - 1));
                const double t = (mean - exact) / (sd / std::sqrt(double(pixels)));
                BOOST_CHECK_MESSAGE(twoSidedTP(t, pixels - 1) > alpha,
                                    patternName(pattern) << " N=" << n << " arity " << arity << ": mean " << mean
                                                         << " exact " << exact << " t = " << t);
            }
}

BOOST_AUTO_TEST_CASE(layout_samples_past_n_read_later_blocks) {
    // A declared layout: sample index i >= N reads block i / N, itself a full stratified set; block 0 equals fill.
    auto s = makeSampler(STIPPLE_PATTERN_STRATIFIED, 16, 61, {{2, 1}});
    const std::vector<float> fill = fillPixel(s.get(), 2, 2, 0);
    std::set<uint32_t> cells;
    for (uint32_t i = 0; i < 16; ++i) {
        float v[2];
        BOOST_REQUIRE_EQUAL(stipple_sampler_sample(s.get(), 2, 2, i, 0, v, 2), STIPPLE_OK);
        BOOST_CHECK(v[0] == fill[2 * i] && v[1] == fill[2 * i + 1]);
        BOOST_REQUIRE_EQUAL(stipple_sampler_sample(s.get(), 2, 2, 16 * 5 + i, 0, v, 2), STIPPLE_OK);
        cells.insert(coarseCell(v, 2, 4));
    }
    BOOST_CHECK_EQUAL(cells.size(), 16u);
}

BOOST_AUTO_TEST_CASE(random_access_equals_the_batch_calls_for_every_pattern_and_flag) {
    // fill_pixel vs sample (block 0), stream vs stream_fill across blocks, and determinism of layout samples past N,
    // for all patterns, with and without the blue-noise flag, at pixels inside and across blue-noise tiles.
    const std::vector<DimensionSpec> layout = {{1, 1}, {2, 3}, {3, 1}};
    for (uint32_t pattern : allPatterns())
        for (uint32_t flags : {0u, uint32_t(STIPPLE_SAMPLER_FLAG_BLUE_NOISE)})
            for (uint32_t n : {1u, 13u, 16u}) {
                if (flags != 0 && !(acceptedFlags(pattern) & STIPPLE_SAMPLER_FLAG_BLUE_NOISE))
                    continue; // refused at creation (blue_noise_test)
                auto s = makeFlaggedStreams(pattern, n, 0x5a11 + n, flags, layout);
                for (uint32_t px : {0u, 63u, 64u, 70000u}) {
                    for (uint32_t d = 0; d < layout.size(); ++d) {
                        const uint32_t k = layout[d].count, arity = layout[d].arity;
                        const std::vector<float> pixel = fillPixel(s.get(), px, 5, d);
                        std::vector<float> one(size_t(k) * arity), again(one.size());
                        for (uint32_t i = 0; i < 3 * n; ++i) {
                            BOOST_REQUIRE_EQUAL(stipple_sampler_sample(s.get(), px, 5, i, d, one.data(), one.size()),
                                                STIPPLE_OK);
                            for (float v : one) BOOST_REQUIRE(v >= 0.0f && v < 1.0f);
                            if (i < n)
                                BOOST_REQUIRE_MESSAGE(
                                    std::memcmp(one.data(), &pixel[size_t(i) * k * arity], one.size() * 4) == 0,
                                    patternName(pattern) << " flags " << flags << " N=" << n << " d " << d << " sample "
                                                         << i << ": sample != fill_pixel");
                            BOOST_REQUIRE_EQUAL(
                                stipple_sampler_sample(s.get(), px, 5, i, d, again.data(), again.size()), STIPPLE_OK);
                            BOOST_REQUIRE(one == again);
                        }
                    }
                    for (uint32_t arity = 1; arity <= 3; ++arity) {
                        const std::vector<float> batch = streamFill(s.get(), px, 5, 1, 3 * n, 6, arity);
                        for (uint32_t i = 0; i < 3 * n; ++i) {
                            const auto v = stream(s.get(), px, 5, 1 + i, 6, arity);
                            BOOST_REQUIRE_MESSAGE(std::memcmp(v.data(), &batch[size_t(i) * arity], arity * 4) == 0,
                                                  patternName(pattern)
                                                      << " flags " << flags << " N=" << n << " arity " << arity
                                                      << " sample " << 1 + i << ": stream != stream_fill");
                            for (uint32_t c = 0; c < arity; ++c) BOOST_REQUIRE(v[c] >= 0.0f && v[c] < 1.0f);
                        }
                    }
                }
            }
}

BOOST_AUTO_TEST_CASE(blue_noise_streams_without_a_layout_keep_their_sets) {
    // dimension_count 0 with the flag: a stratified stream block is still one point per stratum, in every block
    // past N as well.
    auto s = makeFlaggedStreams(STIPPLE_PATTERN_STRATIFIED, 64, 77, STIPPLE_SAMPLER_FLAG_BLUE_NOISE, {});
    for (uint32_t first : {0u, 64u * 3u})
        for (uint32_t px : {0u, 1u, 65u}) {
            const std::vector<float> block = streamFill(s.get(), px, 9, first, 64, 2, 1);
            std::set<uint32_t> cells;
            for (float v : block) cells.insert(uint32_t(std::floor(double(v) * 64)));
            BOOST_CHECK_MESSAGE(cells.size() == 64, "stratified block at " << first << " pixel " << px << ": "
                                                                           << cells.size() << " of 64 strata");
        }
}
