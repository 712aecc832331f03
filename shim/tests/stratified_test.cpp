// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// stratified_test.cpp — one sample per stratum for every N (square, non-square, prime), arity and k; the grid
// rule of shim/README.md (exact most-square factorisation when its aspect is <= 2, else the padded grid).
#define BOOST_TEST_MODULE stratified
#include "sampler_fixture.h"

#include <cmath>
#include <map>

using namespace stipple::test;

namespace {

stipple_dimension_info dimensionInfo(stipple_sampler s, uint32_t d) {
    stipple_dimension_info info{};
    info.struct_size = sizeof info;
    BOOST_REQUIRE_EQUAL(stipple_sampler_get_dimension_info(s, d, &info), STIPPLE_OK);
    return info;
}

// Checks that the set of one pixel puts exactly one point in each of M distinct cells of the grid, and for a
// padded grid that every line along the last axis misses at most one cell.
void checkOneSamplePerStratum(uint32_t arity, uint32_t n, uint32_t k, uint32_t pixelX) {
    auto s = makeSampler(STIPPLE_PATTERN_STRATIFIED, n, 77 + n, {{arity, k}});
    const stipple_dimension_info info = dimensionInfo(s.get(), 0);
    const uint32_t m = n * k;
    uint64_t cells = 1;
    for (uint32_t c = 0; c < arity; ++c) cells *= info.strata[c];
    BOOST_REQUIRE_GE(cells, m);
    const std::vector<float> values = fillPixel(s.get(), pixelX, 3, 0);
    std::map<uint64_t, uint32_t> occupancy;
    std::map<uint64_t, uint32_t> perLine;
    for (uint32_t p = 0; p < m; ++p) {
        uint64_t cell = 0, line = 0;
        for (uint32_t c = arity; c-- > 0;) {
            const double scaled = double(values[size_t(p) * arity + c]) * info.strata[c]; // exact in double
            const uint64_t index = static_cast<uint64_t>(std::floor(scaled));
            BOOST_REQUIRE_LT(index, info.strata[c]);
            cell = cell * info.strata[c] + index;
            if (c + 1 < arity) line = line * info.strata[c] + index;
        }
        ++occupancy[cell];
        ++perLine[line];
    }
    uint32_t doubles = 0;
    for (const auto& [cell, hits] : occupancy) doubles += hits > 1;
    BOOST_CHECK_MESSAGE(doubles == 0 && occupancy.size() == m, "arity " << arity << " N=" << n << " k=" << k << ": "
                                                                        << occupancy.size() << " cells used of " << m
                                                                        << ", " << doubles << " used twice");
    const uint32_t lineLength = info.strata[arity - 1];
    for (const auto& [line, hits] : perLine)
        BOOST_CHECK_MESSAGE(hits + 1 >= lineLength, "arity " << arity << " N=" << n << ": a line holds " << hits
                                                             << " of " << lineLength << " cells");
}

} // namespace

BOOST_AUTO_TEST_CASE(one_sample_per_stratum) {
    const uint32_t counts[] = {1, 2, 3, 5, 7, 10, 13, 16, 17, 32, 97, 100, 256, 1000, 1021, 4096};
    for (uint32_t arity = 1; arity <= 3; ++arity)
        for (uint32_t n : counts)
            for (uint32_t pixel = 0; pixel < 3; ++pixel) checkOneSamplePerStratum(arity, n, 1, pixel);
    // k values per sample: one stratification of k*N points.
    checkOneSamplePerStratum(2, 16, 4, 0);
    checkOneSamplePerStratum(1, 13, 3, 1);
    checkOneSamplePerStratum(3, 7, 5, 2);
}

BOOST_AUTO_TEST_CASE(grid_rule) {
    struct Case {
        uint32_t arity, n, x, y, z;
    };
    const Case cases[] = {
        {1, 13, 13, 0, 0},    {2, 16, 4, 4, 0},      {2, 32, 8, 4, 0},      {2, 8, 4, 2, 0},    {2, 256, 16, 16, 0},
        {2, 1000, 40, 25, 0}, {2, 10, 4, 3, 0},      {2, 13, 4, 4, 0},      {2, 97, 10, 10, 0}, {2, 3, 2, 2, 0},
        {2, 2, 2, 1, 0},      {3, 4096, 16, 16, 16}, {3, 1000, 10, 10, 10}, {3, 16, 4, 2, 2},   {3, 256, 8, 8, 4},
        {3, 13, 3, 3, 2},     {3, 3, 2, 2, 1},       {3, 97, 5, 5, 4},
    };
    for (const Case& c : cases) {
        auto s = makeSampler(STIPPLE_PATTERN_STRATIFIED, c.n, 1, {{c.arity, 1}});
        const stipple_dimension_info info = dimensionInfo(s.get(), 0);
        BOOST_CHECK_MESSAGE(info.strata[0] == c.x && info.strata[1] == c.y && info.strata[2] == c.z,
                            "arity " << c.arity << " N=" << c.n << ": strata " << info.strata[0] << "x"
                                     << info.strata[1] << "x" << info.strata[2] << ", expected " << c.x << "x" << c.y
                                     << "x" << c.z);
    }
    // Other patterns report no strata.
    auto s = makeSampler(STIPPLE_PATTERN_POISSON, 16, 1, {{2, 1}});
    BOOST_CHECK_EQUAL(dimensionInfo(s.get(), 0).strata[0], 0u);
}

BOOST_AUTO_TEST_CASE(padded_holes_vary_between_pixels) {
    // With N = 13 in 2D, 3 of 16 cells stay empty; different pixels must leave different cells empty.
    auto s = makeSampler(STIPPLE_PATTERN_STRATIFIED, 13, 5, {{2, 1}});
    std::map<uint32_t, uint32_t> emptyCount;
    for (uint32_t px = 0; px < 400; ++px) {
        const std::vector<float> v = fillPixel(s.get(), px, 0, 0);
        bool used[16] = {};
        for (uint32_t p = 0; p < 13; ++p) used[uint32_t(v[2 * p] * 4) + 4 * uint32_t(v[2 * p + 1] * 4)] = true;
        for (uint32_t c = 0; c < 16; ++c) emptyCount[c] += !used[c];
    }
    // Each cell is empty with probability 3/16: 75 of 400 expected; binomial sd 7.8. Bound at +-5 sd.
    for (uint32_t c = 0; c < 16; ++c) {
        BOOST_CHECK_GT(emptyCount[c], 75 - 39);
        BOOST_CHECK_LT(emptyCount[c], 75 + 39);
    }
}
