// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors

#include "metrics/regions.h"

#include <algorithm>
#include <cmath>

#include "base/file_names.h"

namespace stipple::validation {

PixelRect pixelRect(const Region& r, int width, int height) {
    PixelRect p;
    p.x = std::clamp(int(std::floor(r.x0 * width)), 0, width - 1);
    p.y = std::clamp(int(std::floor(r.y0 * height)), 0, height - 1);
    const int x1 = std::clamp(int(std::ceil(r.x1 * width)), p.x + 1, width);
    const int y1 = std::clamp(int(std::ceil(r.y1 * height)), p.y + 1, height);
    p.w = x1 - p.x;
    p.h = y1 - p.y;
    return p;
}

Image regionImage(const Image& image, const Region& region, int scale) {
    const PixelRect p = pixelRect(region, image.width, image.height);
    return cropImage(image, p.x, p.y, p.w, p.h, scale);
}

ImageError regionError(const Image& reference, const Image& image, const Region& region) {
    return compareImages(regionImage(reference, region), regionImage(image, region));
}

double regionNoiseFloor(const Image& variance, const Region& region) {
    return noiseFloor(regionImage(variance, region));
}

std::string regionCropFile(const std::string& scene, const std::string& region, const std::string& column) {
    return "crops/" + safeName(scene) + "-region-" + safeName(region) + "-" + safeName(column) + ".png";
}

std::string regionErrorMapFile(const std::string& scene, const std::string& region, const std::string& pattern) {
    return "crops/" + safeName(scene) + "-region-" + safeName(region) + "-error-" + safeName(pattern) + ".png";
}

int regionCropScale(const PixelRect& rect, int minLongSide) {
    const int side = std::max({1, rect.w, rect.h});
    return std::clamp((minLongSide + side - 1) / side, 1, 16);
}

} // namespace stipple::validation
