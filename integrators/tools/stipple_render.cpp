// stipple-render: renders a scene file with a sample pattern from libstipple, writes a float EXR and a PNG.
//   stipple-render <scene.yaml> [--pattern P] [--spp N] [--seed S] [--integrator I] [--width W] [--height H]
//                  [--max-depth D] [--threads T] [--exposure E] [--shim PATH] [--print-layout] [-o out.exr]
// Exit codes: 0 success, 1 render/output failure, 2 bad arguments or a scene that cannot be loaded.
#include <stipple/render/renderer.h>
#include <stipple/render/temp_files.h>

#include "film/output_publish.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>

using namespace stipple::render;

namespace {

const char* kUsage =
    "usage: stipple-render <scene.yaml> [--pattern independent|stratified|poisson|poisson-seed] [--spp N]\n"
    "                      [--seed S] [--integrator path|direct|bdpt] [--width W] [--height H] [--max-depth D]\n"
    "                      [--threads T] [--exposure STOPS] [--shim PATH] [--print-layout] [-o out.exr]\n";

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

long long parseInt(const std::string& opt, const std::string& v, long long lo, long long hi) {
    errno = 0;
    char* end = nullptr;
    long long x = std::strtoll(v.c_str(), &end, 10);
    if (v.empty() || *end != '\0' || errno != 0 || x < lo || x > hi)
        throw UsageError("option " + opt + ": expected an integer in [" + std::to_string(lo) + ", " +
                         std::to_string(hi) + "], got '" + v + "'");
    return x;
}

uint64_t parseU64(const std::string& opt, const std::string& v) {
    errno = 0;
    char* end = nullptr;
    if (v.empty() || v[0] == '-') throw UsageError("option " + opt + ": expected an unsigned integer, got '" + v + "'");
    unsigned long long x = std::strtoull(v.c_str(), &end, 10);
    if (*end != '\0' || errno != 0) throw UsageError("option " + opt + ": expected an unsigned integer, got '" + v + "'");
    return x;
}

float parseFloat(const std::string& opt, const std::string& v) {
    char* end = nullptr;
    float x = std::strtof(v.c_str(), &end);
    if (v.empty() || *end != '\0' || !std::isfinite(x)) throw UsageError("option " + opt + ": expected a number, got '" + v + "'");
    return x;
}

std::string fmt(double v, int precision = 3) {
    std::ostringstream o;
    o.setf(std::ios::fixed);
    o.precision(precision);
    o << v;
    return o.str();
}

} // namespace

int main(int argc, char** argv) {
    installTempCleanupOnSignals();
    RenderOptions options;
    std::string scenePath, output;
    bool printLayout = false;
    float exposure = 0;
    bool patternGiven = false;
    try {
        for (int i = 1; i < argc; ++i) {
            std::string a = argv[i];
            auto value = [&]() -> std::string {
                if (i + 1 >= argc) throw UsageError("option " + a + " needs a value");
                return argv[++i];
            };
            if (a == "-h" || a == "--help") {
                std::cout << kUsage;
                return 0;
            } else if (a == "--pattern") {
                options.pattern = value();
                patternGiven = true;
                if (options.pattern != "independent" && options.pattern != "stratified" && options.pattern != "poisson" &&
                    options.pattern != "poisson-seed")
                    throw UsageError("option --pattern: expected independent, stratified, poisson or poisson-seed, got '" +
                                     options.pattern + "'");
            } else if (a == "--spp") {
                options.spp = uint32_t(parseInt(a, value(), 1, 1 << 20));
            } else if (a == "--seed") {
                options.seed = parseU64(a, value());
            } else if (a == "--integrator") {
                options.integrator = value();
            } else if (a == "--width") {
                options.width = int(parseInt(a, value(), 1, 1 << 15));
            } else if (a == "--height") {
                options.height = int(parseInt(a, value(), 1, 1 << 15));
            } else if (a == "--max-depth") {
                options.maxDepth = int(parseInt(a, value(), 0, 1000));
            } else if (a == "--threads") {
                options.threads = int(parseInt(a, value(), 1, 4096));
            } else if (a == "--exposure") {
                exposure = parseFloat(a, value());
            } else if (a == "--shim") {
                options.shim = value();
            } else if (a == "--print-layout") {
                printLayout = true;
            } else if (a == "-o" || a == "--output") {
                output = value();
            } else if (!a.empty() && a[0] == '-') {
                throw UsageError("unknown option '" + a + "'");
            } else if (scenePath.empty()) {
                scenePath = a;
            } else {
                throw UsageError("unexpected argument '" + a + "' (the scene is already '" + scenePath + "')");
            }
        }
        if (scenePath.empty()) throw UsageError("no scene file given");
        if (!output.empty() && std::filesystem::path(output).extension() != ".exr")
            throw UsageError("option -o: expected a path ending in .exr, got '" + output + "'");
    } catch (const UsageError& e) {
        std::cerr << "stipple-render: " << e.what() << "\n" << kUsage;
        return 2;
    }
    (void)patternGiven;

    // Temporaries of earlier runs that were killed (SIGKILL leaves them) go before this run adds its own.
    sweepStaleTemps(output.empty() ? "." : std::filesystem::path(output).parent_path().empty()
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
        options.progress = true;
        std::cout << "scene " << scene->name() << " (" << scene->triangleCount() << " triangles, hash "
                  << scene->contentHash() << ")\n"
                  << "load " << fmt(scene->loadSeconds()) << " s, BVH build " << fmt(scene->buildSeconds()) << " s\n";
        RenderResult r = scene->render(options);
        std::string integrator = options.integrator.empty() ? scene->defaultIntegrator() : options.integrator;
        uint32_t spp = options.spp ? options.spp : scene->defaultSpp();
        std::cout << "layout:\n" << r.layout;
        std::cout << "render " << fmt(r.renderSeconds) << " s (" << r.image.width << "x" << r.image.height << ", " << spp
                  << " spp, " << options.pattern << ", " << integrator << ")\n"
                  << "sampler " << fmt(r.samplerSeconds, 4) << " s ("
                  << fmt(r.renderSeconds > 0 ? 100 * r.samplerSeconds / r.renderSeconds : 0, 1) << "% of render)\n"
                  << "rays " << r.raysTraced << " (" << fmt(r.raysTraced / std::max(1e-9, r.renderSeconds) / 1e6, 2)
                  << " Mrays/s)\n"
                  << "non-finite samples " << r.nonFiniteSamples << "\n";
        // Never a path from inside the scene file: its name, made safe, in the working folder.
        if (output.empty()) output = safeOutputStem(scene->name()) + ".exr";
        std::vector<std::pair<std::string, std::string>> meta{
            {"scene", scene->name()},
            {"scene_hash", scene->contentHash()},
            {"integrator", integrator},
            {"pattern", options.pattern},
            {"spp", std::to_string(spp)},
            {"seed", std::to_string(options.seed)},
            {"render_seconds", fmt(r.renderSeconds, 6)},
            {"sampler_seconds", fmt(r.samplerSeconds, 6)},
            {"non_finite_samples", std::to_string(r.nonFiniteSamples)},
            {"version", rendererVersion()},
        };
        std::string png = publishRenderOutputs(output, r.image, meta, exposure);
        std::cout << "wrote " << output << " and " << png << "\n";
        return 0;
    } catch (const std::invalid_argument& e) {
        std::cerr << "stipple-render: " << e.what() << "\n";
        return 2;
    } catch (const std::bad_alloc&) {
        std::cerr << "stipple-render: out of memory while rendering " << scenePath << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "stipple-render: " << e.what() << "\n";
        return 1;
    }
}
