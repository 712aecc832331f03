// sampler_fixture.h — helpers shared by the shim tests: build samplers through the C API, read whole pixels.
#pragma once

#include <stipple/stipple.h>

#include <boost/test/unit_test.hpp>

#include <cstdint>
#include <memory>
#include <string>
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

struct SamplerDeleter {
    void operator()(stipple_sampler_t* s) const { stipple_sampler_release(s); }
};
using SamplerPtr = std::unique_ptr<stipple_sampler_t, SamplerDeleter>;

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
    desc.dimensions = descs.data();
    desc.flags = flags;
    stipple_sampler s = nullptr;
    const stipple_status status = stipple_sampler_create(&desc, &s);
    BOOST_REQUIRE_MESSAGE(status == STIPPLE_OK, "stipple_sampler_create: " << stipple_last_error_message());
    return SamplerPtr(s);
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

constexpr uint32_t kAllPatterns[] = {STIPPLE_PATTERN_INDEPENDENT,  STIPPLE_PATTERN_STRATIFIED, STIPPLE_PATTERN_POISSON,
                                     STIPPLE_PATTERN_POISSON_SEED, STIPPLE_PATTERN_SOBOL,      STIPPLE_PATTERN_PMJ02};
constexpr int kPatternCount = int(sizeof kAllPatterns / sizeof kAllPatterns[0]);
// The patterns that take STIPPLE_SAMPLER_FLAG_BLUE_NOISE (the others refuse it at creation: blue_noise_test).
constexpr uint32_t kBlueNoisePatterns[] = {STIPPLE_PATTERN_INDEPENDENT, STIPPLE_PATTERN_STRATIFIED};
constexpr uint32_t kBlueNoiseRefused[] = {STIPPLE_PATTERN_POISSON, STIPPLE_PATTERN_POISSON_SEED, STIPPLE_PATTERN_SOBOL,
                                          STIPPLE_PATTERN_PMJ02};

} // namespace stipple::test
