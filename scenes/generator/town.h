// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The Italian town: a street grid of perimeter blocks, a piazza with a fountain and a campanile, a narrow via
// leading into it; buildings and details are instances of a few prototypes.
#pragma once

#include <cstdint>
#include <string>

namespace stipple::citygen {

struct TownStats {
    uint64_t prototypeTriangles = 0; // written to PLY files
    uint64_t instancedTriangles = 0; // after instancing, as the renderer will count them
    uint64_t instances = 0;
    uint64_t plyFiles = 0;
};

// Writes <outDir>/<name>.yaml (objects + shapes, for `include`) and the PLY files under <outDir>/<name>/.
// The same seed gives byte-identical files.
TownStats generateTown(uint64_t seed, const std::string& outDir, const std::string& name);

} // namespace stipple::citygen
