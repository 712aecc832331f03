#include "runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include <stipple/render/renderer.h>

#include "image_metrics.h"
#include "progress.h"
#include "reference_cache.h"
#include "report.h"

namespace stipple::validation {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::vector<CellGroup> shardGroups(const Matrix& m, int shardIndex, int shardCount) {
    std::vector<CellGroup> groups;
    size_t g = 0;
    for (size_t s = 0; s < m.scenes.size(); ++s)
        for (uint32_t spp : m.spp)
            for (uint64_t seed : m.seeds) {
                if (g % size_t(shardCount) == size_t(shardIndex - 1)) groups.push_back({s, spp, seed});
                ++g;
            }
    return groups;
}

namespace {

std::string fmt(const char* format, auto... args) {
    char buf[512];
    std::snprintf(buf, sizeof buf, format, args...);
    return buf;
}

void writeCrop(const std::string& reportDir, const std::string& scene, const std::string& column,
               const render::Image& image, const CropSettings& crop) {
    int size = std::min({crop.size, image.width, image.height});
    int x = int(crop.x * image.width) - size / 2, y = int(crop.y * image.height) - size / 2;
    fs::create_directories(fs::path(reportDir) / "crops");
    render::writePng((fs::path(reportDir) / cropFile(scene, column)).string(),
                     cropImage(image, x, y, size, size, crop.scale));
}

} // namespace

Results runMatrix(const Matrix& m, const RunOptions& opt) {
    Results results;
    results.matrixName = m.name;
    results.rendererVersion = render::rendererVersion();
    const auto groups = shardGroups(m, opt.shardIndex, opt.shardCount);
    const int threads = opt.threads ? opt.threads : m.threads;
    const uint32_t cropSpp = m.crop.spp ? m.crop.spp : m.spp.back();

    Progress progress(opt.referencesOnly ? 0 : groups.size() * m.patterns.size());
    for (size_t si = 0; si < m.scenes.size(); ++si) {
        const MatrixScene& ms = m.scenes[si];
        std::vector<CellGroup> mine;
        for (const auto& g : groups)
            if (g.scene == si) mine.push_back(g);
        if (mine.empty()) continue;

        // A scene that fails does not take the others down: its error is recorded, its rows dropped, and the
        // run ends with a non-zero status after writing the report of the rest.
        try {
            progress.pause();
            if (auto bad = opt.unloadable.find(ms.name); bad != opt.unloadable.end())
                throw std::runtime_error(std::string("cannot load the scene (matrix ") + m.path + "): " + bad->second);
            progress.note("loading " + ms.path);
            std::unique_ptr<render::Scene> scene;
            try {
                scene = render::Scene::load(ms.path);
            } catch (const std::exception& e) {
                throw std::runtime_error(std::string("cannot load the scene (matrix ") + m.path + "): " + e.what());
            }
            render::RenderOptions base;
            base.width = ms.width ? ms.width : scene->defaultWidth();
            base.height = ms.height ? ms.height : scene->defaultHeight();
            base.integrator = ms.integrator.empty() ? scene->defaultIntegrator() : ms.integrator;
            base.maxDepth = ms.maxDepth;
            base.threads = threads;

            SceneInfo info;
            info.name = ms.name;
            info.file = ms.file;
            info.contentHash = scene->contentHash();
            info.integrator = base.integrator;
            info.width = base.width;
            info.height = base.height;
            info.triangles = scene->triangleCount();
            info.loadSeconds = scene->loadSeconds();
            info.buildSeconds = scene->buildSeconds();

            render::RenderOptions refOptions = base;
            refOptions.pattern = m.reference.pattern;
            refOptions.spp = ms.referenceSpp ? ms.referenceSpp : m.reference.spp;
            refOptions.seed = m.reference.seed;
            progress.note(fmt("reference for %s: %s %u spp seed %llu at %dx%d (key %s)", ms.name.c_str(),
                              refOptions.pattern.c_str(), refOptions.spp, (unsigned long long)refOptions.seed,
                              base.width, base.height, referenceKey(*scene, refOptions).c_str()));
            Reference ref = loadOrRenderReference(*scene, ms.file, refOptions, opt.cacheDir);
            if (!ref.cacheProblem.empty())
                progress.note("  cached entry " + ref.key + " did not verify (" + ref.cacheProblem + "): rendered again");
            info.referenceKey = ref.key;
            info.referenceSpp = refOptions.spp;
            info.referenceSeconds = ref.renderSeconds;
            info.noiseFloor = noiseFloor(ref.variance);
            progress.note(fmt("  %s: %s, noise floor %.4g (MSE)", ref.fromCache ? "cached" : "rendered",
                              ref.fromCache ? ref.imagePath.c_str() : fmt("%.1f s", ref.renderSeconds).c_str(),
                              info.noiseFloor));
            progress.resume();
            if (opt.referencesOnly) {
                results.scenes.push_back(info);
                continue;
            }
            writeCrop(opt.reportDir, ms.name, "reference", ref.image, m.crop);

            // Untimed warm-up: a tiny render per pattern × spp fills whatever the sampler caches per N, so the
            // timed cells measure steady state. Its cost is reported per scene.
            auto warm = Clock::now();
            for (uint32_t spp : m.spp)
                for (const auto& pattern : m.patterns) {
                    render::RenderOptions o = base;
                    o.pattern = pattern;
                    o.spp = spp;
                    o.seed = 0x5eed;
                    o.width = std::min(base.width, 8);
                    o.height = std::min(base.height, 8);
                    scene->render(o);
                }
            info.warmupSeconds = std::chrono::duration<double>(Clock::now() - warm).count();

            for (size_t gi = 0; gi < mine.size(); ++gi) {
                const CellGroup& g = mine[gi];
                for (size_t k = 0; k < m.patterns.size(); ++k) {
                    // Rotate the pattern order per group: no pattern always runs first (cold caches) or last.
                    const std::string& pattern = m.patterns[(k + gi) % m.patterns.size()];
                    render::RenderOptions o = base;
                    o.pattern = pattern;
                    o.spp = g.spp;
                    o.seed = g.seed;
                    render::RenderResult r = scene->render(o);
                    ImageError e = compareImages(ref.image, r.image);
                    ResultRow row;
                    row.scene = ms.name;
                    row.pattern = pattern;
                    row.spp = g.spp;
                    row.seed = g.seed;
                    row.width = r.image.width;
                    row.height = r.image.height;
                    row.mse = e.mse;
                    row.rms = e.rms;
                    row.mseCorrected = correctedMse(e.mse, info.noiseFloor);
                    row.rmsCorrected = std::sqrt(row.mseCorrected);
                    row.floorLimited = floorLimited(row.mseCorrected, info.noiseFloor);
                    row.nonFinitePixels = e.nonFinitePixels;
                    row.nonFiniteSamples = r.nonFiniteSamples;
                    row.renderSeconds = r.renderSeconds;
                    row.samplerSeconds = r.samplerSeconds;
                    results.rows.push_back(row);
                    if (g.spp == cropSpp && g.seed == m.seeds.front()) writeCrop(opt.reportDir, ms.name, pattern, r.image, m.crop);
                    progress.step(fmt("%s %s %u spp seed %llu: RMS %.4g, %.3f s (sampler %.3f s)%s", ms.name.c_str(),
                                      pattern.c_str(), g.spp, (unsigned long long)g.seed, row.rmsCorrected,
                                      row.renderSeconds, row.samplerSeconds, row.floorLimited ? ", floor-limited" : ""));
                }
            }
            results.scenes.push_back(info);
        } catch (const std::exception& e) {
            progress.resume();
            // std::bad_alloc's own text names an internal type: say what it means.
            const bool oom = dynamic_cast<const std::bad_alloc*>(&e) != nullptr;
            std::string what = ms.path + ": " + (oom ? std::string("out of memory") : std::string(e.what()));
            progress.note("ERROR: " + what + " (skipping scene " + ms.name + ")");
            results.skipped.push_back({ms.name, what});
            std::erase_if(results.rows, [&](const ResultRow& r) { return r.scene == ms.name; });
        }
    }
    progress.finish();
    sortRows(results.rows, m);
    return results;
}

} // namespace stipple::validation
