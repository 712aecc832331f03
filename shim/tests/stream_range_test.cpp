// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// stream_range_test.cpp — every value of every pattern, arity, k and N lies in [0, 1); info matches the layout.
#define BOOST_TEST_MODULE stream_range
#include "sampler_fixture.h"

using namespace stipple::test;

BOOST_AUTO_TEST_CASE(values_lie_in_unit_interval) {
    const uint32_t counts[] = {1, 2, 3, 5, 7, 13, 97, 256, 1000, 4096};
    for (uint32_t pattern : allPatterns()) {
        for (uint32_t n : counts) {
            // poisson-seed generates per call: fewer pixels at large N keep the test fast.
            const uint32_t pixels = (pattern == STIPPLE_PATTERN_POISSON_SEED && n >= 1000) ? 1 : 3;
            auto s = makeSampler(pattern, n, 1234 + n, {{1, 1}, {2, 1}, {3, 1}, {2, 3}});
            for (uint32_t d = 0; d < 4; ++d) {
                for (uint32_t px = 0; px < pixels; ++px) {
                    const std::vector<float> values = fillPixel(s.get(), px, 7, d);
                    uint32_t bad = 0;
                    for (float v : values) bad += !(v >= 0.0f && v < 1.0f);
                    BOOST_CHECK_MESSAGE(bad == 0, patternName(pattern) << " N=" << n << " dimension " << d << ": "
                                                                       << bad << " values outside [0,1)");
                }
            }
        }
    }
}

BOOST_AUTO_TEST_CASE(dimension_info_describes_the_layout) {
    auto s = makeSampler(STIPPLE_PATTERN_STRATIFIED, 13, 1, {{1, 1, "pixel"}, {2, 4, "light.0"}, {3, 1, nullptr}});
    stipple_dimension_info info{};
    info.struct_size = sizeof info;
    BOOST_REQUIRE_EQUAL(stipple_sampler_get_dimension_info(s.get(), 1, &info), STIPPLE_OK);
    BOOST_CHECK_EQUAL(info.arity, 2u);
    BOOST_CHECK_EQUAL(info.count, 4u);
    BOOST_CHECK_EQUAL(info.floats_per_pixel, 13u * 4u * 2u);
    BOOST_CHECK_EQUAL(std::string(info.name), "light.0");
    // 52 = 4 x 13 has aspect 3.25 > 2: padded grid, ceil(sqrt(52)) = 8 columns, ceil(52 / 8) = 7 rows.
    BOOST_CHECK_EQUAL(info.strata[0], 8u);
    BOOST_CHECK_EQUAL(info.strata[1], 7u);
    BOOST_CHECK_EQUAL(info.strata[2], 0u);
    BOOST_REQUIRE_EQUAL(stipple_sampler_get_dimension_info(s.get(), 2, &info), STIPPLE_OK);
    BOOST_CHECK_EQUAL(std::string(info.name), "");
    uint32_t found = 99;
    BOOST_REQUIRE_EQUAL(stipple_sampler_find_dimension(s.get(), "light.0", &found), STIPPLE_OK);
    BOOST_CHECK_EQUAL(found, 1u);

    stipple_sampler_info sinfo{};
    sinfo.struct_size = sizeof sinfo;
    BOOST_REQUIRE_EQUAL(stipple_sampler_get_info(s.get(), &sinfo), STIPPLE_OK);
    BOOST_CHECK_EQUAL(sinfo.pattern, STIPPLE_PATTERN_STRATIFIED);
    BOOST_CHECK_EQUAL(sinfo.samples_per_pixel, 13u);
    BOOST_CHECK_EQUAL(sinfo.dimension_count, 3u);
    BOOST_CHECK_EQUAL(sinfo.seed, 1u);
}

BOOST_AUTO_TEST_CASE(past_the_layout_is_independent_and_deterministic) {
    auto s = makeSampler(STIPPLE_PATTERN_STRATIFIED, 16, 5, {{2, 1}});
    float a[64], b[64];
    BOOST_REQUIRE_EQUAL(stipple_sampler_sample_independent(s.get(), 3, 4, 5, 1000, a, 64), STIPPLE_OK);
    BOOST_REQUIRE_EQUAL(stipple_sampler_sample_independent(s.get(), 3, 4, 5, 1000, b, 64), STIPPLE_OK);
    for (int i = 0; i < 64; ++i) {
        BOOST_CHECK(a[i] >= 0.0f && a[i] < 1.0f);
        BOOST_CHECK_EQUAL(a[i], b[i]);
    }
    BOOST_REQUIRE_EQUAL(stipple_sampler_sample_independent(s.get(), 3, 4, 5, 1001, b, 64), STIPPLE_OK);
    int same = 0;
    for (int i = 0; i < 64; ++i) same += a[i] == b[i];
    BOOST_CHECK_LT(same, 2); // another stream gives other values
}
