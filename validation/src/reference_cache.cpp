#include "reference_cache.h"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>

#include <stipple/render/temp_files.h>

#include <stipple/render/input_limits.h>

#include "image_metrics.h"
#include "reference_integrity.h"
#include "report.h"
#include "results.h"

namespace stipple::validation {

namespace fs = std::filesystem;

namespace {
uint64_t fnv1a(const std::string& s) {
    uint64_t h = 1469598103934665603ull;
    for (unsigned char c : s) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
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
        if (ec) throw std::runtime_error("cannot rename '" + temps[i]->path() + "' to '" + target + "': " + ec.message());
        temps[i]->release();
    }
}

} // namespace

std::string referenceKey(const render::Scene& scene, const render::RenderOptions& o) {
    return keyOf(referenceKeyMaterial(scene, o));
}

std::string keyOf(const std::string& material) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", (unsigned long long)fnv1a(material));
    return buf;
}

std::string referenceKeyMaterial(const render::Scene& scene, const render::RenderOptions& o) {
    return scene.contentHash() + "|" + render::rendererVersion() + "|" + render::shimIdentity(o.shim) +
                           "|" + std::to_string(o.width) +
                           "x" + std::to_string(o.height) + "|spp " + std::to_string(o.spp) + "|seed " +
                           std::to_string(o.seed) + "|" + o.pattern + "|" + o.integrator + "|depth " +
                           std::to_string(o.maxDepth) + "|halves";
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
    if (fs::exists(provenancePath)) {
        try {
            Provenance p = parseProvenance(render::readFileBounded(provenancePath, 1 << 20, "cache provenance"));
            ref.cacheProblem = verifyProvenance(p, ref.key, keyMaterial, options.width, options.height);
            if (ref.cacheProblem.empty()) {
                ref.image = render::readImage(ref.imagePath);
                ref.variance = render::readImage(variancePath);
                ref.cacheProblem = verifyPixels(p, ref.image, ref.variance);
            }
        } catch (const std::exception& e) {
            ref.cacheProblem = e.what();
        }
        if (ref.cacheProblem.empty()) {
            ref.fromCache = true;
            return ref;
        }
    } else if (fs::exists(ref.imagePath) || fs::exists(variancePath)) {
        ref.cacheProblem = "entry without provenance (an interrupted write)";
    }

    fs::create_directories(cacheDir);
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
    std::vector<std::pair<std::string, std::string>> meta = {
        {"stipple:scene", scene.name()},          {"stipple:contentHash", scene.contentHash()},
        {"stipple:rendererVersion", render::rendererVersion()},
        {"stipple:pattern", options.pattern},     {"stipple:spp", std::to_string(options.spp)},
        {"stipple:seed", std::to_string(options.seed)}, {"stipple:integrator", options.integrator},
        {"stipple:referenceKey", ref.key}};
    std::string json = "{\n  \"key\": " + jsonString(ref.key) + ",\n  \"key_material\": " + jsonString(keyMaterial) +
                       ",\n  \"image_checksum\": " + jsonString(pixelChecksumHex(ref.image)) +
                       ",\n  \"variance_checksum\": " + jsonString(pixelChecksumHex(ref.variance)) + ",\n  \"scene\": " + jsonString(scene.name()) +
                       ",\n  \"scene_file\": " + jsonString(sceneFile) +
                       ",\n  \"content_hash\": " + jsonString(scene.contentHash()) +
                       ",\n  \"renderer_version\": " + jsonString(render::rendererVersion()) +
                       ",\n  \"width\": " + std::to_string(options.width) +
                       ",\n  \"height\": " + std::to_string(options.height) +
                       ",\n  \"pattern\": " + jsonString(options.pattern) +
                       ",\n  \"spp\": " + std::to_string(2 * half.spp) + ",\n  \"halves\": 2" + ",\n  \"seed\": " + std::to_string(options.seed) +
                       ",\n  \"integrator\": " + jsonString(options.integrator) +
                       ",\n  \"max_depth\": " + std::to_string(options.maxDepth) +
                       ",\n  \"render_seconds\": " + jsonNumber(r.renderSeconds) +
                       ",\n  \"non_finite_samples\": " + std::to_string(r.nonFiniteSamples) +
                       ",\n  \"noise_floor\": " + jsonNumber(noiseFloor(ref.variance)) +
                       ",\n  \"layout\": " + jsonString(r.layout) + ",\n  \"created\": " + jsonString(when) + "\n}\n";
    publishReferenceEntry({{variancePath, &ref.variance}, {ref.imagePath, &ref.image}}, meta, provenancePath, json);
    return ref;
}

} // namespace stipple::validation
