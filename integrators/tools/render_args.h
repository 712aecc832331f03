// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// stipple-render's command line, parsed apart from main so the fuzzer (integrators/fuzz) can drive it.
#pragma once

#include <stipple/render/renderer.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace stipple::render {

extern const char* const kRenderUsage;
// "<pattern>+blue-noise" asks for the shim's screen-space blue-noise flag on that pattern.
inline constexpr const char* kBlueNoiseSuffix = "+blue-noise";

// A bad command line: the message names the option and the value.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct RenderArgs {
    RenderOptions options;
    std::string scenePath, output; // output: empty means <safe scene name>.exr in the working folder
    bool printLayout = false;
    bool quiet = false;        // -q / --quiet: no progress bar, no report lines
    bool help = false;         // -h / --help: print kRenderUsage and stop
    bool version = false;      // --version: print the version line and stop
    bool patternGiven = false; // --pattern: main checks the name against the loaded shim's
    bool blueNoise = false;    // --blue-noise: the pattern gets kBlueNoiseSuffix
    float exposure = 0;
};

// argv without the program name. Throws UsageError.
RenderArgs parseRenderArgs(const std::vector<std::string>& argv);

} // namespace stipple::render
