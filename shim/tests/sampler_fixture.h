// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// sampler_fixture.h — helpers shared by the shim tests: build samplers through the C++ kit, read whole pixels
// through the C API.
#pragma once

#include <stipple/stipple.h>
#include <stipple/stipple.hpp>

#include <boost/test/unit_test.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace stipple::test {

struct DimensionSpec {
    uint32_t arity = 2;
    uint32_t count = 1;
    const char* name = nullptr;
};

inline stipple_dimension_desc toDesc(const DimensionSpec& spec) {
    stipple_dimension_desc d{};
    d.struct_size = sizeof d;
    d.arity = spec.arity;
    d.count = spec.count;
    d.name = spec.name;
    return d;
}

// A test's sampler: the C++ kit's owner (stipple.hpp), so the tests create and release samplers as hosts do;
// get() is the C handle the tests call the ABI with.
class SamplerPtr {
public:
    explicit SamplerPtr(stipple::Sampler sampler) : sampler_(std::move(sampler)) {}
    stipple_sampler get() const { return sampler_.handle(); }
    const stipple::Sampler& kit() const { return sampler_; }

private:
    stipple::Sampler sampler_;
};

inline SamplerPtr makeSampler(uint32_t pattern, uint32_t n, uint64_t seed, const std::vector<DimensionSpec>& dims,
                              uint32_t flags = 0) {
    std::vector<stipple_dimension_desc> descs;
    for (const auto& d : dims) descs.push_back(toDesc(d));
    stipple_sampler_desc desc{};
    desc.struct_size = sizeof desc;
    desc.pattern = pattern;
    desc.samples_per_pixel = n;
    desc.dimension_count = static_cast<uint32_t>(descs.size());
    desc.seed = seed;
    desc.dimensions = descs.empty() ? nullptr : descs.data();
    desc.flags = flags;
    stipple::Sampler sampler;
    const stipple::Status status = stipple::Sampler::create(sampler, desc);
    BOOST_REQUIRE_MESSAGE(status.ok(), "stipple_sampler_create: " << status.message());
    return SamplerPtr(std::move(sampler));
}

// One dimension of `arity` (one point per sample), created with `flags`.
inline SamplerPtr makeFlagged(uint32_t pattern, uint32_t n, uint64_t seed, uint32_t arity, uint32_t flags) {
    return makeSampler(pattern, n, seed, {{arity, 1}}, flags);
}

inline uint32_t floatsPerPixel(stipple_sampler s, uint32_t dimension) {
    stipple_dimension_info info{};
    info.struct_size = sizeof info;
    BOOST_REQUIRE_EQUAL(stipple_sampler_get_dimension_info(s, dimension, &info), STIPPLE_OK);
    return info.floats_per_pixel;
}

inline std::vector<float> fillPixel(stipple_sampler s, uint32_t x, uint32_t y, uint32_t dimension) {
    std::vector<float> out(floatsPerPixel(s, dimension));
    const stipple_status status = stipple_sampler_fill_pixel(s, x, y, dimension, out.data(), out.size());
    BOOST_REQUIRE_MESSAGE(status == STIPPLE_OK, "stipple_sampler_fill_pixel: " << stipple_last_error_message());
    return out;
}

// For worker threads: Boost.Test assertions are not thread-safe, so this one only returns {} on failure.
inline std::vector<float> fillPixelUnchecked(stipple_sampler s, uint32_t x, uint32_t y, uint32_t dimension) {
    stipple_dimension_info info{};
    info.struct_size = sizeof info;
    if (stipple_sampler_get_dimension_info(s, dimension, &info) != STIPPLE_OK) return {};
    std::vector<float> out(info.floats_per_pixel);
    if (stipple_sampler_fill_pixel(s, x, y, dimension, out.data(), out.size()) != STIPPLE_OK) return {};
    return out;
}

inline const char* patternName(uint32_t pattern) {
    const char* name = "?";
    stipple_pattern_name(pattern, &name);
    return name;
}

// Every pattern of the library: numbers are dense from 0 (stipple.h), so a pattern added to the registry and to
// STIPPLE_PATTERN_COUNT is in every test that loops over this list without a change here.
constexpr int kPatternCount = int(STIPPLE_PATTERN_COUNT);
constexpr std::array<uint32_t, STIPPLE_PATTERN_COUNT> kAllPatterns = [] {
    std::array<uint32_t, STIPPLE_PATTERN_COUNT> all{};
    for (uint32_t p = 0; p < all.size(); ++p) all[p] = p;
    return all;
}();
// The patterns that take STIPPLE_SAMPLER_FLAG_BLUE_NOISE (the others refuse it at creation: blue_noise_test). The
// library's limits say the same (batch_isa_test checks the two lists against stipple_pattern_get_limits).
constexpr uint32_t kBlueNoisePatterns[] = {STIPPLE_PATTERN_STRATIFIED};
constexpr uint32_t kBlueNoiseRefused[] = {STIPPLE_PATTERN_INDEPENDENT, STIPPLE_PATTERN_POISSON,
                                          STIPPLE_PATTERN_POISSON_SEED, STIPPLE_PATTERN_SOBOL,
                                          STIPPLE_PATTERN_PMJ02,       STIPPLE_PATTERN_LATTICE,
                                          STIPPLE_PATTERN_HALTON};

} // namespace stipple::test
