// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The fingerprint --merge compares: field order, the first difference (values and absent fields), the matrix-only
// fields, and the round trip through results.json.
#define BOOST_TEST_MODULE validation_shard_fingerprint
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "run/results.h"
#include "run/shard_fingerprint.h"
#include "test_vocabulary.h"

#include <stipple/testing/scratch_folder.h>

using namespace stipple::validation;
namespace fs = std::filesystem;

namespace {
struct Fixture {
    fs::path dir = stipple::testing::freshScratchFolder("fingerprint");
    Matrix matrix;
    Fixture() {
        fs::create_directories(dir);
        std::ofstream(dir / "box.yaml") << "name: box\n";
        matrix =
            parseMatrix("scenes:\n  - { file: box.yaml, name: box, width: 16 }\npatterns: [independent, stratified]\n"
                        "spp: [1, 4]\nseeds: 4\nreference: { spp: 16, seed: 7 }\n"
                        "checks:\n  - { type: time_ceiling, seconds: 30 }\n",
                        (dir / "m.yaml").string(), test::kVocabulary);
    }
    ~Fixture() { fs::remove_all(dir); }
    SceneFingerprint box() const {
        SceneFingerprint s;
        s.loaded = true;
        s.contentHash = "00ff";
        s.width = 16;
        s.height = 16;
        s.integrator = "path";
        s.maxDepth = 8;
        s.referenceSpp = 16;
        return s;
    }
    Fingerprint run(const SceneFingerprint& s, const std::string& version = "r 1") const {
        return runFingerprint(matrix, {s}, version, "shim 1 abc");
    }
    // A shard folder whose results.json carries `f`.
    std::string shard(const std::string& name, const Fingerprint& f) const {
        fs::create_directories(dir / name);
        Results r;
        r.matrixName = "m";
        r.rendererVersion = "r 1";
        r.fingerprint = f;
        writeResultsJson((dir / name / "results.json").string(), r, {}, {}, "");
        return (dir / name).string();
    }
};
} // namespace

BOOST_FIXTURE_TEST_CASE(fields_in_order_and_equal_runs_agree, Fixture) {
    Fingerprint f = run(box());
    BOOST_TEST(f.fields.front().name == "matrix.scenes");
    BOOST_TEST(f.fields.back().name == "shim.identity");
    BOOST_REQUIRE(f.find("scene.box.width"));
    BOOST_TEST(f.find("scene.box.width")->value == "16");
    BOOST_TEST(f.find("matrix.seeds")->value == "[1,2,3,4]");
    BOOST_TEST(f.find("matrix.checks")->value.find("time_ceiling") != std::string::npos);
    BOOST_TEST(!firstDifference(f, run(box())));
}

// Every field that defines a comparison claim is in the fingerprint: shards of matrices that differ in one of
// them do not merge (each of these once left the fingerprint unchanged).
BOOST_FIXTURE_TEST_CASE(comparison_claims_fields_differ, Fixture) {
    auto withCheck = [&](const std::string& check) {
        Matrix m = parseMatrix("scenes:\n  - { file: box.yaml, name: box, width: 16 }\n"
                               "patterns: [independent, stratified]\nspp: [1, 4]\nseeds: 4\n"
                               "reference: { spp: 16, seed: 7 }\nchecks:\n  - " + check + "\n",
                               (dir / "m.yaml").string(), test::kVocabulary);
        return runFingerprint(m, {box()}, "r 1", "shim 1 abc");
    };
    const std::string base = "{ type: compare, patterns: [independent, stratified], basis: samples, expect: equivalent }";
    const Fingerprint a = withCheck(base);
    for (const std::string& other :
         {std::string("{ type: compare, patterns: [stratified, independent], basis: samples, expect: equivalent }"),
          std::string("{ type: compare, patterns: [independent, stratified], basis: time, expect: equivalent }"),
          std::string("{ type: compare, patterns: [independent, stratified], basis: samples, expect: better }"),
          std::string("{ type: compare, patterns: [independent, stratified], basis: samples, expect: equivalent, "
                      "margin: [0.9, 1.1] }"),
          std::string("{ type: compare, patterns: [independent, stratified], basis: samples, expect: equivalent, "
                      "fails_run: false }")}) {
        const auto d = firstDifference(a, withCheck(other));
        BOOST_TEST_CONTEXT(other) {
            BOOST_REQUIRE(d);
            BOOST_TEST(d->field == "matrix.checks");
        }
    }
    BOOST_TEST(!firstDifference(a, withCheck(base)));
}

// The fingerprint walks the key list each kind reads: a key that changes a claim changes the fingerprint, whatever
// the kind (not_separated was once read for four kinds and fingerprinted for one).
BOOST_FIXTURE_TEST_CASE(every_claim_key_is_fingerprinted, Fixture) {
    auto withCheck = [&](const std::string& check) {
        Matrix m = parseMatrix("scenes:\n  - { file: box.yaml, name: box, width: 16 }\n"
                               "patterns: [independent, stratified]\nspp: [1, 4]\nseeds: 4\n"
                               "reference: { spp: 16, seed: 7 }\nchecks:\n  - " + check + "\n",
                               (dir / "m.yaml").string(), test::kVocabulary);
        return matrixFingerprint(m);
    };
    const std::pair<std::string, std::string> variants[] = {
        {"{ type: ordering, scene: box, order: [stratified, independent] }",
         "{ type: ordering, scene: box, order: [stratified, independent], not_separated: pass }"},
        {"{ type: time_ratio, numerator: stratified, denominator: independent, max: 2 }",
         "{ type: time_ratio, numerator: stratified, denominator: independent, max: 2, not_separated: fail }"},
        {"{ type: equal_time, scene: box, order: [stratified, independent] }",
         "{ type: equal_time, scene: box, order: [stratified, independent], not_separated: fail }"},
        {"{ type: equal_spp, scene: box, order: [stratified, independent] }",
         "{ type: equal_spp, scene: box, order: [stratified, independent], spp: 1 }"},
        {"{ type: compare, patterns: [independent, stratified] }",
         "{ type: compare, patterns: [independent, stratified], not_separated: fail }"},
        {"{ type: slope, scene: box, pattern: independent, expected: -0.5, tolerance: 0.1 }",
         "{ type: slope, scene: box, pattern: independent, expected: -0.5, tolerance: 0.2 }"},
        {"{ type: time_ceiling, seconds: 30 }", "{ type: time_ceiling, scene: box, seconds: 30 }"},
    };
    for (const auto& [a, b] : variants) {
        BOOST_TEST_CONTEXT(b) {
            const auto d = firstDifference(withCheck(a), withCheck(b));
            BOOST_REQUIRE(d);
            BOOST_TEST(d->field == "matrix.checks");
        }
    }
    // The study's wording is a label, not a claim: the same claim with another label merges.
    BOOST_TEST(!firstDifference(withCheck("{ type: compare, patterns: [independent, stratified], study: one }"),
                                withCheck("{ type: compare, patterns: [independent, stratified], study: two }")));
}

BOOST_FIXTURE_TEST_CASE(first_difference_names_field_and_values, Fixture) {
    SceneFingerprint deeper = box(), wider = box();
    deeper.maxDepth = 3;
    wider.width = 32;
    wider.maxDepth = 3; // width comes first
    auto d = firstDifference(run(box()), run(wider));
    BOOST_REQUIRE(d);
    BOOST_TEST(d->field == "scene.box.width");
    BOOST_TEST(d->a == "16");
    BOOST_TEST(d->b == "32");
    d = firstDifference(run(box()), run(deeper));
    BOOST_REQUIRE(d);
    BOOST_TEST(d->field == "scene.box.max_depth");
    d = firstDifference(run(box()), run(box(), "r 2"));
    BOOST_REQUIRE(d);
    BOOST_TEST(d->field == "renderer.version");
    BOOST_TEST(d->b == "\"r 2\"");
    // Only the matrix fields: the renderer version is not among them.
    BOOST_TEST(!firstDifference(run(box()), run(box(), "r 2"), "matrix."));
}

BOOST_FIXTURE_TEST_CASE(absent_fields_and_unloaded_scenes, Fixture) {
    Fingerprint a = run(box()), b = a;
    b.fields.pop_back();
    auto d = firstDifference(a, b);
    BOOST_REQUIRE(d);
    BOOST_TEST(d->field == "shim.identity");
    BOOST_TEST(d->b == "(absent)");
    d = firstDifference(b, a);
    BOOST_REQUIRE(d);
    BOOST_TEST(d->a == "(absent)");
    // A scene that did not load: null settings, equal to another run where it did not load either.
    Fingerprint skipped = run(SceneFingerprint{});
    BOOST_TEST(skipped.find("scene.box.width")->value == "null");
    BOOST_TEST(!firstDifference(skipped, run(SceneFingerprint{})));
    d = firstDifference(run(box()), skipped);
    BOOST_REQUIRE(d);
    BOOST_TEST(d->field == "scene.box.content_hash");
}

BOOST_FIXTURE_TEST_CASE(round_trip_and_merge_gate, Fixture) {
    Fingerprint f = run(box());
    std::string s1 = shard("s1", f);
    BOOST_TEST(readFingerprint(s1 + "/results.json").fields == f.fields);
    BOOST_TEST(readResultsJson(s1 + "/results.json").fingerprint.fields == f.fields);
    std::string s2 = shard("s2", f);
    BOOST_CHECK_NO_THROW(checkShardFingerprints(matrix, {s1, s2}));

    SceneFingerprint other = box();
    other.referenceSpp = 32;
    std::string s3 = shard("s3", run(other));
    try {
        checkShardFingerprints(matrix, {s1, s2, s3});
        BOOST_FAIL("shards with different reference spp merged");
    } catch (const std::runtime_error& e) {
        std::string msg = e.what();
        BOOST_TEST(msg.find("scene.box.reference_spp: 16 (" + s1 + ") vs 32 (" + s3 + ")") != std::string::npos, msg);
    }
    // No fingerprint (an older results.json): refused, naming the file.
    std::string old = shard("old", Fingerprint{});
    BOOST_CHECK_EXCEPTION(
        checkShardFingerprints(matrix, {s1, old}), std::runtime_error, [&](const std::runtime_error& e) {
            return std::string(e.what()).find(old + "/results.json has no fingerprint") != std::string::npos;
        });
    // Only the checks edited: the merge evaluates its own.
    Matrix newClaims = matrix;
    newClaims.checks.clear();
    BOOST_CHECK_NO_THROW(checkShardFingerprints(newClaims, {s1, s2}));
    // The shards agree but --merge is given another matrix.
    Matrix edited = matrix;
    edited.spp = {1, 8};
    BOOST_CHECK_EXCEPTION(
        checkShardFingerprints(edited, {s1, s2}), std::runtime_error, [&](const std::runtime_error& e) {
            return std::string(e.what()).find("matrix.spp: [1,4] (" + s1 + ") vs [1,8]") != std::string::npos;
        });
}
