#include "render_args.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace stipple::render {

const char* const kRenderUsage =
    "usage: stipple-render <scene.yaml> [--pattern P] [--blue-noise] [--spp N] [--seed S] [--integrator I]\n"
    "                      [--width W] [--height H] [--max-depth D]\n"
    "                      [--threads T] [--exposure STOPS] [--shim PATH] [--print-layout] [-o out.exr]\n"
    "       stipple-render --version | --help\n";

namespace {

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
    if (*end != '\0' || errno != 0)
        throw UsageError("option " + opt + ": expected an unsigned integer, got '" + v + "'");
    return x;
}

float parseFloat(const std::string& opt, const std::string& v) {
    char* end = nullptr;
    float x = std::strtof(v.c_str(), &end);
    if (v.empty() || *end != '\0' || !std::isfinite(x))
        throw UsageError("option " + opt + ": expected a number, got '" + v + "'");
    return x;
}

} // namespace

RenderArgs parseRenderArgs(const std::vector<std::string>& argv) {
    RenderArgs r;
    for (size_t i = 0; i < argv.size(); ++i) {
        std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argv.size()) throw UsageError("option " + a + " needs a value");
            return argv[++i];
        };
        if (a == "-h" || a == "--help") {
            r.help = true;
            return r;
        } else if (a == "--version") {
            r.version = true;
            return r;
        } else if (a == "--pattern") {
            // The names are the shim's (checked against the loaded library by main).
            r.options.pattern = value();
            if (r.options.pattern.empty()) throw UsageError("option --pattern: expected a pattern name");
            r.patternGiven = true;
        } else if (a == "--blue-noise") {
            r.blueNoise = true;
        } else if (a == "--spp") {
            r.options.spp = uint32_t(parseInt(a, value(), 1, 1 << 20));
        } else if (a == "--seed") {
            r.options.seed = parseU64(a, value());
        } else if (a == "--integrator") {
            r.options.integrator = value();
        } else if (a == "--width") {
            r.options.width = int(parseInt(a, value(), 1, 1 << 15));
        } else if (a == "--height") {
            r.options.height = int(parseInt(a, value(), 1, 1 << 15));
        } else if (a == "--max-depth") {
            r.options.maxDepth = int(parseInt(a, value(), 0, 1000));
        } else if (a == "--threads") {
            r.options.threads = int(parseInt(a, value(), 1, 4096));
        } else if (a == "--exposure") {
            r.exposure = parseFloat(a, value());
        } else if (a == "--shim") {
            r.options.shim = value();
        } else if (a == "--print-layout") {
            r.printLayout = true;
        } else if (a == "-o" || a == "--output") {
            r.output = value();
        } else if (!a.empty() && a[0] == '-') {
            throw UsageError("unknown option '" + a + "'");
        } else if (r.scenePath.empty()) {
            r.scenePath = a;
        } else {
            throw UsageError("unexpected argument '" + a + "' (the scene is already '" + r.scenePath + "')");
        }
    }
    if (r.scenePath.empty()) throw UsageError("no scene file given");
    if (r.blueNoise && r.options.pattern.find(kBlueNoiseSuffix) == std::string::npos)
        r.options.pattern += kBlueNoiseSuffix;
    if (!r.output.empty() && std::filesystem::path(r.output).extension() != ".exr")
        throw UsageError("option -o: expected a path ending in .exr, got '" + r.output + "'");
    return r;
}

} // namespace stipple::render
