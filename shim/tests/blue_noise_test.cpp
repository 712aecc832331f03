// ctest-labels: unit;statistical
// blue_noise_test.cpp — what STIPPLE_SAMPLER_FLAG_BLUE_NOISE promises beyond every pixel's set (sobol_pmj02_test).
//
// Deterministic (exact, no alpha): the pixels of a 64 x 64 tile stratify every stratum among themselves
// (stratified and independent, 1D and 2D: each stratum's 4096 points fall in its 4096 sub-cells); for the base-set
// patterns every pixel of a tile serves the same set, toroidally shifted.
// Statistical (fixed seeds): on the Gaussian (sigma 0.15) in every pixel of 128 x 128 images at N = 16, for every
// pattern but poisson-seed, the low-quarter energy of the per-pixel error (|f| < 1/8 cycle per pixel, white /
// measured) is >= 10 with the flag (measured 45-590 on these seeds: the margin is >= 4x), and the flag does not
// raise the per-pixel MSE: the flag/plain ratio's lower bound at family-wise alpha = 0.01 (Sidak over the 5
// patterns, one-sided) is <= 1. The units of that ratio are 64 x 64 tiles (independent with the flag: each has
// its own offsets and base set), 4 images x 4 tiles per side.
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
    // stratified N = 16 (1D: 16 strata, 2D: 4 x 4) and independent N = 4 (per point index, the unit square): in
    // a tile, stratum s's points of the 4096 pixels take its 4096 sub-cells (2D: 64 x 64, 1D: 4096) once each.
    for (uint32_t pattern : {uint32_t(STIPPLE_PATTERN_STRATIFIED), uint32_t(STIPPLE_PATTERN_INDEPENDENT)})
        for (uint32_t arity : {1u, 2u}) {
            const uint32_t n = pattern == STIPPLE_PATTERN_STRATIFIED ? 16 : 4;
            const uint32_t strataPerAxis = pattern == STIPPLE_PATTERN_INDEPENDENT ? 1 : arity == 1 ? 16 : 4;
            auto s = makeFlagged(pattern, n, 0x711e + arity, arity, kBlue);
            for (uint32_t tile : {0u, 3u}) {
                // key: (stratum, sub-cell); stratum = point index for independent, the cell for stratified.
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
                            if (pattern == STIPPLE_PATTERN_INDEPENDENT) stratum = i;
                            seen.insert({stratum, subcell});
                        }
                    }
                BOOST_CHECK_MESSAGE(seen.size() == size_t(n) * 4096,
                                    patternName(pattern) << " arity " << arity << " tile " << tile << ": "
                                                         << seen.size() << " of " << n * 4096 << " sub-cells");
            }
        }
}

BOOST_AUTO_TEST_CASE(the_pixels_of_a_tile_shift_one_set) {
    // poisson, pmj02, sobol: pixel p's point i minus pixel q's point i (mod 1) is the same for every i, in a tile.
    for (uint32_t pattern :
         {uint32_t(STIPPLE_PATTERN_POISSON), uint32_t(STIPPLE_PATTERN_PMJ02), uint32_t(STIPPLE_PATTERN_SOBOL)}) {
        auto s = makeFlagged(pattern, 64, 0x5b1f, 2, kBlue);
        const std::vector<float> a = fillPixel(s.get(), 128, 64, 0);
        for (uint32_t x : {129u, 150u, 191u}) {
            const std::vector<float> b = fillPixel(s.get(), x, 127, 0);
            for (uint32_t c = 0; c < 2; ++c) {
                const auto wrapped = [](double d) { return d - std::floor(d); };
                const double d0 = wrapped(double(b[c]) - a[c]);
                double worst = 0;
                for (uint32_t i = 1; i < 64; ++i) {
                    const double d = wrapped(double(b[2 * i + c]) - a[2 * i + c] - d0 + 0.5) - 0.5;
                    worst = std::max(worst, std::abs(d));
                }
                BOOST_CHECK_MESSAGE(worst < 0x1p-22, patternName(pattern) << " pixel " << x << " axis " << c
                                                                          << ": shift varies by " << worst);
            }
        }
    }
}

namespace {

struct ImageStats {
    std::vector<double> tileMse; // per 64 x 64 tile
    double band = 0, mse = 0;    // mean low-band periodogram value, mean per-pixel MSE
};

// Per-pixel error of the Gaussian over images of 128 x 128 pixels; the low band's mean periodogram value (white
// noise of variance s^2 has s^2), by a direct DFT at the band's frequencies.
ImageStats measure(uint32_t pattern, uint32_t flags, int images) {
    constexpr int kSize = 128, kBand = 16; // |k| < 16 of 128: |f| < 1/8 cycle per pixel
    constexpr double kSigma = 0.15;
    const double g1 = kSigma * std::sqrt(2 * std::numbers::pi) * std::erf(0.5 / (kSigma * std::numbers::sqrt2));
    const double exact = g1 * g1;
    ImageStats stats;
    int bins = 0;
    for (int image = 0; image < images; ++image) {
        auto s = makeFlagged(pattern, 16, 0xb1e57 + 7919 * uint64_t(image), 2, flags);
        std::vector<double> error(kSize * kSize);
        std::vector<double> tileSum(4, 0.0);
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const std::vector<float> v = fillPixel(s.get(), uint32_t(x), uint32_t(y), 0);
                double sum = 0;
                for (size_t i = 0; i < v.size(); i += 2) {
                    const double dx = v[i] - 0.5, dy = v[i + 1] - 0.5;
                    sum += std::exp(-(dx * dx + dy * dy) / (2 * kSigma * kSigma));
                }
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
    const uint32_t patterns[] = {STIPPLE_PATTERN_INDEPENDENT, STIPPLE_PATTERN_STRATIFIED, STIPPLE_PATTERN_POISSON,
                                 STIPPLE_PATTERN_SOBOL, STIPPLE_PATTERN_PMJ02};
    // One-sided: only a ratio above 1 fails, at family-wise 0.01 over the 5 patterns.
    const double z = sidakZ(0.02, 5);
    for (uint32_t pattern : patterns) {
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
