// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// BDPT and the path tracer estimate the same image: a diffuse Cornell box, a glossy scene (rough plastic and
// rough conductor under a sphere light and a quad light, open to the sky), a Cornell box with a glass and a
// mirror sphere, the Cornell box through a thin lens (defocused: splats must land where the lens projects), and a
// floor lit through a glass ball and seen through it (the paths BDPT splits along specular chains; weighting the
// split samples 1.5x fails it). Each
// image is cut into 8x8 blocks; per block, K = 8 renders of each integrator (different seeds) are compared by Welch's
// t-test (Jung et al. 2020); 2x2 blocks for the thin lens, whose defocus only moves energy by a few pixels. Family-wise
// alpha = 0.01, Sidak-corrected over all blocks of the five scenes.
#define BOOST_TEST_MODULE bdpt_agreement
#include <boost/test/unit_test.hpp>

#include "bdpt_test_support.h"

using namespace stipple::render;
using namespace stipple::render::test;

namespace {
constexpr int kSize = 32, kRenders = 8;
// 8x8 blocks, except 2x2 for the thin lens: defocus moves energy by a few pixels, which large blocks average out.
constexpr int kTests = 4 * (kSize / 8) * (kSize / 8) + (kSize / 2) * (kSize / 2);

void compare(const std::string& file, int maxDepth, uint64_t seed, int kBlock = 8) {
    auto scene = Scene::load(scenePath(file));
    RenderOptions o;
    o.pattern = "stratified";
    o.maxDepth = maxDepth;
    o.width = o.height = kSize;
    o.spp = 16;
    o.integrator = "bdpt";
    SeedRenders bdpt = renderSeeds(*scene, o, kRenders, seed);
    o.integrator = "path";
    o.spp = 32;
    SeedRenders path = renderSeeds(*scene, o, kRenders, seed + 1000);
    for (const RenderResult& r : bdpt.renders) BOOST_TEST(r.nonFiniteSamples == 0u);
    const double alpha = sidak(0.01, kTests);
    double minP = 1;
    for (int by = 0; by < kSize / kBlock; ++by)
        for (int bx = 0; bx < kSize / kBlock; ++bx) {
            BlockEstimate a = blockEstimate(bdpt, bx * kBlock, by * kBlock, kBlock, kBlock);
            BlockEstimate b = blockEstimate(path, bx * kBlock, by * kBlock, kBlock, kBlock);
            double p = welchTwoSidedP(a, b);
            minP = std::min(minP, p);
            BOOST_TEST(p >= alpha, file << " block (" << bx << "," << by << "): bdpt " << a.mean << " +- "
                                        << std::sqrt(a.varianceOfMean) << ", path " << b.mean << " +- "
                                        << std::sqrt(b.varianceOfMean) << ", p = " << p << " < " << alpha);
        }
    BlockEstimate a = blockEstimate(bdpt, 0, 0, kSize, kSize), b = blockEstimate(path, 0, 0, kSize, kSize);
    BOOST_TEST_MESSAGE(file << ": image mean bdpt " << a.mean << " +- " << std::sqrt(a.varianceOfMean) << ", path "
                            << b.mean << " +- " << std::sqrt(b.varianceOfMean) << "; smallest block p " << minP);
    BOOST_TEST(a.mean > 0.01);
}
} // namespace

BOOST_AUTO_TEST_CASE(diffuse_cornell_box) { compare("cornell-box.yaml", 5, 10); }
BOOST_AUTO_TEST_CASE(glossy_plates_two_lights) { compare("glossy-lights.yaml", 4, 20); }
BOOST_AUTO_TEST_CASE(glass_and_mirror_spheres) { compare("bdpt-glass-box.yaml", 6, 30); }
BOOST_AUTO_TEST_CASE(thin_lens_cornell_box) { compare("bdpt-cornell-thinlens.yaml", 5, 40, 2); }
BOOST_AUTO_TEST_CASE(floor_seen_through_glass) { compare("bdpt-glass-view.yaml", 5, 50); }
