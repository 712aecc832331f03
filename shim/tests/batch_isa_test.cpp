// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// batch_isa_test.cpp — the batch kernels compiled per ISA (batch_isa.h) give the per-point values bitwise.
// For every variant this CPU runs (baseline, AVX2, AVX-512), forced in turn: fill_pixel equals sample at every
// index and stream_fill equals stream, for every pattern the library lists (stipple_pattern_count), arity 1..3, N
// from 1 to 2^18 within the pattern's limits (progressive grids with and without the cell table, padded grids),
// k = 1 and 3, runs that start on and off the kernels' 64-point chunks and 16-float vectors, end mid-vector and
// cross blocks, and runs across the end of a sequence's period. With the blue-noise flag (every pattern whose limits
// accept it): every variant's fill_pixel and stream_fill equal the baseline variant's, bitwise.
#define BOOST_TEST_MODULE batch_isa
#include <boost/test/unit_test.hpp>

#include "batch_isa.h"
#include "sampler_fixture.h"

#include <stipple/stipple.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <string>
#include <vector>

namespace {

stipple::Sampler makeSampler(uint32_t pattern, uint32_t n, uint32_t arity, uint32_t k, uint32_t flags = 0) {
    stipple::Sampler s;
    const stipple::Status status = stipple::test::createSampler(s, pattern, n, 0x5eedu + n, {{arity, k}}, flags);
    BOOST_REQUIRE_MESSAGE(status.ok(), status.message());
    return s;
}

bool sameBits(const float* a, const float* b, size_t count) { return std::memcmp(a, b, count * sizeof(float)) == 0; }

// Indices checked: all for small sets, a spread of them (chunk borders included) for large ones.
std::vector<uint32_t> indices(uint32_t n) {
    std::vector<uint32_t> out;
    if (n <= 300) {
        for (uint32_t i = 0; i < n; ++i) out.push_back(i);
        return out;
    }
    for (uint32_t i : {0u, 1u, 63u, 64u, 65u, 127u, 128u}) out.push_back(i);
    for (uint32_t i = 0; i < 200; ++i) out.push_back(uint32_t((uint64_t(i) * 2654435761u) % n));
    out.push_back(n - 1);
    return out;
}

void checkPattern(uint32_t pattern, uint32_t n, uint32_t arity, uint32_t k) {
    const stipple::Sampler sampler = makeSampler(pattern, n, arity, k);
    const stipple_sampler s = sampler.handle();
    const size_t perSample = size_t(k) * arity;
    std::vector<float> full(size_t(n) * perSample), one(perSample);
    BOOST_REQUIRE(stipple_sampler_fill_pixel(s, 5, 9, 0, full.data(), full.size()) == STIPPLE_OK);
    uint32_t mismatches = 0;
    for (uint32_t i : indices(n)) {
        BOOST_REQUIRE(stipple_sampler_sample(s, 5, 9, i, 0, one.data(), one.size()) == STIPPLE_OK);
        mismatches += !sameBits(one.data(), full.data() + i * perSample, perSample);
    }
    // stream_fill against stream: a run starting off the chunk grid and crossing into the next block.
    const uint32_t first = n > 3 ? n - 3 + 64 * (n > 128) : 1;
    const uint32_t count = n + 70;
    std::vector<float> run(size_t(count) * arity);
    BOOST_REQUIRE(stipple_sampler_stream_fill(s, 2, 3, first, count, 11, arity, run.data(), run.size()) == STIPPLE_OK);
    for (uint32_t j = 0; j < count; j += (count > 400 ? 7 : 1)) {
        BOOST_REQUIRE(stipple_sampler_stream(s, 2, 3, first + j, 11, arity, one.data(), arity) == STIPPLE_OK);
        mismatches += !sameBits(one.data(), run.data() + size_t(j) * arity, arity);
    }
    // A run from a position on the 16-float grid but not 0 (the AVX-512 kernels' aligned blocks past the first)
    // ending mid-vector: 2D reads 8-point blocks, 1D 16-point ones.
    const uint32_t alignedFirst = n >= 64 ? 32 : n >= 16 ? 8 : 0;
    const uint32_t alignedCount = n - alignedFirst > 5 ? n - alignedFirst - 5 : 1;
    BOOST_REQUIRE(stipple_sampler_stream_fill(s, 4, 1, alignedFirst, alignedCount, 12, arity, run.data(),
                                              size_t(alignedCount) * arity) == STIPPLE_OK);
    for (uint32_t j = 0; j < alignedCount; j += (alignedCount > 400 ? 7 : 1)) {
        BOOST_REQUIRE(stipple_sampler_stream(s, 4, 1, alignedFirst + j, 12, arity, one.data(), arity) == STIPPLE_OK);
        mismatches += !sameBits(one.data(), run.data() + size_t(j) * arity, arity);
    }
    BOOST_CHECK_MESSAGE(mismatches == 0, "pattern " << pattern << " N " << n << " arity " << arity << " k " << k << ": "
                                                    << mismatches << " values differ");
}

// Every pattern the library offers, asked of the library (a pattern added to the registry is tested here without
// a change), with its limits.
struct PatternUnderTest {
    uint32_t id;
    std::string name;
    stipple_pattern_limits limits;
    uint32_t largestN; // past it a set costs generation, not serving: Poisson-disk sets are generated once
                       // per size (poisson) or per pixel and block, so per point call (poisson-seed)
};

std::vector<PatternUnderTest> everyPattern() {
    std::vector<PatternUnderTest> patterns;
    for (uint32_t id : stipple::test::allPatterns()) {
        PatternUnderTest p{id, {}, {}, 1u << 18};
        const char* name = nullptr;
        BOOST_REQUIRE(stipple_pattern_name(id, &name) == STIPPLE_OK);
        p.name = name;
        p.limits.struct_size = sizeof p.limits;
        BOOST_REQUIRE(stipple_pattern_get_limits(id, &p.limits) == STIPPLE_OK);
        if (p.name == "poisson") p.largestN = 4096;
        if (p.name == "poisson-seed") p.largestN = 256;
        patterns.push_back(p);
    }
    return patterns;
}

} // namespace

BOOST_AUTO_TEST_CASE(every_isa_variant_equals_the_per_point_values) {
    const stipple::detail::BatchIsa widest = stipple::detail::widestBatchIsa();
    BOOST_TEST_MESSAGE("widest batch ISA on this CPU: " << static_cast<uint32_t>(widest));
    const std::vector<PatternUnderTest> patterns = everyPattern();
    for (uint32_t isa = 0; isa <= static_cast<uint32_t>(widest); ++isa) {
        stipple::detail::forceBatchIsa(static_cast<stipple::detail::BatchIsa>(isa));
        BOOST_REQUIRE(stipple::detail::batchIsa() == static_cast<stipple::detail::BatchIsa>(isa));
        for (const PatternUnderTest& p : patterns)
            for (uint32_t arity = 1; arity <= 3; ++arity)
                for (uint32_t n : {1u, 2u, 4u, 13u, 16u, 64u, 256u, 4096u, 1u << 17, 1u << 18}) {
                    if (n > p.limits.max_set_size || n > p.largestN) continue;
                    checkPattern(p.id, n, arity, 1);
                    if (n <= 256 && 3 * n <= p.limits.max_set_size) checkPattern(p.id, n, arity, 3);
                }
    }
    stipple::detail::forceBatchIsa(widest);
}

// Runs across the end of a sequence's period (sobol, lattice: N * 2^(32 - ceil(log2 kN)); halton: N * floor(2^32 / kN);
// past it a fresh sequence) and up to the last index equal the per-point values in every variant, for every pattern:
// streams (k = 1) and arrays (k = 3).
BOOST_AUTO_TEST_CASE(every_isa_variant_equals_the_per_point_values_past_a_sequence_period) {
    const stipple::detail::BatchIsa widest = stipple::detail::widestBatchIsa();
    for (uint32_t isa = 0; isa <= static_cast<uint32_t>(widest); ++isa) {
        stipple::detail::forceBatchIsa(static_cast<stipple::detail::BatchIsa>(isa));
        for (const PatternUnderTest& p : everyPattern())
            for (uint32_t n : {3u, 1000u}) {
                if (n > p.largestN) continue;
                const stipple::Sampler sampler = makeSampler(p.id, n, 1, 1);
                const stipple_sampler s = sampler.handle();
                for (uint32_t k : {1u, 3u}) {
                    const uint64_t m = uint64_t(n) * k;
                    const uint64_t padded = n * (uint64_t(1) << (32 - std::bit_width(m - 1)));
                    const uint64_t unpadded = n * ((uint64_t(1) << 32) / m);
                    for (uint64_t end : {padded, unpadded, uint64_t(1) << 32}) {
                        if (end > (uint64_t(1) << 32)) continue;
                        const uint32_t first = static_cast<uint32_t>(end - n - 2);
                        const uint32_t count =
                            static_cast<uint32_t>(std::min<uint64_t>(2 * n + 4, (1ull << 32) - first));
                        for (uint32_t arity = 1; arity <= 3; ++arity) {
                            const size_t perSample = size_t(k) * arity;
                            std::vector<float> run(count * perSample), one(perSample);
                            uint32_t mismatches = 0;
                            if (k == 1)
                                BOOST_REQUIRE(stipple_sampler_stream_fill(s, 8, 2, first, count, 6, arity, run.data(),
                                                                          run.size()) == STIPPLE_OK);
                            else
                                BOOST_REQUIRE(stipple_sampler_array_fill(s, 8, 2, first, count, 6, arity, k, run.data(),
                                                                         run.size()) == STIPPLE_OK);
                            for (uint32_t j = 0; j < count; ++j) {
                                if (k == 1)
                                    BOOST_REQUIRE(stipple_sampler_stream(s, 8, 2, first + j, 6, arity, one.data(),
                                                                         one.size()) == STIPPLE_OK);
                                else
                                    BOOST_REQUIRE(stipple_sampler_array(s, 8, 2, first + j, 6, arity, k, one.data(),
                                                                        one.size()) == STIPPLE_OK);
                                mismatches += !sameBits(one.data(), run.data() + j * perSample, perSample);
                            }
                            BOOST_CHECK_MESSAGE(mismatches == 0, p.name << " N " << n << " k " << k << " arity "
                                                                        << arity << " from " << first << ": ISA " << isa
                                                                        << ", " << mismatches << " samples differ");
                        }
                    }
                }
            }
    }
    stipple::detail::forceBatchIsa(widest);
}

// The library lists its public patterns (and, in the scratch build, the scratch pattern past them: the fixture's
// allPatterns checks it), each with a name, and the tests' list is drawn from it.
BOOST_AUTO_TEST_CASE(the_library_lists_every_pattern) {
    uint32_t count = 0;
    BOOST_REQUIRE(stipple_pattern_count(&count) == STIPPLE_OK);
    BOOST_CHECK_GE(count, STIPPLE_PATTERN_COUNT);
    for (uint32_t id = 0; id < count; ++id) {
        const char* name = nullptr;
        BOOST_CHECK(stipple_pattern_name(id, &name) == STIPPLE_OK && name && *name);
    }
    BOOST_REQUIRE(!stipple::test::allPatterns().empty());
    BOOST_CHECK_EQUAL(stipple::test::allPatterns().back(), count - 1);
}

BOOST_AUTO_TEST_CASE(forcing_is_clamped_to_the_cpu) {
    const stipple::detail::BatchIsa widest = stipple::detail::widestBatchIsa();
    stipple::detail::forceBatchIsa(stipple::detail::BatchIsa::Avx512);
    BOOST_CHECK(stipple::detail::batchIsa() == widest);
    stipple::detail::forceBatchIsa(widest);
}

// The blue-noise batch kernels (a chunked loop per ISA, AVX-512 stratified by hand) against the baseline variant's
// values: pixels in two tiles, runs on and off the chunk grid and across blocks.
BOOST_AUTO_TEST_CASE(every_isa_variant_gives_the_same_blue_noise_values) {
    const stipple::detail::BatchIsa widest = stipple::detail::widestBatchIsa();
    struct Values {
        std::vector<float> fill, run;
    };
    const auto values = [](uint32_t pattern, uint32_t n, uint32_t arity, uint32_t k) {
        const stipple::Sampler sampler = makeSampler(pattern, n, arity, k, STIPPLE_SAMPLER_FLAG_BLUE_NOISE);
        const stipple_sampler s = sampler.handle();
        Values v;
        const size_t perPixel = size_t(n) * k * arity;
        v.fill.resize(2 * perPixel);
        BOOST_REQUIRE(stipple_sampler_fill_pixel(s, 5, 9, 0, v.fill.data(), perPixel) == STIPPLE_OK);
        BOOST_REQUIRE(stipple_sampler_fill_pixel(s, 70, 3, 0, v.fill.data() + perPixel, perPixel) == STIPPLE_OK);
        const uint32_t first = n > 3 ? n / 3 + 1 : 1, count = 2 * n + 19;
        v.run.resize(size_t(count) * arity);
        BOOST_REQUIRE(stipple_sampler_stream_fill(s, 66, 130, first, count, 3, arity, v.run.data(), v.run.size()) ==
                      STIPPLE_OK);
        return v;
    };
    for (const PatternUnderTest& p : everyPattern()) {
        if (!(p.limits.flags & STIPPLE_SAMPLER_FLAG_BLUE_NOISE)) continue; // the patterns that accept the flag
        const uint32_t pattern = p.id;
        for (uint32_t arity = 1; arity <= 3; ++arity)
            for (uint32_t n : {1u, 2u, 13u, 16u, 64u, 100u, 256u, 4096u, 1u << 16})
                for (uint32_t k : {1u, 3u}) {
                    stipple::detail::forceBatchIsa(stipple::detail::BatchIsa::Baseline);
                    const Values reference = values(pattern, n, arity, k);
                    for (uint32_t isa = 1; isa <= static_cast<uint32_t>(widest); ++isa) {
                        stipple::detail::forceBatchIsa(static_cast<stipple::detail::BatchIsa>(isa));
                        const Values v = values(pattern, n, arity, k);
                        BOOST_CHECK_MESSAGE(sameBits(v.fill.data(), reference.fill.data(), v.fill.size()) &&
                                                sameBits(v.run.data(), reference.run.data(), v.run.size()),
                                            "pattern " << pattern << " N " << n << " arity " << arity << " k " << k
                                                       << ": ISA " << isa << " differs from the baseline");
                    }
                }
    }
    stipple::detail::forceBatchIsa(widest);
}
