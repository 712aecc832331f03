// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "run/run_fingerprint.h"
#include "run/external_renderer.h"

#include <exception>

namespace stipple::validation {

render::RenderOptions resolveRenderOptions(const MatrixScene& ms, const render::Scene& scene, int threads) {
    // The matrix's overrides; the renderer fills in the scene's defaults (integrator, size, depth).
    render::RenderOptions o;
    o.width = ms.width;
    o.height = ms.height;
    o.integrator = ms.integrator;
    o.maxDepth = ms.maxDepth;
    o.threads = threads;
    return scene.resolve(o);
}

SceneFingerprint describeScene(const render::Scene& scene, const render::RenderOptions& base,
                               uint32_t referenceSpp) {
    SceneFingerprint s;
    s.loaded = true;
    s.contentHash = scene.contentHash();
    s.width = base.width;
    s.height = base.height;
    s.integrator = base.integrator;
    s.maxDepth = base.maxDepth;
    s.referenceSpp = referenceSpp;
    return s;
}

Fingerprint fingerprintRun(const Matrix& m, std::vector<std::optional<SceneFingerprint>> known,
                           const std::string& shim) {
    known.resize(m.scenes.size());
    std::vector<SceneFingerprint> scenes;
    for (size_t i = 0; i < m.scenes.size(); ++i) {
        const MatrixScene& ms = m.scenes[i];
        if (!known[i] && !ms.renderer.empty()) known[i] = externalFingerprint(ms, ms.referenceSpp ? ms.referenceSpp : m.reference.spp);
        if (!known[i]) {
            // Not rendered by this shard: loaded for its settings only (a scene that does not load stays
            // "not loaded", as in the shards that tried to render it and skipped it).
            try {
                auto scene = render::Scene::load(ms.path);
                known[i] = describeScene(*scene, resolveRenderOptions(ms, *scene, 0),
                                         ms.referenceSpp ? ms.referenceSpp : m.reference.spp);
            } catch (const std::exception&) {
                known[i] = SceneFingerprint{};
            }
        }
        scenes.push_back(*known[i]);
    }
    std::string shimId;
    try {
        shimId = render::shimIdentity(shim);
    } catch (const std::exception& e) {
        shimId = std::string("unavailable: ") + e.what();
    }
    return runFingerprint(m, scenes, render::rendererVersion(), shimId);
}

} // namespace stipple::validation
