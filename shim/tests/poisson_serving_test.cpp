// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// poisson_serving_test.cpp — serving keeps what generation made: a served pixel set has exactly M points, all
// distinct, and the relative radius rho of the stored set it came from (the torus maps are isometries; a 2D cell
// lattice's within-cell rotation keeps at least its worst-case rho, which the stored set measures); the cache stays
// within its byte bound; 2D cell lattices keep every sample uniform and beat stratified on non-periodic integrands;
// 1D sets hold against stratified on a kink and a peak at small N.
// The quality of the toroidal stored sets is tested by the pointsets_* tests.
#define BOOST_TEST_MODULE poisson_serving
#include "patterns.h"
#include "sampler_fixture.h"
#include <stipple/testing/statistics.h>

#include "hash.h"
#include "pointsets/pointsets.h"
#include "poisson_cache.h"

#include <cmath>
#include <set>
#include <tuple>

using namespace stipple::test;

namespace {

// Served coordinates are rounded to float once more than stored ones (s + x), by at most 2^-24 each: a distance moves
// by at most 2 sqrt(arity) 2^-24, i.e. rho by that over d_max (2.4e-4 at N = 1000 in 1D, where d_max = 1/N).
double rhoTolerance(double rho, uint32_t arity, uint32_t n) {
    return 1e-4 * rho +
           2.0 * std::sqrt(double(arity)) * 0x1p-24 / stipple::detail::pointsets::maxPackingDistance(int(arity), n);
}

void checkServedRho(uint32_t pattern, uint32_t arity, uint32_t n, uint32_t pixelX) {
    const uint64_t seed = 31337;
    auto s = makeSampler(pattern, n, seed, {{arity, 1}});
    const std::vector<float> served = fillPixel(s.get(), pixelX, 5, 0);
    BOOST_REQUIRE_EQUAL(served.size(), size_t(n) * arity);

    std::set<std::tuple<float, float, float>> distinct;
    for (uint32_t p = 0; p < n; ++p)
        distinct.insert(
            {served[p * arity], arity > 1 ? served[p * arity + 1] : 0.f, arity > 2 ? served[p * arity + 2] : 0.f});
    BOOST_CHECK_EQUAL(distinct.size(), n);

    std::vector<float> stored;
    bool cellLattice = false;
    if (pattern == STIPPLE_PATTERN_POISSON) {
        const uint64_t key = stipple::detail::setKey(seed, stipple::detail::HashDomain::Poisson, pixelX, 5, 0);
        auto family = stipple::detail::PoissonCache::global().acquire(arity, n);
        const uint32_t j = stipple::detail::poissonSetIndex(key, family->setCount());
        stored.assign(family->set(j), family->set(j) + size_t(n) * arity);
        cellLattice = arity > 1 && family->cells(j)[0] != 0;
    } else {
        const uint64_t key = stipple::detail::setKey(seed, stipple::detail::HashDomain::PoissonSeed, pixelX, 5, 0);
        stored = stipple::detail::pointsets::generatePoissonSeed(int(arity), n, stipple::detail::hashAt(key, 6));
    }
    const double rhoStored = stipple::detail::pointsets::relativeRadius(int(arity), stored.data(), n);
    const double rhoServed = stipple::detail::pointsets::relativeRadius(int(arity), served.data(), n);
    if (cellLattice) {
        // The stored lattice (no rotation) attains its worst case up to the face margin (cell_lattice.cpp: offsets
        // mapped into [m, 1 - m], moving rho by at most 0.003); a rotation keeps or widens the lattice's distances.
        BOOST_CHECK_MESSAGE(rhoServed >= rhoStored - 0.003 - rhoTolerance(rhoStored, arity, n) && rhoServed >= 0.80,
                            "poisson cell lattice arity " << arity << " N=" << n << ": served rho " << rhoServed
                                                          << ", stored rho " << rhoStored);
        return;
    }
    BOOST_CHECK_MESSAGE(std::abs(rhoServed - rhoStored) <= rhoTolerance(rhoStored, arity, n),
                        patternName(pattern) << " arity " << arity << " N=" << n << ": served rho " << rhoServed
                                             << ", stored rho " << rhoStored);
}

} // namespace

BOOST_AUTO_TEST_CASE(served_sets_keep_rho) {
    for (uint32_t pattern : {STIPPLE_PATTERN_POISSON, STIPPLE_PATTERN_POISSON_SEED})
        for (uint32_t arity = 1; arity <= 3; ++arity)
            for (uint32_t n : {2u, 13u, 64u, 256u, 1000u, 4096u})
                for (uint32_t pixel = 0; pixel < 4; ++pixel) checkServedRho(pattern, arity, n, pixel);
}

BOOST_AUTO_TEST_CASE(pixels_get_different_sets) {
    auto s = makeSampler(STIPPLE_PATTERN_POISSON, 64, 1, {{2, 1}});
    const std::vector<float> a = fillPixel(s.get(), 0, 0, 0), b = fillPixel(s.get(), 1, 0, 0);
    uint32_t same = 0;
    for (size_t i = 0; i < a.size(); ++i) same += a[i] == b[i];
    BOOST_CHECK_LT(same, 4u);
}

BOOST_AUTO_TEST_CASE(cache_stays_within_its_bound) {
    auto& cache = stipple::detail::PoissonCache::global();
    // 2D families of >= 8192 points hold 32 sets of >= 64 KiB: about 2 MiB each (capacity, counted before any set
    // is generated). Acquiring 48 of them (~96 MiB) must evict down to the 64 MiB bound.
    std::vector<std::shared_ptr<const stipple::detail::PoissonFamily>> held;
    for (uint32_t i = 0; i < 48; ++i) {
        auto family = cache.acquire(2, 8192 + i);
        BOOST_CHECK_EQUAL(family->setCount(), stipple::detail::PoissonCache::setCountFor(2, 8192 + i));
        BOOST_CHECK_LE(cache.bytesHeld(), stipple::detail::PoissonCache::kByteBudget);
        if (i < 40) held.push_back(family); // held families cannot be evicted ...
    }
    // ... so once the held ones fill the budget, further families are private and the bound still holds.
    BOOST_CHECK_LE(cache.bytesHeld(), stipple::detail::PoissonCache::kByteBudget);
    BOOST_CHECK_GE(cache.bytesHeld(),
                   stipple::detail::PoissonCache::kByteBudget - 4 * stipple::detail::PoissonCache::kFamilyBytes);
    held.clear();
    auto again = cache.acquire(2, 9000); // now unheld families can be evicted to make room
    BOOST_CHECK_LE(cache.bytesHeld(), stipple::detail::PoissonCache::kByteBudget);
    BOOST_CHECK_EQUAL(stipple::detail::PoissonCache::setCountFor(2, 1u << 22), 1u);
    BOOST_CHECK_EQUAL(stipple::detail::PoissonCache::setCountFor(1, 16),
                      stipple::detail::PoissonCache::kMaxSetsPerFamily);
}

// 1D poisson holds on smooth non-periodic integrands: sets of one point per cell served with whole-cell shifts put
// no seam inside the domain. exp(-x) and the ramp x at N = 64 over 256 pixels (fixed seed): measured MSE ratios to
// stratified 0.035 and 0.017 (shim_battery, 400 pixels); the check asks for < 0.5, which a ratio of 1 would pass
// with probability ~1e-8 at 256 pixels (relative standard error of each MSE estimate sqrt(2/256) = 0.09 for
// Gaussian errors, so log(0.5) is 5.5 standard errors of the log ratio).
// (A randomly shifted lattice, the 1D maximin set, gives 62x on exp(-x) at this N: its common offset is coherent.)
BOOST_AUTO_TEST_CASE(one_dimensional_poisson_beats_stratified_on_non_periodic_integrands) {
    constexpr uint32_t kN = 64, kPixels = 256;
    const auto mse = [&](uint32_t pattern, double (*f)(double), double integral) {
        auto s = makeSampler(pattern, kN, 2024, {{1, 1}});
        double sum = 0.0;
        for (uint32_t p = 0; p < kPixels; ++p) {
            const std::vector<float> x = fillPixel(s.get(), p % 16, p / 16, 0);
            double estimate = 0.0;
            for (float v : x) estimate += f(v);
            const double e = estimate / kN - integral;
            sum += e * e;
        }
        return sum / kPixels;
    };
    const auto expMinus = [](double x) { return std::exp(-x); };
    const auto ramp = [](double x) { return x; };
    for (auto [f, integral, name] :
         {std::tuple<double (*)(double), double, const char*>{expMinus, 1.0 - std::exp(-1.0), "exp(-x)"},
          {ramp, 0.5, "x"}}) {
        const double ratio = mse(STIPPLE_PATTERN_POISSON, f, integral) / mse(STIPPLE_PATTERN_STRATIFIED, f, integral);
        BOOST_TEST_MESSAGE("1D " << name << " N=" << kN << ": poisson / stratified MSE " << ratio);
        BOOST_CHECK_LT(ratio, 0.5);
    }
}

// 1D poisson below 64 points mixes offset steps near 1/2 over its family (cell_set_1d.cpp) so as not to lose to
// stratified on kinks and peaks about a cell wide, where the step 0.809 it used everywhere lost (exact MSE ratios on
// the Genz kink 1.37, 1.66, 1.46 at N = 16, 24, 32). Two non-periodic integrands of the battery's Genz families at
// its difficulties, the kink exp(-20.4 |x - u|) and the product peak 1 / (7.25^-2 + (x - u)^2), centres cycling over
// eight fixed values, N = 16, 24, 32, 4096 pixels per pattern (fixed seed). Measured over 20 seeds: mean ratios
// 0.41-1.10 (the kink at N = 16 the highest, largest single seed 1.17), the standard deviation of the log ratio
// 0.020-0.031; the check asks for <= 1.3, more than 5 standard deviations above the highest mean (one-sided alpha
// < 1e-6 per case). The former sets measured 1.55, 1.36, 1.79 on the kink (N = 16, 24, 32).
BOOST_AUTO_TEST_CASE(one_dimensional_poisson_holds_against_stratified_at_small_n) {
    constexpr uint32_t kPixels = 4096;
    constexpr double kCentres[8] = {0.137, 0.911, 0.452, 0.608, 0.263, 0.785, 0.034, 0.329};
    struct Genz {
        const char* name;
        double (*f)(double x, double u);
        double (*integral)(double u);
    };
    const Genz integrands[] = {
        {"kink", [](double x, double u) { return std::exp(-20.4 * std::abs(x - u)); },
         [](double u) { return (2.0 - std::exp(-20.4 * u) - std::exp(-20.4 * (1.0 - u))) / 20.4; }},
        {"product peak", [](double x, double u) { return 1.0 / (1.0 / (7.25 * 7.25) + (x - u) * (x - u)); },
         [](double u) { return 7.25 * (std::atan(7.25 * (1.0 - u)) + std::atan(7.25 * u)); }},
    };
    // The steps' mix is by counts of a family's 32 sets (cell_set_1d.cpp): 1D families below 64 points hold 32.
    for (uint32_t n = 8; n < 64; ++n) BOOST_REQUIRE_EQUAL(stipple::detail::PoissonCache::setCountFor(1, n), 32u);
    for (uint32_t n : {16u, 24u, 32u})
        for (const Genz& g : integrands) {
            const auto mse = [&](uint32_t pattern) {
                auto s = makeSampler(pattern, n, 0x1d5a11ull, {{1, 1}});
                double sum = 0.0;
                for (uint32_t p = 0; p < kPixels; ++p) {
                    const double u = kCentres[p % 8];
                    const std::vector<float> x = fillPixel(s.get(), p % 64, p / 64, 0);
                    double estimate = 0.0;
                    for (float v : x) estimate += g.f(v, u);
                    const double e = estimate / n - g.integral(u);
                    sum += e * e;
                }
                return sum / kPixels;
            };
            const double ratio = mse(STIPPLE_PATTERN_POISSON) / mse(STIPPLE_PATTERN_STRATIFIED);
            BOOST_TEST_MESSAGE("1D " << g.name << " N=" << n << ": poisson / stratified MSE " << ratio);
            BOOST_CHECK_MESSAGE(ratio <= 1.3, "1D " << g.name << " N=" << n << ": poisson / stratified MSE " << ratio);
        }
}

// 2D poisson from 256 points on is a cell lattice: served sets keep rho >= 0.80 (the measure above: minimum distance on
// the unit torus over the hexagonal packing distance) for every pixel, whatever the within-cell rotation.
BOOST_AUTO_TEST_CASE(two_dimensional_cell_lattices_keep_rho) {
    for (uint32_t n : {256u, 512u, 1024u, 3000u}) {
        auto s = makeSampler(STIPPLE_PATTERN_POISSON, n, 77, {{2, 1}});
        double least = 1.0;
        for (uint32_t pixel = 0; pixel < 96; ++pixel) { // 96 pixels: each of the 32 sets drawn with probability 0.95
            const std::vector<float> served = fillPixel(s.get(), pixel % 12, pixel / 12, 0);
            least = std::min(least, stipple::detail::pointsets::relativeRadius(2, served.data(), n));
        }
        BOOST_TEST_MESSAGE("2D poisson N=" << n << ": least served rho over 96 pixels " << least);
        BOOST_CHECK_GE(least, 0.80);
    }
}

// Every sample of a 2D cell lattice is uniform on the square: sample index i of N = 256 and 1000 over 3200 pixels on
// 8 x 8 bins (50 expected per bin), Pearson chi-square, family-wise alpha = 0.01 Sidak-corrected over the 6 tests.
BOOST_AUTO_TEST_CASE(two_dimensional_cell_lattice_samples_are_uniform) {
    constexpr uint32_t kPixels = 3200, kBins = 8;
    const double alpha = stipple::testing::sidak(0.01, 6);
    for (uint32_t n : {256u, 1000u}) {
        auto s = makeSampler(STIPPLE_PATTERN_POISSON, n, 0x5eed + n, {{2, 1}});
        for (uint32_t index : {0u, n / 3, n - 1}) {
            std::vector<double> observed(kBins * kBins, 0.0), expected(kBins * kBins, double(kPixels) / (kBins * kBins));
            float sample[2];
            for (uint32_t p = 0; p < kPixels; ++p) {
                BOOST_REQUIRE_EQUAL(stipple_sampler_sample(s.get(), p % 80, p / 80, index, 0, sample, 2), STIPPLE_OK);
                observed[uint32_t(sample[1] * kBins) * kBins + uint32_t(sample[0] * kBins)] += 1;
            }
            const stipple::testing::ChiSquareResult r = stipple::testing::chiSquareTest(observed, expected);
            BOOST_CHECK_MESSAGE(r.pValue > alpha, "2D poisson N=" << n << " sample " << index << ": chi2 = "
                                                                  << r.statistic << ", p = " << r.pValue);
        }
    }
}

// 2D poisson holds on smooth non-periodic integrands where the toroidal shift lost: the ramp x + y and
// exp(-x^2 - y^2) at N = 1024 over 256 pixels (fixed seed). Measured MSE ratios to stratified (shim_battery, 400
// pixels): ramp 0.006, exp(-x^2-y^2) 0.019 (the toroidal sets: 3.2x and 4.0x). The check asks for < 0.5: with 256
// pixels the relative standard error of each MSE estimate is about sqrt(2/256) = 0.09 for Gaussian errors, so a true
// ratio of 1 passes with probability ~1e-8 (log 0.5 is 5.5 standard errors of the log ratio).
BOOST_AUTO_TEST_CASE(two_dimensional_poisson_beats_stratified_on_non_periodic_integrands) {
    constexpr uint32_t kN = 1024, kPixels = 256;
    const auto mse = [&](uint32_t pattern, double (*f)(double, double), double integral) {
        auto s = makeSampler(pattern, kN, 2025, {{2, 1}});
        double sum = 0.0;
        for (uint32_t p = 0; p < kPixels; ++p) {
            const std::vector<float> x = fillPixel(s.get(), p % 16, p / 16, 0);
            double estimate = 0.0;
            for (uint32_t i = 0; i < kN; ++i) estimate += f(x[2 * i], x[2 * i + 1]);
            const double e = estimate / kN - integral;
            sum += e * e;
        }
        return sum / kPixels;
    };
    const auto ramp = [](double x, double y) { return x + y; };
    const auto gaussian = [](double x, double y) { return std::exp(-x * x - y * y); };
    const double erf1 = std::sqrt(std::acos(-1.0)) / 2.0 * std::erf(1.0);
    for (auto [f, integral, name] : {std::tuple<double (*)(double, double), double, const char*>{ramp, 1.0, "x + y"},
                                     {gaussian, erf1 * erf1, "exp(-x^2-y^2)"}}) {
        const double ratio = mse(STIPPLE_PATTERN_POISSON, f, integral) / mse(STIPPLE_PATTERN_STRATIFIED, f, integral);
        BOOST_TEST_MESSAGE("2D " << name << " N=" << kN << ": poisson / stratified MSE " << ratio);
        BOOST_CHECK_LT(ratio, 0.5);
    }
}
