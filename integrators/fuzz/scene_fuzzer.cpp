// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// scene_fuzzer.cpp — libFuzzer harness for the scene YAML loader (integrators/SCENE_FORMAT.md). The input is
// written to a scene file in a per-process temporary folder (includes and meshes resolve against it) and loaded.
// Expected: either a SceneDescription or a SceneError whose message names the file; any other exception, a
// crash, a hang or a sanitizer report is a finding.
// When the parsed scene is small (<= 2000 triangles + spheres, <= 64 instances) it is also built (Embree BVH)
// and rendered at 4x4 pixels, 1 spp, max depth 3, one thread; the image must be finite where the renderer says
// it accumulated finite samples. Bigger scenes are only parsed: the cap keeps each input well under a second.
#include "scene/scene_loader.h"

#include <stipple/render/renderer.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

void require(bool condition) {
    if (!condition) __builtin_trap();
}

const std::string& scenePath() {
    static const std::string path = [] {
        static const fs::path dir = fs::temp_directory_path() / ("stipple-scene-fuzz-" + std::to_string(getpid()));
        fs::create_directories(dir);
        // A run that ends normally (its time budget spent) leaves nothing behind; a crash keeps the input.
        std::atexit([] {
            std::error_code ec;
            fs::remove_all(dir, ec);
        });
        return (dir / "fuzz.yaml").string();
    }();
    return path;
}

uint64_t primitiveCount(const stipple::render::ShapeGroup& g) {
    uint64_t n = g.spheres.size();
    for (const auto& m : g.meshes) n += m.indices.size() / 3;
    return n;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > 16384) return 0; // YAML anchors aside, bigger inputs only slow the search down
    {
        std::ofstream out(scenePath(), std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    }
    using namespace stipple::render;
    SceneDescription desc;
    try {
        desc = loadSceneDescription(scenePath());
    } catch (const SceneError& e) {
        const std::string message = e.what();
        require(!message.empty() && message.find(':') != std::string::npos); // "file[:line:column]: what"
        return 0;
    }
    uint64_t primitives = primitiveCount(desc.shapes);
    for (const auto& o : desc.objects) primitives += primitiveCount(o);
    if (primitives > 2000 || desc.instances.size() > 64 || std::getenv("STIPPLE_FUZZ_PARSE_ONLY")) return 0;
    try {
        auto scene = Scene::load(scenePath());
        RenderOptions options;
        options.width = 4;
        options.height = 4;
        options.spp = 1;
        options.maxDepth = 3;
        options.threads = 1;
        RenderResult r = scene->render(options);
        require(r.image.width == 4 && r.image.height == 4 && r.image.rgb.size() == 48);
        for (float v : r.image.rgb) require(std::isfinite(v) && v >= 0.0f);
    } catch (const SceneError&) {
        // Errors found only when building (e.g. a degenerate emitter) are fine as long as they are SceneErrors.
    }
    return 0;
}
