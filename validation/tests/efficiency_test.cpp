// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Equal-time efficiency on synthetic rows with known answers: the ranking, the ratio and its interval, the
// floor share, the heavy-tail mark and the trimmed mean; and the equal_time check's three verdicts.
#define BOOST_TEST_MODULE validation_efficiency
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "claims/checks.h"
#include "matrix/check_kind.h"
#include "claims/efficiency.h"
#include "claims/efficiency_claims.h"

using namespace stipple::validation;

namespace {
// Rows of scene "s" at 16 spp: per seed, measured MSE = floor + corrected[i], CPU seconds cpu[i].
void add(std::vector<ResultRow>& rows, const std::string& pattern, const std::vector<double>& corrected,
         const std::vector<double>& cpu, double floor) {
    for (size_t i = 0; i < corrected.size(); ++i) {
        ResultRow r;
        r.scene = "s";
        r.pattern = pattern;
        r.spp = 16;
        r.seed = i + 1;
        r.mseCorrected = corrected[i];
        r.mse = corrected[i] + floor;
        r.rmsCorrected = std::sqrt(r.mseCorrected);
        r.cpuSeconds = cpu[i];
        r.renderSeconds = 10 * cpu[i]; // wall seconds of a busy machine: not used when CPU seconds exist
        rows.push_back(r);
    }
}
} // namespace

BOOST_AUTO_TEST_CASE(ranking_ratio_and_marks) {
    const double floor = 0.001;
    std::vector<ResultRow> rows;
    // fast: MSE 0.1 in 1 s; slow: the same MSE in 4 s (4× less efficient); noisy: like fast, seeds spread 3×.
    add(rows, "fast", {0.100, 0.102, 0.098, 0.101}, {1.0, 1.0, 1.01, 0.99}, floor);
    add(rows, "slow", {0.100, 0.101, 0.099, 0.100}, {4.0, 4.02, 3.98, 4.0}, floor);
    add(rows, "noisy", {0.05, 0.15, 0.45, 0.10}, {1, 1, 1, 1}, floor);
    const EfficiencyRanking r = rankEfficiency(rows, "s", 16, {"slow", "noisy", "fast"}, floor);
    BOOST_REQUIRE_EQUAL(r.ranked.size(), 3u);
    BOOST_CHECK_EQUAL(r.ranked[0].pattern, "fast");
    BOOST_CHECK_EQUAL(r.ranked.back().pattern, "slow");
    double lo = 0, hi = 0;
    const double ratio = r.ratioOf("fast", "slow", &lo, &hi);
    BOOST_CHECK_CLOSE(ratio, 4.0, 2.0); // within 2%
    BOOST_CHECK(lo > 3.8 && hi < 4.2);
    BOOST_CHECK(r.ratioOf("slow", "fast") < 0.26);
    // fast against noisy: not separated (noisy's seeds spread 9× in MSE).
    const double rn = r.ratioOf("fast", "noisy", &lo, &hi);
    BOOST_CHECK(lo < 1 && hi > 1);
    BOOST_CHECK(rn > 1);
    BOOST_CHECK(!r.steps[0].separated);
    // Floor share: 0.001 / 0.10025.
    BOOST_CHECK_CLOSE(r.ranked[0].floorShare, 0.001 / 0.10025, 1e-6);
    // Heavy tails: noisy's worst seed RMS √0.45 is 3× its best √0.05; fast's are within 2%.
    const PatternEfficiency* noisy = nullptr;
    for (const auto& p : r.ranked)
        if (p.pattern == "noisy") noisy = &p;
    BOOST_REQUIRE(noisy);
    BOOST_CHECK(noisy->rms.heavyTailed);
    BOOST_CHECK_CLOSE(noisy->rms.maxOverMin, 3.0, 1e-6);
    BOOST_CHECK_CLOSE(noisy->rms.trimmedMean, (std::sqrt(0.10) + std::sqrt(0.15)) / 2, 1e-9);
    BOOST_CHECK(!r.ranked[0].rms.heavyTailed);
    // Equal samples ignore the time: fast and slow tie.
    const EfficiencyRanking e = rankEfficiency(rows, "s", 16, {"slow", "fast"}, floor, false);
    BOOST_CHECK_CLOSE(e.ratioOf("fast", "slow"), 1.0, 2.0);
    BOOST_CHECK_CLOSE(floorFromRows(rows, "s"), floor, 1e-6);
}

BOOST_AUTO_TEST_CASE(equal_time_verdicts) {
    std::vector<ResultRow> rows;
    add(rows, "fast", {0.100, 0.102, 0.098, 0.101}, {1.0, 1.0, 1.01, 0.99}, 0);
    add(rows, "slow", {0.100, 0.101, 0.099, 0.100}, {4.0, 4.02, 3.98, 4.0}, 0);
    add(rows, "noisy", {0.05, 0.15, 0.45, 0.10}, {1, 1, 1, 1}, 0);
    Matrix m;
    MatrixScene scene;
    scene.name = "s";
    scene.file = scene.path = "s.yaml";
    m.scenes.push_back(scene);
    m.patterns = {"fast", "slow", "noisy"};
    m.spp = {16};
    const std::vector<CellAggregate> cells;
    const std::vector<SlopeFit> slopes;
    auto run = [&](std::vector<std::string> order) {
        const Check k = parseCheck("{ type: equal_time, scene: s, spp: 16, order: [" + order[0] + ", " + order[1] +
                                       "], study: fast first }",
                                   "check.yaml", m, MatrixVocabulary{m.patterns, {}});
        const CheckOutcome o = evaluateCheck(k, {m, rows, cells, slopes});
        BOOST_TEST_MESSAGE(formatOutcome(o));
        return o;
    };
    BOOST_CHECK(run({"fast", "slow"}).status == CheckStatus::Pass);
    BOOST_CHECK(run({"slow", "fast"}).status == CheckStatus::Fail);
    BOOST_CHECK(run({"fast", "noisy"}).status == CheckStatus::NotSeparated);
    const CheckOutcome o = run({"fast", "slow"});
    BOOST_CHECK(o.claim.find("study: fast first") != std::string::npos);
    BOOST_CHECK(formatOutcome(o).find("measured ranking: fast") != std::string::npos);
}
