// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "render_args.h"

#include <stipple/render/input_limits.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <optional>

namespace stipple::render {

const char* const kRenderUsage =
    "usage: stipple-render <scene.yaml> [--pattern P] [--blue-noise] [--spp N] [--seed S] [--integrator I]\n"
    "                      [--width W] [--height H] [--max-depth D] [--threads T] [--exposure STOPS]\n"
    "                      [--shim PATH] [--print-layout] [--quiet] [-o out.exr]\n"
    "       stipple-render --version | --help\n"
    "Renders a scene file with a sample pattern of libstipple; writes a float EXR and a PNG preview beside it.\n"
    "An option's value may follow as the next argument or after '=' (--spp=64).\n"
    "  --pattern P        the shim's pattern: independent, stratified, poisson, poisson-seed, sobol, pmj02, ...\n"
    "                     (default: stratified)\n"
    "  --blue-noise       the shim's screen-space blue-noise flag on that pattern (default: off)\n"
    "  --spp N            samples per pixel, 1..1048576 (default: the scene's render.spp)\n"
    "  --seed S           the sampler's seed, 0..2^64-1 (default: 1)\n"
    "  --integrator I     path, direct or bdpt (default: the scene's render.integrator)\n"
    "  --width W          image width in pixels, 1..32768 (default: the scene's render.width)\n"
    "  --height H         image height in pixels, 1..32768 (default: the scene's render.height)\n"
    "  --max-depth D      longest path, 0..1000 bounces (default: the scene's render.max_depth)\n"
    "  --threads T        render threads, 0..1024 (default: 0 = all hardware threads)\n"
    "  --exposure STOPS   exposure of the PNG preview only, -64..64 stops (default: 0)\n"
    "  --shim PATH        libstipple.so.1 to load (default: $STIPPLE_LIBRARY, else the one beside this program)\n"
    "  --print-layout     print the dimension layout declared to the shim and stop (default: off)\n"
    "  -o, --output FILE  the EXR to write, ending in .exr; its PNG gets the same stem (default: the scene's\n"
    "                     name, made safe, .exr in the working folder)\n"
    "  -q, --quiet        no progress bar and no report lines: only warnings and errors (default: off)\n"
    "  -h, --help         this text; --version: the version line\n"
    "exit status: 0 written, 1 render or output failure, 2 bad arguments or a scene that cannot be loaded\n";

namespace {

constexpr double kMaxExposureStops = 64;

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

// A decimal number in [-limit, limit]; a hex float (0x1p3) is refused as the integers refuse hex.
float parseStops(const std::string& opt, const std::string& v, double limit) {
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (v.empty() || *end != '\0' || v.find_first_of("xX") != std::string::npos || std::isnan(x))
        throw UsageError("option " + opt + ": expected a decimal number, got '" + v + "'");
    if (!(std::fabs(x) <= limit))
        throw UsageError("option " + opt + ": expected a number in [" + std::to_string(int(-limit)) + ", " +
                         std::to_string(int(limit)) + "], got '" + v + "'");
    return float(x);
}

} // namespace

RenderArgs parseRenderArgs(const std::vector<std::string>& argv) {
    RenderArgs r;
    for (size_t i = 0; i < argv.size(); ++i) {
        std::string a = argv[i];
        // "--opt=value" is "--opt value".
        std::optional<std::string> attached;
        if (a.starts_with("--"))
            if (const size_t eq = a.find('='); eq != std::string::npos) {
                attached = a.substr(eq + 1);
                a.resize(eq);
            }
        // An empty value is an error, never "the default".
        auto value = [&]() -> std::string {
            std::string v;
            if (attached)
                v = *attached;
            else if (i + 1 >= argv.size())
                throw UsageError("option " + a + " needs a value");
            else
                v = argv[++i];
            if (v.empty()) throw UsageError("option " + a + ": expected a value, got an empty one");
            return v;
        };
        auto flag = [&] {
            if (attached) throw UsageError("option " + a + " takes no value, got '" + *attached + "'");
        };
        if (a == "-h" || a == "--help") {
            flag();
            r.help = true;
            return r;
        } else if (a == "--version") {
            flag();
            r.version = true;
            return r;
        } else if (a == "--pattern") {
            // The names are the shim's (checked against the loaded library by main).
            r.options.pattern = value();
            r.patternGiven = true;
        } else if (a == "--blue-noise") {
            flag();
            r.blueNoise = true;
        } else if (a == "--spp") {
            r.options.spp = uint32_t(parseInt(a, value(), 1, 1 << 20));
        } else if (a == "--seed") {
            r.options.seed = parseU64(a, value());
        } else if (a == "--integrator") {
            r.options.integrator = value();
        } else if (a == "--width") {
            r.options.width = int(parseInt(a, value(), 1, limits::kMaxImageSide));
        } else if (a == "--height") {
            r.options.height = int(parseInt(a, value(), 1, limits::kMaxImageSide));
        } else if (a == "--max-depth") {
            r.options.maxDepth = int(parseInt(a, value(), 0, limits::kMaxPathDepth));
        } else if (a == "--threads") {
            r.options.threads = int(parseInt(a, value(), 0, limits::kMaxThreads));
        } else if (a == "--exposure") {
            r.exposure = parseStops(a, value(), kMaxExposureStops);
        } else if (a == "--shim") {
            r.options.shim = value();
        } else if (a == "--print-layout") {
            flag();
            r.printLayout = true;
        } else if (a == "-q" || a == "--quiet") {
            flag();
            r.quiet = true;
        } else if (a == "-o" || a == "--output") {
            r.output = value();
        } else if (!a.empty() && a[0] == '-') {
            throw UsageError("unknown option '" + argv[i] + "'");
        } else if (a.empty()) {
            throw UsageError("an empty argument where the scene file was expected");
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
