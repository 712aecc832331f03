// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The renderer's side of a run's fingerprint (shard_fingerprint.h): the render settings a matrix scene resolves
// to, and the fingerprint of a whole run, loading the scenes a shard did not render so that every shard records
// every scene.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <stipple/render/renderer.h>

#include "matrix/matrix.h"
#include "run/shard_fingerprint.h"

namespace stipple::validation {

// The matrix's overrides over the scene's defaults: size, integrator, depth (-1 stays "the scene's"), threads.
render::RenderOptions resolveRenderOptions(const MatrixScene& ms, const render::Scene& scene, int threads);

// The scene's resolved settings as fingerprinted; `base` from resolveRenderOptions.
SceneFingerprint describeScene(const render::Scene& scene, const render::RenderOptions& base,
                               uint32_t referenceSpp);

// The fingerprint of a run of `matrix`: `known[i]` holds scene i when the run loaded it; the others are loaded
// here (a scene that does not load is recorded as not loaded). `shim` as RenderOptions::shim.
Fingerprint fingerprintRun(const Matrix& matrix, std::vector<std::optional<SceneFingerprint>> known,
                           const std::string& shim);

} // namespace stipple::validation
