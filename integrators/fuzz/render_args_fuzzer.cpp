// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// render_args_fuzzer.cpp — libFuzzer harness of stipple-render's command-line parser. The input is split at NUL
// bytes into arguments (at most 64). Expected: RenderArgs within the documented ranges, or a UsageError with a
// message; any other exception, a crash or a sanitizer report is a finding.
#include "render_args.h"

#include <stipple/render/input_limits.h>
#include <stipple/testing/fuzz_arguments.h>

#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > 4096) return 0;
    const std::vector<std::string> argv = stipple::testing::argumentsFromFuzzInput(data, size);
    using namespace stipple::render;
    using stipple::testing::fuzzRequire;
    try {
        const RenderArgs a = parseRenderArgs(argv);
        if (a.help || a.version) return 0; // both stop before the arguments a run needs
        fuzzRequire(!a.scenePath.empty());
        fuzzRequire(a.options.spp <= (1u << 20));
        fuzzRequire(a.options.width >= 0 && a.options.width <= (1 << 15) && a.options.height >= 0 &&
                    a.options.height <= (1 << 15));
        // Whatever the parser accepts, the renderer's own range check accepts too (one range per setting).
        try {
            checkRenderSettings(a.options.threads, a.options.width, a.options.height, a.options.maxDepth);
        } catch (const std::invalid_argument&) {
            fuzzRequire(false);
        }
        fuzzRequire(a.exposure >= -64 && a.exposure <= 64);
        fuzzRequire(a.output.empty() || a.output.size() >= 4);
    } catch (const UsageError& e) {
        fuzzRequire(e.what()[0] != '\0');
    }
    return 0;
}
