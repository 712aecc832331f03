// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// BDPT images are bitwise identical for 1 and 2 threads: camera and light subpaths read only the pixel sample's
// shim values, and light-tracing splats go to the tile's own list, merged in tile order after the render.
#define BOOST_TEST_MODULE bdpt_determinism
#include <boost/test/unit_test.hpp>

#include "test_support.h"

using namespace stipple::render;
using namespace stipple::render::test;

namespace {
void checkIdentical(const std::string& file, const std::string& pattern) {
    RenderOptions o;
    o.integrator = "bdpt";
    o.pattern = pattern;
    o.seed = 9;
    auto [a, b] = renderWithOneAndTwoThreads(file, o);
    BOOST_TEST(bitwiseEqual(a.image, b.image), file << " " << pattern << ": images differ");
    BOOST_TEST(bitwiseEqual(a.variance, b.variance));
    BOOST_TEST(a.raysTraced == b.raysTraced);
    BOOST_TEST(a.raysTraced > 0u);
}
} // namespace

BOOST_AUTO_TEST_CASE(cornell_box_stratified) { checkIdentical("cornell-box.yaml", "stratified"); }
BOOST_AUTO_TEST_CASE(glass_box_independent) { checkIdentical("bdpt-glass-box.yaml", "independent"); }
BOOST_AUTO_TEST_CASE(thin_lens_furnace_poisson) { checkIdentical("bdpt-furnace-thinlens.yaml", "poisson"); }
