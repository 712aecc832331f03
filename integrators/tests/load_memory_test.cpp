// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Loading a scene takes memory in proportion to its file: the peak a load adds (measured in a child process,
// ru_maxrss) stays within limits::kLoadBytesPerInputByte × the file's size + limits::kLoadBaseBytes, for a
// typical mesh scene (inline vertices and indices) and for the worst case of the compact document (one-digit
// integers: one node per two bytes). yaml-cpp's node tree took 60-250 bytes per byte on the same files.
// Skipped under sanitizers, whose shadow memory and quarantine are not the program's.
#define BOOST_TEST_MODULE load_memory
#include <boost/test/unit_test.hpp>

#include "scene/scene_loader.h"
#include "test_support.h"

#include <stipple/render/input_limits.h>
#include <stipple/testing/peak_memory.h>

#include <cstdio>

using namespace stipple::render;
namespace limits = stipple::render::limits;

namespace {

const char* kHeader = "name: big\ncamera: { position: [0, 1, 6.8], look_at: [0, 1, 0], fov: 40 }\n"
                      "materials:\n  white: { type: diffuse, albedo: 0.5 }\nshapes:\n";

// Meshes of 300 random vertices and 100 triangles each, written inline, until the text reaches `bytes`.
std::string meshScene(size_t bytes) {
    // Varied digits from a fixed 64-bit LCG (Knuth's MMIX constants): the text's shape, not statistics.
    uint64_t state = 1;
    auto next = [&] { return (state = state * 6364136223846793005ull + 1442695040888963407ull) >> 33; };
    auto u = [&] { return float(next() % 10000) / 10000.0f; };
    std::string s = kHeader;
    char buf[64];
    while (s.size() < bytes) {
        s += "  - type: mesh\n    material: white\n    vertices: [";
        for (int i = 0; i < 300; ++i) {
            std::snprintf(buf, sizeof buf, "%s[%.4f, %.4f, %.4f]", i ? ", " : "", u(), u(), u());
            s += buf;
        }
        s += "]\n    indices: [";
        for (int i = 0; i < 300; ++i) s += (i ? ", " : "") + std::to_string(next() % 300);
        s += "]\n";
    }
    return s;
}

// One mesh whose indices are one digit each: the most nodes per byte a scene can have.
std::string denseScene(size_t bytes) {
    std::string s = std::string(kHeader) + "  - type: mesh\n    material: white\n"
                                           "    vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n    indices: [0,1,2";
    while (s.size() < bytes) s += ",0,1,2";
    return s + "]\n";
}

void checkProportional(const std::string& name, const std::string& text) {
    if (stipple::testing::kUnderSanitizer) {
        BOOST_TEST_MESSAGE("skipped under a sanitizer: its shadow memory is not the loader's");
        return;
    }
    const std::string path = test::writeTempFile(name, text);
    const auto grown = stipple::testing::peakGrowthInChild([&] { loadSceneDescription(path); });
    BOOST_REQUIRE_MESSAGE(grown, name << " did not load in the child process");
    const uint64_t bound = limits::kLoadBytesPerInputByte * text.size() + limits::kLoadBaseBytes;
    BOOST_TEST_MESSAGE(name << ": " << text.size() << " bytes, load peak +" << *grown << " bytes = "
                            << double(*grown) / double(text.size()) << " per input byte (bound " << bound << ")");
    BOOST_TEST(*grown <= bound);
}

} // namespace

BOOST_AUTO_TEST_CASE(mesh_scene_loads_in_proportion) { checkProportional("mesh.yaml", meshScene(8u << 20)); }

BOOST_AUTO_TEST_CASE(dense_scene_loads_in_proportion) { checkProportional("dense.yaml", denseScene(4u << 20)); }
