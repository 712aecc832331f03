// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// BDPT on the analytic furnace: a camera inside a sphere of albedo 0.5 whose inside emits
// 0.5 sees radiance sum_{k=0..D} 0.5 * 0.5^k = 1 - 0.5^(D+1) at max depth D (BDPT has no Russian roulette, so
// the truncation is exact). Pinhole camera, and a thin lens (lens density, importance and raster projection of
// the light-tracing strategy t = 1).
// Bound: K = 6 renders per case (different seeds); the image mean must lie within t * s / sqrt(K) of the exact
// value, t the two-sided Student quantile (K - 1 degrees of freedom) for alpha = 0.01 Sidak-corrected over the
// 4 cases here; and the spread itself must be small (s / sqrt(K) < 0.5% of the value), so the bound is tight.
#define BOOST_TEST_MODULE bdpt_analytic
#include <boost/test/unit_test.hpp>

#include "bdpt_test_support.h"

using namespace stipple::render;
using namespace stipple::render::test;

namespace {
constexpr int kCases = 4;
constexpr int kRenders = 6;

void checkFurnace(const std::string& file, int maxDepth, uint64_t seed) {
    auto scene = Scene::load(scenePath(file));
    RenderOptions o;
    o.integrator = "bdpt";
    o.pattern = "stratified";
    o.maxDepth = maxDepth;
    o.spp = 16;
    o.width = o.height = 16;
    SeedRenders s = renderSeeds(*scene, o, kRenders, seed);
    BlockEstimate e = blockEstimate(s, 0, 0, 16, 16);
    double expected = 1 - std::pow(0.5, maxDepth + 1);
    double sd = std::sqrt(e.varianceOfMean);
    double t = stipple::statistics::studentTCritical(sidak(0.01, kCases), kRenders - 1);
    BOOST_TEST_MESSAGE(file << " D=" << maxDepth << ": mean " << e.mean << " expected " << expected << " +- "
                            << t * sd);
    for (const RenderResult& r : s.renders) BOOST_TEST(r.nonFiniteSamples == 0u);
    BOOST_TEST(sd > 0.0);
    BOOST_TEST(sd < 0.005 * expected, file << ": spread " << sd << " too large for a meaningful bound");
    BOOST_TEST(std::abs(e.mean - expected) <= t * sd, file << " max depth " << maxDepth << ": mean " << e.mean
                                                           << ", expected " << expected << " +- " << t * sd);
}
} // namespace

BOOST_AUTO_TEST_CASE(furnace_pinhole_depth_10) { checkFurnace("furnace-sphere.yaml", 10, 100); }
BOOST_AUTO_TEST_CASE(furnace_pinhole_depth_2) { checkFurnace("furnace-sphere.yaml", 2, 200); }
BOOST_AUTO_TEST_CASE(furnace_thin_lens_depth_10) { checkFurnace("bdpt-furnace-thinlens.yaml", 10, 300); }
BOOST_AUTO_TEST_CASE(furnace_thin_lens_depth_2) { checkFurnace("bdpt-furnace-thinlens.yaml", 2, 400); }
