// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Matrix parsing: a good matrix reads back; malformed ones fail with file:line:column and name the culprit.
#define BOOST_TEST_MODULE validation_matrix
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "matrix/check_kind.h"
#include "matrix/matrix.h"
#include "test_vocabulary.h"

#include <stipple/testing/scratch_folder.h>

using namespace stipple::validation;
namespace fs = std::filesystem;

namespace {
// A folder with two (empty) scene files; the parser only checks that they exist.
struct Fixture {
    fs::path dir;
    Fixture() {
        dir = stipple::testing::freshScratchFolder("matrix");
        fs::create_directories(dir / "scenes");
        std::ofstream(dir / "scenes" / "box.yaml") << "name: box\n";
        std::ofstream(dir / "scenes" / "mis.yaml") << "name: mis\n";
    }
    ~Fixture() { fs::remove_all(dir); }
    std::string path() const { return (dir / "m.yaml").string(); }
};

const char* good = R"(name: tiny
scenes:
  - file: scenes/box.yaml
    width: 32
    height: 24
  - { file: scenes/mis.yaml, name: veach }
patterns: [independent, stratified, poisson]
spp: [16, 4]
seeds: 4
reference: { spp: 256, seed: 99 }
checks:
  - { type: ordering, scene: box, spp_min: 16, order: [stratified, independent], not_separated: pass }
  - { type: slope, scene: veach, pattern: independent, expected: -0.5, tolerance: 0.1 }
  - { type: time_ratio, scene: all, numerator: poisson, denominator: stratified, max: 1.05 }
  - { type: time_ceiling, seconds: 5 }
)";

// Expects MatrixError whose message contains every piece.
void expectError(const Fixture& f, const std::string& text, std::vector<std::string> pieces) {
    try {
        parseMatrix(text, f.path(), test::kVocabulary);
        BOOST_ERROR("no error for:\n" + text);
    } catch (const MatrixError& e) {
        std::string msg = e.what();
        for (const auto& p : pieces)
            BOOST_CHECK_MESSAGE(msg.find(p) != std::string::npos, "'" << p << "' not in: " << msg);
    }
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
    auto at = s.find(from);
    BOOST_REQUIRE(at != std::string::npos);
    return s.replace(at, from.size(), to);
}
} // namespace

BOOST_AUTO_TEST_CASE(good_matrix_reads) {
    Fixture f;
    Matrix m = parseMatrix(good, f.path(), test::kVocabulary);
    BOOST_CHECK_EQUAL(m.name, "tiny");
    BOOST_REQUIRE_EQUAL(m.scenes.size(), 2u);
    BOOST_CHECK_EQUAL(m.scenes[0].name, "box"); // default: file stem
    BOOST_CHECK_EQUAL(m.scenes[0].width, 32);
    BOOST_CHECK_EQUAL(m.scenes[1].name, "veach");
    BOOST_CHECK(fs::exists(m.scenes[1].path));
    BOOST_CHECK((m.spp == std::vector<uint32_t>{4, 16})); // sorted
    BOOST_CHECK((m.seeds == std::vector<uint64_t>{1, 2, 3, 4}));
    BOOST_CHECK_EQUAL(m.reference.spp, 256u);
    BOOST_CHECK_EQUAL(m.scenes[1].referenceSpp, 0u); // 0: the matrix's reference spp
    BOOST_CHECK_EQUAL(m.reference.pattern, "independent");
    BOOST_REQUIRE_EQUAL(m.checks.size(), 4u);
    BOOST_CHECK_EQUAL(m.checks[0].kind->name, std::string("ordering"));
    BOOST_CHECK(!m.checks[0].notSeparatedFails);
    BOOST_CHECK_EQUAL(m.checks[0].where, f.path() + ":12:5");
    BOOST_CHECK_EQUAL(m.checks[2].kind->name, std::string("time_ratio"));
    BOOST_CHECK_EQUAL(checkClaimJson(m.checks[2])["spp"], 16u); // default: the largest
    BOOST_CHECK_EQUAL(m.checks[3].scene, "all");
}

BOOST_AUTO_TEST_CASE(yaml_syntax_error_has_line_and_column) {
    Fixture f;
    expectError(f, "name: x\nscenes:\n  - file: a\n   width: 3\n", {f.path() + ":4:4", "end of sequence not found"});
    expectError(f, "patterns: [independent, stratified\nspp: 4\n", {f.path() + ":2:"});
}

BOOST_AUTO_TEST_CASE(duplicate_keys_are_rejected) {
    // yaml-cpp keeps both entries; the strict reader names the second.
    Fixture f;
    expectError(f, replaced(good, "seeds: 4", "seeds: 4\nseeds: 5"), {f.path() + ":10:1", "duplicate key 'seeds'"});
}

BOOST_AUTO_TEST_CASE(unknown_names_are_named) {
    Fixture f;
    expectError(f, replaced(good, "scenes/mis.yaml", "scenes/nope.yaml"),
                {f.path() + ":6:5", "unknown scene file 'scenes/nope.yaml'"});
    expectError(f, replaced(good, "[independent, stratified, poisson]", "[independent, hammersley]"),
                {f.path() + ":7:", "unknown pattern 'hammersley'", "poisson-seed"});
    expectError(f, replaced(good, "type: slope", "type: variance"),
                {f.path() + ":13:13", "unknown check type 'variance'"});
    expectError(f, replaced(good, "scene: veach", "scene: cornell"),
                {f.path() + ":13:27", "unknown scene 'cornell'", "box, veach"});
    expectError(f, replaced(good, "numerator: poisson", "numerator: poisson-seed"),
                {":14:48", "'poisson-seed' is not among the matrix's patterns"});
    expectError(f, replaced(good, "seeds: 4", "sedes: 4"), {f.path() + ":9:1", "unknown key 'sedes'"});
}

BOOST_AUTO_TEST_CASE(bad_values_are_errors) {
    Fixture f;
    expectError(f, replaced(good, "seeds: 4", "seeds: 3"), {f.path() + ":9:", "K ≥ 4"});
    expectError(f, replaced(good, "seeds: 4", "seeds: many"), {f.path() + ":9:8", "cannot read seeds from 'many'"});
    expectError(f, replaced(good, "spp: 256", "spp: 32"), {"must be ≥ 4× the largest cell spp"});
    expectError(f, replaced(good, "width: 32", "width: -2"), {f.path() + ":4:12", "width must be in"});
    expectError(f, replaced(good, "seed: 99", "seed: 3"), {"reference seed must differ"});
    expectError(f, replaced(good, "name: veach }", "name: veach, reference_spp: 32 }"),
                {f.path() + ":6:5", "reference_spp (32) must be ≥ 4× the largest cell spp (16)"});
    expectError(f, replaced(good, "max: 1.05", "max: 0"), {":14:87", "max must be > 0"});
    expectError(f, replaced(good, "max: 1.05", "max: 1.05, margin: [0.9, 1.1]"), {":14:", "max or margin, not both"});
    expectError(f, replaced(good, "max: 1.05", "margin: [1.1, 1.2]"), {":14:", "margin must hold 1 strictly inside"});
    expectError(f, "- a\n- b\n", {f.path() + ":1:1", "must be a YAML map"});
}

BOOST_AUTO_TEST_CASE(a_region_every_scene_has_serves_scene_all) {
    // Both scenes with a region 'shadow': one compare claim covers it in both; a region only one scene has is
    // refused naming the scene that lacks it.
    Fixture f;
    std::string text =
        replaced(good, "    height: 24\n", "    height: 24\n    regions: [{ name: shadow, rect: [0, 0.5, 1, 1] }]\n");
    text = replaced(text, "name: veach }", "name: veach, regions: [{ name: shadow, rect: [0, 0, 0.5, 1] }] }");
    const std::string claim = "  - { type: compare, region: shadow, patterns: [stratified, independent] }\n";
    const Matrix m = parseMatrix(text + claim, f.path(), test::kVocabulary);
    BOOST_REQUIRE_EQUAL(m.checks.size(), 5u);
    BOOST_CHECK_EQUAL(m.checks[4].scene, "all");
    BOOST_CHECK_EQUAL(checkClaimJson(m.checks[4])["region"], "shadow");
    expectError(f,
                replaced(text, "name: veach, regions: [{ name: shadow", "name: veach, regions: [{ name: floor") + claim,
                {":17:", "region 'shadow' is not a region of every scene", "veach lack it"});
    expectError(f, text + "  - { type: compare, scene: box, region: floor, patterns: [stratified, independent] }\n",
                {":17:", "region must be 'image' or a region of the one scene named, got 'floor'"});
}

BOOST_AUTO_TEST_CASE(missing_file_is_named) {
    BOOST_CHECK_EXCEPTION(loadMatrix("no/such/matrix.yaml", test::kVocabulary), MatrixError, [](const MatrixError& e) {
        return std::string(e.what()).find("no/such/matrix.yaml") != std::string::npos;
    });
}

// Regions, equal_time / equal_spp checks and the time_ratio's not_separated default.
BOOST_AUTO_TEST_CASE(regions_and_study_claims) {
    Fixture f;
    const std::string withRegions =
        replaced(replaced(good, "    height: 24\n",
                          "    height: 24\n    regions: [{ name: shade, rect: [0.1, 0.5, 0.6, 1.0] }]\n"),
                 "  - { type: time_ceiling, seconds: 5 }\n",
                 "  - { type: time_ceiling, seconds: 5 }\n"
                 "  - { type: equal_time, scene: box, order: [stratified, independent], study: \"stratified first\" }\n"
                 "  - { type: equal_spp, scene: box, region: shade, metric: flip, order: [poisson, stratified] }\n");
    std::ofstream(f.path()) << withRegions;
    Matrix m = loadMatrix(f.path(), test::kVocabulary);
    BOOST_REQUIRE_EQUAL(m.scenes[0].regions.size(), 1u);
    BOOST_CHECK_EQUAL(m.scenes[0].regions[0].name, "shade");
    BOOST_CHECK_CLOSE(m.scenes[0].regions[0].x1, 0.6, 1e-12);
    BOOST_CHECK(!m.checks[2].notSeparatedFails); // time_ratio: an undecided interval does not fail the run
    BOOST_CHECK_EQUAL(m.checks[4].kind->name, std::string("equal_time"));
    BOOST_CHECK_EQUAL(m.checks[4].study, "stratified first");
    BOOST_CHECK_EQUAL(checkClaimJson(m.checks[4])["spp"], 16u);
    BOOST_CHECK_EQUAL(m.checks[5].kind->name, std::string("equal_spp"));
    BOOST_CHECK_EQUAL(checkClaimJson(m.checks[5])["metric"], "flip");
    BOOST_CHECK_EQUAL(checkClaimJson(m.checks[5])["region"], "shade");

    expectError(f, replaced(withRegions, "[0.1, 0.5, 0.6, 1.0]", "[0.7, 0.5, 0.6, 1.0]"),
                {f.path() + ":6:", "0 ≤ x0 < x1 ≤ 1"});
    expectError(f, replaced(withRegions, "[0.1, 0.5, 0.6, 1.0]", "[0.1, 0.5]"),
                {f.path() + ":6:", "rect must be [x0, y0, x1, y1]"});
    expectError(f, replaced(withRegions, "region: shade", "region: glow"),
                {f.path() + ":18:", "unknown region 'glow' of scene box", "shade"});
    expectError(f, replaced(withRegions, "metric: flip", "metric: ssim"),
                {f.path() + ":18:", "metric must be mse or flip"});
    expectError(f, replaced(withRegions, "study: \"stratified first\"", "studdy: x"),
                {f.path() + ":17:", "unknown key 'studdy'"});
}
