// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Stiff and extreme inputs of validation's metrics, through its library API: references of zero,
// images holding inf and NaN (counted and reported, never averaged in), sizes that differ (a clear error), and
// what those do downstream (aggregates, slopes, results.json). Expected outcomes are exact.
#define BOOST_TEST_MODULE validation_stiff_metrics
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <unistd.h>

#include "metrics/image_metrics.h"
#include "run/results.h"

#include <stipple/testing/scratch_folder.h>

using namespace stipple::validation;

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

Image filled(int w, int h, float v) {
    Image im;
    im.width = w;
    im.height = h;
    im.rgb.assign(size_t(w) * h * 3, v);
    return im;
}

void expectInvalid(const Image& a, const Image& b, const std::string& needle) {
    try {
        compareImages(a, b);
        BOOST_ERROR("compareImages accepted: expected an error mentioning " << needle);
    } catch (const std::invalid_argument& e) {
        BOOST_TEST(std::string(e.what()).find(needle) != std::string::npos, e.what());
    }
}

ResultRow row(const std::string& pattern, uint32_t spp, uint64_t seed, double mse) {
    ResultRow r;
    r.scene = "s";
    r.pattern = pattern;
    r.spp = spp;
    r.seed = seed;
    r.width = r.height = 4;
    r.mse = r.mseCorrected = mse;
    r.rms = r.rmsCorrected = std::sqrt(mse);
    r.renderSeconds = 1;
    return r;
}

} // namespace

BOOST_AUTO_TEST_CASE(zero_reference) {
    // Black reference, black image: error exactly 0 over every pixel; a grey image: Σ_rgb 1² = 3 per pixel.
    ImageError e = compareImages(filled(4, 4, 0), filled(4, 4, 0));
    BOOST_TEST(e.mse == 0.0);
    BOOST_TEST(e.rms == 0.0);
    BOOST_TEST(e.pixels == 16u);
    e = compareImages(filled(4, 4, 0), filled(4, 4, 1));
    BOOST_TEST(e.mse == 3.0);
    BOOST_TEST(e.rms == std::sqrt(3.0));
    // Denormals and negative zero are finite values like any other.
    Image tiny = filled(4, 4, -0.0f);
    tiny.pixel(1, 1)[2] = std::numeric_limits<float>::denorm_min();
    e = compareImages(filled(4, 4, 0), tiny);
    BOOST_TEST(e.pixels == 16u);
    BOOST_TEST(e.nonFinitePixels == 0u);
    BOOST_TEST(std::isfinite(e.mse));
    BOOST_TEST(e.mse >= 0.0);
    BOOST_TEST(noiseFloor(filled(4, 4, 0)) == 0.0);
}

BOOST_AUTO_TEST_CASE(inf_and_nan_pixels_are_counted_and_left_out) {
    Image ref = filled(4, 4, 0.5f), img = filled(4, 4, 1.5f); // every finite pixel: Σ_rgb 1² = 3
    img.pixel(0, 0)[0] = kInf;
    img.pixel(1, 0)[1] = -kInf;
    img.pixel(2, 0)[2] = kNaN;
    ref.pixel(3, 3)[0] = kNaN; // a bad reference pixel is left out too
    img.pixel(3, 3)[0] = kNaN; // both bad: still one pixel
    ImageError e = compareImages(ref, img);
    BOOST_TEST(e.nonFinitePixels == 4u);
    BOOST_TEST(e.pixels == 12u);
    BOOST_TEST(e.mse == 3.0); // exactly the finite pixels' value: nothing non-finite averaged in
    // Finite but huge: the difference of two float extremes squares to ~1e77 in double, still finite.
    Image big = filled(2, 2, std::numeric_limits<float>::max()),
          small = filled(2, 2, -std::numeric_limits<float>::max());
    e = compareImages(big, small);
    BOOST_TEST(std::isfinite(e.mse));
    BOOST_TEST(e.nonFinitePixels == 0u);
    // Every pixel non-finite: no pixel is compared, the error is undefined (NaN) and the count says why.
    e = compareImages(filled(2, 2, 0), filled(2, 2, kNaN));
    BOOST_TEST(e.pixels == 0u);
    BOOST_TEST(e.nonFinitePixels == 4u);
    BOOST_TEST(std::isnan(e.mse));
    // The noise floor skips non-finite variance pixels.
    Image var = filled(2, 2, 0.25f);
    var.pixel(1, 1)[1] = kInf;
    BOOST_TEST(noiseFloor(var) == 0.75);
}

BOOST_AUTO_TEST_CASE(different_sizes_and_malformed_images_are_clear_errors) {
    expectInvalid(filled(4, 4, 0), filled(4, 5, 0), "reference is 4x4, image is 4x5");
    expectInvalid(filled(8, 2, 0), filled(2, 8, 0), "reference is 8x2, image is 2x8");
    Image broken = filled(4, 4, 0);
    broken.rgb.pop_back();
    expectInvalid(filled(4, 4, 0), broken, "malformed");
    expectInvalid(filled(0, 0, 0), filled(0, 0, 0), "malformed");
    Image negative;
    negative.width = -4;
    negative.height = -4;
    expectInvalid(negative, negative, "malformed");
    BOOST_CHECK_THROW(noiseFloor(broken), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(zero_and_undefined_errors_downstream) {
    // A pattern that matches the reference exactly (MSE 0) and one whose image was all NaN (MSE NaN):
    // aggregates keep them apart, the slope fit leaves both out and counts them, results.json stays valid.
    std::vector<ResultRow> rows;
    for (uint64_t seed = 1; seed <= 4; ++seed) {
        for (uint32_t spp : {4u, 16u}) {
            rows.push_back(row("exact", spp, seed, 0.0));
            rows.push_back(row("broken", spp, seed, std::nan("")));
            rows.push_back(row("fine", spp, seed, 1.0 / spp));
        }
    }
    Matrix m;
    MatrixScene scene;
    scene.name = "s";
    scene.file = scene.path = "s.yaml";
    scene.width = scene.height = 4;
    m.scenes.push_back(scene);
    m.patterns = {"exact", "broken", "fine"};
    m.spp = {4, 16};
    sortRows(rows, m);
    const auto cells = aggregate(rows);
    const CellAggregate* exact = findCell(cells, "s", "exact", 16);
    BOOST_REQUIRE(exact != nullptr);
    BOOST_TEST(exact->meanMseCorrected == 0.0);
    BOOST_TEST(std::isinf(exact->efficiency)); // 1 / (0 · s): documented as infinite, written as null
    const auto slopes = fitSlopes(rows, m);
    for (const SlopeFit& f : slopes) {
        BOOST_TEST_MESSAGE(f.pattern << ": slope " << f.fit.slope << ", " << f.excluded << " points excluded");
        if (f.pattern == "fine") {
            BOOST_TEST(f.excluded == 0u);
            BOOST_TEST(std::abs(f.fit.slope + 0.5) < 1e-9);
        } else if (f.pattern == "exact") {
            BOOST_TEST(f.excluded == 8u, f.pattern);
        } else { // points without a finite error: no fit at all, never a fit of the others
            BOOST_TEST(std::isnan(f.fit.slope), f.pattern);
        }
    }
    Results results;
    results.matrixName = "stiff";
    results.rows = rows;
    const std::string path =
        (stipple::testing::scratchRoot() / "stiff-results.json")
            .string();
    writeResultsJson(path, results, cells, slopes, Json::array());
    Results back = readResultsJson(path);
    std::filesystem::remove(path);
    BOOST_TEST(back.rows.size() == rows.size());
}
