// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Light-only, BSDF-only and MIS direct lighting estimate the same image on a glossy scene (rough plastic and
// rough conductor lit by a sphere light and a quad light). Compared per block of 8x8 pixels by a two-sample
// z-test (Welch's test with large samples; Jung et al. 2020) on the block means, alpha = 0.01 Sidak-corrected over
// 3 pairs x 9 blocks. The independent pattern keeps the per-pixel variance estimates unbiased.
#define BOOST_TEST_MODULE mis_agreement
#include <boost/test/unit_test.hpp>

#include "test_support.h"

using namespace stipple::render;
using namespace stipple::render::test;

BOOST_AUTO_TEST_CASE(light_bsdf_and_mis_agree) {
    auto scene = Scene::load(scenePath("glossy-lights.yaml"));
    RenderOptions o;
    o.pattern = "independent";
    o.spp = 128;
    RenderResult r[3];
    const char* names[3] = {"direct", "direct-light", "direct-bsdf"};
    for (int i = 0; i < 3; ++i) {
        o.integrator = names[i];
        o.seed = 100 + uint64_t(i);
        r[i] = scene->render(o);
        BOOST_TEST(r[i].nonFiniteSamples == 0u);
    }
    const int block = 8, blocks = 3;
    double z = sidakZ(0.01, 3 * blocks * blocks);
    int compared = 0;
    for (int by = 0; by < blocks; ++by)
        for (int bx = 0; bx < blocks; ++bx) {
            ImageEstimate e[3];
            for (int i = 0; i < 3; ++i) e[i] = estimate(r[i], bx * block, by * block, block, block);
            for (int i = 0; i < 3; ++i)
                for (int j = i + 1; j < 3; ++j) {
                    double s = std::sqrt(e[i].variance + e[j].variance);
                    if (s == 0) {
                        BOOST_TEST(e[i].mean == e[j].mean);
                        continue;
                    }
                    ++compared;
                    BOOST_TEST(std::abs(e[i].mean - e[j].mean) <= z * s,
                               names[i] << " vs " << names[j] << " block (" << bx << "," << by << "): " << e[i].mean
                                        << " vs " << e[j].mean << ", |z| = " << std::abs(e[i].mean - e[j].mean) / s
                                        << " > " << z);
                }
        }
    BOOST_TEST(compared > 20);
    // MIS should not be noisier than the worse single technique over the whole image.
    ImageEstimate all[3];
    for (int i = 0; i < 3; ++i) all[i] = estimate(r[i]);
    BOOST_TEST_MESSAGE("image means: mis " << all[0].mean << " light " << all[1].mean << " bsdf " << all[2].mean);
    BOOST_TEST(all[0].variance <= std::max(all[1].variance, all[2].variance));
    BOOST_TEST(all[0].mean > 0.01);
}
