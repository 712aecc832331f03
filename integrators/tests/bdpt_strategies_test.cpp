// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Each BDPT strategy (s, t) alone, unweighted, estimates all paths of depth s + t - 2 (every strategy can
// sample every such path in a diffuse scene with an area light), and so does the MIS-weighted sum of the
// strategies of that depth ("bdpt:depth=D"). On the diffuse Cornell box at depths 0, 1 and 2 every unweighted
// strategy is compared with the weighted sum, per 8x8 block, by Welch's t-test over K = 6 renders each;
// family-wise alpha = 0.01 Sidak-corrected over every (strategy, block) pair.
#define BOOST_TEST_MODULE bdpt_strategies
#include <boost/test/unit_test.hpp>

#include "bdpt_test_support.h"

using namespace stipple::render;
using namespace stipple::render::test;

namespace {
constexpr int kSize = 24, kBlock = 8, kRenders = 6;
constexpr int kBlocks = (kSize / kBlock) * (kSize / kBlock);
constexpr int kPairs = 2 + 3 + 4; // strategies at depths 0, 1, 2

void checkDepth(int depth, uint64_t seed) {
    auto scene = Scene::load(scenePath("cornell-box.yaml"));
    RenderOptions o;
    o.pattern = "stratified";
    o.maxDepth = depth; // the walks stop there: cheaper, and nothing deeper is asked
    o.width = o.height = kSize;
    o.spp = 16;
    o.integrator = "bdpt:depth=" + std::to_string(depth);
    SeedRenders mis = renderSeeds(*scene, o, kRenders, seed);
    const double alpha = sidak(0.01, kPairs * kBlocks);
    for (int s = 0; s <= depth + 1; ++s) {
        int t = depth + 2 - s;
        o.integrator = "bdpt:s=" + std::to_string(s) + ",t=" + std::to_string(t);
        SeedRenders one = renderSeeds(*scene, o, kRenders, seed + 100 * uint64_t(s + 1));
        for (int by = 0; by < kSize / kBlock; ++by)
            for (int bx = 0; bx < kSize / kBlock; ++bx) {
                BlockEstimate a = blockEstimate(one, bx * kBlock, by * kBlock, kBlock, kBlock);
                BlockEstimate b = blockEstimate(mis, bx * kBlock, by * kBlock, kBlock, kBlock);
                double p = welchTwoSidedP(a, b);
                BOOST_TEST(p >= alpha, o.integrator << " block (" << bx << "," << by << "): " << a.mean << " +- "
                                                    << std::sqrt(a.varianceOfMean) << " vs MIS " << b.mean << " +- "
                                                    << std::sqrt(b.varianceOfMean) << ", p = " << p);
            }
        BlockEstimate a = blockEstimate(one, 0, 0, kSize, kSize), b = blockEstimate(mis, 0, 0, kSize, kSize);
        BOOST_TEST_MESSAGE(o.integrator << ": image mean " << a.mean << " +- " << std::sqrt(a.varianceOfMean)
                                        << ", MIS depth " << depth << ": " << b.mean << " +- "
                                        << std::sqrt(b.varianceOfMean));
        BOOST_TEST(a.mean > 0.0);
    }
}
} // namespace

BOOST_AUTO_TEST_CASE(depth_0_emitters_seen_directly) { checkDepth(0, 1); }
BOOST_AUTO_TEST_CASE(depth_1_direct_lighting) { checkDepth(1, 2); }
BOOST_AUTO_TEST_CASE(depth_2_one_bounce) { checkDepth(2, 3); }
