// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Every file in tests/bad-scenes/*.yaml starts with "# expect: <substring>". Loading it must throw SceneError
// whose message contains that substring and names a file:line:column.
#define BOOST_TEST_MODULE scene_errors
#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <stipple/testing/expected_errors.h>

#include <optional>
#include <regex>

using namespace stipple::render;
using namespace stipple::render::test;
namespace fs = std::filesystem;

BOOST_AUTO_TEST_CASE(every_bad_scene_gives_its_message) {
    const auto files = stipple::testing::corpusFiles(STIPPLE_TEST_BAD_SCENES, ".yaml", 20);
    stipple::testing::checkExpectedErrors(
        files,
        [](const std::string& path) -> std::optional<std::string> {
            try {
                Scene::load(path);
            } catch (const SceneError& e) {
                return std::string(e.what());
            } catch (const std::exception& e) {
                BOOST_ERROR(path << ": threw a non-SceneError: " << e.what());
                return std::string(e.what());
            }
            return std::nullopt;
        },
        std::regex(R"([^ :]+\.(yaml|inc|ply):[0-9]+(:[0-9]+)?: )"));
}

BOOST_AUTO_TEST_CASE(missing_file_is_a_scene_error) {
    BOOST_CHECK_THROW(Scene::load("no-such-dir/no-such-scene.yaml"), SceneError);
}
