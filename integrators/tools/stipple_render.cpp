// stipple-render: renders a scene file with a sample pattern from libstipple, writes a float EXR and a PNG.
//   stipple-render <scene.yaml> [--pattern P] [--spp N] [--seed S] [--integrator I] [--width W] [--height H]
//                  [--max-depth D] [--threads T] [--exposure E] [--shim PATH] [--print-layout] [-o out.exr]
// Exit codes: 0 success, 1 render/output failure, 2 bad arguments or a scene that cannot be loaded.
#include <stipple/render/renderer.h>
#include <stipple/version.h>

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

using namespace stipple::render;

namespace {

const char* kUsage =
    "usage: stipple-render <scene.yaml> [--pattern P] [--blue-noise] [--spp N] [--seed S] [--integrator I]\n"
    "                      [--width W] [--height H] [--max-depth D]\n"
    "                      [--threads T] [--exposure STOPS] [--shim PATH] [--print-layout] [-o out.exr]\n"
    "       stipple-render --version | --help\n";

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
    RenderOptions options;
    std::string scenePath, output;
    bool printLayout = false;
    float exposure = 0;
    bool patternGiven = false;
    bool blueNoise = false;
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
            } else if (a == "--version") {
                std::cout << stipple::versionLine("stipple-render") << "\n";
                return 0;
            } else if (a == "--pattern") {
                options.pattern = value();
                patternGiven = true;
            } else if (a == "--blue-noise") {
                blueNoise = true;
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
        if (blueNoise && options.pattern.find("+blue-noise") == std::string::npos) options.pattern += "+blue-noise";
        if (!output.empty() && std::filesystem::path(output).extension() != ".exr")
            throw UsageError("option -o: expected a path ending in .exr, got '" + output + "'");
    } catch (const UsageError& e) {
        std::cerr << "stipple-render: " << e.what() << "\n" << kUsage;
        return 2;
    }
    if (patternGiven) {
        // The names come from the shim that will serve them; a shim that does not load is reported by the render.
        std::vector<std::string> known;
        try {
            known = patternNames(options.shim);
        } catch (const std::exception&) {
        }
        // "<name>+blue-noise" asks for the shim's blue-noise flag on pattern <name>.
        const std::string base = options.pattern.substr(0, options.pattern.find("+blue-noise"));
        if (!known.empty() && std::find(known.begin(), known.end(), base) == known.end()) {
            std::string list;
            for (const std::string& n : known) list += (list.empty() ? "" : ", ") + n;
            std::cerr << "stipple-render: option --pattern: expected one of " << list << ", got '" << options.pattern
                      << "'\n"
                      << kUsage;
            return 2;
        }
    }

    std::unique_ptr<Scene> scene;
    try {
        scene = Scene::load(scenePath);
    } catch (const SceneError& e) {
        std::cerr << "stipple-render: " << e.what() << "\n";
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
        const std::string& integrator = r.settings.integrator;
        const uint32_t spp = r.settings.spp;
        std::cout << "layout:\n" << r.layout;
        std::cout << "render " << fmt(r.renderSeconds) << " s (" << r.image.width << "x" << r.image.height << ", " << spp
                  << " spp, " << options.pattern << ", " << integrator << ")\n"
                  << "sampler " << fmt(r.samplerSeconds, 4) << " s ("
                  << fmt(r.renderSeconds > 0 ? 100 * r.samplerSeconds / r.renderSeconds : 0, 1) << "% of render)\n"
                  << "rays " << r.raysTraced << " (" << fmt(r.raysTraced / std::max(1e-9, r.renderSeconds) / 1e6, 2)
                  << " Mrays/s)\n"
                  << "non-finite samples " << r.nonFiniteSamples << "\n";
        if (output.empty()) output = scene->name() + ".exr";
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
        writeExr(output, r.image, meta);
        std::string png = std::filesystem::path(output).replace_extension(".png").string();
        writePng(png, r.image, exposure);
        std::cout << "wrote " << output << " and " << png << "\n";
        return 0;
    } catch (const std::invalid_argument& e) {
        std::cerr << "stipple-render: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "stipple-render: " << e.what() << "\n";
        return 1;
    }
}
