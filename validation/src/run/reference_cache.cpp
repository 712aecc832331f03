// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "run/reference_cache.h"

#include <stipple/render/content_hash.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>

#include <stipple/render/temp_files.h>

#include <stipple/render/input_limits.h>

#include "run/file_lock.h"
#include "metrics/image_metrics.h"
#include "run/reference_integrity.h"
#include "base/file_names.h"
#include "base/fields.h"
#include "run/results.h"

#include <stipple/render/content_hash.h>

namespace stipple::validation {

namespace fs = std::filesystem;

namespace {

// What the cache's .json beside each reference records: how it was made, and (key material, checksums) what
// reference_integrity.h verifies before the entry is used.
struct ProvenanceRecord {
    std::string key, keyMaterial, imageChecksum, varianceChecksum, scene, sceneFile, contentHash, rendererVersion,
        renderer;
    int width = 0, height = 0;
    std::string pattern;
    uint32_t spp = 0;
    int halves = 2;
    uint64_t seed = 0;
    std::string integrator;
    int maxDepth = 0;
    double renderSeconds = 0;
    uint64_t nonFiniteSamples = 0;
    double noiseFloor = 0;
    std::string layout, created;
};

const Fields<ProvenanceRecord>& provenanceFields() {
    using P = ProvenanceRecord;
    static const Fields<P> fields = {
        field("key", &P::key),
        field("key_material", &P::keyMaterial),
        field("image_checksum", &P::imageChecksum),
        field("variance_checksum", &P::varianceChecksum),
        field("scene", &P::scene),
        field("scene_file", &P::sceneFile),
        field("content_hash", &P::contentHash),
        field("renderer_version", &P::rendererVersion),
        field("renderer", &P::renderer),
        field("width", &P::width),
        field("height", &P::height),
        field("pattern", &P::pattern),
        field("spp", &P::spp),
        field("halves", &P::halves),
        field("seed", &P::seed),
        field("integrator", &P::integrator),
        field("max_depth", &P::maxDepth),
        field("render_seconds", &P::renderSeconds),
        field("non_finite_samples", &P::nonFiniteSamples),
        field("noise_floor", &P::noiseFloor),
        field("layout", &P::layout),
        field("created", &P::created),
    };
    return fields;
}
// Every part is written to a temporary beside it, then renamed: the EXRs first, the provenance (which vouches for
// them by checksum) last. A reader between the renames sees a mismatch and re-renders; a killed writer leaves only
// temporaries, which the next run sweeps. Concurrent writers each rename complete parts of identical content.
void publishReferenceEntry(const std::vector<std::pair<std::string, const render::Image*>>& images,
                           const std::vector<std::pair<std::string, std::string>>& meta,
                           const std::string& provenancePath, const std::string& json) {
    std::vector<std::unique_ptr<render::TempPath>> temps;
    for (const auto& [path, image] : images) {
        temps.push_back(std::make_unique<render::TempPath>(path));
        render::writeExr(temps.back()->path(), *image, meta);
    }
    temps.push_back(std::make_unique<render::TempPath>(provenancePath));
    {
        render::SignalHold hold;
        std::ofstream out(temps.back()->path(), std::ios::binary);
        out << json;
        out.close();
        if (!out) throw std::runtime_error("cannot write " + temps.back()->path());
    }
    render::SignalHold hold;
    for (size_t i = 0; i < temps.size(); ++i) {
        const std::string& target = i < images.size() ? images[i].first : provenancePath;
        std::error_code ec;
        fs::rename(temps[i]->path(), target, ec);
        if (ec)
            throw std::runtime_error("cannot rename '" + temps[i]->path() + "' to '" + target + "': " + ec.message());
        temps[i]->release();
    }
}

} // namespace

std::string referenceKey(const render::Scene& scene, const render::RenderOptions& o) {
    return keyOf(referenceKeyMaterial(scene, o));
}

std::string keyOf(const std::string& material) { return render::ContentHash().add(material).hex(); }

std::string referenceKeyMaterial(const render::Scene& scene, const render::RenderOptions& o) {
    return scene.contentHash() + "|" + render::rendererIdentity() + "|" + render::shimIdentity(o.shim) + "|" +
           std::to_string(o.width) + "x" + std::to_string(o.height) + "|spp " + std::to_string(o.spp) + "|seed " +
           std::to_string(o.seed) + "|" + o.pattern + "|" + o.integrator + "|depth " + std::to_string(o.maxDepth) +
           "|halves";
}

render::Image readCachedImage(const std::string& path) {
    requireRegularFile(path);
    return render::readImage(path);
}

Reference loadOrRenderReference(const render::Scene& scene, const std::string& sceneFile,
                                const render::RenderOptions& options, const std::string& cacheDir) {
    Reference ref;
    const std::string keyMaterial = referenceKeyMaterial(scene, options);
    ref.key = keyOf(keyMaterial);
    const std::string stem = (fs::path(cacheDir) / (safeName(scene.name()) + "-" + ref.key)).string();
    ref.imagePath = stem + ".exr";
    const std::string variancePath = stem + ".variance.exr", provenancePath = stem + ".json";

    // Use the entry only when everything verifies; otherwise say why and render it again.
    auto readCached = [&] {
        ref.cacheProblem.clear();
        // Each part must be a regular file: a FIFO would block the read forever, a symlink could lead anywhere.
        for (const std::string& part : {provenancePath, ref.imagePath, variancePath}) {
            std::error_code ec;
            const fs::file_status st = fs::symlink_status(part, ec);
            if (fs::exists(st) && !fs::is_regular_file(st)) {
                ref.cacheProblem = part + " is not a regular file";
                return false;
            }
        }
        if (fs::exists(provenancePath)) {
            try {
                Provenance p = parseProvenance(render::readFileBounded(provenancePath, 1 << 20, "cache provenance"));
                ref.cacheProblem = verifyProvenance(p, ref.key, keyMaterial, options.width, options.height);
                if (ref.cacheProblem.empty()) {
                    ref.image = readCachedImage(ref.imagePath);
                    ref.variance = readCachedImage(variancePath);
                    ref.cacheProblem = verifyPixels(p, ref.image, ref.variance);
                }
            } catch (const std::exception& e) {
                ref.cacheProblem = e.what();
            }
            ref.fromCache = ref.cacheProblem.empty();
        } else if (fs::exists(ref.imagePath) || fs::exists(variancePath)) {
            ref.cacheProblem = "entry without provenance (an interrupted write)";
        }
        return ref.fromCache;
    };
    if (readCached()) return ref;

    fs::create_directories(cacheDir);
    // Shards sharing the cache may need this reference at once: the first renders it under the lock, the others
    // wait and then read what it published (every file appears by rename; the JSON, last, marks it complete).
    FileLock lock(stem + ".lock");
    if (readCached()) return ref;
    // Two independent halves instead of the film's per-pixel variance: the film's variance misses what BDPT
    // splats onto other pixels (light tracing, t = 1), so it would understate a BDPT reference's noise.
    // With halves A and B, (A - B)^2 / 4 is an unbiased estimate of the variance of (A + B) / 2 for any
    // integrator; its mean over pixels is the noise floor.
    render::RenderOptions half = options;
    half.spp = std::max<uint32_t>(1, options.spp / 2);
    render::RenderResult r = scene.render(half);
    half.seed = options.seed ^ 0x9e3779b97f4a7c15ull;
    render::RenderResult r2 = scene.render(half);
    ref.image = r.image;
    ref.variance = r.image;
    for (size_t i = 0; i < ref.image.rgb.size(); ++i) {
        const float a = r.image.rgb[i], b = r2.image.rgb[i];
        ref.image.rgb[i] = 0.5f * (a + b);
        ref.variance.rgb[i] = 0.25f * (a - b) * (a - b);
    }
    r.renderSeconds += r2.renderSeconds;
    r.nonFiniteSamples += r2.nonFiniteSamples;
    ref.renderSeconds = r.renderSeconds;

    std::time_t now = std::time(nullptr);
    char when[32];
    std::strftime(when, sizeof when, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
    const render::ImageMetadata meta = {{"scene", scene.name()},
                                        {"content_hash", scene.contentHash()},
                                        {"renderer", render::rendererIdentity()},
                                        {"pattern", options.pattern},
                                        {"spp", std::to_string(options.spp)},
                                        {"seed", std::to_string(options.seed)},
                                        {"integrator", options.integrator},
                                        {"max_depth", std::to_string(options.maxDepth)},
                                        {"reference_key", ref.key}};
    ProvenanceRecord p;
    p.key = ref.key;
    p.keyMaterial = keyMaterial;
    p.imageChecksum = pixelChecksumHex(ref.image);
    p.varianceChecksum = pixelChecksumHex(ref.variance);
    p.scene = scene.name();
    p.sceneFile = sceneFile;
    p.contentHash = scene.contentHash();
    p.rendererVersion = render::rendererVersion();
    p.renderer = render::rendererIdentity();
    p.width = options.width;
    p.height = options.height;
    p.pattern = options.pattern;
    p.spp = 2 * half.spp;
    p.seed = options.seed;
    p.integrator = options.integrator;
    p.maxDepth = options.maxDepth;
    p.renderSeconds = r.renderSeconds;
    p.nonFiniteSamples = r.nonFiniteSamples;
    p.noiseFloor = noiseFloor(ref.variance);
    p.layout = r.layout;
    p.created = when;
    const std::string json = toJson(p, provenanceFields()).dump(2) + "\n";
    publishReferenceEntry({{variancePath, &ref.variance}, {ref.imagePath, &ref.image}}, meta, provenancePath, json);
    return ref;
}

} // namespace stipple::validation
