// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// ctest-labels: unit;statistical
// sobol_pmj02_test.cpp — what the sobol and pmj02 constructions promise, and the blue-noise flag.
//
// Deterministic properties (exact, no alpha): every prefix of 2^j points of a served 2D set (and of the (x, y)
// projection of a 3D set) has one point in every elementary interval of area 2^-j; 1D prefixes are stratified;
// sobol's blocks past the set continue the sequence (blocks b and b+1 together form a net of 2M); the
// generator's own output is progressive for every prefix. With the blue-noise flag every pixel's set stays valid
// and deterministic (what the flag adds across pixels: blue_noise_test.cpp).
// Statistical (fixed seeds; family-wise alpha = 0.01, Sidak over the 24 tests of blue_noise_samples_are_uniform
// _and_unbiased): with the flag, one sample read in 3200 pixels is uniform (chi-square, 64 cells) and the pixel
// estimates of the quarter disk are unbiased (Student t, 512 pixels), for every pattern and arity 2 and 3. The
// pixels lie in different tiles at varying places in them: inside a tile the values are a lattice over the pixels
// (blue_noise.h), uniform only over the tile's random offsets, so a tile's pixels are not independent draws.
#define BOOST_TEST_MODULE sobol_pmj02
#include <stipple/testing/statistics.h>
#include "sampler_fixture.h"

#include "pmj02_generator.h"
#include "sampler.h"

#include <cmath>
#include <cstring>
#include <numbers>
#include <set>

using namespace stipple::testing;

using namespace stipple::test;
using stipple::detail::FixedPoint2;

namespace {

// Floats of the shim are multiples of 2^-24: exact as 32-bit fractions.
uint32_t toFixed(float v) { return static_cast<uint32_t>(double(v) * 4294967296.0); }

std::vector<FixedPoint2> xyOf(const std::vector<float>& values, uint32_t arity) {
    std::vector<FixedPoint2> points(values.size() / arity);
    for (size_t i = 0; i < points.size(); ++i) points[i] = {toFixed(values[i * arity]), toFixed(values[i * arity + 1])};
    return points;
}

double squaredNorm3(const float* p) { return double(p[0]) * p[0] + double(p[1]) * p[1] + double(p[2]) * p[2]; }

// The largest j with 2^j <= m.
uint32_t floorLog2(uint32_t m) { return 31 - static_cast<uint32_t>(__builtin_clz(m)); }

} // namespace

BOOST_AUTO_TEST_CASE(generator_prefixes_are_elementary_nets) {
    for (uint64_t seed = 0; seed < 8; ++seed) {
        const std::vector<FixedPoint2> points = stipple::detail::generatePmj02(12, seed);
        for (uint32_t k = 0; k <= 12; ++k)
            BOOST_CHECK_MESSAGE(stipple::detail::isElementaryNet(points.data(), k),
                                "pmj02 seed " << seed << " prefix 2^" << k);
    }
    // The checker itself fails on a set that is not a net: two points in one column of 2 x 1.
    const FixedPoint2 bad[2] = {{0x10000000u, 0x10000000u}, {0x20000000u, 0x90000000u}};
    BOOST_CHECK(!stipple::detail::isElementaryNet(bad, 1));
}

BOOST_AUTO_TEST_CASE(served_prefixes_are_elementary_nets) {
    for (uint32_t pattern : {STIPPLE_PATTERN_SOBOL, STIPPLE_PATTERN_PMJ02})
        for (uint32_t arity : {2u, 3u})
            for (uint32_t n : {1u, 2u, 16u, 64u, 97u, 256u, 1000u, 4096u})
                for (uint32_t k : {1u, 3u}) {
                    auto s = makeSampler(pattern, n, 0x5eed + n, {{arity, k}});
                    for (uint32_t pixel = 0; pixel < 3; ++pixel) {
                        const std::vector<FixedPoint2> xy = xyOf(fillPixel(s.get(), pixel, 9, 0), arity);
                        for (uint32_t j = 0; j <= floorLog2(n * k); ++j)
                            BOOST_CHECK_MESSAGE(stipple::detail::isElementaryNet(xy.data(), j),
                                                patternName(pattern)
                                                    << " arity " << arity << " N=" << n << " k=" << k << " pixel "
                                                    << pixel << ": prefix 2^" << j << " not a net");
                    }
                }
}

BOOST_AUTO_TEST_CASE(one_dimensional_prefixes_are_stratified) {
    for (uint32_t pattern : {STIPPLE_PATTERN_SOBOL, STIPPLE_PATTERN_PMJ02}) {
        auto s = makeSampler(pattern, 1024, 3, {{1, 1}, {3, 1}});
        for (uint32_t d = 0; d < 2; ++d) {
            const uint32_t arity = d == 0 ? 1 : 3;
            const std::vector<float> v = fillPixel(s.get(), 4, 4, d);
            for (uint32_t c = 0; c < arity; ++c)
                for (uint32_t j = 0; j <= 10; ++j) {
                    std::set<uint32_t> strata;
                    for (uint32_t i = 0; i < (1u << j); ++i)
                        strata.insert(j == 0 ? 0u : toFixed(v[i * arity + c]) >> (32 - j));
                    BOOST_CHECK_MESSAGE(strata.size() == (1u << j),
                                        patternName(pattern) << " dimension " << d << " axis " << c << ": prefix 2^"
                                                             << j << " fills " << strata.size() << " strata");
                }
        }
    }
}

// pmj02 in 3D: every prefix of 2^k points of a served set, and of the 4N samples an N-sample sampler serves past
// its set, is a (0,k,2)-net in (x, y), stratified in z at 2^-k, and for every r with 2r <= k has one point in every
// box of 2^-r x 2^-r x 2^-(k-2r) (each (x, y) cell of side 2^-r stratified in z at 2^-(k-2r); pmj02_generator.h).
// So the cubes of side 2^-r, and the 2^r x 2^r grids of (x, z) and (y, z), hold equal counts. Exact (no alpha):
// checked on every prefix of 3 pixels and 2 dimensions per N.
BOOST_AUTO_TEST_CASE(pmj02_3d_prefixes_are_stratified) {
    // True if the first `count` points have one point in every box of 2^-r x 2^-r x 2^-depthBits.
    const auto oneInEveryBox = [](const std::vector<float>& v, uint32_t count, uint32_t r, uint32_t depthBits) {
        std::set<uint64_t> boxes;
        for (uint32_t i = 0; i < count; ++i) {
            uint64_t box = 0;
            for (uint32_t c = 0; c < 3; ++c) {
                const uint32_t bits = c == 2 ? depthBits : r;
                box = (box << bits) | (bits == 0 ? 0u : toFixed(v[i * 3 + c]) >> (32 - bits));
            }
            if (!boxes.insert(box).second) return false;
        }
        return boxes.size() == (uint64_t(1) << (2 * r + depthBits));
    };
    for (uint32_t n : {2u, 4u, 8u, 32u, 64u, 512u, 1024u, 4096u, 8192u})
        for (uint32_t pixel = 0; pixel < 3; ++pixel) {
            auto handle = makeSampler(STIPPLE_PATTERN_PMJ02, n, 0x3d + n, {{1, 1}, {3, 1}, {3, 1}});
            const stipple::detail::Sampler& sampler = *stipple::detail::fromHandle(handle.get());
            for (uint32_t d = 1; d <= 2; ++d) {
                std::vector<float> v(size_t(4) * n * 3);
                for (uint32_t i = 0; i < 4 * n; ++i) sampler.sample(pixel, 11, i, d, v.data() + size_t(i) * 3);
                const std::vector<float> set = fillPixel(handle.get(), pixel, 11, d);
                BOOST_REQUIRE(std::memcmp(set.data(), v.data(), set.size() * sizeof(float)) == 0);
                const std::vector<FixedPoint2> xy = xyOf(v, 3);
                for (uint32_t k = 0; (1u << k) <= 4 * n; ++k) {
                    const uint32_t count = 1u << k;
                    BOOST_CHECK_MESSAGE(stipple::detail::isElementaryNet(xy.data(), k),
                                        "N=" << n << " pixel " << pixel << " dim " << d << ": (x, y), prefix 2^" << k);
                    for (uint32_t r = 0; 2 * r <= k; ++r) // r = 0: z alone
                        BOOST_CHECK_MESSAGE(oneInEveryBox(v, count, r, k - 2 * r),
                                            "N=" << n << " pixel " << pixel << " dim " << d << ": boxes of 2^-" << r
                                                 << " x 2^-" << r << " x 2^-" << k - 2 * r << ", prefix 2^" << k);
                }
            }
        }
    // The check fails where it should: z copied from x puts 2 of 8 points in each of 4 boxes of 1/2 x 1/2 x 1/2.
    std::vector<float> diagonal(8 * 3);
    for (uint32_t i = 0; i < 8; ++i)
        diagonal[i * 3] = diagonal[i * 3 + 2] = (float(i) + 0.5f) / 8, diagonal[i * 3 + 1] = float((i * 5) % 8) / 8;
    BOOST_CHECK(!oneInEveryBox(diagonal, 8, 1, 1));
    BOOST_CHECK(oneInEveryBox(diagonal, 8, 0, 3)); // z alone is stratified
}

// pmj02 in 3D is not worse than stratified 3D (statistical: 512 pixels per case, fixed seeds; one-sided Welch
// t-test on the squared errors, family-wise alpha = 0.01, Sidak over the 16 cases) on a smooth non-separable
// integrand and three edges that cut the cube obliquely, at N = 16 and 32 (not cubes: stratified's grids are
// 4 x 2 x 2 and 4 x 4 x 2) and 64 and 512 (one point per cube of side 1/4, 1/8). (A depth matrix that stratified
// z in each (x, y) cell only at the cell's own side had 2.1x stratified's MSE on x + y + z < 1.2 at N = 32.)
// (On the battery, the former z, drawn independently of (x, y), had 2.9x stratified's MSE on its slanted plane at 512.)
BOOST_AUTO_TEST_CASE(pmj02_3d_is_not_worse_than_stratified) {
    struct Integrand {
        const char* name;
        double (*f)(const float*);
        double exact;
    };
    const double erf1 = std::erf(1.0) * std::sqrt(std::numbers::pi) / 2;
    const Integrand integrands[] = {
        {"exp(-|p|^2)", [](const float* p) { return std::exp(-squaredNorm3(p)); }, erf1 * erf1 * erf1},
        {"ball r = 0.75", [](const float* p) { return squaredNorm3(p) < 0.5625 ? 1.0 : 0.0; },
         std::numbers::pi * 0.421875 / 6},
        {"x + y + z < 1.3", [](const float* p) { return double(p[0]) + p[1] + p[2] < 1.3 ? 1.0 : 0.0; },
         (1.3 * 1.3 * 1.3 - 3 * 0.3 * 0.3 * 0.3) / 6},
        {"x + y + z < 1.2", [](const float* p) { return double(p[0]) + p[1] + p[2] < 1.2 ? 1.0 : 0.0; },
         (1.2 * 1.2 * 1.2 - 3 * 0.2 * 0.2 * 0.2) / 6},
    };
    const double alpha = sidak(0.01, 16);
    for (uint32_t n : {16u, 32u, 64u, 512u}) {
        auto pmj = makeSampler(STIPPLE_PATTERN_PMJ02, n, 0x9a3d, {{3, 1}});
        auto strat = makeSampler(STIPPLE_PATTERN_STRATIFIED, n, 0x9a3d, {{3, 1}});
        for (const Integrand& in : integrands) {
            stipple::statistics::MeanEstimate squared[2];
            for (int which = 0; which < 2; ++which) {
                double sum = 0, sumSq = 0;
                for (uint32_t pixel = 0; pixel < 512; ++pixel) {
                    const std::vector<float> v = fillPixel((which == 0 ? pmj : strat).get(), pixel, 3, 0);
                    double estimate = 0;
                    for (uint32_t i = 0; i < n; ++i) estimate += in.f(v.data() + size_t(i) * 3);
                    const double e2 = (estimate / n - in.exact) * (estimate / n - in.exact);
                    sum += e2, sumSq += e2 * e2;
                }
                const double mean = sum / 512;
                squared[which] = {mean, (sumSq / 512 - mean * mean) / 511, 512};
            }
            const double p = stipple::statistics::welchTwoSidedP(squared[0], squared[1]) / 2; // one-sided: pmj02's MSE above stratified's
            BOOST_CHECK_MESSAGE(squared[0].mean <= squared[1].mean || p > alpha,
                                in.name << " N=" << n << ": pmj02 MSE " << squared[0].mean << " vs stratified "
                                        << squared[1].mean << ", one-sided p = " << p);
            BOOST_TEST_MESSAGE(in.name << " N=" << n << ": MSE ratio " << squared[0].mean / squared[1].mean);
        }
    }
}

// pmj02's batch (fill_pixel, stream_fill: the widest kernel the CPU runs, AVX-512 where it can) gives bitwise the
// values of the per-point path, for every arity, sets with tails of every length and blocks past N.
BOOST_AUTO_TEST_CASE(pmj02_batch_equals_the_per_point_path) {
    for (uint32_t n : {1u, 2u, 5u, 16u, 31u, 97u, 1024u}) {
        auto s = makeSampler(STIPPLE_PATTERN_PMJ02, n, 0xba7c + n, {});
        for (uint32_t arity : {1u, 2u, 3u})
            for (uint32_t first : {0u, 3u * n + 1u}) {
                const uint32_t count = 2 * n + 3;
                std::vector<float> batch(size_t(count) * arity), one(arity);
                BOOST_REQUIRE(stipple_sampler_stream_fill(s.get(), 7, 1, first, count, 5, arity, batch.data(),
                                                          batch.size()) == STIPPLE_OK);
                uint32_t mismatches = 0;
                for (uint32_t i = 0; i < count; ++i) {
                    BOOST_REQUIRE(stipple_sampler_stream(s.get(), 7, 1, first + i, 5, arity, one.data(), arity) ==
                                  STIPPLE_OK);
                    mismatches += std::memcmp(one.data(), batch.data() + size_t(i) * arity, arity * sizeof(float)) != 0;
                }
                BOOST_CHECK_MESSAGE(mismatches == 0, "arity " << arity << " N=" << n << " first " << first << ": "
                                                              << mismatches << " of " << count << " points differ");
            }
    }
}

BOOST_AUTO_TEST_CASE(points_past_the_set_continue_the_sequence) {
    // Through the internal Sampler (the C API of this version serves sample indices < N only).
    for (uint32_t pattern : {STIPPLE_PATTERN_SOBOL, STIPPLE_PATTERN_PMJ02})
        for (uint32_t n : {16u, 256u, 97u}) {
            auto handle = makeSampler(pattern, n, 77, {{2, 1}});
            const stipple::detail::Sampler& sampler = *stipple::detail::fromHandle(handle.get());
            std::vector<float> values(size_t(4) * n * 2);
            for (uint32_t i = 0; i < 4 * n; ++i) sampler.sample(5, 6, i, 0, values.data() + size_t(i) * 2);
            // Block 0 is the set itself.
            const std::vector<float> set = fillPixel(handle.get(), 5, 6, 0);
            BOOST_CHECK(std::memcmp(set.data(), values.data(), set.size() * sizeof(float)) == 0);
            const std::vector<FixedPoint2> xy = xyOf(values, 2);
            const uint32_t j = floorLog2(n);
            // sobol: every block is a net (a (0,2)-sequence's aligned blocks are). pmj02 only promises prefixes:
            // block 0 is a net, and blocks past N continue the sequence, so the first 2^i of the 4N points are one.
            for (uint32_t b = 0; b < (pattern == STIPPLE_PATTERN_SOBOL ? 4u : 1u); ++b)
                BOOST_CHECK_MESSAGE(stipple::detail::isElementaryNet(xy.data() + size_t(b) * n, j),
                                    patternName(pattern) << " N=" << n << " block " << b << ": prefix 2^" << j);
            // (sobol's blocks of a non-power-of-two N are parts of separate nets of 2^ceil(log2 N) points.)
            for (uint32_t i = 0; (1u << i) <= 4 * n && (pattern == STIPPLE_PATTERN_PMJ02 || (n & (n - 1)) == 0); ++i)
                BOOST_CHECK_MESSAGE(stipple::detail::isElementaryNet(xy.data(), i),
                                    patternName(pattern) << " N=" << n << ": the first 2^" << i << " of 4N samples");
            if (pattern == STIPPLE_PATTERN_SOBOL && (n & (n - 1)) == 0)
                for (uint32_t b = 0; b < 4; b += 2)
                    BOOST_CHECK_MESSAGE(stipple::detail::isElementaryNet(xy.data() + size_t(b) * n, j + 1),
                                        "sobol N=" << n << ": blocks " << b << " and " << b + 1 << " are not one net");
        }
}

// pmj02's families share their sequences (sequence j of a family is a prefix of sequence j of every longer one,
// z included), so the first 4N samples of an N-sample set are bitwise the fresh 4N-sample set of a sampler with the
// same seed wherever both families hold the drawn sequence: always while their sequence counts are equal (4N <= 1024
// here), for every arity. Exact.
BOOST_AUTO_TEST_CASE(pmj02_samples_past_n_are_the_fresh_4n_set) {
    for (uint32_t n : {4u, 16u, 64u, 256u})
        for (uint32_t arity = 1; arity <= 3; ++arity) {
            auto small = makeSampler(STIPPLE_PATTERN_PMJ02, n, 0x4e + arity, {{arity, 1}});
            auto large = makeSampler(STIPPLE_PATTERN_PMJ02, 4 * n, 0x4e + arity, {{arity, 1}});
            const stipple::detail::Sampler& sampler = *stipple::detail::fromHandle(small.get());
            for (uint32_t pixel = 0; pixel < 8; ++pixel) {
                std::vector<float> past(size_t(4) * n * arity);
                for (uint32_t i = 0; i < 4 * n; ++i) sampler.sample(pixel, 1, i, 0, past.data() + size_t(i) * arity);
                const std::vector<float> fresh = fillPixel(large.get(), pixel, 1, 0);
                BOOST_CHECK_MESSAGE(std::memcmp(fresh.data(), past.data(), fresh.size() * sizeof(float)) == 0,
                                    "N=" << n << " arity " << arity << " pixel " << pixel);
            }
        }
}

BOOST_AUTO_TEST_CASE(pmj02_sets_above_its_limit_are_a_clear_error) {
    stipple::Sampler s;
    const stipple::Status status = createSampler(s, STIPPLE_PATTERN_PMJ02, 65536, 0, {{2, 2}});
    BOOST_CHECK_EQUAL(status.code(), STIPPLE_ERROR_OUT_OF_RANGE);
    BOOST_CHECK(status.message().find("pmj02 pattern serves sets of at most 65536") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(blue_noise_keeps_every_pixel_valid_and_deterministic) {
    for (uint32_t pattern : blueNoisePatterns())
        for (uint32_t arity : {1u, 2u, 3u})
            for (uint32_t n : {1u, 13u, 64u}) {
                auto s = makeFlagged(pattern, n, 0xb1, arity, STIPPLE_SAMPLER_FLAG_BLUE_NOISE);
                for (uint32_t px : {0u, 63u, 64u, 4000000000u}) {
                    const std::vector<float> a = fillPixel(s.get(), px, 17, 0), b = fillPixel(s.get(), px, 17, 0);
                    BOOST_CHECK(a == b);
                    for (float v : a)
                        BOOST_REQUIRE_MESSAGE(v >= 0.0f && v < 1.0f, patternName(pattern) << " value " << v);
                    std::vector<float> one(arity);
                    for (uint32_t i = 0; i < n; ++i) {
                        BOOST_REQUIRE_EQUAL(stipple_sampler_sample(s.get(), px, 17, i, 0, one.data(), one.size()),
                                            STIPPLE_OK);
                        BOOST_CHECK_MESSAGE(
                            std::memcmp(one.data(), a.data() + size_t(i) * arity, arity * sizeof(float)) == 0,
                            patternName(pattern) << " arity " << arity << " N=" << n << " sample " << i);
                    }
                }
            }
}

BOOST_AUTO_TEST_CASE(blue_noise_samples_are_uniform_and_unbiased) {
    const int kTests = int(blueNoisePatterns().size()) * 2 * 2;
    const double alpha = sidak(0.01, kTests);
    for (uint32_t pattern : blueNoisePatterns())
        for (uint32_t arity : {2u, 3u}) {
            const uint32_t n = pattern == STIPPLE_PATTERN_POISSON_SEED ? 7 : 16;
            auto s = makeFlagged(pattern, n, 0x0b1e + arity, arity, STIPPLE_SAMPLER_FLAG_BLUE_NOISE);
            // One pixel per 64 x 64 tile, at a place in it that moves with the tile.
            const auto pixelX = [](uint32_t p) { return 64 * (p % 64) + (p * 37) % 64; };
            const auto pixelY = [](uint32_t p) { return 64 * (p / 64) + (p * 11 + 5) % 64; };
            // chi-square: sample n/2 of 3200 pixels on 64 cells.
            const uint32_t bins = arity == 2 ? 8 : 4;
            std::vector<double> observed(64, 0.0), expected(64, 3200.0 / 64);
            std::vector<float> one(arity);
            for (uint32_t p = 0; p < 3200; ++p) {
                BOOST_REQUIRE_EQUAL(
                    stipple_sampler_sample(s.get(), pixelX(p), pixelY(p), n / 2, 0, one.data(), one.size()),
                    STIPPLE_OK);
                uint32_t cell = 0;
                for (uint32_t c = 0; c < arity; ++c) cell = cell * bins + uint32_t(one[c] * bins);
                observed[cell] += 1;
            }
            const ChiSquareResult r = chiSquareTest(observed, expected);
            BOOST_CHECK_MESSAGE(r.pValue > alpha, patternName(pattern) << " arity " << arity << ": chi2 = "
                                                                       << r.statistic << ", p = " << r.pValue);
            // t-test of the quarter disk (2D) / sphere octant (3D) over 512 pixel estimates.
            const double exact = arity == 2 ? std::numbers::pi / 4 : std::numbers::pi / 6;
            double sum = 0, sumSq = 0;
            for (uint32_t p = 0; p < 512; ++p) {
                const std::vector<float> v = fillPixel(s.get(), pixelX(p), pixelY(p), 0);
                double hits = 0;
                for (uint32_t i = 0; i < n; ++i) {
                    double r2 = 0;
                    for (uint32_t c = 0; c < arity; ++c) r2 += double(v[i * arity + c]) * v[i * arity + c];
                    hits += r2 < 1.0;
                }
                const double e = hits / n - exact;
                sum += e, sumSq += e * e;
            }
            const double mean = sum / 512, sd = std::sqrt((sumSq - 512 * mean * mean) / 511);
            const double t = mean / (sd / std::sqrt(512.0));
            const double p = stipple::statistics::studentTTwoSidedP(t, 511);
            BOOST_CHECK_MESSAGE(p > alpha, patternName(pattern)
                                               << " arity " << arity << ": t = " << t << ", p = " << p);
        }
}
