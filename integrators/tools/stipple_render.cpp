// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// stipple-render: renders a scene file with a sample pattern from libstipple, writes a float EXR and a PNG.
//   stipple-render <scene.yaml> [options] (render_args.cpp's kRenderUsage lists them with their defaults)
// Exit codes: 0 success, 1 render/output failure, 2 bad arguments or a scene that cannot be loaded.
#include <stipple/render/renderer.h>
#include <stipple/render/temp_files.h>
#include <stipple/version.h>

#include "film/output_publish.h"
#include "render_args.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>

#include <fcntl.h>
#include <unistd.h>

using namespace stipple::render;

namespace {

std::string fmt(double v, int precision = 3) {
    std::ostringstream o;
    o.setf(std::ios::fixed);
    o.precision(precision);
    o << v;
    return o.str();
}

// Where --quiet sends the report lines.
std::ostream& quietStream() {
    static std::ostream nowhere(nullptr);
    return nowhere;
}

} // namespace

int main(int argc, char** argv) {
    installTempCleanupOnSignals();
    RenderArgs args;
    try {
        args = parseRenderArgs(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const UsageError& e) {
        std::cerr << "stipple-render: " << e.what() << "\n" << kRenderUsage;
        return 2;
    }
    if (args.help) {
        std::cout << kRenderUsage;
        return 0;
    }
    if (args.version) {
        std::cout << stipple::versionLine("stipple-render") << "\n";
        return 0;
    }
    if (args.patternGiven) {
        // The names come from the shim that will serve them; a shim that does not load is reported by the render.
        std::vector<std::string> known;
        bool served = true;
        try {
            known = patternNames(args.options.shim);
            served = patternServed(args.options.shim, args.options.pattern);
        } catch (const std::exception&) {}
        if (!served) {
            std::string list;
            for (const std::string& n : known) list += (list.empty() ? "" : ", ") + n;
            std::cerr << "stipple-render: option --pattern: expected one of " << list << " (optionally followed by "
                      << kBlueNoiseSuffix << "), got '" << args.options.pattern << "'\n"
                      << kRenderUsage;
            return 2;
        }
    }
    RenderOptions& options = args.options;
    const std::string& scenePath = args.scenePath;
    std::string output = args.output;
    const bool printLayout = args.printLayout;
    const float exposure = args.exposure;

    // Temporaries of earlier runs that were killed (SIGKILL leaves them) go before this run adds its own.
    sweepStaleTemps(output.empty() ? "."
                    : std::filesystem::path(output).parent_path().empty()
                        ? "."
                        : std::filesystem::path(output).parent_path().string());
    std::unique_ptr<Scene> scene;
    try {
        scene = Scene::load(scenePath);
    } catch (const SceneError& e) {
        std::cerr << "stipple-render: " << e.what() << "\n";
        return 2;
    } catch (const std::bad_alloc&) {
        std::cerr << "stipple-render: " << scenePath << ": out of memory while loading the scene\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "stipple-render: " << scenePath << ": " << e.what() << "\n";
        return 2;
    }
    try {
        if (printLayout) {
            std::cout << scene->describeLayout(options);
            return 0;
        }
        // Never a path from inside the scene file: its name, made safe, in the working folder.
        if (output.empty()) output = safeOutputStem(scene->name()) + ".exr";
        const std::string png = std::filesystem::path(output).replace_extension(".png").string();
        std::error_code same;
        for (const std::string& out : {output, png})
            if (std::filesystem::equivalent(out, scenePath, same))
                throw std::invalid_argument("output " + out + " is the scene file " + scenePath +
                                            "; choose another -o");
        // Before the render, not after it: the folder takes a file and the preview's colour transform ($OCIO)
        // works. A 1-pixel PNG is written beside the output and removed.
        try {
            TempPath probe(png);
            {
                // open(2) first: its errno says why (no such folder, read-only, no space) where OIIO's does not.
                SignalHold hold;
                const int fd = ::open(probe.path().c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
                if (fd < 0)
                    throw std::runtime_error("cannot create a file beside it: " + std::string(std::strerror(errno)));
                ::close(fd);
            }
            writePng(probe.path(), Image{1, 1, {0.5f, 0.5f, 0.5f}}, exposure);
        } catch (const std::exception& e) {
            std::cerr << "stipple-render: output " << output << " cannot be written (checked before rendering): "
                      << e.what() << fullDiskNote(output) << "\n";
            return 1;
        }
        if (scene->emitterCount() == 0)
            std::cerr << "stipple-render: warning: scene " << scene->name()
                      << " has no emitter (no shape with an emission); the render will be black\n";
        options.progress = !args.quiet;
        std::ostream& info = args.quiet ? quietStream() : std::cout;
        info << "scene " << scene->name() << " (" << scene->triangleCount() << " triangles, hash "
             << scene->contentHash() << ")\n"
             << "load " << fmt(scene->loadSeconds()) << " s, BVH build " << fmt(scene->buildSeconds()) << " s\n";
        RenderResult r = scene->render(options);
        const std::string& integrator = r.settings.integrator;
        const uint32_t spp = r.settings.spp;
        info << "layout:\n" << r.layout;
        info << "render " << fmt(r.renderSeconds) << " s (" << r.image.width << "x" << r.image.height << ", " << spp
             << " spp, " << options.pattern << ", " << integrator << ")\n"
             << "sampler " << fmt(r.samplerSeconds, 4) << " s ("
             << fmt(r.renderSeconds > 0 ? 100 * r.samplerSeconds / r.renderSeconds : 0, 1) << "% of render)\n"
             << "rays " << r.raysTraced << " (" << fmt(r.raysTraced / std::max(1e-9, r.renderSeconds) / 1e6, 2)
             << " Mrays/s)\n"
             << "non-finite samples " << r.nonFiniteSamples << "\n";
        ImageMetadata meta{
            {"scene", scene->name()},
            {"content_hash", scene->contentHash()},
            {"integrator", integrator},
            {"pattern", options.pattern},
            {"spp", std::to_string(spp)},
            {"seed", std::to_string(options.seed)},
            {"max_depth", std::to_string(r.settings.maxDepth)},
            {"render_seconds", fmt(r.renderSeconds, 6)},
            {"sampler_seconds", fmt(r.samplerSeconds, 6)},
            {"non_finite_samples", std::to_string(r.nonFiniteSamples)},
            {"renderer", rendererIdentity()},
        };
        publishRenderOutputs(output, r.image, meta, exposure);
        info << "wrote " << output << " and " << png << "\n";
        return 0;
    } catch (const std::invalid_argument& e) {
        std::cerr << "stipple-render: " << e.what() << "\n";
        return 2;
    } catch (const std::bad_alloc&) {
        std::cerr << "stipple-render: out of memory while rendering " << scenePath << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "stipple-render: " << e.what() << fullDiskNote(output.empty() ? "." : output) << "\n";
        return 1;
    }
}
