// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Runs a matrix's cells through each scene's CellRenderer (cell_renderer.h: the renderer library in-process, or
// the scene's external program): each scene is loaded once, its reference
// made or read from the cache, then every (spp, seed) group renders all patterns back to back (interleaved,
// order rotated per group) so slow drifts of a shared machine hit every pattern alike.
#pragma once

#include <map>
#include <string>

#include "run/external_renderer.h"
#include "matrix/matrix.h"
#include "run/results.h"

namespace stipple::validation {

struct RunOptions {
    std::string reportDir;                         // crops are written to <reportDir>/crops
    std::string cacheDir;                          // references
    int threads = 0;                               // 0: the matrix's setting
    int shardIndex = 1, shardCount = 1;            // this run does the groups g with g mod n == i − 1
    bool referencesOnly = false;                   // make (or check) the references of this shard's scenes, no cells
    std::map<std::string, std::string> unloadable; // scene name -> error found by the preflight: skipped
    RendererPermission renderer;                   // what the command line allows external renderers to run
};

// One group = one (scene, spp, seed): the unit of sharding, so the patterns of a group stay interleaved.
struct CellGroup {
    size_t scene = 0;
    uint32_t spp = 0;
    uint64_t seed = 0;
};
// The groups of shard i of n, in run order (deterministic: depends on the matrix only).
std::vector<CellGroup> shardGroups(const Matrix& matrix, int shardIndex, int shardCount);

// Throws std::runtime_error (scene file named) when a scene fails to load or render.
Results runMatrix(const Matrix& matrix, const RunOptions& options);

} // namespace stipple::validation
