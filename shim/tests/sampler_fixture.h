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
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace stipple::test {

struct DimensionSpec {
    uint32_t arity = 2;
    uint32_t count = 1;
    const char* name = nullptr;
};

inline const char* patternName(uint32_t pattern) {
    const char* name = "?";
    stipple_pattern_name(pattern, &name);
    return name;
}

// The kit's creation of a sampler for pattern `pattern` (its id, as the tests loop over ids) with a declared layout
// of `dims` (none: streams and arrays only): what every test and benchmark creates samplers with.
inline stipple::Status createSampler(stipple::Sampler& out, uint32_t pattern, uint32_t n, uint64_t seed,
                                     const std::vector<DimensionSpec>& dims, uint32_t flags = 0) {
    std::vector<stipple::LayoutDimension> layout;
    for (const DimensionSpec& d : dims) layout.push_back({d.arity, d.count, d.name ? d.name : ""});
    return stipple::Sampler::create(out, patternName(pattern), n, seed, layout, flags);
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
    stipple::Sampler sampler;
    const stipple::Status status = createSampler(sampler, pattern, n, seed, dims, flags);
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

// Every pattern the library serves, in id order, from its own listing (stipple_pattern_count): a pattern added
// to the registry is in every test that loops over this list without a change here. The scratch build
// (STIPPLE_TEST_SCRATCH_PATTERN, shim/CMakeLists.txt) checks that: its library serves one pattern past the public
// ids, the list must end with it, and the tests loop over it alone.
inline const std::vector<uint32_t>& allPatterns() {
    static const std::vector<uint32_t> all = [] {
        uint32_t count = 0;
        if (stipple_pattern_count(&count) != STIPPLE_OK) throw std::logic_error("stipple_pattern_count failed");
        std::vector<uint32_t> ids(count);
        for (uint32_t p = 0; p < count; ++p) ids[p] = p;
#if defined(STIPPLE_TEST_SCRATCH_PATTERN)
        // The scratch build: the library must list the scratch pattern last; the tests then run on it alone (the
        // public patterns have their own run).
        const char* last = nullptr;
        if (count != STIPPLE_PATTERN_COUNT + 1 || stipple_pattern_name(count - 1, &last) != STIPPLE_OK ||
            std::string(last) != STIPPLE_TEST_SCRATCH_PATTERN)
            throw std::logic_error("the scratch build's library does not list the scratch pattern \""
                                   STIPPLE_TEST_SCRATCH_PATTERN "\" last");
        ids.erase(ids.begin(), ids.end() - 1);
#endif
        return ids;
    }();
    return all;
}
inline int patternCount() { return int(allPatterns().size()); }

#if defined(STIPPLE_TEST_SCRATCH_PATTERN)
} // namespace stipple::test
namespace stipple::detail {
uint64_t scratchPatternUses(); // tests/scratch_pattern.cpp: sets the library prepared or computed with it
}
namespace stipple::test {
// The scratch build's check at the end of every test program: the program did reach the scratch pattern (a test
// that kept a list of its own would not).
struct ScratchPatternReached {
    void setup() {}
    void teardown() {
        BOOST_CHECK_MESSAGE(stipple::detail::scratchPatternUses() > 0,
                            "the scratch pattern \"" STIPPLE_TEST_SCRATCH_PATTERN "\" was never used");
    }
};
BOOST_TEST_GLOBAL_FIXTURE(ScratchPatternReached);
#endif

// The STIPPLE_SAMPLER_FLAG_* bits pattern `pattern` accepts (stipple_pattern_get_limits).
inline uint32_t acceptedFlags(uint32_t pattern) {
    stipple_pattern_limits limits{};
    limits.struct_size = sizeof limits;
    if (stipple_pattern_get_limits(pattern, &limits) != STIPPLE_OK) throw std::logic_error("stipple_pattern_get_limits");
    return limits.flags;
}

// The patterns whose limits accept STIPPLE_SAMPLER_FLAG_BLUE_NOISE, and the others (which refuse it at creation:
// blue_noise_test checks both against sampler creation).
inline std::vector<uint32_t> blueNoisePatterns(bool accepted = true) {
    std::vector<uint32_t> list;
    for (uint32_t p : allPatterns())
        if (bool(acceptedFlags(p) & STIPPLE_SAMPLER_FLAG_BLUE_NOISE) == accepted) list.push_back(p);
    return list;
}
inline std::vector<uint32_t> blueNoiseRefused() { return blueNoisePatterns(false); }

} // namespace stipple::test
