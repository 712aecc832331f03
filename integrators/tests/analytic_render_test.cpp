// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Analytic renders (as pbrt-v4's integrators_test):
//  - the furnace sphere: camera inside a sphere of albedo 0.5 emitting 0.5 -> radiance exactly 1, for each
//    pattern, path tracer;
//  - a square light over a diffuse plane -> the closed-form radiance albedo * L * F, direct integrator.
// Pass when |mean - expected| <= z * sigma + bias, where sigma bounds the standard deviation of the image mean
// (from per-pixel variances), z is the two-sided normal quantile for alpha = 0.01 Sidak-corrected over the 11
// renders here, and bias is the stated deterministic allowance (0 for the sphere; float32 rounding for the
// truncated sphere, whose every path has the same value; 0.3% for the plane, whose pixels see a patch 0.06 wide
// over which the exact radiance varies by less than 0.1%).
#define BOOST_TEST_MODULE analytic_render
#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <iomanip>
#include <iterator>

using namespace stipple::render;
using namespace stipple::render::test;

namespace {
constexpr int kTests = 11;
} // namespace

BOOST_AUTO_TEST_CASE(furnace_sphere_is_one_for_every_pattern) {
    auto scene = Scene::load(scenePath("furnace-sphere.yaml"));
    double z = sidakZ(0.01, kTests);
    for (const char* pattern : {"independent", "stratified", "poisson", "poisson-seed"}) {
        RenderOptions o;
        o.pattern = pattern;
        o.seed = 7;
        RenderResult r = scene->render(o);
        ImageEstimate e = estimate(r);
        double sigma = std::sqrt(e.variance);
        BOOST_TEST_MESSAGE(pattern << ": mean " << e.mean << " sigma " << sigma);
        BOOST_TEST(r.nonFiniteSamples == 0u);
        BOOST_TEST(sigma > 0.0);
        BOOST_TEST(std::abs(e.mean - 1.0) <= z * sigma,
                   pattern << ": mean " << e.mean << ", expected 1 +- " << z * sigma);
    }
}

BOOST_AUTO_TEST_CASE(furnace_sphere_truncated_depth_matches_geometric_sum) {
    // max_depth 2 (no Russian roulette before bounce 3): 0.5 * (1 + 0.5 + 0.25) = 0.875 for every path, so sigma
    // is only the spread of float32 rounding and the mean may sit a few ulps off 0.875 whatever the samples: a
    // path's value is a chain of ~20 float operations (hit point, frame, cosine, BSDF value over pdf per bounce),
    // each rounded by up to half an ulp, and for a constant integrand those roundings need not cancel. Allowance:
    // 32 ulps of float32 (2^-19, 1.9e-6 relative).
    auto scene = Scene::load(scenePath("furnace-sphere.yaml"));
    RenderOptions o;
    o.maxDepth = 2;
    o.seed = 11;
    RenderResult r = scene->render(o);
    ImageEstimate e = estimate(r);
    double sigma = std::sqrt(e.variance);
    constexpr double kFloatRounding = 0x1p-19 * 0.875;
    BOOST_TEST(std::abs(e.mean - 0.875) <= sidakZ(0.01, kTests) * sigma + kFloatRounding,
               std::setprecision(9) << "mean " << e.mean << " sigma " << sigma);
}

namespace {
double squareLightExpected() {
    auto F = [](double X, double Y) { // corner form factor of a parallel rectangle (X, Y in units of height)
        double a = std::sqrt(1 + X * X), b = std::sqrt(1 + Y * Y);
        return (X / a * std::atan(Y / a) + Y / b * std::atan(X / b)) / (2 * M_PI);
    };
    return 0.5 * 3.0 * 4 * F(0.5, 0.5);
}

void checkMean(const std::string& file, double expected, double relativeBias, uint64_t seed) {
    auto scene = Scene::load(scenePath(file));
    RenderOptions o;
    o.pattern = "independent";
    o.seed = seed;
    RenderResult r = scene->render(o);
    ImageEstimate e = estimate(r);
    double tol = sidakZ(0.01, kTests) * std::sqrt(e.variance) + relativeBias * expected;
    BOOST_TEST_MESSAGE(file << ": mean " << e.mean << " expected " << expected << " +- " << tol);
    BOOST_TEST(r.nonFiniteSamples == 0u);
    BOOST_TEST(std::abs(e.mean - expected) <= tol,
               file << ": mean " << e.mean << ", expected " << expected << " +- " << tol);
}
} // namespace

BOOST_AUTO_TEST_CASE(far_from_origin_square_light_and_furnace) {
    // 1e5 units from the origin (float spacing 0.008 there): offsets must scale, nothing may leak.
    checkMean("quad-light-plane-far.yaml", squareLightExpected(), 0.003, 21);
    checkMean("furnace-sphere-far.yaml", 1.0, 0.0, 22);
}

BOOST_AUTO_TEST_CASE(tiny_sphere_light_cone_sampling) {
    // r = 1e-4, L = 1e8: radiance 0.5 below it; 0.3% allowance for the patch the pixels see.
    checkMean("tiny-sphere-light.yaml", 0.5, 0.003, 23);
}

BOOST_AUTO_TEST_CASE(square_light_over_plane_matches_form_factor) {
    auto F = [](double X, double Y) { // corner form factor of a parallel rectangle (X, Y in units of height)
        double a = std::sqrt(1 + X * X), b = std::sqrt(1 + Y * Y);
        return (X / a * std::atan(Y / a) + Y / b * std::atan(X / b)) / (2 * M_PI);
    };
    double expected = 0.5 * 3.0 * 4 * F(0.5, 0.5);
    auto scene = Scene::load(scenePath("quad-light-plane.yaml"));
    RenderOptions o;
    o.pattern = "independent";
    o.seed = 3;
    RenderResult r = scene->render(o);
    ImageEstimate e = estimate(r);
    double sigma = std::sqrt(e.variance), z = sidakZ(0.01, kTests);
    BOOST_TEST_MESSAGE("plane: mean " << e.mean << " expected " << expected << " sigma " << sigma);
    BOOST_TEST(std::abs(e.mean - expected) <= z * sigma + 0.003 * expected,
               "mean " << e.mean << ", expected " << expected << " +- " << z * sigma + 0.003 * expected);
}

BOOST_AUTO_TEST_CASE(direct_with_four_light_samples) {
    // light_samples: 4 declares b0.light.pos and b0.bsdf.dir with k = 4 and averages them: same closed form.
    std::ifstream in(scenePath("quad-light-plane.yaml"));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    size_t at = text.find("light_samples: 1");
    BOOST_REQUIRE(at != std::string::npos);
    text.replace(at, 16, "light_samples: 4");
    auto scene = Scene::load(writeTempFile("quad-light-plane-k4.yaml", text));
    RenderOptions o;
    o.pattern = "stratified";
    o.spp = 16;
    o.seed = 9;
    RenderResult r = scene->render(o);
    BOOST_TEST(r.layout == "0 pixel 2D x1\n1 b0.light.pos 2D x4\n2 b0.bsdf.dir 2D x4\n");
    ImageEstimate e = estimate(r);
    double expected = squareLightExpected();
    double tol = sidakZ(0.01, kTests) * std::sqrt(e.variance) + 0.003 * expected;
    BOOST_TEST(std::abs(e.mean - expected) <= tol, "mean " << e.mean << ", expected " << expected << " +- " << tol);
}

BOOST_AUTO_TEST_CASE(furnace_sphere_through_a_thin_lens) {
    // A thin-lens camera inside the furnace: still radiance 1; the layout gains "lens" right after "pixel".
    std::ifstream in(scenePath("furnace-sphere.yaml"));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    size_t at = text.find("type: pinhole,");
    BOOST_REQUIRE(at != std::string::npos);
    text.replace(at, 14, "type: thinlens, lens_radius: 0.2, focus_distance: 0.7,");
    auto scene = Scene::load(writeTempFile("furnace-thinlens.yaml", text));
    RenderOptions o;
    o.seed = 13;
    RenderResult r = scene->render(o);
    BOOST_TEST(r.layout.find("0 pixel 2D x1\n1 lens 2D x1\n2 b0.light.pos 2D x1\n") == 0u, r.layout);
    ImageEstimate e = estimate(r);
    double tol = sidakZ(0.01, kTests) * std::sqrt(e.variance);
    BOOST_TEST(std::abs(e.mean - 1.0) <= tol, "mean " << e.mean << ", expected 1 +- " << tol);
}
