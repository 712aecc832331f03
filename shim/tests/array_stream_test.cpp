// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// array_stream_test.cpp — array streams (ABI 1.2) and the 1.2 pattern calls, through stipple.hpp as a host sees
// them: k values per sample stratified over the pixel's N * k values, unbiased, independent of call-order
// streams; the batch call equal to the per-sample call; the cursor's batches equal to direct calls.
//
// Statistical checks use fixed seeds and alpha = 0.01, Sidak-corrected over the checks of each test case.
#define BOOST_TEST_MODULE array_stream
#include <stipple/stipple.hpp>
#include <stipple/testing/statistics.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstring>
#include <set>
#include <string>
#include <vector>

using stipple::Pixel;
using stipple::Sampler;

namespace {

Sampler makeSampler(const std::string& pattern, uint32_t n, uint64_t seed,
                    const std::vector<stipple::LayoutDimension>& layout = {}) {
    Sampler sampler;
    const stipple::Status s = Sampler::create(sampler, pattern, n, seed, layout);
    BOOST_REQUIRE_MESSAGE(s.ok(), pattern << ": " << s.message());
    return sampler;
}

// Samples [first, first + count) of array (index, arity, k) of one pixel.
std::vector<float> arrayFill(const Sampler& s, Pixel p, uint32_t first, uint32_t count, uint32_t index,
                             uint32_t arity, uint32_t k) {
    std::vector<float> v(size_t(count) * k * arity, -1.0f);
    const stipple::Status status = s.arrayFill(p, first, count, index, arity, k, v.data());
    BOOST_REQUIRE_MESSAGE(status.ok(), status.message());
    return v;
}

// The cell of a point in a grid of strata[0] x strata[1] x strata[2] cells.
size_t cellOf(const float* v, uint32_t arity, const uint32_t strata[3]) {
    size_t cell = 0;
    for (uint32_t c = arity; c-- > 0;) cell = cell * strata[c] + size_t(v[c] * float(strata[c]));
    return cell;
}

// Every elementary interval of area 2^-m (2D) holds exactly one of the 2^m points.
bool isNet(const std::vector<float>& uv, int m) {
    for (int a = 0; a <= m; ++a) {
        std::set<size_t> cells;
        for (size_t p = 0; p < uv.size() / 2; ++p)
            if (!cells.insert(size_t(uv[2 * p + 1] * float(1u << (m - a))) * (size_t(1) << a) +
                              size_t(uv[2 * p] * float(1u << a)))
                     .second)
                return false;
    }
    return true;
}

} // namespace

// Stratified: an array of (arity, k) in a block is one stratified set of N * k points, on the grid a declared
// dimension of count k has (stipple_sampler_get_dimension_info's strata): every point in a cell of its own.
BOOST_AUTO_TEST_CASE(stratified_over_n_times_k) {
    struct Case {
        uint32_t arity, n, k;
    };
    const Case cases[] = {{1, 16, 4}, {2, 16, 4}, {3, 16, 4}, {2, 8, 8}, {2, 7, 5}, {1, 13, 3}, {3, 32, 3}, {2, 64, 1}};
    for (const Case& c : cases) {
        const Sampler layout = makeSampler("stratified", c.n, 5, {{c.arity, c.k, ""}});
        stipple::DimensionInfo info;
        BOOST_REQUIRE(layout.dimensionInfo(0, info).ok());
        const Sampler s = makeSampler("stratified", c.n, 99);
        for (uint32_t block : {0u, 2u})
            for (int pixel = 0; pixel < 6; ++pixel)
                for (uint32_t index : {0u, 7u, 0xfffffff0u}) {
                    const Pixel p = {pixel - 2, 3 * pixel};
                    const std::vector<float> v = arrayFill(s, p, block * c.n, c.n, index, c.arity, c.k);
                    std::set<size_t> cells;
                    for (size_t q = 0; q < size_t(c.n) * c.k; ++q) cells.insert(cellOf(&v[q * c.arity], c.arity, info.strata));
                    BOOST_REQUIRE_MESSAGE(cells.size() == size_t(c.n) * c.k,
                                          "arity " << c.arity << " N " << c.n << " k " << c.k << " block " << block
                                                   << ": " << cells.size() << " distinct cells for " << c.n * c.k
                                                   << " points");
                }
    }
}

// sobol and pmj02: an array's N * k points of a block are a (0, m, 2)-net when N * k = 2^m (the plain patterns: the
// blue-noise flag's toroidal shift does not keep nets). sobol: every block (aligned blocks of a (0,2)-sequence);
// pmj02 promises prefixes: the first 1, 2 and 8 blocks together (its tables hold 8 blocks of a set's sequence).
BOOST_AUTO_TEST_CASE(nets_over_n_times_k) {
    for (const char* pattern : {"sobol", "pmj02"})
        for (uint32_t n : {4u, 16u, 64u})
            for (uint32_t k : {2u, 4u, 16u}) {
                const Sampler s = makeSampler(pattern, n, 3);
                int m = 0;
                while ((1u << m) < n * k) ++m;
                const bool sobol = std::string(pattern) == "sobol";
                for (uint32_t b : {0u, 1u, 5u})
                    for (int pixel = 0; pixel < 4; ++pixel) {
                        // sobol: block b alone; pmj02: the first 1, 2 or 8 blocks (b = 0, 1, 5 -> 1, 2, 8 blocks)
                        const uint32_t first = sobol ? b * n : 0, blocks = sobol ? 1 : (b == 0 ? 1 : b == 1 ? 2 : 8);
                        const int log2Blocks = blocks == 1 ? 0 : blocks == 2 ? 1 : 3;
                        BOOST_REQUIRE_MESSAGE(
                            isNet(arrayFill(s, Pixel{pixel, -pixel}, first, blocks * n, 2, 2, k), m + log2Blocks),
                            pattern << " N " << n << " k " << k << (sobol ? " block " : " blocks 0.. ")
                                    << (sobol ? b : blocks - 1));
                    }
            }
}

// Unbiased: the mean over a pixel's N * k values of an integrand with an edge, over 256 pixels (independent
// sets), against the exact integral. Two-sided t-test per (pattern, arity).
BOOST_AUTO_TEST_CASE(unbiased) {
    const char* patterns[] = {"independent", "stratified", "poisson", "poisson-seed", "sobol", "pmj02",
                              "stratified+blue-noise"};
    const int kPatterns = 7, kPixels = 256;
    const uint32_t n = 8, k = 3;
    // f = [sum of coordinates < 0.8 * arity / 2] + product of coordinates: an edge plus a smooth non-periodic part.
    const double exact[3] = {0.4 + 0.5, 0.32 + 0.25, 0};
    const double critical = stipple::statistics::studentTCritical(stipple::testing::sidak(0.01, kPatterns * 2), kPixels - 1);
    for (int pi = 0; pi < kPatterns; ++pi)
        for (uint32_t arity = 1; arity <= 2; ++arity) {
            const Sampler s = makeSampler(patterns[pi], n, 1234);
            double sum = 0, sum2 = 0;
            for (int pixel = 0; pixel < kPixels; ++pixel) {
                const std::vector<float> v = arrayFill(s, Pixel{pixel % 16, pixel / 16}, n, n, 1, arity, k); // block 1
                double mean = 0;
                for (size_t q = 0; q < size_t(n) * k; ++q) {
                    const float* x = &v[q * arity];
                    const double total = arity == 1 ? x[0] : x[0] + x[1];
                    const double product = arity == 1 ? x[0] : double(x[0]) * x[1];
                    mean += (total < 0.4 * arity ? 1.0 : 0.0) + product;
                }
                mean /= double(n) * k;
                sum += mean;
                sum2 += mean * mean;
            }
            const double mean = sum / kPixels, var = (sum2 - kPixels * mean * mean) / (kPixels - 1);
            const double t = (mean - exact[arity - 1]) / std::sqrt(var / kPixels);
            BOOST_CHECK_MESSAGE(std::fabs(t) < critical, patterns[pi] << " arity " << arity << ": mean " << mean
                                                                     << " exact " << exact[arity - 1] << " t " << t
                                                                     << " critical " << critical);
        }
}

// Arrays are not call-order streams: array j with k = 1 is a set of its own, not stream j (bitwise different),
// and uncorrelated with it, with array j of another k, and with array j + 1: Pearson's r of the x coordinates
// paired by sample, over 512 pixels x N samples, |r| sqrt(n) below the Sidak-corrected normal critical value.
BOOST_AUTO_TEST_CASE(independent_of_call_order_streams) {
    const char* patterns[] = {"independent", "stratified", "poisson", "sobol", "pmj02", "stratified+blue-noise"};
    const int kPatterns = 6, kPairs = 3, kPixels = 512;
    const uint32_t n = 16;
    const double critical = stipple::testing::sidakZ(0.01, kPatterns * kPairs);
    for (int pi = 0; pi < kPatterns; ++pi) {
        const Sampler s = makeSampler(patterns[pi], n, 77);
        double sx[kPairs] = {}, sy[kPairs] = {}, sxx[kPairs] = {}, syy[kPairs] = {}, sxy[kPairs] = {};
        size_t equal = 0;
        for (int pixel = 0; pixel < kPixels; ++pixel) {
            const Pixel p = {pixel % 32, pixel / 32};
            const std::vector<float> array = arrayFill(s, p, 0, n, 5, 2, 1);
            const std::vector<float> arrayK2 = arrayFill(s, p, 0, n, 5, 2, 2);
            const std::vector<float> next = arrayFill(s, p, 0, n, 6, 2, 1);
            std::vector<float> stream(2 * n);
            BOOST_REQUIRE(s.streamFill(p, 0, n, 5, 2, stream.data()).ok());
            equal += std::memcmp(array.data(), stream.data(), stream.size() * sizeof(float)) == 0;
            for (uint32_t i = 0; i < n; ++i) {
                const double x = array[2 * i], ys[kPairs] = {stream[2 * i], arrayK2[4 * i], next[2 * i]};
                for (int q = 0; q < kPairs; ++q) {
                    sx[q] += x;
                    sy[q] += ys[q];
                    sxx[q] += x * x;
                    syy[q] += ys[q] * ys[q];
                    sxy[q] += x * ys[q];
                }
            }
        }
        BOOST_CHECK_MESSAGE(equal == 0, patterns[pi] << ": array 5 (k = 1) equals stream 5 in " << equal << " pixels");
        const double count = double(kPixels) * n;
        const char* names[kPairs] = {"stream 5", "array 5 with k = 2", "array 6"};
        for (int q = 0; q < kPairs; ++q) {
            const double cov = sxy[q] / count - (sx[q] / count) * (sy[q] / count);
            const double r = cov / std::sqrt((sxx[q] / count - sx[q] * sx[q] / (count * count)) *
                                             (syy[q] / count - sy[q] * sy[q] / (count * count)));
            BOOST_CHECK_MESSAGE(std::fabs(r) * std::sqrt(count) < critical,
                                patterns[pi] << ": array 5 vs " << names[q] << ": r = " << r << ", |r| sqrt(n) = "
                                             << std::fabs(r) * std::sqrt(count) << " (critical " << critical << ")");
        }
    }
}

// array_fill equals array calls bitwise: every pattern, with and without blue noise, across blocks and tiles.
BOOST_AUTO_TEST_CASE(fill_equals_per_sample_calls) {
    std::vector<std::string> names;
    BOOST_REQUIRE(stipple::patternNames(names).ok());
    BOOST_REQUIRE_EQUAL(names.size(), size_t(STIPPLE_PATTERN_COUNT));
    for (const std::string& name : names)
        for (const std::string& suffix : {std::string(), std::string("+blue-noise")}) {
            if (!suffix.empty()) { // the patterns whose limits accept the flag
                uint32_t id = 0;
                stipple_pattern_limits limits{};
                limits.struct_size = sizeof limits;
                BOOST_REQUIRE(stipple_pattern_from_name(name.c_str(), &id) == STIPPLE_OK &&
                              stipple_pattern_get_limits(id, &limits) == STIPPLE_OK);
                if (!(limits.flags & STIPPLE_SAMPLER_FLAG_BLUE_NOISE)) continue;
            }
            const Sampler s = makeSampler(name + suffix, 8, 42);
            for (uint32_t arity = 1; arity <= 3; ++arity)
                for (uint32_t k : {1u, 3u})
                    for (const Pixel p : {Pixel{0, 0}, Pixel{63, 64}, Pixel{-1, 5}}) {
                        const std::vector<float> fill = arrayFill(s, p, 3, 19, 11, arity, k); // blocks 0..2
                        for (uint32_t i = 0; i < 19; ++i) {
                            std::vector<float> one(size_t(k) * arity);
                            BOOST_REQUIRE(s.array(p, 3 + i, 11, arity, k, one.data()).ok());
                            BOOST_REQUIRE_MESSAGE(std::memcmp(one.data(), &fill[size_t(i) * k * arity],
                                                              one.size() * sizeof(float)) == 0,
                                                  name << suffix << " arity " << arity << " k " << k << " sample "
                                                       << 3 + i);
                            for (float v : one) BOOST_REQUIRE(v >= 0.0f && v < 1.0f);
                        }
                    }
        }
}

// The cursor's batches are a cache, not another sequence: every value equals the direct call, in pixel-major and
// sample-major order, with batches of N and of 1, with indices past the cache.
BOOST_AUTO_TEST_CASE(cursor_equals_direct_calls) {
    const Sampler s = makeSampler("stratified", 8, 9);
    for (uint32_t batch : {8u, 3u, 1u})
        for (bool pixelMajor : {true, false}) {
            stipple::PixelSampleCursor cursor(s);
            cursor.setBatchSamples(batch);
            for (int outer = 0; outer < 4; ++outer)
                for (uint32_t inner = 0; inner < 12; ++inner) {
                    const Pixel p = pixelMajor ? Pixel{outer, 1} : Pixel{int(inner % 4), 1};
                    const uint32_t sample = pixelMajor ? inner : uint32_t(outer) * 3 + inner / 4;
                    cursor.start(p, sample, sample % 2 ? 4094 : 0); // some starts cross kMaxCachedIndex
                    const uint32_t first = cursor.dimension();
                    const float a = cursor.get1D();
                    const std::array<float, 2> b = cursor.get2D();
                    const std::array<float, 2> film = cursor.getPixel2D();
                    const float* arr = cursor.get2DArray(3);
                    std::vector<float> arrayValues(arr, arr + 6);
                    BOOST_REQUIRE(cursor.status().ok());
                    float da, db[2], dfilm[2], darr[6];
                    BOOST_REQUIRE(s.stream(p, sample, first, 1, &da).ok());
                    BOOST_REQUIRE(s.stream(p, sample, first + 1, 2, db).ok());
                    BOOST_REQUIRE(s.stream(p, sample, stipple::PixelSampleCursor::kPixelStream, 2, dfilm).ok());
                    BOOST_REQUIRE(s.array(p, sample, 0, 2, 3, darr).ok());
                    BOOST_REQUIRE(a == da && b[0] == db[0] && b[1] == db[1] && film[0] == dfilm[0] &&
                                  film[1] == dfilm[1]);
                    BOOST_REQUIRE(std::memcmp(arrayValues.data(), darr, sizeof darr) == 0);
                }
        }
}

// Errors: every bad argument a status with a message naming it; the status forms of the kit report them.
BOOST_AUTO_TEST_CASE(errors_and_pattern_calls) {
    const Sampler pmj = makeSampler("pmj02", 32768, 1);
    float out[8];
    stipple::Status s = pmj.array(Pixel{0, 0}, 0, 0, 2, 4, out); // 131072 points: past pmj02's sets
    BOOST_CHECK_EQUAL(s.code(), STIPPLE_ERROR_OUT_OF_RANGE);
    BOOST_CHECK_MESSAGE(s.message().find("65536") != std::string::npos, s.message());
    const Sampler st = makeSampler("stratified", 16, 1);
    BOOST_CHECK_EQUAL(st.array(Pixel{0, 0}, 0, 0, 2, 0, out).code(), STIPPLE_ERROR_OUT_OF_RANGE);
    BOOST_CHECK_EQUAL(st.array(Pixel{0, 0}, 0, 0, 4, 1, out).code(), STIPPLE_ERROR_INVALID_ARGUMENT);
    BOOST_CHECK_EQUAL(st.array(Pixel{0, 0}, 0, 0, 2, 1025, out).code(), STIPPLE_ERROR_OUT_OF_RANGE);
    BOOST_CHECK_EQUAL(stipple_sampler_array(st.handle(), 0, 0, 0, 0, 2, 4, out, 7), STIPPLE_ERROR_OUT_OF_RANGE);
    BOOST_CHECK_EQUAL(stipple_sampler_array(st.handle(), 0, 0, 0, 0, 2, 4, nullptr, 8), STIPPLE_ERROR_NULL_ARGUMENT);
    BOOST_CHECK_EQUAL(stipple_sampler_array_fill(st.handle(), 0, 0, 0, 0, 0, 2, 1, out, 8), STIPPLE_ERROR_OUT_OF_RANGE);
    BOOST_CHECK_EQUAL(stipple_sampler_array_fill(st.handle(), 0, 0, 0xffffffffu, 2, 0, 1, 1, out, 8),
                      STIPPLE_ERROR_OUT_OF_RANGE);

    uint32_t count = 0, pattern = 0, flags = 0;
    BOOST_CHECK_EQUAL(stipple_pattern_count(&count), STIPPLE_OK);
    BOOST_CHECK_EQUAL(count, STIPPLE_PATTERN_COUNT);
    BOOST_CHECK_EQUAL(stipple_pattern_parse("sobol+blue-noise", &pattern, &flags), STIPPLE_OK);
    BOOST_CHECK(pattern == STIPPLE_PATTERN_SOBOL && flags == STIPPLE_SAMPLER_FLAG_BLUE_NOISE);
    BOOST_CHECK_EQUAL(stipple_pattern_parse("pmj02", &pattern, &flags), STIPPLE_OK);
    BOOST_CHECK(pattern == STIPPLE_PATTERN_PMJ02 && flags == 0);
    for (const char* bad : {"sobol+blue", "sobol+blue-noise+blue-noise", "+blue-noise", "Sobol", ""})
        BOOST_CHECK_EQUAL(stipple_pattern_parse(bad, &pattern, &flags), STIPPLE_ERROR_INVALID_ARGUMENT);
    BOOST_CHECK_EQUAL(stipple_pattern_parse(nullptr, &pattern, &flags), STIPPLE_ERROR_NULL_ARGUMENT);

    stipple_pattern_limits limits{};
    limits.struct_size = sizeof limits;
    BOOST_CHECK_EQUAL(stipple_pattern_get_limits(STIPPLE_PATTERN_COUNT, &limits), STIPPLE_ERROR_INVALID_ARGUMENT);
    limits.struct_size = 4;
    BOOST_CHECK_EQUAL(stipple_pattern_get_limits(0, &limits), STIPPLE_ERROR_STRUCT_SIZE);
    // The limits are what creation enforces: N at the limit is created, one more is refused.
    for (uint32_t p = 0; p < count; ++p) {
        limits = stipple_pattern_limits{};
        limits.struct_size = sizeof limits;
        BOOST_REQUIRE_EQUAL(stipple_pattern_get_limits(p, &limits), STIPPLE_OK);
        const char* name = nullptr;
        BOOST_REQUIRE_EQUAL(stipple_pattern_name(p, &name), STIPPLE_OK);
        Sampler handle;
        BOOST_CHECK_EQUAL(Sampler::create(handle, name, limits.max_samples_per_pixel + 1, 0).code(),
                          STIPPLE_ERROR_OUT_OF_RANGE);
        BOOST_CHECK(Sampler::create(handle, name, limits.max_samples_per_pixel, 0).ok());
        // The flag is offered exactly where creation accepts it.
        const bool withFlag = Sampler::create(handle, name, 16, 0, STIPPLE_SAMPLER_FLAG_BLUE_NOISE).ok();
        BOOST_CHECK_EQUAL(limits.flags == STIPPLE_SAMPLER_FLAG_BLUE_NOISE, withFlag);
        BOOST_CHECK(limits.flags == 0 || limits.flags == STIPPLE_SAMPLER_FLAG_BLUE_NOISE);
    }

    Sampler empty;
    BOOST_CHECK(!empty);
    BOOST_CHECK_EQUAL(empty.stream(Pixel{0, 0}, 0, 0, 1, out).code(), STIPPLE_ERROR_NULL_ARGUMENT);
    Sampler bad;
    s = Sampler::create(bad, "sobol+pink-noise", 16, 1);
    BOOST_CHECK(!s.ok() && !bad && bad.status().code() == STIPPLE_ERROR_INVALID_ARGUMENT);
    BOOST_CHECK_MESSAGE(s.message().find("+blue-noise") != std::string::npos, s.message());
}
