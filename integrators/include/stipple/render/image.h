// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// The renderer's image: what film produces, image I/O reads and writes and results carry.
#pragma once

#include <cstddef>
#include <vector>

namespace stipple::render {

// Scene-linear Rec.709 RGB image, row-major, top row first, 3 floats per pixel.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;
    float* pixel(int x, int y) { return rgb.data() + 3 * (size_t(y) * width + x); }
    const float* pixel(int x, int y) const { return rgb.data() + 3 * (size_t(y) * width + x); }
};

} // namespace stipple::render
