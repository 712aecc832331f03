// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// What renders one matrix scene's cells and its reference: the renderer library in-process (stipple-render's), or a
// host renderer run as a program (external_renderer.h). The runner drives either through this one interface.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <stipple/render/renderer.h>

#include "matrix/matrix.h"
#include "run/external_renderer.h"
#include "run/reference_cache.h"
#include "run/results.h"
#include "run/shard_fingerprint.h"

namespace stipple::validation {

class CellRenderer {
public:
    virtual ~CellRenderer() = default;
    // The scene's render settings resolved (size, integrator, depth), on `threads` threads; pattern, spp and seed unset.
    virtual render::RenderOptions options(int threads) const = 0;
    // What the report says of the scene, for the settings `base`.
    virtual SceneInfo info(const render::RenderOptions& base) const = 0;
    // What the run's fingerprint records of the scene.
    virtual SceneFingerprint fingerprint(const render::RenderOptions& base, uint32_t referenceSpp) const = 0;
    // " (key …)" or " by …": how the progress note names where the reference comes from.
    virtual std::string referenceSource(const render::RenderOptions& reference) const = 0;
    // The reference, from the cache under cacheDir or rendered (and cached); its seed differs from `cellSeeds`.
    virtual Reference reference(const render::RenderOptions& options, const std::vector<uint64_t>& cellSeeds,
                                const std::string& cacheDir) const = 0;
    // An untimed warm-up before the timed cells; returns its seconds (0 when there is nothing to warm).
    virtual double warmUp(const render::RenderOptions& base, const Matrix& matrix) const = 0;
    // One cell × seed.
    virtual render::RenderResult render(const render::RenderOptions& options) const = 0;
};

// The scene's renderer: its external program when the matrix names one, else the scene loaded in-process. Throws
// std::runtime_error naming the matrix when the scene does not load (or preflight found it `unloadable`), or the
// command line did not allow its program (`permission`).
std::unique_ptr<CellRenderer> makeCellRenderer(const MatrixScene& scene, const Matrix& matrix,
                                               const std::map<std::string, std::string>& unloadable,
                                               const RendererPermission& permission, const std::string& cacheDir);

} // namespace stipple::validation
