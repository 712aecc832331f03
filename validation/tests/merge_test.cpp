// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// mergeShards on synthetic shard folders: the union of the rows in the matrix's order, and an error naming the
// folder for a duplicate row, a differing renderer version (through the fingerprint) and a missing row.
#define BOOST_TEST_MODULE validation_merge
#include <boost/test/unit_test.hpp>

#include <cmath>

#include <filesystem>
#include <functional>
#include <unistd.h>

#include "metrics/image_metrics.h"
#include "run/merge.h"
#include "run/results.h"
#include "run/shard_fingerprint.h"

#include <stipple/testing/scratch_folder.h>

using namespace stipple::validation;
namespace fs = std::filesystem;

namespace {

struct Shards {
    fs::path dir = stipple::testing::freshScratchFolder("merge");
    Matrix matrix;
    Shards() {
        fs::create_directories(dir);
        matrix.name = "m";
        matrix.path = "m.yaml";
        MatrixScene s;
        s.name = "box";
        matrix.scenes = {s};
        matrix.patterns = {"independent", "stratified"};
        matrix.spp = {4};
        matrix.seeds = {1, 2};
    }
    std::string contentHash = "0123456789abcdef", integrator = "path";
    int side = 16; // the renders' width and height
    ~Shards() { fs::remove_all(dir); }
    // A shard folder holding the rows (pattern, seed) given.
    // `edit` changes each row after it is made as a measurement would make it.
    std::string shard(const std::string& name, const std::vector<std::pair<std::string, uint64_t>>& rows,
                      const std::string& version = "stipple-render 1",
                      const std::function<void(ResultRow&)>& edit = [](ResultRow&) {}) {
        const fs::path d = dir / name;
        fs::create_directories(d);
        Results r;
        r.matrixName = "m";
        r.rendererVersion = version;
        SceneInfo info;
        info.name = "box";
        info.width = info.height = side;
        info.contentHash = contentHash;
        info.integrator = integrator;
        r.scenes = {info};
        for (const auto& [pattern, seed] : rows) {
            ResultRow row;
            row.scene = "box";
            row.pattern = pattern;
            row.spp = 4;
            row.seed = seed;
            row.width = row.height = side;
            row.rms = 0.5 + double(seed) / 8;
            row.mse = row.rms * row.rms;
            row.renderSeconds = 0.01;
            // side² pixels in blocks of 8x8: each block's squared error is mse × 64 pixels.
            const size_t blocks = size_t(blockCount(side, side));
            row.blockSse.assign(blocks, row.mse * 64);
            row.blockRse.assign(blocks, 0.25);
            row.blockFlip.assign(blocks, 1.0);
            edit(row);
            r.rows.push_back(row);
        }
        SceneFingerprint box;
        box.loaded = true;
        box.width = box.height = side;
        r.fingerprint = runFingerprint(matrix, {box}, version, "shim 1");
        writeResultsJson((d / "results.json").string(), r, {}, {}, Json::array());
        return d.string();
    }
    std::string out() const { return (dir / "merged").string(); }
};

bool mentions(const std::runtime_error& e, const std::string& what) {
    return std::string(e.what()).find(what) != std::string::npos;
}

} // namespace

BOOST_AUTO_TEST_CASE(union_in_matrix_order) {
    Shards s;
    const std::string a = s.shard("a", {{"stratified", 2}, {"independent", 1}});
    const std::string b = s.shard("b", {{"stratified", 1}, {"independent", 2}});
    const Results merged = mergeShards(s.matrix, {a, b}, s.out());
    BOOST_REQUIRE_EQUAL(merged.rows.size(), 4u);
    BOOST_TEST(merged.rows[0].pattern == "independent");
    BOOST_TEST(merged.rows[0].seed == 1u);
    BOOST_TEST(merged.rows[3].pattern == "stratified");
    BOOST_TEST(merged.rows[3].seed == 2u);
    BOOST_TEST(merged.rows[3].rms == 0.75);
    BOOST_REQUIRE_EQUAL(merged.scenes.size(), 1u);
    BOOST_TEST(merged.rendererVersion == "stipple-render 1");
}

BOOST_AUTO_TEST_CASE(duplicate_row_names_the_folder) {
    Shards s;
    const std::string a = s.shard("a", {{"independent", 1}, {"independent", 2}, {"stratified", 1}});
    const std::string b = s.shard("b", {{"stratified", 1}, {"stratified", 2}});
    BOOST_CHECK_EXCEPTION(mergeShards(s.matrix, {a, b}, s.out()), std::runtime_error,
                          [&](const auto& e) { return mentions(e, b) && mentions(e, "appears in two shards"); });
}

BOOST_AUTO_TEST_CASE(renderer_versions_must_agree) {
    Shards s;
    const std::string a = s.shard("a", {{"independent", 1}, {"independent", 2}});
    const std::string b = s.shard("b", {{"stratified", 1}, {"stratified", 2}}, "stipple-render 2");
    BOOST_CHECK_EXCEPTION(mergeShards(s.matrix, {a, b}, s.out()), std::runtime_error,
                          [&](const auto& e) { return mentions(e, b) && mentions(e, "renderer.version"); });
}

BOOST_AUTO_TEST_CASE(missing_rows_are_an_error) {
    Shards s;
    const std::string a = s.shard("a", {{"independent", 1}, {"independent", 2}, {"stratified", 1}});
    BOOST_CHECK_EXCEPTION(mergeShards(s.matrix, {a}, s.out()), std::runtime_error, [](const auto& e) {
        return mentions(e, "1 cell × seed rows") && mentions(e, "box stratified 4 spp seed 2");
    });
}

// A shard's rows are input: a value no measurement gives is an error naming the folder, the row and the value.
BOOST_AUTO_TEST_CASE(rows_no_measurement_gives_are_refused) {
    const std::vector<std::pair<std::string, std::function<void(ResultRow&)>>> cases = {
        {"rms -0.5 is not a finite value", [](ResultRow& r) { r.rms = -0.5; }},
        {"is not the square root of mse", [](ResultRow& r) { r.mse = 1e300; }},
        {"mse -1 is not a finite value", [](ResultRow& r) { r.mse = -1; }},
        {"render_seconds -1 is not a time", [](ResultRow& r) { r.renderSeconds = -1; }},
        {"cpu_seconds 1e+12 is not a time", [](ResultRow& r) { r.cpuSeconds = 1e12; }},
        {"size 32x16 is not the scene's 16x16", [](ResultRow& r) { r.width = 32; }},
        {"region values for 1 regions; the scene has 0", [](ResultRow& r) { r.regionMse = {0.1}; }},
    };
    for (const auto& [label, edit] : cases) {
        const std::string message = label; // clang 14 cannot capture a structured binding in the lambda below
        Shards s;
        const std::string a = s.shard("a", {{"stratified", 2}, {"independent", 1}}, "stipple-render 1", edit);
        const std::string b = s.shard("b", {{"stratified", 1}, {"independent", 2}});
        BOOST_CHECK_EXCEPTION(mergeShards(s.matrix, {a, b}, s.out()), std::runtime_error, [&](const auto& e) {
            return mentions(e, a + "/results.json: box") && mentions(e, message);
        });
    }
}

BOOST_AUTO_TEST_CASE(shards_of_other_content_or_contradicting_blocks_are_refused) {
    // The same matrix and build, but one shard's scene rendered by another program (its content hash differs): one
    // run cannot average them.
    {
        Shards s;
        const std::string a = s.shard("a", {{"independent", 1}, {"stratified", 1}});
        s.contentHash = "fedcba9876543210";
        s.integrator = "external: other_host";
        const std::string b = s.shard("b", {{"independent", 2}, {"stratified", 2}});
        BOOST_CHECK_EXCEPTION(mergeShards(s.matrix, {a, b}, s.out()), std::runtime_error, [&](const auto& e) {
            return mentions(e, b) && mentions(e, "rendered from other content") && mentions(e, "other_host");
        });
    }
    // Per-block errors that are not the row's: the intervals of compare claims would come from other numbers.
    Shards s;
    const std::string a = s.shard("a", {{"independent", 1}, {"stratified", 1}});
    const std::string scaled = s.shard("b", {{"independent", 2}, {"stratified", 2}}, "stipple-render 1", [](ResultRow& r) {
        if (r.pattern == "stratified") r.blockSse = {0, 0, 0, 4 * r.mse * 64};
        if (r.pattern == "independent") r.blockSse[0] *= 100;
    });
    BOOST_CHECK_EXCEPTION(mergeShards(s.matrix, {a, scaled}, s.out()), std::runtime_error,
                          [&](const auto& e) { return mentions(e, "block_sse sums to"); });
    const std::string shortList = s.shard("c", {{"independent", 2}, {"stratified", 2}}, "stipple-render 1",
                                          [](ResultRow& r) { r.blockRse.pop_back(); });
    BOOST_CHECK_EXCEPTION(mergeShards(s.matrix, {a, shortList}, s.out()), std::runtime_error,
                          [&](const auto& e) { return mentions(e, "block_rse has 3 values"); });
    const std::string nan = s.shard("d", {{"independent", 2}, {"stratified", 2}}, "stipple-render 1",
                                    [](ResultRow& r) { r.blockFlip[1] = std::nan(""); });
    BOOST_CHECK_EXCEPTION(mergeShards(s.matrix, {a, nan}, s.out()), std::runtime_error,
                          [&](const auto& e) { return mentions(e, "block_flip value"); });
    const std::string good = s.shard("e", {{"independent", 2}, {"stratified", 2}});
    BOOST_CHECK_EQUAL(mergeShards(s.matrix, {a, good}, s.out()).rows.size(), 4u);
}

// The read limit is the matrix's: a run's own results.json (its rows' per-block lists at the matrix's image size)
// is read back however large, and a file beyond what the matrix's run writes is refused by name before parsing.
BOOST_AUTO_TEST_CASE(read_limit_comes_from_the_matrix) {
    Shards s;
    s.side = 2048; // 65536 blocks a row: the four rows' lists pass the fixed 16 MiB of other input files
    s.matrix.scenes[0].width = s.matrix.scenes[0].height = s.side;
    const auto longValues = [](ResultRow& r) {
        // Values with all their digits, as measurements have.
        for (double& v : r.blockRse) v = 1.0 / 3;
        for (double& v : r.blockFlip) v = 2.0 / 3;
    };
    const std::string a = s.shard("a", {{"independent", 1}, {"independent", 2}}, "stipple-render 1", longValues);
    const std::string b = s.shard("b", {{"stratified", 1}, {"stratified", 2}}, "stipple-render 1", longValues);
    const uint64_t limit = resultsFileByteLimit(s.matrix);
    const uint64_t bytes = fs::file_size(fs::path(a) / "results.json") + fs::file_size(fs::path(b) / "results.json");
    BOOST_TEST_MESSAGE("two shards' results.json: " << bytes << " bytes; the matrix's limit " << limit);
    BOOST_TEST(bytes > stipple::render::limits::kMaxYamlFileBytes);
    // The rows' share of the limit bounds what the run wrote (the fixed part is for cells, slopes and checks).
    BOOST_TEST(bytes <= limit - stipple::render::limits::kMaxYamlFileBytes);
    BOOST_TEST(mergeShards(s.matrix, {a, b}, s.out()).rows.size() == 4u);

    // One byte over: refused before it is read, naming the file and the limit.
    const fs::path big = fs::path(b) / "results.json";
    fs::resize_file(big, limit + 1); // sparse: costs no disk
    BOOST_CHECK_EXCEPTION(mergeShards(s.matrix, {a, b}, s.out()), std::runtime_error, [&](const auto& e) {
        return mentions(e, big.string()) && mentions(e, "the limit is " + std::to_string(limit));
    });
    BOOST_CHECK_EXCEPTION(readResultsJson(big.string(), limit), std::runtime_error,
                          [&](const auto& e) { return mentions(e, big.string()) && mentions(e, "limit"); });
}

// Whatever the matrix, the limit is bounded: a scene of unknown size counts at the largest render, and the whole at
// kMaxResultsFileBytes.
BOOST_AUTO_TEST_CASE(read_limit_is_bounded) {
    Shards s;
    const uint64_t unknownSize = resultsFileByteLimit(s.matrix); // the scene's width and height are not given
    s.matrix.scenes[0].width = s.matrix.scenes[0].height = 16;
    const uint64_t small = resultsFileByteLimit(s.matrix);
    BOOST_TEST(small > stipple::render::limits::kMaxYamlFileBytes);
    BOOST_TEST(small < unknownSize);
    BOOST_TEST(unknownSize <= kMaxResultsFileBytes);
    s.matrix.seeds.resize(100000, 7);
    BOOST_TEST(resultsFileByteLimit(s.matrix) == kMaxResultsFileBytes);
}
