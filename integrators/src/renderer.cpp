// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Scene::load and Scene::render: the public API of renderer.h on top of the loader, the Embree scene, the shim
// sampler, the integrators and the film. Tiles of kTileSize^2 pixels are rendered in parallel with TBB; every
// pixel's samples depend only on (seed, pixel, sample index, dimension), so the image does not depend on the
// thread count or tile order.
#include <stipple/render/input_limits.h>
#include <stipple/render/renderer.h>
#include <stipple/render/content_hash.h>
#include <stipple/render/progress_bar.h>
#include <stipple/version.h>
#include <stipple/stipple.hpp>

#include "integrators/integrator.h"
#include "scene/render_scene.h"
#include "scene/scene_loader.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <thread>

#if defined(__SSE__) || defined(__x86_64__)
#include <pmmintrin.h>
#include <xmmintrin.h>
#endif
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <mutex>

namespace stipple::render {

const char* rendererVersion() {
    static const std::string version = std::string("stipple-render ") + STIPPLE_VERSION;
    return version.c_str();
}

std::string rendererIdentity() { return std::string(rendererVersion()) + " sources " + rendererSourceHash(); }

std::string shimIdentity(const std::string& shimPath) { return ShimLibrary::get(shimPath).identity(); }

std::vector<std::string> patternNames(const std::string& shimPath) { return ShimLibrary::get(shimPath).patternNames(); }

bool patternServed(const std::string& shimPath, const std::string& pattern) {
    uint32_t id = 0, flags = 0;
    return stipple::parsePattern(pattern, id, flags, ShimLibrary::get(shimPath).api()).ok();
}

std::vector<std::string> integratorNames() { return registeredIntegrators(); }

namespace {

constexpr int kTileSize = 16;

// Flush denormals to zero on tracing threads (Embree's recommendation; also avoids slow paths in BSDF code).
void setFlushToZero() {
#if defined(__SSE__) || defined(__x86_64__)
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
#endif
}

// CPU time of the calling thread: a tile's cost as the cores spent it, whatever else the machine runs.
double threadCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

std::string hashFiles(const std::vector<std::string>& files) {
    ContentHash hash;
    for (const std::string& f : files) {
        hash.addFile(f);
        hash.add(static_cast<unsigned char>(0xff)); // file separator
    }
    return hash.hex();
}

class ProgressBar {
public:
    ProgressBar(bool enabled, size_t total)
        : enabled_(enabled && isatty(2)), total_(total), start_(std::chrono::steady_clock::now()) {}
    void tick() {
        if (!enabled_) return;
        size_t d = ++done_;
        int pct = int(100 * d / total_);
        int last = lastPct_.load();
        if (pct > last && lastPct_.compare_exchange_strong(last, pct)) {
            std::lock_guard<std::mutex> lock(mutex_);
            const double elapsed =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
            std::fprintf(stderr, "\r\033[K%s %3d%% %s", progressBar(d, total_).c_str(), pct,
                         progressEta(d, total_, elapsed).c_str());
            if (d == total_) std::fprintf(stderr, "\n");
            std::fflush(stderr);
        }
    }

private:
    bool enabled_;
    size_t total_;
    std::atomic<size_t> done_{0};
    std::atomic<int> lastPct_{-1};
    std::mutex mutex_;
    std::chrono::steady_clock::time_point start_;
};

class SceneImpl final : public Scene {
public:
    SceneImpl(SceneDescription desc, double loadSeconds)
        : hash_(hashFiles(desc.files)), loadSeconds_(loadSeconds), scene_(std::move(desc)) {}

    const std::string& name() const override { return scene_.description().name; }
    const std::string& defaultIntegrator() const override { return scene_.description().settings.integrator; }
    int defaultWidth() const override { return scene_.description().settings.width; }
    int defaultHeight() const override { return scene_.description().settings.height; }
    uint32_t defaultSpp() const override { return scene_.description().settings.spp; }
    std::string contentHash() const override { return hash_; }
    double loadSeconds() const override { return loadSeconds_; }
    double buildSeconds() const override { return scene_.buildSeconds(); }
    uint64_t triangleCount() const override { return scene_.triangleCount(); }
    size_t emitterCount() const override { return scene_.lights().size(); }

    std::string describeLayout(const RenderOptions& options) const override {
        Resolved r = resolveSettings(options);
        Camera camera(scene_.description().camera, r.width, r.height);
        auto integrator = makeIntegrator(r.integrator, scene_, camera, r.settings);
        return declareLayout(camera, *integrator).describe();
    }

    RenderResult render(const RenderOptions& options) const override;

    RenderOptions resolve(const RenderOptions& options) const override {
        const Resolved r = resolveSettings(options);
        RenderOptions o = options;
        o.integrator = r.integrator;
        o.maxDepth = r.settings.maxDepth;
        o.width = r.width;
        o.height = r.height;
        o.spp = r.spp;
        return o;
    }

private:
    struct Resolved {
        std::string integrator;
        IntegratorSettings settings;
        int width, height;
        uint32_t spp;
    };
    Resolved resolveSettings(const RenderOptions& o) const {
        const RenderSettings& s = scene_.description().settings;
        Resolved r;
        r.integrator = o.integrator.empty() ? s.integrator : o.integrator;
        r.settings.maxDepth = o.maxDepth >= 0 ? o.maxDepth : s.maxDepth;
        r.settings.lightSamples = s.lightSamples;
        r.width = o.width > 0 ? o.width : s.width;
        r.height = o.height > 0 ? o.height : s.height;
        r.spp = o.spp > 0 ? o.spp : s.spp;
        return r;
    }
    static SampleLayout declareLayout(const Camera& camera, Integrator& integrator) {
        SampleLayout layout;
        layout.add("pixel", 2);
        if (camera.isThinLens()) layout.add("lens", 2);
        integrator.declareDimensions(layout);
        return layout;
    }

    std::string hash_;
    double loadSeconds_;
    RenderScene scene_;
};

RenderResult SceneImpl::render(const RenderOptions& options) const {
    // What TBB's arena or the film cannot take is refused here, whoever set it (a command line, a matrix).
    checkRenderSettings(options.threads, options.width, options.height, options.maxDepth);
    Resolved r = resolveSettings(options);
    checkRenderBudget(r.width, r.height, r.spp); // before the film or the sampler allocates
    Camera camera(scene_.description().camera, r.width, r.height);
    auto integrator = makeIntegrator(r.integrator, scene_, camera, r.settings);
    SampleLayout layout = declareLayout(camera, *integrator);
    const int dimPixel = layout.find("pixel"), dimLens = layout.find("lens");
    PixelSampler sampler(ShimLibrary::get(options.shim), options.pattern, r.spp, options.seed, layout);

    Film film(r.width, r.height);
    const int tilesX = (r.width + kTileSize - 1) / kTileSize, tilesY = (r.height + kTileSize - 1) / kTileSize;
    const size_t tileCount = size_t(tilesX) * tilesY;
    std::vector<SplatList> splats(tileCount);
    std::vector<uint64_t> rays(tileCount, 0), nonFinite(tileCount, 0);
    std::vector<double> samplerSeconds(tileCount, 0.0), cpuSeconds(tileCount, 0.0);
    ProgressBar progress(options.progress, tileCount);

    auto renderTile = [&](size_t t) {
        const double cpuStart = threadCpuSeconds();
        setFlushToZero();
        int x0 = int(t % size_t(tilesX)) * kTileSize, y0 = int(t / size_t(tilesX)) * kTileSize;
        int x1 = std::min(x0 + kTileSize, r.width), y1 = std::min(y0 + kTileSize, r.height);
        PixelSamples samples(sampler);
        TileContext ctx;
        ctx.splats = &splats[t];
        ctx.width = r.width;
        ctx.height = r.height;
        // A pixel's camera rays leave one point (a small lens) through one pixel: they are traced in packets.
        constexpr int kPacket = RenderScene::kPacketSize;
        Ray cameraRays[kPacket];
        TracedHit firstHits[kPacket];
        Spectrum radiance[kPacket];
        for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) {
                sampler.startPixel(uint32_t(x), uint32_t(y), samples);
                for (uint32_t i0 = 0; i0 < r.spp; i0 += kPacket) {
                    const int n = int(std::min<uint32_t>(kPacket, r.spp - i0));
                    for (int k = 0; k < n; ++k) {
                        SampleView sv(samples, i0 + uint32_t(k));
                        Point2 u = sv.get2D(dimPixel);
                        Point2 lens = dimLens >= 0 ? sv.get2D(dimLens) : Point2{0.5f, 0.5f};
                        cameraRays[k] = camera.generateRay({float(x) + u.x, float(y) + u.y}, lens);
                    }
                    scene_.intersectPacket(cameraRays, n, firstHits);
                    ctx.rays += uint64_t(n);
                    integrator->LiPacket(cameraRays, firstHits, samples, i0, n, ctx, radiance);
                    for (int k = 0; k < n; ++k)
                        if (!film.addSample(x, y, radiance[k])) ++nonFinite[t];
                }
            }
        }
        rays[t] = ctx.rays;
        nonFinite[t] += ctx.splats->nonFinite();
        samplerSeconds[t] = samples.samplerSeconds();
        cpuSeconds[t] = threadCpuSeconds() - cpuStart;
        progress.tick();
    };

    int threads = options.threads > 0 ? options.threads : tbb::this_task_arena::max_concurrency();
    auto start = std::chrono::steady_clock::now();
#if defined(__SANITIZE_THREAD__)
    // ThreadSanitizer builds: plain threads taking tiles from a counter. Debian's libtbb is not instrumented,
    // so TSan cannot see its task hand-overs and would report them as races; with std::thread it sees every
    // edge and checks what matters here, the tile bodies. The image does not depend on the scheduler.
    std::atomic<size_t> nextTile{0};
    std::vector<std::thread> workers;
    for (int i = 0; i < threads; ++i)
        workers.emplace_back([&] {
            for (size_t t = nextTile.fetch_add(1); t < tileCount; t = nextTile.fetch_add(1)) renderTile(t);
        });
    for (std::thread& w : workers) w.join();
#else
    tbb::task_arena arena(threads);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<size_t>(0, tileCount, 1), [&](const tbb::blocked_range<size_t>& range) {
            for (size_t t = range.begin(); t != range.end(); ++t) renderTile(t);
        });
    });
#endif
    film.mergeSplats(splats, r.spp);
    RenderResult result;
    result.renderSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    result.image.width = result.variance.width = r.width;
    result.image.height = result.variance.height = r.height;
    result.image.rgb = film.mean();
    result.variance.rgb = film.varianceOfMean();
    double sumSampler = 0;
    for (size_t t = 0; t < tileCount; ++t) {
        result.raysTraced += rays[t];
        result.nonFiniteSamples += nonFinite[t];
        sumSampler += samplerSeconds[t];
        result.cpuSeconds += cpuSeconds[t];
    }
    result.samplerSeconds = sumSampler / double(threads);
    result.layout = layout.describe();
    result.settings = resolve(options);
    return result;
}

} // namespace

void checkSceneFile(const std::string& path) { loadSceneDescription(path); }

std::unique_ptr<Scene> Scene::load(const std::string& path) {
    auto start = std::chrono::steady_clock::now();
    SceneDescription desc = loadSceneDescription(path);
    double loadSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    try {
        return std::make_unique<SceneImpl>(std::move(desc), loadSeconds);
    } catch (const SceneError&) {
        throw;
    } catch (const std::runtime_error& e) {
        throw SceneError(path + ": " + e.what());
    }
}

} // namespace stipple::render
