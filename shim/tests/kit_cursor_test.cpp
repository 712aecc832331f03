// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// kit_cursor_test.cpp — stipple.hpp's PixelSampleCursor as a cache of the library's values: every value equals the
// per-value C call under any order of starts (back steps, repeats, blocks past N, batch sizes changed mid-pixel,
// one index asked with several arities or k); a pixel-major host pays one batch call per (pixel, index) and no
// per-value call; errors come back through the status forms without exceptions and without buffers sized by bad
// arguments.
#include <stipple/stipple.hpp>

#define BOOST_TEST_MODULE kit_cursor
#include <boost/test/unit_test.hpp>

#include <sys/resource.h>

#include <cstring>
#include <array>
#include <random>
#include <string>
#include <vector>

using stipple::Pixel;
using stipple::PixelSampleCursor;
using stipple::Sampler;

namespace {

Sampler makeSampler(const std::string& pattern, uint32_t n, uint64_t seed,
                    const stipple_api& api = stipple::linkedApi()) {
    Sampler s;
    const stipple::Status status = Sampler::create(s, pattern, n, seed, 0, api);
    BOOST_REQUIRE_MESSAGE(status.ok(), status.message());
    return s;
}

bool sameBits(const float* a, const float* b, size_t count) { return std::memcmp(a, b, count * sizeof(float)) == 0; }

// The library's table with the batch and per-value calls counted (one thread).
struct CountingApi {
    static stipple_api table;
    static const stipple_api* real;
    static long streamFills, arrayFills, streamCalls, arrayCalls;
    static stipple_status streamFill(stipple_sampler s, uint32_t x, uint32_t y, uint32_t first, uint32_t count,
                                     uint32_t index, uint32_t arity, float* out, size_t outCount) {
        ++streamFills;
        return real->sampler_stream_fill(s, x, y, first, count, index, arity, out, outCount);
    }
    static stipple_status arrayFill(stipple_sampler s, uint32_t x, uint32_t y, uint32_t first, uint32_t count,
                                    uint32_t index, uint32_t arity, uint32_t k, float* out, size_t outCount) {
        ++arrayFills;
        return real->sampler_array_fill(s, x, y, first, count, index, arity, k, out, outCount);
    }
    static stipple_status stream(stipple_sampler s, uint32_t x, uint32_t y, uint32_t sample, uint32_t index,
                                 uint32_t arity, float* out, size_t outCount) {
        ++streamCalls;
        return real->sampler_stream(s, x, y, sample, index, arity, out, outCount);
    }
    static stipple_status array(stipple_sampler s, uint32_t x, uint32_t y, uint32_t sample, uint32_t index,
                                uint32_t arity, uint32_t k, float* out, size_t outCount) {
        ++arrayCalls;
        return real->sampler_array(s, x, y, sample, index, arity, k, out, outCount);
    }
    static const stipple_api& get() {
        real = &stipple::linkedApi();
        table = *real;
        table.sampler_stream_fill = &streamFill;
        table.sampler_array_fill = &arrayFill;
        table.sampler_stream = &stream;
        table.sampler_array = &array;
        streamFills = arrayFills = streamCalls = arrayCalls = 0;
        return table;
    }
};
stipple_api CountingApi::table;
const stipple_api* CountingApi::real = nullptr;
long CountingApi::streamFills = 0, CountingApi::arrayFills = 0, CountingApi::streamCalls = 0,
     CountingApi::arrayCalls = 0;

} // namespace

// 4000 starts in a random order (fixed seed) over 3 pixels and samples 0..3N, each asking a random run of
// streams (arity 1..3 drawn per call, so one index meets several arities) and arrays (arity 1..3, k 1..5), with
// the batch size changed now and then, sometimes between two calls of one sample. Every value must equal the
// per-value call bit for bit; one mismatch is a cache bug (stale window, wrong offset, wrong shape).
BOOST_AUTO_TEST_CASE(values_equal_per_value_calls_in_any_order) {
    for (const char* pattern : {"stratified", "sobol", "pmj02", "independent"}) {
        const uint32_t n = 8;
        const Sampler s = makeSampler(pattern, n, 11);
        PixelSampleCursor cursor(s);
        std::mt19937 rng(2026);
        const Pixel pixels[] = {{0, 0}, {5, -3}, {-1, 7}};
        long checked = 0;
        for (int step = 0; step < 4000; ++step) {
            const Pixel p = pixels[rng() % 10 < 8 ? (step / 200) % 3 : rng() % 3]; // mostly pixel after pixel
            const uint32_t sample = rng() % (3 * n);
            const uint32_t first = rng() % 4 == 0 ? uint32_t(rng() % 8) : 0;
            if (rng() % 50 == 0) cursor.setBatchSamples(1 + rng() % (n + 2));
            cursor.start(p, sample, first);
            const float* film = nullptr;
            std::array<float, 2> f = cursor.getPixel2D();
            film = f.data();
            float direct[16];
            BOOST_REQUIRE(s.stream(p, sample, PixelSampleCursor::kPixelStream, 2, direct).ok());
            BOOST_REQUIRE(sameBits(film, direct, 2));
            const int calls = int(rng() % 12);
            uint32_t index = first, array = 0;
            for (int c = 0; c < calls; ++c) {
                if (rng() % 7 == 0) cursor.setBatchSamples(1 + rng() % (n + 2)); // mid-sample
                const uint32_t arity = 1 + rng() % 3;
                float got[16];
                if (rng() % 4 == 0) {
                    const uint32_t k = 1 + rng() % 5;
                    const float* v = nullptr;
                    BOOST_REQUIRE(cursor.nextArray(arity, k, v).ok());
                    std::memcpy(got, v, k * arity * sizeof(float));
                    BOOST_REQUIRE(s.array(p, sample, array++, arity, k, direct).ok());
                    BOOST_REQUIRE_MESSAGE(sameBits(got, direct, k * arity), pattern << " step " << step << " array");
                } else {
                    if (arity == 1) got[0] = cursor.get1D();
                    if (arity == 2) {
                        const std::array<float, 2> v = cursor.get2D();
                        std::memcpy(got, v.data(), sizeof v);
                    }
                    if (arity == 3) {
                        const std::array<float, 3> v = cursor.get3D();
                        std::memcpy(got, v.data(), sizeof v);
                    }
                    BOOST_REQUIRE(s.stream(p, sample, index++, arity, direct).ok());
                    BOOST_REQUIRE_MESSAGE(sameBits(got, direct, arity),
                                          pattern << " step " << step << " stream " << index - 1 << " arity " << arity);
                }
                ++checked;
            }
            BOOST_REQUIRE(cursor.status().ok());
        }
        BOOST_CHECK_GT(checked, 15000);
    }
}

// Values before the first start() are pixel (0, 0), sample 0 (a cursor is usable as constructed).
BOOST_AUTO_TEST_CASE(a_cursor_without_start_serves_pixel_0_sample_0) {
    const Sampler s = makeSampler("sobol", 16, 3);
    PixelSampleCursor cursor(s);
    const std::array<float, 2> uv = cursor.get2D();
    float direct[2];
    BOOST_REQUIRE(s.stream(Pixel{0, 0}, 0, 0, 2, direct).ok());
    BOOST_CHECK(sameBits(uv.data(), direct, 2));
}

// The fast path is a cache: a pixel-major host makes one stream_fill per (pixel, stream) and one array_fill per
// (pixel, array), never a per-value call; sample-major with setBatchSamples(1) makes one batch call per value.
BOOST_AUTO_TEST_CASE(pixel_major_hosts_make_one_batch_call_per_pixel_and_index) {
    const uint32_t n = 16, pixels = 20;
    const Sampler s = makeSampler("stratified", n, 5, CountingApi::get());
    PixelSampleCursor cursor(s);
    for (uint32_t p = 0; p < pixels; ++p)
        for (uint32_t i = 0; i < n; ++i) {
            cursor.start(Pixel{int32_t(p), 0}, i);
            (void)cursor.getPixel2D();
            for (int d = 0; d < 3; ++d) (void)cursor.get2D(), (void)cursor.get1D();
            (void)cursor.get2DArray(4);
        }
    BOOST_REQUIRE(cursor.status().ok());
    BOOST_CHECK_EQUAL(CountingApi::streamFills, long(pixels) * 7); // film + 6 streams
    BOOST_CHECK_EQUAL(CountingApi::arrayFills, long(pixels));
    BOOST_CHECK_EQUAL(CountingApi::streamCalls + CountingApi::arrayCalls, 0);

    CountingApi::get();
    PixelSampleCursor sampleMajor(s);
    sampleMajor.setBatchSamples(1);
    for (uint32_t i = 0; i < 4; ++i)
        for (uint32_t p = 0; p < pixels; ++p) {
            sampleMajor.start(Pixel{int32_t(p), 0}, i);
            (void)sampleMajor.get1D();
        }
    BOOST_CHECK_EQUAL(CountingApi::streamFills, long(pixels) * 4);
}

// Errors through the status forms: the values are zeros, status() holds the first failure until the next
// start(), and bad shapes size no buffer (k = 2^31 would ask for 8 GiB if it did).
BOOST_AUTO_TEST_CASE(errors_come_back_through_the_status_forms) {
    const Sampler s = makeSampler("stratified", 16, 1);
    PixelSampleCursor cursor(s);
    cursor.start(Pixel{2, 3}, 0);
    const float* v = nullptr;
    stipple::Status st = cursor.nextArray(4, 2, v);
    BOOST_CHECK_EQUAL(st.code(), STIPPLE_ERROR_INVALID_ARGUMENT);
    BOOST_CHECK(v[0] == 0.0f && v[1] == 0.0f && v[2] == 0.0f);
    BOOST_CHECK_EQUAL(cursor.nextArray(2, 0, v).code(), STIPPLE_ERROR_OUT_OF_RANGE);
    BOOST_CHECK_EQUAL(cursor.nextArray(2, 0x80000000u, v).code(), STIPPLE_ERROR_OUT_OF_RANGE);
    BOOST_CHECK_EQUAL(cursor.status().code(), STIPPLE_ERROR_INVALID_ARGUMENT); // the first since start()
    float u = 1.0f;
    BOOST_CHECK(cursor.next1D(u).ok()); // a good call after failures
    cursor.start(Pixel{2, 3}, 1);
    BOOST_CHECK(cursor.status().ok());

    cursor.start(Pixel{2, 3}, 1, STIPPLE_STREAM_RESERVED_FIRST - 1);
    BOOST_CHECK(cursor.next1D(u).ok());
    st = cursor.next1D(u); // the counter reaches the kit's reserved range
    BOOST_CHECK_EQUAL(st.code(), STIPPLE_ERROR_OUT_OF_RANGE);
    BOOST_CHECK_MESSAGE(st.message().find("reserved") != std::string::npos, st.message());
    BOOST_CHECK_EQUAL(u, 0.0f);

    const Sampler none;
    PixelSampleCursor empty(none);
    empty.start(Pixel{0, 0}, 0);
    std::array<float, 2> uv = {{1.0f, 1.0f}};
    BOOST_CHECK_EQUAL(empty.next2D(uv).code(), STIPPLE_ERROR_NULL_ARGUMENT);
    BOOST_CHECK(uv[0] == 0.0f && uv[1] == 0.0f);
#if STIPPLE_HPP_EXCEPTIONS
    BOOST_CHECK_THROW(empty.get1D(), stipple::Error);
#endif
}

// An array shape the library refuses for its k * N (k = 1024 at N = 65536 is 2^26 values of one dimension, past
// STIPPLE_MAX_SET_SIZE) comes back as the library's error without a window-sized buffer (it was 512 MiB).
BOOST_AUTO_TEST_CASE(an_array_past_the_set_size_limit_sizes_nothing_by_its_shape) {
    const uint32_t n = 65536, k = STIPPLE_MAX_VALUES_PER_SAMPLE;
    const Sampler s = makeSampler("independent", n, 7);
    PixelSampleCursor cursor(s);
    cursor.setBatchSamples(n);
    cursor.start(Pixel{0, 0}, 0);
    struct rusage before {}, after {};
    getrusage(RUSAGE_SELF, &before);
    const float* v = nullptr;
    const stipple::Status st = cursor.nextArray(2, k, v);
    getrusage(RUSAGE_SELF, &after);
    BOOST_CHECK(!st.ok());
    BOOST_TEST_MESSAGE(st.message());
    BOOST_CHECK(v != nullptr && v[0] == 0.0f);
    const long grownKiB = after.ru_maxrss - before.ru_maxrss; // a 2^26-pair window would be 512 MiB
    BOOST_CHECK_MESSAGE(grownKiB < 64 * 1024, "peak memory grew by " << grownKiB << " KiB");
    float u = 1.0f;
    BOOST_CHECK(cursor.next1D(u).ok()); // the cursor still serves
}
