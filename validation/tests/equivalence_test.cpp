// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The block-variance intervals of equivalence.h, on squared errors and on capped relative squared errors: coverage
// by simulation with heavy-tailed errors (95% intervals must hold the true error ratio in ≥ 93% of 300 or 600
// synthetic cases per error law), and each verdict reached for its reason. Fixed seeds: the figures are the same on
// every run.
#define BOOST_TEST_MODULE validation_equivalence
#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
#include <random>

#include "claims/comparison_claims.h"
#include "metrics/equivalence.h"

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

// E[min(Z², u)] for the law's unit-variance Z, tabulated on a log grid of u (the truth of a capped error:
// pixel p with variance v and cap T expects v · g(T / v)). Gaussian in closed form; Student-t by quadrature;
// fireflies as a mixture of a point mass and a Gaussian.
class CappedSecondMoment {
public:
    explicit CappedSecondMoment(Law law) {
        for (int i = 0; i < kGrid; ++i) table_[size_t(i)] = exact(law, std::exp(kLogLo + i * kStep));
    }
    double operator()(double u) const {
        const double x = (std::log(u) - kLogLo) / kStep;
        if (x <= 0) return u; // far below every Z²: min(Z², u) = u almost surely
        if (x >= kGrid - 1) return table_.back();
        const int i = int(x);
        return table_[size_t(i)] + (x - i) * (table_[size_t(i) + 1] - table_[size_t(i)]);
    }

private:
    static constexpr int kGrid = 2000;
    static constexpr double kLogLo = -12, kStep = 30.0 / kGrid; // u from e^-12 to e^18
    std::array<double, kGrid> table_{};

    static double gaussian(double u) { // E[min(N², u)], N standard normal
        const double t = std::sqrt(u), phi = std::exp(-0.5 * u) / std::sqrt(2 * M_PI);
        const double inside = std::erf(t / std::sqrt(2.0)); // P(|N| < t)
        return inside - 2 * t * phi + u * (1 - inside);
    }
    static double exact(Law law, double u) {
        switch (law) {
        case Law::Gaussian: return gaussian(u);
        case Law::Fireflies: {
            const double p = 0.002, c = 25, s2 = (1 - p) + p * c * c;
            return p * std::min(c * c / s2, u) + (1 - p) * gaussian(u * s2) / s2;
        }
        case Law::StudentT5: {
            // Z = T · sqrt(3/5), T ~ t(5): E[min(Z², u)] = 2 ∫_0^∞ min(3/5 t², u) f(t) dt, Simpson on t = tan(θ).
            const double nu = 5, norm = std::tgamma(3.0) / (std::sqrt(nu * M_PI) * std::tgamma(2.5));
            const int n = 4000;
            double sum = 0;
            for (int i = 0; i <= n; ++i) {
                const double theta = (M_PI / 2) * i / n * (1 - 1e-9), t = std::tan(theta);
                const double jac = 1 / (std::cos(theta) * std::cos(theta));
                const double f = norm * std::pow(1 + t * t / nu, -(nu + 1) / 2);
                const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
                sum += w * std::min(0.6 * t * t, u) * f * jac;
            }
            return 2 * sum * (M_PI / 2) / n / 3;
        }
        }
        return 0;
    }
};

// As renderBlocks, of the capped relative squared error min(w[p] · e², cap) (image_metrics.h).
std::vector<std::vector<double>> renderRelativeBlocks(const std::vector<double>& v, const std::vector<double>& w,
                                                      double cap, int seeds, Law law, std::mt19937_64& rng) {
    std::vector<std::vector<double>> out(size_t(seeds), std::vector<double>(kBlocks, 0.0));
    for (int k = 0; k < seeds; ++k)
        for (int y = 0; y < kSide; ++y)
            for (int x = 0; x < kSide; ++x) {
                const size_t p = size_t(y) * kSide + x;
                const double e = std::sqrt(v[p]) * draw(law, rng);
                out[size_t(k)][size_t((y / 8) * (kSide / 8) + x / 8)] += std::min(w[p] * e * e, cap);
            }
    return out;
}

// Coverage of the compare check's estimator: weights 1 / (L_p + m)² from a third map shared by both patterns (the
// reference's level L, here of the order of one pattern's error, as at a few spp; m its mean), the cap 3 · 4²; it
// binds on the fireflies and on Student-t's tail. The truth is the ratio of the expected capped relative errors.
double relativeCoverage(Law law, int cases, int seeds, uint64_t seed) {
    std::mt19937_64 rng(seed);
    const CappedSecondMoment g(law);
    const double cap = 3 * 4.0 * 4.0;
    int covered = 0;
    for (int i = 0; i < cases; ++i) {
        const std::vector<double> va = pixelVariance(1.0, seed + 3 * i),
                                  vb = pixelVariance(std::exp2(i % 3 - 1.0), seed + 3 * i + 1);
        std::vector<double> w = pixelVariance(1.0, seed + 3 * i + 2);
        double m = 0;
        for (double& l : w) m += (l = std::sqrt(l)) / double(w.size());
        for (double& l : w) l = 1 / ((l + m) * (l + m));
        double ta = 0, tb = 0;
        for (size_t p = 0; p < w.size(); ++p) {
            ta += w[p] * va[p] * g(cap / (w[p] * va[p]));
            tb += w[p] * vb[p] * g(cap / (w[p] * vb[p]));
        }
        const ErrorEstimate a =
            estimateFromBlocks(renderRelativeBlocks(va, w, cap, seeds, law, rng), {}, kSide * kSide);
        const ErrorEstimate b =
            estimateFromBlocks(renderRelativeBlocks(vb, w, cap, seeds, law, rng), {}, kSide * kSide);
        const Comparison c = compareErrors(a, b, Margin{});
        covered += c.lo95 <= ta / tb && ta / tb <= c.hi95;
    }
    return double(covered) / cases;
}

} // namespace

BOOST_AUTO_TEST_CASE(capped_second_moment_is_exact_at_the_limits) {
    for (Law law : {Law::Gaussian, Law::StudentT5, Law::Fireflies}) {
        const CappedSecondMoment g(law);
        BOOST_TEST(g(1e7) == 1.0, boost::test_tools::tolerance(2e-3));   // no cap: the unit variance
        BOOST_TEST(g(1e-4) == 1e-4, boost::test_tools::tolerance(1e-2)); // every Z² above the cap
        BOOST_TEST(g(1.0) < 1.0);
    }
}

BOOST_AUTO_TEST_CASE(relative_capped_intervals_cover_the_true_ratio_with_heavy_tailed_errors, *boost::unit_test::label("coverage")) {
    // The compare check's estimator (capped relative squared error) at the quick matrix's K = 8 seeds: the same
    // requirement, ≥ 93%, on 600 cases per law (a true 95% falls below 93% with probability ≈ 1%; with 300 cases
    // ≈ 5%, and one 300-case stream of the Gaussian law gave 91.7% where 1200 cases gave 95.7%).
    for (const auto& [law, name] : {std::pair{Law::Gaussian, "gaussian"}, std::pair{Law::StudentT5, "student-t5"},
                                    std::pair{Law::Fireflies, "fireflies"}}) {
        const double c = relativeCoverage(law, 600, 8, 5000 + uint64_t(law) * 7919);
        BOOST_TEST_MESSAGE(name << ", K = 8: capped relative 95% intervals cover the truth in " << 100 * c
                                << "% of 600 cases");
        BOOST_TEST(c >= 0.93, name << ": coverage " << c);
    }
}

BOOST_AUTO_TEST_CASE(intervals_cover_the_true_ratio_with_heavy_tailed_errors, *boost::unit_test::label("coverage")) {
    // 300 cases per law at K = 4 seeds (the fewest a matrix allows); the 95% intervals must cover ≥ 93%: with 300 cases
    // a true coverage of 95% falls below 93% with probability ≈ 5% (binomial), 91% would pass with probability ≈ 10%.
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

BOOST_AUTO_TEST_CASE(the_deciding_verdict_names_what_decided_the_row) {
    // 0.95x with a tight interval: inside the margin (EQUIVALENT) and separated from 1. A check expecting better
    // counts it as a gain, so its words say BETTER; one expecting equivalence says EQUIVALENT; 1.02x, not separated
    // from 1, stays EQUIVALENT (and refutes an expected gain).
    const Comparison gain = judgeLogRatio(std::log(0.95), 1e-4, 50, Margin{}); // log-ratio sd 0.01
    const Comparison same = judgeLogRatio(std::log(1.02), 4e-4, 50, Margin{}); // sd 0.02
    BOOST_TEST(verdictName(gain.verdict) == std::string("EQUIVALENT"));
    BOOST_TEST(gain.hi95 < 1);
    BOOST_TEST(checkStatusName(statusFor(Expectation::Better, gain)) == std::string("PASS"));
    BOOST_TEST(verdictName(decidingVerdict(Expectation::Better, gain)) == std::string("BETTER"));
    BOOST_TEST(verdictName(decidingVerdict(Expectation::Equivalent, gain)) == std::string("EQUIVALENT"));
    BOOST_TEST(verdictName(decidingVerdict(Expectation::Any, gain)) == std::string("EQUIVALENT"));
    BOOST_TEST(verdictName(decidingVerdict(Expectation::Worse, gain)) == std::string("EQUIVALENT"));
    BOOST_TEST(verdictName(decidingVerdict(Expectation::Better, same)) == std::string("EQUIVALENT"));
    BOOST_TEST(checkStatusName(statusFor(Expectation::Better, same)) == std::string("FAIL"));
}

BOOST_AUTO_TEST_CASE(blue_noise_units_are_its_tiles) {
    BOOST_TEST(pixelsIndependent("stratified"));
    BOOST_TEST(!pixelsIndependent("sobol+blue-noise"));
}
