// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The stipple authors
// Regions of an image named by the matrix (the study's soft shadows, caustic, out-of-focus foreground): their
// pixel rectangles, their error against the reference and their share of the reference's noise floor.
#pragma once

#include "metrics/image_metrics.h"
#include "matrix/matrix.h"

namespace stipple::validation {

struct PixelRect {
    int x = 0, y = 0, w = 0, h = 0;
};

// The pixels a normalised region covers in a width × height image (at least one pixel).
PixelRect pixelRect(const Region& region, int width, int height);

Image regionImage(const Image& image, const Region& region, int scale = 1);

// Measured MSE of the region (floor not removed) and the reference's noise floor over it.
ImageError regionError(const Image& reference, const Image& image, const Region& region);
double regionNoiseFloor(const Image& referenceVariance, const Region& region);

// Crop PNG of a region, relative to the report folder: crops/<scene>-region-<region>-<column>.png
std::string regionCropFile(const std::string& scene, const std::string& region, const std::string& column);

// Error map PNG of a region's crop (errorMap, image_metrics.h), relative to the report folder.
std::string regionErrorMapFile(const std::string& scene, const std::string& region, const std::string& pattern);

// Magnification that makes a region's crop at least `minLongSide` pixels on its long side (1..16).
int regionCropScale(const PixelRect& rect, int minLongSide = 256);

} // namespace stipple::validation
