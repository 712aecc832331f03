// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Paired time ratios: the interval of the geometric mean, and the three verdicts each reached for its reason.
#define BOOST_TEST_MODULE validation_timing
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "claims/checks.h"
#include "matrix/check_kind.h"
#include "claims/timing.h"

using namespace stipple::validation;

namespace {
// Rows of scene "s", 64 spp, seeds 1..K: pattern a and b with the given CPU and wall seconds per seed.
std::vector<ResultRow> pairs(const std::vector<double>& aCpu, const std::vector<double>& bCpu,
                             const std::vector<double>& aWall, const std::vector<double>& bWall) {
    std::vector<ResultRow> rows;
    for (size_t i = 0; i < aCpu.size(); ++i)
        for (int side = 0; side < 2; ++side) {
            ResultRow r;
            r.scene = "s";
            r.pattern = side ? "b" : "a";
            r.spp = 64;
            r.seed = i + 1;
            r.cpuSeconds = side ? bCpu[i] : aCpu[i];
            r.renderSeconds = side ? bWall[i] : aWall[i];
            rows.push_back(r);
        }
    return rows;
}
// A matrix of scene "s" and patterns a and b at the given spp.
Matrix matrixOf(std::vector<uint32_t> spp) {
    Matrix m;
    MatrixScene scene;
    scene.name = "s";
    scene.file = scene.path = "s.yaml";
    m.scenes.push_back(scene);
    m.patterns = {"a", "b"};
    m.spp = std::move(spp);
    return m;
}
} // namespace

BOOST_AUTO_TEST_CASE(geometric_mean_and_t_interval) {
    // log ratios ln 1, ln 2: mean ln √2, sd ln2/√2, t(0.975, 1) = 12.706: hi = √2 · exp(12.706 · ln2 / 2).
    auto rows = pairs({1, 2}, {1, 1}, {1, 1}, {1, 1});
    PairedRatio r = pairedTimeRatio(rows, "s", "a", "b", 64, TimeBasis::Cpu);
    BOOST_CHECK_EQUAL(r.pairs, 2u);
    BOOST_CHECK_CLOSE(r.ratio, std::sqrt(2.0), 1e-9);
    BOOST_CHECK_CLOSE(r.hi, std::sqrt(2.0) * std::exp(12.7062047361747 * std::log(2.0) / 2), 1e-6);
    BOOST_CHECK_CLOSE(r.lo * r.hi, 2.0, 1e-9); // symmetric on the log scale
    PairedRatio w = pairedTimeRatio(rows, "s", "a", "b", 64, TimeBasis::Wall);
    BOOST_CHECK_CLOSE(w.ratio, 1.0, 1e-9);
}

BOOST_AUTO_TEST_CASE(verdicts) {
    // Consistent ratios around 1.00: PASS against 1.05.
    auto ok = pairs({1.00, 1.01, 0.99, 1.00}, {1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1});
    BOOST_CHECK(ratioVerdict(pairedTimeRatio(ok, "s", "a", "b", 64, TimeBasis::Cpu), 1.05) == CheckStatus::Pass);
    // Consistent ratios around 10: FAIL.
    auto slow = pairs({10, 11, 9.5, 10}, {1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1});
    BOOST_CHECK(ratioVerdict(pairedTimeRatio(slow, "s", "a", "b", 64, TimeBasis::Cpu), 1.05) == CheckStatus::Fail);
    // One pair at 1.3 among 1.0s: the interval straddles 1.05, NOT SEPARATED.
    auto noisy = pairs({1.0, 1.3, 1.0, 1.02}, {1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1});
    PairedRatio n = pairedTimeRatio(noisy, "s", "a", "b", 64, TimeBasis::Cpu);
    BOOST_CHECK(n.lo < 1.05 && n.hi > 1.05);
    BOOST_CHECK(ratioVerdict(n, 1.05) == CheckStatus::NotSeparated);
    // A single pair has no interval: NOT SEPARATED, never PASS or FAIL on one number.
    auto one = pairs({2}, {1}, {2}, {1});
    BOOST_CHECK(ratioVerdict(pairedTimeRatio(one, "s", "a", "b", 64, TimeBasis::Cpu), 1.05) ==
                CheckStatus::NotSeparated);
}

BOOST_AUTO_TEST_CASE(equivalence_verdicts) {
    // Within [0.9, 1.1]: consistent ratios around 1.02 are EQUIVALENT (90% interval inside); around 1.3, FAIL (95%
    // interval above 1.1); ratios spread from 0.95 to 1.15, NOT SEPARATED (the interval reaches past 1.1).
    auto same = pairs({1.02, 1.03, 1.01, 1.02}, {1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1});
    const PairedRatio s = pairedTimeRatio(same, "s", "a", "b", 64, TimeBasis::Cpu);
    BOOST_CHECK(s.lo < s.lo90 && s.hi90 < s.hi);
    BOOST_CHECK(equivalenceVerdict(s, 0.9, 1.1) == CheckStatus::Pass);
    auto slower = pairs({1.3, 1.32, 1.28, 1.3}, {1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1});
    BOOST_CHECK(equivalenceVerdict(pairedTimeRatio(slower, "s", "a", "b", 64, TimeBasis::Cpu), 0.9, 1.1) ==
                CheckStatus::Fail);
    auto spread = pairs({0.95, 1.15, 1.0, 1.1}, {1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1});
    BOOST_CHECK(equivalenceVerdict(pairedTimeRatio(spread, "s", "a", "b", 64, TimeBasis::Cpu), 0.9, 1.1) ==
                CheckStatus::NotSeparated);
    auto one = pairs({1}, {1}, {1}, {1});
    BOOST_CHECK(equivalenceVerdict(pairedTimeRatio(one, "s", "a", "b", 64, TimeBasis::Cpu), 0.9, 1.1) ==
                CheckStatus::NotSeparated);
}

BOOST_AUTO_TEST_CASE(check_judges_cpu_seconds_not_wall) {
    // A busy machine: wall seconds of pattern a inflated by 40-80% on the seeds where a hog ran beside it; the CPU
    // seconds are unchanged. The claim a / b ≤ 1.05 passes on CPU seconds; the wall ratio is shown beside.
    auto rows = pairs({1.00, 1.01, 0.99, 1.00}, {1, 1, 1, 1}, {1.4, 1.8, 1.0, 1.5}, {1, 1, 1, 1});
    const Matrix m = matrixOf({64});
    const Check k = parseCheck("{ type: time_ratio, numerator: a, denominator: b, max: 1.05, spp: 64 }", "check.yaml", m,
                               MatrixVocabulary{{"a", "b"}, {}});
    const std::vector<CellAggregate> cells;
    const std::vector<SlopeFit> slopes;
    const CheckOutcome o = evaluateCheck(k, {m, rows, cells, slopes});
    BOOST_TEST_MESSAGE(formatOutcome(o));
    BOOST_CHECK(o.status == CheckStatus::Pass);
    BOOST_CHECK(formatOutcome(o).find("wall ratio 1.") != std::string::npos);
    // Rows without CPU seconds (older results) cannot be judged: FAIL naming the missing cells.
    for (auto& r : rows) r.cpuSeconds = 0;
    const CheckOutcome missing = evaluateCheck(k, {m, rows, cells, slopes});
    BOOST_CHECK(missing.status == CheckStatus::Fail);
}

BOOST_AUTO_TEST_CASE(every_spp_pairs_each_seed_at_each_spp) {
    // Seeds 1..3 at 16 and 64 spp. At 16 spp a costs 2x b, at 64 spp 1x: six pairs, geometric mean sqrt(2). A
    // pairing across spp (a at 16 with b at 64, whose times differ 4x) would give other ratios and more pairs.
    std::vector<ResultRow> rows;
    for (uint32_t spp : {16u, 64u})
        for (uint64_t seed = 1; seed <= 3; ++seed)
            for (int side = 0; side < 2; ++side) {
                ResultRow r;
                r.scene = "s";
                r.pattern = side ? "b" : "a";
                r.spp = spp;
                r.seed = seed;
                const double b = spp == 16 ? 1.0 : 4.0;
                r.cpuSeconds = r.renderSeconds = side ? b : (spp == 16 ? 2 * b : b) * (1 + 0.01 * double(seed));
                rows.push_back(r);
            }
    const PairedRatio all = pairedTimeRatio(rows, "s", "a", "b", kAllSpp, TimeBasis::Cpu);
    BOOST_CHECK_EQUAL(all.pairs, 6u);
    BOOST_CHECK_CLOSE(all.ratio, std::sqrt(2.0) * std::cbrt(1.01 * 1.02 * 1.03), 1e-9);
    const PairedRatio at64 = pairedTimeRatio(rows, "s", "a", "b", 64, TimeBasis::Cpu);
    BOOST_CHECK_EQUAL(at64.pairs, 3u);
    BOOST_CHECK_CLOSE(at64.ratio, std::cbrt(1.01 * 1.02 * 1.03), 1e-9);

    // The check reads spp: all, and refuses a word that is neither all nor one of the matrix's spp.
    const Matrix m = matrixOf({16, 64});
    const MatrixVocabulary vocabulary{{"a", "b"}, {}};
    const Check k = parseCheck("{ type: time_ratio, numerator: a, denominator: b, max: 1.5, spp: all }", "check.yaml",
                               m, vocabulary);
    const std::vector<CellAggregate> cells;
    const std::vector<SlopeFit> slopes;
    const CheckOutcome o = evaluateCheck(k, {m, rows, cells, slopes});
    BOOST_TEST_MESSAGE(formatOutcome(o));
    BOOST_CHECK(formatOutcome(o).find("every spp") != std::string::npos);
    BOOST_CHECK(formatOutcome(o).find("6 pairs") != std::string::npos);
    // ratio 1.44, 95% interval 0.98-2.13 (the two spp disagree): it straddles max 1.5.
    BOOST_CHECK(o.status == CheckStatus::NotSeparated);
    try {
        parseCheck("{ type: time_ratio, numerator: a, denominator: b, max: 1.5, spp: every }", "check.yaml", m,
                   vocabulary);
        BOOST_ERROR("spp: every was accepted");
    } catch (const std::exception& e) {
        BOOST_TEST_MESSAGE(e.what());
        BOOST_CHECK(std::string(e.what()).find("check.yaml") != std::string::npos);
        BOOST_CHECK(std::string(e.what()).find("spp") != std::string::npos);
    }
}
