// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The city generator is deterministic: the same seed writes byte-identical files; another seed does not.
#define BOOST_TEST_MODULE citygen
#include <boost/test/unit_test.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include <unistd.h>
#include <stipple/testing/scratch_folder.h>

namespace fs = std::filesystem;

namespace {

// Relative path -> contents of every file under `root`.
std::map<std::string, std::string> readTree(const fs::path& root) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(root)) {
        if (!e.is_regular_file()) continue;
        std::ifstream in(e.path(), std::ios::binary);
        files[fs::relative(e.path(), root).generic_string()] =
            std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    return files;
}

fs::path generate(const std::string& tag, unsigned seed) {
    fs::path dir = stipple::testing::scratchRoot() / ("citygen-" + tag);
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::string cmd = std::string("\"") + STIPPLE_CITYGEN + "\" --seed " + std::to_string(seed) + " --out \"" +
                      dir.string() + "\" --name town > /dev/null";
    BOOST_REQUIRE_MESSAGE(std::system(cmd.c_str()) == 0, "generator failed: " << cmd);
    return dir;
}

} // namespace

BOOST_AUTO_TEST_CASE(same_seed_same_bytes) {
    fs::path a = generate("a", 7), b = generate("b", 7), c = generate("c", 8);
    auto ta = readTree(a), tb = readTree(b), tc = readTree(c);
    BOOST_TEST_MESSAGE("seed 7 wrote " << ta.size() << " files");
    BOOST_TEST(ta.size() > 10u);
    BOOST_TEST(ta.count("town.yaml") == 1u);
    BOOST_REQUIRE(ta.size() == tb.size());
    for (const auto& [name, bytes] : ta) {
        auto it = tb.find(name);
        BOOST_REQUIRE_MESSAGE(it != tb.end(), name << " missing from the second run");
        BOOST_TEST_CONTEXT(name) { BOOST_TEST((bytes == it->second)); }
    }
    // another seed gives another town (the instance list differs)
    BOOST_TEST((ta["town.yaml"] != tc["town.yaml"]));
    fs::remove_all(a);
    fs::remove_all(b);
    fs::remove_all(c);
}

BOOST_AUTO_TEST_CASE(bad_arguments_are_errors) {
    std::string gen = std::string("\"") + STIPPLE_CITYGEN + "\"";
    BOOST_TEST(std::system((gen + " --seed banana > /dev/null 2>&1").c_str()) != 0);
    BOOST_TEST(std::system((gen + " --frobnicate 1 > /dev/null 2>&1").c_str()) != 0);
    BOOST_TEST(std::system((gen + " --seed > /dev/null 2>&1").c_str()) != 0);
    BOOST_TEST(std::system((gen + " --seed -3 > /dev/null 2>&1").c_str()) != 0);
    BOOST_TEST(std::system((gen + " --seed 99999999999999999999999 > /dev/null 2>&1").c_str()) != 0);
    BOOST_TEST(std::system((gen + " --name a/b > /dev/null 2>&1").c_str()) != 0);
}
