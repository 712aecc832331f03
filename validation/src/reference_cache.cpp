#include "reference_cache.h"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>

#include "file_lock.h"
#include "image_metrics.h"
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
} // namespace

std::string referenceKey(const render::Scene& scene, const render::RenderOptions& o) {
    std::string material = scene.contentHash() + "|" + render::rendererVersion() + "|" + render::shimIdentity(o.shim) +
                           "|" + std::to_string(o.width) +
                           "x" + std::to_string(o.height) + "|spp " + std::to_string(o.spp) + "|seed " +
                           std::to_string(o.seed) + "|" + o.pattern + "|" + o.integrator + "|depth " +
                           std::to_string(o.maxDepth) + "|halves";
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", (unsigned long long)fnv1a(material));
    return buf;
}

Reference loadOrRenderReference(const render::Scene& scene, const std::string& sceneFile,
                                const render::RenderOptions& options, const std::string& cacheDir) {
    Reference ref;
    ref.key = referenceKey(scene, options);
    const std::string stem = (fs::path(cacheDir) / (safeName(scene.name()) + "-" + ref.key)).string();
    ref.imagePath = stem + ".exr";
    const std::string variancePath = stem + ".variance.exr", provenancePath = stem + ".json";

    auto readCached = [&] {
        if (!fs::exists(provenancePath) || !fs::exists(ref.imagePath) || !fs::exists(variancePath)) return false;
        ref.image = render::readImage(ref.imagePath);
        ref.variance = render::readImage(variancePath);
        // A size that does not match its key means a damaged entry: render it again.
        ref.fromCache = ref.image.width == options.width && ref.image.height == options.height &&
                        ref.variance.width == options.width && ref.variance.height == options.height;
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
    std::vector<std::pair<std::string, std::string>> meta = {
        {"stipple:scene", scene.name()},          {"stipple:contentHash", scene.contentHash()},
        {"stipple:rendererVersion", render::rendererVersion()},
        {"stipple:pattern", options.pattern},     {"stipple:spp", std::to_string(options.spp)},
        {"stipple:seed", std::to_string(options.seed)}, {"stipple:integrator", options.integrator},
        {"stipple:referenceKey", ref.key}};
    render::writeExr(variancePath, ref.variance, meta);
    render::writeExr(ref.imagePath, ref.image, meta);
    std::string json = "{\n  \"key\": " + jsonString(ref.key) + ",\n  \"scene\": " + jsonString(scene.name()) +
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
    writeTextFile(provenancePath, json);
    return ref;
}

} // namespace stipple::validation
