// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The integrator interface. The render loop (renderer.cpp) declares "pixel" (and "lens" for a thin-lens camera),
// asks the integrator to declare the rest, creates the shim sampler, then calls Li once per camera sample from
// the thread that owns the pixel's tile with the camera ray's closest hit already found.
//
// Adding an integrator: implement Integrator in src/integrators/<name>_integrator.cpp, list the file in
// integrators/CMakeLists.txt, declare its factory in integrator_registry.h and add it to the table in
// integrator_registry.cpp.
#pragma once

#include "camera/camera.h"
#include "film/film.h"
#include "sampling/pixel_sampler.h"
#include "scene/render_scene.h"

#include <memory>
#include <string>
#include <vector>

namespace stipple::render {

// What one tile's worker may touch while rendering: counters and its own splat list.
struct TileContext {
    uint64_t rays = 0;
    SplatList* splats = nullptr; // this tile's list (see film.h for the determinism rule)
    int width = 0, height = 0;   // film size, for splats
};

struct IntegratorSettings {
    int maxDepth = 8;          // bounces; 0 = emitters seen directly only
    uint32_t lightSamples = 1; // direct: k light and k BSDF samples per camera sample
};

class Integrator {
public:
    virtual ~Integrator() = default;
    virtual const char* name() const = 0;
    // Appends the dimensions this integrator reads (after "pixel"/"lens"), remembering their indices.
    virtual void declareDimensions(SampleLayout& layout) = 0;
    // Radiance along a camera ray for one camera sample, given the ray's closest hit (the render loop traces a
    // pixel's camera rays in packets and counts them). Light-tracing contributions go to tile.splats.
    virtual Spectrum Li(const Ray& ray, const TracedHit& first, const SampleView& samples, TileContext& tile) const = 0;
    // The radiance of `count` (<= RenderScene::kPacketSize) consecutive camera samples of one pixel, from sample
    // index firstSample on: what Li returns for each. An integrator whose next rays stay coherent within a pixel
    // traces them in packets here; the default calls Li in sample order.
    virtual void LiPacket(const Ray* rays, const TracedHit* firsts, const PixelSamples& samples, uint32_t firstSample,
                          int count, TileContext& tile, Spectrum* L) const {
        for (int k = 0; k < count; ++k)
            L[k] = Li(rays[k], firsts[k], SampleView(samples, firstSample + uint32_t(k)), tile);
    }
};

// "path", "direct", "direct-light" (light sampling only), "direct-bsdf" (BSDF sampling only), "bdpt" when built.
// Throws std::invalid_argument naming the known integrators for anything else.
std::unique_ptr<Integrator> makeIntegrator(const std::string& name, const RenderScene& scene, const Camera& camera,
                                           const IntegratorSettings& settings);
std::string knownIntegrators();
// The names makeIntegrator accepts (the debug variants aside), in the registry's order.
std::vector<std::string> registeredIntegrators();

} // namespace stipple::render
