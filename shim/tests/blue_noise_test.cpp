// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// ctest-labels: unit;statistical
// blue_noise_test.cpp — what STIPPLE_SAMPLER_FLAG_BLUE_NOISE promises beyond every pixel's set (sobol_pmj02_test).
//
// Deterministic (exact, no alpha): the pixels of a 64 x 64 tile stratify every stratum among themselves
// (stratified, 1D and 2D: each stratum's 4096 points fall in its 4096 sub-cells); every other pattern refuses the
// flag at creation with STIPPLE_ERROR_INVALID_ARGUMENT naming the pattern and the flag (shim_blue_noise_gain
// measured independent's lattice map of the unit square and the others' per-pixel toroidal shift adding
// low-frequency error).
// Statistical (fixed seeds), over images of 128 x 128 pixels, the low-quarter energy of the per-pixel error
// (|f| < 1/8 cycle per pixel, DC excluded) for stratified:
// - on the Gaussian (sigma 0.15) at N = 16 it is >= 10 times below white with the flag (measured 45-590 on these
//   seeds), and the flag does not raise the per-pixel MSE: the flag/plain ratio's lower bound at family-wise
//   alpha = 0.01 (Sidak over the 2 patterns, one-sided) is <= 1. The units of that ratio are 64 x 64 tiles,
//   4 images x 4 tiles per side;
// - on two edges (the slanted step x < 0.3 + 0.4 y and the PMJ paper's quarter disk) at N = 16 and 64, the flag
//   does not add low-frequency error: the gain (low-band energy without / with the flag) is >= 2 and its upper
//   bound at family-wise alpha = 0.01 (Sidak over 2 patterns x 2 integrands x 2 N, one-sided; images are the
//   units, 4 per side) is >= 1. shim_blue_noise_gain measured 4.1-12.6 on these integrands (24 images).
#define BOOST_TEST_MODULE blue_noise
#include <stipple/testing/statistics.h>
#include "sampler_fixture.h"

#include <cmath>
#include <complex>
#include <numbers>
#include <set>

using namespace stipple::testing;
using namespace stipple::test;

namespace {

constexpr uint32_t kBlue = STIPPLE_SAMPLER_FLAG_BLUE_NOISE;

} // namespace

BOOST_AUTO_TEST_CASE(a_tile_of_pixels_stratifies_every_stratum) {
    // stratified N = 16 (1D: 16 strata, 2D: 4 x 4): in a tile, stratum s's points of the 4096 pixels take its 4096
    // sub-cells (2D: 64 x 64, 1D: 4096) once each, whichever map of the 2D family the tile has.
    for (uint32_t pattern : blueNoisePatterns())
        for (uint32_t arity : {1u, 2u}) {
            const uint32_t n = 16;
            const uint32_t strataPerAxis = arity == 1 ? 16 : 4;
            auto s = makeFlagged(pattern, n, 0x711e + arity, arity, kBlue);
            for (uint32_t tile : {0u, 1u, 2u, 3u, 5u, 8u}) {
                // key: (stratum, sub-cell).
                std::set<std::pair<uint32_t, uint32_t>> seen;
                for (uint32_t y = 0; y < 64; ++y)
                    for (uint32_t x = 0; x < 64; ++x) {
                        const std::vector<float> v = fillPixel(s.get(), 64 * tile + x, 64 * (tile + 1) + y, 0);
                        for (uint32_t i = 0; i < n; ++i) {
                            uint32_t stratum = 0, subcell = 0;
                            for (uint32_t c = 0; c < arity; ++c) {
                                const double scaled = double(v[i * arity + c]) * strataPerAxis;
                                const uint32_t cell = uint32_t(scaled);
                                const uint32_t sub = uint32_t((scaled - cell) * (arity == 1 ? 4096 : 64));
                                stratum = stratum * strataPerAxis + cell;
                                subcell = subcell * 64 + sub;
                            }
                            seen.insert({stratum, subcell});
                        }
                    }
                BOOST_CHECK_MESSAGE(seen.size() == size_t(n) * 4096,
                                    patternName(pattern) << " arity " << arity << " tile " << tile << ": "
                                                         << seen.size() << " of " << n * 4096 << " sub-cells");
            }
        }
}

BOOST_AUTO_TEST_CASE(the_flag_is_refused_for_the_patterns_it_cannot_serve) {
    // With a declared layout and streams only (dimension_count 0): the error names the pattern and the flag, no
    // sampler is returned, and the same description without the flag is accepted.
    for (uint32_t pattern : blueNoiseRefused())
        for (uint32_t dimensions : {0u, 1u}) {
            const std::vector<DimensionSpec> layout =
                dimensions ? std::vector<DimensionSpec>{{2, 1}} : std::vector<DimensionSpec>{};
            stipple::Sampler s;
            const stipple::Status refused = createSampler(s, pattern, 16, 0, layout, kBlue);
            BOOST_CHECK_EQUAL(refused.code(), STIPPLE_ERROR_INVALID_ARGUMENT);
            BOOST_CHECK(!s);
            const std::string& message = refused.message();
            BOOST_CHECK_MESSAGE(message.find(std::string("the ") + patternName(pattern) + " pattern") !=
                                        std::string::npos &&
                                    message.find("STIPPLE_SAMPLER_FLAG_BLUE_NOISE") != std::string::npos &&
                                    message.find("\"stratified\"") != std::string::npos,
                                patternName(pattern) << ": " << message);
            BOOST_REQUIRE(createSampler(s, pattern, 16, 0, layout).ok());
        }
    for (uint32_t pattern : blueNoisePatterns()) { // accepted
        auto s = makeFlagged(pattern, 16, 1, 2, kBlue);
        BOOST_CHECK(s.get() != nullptr);
    }
}

namespace {

struct ImageStats {
    std::vector<double> tileMse; // per 64 x 64 tile
    double band = 0, mse = 0;    // mean low-band periodogram value, mean per-pixel MSE
};

struct Integrand2 {
    double (*f)(double x, double y);
    double exact;
};

double centredGaussian(double x, double y) {
    constexpr double kSigma = 0.15;
    const double dx = x - 0.5, dy = y - 0.5;
    return std::exp(-(dx * dx + dy * dy) / (2 * kSigma * kSigma));
}
double centredGaussianIntegral() {
    constexpr double kSigma = 0.15;
    const double g1 = kSigma * std::sqrt(2 * std::numbers::pi) * std::erf(0.5 / (kSigma * std::numbers::sqrt2));
    return g1 * g1;
}
double slantedStep(double x, double y) { return x < 0.3 + 0.4 * y ? 1.0 : 0.0; }                    // integral 1/2
double quarterDisk(double x, double y) { return x * x + y * y < 2 / std::numbers::pi ? 1.0 : 0.0; } // 1/2
// The battery's zone plate: about 10 rings over the square, 2-7 periods across a stratum at N = 16 (aliasing).
double zonePlate(double x, double y) { return 0.5 + 0.5 * std::cos(60 * (x * x + y * y)); }
double zonePlateIntegral() {
    // 0.5 + 0.5 Re((int_0^1 exp(60 i x^2) dx)^2), midpoint rule (the constant only moves the error's DC term, which
    // the low band excludes).
    constexpr int kSteps = 1 << 16;
    std::complex<double> ring = 0;
    for (int i = 0; i < kSteps; ++i) {
        const double x = (i + 0.5) / kSteps;
        ring += std::polar(1.0, 60 * x * x) / double(kSteps);
    }
    return 0.5 + 0.5 * (ring * ring).real();
}

// Per-pixel error of `integrand` over images of 128 x 128 pixels at N samples; the low band's mean periodogram
// value (white noise of variance s^2 has s^2), by a direct DFT at the band's frequencies, overall and per image.
ImageStats measure(uint32_t pattern, uint32_t flags, int images,
                   const Integrand2& integrand = {centredGaussian, centredGaussianIntegral()}, uint32_t n = 16,
                   std::vector<double>* imageBands = nullptr) {
    constexpr int kSize = 128, kBand = 16; // |k| < 16 of 128: |f| < 1/8 cycle per pixel
    const double exact = integrand.exact;
    ImageStats stats;
    int bins = 0;
    for (int image = 0; image < images; ++image) {
        const double bandBefore = stats.band;
        const int binsBefore = bins;
        auto s = makeFlagged(pattern, n, 0xb1e57 + 7919 * uint64_t(image), 2, flags);
        std::vector<double> error(kSize * kSize);
        std::vector<double> tileSum(4, 0.0);
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const std::vector<float> v = fillPixel(s.get(), uint32_t(x), uint32_t(y), 0);
                double sum = 0;
                for (size_t i = 0; i < v.size(); i += 2) sum += integrand.f(v[i], v[i + 1]);
                const double e = sum / double(v.size() / 2) - exact;
                error[size_t(y) * kSize + x] = e;
                tileSum[(y / 64) * 2 + x / 64] += e * e;
            }
        for (double t : tileSum) stats.tileMse.push_back(t / (64 * 64));
        // Rows first: each row's DFT at |kx| < 16, then the columns at |ky| < 16.
        std::vector<std::complex<double>> rows(size_t(kSize) * (2 * kBand - 1));
        for (int y = 0; y < kSize; ++y)
            for (int kx = -kBand + 1; kx < kBand; ++kx) {
                std::complex<double> acc = 0;
                for (int x = 0; x < kSize; ++x)
                    acc += error[size_t(y) * kSize + x] * std::polar(1.0, -2 * std::numbers::pi * kx * x / kSize);
                rows[size_t(y) * (2 * kBand - 1) + size_t(kx + kBand - 1)] = acc;
            }
        for (int ky = -kBand + 1; ky < kBand; ++ky)
            for (int kx = -kBand + 1; kx < kBand; ++kx) {
                if ((kx == 0 && ky == 0) || kx * kx + ky * ky >= kBand * kBand) continue;
                std::complex<double> acc = 0;
                for (int y = 0; y < kSize; ++y)
                    acc += rows[size_t(y) * (2 * kBand - 1) + size_t(kx + kBand - 1)] *
                           std::polar(1.0, -2 * std::numbers::pi * ky * y / kSize);
                stats.band += std::norm(acc) / (kSize * kSize);
                ++bins;
            }
        if (imageBands) imageBands->push_back((stats.band - bandBefore) / (bins - binsBefore));
    }
    stats.band /= bins;
    for (double t : stats.tileMse) stats.mse += t;
    stats.mse /= double(stats.tileMse.size());
    return stats;
}

// Variance of the log of a mean of k samples (delta method).
double logMeanVariance(const std::vector<double>& v, double mean) {
    double s = 0;
    for (double x : v) s += (x - mean) * (x - mean);
    return s / double(v.size() - 1) / double(v.size()) / (mean * mean);
}

} // namespace

BOOST_AUTO_TEST_CASE(the_error_is_blue_at_no_loss_of_per_pixel_mse) {
    constexpr int kImages = 4;
    // One-sided: only a ratio above 1 fails, at family-wise 0.01 over the patterns.
    const double z = sidakZ(0.02, int(blueNoisePatterns().size()));
    for (uint32_t pattern : blueNoisePatterns()) {
        const ImageStats plain = measure(pattern, 0, kImages), blue = measure(pattern, kBlue, kImages);
        const double whiteOverBand = blue.mse / blue.band;
        BOOST_CHECK_MESSAGE(whiteOverBand >= 10, patternName(pattern) << ": low-quarter energy white / measured = "
                                                                      << whiteOverBand << " < 10");
        const double ratio = blue.mse / plain.mse;
        const double se =
            std::sqrt(logMeanVariance(blue.tileMse, blue.mse) + logMeanVariance(plain.tileMse, plain.mse));
        const double low = ratio * std::exp(-z * se);
        BOOST_TEST_MESSAGE(patternName(pattern) << ": white / low band " << whiteOverBand << ", MSE flag / plain "
                                                << ratio << " [" << low << ", " << ratio * std::exp(z * se) << "]");
        BOOST_CHECK_MESSAGE(low <= 1.0, patternName(pattern)
                                            << ": MSE flag / plain " << ratio << ", lower bound " << low << " > 1");
    }
}

BOOST_AUTO_TEST_CASE(the_flag_adds_no_low_frequency_error_on_edges) {
    constexpr int kImages = 4;
    const struct {
        const char* name;
        Integrand2 integrand;
    } edges[] = {{"slanted step", {slantedStep, 0.5}}, {"quarter disk", {quarterDisk, 0.5}}};
    const uint32_t ns[] = {16, 64};
    // One-sided: only a gain significantly below 1 fails, at family-wise 0.01.
    const double z = sidakZ(0.02, int(blueNoisePatterns().size() * std::size(edges) * std::size(ns)));
    for (uint32_t pattern : blueNoisePatterns())
        for (const auto& edge : edges)
            for (uint32_t n : ns) {
                std::vector<double> plainBands, blueBands;
                const ImageStats plain = measure(pattern, 0, kImages, edge.integrand, n, &plainBands);
                const ImageStats blue = measure(pattern, kBlue, kImages, edge.integrand, n, &blueBands);
                const double gain = plain.band / blue.band;
                const double se =
                    std::sqrt(logMeanVariance(plainBands, plain.band) + logMeanVariance(blueBands, blue.band));
                const double high = gain * std::exp(z * se);
                BOOST_TEST_MESSAGE(patternName(pattern) << " " << edge.name << " N=" << n << ": low-band gain " << gain
                                                        << " [" << gain * std::exp(-z * se) << ", " << high << "]");
                BOOST_CHECK_MESSAGE(gain >= 2 && high >= 1, patternName(pattern) << " " << edge.name << " N=" << n
                                                                                 << ": the flag's low-band gain is "
                                                                                 << gain << ", upper bound " << high);
            }
}

// Checkerboards with squares near the sample spacing: a single lattice map sends their error into the low band in
// every tile (the former map: 12 x 12 squares at N = 16 and 24 x 24 at N = 64, 1.25-1.4 times the plain pattern's
// low-band energy); the family of maps hashed per tile (blue_noise.cpp) averages that out. Checked on those two: the
// gain's lower bound at family-wise alpha = 0.01 (Sidak over the 2 cases, one-sided; images the units, 8 per side)
// is >= 1, i.e. the flag lowers their low-frequency error (shim_blue_noise_gain --grown measured 2.25 and 2.64).
double checkerboard12(double x, double y) { return (int(x * 12) + int(y * 12)) % 2 == 1 ? 1.0 : 0.0; } // 1/2
double checkerboard24(double x, double y) { return (int(x * 24) + int(y * 24)) % 2 == 1 ? 1.0 : 0.0; } // 1/2

BOOST_AUTO_TEST_CASE(the_flag_lowers_low_frequency_error_on_checkerboards_at_the_sample_spacing) {
    constexpr int kImages = 8;
    const struct {
        const char* name;
        Integrand2 integrand;
        uint32_t n;
    } cases[] = {{"12 x 12 checkerboard", {checkerboard12, 0.5}, 16}, {"24 x 24 checkerboard", {checkerboard24, 0.5}, 64}};
    const double z = sidakZ(0.02, int(std::size(cases)));
    for (const auto& c : cases) {
        std::vector<double> plainBands, blueBands;
        const ImageStats plain = measure(STIPPLE_PATTERN_STRATIFIED, 0, kImages, c.integrand, c.n, &plainBands);
        const ImageStats blue = measure(STIPPLE_PATTERN_STRATIFIED, kBlue, kImages, c.integrand, c.n, &blueBands);
        const double gain = plain.band / blue.band;
        const double se = std::sqrt(logMeanVariance(plainBands, plain.band) + logMeanVariance(blueBands, blue.band));
        const double low = gain * std::exp(-z * se);
        BOOST_TEST_MESSAGE("stratified " << c.name << " N=" << c.n << ": low-band gain " << gain << " [" << low << ", "
                                         << gain * std::exp(z * se) << "]");
        BOOST_CHECK_MESSAGE(low >= 1, "stratified " << c.name << " N=" << c.n << ": the flag's low-band gain is " << gain
                                                    << ", lower bound " << low << " < 1");
    }
}

// Aliasing: on the zone plate at N = 16 the lattice that minimised only the smooth (Taylor) share added low-frequency
// error (shim_blue_noise_gain, 64 images: stratified 0.93 [0.90, 0.96]); the later single map measured 1.57
// [1.52, 1.61], the family of maps 1.35 [1.25, 1.45] (12 images). Checked: the gain's upper bound at family-wise
// alpha = 0.01 (Sidak over the flag's patterns, one-sided; images the units, 8 per side) is >= 1, and stratified's
// gain is >= 1.2 (the first lattice's 0.93 fails it).
BOOST_AUTO_TEST_CASE(the_flag_adds_no_low_frequency_error_on_the_zone_plate) {
    constexpr int kImages = 8;
    const Integrand2 zone{zonePlate, zonePlateIntegral()};
    const double z = sidakZ(0.02, int(blueNoisePatterns().size()));
    for (uint32_t pattern : blueNoisePatterns()) {
        std::vector<double> plainBands, blueBands;
        const ImageStats plain = measure(pattern, 0, kImages, zone, 16, &plainBands);
        const ImageStats blue = measure(pattern, kBlue, kImages, zone, 16, &blueBands);
        const double gain = plain.band / blue.band;
        const double se = std::sqrt(logMeanVariance(plainBands, plain.band) + logMeanVariance(blueBands, blue.band));
        const double high = gain * std::exp(z * se);
        BOOST_TEST_MESSAGE(patternName(pattern) << " zone plate N=16: low-band gain " << gain << " ["
                                                << gain * std::exp(-z * se) << ", " << high << "]");
        BOOST_CHECK_MESSAGE(high >= 1, patternName(pattern) << " zone plate: the flag's low-band gain is " << gain
                                                            << ", upper bound " << high);
        if (pattern == STIPPLE_PATTERN_STRATIFIED)
            BOOST_CHECK_MESSAGE(gain >= 1.2, "stratified zone plate: the flag's low-band gain is " << gain);
    }
}
