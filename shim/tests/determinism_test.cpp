// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// determinism_test.cpp — every value is a pure function of (seed, pixel, sample, dimension): the same from any
// thread, in any call order, and random access (stipple_sampler_sample) equals the batch call bitwise.
#define BOOST_TEST_MODULE determinism
#include "sampler_fixture.h"

#include <algorithm>
#include <cstring>
#include <random>
#include <thread>

using namespace stipple::test;

namespace {

const std::vector<DimensionSpec> kLayout = {{2, 1, "pixel"}, {1, 1, "time"}, {3, 2, "light"}, {2, 4, "bsdf"}};
constexpr uint32_t kTileW = 6, kTileH = 5;

struct Request {
    uint32_t x, y, d;
};

// Fills every (pixel, dimension) of the tile, in the order given, into results[(y * W + x) * D + d].
void fillInOrder(stipple_sampler s, const std::vector<Request>& order, std::vector<std::vector<float>>& results) {
    for (const Request& r : order) {
        results[(r.y * kTileW + r.x) * kLayout.size() + r.d] = fillPixelUnchecked(s, r.x, r.y, r.d);
    }
}

std::vector<Request> allRequests() {
    std::vector<Request> order;
    for (uint32_t y = 0; y < kTileH; ++y)
        for (uint32_t x = 0; x < kTileW; ++x)
            for (uint32_t d = 0; d < kLayout.size(); ++d) order.push_back({x, y, d});
    return order;
}

bool bitwiseEqual(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

} // namespace

BOOST_AUTO_TEST_CASE(same_values_for_any_thread_count_and_order) {
    for (uint32_t pattern : allPatterns()) {
        BOOST_TEST_CONTEXT(patternName(pattern)) {
            auto s = makeSampler(pattern, 19, 0xfeedbeefcafe, kLayout);
            const std::vector<Request> order = allRequests();
            std::vector<std::vector<float>> reference(order.size());
            fillInOrder(s.get(), order, reference);

            for (uint32_t threads : {2u, 4u}) {
                std::vector<std::vector<float>> results(order.size());
                std::vector<std::thread> pool;
                for (uint32_t t = 0; t < threads; ++t) {
                    pool.emplace_back([&, t] {
                        // Each thread takes every threads-th request, shuffled by its own fixed seed.
                        std::vector<Request> mine;
                        for (size_t i = t; i < order.size(); i += threads) mine.push_back(order[i]);
                        std::shuffle(mine.begin(), mine.end(), std::mt19937(1000 + t));
                        std::vector<std::vector<float>> local(order.size());
                        fillInOrder(s.get(), mine, local);
                        for (size_t i = t; i < order.size(); i += threads) results[i] = std::move(local[i]);
                    });
                }
                for (auto& th : pool) th.join();
                size_t mismatches = 0;
                for (size_t i = 0; i < order.size(); ++i)
                    mismatches += results[i].empty() || !bitwiseEqual(results[i], reference[i]);
                BOOST_CHECK_MESSAGE(mismatches == 0, threads << " threads: " << mismatches << " sets differ");
            }

            // A second sampler with the same description gives the same values (nothing depends on the handle).
            auto again = makeSampler(pattern, 19, 0xfeedbeefcafe, kLayout);
            BOOST_CHECK(
                bitwiseEqual(fillPixel(again.get(), 3, 2, 3), reference[(2 * kTileW + 3) * kLayout.size() + 3]));
            // And a different seed gives different values.
            auto other = makeSampler(pattern, 19, 0xfeedbeefcaff, kLayout);
            BOOST_CHECK(
                !bitwiseEqual(fillPixel(other.get(), 3, 2, 3), reference[(2 * kTileW + 3) * kLayout.size() + 3]));
        }
    }
}

BOOST_AUTO_TEST_CASE(random_access_equals_batch) {
    for (uint32_t pattern : allPatterns()) {
        for (uint32_t n : {1u, 7u, 16u, 50u}) {
            BOOST_TEST_CONTEXT(patternName(pattern) << " N=" << n) {
                auto s = makeSampler(pattern, n, 42, kLayout);
                for (uint32_t d = 0; d < kLayout.size(); ++d) {
                    const std::vector<float> batch = fillPixel(s.get(), 11, 13, d);
                    const uint32_t perSample = kLayout[d].arity * kLayout[d].count;
                    // Random access in reverse order, to make sure no state carries over from the previous call.
                    size_t mismatches = 0;
                    for (uint32_t i = n; i-- > 0;) {
                        std::vector<float> one(perSample);
                        BOOST_REQUIRE_EQUAL(stipple_sampler_sample(s.get(), 11, 13, i, d, one.data(), one.size()),
                                            STIPPLE_OK);
                        mismatches += std::memcmp(one.data(), batch.data() + size_t(i) * perSample,
                                                  perSample * sizeof(float)) != 0;
                    }
                    BOOST_CHECK_MESSAGE(mismatches == 0, "dimension " << d << ": " << mismatches << " samples differ");
                }
            }
        }
    }
}

BOOST_AUTO_TEST_CASE(poisson_cache_fills_deterministically_under_contention) {
    // Fresh set sizes (not used elsewhere in this process): threads race to generate the cached sets.
    const std::vector<DimensionSpec> layout = {{2, 1}, {3, 1}, {1, 1}};
    auto s = makeSampler(STIPPLE_PATTERN_POISSON, 333, 9, layout);
    std::vector<std::vector<float>> first(64 * 3), second(64 * 3);
    auto work = [&](std::vector<std::vector<float>>& into, uint32_t t) {
        for (uint32_t i = t; i < 64 * 3; i += 4) into[i] = fillPixelUnchecked(s.get(), i / 3, 0, i % 3);
    };
    std::vector<std::thread> pool;
    for (uint32_t t = 0; t < 4; ++t) pool.emplace_back(work, std::ref(first), t);
    for (auto& th : pool) th.join();
    work(second, 0), work(second, 1), work(second, 2), work(second, 3);
    size_t mismatches = 0;
    for (size_t i = 0; i < first.size(); ++i) mismatches += first[i].empty() || !bitwiseEqual(first[i], second[i]);
    BOOST_CHECK_EQUAL(mismatches, 0u);
}

BOOST_AUTO_TEST_CASE(appending_dimensions_changes_nothing_before_them) {
    // A host that declares more dimensions later (e.g. a deeper path) keeps the values of the ones it had.
    for (uint32_t pattern : allPatterns()) {
        auto shorter = makeSampler(pattern, 9, 77, {{2, 1}, {1, 3}});
        auto longer = makeSampler(pattern, 9, 77, {{2, 1}, {1, 3}, {3, 2}, {2, 1}});
        for (uint32_t d = 0; d < 2; ++d)
            BOOST_CHECK_MESSAGE(bitwiseEqual(fillPixel(shorter.get(), 4, 4, d), fillPixel(longer.get(), 4, 4, d)),
                                patternName(pattern) << " dimension " << d);
    }
}
