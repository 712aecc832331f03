// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "base/file_names.h"

#include <cctype>

namespace stipple::validation {

std::string safeName(const std::string& name) {
    std::string s;
    for (char c : name) s += (std::isalnum((unsigned char)c) || c == '-' || c == '_') ? c : '_';
    return s;
}

std::string cropFile(const std::string& scene, const std::string& pattern) {
    return "crops/" + safeName(scene) + "-" + safeName(pattern) + ".png";
}

std::string cellExrFile(const std::string& scene, const std::string& pattern, uint32_t spp, uint64_t seed) {
    return "exr/" + safeName(scene) + "-" + safeName(pattern) + "-" + std::to_string(spp) + "spp-seed" +
           std::to_string(seed) + ".exr";
}

} // namespace stipple::validation
