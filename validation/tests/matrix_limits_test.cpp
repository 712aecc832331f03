// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The matrix loader on hostile input: every file in bad-matrices/ starts with "# expect: <substring>" and must
// fail with a MatrixError containing it and naming file:line:column; generated inputs (an endless device, a FIFO,
// a file beyond the size limit, nesting deeper than the parser allows) fail at once with the limit named.
#define BOOST_TEST_MODULE matrix_limits
#include <boost/test/unit_test.hpp>

#include <stipple/render/input_limits.h>
#include <stipple/testing/expected_errors.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>

#include "matrix/matrix.h"
#include "test_vocabulary.h"

#include <stipple/testing/scratch_folder.h>

using namespace stipple::validation;
namespace fs = std::filesystem;

namespace {

std::string loadError(const std::string& path) {
    try {
        loadMatrix(path, test::kVocabulary);
    } catch (const MatrixError& e) {
        return e.what();
    }
    return "(loaded)";
}

fs::path freshDir(const std::string& name) {
    fs::path dir = stipple::testing::scratchRoot() / "matrix-limits" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

} // namespace

BOOST_AUTO_TEST_CASE(every_bad_matrix_gives_its_message) {
    const auto files = stipple::testing::corpusFiles(STIPPLE_TEST_BAD_MATRICES, ".yaml", 6);
    stipple::testing::checkExpectedErrors(
        files,
        [](const std::string& path) -> std::optional<std::string> {
            const std::string msg = loadError(path);
            if (msg == "(loaded)") return std::nullopt;
            return msg;
        },
        std::regex(R"(\.yaml:[0-9]+:[0-9]+: )"));
}

BOOST_AUTO_TEST_CASE(endless_and_special_files_fail_at_once) {
    BOOST_TEST(loadError("/dev/zero").find("/dev/zero: matrix file is not a regular file") != std::string::npos);
    BOOST_TEST(loadError("/nonexistent/m.yaml").find("cannot open matrix file") != std::string::npos);
    const fs::path fifo = freshDir("fifo") / "m.yaml";
    BOOST_REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    BOOST_TEST(loadError(fifo.string()).find("not a regular file") != std::string::npos); // would block forever
}

BOOST_AUTO_TEST_CASE(matrix_beyond_the_size_limit_fails_before_reading) {
    const fs::path p = freshDir("big") / "m.yaml";
    { std::ofstream(p) << "name: big\n"; }
    fs::resize_file(p, stipple::render::limits::kMaxYamlFileBytes + 1);
    const std::string msg = loadError(p.string());
    BOOST_TEST(msg.find("matrix file is 16777217 bytes; the limit is 16777216 bytes") != std::string::npos, msg);
}

BOOST_AUTO_TEST_CASE(nesting_deeper_than_the_parser_allows_is_an_error) {
    const std::string text = "name: x\nspp: " + std::string(100000, '[') + std::string(100000, ']') + "\n";
    try {
        parseMatrix(text, "deep.yaml", test::kVocabulary);
        BOOST_ERROR("parsed 100000 nested lists");
    } catch (const MatrixError& e) {
        BOOST_TEST(std::string(e.what()).find("deep.yaml:2:") == 0u, e.what());
        BOOST_TEST(std::string(e.what()).find("nested deeper than the parser's limit") != std::string::npos, e.what());
    }
}
