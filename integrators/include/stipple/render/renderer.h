// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The renderer library's public C++ API: what stipple-render and stipple-validate use.
// Contract between integrators/ (implements it) and validation/ (drives it in-process). Its vocabulary (Image,
// SceneError, image I/O, the renderer's identity) lives in headers of its own, below the renderer's layers.
#pragma once

#include <stipple/render/image.h>
#include <stipple/render/image_io.h>
#include <stipple/render/renderer_identity.h>
#include <stipple/render/scene_error.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace stipple::render {

// The sample patterns the shim that RenderOptions::shim = shimPath selects serves (their one owner), in id
// order. Loads the library if needed; throws std::runtime_error when none loads.
std::vector<std::string> patternNames(const std::string& shimPath);
// Whether that shim serves `pattern` ("<name>" or "<name>+blue-noise", read by the shim's own parser).
bool patternServed(const std::string& shimPath, const std::string& pattern);

// The integrators a render can name (RenderOptions::integrator), from the renderer's one registry.
std::vector<std::string> integratorNames();

// Identity of the sample-stream library that RenderOptions::shim = shimPath selects: its version and a hash of
// the file's bytes, so a reference cache notices a rebuilt shim. Loads the library if needed; throws
// std::runtime_error, as a render would, when none loads.
std::string shimIdentity(const std::string& shimPath);

// Everything a render can be told; zero / empty means "the scene's default".
struct RenderOptions {
    std::string pattern = "stratified"; // a shim pattern name (stipple_pattern_name), optionally "+blue-noise"
    uint32_t spp = 0;
    uint64_t seed = 1;
    int width = 0;
    int height = 0;
    std::string integrator; // path | direct | bdpt; empty: the scene's
    int maxDepth = -1;      // -1: the scene's
    int threads = 0;        // 0: all hardware threads
    bool progress = false;  // progress bar on stderr when it is a TTY
    std::string shim;       // path of libstipple.so.1; empty: $STIPPLE_LIBRARY (or its alias $STIPPLE_SHIM), then beside the executable
};

struct RenderResult {
    Image image;               // per-pixel mean radiance
    Image variance;            // per-pixel, per-channel variance of the mean (sample variance / spp)
    double renderSeconds = 0;  // wall seconds of the render loop (no scene load, no BVH build)
    double samplerSeconds = 0; // seconds spent inside the shim, summed over threads / thread count
    double cpuSeconds = 0;     // CPU seconds of the render loop, summed over its worker threads: unlike the
                               // wall time, it does not grow when other processes take the cores
    uint64_t nonFiniteSamples = 0;
    uint64_t raysTraced = 0;
    std::string layout;     // the dimension layout declared to the shim, one line per dimension
    RenderOptions settings; // what was rendered: the options with every scene default resolved
};

class Scene {
public:
    // Loads a scene file and builds its BVH. Throws SceneError naming file, line, column and key.
    static std::unique_ptr<Scene> load(const std::string& path);
    virtual ~Scene() = default;

    virtual const std::string& name() const = 0;
    virtual const std::string& defaultIntegrator() const = 0;
    virtual int defaultWidth() const = 0;
    virtual int defaultHeight() const = 0;
    virtual uint32_t defaultSpp() const = 0;
    virtual std::string contentHash() const = 0; // hash of the file and everything it includes
    virtual double loadSeconds() const = 0;      // parsing + geometry generation
    virtual double buildSeconds() const = 0;     // Embree BVH build
    virtual uint64_t triangleCount() const = 0;  // after instancing
    virtual size_t emitterCount() const = 0;     // lights (emitting shapes); 0: every render is black

    // The options with every "scene default" (zero, empty, -1) replaced by the scene's value: what a render with
    // them uses, and what a cache keyed on a render must name. Resolved here only.
    virtual RenderOptions resolve(const RenderOptions& options) const = 0;

    // The layout this scene would declare to the shim for the given options, one line per dimension.
    virtual std::string describeLayout(const RenderOptions& options) const = 0;

    // Renders; thread-safe to call repeatedly, deterministic for a given (options) and any thread count.
    virtual RenderResult render(const RenderOptions& options) const = 0;
};

// Parses a scene file and checks it as Scene::load does, without building anything to render it: the cheap
// "will this load" of a run's preflight. Throws SceneError like Scene::load.
void checkSceneFile(const std::string& path);

} // namespace stipple::render
