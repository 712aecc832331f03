// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// validate_args_fuzzer.cpp — libFuzzer harness of stipple-validate's command-line parser. The input is split at
// NUL bytes into arguments (at most 64). Expected: Args within the documented ranges, or a UsageError with a
// message; any other exception, a crash or a sanitizer report is a finding.
#include "matrix/cli_args.h"

#include <stipple/render/input_limits.h>
#include <stipple/testing/fuzz_arguments.h>

#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size > 4096) return 0;
    const std::vector<std::string> argv = stipple::testing::argumentsFromFuzzInput(data, size);
    using namespace stipple::validation;
    using stipple::testing::fuzzRequire;
    try {
        const Args a = parseArgs(argv);
        if (a.help || a.version) return 0; // both stop before the arguments a run needs
        // The perceptual experiment's standalone modes: one folder, no matrix, a port in range.
        if (!a.serveStudy.empty() || !a.analyseStudy.empty()) {
            fuzzRequire(a.matrix.empty() && (a.serveStudy.empty() != a.analyseStudy.empty()));
            fuzzRequire(a.port >= 0 && a.port <= 65535);
            for (const std::string& votes : a.extraVotes) fuzzRequire(!votes.empty());
            return 0;
        }
        fuzzRequire(!a.matrix.empty());
        // A path given empty is a usage error, never "the default" (or the working folder).
        fuzzRequire(!a.out.empty());
        for (const std::string& dir : a.merge) fuzzRequire(!dir.empty());
        fuzzRequire(a.threads >= 0 && a.threads <= stipple::render::limits::kMaxThreads);
        fuzzRequire(a.shardCount >= 1 && a.shardIndex >= 1 && a.shardIndex <= a.shardCount);
        fuzzRequire(a.merge.empty() || (a.shardCount == 1 && !a.referencesOnly));
    } catch (const UsageError& e) {
        fuzzRequire(e.what()[0] != '\0');
    }
    return 0;
}
