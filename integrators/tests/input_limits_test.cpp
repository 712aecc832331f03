// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Inputs that ask for more than the renderer can give end in a SceneError (or std::invalid_argument for render
// options) naming the limit and the offending value: never a stack overflow, std::bad_alloc, a hang on an
// endless file or an Embree assertion. The static cases are in bad-scenes/ (scene_errors_test); these need
// generated files.
#define BOOST_TEST_MODULE input_limits
#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <stipple/render/input_limits.h>
#include <stipple/render/progress_bar.h>
#include <stipple/testing/scratch_folder.h>

#include <fstream>

using namespace stipple::render;
using namespace stipple::render::test;
namespace fs = std::filesystem;

namespace {

const char* kHeader = "camera: { position: [0, 0, 5], look_at: [0, 0, 0], fov: 40 }\n"
                      "materials:\n  white: { type: diffuse, albedo: 0.5 }\n";
const char* kQuad = "  - { type: quad, vertices: [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], material: white }\n";

fs::path freshDir(const std::string& name) {
    fs::path dir = stipple::testing::scratchRoot() / "input-limits" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void writeText(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

std::string loadError(const std::string& path) {
    try {
        Scene::load(path);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(loaded)";
}

// A chain of `depth` files, each including the next; the last holds a quad.
std::string includeChain(const fs::path& dir, int depth) {
    for (int i = 1; i <= depth; ++i) {
        std::string body = i < depth ? "shapes:\n  - { type: include, file: part" + std::to_string(i + 1) + ".yaml }\n"
                                     : std::string("shapes:\n") + kQuad;
        writeText(dir / ("part" + std::to_string(i) + ".yaml"), body);
    }
    writeText(dir / "main.yaml",
              std::string("name: chain\n") + kHeader + "shapes:\n  - { type: include, file: part1.yaml }\n");
    return (dir / "main.yaml").string();
}

} // namespace

BOOST_AUTO_TEST_CASE(include_chain_thousands_deep_is_an_error_not_a_stack_overflow) {
    std::string msg = loadError(includeChain(freshDir("deep"), 3000));
    BOOST_TEST_MESSAGE(msg);
    BOOST_TEST(msg.find("nested deeper than the limit of 32 files") != std::string::npos, msg);
    BOOST_TEST(msg.find("part31.yaml:2:") != std::string::npos, msg); // names the include that went too deep
}

BOOST_AUTO_TEST_CASE(include_chain_within_the_limit_loads) {
    auto scene = Scene::load(includeChain(freshDir("shallow"), limits::kMaxIncludeDepth - 1));
    BOOST_TEST(scene->triangleCount() == 2u);
}

BOOST_AUTO_TEST_CASE(scene_file_beyond_the_size_limit_fails_before_reading) {
    fs::path p = freshDir("big") / "big.yaml";
    { std::ofstream(p) << "name: big\n"; }
    fs::resize_file(p, limits::kMaxYamlFileBytes + 1); // sparse: costs no disk
    std::string msg = loadError(p.string());
    BOOST_TEST(msg.find("scene file is 16777217 bytes; the limit is 16777216 bytes") != std::string::npos, msg);
}

BOOST_AUTO_TEST_CASE(endless_device_as_scene_fails_at_once) {
    std::string msg = loadError("/dev/zero");
    BOOST_TEST(msg.find("/dev/zero: scene file is not a regular file") != std::string::npos, msg);
}

BOOST_AUTO_TEST_CASE(render_options_beyond_the_budget_are_invalid_arguments) {
    fs::path p = freshDir("budget") / "quad.yaml";
    writeText(p, std::string("name: q\n") + kHeader + "shapes:\n" + kQuad);
    auto scene = Scene::load(p.string());
    RenderOptions o;
    o.width = 32768;
    o.height = 32768;
    o.spp = 1;
    try {
        scene->render(o);
        BOOST_ERROR("rendered 32768x32768");
    } catch (const std::invalid_argument& e) {
        BOOST_TEST(std::string(e.what()).find("1073741824 pixels exceeds the limit") != std::string::npos, e.what());
    }
    o.width = o.height = 4096;
    o.spp = 1 << 20;
    BOOST_CHECK_THROW(scene->render(o), std::invalid_argument);
}

// Settings TBB's arena or the film cannot take are refused by the renderer itself, whoever sets them (65537
// threads crashed inside TBB).
BOOST_AUTO_TEST_CASE(render_settings_outside_their_ranges_are_invalid_arguments) {
    fs::path p = freshDir("settings") / "quad.yaml";
    writeText(p, std::string("name: q\n") + kHeader + "shapes:\n" + kQuad);
    auto scene = Scene::load(p.string());
    auto refused = [&](RenderOptions o, const std::string& what) {
        o.spp = 1;
        try {
            scene->render(o);
            BOOST_ERROR("rendered with " << what);
        } catch (const std::invalid_argument& e) {
            BOOST_TEST(std::string(e.what()).find(what) != std::string::npos, e.what());
        }
    };
    RenderOptions o;
    o.threads = 65537;
    refused(o, "threads 65537 is outside [0, 1024]");
    o.threads = -1;
    refused(o, "threads -1 is outside [0, 1024]");
    o = {};
    o.width = -5;
    refused(o, "width -5 is outside [0, 32768]");
    o = {};
    o.maxDepth = 1 << 20;
    refused(o, "max depth 1048576 is outside [-1, 1000]");
    o = {};
    o.threads = limits::kMaxThreads;
    o.width = o.height = 4;
    o.spp = 1;
    BOOST_CHECK_NO_THROW(scene->render(o));
}

// The estimate beside the render's progress bar: the time left at the rate so far.
BOOST_AUTO_TEST_CASE(progress_eta_is_the_time_left_at_the_rate_so_far) {
    BOOST_TEST(progressEta(0, 100, 5.0) == "ETA ?");
    BOOST_TEST(progressEta(1, 4, 10.0) == "ETA 0m30s");
    BOOST_TEST(progressEta(10, 100, 60.0) == "ETA 9m00s");
    BOOST_TEST(progressEta(1, 1000, 10.0) == "ETA 2h46m");
    BOOST_TEST(progressEta(100, 100, 60.0) == "done");
}

BOOST_AUTO_TEST_CASE(bounded_read_stops_on_a_growing_file) {
    // A FIFO is refused before reading (it could be endless); a regular file is read whole.
    fs::path dir = freshDir("fifo");
    fs::path fifo = dir / "fifo.yaml";
    BOOST_REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    BOOST_CHECK_THROW(readFileBounded(fifo.string(), 1024, "scene file"), InputLimitError);
    writeText(dir / "small.yaml", "abc");
    BOOST_TEST(readFileBounded((dir / "small.yaml").string(), 3, "scene file") == "abc");
    BOOST_CHECK_THROW(readFileBounded((dir / "small.yaml").string(), 2, "scene file"), InputLimitError);
}
