// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Everything that can fail before the first cell renders is checked first, so a run does not spend an hour and
// then fail on a missing baseline or an unwritable folder: the baseline file reads as a results.json, the cache
// folder takes a file, and every scene file parses (a scene that does not is reported now and skipped later).
// The report folder of a --merge must not overlap a shard folder it reads (it would replace one of them).
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <stipple/render/input_limits.h>

#include "matrix/matrix.h"

namespace stipple::validation {

// A check that makes the whole run pointless (exit status 2, before any rendering).
class PreflightError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct PreflightInputs {
    const Matrix* matrix = nullptr;
    std::string cacheDir;
    std::string baselinePath; // empty: none
    std::string reportDir;    // empty: no report (references only)
    std::vector<std::string> mergeDirs; // --merge's shard folders: the report folder must be none of them
    uint64_t resultsMaxBytes = render::limits::kMaxYamlFileBytes; // the baseline's read limit (resultsFileByteLimit of the matrix)
};

// Throws PreflightError for the baseline and the cache; returns scene name -> load error for the scenes that
// cannot be loaded.
std::map<std::string, std::string> preflight(const PreflightInputs& in);

} // namespace stipple::validation
