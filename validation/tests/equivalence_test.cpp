// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The block-variance intervals of equivalence.h: coverage by simulation with heavy-tailed errors (95% intervals
// must hold the true error ratio in ≥ 93% of 300 synthetic cases per error law), and each verdict reached for its
// reason. Fixed seeds: the figures are the same on every run.
#define BOOST_TEST_MODULE validation_equivalence
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <random>

#include "comparison_claims.h"
#include "equivalence.h"

using namespace stipple::validation;

namespace {

// A synthetic 128 × 128 render's error, K seeds, in 8 × 8 blocks: pixel p's error is sqrt(v_p) · Z, E[Z²] = 1, so its
// expected squared error is v_p. v varies over the image like a render's (a lognormal spread and a bright 20 × 20
// patch of 50× the variance, a light source's edge).
enum class Law { Gaussian, StudentT5, Fireflies };

double draw(Law law, std::mt19937_64& rng) {
    std::normal_distribution<double> n;
    switch (law) {
    case Law::Gaussian: return n(rng);
    case Law::StudentT5: {
        std::chi_squared_distribution<double> chi(5);
        return n(rng) / std::sqrt(chi(rng) / 5) * std::sqrt(3.0 / 5); // unit variance
    }
    case Law::Fireflies: {
        // One pixel in 500 meets a rare bright path worth 25σ; they carry 55% of the expected squared error.
        std::uniform_real_distribution<double> u;
        const double p = 0.002, c = 25, scale = std::sqrt((1 - p) + p * c * c);
        return (u(rng) < p ? c : n(rng)) / scale;
    }
    }
    return 0;
}

constexpr int kSide = 128, kBlocks = (kSide / 8) * (kSide / 8);

std::vector<double> pixelVariance(double level, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::lognormal_distribution<double> spread(0, 0.7);
    std::vector<double> v(size_t(kSide) * kSide);
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x)
            v[size_t(y) * kSide + x] = level * spread(rng) * ((x >= 50 && x < 70 && y >= 10 && y < 30) ? 50 : 1);
    return v;
}

std::vector<std::vector<double>> renderBlocks(const std::vector<double>& v, int seeds, Law law, std::mt19937_64& rng) {
    std::vector<std::vector<double>> out(size_t(seeds), std::vector<double>(kBlocks, 0.0));
    for (int k = 0; k < seeds; ++k)
        for (int y = 0; y < kSide; ++y)
            for (int x = 0; x < kSide; ++x) {
                const double e = std::sqrt(v[size_t(y) * kSide + x]) * draw(law, rng);
                out[size_t(k)][size_t((y / 8) * (kSide / 8) + x / 8)] += e * e;
            }
    return out;
}

double sum(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s;
}

// Share of `cases` synthetic comparisons whose 95% interval holds the true ratio.
double coverage(Law law, int cases, int seeds, uint64_t seed) {
    std::mt19937_64 rng(seed);
    int covered = 0;
    for (int i = 0; i < cases; ++i) {
        // Two patterns with different spatial structure and a true ratio between 0.5 and 2.
        const std::vector<double> va = pixelVariance(1.0, seed + 2 * i), vb = pixelVariance(std::exp2(i % 3 - 1.0), seed + 2 * i + 1);
        const double truth = sum(va) / sum(vb);
        const ErrorEstimate a = estimateFromBlocks(renderBlocks(va, seeds, law, rng), {}, kSide * kSide);
        const ErrorEstimate b = estimateFromBlocks(renderBlocks(vb, seeds, law, rng), {}, kSide * kSide);
        const Comparison c = compareErrors(a, b, Margin{});
        covered += c.lo95 <= truth && truth <= c.hi95;
    }
    return double(covered) / cases;
}

} // namespace

BOOST_AUTO_TEST_CASE(intervals_cover_the_true_ratio_with_heavy_tailed_errors) {
    // 300 cases per law at K = 4 seeds (the quick matrix's); the 95% intervals must cover ≥ 93%: with 300 cases a
    // true coverage of 95% falls below 93% with probability ≈ 5% (binomial), 91% would pass with probability ≈ 10%.
    for (const auto& [law, name] : {std::pair{Law::Gaussian, "gaussian"}, std::pair{Law::StudentT5, "student-t5"},
                                    std::pair{Law::Fireflies, "fireflies"}}) {
        const double c = coverage(law, 300, 4, 1000 + uint64_t(law) * 7919);
        BOOST_TEST_MESSAGE(name << ": 95% intervals cover the truth in " << 100 * c << "% of 300 cases");
        BOOST_TEST(c >= 0.93, name << ": coverage " << c);
    }
}

BOOST_AUTO_TEST_CASE(variance_comes_from_the_blocks_not_from_the_image_structure) {
    // Seeds' totals are the only information with one unit: K − 1 dof. With every block its own unit the dof grow
    // with the blocks that carry the error (here the bright patch's ~9 blocks hold most of it: ≈ 20 dof), and the
    // image's structure does not count as noise.
    std::mt19937_64 rng(7);
    const auto v = pixelVariance(1.0, 11);
    const auto blocks = renderBlocks(v, 4, Law::Gaussian, rng);
    const ErrorEstimate perBlock = estimateFromBlocks(blocks, {}, kSide * kSide);
    const ErrorEstimate perSeed = estimateFromBlocks(blocks, std::vector<int>(kBlocks, 0), kSide * kSide);
    BOOST_TEST(perSeed.dof == 3.0);
    BOOST_TEST(perBlock.dof > 15.0);
    BOOST_TEST(perBlock.mean == perSeed.mean, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(std::abs(perBlock.mean - sum(v) / (kSide * kSide)) < 0.05 * perBlock.mean);
}

BOOST_AUTO_TEST_CASE(each_verdict_for_its_reason) {
    std::mt19937_64 rng(3);
    const auto v = pixelVariance(1.0, 5);
    std::vector<double> half = v, quarterMore = v;
    for (double& x : half) x *= 0.5;
    for (double& x : quarterMore) x *= 1.6;
    const ErrorEstimate a = estimateFromBlocks(renderBlocks(v, 8, Law::Gaussian, rng), {}, kSide * kSide);
    const ErrorEstimate same = estimateFromBlocks(renderBlocks(v, 8, Law::Gaussian, rng), {}, kSide * kSide);
    const ErrorEstimate lower = estimateFromBlocks(renderBlocks(half, 8, Law::Gaussian, rng), {}, kSide * kSide);
    const ErrorEstimate higher = estimateFromBlocks(renderBlocks(quarterMore, 8, Law::Gaussian, rng), {}, kSide * kSide);
    BOOST_TEST(verdictName(compareErrors(same, a, Margin{}).verdict) == std::string("EQUIVALENT"));
    BOOST_TEST(verdictName(compareErrors(lower, a, Margin{}).verdict) == std::string("BETTER"));
    BOOST_TEST(verdictName(compareErrors(higher, a, Margin{}).verdict) == std::string("WORSE"));
    // Two seeds' totals alone (one unit) cannot separate a factor of 1.6 nor show equivalence.
    std::mt19937_64 rng2(9);
    const std::vector<int> one(kBlocks, 0);
    const ErrorEstimate a2 = estimateFromBlocks(renderBlocks(v, 2, Law::Fireflies, rng2), one, kSide * kSide);
    const ErrorEstimate h2 = estimateFromBlocks(renderBlocks(quarterMore, 2, Law::Fireflies, rng2), one, kSide * kSide);
    BOOST_TEST(verdictName(compareErrors(h2, a2, Margin{}).verdict) == std::string("NOT SEPARATED"));
    // At equal time the CPU-time ratio multiplies the error ratio: half the error at three times the time is worse.
    const LogShift slower = pairedLogRatio({3.0, 3.1, 2.9, 3.0}, {1.0, 1.0, 1.0, 1.0});
    const Comparison t = compareErrors(lower, a, Margin{}, slower);
    BOOST_TEST(t.ratio > 1.3);
    BOOST_TEST(verdictName(t.verdict) == std::string("WORSE"));
}

BOOST_AUTO_TEST_CASE(expectations_judge_the_verdicts) {
    Comparison better = judgeLogRatio(std::log(0.5), 0.01, 50, Margin{});
    Comparison equivalent = judgeLogRatio(std::log(1.02), 0.001, 50, Margin{});
    Comparison unsure = judgeLogRatio(std::log(1.1), 0.2, 5, Margin{});
    BOOST_TEST(checkStatusName(statusFor(Expectation::Better, better)) == std::string(checkStatusName(CheckStatus::Pass)));
    BOOST_TEST(checkStatusName(statusFor(Expectation::Worse, better)) == std::string(checkStatusName(CheckStatus::Fail)));
    BOOST_TEST(checkStatusName(statusFor(Expectation::Equivalent, better)) == std::string(checkStatusName(CheckStatus::Fail)));
    BOOST_TEST(checkStatusName(statusFor(Expectation::Equivalent, equivalent)) == std::string(checkStatusName(CheckStatus::Pass)));
    BOOST_TEST(checkStatusName(statusFor(Expectation::Better, equivalent)) == std::string(checkStatusName(CheckStatus::Fail))); // no gain worth the margin
    BOOST_TEST(checkStatusName(statusFor(Expectation::Equivalent, unsure)) == std::string(checkStatusName(CheckStatus::NotSeparated)));
    BOOST_TEST(checkStatusName(statusFor(Expectation::Any, unsure)) == std::string(checkStatusName(CheckStatus::NotSeparated)));
    BOOST_TEST(checkStatusName(statusFor(Expectation::Any, better)) == std::string(checkStatusName(CheckStatus::Pass)));
}

BOOST_AUTO_TEST_CASE(blue_noise_units_are_its_tiles) {
    BOOST_TEST(pixelsIndependent("stratified"));
    BOOST_TEST(!pixelsIndependent("sobol+blue-noise"));
}
