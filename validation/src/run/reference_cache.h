// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The reference image of a scene (independent pattern at high spp), rendered once and cached as EXR + the
// variance-of-the-mean EXR + provenance JSON, keyed by everything that changes its pixels. The reference is the
// mean of two independent half-spp renders; their difference gives the variance (see the .cpp for why).
#pragma once

#include <string>

#include <stipple/render/renderer.h>

namespace stipple::validation {

struct Reference {
    render::Image image;
    render::Image variance;   // per-pixel, per-channel variance of the mean, from two independent halves
    std::string key;          // 16 hex digits
    std::string imagePath;    // the cached EXR
    double renderSeconds = 0; // 0 when read from the cache
    bool fromCache = false;
    std::string cacheProblem; // why a cache entry that was there did not verify (it was re-rendered); empty if none
};

// Key over scene content hash, renderer version, resolution, spp, seed, pattern, integrator and depth.
std::string referenceKey(const render::Scene& scene, const render::RenderOptions& options);
// Everything the key hashes, in full: stored in the provenance and compared on every use.
std::string referenceKeyMaterial(const render::Scene& scene, const render::RenderOptions& options);
// The 16-hex-digit key of a key material.
std::string keyOf(const std::string& keyMaterial);

// An image of a cache entry, read only after requireRegularFile (reference_integrity.h): never through a symlink,
// never from a FIFO or a device.
render::Image readCachedImage(const std::string& path);

// Returns the cached reference for these options, or renders it (options.threads, .pattern, .spp, .seed,
// size, integrator and depth as given) and stores it under cacheDir. An entry is used only when its provenance
// has the full key and both EXRs match its pixel checksums (reference_integrity.h); anything else is rendered
// again and replaced by atomic renames, the provenance last.
Reference loadOrRenderReference(const render::Scene& scene, const std::string& sceneFile,
                                const render::RenderOptions& options, const std::string& cacheDir);

} // namespace stipple::validation
