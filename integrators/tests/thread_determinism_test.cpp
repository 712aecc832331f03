// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The image is bitwise identical for 1 and 2 threads (every value is a function of (seed, pixel, sample,
// dimension); tiles never share state; splats merge in tile order).
#define BOOST_TEST_MODULE thread_determinism
#include <boost/test/unit_test.hpp>

#include "test_support.h"

using namespace stipple::render;
using namespace stipple::render::test;

namespace {
void checkIdentical(const std::string& scene, const std::string& pattern, const std::string& integrator) {
    RenderOptions o;
    o.pattern = pattern;
    o.integrator = integrator;
    o.seed = 5;
    auto [a, b] = renderWithOneAndTwoThreads(scene, o);
    BOOST_TEST(bitwiseEqual(a.image, b.image), scene << " " << pattern << " " << integrator << ": images differ");
    BOOST_TEST(bitwiseEqual(a.variance, b.variance));
    BOOST_TEST(a.raysTraced == b.raysTraced);
}
} // namespace

BOOST_AUTO_TEST_CASE(path_cornell_box_one_vs_two_threads) { checkIdentical("cornell-box.yaml", "stratified", "path"); }
BOOST_AUTO_TEST_CASE(path_cornell_box_poisson_one_vs_two_threads) {
    checkIdentical("cornell-box.yaml", "poisson", "path");
}
BOOST_AUTO_TEST_CASE(direct_glossy_one_vs_two_threads) {
    checkIdentical("glossy-lights.yaml", "independent", "direct");
}
