// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "run/cell_renderer.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <stdexcept>

#include <stipple/render/temp_files.h>

#include "run/run_fingerprint.h"

namespace stipple::validation {

namespace fs = std::filesystem;

namespace {

// A scene of the renderer library, loaded once.
class InProcessScene final : public CellRenderer {
public:
    // The matrix's scene loaded, or an error naming the matrix; a scene marked unloadable by preflight fails the same.
    InProcessScene(const MatrixScene& ms, const Matrix& m, const std::map<std::string, std::string>& unloadable)
        : ms_(ms) {
        if (auto bad = unloadable.find(ms.name); bad != unloadable.end())
            throw std::runtime_error(std::string("cannot load the scene (matrix ") + m.path + "): " + bad->second);
        try {
            scene_ = render::Scene::load(ms.path);
        } catch (const std::exception& e) {
            throw std::runtime_error(std::string("cannot load the scene (matrix ") + m.path + "): " + e.what());
        }
    }

    render::RenderOptions options(int threads) const override { return resolveRenderOptions(ms_, *scene_, threads); }

    SceneInfo info(const render::RenderOptions& base) const override {
        SceneInfo info;
        info.name = ms_.name;
        info.file = ms_.file;
        info.contentHash = scene_->contentHash();
        info.integrator = base.integrator;
        info.width = base.width;
        info.height = base.height;
        info.triangles = scene_->triangleCount();
        info.loadSeconds = scene_->loadSeconds();
        info.buildSeconds = scene_->buildSeconds();
        return info;
    }

    SceneFingerprint fingerprint(const render::RenderOptions& base, uint32_t referenceSpp) const override {
        return describeScene(*scene_, base, referenceSpp);
    }

    std::string referenceSource(const render::RenderOptions& reference) const override {
        return " (key " + referenceKey(*scene_, reference) + ")";
    }

    Reference reference(const render::RenderOptions& options, const std::vector<uint64_t>&,
                        const std::string& cacheDir) const override {
        return loadOrRenderReference(*scene_, ms_.file, options, cacheDir);
    }

    // Untimed: a tiny render per pattern × spp fills whatever the sampler caches per N, so the timed cells measure
    // steady state.
    double warmUp(const render::RenderOptions& base, const Matrix& m) const override {
        const auto start = std::chrono::steady_clock::now();
        for (uint32_t spp : m.spp)
            for (const auto& pattern : m.patterns) {
                render::RenderOptions o = base;
                o.pattern = pattern;
                o.spp = spp;
                o.seed = 0x5eed;
                o.width = std::min(base.width, 8);
                o.height = std::min(base.height, 8);
                scene_->render(o);
            }
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    render::RenderResult render(const render::RenderOptions& options) const override {
        return scene_->render(options);
    }

private:
    const MatrixScene& ms_;
    std::unique_ptr<render::Scene> scene_;
};

// A scene of an external renderer: the program, a private folder for the images it writes, and what the report
// and the fingerprint say about it.
class ExternalScene final : public CellRenderer {
public:
    ExternalScene(const MatrixScene& scene, const RendererPermission& permission, const std::string& cacheDir)
        : ms_(scene), work_(permitted(scene, permission, cacheDir)), renderer_(scene, permission, work_.path()) {
        render::SignalHold hold; // made and registered, or not at all
        std::error_code ec;
        if (!fs::create_directory(work_.path(), ec) || ec)
            throw std::runtime_error("cannot make a work folder for an external renderer (" + work_.path() +
                                     "): " + (ec ? ec.message() : std::string("it exists")));
    }

    render::RenderOptions options(int threads) const override {
        render::RenderOptions o;
        o.width = ms_.width;
        o.height = ms_.height;
        o.threads = threads;
        return o;
    }

    SceneInfo info(const render::RenderOptions& base) const override {
        SceneInfo info;
        info.name = ms_.name;
        info.file = ms_.file;
        info.contentHash = renderer_.contentHash();
        info.integrator = renderer_.description();
        info.width = base.width;
        info.height = base.height;
        return info;
    }

    SceneFingerprint fingerprint(const render::RenderOptions&, uint32_t referenceSpp) const override {
        return externalFingerprint(ms_, referenceSpp);
    }

    std::string referenceSource(const render::RenderOptions&) const override {
        return " by " + renderer_.description();
    }

    Reference reference(const render::RenderOptions& options, const std::vector<uint64_t>& cellSeeds,
                        const std::string& cacheDir) const override {
        return renderer_.reference(options, cellSeeds, cacheDir);
    }

    // None: a program's start-up is part of its time.
    double warmUp(const render::RenderOptions&, const Matrix&) const override { return 0; }

    render::RenderResult render(const render::RenderOptions& options) const override {
        return renderer_.render(options);
    }

private:
    static std::string permitted(const MatrixScene& scene, const RendererPermission& permission,
                                 const std::string& cacheDir) {
        if (const std::string why = checkRendererPermission(scene, permission); !why.empty())
            throw std::runtime_error(why);
        std::error_code ec;
        fs::create_directories(cacheDir, ec);
        return fs::absolute(fs::path(cacheDir) / "external-work").lexically_normal().string();
    }

    const MatrixScene& ms_;
    // The work folder: made only once the command line's permission is checked (a refused scene leaves none),
    // named and registered as a temporary in the cache folder, so a signal removes it and the next run's sweep
    // finds it after a SIGKILL.
    render::TempPath work_;
    ExternalRenderer renderer_;
};

} // namespace

std::unique_ptr<CellRenderer> makeCellRenderer(const MatrixScene& scene, const Matrix& matrix,
                                               const std::map<std::string, std::string>& unloadable,
                                               const RendererPermission& permission, const std::string& cacheDir) {
    if (scene.renderer.empty()) return std::make_unique<InProcessScene>(scene, matrix, unloadable);
    return std::make_unique<ExternalScene>(scene, permission, cacheDir);
}

} // namespace stipple::validation
