// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// kit_with_internals_test.cpp — one translation unit with the public C++ kit (stipple.hpp: stipple::Sampler,
// stipple::Error) and every internal header of the library (stipple::detail): the two never clash, and a kit
// sampler is the internal sampler its handle names.
#include <stipple/stipple.hpp>

#include "avx512_intrinsics.h"
#include "batch_isa.h"
#include "blue_noise.h"
#include "dimension.h"
#include "error.h"
#include "fast_divider.h"
#include "hash.h"
#include "owen_scrambling.h"
#include "pattern_registry.h"
#include "permutation.h"
#include "pmj02_family.h"
#include "pmj02_generator.h"
#include "pointsets/cell_grid.h"
#include "pointsets/dart_grid.h"
#include "pointsets/pointsets.h"
#include "pointsets/random.h"
#include "pointsets/spectrum.h"
#include "pointsets/torus.h"
#include "poisson_cache.h"
#include "progressive_order.h"
#include "progressive_strata.h"
#include "sampler.h"
#include "simd_avx512.h"
#include "sobol_matrices.h"
#include "strata_grid.h"

#define BOOST_TEST_MODULE kit_with_internals
#include <boost/test/unit_test.hpp>

#include <cstdint>
#include <cstring>
#include <string>

BOOST_AUTO_TEST_CASE(a_kit_sampler_is_the_internal_sampler_of_its_handle) {
    for (uint32_t id = 0; id < stipple::detail::patternCount(); ++id) {
        const stipple::detail::PatternOps& ops = *stipple::detail::findPattern(id);
        const stipple::Sampler kit(ops.name, 16, 42);
        const stipple::detail::Sampler& inside = *stipple::detail::fromHandle(kit.handle());
        BOOST_TEST(inside.pattern() == id);
        BOOST_TEST(&inside.patternOps() == &ops);
        BOOST_TEST(inside.samplesPerPixel() == 16u);
        BOOST_TEST(inside.seed() == 42u);
        // The same value through the kit (the C ABI) and through the internal object.
        float viaKit[3], viaInside[3];
        BOOST_TEST(kit.stream({5, 9}, 21, 3, 3, viaKit).ok());
        inside.stream(5, 9, 21, 3, 3, viaInside);
        BOOST_TEST(std::memcmp(viaKit, viaInside, sizeof viaKit) == 0, ops.name);
    }
}

BOOST_AUTO_TEST_CASE(kit_and_internal_errors_are_distinct_types) {
    // An unknown pattern reaches the kit as its stipple::Error, built from the message the internal
    // stipple::detail::Error carried to the ABI.
    try {
        const stipple::Sampler kit("no-such-pattern", 16, 1);
        BOOST_FAIL("an unknown pattern name was accepted");
    } catch (const stipple::detail::Error&) {
        BOOST_FAIL("an internal error crossed the ABI");
    } catch (const stipple::Error& error) {
        BOOST_TEST(std::string(error.what()).find(stipple::detail::patternNameList()) != std::string::npos,
                   error.what());
    }
}
