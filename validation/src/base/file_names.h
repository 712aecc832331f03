// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The names of the files a run writes into the report folder and its cache: the matrix reader refuses two scenes
// (or regions) whose names give one file name, the runner and the merge write and copy the files, the report links
// them.
#pragma once

#include <cstdint>
#include <string>

namespace stipple::validation {

// File-name-safe form of a scene or pattern name.
std::string safeName(const std::string& name);
// Crop PNG path relative to the report folder.
std::string cropFile(const std::string& scene, const std::string& pattern);
// One seed's render of a cell as EXR (for outside viewers), relative to the report folder.
std::string cellExrFile(const std::string& scene, const std::string& pattern, uint32_t spp, uint64_t seed);
// The colour bar of the error maps, relative to the report folder.
inline const char* kErrorBarFile = "crops/error-scale.png";

} // namespace stipple::validation
