// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// stipple-validate's command line, parsed apart from main so the fuzzer (validation/fuzz) can drive it.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace stipple::validation {

extern const char* const kValidateUsage;

// A bad command line: the message names the option and the value.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Args {
    std::string matrix, out = "report", cache, baseline;
    int threads = 0, shardIndex = 1, shardCount = 1;
    bool referencesOnly = false;
    bool quiet = false; // -q / --quiet: warnings, errors and the exit status only
    std::vector<std::string> merge;
    bool help = false;    // -h / --help: print kValidateUsage and stop
    bool version = false; // --version: print the version line and stop
    // External renderers (a matrix's 'renderer'): run the matrix's own command, or this program in its place,
    // when the command is one of the templates of rendererCommand (external_renderer.h, RendererPermission).
    bool allowRenderer = false;
    std::string renderer;
    // The perceptual experiment (validation/src/perceptual/): its votes in the report, serving it, analysing it.
    std::string study;        // --study FOLDER: the report's perceptual block from FOLDER's votes
    std::string serveStudy;   // --serve-study FOLDER
    int port = 8765;          // --port for --serve-study (0: any free port)
    std::string analyseStudy; // --analyse-study FOLDER [VOTES...]
    std::vector<std::string> extraVotes;
    std::string rendererCommand;
    double rendererTimeout = 0; // --renderer-timeout SECONDS: per image; 0: the matrix's
};

// argv without the program name. Throws UsageError.
Args parseArgs(const std::vector<std::string>& argv);

} // namespace stipple::validation
