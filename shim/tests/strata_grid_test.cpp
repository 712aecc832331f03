// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// strata_grid_test.cpp — the grid rule and the cell map for every M up to 2000 (and spot checks up to 2^22):
// cellOf maps the M set points to M distinct cells of the grid, a padded grid misses fewer cells than it has
// lines and at most one per line, and the aspect of an exact factorisation is at most 2.
#define BOOST_TEST_MODULE strata_grid
#include <boost/test/unit_test.hpp>

#include "fast_divider.h"
#include "hash.h"
#include "permutation.h"
#include "strata_grid.h"

#include <algorithm>
#include <random>
#include <vector>

using stipple::detail::StrataGrid;

namespace {

void checkGrid(uint32_t arity, uint32_t m, uint32_t lineSeed, uint32_t holeOffset) {
    const StrataGrid grid = StrataGrid::choose(arity, m);
    uint64_t cells = 1;
    for (uint32_t c = 0; c < arity; ++c) cells *= grid.axis[c];
    BOOST_REQUIRE_GE(cells, m);
    BOOST_REQUIRE_EQUAL(cells - m, grid.emptyCells);
    if (!grid.padded() && arity > 1) {
        // A full grid is either the most-square factorisation (aspect <= 2) or the padded shape n^(d-1) x L that
        // happens to have no hole (e.g. 3D M = 9: 3x3x1).
        const uint32_t largest = *std::max_element(grid.axis, grid.axis + arity);
        const uint32_t smallest = *std::min_element(grid.axis, grid.axis + arity);
        const bool paddedShape = arity == 3 && grid.axis[0] == grid.axis[1] && grid.axis[2] < grid.axis[0];
        BOOST_CHECK_MESSAGE(largest <= 2 * smallest || paddedShape, "arity " << arity << " M=" << m << ": "
                                                                             << grid.axis[0] << "x" << grid.axis[1]
                                                                             << "x" << grid.axis[2]);
    }
    if (grid.padded()) BOOST_CHECK_LT(grid.emptyCells, grid.lineCount);
    std::vector<uint8_t> used(cells, 0);
    std::vector<uint32_t> perLine(grid.lineCount, 0);
    uint32_t collisions = 0, outside = 0;
    for (uint32_t q = 0; q < m; ++q) {
        uint32_t cell[3] = {0, 0, 0};
        grid.cellOf(q, lineSeed, holeOffset % grid.lineLength, cell);
        uint64_t index = 0, line = 0;
        for (uint32_t c = arity; c-- > 0;) {
            if (cell[c] >= grid.axis[c]) {
                ++outside;
                cell[c] = 0;
            }
            index = index * grid.axis[c] + cell[c];
            if (c + 1 < arity) line = line * grid.axis[c] + cell[c];
        }
        collisions += used[index]++ != 0;
        ++perLine[line];
    }
    BOOST_CHECK_MESSAGE(collisions == 0 && outside == 0, "arity " << arity << " M=" << m << ": " << collisions
                                                                  << " collisions, " << outside << " outside");
    const uint32_t shortLines = uint32_t(
        std::count_if(perLine.begin(), perLine.end(), [&](uint32_t hits) { return hits + 1 < grid.lineLength; }));
    BOOST_CHECK_MESSAGE(shortLines == 0,
                        "arity " << arity << " M=" << m << ": " << shortLines << " lines miss 2+ cells");
}

} // namespace

BOOST_AUTO_TEST_CASE(every_small_set_size) {
    for (uint32_t arity = 1; arity <= 3; ++arity)
        for (uint32_t m = 1; m <= 2000; ++m) checkGrid(arity, m, m * 2654435761u, m * 7u);
}

BOOST_AUTO_TEST_CASE(large_set_sizes) {
    for (uint32_t m : {4093u, 65521u, 65536u, 1000003u, (1u << 22) - 1, 1u << 22})
        for (uint32_t arity = 1; arity <= 3; ++arity) checkGrid(arity, m, 12345, 678);
}

BOOST_AUTO_TEST_CASE(fast_divider_is_exact) {
    std::mt19937 rng(7);
    for (uint32_t d = 1; d <= 600; ++d) {
        const stipple::detail::FastDivider divider(d);
        uint32_t wrong = 0;
        for (uint32_t n = 0; n < (1u << 22); n += 1 + (d % 97)) wrong += divider.divide(n) != n / d;
        BOOST_REQUIRE_MESSAGE(wrong == 0, "divisor " << d << ": " << wrong << " wrong quotients");
    }
    for (int t = 0; t < 300; ++t) {
        const uint32_t d = rng() % (1u << 22) + 1;
        const stipple::detail::FastDivider divider(d);
        uint32_t wrong = 0;
        for (int j = 0; j < 2000; ++j) {
            const uint32_t n = rng() % (1u << 22);
            wrong += divider.divide(n) != n / d;
        }
        BOOST_REQUIRE_MESSAGE(wrong == 0, "divisor " << d << ": " << wrong << " wrong quotients");
        BOOST_REQUIRE_EQUAL(divider.divide((1u << 22) - 1), ((1u << 22) - 1) / d);
    }
}

BOOST_AUTO_TEST_CASE(hashed_permutation_is_a_bijection) {
    for (uint32_t length : {1u, 2u, 3u, 5u, 16u, 97u, 256u, 1000u, 4096u, 65537u}) {
        for (uint32_t seed : {0u, 1u, 0xdeadbeefu}) {
            std::vector<uint8_t> hit(length, 0);
            for (uint32_t i = 0; i < length; ++i) {
                const uint32_t j = stipple::detail::permuteIndex(i, length, seed);
                if (j < length) hit[j]++;
            }
            BOOST_CHECK(std::all_of(hit.begin(), hit.end(), [](uint8_t h) { return h == 1; }));
        }
    }
}

BOOST_AUTO_TEST_CASE(unit_float_never_reaches_one) {
    BOOST_CHECK_LT(stipple::detail::unitFloat(~uint64_t(0)), 1.0f);
    BOOST_CHECK_EQUAL(stipple::detail::unitFloat(~uint64_t(0)), 0x1.fffffep-1f);
    BOOST_CHECK_EQUAL(stipple::detail::unitFloat(0), 0.0f);
}
