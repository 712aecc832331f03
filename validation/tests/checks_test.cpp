// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Checks on synthetic results: each outcome (PASS, FAIL, NOT SEPARATED) is reached for the right reason;
// the baseline comparison and results.json round trip; seeds that rendered one image.
#define BOOST_TEST_MODULE validation_checks
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <limits>
#include <fstream>
#include <unistd.h>

#include "claims/baseline.h"
#include "claims/checks.h"
#include "claims/identical_renders.h"
#include "metrics/image_metrics.h"
#include "report/report.h"
#include "report/study_answers.h"
#include "test_vocabulary.h"

#include <stipple/testing/scratch_folder.h>

using namespace stipple::validation;
namespace fs = std::filesystem;

namespace {
struct Fixture {
    fs::path dir;
    Matrix matrix;
    Fixture() {
        dir = stipple::testing::freshScratchFolder("checks");
        fs::create_directories(dir);
        std::ofstream(dir / "box.yaml") << "name: box\n";
        std::ofstream(dir / "m.yaml") << R"(scenes: [box.yaml]
patterns: [independent, stratified, poisson]
spp: [4, 16, 64]
seeds: 4
reference: { spp: 1024 }
checks:
  - { type: ordering, scene: box, spp_min: 16, order: [stratified, independent] }
  - { type: ordering, scene: box, spp_min: 64, order: [poisson, stratified] }
  - { type: ordering, scene: box, spp_min: 64, order: [independent, stratified] }
  - { type: slope, scene: box, pattern: independent, expected: -0.5, tolerance: 0.05 }
  - { type: slope, scene: box, pattern: stratified, expected: -0.5, tolerance: 0.05 }
  - { type: time_ratio, numerator: poisson, denominator: stratified, max: 1.05 }
  - { type: time_ratio, numerator: independent, denominator: stratified, max: 1.05 }
  - { type: time_ceiling, seconds: 1.5 }
)";
        matrix = loadMatrix((dir / "m.yaml").string(), test::kVocabulary);
    }
    ~Fixture() { fs::remove_all(dir); }
};

// Rows of the fixture's matrix (scene box; independent, stratified, poisson; 4, 16, 64 spp; 4 seeds) with the
// given RMS per (pattern, spp, seed index) and 1 s render times.
template <class Rms>
std::vector<ResultRow> rowsWith(Rms rms) {
    std::vector<ResultRow> rows;
    for (const char* pattern : {"independent", "stratified", "poisson"})
        for (uint32_t spp : {4u, 16u, 64u})
            for (int s = 0; s < 4; ++s) {
                ResultRow r;
                r.scene = "box";
                r.pattern = pattern;
                r.spp = spp;
                r.seed = uint64_t(s + 1);
                r.rmsCorrected = r.rms = rms(std::string(pattern), spp, s);
                r.mseCorrected = r.mse = r.rms * r.rms;
                r.renderSeconds = r.cpuSeconds = 1.0;
                rows.push_back(r);
            }
    return rows;
}

// independent: RMS = spp^-0.5 (slope −0.5); stratified: spp^-0.75; poisson: as stratified with the same spread,
// so stratified vs poisson overlap. Seeds spread the RMS by ±2%. Times: independent 1 s, stratified 1 s,
// poisson 1.02 s, independent at 64 spp takes 2 s for seed 4 (the slowest cell).
std::vector<ResultRow> syntheticRows() {
    const double spread[4] = {-0.02, -0.01, 0.01, 0.02};
    std::vector<ResultRow> rows = rowsWith([&](const std::string& pattern, uint32_t spp, int s) {
        return std::pow(double(spp), pattern == "independent" ? -0.5 : -0.75) * (1 + spread[s]);
    });
    for (ResultRow& r : rows) {
        if (r.pattern == "poisson") r.renderSeconds = r.cpuSeconds = 1.02;
        if (r.pattern == "independent" && r.spp == 64 && r.seed == 4) r.renderSeconds = r.cpuSeconds = 2.0;
    }
    return rows;
}
} // namespace

BOOST_AUTO_TEST_CASE(outcomes_of_synthetic_claims) {
    Fixture f;
    auto rows = syntheticRows();
    sortRows(rows, f.matrix);
    auto cells = aggregate(rows);
    BOOST_REQUIRE_EQUAL(cells.size(), 9u);
    auto slopes = fitSlopes(rows, f.matrix);
    auto out = evaluateChecks(f.matrix, rows, cells, slopes);
    BOOST_REQUIRE_EQUAL(out.size(), 8u);
    for (const auto& o : out) BOOST_TEST_MESSAGE(formatOutcome(o));
    BOOST_CHECK(out[0].status == CheckStatus::Pass); // stratified < independent, separated at 16 and 64
    BOOST_CHECK_EQUAL(out[0].figures.size(), 2u);
    BOOST_CHECK(out[1].status == CheckStatus::NotSeparated); // poisson ~ stratified
    BOOST_CHECK(out[1].failsRun);                            // default: not_separated fails
    BOOST_CHECK(out[2].status == CheckStatus::Fail);         // reversed
    BOOST_CHECK(formatOutcome(out[2]).find("> (reversed)") != std::string::npos);
    BOOST_CHECK(out[3].status == CheckStatus::Pass); // slope −0.5
    BOOST_CHECK(out[4].status == CheckStatus::Fail); // stratified's −0.75 is not −0.5 ± 0.05
    BOOST_CHECK(formatOutcome(out[4]).find("slope -0.750") != std::string::npos);
    BOOST_CHECK(out[5].status == CheckStatus::Pass); // 1.02 ≤ 1.05
    // Paired ratios 1, 1, 1, 2: geometric mean 1.19 with a 95% interval that straddles 1.05. The run cannot
    // tell, which is not a failure of the claim.
    BOOST_CHECK(out[6].status == CheckStatus::NotSeparated);
    BOOST_CHECK(!out[6].failsRun);
    BOOST_CHECK(out[7].status == CheckStatus::Fail); // the 2 s cell breaks the 1.5 s ceiling
    BOOST_CHECK(formatOutcome(out[7]).find("independent @ 64 spp seed 4: 2.0000s") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(ordering_compares_geometric_means_of_skewed_rms) {
    // Per-seed RMS as measured on Veach MIS at 64 spp (quick matrix, four seeds): every seed of stratified is
    // 2-9x below every seed of independent, but one heavy seed widens the mean-RMS intervals until they overlap.
    // On log RMS Welch's interval separates them; equal samples still do not separate.
    Fixture f;
    const double independent[4] = {1.661, 0.854, 1.156, 0.843}, stratified[4] = {0.450, 0.252, 0.133, 0.386};
    std::vector<ResultRow> rows = rowsWith([&](const std::string& pattern, uint32_t, int s) {
        return pattern == "independent" ? independent[s] : stratified[s];
    });
    sortRows(rows, f.matrix);
    auto cells = aggregate(rows);
    const CellAggregate *a = findCell(cells, "box", "stratified", 64), *b = findCell(cells, "box", "independent", 64);
    BOOST_REQUIRE(a && b);
    BOOST_CHECK(!separatedBelow(a->rms, b->rms)); // the mean-RMS intervals overlap
    auto out = evaluateChecks(f.matrix, rows, cells, fitSlopes(rows, f.matrix));
    for (const auto& o : out) BOOST_TEST_MESSAGE(formatOutcome(o));
    BOOST_CHECK(out[0].status == CheckStatus::Pass);         // stratified < independent on log RMS
    BOOST_CHECK(out[1].status == CheckStatus::NotSeparated); // poisson = stratified
    BOOST_CHECK(out[2].status == CheckStatus::Fail);         // independent < stratified is reversed

    // A seed at the reference's noise floor (zero corrected RMS, no logarithm): the measured RMS is compared
    // instead. Measured RMS of 0.3 for every stratified seed against the independent ones still separates; with
    // a measured zero as well, only the mean-RMS intervals are left.
    for (auto& r : rows)
        if (r.pattern == "stratified") {
            r.rms = 0.3;
            if (r.seed == 1) r.rmsCorrected = 0;
        }
    cells = aggregate(rows);
    out = evaluateChecks(f.matrix, rows, cells, fitSlopes(rows, f.matrix));
    BOOST_CHECK(formatOutcome(out[0]).find("measured RMS, a seed at the floor") != std::string::npos);
    BOOST_CHECK(out[0].status == CheckStatus::Pass);
    for (auto& r : rows)
        if (r.pattern == "stratified" && r.seed == 1) r.rms = 0;
    cells = aggregate(rows);
    a = findCell(cells, "box", "stratified", 64);
    b = findCell(cells, "box", "independent", 64);
    out = evaluateChecks(f.matrix, rows, cells, fitSlopes(rows, f.matrix));
    BOOST_CHECK(formatOutcome(out[0]).find("mean RMS intervals") != std::string::npos);
    BOOST_CHECK(out[0].status == (separatedBelow(a->rms, b->rms) ? CheckStatus::Pass : CheckStatus::NotSeparated));
}

BOOST_AUTO_TEST_CASE(results_json_round_trips_and_baseline_compares) {
    Fixture f;
    Results r;
    r.matrixName = "m";
    r.rendererVersion = "test \"1\"";
    r.rows = syntheticRows();
    r.rows[0].rms = std::numeric_limits<double>::quiet_NaN(); // written as null, read as NaN
    sortRows(r.rows, f.matrix);
    SceneInfo s;
    s.name = "box";
    s.noiseFloor = 1e-5;
    r.scenes.push_back(s);
    r.skipped = {{"broken", "broken.yaml:3:1: key 'shapez': unknown key"}};
    auto cells = aggregate(r.rows);
    std::string path = (f.dir / "results.json").string();
    writeResultsJson(path, r, cells, fitSlopes(r.rows, f.matrix), Json::array());
    Results back = readResultsJson(path);
    BOOST_CHECK_EQUAL(back.rendererVersion, "test \"1\"");
    BOOST_REQUIRE_EQUAL(back.rows.size(), r.rows.size());
    BOOST_CHECK(std::isnan(back.rows[0].rms));
    BOOST_CHECK_EQUAL(back.rows[5].rmsCorrected, r.rows[5].rmsCorrected); // %.17g is exact
    BOOST_CHECK_EQUAL(back.scenes.at(0).noiseFloor, 1e-5);
    BOOST_CHECK(back.skipped == r.skipped);

    // A row without a finite error fails any baseline comparison (see no_verdict_from_cells_without_a_finite_error);
    // the rest compares rows that all have one.
    BOOST_CHECK(compareToBaseline(cells, aggregate(back.rows), 1.5).failed);
    r.rows[0].rms = back.rows[0].rms = r.rows[0].rmsCorrected;
    cells = aggregate(r.rows);
    // Same run: no regression. Worse RMS beyond the intervals, or slower beyond the factor: FAIL.
    BOOST_CHECK(!compareToBaseline(cells, aggregate(back.rows), 1.5).failed);
    auto worse = r.rows;
    for (auto& row : worse)
        if (row.pattern == "stratified" && row.spp == 64) row.rmsCorrected *= 1.2;
    auto cmp = compareToBaseline(aggregate(worse), cells, 1.5);
    BOOST_CHECK(cmp.failed);
    BOOST_REQUIRE_EQUAL(cmp.lines.size(), 1u);
    BOOST_CHECK(cmp.lines[0].find("FAIL rms  box stratified @ 64 spp") == 0);
    auto slower = r.rows;
    for (auto& row : slower) row.renderSeconds *= 2;
    BOOST_CHECK(compareToBaseline(aggregate(slower), cells, 1.5).failed);
    BOOST_CHECK(!compareToBaseline(aggregate(slower), cells, 2.5).failed);

    BOOST_CHECK_THROW(readResultsJson((f.dir / "m.yaml").string()), std::runtime_error);
}

BOOST_AUTO_TEST_CASE(results_json_of_the_hand_written_format_reads) {
    // A file as the writer before the field lists made it (same format tag): %.17g numbers, null for NaN,
    // one object per line, no skipped_scenes.
    Fixture f;
    const std::string path = (f.dir / "old.json").string();
    std::ofstream(path) << "{\n  \"format\": \"stipple-validate results 1\",\n  \"matrix\": \"quick\",\n"
                           "  \"renderer_version\": \"stipple-render 1.0.0\",\n  \"scenes\": [\n"
                           "    {\"name\": \"box\", \"file\": \"box.yaml\", \"width\": 64, \"height\": 64, "
                           "\"noise_floor\": 2.5000000000000001e-05}\n  ],\n  \"rows\": [\n"
                           "    {\"scene\": \"box\", \"pattern\": \"independent\", \"spp\": 4, \"seed\": 1, "
                           "\"rms\": 0.10000000000000001, \"mse\": null, \"floor_limited\": true}\n  ],\n"
                           "  \"cells\": [],\n  \"slopes\": [],\n  \"checks\": []\n}\n";
    const Results r = readResultsJson(path);
    BOOST_CHECK_EQUAL(r.matrixName, "quick");
    BOOST_REQUIRE_EQUAL(r.rows.size(), 1u);
    BOOST_CHECK_EQUAL(r.rows[0].rms, 0.1);
    BOOST_CHECK(std::isnan(r.rows[0].mse));
    BOOST_CHECK(r.rows[0].floorLimited);
    BOOST_CHECK_EQUAL(r.scenes.at(0).noiseFloor, 2.5e-5);
    BOOST_CHECK(r.skipped.empty());
    // A row without its scene is named with its index.
    std::ofstream(path) << "{\"format\": \"stipple-validate results 1\", \"rows\": [{\"pattern\": \"x\"}]}";
    BOOST_CHECK_EXCEPTION(readResultsJson(path), std::runtime_error, [](const std::runtime_error& e) {
        return std::string(e.what()).find("rows[0] lacks 'scene'") != std::string::npos;
    });
}

BOOST_AUTO_TEST_CASE(csv_fields_are_quoted) {
    // Scene names are free text: a comma, a quote or a line break must not shift the columns.
    BOOST_CHECK_EQUAL(csvField("plain-name"), "plain-name");
    BOOST_CHECK_EQUAL(csvField("a,b"), "\"a,b\"");
    BOOST_CHECK_EQUAL(csvField("say \"hi\""), "\"say \"\"hi\"\"\"");
    BOOST_CHECK_EQUAL(csvField("two\nlines"), "\"two\nlines\"");
    ResultRow row;
    row.scene = "box, lit";
    row.pattern = "independent";
    row.rms = 0.25;
    const std::string line = csvRow(row, resultRowFields());
    BOOST_CHECK(line.rfind("\"box, lit\",independent,", 0) == 0);
    BOOST_CHECK_EQUAL(csvHeader(resultRowFields()).substr(0, 24), "scene,pattern,spp,seed,w");
}

BOOST_AUTO_TEST_CASE(bitwise_equal_seed_renders_are_named) {
    // Four seeds of one cell; seeds 2 and 7 rendered the same image (the same per-block errors), as a renderer that
    // keeps 31 bits of {seed} would for 2 and 2 + 2^31. A black cell (every block 0) is not a repeat.
    std::vector<ResultRow> rows;
    const std::vector<std::vector<double>> blocks = {{1, 2, 3}, {4, 5, 6}, {1, 2, 3.5}, {4, 5, 6}};
    const uint64_t seeds[] = {1, 2, 5, 7};
    for (size_t i = 0; i < 4; ++i) {
        ResultRow r;
        r.scene = "box";
        r.pattern = "stratified";
        r.spp = 8;
        r.seed = seeds[i];
        r.blockSse = blocks[i];
        r.mse = blocks[i][0];
        rows.push_back(r);
        r.pattern = "independent";
        r.blockSse = {0, 0, 0};
        r.mse = 0;
        rows.push_back(r);
    }
    const std::vector<std::string> found = identicalSeedRenders(rows);
    BOOST_REQUIRE_EQUAL(found.size(), 1u);
    BOOST_CHECK_MESSAGE(found[0].find("box, stratified, 8 spp") != std::string::npos, found[0]);
    BOOST_CHECK_MESSAGE(found[0].find("seeds 2, 7") != std::string::npos, found[0]);
    BOOST_CHECK_MESSAGE(found[0].find("64-bit") != std::string::npos, found[0]);
    rows[2].blockSse = {4, 5, 6.5}; // seed 2 (stratified) now differs from seed 7
    BOOST_CHECK(identicalSeedRenders(rows).empty());
}

BOOST_AUTO_TEST_CASE(refuted_study_statements_are_not_counted_as_failures) {
    // As the terminal counts: FAIL is what fails the run. A study statement the data refutes (fails_run: false) is
    // refuted, a library finding that did not hold and does not fail the run is reported.
    std::vector<CheckOutcome> o(6);
    o[0].status = CheckStatus::Pass;
    o[1].status = CheckStatus::Fail, o[1].failsRun = true;
    o[2].status = CheckStatus::Fail, o[2].check.study = "Poisson disk as good as stratified per sample";
    o[3].status = CheckStatus::Fail;
    o[4].status = CheckStatus::NotSeparated;
    o[5].status = CheckStatus::NotSeparated, o[5].failsRun = true;
    const ClaimCounts n = countClaims(o);
    BOOST_CHECK_EQUAL(n.total, 6u);
    BOOST_CHECK_EQUAL(n.pass, 1u);
    BOOST_CHECK_EQUAL(n.fail, 2u);
    BOOST_CHECK_EQUAL(n.refuted, 1u);
    BOOST_CHECK_EQUAL(n.reported, 1u);
    BOOST_CHECK_EQUAL(n.notSeparated, 1u);
}

BOOST_AUTO_TEST_CASE(no_verdict_from_cells_without_a_finite_error) {
    // Every stratified seed measured against an image with no finite pixel: its MSE is not a number. Each
    // aggregate that meets it says so, and no claim that needs the cell passes.
    Fixture f;
    std::ofstream(f.dir / "claims.yaml") << R"(scenes: [box.yaml]
patterns: [independent, stratified, poisson]
spp: [4, 16, 64]
seeds: 4
reference: { spp: 1024 }
checks:
  - { type: ordering, scene: box, spp_min: 16, order: [stratified, independent] }
  - { type: slope, scene: box, pattern: stratified, expected: -0.75, tolerance: 0.05 }
  - { type: compare, scene: box, patterns: [stratified, independent], basis: samples, expect: better }
  - { type: equal_spp, scene: box, order: [stratified, independent] }
)";
    const Matrix m = loadMatrix((f.dir / "claims.yaml").string(), test::kVocabulary);
    const double floor = 1e-4;
    BOOST_CHECK(std::isnan(correctedMse(std::nan(""), floor))); // never max(NaN − floor, 0) = 0
    BOOST_CHECK(std::isnan(correctedMse(0.5, std::nan(""))));
    BOOST_CHECK_EQUAL(correctedMse(0.5, floor), 0.5 - floor);
    std::vector<ResultRow> rows = syntheticRows();
    for (ResultRow& r : rows) {
        r.mseCorrected = correctedMse(r.mse, floor);
        r.rmsCorrected = std::sqrt(r.mseCorrected);
        if (r.pattern != "stratified") continue;
        r.mse = r.rms = std::nan(""); // what compareImages gives an image with no finite pixel
        r.mseCorrected = correctedMse(r.mse, floor);
        r.rmsCorrected = std::sqrt(r.mseCorrected);
    }
    sortRows(rows, m);
    const auto cells = aggregate(rows);
    const CellAggregate* broken = findCell(cells, "box", "stratified", 64);
    BOOST_REQUIRE(broken);
    BOOST_CHECK_EQUAL(broken->unmeasuredSeeds, 4u);
    BOOST_CHECK(!std::isfinite(broken->rms.mean));
    BOOST_CHECK_EQUAL(findCell(cells, "box", "independent", 64)->unmeasuredSeeds, 0u);
    const auto slopes = fitSlopes(rows, m);
    for (const auto& s : slopes)
        if (s.pattern == "stratified") BOOST_CHECK(std::isnan(s.fit.slope)); // not a fit of the remaining points
    const auto out = evaluateChecks(m, rows, cells, slopes);
    BOOST_REQUIRE_EQUAL(out.size(), 4u);
    for (const auto& o : out) {
        BOOST_TEST_MESSAGE(formatOutcome(o));
        BOOST_CHECK_MESSAGE(o.status != CheckStatus::Pass, formatOutcome(o));
        BOOST_CHECK(o.failsRun);
    }
    BOOST_CHECK(out[0].status == CheckStatus::Fail);
    BOOST_CHECK(formatOutcome(out[0]).find("without a finite error") != std::string::npos);
    BOOST_CHECK(out[1].status == CheckStatus::Fail);
    // The baseline: a cell without a finite error now, or in the baseline, fails the comparison.
    const auto good = aggregate([&] {
        auto r = syntheticRows();
        sortRows(r, m);
        return r;
    }());
    const BaselineComparison now = compareToBaseline(cells, good, 10.0);
    BOOST_CHECK(now.failed);
    const BaselineComparison before = compareToBaseline(good, cells, 10.0);
    BOOST_CHECK(before.failed);
}
