// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The study's RMS and the reference noise-floor correction on synthetic images with known answers.
#define BOOST_TEST_MODULE validation_image_metrics
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "metrics/image_metrics.h"

using namespace stipple::validation;

namespace {
Image filled(int w, int h, float r, float g, float b) {
    Image im;
    im.width = w;
    im.height = h;
    im.rgb.resize(size_t(w) * h * 3);
    for (size_t i = 0; i < im.rgb.size(); i += 3) {
        im.rgb[i] = r;
        im.rgb[i + 1] = g;
        im.rgb[i + 2] = b;
    }
    return im;
}
} // namespace

BOOST_AUTO_TEST_CASE(rms_sums_channels_and_averages_pixels) {
    // Every pixel differs by (1, 2, 2): Σ_rgb d² = 9, so RMS = 3 (not sqrt(3) as a per-channel RMS would be).
    ImageError e = compareImages(filled(8, 4, 0, 0, 0), filled(8, 4, 1, 2, 2));
    BOOST_CHECK_CLOSE(e.mse, 9.0, 1e-12);
    BOOST_CHECK_CLOSE(e.rms, 3.0, 1e-12);
    BOOST_CHECK_EQUAL(e.pixels, 32u);
    BOOST_CHECK_EQUAL(e.nonFinitePixels, 0u);
}

BOOST_AUTO_TEST_CASE(rms_of_one_differing_pixel) {
    // One pixel of 16 differs by 4 in red: MSE = 16/16 = 1.
    Image a = filled(4, 4, 0.5f, 0.5f, 0.5f), b = a;
    b.pixel(2, 3)[0] += 4.0f;
    BOOST_CHECK_CLOSE(compareImages(a, b).rms, 1.0, 1e-6);
}

BOOST_AUTO_TEST_CASE(non_finite_pixels_are_counted_and_excluded) {
    Image a = filled(4, 4, 0, 0, 0), b = filled(4, 4, 1, 0, 0);
    b.pixel(0, 0)[1] = std::numeric_limits<float>::quiet_NaN();
    a.pixel(1, 0)[2] = std::numeric_limits<float>::infinity();
    ImageError e = compareImages(a, b);
    BOOST_CHECK_EQUAL(e.nonFinitePixels, 2u);
    BOOST_CHECK_EQUAL(e.pixels, 14u);
    BOOST_CHECK_CLOSE(e.mse, 1.0, 1e-12);
}

BOOST_AUTO_TEST_CASE(relative_squared_error_weighs_by_brightness_and_caps_outliers) {
    // Reference: a 16 × 8 image at 1, its right half a light at 9: image mean m = 5, weights 1/(1+5)² and 1/(9+5)².
    Image ref = filled(16, 8, 1, 1, 1);
    for (int y = 0; y < 8; ++y)
        for (int x = 8; x < 16; ++x) std::fill(ref.pixel(x, y), ref.pixel(x, y) + 3, 9.0f);
    // The reference's own noise: a variance of 0.01 per channel everywhere (no block noisier than the median).
    const Image variance = filled(16, 8, 0.01f, 0.01f, 0.01f);
    const std::vector<float> w = relativeErrorWeights(ref, variance);
    BOOST_CHECK_CLOSE(w[0], 1.0 / 36, 1e-5);
    BOOST_CHECK_CLOSE(w[15], 1.0 / 196, 1e-5);
    // An error of 1.4 in red on a dark pixel and on a light pixel: 1.96/36 and 1.96/196, in blocks 0 and 1.
    Image im = ref;
    im.pixel(0, 0)[0] += 1.4f;
    im.pixel(8, 0)[0] += 1.4f;
    std::vector<double> b = blockRelativeSquaredErrors(ref, im, w, 0, 0, 16, 8);
    BOOST_REQUIRE_EQUAL(b.size(), 2u);
    BOOST_CHECK_CLOSE(b[0], 1.96 / 36, 1e-3);
    BOOST_CHECK_CLOSE(b[1], 1.96 / 196, 1e-3);
    // A firefly of 1000 on a dark pixel counts 3 · 4² = 48, not 10⁶ / 36.
    im.pixel(3, 3)[1] += 1000.0f;
    b = blockRelativeSquaredErrors(ref, im, w, 0, 0, 16, 8);
    BOOST_CHECK_CLOSE(b[0], 1.96 / 36 + 3 * kRelativeErrorCap * kRelativeErrorCap, 1e-3);
    // The reference's own noise in the same units.
    BOOST_CHECK_CLOSE(relativeNoiseFloor(variance, w, 0, 0, 16, 8), 0.03 * (1.0 / 36 + 1.0 / 196) / 2, 1e-3);
    BOOST_CHECK_THROW(blockRelativeSquaredErrors(ref, im, std::vector<float>(3), 0, 0, 16, 8), std::invalid_argument);
}

// The share of the relative squared error held by block `block` of a 64 × 64 image.
static double blockShare(const std::vector<double>& blocks, size_t block) {
    double total = 0;
    for (double v : blocks) total += v;
    return blocks[block] / total;
}

BOOST_AUTO_TEST_CASE(a_small_lights_edge_cannot_decide_the_relative_error) {
    // A 64 × 64 scene at level 1 with a 2 × 2 light of 100 in block (1, 1); the reference is quiet (variance 1e-4)
    // except in that block, where one sample hits or misses the light (variance 10). A render off by 0.1 in red
    // everywhere, and by 20 on the 16 pixels around the light: those pixels' relative errors (400 / (1 + m)², capped
    // at 48) are thousands of times the others' (0.01 / (1 + m)²).
    Image ref = filled(64, 64, 1, 1, 1), noise = filled(64, 64, 1e-4f, 1e-4f, 1e-4f), im = ref;
    for (int y = 10; y < 12; ++y)
        for (int x = 10; x < 12; ++x) std::fill(ref.pixel(x, y), ref.pixel(x, y) + 3, 100.0f);
    for (int y = 8; y < 16; ++y)
        for (int x = 8; x < 16; ++x) std::fill(noise.pixel(x, y), noise.pixel(x, y) + 3, 10.0f);
    im = ref;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) im.pixel(x, y)[0] += 0.1f;
    for (int y = 9; y < 13; ++y)
        for (int x = 9; x < 13; ++x)
            if (x == 9 || x == 12 || y == 9 || y == 12) im.pixel(x, y)[1] += 20.0f;
    const size_t edge = 1 * 8 + 1; // block (1, 1) of 8 × 8
    // Without the reference's noise (a quiet variance image everywhere) the edge block holds nearly all of it.
    const Image quiet = filled(64, 64, 1e-4f, 1e-4f, 1e-4f);
    const double before =
        blockShare(blockRelativeSquaredErrors(ref, im, relativeErrorWeights(ref, quiet), 0, 0, 64, 64), edge);
    BOOST_CHECK_GT(before, 0.9);
    // With it, the block counts by its error relative to its own noise, as one block of 64.
    const std::vector<float> w = relativeErrorWeights(ref, noise);
    const double after = blockShare(blockRelativeSquaredErrors(ref, im, w, 0, 0, 64, 64), edge);
    BOOST_CHECK_LT(after, 1.0 / 64);
    // Quiet blocks keep 1 / (r̄ + m)²: the median block's noise is theirs.
    const std::vector<float> plain = relativeErrorWeights(ref, quiet);
    BOOST_CHECK_EQUAL(w[0], plain[0]);
    BOOST_CHECK_LT(w[size_t(9) * 64 + 9], plain[size_t(9) * 64 + 9] * 1e-3);
    BOOST_CHECK_THROW(relativeErrorWeights(ref, filled(32, 64, 0, 0, 0)), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(size_mismatch_is_a_clear_error) {
    try {
        compareImages(filled(4, 4, 0, 0, 0), filled(4, 5, 0, 0, 0));
        BOOST_FAIL("no exception");
    } catch (const std::invalid_argument& e) {
        BOOST_CHECK(std::string(e.what()).find("4x4") != std::string::npos);
        BOOST_CHECK(std::string(e.what()).find("4x5") != std::string::npos);
    }
}

BOOST_AUTO_TEST_CASE(noise_floor_correction_recovers_the_true_error) {
    // Truth T; reference R = T + noise of variance vr per channel (its variance image says vr);
    // image I = T + noise of variance vi. E[MSE(R, I)] = 3 (vr + vi); the floor is 3 vr, so the corrected
    // MSE estimates 3 vi. 256×256×3 draws put the estimate within ~1% (5 standard errors below 3%).
    const int w = 256, h = 256;
    const double vr = 0.02, vi = 0.05;
    std::mt19937_64 rng(12345);
    std::normal_distribution<double> nr(0.0, std::sqrt(vr)), ni(0.0, std::sqrt(vi));
    std::uniform_real_distribution<double> u(0.0, 2.0);
    Image ref = filled(w, h, 0, 0, 0), img = ref, var = filled(w, h, float(vr), float(vr), float(vr));
    for (size_t i = 0; i < ref.rgb.size(); ++i) {
        double t = u(rng);
        ref.rgb[i] = float(t + nr(rng));
        img.rgb[i] = float(t + ni(rng));
    }
    double floor = noiseFloor(var);
    BOOST_CHECK_CLOSE(floor, 3 * vr, 1e-4);
    ImageError e = compareImages(ref, img);
    BOOST_CHECK_CLOSE(e.mse, 3 * (vr + vi), 3.0);
    double corrected = correctedMse(e.mse, floor);
    BOOST_CHECK_CLOSE(corrected, 3 * vi, 3.0);
    BOOST_CHECK(!floorLimited(corrected, floor)); // 0.15 > 2 × 0.06
    BOOST_CHECK(floorLimited(correctedMse(3 * vr * 1.5, floor), floor));
    BOOST_CHECK_EQUAL(correctedMse(0.01, 0.02), 0.0); // never negative
}

BOOST_AUTO_TEST_CASE(crop_is_clamped_and_magnified) {
    Image a = filled(10, 6, 0, 0, 0);
    a.pixel(9, 5)[0] = 7.0f;
    Image c = cropImage(a, 8, 4, 4, 4, 3); // clamped to x 6..9, y 2..5
    BOOST_CHECK_EQUAL(c.width, 12);
    BOOST_CHECK_EQUAL(c.height, 12);
    BOOST_CHECK_EQUAL(c.pixel(11, 11)[0], 7.0f);
    BOOST_CHECK_EQUAL(c.pixel(9, 9)[0], 7.0f);
    BOOST_CHECK_EQUAL(c.pixel(8, 8)[0], 0.0f);
}

BOOST_AUTO_TEST_CASE(an_image_with_too_many_non_finite_pixels_is_not_measured) {
    // kMaxNonFinitePixelShare (1%) of 10 000 pixels: 100 may be NaN, 101 may not; none finite is never measured.
    Image ref, img;
    ref.width = img.width = 100;
    ref.height = img.height = 100;
    ref.rgb.assign(100 * 100 * 3, 1.0f);
    img.rgb.assign(100 * 100 * 3, 1.5f);
    for (int i = 0; i < 100; ++i) img.rgb[size_t(i) * 3] = std::nanf("");
    ImageError e = compareImages(ref, img);
    BOOST_CHECK_EQUAL(e.nonFinitePixels, 100u);
    BOOST_CHECK_EQUAL(unmeasurableWhy(e), "");
    img.rgb[100 * 3 + 1] = std::numeric_limits<float>::infinity();
    e = compareImages(ref, img);
    BOOST_CHECK(unmeasurableWhy(e).find("101 of 10000 pixels are not finite") != std::string::npos);
    ref.rgb[5000 * 3] = std::nanf(""); // the reference's own count as well
    BOOST_CHECK(unmeasurableWhy(compareImages(ref, img)).find("102 of 10000") != std::string::npos);
    img.rgb.assign(img.rgb.size(), std::nanf(""));
    e = compareImages(ref, img);
    BOOST_CHECK(std::isnan(e.mse));
    BOOST_CHECK(unmeasurableWhy(e).find("no pixel is finite") != std::string::npos);
    BOOST_CHECK(std::isnan(correctedMse(e.mse, 0.01)));
}
