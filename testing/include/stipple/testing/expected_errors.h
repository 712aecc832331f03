// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Bad-input corpora: a folder of files, each starting with "# expect: <substring>", that a loader must reject with
// a message containing that substring and naming where (file:line[:column]). Shared by the scene and matrix
// loaders' tests; include after <boost/test/unit_test.hpp>.
#pragma once

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <regex>
#include <string>
#include <vector>

namespace stipple::testing {

// The files of `dir` with `extension`, sorted, and checks that there are at least `atLeast` of them.
inline std::vector<std::filesystem::path> corpusFiles(const std::filesystem::path& dir, const std::string& extension,
                                                      size_t atLeast) {
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.path().extension() == extension) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    BOOST_TEST(files.size() >= atLeast, dir.string() << " holds " << files.size() << " files, expected " << atLeast);
    return files;
}

// For each file: `load` returns the loader's error message, or nothing when the file loaded; the message must
// contain the file's expectation and match `place`.
inline void checkExpectedErrors(const std::vector<std::filesystem::path>& files,
                                const std::function<std::optional<std::string>(const std::string&)>& load,
                                const std::regex& place) {
    const std::string tag = "# expect: ";
    for (const auto& f : files) {
        std::ifstream in(f);
        std::string first;
        std::getline(in, first);
        BOOST_REQUIRE_MESSAGE(first.rfind(tag, 0) == 0, f.filename() << ": first line must be '" << tag << "...'");
        const std::string expected = first.substr(tag.size());
        const std::optional<std::string> msg = load(f.string());
        if (!msg) {
            BOOST_ERROR(f.filename() << ": loaded, expected an error containing '" << expected << "'");
            continue;
        }
        BOOST_TEST_MESSAGE(f.filename().string() << ": " << *msg);
        BOOST_TEST(msg->find(expected) != std::string::npos,
                   f.filename() << ": message '" << *msg << "' lacks '" << expected << "'");
        BOOST_TEST(std::regex_search(*msg, place), f.filename() << ": message '" << *msg << "' names no place");
    }
}

} // namespace stipple::testing
