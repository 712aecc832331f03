#include "reference_cache.h"

#include <stipple/render/content_hash.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>

#include "file_lock.h"
#include "image_metrics.h"
#include "report.h"
#include "fields.h"
#include "results.h"

namespace stipple::validation {

namespace fs = std::filesystem;

namespace {

// What the cache's .json beside each reference records: how it was made.
struct Provenance {
    std::string key, scene, sceneFile, contentHash, rendererVersion, renderer;
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

const Fields<Provenance>& provenanceFields() {
    using P = Provenance;
    static const Fields<P> fields = {
        field("key", &P::key),
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

} // namespace

std::string referenceKey(const render::Scene& scene, const render::RenderOptions& o) {
    std::string material = scene.contentHash() + "|" + render::rendererIdentity() + "|" + render::shimIdentity(o.shim) +
                           "|" + std::to_string(o.width) +
                           "x" + std::to_string(o.height) + "|spp " + std::to_string(o.spp) + "|seed " +
                           std::to_string(o.seed) + "|" + o.pattern + "|" + o.integrator + "|depth " +
                           std::to_string(o.maxDepth) + "|halves";
    return render::ContentHash().add(material).hex();
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
    const render::ImageMetadata meta = {
        {"scene", scene.name()},           {"content_hash", scene.contentHash()},
        {"renderer", render::rendererIdentity()},
        {"pattern", options.pattern},      {"spp", std::to_string(options.spp)},
        {"seed", std::to_string(options.seed)}, {"integrator", options.integrator},
        {"max_depth", std::to_string(options.maxDepth)}, {"reference_key", ref.key}};
    render::writeExr(variancePath, ref.variance, meta);
    render::writeExr(ref.imagePath, ref.image, meta);
    Provenance p;
    p.key = ref.key;
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
    writeTextFile(provenancePath, json);
    return ref;
}

} // namespace stipple::validation
