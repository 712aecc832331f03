// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// FLIP's documented behaviour (Andersson et al. 2020): zero for identical images, values in [0, 1] with the
// maximum for green against blue, symmetric, invisible detail (high frequency at a large viewing distance)
// suppressed by the contrast sensitivity filters, and colour errors amplified where features differ.
#define BOOST_TEST_MODULE validation_flip
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <random>

#include "metrics/flip.h"

using namespace stipple::validation;

namespace {
Image uniform(int w, int h, float r, float g, float b) {
    Image im;
    im.width = w;
    im.height = h;
    for (int i = 0; i < w * h; ++i) im.rgb.insert(im.rgb.end(), {r, g, b});
    return im;
}
} // namespace

BOOST_AUTO_TEST_CASE(default_pixels_per_degree_is_67) { BOOST_CHECK_CLOSE(kFlipDefaultPixelsPerDegree, 67.02, 0.01); }

BOOST_AUTO_TEST_CASE(identical_images_have_zero_error) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0, 1);
    Image a = uniform(24, 20, 0, 0, 0);
    for (float& v : a.rgb) v = u(rng);
    const FlipMaps m = ldrFlipSrgb(a, a);
    for (float v : m.flip) BOOST_REQUIRE_SMALL(v, 1e-6f);
}

BOOST_AUTO_TEST_CASE(green_against_blue_is_the_largest_difference) {
    // FLIP's colour scale is normalised by the HyAB distance of green and blue (the largest in the unit cube):
    // uniform green against uniform blue is exactly 1, every other pair of the cube's corners less.
    const FlipMaps gb = ldrFlipSrgb(uniform(16, 16, 0, 1, 0), uniform(16, 16, 0, 0, 1));
    BOOST_CHECK_CLOSE(gb.mean(), 1.0, 1e-4);
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) {
            if ((i == 2 && j == 4) || (i == 4 && j == 2)) continue;
            const FlipMaps m = ldrFlipSrgb(uniform(12, 12, i & 1, (i >> 1) & 1, (i >> 2) & 1),
                                           uniform(12, 12, j & 1, (j >> 1) & 1, (j >> 2) & 1));
            BOOST_CHECK_LT(m.mean(), 1.0 - 1e-6);
            BOOST_CHECK_GE(m.mean(), 0.0);
            if (i == j) BOOST_CHECK_SMALL(m.mean(), 1e-6);
        }
    // Black against white: uniform images have no features, so FLIP is the colour term alone, which lies in
    // the compressed top band (0.95, 1] (HyAB 100^0.7 ≈ 25 is above 40% of the maximum, ≈ 16.5).
    const FlipMaps bw = ldrFlipSrgb(uniform(12, 12, 0, 0, 0), uniform(12, 12, 1, 1, 1));
    BOOST_CHECK_GT(bw.mean(), 0.95);
    BOOST_CHECK_LT(bw.mean(), 1.0);
}

BOOST_AUTO_TEST_CASE(symmetric) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0, 1);
    Image a = uniform(20, 16, 0, 0, 0), b = a;
    for (float& v : a.rgb) v = u(rng);
    for (float& v : b.rgb) v = u(rng);
    const FlipMaps ab = ldrFlipSrgb(a, b), ba = ldrFlipSrgb(b, a);
    for (size_t i = 0; i < ab.flip.size(); ++i) BOOST_REQUIRE_CLOSE(ab.flip[i], ba.flip[i], 1e-3);
}

BOOST_AUTO_TEST_CASE(viewing_distance_hides_fine_detail) {
    // A one-pixel black/white checkerboard against the grey of the same mean luminance: seen from far (many
    // pixels per degree) the eye averages it away; seen from close, it is plainly different. FLIP must fall with
    // the pixels per degree.
    Image checker = uniform(48, 48, 0, 0, 0), grey = uniform(48, 48, 0, 0, 0);
    const float mid = float(1.055 * std::pow(0.5, 1 / 2.4) - 0.055); // sRGB of linear 0.5
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 48; ++x)
            for (int c = 0; c < 3; ++c) {
                checker.rgb[3 * (y * 48 + x) + c] = float((x + y) & 1);
                grey.rgb[3 * (y * 48 + x) + c] = mid;
            }
    double previous = 2;
    for (double ppd : {4.0, 8.0, 16.0, 32.0, 67.0}) {
        const double e = ldrFlipSrgb(grey, checker, ppd).mean();
        BOOST_TEST_MESSAGE("checker vs grey at " << ppd << " ppd: " << e);
        BOOST_CHECK_LT(e, previous);
        previous = e;
    }
    BOOST_CHECK_GT(ldrFlipSrgb(grey, checker, 4).mean(), 0.4);
    BOOST_CHECK_LT(ldrFlipSrgb(grey, checker).mean(), 0.05); // at the default distance: nearly invisible
}

BOOST_AUTO_TEST_CASE(features_amplify_colour_errors) {
    // An edge present in one image only: the feature term raises FLIP above the colour term there (c^(1-f) ≥ c for
    // c ≤ 1), while on flat areas far from the edge FLIP equals the colour term.
    Image ref = uniform(40, 40, 0.5f, 0.5f, 0.5f), test = ref;
    for (int y = 0; y < 40; ++y)
        for (int x = 20; x < 40; ++x)
            for (int c = 0; c < 3; ++c) test.rgb[3 * (y * 40 + x) + c] = 0.6f;
    const FlipMaps m = ldrFlipSrgb(ref, test);
    for (size_t i = 0; i < m.flip.size(); ++i) BOOST_REQUIRE_GE(m.flip[i] + 1e-6f, m.color[i]);
    const size_t atEdge = 20 * 40 + 20, farAway = 20 * 40 + 39;
    BOOST_CHECK_GT(m.feature[atEdge], 0.1f);
    BOOST_CHECK_GT(m.flip[atEdge], m.color[atEdge] + 0.05f);
    BOOST_CHECK_SMALL(m.feature[farAway], 1e-6f);
    BOOST_CHECK_CLOSE(m.flip[farAway], m.color[farAway], 1e-3);
}

BOOST_AUTO_TEST_CASE(size_mismatch_is_an_error) {
    BOOST_CHECK_THROW(ldrFlipSrgb(uniform(4, 4, 0, 0, 0), uniform(5, 4, 0, 0, 0)), std::invalid_argument);
}
